/* SPDX-License-Identifier: BSD-3-Clause */
/* Lexer: tokens, numbers, strings, continuation lines, CRLF, tabs, comments,
 * positions and lexical errors. */
#include <stdlib.h>

#include "harness.h"
#include "lang/lex_int.h"

typedef struct lexed {
  bg_arena arena;
  bg_diags dg;
  bg_tokens t;
} lexed;

static void lex(lexed *l, const char *src) {
  memset(l, 0, sizeof *l);
  bg_diags_init(&l->dg, "t.bg", src, strlen(src));
  bg_lex_all(src, strlen(src), &l->arena, &l->dg, &l->t);
}

static void unlex(lexed *l) {
  bg_lex_free(&l->t);
  bg_diags_free(&l->dg);
  bg_arena_free(&l->arena);
}

static void test_punctuation(void) {
  lexed l;
  lex(&l, "a->b ->| |-> <= >= == != && || ! ' ^ ;");
  bg_tkind want[] = {BG_TK_NAME, BG_TK_ARROW, BG_TK_NAME, BG_TK_ARROW_HEAD, BG_TK_ARROW_TAIL,
                     BG_TK_LE, BG_TK_GE, BG_TK_EQ, BG_TK_NE, BG_TK_AND, BG_TK_OR, BG_TK_NOT,
                     BG_TK_PRIME, BG_TK_CARET, BG_TK_SEMI, BG_TK_EOL, BG_TK_EOF};
  INT_EQ(l.t.n, (int)(sizeof want / sizeof want[0]));
  for (int i = 0; i < l.t.n && i < (int)(sizeof want / sizeof want[0]); i++)
    INT_EQ(l.t.tok[i].kind, want[i]);
  INT_EQ(l.dg.nerrors, 0);
  unlex(&l);
}

static void test_numbers(void) {
  lexed l;
  lex(&l, "2 2.5 1e-3 .5 2. 3E+2 007");
  double want[] = {2, 2.5, 1e-3, 0.5, 2.0, 300, 7};
  for (int i = 0; i < 7; i++) {
    INT_EQ(l.t.tok[i].kind, BG_TK_NUMBER);
    DBL_NEAR(l.t.tok[i].num, want[i], 1e-15);
  }
  STR_EQ(l.t.tok[1].text, "2.5");
  INT_EQ(l.dg.nerrors, 0);
  unlex(&l);
  const char *bad[] = {"1e", "2x", "1.2.3", "1e+"};
  for (int i = 0; i < 4; i++) {
    lex(&l, bad[i]);
    INT_EQ(l.dg.nerrors, 1);
    INT_EQ(l.t.tok[0].kind, BG_TK_ERROR);
    OK(strstr(l.dg.items[0].msg, "malformed number") != NULL);
    unlex(&l);
  }
}

static void test_strings(void) {
  lexed l;
  lex(&l, "\"a \\\"q\\\" b\\\\c\" \"\"");
  INT_EQ(l.t.tok[0].kind, BG_TK_STRING);
  STR_EQ(l.t.tok[0].text, "a \"q\" b\\c");
  STR_EQ(l.t.tok[1].text, "");
  INT_EQ(l.dg.nerrors, 0);
  unlex(&l);
  lex(&l, "x = \"open\ny = 2");
  INT_EQ(l.dg.nerrors, 1);
  INT_EQ(l.dg.items[0].loc.line, 1);
  INT_EQ(l.dg.items[0].loc.col, 5);
  OK(strstr(l.dg.items[0].msg, "unterminated string") != NULL);
  unlex(&l);
  lex(&l, "\"a\\nb\"");
  INT_EQ(l.dg.nerrors, 1);
  unlex(&l);
}

static void test_positions_tabs_comments(void) {
  lexed l;
  lex(&l, "# comment only\n\n\tR  R1 # trailing\n  x");
  INT_EQ(l.t.tok[0].kind, BG_TK_NAME);
  INT_EQ(l.t.tok[0].loc.line, 3);
  INT_EQ(l.t.tok[0].loc.col, 2); /* the tab counts as one byte column */
  INT_EQ(l.t.tok[1].loc.col, 5);
  INT_EQ(l.t.tok[2].kind, BG_TK_EOL);
  INT_EQ(l.t.tok[3].loc.line, 4);
  INT_EQ(l.t.tok[3].loc.col, 3);
  INT_EQ(l.t.tok[4].kind, BG_TK_EOL);
  INT_EQ(l.t.tok[5].kind, BG_TK_EOF);
  unlex(&l);
}

static void test_continuation_crlf(void) {
  lexed l;
  lex(&l, "a = 1 + \\\r\n   2\r\nb\r\n");
  bg_tkind want[] = {BG_TK_NAME, BG_TK_ASSIGN, BG_TK_NUMBER, BG_TK_PLUS, BG_TK_NUMBER,
                     BG_TK_EOL, BG_TK_NAME, BG_TK_EOL, BG_TK_EOF};
  INT_EQ(l.t.n, 9);
  for (int i = 0; i < l.t.n && i < 9; i++) INT_EQ(l.t.tok[i].kind, want[i]);
  INT_EQ(l.t.tok[4].loc.line, 2);
  INT_EQ(l.t.tok[4].loc.col, 4);
  INT_EQ(l.t.tok[5].loc.col, 5); /* the EOL sits where the CR is */
  INT_EQ(l.t.tok[6].loc.line, 3);
  INT_EQ(l.dg.nerrors, 0);
  unlex(&l);
}

static void test_stray(void) {
  lexed l;
  lex(&l, "a $ \xC3\xA9 b");
  INT_EQ(l.dg.nerrors, 2);
  INT_EQ(l.dg.items[0].loc.col, 3);
  OK(strstr(l.dg.items[1].msg, "'\xC3\xA9'") != NULL);
  INT_EQ(l.t.tok[3].kind, BG_TK_NAME);
  INT_EQ(l.t.tok[3].loc.col, 8);
  unlex(&l);
  lex(&l, "\"h\xC3\xA9llo\"  # caf\xC3\xA9\n"); /* UTF-8 in strings and comments */
  INT_EQ(l.dg.nerrors, 0);
  STR_EQ(l.t.tok[0].text, "h\xC3\xA9llo");
  unlex(&l);
}

int main(void) {
  test_punctuation();
  test_numbers();
  test_strings();
  test_positions_tabs_comments();
  test_continuation_crlf();
  test_stray();
  return bg_t_done();
}
