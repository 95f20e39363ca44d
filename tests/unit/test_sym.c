/* SPDX-License-Identifier: BSD-3-Clause */
/* The symbolic layer (sym.h) and the reduced form (eqsym.h):
 * - canonical forms: shared nodes, constant folding, neutral elements,
 *   signs, like terms, exact cancellation; printing;
 * - symbolic derivatives of every function against central differences;
 * - the rows of every example differentiated symbolically (bond variables
 *   substituted) against the exact AD Jacobians of the tape;
 * - the reduced ODE of every example that has one satisfies the DAE
 *   residual of the engine at pseudo-random states;
 * - which examples reduce to an ODE, and the printed reduced equations. */
#include "harness.h"
#include "eqs_fixture.h"
#include "equations/equations.h"
#include "model/model.h"
#include "equations/eqsys_int.h" /* row kinds */
#include "sym/sym.h"

static const char *src_small =
    "model small\nparam n = 2, R = 3, C0 = 0.5, k = 1.5\ninput u = 0.2*step(t)\n"
    "Se U = 1\n1 j\nR R1 = R\nC C1 = C0\nbond 1 U -> j\nbond 2 j -> R1\nbond 3 j -> C1\n";

static void pr_str(bg_sym *S, int a, char *buf, size_t len) {
  bg_strbuf sb = {0};
  bg_sym_print(S, a, 0, NULL, NULL, &sb);
  snprintf(buf, len, "%s", bg_sb_str(&sb));
  bg_sb_free(&sb);
}

#define PRINTS(a, text)                                                                       \
  do {                                                                                        \
    char b__[512];                                                                            \
    pr_str(S, (a), b__, sizeof b__);                                                          \
    BG_T_REPORT(!strcmp(b__, (text)), "printed \"%s\", expected \"%s\"", b__, (text));       \
  } while (0)

