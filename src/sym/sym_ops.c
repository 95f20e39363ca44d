/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_sym operations: substitution, differentiation, expansion, common
 * denominators, dependency tests and evaluation (sym.h). Each walk keeps
 * its own memo (a small hash map from node id to result), so shared
 * subexpressions are visited once and walks may nest. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "sym/sym.h"

/* ------------------------------------------------------------ memo */
typedef struct memo { int *key; double *val; int n, cap; } memo;

static int memo_find(const memo *M, int key, double *val) {
  if (!M->cap) return 0;
  unsigned p = ((unsigned)key * 2654435761u) & (unsigned)(M->cap - 1);
  for (; M->key[p] >= 0; p = (p + 1) & (unsigned)(M->cap - 1))
    if (M->key[p] == key) return *val = M->val[p], 1;
  return 0;
}

static void memo_put(memo *M, int key, double val) {
  if (2 * (M->n + 1) > M->cap) {
    memo old = *M;
    M->cap = M->cap ? 2 * M->cap : 64, M->n = 0;
    M->key = bg_xmalloc((size_t)M->cap * sizeof *M->key);
    M->val = bg_xmalloc((size_t)M->cap * sizeof *M->val);
    for (int i = 0; i < M->cap; i++) M->key[i] = -1;
    for (int i = 0; i < old.cap; i++)
      if (old.key[i] >= 0) memo_put(M, old.key[i], old.val[i]);
    free(old.key), free(old.val);
  }
  unsigned p = ((unsigned)key * 2654435761u) & (unsigned)(M->cap - 1);
  while (M->key[p] >= 0 && M->key[p] != key) p = (p + 1) & (unsigned)(M->cap - 1);
  if (M->key[p] < 0) M->n++;
  M->key[p] = key, M->val[p] = val;
}

static void memo_free(memo *M) { free(M->key), free(M->val); }

/* Arguments and weights of a node, copied (the store may grow meanwhile). */
typedef struct nargs { int t[8]; double w[8]; int *tp; double *wp; int n; } nargs;
static void args_get(const bg_sym *S, int a, nargs *A) {
  const bg_symnode *x = &S->node[a];
  A->n = x->n;
  A->tp = x->n <= 8 ? A->t : bg_xmalloc((size_t)x->n * sizeof(int));
  A->wp = x->n <= 8 ? A->w : bg_xmalloc((size_t)x->n * sizeof(double));
  memcpy(A->tp, S->arg + x->adr, (size_t)x->n * sizeof(int));
  memcpy(A->wp, S->w + x->adr, (size_t)x->n * sizeof(double));
}
static void args_free(nargs *A) {
  if (A->tp != A->t) free(A->tp), free(A->wp);
}

/* Rebuilds node a (fields nd) with new arguments. */
static int rebuild(bg_sym *S, const bg_symnode *nd, const int *t, const double *w) {
  switch (nd->kind) {
  case SYM_ADD: return bg_sym_sum(S, nd->c, nd->n, t, w);
  case SYM_MUL: return bg_sym_prod(S, nd->c, nd->n, t, w);
  case SYM_POW: return bg_sym_pow(S, t[0], t[1]);
  case SYM_CALL: return bg_sym_call(S, nd->ref, nd->n, t);
  case SYM_TABLE: return bg_sym_table(S, nd->ref, t[0]);
  case SYM_DTABLE: return bg_sym_dtable(S, nd->ref, t[0]);
  default: return bg_sym_op(S, nd->ref, t[0], nd->n > 1 ? t[1] : t[0]);
  }
}

/* ------------------------------------------------------------ substitution */
static int subst_rec(bg_sym *S, int a, bg_sym_substfn f, void *ctx, memo *M) {
  bg_symnode nd = S->node[a];
  double got;
  if (S->over) return a;
  bg_sym_spend(S, 1);
  if (nd.kind == SYM_NUM) return a;
  if (nd.n == 0) {
    int r = f(ctx, nd.kind, nd.ref);
    return r >= 0 ? r : a;
  }
  if (memo_find(M, a, &got)) return (int)got;
  nargs A;
  args_get(S, a, &A);
  int changed = 0;
  for (int k = 0; k < A.n; k++) {
    int r = subst_rec(S, A.tp[k], f, ctx, M);
    changed |= r != A.tp[k];
    A.tp[k] = r;
  }
  int r = changed ? rebuild(S, &nd, A.tp, A.wp) : a;
  args_free(&A);
  memo_put(M, a, r);
  return r;
}

int bg_sym_subst(bg_sym *S, int a, bg_sym_substfn f, void *ctx) {
  memo M = {0};
  int r = subst_rec(S, a, f, ctx, &M);
  memo_free(&M);
  return r;
}

