/* SPDX-License-Identifier: BSD-3-Clause */
/* The equations compiled to one straight-line tape over a slot array
 * [t | y | yp | constants and intermediate values], evaluated with no
 * allocation, and differentiated exactly by forward-mode automatic
 * differentiation (one pass per colour of a column colouring of the sparse
 * Jacobian pattern). Operators and functions are applied with the shared
 * definitions of expr.h; their derivatives are here. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsys_int.h"
#include "model/model.h"

static double ev_der(const bg_eqsys *s, int e, const double *v, const double *dv);

/* ------------------------------------------------------------ slots and code */
static int new_slot(bg_eqsys *s, int cst, double val) {
  if (s->nslot == s->capslot) {
    s->capslot = s->capslot ? 2 * s->capslot : 256;
    s->v = bg_xrealloc(s->v, (size_t)s->capslot * sizeof *s->v);
    s->is_const = bg_xrealloc(s->is_const, (size_t)s->capslot);
  }
  s->v[s->nslot] = val;
  s->is_const[s->nslot] = (unsigned char)cst;
  return s->nslot++;
}

static void push_code(bg_eqsys *s, tinstr I) {
  if (s->ncode == s->capcode) {
    s->capcode = s->capcode ? 2 * s->capcode : 256;
    s->code = bg_xrealloc(s->code, (size_t)s->capcode * sizeof *s->code);
  }
  s->code[s->ncode++] = I;
}

static int tl_push(bg_eqsys *s, int slot, double c) {
  if (s->ntl == s->captl) {
    s->captl = s->captl ? 2 * s->captl : 256;
    s->tl_slot = bg_xrealloc(s->tl_slot, (size_t)s->captl * sizeof *s->tl_slot);
    s->tl_coef = bg_xrealloc(s->tl_coef, (size_t)s->captl * sizeof *s->tl_coef);
  }
  s->tl_slot[s->ntl] = slot;
  s->tl_coef[s->ntl] = c;
  return s->ntl++;
}

static double ins_val(const bg_eqsys *s, const tinstr *I, const double *v) {
  switch (I->op) {
  case T_LIN: {
    double r = 0;
    for (int k = 0; k < I->a[0]; k++) r += s->tl_coef[I->ref + k] * v[s->tl_slot[I->ref + k]];
    return r;
  }
  case BG_X_CALL: {
    double args[3] = {0, 0, 0};
    for (int k = 0; k < I->na; k++) args[k] = v[I->a[k]];
    return bg_func_apply(I->ref, args, I->na);
  }
  case BG_X_TABLE: return bg_table_lookup(s->m, I->ref, v[I->a[0]]);
  case T_DTABLE: return bg_table_slope(s->m, I->ref, v[I->a[0]]);
  default: return bg_xop_apply(I->op, v[I->a[0]], I->na > 1 ? v[I->a[1]] : 0);
  }
}

double bg_eqs_ins_value(const bg_eqsys *s, int k, const double *v) { return ins_val(s, &s->code[k], v); }

/* The evaluation loop's step: the operators the tape is mostly made of
 * (sums, products, quotients) inline, every other op through ins_val. The
 * same operations in the same order as ins_val: the same values. */
static inline double ins_fast(const bg_eqsys *s, const tinstr *I, const double *v) {
  switch (I->op) {
  case BG_X_ADD: return v[I->a[0]] + v[I->a[1]];
  case BG_X_SUB: return v[I->a[0]] - v[I->a[1]];
  case BG_X_MUL: return v[I->a[0]] * v[I->a[1]];
  case BG_X_DIV: return v[I->a[0]] / v[I->a[1]];
  case BG_X_NEG: return -v[I->a[0]];
  case T_LIN: {
    const double *c = s->tl_coef + I->ref;
    const int *sl = s->tl_slot + I->ref;
    double r = 0;
    for (int k = 0; k < I->a[0]; k++) r += c[k] * v[sl[k]];
    return r;
  }
  default: return ins_val(s, I, v);
  }
}

/* Emits out = op(args), folding it when every argument is a constant. */
static int emit(bg_eqsys *s, int op, int ref, int na, const int *args, int eq) {
  tinstr I = {(unsigned char)op, (unsigned char)na, ref, -1, {0, 0, 0}, eq, -1};
  int cst = 1;
  for (int k = 0; k < na && op != T_LIN; k++) I.a[k] = args[k], cst &= s->is_const[args[k]];
  if (op == T_LIN) {
    I.a[0] = na;
    for (int k = 0; k < na; k++) cst &= s->is_const[s->tl_slot[ref + k]];
  }
  if (cst) return new_slot(s, 1, ins_val(s, &I, s->v));
  I.out = new_slot(s, 0, 0);
  push_code(s, I);
  return I.out;
}

int bg_eqs_const(bg_eqsys *s, double val) { return new_slot(s, 1, val); }
int bg_eqs_var_slot(bg_eqsys *s) { return new_slot(s, 0, 0); }
int bg_eqs_emit(bg_eqsys *s, int op, int ref, int na, const int *args, int eq) {
  return emit(s, op, ref, na, args, eq);
}
int bg_eqs_tl_push(bg_eqsys *s, int slot, double c) { return tl_push(s, slot, c); }

/* ------------------------------------------------------------ compilation */
/* Linear analysis: the value of input k of the linearisation plus u_k, a
 * slot that stays 0 except while differentiating (bg_eqsys_jac_io). */
