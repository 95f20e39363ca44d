/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_sym core: hash-consed nodes and the canonical constructors (sym.h).
 * Differentiation, substitution, expansion and evaluation are in
 * sym_ops.c, printing in sym_print.c. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "sym/sym.h"

/* ------------------------------------------------------------ the store */
bg_sym *bg_sym_new(const bg_model *m) {
  bg_sym *S = bg_xcalloc(1, sizeof *S);
  S->m = m;
  S->captab = 1024;
  S->tab = bg_xmalloc((size_t)S->captab * sizeof *S->tab);
  for (int i = 0; i < S->captab; i++) S->tab[i] = -1;
  S->max_nodes = 400000;
  return S;
}

void bg_sym_free(bg_sym *S) {
  if (!S) return;
  free(S->node), free(S->arg), free(S->w), free(S->tab);
  free(S->memo), free(S->stamp), free(S->val);
  free(S->alias_expr), free(S->dalias_of), free(S->dalias_var), free(S->dalias_expr);
  free(S);
}

int bg_sym_full(const bg_sym *S) { return S->over || S->nnode > S->max_nodes; }
int bg_sym_over(const bg_sym *S) { return S->over; }

void bg_sym_spend(bg_sym *S, long n) {
  S->work += n;
  if (S->budget > 0 && S->work > S->budget) S->over = 1;
}

static unsigned hash_mix(unsigned h, unsigned x) {
  h ^= x + 0x9e3779b9u + (h << 6) + (h >> 2);
  return h;
}

static unsigned hash_dbl(double d) {
  unsigned long long u;
  if (d == 0) d = 0; /* -0 and +0 alike */
  memcpy(&u, &d, sizeof u);
  return (unsigned)(u ^ (u >> 32));
}

static int same_dbl(double a, double b) {
  if (a == 0 && b == 0) return 1;
  return memcmp(&a, &b, sizeof a) == 0;
}

static unsigned node_hash(int kind, int ref, double c, int n, const int *args, const double *w) {
  unsigned h = hash_mix((unsigned)kind * 2654435761u, (unsigned)ref);
  h = hash_mix(h, hash_dbl(c));
  for (int k = 0; k < n; k++) h = hash_mix(hash_mix(h, (unsigned)args[k]), w ? hash_dbl(w[k]) : 0);
  return h;
}

static int node_eq(const bg_sym *S, int id, int kind, int ref, double c, int n, const int *args,
                   const double *w) {
  const bg_symnode *x = &S->node[id];
  if (x->kind != kind || x->ref != ref || x->n != n || !same_dbl(x->c, c)) return 0;
  for (int k = 0; k < n; k++) {
    if (S->arg[x->adr + k] != args[k]) return 0;
    if (!same_dbl(S->w[x->adr + k], w ? w[k] : 1)) return 0;
  }
  return 1;
}

static void rehash(bg_sym *S) {
  free(S->tab);
  S->captab *= 2;
  S->tab = bg_xmalloc((size_t)S->captab * sizeof *S->tab);
  for (int i = 0; i < S->captab; i++) S->tab[i] = -1;
  for (int id = 0; id < S->nnode; id++) {
    unsigned p = S->node[id].h & (unsigned)(S->captab - 1);
    while (S->tab[p] >= 0) p = (p + 1) & (unsigned)(S->captab - 1);
    S->tab[p] = id;
  }
}

