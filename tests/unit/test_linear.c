/* SPDX-License-Identifier: BSD-3-Clause */
/* Linear analysis (docs/linear.md): operating points, A, B, C, D against
 * matrices derived by hand, transfer functions with exact polynomial
 * coefficients, poles and zeros, DC gains, frequency responses against
 * C (jwI - A)^-1 B + D evaluated from the hand-derived matrices. */
#include <complex.h>
#include <math.h>
#include <stdio.h>

#include "harness.h"
#include "linear_fixture.h"

static double at(const double *M, int ld, int i, int j) { return M[(size_t)j * ld + i]; }

static const char *rlc =
    "param V = 1, R0 = 2, L0 = 0.5, C0 = 0.1\n"
    "Se U = V\n1 j\nR R1 = R0\nI L1 = L0\nC C1 = C0\n"
    "bond U -> j\nbond j -> R1\nbond j -> L1\nbond j -> C1\n"
    "output vC = C1.e \"capacitor voltage\", i = L1.f\n";

/* p' = U - R/L p - q/C, q' = p/L; vC = q/C, i = p/L. */
static void test_rlc(void) {
  OK(lin(rlc, 0) == 0);
  INT_EQ(L.reduced, 1);
  INT_EQ(L.n, 2);
  INT_EQ(L.nu, 1);
  INT_EQ(L.ny, 2);
  STR_EQ(L.uname[0], "U");
  STR_EQ(L.yname[0], "vC");
  STR_EQ(L.uname_all[L.state[0]], "L1.p");
  DBL_NEAR(at(L.A, 2, 0, 0), -4, 1e-15);
  DBL_NEAR(at(L.A, 2, 0, 1), -10, 1e-15);
  DBL_NEAR(at(L.A, 2, 1, 0), 2, 1e-15);
  DBL_NEAR(at(L.A, 2, 1, 1), 0, 1e-15);
  DBL_NEAR(L.B[0], 1, 0); DBL_NEAR(L.B[1], 0, 0);
  DBL_NEAR(at(L.C, 2, 0, 1), 10, 1e-15); DBL_NEAR(at(L.C, 2, 1, 0), 2, 1e-15);
  DBL_NEAR(at(L.C, 2, 0, 0), 0, 0); DBL_NEAR(L.D[0], 0, 0);
  INT_EQ(L.npole, 2);
  DBL_NEAR(L.pole_re[0], -2, 1e-12); DBL_NEAR(L.pole_im[0], -4, 1e-12);
  DBL_NEAR(L.pole_re[1], -2, 1e-12); DBL_NEAR(L.pole_im[1], 4, 1e-12);
  /* vC/U = 20/(s^2 + 4s + 20), i/U = 2s/(s^2 + 4s + 20) */
  tf_is(0, 0, (double[]){20}, 1, (double[]){1, 4, 20}, 3, 1e-12);
  tf_is(1, 0, (double[]){2, 0}, 2, (double[]){1, 4, 20}, 3, 1e-12);
  DBL_NEAR(L.tf[0].dc_gain, 1, 1e-12);
  DBL_NEAR(L.tf[1].dc_gain, 0, 1e-12);
  INT_EQ(L.tf[1].nzero, 1);
  DBL_NEAR(L.tf[1].zero_re[0], 0, 1e-12);
  done();
}

/* H(jw) = C (jwI - A)^-1 B + D from hand-derived matrices (Gaussian
 * elimination with partial pivoting, n <= 8), against bg_linear_freqresp. */
static double complex hand_h(int n, const double *A, const double *b, const double *c, double d,
                             double w) {
  double complex M[8][9];
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) M[i][j] = (i == j ? I * w : 0) - A[i * n + j];
    M[i][n] = b[i];
  }
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int i = k + 1; i < n; i++) if (cabs(M[i][k]) > cabs(M[p][k])) p = i;
    for (int j = 0; j <= n; j++) { double complex t = M[k][j]; M[k][j] = M[p][j], M[p][j] = t; }
    for (int i = k + 1; i < n; i++) {
      double complex f = M[i][k] / M[k][k];
      for (int j = k; j <= n; j++) M[i][j] -= f * M[k][j];
    }
  }
  double complex x[8], y = d;
  for (int i = n - 1; i >= 0; i--) {
    x[i] = M[i][n];
    for (int j = i + 1; j < n; j++) x[i] -= M[i][j] * x[j];
    x[i] /= M[i][i];
  }
  for (int i = 0; i < n; i++) y += c[i] * x[i];
  return y;
}