static int lin_offset(bg_eqsys *s, int ref, int slot, int eq) {
  for (int k = 0; k < s->lin_nu; k++)
    if (s->lin_ref[k] == ref) {
      int args[2] = {slot, s->lin_uslot[k]};
      return emit(s, BG_X_ADD, 0, 2, args, eq);
    }
  return slot;
}

static int cx(bg_eqsys *s, int root, int eq) {
  const bg_model *m = s->m;
  const bg_xnode *n = &m->xnode[root];
  int args[3], slot;
  switch (n->op) {
  case BG_X_NUM: return new_slot(s, 1, n->num);
  case BG_X_TIME: return 0;
  case BG_X_PARAM:
    if (s->live_params) return s->param_slot[n->ref];
    return new_slot(s, 1, m->param_value[n->ref]);
  case BG_X_INPUT:
    if (s->input_slot[n->ref] < 0)
      s->input_slot[n->ref] = lin_offset(s, -1 - n->ref, cx(s, m->input_expr[n->ref], eq), eq);
    return s->input_slot[n->ref];
  case BG_X_STATE: return s->slot_y + s->state_y[n->ref];
  case BG_X_STORE: return s->slot_y + s->store_y[n->ref];
  case BG_X_EFFORT: case BG_X_FLOW:
    slot = s->sig_slot[2 * n->ref + (n->op == BG_X_FLOW)];
    if (slot < 0) BG_FATAL("eqsys: bond variable used before it is computed");
    return slot;
  default:
    for (int k = 0; k < n->nargs; k++) args[k] = cx(s, n->arg[k], eq);
    slot = emit(s, n->op, n->ref, n->nargs, args, eq);
    if (s->ncode && s->code[s->ncode - 1].out == slot) s->code[s->ncode - 1].xn = root;
    return slot;
  }
}

static int ce(bg_eqsys *s, int nd, int eq) {
  const eq_node *n = &s->node[nd];
  int args[2], slot;
  switch (n->kind) {
  case EQ_NUM: return new_slot(s, 1, n->c);
  case EQ_X: /* a linearisation source's value (its own equation, or a conflict's) */
    slot = cx(s, n->a, eq);
    for (int k = 0; k < s->lin_nu; k++)
      if (s->lin_ref[k] >= 0 && s->m->elem_expr[s->lin_ref[k]] == n->a)
        return lin_offset(s, s->lin_ref[k], slot, eq);
    return slot;
  case EQ_SIG:
    slot = s->sig_slot[n->a];
    if (slot < 0) BG_FATAL("eqsys: bond variable used before it is computed");
    return slot;
  case EQ_Y: return s->slot_y + n->a;
  case EQ_YP: return s->slot_yp + n->a;
  case EQ_MUL: case EQ_DIV:
    args[0] = ce(s, n->a, eq), args[1] = ce(s, n->b, eq);
    return emit(s, n->kind == EQ_MUL ? BG_X_MUL : BG_X_DIV, 0, 2, args, eq);
  default: { /* EQ_LIN: children first, then the terms contiguously */
    if (n->b == 1 && s->lin_coef[n->a] == 1) return ce(s, s->lin_node[n->a], eq);
    int tmp[64], *cs = n->b <= 64 ? tmp : bg_xmalloc((size_t)n->b * sizeof(int));
    for (int k = 0; k < n->b; k++) cs[k] = ce(s, s->lin_node[n->a + k], eq);
    int adr = s->ntl;
    for (int k = 0; k < n->b; k++) tl_push(s, cs[k], s->lin_coef[n->a + k]);
    if (cs != tmp) free(cs);
    return emit(s, T_LIN, adr, n->b, NULL, eq);
  }
  }
}

int bg_eqs_cx(bg_eqsys *s, int root, int eq) { return cx(s, root, eq); }

/* The run's outputs (CSV columns): the plot expressions, else the states
 * followed by the detectors (docs/simulation.md, "CSV"). */
static void compile_outputs(bg_eqsys *s) {
  const bg_model *m = s->m;
  int np = m->nplotexpr;
  s->nout = np ? np : s->nx + m->ndet;
  s->out_name = bg_arena_alloc(&s->arena, (size_t)(s->nout + 1) * sizeof(char *));
  s->out_slot = bg_arena_alloc(&s->arena, (size_t)(s->nout + 1) * sizeof(int));
  for (int k = 0; k < s->nout; k++) {
    if (np) {
      s->out_name[k] = m->plotexpr_text[k];
      s->out_slot[k] = cx(s, m->plotexpr_root[k], -1000000 - k);
    } else if (k < s->nx) {
      s->out_name[k] = s->uname[k];
      s->out_slot[k] = s->slot_y + k;
    } else {
      int d = k - s->nx, o = 0; /* errors are named by the detector's output */
      while (o < m->noutput && m->output_det[o] != d) o++;
      s->out_name[k] = m->det_name[d];
      s->out_slot[k] = cx(s, m->det_expr[d], -2000000 - o);
    }
  }
  for (int k = 0; k < s->lin_nh; k++) s->lin_hslot[k] = cx(s, m->output_expr[k], -2000000 - k);
}

/* Marks the instructions the output slots depend on (a walk back from
 * them through the instruction that writes each slot) and keeps them in
 * tape order, with the unknowns and derivatives they read. */
static int *slice_list(bg_eqsys *s, const unsigned char *mark, int lo, int hi, int *cnt) {
  int c = 0;
  for (int i = lo; i < hi; i++) c += mark[i];
  int *L = bg_arena_alloc(&s->arena, (size_t)(c + 1) * sizeof(int));
  c = 0;
  for (int i = lo; i < hi; i++)
    if (mark[i]) L[c++] = i - lo;
  *cnt = c;
  return L;
}

