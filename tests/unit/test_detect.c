/* SPDX-License-Identifier: BSD-3-Clause */
/* Effort and flow detectors (De, Df): a detector changes no causality and no
 * equation (the model with and without detectors gives the same strokes and
 * the same equations), its name reads its node's effort or flow in any
 * expression, it is an output of the linear analysis, and inside a submodel
 * it is qualified like the other names. */
#include "causality/causality.h"
#include "equations/equations.h"
#include "harness.h"
#include "lang/lang.h"
#include "model/model.h"
#include "analysis/analysis.h"

typedef struct run {
  bg_model *m;
  bg_analysis a;
  bg_diags dg;
  char *eqs;
  int ok;
} run;

static void go(run *r, const char *src) {
  memset(r, 0, sizeof *r);
  bg_diags_init(&r->dg, "det.bg", src, strlen(src));
  bg_ast *ast = bg_parse_string("det.bg", src, strlen(src), &r->dg);
  if (ast && !r->dg.nerrors) r->m = bg_model_compile(ast, NULL, 0, &r->dg);
  bg_ast_free(ast);
  if (!r->m) { bg_diags_print(&r->dg, stderr); return; }
  bg_analysis_init(&r->a, r->m);
  bg_causality_assign(r->m, BG_METHOD_SCAP, &r->a, &r->dg);
  bg_analysis_run(r->m, &r->a, NULL);
  bg_eqsys *s = bg_eqsys_build(r->m, &r->a, &r->dg);
  bg_strbuf sb = {0};
  if (s) bg_eqprint_text(s, &sb);
  r->eqs = strdup(bg_sb_str(&sb));
  bg_sb_free(&sb);
  bg_eqsys_free(s);
  r->ok = s != NULL;
}

/* The equations without the detectors' section (the outputs they add). */
static void strip_detectors(char *eqs) {
  char *a = eqs ? strstr(eqs, "# detectors") : NULL;
  if (!a) return;
  char *b = strchr(a + 1, '#');
  while (b && b[-1] != '\n') b = strchr(b + 1, '#');
  memmove(a, b ? b : a + strlen(a), strlen(b ? b : a + strlen(a)) + 1);
}

static void done(run *r) {
  if (r->m) bg_analysis_free(&r->a), bg_model_free(r->m);
  bg_diags_free(&r->dg);
  free(r->eqs);
}

#define RLC "model det\nSe U = 1\n1 j\nR R1 = 2\nI L1 = 0.5\n0 n\nC C1 = 0.1\nR R2 = 4\n" \
            "bond U -> j\nbond j -> R1\nbond j -> L1\nbond j -> n\nbond n -> C1\nbond n -> R2\n"

static void test_no_change(void) {
  run plain, det;
  go(&plain, RLC "plot C1.e, j.f\n");
  go(&det, RLC "De vC = n\nDf i = j\nDe vR = R2\nplot vC, i\n");
  OK(plain.ok && det.ok);
  if (!plain.ok || !det.ok) { done(&plain), done(&det); return; }
  INT_EQ(det.m->nelem, plain.m->nelem); /* no element, no bond */
  INT_EQ(det.m->nbond, plain.m->nbond);
  for (int b = 0; b < plain.m->nbond; b++) INT_EQ(det.a.bond_stroke[b], plain.a.bond_stroke[b]);
  /* the equations printed name each detector's bond variable */
  OK(strstr(det.eqs, "# detectors (outputs: the bond variables they read)\nvC = e4\ni = f1\nvR = e6\n") != NULL);
  OK(strstr(plain.eqs, "# detectors") == NULL);
  strip_detectors(det.eqs);
  STR_EQ(det.eqs, plain.eqs);
  INT_EQ(det.m->ndet, 3);
  STR_EQ(det.m->elem_name[det.m->det_node[1]], "j");
  INT_EQ(det.m->det_var[1], 'f');
  /* the plot reads what the detector names: n's effort, j's flow */
  const bg_xnode *x0 = &det.m->xnode[det.m->plotexpr_root[0]];
  const bg_xnode *p0 = &plain.m->xnode[plain.m->plotexpr_root[0]];
  INT_EQ(x0->op, BG_X_EFFORT);
  INT_EQ(p0->op, BG_X_EFFORT);
  const bg_xnode *x1 = &det.m->xnode[det.m->plotexpr_root[1]];
  INT_EQ(x1->op, BG_X_FLOW);
  /* the 0-junction's effort is C1's (bond 5's) effort: the same variable */
  INT_EQ(det.m->bond_num[x0->ref] == 4 || det.m->bond_num[x0->ref] == 5 || det.m->bond_num[x0->ref] == 6, 1);
  /* outputs of the linear analysis, in statement order */
  INT_EQ(det.m->noutput, 3);
  STR_EQ(det.m->output_name[0], "vC");
  STR_EQ(det.m->output_name[2], "vR");
  done(&plain);
  done(&det);
}

static void test_in_submodel(void) {
  run r;
  go(&r, "submodel Load(R = 2)\n  port a\n  1 j\n  R r = R\n  Df i = j\n  bond a -> j\n"
         "  bond j -> r\nend\nSe U = 3\nLoad L1\nbond U -> L1.a\nplot L1.i\n");
  OK(r.ok);
  if (r.ok) {
    INT_EQ(r.m->ndet, 1);
    STR_EQ(r.m->det_name[0], "L1.i");
    STR_EQ(r.m->elem_name[r.m->det_node[0]], "L1.j");
    INT_EQ(r.m->xnode[r.m->plotexpr_root[0]].op, BG_X_FLOW);
  }
  done(&r);
}

int main(void) {
  test_no_change();
  test_in_submodel();
  return bg_t_done();
}