/* The unique node with these fields (w NULL: all weights 1). */
static int intern(bg_sym *S, int kind, int ref, double c, int n, const int *args, const double *w) {
  if (c == 0) c = 0;
  bg_sym_spend(S, 1 + n);
  unsigned h = node_hash(kind, ref, c, n, args, w);
  unsigned p = h & (unsigned)(S->captab - 1);
  for (; S->tab[p] >= 0; p = (p + 1) & (unsigned)(S->captab - 1))
    if (S->node[S->tab[p]].h == h && node_eq(S, S->tab[p], kind, ref, c, n, args, w)) return S->tab[p];
  if (S->nnode == S->capnode) {
    S->capnode = S->capnode ? 2 * S->capnode : 1024;
    S->node = bg_xrealloc(S->node, (size_t)S->capnode * sizeof *S->node);
  }
  /* args and w may point into S->arg and S->w (an existing node's operands,
   * as monomial() passes them): grow into new arrays and free the old ones
   * only after the operands are copied */
  int *old_arg = NULL;
  double *old_w = NULL;
  if (S->narg + n > S->caparg) {
    while (S->narg + n > S->caparg) S->caparg = S->caparg ? 2 * S->caparg : 4096;
    old_arg = S->arg, old_w = S->w;
    S->arg = bg_xmalloc((size_t)S->caparg * sizeof *S->arg);
    S->w = bg_xmalloc((size_t)S->caparg * sizeof *S->w);
    if (S->narg) memcpy(S->arg, old_arg, (size_t)S->narg * sizeof *S->arg);
    if (S->narg) memcpy(S->w, old_w, (size_t)S->narg * sizeof *S->w);
  }
  int id = S->nnode++;
  S->node[id] = (bg_symnode){kind, ref, n, S->narg, c, h};
  for (int k = 0; k < n; k++) S->arg[S->narg + k] = args[k], S->w[S->narg + k] = w ? w[k] : 1;
  S->narg += n;
  free(old_arg), free(old_w);
  S->tab[p] = id;
  if (2 * S->nnode > S->captab) rehash(S);
  return id;
}

int bg_sym_num(bg_sym *S, double c) { return intern(S, SYM_NUM, 0, c, 0, NULL, NULL); }

int bg_sym_alias(bg_sym *S, int ref, int e) {
  if (ref >= S->nalias) {
    S->alias_expr = bg_xrealloc(S->alias_expr, (size_t)(ref + 1) * sizeof(int));
    for (int k = S->nalias; k <= ref; k++) S->alias_expr[k] = -1;
    S->nalias = ref + 1;
  }
  S->alias_expr[ref] = e;
  return bg_sym_leaf(S, SYM_ALIAS, ref);
}

void bg_sym_dalias_info(const bg_sym *S, int ref, int *alias, int *var) {
  *alias = S->dalias_of[ref], *var = S->dalias_var[ref];
}
int bg_sym_leaf(bg_sym *S, int kind, int ref) { return intern(S, kind, ref, 0, 0, NULL, NULL); }

/* ------------------------------------------------------------ order */
/* Structural order (the order of sorted terms); 0 only for equal ids. One
 * step per node pair visited: different canonical nodes always differ, so
 * the walk follows a single path down to the first difference. */
static int cmp_rec(const bg_sym *S, int a, int b, long *steps) {
  (*steps)++;
  if (a == b) return 0;
  const bg_symnode *x = &S->node[a], *y = &S->node[b];
  if (x->kind != y->kind) return x->kind < y->kind ? -1 : 1;
  if (x->kind == SYM_NUM) return x->c < y->c ? -1 : x->c > y->c ? 1 : (a < b ? -1 : 1);
  if (x->ref != y->ref) return x->ref < y->ref ? -1 : 1;
  int n = x->n < y->n ? x->n : y->n;
  for (int k = 0; k < n; k++) {
    int r = cmp_rec(S, S->arg[x->adr + k], S->arg[y->adr + k], steps);
    if (r) return r;
  }
  if (x->n != y->n) return x->n < y->n ? -1 : 1;
  for (int k = 0; k < n; k++) {
    double p = S->w[x->adr + k], q = S->w[y->adr + k];
    if (p != q) return p > q ? -1 : 1; /* higher powers, larger weights first */
  }
  if (x->c != y->c) return x->c < y->c ? -1 : 1;
  return a < b ? -1 : 1; /* not reached for canonical nodes */
}

/* ------------------------------------------------------------ scratch vectors */
typedef struct tv { int *t; double *w; int n, cap; } tv;

