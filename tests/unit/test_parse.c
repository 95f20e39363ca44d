/* SPDX-License-Identifier: BSD-3-Clause */
/* Parser: every statement form, the expression grammar (checked by value
 * through bg_model_compile + bg_xeval), functions, tables, error recovery. */
#include <stdlib.h>

#include "model/model.h"
#include "harness.h"
#include "lang/lang.h"

#define PI 3.14159265358979323846

static bg_ast *parse(const char *src, bg_diags *dg) {
  bg_diags_init(dg, "t.bg", src, strlen(src));
  return bg_parse_string(BG_SOURCE_DIR "/tests/data/t.bg", src, strlen(src), dg);
}

/* Compiles src and returns the model (NULL on errors); dg is left for checks. */
static bg_model *compile(const char *src, bg_diags *dg) {
  bg_ast *ast = parse(src, dg);
  bg_model *m = dg->nerrors ? NULL : bg_model_compile(ast, NULL, 0, dg);
  bg_ast_free(ast);
  return m;
}

/* The value of `param p = EXPR`, with x = 2 and y = 0.5 available. */
static double eval(const char *expr) {
  char src[1024];
  snprintf(src, sizeof src, "param x = 2, y = 0.5\nparam p = %s\n", expr);
  bg_diags dg;
  bg_model *m = compile(src, &dg);
  double v = NAN;
  if (m) v = m->param_value[2];
  else fprintf(stderr, "eval(%s): %s\n", expr, dg.n ? dg.items[0].msg : "?");
  bg_model_free(m);
  bg_diags_free(&dg);
  return v;
}

/* The value of plot expression `expr` (may use t and an input u = 2*t) at time t. */
static double eval_t(const char *expr, double t) {
  char src[1024];
  snprintf(src, sizeof src, "input u = 2*t\nplot %s\n", expr);
  bg_diags dg;
  bg_model *m = compile(src, &dg);
  double v = NAN;
  bg_xenv env = {0};
  env.t = t;
  if (m) v = bg_xeval(m, m->plotexpr_root[0], &env);
  else fprintf(stderr, "eval_t(%s): %s\n", expr, dg.n ? dg.items[0].msg : "?");
  bg_model_free(m);
  bg_diags_free(&dg);
  return v;
}

static void test_precedence(void) {
  DBL_NEAR(eval("2^3^2"), 512, 0);
  DBL_NEAR(eval("-2^2"), -4, 0);
  DBL_NEAR(eval("2^-1"), 0.5, 0);
  DBL_NEAR(eval("1 - 2 - 3"), -4, 0);
  DBL_NEAR(eval("2*3+4"), 10, 0);
  DBL_NEAR(eval("2+3*4"), 14, 0);
  DBL_NEAR(eval("8/4/2"), 1, 0);
  DBL_NEAR(eval("(1 + 2) * 3"), 9, 0);
  DBL_NEAR(eval("1 < 2 && 3 > 4 || 1"), 1, 0);
  DBL_NEAR(eval("1 < 2 && 3 > 4"), 0, 0);
  DBL_NEAR(eval("0 || 0 && 1"), 0, 0);
  DBL_NEAR(eval("1 || 0 && 0"), 1, 0);
  DBL_NEAR(eval("1 + 1 == 2"), 1, 0);
  DBL_NEAR(eval("3 > 2 > 0"), 1, 0); /* (3 > 2) > 0 */
  DBL_NEAR(eval("1 <= 1"), 1, 0);
  DBL_NEAR(eval("1 >= 2"), 0, 0);
  DBL_NEAR(eval("1 != 2"), 1, 0);
  DBL_NEAR(eval("!0 + 1"), 2, 0);
  DBL_NEAR(eval("- -x"), 2, 0);
  DBL_NEAR(eval("+x * -y"), -1, 0);
  DBL_NEAR(eval("x^2^-1"), sqrt(2), 1e-15);
  DBL_NEAR(eval("pi"), PI, 1e-15);
  DBL_NEAR(eval("y * 4 + x"), 4, 0);
}

/* Params may refer forward; they are evaluated in dependency order. */
static void test_forward_params(void) {
  bg_diags dg;
  bg_model *m = compile("param p = later + 1, later = q * 2\nparam q = 21\n", &dg);
  OK(m != NULL);
  if (m) {
    INT_EQ(m->nparam, 3);
    STR_EQ(m->param_name[0], "q"); /* dependency order */
    STR_EQ(m->param_name[1], "later");
    STR_EQ(m->param_name[2], "p");
    DBL_NEAR(m->param_value[2], 43, 0);
  }
  bg_model_free(m);
  bg_diags_free(&dg);
}