/* Every frequency of the automatic grid for pair (iy, iu), to 1e-10 relative. */
static void bode_is(int iy, int iu, int n, const double *A, const double *b, const double *c, double d) {
  enum { NW = 200 };
  double w[NW], *re = malloc(sizeof(double) * NW * L.ny * L.nu), *im = malloc(sizeof(double) * NW * L.ny * L.nu);
  INT_EQ(bg_linear_freqs(&L, F.m, NW, w), NW);
  OK(w[0] > 0 && w[NW - 1] > w[0]);
  OK(bg_linear_freqresp(&L, NW, w, re, im) == 0);
  double worst = 0;
  for (int k = 0; k < NW; k++) {
    double complex h = hand_h(n, A, b, c, d, w[k]);
    size_t at = (size_t)(iy * L.nu + iu) * NW + k;
    worst = fmax(worst, cabs(re[at] + I * im[at] - h) / cabs(h));
  }
  OK(worst < 1e-10);
  if (worst >= 1e-10) printf("  worst relative difference %g\n", worst);
  free(re), free(im);
}

static void test_rlc_bode(void) {
  OK(lin(rlc, 0) == 0);
  const double A[] = {-4, -10, 2, 0}, b[] = {1, 0}, c0[] = {0, 10}, c1[] = {2, 0};
  bode_is(0, 0, 2, A, b, c0, 0);
  bode_is(1, 0, 2, A, b, c1, 0);
  done();
}

/* Two masses: F on m1 (damper b to ground), spring K1 between, K2 from m2 to
 * ground. x2/F = K1 / ((m1 s^2 + b s + K1)(m2 s^2 + K1 + K2) - K1^2). */
static const char *two_mass =
    "param F0 = 1, m1 = 1, m2 = 2, b = 0.5, K1 = 3, K2 = 4\n"
    "Se F = F0\n1 j1\nI M1 = m1\nR B = b\n0 n\nC S1 = 1/K1\n1 j2\nI M2 = m2\nC S2 = 1/K2\n"
    "bond F -> j1\nbond j1 -> M1\nbond j1 -> B\nbond j1 -> n\nbond n -> S1\nbond n -> j2\n"
    "bond j2 -> M2\nbond j2 -> S2\n"
    "output x2 = S2.q, v1 = M1.f\n";

static void test_two_mass(void) {
  OK(lin(two_mass, 0) == 0);
  INT_EQ(L.n, 4);
  /* (s^2 + 0.5 s + 3)(2 s^2 + 7) - 9 = 2 s^4 + s^3 + 13 s^2 + 3.5 s + 12 */
  tf_is(0, 0, (double[]){1.5}, 1, (double[]){1, 0.5, 6.5, 1.75, 6}, 5, 1e-11);
  tf_is(1, 0, (double[]){1, 0, 3.5, 0}, 4, (double[]){1, 0.5, 6.5, 1.75, 6}, 5, 1e-11);
  DBL_NEAR(L.tf[0].dc_gain, 0.25, 1e-12);
  /* states M1.p, S1.q, M2.p, S2.q: p1' = F - b p1/m1 - K1 q1, q1' = p1/m1 - p2/m2,
   * p2' = K1 q1 - K2 q2, q2' = p2/m2 (row-major here) */
  const double A[] = {-0.5, -3, 0, 0, 1, 0, -0.5, 0, 0, 3, 0, -4, 0, 0, 0.5, 0};
  const double b[] = {1, 0, 0, 0}, cx[] = {0, 0, 0, 1}, cv[] = {1, 0, 0, 0};
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++) DBL_NEAR(at(L.A, 4, i, j), A[i * 4 + j], 1e-15);
  bode_is(0, 0, 4, A, b, cx, 0);
  bode_is(1, 0, 4, A, b, cv, 0);
  done();
}

/* DC motor: V = Ra i + La di/dt + k w, J w' = k i - bm w - TL, theta' = w.
 * w/V = k / ((La s + Ra)(J s + bm) + k^2) = 10/(s^2 + 6 s + 13);
 * w/TL = -(10 s + 40)/(s^2 + 6 s + 13); theta/V = 10/(s (s^2 + 6 s + 13)). */
