/* SPDX-License-Identifier: BSD-3-Clause */
/* Model compiler: the examples' arrays in detail, bond numbering, params with
 * overrides and dependency order, signals, modulation, linearity, queries. */
#include <stdlib.h>

#include "model/model.h"
#include "harness.h"
#include "lang/lang.h"

/* Compiles a model from text (path only names the file). */
static bg_model *compile_src(const char *path, const char *src, const bg_param_override *ov,
                             int nov, bg_diags *dg) {
  bg_diags_init(dg, path, src, strlen(src));
  bg_ast *ast = bg_parse_string(path, src, strlen(src), dg);
  bg_model *m = dg->nerrors ? NULL : bg_model_compile(ast, ov, nov, dg);
  bg_ast_free(ast);
  return m;
}

static bg_model *example(const char *name, const bg_param_override *ov, int nov) {
  char path[512];
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  size_t len;
  char *src = bg_read_file(path, &len);
  OK(src != NULL);
  if (!src) return NULL;
  bg_diags dg;
  bg_model *m = compile_src(path, src, ov, nov, &dg);
  if (!m)
    for (int i = 0; i < dg.n; i++) fprintf(stderr, "%s: %s\n", name, dg.items[i].msg);
  OK(m != NULL);
  bg_diags_free(&dg);
  free(src);
  return m;
}

static int elem(const bg_model *m, const char *name) { return bg_model_find_elem(m, name); }

static void test_rlc(void) {
  bg_model *m = example("rlc", NULL, 0);
  if (!m) return;
  STR_EQ(m->name, "rlc");
  STR_EQ(m->title, "Series RLC circuit driven by a voltage step");
  INT_EQ(m->nelem, 5);
  int kinds[] = {BG_ELEM_SE, BG_ELEM_J1, BG_ELEM_R, BG_ELEM_I, BG_ELEM_C};
  const char *names[] = {"U", "j", "R1", "L1", "C1"};
  for (int e = 0; e < 5; e++) {
    INT_EQ(m->elem_kind[e], kinds[e]);
    STR_EQ(m->elem_name[e], names[e]);
  }
  INT_EQ(m->nbond, 4);
  int tails[] = {0, 1, 1, 1}, heads[] = {1, 2, 3, 4};
  for (int b = 0; b < 4; b++) {
    INT_EQ(m->bond_num[b], b + 1);
    INT_EQ(m->bond_tail[b], tails[b]);
    INT_EQ(m->bond_head[b], heads[b]);
    INT_EQ(m->bond_fix[b], BG_FIX_NONE);
  }
  INT_EQ(m->elem_nbond[1], 4);
  for (int i = 0; i < 4; i++) INT_EQ(m->elem_bonds[m->elem_bondadr[1] + i], i);
  INT_EQ(bg_elem_port_bond(m, elem(m, "C1")), 3);
  INT_EQ(m->elem_loc[2].line, 6);
  INT_EQ(m->elem_loc[2].col, 5);
  /* params and values */
  INT_EQ(m->nparam, 4);
  DBL_NEAR(m->param_value[1], 10, 0);
  bg_xenv env = {0};
  env.t = 1;
  DBL_NEAR(bg_xeval(m, m->elem_expr[0], &env), 1, 0); /* V * step(t) */
  env.t = -1;
  DBL_NEAR(bg_xeval(m, m->elem_expr[0], &env), 0, 0);
  DBL_NEAR(bg_xeval(m, m->elem_expr[3], NULL), 1e-3, 0);
  for (int e = 0; e < 5; e++) {
    INT_EQ(m->elem_form[e], e == 1 ? BG_FORM_NONE : BG_FORM_VALUE);
    INT_EQ(m->elem_modulated[e], 0);
    INT_EQ(m->elem_init[e], -1);
  }
  INT_EQ(m->elem_linear[2], 1);
  INT_EQ(m->nsignal, 0);
  OK(m->sim.present);
  DBL_NEAR(m->sim.t_end, 2e-3, 0);
  DBL_NEAR(m->sim.dt, 1e-6, 0);
  STR_EQ(m->sim.solver, "auto");
  INT_EQ(m->nplot, 1);
  INT_EQ(m->plot_nexpr[0], 2);
  STR_EQ(m->plotexpr_text[1], "L1.f");
  INT_EQ(m->xnode[m->plotexpr_root[0]].op, BG_X_EFFORT);
  INT_EQ(m->xnode[m->plotexpr_root[0]].ref, 3);
  INT_EQ(m->xnode[m->plotexpr_root[1]].op, BG_X_FLOW);
  INT_EQ(m->xnode[m->plotexpr_root[1]].ref, 2);
  INT_EQ(m->method, BG_METHOD_SCAP);
  INT_EQ(m->method_given, 0);
  bg_strbuf sb = {0};
  bg_model_summary(m, &sb);
  STR_EQ(bg_sb_str(&sb), "rlc: 4 elements (Se 1, R 1, I 1, C 1), 1 junction, 4 bonds; 2 stores, 1 source");
  bg_sb_free(&sb);
  bg_model_free(m);
}

