/* SPDX-License-Identifier: BSD-3-Clause */
/* Lagrange causality with a 1-junction inserted into a bond (Section 4.10.1,
 * step 2): the inserted junction's flow is a generalised velocity, its
 * effort balance (the two efforts of the split bond agree) is its equation.
 * Residuals written here by hand from each bond graph, compared with the
 * engine's at deterministic pseudo-random points (1e-12 relative); the
 * coordinates, the causality of the store on a split bond, the numeric index
 * and the consistent initial point. The simulations against SCAP are in
 * tests/lagrange_inserted.sh. */
#include "harness.h"
#include "eqs_fixture.h"
#include "equations/equations.h"

/* a == b to 1e-12 relative to the sum of magnitudes `scale`. */
#define CLOSE(a, b, scale, what)                                                           \
  do {                                                                                     \
    double a__ = (a), b__ = (b), s__ = fabs(a__) + fabs(b__) + (scale);                   \
    BG_T_REPORT(fabs(a__ - b__) <= 1e-12 * (s__ > 0 ? s__ : 1), "%s: %s: %.17g vs %.17g", \
                f.m->name, what, a__, b__);                                                \
  } while (0)

static int U(efx *f, const char *name) {
  int i = efx_u(f, name);
  BG_T_REPORT(i >= 0, "%s: unknown %s", f->m->name, name);
  return i < 0 ? 0 : i;
}

static int load_lagrange(efx *f, const char *name) {
  int rc = efx_load(f, name, NULL, BG_METHOD_LAGRANGE, NULL, 0);
  OK(rc == 0);
  return rc;
}

/* The inserted 1-junctions, by bond number, in the order of the coordinates. */
static void check_inserted(efx *f, int nlag, const int *bonds) {
  const bg_analysis *a = &f->a;
  INT_EQ(a->nlag, nlag);
  int k = 0;
  for (int i = 0; i < a->nlag; i++)
    if (a->lag_junction[i] < 0) {
      OK(k < 4);
      if (k < 4) INT_EQ(f->m->bond_num[a->lag_bond[i]], bonds[k]);
      k++;
    }
}

static void check_index1(efx *f) {
  bg_index_result r;
  INT_EQ(bg_index_compute(f->s, f->m, &r), 1);
  bg_index_free(&r);
}

/* mod_no_loop: js gets an artificial source (q1' = js.f), then a 1-junction
 * is inserted into bond 4 (jp -> Cp, q2' = f4). Cp receives the inserted
 * junction's flow: integral, so Cp.q is a state (q2 itself). jp's strong bond
 * is Rg's: resistance, its conductance law solved implicitly for Rg.e.
 *   Cp.q' = f4
 *   0 = G0*e5*(1 + a*js.f^2) - (js.f - f4)     Rg's law, f5 = f3 - f4
 *   0 = E0 - R0*js.f - e5                       effort balance at js
 *   0 = e5 - Cp.q/C0                            the inserted junction: e4 at jp = e4 at Cp */
static void test_mod_no_loop(void) {
  efx f;
  if (load_lagrange(&f, "mod_no_loop")) { efx_free(&f); return; }
  check_inserted(&f, 2, (const int[]){4});
  INT_EQ(f.a.nstates, 1);
  if (f.a.nstates == 1) STR_EQ(f.a.states[0], "Cp.q");
  INT_EQ(f.a.ndependent, 0);
  int n = bg_eqsys_n(f.s), q = U(&f, "Cp.q"), e5 = U(&f, "Rg.e"), v1 = U(&f, "js.f"), v2 = U(&f, "Cp.f");
  INT_EQ(n, 4);
  INT_EQ(bg_eqsys_nx(f.s), 1);
  const double E0 = 1, C0 = 1, G0 = 1, a = 0.5, R0 = 2;
  unsigned st = 7;
  for (int k = 0; k < 20; k++) {
    double y[4], yp[4], r[4];
    for (int i = 0; i < 4; i++) y[i] = efx_rand(&st, -2, 2), yp[i] = efx_rand(&st, -2, 2);
    OK(bg_eqsys_residual(f.s, 0.3, y, yp, r) == 0);
    CLOSE(r[q], yp[q] - y[v2], 1, "Cp.q'");
    CLOSE(r[e5], G0 * y[e5] * (1 + a * y[v1] * y[v1]) - (y[v1] - y[v2]), 1, "Rg law");
    CLOSE(r[v1], E0 - R0 * y[v1] - y[e5], 1, "balance at js");
    CLOSE(r[v2], y[e5] - y[q] / C0, 1, "inserted junction in bond 4");
  }
  check_index1(&f);
  efx_free(&f);
}

