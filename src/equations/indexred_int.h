/* SPDX-License-Identifier: BSD-3-Clause */
/* Internals of the index reduction shared by indexred.c (Pantelides, dummy
 * derivatives), indexred_build.c (the reduced bg_eqsys), indexred_tape.c
 * (symbolic expressions compiled to the tape) and indexred_words.c (what was
 * done, in bond-graph terms). Not a public interface.
 *
 * Variables are the unknowns of the original system and their derivatives:
 * variable j < n is unknown j itself, (j, 1) of a differential unknown is
 * its yp, and Pantelides adds (j, k + 1) as it needs them. In the
 * equations every variable v is the leaf SYM_Y with ref v (aliases read
 * unknowns j < n only, which keep their leaf). */
#ifndef BG_INDEXRED_INT_H
#define BG_INDEXRED_INT_H
#include "base/arena.h"
#include "equations/eqsys_int.h"
#include "equations/indexred.h"
#include "sym/sym.h"

typedef struct ir_work {
  const bg_eqsys *s;
  bg_sym *S;
  int n;                               /* unknowns of s */
  int nv, capv;                        /* variables */
  int *v_unk, *v_ord, *v_der, *v_anti; /* unknown, derivative order, derivative, antiderivative */
  unsigned char *v_dummy;              /* chosen as a dummy derivative */
  int ne, cape;                        /* equations */
  int *e_expr, *e_der, *e_anti, *e_row, *e_ord; /* expression, derivative, parent, row of s, order */
  int *inc_adr, *inc_n;                /* structural incidence (Pantelides' rule) into inc */
  bg_ivec inc;
  int *assign;                         /* per variable: the equation it is matched to, -1 */
  int *row_sym;                        /* rows of s as printed (params as symbols) */
  int *sig;                            /* per signal: expression in the variables */
  double *val;                         /* per variable: value at the initial point */
  char why[400];                       /* the failure, in words */
} ir_work;

/* indexred.c */
int ir_var_leaf(ir_work *W, int v);
/* Variables of expression e (leaves SYM_Y), distinct, appended to out. */
void ir_expr_vars(ir_work *W, int e, bg_ivec *out);
/* indexred_tape.c: expression e compiled into the tape of r; map[v] is the
 * slot of variable v; SYM_YP leaves (ref u) read yp of r's unknown u. */
int ir_compile(bg_eqsys *r, bg_sym *S, int e, const int *map, int *memo, int eq);
/* indexred_build.c: the reduced system from the variables, equations and
 * dummies; NULL with W->why when it is not index 1 by structure. */
bg_eqsys *ir_build(ir_work *W);
/* indexred_words.c: the constraints, lost states and dummies in words. */
void ir_describe(ir_work *W, bg_indexred *out);
#endif
