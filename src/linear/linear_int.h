/* SPDX-License-Identifier: BSD-3-Clause */
/* Internals of the linear analysis shared by its files. Not a public interface. */
#ifndef BG_LINEAR_INT_H
#define BG_LINEAR_INT_H
#include <complex.h>

#include "linear/linear.h"
#include "sym/sym.h"

/* linear_point.c: the operating point into y (n = bg_eqsys_n); notes go to
 * `note`. 0, or -1 when there is no usable point (note says why). */
int bg_lin_point(bg_eqsys *s, double t, int steady, double *y, bg_strbuf *note);
/* linear_reduce.c: A, B, C, D from the descriptor form, or reduce_note;
 * order: the unknowns in the order they are preferably eliminated. */
void bg_lin_reduce(bg_linear *l, const int *order);
/* C = Cx + Cp A, D = Dd + Cp B (outputs reading x'), into l->C, l->D. */
void bg_lin_outputs_through(bg_linear *l, const double *Cx, const double *Cp, const double *Dd);
/* linear_dep.c: dependent stores eliminated; 0, or -1 with reduce_note. */
int bg_lin_reduce_dependent(bg_linear *l, const int *order);
/* linear_tf.c: poles of the linearisation and the transfer functions. */
void bg_lin_poles(bg_linear *l);
void bg_lin_tfs(bg_linear *l);
/* linear_sym.c: l->sym for a linear model (s: the equations, still alive). */
void bg_lin_sym_derive(bg_linear *l, const bg_model *m, bg_eqsys *s);
/* linear_symtf.c: den (n + 1 ids, s^n first, monic) = det(sI - A) and num
 * (per pair, output-major, n + 1 ids) = det [sI - A, -b; c, d] for symbolic
 * A, B, C, D (column-major ids) by Laplace expansion over column sets,
 * expanded into monomials; -1 when a coefficient exceeds max_terms terms. */
int bg_lin_sym_tfs(bg_sym *S, int n, int nu, int ny, const int *A, const int *B, const int *C,
                   const int *D, int max_terms, int *den, int *num);
/* H(s) for pair (iy, iu) by a dense complex solve of the system in use
 * (reduced when l->reduced, else descriptor). */
double complex bg_lin_eval(const bg_linear *l, int iy, int iu, double complex s);
/* Column-major n x n product C = A B (small dense helpers). */
void bg_lin_matmul(int m, int k, int n, const double *A, const double *B, double *C);
#endif