static const char *dc_motor =
    "param V0 = 0, T0 = 0, Ra = 2, La = 0.5, k = 0.5, J0 = 0.1, bm = 0.2\n"
    "Se V = V0\n1 je\nR Rm = Ra\nI Lm = La\nGY G = k\n1 jm\nI J = J0\nR Bm = bm\nSe TL = T0\n"
    "state theta' = J.f\n"
    "bond V -> je\nbond je -> Rm\nbond je -> Lm\nbond je -> G\nbond G -> jm\nbond jm -> J\n"
    "bond jm -> Bm\nbond jm -> TL\n"
    "output w = J.f, th = theta, i = Lm.f\n"
    "linearise at = steady\n";

static void test_dc_motor(void) {
  OK(lin(dc_motor, -1) == 0);
  INT_EQ(L.steady, 1);
  INT_EQ(L.nu, 2);
  STR_EQ(L.uname[1], "TL");
  OK(L.message && strstr(L.message, "not unique")); /* theta is free */
  tf_is(0, 0, (double[]){10}, 1, (double[]){1, 6, 13}, 3, 1e-12);
  tf_is(0, 1, (double[]){-10, -40}, 2, (double[]){1, 6, 13}, 3, 1e-12);
  tf_is(1, 0, (double[]){10}, 1, (double[]){1, 6, 13, 0}, 4, 1e-12);
  OK(isinf(L.tf[1 * 2 + 0].dc_gain));
  DBL_NEAR(L.tf[0].dc_gain, 10.0 / 13, 1e-12);
  done();
  /* with V0 = 1 the motor turns: theta grows, so there is no steady state */
  char *src = strdup(dc_motor);
  OK(bg_t_replace(&src, "V0 = 0", "V0 = 1") == 0);
  OK(lin(src, -1) == -1);
  OK(L.message && strstr(L.message, "no steady state"));
  done();
  free(src);
}

/* Index-1 DAE: bond_loop (a causal loop through a TF, Equation 4.27) with
 * n = 3, C0 = 2, I0 = 0.5: Cs.q' = (n F - Is.p/I0)/(n - 1) = 1.5 F - Is.p,
 * Is.p' = Cs.q/(C0 (n - 1)) = Cs.q/4: Is.p/F = 0.375/(s^2 + 0.25). */
static void test_dae(void) {
  OK(efx_load(&F, "bond_loop", NULL, -1, NULL, 0) == 0);
  efx_free(&F);
  char *src = bg_read_file(BG_SOURCE_DIR "/examples/bond_loop.bg", NULL);
  OK(bg_t_replace(&src, "param n = 2, C0 = 1, I0 = 1", "param n = 3, C0 = 2, I0 = 0.5") == 0);
  OK(lin(src, 0) == 0);
  OK(!bg_eqsys_is_ode(F.s));
  INT_EQ(L.N, 4);
  INT_EQ(L.reduced, 1);
  INT_EQ(L.n, 2);
  const double A[] = {0, -1, 0.25, 0}, b[] = {1.5, 0}, cq[] = {1, 0}, cp[] = {0, 1};
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) DBL_NEAR(at(L.A, 2, i, j), A[i * 2 + j], 1e-14);
  DBL_NEAR(L.B[0], 1.5, 1e-14);
  tf_is(1, 0, (double[]){0.375}, 1, (double[]){1, 0, 0.25}, 3, 1e-12);
  tf_is(0, 0, (double[]){1.5, 0}, 2, (double[]){1, 0, 0.25}, 3, 1e-12);
  bode_is(0, 0, 2, A, b, cq, 0);
  bode_is(1, 0, 2, A, b, cp, 0);
  done();
  free(src);
}

/* A tank with Torricelli outflow f = k sqrt(e): steady e* = (Q0/k)^2, and
 * the linearisation h/Q = (1/C0)/(s + k/(2 C0 sqrt(e*))). Two operating
 * points: the steady states for Q0 = 1 and Q0 = 2, and the initial point. */
