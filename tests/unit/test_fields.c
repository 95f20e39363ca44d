/* SPDX-License-Identifier: BSD-3-Clause */
/* Multiport C and R fields (docs/format.md, Multiport fields): the ports as
 * one-port elements, the energy's gradient (checked against src/sym's
 * bg_sym_diff), and the two reference models of tests/data/fields/ against
 * hand-derived equations: the printed equations, and trajectories against
 * an independent integration (RK4 of the hand-derived ODE; the reaction also
 * against its closed-form solution). */
#include "harness.h"
#include "sim_fixture.h"
#include "base/strbuf.h"
#include "equations/equations.h"
#include "model/model.h"
#include "sym/sym.h"
#include "json/json.h"

/* Loads tests/data/fields/NAME.bg, applies nedit (from, to) edits, runs. */
static int load_edits(fx *f, const char *name, const char *const (*edit)[2], int nedit) {
  char path[512];
  size_t len;
  snprintf(path, sizeof path, "%s/tests/data/fields/%s.bg", BG_SOURCE_DIR, name);
  memset(f, 0, sizeof *f);
  f->src = bg_read_file(path, &len);
  if (!f->src) return -1;
  for (int i = 0; i < nedit; i++)
    if (fx_edit(f, edit[i][0], edit[i][1])) return -1;
  return fx_run(f, path, BG_METHOD_SCAP, NULL, 0, NULL);
}

static int load_data(fx *f, const char *name, const char *from, const char *to) {
  const char *const edit[1][2] = {{from, to}};
  return load_edits(f, name, edit, from ? 1 : 0);
}

/* ---------------------------------------------------------------- the model */
static void test_ports_as_elements(void) {
  fx f;
  OK(load_data(&f, "transducer", NULL, NULL) == 0 && f.m);
  if (!f.m) return;
  const bg_model *m = f.m;
  INT_EQ(m->nfield, 1);
  STR_EQ(m->field_name[0], "K");
  INT_EQ(m->field_kind[0], BG_ELEM_C);
  INT_EQ(m->field_nport[0], 2);
  int el = bg_model_find_elem(m, "K.el"), mech = bg_model_find_elem(m, "K.mech");
  INT_EQ(el, m->field_elemadr[0]);
  INT_EQ(mech, el + 1);
  INT_EQ(bg_elem_field(m, el), 0);
  INT_EQ(m->elem_fport[mech], 2);
  STR_EQ(bg_elem_port_name(m, mech), "mech");
  INT_EQ(bg_model_find_elem(m, "K"), -1); /* the field itself is no element */
  INT_EQ(m->elem_form[el], BG_FORM_LAW_E);
  OK(m->field_energy[0] >= 0);
  /* the ports read each other's q: no signal, not modulated */
  INT_EQ(m->nsignal, 0);
  INT_EQ(m->elem_modulated[el] + m->elem_modulated[mech], 0);
  /* e_el = q x / (eps A) is linear in q; e_mech = q^2/(2 eps A) does not read x */
  INT_EQ(m->elem_linear[el], 1);
  INT_EQ(m->elem_linear[mech], 1);
  /* both ports in integral causality; states are the ports' q */
  INT_EQ(f.a.elem_caus[el], BG_CAUS_INTEGRAL);
  INT_EQ(f.a.elem_caus[mech], BG_CAUS_INTEGRAL);
  fx_free(&f);
}

/* The same field written with numbered ports and laws per port gives the same
 * trajectories as the energy form. */