static void tv_push(tv *v, int t, double w) {
  if (v->n == v->cap) {
    v->cap = v->cap ? 2 * v->cap : 16;
    v->t = bg_xrealloc(v->t, (size_t)v->cap * sizeof *v->t);
    v->w = bg_xrealloc(v->w, (size_t)v->cap * sizeof *v->w);
  }
  v->t[v->n] = t, v->w[v->n++] = w;
}
static void tv_free(tv *v) { free(v->t), free(v->w); }

/* Stable merge sort by structural order (a sum may have thousands of terms:
 * insertion sort was quadratic); the comparisons' steps are work. */
static void tv_merge(const bg_sym *S, tv *v, int lo, int hi, int *tt, double *tw, long *steps) {
  if (hi - lo < 2) return;
  int mid = lo + (hi - lo) / 2;
  tv_merge(S, v, lo, mid, tt, tw, steps), tv_merge(S, v, mid, hi, tt, tw, steps);
  if (cmp_rec(S, v->t[mid - 1], v->t[mid], steps) <= 0) return; /* already in order */
  int i = lo, j = mid, k = lo;
  while (i < mid && j < hi) {
    if (cmp_rec(S, v->t[i], v->t[j], steps) <= 0) tt[k] = v->t[i], tw[k++] = v->w[i++];
    else tt[k] = v->t[j], tw[k++] = v->w[j++];
  }
  while (i < mid) tt[k] = v->t[i], tw[k++] = v->w[i++];
  while (j < hi) tt[k] = v->t[j], tw[k++] = v->w[j++];
  memcpy(v->t + lo, tt + lo, (size_t)(hi - lo) * sizeof *tt);
  memcpy(v->w + lo, tw + lo, (size_t)(hi - lo) * sizeof *tw);
}

static void tv_sort(bg_sym *S, tv *v) {
  if (v->n < 2) return;
  int *tt = bg_xmalloc((size_t)v->n * sizeof *tt);
  double *tw = bg_xmalloc((size_t)v->n * sizeof *tw);
  long steps = 0;
  tv_merge(S, v, 0, v->n, tt, tw, &steps);
  bg_sym_spend(S, steps);
  free(tt), free(tw);
}

/* a + b with the exact-cancellation rule; *mag collects |terms|. */
static double xsum(double a, double b, double *mag) {
  double r = a + b, m = (mag ? *mag : fabs(a)) + fabs(b);
  if (mag) *mag = m;
  return fabs(r) <= 16 * DBL_EPSILON * m ? 0.0 : r;
}

static int is_int(double e) { return e == floor(e) && fabs(e) < 1e9; }

/* ------------------------------------------------------------ sums */
/* The monomial of a product (coefficient 1) and its coefficient. */
static int monomial(bg_sym *S, int x, double *coef) {
  const bg_symnode *nd = &S->node[x];
  *coef = 1;
  if (nd->kind != SYM_MUL || nd->c == 1) return x;
  *coef = nd->c;
  if (nd->n == 1 && S->w[nd->adr] == 1) return S->arg[nd->adr];
  return intern(S, SYM_MUL, 0, 1, nd->n, S->arg + nd->adr, S->w + nd->adr);
}

/* Sorts the terms, merges equal ones and drops those whose weight became 0; returns how
 * many are left. A sum's like terms add their coefficients with xsum (so a cancellation
 * leaves an exact 0); a product's equal bases add their exponents plainly. */
static int tv_collect(bg_sym *S, tv *v, int like_terms) {
  tv_sort(S, v);
  int m = 0;
  for (int i = 0; i < v->n; i++) {
    if (m > 0 && v->t[m - 1] == v->t[i]) {
      v->w[m - 1] = like_terms ? xsum(v->w[m - 1], v->w[i], NULL) : v->w[m - 1] + v->w[i];
      continue;
    }
    v->t[m] = v->t[i], v->w[m++] = v->w[i];
  }
  int k = 0;
  for (int i = 0; i < m; i++)
    if (v->w[i] != 0) v->t[k] = v->t[i], v->w[k++] = v->w[i];
  return k;
}