static const char *tank =
    "param Q0 = 1, C0 = 2, k = 1\n"
    "Sf Q = Q0\n0 n\nC T = C0 [q0 = 8]\nR Out : f = k*sqrt(e)\n"
    "bond Q -> n\nbond n -> T\nbond n -> Out\n"
    "output h = T.e\n";

static void test_nonlinear(void) {
  OK(lin(tank, 1) == 0);
  DBL_NEAR(L.h0[0], 1, 1e-10);
  tf_is(0, 0, (double[]){0.5}, 1, (double[]){1, 0.25}, 2, 1e-9);
  done();
  char *src = strdup(tank);
  OK(bg_t_replace(&src, "Q0 = 1", "Q0 = 2") == 0);
  OK(lin(src, 1) == 0);
  DBL_NEAR(L.h0[0], 4, 1e-10);
  tf_is(0, 0, (double[]){0.5}, 1, (double[]){1, 0.125}, 2, 1e-9);
  done();
  OK(lin(tank, 0) == 0); /* the initial point q = 8, e = 4 with Q0 = 1: not a steady state */
  DBL_NEAR(L.h0[0], 4, 1e-15);
  OK(L.resid > 0.9);
  tf_is(0, 0, (double[]){0.5}, 1, (double[]){1, 0.125}, 2, 1e-12);
  done();
  free(src);
}

/* No steady state: a mass pushed by a constant force accelerates forever. */
static void test_no_steady(void) {
  OK(lin("Se F = 1\n1 j\nI m = 2\nbond F -> j\nbond j -> m\n", 1) == -1);
  OK(L.message && strstr(L.message, "no steady state"));
  done();
  OK(lin("Se F = 1\n1 j\nI m = 2\nbond F -> j\nbond j -> m\n", 0) == 0);
  tf_is(0, 0, (double[]){1}, 1, (double[]){1, 0}, 2, 1e-14); /* m.p/F = 1/s */
  done();
}

/* RLC step and impulse responses against the closed forms:
 * vC = 1 - e^-2t (cos 4t + sin(4t)/2), i = e^-2t sin(4t)/2, impulse of vC = 5 e^-2t sin 4t. */
static void test_rlc_time(void) {
  OK(lin(rlc, 0) == 0);
  double t_end = bg_linear_t_end(&L, F.m); /* 5 time constants of the -2 pair: 2.5 -> 5 */
  DBL_NEAR(t_end, 5, 0);
  enum { NT = 201 };
  double y[2 * NT], yi[2 * NT], worst = 0;
  OK(bg_linear_step(&L, t_end, NT, 0, y) == 0);
  OK(bg_linear_step(&L, t_end, NT, 1, yi) == 0);
  for (int k = 0; k < NT; k++) {
    double t = t_end * k / (NT - 1), e = exp(-2 * t);
    worst = fmax(worst, fabs(y[k] - (1 - e * (cos(4 * t) + 0.5 * sin(4 * t)))));
    worst = fmax(worst, fabs(y[NT + k] - 0.5 * e * sin(4 * t)));
    worst = fmax(worst, fabs(yi[k] - 5 * e * sin(4 * t)));
  }
  OK(worst < 1e-12);
  if (worst >= 1e-12) printf("  worst step/impulse difference %g\n", worst);
  done();
}

/* The symbolic form (linear models): entries and transfer functions in the
 * params, as derived by hand. */
static void sym_is(char **M, int k, const char *want) { STR_EQ(M[k], want); }

