/* SPDX-License-Identifier: BSD-3-Clause */
/* Symbolic expressions (sym.h) compiled to the tape of a bg_eqsys, so the
 * reduced system's differentiated equations evaluate, and are
 * differentiated exactly, like every other equation (eqsys_tape.c). Sums
 * become one linear combination, products numerator / denominator as the
 * symbolic evaluator computes them. Recursion follows the expression depth,
 * as every walk of the symbolic layer does. */
#include <stdlib.h>

#include "equations/indexred_int.h"
#include "model/model.h"

static int pow_slot(bg_eqsys *r, int a, double w, int eq) {
  if (w == 1) return a;
  int args[2] = {a, w == 2 ? a : bg_eqs_const(r, w)};
  return bg_eqs_emit(r, w == 2 ? BG_X_MUL : BG_X_POW, 0, 2, args, eq);
}

static int times(bg_eqsys *r, int acc, int x, int eq) {
  if (acc < 0) return x;
  int args[2] = {acc, x};
  return bg_eqs_emit(r, BG_X_MUL, 0, 2, args, eq);
}

/* c * prod b_k^w_k as (c * prod_{w > 0} b^w) / prod_{w < 0} b^-w. */
static int product(bg_eqsys *r, bg_sym *S, int e, const int *map, int *memo, int eq) {
  const bg_symnode x = S->node[e];
  int num = x.c != 1 ? bg_eqs_const(r, x.c) : -1, den = -1;
  for (int k = 0; k < x.n; k++) {
    double w = S->w[x.adr + k];
    int b = ir_compile(r, S, S->arg[x.adr + k], map, memo, eq);
    if (w > 0) num = times(r, num, pow_slot(r, b, w, eq), eq);
    else den = times(r, den, pow_slot(r, b, -w, eq), eq);
  }
  if (num < 0) num = bg_eqs_const(r, 1);
  if (den < 0) return num;
  int args[2] = {num, den};
  return bg_eqs_emit(r, BG_X_DIV, 0, 2, args, eq);
}

/* c + sum w_k a_k: the children first, then the terms contiguously. */
static int sum(bg_eqsys *r, bg_sym *S, int e, const int *map, int *memo, int eq) {
  const bg_symnode x = S->node[e];
  int *cs = bg_xmalloc((size_t)(x.n + 1) * sizeof(int));
  for (int k = 0; k < x.n; k++) cs[k] = ir_compile(r, S, S->arg[x.adr + k], map, memo, eq);
  int c = x.c != 0 ? bg_eqs_const(r, x.c) : -1, adr = -1, cnt = 0;
  for (int k = 0; k < x.n; k++, cnt++) {
    int q = bg_eqs_tl_push(r, cs[k], S->w[x.adr + k]);
    if (adr < 0) adr = q;
  }
  if (c >= 0) {
    int q = bg_eqs_tl_push(r, c, 1.0);
    if (adr < 0) adr = q;
    cnt++;
  }
  free(cs);
  return bg_eqs_emit(r, T_LIN, adr, cnt, NULL, eq);
}

static int node(bg_eqsys *r, bg_sym *S, int e, const int *map, int *memo, int eq) {
  const bg_symnode x = S->node[e];
  const bg_model *m = r->m;
  int args[3] = {0, 0, 0};
  switch (x.kind) {
  case SYM_NUM: return bg_eqs_const(r, x.c);
  case SYM_PARAM: return bg_eqs_const(r, m->param_value[x.ref]);
  case SYM_INPUT:
    if (r->input_slot[x.ref] < 0) r->input_slot[x.ref] = bg_eqs_cx(r, m->input_expr[x.ref], eq);
    return r->input_slot[x.ref];
  case SYM_ALIAS: return ir_compile(r, S, S->alias_expr[x.ref], map, memo, eq);
  case SYM_DALIAS: return ir_compile(r, S, S->dalias_expr[x.ref], map, memo, eq);
  case SYM_T: return 0;
  case SYM_Y: return map[x.ref];
  case SYM_YP: return r->slot_yp + x.ref;
  case SYM_SIG: BG_FATAL("indexred: a bond variable left in a reduced equation");
  case SYM_MUL: return product(r, S, e, map, memo, eq);
  case SYM_ADD: return sum(r, S, e, map, memo, eq);
  default: break;
  }
  for (int k = 0; k < x.n && k < 3; k++) args[k] = ir_compile(r, S, S->arg[x.adr + k], map, memo, eq);
  switch (x.kind) {
  case SYM_POW: return bg_eqs_emit(r, BG_X_POW, 0, 2, args, eq);
  case SYM_CALL: return bg_eqs_emit(r, BG_X_CALL, x.ref, x.n, args, eq);
  case SYM_TABLE: return bg_eqs_emit(r, BG_X_TABLE, x.ref, 1, args, eq);
  case SYM_DTABLE: return bg_eqs_emit(r, T_DTABLE, x.ref, 1, args, eq);
  default: return bg_eqs_emit(r, x.ref, 0, x.n, args, eq); /* SYM_OP: comparison, logic */
  }
}

int ir_compile(bg_eqsys *r, bg_sym *S, int e, const int *map, int *memo, int eq) {
  if (memo[e] >= 0) return memo[e];
  int slot = node(r, S, e, map, memo, eq);
  memo[e] = slot;
  return slot;
}
