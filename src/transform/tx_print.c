/* SPDX-License-Identifier: BSD-3-Clause */
/* The statement printer of the transformations: elements and bonds written
 * back from their syntax, expressions by their source text. */
#include <string.h>

#include "transform/tx_int.h"

static void print_string(bg_strbuf *b, const char *s) {
  bg_sb_putc(b, '"');
  for (; *s; s++) {
    if (*s == '"' || *s == '\\') bg_sb_putc(b, '\\');
    bg_sb_putc(b, *s);
  }
  bg_sb_putc(b, '"');
}

static const char *const op_text[] = {
    [BG_OP_ADD] = " + ", [BG_OP_SUB] = " - ", [BG_OP_MUL] = "*", [BG_OP_DIV] = "/",
    [BG_OP_POW] = "^", [BG_OP_LT] = " < ", [BG_OP_LE] = " <= ", [BG_OP_GT] = " > ",
    [BG_OP_GE] = " >= ", [BG_OP_EQ] = " == ", [BG_OP_NE] = " != ", [BG_OP_AND] = " && ",
    [BG_OP_OR] = " || "};

/* Whole expressions carry their text; inner operators are rebuilt, fully
 * parenthesised so the printed text parses to the same tree. */
static void print_expr(bg_strbuf *b, const bg_expr *e) {
  if (e->kind == BG_EX_STR) {
    print_string(b, e->str);
    return;
  }
  if (e->text) {
    bg_sb_puts(b, e->text);
    return;
  }
  switch (e->kind) {
  case BG_EX_NUM: bg_sb_num(b, e->num); return;
  case BG_EX_NAME: bg_sb_puts(b, e->str); return;
  case BG_EX_FIELD: bg_sb_printf(b, "%s.%s", e->str, e->field); return;
  case BG_EX_UNARY:
    bg_sb_puts(b, e->op == BG_OP_NOT ? "!(" : "-(");
    print_expr(b, e->args[0]);
    bg_sb_putc(b, ')');
    return;
  case BG_EX_BINARY:
    bg_sb_putc(b, '(');
    print_expr(b, e->args[0]);
    bg_sb_puts(b, op_text[e->op]);
    print_expr(b, e->args[1]);
    bg_sb_putc(b, ')');
    return;
  default: break;
  }
  /* calls, matrices, tuples: the parser always keeps their text */
  BG_FATAL("expression of kind %d without its text", (int)e->kind);
}

void tx_print_options(bg_strbuf *b, const bg_ast_stmt *s, const char *key, const char *optval) {
  int n = 0, replaced = 0;
  for (int i = 0; i < s->nopts; i++) {
    bg_sb_puts(b, n++ ? ", " : "  [");
    bg_sb_printf(b, "%s = ", s->opts[i].key);
    if (key && !strcmp(key, s->opts[i].key)) {
      bg_sb_puts(b, optval);
      replaced = 1;
    } else {
      print_expr(b, s->opts[i].value);
    }
  }
  if (key && !replaced) {
    bg_sb_puts(b, n++ ? ", " : "  [");
    bg_sb_printf(b, "%s = %s", key, optval);
  }
  if (n) bg_sb_putc(b, ']');
}

void tx_print_element(bg_strbuf *b, const bg_ast_stmt *s, const char *value, const char *key,
                      const char *optval) {
  bg_sb_printf(b, "%-3s %s", s->kindword, s->name);
  if (s->expr || value) {
    if (s->has_law) bg_sb_printf(b, " : %s", s->law_lhs);
    bg_sb_puts(b, " = ");
    if (value) bg_sb_puts(b, value);
    else print_expr(b, s->expr);
  }
  tx_print_options(b, s, key, optval);
}

void tx_print_bond(bg_strbuf *b, int number, const char *from, bg_arrow arrow, const char *to,
                   const bg_ast_stmt *like) {
  bg_sb_puts(b, "bond ");
  if (number) bg_sb_printf(b, "%d ", number);
  const char *arrows[] = {"->", "->|", "|->"};
  bg_sb_printf(b, "%s %s %s", from, arrows[arrow], to);
  if (like) tx_print_options(b, like, NULL, NULL);
}