static void test_symbolic(void) {
  OK(lin(rlc, 0) == 0);
  OK(L.sym.ok);
  sym_is(L.sym.A[0], 0, "-R0/L0"), sym_is(L.sym.A[0], 2, "-1/C0"), sym_is(L.sym.A[0], 1, "1/L0");
  sym_is(L.sym.C[0], 2, "1/C0"), sym_is(L.sym.C[0], 1, "1/L0");
  sym_is(L.sym.den[0], 1, "R0/L0"), sym_is(L.sym.den[0], 2, "1/(L0*C0)");
  sym_is(L.sym.num[0], 2, "1/(L0*C0)"); /* vC/U */
  sym_is(L.sym.num[0], 4, "1/L0");      /* i/U: (1/L0) s */
  OK(strstr(L.sym.A[1][0], "\\frac{\\mathrm{R0}}{\\mathrm{L0}}") != NULL); /* LaTeX */
  done();
  /* Equation 4.27: Cs.q' = (n F - Is.p/I0)/(n - 1), Is.p' = Cs.q/(C0 (n - 1)) */
  OK(efx_load(&F, "bond_loop", NULL, -1, NULL, 0) == 0);
  OK(bg_linear_compute(F.m, &F.a, 0, &L) == 0);
  OK(L.sym.ok);
  sym_is(L.sym.A[0], 2, "-1/(I0*(n - 1))"), sym_is(L.sym.A[0], 1, "1/(C0*(n - 1))");
  sym_is(L.sym.B[0], 0, "n/(n - 1)");
  sym_is(L.sym.den[0], 2, "1/(C0*I0*(n - 1)^2)");
  done();
  /* DC motor: w/V = (k/(La J0)) s / (s^3 + ... ): the denominator of the hand-derived
   * (La s + Ra)(J0 s + bm) + k^2 over La J0, times s for the angle */
  OK(lin(dc_motor, 0) == 0);
  OK(L.sym.ok);
  sym_is(L.sym.den[0], 1, "(Ra*J0 + La*bm)/(La*J0)"), sym_is(L.sym.den[0], 2, "(Ra*bm + k^2)/(La*J0)");
  sym_is(L.sym.den[0], 3, "0");
  sym_is(L.sym.num[0], 2, "k/(La*J0)");
  done();
  /* two masses: K1 K2/(m1 m2) at s^0 */
  OK(lin(two_mass, 0) == 0);
  OK(L.sym.ok);
  sym_is(L.sym.den[0], 4, "K1*K2/(m1*m2)"), sym_is(L.sym.den[0], 2, "(m1*K1 + m1*K2 + m2*K1)/(m1*m2)");
  sym_is(L.sym.num[0], 4, "K1/(m1*m2)");
  done();
  /* nonlinear: numeric only, and the reason */
  OK(lin(tank, 1) == 0);
  OK(!L.sym.ok && L.sym.note && strstr(L.sym.note, "numeric only"));
  done();
}

/* Detectors are outputs (docs/linear.md): with the output statement, in file
 * order; the RLC's vC/U and i/U as from `output vC = C1.e, i = L1.f`. */
static void test_detectors(void) {
  const char *m = "param V = 1, R0 = 2, L0 = 0.5, C0 = 0.1\n"
                  "Se U = V\n1 j\nR R1 = R0\nI L1 = L0\nC C1 = C0\n"
                  "bond U -> j\nbond j -> R1\nbond j -> L1\nbond j -> C1\n"
                  "De vC = C1\noutput vR = R1.e\nDf i = j\n";
  OK(lin(m, 0) == 0);
  INT_EQ(L.ny, 3);
  INT_EQ(L.outputs_are_states, 0);
  STR_EQ(L.yname[0], "vC");
  STR_EQ(L.yname[1], "vR");
  STR_EQ(L.yname[2], "i");
  INT_EQ(L.n, 2); /* the detectors add no state */
  tf_is(0, 0, (double[]){20}, 1, (double[]){1, 4, 20}, 3, 1e-12);
  tf_is(1, 0, (double[]){4, 0}, 2, (double[]){1, 4, 20}, 3, 1e-12); /* R0 * i */
  tf_is(2, 0, (double[]){2, 0}, 2, (double[]){1, 4, 20}, 3, 1e-12);
  DBL_NEAR(L.tf[0].dc_gain, 1, 1e-12);
  done();
  /* detectors alone: they are the outputs, not the states */
  OK(lin("Se U = 1\n1 j\nR R1 = 2\nI L1 = 0.5\nC C1 = 0.1\nbond U -> j\nbond j -> R1\n"
         "bond j -> L1\nbond j -> C1\nDe vC = C1\n", 0) == 0);
  INT_EQ(L.ny, 1);
  STR_EQ(L.yname[0], "vC");
  tf_is(0, 0, (double[]){20}, 1, (double[]){1, 4, 20}, 3, 1e-12);
  done();
}


