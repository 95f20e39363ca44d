/* SPDX-License-Identifier: BSD-3-Clause */
/* Tree-walking evaluation of model expressions and the one definition of
 * every built-in function (the bytecode VM calls the same bg_func_apply). */
#include <math.h>
#include <string.h>

#include "model/expr.h"

static const struct {
  const char *name;
  int min_args, max_args;
} funcs[BG_FN_COUNT] = {
    [BG_FN_ABS] = {"abs", 1, 1},     [BG_FN_SIGN] = {"sign", 1, 1},
    [BG_FN_SQRT] = {"sqrt", 1, 1},   [BG_FN_EXP] = {"exp", 1, 1},
    [BG_FN_LOG] = {"log", 1, 1},     [BG_FN_LOG10] = {"log10", 1, 1},
    [BG_FN_SIN] = {"sin", 1, 1},     [BG_FN_COS] = {"cos", 1, 1},
    [BG_FN_TAN] = {"tan", 1, 1},     [BG_FN_ASIN] = {"asin", 1, 1},
    [BG_FN_ACOS] = {"acos", 1, 1},   [BG_FN_ATAN] = {"atan", 1, 1},
    [BG_FN_ATAN2] = {"atan2", 2, 2}, [BG_FN_SINH] = {"sinh", 1, 1},
    [BG_FN_COSH] = {"cosh", 1, 1},   [BG_FN_TANH] = {"tanh", 1, 1},
    [BG_FN_MIN] = {"min", 2, 2},     [BG_FN_MAX] = {"max", 2, 2},
    [BG_FN_POW] = {"pow", 2, 2},     [BG_FN_FLOOR] = {"floor", 1, 1},
    [BG_FN_CEIL] = {"ceil", 1, 1},   [BG_FN_IF] = {"if", 3, 3},
    [BG_FN_STEP] = {"step", 1, 1},   [BG_FN_RAMP] = {"ramp", 1, 1},
    [BG_FN_PULSE] = {"pulse", 2, 2}, [BG_FN_SAT] = {"sat", 3, 3},
    [BG_FN_HYST] = {"hyst", 3, 3},   [BG_FN_STICK] = {"stick", 3, 3},
};

const char *bg_func_name(int fn) {
  return fn >= 0 && fn < BG_FN_COUNT ? funcs[fn].name : "?";
}

int bg_func_lookup(const char *name, int *min_args, int *max_args) {
  for (int i = 0; i < BG_FN_COUNT; i++)
    if (strcmp(funcs[i].name, name) == 0) {
      if (min_args) *min_args = funcs[i].min_args;
      if (max_args) *max_args = funcs[i].max_args;
      return i;
    }
  return -1;
}

double bg_func_apply(int fn, const double *a, int nargs) {
  (void)nargs;
  switch (fn) {
  case BG_FN_ABS: return fabs(a[0]);
  case BG_FN_SIGN: return a[0] > 0 ? 1.0 : a[0] < 0 ? -1.0 : 0.0;
  case BG_FN_SQRT: return sqrt(a[0]);
  case BG_FN_EXP: return exp(a[0]);
  case BG_FN_LOG: return log(a[0]);
  case BG_FN_LOG10: return log10(a[0]);
  case BG_FN_SIN: return sin(a[0]);
  case BG_FN_COS: return cos(a[0]);
  case BG_FN_TAN: return tan(a[0]);
  case BG_FN_ASIN: return asin(a[0]);
  case BG_FN_ACOS: return acos(a[0]);
  case BG_FN_ATAN: return atan(a[0]);
  case BG_FN_ATAN2: return atan2(a[0], a[1]);
  case BG_FN_SINH: return sinh(a[0]);
  case BG_FN_COSH: return cosh(a[0]);
  case BG_FN_TANH: return tanh(a[0]);
  case BG_FN_MIN: return fmin(a[0], a[1]);
  case BG_FN_MAX: return fmax(a[0], a[1]);
  case BG_FN_POW: return pow(a[0], a[1]);
  case BG_FN_FLOOR: return floor(a[0]);
  case BG_FN_CEIL: return ceil(a[0]);
  case BG_FN_IF: return a[0] != 0 ? a[1] : a[2];
  case BG_FN_STEP: return a[0] < 0 ? 0.0 : 1.0;
  case BG_FN_RAMP: return a[0] < 0 ? 0.0 : a[0];
  case BG_FN_PULSE: return a[0] >= 0 && a[0] < a[1] ? 1.0 : 0.0;
  case BG_FN_SAT: return a[0] < a[1] ? a[1] : a[0] > a[2] ? a[2] : a[0];
  /* the memory functions without their memory: the value they start with
   * (docs/format.md, "Memory"); a simulation holds the rest as a mode */
  case BG_FN_HYST: return a[0] >= a[2] ? 1.0 : 0.0;
  case BG_FN_STICK: return a[0] == 0 && fabs(a[1]) <= a[2] ? 1.0 : 0.0;
  default: return NAN;
  }
}

