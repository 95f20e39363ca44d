/* SPDX-License-Identifier: BSD-3-Clause */
/* The .bg lexer: bytes -> tokens with 1-based line and byte-column positions. */
#include "lang/lex_int.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

typedef struct lexer {
  const char *src;
  size_t len, pos;
  int line;
  size_t line_start; /* offset of the current physical line */
  bg_arena *arena;
  bg_diags *dg;
  bg_tokens *out;
  int cap;
  int line_has_tokens; /* a token since the last EOL */
  int file;            /* the diagnostics source index of positions */
} lexer;

static int peek(const lexer *lx, size_t k) {
  return lx->pos + k < lx->len ? (unsigned char)lx->src[lx->pos + k] : -1;
}

static bg_srcloc loc_at(const lexer *lx, size_t pos) {
  bg_srcloc l = {lx->line, (int)(pos - lx->line_start) + 1, lx->file};
  return l;
}

static bg_token *push(lexer *lx, bg_tkind kind, size_t start) {
  if (lx->out->n == lx->cap) {
    lx->cap = lx->cap ? 2 * lx->cap : 256;
    lx->out->tok = bg_xrealloc(lx->out->tok, (size_t)lx->cap * sizeof *lx->out->tok);
  }
  bg_token *t = &lx->out->tok[lx->out->n++];
  memset(t, 0, sizeof *t);
  t->kind = kind;
  t->loc = loc_at(lx, start);
  t->start = (int)start;
  t->end = (int)lx->pos;
  lx->line_has_tokens = kind != BG_TK_EOL;
  return t;
}

static void newline(lexer *lx) {
  lx->pos++;
  lx->line++;
  lx->line_start = lx->pos;
}

/* A `\` that ends a physical line (spaces, tabs and CR may follow it). */
static int is_continuation(const lexer *lx) {
  size_t p = lx->pos + 1;
  while (p < lx->len && (lx->src[p] == ' ' || lx->src[p] == '\t' || lx->src[p] == '\r')) p++;
  return p >= lx->len || lx->src[p] == '\n';
}

/* Skips blanks, comments and continuations; stops at '\n', EOF or a token. */
static void skip_space(lexer *lx) {
  for (;;) {
    int c = peek(lx, 0);
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') lx->pos++;
    else if (c == '#') {
      while (peek(lx, 0) != -1 && peek(lx, 0) != '\n') lx->pos++;
    } else if (c == '\\' && is_continuation(lx)) {
      while (peek(lx, 0) != -1 && peek(lx, 0) != '\n') lx->pos++;
      if (peek(lx, 0) == '\n') newline(lx);
    } else return;
  }
}

static void lex_name(lexer *lx) {
  size_t start = lx->pos;
  while (isalnum(peek(lx, 0)) || peek(lx, 0) == '_') lx->pos++;
  bg_token *t = push(lx, BG_TK_NAME, start);
  t->text = bg_arena_strndup(lx->arena, lx->src + start, lx->pos - start);
}

int bg_lex_is_unit(const char *w) {
  static const char *const units[] = {"V", "A", "ohm", "Ohm", "F", "H", "s", "Hz", "W", "J",
                                      "N", "Nm", "m", "kg", "g", "Pa", "bar", "rad", "K", "degC",
                                      "S", "C", "Wb", "T", "l", "L", "mol", "min", "h"};
  static const char prefixes[] = "pnumkMG";
  for (size_t i = 0; i < sizeof units / sizeof *units; i++) {
    if (!strcmp(w, units[i])) return 1;
    if (w[0] && strchr(prefixes, w[0]) && !strcmp(w + 1, units[i])) return 1;
  }
  return !strcmp(w, "kohm") || !strcmp(w, "Mohm") || !strcmp(w, "ohms");
}

static void skip_digits(lexer *lx) {
  while (isdigit(peek(lx, 0))) lx->pos++;
}