int bg_sym_sum(bg_sym *S, double c0, int n, const int *t, const double *w) {
  tv v = {0};
  double cst = c0, cmag = fabs(c0);
  for (int k = 0; k < n; k++) {
    double wk = w ? w[k] : 1;
    if (wk == 0) continue;
    const bg_symnode *x = &S->node[t[k]];
    if (x->kind == SYM_NUM) {
      cst = xsum(cst, wk * x->c, &cmag);
    } else if (x->kind == SYM_ADD) {
      int adr = x->adr, cnt = x->n;
      cst = xsum(cst, wk * x->c, &cmag);
      for (int q = 0; q < cnt; q++) tv_push(&v, S->arg[adr + q], wk * S->w[adr + q]);
    } else {
      double c;
      int mono = monomial(S, t[k], &c);
      tv_push(&v, mono, wk * c);
    }
  }
  int k2 = tv_collect(S, &v, 1);
  int r;
  if (k2 == 0) r = bg_sym_num(S, cst);
  else if (k2 == 1 && cst == 0) r = bg_sym_scale(S, v.w[0], v.t[0]);
  else r = intern(S, SYM_ADD, 0, cst, k2, v.t, v.w);
  tv_free(&v);
  return r;
}

int bg_sym_add(bg_sym *S, int a, int b) {
  int t[2] = {a, b};
  return bg_sym_sum(S, 0, 2, t, NULL);
}

int bg_sym_sub(bg_sym *S, int a, int b) {
  int t[2] = {a, b};
  double w[2] = {1, -1};
  return bg_sym_sum(S, 0, 2, t, w);
}

/* ------------------------------------------------------------ products */
/* The sum with every weight and the constant negated. */
static int negate_sum(bg_sym *S, int x) {
  const bg_symnode *nd = &S->node[x];
  int n = nd->n, adr = nd->adr;
  double *w = bg_xmalloc((size_t)n * sizeof *w);
  for (int k = 0; k < n; k++) w[k] = -S->w[adr + k];
  int *t = bg_xmalloc((size_t)n * sizeof *t);
  memcpy(t, S->arg + adr, (size_t)n * sizeof *t);
  int r = intern(S, SYM_ADD, 0, -nd->c, n, t, w);
  free(w), free(t);
  return r;
}

int bg_sym_prod(bg_sym *S, double c, int n, const int *b, const double *e) {
  tv v = {0};
  for (int k = 0; k < n; k++) {
    double ek = e ? e[k] : 1;
    const bg_symnode *x = &S->node[b[k]];
    if (ek == 0) continue;
    if (x->kind == SYM_NUM) {
      c *= ek == 1 ? x->c : ek == -1 ? 1 / x->c : pow(x->c, ek);
    } else if (x->kind == SYM_MUL && is_int(ek)) {
      int adr = x->adr, cnt = x->n;
      c *= ek == 1 ? x->c : pow(x->c, ek);
      for (int q = 0; q < cnt; q++) tv_push(&v, S->arg[adr + q], ek * S->w[adr + q]);
    } else if (x->kind == SYM_ADD && is_int(ek) && S->w[x->adr] < 0) {
      tv_push(&v, negate_sum(S, b[k]), ek); /* first term positive */
      if (fmod(fabs(ek), 2) == 1) c = -c;
    } else {
      tv_push(&v, b[k], ek);
    }
  }
  if (c == 0 || v.n == 0) {
    tv_free(&v);
    return bg_sym_num(S, c);
  }
  int k2 = tv_collect(S, &v, 0);
  int r;
  if (k2 == 0) r = bg_sym_num(S, c);
  else if (k2 == 1 && v.w[0] == 1 && c == 1) r = v.t[0];
  else if (k2 == 1 && v.w[0] == 1 && S->node[v.t[0]].kind == SYM_ADD) {
    int x = v.t[0]; /* a number times a sum: distributed */
    r = bg_sym_sum(S, 0, 1, &x, &c);
  } else r = intern(S, SYM_MUL, 0, c, k2, v.t, v.w);
  tv_free(&v);
  return r;
}

