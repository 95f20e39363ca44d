/* SPDX-License-Identifier: BSD-3-Clause */
/* Register bytecode for model expressions: a compiler from bg_xnode trees
 * and a small VM. Every operator and function goes through the same
 * definitions as the tree evaluator (bg_xop_apply, bg_func_apply,
 * bg_table_lookup, or the identical C operator), so both agree bit for bit.
 *
 * Operands are addressed three ways, spelled in opcode names: R a register,
 * V an entry of the caller's variable vector, K the instruction's constant.
 * Arithmetic has an opcode per operand combination (no separate loads),
 * x + c*y / x - c*y are fused, and a run of them on one register becomes a
 * CHAIN that keeps the running sum out of memory: a linear right-hand side
 * of N terms is about N instructions. Left-deep chains (long sums) compile
 * without recursion. Registers are allocated as a stack during
 * compilation; the register file is sized then and lives in the program.
 * Figures: bench/README.md. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr.h"

#ifdef __clang__
/* x + c*y must round twice, like the tree evaluator (GCC in ISO C mode
 * already never contracts). */
#pragma STDC FP_CONTRACT OFF
#endif

/* Nesting far deeper than the parser allows (~200 plus inlined inputs)
 * means a corrupt tree or an input cycle, not a user model. */
#define MAX_DEPTH 10000

/* ---------------------------------------------------------------- opcodes */
#define RA reg[ip->a]
#define RB reg[ip->b]
#define VA vars[ip->a]
#define VB vars[ip->b]
#define K ip->k

/* + - * / and every other binary operator (BIN, sub = the bg_xop), each
 * with its 8 operand combinations in the order kindA*3 + kindB (R=0, V=1,
 * K=2; K,K never occurs: it folds). */
#define F_ADD(x, y) (x) + (y)
#define F_SUB(x, y) (x) - (y)
#define F_MUL(x, y) (x) * (y)
#define F_DIV(x, y) (x) / (y)
#define F_BIN(x, y) bg_xop_apply(ip->sub, x, y)
#define VM_BINARY(Y, Z)                                                        \
  Y(Z, ADD, F_ADD) Y(Z, SUB, F_SUB) Y(Z, MUL, F_MUL) Y(Z, DIV, F_DIV) Y(Z, BIN, F_BIN)