static void test_numbered_laws_equal_energy(void) {
  static const char *const edit[][2] = {
      {"C K(el, mech) : energy = el.q^2 * mech.q / (2*eps*A)",
       "C K(2) : e1 = q1*q2/(eps*A), e2 = q1^2/(2*eps*A)"},
      {"je -> K.el", "je -> K.1"}, {"jm -> K.mech", "jm -> K.2"},
      {"plot K.el.q, K.mech.q, mass.p, K.el.e", "plot K.1.q, K.2.q, mass.p, K.1.e"}};
  fx a, b;
  OK(load_data(&a, "transducer", NULL, NULL) == 0 && a.rc == 0);
  OK(load_edits(&b, "transducer", edit, 4) == 0 && b.rc == 0);
  if (b.m) {
    OK(bg_model_find_elem(b.m, "K.1") >= 0 && b.m->field_numbered[0]);
    INT_EQ(b.m->field_energy[0], -1);
  }
  int ca = col(&a.r, "K.mech.q"), cb = col(&b.r, "K.2.q");
  OK(ca >= 0 && cb >= 0 && a.r.nrows == b.r.nrows && a.r.nrows > 10);
  double worst = 0;
  for (int i = 0; ca >= 0 && cb >= 0 && i < a.r.nrows && i < b.r.nrows; i++)
    worst = fmax(worst, fabs(val(&a.r, i, ca) - val(&b.r, i, cb)));
  BG_T_REPORT(worst < 1e-12, "energy form against laws per port: %g", worst);
  fx_free(&a);
  fx_free(&b);
}

/* ---------------------------------------------------------------- gradient */
/* The efforts of an energy field against bg_sym_diff of the energy, at
 * several points. */