/* ------------------------------------------------------------ differentiation */
static int call1(bg_sym *S, int fn, int x) { return bg_sym_call(S, fn, 1, &x); }
static int ifelse(bg_sym *S, int c, int p, int q) {
  int a[3] = {c, p, q};
  return bg_sym_call(S, BG_FN_IF, 3, a);
}
static int prod3(bg_sym *S, double c, int a, double ea, int b, double eb, int d, double ed) {
  int t[3] = {a, b, d};
  double e[3] = {ea, eb, ed};
  return bg_sym_prod(S, c, 3, t, e);
}

static int diff_rec(bg_sym *S, int a, int x, memo *M);

/* d f(args)/dx for a function call a = f(u, v, w). */
static int diff_call(bg_sym *S, int a, const int *u, int n, int x, memo *M) {
  int fn = S->node[a].ref, zero = bg_sym_num(S, 0);
  int d0 = n > 0 ? diff_rec(S, u[0], x, M) : zero, d1 = n > 1 ? diff_rec(S, u[1], x, M) : zero;
  int d2 = n > 2 ? diff_rec(S, u[2], x, M) : zero;
  int one = bg_sym_num(S, 1);
  switch (fn) {
  case BG_FN_ABS: return bg_sym_mul(S, call1(S, BG_FN_SIGN, u[0]), d0);
  case BG_FN_SQRT: return prod3(S, 0.5, d0, 1, a, -1, one, 1);
  case BG_FN_EXP: return bg_sym_mul(S, a, d0);
  case BG_FN_LOG: return bg_sym_div(S, d0, u[0]);
  case BG_FN_LOG10: return prod3(S, 1 / log(10.0), d0, 1, u[0], -1, one, 1);
  case BG_FN_SIN: return bg_sym_mul(S, call1(S, BG_FN_COS, u[0]), d0);
  case BG_FN_COS: return bg_sym_neg(S, bg_sym_mul(S, call1(S, BG_FN_SIN, u[0]), d0));
  case BG_FN_TAN: return bg_sym_mul(S, bg_sym_add(S, one, bg_sym_powc(S, a, 2)), d0);
  case BG_FN_ASIN: case BG_FN_ACOS: {
    int r = prod3(S, fn == BG_FN_ASIN ? 1 : -1, d0, 1, bg_sym_sub(S, one, bg_sym_powc(S, u[0], 2)), -0.5, one, 1);
    return r;
  }
  case BG_FN_ATAN: return prod3(S, 1, d0, 1, bg_sym_add(S, one, bg_sym_powc(S, u[0], 2)), -1, one, 1);
  case BG_FN_ATAN2: {
    int num = bg_sym_sub(S, bg_sym_mul(S, u[1], d0), bg_sym_mul(S, u[0], d1));
    int den = bg_sym_add(S, bg_sym_powc(S, u[0], 2), bg_sym_powc(S, u[1], 2));
    return bg_sym_div(S, num, den);
  }
  case BG_FN_SINH: return bg_sym_mul(S, call1(S, BG_FN_COSH, u[0]), d0);
  case BG_FN_COSH: return bg_sym_mul(S, call1(S, BG_FN_SINH, u[0]), d0);
  case BG_FN_TANH: return bg_sym_mul(S, bg_sym_sub(S, one, bg_sym_powc(S, a, 2)), d0);
  case BG_FN_MIN: return ifelse(S, bg_sym_op(S, BG_X_LE, u[0], u[1]), d0, d1);
  case BG_FN_MAX: return ifelse(S, bg_sym_op(S, BG_X_GE, u[0], u[1]), d0, d1);
  case BG_FN_IF: return ifelse(S, u[0], d1, d2);
  case BG_FN_RAMP: return bg_sym_mul(S, call1(S, BG_FN_STEP, u[0]), d0);
  case BG_FN_SAT:
    return ifelse(S, bg_sym_op(S, BG_X_LT, u[0], u[1]), d1,
                  ifelse(S, bg_sym_op(S, BG_X_GT, u[0], u[2]), d2, d0));
  default: return zero; /* sign, floor, ceil, step, pulse, hyst, stick: piecewise constant */
  }
}