static void test_canonical(void) {
  efx f;
  OK(efx_load(&f, NULL, src_small, -1, NULL, 0) == 0);
  if (!f.m) { efx_free(&f); return; }
  bg_sym *S = bg_sym_new(f.m);
  int n = bg_sym_leaf(S, SYM_PARAM, 0), R = bg_sym_leaf(S, SYM_PARAM, 1), C = bg_sym_leaf(S, SYM_PARAM, 2);
  int x = bg_sym_leaf(S, SYM_Y, 0), y = bg_sym_leaf(S, SYM_Y, 1), one = bg_sym_num(S, 1), zero = bg_sym_num(S, 0);
  /* shared nodes, order independence */
  INT_EQ(bg_sym_add(S, x, y), bg_sym_add(S, y, x));
  INT_EQ(bg_sym_mul(S, bg_sym_mul(S, n, x), y), bg_sym_mul(S, y, bg_sym_mul(S, x, n)));
  /* constant folding, neutral elements */
  INT_EQ(bg_sym_add(S, bg_sym_num(S, 2), bg_sym_num(S, 3)), bg_sym_num(S, 5));
  INT_EQ(bg_sym_add(S, x, zero), x);
  INT_EQ(bg_sym_mul(S, x, one), x);
  INT_EQ(bg_sym_mul(S, x, zero), zero);
  INT_EQ(bg_sym_powc(S, x, 1), x);
  INT_EQ(bg_sym_powc(S, x, 0), one);
  int sq = bg_sym_call(S, BG_FN_SQRT, 1, (int[]){bg_sym_num(S, 16)});
  INT_EQ(sq, bg_sym_num(S, 4));
  /* like terms */
  INT_EQ(bg_sym_add(S, x, x), bg_sym_scale(S, 2, x));
  INT_EQ(bg_sym_sub(S, bg_sym_add(S, x, y), x), y);
  INT_EQ(bg_sym_mul(S, x, x), bg_sym_powc(S, x, 2));
  INT_EQ(bg_sym_div(S, bg_sym_mul(S, n, x), x), n);
  INT_EQ(bg_sym_sub(S, bg_sym_mul(S, n, x), bg_sym_mul(S, x, n)), zero);
  /* signs: 1/(1 - n) is -1/(n - 1); (1 - n) (n - 1)^-1 is -1 */
  int a1 = bg_sym_sub(S, one, n), a2 = bg_sym_sub(S, n, one);
  INT_EQ(bg_sym_div(S, one, a1), bg_sym_neg(S, bg_sym_div(S, one, a2)));
  INT_EQ(bg_sym_mul(S, bg_sym_powc(S, a1, 1), bg_sym_powc(S, a2, -1)), bg_sym_num(S, -1));
  INT_EQ(bg_sym_div(S, a1, a1), one);
  /* exact cancellation of unity-gain coefficients */
  INT_EQ(bg_sym_sub(S, one, bg_sym_mul(S, bg_sym_num(S, 49), bg_sym_num(S, 1.0 / 49))), zero);
  INT_EQ(bg_sym_sub(S, bg_sym_scale(S, 1.0 / 3, x), bg_sym_scale(S, 1.0 / 3, x)), zero);
  /* a number times a sum is distributed: collected with other terms */
  INT_EQ(bg_sym_add(S, bg_sym_scale(S, 2, bg_sym_add(S, x, y)), bg_sym_scale(S, -2, y)), bg_sym_scale(S, 2, x));
  /* printing */
  PRINTS(a2, "n - 1");
  PRINTS(a1, "1 - n");
  PRINTS(bg_sym_div(S, one, a1), "-1/(n - 1)");
  PRINTS(bg_sym_sub(S, x, bg_sym_mul(S, n, y)), "y0 - n*y1");
  PRINTS(bg_sym_sub(S, bg_sym_neg(S, x), y), "-y0 - y1");
  PRINTS(bg_sym_div(S, x, bg_sym_div(S, one, C)), "C0*y0");
  PRINTS(bg_sym_div(S, x, bg_sym_mul(S, R, C)), "y0/(R*C0)");
  PRINTS(bg_sym_mul(S, bg_sym_mul(S, R, x), bg_sym_sub(S, one, bg_sym_leaf(S, SYM_INPUT, 0))), "R*y0*(1 - u)");
  PRINTS(bg_sym_sub(S, bg_sym_mul(S, bg_sym_mul(S, R, x), bg_sym_sub(S, one, bg_sym_leaf(S, SYM_INPUT, 0))), y),
         "R*y0*(1 - u) - y1");
  PRINTS(bg_sym_powc(S, bg_sym_add(S, x, y), -2), "1/(y0 + y1)^2");
  /* together, collect: bond_loop's 4.27a from its pieces */
  int F = bg_sym_leaf(S, SYM_T, 0);
  int f3 = bg_sym_div(S, bg_sym_mul(S, n, bg_sym_sub(S, F, x)), a2); /* n (F - p)/(n - 1) */
  int qd = bg_sym_add(S, f3, x);
  int e = bg_sym_together(S, bg_sym_collect(S, bg_sym_expand(S, qd, 100)), 0);
  PRINTS(e, "(n*t - y0)/(n - 1)");
  /* exact division by a linear factor: (2n - n^2 - 1)/(n - 1)^2 = -1 */
  int num = bg_sym_sum(S, -1, 2, (int[]){n, bg_sym_powc(S, n, 2)}, (double[]){2, -1});
  INT_EQ(bg_sym_rational(S, bg_sym_add(S, bg_sym_div(S, num, bg_sym_powc(S, a2, 2)), zero)), bg_sym_num(S, -1));
  /* rational coefficients: 1/C0 - n/(C0 (n - 1)) = -1/(C0 (n - 1)) */
  int co = bg_sym_sub(S, bg_sym_div(S, one, C), bg_sym_div(S, n, bg_sym_mul(S, C, a2)));
  PRINTS(bg_sym_rational(S, co), "-1/(C0*(n - 1))");
  /* evaluation: k/R exactly, 1 - k/R = 0 when k = R */
  double par[4] = {2, 3, 0.5, 3};
  bg_symenv env = {0, NULL, NULL, NULL, par};
  int kk = bg_sym_leaf(S, SYM_PARAM, 3);
  DBL_NEAR(bg_sym_eval(S, bg_sym_sub(S, one, bg_sym_div(S, kk, R)), &env), 0, 0);
  par[1] = par[3] = 49;
  DBL_NEAR(bg_sym_eval(S, bg_sym_sub(S, one, bg_sym_div(S, kk, R)), &env), 0, 0);
  bg_sym_free(S);
  efx_free(&f);
}