static void test_numbers(void) {
  DBL_NEAR(eval("2."), 2, 0);
  DBL_NEAR(eval(".5"), 0.5, 0);
  DBL_NEAR(eval("1e-3"), 1e-3, 0);
  DBL_NEAR(eval("2.5e2"), 250, 0);
}

static void test_functions(void) {
  DBL_NEAR(eval("abs(-3)"), 3, 0);
  DBL_NEAR(eval("sign(-3) + sign(0) * 10 + sign(5) * 100"), 99, 0);
  DBL_NEAR(eval("sqrt(16)"), 4, 0);
  DBL_NEAR(eval("exp(1)"), exp(1), 1e-15);
  DBL_NEAR(eval("log(exp(2))"), 2, 1e-15);
  DBL_NEAR(eval("log10(1000)"), 3, 1e-15);
  DBL_NEAR(eval("sin(pi/2)"), 1, 1e-15);
  DBL_NEAR(eval("cos(pi)"), -1, 1e-15);
  DBL_NEAR(eval("tan(pi/4)"), 1, 1e-15);
  DBL_NEAR(eval("asin(1)"), PI / 2, 1e-15);
  DBL_NEAR(eval("acos(0)"), PI / 2, 1e-15);
  DBL_NEAR(eval("atan(1)"), PI / 4, 1e-15);
  DBL_NEAR(eval("atan2(1, -1)"), 3 * PI / 4, 1e-15);
  DBL_NEAR(eval("sinh(1)"), sinh(1), 1e-15);
  DBL_NEAR(eval("cosh(1)"), cosh(1), 1e-15);
  DBL_NEAR(eval("tanh(0.5)"), tanh(0.5), 1e-15);
  DBL_NEAR(eval("min(x, y)"), 0.5, 0);
  DBL_NEAR(eval("max(x, y)"), 2, 0);
  DBL_NEAR(eval("pow(x, 10)"), 1024, 0);
  DBL_NEAR(eval("floor(-1.5)"), -2, 0);
  DBL_NEAR(eval("ceil(1.2)"), 2, 0);
  DBL_NEAR(eval("if(x > 1, 10, 20)"), 10, 0);
  DBL_NEAR(eval("if(x < 1, 10, 20)"), 20, 0);
  DBL_NEAR(eval("step(-1) + 10 * step(0) + 100 * step(2)"), 110, 0);
  DBL_NEAR(eval("ramp(-1) + ramp(3)"), 3, 0);
  DBL_NEAR(eval("pulse(0.5, 1) + 10 * pulse(1, 1) + 100 * pulse(-0.1, 1)"), 1, 0);
  DBL_NEAR(eval("sat(5, 0, 2) + 10 * sat(-1, 0, 2) + 100 * sat(1.5, 0, 2)"), 152, 0);
  /* time and inputs */
  DBL_NEAR(eval_t("t", 0.25), 0.25, 0);
  DBL_NEAR(eval_t("u + 1", 3), 7, 0);
  DBL_NEAR(eval_t("step(t - 1)", 0.5), 0, 0);
  DBL_NEAR(eval_t("step(t - 1)", 1.5), 1, 0);
}

static void test_tables(void) {
  DBL_NEAR(eval_t("table(t, [0, 0; 1, 10; 3, 20])", 0.5), 5, 1e-12);
  DBL_NEAR(eval_t("table(t, [0, 0; 1, 10; 3, 20])", 2), 15, 1e-12);
  DBL_NEAR(eval_t("table(t, [0, 0; 1, 10; 3, 20])", -1), 0, 0);  /* clamped */
  DBL_NEAR(eval_t("table(t, [0, 0; 1, 10; 3, 20])", 9), 20, 0);  /* clamped */
  /* the CSV has a comment, a header line and a trailing comment */
  DBL_NEAR(eval_t("table(t, \"table_ramp.csv\")", 0.5), 5, 1e-12);
  DBL_NEAR(eval_t("table(t, \"table_ramp.csv\")", 2), 15, 1e-12);
  DBL_NEAR(eval_t("2 * table(u, \"table_ramp.csv\")", 1), 30, 1e-12);
  bg_diags dg;
  bg_model *m = compile("plot table(t, \"table_bad.csv\")\n", &dg);
  OK(m == NULL);
  INT_EQ(dg.nerrors, 1);
  if (dg.nerrors) {
    INT_EQ(dg.items[0].loc.col, 6);
    OK(strstr(dg.items[0].msg, "line 3") != NULL);
  }
  bg_diags_free(&dg);
}