#define VM_COMBOS(Z, N, F)                                                     \
  Z(N##_RR, F(RA, RB)) Z(N##_RV, F(RA, VB)) Z(N##_RK, F(RA, K))                \
  Z(N##_VR, F(VA, RB)) Z(N##_VV, F(VA, VB)) Z(N##_VK, F(VA, K))                \
  Z(N##_KR, F(K, RB)) Z(N##_KV, F(K, VB))
/* Fused x + c*y and x - c*y, combinations in the order kindX*2 + kindY. */
#define VM_FUSED(Z)                                                            \
  Z(AXPY_RR, RA + K * RB) Z(AXPY_RV, RA + K * VB)                              \
  Z(AXPY_VR, VA + K * RB) Z(AXPY_VV, VA + K * VB)                              \
  Z(AXMY_RR, RA - K * RB) Z(AXMY_RV, RA - K * VB)                              \
  Z(AXMY_VR, VA - K * RB) Z(AXMY_VV, VA - K * VB)
/* The rest of the value-producing instructions (CALL: sub is the bg_func). */
#define VM_OTHER(Z)                                                            \
  Z(LOADK, K) Z(LOADV, VA) Z(NEG_R, -RA) Z(NEG_V, -VA)                         \
  Z(CALL, bg_func_apply(ip->sub, &RA, ip->b))                                  \
  Z(TABLE, bg_table_lookup(p->m, ip->b, RA))
#define VM_VALUE_OPS(Z) VM_BINARY(VM_COMBOS, Z) VM_FUSED(Z) VM_OTHER(Z)
/* Control and output: hand-written in the VM. */
#define VM_CONTROL_OPS(C) C(JZ_R) C(JZ_V) C(JMP) C(OUT_R) C(OUT_V) C(OUT_K) C(END) C(CHAIN)

#define ENUM_VALUE(name, expr) OP_##name,
#define ENUM_CONTROL(name) OP_##name,
/* OP_TERM: data of a CHAIN (never dispatched). */
enum { VM_VALUE_OPS(ENUM_VALUE) VM_CONTROL_OPS(ENUM_CONTROL) OP_COUNT, OP_TERM = OP_COUNT };

enum { KIND_R, KIND_V, KIND_K };

typedef struct vm_instr {
  uint16_t op, sub; /* opcode; bg_xop or bg_func for BIN_* and CALL */
  int32_t d, a, b;  /* destination, operands (b: jump target, nargs, table id) */
  double k;
} vm_instr;

struct bg_prog {
  const bg_model *m; /* borrowed, for tables: must outlive the program */
  vm_instr *code;
  int ncode;
  double *reg;
  int nreg;
};

/* ---------------------------------------------------------------- the VM */
void bg_prog_eval(bg_prog *p, const double *vars, double *out) {
  double *reg = p->reg;
  const vm_instr *ip = p->code;
#ifdef __GNUC__
#define LABEL_VALUE(name, expr) [OP_##name] = &&L_##name,
#define LABEL_CONTROL(name) [OP_##name] = &&L_##name,
  static const void *const dispatch[OP_COUNT] = {
      VM_VALUE_OPS(LABEL_VALUE) VM_CONTROL_OPS(LABEL_CONTROL)};
#define VM_CASE(name) L_##name:
#define VM_NEXT goto *dispatch[ip->op]
  VM_NEXT;
#else
#define VM_CASE(name) case OP_##name:
#define VM_NEXT continue
  for (;;) switch (ip->op) {
#endif
#define HANDLER(name, expr)                                                    \
  VM_CASE(name) reg[ip->d] = (expr);                                           \
  ip++;                                                                        \
  VM_NEXT;
  VM_VALUE_OPS(HANDLER)
  VM_CASE(JZ_R) ip = RA == 0 ? p->code + ip->b : ip + 1; VM_NEXT;
  VM_CASE(JZ_V) ip = VA == 0 ? p->code + ip->b : ip + 1; VM_NEXT;
  VM_CASE(JMP) ip = p->code + ip->b; VM_NEXT;
  VM_CASE(OUT_R) out[ip->d] = RA; ip++; VM_NEXT;
  VM_CASE(OUT_V) out[ip->d] = VA; ip++; VM_NEXT;
  VM_CASE(OUT_K) out[ip->d] = K; ip++; VM_NEXT;
  VM_CASE(END) return;
  /* r[d] = r[a] + k1*v[b1] + k2*v[b2] + ... over the b TERMs that follow,
   * the sum kept in a machine register (x - k*y is stored as x + (-k)*y,
   * which IEEE arithmetic rounds identically). */
  VM_CASE(CHAIN) {
    double s = RA;
    const vm_instr *t = ip + 1, *end = t + ip->b;
    for (; t < end; t++) s = s + t->k * vars[t->b];
    reg[ip->d] = s;
    ip = end;
    VM_NEXT;
  }
#ifndef __GNUC__
  default: BG_FATAL("bg_prog_eval: bad opcode %d", ip->op);
  }
#endif
}

/* ---------------------------------------------------------------- compiler */
typedef struct opnd {
  int kind; /* KIND_R, KIND_V, KIND_K */
  int idx;  /* register or variable slot */
  double k;
} opnd;

typedef struct compiler {
  const bg_model *m;
  const bg_slotmap *map; /* nullable: no variables at all */
  vm_instr *code;
  int n, cap;
  int sp, maxsp;  /* registers in use (a stack) and the high-water mark */
  int label_at;   /* highest instruction index some jump lands on */
  int depth;
  int *spine;     /* left spines of binary chains being compiled (a stack) */
  int nspine, spinecap;
  int chain;      /* index of the last CHAIN instruction, or -1 */
} compiler;

static opnd konst(double k) { return (opnd){KIND_K, -1, k}; }
static opnd inreg(int r) { return (opnd){KIND_R, r, 0}; }

static int emit(compiler *c, int op, int sub, int d, int a, int b, double k) {
  if (c->n == c->cap) {
    c->cap = c->cap ? 2 * c->cap : 64;
    c->code = bg_xrealloc(c->code, (size_t)c->cap * sizeof *c->code);
  }
  c->code[c->n] = (vm_instr){(uint16_t)op, (uint16_t)sub, d, a, b, k};
  return c->n++;
}

static int alloc_reg(compiler *c) {
  int r = c->sp++;
  if (c->sp > c->maxsp) c->maxsp = c->sp;
  return r;
}

/* Releases every register from r up and returns a fresh one at r: the
 * result of a subtree always lands in the first register it was given. */
static int result_reg(compiler *c, int r) {
  c->sp = r;
  return alloc_reg(c);
}

/* Puts o into register r (which must be the top of the stack or free). */
static void to_reg(compiler *c, opnd o, int r) {
  if (o.kind == KIND_R && o.idx == r) return;
  if (o.kind == KIND_K) emit(c, OP_LOADK, 0, r, 0, 0, o.k);
  else if (o.kind == KIND_V) emit(c, OP_LOADV, 0, r, o.idx, 0, 0);
  else BG_FATAL("bg_prog_compile: result in r%d, expected r%d", o.idx, r);
}

/* A V or K operand moved into a new register; R operands stay. */
static opnd materialize(compiler *c, opnd o) {
  if (o.kind == KIND_R) return o;
  int r = alloc_reg(c);
  to_reg(c, o, r);
  return inreg(r);
}

static void mark_label(compiler *c, int pos) {
  if (pos > c->label_at) c->label_at = pos;
}

static opnd compile(compiler *c, int x);

/* ---------------------------------------------------------------- leaves */
static opnd var_slot(const int *slots, int ref, const char *what) {
  if (!slots || slots[ref] < 0)
    BG_FATAL("bg_prog_compile: %s %d has no slot in the variable vector", what, ref);
  return (opnd){KIND_V, slots[ref], 0};
}

static opnd compile_var(compiler *c, const bg_xnode *n) {
  const bg_slotmap *map = c->map;
  switch (n->op) {
  case BG_X_TIME:
    if (!map || map->time_slot < 0) BG_FATAL("bg_prog_compile: time has no slot");
    return (opnd){KIND_V, map->time_slot, 0};
  case BG_X_PARAM:
    if (!map || !map->param_slot) return konst(c->m->param_value[n->ref]);
    return var_slot(map->param_slot, n->ref, "param");
  case BG_X_STATE: return var_slot(map ? map->state_slot : NULL, n->ref, "state");
  case BG_X_EFFORT: return var_slot(map ? map->effort_slot : NULL, n->ref, "effort of bond");
  case BG_X_FLOW: return var_slot(map ? map->flow_slot : NULL, n->ref, "flow of bond");
  default: return var_slot(map ? map->store_slot : NULL, n->ref, "store of element");
  }
}

/* ---------------------------------------------------------------- operators */
static opnd compile_unary(compiler *c, const bg_xnode *n) {
  int s0 = c->sp;
  opnd a = compile(c, n->arg[0]);
  if (a.kind == KIND_K) return konst(bg_xop_apply(n->op, a.k, 0));
  if (n->op == BG_X_NEG) {
    int d = result_reg(c, s0);
    emit(c, a.kind == KIND_R ? OP_NEG_R : OP_NEG_V, 0, d, a.idx, 0, 0);
    return inreg(d);
  }
  emit(c, OP_BIN_RR + a.kind * 3 + a.kind, n->op, result_reg(c, s0), a.idx, a.idx, 0);
  return inreg(s0);
}

/* If the last instruction computes c*y into the register that b names,
 * replaces it by one fused x + c*y (or x - c*y). Not when a jump lands right
 * after it: that jump would skip the fused instruction. */
static int try_fuse(compiler *c, int s0, int op, opnd a, opnd b) {
  if (a.kind == KIND_K || b.kind != KIND_R || c->n == 0 || c->label_at == c->n) return 0;
  const vm_instr *last = &c->code[c->n - 1];
  if (last->d != b.idx) return 0;
  int ykind, y;
  switch (last->op) {
  case OP_MUL_RK: ykind = KIND_R; y = last->a; break;
  case OP_MUL_KR: ykind = KIND_R; y = last->b; break;
  case OP_MUL_VK: ykind = KIND_V; y = last->a; break;
  case OP_MUL_KV: ykind = KIND_V; y = last->b; break;
  default: return 0;
  }
  double k = last->k;
  c->n--;
  int base = op == BG_X_ADD ? OP_AXPY_RR : OP_AXMY_RR;
  emit(c, base + a.kind * 2 + ykind, 0, result_reg(c, s0), a.idx, y, k);
  return 1;
}

static int binary_base(int op) {
  switch (op) {
  case BG_X_ADD: return OP_ADD_RR;
  case BG_X_SUB: return OP_SUB_RR;
  case BG_X_MUL: return OP_MUL_RR;
  case BG_X_DIV: return OP_DIV_RR;
  default: return OP_BIN_RR;
  }
}

/* x*1, 1*x and x/1 are exactly x in IEEE arithmetic: the operand itself,
 * already in place (a K operand holds no register). */
static int is_identity(int op, opnd a, opnd b, opnd *res) {
  if (op == BG_X_MUL && a.kind == KIND_K && a.k == 1) { *res = b; return 1; }
  if ((op == BG_X_MUL || op == BG_X_DIV) && b.kind == KIND_K && b.k == 1) { *res = a; return 1; }
  return 0;
}

/* Long sums x + c1*y1 + c2*y2 + ... would pass every partial sum through
 * memory (a store-to-load latency per term): a run of fused instructions on
 * one register becomes one CHAIN with its TERMs. The just-emitted fused
 * instruction consumes the value of the one before it (a tree value has
 * one consumer) and try_fuse made sure no jump lands between them. */
static void chain_terms(compiler *c) {
  if (c->n < 2) return;
  vm_instr *cur = &c->code[c->n - 1], *prev = &c->code[c->n - 2];
  if ((cur->op != OP_AXPY_RV && cur->op != OP_AXMY_RV) || cur->a != cur->d) return;
  vm_instr term = {OP_TERM, 0, 0, 0, cur->b, cur->op == OP_AXPY_RV ? cur->k : -cur->k};
  int h = c->chain;
  if (h >= 0 && h + c->code[h].b == c->n - 2 && c->code[h].d == cur->a) {
    *cur = term; /* extends the chain that ends right before */
    c->code[h].b++;
    return;
  }
  if ((prev->op != OP_AXPY_RV && prev->op != OP_AXMY_RV) || prev->d != cur->a) return;
  vm_instr first = {OP_TERM, 0, 0, 0, prev->b, prev->op == OP_AXPY_RV ? prev->k : -prev->k};
  *prev = (vm_instr){OP_CHAIN, 0, prev->d, prev->a, 2, 0};
  *cur = first;
  emit(c, OP_TERM, 0, 0, 0, term.b, term.k);
  c->chain = c->n - 3;
}

/* a OP b from compiled operands: a in register s0 if any, b above it. */
static opnd combine(compiler *c, int s0, int op, opnd a, opnd b) {
  if (a.kind == KIND_K && b.kind == KIND_K) return konst(bg_xop_apply(op, a.k, b.k));
  if ((op == BG_X_ADD || op == BG_X_SUB) && try_fuse(c, s0, op, a, b)) {
    chain_terms(c);
    return inreg(s0);
  }
  opnd same;
  if (is_identity(op, a, b, &same)) return same;
  emit(c, binary_base(op) + a.kind * 3 + b.kind, op, result_reg(c, s0), a.idx, b.idx,
       a.kind == KIND_K ? a.k : b.k);
  return inreg(s0);
}

static int is_binary(int op) { return op >= BG_X_ADD && op <= BG_X_OR; }

/* product + non-product: addition commutes exactly in IEEE arithmetic, so
 * the product is compiled last where it can fuse into x + c*y. */
static int swaps(const bg_model *m, const bg_xnode *n) {
  return n->op == BG_X_ADD && m->xnode[n->arg[0]].op == BG_X_MUL &&
         m->xnode[n->arg[1]].op != BG_X_MUL;
}

static opnd compile_swapped(compiler *c, const bg_xnode *n) {
  int s0 = c->sp;
  opnd b = compile(c, n->arg[1]);
  opnd a = compile(c, n->arg[0]);
  return combine(c, s0, n->op, b, a);
}

/* Sums and products of many terms come as left-deep trees of any depth
 * (a + b + c + ... needs no parentheses): the left spine is walked with an
 * explicit stack, and only right operands are compiled recursively. */
static opnd compile_binary(compiler *c, const bg_xnode *n) {
  int s0 = c->sp, base = c->nspine, x = (int)(n - c->m->xnode);
  while (is_binary(c->m->xnode[x].op) && !swaps(c->m, &c->m->xnode[x])) {
    if (c->nspine == c->spinecap) {
      c->spinecap = c->spinecap ? 2 * c->spinecap : 64;
      c->spine = bg_xrealloc(c->spine, (size_t)c->spinecap * sizeof *c->spine);
    }
    c->spine[c->nspine++] = x;
    x = c->m->xnode[x].arg[0];
  }
  const bg_xnode *bottom = &c->m->xnode[x];
  opnd a = is_binary(bottom->op) ? compile_swapped(c, bottom) : compile(c, x);
  for (int i = c->nspine - 1; i >= base; i--) {
    const bg_xnode *up = &c->m->xnode[c->spine[i]];
    opnd b = compile(c, up->arg[1]); /* may grow c->spine: index it afresh */
    a = combine(c, s0, up->op, a, b);
  }
  c->nspine = base;
  return a;
}

/* ---------------------------------------------------------------- calls */
/* if(c, a, b) evaluates only the branch taken, like bg_xeval: a conditional
 * jump around two branches that both leave their value in register s0. */
static opnd compile_if(compiler *c, const bg_xnode *n) {
  int s0 = c->sp;
  opnd cond = compile(c, n->arg[0]);
  if (cond.kind == KIND_K) return compile(c, cond.k != 0 ? n->arg[1] : n->arg[2]);
  int jz = emit(c, cond.kind == KIND_R ? OP_JZ_R : OP_JZ_V, 0, 0, cond.idx, -1, 0);
  c->sp = s0;
  opnd t = compile(c, n->arg[1]);
  to_reg(c, t, result_reg(c, s0));
  int jmp = emit(c, OP_JMP, 0, 0, 0, -1, 0);
  c->code[jz].b = c->n;
  mark_label(c, c->n);
  c->sp = s0;
  opnd e = compile(c, n->arg[2]);
  to_reg(c, e, result_reg(c, s0));
  c->code[jmp].b = c->n;
  mark_label(c, c->n);
  return inreg(s0);
}

/* Arguments go to consecutive registers s0, s0+1, ...; constants are loaded
 * only once it is known that not all of them are constant. */
static opnd compile_call(compiler *c, const bg_xnode *n) {
  if (n->ref == BG_FN_IF) return compile_if(c, n);
  int s0 = c->sp, nconst = 0;
  double kval[3];
  int kreg[3];
  for (int i = 0; i < n->nargs; i++) {
    opnd o = compile(c, n->arg[i]);
    int r = o.kind == KIND_R ? o.idx : alloc_reg(c);
    if (o.kind == KIND_V) to_reg(c, o, r);
    if (o.kind == KIND_K) {
      kval[nconst] = o.k;
      kreg[nconst++] = r;
    }
  }
  if (nconst == n->nargs) {
    c->sp = s0;
    return konst(bg_func_apply(n->ref, kval, n->nargs));
  }
  for (int i = 0; i < nconst; i++) emit(c, OP_LOADK, 0, kreg[i], 0, 0, kval[i]);
  emit(c, OP_CALL, n->ref, result_reg(c, s0), s0, n->nargs, 0);
  return inreg(s0);
}

static opnd compile_table(compiler *c, const bg_xnode *n) {
  int s0 = c->sp;
  opnd x = compile(c, n->arg[0]);
  if (x.kind == KIND_K) return konst(bg_table_lookup(c->m, n->ref, x.k));
  x = materialize(c, x);
  emit(c, OP_TABLE, 0, result_reg(c, s0), x.idx, n->ref, 0);
  return inreg(s0);
}

static opnd compile_node(compiler *c, int x) {
  const bg_xnode *n = &c->m->xnode[x];
  switch (n->op) {
  case BG_X_NUM: return konst(n->num);
  case BG_X_INPUT: return compile(c, c->m->input_expr[n->ref]); /* inlined */
  case BG_X_TIME: case BG_X_PARAM: case BG_X_STATE:
  case BG_X_EFFORT: case BG_X_FLOW: case BG_X_STORE: return compile_var(c, n);
  case BG_X_CALL: return compile_call(c, n);
  case BG_X_TABLE: return compile_table(c, n);
  case BG_X_NEG: case BG_X_NOT: return compile_unary(c, n);
  default: return compile_binary(c, n);
  }
}

/* The one recursive entry point, with the depth guard. */
static opnd compile(compiler *c, int x) {
  if (x < 0 || x >= c->m->nxnode) BG_FATAL("bg_prog_compile: bad node %d", x);
  if (++c->depth > MAX_DEPTH)
    BG_FATAL("bg_prog_compile: expression nested deeper than %d", MAX_DEPTH);
  opnd o = compile_node(c, x);
  c->depth--;
  return o;
}

/* ---------------------------------------------------------------- programs */
static void emit_output(compiler *c, opnd o, int k) {
  if (o.kind == KIND_R) emit(c, OP_OUT_R, 0, k, o.idx, 0, 0);
  else if (o.kind == KIND_V) emit(c, OP_OUT_V, 0, k, o.idx, 0, 0);
  else emit(c, OP_OUT_K, 0, k, 0, 0, o.k);
}

bg_prog *bg_prog_compile(const bg_model *m, const int *roots, int nroots,
                         const bg_slotmap *map) {
  compiler c = {.m = m, .map = map, .label_at = -1, .chain = -1};
  for (int k = 0; k < nroots; k++) {
    c.sp = 0;
    emit_output(&c, compile(&c, roots[k]), k);
  }
  emit(&c, OP_END, 0, 0, 0, 0, 0);
  free(c.spine);
  bg_prog *p = bg_xcalloc(1, sizeof *p);
  p->m = m;
  p->code = c.code;
  p->ncode = c.n;
  p->nreg = c.maxsp;
  p->reg = bg_xcalloc((size_t)(c.maxsp ? c.maxsp : 1), sizeof *p->reg);
  return p;
}

int bg_prog_ninstr(const bg_prog *p) { return p->ncode - 1; /* without END */ }

void bg_prog_free(bg_prog *p) {
  if (!p) return;
  free(p->code);
  free(p->reg);
  free(p);
}