static void compile_output_slice(bg_eqsys *s) {
  int *prod = bg_xmalloc((size_t)s->nslot * sizeof(int));
  int *stack = bg_xmalloc((size_t)(s->nslot + 1) * sizeof(int)), top = 0;
  unsigned char *seen = bg_xcalloc((size_t)s->nslot, 1), *used = bg_xcalloc((size_t)s->ncode + 1, 1);
  for (int i = 0; i < s->nslot; i++) prod[i] = -1;
  for (int k = 0; k < s->nout_code; k++) prod[s->code[k].out] = k;
  for (int k = 0; k < s->nout; k++)
    if (!seen[s->out_slot[k]]) seen[s->out_slot[k]] = 1, stack[top++] = s->out_slot[k];
  while (top) {
    int k = prod[stack[--top]];
    if (k < 0 || used[k]) continue;
    used[k] = 1;
    const tinstr *I = &s->code[k];
    int na = I->op == T_LIN ? I->a[0] : I->na;
    for (int a = 0; a < na; a++) {
      int sl = I->op == T_LIN ? s->tl_slot[I->ref + a] : I->a[a];
      if (!seen[sl]) seen[sl] = 1, stack[top++] = sl;
    }
  }
  int c = 0;
  for (int k = 0; k < s->nout_code; k++) c += used[k];
  s->oslice = bg_arena_alloc(&s->arena, (size_t)(c + 1) * sizeof(int));
  for (int k = 0; k < s->nout_code; k++)
    if (used[k]) s->oslice[s->noslice++] = k;
  s->oslice_y = slice_list(s, seen, s->slot_y, s->slot_y + s->n, &s->noslice_y);
  s->oslice_yp = slice_list(s, seen, s->slot_yp, s->slot_yp + s->n, &s->noslice_yp);
  free(prod), free(stack), free(seen), free(used);
}

/* 1 when the expression reads a param. */
static int reads_param(const bg_model *m, int root) {
  const bg_xnode *n = &m->xnode[root];
  if (n->op == BG_X_PARAM) return 1;
  for (int k = 0; k < n->nargs && n->op != BG_X_NUM; k++)
    if (reads_param(m, n->arg[k])) return 1;
  return 0;
}

/* Export builds: a slot per param, then the code of the params defined by
 * others (in definition order, so each reads only earlier ones). */
static void live_param_slots(bg_eqsys *s) {
  const bg_model *m = s->m;
  s->param_slot = bg_arena_alloc(&s->arena, (size_t)(m->nparam + 1) * sizeof(int));
  for (int k = 0; k < m->nparam; k++) s->param_slot[k] = new_slot(s, 0, m->param_value[k]);
  for (int k = 0; k < m->nparam; k++)
    if (bg_eqsys_param_is_derived(s, k)) s->param_slot[k] = cx(s, m->param_expr[k], -5000000 - k);
}

int bg_eqsys_param_is_derived(const bg_eqsys *s, int k) {
  const bg_model *m = s->m;
  return !m->param_overridden[k] && m->param_expr[k] >= 0 && reads_param(m, m->param_expr[k]);
}

/* Initial values as code (export builds): the expressions of q0, p0 and
 * state initial values, so exported code recomputes them from its params. */
static void compile_initial(bg_eqsys *s) {
  const bg_model *m = s->m;
  s->init_slot = bg_arena_alloc(&s->arena, (size_t)(s->n + 1) * sizeof(int));
  for (int i = 0; i < s->n; i++) {
    int root = s->u_elem[i] >= 0 ? m->elem_init[s->u_elem[i]] : s->u_state[i] >= 0 ? m->state_init[s->u_state[i]] : -1;
    s->init_slot[i] = root >= 0 ? cx(s, root, -4000000 - i) : -1;
  }
}

void bg_eqs_compile(bg_eqsys *s) {
  int n = s->n;
  new_slot(s, 0, 0); /* t */
  s->slot_y = 1, s->slot_yp = 1 + n;
  for (int i = 0; i < 2 * n; i++) new_slot(s, 0, 0);
  s->slot_p = s->nslot;
  if (s->live_params) live_param_slots(s);
  s->sig_slot = bg_arena_alloc(&s->arena, (size_t)(s->nsig + 1) * sizeof(int));
  s->row_slot = bg_arena_alloc(&s->arena, (size_t)(n + 1) * sizeof(int));
  s->input_slot = bg_arena_alloc(&s->arena, (size_t)(s->m->ninput + 1) * sizeof(int));
  for (int k = 0; k < s->m->ninput; k++) s->input_slot[k] = -1;
  for (int k = 0; k < s->lin_nu; k++) s->lin_uslot[k] = new_slot(s, 0, 0);
  for (int v = 0; v < s->nsig; v++) s->sig_slot[v] = s->sig_torn[v] ? s->slot_y + s->sig_z[v] : -1;
  for (int k = 0; k < s->norder; k++) {
    int v = s->order[k];
    s->sig_slot[v] = ce(s, s->sig_root[v], v);
  }
  for (int i = 0; i < n; i++) s->row_slot[i] = ce(s, s->row_root[i], -1 - i);
  s->nmain = s->ncode;
  compile_outputs(s);
  s->nout_code = s->ncode;
  compile_output_slice(s);
  if (s->live_params) compile_initial(s);
  s->dv = bg_xcalloc((size_t)s->nslot + 1, sizeof(double));
}

void bg_eqs_tape_free(bg_eqsys *s) {
  free(s->code), free(s->tl_slot), free(s->tl_coef), free(s->v), free(s->dv), free(s->is_const);
}

