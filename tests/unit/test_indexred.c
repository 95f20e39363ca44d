/* SPDX-License-Identifier: BSD-3-Clause */
/* Index reduction (issue 17; src/equations/indexred.h, docs/equations.md
 * "Index reduction"): Pantelides' algorithm and dummy derivatives on the
 * index-2 examples. Each reduced system has numeric index 1, its consistent
 * initial point satisfies every row (the differentiated constraints too),
 * and its simulation follows an independent reference: the analytic
 * solution derived by hand, or the same model made index 1 by the chapter's
 * remedy (van Dijk's causality for delta, Lagrange causality for
 * loop_class1). The words name the differentiated constraint and the store
 * that lost its state; a structurally singular model is refused with the
 * reason. */
#include "harness.h"
#include "eqs_fixture.h"
#include "equations/equations.h"
#include "simulate/simulate.h"

/* What the simulation is told about the index (the run's facts): the
 * reduction, when the test publishes it. */
static bg_index_facts facts;

/* The reduction of f, published in the facts as the run does. */
static int reduce(efx *f, bg_indexred *r) {
  int st = bg_indexred_run(f->s, r);
  facts.reduction = r;
  return st;
}

/* Largest residual of any row at the reduced system's initial point. */
static double start_residual(bg_eqsys *s, double *y, double *yp) {
  int n = bg_eqsys_n(s);
  double res[64], mx = 0;
  bg_eqsys_initial_yp(s, y, yp);
  if (n > 64 || bg_eqsys_residual(s, 0, y, yp, res)) return INFINITY;
  for (int i = 0; i < n; i++) mx = fmax(mx, fabs(res[i]));
  return mx;
}

static int unknown(bg_eqsys *s, const char *name) {
  for (int i = 0; i < bg_eqsys_n(s); i++)
    if (!strcmp(bg_eqsys_name(s, i), name)) return i;
  return -1;
}

static int has_text(char **v, int n, const char *needle) {
  for (int k = 0; k < n; k++)
    if (strstr(v[k], needle)) return 1;
  return 0;
}

static int simulate(efx *f, bg_eqsys *s, bg_simresult *sr) {
  bg_sim_opts o = {0};
  o.facts = &facts;
  return bg_simulate(f->m, &f->a, s, &o, sr);
}

/* delta under SCAP (class 5 loop of gain +1, Figure 4.18): the balance at nA
 * is the cut-set constraint iL1 + iL2 = I0; differentiated once, L1 (no p0
 * in the model) loses its state. Against van Dijk's causality (L1 in
 * derivative causality: index 1, Figure 4.20) and against
 * L1.f = (I0/2)(1 - e^{-t/3}). */
static void test_delta(void) {
  efx f, v;
  bg_indexred r;
  OK(efx_load(&f, "delta", NULL, BG_METHOD_SCAP, NULL, 0) == 0);
  INT_EQ(reduce(&f, &r), 1);
  INT_EQ(r.index, 1);
  INT_EQ(r.ndiff, 1);
  INT_EQ(r.ndummy, 1);
  STR_EQ(r.ndummy ? r.dummy[0] : NULL, "L1.p'");
  OK(has_text(r.constraint, r.nconstraint, "the residual of f5 (the balance of nA); it closes causal loop 1 (bonds 2, 3, 8, 9, 6, 5, gain 1, class 5): 0 = L1.p/L10 - I0 + L2.p/L20"));
  OK(has_text(r.lost, r.nlost, "L1: L1.p is no longer a state"));
  bg_eqsys *s = r.reduced;
  INT_EQ(bg_eqsys_nx(s), 1); /* L2.p alone */
  STR_EQ(bg_eqsys_name(s, 0), "L2.p");
  double y[64], yp[64];
  OK(start_residual(s, y, yp) < 1e-12);
  int l1 = unknown(s, "L1.p"), d1 = unknown(s, "L1.p'");
  OK(l1 >= 0 && d1 >= 0);
  DBL_NEAR(y[l1] + y[0], 1.0, 1e-12); /* the constraint: iL1 + iL2 = I0 */
  DBL_NEAR(y[d1] + yp[0], 0.0, 1e-12); /* differentiated: iL1' + iL2' = 0 */
  DBL_NEAR(y[d1], 1.0 / 6, 1e-10);     /* L1.f' = (I0/6) e^{-t/3} at t = 0 */
  bg_simresult sr, vr;
  INT_EQ(simulate(&f, s, &sr), 0);
  OK(efx_load(&v, "delta", NULL, BG_METHOD_VANDIJK, NULL, 0) == 0);
  INT_EQ(simulate(&v, v.s, &vr), 0);
  INT_EQ(sr.nrows, vr.nrows);
  double dev = 0, err = 0;
  for (int k = 0; k < sr.nrows && sr.nrows == vr.nrows; k++)
    for (int c = 0; c < 2; c++) {
      double want = 0.5 * (1 - exp(-sr.t[k] / 3)), x = sr.values[2 * k + c];
      dev = fmax(dev, fabs(x - vr.values[2 * k + c]));
      err = fmax(err, fabs(x - (c == 0 ? want : 1 - want)));
    }
  OK(dev < 2e-6);
  OK(err < 1e-6);
  /* the original system stays refused: only the reduced one lifts it */
  bg_simresult orr;
  INT_EQ(simulate(&f, f.s, &orr), 1);
  bg_simresult_free(&orr), bg_simresult_free(&vr), bg_simresult_free(&sr);
  efx_free(&v);
  bg_indexred_free(&r);
  efx_free(&f);
}