static void check_gradient(const char *energy) {
  char text[1024];
  snprintf(text, sizeof text,
           "param c = 0.7\nSe U = 1\nSe V = 2\nC K(2) : energy = %s\nbond U -> K.1\nbond V -> K.2\n",
           energy);
  fx f;
  memset(&f, 0, sizeof f);
  f.src = strdup(text);
  size_t len = strlen(f.src);
  bg_diags_init(&f.dg, "inline.bg", f.src, len);
  bg_ast *ast = bg_parse_string("inline.bg", f.src, len, &f.dg);
  f.m = ast ? bg_model_compile(ast, NULL, 0, &f.dg) : NULL;
  if (ast) bg_ast_free(ast);
  OK(f.m != NULL);
  if (!f.m) { bg_diags_print(&f.dg, stderr); fx_free(&f); return; }
  const bg_model *m = f.m;
  int p1 = m->field_elemadr[0], store_y[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
  store_y[p1] = 0, store_y[p1 + 1] = 1;
  bg_sym *S = bg_sym_new(m);
  int w = bg_sym_from_x(S, m->field_energy[0], NULL, store_y);
  static const double pts[][2] = {{0.3, 1.7}, {-0.4, 0.9}, {1.2, -0.6}, {2.0, 0.25}};
  for (int p = 0; p < 4; p++) {
    double store[8] = {0}, y[2] = {pts[p][0], pts[p][1]};
    store[p1] = y[0], store[p1 + 1] = y[1];
    bg_xenv env = {0};
    env.store = store;
    bg_symenv senv = {0};
    senv.y = y;
    for (int k = 0; k < 2; k++) {
      double mine = bg_xeval(m, m->elem_expr[p1 + k], &env);
      double ref = bg_sym_eval(S, bg_sym_diff(S, w, bg_sym_leaf(S, SYM_Y, k)), &senv);
      BG_T_REPORT(fabs(mine - ref) <= 1e-12 * (1 + fabs(ref)), "d(%s)/dq%d at (%g, %g): %.17g vs %.17g",
                  energy, k + 1, y[0], y[1], mine, ref);
    }
  }
  bg_sym_free(S);
  bg_model_free(f.m);
  f.m = NULL;
  fx_free(&f);
}

static void test_gradient_against_sym(void) {
  check_gradient("q1^2*q2/(2*c)");
  check_gradient("c*q1*q2 + q1^3/3 - q2/(1 + q1^2)");
  check_gradient("exp(q1*q2) + log(2 + q2^2) + sqrt(3 + q1^2) + log10(5 + q1^2)");
  check_gradient("sin(q1)*cos(q2) + tan(q1/3) + atan(q2) + asin(q1/3) + acos(q2/3)");
  check_gradient("sinh(q1) + cosh(q2) + tanh(q1*q2) + abs(q1 - q2) + atan2(q1, 2 + q2)");
  check_gradient("pow(2 + q1^2, q2) + (3 + q2^2)^q1 + (1 + q1^2)^2.5 + ramp(q1)*q2");
  check_gradient("min(q1, q2)^2 + max(q1*q2, 0.5) + sat(q1, -0.5, 1)*q2 + if(q1 > 0, q1*q2, -q2)");
  check_gradient("step(q1)*q2 + floor(q1) + sign(q2)*q1 + pulse(q1, 1)");
}

/* ---------------------------------------------------------------- transducer */
/* The hand-derived equations: q' = (U0 - q x/(eps A))/Rs, x' = p/m0,
 * p' = -q^2/(2 eps A) - k s - b0 p/m0, s' = p/m0. */
static void transducer_rhs(const double *y, double *dy) {
  const double U0 = 1, Rs = 1, epsA = 1, m0 = 1, k = 4, b0 = 0.5;
  double q = y[0], x = y[1], p = y[2], s = y[3];
  dy[0] = (U0 - q * x / epsA) / Rs;
  dy[1] = p / m0;
  dy[2] = -q * q / (2 * epsA) - k * s - b0 * p / m0;
  dy[3] = p / m0;
}

static void rk4(void (*rhs)(const double *, double *), double *y, int n, double h) {
  double k1[8], k2[8], k3[8], k4[8], t[8];
  rhs(y, k1);
  for (int i = 0; i < n; i++) t[i] = y[i] + h / 2 * k1[i];
  rhs(t, k2);
  for (int i = 0; i < n; i++) t[i] = y[i] + h / 2 * k2[i];
  rhs(t, k3);
  for (int i = 0; i < n; i++) t[i] = y[i] + h * k3[i];
  rhs(t, k4);
  for (int i = 0; i < n; i++) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
}

static void test_transducer_equations(void) {
  fx f;
  OK(load_data(&f, "transducer", NULL, NULL) == 0 && f.s);
  if (!f.s) { fx_free(&f); return; }
  bg_strbuf out = {0};
  bg_eqprint_text(f.s, &out);
  /* e_el = dW/dq = q x/(eps A) on bond 3, e_mech = dW/dx = q^2/(2 eps A) on bond 4 */
  OK(has(out.s, "e3 = K.el.q*K.mech.q/(eps*A)\n"));
  OK(has(out.s, "e4 = 0.5*K.el.q^2/(eps*A)\n"));
  OK(has(out.s, "K.el.q' = f3\n"));
  OK(has(out.s, "K.mech.q' = f4\n"));
  OK(has(out.s, "e5 = -e4 - e6 - e7\n")); /* the plate's force balance at jm */
  if (!has(out.s, "e3 = K.el.q*K.mech.q/(eps*A)\n")) fputs(out.s, stderr);
  bg_sb_free(&out);
  fx_free(&f);
}

static void test_transducer_trajectory(void) {
  fx f;
  OK(load_data(&f, "transducer", NULL, NULL) == 0 && f.rc == 0);
  int cq = col(&f.r, "K.el.q"), cx = col(&f.r, "K.mech.q"), cp = col(&f.r, "mass.p");
  OK(cq >= 0 && cx >= 0 && cp >= 0);
  INT_EQ(f.r.nrows, 21);
  double y[4] = {0, 1, 0, 0}, worst = 0;
  int steps = 200; /* RK4 at h = 0.0025 per output interval of 0.5 */
  for (int i = 1; i < f.r.nrows && cq >= 0 && cx >= 0 && cp >= 0; i++) {
    for (int s = 0; s < steps; s++) rk4(transducer_rhs, y, 4, 0.5 / steps);
    double d[3] = {val(&f.r, i, cq) - y[0], val(&f.r, i, cx) - y[1], val(&f.r, i, cp) - y[2]};
    for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(d[k]));
  }
  BG_T_REPORT(worst < 1e-6, "transducer against RK4: worst difference %g", worst);
  /* port mech's bond drawn out of the field: the same trajectories */
  fx g;
  OK(load_data(&g, "transducer", "bond jm -> K.mech", "bond K.mech -> jm") == 0 && g.rc == 0);
  int gx = col(&g.r, "K.mech.q");
  double diff = 0;
  for (int i = 0; gx >= 0 && cx >= 0 && i < f.r.nrows && i < g.r.nrows; i++)
    diff = fmax(diff, fabs(val(&f.r, i, cx) - val(&g.r, i, gx)));
  OK(gx >= 0 && g.r.nrows == f.r.nrows);
  BG_T_REPORT(diff < 1e-9, "transducer with port mech's bond reversed: %g", diff);
  fx_free(&g);
  /* the plates were pulled together: the gap is below x0 at the end */
  OK(cx >= 0 && val(&f.r, f.r.nrows - 1, cx) < 0.99);
  fx_free(&f);
}