/* ------------------------------------------------------------ derivatives */
/* a + b with the exact-cancellation rule of docs/equations.md. */
static double csum(double a, double b) {
  double r = a + b;
  return fabs(r) <= 16 * DBL_EPSILON * (fabs(a) + fabs(b)) ? 0.0 : r;
}

static double pow_der(double x, double y, double v, double dx, double dy) {
  double r = dx != 0 ? dx * (y == 0 ? 0 : y * pow(x, y - 1)) : 0;
  if (dy != 0) r = csum(r, dy * v * log(x));
  return r;
}

static double call_der(int fn, const double *x, const double *d, double v) {
  switch (fn) {
  case BG_FN_ABS: return x[0] > 0 ? d[0] : x[0] < 0 ? -d[0] : 0;
  case BG_FN_SQRT: return d[0] / (2 * v);
  case BG_FN_EXP: return v * d[0];
  case BG_FN_LOG: return d[0] / x[0];
  case BG_FN_LOG10: return d[0] / (x[0] * log(10.0));
  case BG_FN_SIN: return cos(x[0]) * d[0];
  case BG_FN_COS: return -sin(x[0]) * d[0];
  case BG_FN_TAN: return (1 + v * v) * d[0];
  case BG_FN_ASIN: return d[0] / sqrt(1 - x[0] * x[0]);
  case BG_FN_ACOS: return -d[0] / sqrt(1 - x[0] * x[0]);
  case BG_FN_ATAN: return d[0] / (1 + x[0] * x[0]);
  case BG_FN_ATAN2: return csum(x[1] * d[0], -x[0] * d[1]) / (x[0] * x[0] + x[1] * x[1]);
  case BG_FN_SINH: return cosh(x[0]) * d[0];
  case BG_FN_COSH: return sinh(x[0]) * d[0];
  case BG_FN_TANH: return (1 - v * v) * d[0];
  case BG_FN_MIN: return x[0] <= x[1] ? d[0] : d[1];
  case BG_FN_MAX: return x[0] >= x[1] ? d[0] : d[1];
  case BG_FN_POW: return pow_der(x[0], x[1], v, d[0], d[1]);
  case BG_FN_IF: return x[0] != 0 ? d[1] : d[2];
  case BG_FN_RAMP: return x[0] < 0 ? 0 : d[0];
  case BG_FN_SAT: return x[0] < x[1] ? d[1] : x[0] > x[2] ? d[2] : d[0];
  default: return 0; /* sign, floor, ceil, step, pulse: piecewise constant */
  }
}

static double ins_der(const bg_eqsys *s, const tinstr *I, const double *v, const double *dv) {
  if (I->op == T_LIN) {
    double r = 0, mag = 0;
    for (int k = 0; k < I->a[0]; k++) {
      double t = s->tl_coef[I->ref + k] * dv[s->tl_slot[I->ref + k]];
      r += t, mag += fabs(t);
    }
    return fabs(r) <= 16 * DBL_EPSILON * mag ? 0.0 : r;
  }
  double x[3] = {0, 0, 0}, d[3] = {0, 0, 0};
  int any = 0;
  for (int k = 0; k < I->na; k++) x[k] = v[I->a[k]], d[k] = dv[I->a[k]], any |= d[k] != 0;
  if (!any) return 0; /* also keeps 0 * inf (sqrt at 0) out of constant directions */
  double y = v[I->out];
  switch (I->op) {
  case BG_X_NEG: return -d[0];
  case BG_X_ADD: return csum(d[0], d[1]);
  case BG_X_SUB: return csum(d[0], -d[1]);
  case BG_X_MUL: return csum(d[0] == 0 ? 0 : d[0] * x[1], d[1] == 0 ? 0 : x[0] * d[1]);
  case BG_X_DIV: return csum(d[0], d[1] == 0 ? 0 : -y * d[1]) / x[1];
  case BG_X_POW: return pow_der(x[0], x[1], y, d[0], d[1]);
  case BG_X_CALL: return call_der(I->ref, x, d, y);
  case BG_X_TABLE: return bg_table_slope(s->m, I->ref, x[0]) * d[0];
  default: return 0; /* comparisons and logic; T_DTABLE: a piecewise-linear table's slope is piecewise constant */
  }
}

/* ------------------------------------------------------------ evaluation */
/* What went wrong in instruction I, whose arguments are finite and whose
 * value is not. */
static const char *what_failed(const bg_eqsys *s, const tinstr *I) {
  double x0 = s->v[I->a[0]];
  const char *what = "a value that is not a finite number";
  if (I->op == BG_X_DIV) what = "a division by zero";
  else if (I->op == BG_X_POW || (I->op == BG_X_CALL && I->ref == BG_FN_POW)) what = "a power outside its domain";
  else if (I->op == BG_X_CALL && I->ref == BG_FN_SQRT && x0 < 0) what = "sqrt of a negative number";
  else if (I->op == BG_X_CALL && (I->ref == BG_FN_LOG || I->ref == BG_FN_LOG10) && x0 <= 0) what = "log of a non-positive number";
  else if (I->op == BG_X_CALL && (I->ref == BG_FN_ASIN || I->ref == BG_FN_ACOS)) what = "asin/acos of a number outside [-1, 1]";
  else if (I->op == BG_X_CALL) what = "an overflow in a function";
  return what;
}