static void test_slider_crank(void) {
  bg_model *m = example("slider_crank", NULL, 0);
  if (!m) return;
  int T = elem(m, "T"), w = elem(m, "w"), v = elem(m, "v");
  INT_EQ(m->elem_kind[T], BG_ELEM_MTF);
  INT_EQ(m->elem_modulated[T], 1);
  STR_EQ(bg_elem_display_kind(m, T), "MTF");
  INT_EQ(bg_elem_in_bond(m, T), 2);  /* bond 3 v -> T */
  INT_EQ(bg_elem_out_bond(m, T), 3); /* bond 4 T -> w */
  INT_EQ(m->bond_tail[2], v);
  INT_EQ(m->bond_head[3], w);
  INT_EQ(bg_bond_other(m, 3, T), w);
  INT_EQ(m->nstate, 1);
  STR_EQ(m->state_name[0], "phi");
  INT_EQ(m->xnode[m->state_expr[0]].op, BG_X_FLOW); /* w.f: the flow of w's first bond */
  INT_EQ(m->xnode[m->state_expr[0]].ref, 0);
  DBL_NEAR(bg_xeval(m, m->state_init[0], NULL), 0, 0);
  INT_EQ(m->nsignal, 1);
  INT_EQ(m->signal_from[0], -1);
  INT_EQ(m->signal_to[0], T);
  STR_EQ(m->signal_var[0], "phi");
  /* the modulus at phi = pi/2: rc*(0 + sqrt(L^2 - rc^2))*1/sqrt(L^2 - rc^2) = rc */
  double phi = 3.14159265358979323846 / 2;
  bg_xenv env = {0};
  env.state = &phi;
  DBL_NEAR(bg_xeval(m, m->elem_expr[T], &env), 0.05, 1e-15);
  DBL_NEAR(bg_xeval(m, m->elem_expr[elem(m, "F")], NULL), 0, 0); /* -F0 */
  INT_EQ(m->nplotexpr, 3);
  STR_EQ(m->plotexpr_text[0], "phi");
  INT_EQ(m->xnode[m->plotexpr_root[0]].op, BG_X_STATE);
  bg_model_free(m);
}

static void test_fixed_strokes(void) {
  bg_model *m = example("class12_paths", NULL, 0);
  if (m) {
    int b = bg_model_find_bond(m, 5);
    INT_EQ(b, 4);
    INT_EQ(m->bond_fix[b], BG_FIX_TAIL);
    STR_EQ(m->elem_name[m->bond_tail[b]], "jB");
    for (int k = 0; k < m->nbond; k++)
      if (k != b) INT_EQ(m->bond_fix[k], BG_FIX_NONE);
  }
  bg_model_free(m);
  m = example("loop_class1", NULL, 0);
  if (m) {
    int b = bg_model_find_bond(m, 7);
    INT_EQ(m->bond_fix[b], BG_FIX_HEAD);
    STR_EQ(m->elem_name[m->bond_head[b]], "jP");
    OK(!m->sim.present || m->nplot == 0);
  }
  bg_model_free(m);
}

static void test_bond_numbering(void) {
  bg_diags dg;
  bg_model *m = compile_src("n.bg",
                            "Se U = 1\n0 a\n0 b\n0 c\nR R1 = 1\nR R2 = 1\n"
                            "bond 3 U -> a\nbond a -> b\nbond 1 b -> c\nbond c -> R1\nbond a -> R2\n",
                            NULL, 0, &dg);
  OK(m != NULL);
  if (m) {
    int want[] = {3, 2, 1, 4, 5};
    for (int k = 0; k < 5; k++) INT_EQ(m->bond_num[k], want[k]);
    INT_EQ(bg_model_find_bond(m, 4), 3);
    INT_EQ(bg_model_find_bond(m, 9), -1);
  }
  bg_model_free(m);
  bg_diags_free(&dg);
  m = compile_src("n.bg", "Se U = 1\n0 a\nR R1 = 1\nbond 2 U -> a\nbond 2 a -> R1\n", NULL, 0, &dg);
  OK(m == NULL);
  INT_EQ(dg.nerrors, 1);
  if (dg.n) {
    STR_EQ(dg.items[0].msg, "bond 2 already defined at line 4");
    INT_EQ(dg.items[0].loc.line, 5);
    INT_EQ(dg.items[0].loc.col, 6);
  }
  bg_diags_free(&dg);
}