/* ---------------------------------------------------------------- reaction */
static void test_reaction(void) {
  fx f;
  OK(load_data(&f, "reaction", NULL, NULL) == 0 && f.rc == 0 && f.s);
  if (!f.s) { fx_free(&f); return; }
  bg_strbuf out = {0};
  bg_eqprint_text(f.s, &out);
  /* v = kr (exp(mu_A/RT) - exp(mu_B/RT)) into port a, -v into port b */
  OK(has(out.s, "f2 = kr*(exp(e2/RT) - exp(e3/RT))\n"));
  OK(has(out.s, "f3 = kr*(exp(e3/RT) - exp(e2/RT))\n"));
  OK(has(out.s, "e1 = RT*log(KA*A.q)\n"));
  bg_sb_free(&out);
  /* closed form: u = KA qA - KB qB decays at kr (KA + KB); qA + qB = N */
  const double kr = 0.5, KA = 1, KB = 3, N = 1.1, u0 = 1 - 3 * 0.1;
  int ca = col(&f.r, "A.q"), cb = col(&f.r, "B.q");
  double worst = 0;
  for (int i = 0; i < f.r.nrows && ca >= 0 && cb >= 0; i++) {
    double u = u0 * exp(-kr * (KA + KB) * f.r.t[i]);
    worst = fmax(worst, fabs(val(&f.r, i, ca) - (KB * N + u) / (KA + KB)));
    worst = fmax(worst, fabs(val(&f.r, i, cb) - (KA * N - u) / (KA + KB)));
  }
  OK(ca >= 0 && cb >= 0 && f.r.nrows == 17);
  BG_T_REPORT(worst < 1e-6, "reaction against the closed form: worst difference %g", worst);
  /* the own-variable convention: port b's bond drawn out of the field means the same */
  fx g;
  OK(load_data(&g, "reaction", "bond jB -> Re.b", "bond Re.b -> jB") == 0 && g.rc == 0);
  int gb = col(&g.r, "B.q");
  double diff = 0;
  for (int i = 0; gb >= 0 && cb >= 0 && i < f.r.nrows && i < g.r.nrows; i++)
    diff = fmax(diff, fabs(val(&f.r, i, cb) - val(&g.r, i, gb)));
  OK(gb >= 0 && g.r.nrows == f.r.nrows);
  BG_T_REPORT(diff < 1e-9, "reaction with port b's bond reversed: %g", diff);
  fx_free(&g);
  fx_free(&f);
}


/* ---------------------------------------------------------------- the chapter's notions */
/* The causal path between elements named a and b (either order), or -1. */
static int path_between(const fx *f, const char *a, const char *b) {
  int ea = bg_model_find_elem(f->m, a), eb = bg_model_find_elem(f->m, b);
  for (int i = 0; i < f->a.npath; i++)
    if ((f->a.path_end0[i] == ea && f->a.path_end1[i] == eb) ||
        (f->a.path_end0[i] == eb && f->a.path_end1[i] == ea))
      return i;
  return -1;
}

static int numeric_index(fx *f) {
  bg_index_result r;
  memset(&r, 0, sizeof r);
  int k = bg_index_compute(f->s, f->m, &r);
  bg_index_free(&r);
  return k;
}

/* A causal path of class cls between a and b, predicted and numeric index 1,
 * and an algebraic loop with that cause and gain. */
