/* SPDX-License-Identifier: BSD-3-Clause */
/* The .bg parser: tokens -> bg_ast. One statement per logical line; after a
 * syntax error the parser reports it, skips to the next line and goes on, so
 * one run reports every error. Expressions are parsed by recursive descent
 * with a nesting limit (no unbounded recursion on user input). */
#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "lang/lex_int.h"
#include "lang/parse.h"
#include "base/strbuf.h"

enum { MAX_DEPTH = 200 };

typedef struct parser {
  bg_tokens toks;
  int pos;
  const char *src;
  bg_ast *ast;
  bg_diags *dg;
  jmp_buf on_error; /* back to the statement loop */
  int depth;
  bg_ast_stmt *stmts; /* malloc'd while parsing, copied into the arena at the end */
  int nstmts, cap;
  int open_def;       /* index of the SUBMODEL statement whose body is being read, or -1 */
  bg_strbuf words;    /* a study statement's words while they are built (here, not on the
                         stack: a syntax error leaves by longjmp); freed at the end */
} parser;

static const char *const keywords[] = {"model", "param", "input", "state", "bond",
                                       "simulate", "plot", "layout", "causality",
                                       "output", "linearise"};
/* the contextual word `study` and what may follow it */
static const char *const study_words[] = {"sweep", "vary", "draws", "seed", "collect"};
static const char *const kinds[] = {"Se", "Sf", "MSe", "MSf", "C", "I", "R",
                                    "TF", "MTF", "GY", "MGY", "0", "1", "De", "Df"};
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* ---------------------------------------------------------------- helpers */
static const bg_token *cur(const parser *p) { return &p->toks.tok[p->pos]; }
static const bg_token *next(parser *p) { return &p->toks.tok[p->pos++]; }
static int at(const parser *p, bg_tkind k) { return cur(p)->kind == k; }

static int accept(parser *p, bg_tkind k) {
  if (!at(p, k)) return 0;
  p->pos++;
  return 1;
}

/* "'foo'", "end of line", ... for messages */
static void describe(const bg_token *t, char *buf, size_t n) {
  if (t->kind == BG_TK_NAME || t->kind == BG_TK_NUMBER) snprintf(buf, n, "'%s'", t->text);
  else if (t->kind == BG_TK_STRING) snprintf(buf, n, "a string");
  else snprintf(buf, n, "%s", bg_lex_kind_name(t->kind));
}

/* Reports a syntax error at token t (unless the lexer already reported that
 * token) and abandons the statement. */