static void describe(bg_eqsys *s, const tinstr *I, double t) {
  const bg_model *m = s->m;
  const char *what = what_failed(s, I);
  char where[160];
  if (I->eq >= 0) {
    int e = s->sig_elem[I->eq];
    snprintf(where, sizeof where, "the %s of %s", s->sig_what[I->eq], m->elem_name[e]);
  } else if (I->eq > -1000000) {
    snprintf(where, sizeof where, "the equation of %s", s->uname[-1 - I->eq]);
  } else if (I->eq <= -5000000) {
    snprintf(where, sizeof where, "the definition of param %s", m->param_name[-5000000 - I->eq]);
  } else if (I->eq <= -4000000) {
    snprintf(where, sizeof where, "the initial value of %s", s->uname[-4000000 - I->eq]);
  } else if (I->eq <= -2000000) {
    snprintf(where, sizeof where, "output %s", m->output_name[-2000000 - I->eq]);
  } else {
    snprintf(where, sizeof where, "plot expression %s", m->plotexpr_text[-1000000 - I->eq]);
  }
  snprintf(s->err, sizeof s->err, "%s in %s at t = %g", what, where, t);
}


/* The first argument slot of I that is not finite, or -1. */
static int bad_arg(const bg_eqsys *s, const tinstr *I) {
  int n = I->op == T_LIN ? I->a[0] : I->na;
  for (int q = 0; q < n && (I->op == T_LIN || q < 3); q++) {
    int slot = I->op == T_LIN ? s->tl_slot[I->ref + q] : I->a[q];
    if (!isfinite(s->v[slot])) return slot;
  }
  return -1;
}

const char *bg_eqs_why_not_finite(const bg_eqsys *s, int slot) {
  /* arguments are computed before their readers: the walk only goes back */
  for (int k = s->nmain - 1; k >= 0; k--) {
    if (s->code[k].out != slot) continue;
    int next = bad_arg(s, &s->code[k]);
    if (next < 0) return what_failed(s, &s->code[k]);
    slot = next;
  }
  return "a value that is not a finite number"; /* an unknown itself */
}

static int diagnose(bg_eqsys *s, int c0, int c1, double t) {
  s->has_err = 1;
  for (int i = 0; i < s->n; i++)
    if (!isfinite(s->v[s->slot_y + i])) {
      snprintf(s->err, sizeof s->err, "the unknown %s is not a finite number at t = %g",
               s->uname[i], t);
      return -1;
    }
  for (int k = c0; k < c1; k++) {
    const tinstr *I = &s->code[k];
    if (isfinite(s->v[I->out])) continue;
    describe(s, I, t);
    return -1;
  }
  snprintf(s->err, sizeof s->err, "a value that is not a finite number at t = %g", t);
  return -1;
}

/* The code [0, c1): with the modes of the state events frozen between
 * events (docs/simulation.md, "State events"), or as compiled. A model
 * without events never takes the first loop. */
static void run_code(bg_eqsys *s, int c1, int frozen) {
  double *v = s->v;
  s->vals_frozen = frozen;
  /* memory (hyst, stick) keeps its mode during a run even where the rest
   * is evaluated as compiled: its mode is its value */
  if (frozen || (s->ev_frozen && s->nmem)) {
    for (int k = 0; k < c1; k++) {
      int e = k < s->nmain ? s->code_ev[k] : -1;
      if (e >= 0 && !frozen && !s->ev_mem[e]) e = -1;
      v[s->code[k].out] = e >= 0 ? bg_eqs_ev_value(s, e, v) : ins_fast(s, &s->code[k], v);
    }
    return;
  }
  for (int k = 0; k < c1; k++) v[s->code[k].out] = ins_fast(s, &s->code[k], v);
}

static void load_point(bg_eqsys *s, double t, const double *y, const double *yp) {
  double *v = s->v;
  int n = s->n;
  v[0] = t;
  memcpy(v + s->slot_y, y, (size_t)n * sizeof *v);
  if (yp) memcpy(v + s->slot_yp, yp, (size_t)n * sizeof *v);
  else memset(v + s->slot_yp, 0, (size_t)n * sizeof *v);
}

void bg_eqs_eval_raw(bg_eqsys *s, double t, const double *y, const double *yp) {
  load_point(s, t, y, yp);
  run_code(s, s->nmain, s->ev_frozen && s->nev);
}

static int eval_bad(const bg_eqsys *s, int outputs) {
  const double *v = s->v;
  int bad = 0;
  for (int i = 0; i < s->n; i++) bad |= !isfinite(v[s->row_slot[i]]);
  for (int k = 0; outputs && k < s->nout; k++) bad |= !isfinite(v[s->out_slot[k]]);
  for (int k = 0; outputs && k < s->lin_nh; k++) bad |= !isfinite(v[s->lin_hslot[k]]);
  return bad;
}

int bg_eqs_eval(bg_eqsys *s, double t, const double *y, const double *yp, int outputs) {
  int c1 = outputs ? s->nout_code : s->nmain;
  load_point(s, t, y, yp);
  run_code(s, c1, s->ev_frozen && s->nev);
  s->has_err = 0;
  /* A frozen branch continued past its switching point can leave a law's
   * domain (sqrt(abs(e)) with abs held at +e while e < 0): the values as
   * compiled then, which are what the model means anyway. */
  if (s->vals_frozen && eval_bad(s, outputs)) run_code(s, c1, 0);
  return eval_bad(s, outputs) ? diagnose(s, 0, c1, t) : 0;
}