/* parallel_conductance: no 1-junction, so one is inserted into bond 2
 * (k -> Rg); its flow q' = Rg.f is the coordinate. k's last bond is Lk's:
 * Lk gets derivative causality (a dependent store fed by the coordinate).
 *   0 = Lk.p - L0*(S - Rg.f)                    Lk's constraint, f3 = f1 - f2
 *   0 = G0*e2^3 - Rg.f, e2 = e3 = Lk.p'          Rg's law at the inserted junction
 * The initial point holds Lk.p at its p0 = 0 (the SCAP run's state): then
 * Rg.f = S = 1 and Lk.p' = (S/G0)^(1/3) = 1, not the steady state Lk.p = 1
 * that holding yp = 0 would give. */
static void test_parallel_conductance(void) {
  efx f;
  if (load_lagrange(&f, "parallel_conductance")) { efx_free(&f); return; }
  check_inserted(&f, 1, (const int[]){2});
  INT_EQ(f.a.ndependent, 1);
  int p = U(&f, "Lk.p"), v = U(&f, "Rg.f");
  INT_EQ(bg_eqsys_n(f.s), 2);
  unsigned st = 11;
  for (int k = 0; k < 20; k++) {
    double y[2], yp[2], r[2];
    for (int i = 0; i < 2; i++) y[i] = efx_rand(&st, -2, 2), yp[i] = efx_rand(&st, -2, 2);
    OK(bg_eqsys_residual(f.s, 0.1, y, yp, r) == 0);
    CLOSE(r[p], y[p] - 1.0 * (1.0 - y[v]), 1, "Lk constraint");
    CLOSE(r[v], pow(yp[p], 3) - y[v], 1, "Rg law");
  }
  double y0[2], yp0[2];
  bg_eqsys_initial_yp(f.s, y0, yp0);
  DBL_NEAR(y0[p], 0, 0);
  DBL_NEAR(y0[v], 1, 1e-12);
  DBL_NEAR(yp0[p], 1, 1e-9);
  check_index1(&f);
  efx_free(&f);
}

/* internal_mod_tf: the flow source fixes the transformer; the 1-junction is
 * inserted into bond 3 (j -> Cj), Rj takes resistance causality.
 *   0 = f2 - F0/(1 + k*f2^2)                    the modulated transformer
 *   0 = R0*(f2 - Cj.f) - Cj.q/C0                the inserted junction, e3 = e4 = R0*f4
 *   Cj.q' = Cj.f */
static void test_internal_mod_tf(void) {
  efx f;
  if (load_lagrange(&f, "internal_mod_tf")) { efx_free(&f); return; }
  check_inserted(&f, 1, (const int[]){3});
  int q = U(&f, "Cj.q"), f2 = U(&f, "f2"), v = U(&f, "Cj.f");
  INT_EQ(bg_eqsys_n(f.s), 3);
  const double k = 0.5, C0 = 1, R0 = 1, F0 = 1;
  unsigned st = 13;
  for (int it = 0; it < 20; it++) {
    double y[3], yp[3], r[3];
    for (int i = 0; i < 3; i++) y[i] = efx_rand(&st, -2, 2), yp[i] = efx_rand(&st, -2, 2);
    OK(bg_eqsys_residual(f.s, 0.2, y, yp, r) == 0);
    CLOSE(r[f2], y[f2] - F0 / (1 + k * y[f2] * y[f2]), 1, "transformer");
    CLOSE(r[v], R0 * (y[f2] - y[v]) - y[q] / C0, 1, "inserted junction in bond 3");
    CLOSE(r[q], yp[q] - y[v], 1, "Cj.q'");
  }
  check_index1(&f);
  efx_free(&f);
}