static int diff_node(bg_sym *S, int a, int x, memo *M) {
  bg_symnode nd = S->node[a];
  int zero = bg_sym_num(S, 0);
  nargs A;
  args_get(S, a, &A);
  int r = zero;
  if (nd.kind == SYM_ADD) {
    for (int k = 0; k < A.n; k++) A.tp[k] = diff_rec(S, A.tp[k], x, M);
    r = bg_sym_sum(S, 0, A.n, A.tp, A.wp);
  } else if (nd.kind == SYM_MUL) {
    int *t = bg_xmalloc((size_t)A.n * sizeof *t), nt = 0;
    for (int k = 0; k < A.n; k++) {
      int d = diff_rec(S, A.tp[k], x, M);
      if (d != zero) t[nt++] = prod3(S, A.wp[k], a, 1, A.tp[k], -1, d, 1);
    }
    r = bg_sym_sum(S, 0, nt, t, NULL);
    free(t);
  } else if (nd.kind == SYM_POW) {
    int du = diff_rec(S, A.tp[0], x, M), dv = diff_rec(S, A.tp[1], x, M);
    int inner = bg_sym_add(S, bg_sym_mul(S, dv, call1(S, BG_FN_LOG, A.tp[0])),
                           prod3(S, 1, A.tp[1], 1, du, 1, A.tp[0], -1));
    r = bg_sym_mul(S, a, inner);
  } else if (nd.kind == SYM_CALL) {
    r = diff_call(S, a, A.tp, A.n, x, M);
  } else if (nd.kind == SYM_TABLE) {
    r = bg_sym_mul(S, bg_sym_dtable(S, nd.ref, A.tp[0]), diff_rec(S, A.tp[0], x, M));
  }
  args_free(&A);
  return r;
}

/* d alias / d x: 0, or the leaf of the partial derivative (made once). */
static int dalias(bg_sym *S, int alias, int x) {
  int d = bg_sym_diff(S, S->alias_expr[alias], x);
  if (S->node[d].kind == SYM_NUM) return d;
  for (int k = 0; k < S->ndalias; k++)
    if (S->dalias_of[k] == alias && S->dalias_var[k] == x) return bg_sym_leaf(S, SYM_DALIAS, k);
  int k = S->ndalias++;
  S->dalias_of = bg_xrealloc(S->dalias_of, (size_t)S->ndalias * sizeof(int));
  S->dalias_var = bg_xrealloc(S->dalias_var, (size_t)S->ndalias * sizeof(int));
  S->dalias_expr = bg_xrealloc(S->dalias_expr, (size_t)S->ndalias * sizeof(int));
  S->dalias_of[k] = alias, S->dalias_var[k] = x, S->dalias_expr[k] = d;
  return bg_sym_leaf(S, SYM_DALIAS, k);
}

static int diff_rec(bg_sym *S, int a, int x, memo *M) {
  if (S->over) return bg_sym_num(S, 0); /* dropped by the caller (bg_sym_full) */
  bg_sym_spend(S, 1);
  if (a == x) return bg_sym_num(S, 1);
  bg_symnode nd = S->node[a];
  double got;
  if (nd.n == 0) {
    if (nd.kind == SYM_INPUT && S->node[x].kind == SYM_T) {
      int e = bg_sym_from_x(S, S->m->input_expr[nd.ref], NULL, NULL);
      return diff_rec(S, e, x, M);
    }
    if (nd.kind == SYM_ALIAS) return dalias(S, nd.ref, x);
    if (nd.kind == SYM_DALIAS) return bg_sym_diff(S, S->dalias_expr[nd.ref], x);
    return bg_sym_num(S, 0);
  }
  if (memo_find(M, a, &got)) return (int)got;
  int r = diff_node(S, a, x, M);
  memo_put(M, a, r);
  return r;
}

int bg_sym_diff(bg_sym *S, int a, int x) {
  memo M = {0};
  int r = diff_rec(S, a, x, &M);
  memo_free(&M);
  return r;
}

/* ------------------------------------------------------------ expansion */
/* Terms of a as (term, weight): a sum's constant is the term 1. */
static int terms_of(bg_sym *S, int a, int **t, double **w) {
  const bg_symnode *x = &S->node[a];
  if (x->kind != SYM_ADD) {
    *t = bg_xmalloc(sizeof **t), *w = bg_xmalloc(sizeof **w);
    (*t)[0] = a, (*w)[0] = 1;
    return 1;
  }
  int n = x->n, adr = x->adr, k = 0;
  double c = x->c;
  *t = bg_xmalloc((size_t)(n + 1) * sizeof **t), *w = bg_xmalloc((size_t)(n + 1) * sizeof **w);
  if (c != 0) (*t)[k] = bg_sym_num(S, 1), (*w)[k++] = c;
  for (int q = 0; q < n; q++) (*t)[k] = S->arg[adr + q], (*w)[k++] = S->w[adr + q];
  return k;
}

/* The product of two expanded sums, term by term; -1 above max terms. */
static int mul_out(bg_sym *S, int a, int b, int max) {
  int *ta, *tb;
  double *wa, *wb;
  int na = terms_of(S, a, &ta, &wa), nb = terms_of(S, b, &tb, &wb), r = -1;
  if ((long)na * nb <= max && !S->over) {
    int *t = bg_xmalloc((size_t)na * nb * sizeof *t);
    double *w = bg_xmalloc((size_t)na * nb * sizeof *w);
    for (int i = 0; i < na; i++)
      for (int j = 0; j < nb; j++) t[i * nb + j] = bg_sym_mul(S, ta[i], tb[j]), w[i * nb + j] = wa[i] * wb[j];
    r = bg_sym_sum(S, 0, na * nb, t, w);
    free(t), free(w);
  }
  free(ta), free(wa), free(tb), free(wb);
  return r;
}

