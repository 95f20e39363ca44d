/* The state space and transfer functions of a linear model in its params
 * (docs/linear.md#symbolic): the reduced form (src/equations/eqreduce.c)
 * with the sources' own variables kept as leaves, A = d x'/d x and
 * B = d x'/d u by symbolic differentiation, C and D from the outputs in the
 * reduced states; accepted only when no entry reads a state, an input or t
 * (a linear time-invariant model) and every entry evaluates to the numeric
 * matrices. Transfer functions by Faddeev-LeVerrier: det(sI - A) =
 * s^n + c1 s^(n-1) + ... + cn and adj(sI - A) = sum M_k s^(n-k), so the
 * numerator of pair (i, j) has the coefficients C M_k B + D c_k. Up to 4
 * states; full order (no cancellations, unlike the numeric ones). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsym.h"
#include "linear/linear_int.h"

enum { SYM_MAX_STATES = 4, SYM_MAX_SIZE = 400 };

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
    int h = X->l->outputs_are_states ? -1 : bg_eqred_reduce_expr(r, X->m->output_expr[i]);
    if (!X->l->outputs_are_states && h < 0) return -1;
    for (int j = 0; j < n; j++)
      X->C[(size_t)j * ny + i] = h < 0 ? bg_sym_num(X->S, X->l->state[j] == i)
                                       : bg_sym_diff(X->S, h, bg_sym_leaf(X->S, SYM_Y, X->l->state[j]));
    for (int j = 0; j < X->nu; j++)
      X->D[(size_t)j * ny + i] = h < 0 ? bg_sym_num(X->S, 0)
                                       : bg_sym_diff(X->S, h, bg_sym_leaf(X->S, SYM_SIG, X->own[j]));
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

/* M (n x n) = A P + c I, all symbolic. */
static void fl_step(symctx *X, const int *P, int c, int *M) {
  int n = X->n;
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) {
      int e = i == j ? c : bg_sym_num(X->S, 0);
      for (int q = 0; q < n; q++)
        e = bg_sym_add(X->S, e, bg_sym_mul(X->S, X->A[(size_t)q * n + i], P[(size_t)j * n + q]));
      M[(size_t)j * n + i] = simplify(X->S, e);
    }
}

static int trace_AM(symctx *X, const int *M) {
  int n = X->n, e = bg_sym_num(X->S, 0);
  for (int i = 0; i < n; i++)
    for (int q = 0; q < n; q++)
      e = bg_sym_add(X->S, e, bg_sym_mul(X->S, X->A[(size_t)q * n + i], M[(size_t)i * n + q]));
  return e;
}

/* c[0..n] (c0 = 1) and num[(iy * nu + iu) * (n + 1) + k]. */
static void faddeev(symctx *X, int *c, int *num) {
  int n = X->n, nu = X->nu, ny = X->ny;
  int *P = bg_xcalloc((size_t)n * n + 1, sizeof *P), *M = bg_xcalloc((size_t)n * n + 1, sizeof *M);
  for (int q = 0; q < n * n; q++) P[q] = bg_sym_num(X->S, 0);
  c[0] = bg_sym_num(X->S, 1);
  for (int p = 0; p < ny * nu; p++) num[p * (n + 1)] = X->D[(size_t)(p % nu) * ny + p / nu];
  for (int k = 1; k <= n; k++) {
    fl_step(X, P, c[k - 1], M);
    c[k] = simplify(X->S, bg_sym_scale(X->S, -1.0 / k, trace_AM(X, M)));
    for (int p = 0; p < ny * nu; p++) {
      int iy = p / nu, iu = p % nu, e = bg_sym_mul(X->S, X->D[(size_t)iu * ny + iy], c[k]);
      for (int i = 0; i < n; i++)
        for (int q = 0; q < n; q++)
          e = bg_sym_add(X->S, e, bg_sym_mul(X->S, X->C[(size_t)i * ny + iy],
                                               bg_sym_mul(X->S, M[(size_t)q * n + i], X->B[(size_t)iu * n + q])));
      num[p * (n + 1) + k] = simplify(X->S, e);
    }
    memcpy(P, M, (size_t)n * n * sizeof *P);
  }
  free(P), free(M);
}

static char *print(symctx *X, int e, int latex) {
  bg_strbuf b = {0};
  bg_sym_print(X->S, e, latex, bg_eqsym_name, (void *)X->s, &b);
  char *r = bg_arena_strdup(&X->l->arena, bg_sb_str(&b));
  bg_sb_free(&b);
  return r;
}

static char **print_all(symctx *X, const int *E, int count, int latex) {
  char **out = bg_arena_alloc(&X->l->arena, (size_t)(count + 1) * sizeof *out);
  for (int k = 0; k < count; k++) out[k] = print(X, E[k], latex);
  return out;
}

static void store(symctx *X, const int *c, const int *num) {
  bg_lin_symbolic *y = &X->l->sym;
  int n = X->n, np = X->ny * X->nu;
  for (int latex = 0; latex < 2; latex++) {
    y->A[latex] = print_all(X, X->A, n * n, latex), y->B[latex] = print_all(X, X->B, n * X->nu, latex);
    y->C[latex] = print_all(X, X->C, X->ny * n, latex), y->D[latex] = print_all(X, X->D, X->ny * X->nu, latex);
    y->den[latex] = print_all(X, c, n + 1, latex), y->num[latex] = print_all(X, num, np * (n + 1), latex);
  }
  y->ok = 1, y->n = n;
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
    int np = X->ny * X->nu, *c = bg_xcalloc((size_t)X->n + 2, sizeof *c);
    int *num = bg_xcalloc((size_t)np * (X->n + 1) + 1, sizeof *num);
    faddeev(X, c, num);
    store(X, c, num);
    free(c), free(num);
  }
  bg_eqred_free(r);
  return why;
}

void bg_lin_sym_derive(bg_linear *l, const bg_model *m, bg_eqsys *s) {
  const char *why = NULL;
  if (!l->reduced) why = "no state space";
  else if (l->n > SYM_MAX_STATES) why = "more than 4 states: numeric only";
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