static void check_paths_index(fx *f, const char *a, const char *b, int cls, const char *cause,
                              double gain) {
  int p = path_between(f, a, b), found = 0;
  OK(p >= 0);
  INT_EQ(p >= 0 ? f->a.path_class[p] : -1, cls);
  INT_EQ(f->a.index_predicted, 1);
  INT_EQ(numeric_index(f), 1);
  for (int i = 0; i < f->a.ntloop; i++)
    if (has(f->a.tloop_cause[i], cause) && f->a.tloop_algebraic[i]) {
      found = 1;
      DBL_NEAR(f->a.tloop_gain_value[i], gain, 1e-9);
    }
  BG_T_REPORT(found, "an algebraic loop from %s", cause);
}

/* Dependent store in a field: mixed causality, a class 1 path between two
 * ports of one field, index 1 predicted and numeric, and the trajectory of
 * the hand-derived DAE (q1 = (b - c) F t/(a + b - 2c)). */
static void test_dependent_port(void) {
  fx f;
  OK(load_data(&f, "dependent", NULL, NULL) == 0 && f.s && f.rc == 0);
  if (!f.s) { fx_free(&f); return; }
  int k1 = bg_model_find_elem(f.m, "K.1"), k2 = bg_model_find_elem(f.m, "K.2");
  INT_EQ(f.a.elem_caus[k1], BG_CAUS_INTEGRAL);
  INT_EQ(f.a.elem_caus[k2], BG_CAUS_DERIVATIVE);
  INT_EQ(f.a.ndependent, 1);
  STR_EQ(f.a.ndependent ? f.a.dependent_stores[0] : NULL, "K.2");
  /* the field's coupling closes an algebraic loop of gain c/b through the
   * dependent port (q2 = (e - c q1)/b): not 1, so solvable */
  check_paths_index(&f, "K.1", "K.2", 1, "coupling of the ports of field K", 1.0 / 5.0);
  OK(bg_json_field_mixed(f.m, &f.a, 0));
  int c1 = col(&f.r, "K.1.q"), c2 = col(&f.r, "K.2.q");
  double worst = 0;
  for (int i = 0; c1 >= 0 && c2 >= 0 && i < f.r.nrows; i++) {
    double t = f.r.t[i], Q = 2 * t; /* F0 = 2, a = 3, b = 5, c = 1 */
    worst = fmax(worst, fabs(val(&f.r, i, c1) - 4 * Q / 6));
    worst = fmax(worst, fabs(val(&f.r, i, c2) - 2 * Q / 6));
  }
  OK(c1 >= 0 && c2 >= 0 && f.r.nrows == 5);
  BG_T_REPORT(worst < 1e-6, "dependent port against the hand-derived solution: %g", worst);
  fx_free(&f);
}

/* An R field port in the causality its law does not have: solved
 * implicitly; a class 2 path between the field's port and Ra; the field's
 * coupling an algebraic loop of gain Rm^2/(R1 R2); index 1; the trajectory
 * q(t) = q_inf + (q0 - q_inf) exp(-t/(C0 Reff)). */
static void test_implicit_r_field(void) {
  fx f;
  OK(load_data(&f, "implicit", NULL, NULL) == 0 && f.s && f.rc == 0);
  if (!f.s) { fx_free(&f); return; }
  int r1 = bg_model_find_elem(f.m, "Rf.1"), r2 = bg_model_find_elem(f.m, "Rf.2");
  INT_EQ(f.a.elem_caus[r2], BG_CAUS_CONDUCTANCE);
  INT_EQ(f.a.elem_inverted[r2], 1);
  INT_EQ(f.a.elem_caus[r1], BG_CAUS_CONDUCTANCE);
  check_paths_index(&f, "Ra", "Rf.1", 2, "coupling of the ports of field Rf", 1.0 / 8.0);
  const double U0 = 2, F2 = 0.5, Rt = 1 + 2, R2 = 4, Rm = 1, C0 = 0.5, Reff = R2 - Rm * Rm / Rt;
  const double qinf = C0 * (F2 * Reff + Rm * U0 / Rt);
  int cq = col(&f.r, "C2.q");
  double worst = 0;
  for (int i = 0; cq >= 0 && i < f.r.nrows; i++)
    worst = fmax(worst, fabs(val(&f.r, i, cq) - qinf * (1 - exp(-f.r.t[i] / (C0 * Reff)))));
  OK(cq >= 0 && f.r.nrows == 7);
  BG_T_REPORT(worst < 1e-6, "implicit R field against the closed form: %g", worst);
  fx_free(&f);
}