/* Every function's derivative against central differences. */
static void test_diff_functions(void) {
  efx f;
  OK(efx_load(&f, NULL, src_small, -1, NULL, 0) == 0);
  if (!f.m) { efx_free(&f); return; }
  bg_sym *S = bg_sym_new(f.m);
  int x = bg_sym_leaf(S, SYM_Y, 0), y = bg_sym_leaf(S, SYM_Y, 1);
  int fns[] = {BG_FN_ABS, BG_FN_SQRT, BG_FN_EXP, BG_FN_LOG, BG_FN_LOG10, BG_FN_SIN, BG_FN_COS, BG_FN_TAN,
               BG_FN_ASIN, BG_FN_ACOS, BG_FN_ATAN, BG_FN_SINH, BG_FN_COSH, BG_FN_TANH, BG_FN_RAMP};
  double pts[3] = {0.3, 0.7, 0.45};
  for (size_t k = 0; k < sizeof fns / sizeof *fns; k++) {
    int arg = bg_sym_add(S, bg_sym_scale(S, 0.5, x), bg_sym_mul(S, x, y)); /* 0.5 x + x y */
    int e = bg_sym_call(S, fns[k], 1, &arg), d = bg_sym_diff(S, e, x);
    for (int p = 0; p < 3; p++) {
      double yv[2] = {pts[p], 0.4}, h = 1e-6, v1, v2, dv;
      bg_symenv env = {0, yv, NULL, NULL, NULL};
      dv = bg_sym_eval(S, d, &env);
      yv[0] += h, v1 = bg_sym_eval(S, e, &env), yv[0] -= 2 * h, v2 = bg_sym_eval(S, e, &env);
      BG_T_REPORT(fabs(dv - (v1 - v2) / (2 * h)) < 1e-6 * (1 + fabs(dv)), "d %s: %g vs %g", bg_func_name(fns[k]), dv,
                  (v1 - v2) / (2 * h));
    }
  }
  int two[] = {BG_FN_ATAN2, BG_FN_MIN, BG_FN_MAX, BG_FN_POW};
  for (size_t k = 0; k < 4; k++) {
    int args[2] = {bg_sym_add(S, x, bg_sym_num(S, 0.2)), bg_sym_mul(S, y, x)};
    int e = bg_sym_call(S, two[k], 2, args), d = bg_sym_diff(S, e, x);
    double yv[2] = {0.6, 1.3}, h = 1e-6;
    bg_symenv env = {0, yv, NULL, NULL, NULL};
    double dv = bg_sym_eval(S, d, &env), v1, v2;
    yv[0] += h, v1 = bg_sym_eval(S, e, &env), yv[0] -= 2 * h, v2 = bg_sym_eval(S, e, &env);
    BG_T_REPORT(fabs(dv - (v1 - v2) / (2 * h)) < 1e-6 * (1 + fabs(dv)), "d %s: %g", bg_func_name(two[k]), dv);
  }
  /* inputs are differentiated through their expression in t; piecewise
   * constant functions have derivative 0 */
  int t = bg_sym_leaf(S, SYM_T, 0), u = bg_sym_leaf(S, SYM_INPUT, 0);
  INT_EQ(bg_sym_diff(S, bg_sym_mul(S, u, t), t), u); /* du/dt = 0.2 * step' = 0 */
  INT_EQ(bg_sym_diff(S, bg_sym_call(S, BG_FN_STEP, 1, &x), x), bg_sym_num(S, 0));
  /* an alias differentiates through its expression */
  int T = bg_sym_alias(S, 7, bg_sym_call(S, BG_FN_SIN, 1, &x)), dT = bg_sym_diff(S, bg_sym_powc(S, T, 2), x);
  double yv[2] = {0.3, 0};
  bg_symenv env = {0, yv, NULL, NULL, NULL};
  DBL_NEAR(bg_sym_eval(S, dT, &env), 2 * sin(0.3) * cos(0.3), 1e-15);
  bg_sym_free(S);
  efx_free(&f);
}

static const char *examples[] = {"rlc", "bond_loop", "bridge_compliance", "class12_paths", "delta",
                                 "hydraulic_bridge", "internal_mod_r", "internal_mod_tf", "loop_class1",
                                 "mod_no_loop", "modulated_source", "parallel_conductance",
                                 "series_conductances", "series_motor", "series_motor_L", "slider_crank"};
#define NEX (sizeof examples / sizeof *examples)

/* Symbolic derivatives of the substituted rows against the tape's exact
 * Jacobians (A = dF/dyp, B = dF/dy) at a pseudo-random point. */
