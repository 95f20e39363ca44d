/* SPDX-License-Identifier: BSD-3-Clause */
/* The equations of a bg_eqsys as bg_sym expressions (for the printers and
 * symbolic elimination), the names of their leaves in text and LaTeX, and
 * the reduced form: linear algebraic blocks eliminated symbolically
 * (bond_loop becomes Equation 4.27), dependent stores combined (their
 * constraint differentiated once when it holds no algebraic unknown). */
#ifndef BG_EQSYM_H
#define BG_EQSYM_H
#include "equations/eqsys.h"
#include "base/strbuf.h"
#include "sym/sym.h"

/* Equation tree nd of s as a simplified expression. sigmap (nullable):
 * the expression to use for each signal (-1: the signal's leaf). */
int bg_eqsym_tree(bg_sym *S, const bg_eqsys *s, int nd, const int *sigmap);
/* Leaf names for bg_sym_print: ctx is the bg_eqsys. */
void bg_eqsym_name(void *ctx, int kind, int ref, int latex, bg_strbuf *out);
/* Definitions of the aliases S holds, as equations ("T = ..."; LaTeX:
 * align* rows), for the head of the sorted equations. */
void bg_eqsym_aliases(bg_sym *S, const bg_eqsys *s, int latex, bg_strbuf *out);
/* "C1.q" -> "q_{\mathrm{C1}}", "e4" -> "e_{4}", other names upright. */
void bg_eqsym_latex_name(const char *nm, bg_strbuf *out);
/* The same as MathML: <msub><mi>q</mi><mi mathvariant="normal">C1</mi></msub>. */
void bg_eqsym_mathml_name(const char *nm, bg_strbuf *out);
/* What the equation printers put around and between the parts of a row, per
 * form (BG_SYM_*): the row's start, " = " (LaTeX " &= "), its end, parentheses,
 * a product's dot and the signs of a sum. */
typedef struct bg_eqpunct {
  const char *row, *eq, *end, *lp, *rp, *times, *plus, *minus;
} bg_eqpunct;
const bg_eqpunct *bg_eqpunct_of(int form);
/* JSON objects {"name", "kind": "alias"|"derivative", "expr"} for the aliases
 * (T) and their derivative leaves (dT/dphi, printed "(dT/dphi)") of S that
 * are not yet in `seen` (names, one a line; the new ones are added), each
 * preceded by ", " unless it is the first of the list (*first). */
void bg_eqsym_json_defs(bg_sym *S, const bg_eqsys *s, bg_strbuf *seen, int *first, bg_strbuf *out);

/* ---------------------------------------------------------------- reduced form
 * Owns its symbols; s is borrowed and must outlive it. Never NULL. */
typedef struct bg_eqred bg_eqred;
bg_eqred *bg_eqred_build(const bg_eqsys *s);
void bg_eqred_free(bg_eqred *r);
/* "ode" or "dae" (static strings): the reduced form of s, built (without
 * the printed forms) and freed (the analysis JSON's reduced_form). NULL when
 * the symbolic work budget ran out; then *why (if why is not NULL) is
 * BG_EQRED_SKIPPED, else NULL. */
const char *bg_eqred_form(const bg_eqsys *s, const char **why);
#define BG_EQRED_SKIPPED                                                                  \
  "skipped: the symbolic work exceeds its budget of " BG_SYM_BUDGET_WORDS " operations (the equations, " \
  "the numeric index and the simulation do not need it)"
/* 1 when the equations became (or were) an explicit ODE x' = f(t, x). */
int bg_eqred_is_ode(const bg_eqred *r);
/* 1 when something was eliminated or combined (the reduced form differs). */
int bg_eqred_changed(const bg_eqred *r);
/* One line: what was eliminated, or why the form stays a DAE. */
const char *bg_eqred_note(const bg_eqred *r);
/* States of the reduced ODE, as unknowns of s (independent stores, user
 * states, dependent stores kept as states). Only when is_ode. */
int bg_eqred_nstate(const bg_eqred *r);
int bg_eqred_state(const bg_eqred *r, int k);
/* x' of the reduced ODE at (t, x), x in the reduced states' order; the
 * symbolic right-hand sides evaluated (for tests and checks, not for
 * simulation). 0, or -1 when not an ODE or a value is not finite. */
int bg_eqred_rhs(bg_eqred *r, double t, const double *x, double *xdot);
/* 1 when row i of s holds only as an invariant of the reduced ODE: it was
 * replaced by its time derivative (a Lagrange balance without
 * accelerations, 4.58a), so it holds where it held initially. */
int bg_eqred_invariant(const bg_eqred *r, int i);
/* The full point of s the reduced ODE gives at (t, x): y (states x, the
 * eliminated algebraic unknowns, dropped dependent states) and yp (x' and
 * the dependent stores' derivatives); s's residual vanishes there (for a
 * dropped store: when x satisfies its constraint, which then holds). */
int bg_eqred_point(bg_eqred *r, double t, const double *x, double *y, double *yp);
/* Every row of s with the bond variables substituted: expressions in y,
 * yp, t (residual rows: the expression; state rows: the right-hand side).
 * rows has s's n entries. -1 for models too large. */
int bg_eqsym_rows(bg_sym *S, const bg_eqsys *s, int *rows);
/* The same, and every bond variable as an expression in y, yp, t (sigs has
 * 2 * nbond entries: effort 2b, flow 2b + 1). */
int bg_eqsym_rows_signals(bg_sym *S, const bg_eqsys *s, int *rows, int *sigs);
/* The reduced ODE printed: "# reduced form: ..." then the solved algebraic
 * unknowns, the dropped dependent stores and the state equations.
 * latex: align* rows. Prints nothing for a model that was an ODE already. */
void bg_eqred_print(bg_eqred *r, int latex, bg_strbuf *out);
/* As JSON members: "reduced_form": "ode", "reduced": [{"lhs":, "rhs":}]. */
void bg_eqred_json(bg_eqred *r, bg_strbuf *out);
/* For the linear analysis: the reduced form with the signals marked in keep
 * (per signal; the sources' own variables) left as leaves, so the input
 * matrix is the derivative with respect to them. */
bg_eqred *bg_eqred_build_keep(const bg_eqsys *s, const unsigned char *keep);
/* x' of reduced state k as an expression (bg_eqred_sym), -1 when not an ODE. */
int bg_eqred_state_rhs(const bg_eqred *r, int k);
/* Model expression xroot (an output) in the reduced states, t, params and
 * the kept leaves; -1 when not an ODE or not built with keep. */
int bg_eqred_reduce_expr(bg_eqred *r, int xroot);
/* Unknown u of s in the reduced variables: a reduced state's leaf, a
 * dependent store's expression (no longer a state), an eliminated unknown's
 * solution; -1 when u is none of them or the form is not an ODE. */
int bg_eqred_unknown_expr(bg_eqred *r, int u);
/* The symbols of the reduced form (its aliases and their derivatives). */
bg_sym *bg_eqred_sym(bg_eqred *r);
#endif
