/* SPDX-License-Identifier: BSD-3-Clause */
/* Lexer for .bg files: the whole source becomes one token array, with a
 * BG_TK_EOL token at the end of every logical line (a line ending in `\`
 * continues on the next). Lexical errors go to the diagnostics and leave a
 * BG_TK_ERROR token, so the parser can skip that statement silently. Internal
 * to the lang stage (lex.c, parse.c): other stages include lang/lang.h. */
#ifndef BG_LEX_H
#define BG_LEX_H
#include <stddef.h>

#include "base/arena.h"
#include "base/diag.h"

typedef enum {
  BG_TK_EOF, BG_TK_EOL, BG_TK_ERROR,
  BG_TK_NAME, BG_TK_NUMBER, BG_TK_STRING,
  BG_TK_ASSIGN,  /* = */
  BG_TK_COMMA, BG_TK_SEMI, BG_TK_COLON, BG_TK_DOT, BG_TK_PRIME,
  BG_TK_LPAREN, BG_TK_RPAREN, BG_TK_LBRACK, BG_TK_RBRACK,
  BG_TK_PLUS, BG_TK_MINUS, BG_TK_STAR, BG_TK_SLASH, BG_TK_CARET,
  BG_TK_LT, BG_TK_LE, BG_TK_GT, BG_TK_GE, BG_TK_EQ, BG_TK_NE,
  BG_TK_AND, BG_TK_OR, BG_TK_NOT,
  BG_TK_ARROW,        /* -> */
  BG_TK_ARROW_HEAD,   /* ->| stroke at the head */
  BG_TK_ARROW_TAIL    /* |-> stroke at the tail */
} bg_tkind;

typedef struct bg_token {
  bg_tkind kind;
  bg_srcloc loc;
  int start, end;   /* byte offsets of the token in the source */
  const char *text; /* NAME: the name; STRING: unescaped; NUMBER: as written */
  double num;       /* NUMBER */
} bg_token;

typedef struct bg_tokens {
  bg_token *tok; /* owned (malloc) */
  int n;
} bg_tokens;

/* 1 when w is a unit (V, mH, uF, ohm, kohm...): the messages for "12 V" and
 * "1mH", which take a unit for part of an expression. */
int bg_lex_is_unit(const char *w);
/* Tokenizes src (len bytes). Strings live in arena a; errors go to dg. */
void bg_lex_all(const char *src, size_t len, bg_arena *a, bg_diags *dg, bg_tokens *out);
/* The same for source `file` of dg (a used file): positions carry that index. */
void bg_lex_source(const char *src, size_t len, int file, bg_arena *a, bg_diags *dg,
                   bg_tokens *out);
void bg_lex_free(bg_tokens *t);
/* Human name of a token kind for "expected ... near ..." messages. */
const char *bg_lex_kind_name(bg_tkind k);
#endif
