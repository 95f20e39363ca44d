/* SPDX-License-Identifier: BSD-3-Clause */
/* State space of DAEs with dependent stores (docs/linear.md#matrices): two
 * inertias rigidly coupled through a TF reduce to one state with the merged
 * inertia J1 + n^2 J2 (exact coefficients derived by hand), and the reduced
 * and descriptor forms give the same H(s) at several frequencies; a source
 * of effort on a capacitor makes the source's current improper (refused,
 * descriptor kept, the input named); a hand-made descriptor system whose
 * states need an input's derivative is refused as well. */
#include <complex.h>
#include <math.h>
#include <stdio.h>

#include "harness.h"
#include "linear_fixture.h"
#include "linear/linear_int.h"

/* H(s) of every pair from the reduced form against the descriptor form. */
static void forms_agree(void) {
  bg_linear desc = L;
  desc.reduced = 0;
  const double complex s[] = {0.01 * I, 0.3 * I, I, 7 * I, 100 * I, 0.5 + 2 * I};
  double worst = 0;
  for (int p = 0; p < L.ny * L.nu; p++)
    for (int k = 0; k < 6; k++) {
      double complex hr = bg_lin_eval(&L, p / L.nu, p % L.nu, s[k]);
      double complex hd = bg_lin_eval(&desc, p / L.nu, p % L.nu, s[k]);
      worst = fmax(worst, cabs(hr - hd) / fmax(cabs(hd), 1e-300));
    }
  OK(worst < 1e-12);
  if (worst >= 1e-12) printf("  worst relative difference %g\n", worst);
}

/* T drives J1 (damper b1); J2 turns at w2 = n w1 (bond w2 -> g -> w1:
 * f1 = n f2 on the TF's sides, docs/format.md), so I2 takes derivative
 * causality and J_eq = J1 + n^2 J2 = 2 + 4*3 = 14. With p1 = J1 w1:
 * p1' = (J1/J_eq)(T - b1 p1/J1): A = -b1/J_eq = -1/28, B = J1/J_eq = 1/7;
 * w/T = (1/14)/(s + 1/28), w2/T = (n/14)/(s + 1/28), and the torque on J2,
 * e2 = J2 w2' = J2 n w1': e2/T = (J2 n/J_eq) s/(s + 1/28) = (3/7) s/(s + 1/28). */
static const char *gear =
    "param J1 = 2, J2 = 3, b1 = 0.5, n = 2\n"
    "Se T = 1\n1 w1\nI I1 = J1\nR R1 = b1\nTF g = n\n1 w2\nI I2 = J2\n"
    "bond T -> w1\nbond w1 -> I1\nbond w1 -> R1\nbond w2 -> g\nbond g -> w1\nbond w2 -> I2\n"
    "output w = I1.f, w2f = I2.f, e2 = I2.e\n";

static void test_gear(void) {
  OK(lin(gear, 0) == 0);
  INT_EQ(L.N, 2);
  INT_EQ(L.reduced, 1);
  OK(L.reduce_note == NULL);
  INT_EQ(L.n, 1);
  STR_EQ(L.uname_all[L.state[0]], "I1.p");
  INT_EQ(L.nelim, 1);
  STR_EQ(L.uname_all[L.elim[0]], "I2.p");
  DBL_NEAR(L.A[0], -1.0 / 28, 1e-15);
  DBL_NEAR(L.B[0], 1.0 / 7, 1e-15);
  DBL_NEAR(L.C[0], 0.5, 1e-15);          /* w = p1/J1 */
  DBL_NEAR(L.C[1], 1, 1e-15);            /* w2 = n p1/J1 */
  DBL_NEAR(L.C[2], -3.0 / 28, 1e-15);    /* e2 = J2 n p1'/J1 = (J2 n/J1)(A p1 + B T) */
  DBL_NEAR(L.D[2], 3.0 / 7, 1e-15);
  INT_EQ(L.npole, 1);
  DBL_NEAR(L.pole_re[0], -1.0 / 28, 1e-15);
  tf_is(0, 0, (double[]){1.0 / 14}, 1, (double[]){1, 1.0 / 28}, 2, 1e-12);
  tf_is(1, 0, (double[]){2.0 / 14}, 1, (double[]){1, 1.0 / 28}, 2, 1e-12);
  tf_is(2, 0, (double[]){3.0 / 7, 0}, 2, (double[]){1, 1.0 / 28}, 2, 1e-12);
  DBL_NEAR(L.tf[0].dc_gain, 2, 1e-12); /* 1/b1 */
  forms_agree();
  OK(L.sym.ok); /* the symbolic form of the merged inertia */
  if (L.sym.ok) STR_EQ(L.sym.A[0][0], "-b1/(J1 + J2*n^2)");
  done();
}

