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

#include "lang/lex.h"
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
} parser;

static const char *const keywords[] = {"model", "param", "input", "state", "bond",
                                       "simulate", "plot", "layout", "causality",
                                       "output", "linearise"};
static const char *const kinds[] = {"Se", "Sf", "MSe", "MSf", "C", "I", "R",
                                    "TF", "MTF", "GY", "MGY", "0", "1"};
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

/* name_expr := NAME ['.' NAME | '(' [args] ')'] */
static bg_expr *parse_name(parser *p) {
  const bg_token *t = next(p);
  bg_expr *e = new_expr(p, BG_EX_NAME, t);
  e->str = t->text;
  if (accept(p, BG_TK_DOT)) {
    const bg_token *f = expect_name(p, "a field name after '.'");
    e->kind = BG_EX_FIELD;
    e->field = f->text;
    e->field_loc = f->loc;
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

/* bond_stmt := 'bond' [NUMBER] NAME ('->' | '->|' | '|->') NAME [options] */
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
  const bg_token *a = expect_name(p, "the bond's first node");
  const bg_token *ar = cur(p);
  if (ar->kind != BG_TK_ARROW && ar->kind != BG_TK_ARROW_HEAD && ar->kind != BG_TK_ARROW_TAIL) {
    char found[128];
    describe(ar, found, sizeof found);
    fail_at(p, ar, "expected '->', '->|' or '|->' after '%s', found %s", a->text, found);
  }
  next(p);
  const bg_token *b = expect_name(p, "the bond's second node after the arrow");
  bg_ast_stmt *s = new_stmt(p, BG_ST_BOND, kw);
  s->number = number;
  s->number_loc = numloc;
  s->from = a->text;
  s->from_loc = a->loc;
  s->to = b->text;
  s->to_loc = b->loc;
  s->arrow = arrow_of(ar->kind);
  parse_options(s, p, 0);
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

/* element_stmt := KIND NAME ['=' expr | ':' NAME '=' expr] [options] */
static void parse_element(parser *p, const bg_token *kind) {
  const bg_token *n = expect_name(p, "an element name after the kind");
  /* kind words may name elements (lagrange_rlc has "R R = R0"); keywords may not */
  if (in_list(n->text, keywords, COUNT(keywords)))
    fail_at(p, n, "'%s' is a keyword and cannot name an element", n->text);
  bg_ast_stmt *s = new_stmt(p, BG_ST_ELEMENT, kind);
  int si = p->nstmts - 1;
  s->kindword = kind->text;
  s->name = n->text;
  s->name_loc = n->loc;
  if (accept(p, BG_TK_ASSIGN)) {
    bg_expr *e = parse_expr(p);
    p->stmts[si].expr = e;
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

/* Parses one logical line; on a syntax error drops what the statement added. */
static void parse_line(parser *p) {
  int nstmts = p->nstmts;
  p->depth = 0;
  if (setjmp(p->on_error)) {
    p->nstmts = nstmts;
    while (!at(p, BG_TK_EOL) && !at(p, BG_TK_EOF)) p->pos++;
    accept(p, BG_TK_EOL);
    return;
  }
  parse_statement(p);
  if (!at(p, BG_TK_EOL) && !at(p, BG_TK_EOF)) {
    char found[128];
    describe(cur(p), found, sizeof found);
    fail_at(p, cur(p), "unexpected %s after the end of the statement", found);
  }
  accept(p, BG_TK_EOL);
}

/* A model is UTF-8 text without NUL bytes: anything else (a binary file, a
 * Latin-1 file) is refused at its first bad byte, instead of a flood of
 * errors, and no invalid text ever reaches pango and cairo. */
static int is_text(const char *src, size_t len, bg_diags *dg) {
  const char *why;
  size_t bad = bg_text_bad_byte(src, len, &why);
  if (bad == len) return 1;
  bg_srcloc at = {1, 1};
  for (size_t i = 0; i < bad; i++) {
    if (src[i] == '\n') at.line++, at.col = 1;
    else at.col++;
  }
  bg_diag_error(dg, at, "not a text file: %s (0x%02X) at byte %zu; a model is UTF-8 text",
                why, (unsigned char)src[bad], bad);
  return 0;
}

bg_ast *bg_parse_string(const char *path, const char *src, size_t len, bg_diags *dg) {
  bg_ast *ast = bg_xcalloc(1, sizeof *ast);
  ast->path = bg_arena_strdup(&ast->arena, path ? path : "");
  parser *p = bg_xcalloc(1, sizeof *p); /* jmp_buf is large; keep it off the stack */
  p->src = src;
  p->ast = ast;
  p->dg = dg;
  if (!is_text(src, len, dg)) len = 0; /* parse nothing: one error, at the byte */
  bg_lex_all(src, len, &ast->arena, dg, &p->toks);
  while (!at(p, BG_TK_EOF) && !bg_diags_full(dg)) parse_line(p);
  ast->stmts = bg_arena_alloc(&ast->arena, (size_t)(p->nstmts ? p->nstmts : 1) * sizeof *ast->stmts);
  if (p->nstmts) memcpy(ast->stmts, p->stmts, (size_t)p->nstmts * sizeof *ast->stmts);
  ast->nstmts = p->nstmts;
  free(p->stmts);
  bg_lex_free(&p->toks);
  free(p);
  return ast;
}

void bg_ast_free(bg_ast *ast) {
  if (!ast) return;
  bg_arena_free(&ast->arena);
  free(ast);
}