static void test_params_overrides(void) {
  bg_param_override ov[] = {{"R0", 20}, {"V", 3}};
  bg_model *m = example("rlc", ov, 2);
  if (m) {
    DBL_NEAR(bg_xeval(m, m->elem_expr[elem(m, "R1")], NULL), 20, 0);
    INT_EQ(m->param_overridden[1], 1);
    INT_EQ(m->param_overridden[2], 0);
    bg_xenv env = {0};
    env.t = 1;
    DBL_NEAR(bg_xeval(m, m->elem_expr[0], &env), 3, 0);
  }
  bg_model_free(m);
  /* an override reaches the params that depend on it */
  bg_diags dg;
  bg_param_override ov2[] = {{"b", 5}};
  m = compile_src("p.bg", "param a = b * 2\nparam b = 1, c = a + b\n", ov2, 1, &dg);
  OK(m != NULL);
  if (m) {
    STR_EQ(m->param_name[0], "b");
    STR_EQ(m->param_name[1], "a");
    STR_EQ(m->param_name[2], "c");
    DBL_NEAR(m->param_value[1], 10, 0);
    DBL_NEAR(m->param_value[2], 15, 0);
  }
  bg_model_free(m);
  bg_diags_free(&dg);
  bg_param_override ov3[] = {{"bb", 5}};
  m = compile_src("p.bg", "param a = 1, b = 2\n", ov3, 1, &dg);
  OK(m == NULL);
  if (dg.n) {
    INT_EQ(dg.items[0].loc.line, 0);
    OK(strstr(dg.items[0].msg, "did you mean 'b'?") != NULL);
  }
  bg_diags_free(&dg);
  m = compile_src("p.bg", "param a = c + 1, b = a, c = b * 2\n", NULL, 0, &dg);
  OK(m == NULL);
  INT_EQ(dg.nerrors, 1);
  if (dg.n) STR_EQ(dg.items[0].msg, "cyclic param definition: a -> c -> b -> a");
  bg_diags_free(&dg);
}

static void test_signals(void) {
  bg_model *m = example("series_motor", NULL, 0);
  if (m) {
    INT_EQ(m->nsignal, 1);
    STR_EQ(m->elem_name[m->signal_from[0]], "ji");
    STR_EQ(m->elem_name[m->signal_to[0]], "K");
    STR_EQ(m->signal_var[0], "ji.f");
    INT_EQ(m->elem_modulated[elem(m, "K")], 1);
  }
  bg_model_free(m);
  m = example("modulated_source", NULL, 0);
  if (m) {
    INT_EQ(m->nsignal, 1);
    STR_EQ(m->elem_name[m->signal_from[0]], "R2");
    STR_EQ(m->elem_name[m->signal_to[0]], "U");
    STR_EQ(m->signal_var[0], "R2.f");
    INT_EQ(m->elem_modulated[elem(m, "U")], 1);
    INT_EQ(m->elem_modulated[elem(m, "E")], 0);
  }
  bg_model_free(m);
  m = example("internal_mod_r", NULL, 0);
  if (m) {
    int ra = elem(m, "Ra");
    INT_EQ(m->elem_modulated[ra], 1);
    STR_EQ(bg_elem_display_kind(m, ra), "MR");
    STR_EQ(bg_elem_display_kind(m, elem(m, "Rb")), "R");
    INT_EQ(m->elem_form[ra], BG_FORM_LAW_F);
    INT_EQ(m->elem_linear[ra], 1); /* G0*e*(1 + a*js.f^2) is linear in e */
    INT_EQ(m->nsignal, 1);
    STR_EQ(m->elem_name[m->signal_from[0]], "js");
  }
  bg_model_free(m);
}