static void check_sym_jacobian(const char *name) {
  efx f;
  if (efx_load(&f, name, NULL, -1, NULL, 0)) { OK(0); efx_free(&f); return; }
  bg_eqsys *s = f.s;
  int n = bg_eqsys_n(s);
  bg_sym *S = bg_sym_new(f.m);
  int *rows = calloc(n + 1, sizeof *rows);
  OK(bg_eqsym_rows(S, s, rows) == 0);
  double *y = calloc(n + 1, 8), *yp = calloc(n + 1, 8), *A = calloc((size_t)n * n + 1, 8), *B = calloc((size_t)n * n + 1, 8);
  unsigned st = 23;
  bg_eqsys_initial(s, y);
  for (int i = 0; i < n; i++) y[i] += efx_rand(&st, 0.1, 0.5) * (1 + fabs(y[i])), yp[i] = efx_rand(&st, -1, 1);
  double t = 0.3, maxerr = 0;
  OK(bg_eqsys_linearise(s, t, y, yp, A, B) == 0);
  bg_symenv env = {t, y, yp, NULL, NULL};
  for (int i = 0; i < n; i++) {
    int staterow = s->row_kind[i] == 0; /* residual yp_i - rhs */
    for (int j = 0; j < n; j++) {
      double dA = bg_sym_eval(S, bg_sym_diff(S, rows[i], bg_sym_leaf(S, SYM_YP, j)), &env);
      double dB = bg_sym_eval(S, bg_sym_diff(S, rows[i], bg_sym_leaf(S, SYM_Y, j)), &env);
      double a = A[(size_t)j * n + i], b = B[(size_t)j * n + i];
      if (staterow) dA = (i == j) - dA, dB = -dB;
      double e = fmax(fabs(dA - a) / (1 + fabs(a)), fabs(dB - b) / (1 + fabs(b)));
      if (e > maxerr) maxerr = e;
      if (e > 1e-10) fprintf(stderr, "%s: row %d col %d: sym %g %g tape %g %g\n", name, i, j, dA, dB, a, b);
    }
  }
  BG_T_REPORT(maxerr <= 1e-10, "%s: symbolic vs AD Jacobian %g", name, maxerr);
  free(rows), free(y), free(yp), free(A), free(B);
  bg_sym_free(S);
  efx_free(&f);
}

static void test_sym_jacobians(void) {
  for (size_t k = 0; k < NEX; k++) check_sym_jacobian(examples[k]);
}

/* The reduced ODE at pseudo-random states gives a point where the engine's
 * DAE residual vanishes (for dropped dependent stores their constraint
 * holds by construction). */
static void check_reduced_m(const char *name, int method, const char *set, double val, int expect_ode) {
  efx f;
  if (efx_load(&f, name, NULL, method, set, val)) { OK(0); efx_free(&f); return; }
  bg_eqsys *s = f.s;
  bg_eqred *r = bg_eqred_build(s);
  BG_T_REPORT(bg_eqred_is_ode(r) == expect_ode, "%s%s: reduced to an ODE: %d (%s)", name, set ? " (set)" : "",
              bg_eqred_is_ode(r), bg_eqred_note(r));
  int n = bg_eqsys_n(s), ns = bg_eqred_nstate(r);
  double *x = calloc(ns + 1, 8), *y = calloc(n + 1, 8), *yp = calloc(n + 1, 8), *res = calloc(n + 1, 8);
  double *y0 = calloc(n + 1, 8);
  unsigned st = 31;
  bg_eqsys_initial(s, y0);
  for (int k = 0; bg_eqred_is_ode(r) && k < 6; k++) {
    double t = efx_rand(&st, 0.01, 1);
    for (int q = 0; q < ns; q++) x[q] = y0[bg_eqred_state(r, q)] + efx_rand(&st, -1, 1) * (1 + fabs(y0[bg_eqred_state(r, q)]));
    OK(bg_eqred_point(r, t, x, y, yp) == 0);
    OK(bg_eqsys_residual(s, t, y, yp, res) == 0);
    double mx = 0, sc = 0;
    for (int i = 0; i < n; i++) sc = fmax(sc, fmax(fabs(y[i]), fabs(yp[i])));
    for (int i = 0; i < n; i++)
      if (!bg_eqred_invariant(r, i)) mx = fmax(mx, fabs(res[i]));
    BG_T_REPORT(mx <= 1e-10 * (1 + sc), "%s: DAE residual at the reduced ODE's point %g (scale %g)", name, mx, sc);
  }
  free(x), free(y), free(yp), free(res), free(y0);
  bg_eqred_free(r);
  efx_free(&f);
}

