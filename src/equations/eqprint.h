/* SPDX-License-Identifier: BSD-3-Clause */
/* Printers of the equation system (--equations text|latex|mathml|c|json): the
 * sorted equations in computational order with bond-numbered variables, the
 * algebraic residuals and the ODE/DAE form. Each appends to out. */
#ifndef BG_EQPRINT_H
#define BG_EQPRINT_H
#include "equations/eqsys.h"
#include "base/strbuf.h"

void bg_eqprint_text(const bg_eqsys *s, bg_strbuf *out);
void bg_eqprint_latex(const bg_eqsys *s, bg_strbuf *out);
void bg_eqprint_json(const bg_eqsys *s, bg_strbuf *out);
/* MathML in an HTML fragment: <h3> per group, one <math display="block"> per row. */
void bg_eqprint_mathml(const bg_eqsys *s, bg_strbuf *out);
/* By name: "text", "latex", "mathml", "json"; -1 for an unknown format (C is an export:
 * bg_export_c). */
int bg_eqprint(const bg_eqsys *s, const char *format, bg_strbuf *out);
#endif
