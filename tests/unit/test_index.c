/* Numeric index (Algorithm 4.1) of every example, badly scaled circuits,
 * and the eigenvalues of rlc against the roots of L C s^2 + R C s + 1. */
#include "harness.h"
#include "eqs_fixture.h"
#include "index.h"

static int index_of(const char *name, const char *text, int method, const char *set, double val,
                    int print) {
  efx f;
  if (efx_load(&f, name, text, method, set, val)) {
    efx_free(&f);
    return -100;
  }
  bg_index_result r;
  int k = bg_index_compute(f.s, f.m, &r);
  if (print) {
    bg_strbuf sb = {0};
    bg_index_report(&r, &sb);
    printf("%s%s: %s", name ? name : "inline", set ? " (set)" : "", bg_sb_str(&sb));
    bg_sb_free(&sb);
  }
  bg_index_free(&r);
  efx_free(&f);
  return k;
}

static void test_examples(void) {
  INT_EQ(index_of("rlc", NULL, -1, NULL, 0, 1), 0);
  INT_EQ(index_of("bridge_compliance", NULL, -1, NULL, 0, 1), 0);
  INT_EQ(index_of("hydraulic_bridge", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("slider_crank", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("class12_paths", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("bond_loop", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("loop_class1", NULL, -1, NULL, 0, 1), 2);
  INT_EQ(index_of("delta", NULL, -1, NULL, 0, 1), 2);
  INT_EQ(index_of("delta", NULL, BG_METHOD_VANDIJK, NULL, 0, 1), 1);
  INT_EQ(index_of("modulated_source", NULL, -1, NULL, 0, 1), 1);
  /* k = R20: the loop residual loses U.e and becomes eC = 0, a constraint
   * on the state: index 2, not a singular pencil */
  INT_EQ(index_of("modulated_source", NULL, -1, "k", 2, 1), 2);
  /* n = 1: the unity-gain loop leaves e6 = 0 (Cs.q = 0): index 2 */
  INT_EQ(index_of("bond_loop", NULL, -1, "n", 1, 1), 2);
}

static void test_scaling(void) {
  const char *rc = "model rc\nparam C0 = 1e-9, R0 = 1e6\nSe U = 1\n1 j\nR R1 = R0\nC C1 = C0\n"
                   "bond 1 U -> j\nbond 2 j -> R1\nbond 3 j -> C1\n";
  INT_EQ(index_of(NULL, rc, -1, NULL, 0, 1), 0);
  /* a class 2 path R2 - j - n - R1 (fixed stroke at R2), values 1e-9 .. 1e6 */
  const char *c2 = "model c2\nparam L0 = 1e-9, R0 = 1e6, R1v = 1e-3\nSe U = 1\n1 j\nR R2 = R0\n0 n\n"
                   "R R1 = R1v\nI L1 = L0\nbond 1 U -> j\nbond 2 j ->| R2\nbond 3 j -> n\n"
                   "bond 4 n -> R1\nbond 5 n -> L1\n";
  efx f;
  OK(efx_load(&f, NULL, c2, -1, NULL, 0) == 0);
  if (f.s) INT_EQ(bg_eqsys_n(f.s) - bg_eqsys_nx(f.s), 2); /* R2.f, R1.e */
  efx_free(&f);
  INT_EQ(index_of(NULL, c2, -1, NULL, 0, 1), 1);
}

static void test_rlc_eigen(void) {
  efx f;
  OK(efx_load(&f, "rlc", NULL, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_index_result r;
  INT_EQ(bg_index_compute(f.s, f.m, &r), 0);
  INT_EQ(r.neig, 2);
  double L = 1e-3, C = 1e-6, R = 10, re = -R / (2 * L), im = sqrt(1 / (L * C) - re * re);
  if (r.neig == 2) {
    DBL_NEAR(r.eig_re[0], re, 1e-9 * fabs(re));
    DBL_NEAR(r.eig_im[0], -im, 1e-9 * im);
    DBL_NEAR(r.eig_re[1], re, 1e-9 * fabs(re));
    DBL_NEAR(r.eig_im[1], im, 1e-9 * im);
  }
  bg_index_free(&r);
  efx_free(&f);
}

int main(void) {
  test_examples();
  test_scaling();
  test_rlc_eigen();
  return bg_t_done();
}
