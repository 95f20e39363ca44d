/* SPDX-License-Identifier: BSD-3-Clause */
/* Internals of bg_eqsys shared by eqsys.c (derivation of the equations),
 * eqsys_order.c (sorting and tearing), eqsys_tape.c (evaluation and exact
 * Jacobians), eqprint.c, index.c and the index reduction. Not a public
 * interface: other stages include equations/equations.h. */
#ifndef BG_EQSYS_INT_H
#define BG_EQSYS_INT_H
#include "equations/eqtape.h"

/* eqsys_order.c: dependency lists, tearing and the computational order. */
void bg_eqs_deps(bg_eqsys *s);
/* Tears and orders; the signals tearing leaves as algebraic unknowns go into
 * torn_out (room for nsig), in the order they become unknowns; their count. */
int bg_eqs_sort(bg_eqsys *s, int *torn_out);
/* eqsym.c: fills state_y and x_modulus. */
void bg_eqs_sym_lookups(bg_eqsys *s);
/* eqsys_lagstart.c: Lagrange causality's initial point, every store held;
 * y and yp updated only on success (0). */
int bg_eqs_lagrange_start(bg_eqsys *s, double t, double *y, double *yp, int maxit);
/* Sets to 0 the unknowns u[0..nu) (pointers into y or yp) below Newton's
 * resolution (levels from first of unit + the largest down) when the
 * residual of the rows (NULL: rows 0..nrows) stays within its rounding; r is
 * left the residual at the result. unit 0: relative to the largest alone, so
 * values that are all small (a moment after a start from rest, where the
 * modes' look-ahead reads them) are kept (docs/property.md, finding 29). */
void bg_eqs_snap_zeros(bg_eqsys *s, double t, double *y, double *yp, double *r, double *const *u, int nu,
                       const int *rows, int nrows, double first, double unit);
/* eqsys_tape.c */
void bg_eqs_compile(bg_eqsys *s);
/* Tape building blocks for systems compiled from other trees (indexred_tape.c):
 * a constant slot; out = op(args) folded when constant (op T_LIN: ref is
 * the first term pushed with bg_eqs_tl_push, na the number of terms); a
 * model expression (inputs compiled once). */
int bg_eqs_const(bg_eqsys *s, double val);
int bg_eqs_emit(bg_eqsys *s, int op, int ref, int na, const int *args, int eq);
int bg_eqs_tl_push(bg_eqsys *s, int slot, double c);
int bg_eqs_cx(bg_eqsys *s, int root, int eq);
/* A slot whose value is set by the caller (t, y, yp of a compiled system). */
int bg_eqs_var_slot(bg_eqsys *s);
void bg_eqs_pattern(bg_eqsys *s);
void bg_eqs_tape_free(bg_eqsys *s);
/* Runs the main tape (and the outputs with `outputs`); 0, or -1 with s->err. */
int bg_eqs_eval(bg_eqsys *s, double t, const double *y, const double *yp, int outputs);
/* Runs only the outputs' slice of the tape: every output slot gets the
 * value bg_eqs_eval(.., 1) gives it; 0, or -1 with s->err when an output (or
 * an unknown it reads) is not finite. The other slots are left as they were. */
int bg_eqs_eval_outputs(bg_eqsys *s, double t, const double *y, const double *yp);
/* Jacobian columns: fills J (dense column-major, or CSC values when sparse)
 * with dF/dy + cj dF/dyp (rhs form rows as residual rows when `resid`, else
 * as the ODE right-hand side). Values must be current (bg_eqs_eval). */
void bg_eqs_jac(bg_eqsys *s, double cj, int resid, double *J, int sparse, int only_y,
                int only_yp);
/* eqsys_events.c: finds the event instructions (after compilation). */
void bg_eqs_events_find(bg_eqsys *s);
/* eqsys_tape.c: an event instruction's value in its mode (frozen, or as
 * compiled when free); the value of instruction k as compiled. */
double bg_eqs_ev_value(const bg_eqsys *s, int e, const double *v);
double bg_eqs_ins_value(const bg_eqsys *s, int k, const double *v);
/* eqsys_tape.c: values of the main tape at (t, y, yp) without any check. */
void bg_eqs_eval_raw(bg_eqsys *s, double t, const double *y, const double *yp);
/* Why the main tape's slot is not a finite number (values current): what the
 * first instruction on its way whose own arguments are finite did, in words
 * ("sqrt of a negative number"). */
const char *bg_eqs_why_not_finite(const bg_eqsys *s, int slot);
#endif