/* The segment [tx[lo], tx[lo + 1]] holding x, for tx[0] < x < tx[n - 1]. */
static int table_segment(const double *tx, int n, double x) {
  int lo = 0, hi = n - 1; /* tx[lo] < x < tx[hi] */
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    if (tx[mid] <= x) lo = mid; else hi = mid;
  }
  return lo;
}

double bg_table_lookup(const bg_model *m, int table, double x) {
  const double *tx = m->table_x + m->table_adr[table];
  const double *ty = m->table_y + m->table_adr[table];
  int n = m->table_n[table];
  if (n == 0) return NAN;
  if (x <= tx[0]) return ty[0];
  if (x >= tx[n - 1]) return ty[n - 1];
  int lo = table_segment(tx, n, x), hi = lo + 1;
  double w = (x - tx[lo]) / (tx[hi] - tx[lo]);
  return ty[lo] + w * (ty[hi] - ty[lo]);
}

double bg_table_slope(const bg_model *m, int table, double x) {
  const double *tx = m->table_x + m->table_adr[table];
  const double *ty = m->table_y + m->table_adr[table];
  int n = m->table_n[table];
  if (n < 2 || x < tx[0] || x >= tx[n - 1]) return 0; /* clamped outside */
  int lo = table_segment(tx, n, x), hi = lo + 1;
  return tx[hi] > tx[lo] ? (ty[hi] - ty[lo]) / (tx[hi] - tx[lo]) : 0;
}

static double read_var(const double *v, int i) { return v ? v[i] : NAN; }

/* Binary and unary operators, shared with the bytecode VM's folding. */
static double apply_op(int op, double x, double y) {
  switch (op) {
  case BG_X_ADD: return x + y;
  case BG_X_SUB: return x - y;
  case BG_X_MUL: return x * y;
  case BG_X_DIV: return x / y;
  case BG_X_POW: return pow(x, y);
  case BG_X_LT: return x < y;
  case BG_X_LE: return x <= y;
  case BG_X_GT: return x > y;
  case BG_X_GE: return x >= y;
  case BG_X_EQ: return x == y;
  case BG_X_NE: return x != y;
  case BG_X_AND: return x != 0 && y != 0;
  case BG_X_OR: return x != 0 || y != 0;
  case BG_X_NEG: return -x;
  case BG_X_NOT: return x == 0;
  default: return NAN;
  }
}

double bg_xop_apply(int op, double x, double y) { return apply_op(op, x, y); }

double bg_xeval(const bg_model *m, int root, const bg_xenv *env) {
  const bg_xnode *n = &m->xnode[root];
  double a[3];
  switch (n->op) {
  case BG_X_NUM: return n->num;
  case BG_X_TIME: return env ? env->t : NAN;
  case BG_X_PARAM: return env && env->param ? env->param[n->ref] : m->param_value[n->ref];
  case BG_X_INPUT: return bg_xeval(m, m->input_expr[n->ref], env);
  case BG_X_STATE: return env ? read_var(env->state, n->ref) : NAN;
  case BG_X_EFFORT: return env ? read_var(env->effort, n->ref) : NAN;
  case BG_X_FLOW: return env ? read_var(env->flow, n->ref) : NAN;
  case BG_X_STORE: return env ? read_var(env->store, n->ref) : NAN;
  case BG_X_CALL:
    if (n->ref == BG_FN_IF) /* lazy, like C's ?: */
      return bg_xeval(m, n->arg[0], env) != 0 ? bg_xeval(m, n->arg[1], env)
                                              : bg_xeval(m, n->arg[2], env);
    for (int i = 0; i < n->nargs; i++) a[i] = bg_xeval(m, n->arg[i], env);
    return bg_func_apply(n->ref, a, n->nargs);
  case BG_X_TABLE: return bg_table_lookup(m, n->ref, bg_xeval(m, n->arg[0], env));
  case BG_X_NEG:
  case BG_X_NOT: return apply_op(n->op, bg_xeval(m, n->arg[0], env), 0);
  default:
    return apply_op(n->op, bg_xeval(m, n->arg[0], env), bg_xeval(m, n->arg[1], env));
  }
}