/* The phase is continuous along the frequencies, on the branch of the
 * transfer function's poles and zeros, where unwrapping the samples fails:
 * (1) a hand-made response with two lightly damped pole pairs at 100 and 101
 * rad/s between two samples (-360 degrees inside one step, which unwrapping
 * cannot see: every later sample 360 off); (2) a collocated two-mass model
 * whose antiresonance (zero pair at 100 rad/s) nearly cancels its resonance
 * (100.5 rad/s), with a sample between them, against the phase written from
 * v1/F = (m2 s^2 + b s + k) / (s (m1 m2 s^2 + (m1 + m2)(b s + k))). */
#define DEG_PER_RAD (180 / 3.14159265358979323846)
static double hand_phase(double w) { /* the pole pairs and a pole at -1, continuous */
  const double pr[] = {-0.01, -0.01, -0.01, -0.01, -1}, pi[] = {100, -100, 101, -101, 0};
  double a = 0;
  for (int i = 0; i < 5; i++) a -= atan2(w - pi[i], -pr[i]) * DEG_PER_RAD;
  return a;
}

static void test_phase(void) {
  enum { NW = 41 };
  double pr[] = {-0.01, -0.01, -0.01, -0.01, -1}, pi[] = {100, -100, 101, -101, 0};
  bg_lin_tf t = {0};
  t.npole = 5, t.pole_re = pr, t.pole_im = pi;
  bg_linear l = {0};
  l.ntf = 1, l.tf = &t;
  double w[NW], re[NW], im[NW], ph[NW];
  for (int k = 0; k < NW; k++) {
    w[k] = pow(10, 1 + 2.0 * k / (NW - 1)); /* 10 to 1000 rad/s, 20 a decade: 97.7, 109.6 */
    double complex s = I * w[k], h = 1;
    for (int i = 0; i < 5; i++) h /= s - (pr[i] + I * pi[i]);
    re[k] = creal(h), im[k] = cimag(h);
  }
  bg_linear_phase(&l, 0, NW, w, re, im, ph);
  double worst = 0;
  for (int k = 0; k < NW; k++) worst = fmax(worst, fabs(ph[k] - hand_phase(w[k])));
  OK(worst < 1e-9);
  DBL_NEAR(ph[NW - 1], -450, 0.5); /* four poles of a pair and one real: -4 * 90 - 90 */
  l.ntf = 0; /* no factored form: the samples unwrapped, 360 off after the pairs */
  bg_linear_phase(&l, 0, NW, w, re, im, ph);
  DBL_NEAR(ph[NW - 1] - hand_phase(w[NW - 1]), 360, 1e-6);

  static const char *near_cancel =
      "param m1 = 1, m2 = 0.01, k = 100, b = 1e-3\n"
      "Se F = 1\n1 a\nI M1 = m1\n0 n\n1 d\nC K = 1/k\nR B = b\n1 c\nI M2 = m2\n"
      "bond F -> a\nbond a -> M1\nbond a -> n\nbond n -> d\nbond d -> K\nbond d -> B\n"
      "bond n -> c\nbond c -> M2\n"
      "output v1 = M1.f\nlinearise at = initial\n";
  OK(lin(near_cancel, 0) == 0);
  INT_EQ(L.ntf, 1);
  enum { NM = 9 };
  double wm[NM] = {1, 10, 50, 99.9, 100.25, 101, 200, 1000, 1e4}, rm[NM], imm[NM], pm[NM];
  OK(bg_linear_freqresp(&L, NM, wm, rm, imm) == 0);
  bg_linear_phase(&L, 0, NM, wm, rm, imm, pm);
  const double m1 = 1, m2 = 0.01, k = 100, b = 1e-3;
  worst = 0;
  for (int i = 0; i < NM; i++) {
    double v = wm[i], want = atan2(b * v, k - m2 * v * v) * DEG_PER_RAD - 90 -
                             atan2((m1 + m2) * b * v, (m1 + m2) * k - m1 * m2 * v * v) * DEG_PER_RAD;
    worst = fmax(worst, fabs(pm[i] - want));
  }
  OK(worst < 1e-6);
  OK(pm[4] > 60); /* between the antiresonance and the resonance: +67, not -293 */
  done();
}

int main(void) {
  test_detectors();
  test_symbolic();
  test_rlc_time();
  test_rlc();
  test_rlc_bode();
  test_two_mass();
  test_phase();
  test_dc_motor();
  test_dae();
  test_nonlinear();
  test_no_steady();
  return bg_t_done();
}