static int expand_rec(bg_sym *S, int a, int max, memo *M) {
  bg_symnode nd = S->node[a];
  double got;
  if (nd.kind != SYM_ADD && nd.kind != SYM_MUL) return a;
  if (S->over) return a;
  bg_sym_spend(S, 1);
  if (memo_find(M, a, &got)) return (int)got;
  nargs A;
  args_get(S, a, &A);
  int r = a;
  if (nd.kind == SYM_ADD) {
    for (int k = 0; k < A.n; k++) A.tp[k] = expand_rec(S, A.tp[k], max, M);
    r = bg_sym_sum(S, nd.c, A.n, A.tp, A.wp);
  } else {
    int nrest = 0, acc;
    for (int k = 0; k < A.n; k++) /* factors that stay: all but sums to small powers */
      if (!(S->node[A.tp[k]].kind == SYM_ADD && A.wp[k] >= 1 && A.wp[k] <= 8 && A.wp[k] == floor(A.wp[k])))
        A.tp[nrest] = A.tp[k], A.wp[nrest++] = A.wp[k];
    acc = bg_sym_prod(S, nd.c, nrest, A.tp, A.wp);
    const bg_symnode *x = &S->node[a];
    for (int k = 0; k < x->n && acc >= 0; k++) {
      int b = S->arg[S->node[a].adr + k];
      double e = S->w[S->node[a].adr + k];
      if (!(S->node[b].kind == SYM_ADD && e >= 1 && e <= 8 && e == floor(e))) continue;
      int eb = expand_rec(S, b, max, M);
      for (int q = 0; q < (int)e && acc >= 0; q++) acc = mul_out(S, acc, eb, max);
      x = &S->node[a];
    }
    r = acc >= 0 ? acc : a;
  }
  args_free(&A);
  memo_put(M, a, r);
  return r;
}

int bg_sym_expand(bg_sym *S, int a, int max_terms) {
  memo M = {0};
  int r = expand_rec(S, a, max_terms, &M);
  memo_free(&M);
  return r;
}

/* ------------------------------------------------------------ common factors */
static double gcd_d(double a, double b) {
  while (b > 0.5) {
    double r = fmod(a, b);
    a = b, b = r;
  }
  return a;
}

/* N = g * N2 with g the monomial (and integer content) common to every term. */
static int content(bg_sym *S, int N) {
  if (S->node[N].kind != SYM_ADD || S->over) return N;
  int *t;
  double *w;
  int n = terms_of(S, N, &t, &w), nc = 0;
  int cb[16];
  double ce[16], g = 0;
  int allint = 1;
  for (int i = 0; i < n; i++) allint &= w[i] == floor(w[i]) && fabs(w[i]) < 1e9;
  for (int i = 0; i < n && allint; i++) g = gcd_d(fmax(g, fabs(w[i])), fmin(g, fabs(w[i])));
  if (!allint || g == 0) g = 1;
  const bg_symnode *x0 = &S->node[t[0]];
  if (x0->kind == SYM_MUL)
    for (int k = 0; k < x0->n && nc < 16; k++)
      if (S->w[x0->adr + k] > 0) cb[nc] = S->arg[x0->adr + k], ce[nc++] = S->w[x0->adr + k];
  if (x0->kind != SYM_MUL && x0->kind != SYM_NUM) cb[nc] = t[0], ce[nc++] = 1;
  for (int i = 1; i < n && nc; i++) { /* intersect, smallest exponents */
    const bg_symnode *x = &S->node[t[i]];
    for (int c = 0; c < nc; c++) {
      double e = 0;
      if (x->kind == SYM_MUL) {
        for (int k = 0; k < x->n; k++)
          if (S->arg[x->adr + k] == cb[c] && S->w[x->adr + k] > 0) e = S->w[x->adr + k];
      } else if (t[i] == cb[c]) e = 1;
      ce[c] = fmin(ce[c], e);
    }
  }
  int m = 0;
  for (int c = 0; c < nc; c++)
    if (ce[c] > 0) cb[m] = cb[c], ce[m++] = ce[c];
  int r = N;
  if (m > 0 || g != 1) {
    int G = bg_sym_prod(S, g, m, cb, ce);
    for (int i = 0; i < n; i++) t[i] = bg_sym_div(S, t[i], G);
    r = bg_sym_mul(S, G, bg_sym_sum(S, 0, n, t, w));
  }
  free(t), free(w);
  return r;
}

/* ------------------------------------------------------------ exact division */
static int is_num0(const bg_sym *S, int a) { return S->node[a].kind == SYM_NUM && S->node[a].c == 0; }

