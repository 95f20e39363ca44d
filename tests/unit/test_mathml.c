/* SPDX-License-Identifier: BSD-3-Clause */
/* The MathML printer (sym_print.c's third form, eqprint.c's
 * bg_eqprint_mathml): known expressions print as the presentation MathML a
 * reader expects (fractions, powers, roots, functions, signs, numbers with
 * exponents, comparisons); every example's equations give one <math> per row
 * the LaTeX printer writes, with balanced elements. What the rows mean is
 * checked against the text printer by tests/html/mathml_check.py. */
#include "harness.h"
#include "eqs_fixture.h"
#include "examples_list.h"
#include "equations/equations.h"
#include "sym/sym.h"

static const char *src =
    "model small\nparam R = 3, C0 = 0.5\n"
    "Se U = 1\n1 j\nR R1 = R\nC C1 = C0\nbond 1 U -> j\nbond 2 j -> R1\nbond 3 j -> C1\n";

static void ml(bg_sym *S, int a, const char *want) {
  bg_strbuf sb = {0};
  bg_sym_print(S, a, BG_SYM_MATHML, NULL, NULL, &sb);
  BG_T_REPORT(!strcmp(bg_sb_str(&sb), want), "printed\n  %s\nexpected\n  %s", bg_sb_str(&sb), want);
  bg_sb_free(&sb);
}

static void test_known(void) {
  efx f;
  OK(efx_load(&f, NULL, src, -1, NULL, 0) == 0);
  if (!f.m) { efx_free(&f); return; }
  bg_sym *S = bg_sym_new(f.m);
  int R = bg_sym_leaf(S, SYM_PARAM, 0), C = bg_sym_leaf(S, SYM_PARAM, 1);
  int x = bg_sym_leaf(S, SYM_Y, 0), y = bg_sym_leaf(S, SYM_Y, 1);
  ml(S, bg_sym_mul(S, R, x), "<mi>R</mi><mo>&#x2062;</mo><mi>y0</mi>");
  ml(S, bg_sym_div(S, x, C), "<mfrac><mrow><mi>y0</mi></mrow><mrow><mi>C0</mi></mrow></mfrac>");
  ml(S, bg_sym_sub(S, x, y), "<mi>y0</mi><mo>&#x2212;</mo><mi>y1</mi>");
  ml(S, bg_sym_neg(S, x), "<mo>&#x2212;</mo><mi>y0</mi>");
  ml(S, bg_sym_powc(S, x, 2), "<msup><mrow><mi>y0</mi></mrow><mrow><mn>2</mn></mrow></msup>");
  ml(S, bg_sym_powc(S, bg_sym_add(S, x, y), 0.5), "<msqrt><mi>y0</mi><mo>+</mo><mi>y1</mi></msqrt>");
  ml(S, bg_sym_call(S, BG_FN_SIN, 1, (int[]){x}),
     "<mi>sin</mi><mo>&#x2061;</mo><mrow><mo>(</mo><mi>y0</mi><mo>)</mo></mrow>");
  ml(S, bg_sym_num(S, 2.5e-7),
     "<mn>2.5</mn><mo>&#x22c5;</mo><msup><mn>10</mn><mrow><mo>&#x2212;</mo><mn>7</mn></mrow></msup>");
  ml(S, bg_sym_num(S, -4), "<mo>&#x2212;</mo><mn>4</mn>");
  /* a sum as a factor keeps its parentheses; a quotient of two factors */
  ml(S, bg_sym_mul(S, R, bg_sym_add(S, x, y)),
     "<mi>R</mi><mo>&#x2062;</mo><mrow><mo>(</mo><mi>y0</mi><mo>+</mo><mi>y1</mi><mo>)</mo></mrow>");
  ml(S, bg_sym_div(S, x, bg_sym_mul(S, R, C)),
     "<mfrac><mrow><mi>y0</mi></mrow><mrow><mi>R</mi><mo>&#x2062;</mo><mi>C0</mi></mrow></mfrac>");
  ml(S, bg_sym_op(S, BG_X_LT, x, y), "<mi>y0</mi><mo>&lt;</mo><mi>y1</mi>");
  bg_sym_free(S);
  /* the equation system's names: bond variables, store states, a derivative */
  bg_strbuf b = {0};
  bg_eqprint_mathml(f.s, &b);
  const char *t = bg_sb_str(&b);
  OK(strstr(t, "<msub><mi>q</mi><mi mathvariant=\"normal\">C1</mi></msub>") != NULL);
  OK(strstr(t, "<msub><mi>e</mi><mn>3</mn></msub>") != NULL);
  OK(strstr(t, "<mover accent=\"true\"><mrow><msub><mi>q</mi><mi mathvariant=\"normal\">C1</mi></msub></mrow>"
               "<mo>&#x02d9;</mo></mover><mo>=</mo>") != NULL);
  bg_sb_free(&b);
  efx_free(&f);
}

/* Elements open and close in order (names only; no attribute holds '<'). */
static int balanced(const char *s) {
  char stack[256][16];
  int n = 0;
  for (const char *p = strchr(s, '<'); p; p = strchr(p + 1, '<')) {
    const char *e = strchr(p, '>');
    if (!e) return 0;
    int close = p[1] == '/', self = e[-1] == '/';
    const char *nm = p + 1 + close;
    size_t len = strcspn(nm, " />");
    if (len >= 16) return 0;
    if (self) continue;
    if (close) {
      if (n == 0 || strncmp(stack[n - 1], nm, len) || stack[n - 1][len]) return 0;
      n--;
    } else {
      if (n == 256) return 0;
      memcpy(stack[n], nm, len), stack[n][len] = 0, n++;
    }
  }
  return n == 0;
}

static int count(const char *s, const char *what) {
  int n = 0;
  for (const char *p = strstr(s, what); p; p = strstr(p + 1, what)) n++;
  return n;
}

static void test_examples(void) {
  char *names[64];
  int n = bg_t_list_examples(names, 64);
  OK(n >= 10);
  for (int i = 0; i < n; i++) {
    char stem[128];
    snprintf(stem, sizeof stem, "%.*s", (int)strlen(names[i]) - 3, names[i]);
    efx f;
    if (efx_load(&f, stem, NULL, -1, NULL, 0) == 0) {
      bg_strbuf m = {0}, l = {0};
      bg_eqprint_mathml(f.s, &m);
      bg_eqprint_latex(f.s, &l);
      int rows = count(bg_sb_str(&m), "<math display=\"block\">"), lrows = count(bg_sb_str(&l), " \\\\\n");
      BG_T_REPORT(rows == lrows, "%s: %d MathML rows, %d LaTeX rows", stem, rows, lrows);
      BG_T_REPORT(balanced(bg_sb_str(&m)), "%s: unbalanced MathML", stem);
      bg_sb_free(&m), bg_sb_free(&l);
    }
    efx_free(&f);
    free(names[i]);
  }
}

int main(void) {
  test_known();
  test_examples();
  return bg_t_done();
}