/* diagnose() for the outputs' slice: only what the slice read and wrote. */
static int diagnose_slice(bg_eqsys *s, double t) {
  s->has_err = 1;
  for (int k = 0; k < s->noslice_y; k++) {
    int i = s->oslice_y[k];
    if (isfinite(s->v[s->slot_y + i])) continue;
    snprintf(s->err, sizeof s->err, "the unknown %s is not a finite number at t = %g",
             s->uname[i], t);
    return -1;
  }
  for (int k = 0; k < s->noslice; k++) {
    const tinstr *I = &s->code[s->oslice[k]];
    if (isfinite(s->v[I->out])) continue;
    describe(s, I, t);
    return -1;
  }
  snprintf(s->err, sizeof s->err, "a value that is not a finite number at t = %g", t);
  return -1;
}

/* run_code() on the outputs' slice. */
static void run_slice(bg_eqsys *s, int frozen) {
  double *v = s->v;
  s->vals_frozen = frozen;
  for (int q = 0; q < s->noslice; q++) {
    int k = s->oslice[q], e = s->nev && k < s->nmain ? s->code_ev[k] : -1;
    if (e >= 0 && !frozen && !(s->ev_frozen && s->ev_mem[e])) e = -1;
    v[s->code[k].out] = e >= 0 ? bg_eqs_ev_value(s, e, v) : ins_fast(s, &s->code[k], v);
  }
}

static int outputs_bad(const bg_eqsys *s) {
  int bad = 0;
  for (int k = 0; k < s->nout; k++) bad |= !isfinite(s->v[s->out_slot[k]]);
  return bad;
}

int bg_eqs_eval_outputs(bg_eqsys *s, double t, const double *y, const double *yp) {
  double *v = s->v;
  v[0] = t;
  for (int k = 0; k < s->noslice_y; k++) v[s->slot_y + s->oslice_y[k]] = y[s->oslice_y[k]];
  for (int k = 0; k < s->noslice_yp; k++)
    v[s->slot_yp + s->oslice_yp[k]] = yp ? yp[s->oslice_yp[k]] : 0;
  int frozen = s->ev_frozen && s->nev;
  run_slice(s, frozen);
  s->has_err = 0;
  /* as bg_eqs_eval: a frozen branch past its switching point, the values as compiled */
  if (frozen && outputs_bad(s)) run_slice(s, 0);
  return outputs_bad(s) ? diagnose_slice(s, t) : 0;
}

/* ------------------------------------------------------------ Jacobians */
static void seed(bg_eqsys *s, int c, double sy, double syp) {
  memset(s->dv + s->slot_y, 0, (size_t)(2 * s->n) * sizeof(double));
  for (int k = s->color_adr[c]; k < s->color_adr[c + 1]; k++) {
    int j = s->color_cols[k];
    s->dv[s->slot_y + j] = sy, s->dv[s->slot_yp + j] = syp;
  }
  if (s->vals_frozen) {
    for (int k = 0; k < s->nmain; k++) {
      int e = s->code_ev[k];
      s->dv[s->code[k].out] = e >= 0 && !s->ev_free[e] ? ev_der(s, e, s->v, s->dv)
                                                       : ins_der(s, &s->code[k], s->v, s->dv);
    }
    return;
  }
  for (int k = 0; k < s->nmain; k++) s->dv[s->code[k].out] = ins_der(s, &s->code[k], s->v, s->dv);
}

void bg_eqs_jac(bg_eqsys *s, double cj, int resid, double *J, int sparse, int only_y, int only_yp) {
  int n = s->n;
  double sy = only_yp ? 0 : 1, syp = only_y ? 0 : only_yp ? 1 : cj;
  if (!sparse) memset(J, 0, (size_t)n * (size_t)n * sizeof *J);
  for (int c = 0; c < s->ncolor; c++) {
    seed(s, c, sy, syp);
    for (int q = s->color_adr[c]; q < s->color_adr[c + 1]; q++) {
      int j = s->color_cols[q];
      for (int k = s->colptr[j]; k < s->colptr[j + 1]; k++) {
        int i = s->rowind[k];
        double d = s->dv[s->row_slot[i]];
        if (s->row_kind[i] == 0 && resid) d = (i == j ? syp : 0) - d;
        if (sparse) J[k] = d;
        else J[(size_t)j * n + i] = d;
      }
    }
  }
}

/* ------------------------------------------------------------ pattern */
typedef struct sets { int *adr, *cnt, *pool; int npool, cap; } sets;

static void set_union(sets *S, int out, const int *in, int nin, int *mark, int stamp) {
  S->adr[out] = S->npool;
  for (int k = 0; k < nin; k++) {
    int a = in[k];
    for (int q = S->adr[a]; q < S->adr[a] + S->cnt[a]; q++) {
      int j = S->pool[q];
      if (mark[j] == stamp) continue;
      mark[j] = stamp;
      if (S->npool == S->cap) {
        S->cap = S->cap ? 2 * S->cap : 1024;
        S->pool = bg_xrealloc(S->pool, (size_t)S->cap * sizeof(int));
      }
      S->pool[S->npool++] = j;
    }
  }
  S->cnt[out] = S->npool - S->adr[out];
}