/* Se U on C1 in parallel with R1 + L1: C1.q = C0 U, so the source's current
 * is = C0 U' + iL: is/U = 0.5 s + 4/(s + 8) = (0.5 s^2 + 4 s + 4)/(s + 8),
 * improper: no state space, the input named; without that output the
 * state space of L1 alone: i/U = 4/(s + 8). */
static const char *secap =
    "param V = 1, C0 = 0.5, R0 = 2, L0 = 0.25\n"
    "Se U = V\n0 j\nC C1 = C0\n1 k\nR R1 = R0\nI L1 = L0\n"
    "bond U -> j\nbond j -> C1\nbond j -> k\nbond k -> R1\nbond k -> L1\n";

static void test_improper(void) {
  char src[1024];
  snprintf(src, sizeof src, "%soutput i = L1.f, is = U.f, vC = C1.e\n", secap);
  OK(lin(src, 0) == 0);
  INT_EQ(L.reduced, 0);
  OK(L.reduce_note && strstr(L.reduce_note, "output is needs the derivative of input U (an improper"));
  tf_is(0, 0, (double[]){4}, 1, (double[]){1, 8}, 2, 1e-12);
  tf_is(1, 0, (double[]){0.5, 4, 4}, 3, (double[]){1, 8}, 2, 1e-12);
  done();
  snprintf(src, sizeof src, "%soutput i = L1.f, vC = C1.e\n", secap);
  OK(lin(src, 0) == 0);
  INT_EQ(L.reduced, 1);
  INT_EQ(L.n, 1);
  STR_EQ(L.uname_all[L.state[0]], "L1.p");
  tf_is(0, 0, (double[]){4}, 1, (double[]){1, 8}, 2, 1e-12);
  DBL_NEAR(L.D[1], 1, 1e-15); /* vC = U */
  done();
}

/* E = [1 1; 0 0], A = -I, B = [0; 1]: x2 = u from the second row, so
 * x1' = -x1 - u': the states need the input's derivative. */
static void test_input_rate(void) {
  bg_linear l;
  memset(&l, 0, sizeof l);
  static const char *un[] = {"u"}, *yn[] = {"y"};
  double E[] = {1, 0, 1, 0}, A[] = {-1, 0, 0, -1}, B[] = {0, 1}, C[] = {1, 0}, Cp[] = {0, 0}, D[] = {0};
  l.ok = 1, l.N = 2, l.nu = 1, l.ny = 1, l.uname = un, l.yname = yn;
  l.E = E, l.Ad = A, l.Bd = B, l.Cd = C, l.Cpd = Cp, l.Dd = D;
  int order[] = {1, 0};
  bg_lin_reduce(&l, order);
  INT_EQ(l.reduced, 0);
  OK(l.reduce_note && strstr(l.reduce_note, "the states would need the derivative of input u"));
  free(l.reduce_note), free(l.elim), free(l.state), free(l.A), free(l.B), free(l.C), free(l.D);
}

int main(void) {
  test_gear();
  test_improper();
  test_input_rate();
  return bg_t_done();
}