static _Noreturn void fail_at(parser *p, const bg_token *t, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static _Noreturn void fail_at(parser *p, const bg_token *t, const char *fmt, ...) {
  if (t->kind != BG_TK_ERROR) {
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    bg_diag_error(p->dg, t->loc, "%s", msg);
  }
  longjmp(p->on_error, 1);
}

static const bg_token *expect(parser *p, bg_tkind k, const char *what) {
  if (!at(p, k)) {
    char found[128];
    describe(cur(p), found, sizeof found);
    fail_at(p, cur(p), "expected %s %s, found %s", bg_lex_kind_name(k), what, found);
  }
  return next(p);
}

static const bg_token *expect_name(parser *p, const char *what) {
  if (!at(p, BG_TK_NAME)) {
    char found[128];
    describe(cur(p), found, sizeof found);
    fail_at(p, cur(p), "expected %s, found %s", what, found);
  }
  return next(p);
}

static int in_list(const char *s, const char *const *list, int n) {
  for (int i = 0; i < n; i++)
    if (strcmp(s, list[i]) == 0) return 1;
  return 0;
}


static const char *closest_word(const char *w) {
  /* a case slip first: r is R, tf is TF, mse is MSe */
  for (int i = 0; i < COUNT(kinds) + COUNT(keywords); i++) {
    const char *c = i < COUNT(kinds) ? kinds[i] : keywords[i - COUNT(kinds)];
    if (!strcasecmp(w, c)) return c;
  }
  const char *best = NULL;
  int bestd = strlen(w) < 3 ? 2 : 3;
  for (int i = 0; i < COUNT(kinds) + COUNT(keywords); i++) {
    const char *c = i < COUNT(kinds) ? kinds[i] : keywords[i - COUNT(kinds)];
    int d = bg_edit_distance(w, c);
    if (d < bestd) { bestd = d; best = c; }
  }
  return best;
}

/* ---------------------------------------------------------------- expressions */
static bg_expr *parse_expr(parser *p);
static bg_expr *parse_unary(parser *p);

static void enter(parser *p) {
  if (++p->depth > MAX_DEPTH)
    fail_at(p, cur(p), "expression nested too deeply (more than %d levels)", MAX_DEPTH);
}

static bg_expr *new_expr(parser *p, bg_exkind kind, const bg_token *t) {
  bg_expr *e = bg_arena_alloc(&p->ast->arena, sizeof *e);
  e->kind = kind;
  e->loc = t->loc;
  e->start = t->start;
  e->end = t->end;
  return e;
}

/* The source text of [start, end) without line continuations, trimmed. */
static const char *span_text(parser *p, int start, int end) {
  char *s = bg_arena_alloc(&p->ast->arena, (size_t)(end - start) + 1);
  size_t n = 0;
  for (int i = start; i < end; i++) {
    char c = p->src[i];
    if (c == '\\') { /* a continuation: skip to the next line */
      while (i < end && p->src[i] != '\n') i++;
      if (n && s[n - 1] != ' ') s[n++] = ' ';
      continue;
    }
    if (c == '\r' || c == '\n' || c == '\t') c = ' ';
    if (c == ' ' && (n == 0 || s[n - 1] == ' ')) continue;
    s[n++] = c;
  }
  while (n && s[n - 1] == ' ') n--;
  s[n] = '\0';
  return s;
}

/* Deepest operator tree accepted: recursive walkers of later stages stay
 * far from the C stack's limit even on sums of thousands of terms. */
enum { MAX_TREE_DEPTH = 2000 };

/* Sets e's span to [start, end of the last consumed token), its depth, and
 * (except for inner operators, see ast.h) its text. */
static bg_expr *finish(parser *p, bg_expr *e, int start) {
  e->start = start;
  e->end = p->toks.tok[p->pos - 1].end;
  e->depth = 1;
  for (int i = 0; i < e->nargs; i++)
    if (e->args[i] && e->args[i]->depth + 1 > e->depth) e->depth = e->args[i]->depth + 1;
  if (e->depth > MAX_TREE_DEPTH)
    fail_at(p, &p->toks.tok[p->pos - 1],
            "expression too long: more than %d nested operations; split it into params",
            MAX_TREE_DEPTH);
  if (e->kind != BG_EX_BINARY && e->kind != BG_EX_UNARY)
    e->text = span_text(p, e->start, e->end);
  return e;
}

static void push_arg(parser *p, bg_expr *e, bg_expr ***buf, int *cap, bg_expr *a) {
  if (e->nargs == *cap) {
    int ncap = *cap ? 2 * *cap : 4;
    bg_expr **nb = bg_arena_alloc(&p->ast->arena, (size_t)ncap * sizeof *nb);
    if (e->nargs && *buf) memcpy(nb, *buf, (size_t)e->nargs * sizeof *nb);
    *buf = nb;
    *cap = ncap;
  }
  (*buf)[e->nargs++] = a;
  e->args = *buf;
}

/* args := expr {',' expr}   (up to `close`) */
static void parse_list(parser *p, bg_expr *e, bg_tkind close, bg_tkind sep2) {
  bg_expr **buf = NULL;
  int cap = 0, row = 0;
  e->nrows = 1;
  if (at(p, close)) return;
  for (;;) {
    push_arg(p, e, &buf, &cap, parse_expr(p));
    row++;
    if (accept(p, BG_TK_COMMA)) continue;
    if (sep2 != BG_TK_EOF && at(p, sep2)) {
      if (e->nrows == 1) e->ncols = row;
      else if (row != e->ncols)
        fail_at(p, cur(p), "matrix rows must have the same length (row %d has %d entries, row 1 has %d)",
                e->nrows, row, e->ncols);
      next(p);
      e->nrows++;
      row = 0;
      continue;
    }
    break;
  }
  if (e->nrows == 1) e->ncols = row;
  else if (row != e->ncols)
    fail_at(p, cur(p), "matrix rows must have the same length (row %d has %d entries, row 1 has %d)",
            e->nrows, row, e->ncols);
}

/* Consumes the closing bracket `close` of the one opened by token `open`,
 * or fails naming both; pair is the closing and the opening character. */
static void expect_close(parser *p, bg_tkind close, const char *pair, const bg_token *open) {
  if (!at(p, close)) {
    char found[128];
    describe(cur(p), found, sizeof found);
    fail_at(p, cur(p), "expected '%c' to close '%c' at column %d, found %s", pair[0], pair[1],
            open->loc.col, found);
  }
  next(p);
}

const char *bg_ast_join(bg_arena *a, const char *prefix, const char *name) {
  if (!prefix || !*prefix) return bg_arena_strdup(a, name);
  size_t np = strlen(prefix), nn = strlen(name);
  char *s = bg_arena_alloc(a, np + nn + 2);
  memcpy(s, prefix, np);
  s[np] = '.';
  memcpy(s + np + 1, name, nn + 1);
  return s;
}

static const char *join_dotted(parser *p, const char *a, const char *b) {
  return bg_ast_join(&p->ast->arena, a, b);
}

/* name_expr := NAME {'.' NAME} | NAME '(' [args] ')'
 * A dotted path's last part is the field, the rest (M1.La) its node. */
static bg_expr *parse_name(parser *p) {
  const bg_token *t = next(p);
  bg_expr *e = new_expr(p, BG_EX_NAME, t);
  e->str = t->text;
  if (accept(p, BG_TK_DOT)) {
    /* a numbered port stands inside a path only: K.2.e */
    const bg_token *f = at(p, BG_TK_NUMBER) ? next(p) : expect_name(p, "a field name after '.'");
    e->kind = BG_EX_FIELD;
    e->field = f->text;
    e->field_loc = f->loc;
    while (f->kind == BG_TK_NUMBER || accept(p, BG_TK_DOT)) {
      if (f->kind == BG_TK_NUMBER) expect(p, BG_TK_DOT, "and a variable after a port number (K.2.e)");
      f = at(p, BG_TK_NUMBER) ? next(p) : expect_name(p, "a name after '.'");
      e->str = join_dotted(p, e->str, e->field);
      e->field = f->text;
      e->field_loc = f->loc;
    }
  } else if (accept(p, BG_TK_LPAREN)) {
    const bg_token *open = &p->toks.tok[p->pos - 1];
    e->kind = BG_EX_CALL;
    parse_list(p, e, BG_TK_RPAREN, BG_TK_EOF);
    expect_close(p, BG_TK_RPAREN, ")(", open);
  }
  return finish(p, e, t->start);
}

/* paren := '(' expr ')' | '(' expr ',' expr {',' expr} ')'   (a tuple) */
static bg_expr *parse_paren(parser *p) {
  const bg_token *open = next(p);
  bg_expr *first = parse_expr(p);
  bg_expr *e = first;
  if (at(p, BG_TK_COMMA)) {
    e = new_expr(p, BG_EX_TUPLE, open);
    bg_expr **buf = NULL;
    int cap = 0;
    push_arg(p, e, &buf, &cap, first);
    while (accept(p, BG_TK_COMMA)) push_arg(p, e, &buf, &cap, parse_expr(p));
  }
  expect_close(p, BG_TK_RPAREN, ")(", open);
  if (e == first) return e; /* keeps the inner span; parentheses carry no meaning */
  return finish(p, e, open->start);
}

/* matrix := '[' expr {',' expr} {';' expr {',' expr}} ']' */
static bg_expr *parse_matrix(parser *p) {
  const bg_token *open = next(p);
  bg_expr *e = new_expr(p, BG_EX_MATRIX, open);
  parse_list(p, e, BG_TK_RBRACK, BG_TK_SEMI);
  expect_close(p, BG_TK_RBRACK, "][", open);
  return finish(p, e, open->start);
}

/* primary := NUMBER | STRING | name_expr | paren | matrix */
static bg_expr *parse_primary(parser *p) {
  const bg_token *t = cur(p);
  switch (t->kind) {
  case BG_TK_NUMBER: {
    bg_expr *e = new_expr(p, BG_EX_NUM, next(p));
    e->num = t->num;
    return finish(p, e, t->start);
  }
  case BG_TK_STRING: {
    bg_expr *e = new_expr(p, BG_EX_STR, next(p));
    e->str = t->text;
    return finish(p, e, t->start);
  }
  case BG_TK_NAME: return parse_name(p);
  case BG_TK_LPAREN: return parse_paren(p);
  case BG_TK_LBRACK: return parse_matrix(p);
  default: {
    char found[128];
    describe(t, found, sizeof found);
    fail_at(p, t, "expected an expression, found %s", found);
  }
  }
}

/* power := primary ['^' unary]   (right-associative; 2^-1 allowed) */
static bg_expr *parse_power(parser *p) {
  int start = cur(p)->start;
  bg_expr *base = parse_primary(p);
  if (!at(p, BG_TK_CARET)) return base;
  bg_expr *e = new_expr(p, BG_EX_BINARY, next(p));
  e->op = BG_OP_POW;
  e->args = bg_arena_alloc(&p->ast->arena, 2 * sizeof *e->args);
  e->args[0] = base;
  enter(p); /* 2^2^2^...: the exponent recurses */
  e->args[1] = parse_unary(p);
  p->depth--;
  e->nargs = 2;
  return finish(p, e, start);
}

/* unary := ('-' | '!' | '+') unary | power */
static bg_expr *parse_unary(parser *p) {
  const bg_token *t = cur(p);
  if (t->kind != BG_TK_MINUS && t->kind != BG_TK_NOT && t->kind != BG_TK_PLUS)
    return parse_power(p);
  enter(p);
  next(p);
  bg_expr *operand = parse_unary(p);
  p->depth--;
  if (t->kind == BG_TK_PLUS) return operand;
  bg_expr *e = new_expr(p, BG_EX_UNARY, t);
  e->op = t->kind == BG_TK_MINUS ? BG_OP_NEG : BG_OP_NOT;
  e->args = bg_arena_alloc(&p->ast->arena, sizeof *e->args);
  e->args[0] = operand;
  e->nargs = 1;
  return finish(p, e, t->start);
}

/* Binary levels, loosest first; each level is left-associative. */
static const struct { bg_tkind tk; int op; int level; } binops[] = {
    {BG_TK_OR, BG_OP_OR, 0},  {BG_TK_AND, BG_OP_AND, 1}, {BG_TK_EQ, BG_OP_EQ, 2},
    {BG_TK_NE, BG_OP_NE, 2},  {BG_TK_LT, BG_OP_LT, 2},   {BG_TK_LE, BG_OP_LE, 2},
    {BG_TK_GT, BG_OP_GT, 2},  {BG_TK_GE, BG_OP_GE, 2},   {BG_TK_PLUS, BG_OP_ADD, 3},
    {BG_TK_MINUS, BG_OP_SUB, 3}, {BG_TK_STAR, BG_OP_MUL, 4}, {BG_TK_SLASH, BG_OP_DIV, 4},
};
enum { NLEVELS = 5 };

static int binop_at(const parser *p, int level) {
  for (int i = 0; i < COUNT(binops); i++)
    if (binops[i].level == level && binops[i].tk == cur(p)->kind) return binops[i].op;
  return 0;
}

/* level L := level L+1 {op_L level L+1}; level NLEVELS is unary.
 *   or := and {'||' and};  and := cmp {'&&' cmp};
 *   cmp := add {('=='|'!='|'<'|'<='|'>'|'>=') add};  add := mul {('+'|'-') mul};
 *   mul := unary {('*'|'/') unary} */
static bg_expr *parse_level(parser *p, int level) {
  if (level == NLEVELS) return parse_unary(p);
  int start = cur(p)->start;
  bg_expr *lhs = parse_level(p, level + 1);
  int op;
  while ((op = binop_at(p, level)) != 0) {
    bg_expr *e = new_expr(p, BG_EX_BINARY, next(p));
    e->op = op;
    e->args = bg_arena_alloc(&p->ast->arena, 2 * sizeof *e->args);
    e->args[0] = lhs;
    e->args[1] = parse_level(p, level + 1);
    e->nargs = 2;
    lhs = finish(p, e, start);
  }
  return lhs;
}

/* expr := or */
static bg_expr *parse_expr(parser *p) {
  enter(p);
  bg_expr *e = parse_level(p, 0);
  p->depth--;
  if (!e->text) e->text = span_text(p, e->start, e->end);
  return e;
}

/* ---------------------------------------------------------------- statements */
static bg_ast_stmt *new_stmt(parser *p, bg_stkind kind, const bg_token *first) {
  if (p->nstmts == p->cap) {
    p->cap = p->cap ? 2 * p->cap : 64;
    p->stmts = bg_xrealloc(p->stmts, (size_t)p->cap * sizeof *p->stmts);
  }
  bg_ast_stmt *s = &p->stmts[p->nstmts++];
  memset(s, 0, sizeof *s);
  s->kind = kind;
  s->loc = first->loc;
  return s;
}

/* option := NAME '=' expr */
static void parse_option(parser *p, bg_ast_option *o) {
  const bg_token *k = expect_name(p, "an option name");
  o->key = k->text;
  o->loc = k->loc;
  expect(p, BG_TK_ASSIGN, "after the option name");
  o->value = parse_expr(p);
}

/* options := '[' [option {',' option}] ']'   (brackets optional when `bare`) */
static void parse_options(bg_ast_stmt *s, parser *p, int bare) {
  const bg_token *open = cur(p);
  int bracket = accept(p, BG_TK_LBRACK);
  if (!bracket && !bare) return;
  bg_ast_option buf[64];
  int n = 0;
  while (!at(p, BG_TK_RBRACK) && !at(p, BG_TK_EOL)) {
    if (n == COUNT(buf)) fail_at(p, cur(p), "too many options (at most %d)", COUNT(buf));
    parse_option(p, &buf[n++]);
    if (!accept(p, BG_TK_COMMA)) break;
  }
  if (bracket && !at(p, BG_TK_RBRACK)) {
    char found[128];
    describe(cur(p), found, sizeof found);
    fail_at(p, cur(p), "expected ',' or ']' to close '[' at column %d, found %s", open->loc.col,
            found);
  }
  accept(p, BG_TK_RBRACK);
  s->opts = bg_arena_alloc(&p->ast->arena, (size_t)(n ? n : 1) * sizeof *s->opts);
  memcpy(s->opts, buf, (size_t)n * sizeof *s->opts);
  s->nopts = n;
}

/* model_stmt := 'model' NAME [STRING] */
static void parse_model(parser *p, const bg_token *kw) {
  bg_ast_stmt *s = new_stmt(p, BG_ST_MODEL, kw);
  const bg_token *n = expect_name(p, "the model name after 'model'");
  s->name = n->text;
  s->name_loc = n->loc;
  if (at(p, BG_TK_STRING)) s->text = next(p)->text;
}

/* A list of named definitions with optional descriptions, one statement each:
 * param_stmt  := 'param'  NAME '=' expr [STRING] {',' NAME '=' expr [STRING]}
 * output_stmt := 'output' NAME '=' expr [STRING] {',' NAME '=' expr [STRING]} */
static void parse_definitions(parser *p, const bg_token *kw, bg_stkind kind, const char *what,
                              const char *after) {
  do {
    const bg_token *n = expect_name(p, what);
    expect(p, BG_TK_ASSIGN, after);
    bg_expr *e = parse_expr(p);
    bg_ast_stmt *s = new_stmt(p, kind, kw);
    s->name = n->text;
    s->name_loc = n->loc;
    s->expr = e;
    if (at(p, BG_TK_STRING)) s->text = next(p)->text;
  } while (accept(p, BG_TK_COMMA));
}

/* input_stmt := 'input' NAME '=' expr */
static void parse_input(parser *p, const bg_token *kw) {
  const bg_token *n = expect_name(p, "an input name");
  expect(p, BG_TK_ASSIGN, "after the input name");
  bg_expr *e = parse_expr(p);
  bg_ast_stmt *s = new_stmt(p, BG_ST_INPUT, kw);
  s->name = n->text;
  s->name_loc = n->loc;
  s->expr = e;
}

/* state_stmt := 'state' NAME "'" '=' expr [options] */
static void parse_state(parser *p, const bg_token *kw) {
  const bg_token *n = expect_name(p, "a state name");
  expect(p, BG_TK_PRIME, "after the state name (write: state x' = EXPR)");
  expect(p, BG_TK_ASSIGN, "after the state's derivative");
  bg_expr *e = parse_expr(p);
  bg_ast_stmt *s = new_stmt(p, BG_ST_STATE, kw);
  s->name = n->text;
  s->name_loc = n->loc;
  s->expr = e;
  parse_options(s, p, 0);
}

static bg_arrow arrow_of(bg_tkind k) {
  return k == BG_TK_ARROW_HEAD ? BG_ARROW_STROKE_HEAD
         : k == BG_TK_ARROW_TAIL ? BG_ARROW_STROKE_TAIL : BG_ARROW_PLAIN;
}

/* bond_end := NAME {'.' NAME}   (M1.a: port a of instance M1) */
static const bg_token *parse_bond_end(parser *p, const char *what, const char **name) {
  const bg_token *t = expect_name(p, what);
  *name = t->text;
  while (accept(p, BG_TK_DOT)) {
    const bg_token *port = at(p, BG_TK_NUMBER) ? next(p) : expect_name(p, "a port name after '.'");
    *name = join_dotted(p, *name, port->text); /* K.2: port 2 of field K */
  }
  return t;
}

/* bond_stmt := 'bond' [NUMBER] bond_end ('->' | '->|' | '|->') bond_end [options] */
static void parse_bond(parser *p, const bg_token *kw) {
  int number = 0;
  bg_srcloc numloc = kw->loc;
  if (at(p, BG_TK_NUMBER)) {
    const bg_token *n = next(p);
    /* the range first: converting a double beyond int's range is undefined */
    if (!(n->num >= 1 && n->num <= BG_BOND_NUMBER_MAX) || n->num != floor(n->num))
      fail_at(p, n, "a bond number must be a whole number from 1 to %d, not '%s'",
              BG_BOND_NUMBER_MAX, n->text);
    number = (int)n->num;
    numloc = n->loc;
  }
  const char *from, *to;
  const bg_token *a = parse_bond_end(p, "the bond's first node", &from);
  const bg_token *ar = cur(p);
  if (ar->kind != BG_TK_ARROW && ar->kind != BG_TK_ARROW_HEAD && ar->kind != BG_TK_ARROW_TAIL) {
    char found[128];
    describe(ar, found, sizeof found);
    fail_at(p, ar, "expected '->', '->|' or '|->' after '%s', found %s", from, found);
  }
  next(p);
  const bg_token *b = parse_bond_end(p, "the bond's second node after the arrow", &to);
  bg_ast_stmt *s = new_stmt(p, BG_ST_BOND, kw);
  s->number = number;
  s->number_loc = numloc;
  s->from = from;
  s->from_loc = a->loc;
  s->to = to;
  s->to_loc = b->loc;
  s->arrow = arrow_of(ar->kind);
  parse_options(s, p, 0);
}

/* open_stmt := ('open' | 'short') bond_end {',' bond_end}: each node (a port
 * of an instance, M1.shaft, or a junction) gets a zero source, open an Sf
 * (zero flow), short an Se (zero effort), written as the element and bond
 * they mean, the element named NODE_open or NODE_short with the node's dots
 * as '_' (docs/format.md, "Open and shorted ports"). */
static void parse_open(parser *p, const bg_token *kw) {
  int is_short = kw->text[0] == 's';
  do {
    const char *node;
    const bg_token *n = parse_bond_end(p, is_short ? "a port (M1.a) or a junction to short"
                                                   : "a port (M1.a) or a junction to leave open", &node);
    size_t len = strlen(node);
    char *name = bg_arena_alloc(&p->ast->arena, len + 7);
    for (size_t i = 0; i < len; i++) name[i] = node[i] == '.' ? '_' : node[i];
    strcpy(name + len, is_short ? "_short" : "_open");
    bg_expr *zero = new_expr(p, BG_EX_NUM, n);
    zero->num = 0;
    zero->text = "0";
    zero->depth = 1;
    bg_ast_stmt *e = new_stmt(p, BG_ST_ELEMENT, kw);
    e->kindword = is_short ? "Se" : "Sf";
    e->name = name;
    e->name_loc = n->loc;
    e->expr = zero;
    e->zero_port = 1;
    bg_ast_stmt *b = new_stmt(p, BG_ST_BOND, kw); /* e may have moved */
    b->from = name;
    b->from_loc = n->loc;
    b->to = node;
    b->to_loc = n->loc;
    b->arrow = BG_ARROW_PLAIN;
    b->zero_port = 1;
  } while (accept(p, BG_TK_COMMA));
}

/* causality_stmt := 'causality' NAME */
static void parse_causality(parser *p, const bg_token *kw) {
  const bg_token *n = expect_name(p, "a causality method (scap, relaxed, vandijk, lagrange)");
  bg_ast_stmt *s = new_stmt(p, BG_ST_CAUSALITY, kw);
  s->name = n->text;
  s->name_loc = n->loc;
}

/* plot_stmt := 'plot' expr {',' expr} [options] */
static void parse_plot(parser *p, const bg_token *kw) {
  bg_expr holder = {0};
  bg_expr **buf = NULL;
  int cap = 0;
  do push_arg(p, &holder, &buf, &cap, parse_expr(p));
  while (accept(p, BG_TK_COMMA));
  bg_ast_stmt *s = new_stmt(p, BG_ST_PLOT, kw);
  s->exprs = holder.args;
  s->nexprs = holder.nargs;
  parse_options(s, p, 0);
}

/* ---------------------------------------------------------------- study */
/* A parameter study carried by the model (docs/format.md, "study";
 * docs/study.md). Each statement becomes the command line's word for it
 * ("R0=5:125:7", "v0=normal(0.5,0.05)", "C1.e:max", "draws=500"), the
 * numbers as written, so the study reads the same values from either. */
enum { STUDY_MAX_VALUES = 100000 };

/* signed_number := ['-' | '+'] NUMBER; its text as written (with the sign). */
static const char *signed_number(parser *p, const char *what, double *v) {
  const bg_token *sign = at(p, BG_TK_MINUS) || at(p, BG_TK_PLUS) ? next(p) : NULL;
  if (!at(p, BG_TK_NUMBER)) {
    char found[128];
    describe(cur(p), found, sizeof found);
    fail_at(p, cur(p), "expected %s (a number: a study's values are written out, not "
            "computed), found %s", what, found);
  }
  const bg_token *t = next(p);
  *v = sign && sign->kind == BG_TK_MINUS ? -t->num : t->num;
  if (!isfinite(*v)) fail_at(p, t, "%s must be a finite number, not '%s'", what, t->text);
  if (!sign || sign->kind == BG_TK_PLUS) return t->text;
  size_t n = strlen(t->text); /* "-5", whatever stood between the sign and the digits */
  char *neg = bg_arena_alloc(&p->ast->arena, n + 2);
  neg[0] = '-';
  memcpy(neg + 1, t->text, n + 1);
  return neg;
}

static void study_item(parser *p, bg_ast_stmt *s, const char *word, bg_srcloc loc) {
  bg_ast_item *it = bg_arena_alloc(&p->ast->arena, (size_t)(s->nitems + 1) * sizeof *it);
  if (s->nitems) memcpy(it, s->items, (size_t)s->nitems * sizeof *it);
  memset(&it[s->nitems], 0, sizeof *it);
  it[s->nitems].name = bg_arena_strdup(&p->ast->arena, word);
  it[s->nitems].loc = loc;
  s->items = it;
  s->nitems++;
}

/* sweep NAME = NUMBER | '[' NUMBER {',' NUMBER} ']' | range(FROM, TO, COUNT)
 *            | logrange(FROM, TO, COUNT) */
static void study_sweep(parser *p, bg_ast_stmt *s, const bg_token *n, bg_strbuf *w) {
  double v;
  bg_sb_printf(w, "%s=", n->text);
  if (at(p, BG_TK_LBRACK)) {
    const bg_token *open = next(p);
    int count = 0;
    do {
      if (++count > STUDY_MAX_VALUES)
        fail_at(p, cur(p), "a sweep lists at most %d values", STUDY_MAX_VALUES);
      bg_sb_printf(w, "%s%s", count > 1 ? "," : "", signed_number(p, "a value of the sweep", &v));
    } while (accept(p, BG_TK_COMMA));
    expect_close(p, BG_TK_RBRACK, "][", open);
  } else if (at(p, BG_TK_NAME)) {
    const bg_token *f = next(p);
    int lg = !strcmp(f->text, "logrange");
    if (!lg && strcmp(f->text, "range"))
      fail_at(p, f, "a sweep's values are a number, a list [V1, V2, ...], range(FROM, TO, COUNT) "
              "or logrange(FROM, TO, COUNT), not '%s'", f->text);
    const bg_token *open = expect(p, BG_TK_LPAREN, "after the range's name");
    double a, b, c;
    const char *ta = signed_number(p, "FROM", &a);
    expect(p, BG_TK_COMMA, "between FROM and TO");
    const char *tb = signed_number(p, "TO", &b);
    expect(p, BG_TK_COMMA, "between TO and COUNT");
    const bg_token *ct = cur(p);
    const char *tc = signed_number(p, "COUNT", &c);
    if (!(c >= 1 && c <= 1000000) || c != floor(c))
      fail_at(p, ct, "a range's COUNT is a whole number from 1 to 1000000, not '%s'", tc);
    if (lg && !(a > 0 && b > 0))
      fail_at(p, f, "a logarithmic range needs FROM and TO above 0 (here %s and %s)", ta, tb);
    expect_close(p, BG_TK_RPAREN, ")(", open);
    bg_sb_printf(w, "%s:%s:%.0f%s", ta, tb, c, lg ? ":log" : "");
  } else {
    bg_sb_puts(w, signed_number(p, "the sweep's values", &v));
  }
  study_item(p, s, bg_sb_str(w), n->loc);
}

/* vary NAME = normal(MEAN, SD) | uniform(LOW, HIGH) | lognormal(MU, SIGMA) */
static void study_vary(parser *p, bg_ast_stmt *s, const bg_token *n, bg_strbuf *w) {
  const bg_token *f = expect_name(p, "a distribution: normal(MEAN, SD), uniform(LOW, HIGH) or "
                                     "lognormal(MU, SIGMA)");
  int uni = !strcmp(f->text, "uniform");
  if (!uni && strcmp(f->text, "normal") && strcmp(f->text, "lognormal"))
    fail_at(p, f, "'%s' is not a distribution: normal(MEAN, SD), uniform(LOW, HIGH) or "
            "lognormal(MU, SIGMA)", f->text);
  const bg_token *open = expect(p, BG_TK_LPAREN, "after the distribution's name");
  double a, b;
  const char *ta = signed_number(p, uni ? "LOW" : "the mean", &a);
  expect(p, BG_TK_COMMA, "between the distribution's two numbers");
  const bg_token *bt = cur(p);
  const char *tb = signed_number(p, uni ? "HIGH" : "the spread", &b);
  if (uni && b < a) fail_at(p, bt, "uniform(LOW, HIGH): HIGH (%s) is below LOW (%s)", tb, ta);
  if (!uni && b < 0) fail_at(p, bt, "%s(...): the spread (%s) is negative", f->text, tb);
  expect_close(p, BG_TK_RPAREN, ")(", open);
  bg_sb_printf(w, "%s=%s(%s,%s)", n->text, f->text, ta, tb);
  study_item(p, s, bg_sb_str(w), n->loc);
}

/* draws = N [, seed = S] | seed = S  (either order) */
static void study_draws(parser *p, bg_ast_stmt *s, const bg_token *first) {
  const bg_token *k = first;
  for (;;) {
    if (strcmp(k->text, "draws") && strcmp(k->text, "seed"))
      fail_at(p, k, "expected draws = N or seed = S, found '%s'", k->text);
    for (int i = 0; i < s->nitems; i++)
      if (!strncmp(s->items[i].name, k->text, strlen(k->text)))
        fail_at(p, k, "'%s' is given twice", k->text);
    expect(p, BG_TK_ASSIGN, "after draws or seed");
    const bg_token *t = cur(p);
    double v;
    const char *txt = signed_number(p, k->text, &v);
    int seed = !strcmp(k->text, "seed");
    size_t len = strlen(txt);
    if (seed ? (strspn(txt, "0123456789") != len || len > 20 ||
                (len == 20 && strcmp(txt, "18446744073709551615") > 0))
             : !(v >= 1 && v <= 1000000 && v == floor(v)))
      fail_at(p, t, seed ? "the seed is a whole number from 0 to 2^64-1, written in digits, not '%s'"
                         : "draws is the number of runs, a whole number from 1 to 1000000, not '%s'",
              txt);
    char word[64];
    if (seed) snprintf(word, sizeof word, "seed=%s", txt);
    else snprintf(word, sizeof word, "draws=%.0f", v);
    study_item(p, s, word, k->loc);
    if (!accept(p, BG_TK_COMMA)) break;
    k = expect_name(p, "draws or seed after ','");
  }
}

/* collect ITEM {',' ITEM};  ITEM := 'poles' | EXPR ':' WHAT ['=' NUMBER] */
static void study_collect(parser *p, bg_ast_stmt *s, bg_strbuf *w) {
  static const char *const whats[] = {"final", "min", "max", "mean", "tmin", "tmax", "cross"};
  do {
    bg_sb_clear(w);
    bg_sb_puts(w, "");
    const bg_token *t = cur(p);
    if (t->kind == BG_TK_NAME && !strcmp(t->text, "poles") &&
        (p->toks.tok[p->pos + 1].kind == BG_TK_COMMA || p->toks.tok[p->pos + 1].kind == BG_TK_EOL ||
         p->toks.tok[p->pos + 1].kind == BG_TK_EOF)) {
      next(p);
      study_item(p, s, "poles", t->loc);
      continue;
    }
    bg_expr *e = parse_expr(p);
    if (!at(p, BG_TK_COLON)) {
      char found[128];
      describe(cur(p), found, sizeof found);
      fail_at(p, cur(p), "expected ':' and what to collect of '%s' (final, min, max, mean, tmin, "
              "tmax, cross = LEVEL), found %s", span_text(p, e->start, e->end), found);
    }
    next(p);
    const bg_token *k = expect_name(p, "what to collect: final, min, max, mean, tmin, tmax or "
                                       "cross = LEVEL");
    if (!in_list(k->text, whats, COUNT(whats)))
      fail_at(p, k, "'%s' is not final, min, max, mean, tmin, tmax or cross = LEVEL", k->text);
    bg_sb_printf(w, "%s:%s", span_text(p, e->start, e->end), k->text);
    if (!strcmp(k->text, "cross")) {
      expect(p, BG_TK_ASSIGN, "after cross (cross = LEVEL)");
      double v;
      bg_sb_printf(w, "=%s", signed_number(p, "the level", &v));
    }
    for (int i = 0; i < s->nitems; i++)
      if (!strcmp(s->items[i].name, bg_sb_str(w)))
        fail_at(p, t, "'%s' is collected twice", bg_sb_str(w));
    study_item(p, s, bg_sb_str(w), t->loc);
  } while (accept(p, BG_TK_COMMA));
}

/* study_stmt := 'study' ('sweep' NAME '=' VALUES | 'vary' NAME '=' DIST
 *                      | ('draws' | 'seed') '=' NUMBER {',' ...} | 'collect' ITEM {',' ITEM}) */
static void parse_study(parser *p, const bg_token *kw) {
  if (p->open_def >= 0) fail_at(p, kw, "'study' is not allowed inside a submodel (it belongs to the model)");
  const bg_token *sub = next(p);
  bg_ast_stmt *s = new_stmt(p, BG_ST_STUDY, kw);
  int si = p->nstmts - 1;
  s->name = sub->text;
  s->name_loc = sub->loc;
  bg_ast_stmt tmp = {0}; /* the items, while new statements cannot move it */
  bg_strbuf *w = &p->words;
  bg_sb_clear(w);
  if (!strcmp(sub->text, "sweep") || !strcmp(sub->text, "vary")) {
    const bg_token *n = expect_name(p, "the param to vary");
    expect(p, BG_TK_ASSIGN, !strcmp(sub->text, "sweep") ? "after the param (sweep NAME = VALUES)"
                                                       : "after the param (vary NAME = DIST)");
    if (!strcmp(sub->text, "sweep")) study_sweep(p, &tmp, n, w);
    else study_vary(p, &tmp, n, w);
  } else if (!strcmp(sub->text, "collect")) {
    study_collect(p, &tmp, w);
  } else {
    study_draws(p, &tmp, sub);
    p->stmts[si].name = "draws";
  }
  p->stmts[si].items = tmp.items;
  p->stmts[si].nitems = tmp.nitems;
}

/* "KIND NAME" of an element or an instance: a statement named n, of kind word `kind`. */
static int named_stmt(parser *p, bg_stkind k, const bg_token *kind, const bg_token *n,
                      const char *what) {
  if (in_list(n->text, keywords, COUNT(keywords)))
    fail_at(p, n, "'%s' is a keyword and cannot name %s", n->text, what);
  bg_ast_stmt *s = new_stmt(p, k, kind);
  s->kindword = kind->text;
  s->name = n->text;
  s->name_loc = n->loc;
  return p->nstmts - 1;
}

static void parse_field(parser *p, int si);
static void parse_items(parser *p, bg_ast_stmt *s, bg_tkind close, int value, const char *what);

/* element_stmt := KIND NAME ['=' expr | ':' NAME '=' expr] [options]
 *               | field_stmt */
static void parse_element(parser *p, const bg_token *kind) {
  const bg_token *n = expect_name(p, "an element name after the kind");
  /* kind words may name elements (lagrange_rlc has "R R = R0"); keywords may not */
  int si = named_stmt(p, BG_ST_ELEMENT, kind, n, "an element");
  bg_ast_stmt *s = &p->stmts[si];
  if (at(p, BG_TK_LPAREN)) {
    if (strcmp(kind->text, "C") != 0 && strcmp(kind->text, "I") != 0 && strcmp(kind->text, "R") != 0)
      fail_at(p, cur(p), "only C, I and R elements can be multiport fields (a port list after "
              "the name); %s '%s' has one port or two sides", kind->text, n->text);
    parse_field(p, si);
  } else if (accept(p, BG_TK_ASSIGN)) {
    bg_expr *e = parse_expr(p);
    p->stmts[si].expr = e;
  } else if (at(p, BG_TK_NUMBER)) { /* "Se U2 12" */
    fail_at(p, cur(p), "missing '=' before '%s'? (write: %s %s = %s)", cur(p)->text, kind->text,
            n->text, cur(p)->text);
  } else if (accept(p, BG_TK_COLON)) {
    const bg_token *v = expect_name(p, "the law's variable after ':' (e or f)");
    expect(p, BG_TK_ASSIGN, "after the law's variable");
    bg_expr *e = parse_expr(p);
    s = &p->stmts[si];
    s->has_law = 1;
    s->law_var = v->text[0];
    s->law_lhs = v->text;
    s->law_loc = v->loc;
    s->expr = e;
  }
  parse_options(&p->stmts[si], p, 0);
}

/* ---------------------------------------------------------------- fields */
/* A port given by number: 1 .. 10^6. */
enum { MAX_FIELD_PORTS = 256 }; /* as many as a list of names may hold */

static int port_count(parser *p, const bg_token *t) {
  if (!(t->num >= 1 && t->num <= MAX_FIELD_PORTS) || t->num != floor(t->num))
    fail_at(p, t, "a field's number of ports must be a whole number from 1 to %d, not '%s'",
            MAX_FIELD_PORTS, t->text);
  return (int)t->num;
}

/* ports := NUMBER | NAME {',' NAME}   (inside the parentheses) */
static void parse_field_ports(parser *p, int si) {
  const bg_token *open = next(p);
  bg_ast_stmt *s = &p->stmts[si];
  if (at(p, BG_TK_NUMBER)) {
    const bg_token *t = next(p);
    int n = port_count(p, t);
    s->items = bg_arena_alloc(&p->ast->arena, (size_t)n * sizeof *s->items);
    for (int i = 0; i < n; i++) {
      char num[16];
      snprintf(num, sizeof num, "%d", i + 1);
      memset(&s->items[i], 0, sizeof s->items[i]);
      s->items[i].name = bg_arena_strdup(&p->ast->arena, num);
      s->items[i].loc = t->loc;
    }
    s->nitems = n;
    s->field_numbered = 1;
  } else {
    bg_ast_stmt tmp = {0};
    if (at(p, BG_TK_RPAREN)) fail_at(p, cur(p), "a field needs at least one port: K(a, b) or K(2)");
    parse_items(p, &tmp, BG_TK_RPAREN, 0, "a port name (or the number of ports)");
    s = &p->stmts[si];
    s->items = tmp.items;
    s->nitems = tmp.nitems;
  }
  expect_close(p, BG_TK_RPAREN, ")(", open);
}

/* law_lhs := NAME ['.' NAME]   (e1, q2, el.e, energy) */
static void parse_law_lhs(parser *p, bg_ast_item *law) {
  const bg_token *v = expect_name(p, "a law's left-hand side (e1, f2, PORT.e, energy)");
  law->name = v->text;
  law->loc = v->loc;
  if (accept(p, BG_TK_DOT))
    law->name = join_dotted(p, v->text, expect_name(p, "e or f after the port's name")->text);
}

/* field_stmt := ('C' | 'I' | 'R') NAME '(' ports ')' ':' law {',' law} [options]
 * law := law_lhs '=' expr */
static void parse_field(parser *p, int si) {
  parse_field_ports(p, si);
  if (!at(p, BG_TK_COLON)) {
    char found[128];
    describe(cur(p), found, sizeof found);
    fail_at(p, cur(p), "expected ':' and the field's laws (e.g. ': e1 = F1(q1, q2), e2 = "
            "F2(q1, q2)' or ': energy = W(q1, q2)'), found %s", found);
  }
  next(p);
  bg_ast_item buf[256];
  int n = 0;
  do {
    if (n == COUNT(buf)) fail_at(p, cur(p), "too many laws in one field (at most %d)", COUNT(buf));
    memset(&buf[n], 0, sizeof buf[n]);
    parse_law_lhs(p, &buf[n]);
    expect(p, BG_TK_ASSIGN, "after the law's left-hand side");
    buf[n++].value = parse_expr(p);
  } while (accept(p, BG_TK_COMMA));
  bg_ast_stmt *s = &p->stmts[si];
  s->is_field = 1;
  s->has_law = 1;
  s->law_loc = buf[0].loc;
  s->law_lhs = buf[0].name;
  s->laws = bg_arena_alloc(&p->ast->arena, (size_t)n * sizeof *s->laws);
  memcpy(s->laws, buf, (size_t)n * sizeof *s->laws);
  s->nlaws = n;
}

/* ---------------------------------------------------------------- components */
/* item := NAME ['=' expr] [STRING]; `value`: 0 no value, 1 optional, 2 required */
static void parse_item(parser *p, bg_ast_item *it, int value, const char *what) {
  const bg_token *n = expect_name(p, what);
  memset(it, 0, sizeof *it);
  it->name = n->text;
  it->loc = n->loc;
  if (value == 2) expect(p, BG_TK_ASSIGN, "after the parameter name (write NAME = EXPR)");
  if (value && (value == 2 || accept(p, BG_TK_ASSIGN))) it->value = parse_expr(p);
  if (value != 2 && at(p, BG_TK_STRING)) it->text = next(p)->text;
}

/* items := item {',' item}, up to `close` (EOL when 0); stored in s. */
static void parse_items(parser *p, bg_ast_stmt *s, bg_tkind close, int value, const char *what) {
  bg_ast_item buf[256];
  int n = 0;
  if (close == BG_TK_EOL || !at(p, close)) do {
      if (n == COUNT(buf)) fail_at(p, cur(p), "too many names in one list (at most %d)", COUNT(buf));
      parse_item(p, &buf[n++], value, what);
    } while (accept(p, BG_TK_COMMA));
  s->items = bg_arena_alloc(&p->ast->arena, (size_t)(n ? n : 1) * sizeof *s->items);
  memcpy(s->items, buf, (size_t)n * sizeof *s->items);
  s->nitems = n;
}

/* A parenthesised list "(...)" after `open` was seen; items go to stmt si. */
static void parse_paren_items(parser *p, int si, int value, const char *what) {
  const bg_token *open = next(p);
  bg_ast_stmt tmp = {0};
  parse_items(p, &tmp, BG_TK_RPAREN, value, what);
  expect_close(p, BG_TK_RPAREN, ")(", open);
  p->stmts[si].items = tmp.items;
  p->stmts[si].nitems = tmp.nitems;
}

/* submodel_stmt := 'submodel' NAME ['(' [item {',' item}] ')'] [STRING] */
static void parse_submodel(parser *p, const bg_token *kw) {
  if (p->open_def >= 0)
    fail_at(p, kw, "a submodel cannot be defined inside another (submodel '%s' at line %d has "
            "no 'end' yet)", p->stmts[p->open_def].name, p->stmts[p->open_def].loc.line);
  const bg_token *n = expect_name(p, "the submodel's name after 'submodel'");
  if (in_list(n->text, keywords, COUNT(keywords)) || in_list(n->text, kinds, COUNT(kinds)))
    fail_at(p, n, "'%s' is a keyword or element kind and cannot name a submodel", n->text);
  bg_ast_stmt *s = new_stmt(p, BG_ST_SUBMODEL, kw);
  int si = p->nstmts - 1;
  s->name = n->text;
  s->name_loc = n->loc;
  if (at(p, BG_TK_LPAREN)) parse_paren_items(p, si, 1, "a parameter name");
  if (at(p, BG_TK_STRING)) p->stmts[si].text = next(p)->text;
  p->open_def = si;
  p->ast->has_components = 1;
}

/* end_stmt := 'end' [NAME]   (the name, when given, is the submodel's) */
static void parse_end(parser *p, const bg_token *kw) {
  const bg_ast_stmt *def = &p->stmts[p->open_def];
  const char *name = def->name;
  int line = def->loc.line;
  new_stmt(p, BG_ST_END, kw);
  p->open_def = -1; /* closed even when the name is wrong: no cascade of errors */
  if (at(p, BG_TK_NAME) && strcmp(cur(p)->text, name) != 0)
    fail_at(p, cur(p), "'end %s' closes submodel '%s' (line %d)", cur(p)->text, name, line);
  accept(p, BG_TK_NAME);
}

/* use_stmt := 'use' STRING */
static void parse_use(parser *p, const bg_token *kw) {
  if (p->open_def >= 0) fail_at(p, kw, "'use' belongs at the top of a file, not inside a submodel");
  const bg_token *f = expect(p, BG_TK_STRING, "(the file to use, in quotes) after 'use'");
  bg_ast_stmt *s = new_stmt(p, BG_ST_USE, kw);
  s->text = f->text;
  s->name_loc = f->loc;
  p->ast->has_components = 1;
}

/* instance_stmt := NAME NAME ['(' [NAME '=' expr {',' NAME '=' expr}] ')'] [options] */
static void parse_instance(parser *p, const bg_token *def) {
  int si = named_stmt(p, BG_ST_INSTANCE, def, next(p), "an instance");
  if (at(p, BG_TK_LPAREN)) parse_paren_items(p, si, 2, "a parameter name");
  parse_options(&p->stmts[si], p, 0);
  p->ast->has_components = 1;
}

/* Statements of the model itself may not stand inside a submodel. */
static void check_in_def(parser *p, const bg_token *t) {
  static const char *const model_only[] = {"model", "causality", "simulate", "plot", "layout",
                                           "linearise"};
  if (p->open_def >= 0 && in_list(t->text, model_only, COUNT(model_only)))
    fail_at(p, t, "'%s' is not allowed inside a submodel (it belongs to the model)", t->text);
}

/* After "WORD NAME": an instance has arguments, options or nothing; "Cap C1 = 1"
 * stays a misspelled element kind. */
static int instance_follows(const parser *p) {
  bg_tkind k = p->toks.tok[p->pos + 1].kind;
  return k == BG_TK_EOL || k == BG_TK_EOF || k == BG_TK_LPAREN || k == BG_TK_LBRACK;
}

/* The contextual words of version 2; 1 when the statement was one of them.
 * They are not reserved, so no version 1 file changes meaning. */
static int parse_component_stmt(parser *p, const bg_token *t) {
  const char *w = t->text;
  bg_tkind k = cur(p)->kind;
  if (strcmp(w, "submodel") == 0 && k == BG_TK_NAME) parse_submodel(p, t);
  else if ((strcmp(w, "open") == 0 || strcmp(w, "short") == 0) && k == BG_TK_NAME) parse_open(p, t);
  else if (strcmp(w, "use") == 0 && k == BG_TK_STRING) parse_use(p, t);
  else if (strcmp(w, "study") == 0 && k == BG_TK_NAME && !instance_follows(p) &&
           in_list(cur(p)->text, study_words, COUNT(study_words)))
    parse_study(p, t);
  else if (p->open_def >= 0 && strcmp(w, "end") == 0 && (k == BG_TK_EOL || k == BG_TK_EOF || k == BG_TK_NAME))
    parse_end(p, t);
  else if (p->open_def >= 0 && strcmp(w, "port") == 0 && k == BG_TK_NAME) {
    parse_items(p, new_stmt(p, BG_ST_PORT, t), BG_TK_EOL, 0, "a port name");
  } else if (k == BG_TK_NAME && !in_list(w, keywords, COUNT(keywords)) &&
             !in_list(w, kinds, COUNT(kinds)) && instance_follows(p))
    parse_instance(p, t);
  else return 0;
  return 1;
}

static void parse_statement(parser *p) {
  const bg_token *t = next(p);
  if (t->kind == BG_TK_NUMBER && (strcmp(t->text, "0") == 0 || strcmp(t->text, "1") == 0)) {
    parse_element(p, t);
    return;
  }
  if (t->kind != BG_TK_NAME) {
    char found[128];
    describe(t, found, sizeof found);
    fail_at(p, t, "expected a statement (a keyword or an element kind), found %s", found);
  }
  const char *w = t->text;
  check_in_def(p, t);
  if (parse_component_stmt(p, t)) return;
  if (strcmp(w, "model") == 0) parse_model(p, t);
  else if (strcmp(w, "param") == 0)
    parse_definitions(p, t, BG_ST_PARAM, "a param name", "after the param name");
  else if (strcmp(w, "input") == 0) parse_input(p, t);
  else if (strcmp(w, "state") == 0) parse_state(p, t);
  else if (strcmp(w, "bond") == 0) parse_bond(p, t);
  else if (strcmp(w, "causality") == 0) parse_causality(p, t);
  else if (strcmp(w, "plot") == 0) parse_plot(p, t);
  else if (strcmp(w, "simulate") == 0) parse_options(new_stmt(p, BG_ST_SIMULATE, t), p, 1);
  else if (strcmp(w, "layout") == 0) parse_options(new_stmt(p, BG_ST_LAYOUT, t), p, 1);
  else if (strcmp(w, "output") == 0)
    parse_definitions(p, t, BG_ST_OUTPUT, "an output name",
                      "after the output name (write: output y = EXPR)");
  else if (strcmp(w, "linearise") == 0) parse_options(new_stmt(p, BG_ST_LINEARISE, t), p, 1);
  else if (in_list(w, kinds, COUNT(kinds))) parse_element(p, t);
  else {
    const char *s = closest_word(w);
    if (s) fail_at(p, t, "unknown element kind '%s' (did you mean '%s'?)", w, s);
    fail_at(p, t, "unknown element kind or statement '%s'", w);
  }
}

/* A dropped line's names, for the checks after the parser: an undefined
 * name or a bond count that may follow from the dropped statement is not
 * reported (bg_diags_unsure). A bond line that does not name both ends may
 * have been the missing bond of any element. */
static void note_skipped(parser *p, int start) {
  const char *names[64];
  int n = 0, bond = 0, ends = 0;
  for (int i = start; p->toks.tok[i].kind != BG_TK_EOL && p->toks.tok[i].kind != BG_TK_EOF; i++) {
    const bg_token *t = &p->toks.tok[i];
    if (t->kind == BG_TK_ARROW || t->kind == BG_TK_ARROW_HEAD || t->kind == BG_TK_ARROW_TAIL ||
        (i == start && t->kind == BG_TK_NAME && !strcmp(t->text, "bond")))
      bond = 1;
    else if (t->kind == BG_TK_NAME || t->kind == BG_TK_NUMBER) /* 0 and 1 name junctions */
      names[n++] = t->text, ends += t->kind == BG_TK_NAME && (i == start || t[-1].kind != BG_TK_DOT);
    if (n == COUNT(names)) bg_diags_skipped(p->dg, names, n, 0), n = 0;
  }
  bg_diags_skipped(p->dg, names, n, bond && ends < 2);
}

/* Parses one logical line; on a syntax error drops what the statement added. */
static void parse_line(parser *p) {
  int nstmts = p->nstmts, start = p->pos;
  p->depth = 0;
  if (setjmp(p->on_error)) {
    note_skipped(p, start);
    if (p->open_def >= nstmts) { /* a bad submodel header: keep the body's block open */
      p->stmts[nstmts] = p->stmts[p->open_def];
      p->open_def = nstmts++;
    }
    if (p->nstmts > nstmts && p->stmts[p->nstmts - 1].kind == BG_ST_END &&
        p->open_def < 0) /* a bad 'end' line still closes */
      p->stmts[nstmts++] = p->stmts[p->nstmts - 1];
    p->nstmts = nstmts;
    while (!at(p, BG_TK_EOL) && !at(p, BG_TK_EOF)) p->pos++;
    accept(p, BG_TK_EOL);
    return;
  }
  parse_statement(p);
  if (!at(p, BG_TK_EOL) && !at(p, BG_TK_EOF)) {
    char found[128];
    const bg_token *t = cur(p);
    if (t->kind == BG_TK_NAME && p->pos > 0 && p->toks.tok[p->pos - 1].kind == BG_TK_NUMBER &&
        bg_lex_is_unit(t->text))
      fail_at(p, t, "units are not part of expressions: '%s %s' is the number %s and a stray "
              "'%s'; write the number alone and give the unit in the description "
              "(param V0 = %s \"supply voltage [%s]\")", p->toks.tok[p->pos - 1].text, t->text,
              p->toks.tok[p->pos - 1].text, t->text, p->toks.tok[p->pos - 1].text, t->text);
    describe(t, found, sizeof found);
    fail_at(p, cur(p), "unexpected %s after the end of the statement", found);
  }
  accept(p, BG_TK_EOL);
}

/* A model is UTF-8 text without NUL bytes: anything else (a binary file, a
 * Latin-1 file) is refused at its first bad byte, instead of a flood of
 * errors, and no invalid text ever reaches pango and cairo. */
static int is_text(const char *src, size_t len, int file, bg_diags *dg) {
  const char *why;
  size_t bad = bg_text_bad_byte(src, len, &why);
  if (bad == len) return 1;
  bg_srcloc at = {1, 1, file};
  for (size_t i = 0; i < bad; i++) {
    if (src[i] == '\n') at.line++, at.col = 1;
    else at.col++;
  }
  bg_diag_error(dg, at, "not a text file: %s (0x%02X) at byte %zu; a model is UTF-8 text",
                why, (unsigned char)src[bad], bad);
  return 0;
}

/* BondGraphTools saves its models as YAML with the same .bg extension
 * (`root:`, `models:`, `components:`, `netlist:`): such a file is one clear
 * error at its first key instead of an error a line. 1 when src is one. */
static int is_foreign_yaml(const char *src, size_t len, int file, bg_diags *dg) {
  static const char *const keys[] = {"root:", "models:", "netlist:", "components:", "version:"};
  int hits = 0, first_line = 0, line = 1;
  for (size_t i = 0; i < len;) {
    size_t end = i;
    while (end < len && src[end] != '\n') end++;
    for (size_t k = 0; k < sizeof keys / sizeof *keys; k++) {
      size_t n = strlen(keys[k]);
      if (end - i >= n && !strncmp(src + i, keys[k], n)) {
        hits++;
        if (!first_line) first_line = line;
      }
    }
    i = end + 1, line++;
  }
  if (hits < 2) return 0;
  bg_diag_error(dg, (bg_srcloc){first_line, 1, file},
                "this looks like a BondGraphTools model (YAML with root:, models:, netlist:), "
                "not bgdraw's model language; bgdraw reads models written as in docs/format.md");
  return 1;
}

bg_ast *bg_parse_string(const char *path, const char *src, size_t len, bg_diags *dg) {
  return bg_parse_source(path, src, len, 0, dg);
}

bg_ast *bg_parse_source(const char *path, const char *src, size_t len, int file, bg_diags *dg) {
  bg_ast *ast = bg_xcalloc(1, sizeof *ast);
  ast->path = bg_arena_strdup(&ast->arena, path ? path : "");
  ast->file = file;
  parser *p = bg_xcalloc(1, sizeof *p); /* jmp_buf is large; keep it off the stack */
  p->src = src;
  p->ast = ast;
  p->dg = dg;
  if (!is_text(src, len, file, dg)) len = 0; /* parse nothing: one error, at the byte */
  else if (is_foreign_yaml(src, len, file, dg)) len = 0;
  p->open_def = -1;
  bg_lex_source(src, len, file, &ast->arena, dg, &p->toks);
  while (!at(p, BG_TK_EOF) && !bg_diags_full(dg)) parse_line(p);
  if (p->open_def >= 0) {
    const bg_ast_stmt *d = &p->stmts[p->open_def];
    bg_diag_error(dg, d->loc, "submodel '%s' has no 'end' (its body runs to the end of the file)",
                  d->name);
  }
  ast->stmts = bg_arena_alloc(&ast->arena, (size_t)(p->nstmts ? p->nstmts : 1) * sizeof *ast->stmts);
  if (p->nstmts) memcpy(ast->stmts, p->stmts, (size_t)p->nstmts * sizeof *ast->stmts);
  ast->nstmts = p->nstmts;
  free(p->stmts);
  bg_sb_free(&p->words);
  bg_lex_free(&p->toks);
  free(p);
  return ast;
}

void bg_ast_free(bg_ast *ast) {
  if (!ast) return;
  free(ast->heap_stmts);
  bg_arena_free(&ast->arena);
  free(ast);
}

int bg_ast_is_detector(const bg_ast_stmt *s) {
  return s->kind == BG_ST_ELEMENT && s->kindword &&
         (!strcmp(s->kindword, "De") || !strcmp(s->kindword, "Df"));
}
