/* SPDX-License-Identifier: BSD-3-Clause */
/* The state space and transfer functions of a linear model in its params
 * (docs/linear.md#symbolic): the reduced form (src/equations/eqreduce.c)
 * with the sources' own variables kept as leaves, A = d x'/d x and
 * B = d x'/d u by symbolic differentiation, C and D from the outputs in the
 * reduced states; accepted only when no entry reads a state, an input or t
 * (a linear time-invariant model) and every entry evaluates to the numeric
 * matrices. Transfer functions by division-free determinant expansion
 * (linear_symtf.c), each coefficient then over one denominator; checked
 * against the numeric matrices at one complex point. Up to 8 states and a
 * size cap on the printed coefficients; full order (no cancellations,
 * unlike the numeric ones). */
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/equations.h"
#include "linear/linear_int.h"

/* Why these caps: the expansion costs (n + 1) 2^(n + 1) entry products per
 * input, and a coefficient's terms grow with the permutations a dense
 * matrix has (8! terms at n = 8): beyond them the formulas are not worth
 * reading, and the numeric transfer functions say the same. */
enum { SYM_MAX_STATES = 8, SYM_MAX_TERMS = 400, SYM_MAX_CHARS = 4000 };

typedef struct symctx {
  bg_linear *l;
  const bg_model *m;
  bg_eqsys *s;
  bg_sym *S;
  int n, nu, ny;
  int *A, *B, *C, *D; /* symbol ids, column-major like the numeric matrices */
  int *own;           /* per input: the kept signal */
} symctx;

static int own_signal(const bg_model *m, int e) {
  int b = bg_elem_port_bond(m, e), k = m->elem_kind[e];
  return k == BG_ELEM_SE || k == BG_ELEM_MSE ? 2 * b : 2 * b + 1;
}

/* Entries of A, B (rows: the reduced states in l->state order). */
static int state_rows(symctx *X, bg_eqred *r) {
  bg_linear *l = X->l;
  int n = X->n;
  if (bg_eqred_nstate(r) != n) return -1;
  for (int k = 0; k < n; k++) {
    int i = 0;
    while (i < n && l->state[i] != bg_eqred_state(r, k)) i++;
    if (i == n) return -1;
    int rhs = bg_eqred_state_rhs(r, k);
    for (int j = 0; j < n; j++)
      X->A[(size_t)j * n + i] = bg_sym_diff(X->S, rhs, bg_sym_leaf(X->S, SYM_Y, l->state[j]));
    for (int j = 0; j < X->nu; j++)
      X->B[(size_t)j * n + i] = bg_sym_diff(X->S, rhs, bg_sym_leaf(X->S, SYM_SIG, X->own[j]));
  }
  return 0;
}

static int output_rows(symctx *X, bg_eqred *r) {
  int n = X->n, ny = X->ny;
  for (int i = 0; i < ny; i++) {
    /* without an output statement output i is unknown i: a state, or a
     * dependent store the reduction expressed through the others */
    int h = X->l->outputs_are_states ? bg_eqred_unknown_expr(r, i) : bg_eqred_reduce_expr(r, X->m->output_expr[i]);
    if (h < 0) return -1;
    for (int j = 0; j < n; j++)
      X->C[(size_t)j * ny + i] = bg_sym_diff(X->S, h, bg_sym_leaf(X->S, SYM_Y, X->l->state[j]));
    for (int j = 0; j < X->nu; j++)
      X->D[(size_t)j * ny + i] = bg_sym_diff(X->S, h, bg_sym_leaf(X->S, SYM_SIG, X->own[j]));
  }
  return 0;
}

/* Every entry free of states, kept signals, inputs and t, and equal to the
 * numeric matrix entry at the model's params. */