/* loop_class1 (Figure 4.14, Proposition 5.10), by hand from its equations:
 * e7 = n1 e1/(n1 - 1), C2.q = k C1.q with k = C20 (n2 - n1)/((n1 - 1) C10),
 * C1.q' ((1 - n1) - (n2 - n1) k) = L.p/I0 - n1 F0 and L.p' = C1.q/(C10 (n1 - 1)):
 * L.p = n1 F0 I0 (1 - cos w t), C1.q = C10 (n1 - 1) n1 F0 I0 w sin w t,
 * w^2 = -1/(((1 - n1) - (n2 - n1) k) I0 C10 (n1 - 1)). */
static void check_loop_class1(int method, const char *set, double n2) {
  efx f;
  bg_indexred r;
  OK(efx_load(&f, "loop_class1", NULL, method, set, n2) == 0);
  INT_EQ(reduce(&f, &r), 1);
  INT_EQ(r.index, 1);
  double y[64], yp[64];
  OK(r.reduced && start_residual(r.reduced, y, yp) < 1e-12);
  double n1 = 2, C10 = 1, C20 = 1, I0 = 1, F0 = 1, k = C20 * (n2 - n1) / ((n1 - 1) * C10);
  double w = sqrt(-1 / (((1 - n1) - (n2 - n1) * k) * I0 * C10 * (n1 - 1))), A = n1 * F0 * I0;
  bg_simresult sr;
  INT_EQ(r.reduced ? simulate(&f, r.reduced, &sr) : -1, 0);
  int cq = -1, cp = -1, c2 = -1;
  for (int c = 0; c < sr.nout; c++) {
    if (!strcmp(sr.names[c], "C1.q")) cq = c;
    if (!strcmp(sr.names[c], "L.p")) cp = c;
    if (!strcmp(sr.names[c], "C2.q")) c2 = c;
  }
  OK(cq >= 0 && cp >= 0 && c2 >= 0);
  double err = 0;
  for (int i = 0; i < sr.nrows && cq >= 0 && cp >= 0 && c2 >= 0; i++) {
    double t = sr.t[i], q = C10 * (n1 - 1) * A * w * sin(w * t), p = A * (1 - cos(w * t));
    err = fmax(err, fmax(fabs(sr.values[i * sr.nout + cq] - q), fabs(sr.values[i * sr.nout + cp] - p)));
    err = fmax(err, fabs(sr.values[i * sr.nout + c2] - k * q));
  }
  OK(sr.nrows == 501 && err < 1e-5);
  bg_simresult_free(&sr);
  if (method == BG_METHOD_SCAP) { /* the constraint of C2 and the loop's residual */
    OK(has_text(r.constraint, r.nconstraint, "the constraint of the dependent store C2; causal path 2 from C1 to C2 (bonds 1, 2, 3, 4, 5)"));
    OK(has_text(r.constraint, r.nconstraint, "the residual of e7 (the modulus of TF1); it closes causal loop 1 (bonds 2, 6, 7, 8, gain n1, class 4)"));
    OK(has_text(r.lost, r.nlost, "C2 (a dependent store already)"));
  } else { /* Lagrange: both balances, and a second derivative of L.p */
    OK(has_text(r.dummy, r.ndummy, "L.p''"));
    OK(has_text(r.lost, r.nlost, "C1: C1.q is no longer a state"));
  }
  bg_indexred_free(&r);
  efx_free(&f);
}

