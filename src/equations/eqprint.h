/* Printers of the equation system (--equations text|latex|c|json): the
 * sorted equations in computational order with bond-numbered variables, the
 * algebraic residuals and the ODE/DAE form; C: a self-contained translation
 * unit with the right-hand side (ODE) or residual (DAE) and its dense
 * Jacobian. Each appends to out. */
#ifndef BG_EQPRINT_H
#define BG_EQPRINT_H
#include "equations/eqsys.h"
#include "base/strbuf.h"

void bg_eqprint_text(const bg_eqsys *s, bg_strbuf *out);
void bg_eqprint_latex(const bg_eqsys *s, bg_strbuf *out);
void bg_eqprint_json(const bg_eqsys *s, bg_strbuf *out);
/* Defines int bg_model_rhs(double t, const double *y, double *ydot) (ODE
 * only), int bg_model_residual(double t, const double *y, const double *yp,
 * double *res), void bg_model_jacobian(double t, const double *y, const
 * double *yp, double cj, double *J) (dense column-major; ODE: df/dy, DAE:
 * dF/dy + cj dF/dyp) and the sizes BG_MODEL_N, BG_MODEL_NX. Compiles with
 * cc -std=c11 -Wall -Werror. */
void bg_eqprint_c(const bg_eqsys *s, bg_strbuf *out);
/* By name: "text", "latex", "c", "json"; -1 for an unknown format. */
int bg_eqprint(const bg_eqsys *s, const char *format, bg_strbuf *out);
#endif