/* internal_mod_r: js gets an artificial source, then bond 4 (jp -> Ra) a
 * 1-junction; Rb is jp's strong bond (resistance), Ra's law solved for Ra.f.
 *   0 = E0 - Cs.q/C0 - Rb0*(js.f - Ra.f)        balance at js
 *   0 = G0*Rb0*(js.f - Ra.f)*(1 + a*js.f^2) - Ra.f   Ra's law at the inserted junction
 *   Cs.q' = js.f */
static void test_internal_mod_r(void) {
  efx f;
  if (load_lagrange(&f, "internal_mod_r")) { efx_free(&f); return; }
  check_inserted(&f, 2, (const int[]){4});
  int q = U(&f, "Cs.q"), v1 = U(&f, "js.f"), v2 = U(&f, "Ra.f");
  const double E0 = 1, C0 = 1, G0 = 1, a = 0.1, Rb0 = 2;
  unsigned st = 17;
  for (int it = 0; it < 20; it++) {
    double y[3], yp[3], r[3];
    for (int i = 0; i < 3; i++) y[i] = efx_rand(&st, -2, 2), yp[i] = efx_rand(&st, -2, 2);
    OK(bg_eqsys_residual(f.s, 0.2, y, yp, r) == 0);
    double e5 = Rb0 * (y[v1] - y[v2]);
    CLOSE(r[v1], E0 - y[q] / C0 - e5, 1, "balance at js");
    CLOSE(r[v2], G0 * e5 * (1 + a * y[v1] * y[v1]) - y[v2], 1, "Ra law");
    CLOSE(r[q], yp[q] - y[v1], 1, "Cs.q'");
  }
  check_index1(&f);
  efx_free(&f);
}

/* bridge_compliance: ja, jb, v get artificial sources, then 1-junctions are
 * inserted into bonds 1 and 4 (the orifices to the tank); the chamber stores
 * stay integral, the piston mass becomes dependent. Every orifice law is
 * solved implicitly; the inserted junctions say p1 = C1.q/Cc, p4 = C2.q/Cc. */
static void test_bridge_compliance(void) {
  efx f;
  if (load_lagrange(&f, "bridge_compliance")) { efx_free(&f); return; }
  check_inserted(&f, 5, (const int[]){1, 4});
  INT_EQ(f.a.nstates, 2);
  INT_EQ(f.a.ndependent, 1);
  int n = bg_eqsys_n(f.s);
  INT_EQ(n, 10);
  /* at the consistent initial point the chamber pressures are the stores'
   * (q0 = 0: both 0), and the orifices to the tank carry no flow */
  double y[16], yp[16], e[20], fl[20];
  if (n <= 16) {
    bg_eqsys_initial_yp(f.s, y, yp);
    OK(bg_eqsys_signals(f.s, 0, y, yp, e, fl) == 0);
    DBL_NEAR(e[0], 0, 1e-6);  /* bond 1: p1 */
    DBL_NEAR(e[3], 0, 1e-6);  /* bond 4: p4 */
    DBL_NEAR(fl[0], 0, 1e-15);
    DBL_NEAR(y[U(&f, "mp.p")], 0, 0);
  }
  check_index1(&f);
  efx_free(&f);
}

int main(void) {
  test_mod_no_loop();
  test_parallel_conductance();
  test_internal_mod_tf();
  test_internal_mod_r();
  test_bridge_compliance();
  return bg_t_done();
}