/* A causality option per port that propagation contradicts is a conflict
 * at that port; a time constant from a path between a field port and an R:
 * Rs times the port's capacitance eps A / x0 (the slope of its effort). */
static void test_conflict_and_estimate(void) {
  fx f;
  OK(load_data(&f, "dependent", "c*q1*q2 + b*q2^2/2", "c*q1*q2 + b*q2^2/2  [causality = (integral, integral)]") == 0);
  if (f.m) {
    int k2 = bg_model_find_elem(f.m, "K.2"), n = 0;
    for (int i = 0; i < f.a.nconflict; i++) n += f.a.conflict_node[i] == k2;
    INT_EQ(n, 1);
  }
  fx_free(&f);
  OK(load_data(&f, "transducer", NULL, NULL) == 0);
  int p = f.m ? path_between(&f, "K.el", "Rs1") : -1, est = 0;
  OK(p >= 0);
  for (int i = 0; i < f.a.nestimate; i++)
    if (f.a.estimate_path[i] == p && f.a.estimate_kind[i] == 0) {
      est = 1;
      DBL_NEAR(f.a.estimate_value[i], 1.0, 1e-9); /* Rs eps A / x0 = 1 */
    }
  OK(est);
  fx_free(&f);
}

/* A field inside a submodel: qualified by the instance (T1.K.el), joined
 * through the submodel's ports, the same trajectories as the flat model; a
 * field of the model's own scope beside it (K, both ports driven by efforts:
 * derivative causality). */
static void test_field_in_submodel(void) {
  fx a, b;
  OK(load_data(&a, "transducer", NULL, NULL) == 0 && a.rc == 0);
  OK(load_data(&b, "transducer_sub", NULL, NULL) == 0 && b.rc == 0);
  if (!b.m) { fx_free(&a); fx_free(&b); return; }
  INT_EQ(b.m->nfield, 2);
  STR_EQ(b.m->field_name[0], "T1.K");
  int el = bg_model_find_elem(b.m, "T1.K.el"), k2 = bg_model_find_elem(b.m, "K.2");
  OK(el >= 0 && k2 >= 0);
  INT_EQ(el >= 0 ? b.m->elem_inst[el] : -2, 0);
  INT_EQ(k2 >= 0 ? b.a.elem_caus[k2] : -1, BG_CAUS_DERIVATIVE);
  static const char *const cols[][2] = {{"K.el.q", "T1.K.el.q"}, {"K.mech.q", "T1.K.mech.q"},
                                        {"mass.p", "mass.p"}};
  double worst = 0;
  for (int c = 0; c < 3; c++) {
    int ca = col(&a.r, cols[c][0]), cb = col(&b.r, cols[c][1]);
    OK(ca >= 0 && cb >= 0 && a.r.nrows == b.r.nrows);
    for (int i = 0; ca >= 0 && cb >= 0 && i < a.r.nrows && i < b.r.nrows; i++)
      worst = fmax(worst, fabs(val(&a.r, i, ca) - val(&b.r, i, cb)));
  }
  BG_T_REPORT(worst < 1e-6, "field in a submodel against the flat model: %g", worst);
  fx_free(&a);
  fx_free(&b);
}

int main(void) {
  test_ports_as_elements();
  test_numbered_laws_equal_energy();
  test_gradient_against_sym();
  test_transducer_equations();
  test_transducer_trajectory();
  test_reaction();
  test_dependent_port();
  test_implicit_r_field();
  test_conflict_and_estimate();
  test_field_in_submodel();
  return bg_t_done();
}