/* number: digits [. digits] [e [+-] digits] | . digits [e ...]  (C syntax) */
static void lex_number(lexer *lx) {
  size_t start = lx->pos;
  int ok = 1;
  skip_digits(lx);
  if (peek(lx, 0) == '.') { lx->pos++; skip_digits(lx); }
  if (peek(lx, 0) == 'e' || peek(lx, 0) == 'E') {
    lx->pos++;
    if (peek(lx, 0) == '+' || peek(lx, 0) == '-') lx->pos++;
    if (!isdigit(peek(lx, 0))) ok = 0;
    skip_digits(lx);
  }
  /* "2x", "1e", "1.2.3": one malformed token rather than two confusing ones */
  size_t num_end = lx->pos;
  int numeric_ok = ok;
  while (isalnum(peek(lx, 0)) || peek(lx, 0) == '_' || peek(lx, 0) == '.') { lx->pos++; ok = 0; }
  char *text = bg_arena_strndup(lx->arena, lx->src + start, lx->pos - start);
  char *suffix = bg_arena_strndup(lx->arena, lx->src + num_end, lx->pos - num_end);
  if (!ok && numeric_ok && bg_lex_is_unit(suffix)) { /* "1mH", "10uF" */
    bg_diag_error(lx->dg, loc_at(lx, start), "units are not part of expressions: '%s' is the "
                  "number %.*s with the unit %s; write the number alone and give the unit in "
                  "the description (param L0 = %.*s \"inductance [%s]\")", text,
                  (int)(num_end - start), lx->src + start, suffix, (int)(num_end - start),
                  lx->src + start, suffix);
    push(lx, BG_TK_ERROR, start);
    return;
  }
  if (!ok) {
    bg_diag_error(lx->dg, loc_at(lx, start), "malformed number '%s'", text);
    push(lx, BG_TK_ERROR, start);
    return;
  }
  bg_token *t = push(lx, BG_TK_NUMBER, start);
  t->text = text;
  t->num = strtod(text, NULL);
}

/* A '.' right after a name, then digits: a numbered port (K.1, K.2.e of a
 * field, docs/format.md), lexed as '.' and a whole number, never as the
 * number .1 (a name followed by a number was a syntax error before). */
static int after_name(const lexer *lx) {
  if (lx->pos <= lx->line_start) return 0;
  int c = (unsigned char)lx->src[lx->pos - 1];
  return isalnum(c) || c == '_';
}

static void lex_port_number(lexer *lx) {
  push(lx, BG_TK_DOT, lx->pos++);
  size_t start = lx->pos;
  skip_digits(lx);
  bg_token *t = push(lx, BG_TK_NUMBER, start);
  t->text = bg_arena_strndup(lx->arena, lx->src + start, lx->pos - start);
  t->num = strtod(t->text, NULL);
}

/* string: '"' { char | '\"' | '\\' } '"' on one physical line */
static void lex_string(lexer *lx) {
  size_t start = lx->pos++;
  char *buf = bg_arena_alloc(lx->arena, lx->len - start + 1);
  size_t n = 0;
  for (;;) {
    int c = peek(lx, 0);
    if (c == -1 || c == '\n') {
      bg_diag_error(lx->dg, loc_at(lx, start), "unterminated string (a string ends on its line)");
      push(lx, BG_TK_ERROR, start);
      return;
    }
    lx->pos++;
    if (c == '"') break;
    if (c == '\\') {
      int d = peek(lx, 0);
      if (d != '"' && d != '\\') {
        bg_diag_error(lx->dg, loc_at(lx, lx->pos - 1),
                      "unknown escape in string (only \\\" and \\\\ are allowed)");
        continue;
      }
      lx->pos++;
      c = d;
    }
    buf[n++] = (char)c;
  }
  bg_token *t = push(lx, BG_TK_STRING, start);
  t->text = buf;
}

