/* SPDX-License-Identifier: BSD-3-Clause */
/* The model compiler, part 5: the gradient of a C field's energy, as model
 * expressions (each port's effort e_k = dW/dq_k).
 *
 * Why here and not with src/sym's bg_sym_diff: the efforts are the ports'
 * laws, which the causality and analysis stages (below sym in the pipeline,
 * docs/architecture.md) read as model expressions, so they must exist when
 * the model is compiled; the model stage may not include sym. The rules are
 * sym's (the active branch of if/min/max/sat, piecewise-constant functions
 * 0); tests/unit/test_fields.c checks every efforts' tree against
 * bg_sym_diff of the energy. Trees stay small: exact zeros are -1 and drop
 * out, a factor 1 is not written. Recursion follows the expression's depth
 * (the parser bounds it). */
#include <math.h>

#include "model/model_int.h"

enum { ZERO = -1, TABLE = -2 };

typedef struct grad {
  bg_build *b;
  int store;     /* the C element whose q we differentiate by */
  bg_srcloc loc;
  int table;     /* a table() was met */
} grad;

static int num(grad *g, double v) { return bg_build_num(g->b, v, g->loc); }
static int op2(grad *g, int op, int a, int c) { return bg_build_op(g->b, op, a, c, g->loc); }
static int neg(grad *g, int a) { return a == ZERO ? ZERO : op2(g, BG_X_NEG, a, -1); }
static int add(grad *g, int a, int c) {
  return a == ZERO ? c : c == ZERO ? a : op2(g, BG_X_ADD, a, c);
}
static int sub(grad *g, int a, int c) {
  return c == ZERO ? a : a == ZERO ? neg(g, c) : op2(g, BG_X_SUB, a, c);
}
static int is_one(grad *g, int a) {
  const bg_xnode *x = &g->b->m->xnode[a];
  return x->op == BG_X_NUM && x->num == 1;
}
static int mul(grad *g, int a, int c) {
  if (a == ZERO || c == ZERO) return ZERO;
  return is_one(g, a) ? c : is_one(g, c) ? a : op2(g, BG_X_MUL, a, c);
}
static int dvd(grad *g, int a, int c) { return a == ZERO ? ZERO : op2(g, BG_X_DIV, a, c); }

static int call(grad *g, int fn, int n, const int *args) {
  int k = bg_build_ref(g->b, BG_X_CALL, fn, g->loc);
  bg_xnode *x = &g->b->m->xnode[k];
  x->nargs = (unsigned char)n;
  for (int i = 0; i < n; i++) x->arg[i] = args[i];
  return k;
}
static int call1(grad *g, int fn, int a) { return call(g, fn, 1, &a); }
/* if(c, a, b) with exact zeros written as 0 */
static int pick(grad *g, int c, int a, int d) {
  if (a == ZERO && d == ZERO) return ZERO;
  int args[3] = {c, a == ZERO ? num(g, 0) : a, d == ZERO ? num(g, 0) : d};
  return call(g, BG_FN_IF, 3, args);
}

static int diff(grad *g, int k);

/* d(u^w) = u^w (w' log u + w u'/u); w' = 0: w u^(w-1) u' */
static int diff_pow(grad *g, int k, int u, int w) {
  int du = diff(g, u), dw = diff(g, w);
  if (dw == ZERO) {
    if (du == ZERO) return ZERO;
    const bg_xnode *xw = &g->b->m->xnode[w];
    if (xw->op == BG_X_NUM) { /* q^2 gives 2 q, not 2 q^(2 - 1): linear where it is */
      double c = xw->num;
      int pw = c == 2 ? u : op2(g, BG_X_POW, u, num(g, c - 1));
      return mul(g, mul(g, num(g, c), pw), du);
    }
    int wm1 = op2(g, BG_X_SUB, w, num(g, 1));
    return mul(g, mul(g, w, op2(g, BG_X_POW, u, wm1)), du);
  }
  return mul(g, k, add(g, mul(g, dw, call1(g, BG_FN_LOG, u)), dvd(g, mul(g, w, du), u)));
}

/* 1 - a^2 and 1 + a^2 */
static int one_pm_sq(grad *g, int a, int op) {
  return op2(g, op, num(g, 1), op2(g, BG_X_MUL, a, a));
}