int bg_sym_mul(bg_sym *S, int a, int b) {
  int t[2] = {a, b};
  return bg_sym_prod(S, 1, 2, t, NULL);
}

int bg_sym_div(bg_sym *S, int a, int b) {
  int t[2] = {a, b};
  double e[2] = {1, -1};
  return bg_sym_prod(S, 1, 2, t, e);
}

int bg_sym_scale(bg_sym *S, double c, int a) {
  if (c == 1) return a;
  return bg_sym_prod(S, c, 1, &a, NULL);
}

int bg_sym_neg(bg_sym *S, int a) { return bg_sym_scale(S, -1, a); }

int bg_sym_powc(bg_sym *S, int a, double e) { return bg_sym_prod(S, 1, 1, &a, &e); }

int bg_sym_pow(bg_sym *S, int a, int b) {
  const bg_symnode *y = &S->node[b];
  if (y->kind == SYM_NUM) {
    if (S->node[a].kind == SYM_NUM) return bg_sym_num(S, pow(S->node[a].c, y->c));
    return bg_sym_powc(S, a, y->c);
  }
  int t[2] = {a, b};
  return intern(S, SYM_POW, 0, 0, 2, t, NULL);
}

/* ------------------------------------------------------------ functions */
static int all_num(const bg_sym *S, int n, const int *args) {
  for (int k = 0; k < n; k++)
    if (S->node[args[k]].kind != SYM_NUM) return 0;
  return 1;
}

int bg_sym_call(bg_sym *S, int fn, int nargs, const int *args) {
  if (fn == BG_FN_POW && nargs == 2) return bg_sym_pow(S, args[0], args[1]);
  if (all_num(S, nargs, args)) {
    double x[3] = {0, 0, 0};
    for (int k = 0; k < nargs && k < 3; k++) x[k] = S->node[args[k]].c;
    return bg_sym_num(S, bg_func_apply(fn, x, nargs));
  }
  if (fn == BG_FN_IF && S->node[args[0]].kind == SYM_NUM) return S->node[args[0]].c != 0 ? args[1] : args[2];
  if (fn == BG_FN_IF && args[1] == args[2]) return args[1];
  return intern(S, SYM_CALL, fn, 0, nargs, args, NULL);
}

int bg_sym_op(bg_sym *S, int op, int a, int b) {
  if (op == BG_X_NEG) return bg_sym_neg(S, a);
  int n = op == BG_X_NOT ? 1 : 2, t[2] = {a, b};
  if (all_num(S, n, t)) return bg_sym_num(S, bg_xop_apply(op, S->node[a].c, n > 1 ? S->node[b].c : 0));
  switch (op) {
  case BG_X_ADD: return bg_sym_add(S, a, b);
  case BG_X_SUB: return bg_sym_sub(S, a, b);
  case BG_X_MUL: return bg_sym_mul(S, a, b);
  case BG_X_DIV: return bg_sym_div(S, a, b);
  case BG_X_POW: return bg_sym_pow(S, a, b);
  default: return intern(S, SYM_OP, op, 0, n, t, NULL);
  }
}

int bg_sym_table(bg_sym *S, int table, int x) {
  if (S->node[x].kind == SYM_NUM) return bg_sym_num(S, bg_table_lookup(S->m, table, S->node[x].c));
  return intern(S, SYM_TABLE, table, 0, 1, &x, NULL);
}

int bg_sym_dtable(bg_sym *S, int table, int x) { return intern(S, SYM_DTABLE, table, 0, 1, &x, NULL); }

