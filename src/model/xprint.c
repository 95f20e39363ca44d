/* SPDX-License-Identifier: BSD-3-Clause */
/* Printing model expressions as readable text with minimal parentheses.
 * The text re-parses to the same tree: parentheses are dropped only where
 * precedence and associativity make them redundant, so floating-point
 * evaluation order is preserved ((a - b) - c prints as a - b - c, but
 * a + (b + c) keeps its parentheses). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr.h"

/* Binding strength, weakest first. All comparisons share one level and
 * never chain without parentheses, and && / || never mix without them, so
 * the text means the same whichever of the usual grammars reads it. */
enum {
  PREC_OR = 1, PREC_AND, PREC_CMP, PREC_ADD, PREC_MUL, PREC_UNARY, PREC_POW, PREC_ATOM
};

static int prec_of_op(int op) {
  switch (op) {
  case BG_X_OR: return PREC_OR;
  case BG_X_AND: return PREC_AND;
  case BG_X_LT: case BG_X_LE: case BG_X_GT: case BG_X_GE:
  case BG_X_EQ: case BG_X_NE: return PREC_CMP;
  case BG_X_ADD: case BG_X_SUB: return PREC_ADD;
  case BG_X_MUL: case BG_X_DIV: return PREC_MUL;
  case BG_X_NEG: case BG_X_NOT: return PREC_UNARY;
  case BG_X_POW: return PREC_POW;
  default: return PREC_ATOM;
  }
}

/* A negative literal prints with a leading '-', so it binds like a unary minus. */
static int prec_of(const bg_model *m, int x) {
  const bg_xnode *n = &m->xnode[x];
  if (n->op == BG_X_NUM && signbit(n->num)) return PREC_UNARY;
  return prec_of_op(n->op);
}

static const char *op_text(int op) {
  switch (op) {
  case BG_X_ADD: return " + ";
  case BG_X_SUB: return " - ";
  case BG_X_MUL: return "*";
  case BG_X_DIV: return "/";
  case BG_X_POW: return "^";
  case BG_X_LT: return " < ";
  case BG_X_LE: return " <= ";
  case BG_X_GT: return " > ";
  case BG_X_GE: return " >= ";
  case BG_X_EQ: return " == ";
  case BG_X_NE: return " != ";
  case BG_X_AND: return " && ";
  case BG_X_OR: return " || ";
  case BG_X_NEG: return "-";
  case BG_X_NOT: return "!";
  default: return " ? ";
  }
}

static void put_store(const bg_model *m, int elem, bg_strbuf *out) {
  bg_sb_puts(out, m->elem_name[elem]);
  bg_sb_puts(out, m->elem_kind[elem] == BG_ELEM_I ? ".p" : ".q");
}

static void print_node(const bg_model *m, int x, bg_strbuf *out);

/* Child x of a parent that needs at least binding strength `need`. */
static void print_child(const bg_model *m, int x, int need, bg_strbuf *out) {
  int paren = prec_of(m, x) < need;
  if (paren) bg_sb_putc(out, '(');
  print_node(m, x, out);
  if (paren) bg_sb_putc(out, ')');
}

static void print_args(const bg_model *m, const bg_xnode *n, bg_strbuf *out) {
  for (int i = 0; i < n->nargs; i++) {
    if (i) bg_sb_puts(out, ", ");
    print_node(m, n->arg[i], out);
  }
}

static void print_unary(const bg_model *m, const bg_xnode *n, bg_strbuf *out) {
  bg_sb_puts(out, op_text(n->op));
  /* -(-x) rather than --x, -(x*y) rather than -x*y (which means (-x)*y). */
  print_child(m, n->arg[0], PREC_UNARY + 1, out);
}

/* Strength each operand of a binary operator needs, for left-associative
 * operators and right-associative ^. Comparisons and mixed && / || always
 * get parentheses (see the enum). A unary right operand of arithmetic is
 * parenthesised for readability: a*(-b), a - (-b). */
static void binary_needs(const bg_model *m, const bg_xnode *n, int *lneed, int *rneed) {
  int p = prec_of_op(n->op);
  *lneed = p;
  *rneed = p + 1;
  if (n->op == BG_X_POW) { *lneed = p + 1; *rneed = p; }
  if (p == PREC_CMP) *lneed = *rneed = PREC_CMP + 1;
  if (p == PREC_AND || p == PREC_OR) {
    *lneed = *rneed = PREC_CMP;
    if (m->xnode[n->arg[0]].op == n->op) *lneed = p; /* a && b && c */
  }
  if (p >= PREC_ADD && prec_of(m, n->arg[1]) == PREC_UNARY) *rneed = PREC_UNARY + 1;
}

static int is_binary(int op) { return op >= BG_X_ADD && op <= BG_X_OR; }

/* a + b + c + ... comes as a left-deep tree of any depth (it needs no
 * parentheses): its left spine is collected on an explicit stack, and only
 * right operands and parenthesised parts recurse. */
static void print_binary(const bg_model *m, const bg_xnode *n, bg_strbuf *out) {
  const bg_xnode *local[32], **spine = local;
  int k = 0, cap = 32, lneed, rneed;
  for (;;) {
    if (k == cap) {
      const bg_xnode **grown = bg_xmalloc(2 * (size_t)cap * sizeof *grown);
      memcpy(grown, spine, (size_t)cap * sizeof *grown);
      if (spine != local) free(spine);
      spine = grown;
      cap *= 2;
    }
    spine[k++] = n;
    binary_needs(m, n, &lneed, &rneed);
    if (!is_binary(m->xnode[n->arg[0]].op) || prec_of(m, n->arg[0]) < lneed) break;
    n = &m->xnode[n->arg[0]];
  }
  print_child(m, n->arg[0], lneed, out);
  while (k-- > 0) {
    binary_needs(m, spine[k], &lneed, &rneed);
    bg_sb_puts(out, op_text(spine[k]->op));
    print_child(m, spine[k]->arg[1], rneed, out);
  }
  if (spine != local) free(spine);
}

static void print_node(const bg_model *m, int x, bg_strbuf *out) {
  const bg_xnode *n = &m->xnode[x];
  switch (n->op) {
  case BG_X_NUM: bg_sb_num(out, n->num); break;
  case BG_X_TIME: bg_sb_putc(out, 't'); break;
  case BG_X_PARAM: bg_sb_puts(out, m->param_name[n->ref]); break;
  case BG_X_INPUT: bg_sb_puts(out, m->input_name[n->ref]); break;
  case BG_X_STATE: bg_sb_puts(out, m->state_name[n->ref]); break;
  case BG_X_EFFORT: bg_sb_printf(out, "e%d", m->bond_num[n->ref]); break;
  case BG_X_FLOW: bg_sb_printf(out, "f%d", m->bond_num[n->ref]); break;
  case BG_X_STORE: put_store(m, n->ref, out); break;
  case BG_X_CALL:
    bg_sb_printf(out, "%s(", bg_func_name(n->ref));
    print_args(m, n, out);
    bg_sb_putc(out, ')');
    break;
  case BG_X_TABLE:
    bg_sb_puts(out, "table(");
    print_node(m, n->arg[0], out);
    bg_sb_printf(out, ", #%d)", n->ref);
    break;
  case BG_X_NEG: case BG_X_NOT: print_unary(m, n, out); break;
  default: print_binary(m, n, out); break;
  }
}

void bg_xprint(const bg_model *m, int root, bg_strbuf *out) { print_node(m, root, out); }