/* Substitutes leaf x by r. */
typedef struct xsub { bg_sym *S; int x, r; } xsub;
static int leaf_cb(void *ctx, int kind, int ref) {
  xsub *X = ctx;
  const bg_symnode *n = &X->S->node[X->x];
  return n->kind == kind && n->ref == ref ? X->r : -1;
}

/* N / d when the sum d is linear in some leaf x (d = a x + b) and N
 * vanishes at x = -b/a: synthetic division of N as a polynomial in x (at
 * most degree 8). Returns the quotient, or -1. */
static int div_linear(bg_sym *S, int N, int d) {
  const bg_symnode *dn = &S->node[d];
  if (dn->kind != SYM_ADD || S->over || bg_sym_size(S, N) > 400) return -1;
  for (int k = 0; k < S->node[d].n; k++) {
    int term = S->arg[S->node[d].adr + k], x = -1;
    if (S->node[term].n == 0 && S->node[term].kind != SYM_NUM) x = term;
    else if (S->node[term].kind == SYM_MUL)
      for (int q = 0; q < S->node[term].n; q++)
        if (S->w[S->node[term].adr + q] == 1 && S->node[S->arg[S->node[term].adr + q]].n == 0)
          x = S->arg[S->node[term].adr + q];
    if (x < 0) continue;
    int a = bg_sym_diff(S, d, x);
    if (is_num0(S, a) || !is_num0(S, bg_sym_diff(S, a, x))) continue;
    xsub X = {S, x, bg_sym_num(S, 0)};
    int b = bg_sym_subst(S, d, leaf_cb, &X);
    X.r = bg_sym_rational(S, bg_sym_neg(S, bg_sym_div(S, b, a)));
    int c[10], deg = -1, Nj = N;
    double fact = 1;
    for (int j = 0; j < 10 && !is_num0(S, Nj); j++) {
      if (j == 9) return -1;
      if (j) fact *= j;
      xsub Z = {S, x, bg_sym_num(S, 0)};
      c[j] = bg_sym_scale(S, 1 / fact, bg_sym_subst(S, Nj, leaf_cb, &Z));
      deg = j;
      Nj = bg_sym_diff(S, Nj, x);
    }
    if (deg < 1) continue;
    if (!is_num0(S, bg_sym_rational(S, bg_sym_subst(S, N, leaf_cb, &X)))) continue;
    int q[10], t[10];
    q[deg - 1] = c[deg];
    for (int j = deg - 1; j >= 1; j--) q[j - 1] = bg_sym_add(S, c[j], bg_sym_mul(S, X.r, q[j]));
    for (int j = 0; j < deg; j++) t[j] = bg_sym_mul(S, q[j], bg_sym_powc(S, x, j));
    int Q = bg_sym_div(S, bg_sym_sum(S, 0, deg, t, NULL), a);
    return bg_sym_expand(S, bg_sym_rational(S, Q), 4000);
  }
  return -1;
}

/* ------------------------------------------------------------ common denominator */
/* A product with its sum denominators made rational: (1 + m T^2/J)^-1
 * becomes J (J + m T^2)^-1. */
static int rational_dens(bg_sym *S, int t) {
  if (S->node[t].kind != SYM_MUL) return t;
  nargs A;
  args_get(S, t, &A);
  int ch = 0;
  double c = S->node[t].c;
  for (int k = 0; k < A.n; k++)
    if (A.wp[k] < 0 && S->node[A.tp[k]].kind == SYM_ADD) {
      int b = bg_sym_rational(S, A.tp[k]);
      ch |= b != A.tp[k], A.tp[k] = b;
    }
  int r = ch ? bg_sym_prod(S, c, A.n, A.tp, A.wp) : t;
  args_free(&A);
  return r;
}

/* Exponent of base b among the denominators of term t (0: none). */
static double den_exp(const bg_sym *S, int t, int b) {
  const bg_symnode *x = &S->node[t];
  if (x->kind != SYM_MUL) return 0;
  for (int k = 0; k < x->n; k++)
    if (S->arg[x->adr + k] == b && S->w[x->adr + k] < 0) return -S->w[x->adr + k];
  return 0;
}

/* Over one denominator. mode 2: every denominator (monomials too),
 * highest powers; 1: every sum denominator; 0: only the sum denominators
 * every term has (bond_loop's n - 1), lowest powers. The numerator is
 * expanded, its common factors and the sum denominators it is divisible by
 * are cancelled. */