/* ------------------------------------------------------------ model expressions */
/* A chain of products and quotients (q1*q2*...*q256, a field's gradient) as
 * one product: built pairwise, each step copied and sorted all factors so
 * far (cubic in the chain's length). Factors in the chain's order. */
static int from_x_product(bg_sym *S, int root, const int *state_y, const int *store_y) {
  const bg_model *m = S->m;
  int cap = 16, n = 0, nst = 0, *b = bg_xmalloc((size_t)cap * sizeof *b), *st = bg_xmalloc((size_t)cap * sizeof *st);
  double *e = bg_xmalloc((size_t)cap * sizeof *e), *se = bg_xmalloc((size_t)cap * sizeof *se);
  st[nst] = root, se[nst++] = 1;
  while (nst > 0) { /* right operands pushed first: factors come out left to right */
    int x = st[--nst];
    double ex = se[nst];
    const bg_xnode *nd = &m->xnode[x];
    if (nst + 2 > cap || n + 1 > cap) {
      cap *= 2;
      b = bg_xrealloc(b, (size_t)cap * sizeof *b), st = bg_xrealloc(st, (size_t)cap * sizeof *st);
      e = bg_xrealloc(e, (size_t)cap * sizeof *e), se = bg_xrealloc(se, (size_t)cap * sizeof *se);
    }
    int folds = m->xnode[nd->arg[0]].op == BG_X_NUM && m->xnode[nd->arg[1]].op == BG_X_NUM;
    if ((nd->op == BG_X_MUL || nd->op == BG_X_DIV) && !(folds && x != root)) { /* 2/3: folded as before */
      st[nst] = nd->arg[1], se[nst++] = nd->op == BG_X_DIV ? -ex : ex;
      st[nst] = nd->arg[0], se[nst++] = ex;
    } else {
      b[n] = bg_sym_from_x(S, x, state_y, store_y), e[n++] = ex;
    }
  }
  int r = bg_sym_prod(S, 1, n, b, e);
  free(b), free(st), free(e), free(se);
  return r;
}

int bg_sym_from_x(bg_sym *S, int root, const int *state_y, const int *store_y) {
  const bg_model *m = S->m;
  const bg_xnode *n = &m->xnode[root];
  int a[3] = {0, 0, 0};
  switch (n->op) {
  case BG_X_NUM: return bg_sym_num(S, n->num);
  case BG_X_TIME: return bg_sym_leaf(S, SYM_T, 0);
  case BG_X_PARAM: return bg_sym_leaf(S, SYM_PARAM, n->ref);
  case BG_X_INPUT: return bg_sym_leaf(S, SYM_INPUT, n->ref);
  case BG_X_STATE:
    if (!state_y || state_y[n->ref] < 0) BG_FATAL("sym: a user state that is not an unknown");
    return bg_sym_leaf(S, SYM_Y, state_y[n->ref]);
  case BG_X_STORE:
    if (!store_y || store_y[n->ref] < 0) BG_FATAL("sym: a store state that is not an unknown");
    return bg_sym_leaf(S, SYM_Y, store_y[n->ref]);
  case BG_X_EFFORT: return bg_sym_leaf(S, SYM_SIG, 2 * n->ref);
  case BG_X_FLOW: return bg_sym_leaf(S, SYM_SIG, 2 * n->ref + 1);
  case BG_X_MUL: case BG_X_DIV:
    if (m->xnode[n->arg[0]].op != BG_X_NUM || m->xnode[n->arg[1]].op != BG_X_NUM)
      return from_x_product(S, root, state_y, store_y);
    break;
  default: break;
  }
  for (int k = 0; k < n->nargs && k < 3; k++) a[k] = bg_sym_from_x(S, n->arg[k], state_y, store_y);
  if (n->op == BG_X_CALL) return bg_sym_call(S, n->ref, n->nargs, a);
  if (n->op == BG_X_TABLE) return bg_sym_table(S, n->ref, a[0]);
  return bg_sym_op(S, n->op, a[0], a[1]);
}