static void check_reduced(const char *name, const char *set, double val, int expect_ode) {
  check_reduced_m(name, -1, set, val, expect_ode);
}

static void test_reduced(void) {
  /* ODE already, or after eliminating linear blocks / combining stores */
  const char *ode[] = {"rlc", "bond_loop", "bridge_compliance", "class12_paths", "mod_no_loop",
                       "modulated_source", "series_motor_L", "slider_crank"};
  for (size_t k = 0; k < sizeof ode / sizeof *ode; k++) check_reduced(ode[k], NULL, 0, 1);
  /* nonlinear blocks (implicit laws, internal modulation), index 2 */
  const char *dae[] = {"hydraulic_bridge", "internal_mod_r", "internal_mod_tf", "loop_class1", "delta",
                       "parallel_conductance", "series_conductances", "series_motor"};
  for (size_t k = 0; k < sizeof dae / sizeof *dae; k++) check_reduced(dae[k], NULL, 0, 0);
  check_reduced("bond_loop", "n", 1, 0);        /* unity gain: singular block */
  check_reduced("bond_loop", "n", 0.5, 1);
  check_reduced("modulated_source", "k", 2, 0); /* k = R20 (Equation 4.45) */
  check_reduced("modulated_source", "k", 3, 1);
  check_reduced("class12_paths", "C20", 0.1, 1);
  /* Lagrange causality: the artificial sources' flows become states */
  check_reduced("lagrange_rlc", NULL, 0, 1);
  check_reduced_m("slider_crank", BG_METHOD_LAGRANGE, NULL, 0, 1);
  check_reduced_m("rlc", BG_METHOD_LAGRANGE, NULL, 0, 1);
  check_reduced_m("bond_loop", BG_METHOD_LAGRANGE, NULL, 0, 1);
}

static void test_printed(void) {
  efx f;
  bg_strbuf sb = {0};
  OK(efx_load(&f, "bond_loop", NULL, -1, NULL, 0) == 0);
  if (f.s) {
    bg_eqprint_text(f.s, &sb);
    const char *t = bg_sb_str(&sb);
    OK(strstr(t, "# reduced form: explicit ODE after symbolic elimination of 2 algebraic unknowns\n") != NULL);
    /* Equation 4.27 in the states q = C eC, p = I fI */
    OK(strstr(t, "Cs.q' = (n*F0*step(t) - Is.p/I0)/(n - 1)\n") != NULL);
    OK(strstr(t, "Is.p' = Cs.q/(C0*(n - 1))\n") != NULL);
    bg_sb_clear(&sb);
    bg_eqprint_latex(f.s, &sb);
    OK(strstr(bg_sb_str(&sb), "\\dot{p_{\\mathrm{Is}}} &= \\frac{q_{\\mathrm{Cs}}}{\\mathrm{C0} \\left(n - 1\\right)}") != NULL);
    bg_sb_clear(&sb);
    bg_eqprint_json(f.s, &sb);
    OK(strstr(bg_sb_str(&sb), "\"reduced_form\": \"ode\"") != NULL);
    OK(strstr(bg_sb_str(&sb), "{\"lhs\": \"Cs.q'\", \"rhs\": \"(n*F0*step(t) - Is.p/I0)/(n - 1)\", \"kind\": \"state\"}") != NULL);
  }
  efx_free(&f);
  /* slider_crank: the modulus prints as T, the ODE as Equation 4.53 */
  OK(efx_load(&f, "slider_crank", NULL, -1, NULL, 0) == 0);
  if (f.s) {
    bg_sb_clear(&sb);
    bg_eqprint_text(f.s, &sb);
    const char *t = bg_sb_str(&sb);
    OK(strstr(t, "f3 = T*f4\n") != NULL);
    OK(strstr(t, "\nT = rc*sin(phi)*(sqrt(L^2 - rc^2*sin(phi)^2) + rc*cos(phi))/sqrt(L^2 - rc^2*sin(phi)^2)\ne1 = M0\n") != NULL);
    OK(strstr(t, "m.p = m0*T*J.p/J0\n") != NULL);
    OK(strstr(t, "J.p' = (J0*M0 - m0*T*(dT/dphi)*J.p^2/J0 - J0*F0*T - b0*T^2*J.p)/(J0 + m0*T^2)\n") != NULL);
  }
  efx_free(&f);
  /* Lagrange causality: the mass-matrix form, Equations 4.53 and 4.58 */
  OK(efx_load(&f, "slider_crank", NULL, BG_METHOD_LAGRANGE, NULL, 0) == 0);
  if (f.s) {
    bg_sb_clear(&sb);
    bg_eqprint_text(f.s, &sb);
    const char *t = bg_sb_str(&sb);
    OK(strstr(t, "z = (w.f)") != NULL);
    OK(strstr(t, "# Lagrange equations, mass-matrix form M(x) v' = f(x)\n"
                 "(J0 + m0*T^2)*w.f' = M0 - m0*T*(dT/dphi)*w.f^2 - b0*T^2*w.f - F0*T\n") != NULL);
  }
  efx_free(&f);
  OK(efx_load(&f, "lagrange_rlc", NULL, -1, NULL, 0) == 0);
  if (f.s) {
    bg_sb_clear(&sb);
    bg_eqprint_text(f.s, &sb);
    const char *t = bg_sb_str(&sb);
    OK(strstr(t, "R0*ma.f' = Ie0*step(t)/C10 - ma.f*(C10 + C20)/(C10*C20) + mb.f/C20\n") != NULL);
    OK(strstr(t, "L10*mb.f' = C2.q/C20\n") != NULL);
  }
  efx_free(&f);
  /* hydraulic bridge: the law as written, signs normalised for reading */
  OK(efx_load(&f, "hydraulic_bridge", NULL, -1, NULL, 0) == 0);
  if (f.s) {
    bg_sb_clear(&sb);
    bg_eqprint_text(f.s, &sb);
    const char *t = bg_sb_str(&sb);
    OK(strstr(t, "f14 = A*f13\n") != NULL);                 /* f13/(1/A) */
    OK(strstr(t, "0 = Kv*e3*(1 - u)/sqrt(sqrt(pt^2 + e3^2)) - f3    (solved for R2.e)\n") != NULL);
    OK(strstr(t, "# reduced form: DAE (the algebraic equations are not linear in their unknowns: they stay implicit)\n") != NULL);
  }
  efx_free(&f);
  bg_sb_free(&sb);
}