static void test_linearity(void) {
  bg_model *m = example("hydraulic_bridge", NULL, 0);
  if (m) {
    int r1 = elem(m, "R1");
    INT_EQ(m->elem_form[r1], BG_FORM_LAW_F);
    INT_EQ(m->elem_linear[r1], 0);
    INT_EQ(m->elem_modulated[r1], 0); /* u is an input */
    INT_EQ(m->elem_linear[elem(m, "Rb")], 1);
  }
  bg_model_free(m);
  m = example("parallel_conductance", NULL, 0);
  if (m) INT_EQ(m->elem_linear[elem(m, "Rg")], 0); /* e^3 */
  bg_model_free(m);
  bg_diags dg;
  m = compile_src("l.bg",
                  "Se U = 1\n1 j\nR Ra : e = 2*f + 1\nR Rb : f = e^1 / 3 - if(t > 1, 2*e, e)\n"
                  "C C1 : e = q * q\nI L1 : f = p / 2 [p0 = 4]\n"
                  "bond U -> j\nbond j -> Ra\nbond j -> Rb\nbond j -> C1\nbond j -> L1\n",
                  NULL, 0, &dg);
  OK(m != NULL);
  if (m) {
    INT_EQ(m->elem_linear[elem(m, "Ra")], 1);
    INT_EQ(m->elem_form[elem(m, "Ra")], BG_FORM_LAW_E);
    INT_EQ(m->elem_linear[elem(m, "Rb")], 1);
    INT_EQ(m->elem_linear[elem(m, "C1")], 0);
    INT_EQ(m->elem_linear[elem(m, "L1")], 1);
    INT_EQ(m->xnode[m->elem_expr[elem(m, "L1")]].op, BG_X_DIV);
    DBL_NEAR(bg_xeval(m, m->elem_init[elem(m, "L1")], NULL), 4, 0);
  }
  bg_model_free(m);
  bg_diags_free(&dg);
}

static void test_queries(void) {
  STR_EQ(bg_elem_kind_name(BG_ELEM_MTF), "MTF");
  STR_EQ(bg_elem_kind_name(BG_ELEM_J0), "0");
  STR_EQ(bg_method_name(BG_METHOD_VANDIJK), "vandijk");
  INT_EQ(bg_method_parse("lagrange"), BG_METHOD_LAGRANGE);
  INT_EQ(bg_method_parse("scapp"), -1);
  OK(bg_elem_is_oneport(BG_ELEM_R) && !bg_elem_is_oneport(BG_ELEM_TF));
  OK(bg_elem_is_twoport(BG_ELEM_MGY) && bg_elem_is_store(BG_ELEM_I));
  OK(bg_elem_is_source(BG_ELEM_MSF) && bg_elem_is_junction(BG_ELEM_J1));
  bg_model *m = example("lagrange_rlc", NULL, 0);
  if (m) {
    INT_EQ(m->method, BG_METHOD_LAGRANGE);
    INT_EQ(m->method_given, 1);
    INT_EQ(m->elem_kind[elem(m, "R")], BG_ELEM_R); /* a kind word may name an element */
    OK(m->sim.present);
    DBL_NEAR(m->sim.t_end, 10.0, 0);
    INT_EQ(m->nplot, 1);
    INT_EQ(m->plot_nexpr[0], 2);
  }
  bg_model_free(m);
}

/* Every example compiles. */
static void test_all_examples(void) {
  const char *names[] = {"bond_loop", "bridge_compliance", "class12_paths", "delta",
                         "hydraulic_bridge", "internal_mod_r", "internal_mod_tf", "lagrange_rlc",
                         "loop_class1", "mod_no_loop", "modulated_source", "parallel_conductance",
                         "rlc", "series_conductances", "series_motor", "series_motor_L",
                         "slider_crank"};
  for (int i = 0; i < (int)(sizeof names / sizeof names[0]); i++) bg_model_free(example(names[i], NULL, 0));
  bg_model *m = example("internal_mod_tf", NULL, 0);
  if (m) { /* T = 1 + k*T.f2^2: T reads its own out-side flow */
    int T = elem(m, "T");
    INT_EQ(m->elem_modulated[T], 1);
    INT_EQ(m->nsignal, 1);
    INT_EQ(m->signal_from[0], T);
    STR_EQ(m->signal_var[0], "T.f2");
  }
  bg_model_free(m);
}

int main(void) {
  test_rlc();
  test_slider_crank();
  test_fixed_strokes();
  test_bond_numbering();
  test_params_overrides();
  test_signals();
  test_linearity();
  test_queries();
  test_all_examples();
  return bg_t_done();
}