/* bond_loop with n = 1 (a unity-gain loop): both residuals of the TF lose
 * their torn variable and constrain the states: Cs.q = 0 and Is.p = I0 F0
 * step(t). Both stores lose their state; nothing is left to integrate. */
static void test_bond_loop_unity(void) {
  efx f;
  bg_indexred r;
  OK(efx_load(&f, "bond_loop", NULL, BG_METHOD_SCAP, "n", 1) == 0);
  INT_EQ(reduce(&f, &r), 1);
  INT_EQ(r.index, 1);
  INT_EQ(r.nlost, 2);
  INT_EQ(r.reduced ? bg_eqsys_nx(r.reduced) : -1, 0);
  bg_simresult sr;
  INT_EQ(r.reduced ? simulate(&f, r.reduced, &sr) : -1, 0);
  double err = 0;
  for (int i = 0; i < sr.nrows; i++) err = fmax(err, fmax(fabs(sr.values[2 * i]), fabs(sr.values[2 * i + 1] - 1)));
  OK(sr.nrows == 1001 && err < 1e-12);
  OK(sr.ic_report && strstr(sr.ic_report, "Is.p 0 -> 1"));
  bg_simresult_free(&sr);
  bg_indexred_free(&r);
  efx_free(&f);
}

/* Two flow sources in series: their balance holds no unknown (0 = F2 - F1),
 * so the equations are structurally singular and the reduction says so;
 * the simulation stays refused and gives that reason. */
static void test_failure(void) {
  static const char *src = "model twosf\nSf S1 = 1\nSf S2 = 2\n1 j\nR R1 = 1\nC C1 = 1\n"
                           "bond 1 S1 -> j\nbond 2 S2 -> j\nbond 3 j -> R1\nbond 4 j -> C1\nsimulate t_end = 1\n";
  efx f;
  bg_indexred r;
  OK(efx_load(&f, NULL, src, BG_METHOD_RELAXED, NULL, 0) == 0);
  INT_EQ(reduce(&f, &r), -1);
  OK(r.reduced == NULL);
  OK(r.message && strstr(r.message, "index reduction failed: the equations are structurally singular: the equation of S2.e"));
  bg_simresult sr;
  INT_EQ(simulate(&f, f.s, &sr), 1);
  OK(sr.message && strstr(sr.message, "was tried and failed: the equations are structurally singular"));
  bg_simresult_free(&sr);
  facts.reduction = NULL;
  bg_indexred_free(&r);
  efx_free(&f);
}

/* The same model reduced twice gives the same words (deterministic). */
static void test_deterministic(void) {
  efx f;
  bg_indexred a, b;
  OK(efx_load(&f, "loop_class1", NULL, BG_METHOD_SCAP, NULL, 0) == 0);
  bg_indexred_run(f.s, &a), bg_indexred_run(f.s, &b);
  bg_strbuf ta = {0}, tb = {0};
  bg_indexred_text(&a, "", &ta), bg_indexred_text(&b, "", &tb);
  STR_EQ(bg_sb_str(&ta), bg_sb_str(&tb));
  bg_sb_free(&ta), bg_sb_free(&tb);
  bg_indexred_free(&a), bg_indexred_free(&b);
  efx_free(&f);
}

int main(void) {
  test_delta();
  check_loop_class1(BG_METHOD_SCAP, NULL, 3);
  check_loop_class1(BG_METHOD_SCAP, "n2", 4);
  check_loop_class1(BG_METHOD_LAGRANGE, NULL, 3);
  test_bond_loop_unity();
  test_failure();
  test_deterministic();
  return bg_t_done();
}