/* The node store grows while a sum re-interns the monomial of a scaled
 * product from the product's own operands (a use-after-free before: the
 * operands pointed into the array being reallocated). One-operand nodes
 * (x_k^2) fill the operand array up to 4 below its capacity, so that the
 * product's 3 operands fit and its monomial's 3 do not; the term must keep
 * its factors. Twice, across two growths. */
static void test_growth(void) {
  efx f;
  OK(efx_load(&f, NULL, src_small, -1, NULL, 0) == 0);
  if (!f.m) { efx_free(&f); return; }
  bg_sym *S = bg_sym_new(f.m);
  int ok = 1, k = 0;
  for (int round = 0; round < 2; round++) {
    while (S->narg == 0 || S->narg != S->caparg - 4) bg_sym_powc(S, bg_sym_leaf(S, SYM_Y, 1000 + k++), 2);
    int b[3] = {bg_sym_leaf(S, SYM_Y, 1), bg_sym_leaf(S, SYM_Y, 2), bg_sym_leaf(S, SYM_Y, 3 + round)};
    int cap = S->caparg, p = bg_sym_prod(S, 3, 3, b, NULL), s = bg_sym_add(S, p, bg_sym_leaf(S, SYM_T, 0));
    OK(S->caparg > cap);
    const bg_symnode *nd = &S->node[s];
    ok = nd->kind == SYM_ADD && nd->n == 2;
    for (int q = 0; q < 2 && ok; q++) {
      const bg_symnode *t = &S->node[S->arg[nd->adr + q]];
      if (t->kind != SYM_MUL) continue;
      ok = S->w[nd->adr + q] == 3 && t->n == 3 && t->c == 1;
      for (int i = 0; i < 3 && ok; i++) ok = S->node[S->arg[t->adr + i]].ref == (i < 2 ? i + 1 : 3 + round);
    }
    OK(ok);
  }
  bg_sym_free(S);
  efx_free(&f);
}

int main(void) {
  test_growth();
  test_canonical();
  test_diff_functions();
  test_sym_jacobians();
  test_reduced();
  test_printed();
  return bg_t_done();
}