static int diff_call1(grad *g, int k, int fn, int u) {
  int du = diff(g, u);
  if (du == ZERO) return ZERO;
  switch (fn) {
  case BG_FN_ABS: return mul(g, call1(g, BG_FN_SIGN, u), du);
  case BG_FN_SQRT: return dvd(g, du, op2(g, BG_X_MUL, num(g, 2), k));
  case BG_FN_EXP: return mul(g, k, du);
  case BG_FN_LOG: return dvd(g, du, u);
  case BG_FN_LOG10: return dvd(g, du, op2(g, BG_X_MUL, u, num(g, log(10.0))));
  case BG_FN_SIN: return mul(g, call1(g, BG_FN_COS, u), du);
  case BG_FN_COS: return neg(g, mul(g, call1(g, BG_FN_SIN, u), du));
  case BG_FN_TAN: return mul(g, one_pm_sq(g, k, BG_X_ADD), du);
  case BG_FN_ASIN: return dvd(g, du, call1(g, BG_FN_SQRT, one_pm_sq(g, u, BG_X_SUB)));
  case BG_FN_ACOS: return neg(g, dvd(g, du, call1(g, BG_FN_SQRT, one_pm_sq(g, u, BG_X_SUB))));
  case BG_FN_ATAN: return dvd(g, du, one_pm_sq(g, u, BG_X_ADD));
  case BG_FN_SINH: return mul(g, call1(g, BG_FN_COSH, u), du);
  case BG_FN_COSH: return mul(g, call1(g, BG_FN_SINH, u), du);
  case BG_FN_TANH: return mul(g, one_pm_sq(g, k, BG_X_SUB), du);
  case BG_FN_RAMP: return mul(g, call1(g, BG_FN_STEP, u), du);
  default: return ZERO; /* sign, floor, ceil, step: piecewise constant */
  }
}

static int diff_call(grad *g, int k) {
  bg_xnode x = g->b->m->xnode[k];
  const int *a = x.arg;
  switch (x.ref) {
  case BG_FN_POW: return diff_pow(g, k, a[0], a[1]);
  case BG_FN_IF: return pick(g, a[0], diff(g, a[1]), diff(g, a[2]));
  case BG_FN_MIN: return pick(g, op2(g, BG_X_LE, a[0], a[1]), diff(g, a[0]), diff(g, a[1]));
  case BG_FN_MAX: return pick(g, op2(g, BG_X_GE, a[0], a[1]), diff(g, a[0]), diff(g, a[1]));
  case BG_FN_SAT: /* sat(x, lo, hi): lo below, hi above, else x */
    return pick(g, op2(g, BG_X_LT, a[0], a[1]), diff(g, a[1]),
                pick(g, op2(g, BG_X_GT, a[0], a[2]), diff(g, a[2]), diff(g, a[0])));
  case BG_FN_ATAN2: { /* atan2(y, x)' = (x y' - y x') / (x^2 + y^2) */
    int dy = diff(g, a[0]), dx = diff(g, a[1]);
    int den = op2(g, BG_X_ADD, op2(g, BG_X_MUL, a[1], a[1]), op2(g, BG_X_MUL, a[0], a[0]));
    return dvd(g, sub(g, mul(g, a[1], dy), mul(g, a[0], dx)), den);
  }
  case BG_FN_PULSE: case BG_FN_HYST: case BG_FN_STICK: return ZERO;
  default: return diff_call1(g, k, x.ref, a[0]);
  }
}

static int diff(grad *g, int k) {
  bg_xnode x = g->b->m->xnode[k]; /* a copy: building nodes may move the array */
  int a = x.arg[0], c = x.arg[1];
  switch (x.op) {
  case BG_X_STORE: return x.ref == g->store ? num(g, 1) : ZERO;
  case BG_X_NEG: return neg(g, diff(g, a));
  case BG_X_ADD: return add(g, diff(g, a), diff(g, c));
  case BG_X_SUB: return sub(g, diff(g, a), diff(g, c));
  case BG_X_MUL: return add(g, mul(g, diff(g, a), c), mul(g, a, diff(g, c)));
  case BG_X_DIV: { /* (u/w)' = u'/w - u w'/w^2 */
    int du = diff(g, a), dw = diff(g, c);
    return sub(g, dvd(g, du, c), dvd(g, mul(g, a, dw), op2(g, BG_X_MUL, c, c)));
  }
  case BG_X_POW: return diff_pow(g, k, a, c);
  case BG_X_CALL: return diff_call(g, k);
  case BG_X_TABLE: /* only a table of a q has no smooth derivative */
    if (diff(g, a) != ZERO) g->table = 1;
    return ZERO;
  default: return ZERO; /* numbers, t, params, inputs, other variables, comparisons, logic */
  }
}

int bg_build_diff(bg_build *b, int root, int store) {
  grad g = {b, store, b->m->xnode[root].loc, 0};
  int d = diff(&g, root);
  return g.table ? TABLE : d;
}
