/* Numeric index (Algorithm 4.1) of every example, badly scaled circuits,
 * and the eigenvalues of rlc against the roots of L C s^2 + R C s + 1. */
#include "harness.h"
#include "eqs_fixture.h"
#include "equations/index.h"

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

/* The other examples (docs/examples.md): ODE forms 0, DAEs from internal
 * modulation or relaxed conflicts 1 (their predicted index). */
static void test_other_examples(void) {
  INT_EQ(index_of("internal_mod_tf", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("internal_mod_r", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("mod_no_loop", NULL, -1, NULL, 0, 1), 0);
  INT_EQ(index_of("series_motor", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("series_motor_L", NULL, -1, NULL, 0, 1), 0);
  /* relaxed causality: the consistent initial values must be found (a cubic
   * conductance has zero slope at e = 0, where the linearisation would be
   * index 2 or singular) */
  INT_EQ(index_of("series_conductances", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("parallel_conductance", NULL, -1, NULL, 0, 1), 1);
  INT_EQ(index_of("hydraulic_bridge", NULL, BG_METHOD_RELAXED, NULL, 0, 1), 1);
  INT_EQ(index_of("slider_crank", NULL, BG_METHOD_VANDIJK, NULL, 0, 1), 1);
}

/* An example's source with its first `param` line replaced. */
static char *with_params(const char *name, const char *params) {
  char path[512];
  size_t len = 0;
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  char *src = bg_read_file(path, &len);
  if (!src) return NULL;
  char *p = strstr(src, "\nparam ");
  char *out = malloc(len + strlen(params) + 2);
  if (!p) { free(out); return src; }
  char *eol = strchr(p + 1, '\n');
  size_t head = (size_t)(p + 1 - src);
  memcpy(out, src, head);
  strcpy(out + head, params);
  strcat(out, eol ? eol : "\n");
  free(src);
  return out;
}

static int index_scaled(const char *name, const char *params, int method) {
  char *text = with_params(name, params);
  int k = text ? index_of(NULL, text, method, NULL, 0, 1) : -100;
  free(text);
  return k;
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
  /* the reference's DAE examples with C = 1e-9, R = 1e6 (and inductances
   * and moduli far from 1): the index must not change */
  INT_EQ(index_scaled("class12_paths", "param n = 2, C10 = 1e-9, C20 = 0.5e-9, R10 = 1e6, R20 = 2e6, F0 = 1e-3", -1), 1);
  INT_EQ(index_scaled("bond_loop", "param n = 2, C0 = 1e-9, I0 = 1e6, F0 = 1e-3", -1), 1);
  INT_EQ(index_scaled("bond_loop", "param n = 1, C0 = 1e-9, I0 = 1e6, F0 = 1e-3", -1), 2);
  INT_EQ(index_scaled("loop_class1", "param n1 = 2, n2 = 3, C10 = 1e-9, C20 = 1e-9, I0 = 1e-3, F0 = 1e-3", -1), 2);
  INT_EQ(index_scaled("delta", "param I0 = 1e-3, R10 = 1e6, R20 = 2e6, R30 = 1e6, L10 = 1e-9, L20 = 1e-9", -1), 2);
  INT_EQ(index_scaled("delta", "param I0 = 1e-3, R10 = 1e6, R20 = 2e6, R30 = 1e6, L10 = 1e-9, L20 = 1e-9",
                      BG_METHOD_VANDIJK), 1);
  INT_EQ(index_scaled("modulated_source", "param E0 = 1e-3, R10 = 1e6, R20 = 2e6, k = 1e6, C0 = 1e-9", -1), 1);
  INT_EQ(index_scaled("modulated_source", "param E0 = 1e-3, R10 = 1e6, R20 = 2e6, k = 2e6, C0 = 1e-9", -1), 2);
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
  test_other_examples();
  test_scaling();
  test_rlc_eigen();
  return bg_t_done();
}
