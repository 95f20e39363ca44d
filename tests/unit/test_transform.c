/* SPDX-License-Identifier: BSD-3-Clause */
/* The transformations' text editor (src/transform/tx_doc.c): statements
 * spanning continuation lines, comments kept, CRLF and a byte-order mark;
 * and the merged store through the library call, its parameter evaluated. */
#include "harness.h"
#include "analysis/analysis.h"
#include "causality/causality.h"
#include "lang/lang.h"
#include "model/model.h"
#include "transform/tx_int.h"

static void test_doc_edits(void) {
  const char *src = "\xEF\xBB\xBFmodel m\r\n"
                    "R a = 1 + \\\r\n"
                    "      2   # cont\r\n"
                    "R b = 3   # a comment with a \\\r\n"
                    "R c = 4 \\   # not a continuation\r\n"
                    "bond a -> b\r\n";
  tx_doc d;
  tx_doc_init(&d, src, strlen(src));
  INT_EQ(d.nline, 6);
  INT_EQ(tx_stmt_end(&d, 2), 3);
  INT_EQ(tx_stmt_end(&d, 4), 4);
  INT_EQ(tx_stmt_end(&d, 5), 5);
  tx_replace_stmt(&d, 2, "R a = 3");
  tx_delete_stmt(&d, 5);
  tx_insert_after(&d, 2, "R z = 9");
  tx_insert_after(&d, 0, "# top");
  bg_sb_puts(&d.head, "# head\n");
  char *t = tx_doc_text(&d);
  /* most lines end in CR LF (4 of 6): so do the new ones (issue 28) */
  STR_EQ(t, "# head\r\n# top\r\nmodel m\r\nR a = 3  # cont\r\nR z = 9\r\n"
            "R b = 3   # a comment with a \\\r\nbond a -> b\r\n");
  free(t);
  tx_doc_free(&d);
}

static bg_model *compile(const char *src, bg_diags *dg) {
  bg_ast *ast = bg_parse_string("t.bg", src, strlen(src), dg);
  bg_model *m = ast && !dg->nerrors ? bg_model_compile(ast, NULL, 0, dg) : NULL;
  if (ast) bg_ast_free(ast);
  return m;
}

/* Two capacitors on 0-junctions through a TF: e2 = n e1, so a C on side 2
 * adds n^2 times its capacitance to one on side 1. */
static void test_merge_capacitors(void) {
  const char *src = "param C1v = 2, C2v = 5, n = 3, R0 = 1\n"
                    "Sf S = 1\n0 a\nC C1 = C1v\nTF T = n\n0 b\nC C2 = C2v\nR R1 = R0\n"
                    "bond S -> a\nbond a -> C1\nbond a -> T\nbond T -> b\nbond b -> C2\n"
                    "bond b -> R1\n";
  bg_diags dg;
  bg_diags_init(&dg, "t.bg", src, strlen(src));
  bg_ast *ast = bg_parse_string("t.bg", src, strlen(src), &dg);
  bg_model *m = compile(src, &dg);
  OK(m != NULL);
  bg_analysis a;
  bg_analysis_init(&a, m);
  bg_causality_assign(m, BG_METHOD_SCAP, &a, &dg);
  bg_analysis_run(m, &a, NULL);
  bg_transform_input in = {"merge-stores", src, strlen(src), "t.bg", ast, m, &a, NULL, 0};
  bg_transform_result r;
  char *why = NULL;
  INT_EQ(bg_transform_apply(&in, &r, &why), 0);
  OK(strstr(r.text, "C   C1 = C1v + C2v*n^2\n") != NULL);
  int e = bg_model_find_elem(r.run->model, "C1");
  OK(e >= 0 && bg_model_find_elem(r.run->model, "C2") < 0);
  INT_EQ(r.run->analysis.elem_caus[e], BG_CAUS_INTEGRAL);
  INT_EQ(r.run->analysis.ndependent, 0);
  bg_xenv env = {0};
  DBL_NEAR(bg_xeval(r.run->model, r.run->model->elem_expr[e], &env), 2 + 9 * 5, 1e-12);
  bg_transform_result_free(&r);
  bg_analysis_free(&a);
  bg_model_free(m);
  bg_ast_free(ast);
  bg_diags_free(&dg);
}

int main(void) {
  test_doc_edits();
  test_merge_capacitors();
  return bg_t_done();
}