/* Punctuation, longest match first. */
static const struct { const char *s; bg_tkind k; } puncts[] = {
    {"->|", BG_TK_ARROW_HEAD}, {"|->", BG_TK_ARROW_TAIL}, {"->", BG_TK_ARROW},
    {"<=", BG_TK_LE}, {">=", BG_TK_GE}, {"==", BG_TK_EQ}, {"!=", BG_TK_NE},
    {"&&", BG_TK_AND}, {"||", BG_TK_OR},
    {"=", BG_TK_ASSIGN}, {",", BG_TK_COMMA}, {";", BG_TK_SEMI}, {":", BG_TK_COLON},
    {".", BG_TK_DOT}, {"'", BG_TK_PRIME}, {"(", BG_TK_LPAREN}, {")", BG_TK_RPAREN},
    {"[", BG_TK_LBRACK}, {"]", BG_TK_RBRACK}, {"+", BG_TK_PLUS}, {"-", BG_TK_MINUS},
    {"*", BG_TK_STAR}, {"/", BG_TK_SLASH}, {"^", BG_TK_CARET}, {"<", BG_TK_LT},
    {">", BG_TK_GT}, {"!", BG_TK_NOT},
};

static int lex_punct(lexer *lx) {
  for (size_t i = 0; i < sizeof puncts / sizeof puncts[0]; i++) {
    size_t n = strlen(puncts[i].s);
    if (lx->pos + n <= lx->len && memcmp(lx->src + lx->pos, puncts[i].s, n) == 0) {
      size_t start = lx->pos;
      lx->pos += n;
      push(lx, puncts[i].k, start);
      return 1;
    }
  }
  return 0;
}

/* Reports a stray character (a whole UTF-8 sequence) and skips it. */
static void lex_stray(lexer *lx) {
  size_t start = lx->pos++;
  while ((peek(lx, 0) & 0xC0) == 0x80) lx->pos++;
  bg_diag_error(lx->dg, loc_at(lx, start), "unexpected character '%.*s'",
                (int)(lx->pos - start), lx->src + start);
  push(lx, BG_TK_ERROR, start);
}

static void lex_eol(lexer *lx) {
  size_t at = lx->pos;
  if (at > lx->line_start && lx->src[at - 1] == '\r') at--;
  if (lx->line_has_tokens) push(lx, BG_TK_EOL, at);
}

void bg_lex_all(const char *src, size_t len, bg_arena *a, bg_diags *dg, bg_tokens *out) {
  bg_lex_source(src, len, 0, a, dg, out);
}

void bg_lex_source(const char *src, size_t len, int file, bg_arena *a, bg_diags *dg,
                   bg_tokens *out) {
  lexer lx = {src, len, 0, 1, 0, a, dg, out, 0, 0, file};
  out->tok = NULL;
  out->n = 0;
  if (len >= 3 && memcmp(src, "\xEF\xBB\xBF", 3) == 0) lx.pos = lx.line_start = 3; /* BOM */
  for (;;) {
    skip_space(&lx);
    int c = peek(&lx, 0);
    if (c == -1) break;
    if (c == '\n') { lex_eol(&lx); newline(&lx); }
    else if (isalpha(c) || c == '_') lex_name(&lx);
    else if (c == '.' && isdigit(peek(&lx, 1)) && after_name(&lx)) lex_port_number(&lx);
    else if (isdigit(c) || (c == '.' && isdigit(peek(&lx, 1)))) lex_number(&lx);
    else if (c == '"') lex_string(&lx);
    else if (!lex_punct(&lx)) lex_stray(&lx);
  }
  lex_eol(&lx);
  push(&lx, BG_TK_EOF, lx.pos);
}

void bg_lex_free(bg_tokens *t) {
  free(t->tok);
  t->tok = NULL;
  t->n = 0;
}

const char *bg_lex_kind_name(bg_tkind k) {
  static const char *const names[] = {
      "end of file", "end of line", "invalid token", "name", "number", "string",
      "'='", "','", "';'", "':'", "'.'", "\"'\"", "'('", "')'", "'['", "']'",
      "'+'", "'-'", "'*'", "'/'", "'^'", "'<'", "'<='", "'>'", "'>='", "'=='", "'!='",
      "'&&'", "'||'", "'!'", "'->'", "'->|'", "'|->'"};
  return (unsigned)k < sizeof names / sizeof names[0] ? names[k] : "?";
}
