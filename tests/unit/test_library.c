/* SPDX-License-Identifier: BSD-3-Clause */
/* The component library lib/ (*.bg files): every component in a small driver model,
 * its state derivatives evaluated at a chosen state against the equations
 * derived by hand from the component's header comment. */
#include "causality/causality.h"
#include "equations/equations.h"
#include "harness.h"
#include "lang/lang.h"
#include "analysis/analysis.h"

#define LIB BG_SOURCE_DIR "/lib/"

typedef struct drv {
  bg_model *m;
  bg_analysis a;
  bg_diags dg;
  char *src;
  bg_eqsys *s;
  double y[16], ydot[16];
} drv;

/* Builds the driver: `use` of the library file, then the text. */
static int drv_load(drv *d, const char *file, const char *text) {
  memset(d, 0, sizeof *d);
  size_t n = strlen(LIB) + strlen(file) + strlen(text) + 16;
  d->src = malloc(n);
  snprintf(d->src, n, "use \"%s%s\"\n%s", LIB, file, text);
  bg_diags_init(&d->dg, "driver.bg", d->src, strlen(d->src));
  bg_ast *ast = bg_parse_string("driver.bg", d->src, strlen(d->src), &d->dg);
  if (ast && !d->dg.nerrors) d->m = bg_model_compile(ast, NULL, 0, &d->dg);
  bg_ast_free(ast);
  if (!d->m) { bg_diags_print(&d->dg, stderr); return -1; }
  bg_analysis_init(&d->a, d->m);
  bg_causality_assign(d->m, BG_METHOD_SCAP, &d->a, &d->dg);
  bg_analysis_run(d->m, &d->a, NULL);
  d->s = bg_eqsys_build(d->m, &d->a, &d->dg);
  if (!d->s || bg_eqsys_n(d->s) > 16) {
    bg_diags_print(&d->dg, stderr);
    return -1;
  }
  bg_eqsys_initial(d->s, d->y);
  return 0;
}

static int idx(const drv *d, const char *name) {
  for (int i = 0; i < bg_eqsys_n(d->s); i++)
    if (!strcmp(bg_eqsys_name(d->s, i), name)) return i;
  fprintf(stderr, "no state '%s'\n", name);
  return 15;
}

static void set(drv *d, const char *name, double v) { d->y[idx(d, name)] = v; }
static double der(drv *d, const char *name) { return d->ydot[idx(d, name)]; }
/* The state derivatives at d->y: the ODE's right-hand side, or for a DAE
 * (the transformer's resistive loop) the algebraic unknowns solved with the
 * states held, then F = yp - f(t, y) of the state rows at yp = 0. */
static void eval(drv *d) {
  if (bg_eqsys_is_ode(d->s)) {
    OK(bg_eqsys_rhs(d->s, 0, d->y, d->ydot) == 0);
    return;
  }
  double yp[16] = {0}, res[16];
  OK(bg_eqsys_consistent(d->s, 0, d->y, 50) == 0);
  OK(bg_eqsys_residual(d->s, 0, d->y, yp, res) == 0);
  for (int i = 0; i < bg_eqsys_nx(d->s); i++) d->ydot[i] = -res[i];
}

static void drv_free(drv *d) {
  bg_eqsys_free(d->s);
  if (d->m) bg_analysis_free(&d->a);
  bg_model_free(d->m);
  bg_diags_free(&d->dg);
  free(d->src);
}

#define LOAD(d, file, text) if (drv_load(d, file, text) != 0) { OK(!"driver compiles"); drv_free(d); return; }

static void test_rc_section(void) {
  drv d;
  LOAD(&d, "electrical.bg", "Se U = 10\nRCSection S(R = 2, C = 1e-3)\nR load = 5\n"
                            "bond U -> S.p\nbond S.n -> load\n");
  set(&d, "S.Cs.q", 0.004); /* v_C = 4 V */
  eval(&d);
  DBL_NEAR(der(&d, "S.Cs.q"), (10 - 4) / 2.0 - 4 / 5.0, 1e-12);
  drv_free(&d);
}

static void test_lossy_transformer(void) {
  drv d;
  LOAD(&d, "electrical.bg", "Se U = 10\nLossyTransformer T(N = 2, Rp = 0.5, Rs = 1, Lm = 2)\n"
                            "R load = 3\nbond U -> T.p\nbond T.n -> load\n");
  set(&d, "T.Lmag.p", 4); /* magnetising current 2 A */
  OK(!bg_eqsys_is_ode(d.s)); /* Rp and Rs + load form a resistive loop: index 1 */
  eval(&d);
  /* v_m (1 + Rp N^2 / (Rs + Rl)) = U - Rp lambda / Lm  ->  v_m = 9 / 1.5 */
  DBL_NEAR(der(&d, "T.Lmag.p"), 6, 1e-12);
  drv_free(&d);
}

static void test_dc_motor(void) {
  drv d;
  LOAD(&d, "mechanical.bg", "Se U = 12\nDCMotor M(R = 2, L = 0.01, K = 0.1, J = 0.02, b = 0.001)\n"
                            "R load = 0.05\nbond U -> M.a\nbond M.shaft -> load\n");
  set(&d, "M.La.p", 0.03); /* i = 3 A */
  set(&d, "M.Jm.p", 0.4);  /* w = 20 rad/s */
  eval(&d);
  DBL_NEAR(der(&d, "M.La.p"), 12 - 2 * 3 - 0.1 * 20, 1e-12);
  DBL_NEAR(der(&d, "M.Jm.p"), 0.1 * 3 - 0.001 * 20 - 0.05 * 20, 1e-12);
  drv_free(&d);
}