static int entries_ok(symctx *X, const int *E, const double *num, int count) {
  bg_sym *S = X->S;
  int leaves[SYM_MAX_STATES + 64], nl = 0;
  for (int j = 0; j < X->n; j++) leaves[nl++] = bg_sym_leaf(S, SYM_Y, X->l->state[j]);
  for (int j = 0; j < X->nu && nl < SYM_MAX_STATES + 62; j++) leaves[nl++] = bg_sym_leaf(S, SYM_SIG, X->own[j]);
  leaves[nl++] = bg_sym_leaf(S, SYM_T, 0);
  unsigned char *mark = bg_xcalloc((size_t)S->nnode + 1, 1);
  for (int k = 0; k < nl; k++) mark[leaves[k]] = 1;
  for (int k = 0; k < X->m->ninput; k++) {
    int id = bg_sym_leaf(S, SYM_INPUT, k);
    if (id < S->nnode) mark[id] = 1;
  }
  int ok = 1;
  bg_symenv env = {X->l->t, X->l->y0, NULL, NULL, NULL};
  for (int k = 0; k < count && ok; k++) {
    double v = bg_sym_eval(S, E[k], &env);
    ok = !bg_sym_depends(S, E[k], mark, S->nnode) && fabs(v - num[k]) <= 1e-9 * (1 + fabs(num[k]));
  }
  free(mark);
  return ok;
}

static int simplify(bg_sym *S, int e) { return bg_sym_together(S, bg_sym_collect(S, e), 0); }

/* Printed entry; NULL when it is longer than SYM_MAX_CHARS. */
static char *print(symctx *X, int e, int latex) {
  bg_strbuf b = {0};
  bg_sym_print(X->S, e, latex, bg_eqsym_name, (void *)X->s, &b);
  char *r = b.len > SYM_MAX_CHARS ? NULL : bg_arena_strdup(&X->l->arena, bg_sb_str(&b));
  bg_sb_free(&b);
  return r;
}

static char **print_all(symctx *X, const int *E, int count, int latex, int *too_long) {
  char **out = bg_arena_alloc(&X->l->arena, (size_t)(count + 1) * sizeof *out);
  for (int k = 0; k < count; k++)
    if (!(out[k] = print(X, E[k], latex))) *too_long = 1, out[k] = "";
  return out;
}

/* 0, or -1 when a printed entry or coefficient is too long. */
static int store(symctx *X, const int *c, const int *num) {
  bg_lin_symbolic *y = &X->l->sym;
  int n = X->n, np = X->ny * X->nu, too_long = 0;
  for (int latex = 0; latex < 2; latex++) {
    y->A[latex] = print_all(X, X->A, n * n, latex, &too_long);
    y->B[latex] = print_all(X, X->B, n * X->nu, latex, &too_long);
    y->C[latex] = print_all(X, X->C, X->ny * n, latex, &too_long);
    y->D[latex] = print_all(X, X->D, X->ny * X->nu, latex, &too_long);
    y->den[latex] = print_all(X, c, n + 1, latex, &too_long);
    y->num[latex] = print_all(X, num, np * (n + 1), latex, &too_long);
  }
  if (too_long) {
    memset(y->A, 0, sizeof y->A), memset(y->B, 0, sizeof y->B), memset(y->C, 0, sizeof y->C);
    memset(y->D, 0, sizeof y->D), memset(y->den, 0, sizeof y->den), memset(y->num, 0, sizeof y->num);
    return -1;
  }
  y->ok = 1, y->n = n;
  return 0;
}

/* sum_k c[k] s^(deg - k) with the coefficients evaluated at the params;
 * *scale gets sum |c_k| |s|^(deg - k), the size of its rounding. */
static double complex poly_at(symctx *X, const int *c, int deg, double complex s, double *scale) {
  bg_symenv env = {X->l->t, X->l->y0, NULL, NULL, NULL};
  double complex v = 0;
  *scale = 0;
  for (int k = 0; k <= deg; k++) {
    double ck = bg_sym_eval(X->S, c[k], &env);
    v = v * s + ck;
    *scale = *scale * cabs(s) + fabs(ck);
  }
  return v;
}

/* The symbolic polynomials against the numeric state space at one complex
 * point s0 off the axes: den(s0) = det(s0 I - A) and num(s0) = den(s0) H(s0)
 * (a wrong formula is worse than none). */
static int tfs_match(symctx *X, const int *c, const int *num) {
  bg_linear *l = X->l;
  int n = X->n;
  double rho = 1, sc;
  for (int i = 0; i < l->npole; i++) rho = fmax(rho, hypot(l->pole_re[i], l->pole_im[i]));
  double complex s0 = rho * (0.7548776662 + 1.1892071150 * I), d = poly_at(X, c, n, s0, &sc);
  double complex det = 1; /* det(s0 I - A) = prod of the eigenvalue differences */
  for (int i = 0; i < l->npole; i++) det *= s0 - (l->pole_re[i] + I * l->pole_im[i]);
  if (l->npole != n || !(cabs(d - det) <= 1e-8 * sc)) return 0;
  for (int p = 0; p < X->ny * X->nu; p++) {
    double complex h = bg_lin_eval(l, p / X->nu, p % X->nu, s0), v = poly_at(X, num + (size_t)p * (n + 1), n, s0, &sc);
    if (!(cabs(v - d * h) <= 1e-8 * (sc + cabs(d * h)))) return 0;
  }
  return 1;
}