static void test_statement_forms(void) {
  const char *src =
      "model m \"A \\\"title\\\"\"\n"
      "param a = 1 \"first\", b = a * 2\n"
      "input u = a * t\n"
      "state z' = -z [init = 1]\n"
      "Se U = u\n"
      "1 j [label = \"J\", at = (10, 20)]\n"
      "R R1 : f = e / 2\n"
      "bond U ->| j\n"
      "bond 7 j |-> R1 [color = \"#00ff00\"]\n"
      "causality relaxed\n"
      "simulate [t_end = 2, dt = 0.5]\n"
      "plot j.f, R1.e [title = \"T\"]\n"
      "layout engine = neato, rankdir = TB\n";
  bg_diags dg;
  bg_ast *ast = parse(src, &dg);
  INT_EQ(dg.nerrors, 0);
  INT_EQ(ast->nstmts, 14);
  const bg_ast_stmt *s = ast->stmts;
  INT_EQ(s[0].kind, BG_ST_MODEL);
  STR_EQ(s[0].text, "A \"title\"");
  INT_EQ(s[1].kind, BG_ST_PARAM);
  STR_EQ(s[1].name, "a");
  STR_EQ(s[1].text, "first");
  STR_EQ(s[2].name, "b");
  STR_EQ(s[2].expr->text, "a * 2");
  OK(s[2].text == NULL);
  INT_EQ(s[3].kind, BG_ST_INPUT);
  INT_EQ(s[4].kind, BG_ST_STATE);
  STR_EQ(s[4].name, "z");
  INT_EQ(s[4].nopts, 1);
  STR_EQ(s[4].opts[0].key, "init");
  INT_EQ(s[5].kind, BG_ST_ELEMENT);
  STR_EQ(s[5].kindword, "Se");
  STR_EQ(s[6].kindword, "1");
  INT_EQ(s[6].nopts, 2);
  INT_EQ(s[6].opts[1].value->kind, BG_EX_TUPLE);
  INT_EQ(s[7].has_law, 1);
  INT_EQ(s[7].law_var, 'f');
  STR_EQ(s[7].expr->text, "e / 2");
  INT_EQ(s[8].kind, BG_ST_BOND);
  INT_EQ(s[8].number, 0);
  INT_EQ(s[8].arrow, BG_ARROW_STROKE_HEAD);
  INT_EQ(s[9].number, 7);
  INT_EQ(s[9].arrow, BG_ARROW_STROKE_TAIL);
  STR_EQ(s[9].from, "j");
  STR_EQ(s[9].to, "R1");
  INT_EQ(s[9].to_loc.col, 14);
  INT_EQ(s[10].kind, BG_ST_CAUSALITY);
  STR_EQ(s[10].name, "relaxed");
  INT_EQ(s[11].kind, BG_ST_SIMULATE);
  INT_EQ(s[11].nopts, 2);
  INT_EQ(s[12].kind, BG_ST_PLOT);
  INT_EQ(s[12].nexprs, 2);
  STR_EQ(s[12].exprs[1]->text, "R1.e");
  INT_EQ(s[13].kind, BG_ST_LAYOUT);
  INT_EQ(s[13].nopts, 2);
  bg_model *m = bg_model_compile(ast, NULL, 0, &dg);
  OK(m != NULL);
  if (m) {
    STR_EQ(m->name, "m");
    INT_EQ(m->method, BG_METHOD_RELAXED);
    DBL_NEAR(m->sim.t_end, 2, 0);
    DBL_NEAR(m->sim.dt, 0.5, 0);
    STR_EQ(m->layout.engine, "neato");
    STR_EQ(m->layout.rankdir, "TB");
    STR_EQ(m->plot_title[0], "T");
    STR_EQ(m->bond_color[1], "#00ff00");
    INT_EQ(m->bond_num[0], 1);
    INT_EQ(m->bond_fix[0], BG_FIX_HEAD);
    INT_EQ(m->bond_fix[1], BG_FIX_TAIL);
    INT_EQ(m->elem_has_at[1], 1);
    DBL_NEAR(m->elem_at_y[1], 20, 0);
    DBL_NEAR(bg_xeval(m, m->state_init[0], NULL), 1, 0);
    DBL_NEAR(m->param_value[1], 2, 0);
    STR_EQ(m->param_desc[0], "first");
  }
  bg_model_free(m);
  bg_ast_free(ast);
  bg_diags_free(&dg);
}