static int over_one(bg_sym *S, int a, int mode) {
  int all = mode == 2;
  if (S->over) return a;
  if (S->node[a].kind == SYM_MUL && !all) return rational_dens(S, a);
  if (S->node[a].kind != SYM_ADD && (S->node[a].kind != SYM_MUL || !all)) return a;
  int *t;
  double *w;
  int n = terms_of(S, a, &t, &w), nd = 0, capd = 8;
  for (int i = 0; i < n; i++) t[i] = rational_dens(S, t[i]);
  int *db = bg_xmalloc((size_t)capd * sizeof *db);
  double *de = bg_xmalloc((size_t)capd * sizeof *de);
  for (int i = 0; i < n; i++) { /* candidate denominators */
    const bg_symnode *x = &S->node[t[i]];
    if (x->kind != SYM_MUL || (mode == 0 && i > 0)) continue;
    for (int k = 0; k < x->n; k++) {
      int b = S->arg[x->adr + k];
      double e = -S->w[x->adr + k];
      if (e <= 0 || (!all && S->node[b].kind != SYM_ADD)) continue;
      int j = 0;
      while (j < nd && db[j] != b) j++;
      if (j == nd) {
        if (nd == capd) capd *= 2, db = bg_xrealloc(db, (size_t)capd * sizeof *db), de = bg_xrealloc(de, (size_t)capd * sizeof *de);
        db[nd] = b, de[nd++] = e;
      } else if (e > de[j]) de[j] = e;
    }
  }
  if (mode == 0) { /* only what every term has */
    int m = 0;
    for (int j = 0; j < nd; j++) {
      double e = de[j];
      for (int i = 1; i < n; i++) e = fmin(e, den_exp(S, t[i], db[j]));
      if (e > 0) db[m] = db[j], de[m++] = e;
    }
    nd = m;
  }
  int r = a;
  if (nd > 0) {
    int D = bg_sym_prod(S, 1, nd, db, de);
    for (int i = 0; i < n; i++) t[i] = bg_sym_mul(S, t[i], D);
    int N = content(S, bg_sym_expand(S, bg_sym_sum(S, 0, n, t, w), 4000));
    for (int j = 0; j < nd; j++) /* cancel sum factors of the denominator */
      while (de[j] > 0 && S->node[db[j]].kind == SYM_ADD) {
        int q = div_linear(S, bg_sym_expand(S, N, 4000), db[j]);
        if (q < 0) break;
        N = content(S, q), de[j] -= 1;
      }
    for (int j = 0; j < nd; j++) de[j] = -de[j];
    int *fb = bg_xmalloc((size_t)(nd + 1) * sizeof *fb);
    double *fe = bg_xmalloc((size_t)(nd + 1) * sizeof *fe);
    fb[0] = N, fe[0] = 1;
    memcpy(fb + 1, db, (size_t)nd * sizeof *fb), memcpy(fe + 1, de, (size_t)nd * sizeof *fe);
    r = bg_sym_prod(S, 1, nd + 1, fb, fe);
    free(fb), free(fe);
  } else {
    r = bg_sym_sum(S, 0, n, t, w);
  }
  free(t), free(w), free(db), free(de);
  return r;
}

int bg_sym_together(bg_sym *S, int a, int every) { return over_one(S, a, every ? 1 : 0); }

/* A product with a sum among its denominators. */
static int has_sum_den(const bg_sym *S, int a) {
  const bg_symnode *x = &S->node[a];
  if (x->kind != SYM_MUL) return 0;
  for (int k = 0; k < x->n; k++)
    if (S->w[x->adr + k] < 0 && S->node[S->arg[x->adr + k]].kind == SYM_ADD) return 1;
  return 0;
}

static int rational_rec(bg_sym *S, int a, memo *M) {
  bg_symnode nd = S->node[a];
  double got;
  if (nd.n == 0 || nd.kind == SYM_NUM || S->over) return a;
  bg_sym_spend(S, 1);
  if (memo_find(M, a, &got)) return (int)got;
  nargs A;
  args_get(S, a, &A);
  int ch = 0;
  for (int k = 0; k < A.n; k++) {
    int r = rational_rec(S, A.tp[k], M);
    ch |= r != A.tp[k], A.tp[k] = r;
  }
  int r = ch ? rebuild(S, &nd, A.tp, A.wp) : a;
  args_free(&A);
  if (S->node[r].kind == SYM_ADD || has_sum_den(S, r)) r = over_one(S, r, 2);
  memo_put(M, a, r);
  return r;
}

int bg_sym_rational(bg_sym *S, int a) {
  memo M = {0};
  int r = rational_rec(S, a, &M);
  memo_free(&M);
  return r;
}

/* ------------------------------------------------------------ collecting */
static int params_only(bg_sym *S, int a, memo *M) {
  const bg_symnode *x = &S->node[a];
  double got;
  bg_sym_spend(S, 1);
  if (x->kind == SYM_NUM || x->kind == SYM_PARAM) return 1;
  if (x->n == 0) return 0;
  if (memo_find(M, a, &got)) return (int)got;
  int r = 1;
  for (int k = 0; k < x->n && r; k++) r = params_only(S, S->arg[S->node[a].adr + k], M);
  memo_put(M, a, r);
  return r;
}