static const char *transfer(symctx *X) {
  int n = X->n, np = X->ny * X->nu, *c = bg_xcalloc((size_t)n + 2, sizeof *c);
  int *num = bg_xcalloc((size_t)np * (n + 1) + 1, sizeof *num);
  const char *why = NULL;
  if (bg_lin_sym_tfs(X->S, n, X->nu, X->ny, X->A, X->B, X->C, X->D, SYM_MAX_TERMS, c, num))
    why = "the symbolic transfer functions are too large (a coefficient of more than 400 "
          "terms): numeric only";
  else {
    for (int k = 0; k <= n; k++) c[k] = simplify(X->S, c[k]);
    for (int k = 0; k < np * (n + 1); k++) num[k] = simplify(X->S, num[k]);
    if (!tfs_match(X, c, num))
      why = "the symbolic transfer functions do not match the numeric ones at a test point: "
            "numeric only";
    else if (store(X, c, num))
      why = "the symbolic form is too long to print (an entry or coefficient of more than "
            "4000 characters): numeric only";
  }
  free(c), free(num);
  return why;
}

static const char *derive(symctx *X) {
  const bg_model *m = X->m;
  bg_linear *l = X->l;
  for (int j = 0; j < X->nu; j++) {
    int k = 0;
    while (k < m->nelem && strcmp(m->elem_name[k], l->uname[j])) k++;
    if (k == m->nelem) return "an input is an `input`, not a source: symbolic form for sources only";
    X->own[j] = own_signal(m, k);
  }
  unsigned char *keep = bg_xcalloc((size_t)2 * m->nbond + 1, 1);
  for (int j = 0; j < X->nu; j++) keep[X->own[j]] = 1;
  bg_eqred *r = bg_eqred_build_keep(X->s, keep);
  free(keep);
  X->S = bg_eqred_sym(r);
  const char *why = NULL;
  if (!bg_eqred_is_ode(r) || state_rows(X, r) || output_rows(X, r))
    why = "the equations do not reduce symbolically to the state space";
  else if (!entries_ok(X, X->A, l->A, X->n * X->n) || !entries_ok(X, X->B, l->B, X->n * X->nu) ||
           !entries_ok(X, X->C, l->C, X->ny * X->n) || !entries_ok(X, X->D, l->D, X->ny * X->nu))
    why = "the symbolic form does not match the numeric linearisation (a modulated source, "
          "or a model that is not linear time-invariant): numeric only";
  else {
    int *mats[] = {X->A, X->B, X->C, X->D};
    const int counts[] = {X->n * X->n, X->n * X->nu, X->ny * X->n, X->ny * X->nu};
    for (int q = 0; q < 4; q++)
      for (int k = 0; k < counts[q]; k++) mats[q][k] = simplify(X->S, mats[q][k]);
    why = transfer(X);
  }
  bg_eqred_free(r);
  return why;
}

void bg_lin_sym_derive(bg_linear *l, const bg_model *m, bg_eqsys *s) {
  const char *why = NULL;
  if (!l->reduced) why = "no state space";
  else if (l->n > SYM_MAX_STATES) why = "more than 8 states: numeric only";
  if (why) {
    l->sym.note = why;
    return;
  }
  symctx X = {l, m, s, NULL, l->n, l->nu, l->ny, NULL, NULL, NULL, NULL, NULL};
  size_t n = (size_t)l->n;
  X.A = bg_xcalloc(n * n + 1, sizeof(int)), X.B = bg_xcalloc(n * l->nu + 1, sizeof(int));
  X.C = bg_xcalloc((size_t)l->ny * n + 1, sizeof(int)), X.D = bg_xcalloc((size_t)l->ny * l->nu + 1, sizeof(int));
  X.own = bg_xcalloc((size_t)l->nu + 1, sizeof(int));
  l->sym.note = derive(&X);
  free(X.A), free(X.B), free(X.C), free(X.D), free(X.own);
}