static void test_continuation_and_crlf(void) {
  bg_diags dg;
  bg_model *m = compile("param a = 1 + \\\r\n  2 * \\\n  3\r\nplot a + \\\n   a\r\n", &dg);
  OK(m != NULL);
  if (m) {
    DBL_NEAR(m->param_value[0], 7, 0);
    STR_EQ(m->plotexpr_text[0], "a + a");
  }
  bg_model_free(m);
  bg_diags_free(&dg);
}

static void test_error_recovery(void) {
  bg_diags dg;
  bg_ast *ast = parse("param a = (1\nparam b = 2\nparam = 3\nparam c = 1 +\nparam d 4\n", &dg);
  INT_EQ(dg.nerrors, 4);
  INT_EQ(ast->nstmts, 1); /* only b survives */
  STR_EQ(ast->stmts[0].name, "b");
  int lines[] = {1, 3, 4, 5};
  for (int i = 0; i < dg.n && i < 4; i++) INT_EQ(dg.items[i].loc.line, lines[i]);
  bg_ast_free(ast);
  bg_diags_free(&dg);
  ast = parse("Cpa C1 = 1\n", &dg);
  INT_EQ(dg.nerrors, 1);
  STR_EQ(dg.items[0].msg, "unknown element kind 'Cpa' (did you mean 'C'?)");
  bg_ast_free(ast);
  bg_diags_free(&dg);
}

/* A dropped line's names are remembered (bg_diags_unsure: no follow-on
 * error names them); a dropped bond without both ends makes every bond count
 * unsure; names of lines that parsed are not. */
static void test_dropped_names(void) {
  bg_diags dg;
  bg_ast *ast = parse("param k = 2\nR R1 = k *\nC C2 = 1\nbond M1.a -> \n", &dg);
  INT_EQ(dg.nerrors, 2);
  INT_EQ(dg.nskipped, 2);
  INT_EQ(ast->nstmts, 2); /* k and C2 */
  OK(bg_diags_unsure(&dg, "R1"));
  OK(bg_diags_unsure(&dg, "M1"));
  OK(bg_diags_unsure(&dg, "M1.b"));      /* the instance named on the dropped bond */
  OK(bg_diags_unsure(&dg, "X.Y.R1"));    /* R1 of an instance: its last part */
  OK(!bg_diags_unsure(&dg, "C2"));
  OK(!bg_diags_unsure(&dg, "k2"));
  OK(bg_diags_unsure_bonds(&dg, "C2"));  /* the bond names one end only */
  INT_EQ(bg_diags_failures(&dg), 2 + dg.unsaid);
  bg_ast_free(ast);
  bg_diags_free(&dg);
  ast = parse("Se U = 1\nR R1 = 1\nC C2 = 1\nbond U -> R1 [\n", &dg);
  INT_EQ(dg.nskipped, 1);
  OK(!bg_diags_unsure_bonds(&dg, "C2")); /* both ends named: only they are unsure */
  OK(bg_diags_unsure_bonds(&dg, "R1"));
  bg_ast_free(ast);
  bg_diags_free(&dg);
}

static void test_depth_limit(void) {
  char src[4096] = "param p = ";
  for (int i = 0; i < 150; i++) strcat(src, "(");
  strcat(src, "1");
  for (int i = 0; i < 150; i++) strcat(src, ")");
  strcat(src, "\n");
  bg_diags dg;
  bg_model *m = compile(src, &dg);
  OK(m != NULL); /* 150 levels are fine */
  bg_model_free(m);
  bg_diags_free(&dg);
  for (int i = 0; i < 100; i++) memmove(src + 11, src + 10, strlen(src + 10) + 1), src[10] = '(';
  bg_ast_free(parse(src, &dg));
  INT_EQ(dg.nerrors, 1);
  OK(dg.n && strstr(dg.items[0].msg, "nested too deeply"));
  bg_diags_free(&dg);
}

int main(void) {
  test_precedence();
  test_forward_params();
  test_numbers();
  test_functions();
  test_tables();
  test_statement_forms();
  test_continuation_and_crlf();
  test_error_recovery();
  test_dropped_names();
  test_depth_limit();
  return bg_t_done();
}