/* Column j of row i is structurally nonzero when the row reads y_j or yp_j. */
static void slot_sets(bg_eqsys *s, sets *S, int *mark) {
  int n = s->n;
  S->adr = bg_xcalloc((size_t)s->nslot + 1, sizeof(int));
  S->cnt = bg_xcalloc((size_t)s->nslot + 1, sizeof(int));
  S->cap = 2 * n + 16, S->pool = bg_xmalloc((size_t)S->cap * sizeof(int));
  for (int j = 0; j < n; j++) {
    S->adr[s->slot_y + j] = S->npool, S->cnt[s->slot_y + j] = 1, S->pool[S->npool++] = j;
    S->adr[s->slot_yp + j] = S->npool, S->cnt[s->slot_yp + j] = 1, S->pool[S->npool++] = j;
  }
  int tmp[3];
  for (int k = 0; k < s->nmain; k++) {
    const tinstr *I = &s->code[k];
    if (I->op == T_LIN) set_union(S, I->out, s->tl_slot + I->ref, I->a[0], mark, k + 1);
    else {
      for (int q = 0; q < I->na; q++) tmp[q] = I->a[q];
      set_union(S, I->out, tmp, I->na, mark, k + 1);
    }
  }
}

/* A long row (a junction's balance over 10^5 stores) keeps the colours its
 * columns took: visiting the whole row for each of its columns made the
 * colouring quadratic in the row's length. */
enum { DENSE_ROW = 64 };
typedef struct dense_row { unsigned char *used; int cap, mex; } dense_row;

static int dense_used(const dense_row *d, int c) { return c < d->cap && d->used[c]; }

static void dense_take(dense_row *d, int c) {
  if (c >= d->cap) {
    int cap = d->cap ? d->cap : 64;
    while (cap <= c) cap *= 2;
    d->used = bg_xrealloc(d->used, (size_t)cap);
    memset(d->used + d->cap, 0, (size_t)(cap - d->cap));
    d->cap = cap;
  }
  d->used[c] = 1;
  while (dense_used(d, d->mex)) d->mex++;
}

/* Greedy colouring of the columns: column j takes the smallest colour no
 * column sharing a row with it has (the colours below a long row's mex are
 * all taken, so its columns start there). Linear in the nonzeros for short
 * rows, in the colours tried for long ones. */
static void colour(bg_eqsys *s, const int *radr, const int *rcols) {
  int n = s->n, *forbid = bg_xmalloc((size_t)(n + 1) * sizeof(int));
  dense_row *dr = bg_xcalloc((size_t)n + 1, sizeof *dr);
  s->color = bg_arena_alloc(&s->arena, (size_t)(n + 1) * sizeof(int));
  for (int j = 0; j <= n; j++) s->color[j] = -1, forbid[j] = -1;
  s->ncolor = 0;
  for (int j = 0; j < n; j++) {
    int c = 0;
    for (int k = s->colptr[j]; k < s->colptr[j + 1]; k++) {
      int i = s->rowind[k];
      if (radr[i + 1] - radr[i] > DENSE_ROW) {
        if (dr[i].mex > c) c = dr[i].mex;
        continue;
      }
      for (int q = radr[i]; q < radr[i + 1]; q++)
        if (s->color[rcols[q]] >= 0) forbid[s->color[rcols[q]]] = j;
    }
    for (;;) {
      int taken = forbid[c] == j;
      for (int k = s->colptr[j]; k < s->colptr[j + 1] && !taken; k++) {
        int i = s->rowind[k];
        taken = radr[i + 1] - radr[i] > DENSE_ROW && dense_used(&dr[i], c);
      }
      if (!taken) break;
      c++;
    }
    s->color[j] = c;
    if (c + 1 > s->ncolor) s->ncolor = c + 1;
    for (int k = s->colptr[j]; k < s->colptr[j + 1]; k++) {
      int i = s->rowind[k];
      if (radr[i + 1] - radr[i] > DENSE_ROW) dense_take(&dr[i], c);
    }
  }
  for (int i = 0; i < n; i++) free(dr[i].used);
  free(dr);
  s->color_adr = bg_arena_alloc(&s->arena, (size_t)(s->ncolor + 2) * sizeof(int));
  s->color_cols = bg_arena_alloc(&s->arena, (size_t)(n + 1) * sizeof(int));
  for (int j = 0; j < n; j++) s->color_adr[s->color[j] + 1]++;
  for (int c = 0; c < s->ncolor; c++) s->color_adr[c + 1] += s->color_adr[c];
  int *pos = bg_xcalloc((size_t)s->ncolor + 1, sizeof(int));
  for (int j = 0; j < n; j++) s->color_cols[s->color_adr[s->color[j]] + pos[s->color[j]]++] = j;
  free(pos), free(forbid);
}

void bg_eqs_pattern(bg_eqsys *s) {
  int n = s->n, *mark = bg_xmalloc((size_t)(n + 1) * sizeof(int));
  for (int j = 0; j <= n; j++) mark[j] = -1;
  sets S = {0};
  slot_sets(s, &S, mark);
  /* rows (CSR, with the diagonal), then transposed to CSC */
  int *radr = bg_xcalloc((size_t)n + 1, sizeof(int)), nr = 0, capr = 4 * n + 16;
  int *rcols = bg_xmalloc((size_t)capr * sizeof(int));
  for (int i = 0; i < n; i++) {
    int sl = s->row_slot[i], stamp = -2 - i;
    radr[i] = nr;
    if (nr + S.cnt[sl] + 1 > capr) capr = 2 * (nr + S.cnt[sl] + 1), rcols = bg_xrealloc(rcols, (size_t)capr * sizeof(int));
    rcols[nr++] = i, mark[i] = stamp;
    for (int q = S.adr[sl]; q < S.adr[sl] + S.cnt[sl]; q++)
      if (mark[S.pool[q]] != stamp) mark[S.pool[q]] = stamp, rcols[nr++] = S.pool[q];
  }
  radr[n] = nr;
  s->nnz = nr;
  s->colptr = bg_arena_alloc(&s->arena, (size_t)(n + 1) * sizeof(int));
  s->rowind = bg_arena_alloc(&s->arena, (size_t)(nr + 1) * sizeof(int));
  for (int q = 0; q < nr; q++) s->colptr[rcols[q] + 1]++;
  for (int j = 0; j < n; j++) s->colptr[j + 1] += s->colptr[j];
  int *pos = bg_xcalloc((size_t)n + 1, sizeof(int));
  for (int i = 0; i < n; i++) /* rows in increasing order within each column */
    for (int q = radr[i]; q < radr[i + 1]; q++) s->rowind[s->colptr[rcols[q]] + pos[rcols[q]]++] = i;
  colour(s, radr, rcols);
  free(pos), free(radr), free(rcols), free(mark), free(S.adr), free(S.cnt), free(S.pool);
}