int bg_sym_collect(bg_sym *S, int a) {
  if (S->node[a].kind != SYM_ADD || S->over) return a;
  int *t;
  double *w;
  int n = terms_of(S, a, &t, &w), ng = 0;
  int *gv = bg_xmalloc((size_t)n * sizeof *gv), *cnt = bg_xcalloc((size_t)n, sizeof *cnt);
  int *cf = bg_xmalloc((size_t)n * sizeof *cf), *grp = bg_xmalloc((size_t)n * sizeof *grp);
  memo P = {0};
  for (int i = 0; i < n; i++) { /* term = coefficient (params) * variable part */
    int var = t[i], co = bg_sym_num(S, 1);
    if (params_only(S, t[i], &P)) var = bg_sym_num(S, 1), co = t[i];
    else if (S->node[t[i]].kind == SYM_MUL) {
      nargs A;
      args_get(S, t[i], &A);
      double c = S->node[t[i]].c;
      int nv = 0, nc = 0, *vb = bg_xmalloc((size_t)A.n * sizeof *vb), *cb = bg_xmalloc((size_t)A.n * sizeof *cb);
      double *ve = bg_xmalloc((size_t)A.n * sizeof *ve), *ce = bg_xmalloc((size_t)A.n * sizeof *ce);
      for (int k = 0; k < A.n; k++) {
        if (params_only(S, A.tp[k], &P)) cb[nc] = A.tp[k], ce[nc++] = A.wp[k];
        else vb[nv] = A.tp[k], ve[nv++] = A.wp[k];
      }
      var = bg_sym_prod(S, 1, nv, vb, ve), co = bg_sym_prod(S, c, nc, cb, ce);
      free(vb), free(cb), free(ve), free(ce);
      args_free(&A);
    }
    int g = 0;
    while (g < ng && gv[g] != var) g++;
    if (g == ng) gv[ng++] = var;
    grp[i] = g, cf[i] = co;
  }
  memo_free(&P);
  int *ct = bg_xmalloc((size_t)n * sizeof *ct), *out = bg_xmalloc((size_t)(ng + 1) * sizeof *out);
  double *cw = bg_xmalloc((size_t)n * sizeof *cw);
  for (int g = 0; g < ng; g++) {
    int k = 0;
    for (int i = 0; i < n; i++)
      if (grp[i] == g) ct[k] = cf[i], cw[k++] = w[i];
    out[g] = bg_sym_mul(S, bg_sym_rational(S, bg_sym_sum(S, 0, k, ct, cw)), gv[g]);
  }
  int r = bg_sym_sum(S, 0, ng, out, NULL);
  free(t), free(w), free(gv), free(cnt), free(cf), free(grp), free(ct), free(out), free(cw);
  return r;
}

/* ------------------------------------------------------------ dependencies */
static int dep_rec(bg_sym *S, int a, const unsigned char *mark, int nmark, int piecewise, memo *M);

static int is_piecewise(const bg_symnode *x) {
  if (x->kind == SYM_OP || x->kind == SYM_TABLE || x->kind == SYM_DTABLE) return 1;
  if (x->kind != SYM_CALL) return 0;
  switch (x->ref) {
  case BG_FN_SIGN: case BG_FN_FLOOR: case BG_FN_CEIL: case BG_FN_STEP: case BG_FN_PULSE:
  case BG_FN_IF: case BG_FN_MIN: case BG_FN_MAX: case BG_FN_ABS: case BG_FN_RAMP: case BG_FN_SAT:
  case BG_FN_HYST: case BG_FN_STICK:
    return 1;
  default: return 0;
  }
}

static int dep_rec(bg_sym *S, int a, const unsigned char *mark, int nmark, int piecewise, memo *M) {
  const bg_symnode *x = &S->node[a];
  double got;
  bg_sym_spend(S, 1);
  if (x->kind == SYM_ALIAS) return dep_rec(S, S->alias_expr[x->ref], mark, nmark, piecewise, M);
  if (x->kind == SYM_DALIAS) return dep_rec(S, S->dalias_expr[x->ref], mark, nmark, piecewise, M);
  if (x->n == 0) return !piecewise && a < nmark && mark[a];
  if (memo_find(M, a, &got)) return (int)got;
  int r = 0;
  if (piecewise && is_piecewise(x)) {
    memo M2 = {0};
    r = dep_rec(S, a, mark, nmark, 0, &M2);
    memo_free(&M2);
  }
  for (int k = 0; k < x->n && !r; k++) r = dep_rec(S, S->arg[x->adr + k], mark, nmark, piecewise, M);
  memo_put(M, a, r);
  return r;
}

int bg_sym_depends(bg_sym *S, int a, const unsigned char *mark, int nmark) {
  memo M = {0};
  int r = dep_rec(S, a, mark, nmark, 0, &M);
  memo_free(&M);
  return r;
}