static void test_gearbox(void) {
  drv d;
  LOAD(&d, "mechanical.bg", "Se tau = 2\nGearbox G(n = 4, J = 0.01, bf = 0.002)\nR load = 0.8\n"
                            "bond tau -> G.a\nbond G.b -> load\n");
  set(&d, "G.Jg.p", 0.1); /* w_in = 10, w_out = 2.5, torque out 2, torque in 0.5 */
  eval(&d);
  DBL_NEAR(der(&d, "G.Jg.p"), 2 - 0.002 * 10 - 0.8 * 10 / 16, 1e-12);
  drv_free(&d);
}

static void test_compliant_shaft(void) {
  drv d;
  LOAD(&d, "mechanical.bg", "Sf w0 = 5\nCompliantShaft S(k = 50, d = 0.2)\nI load = 0.5\n"
                            "bond w0 -> S.a\nbond S.b -> load\n");
  set(&d, "S.spring.q", 0.1); /* twist 0.1 rad */
  set(&d, "load.p", 1);       /* w_load = 2 */
  eval(&d);
  DBL_NEAR(der(&d, "S.spring.q"), 5 - 2, 1e-12);
  DBL_NEAR(der(&d, "load.p"), 50 * 0.1 + 0.2 * (5 - 2), 1e-12);
  drv_free(&d);
}

static void test_mass_spring_damper(void) {
  drv d;
  LOAD(&d, "mechanical.bg", "Se F = 3\nMassSpringDamper M(m = 2, k = 8, b = 0.5)\nbond F -> M.p\n");
  set(&d, "M.mass.p", 4);    /* v = 2 */
  set(&d, "M.spring.q", 0.25);
  eval(&d);
  DBL_NEAR(der(&d, "M.mass.p"), 3 - 8 * 0.25 - 0.5 * 2, 1e-12);
  DBL_NEAR(der(&d, "M.spring.q"), 2, 1e-12);
  drv_free(&d);
}

static void test_pipe(void) {
  drv d;
  LOAD(&d, "hydraulic.bg", "Se P0 = 1e6\nPipe L1(R = 1e8, L = 1e6, C = 1e-11)\nR out = 2e9\n"
                           "bond P0 -> L1.a\nbond L1.b -> out\n");
  set(&d, "L1.fluid.p", 2);     /* Q = 2e-6 m3/s */
  set(&d, "L1.line.q", 4e-6);   /* p_line = 4e5 Pa */
  eval(&d);
  DBL_NEAR(der(&d, "L1.fluid.p"), 1e6 - 1e8 * 2e-6 - 4e5, 1e-6);
  DBL_NEAR(der(&d, "L1.line.q"), 2e-6 - 4e5 / 2e9, 1e-18);
  drv_free(&d);
}

static void test_cylinder(void) {
  drv d;
  LOAD(&d, "hydraulic.bg", "Se P = 2e5\nCylinder Cy(A = 5e-4, m = 2, b = 20)\nC ks = 1 / 1000\n"
                           "bond P -> Cy.p\nbond Cy.rod -> ks\n");
  set(&d, "Cy.piston.p", 1); /* v = 0.5 */
  set(&d, "ks.q", 0.02);     /* spring force 20 N */
  eval(&d);
  DBL_NEAR(der(&d, "Cy.piston.p"), 5e-4 * 2e5 - 20 * 0.5 - 1000 * 0.02, 1e-9);
  DBL_NEAR(der(&d, "ks.q"), 0.5, 1e-12);
  drv_free(&d);
}

static void test_orifice(void) {
  drv d;
  LOAD(&d, "hydraulic.bg", "Se P1 = 3e5\nOrifice O(Cd = 0.6, A = 1e-5, rho = 800)\nC tank = 1e-9\n"
                           "bond P1 -> O.a\nbond O.b -> tank\n");
  set(&d, "tank.q", 1e-4); /* p_tank = 1e5: dp = 2e5 */
  eval(&d);
  DBL_NEAR(der(&d, "tank.q"), 0.6 * 1e-5 * sqrt(2 * 2e5 / 800), 1e-15);
  set(&d, "tank.q", 5e-4); /* p_tank = 5e5: flow back */
  eval(&d);
  DBL_NEAR(der(&d, "tank.q"), -0.6 * 1e-5 * sqrt(2 * 2e5 / 800), 1e-15);
  drv_free(&d);
}

static void test_thermal(void) {
  drv d;
  LOAD(&d, "thermal.bg", "Se Tamb = 300\nThermalResistance W(R = 0.5)\n"
                         "ThermalCapacitance B(C = 200, T0 = 280)\nbond Tamb -> W.a\nbond W.b -> B.p\n");
  DBL_NEAR(d.y[idx(&d, "B.body.q")], 200 * 280, 1e-9); /* q0 = C T0 */
  eval(&d);
  DBL_NEAR(der(&d, "B.body.q"), (300 - 280) / 0.5, 1e-9);
  drv_free(&d);
}

int main(void) {
  test_rc_section();
  test_lossy_transformer();
  test_dc_motor();
  test_gearbox();
  test_compliant_shaft();
  test_mass_spring_damper();
  test_pipe();
  test_cylinder();
  test_orifice();
  test_thermal();
  return bg_t_done();
}