/* ------------------------------------------------------------ linear analysis */
/* One forward pass through the whole tape (equations and outputs) in the
 * direction seeded into dv (y, yp and u slots); values must be current. */
static void sweep_all(bg_eqsys *s) {
  for (int k = 0; k < s->ncode; k++) s->dv[s->code[k].out] = ins_der(s, &s->code[k], s->v, s->dv);
}

/* Column j of the residual and output derivatives for the current direction. */
static void io_column(const bg_eqsys *s, int j, double *F, double *H) {
  int n = s->n;
  for (int i = 0; F && i < n; i++) {
    double d = s->dv[s->row_slot[i]];
    F[(size_t)j * n + i] = s->row_kind[i] == 0 ? s->dv[s->slot_yp + i] - d : d;
  }
  for (int k = 0; H && k < s->lin_nh; k++) H[(size_t)j * s->lin_nh + k] = s->dv[s->lin_hslot[k]];
}

int bg_eqsys_jac_io(bg_eqsys *s, double t, const double *y, const double *yp, double *Fy,
                    double *Fyp, double *Fu, double *Hy, double *Hyp, double *Hu, double *h) {
  if (bg_eqs_eval(s, t, y, yp, 1)) return -1;
  for (int k = 0; h && k < s->lin_nh; k++) h[k] = s->v[s->lin_hslot[k]];
  int n = s->n, nu = s->lin_nu;
  for (int dir = 0; dir < 2 * n + nu; dir++) {
    int which = dir < n ? 0 : dir < 2 * n ? 1 : 2, j = which == 0 ? dir : which == 1 ? dir - n : dir - 2 * n;
    double *F = which == 0 ? Fy : which == 1 ? Fyp : Fu, *H = which == 0 ? Hy : which == 1 ? Hyp : Hu;
    if (!F && !H) continue;
    memset(s->dv, 0, (size_t)s->nslot * sizeof *s->dv);
    s->dv[which == 0 ? s->slot_y + j : which == 1 ? s->slot_yp + j : s->lin_uslot[j]] = 1;
    sweep_all(s);
    io_column(s, j, F, H);
  }
  return 0;
}

/* ------------------------------------------------------------ modes */
/* What an instruction with a switching condition gives in its current mode
 * (the mode itself is decided by eqsys_events.c at events): the tape's own
 * evaluation of those instructions, so the tape calls nothing above it. */
/* Value (der = 0) or slope (der = 1) of segment k, continued linearly. */
static double table_segment_val(const bg_model *m, int table, int k, double x, int der) {
  const double *tx = m->table_x + m->table_adr[table], *ty = m->table_y + m->table_adr[table];
  int n = m->table_n[table];
  if (k < 0 || k >= n - 1) return der ? 0 : ty[k < 0 ? 0 : n - 1];
  double slope = (ty[k + 1] - ty[k]) / (tx[k + 1] - tx[k]);
  return der ? slope : ty[k] + slope * (x - tx[k]);
}

double bg_eqs_ev_value(const bg_eqsys *s, int e, const double *v) {
  if (s->ev_free[e] && !s->ev_mem[e]) return bg_eqs_ins_value(s, s->ev_code[e], v);
  const tinstr *I = &s->code[s->ev_code[e]];
  double mode = s->ev_mode[e], x = v[I->a[0]];
  if (I->op == BG_X_TABLE) return table_segment_val(s->m, I->ref, (int)mode, x, 0);
  if (I->op != BG_X_CALL) return mode;
  switch (I->ref) {
  case BG_FN_ABS: return mode ? x : -x;
  case BG_FN_RAMP: return mode ? x : 0;
  case BG_FN_MIN: case BG_FN_MAX: return mode ? x : v[I->a[1]];
  case BG_FN_SAT: return mode == 0 ? v[I->a[1]] : mode == 2 ? v[I->a[2]] : x;
  default: return mode; /* sign, step, pulse, floor, ceil, hyst, stick */
  }
}

static double ev_der(const bg_eqsys *s, int e, const double *v, const double *dv) {
  const tinstr *I = &s->code[s->ev_code[e]];
  double mode = s->ev_mode[e], d = dv[I->a[0]];
  if (I->op == BG_X_TABLE) return table_segment_val(s->m, I->ref, (int)mode, v[I->a[0]], 1) * d;
  if (I->op != BG_X_CALL) return 0;
  switch (I->ref) {
  case BG_FN_ABS: return mode ? d : -d;
  case BG_FN_RAMP: return mode ? d : 0;
  case BG_FN_MIN: case BG_FN_MAX: return mode ? d : dv[I->a[1]];
  case BG_FN_SAT: return mode == 0 ? dv[I->a[1]] : mode == 2 ? dv[I->a[2]] : d;
  default: return 0;
  }
}