int bg_sym_piecewise(bg_sym *S, int a, const unsigned char *mark, int nmark) {
  memo M = {0};
  int r = dep_rec(S, a, mark, nmark, 1, &M);
  memo_free(&M);
  return r;
}

static void leaves_rec(bg_sym *S, int a, const unsigned char *mark, int nmark, int *out, int max, int *cnt,
                       memo *M) {
  double got;
  const bg_symnode *x = &S->node[a];
  if (memo_find(M, a, &got)) return;
  memo_put(M, a, 1);
  bg_sym_spend(S, 1);
  if (x->kind == SYM_ALIAS || x->kind == SYM_DALIAS) {
    int e = x->kind == SYM_ALIAS ? S->alias_expr[x->ref] : S->dalias_expr[x->ref];
    leaves_rec(S, e, mark, nmark, out, max, cnt, M);
    return;
  }
  if (x->n == 0) {
    if (a < nmark && mark[a]) {
      if (*cnt < max) out[*cnt] = a;
      (*cnt)++;
    }
    return;
  }
  for (int k = 0; k < x->n; k++) leaves_rec(S, S->arg[S->node[a].adr + k], mark, nmark, out, max, cnt, M);
}

int bg_sym_leaves(bg_sym *S, int a, const unsigned char *mark, int nmark, int *out, int max) {
  memo M = {0};
  int cnt = 0;
  leaves_rec(S, a, mark, nmark, out, max, &cnt, &M);
  memo_free(&M);
  return cnt;
}

static int size_rec(bg_sym *S, int a, memo *M) {
  double got;
  if (memo_find(M, a, &got)) return 0;
  memo_put(M, a, 1);
  bg_sym_spend(S, 1);
  int r = 1;
  for (int k = 0; k < S->node[a].n; k++) r += size_rec(S, S->arg[S->node[a].adr + k], M);
  return r;
}

int bg_sym_size(bg_sym *S, int a) {
  memo M = {0};
  int r = size_rec(S, a, &M);
  memo_free(&M);
  return r;
}

/* ------------------------------------------------------------ evaluation */
static double powe(double b, double e) { return e == 1 ? b : e == 2 ? b * b : pow(b, e); }

static double eval_rec(bg_sym *S, int a, const bg_symenv *env, memo *M) {
  const bg_symnode *x = &S->node[a];
  const bg_model *m = S->m;
  double got;
  switch (x->kind) {
  case SYM_NUM: return x->c;
  case SYM_PARAM: return env->param ? env->param[x->ref] : m->param_value[x->ref];
  case SYM_T: return env->t;
  case SYM_Y: return env->y ? env->y[x->ref] : 0;
  case SYM_YP: return env->yp ? env->yp[x->ref] : 0;
  case SYM_SIG: return env->sig ? env->sig[x->ref] : NAN;
  case SYM_ALIAS: return eval_rec(S, S->alias_expr[x->ref], env, M);
  case SYM_DALIAS: return eval_rec(S, S->dalias_expr[x->ref], env, M);
  case SYM_INPUT: {
    bg_xenv xe = {env->t, env->param, NULL, NULL, NULL, NULL};
    return bg_xeval(m, m->input_expr[x->ref], &xe);
  }
  default: break;
  }
  if (memo_find(M, a, &got)) return got;
  double v[3] = {0, 0, 0}, r = 0;
  int n = x->n, adr = x->adr;
  if (x->kind == SYM_ADD) {
    double mag = fabs(x->c);
    r = x->c;
    for (int k = 0; k < n; k++) {
      double t = S->w[adr + k] * eval_rec(S, S->arg[adr + k], env, M);
      r += t, mag += fabs(t);
    }
    if (fabs(r) <= 16 * DBL_EPSILON * mag) r = 0;
  } else if (x->kind == SYM_MUL) {
    double num = x->c, den = 1;
    for (int k = 0; k < n; k++) {
      double e = S->w[adr + k], b = eval_rec(S, S->arg[adr + k], env, M);
      if (e > 0) num *= powe(b, e);
      else den *= powe(b, -e);
    }
    r = num / den;
  } else {
    for (int k = 0; k < n && k < 3; k++) v[k] = eval_rec(S, S->arg[adr + k], env, M);
    x = &S->node[a];
    switch (x->kind) {
    case SYM_POW: r = pow(v[0], v[1]); break;
    case SYM_CALL: r = bg_func_apply(x->ref, v, n); break;
    case SYM_TABLE: r = bg_table_lookup(m, x->ref, v[0]); break;
    case SYM_DTABLE: r = bg_table_slope(m, x->ref, v[0]); break;
    default: r = bg_xop_apply(x->ref, v[0], v[1]); break;
    }
  }
  memo_put(M, a, r);
  return r;
}

double bg_sym_eval(bg_sym *S, int a, const bg_symenv *env) {
  memo M = {0};
  double r = eval_rec(S, a, env, &M);
  memo_free(&M);
  return r;
}
