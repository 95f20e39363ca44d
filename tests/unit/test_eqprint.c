/* Printers: text and LaTeX of rlc and bond_loop, JSON shape, the generated
 * C of every example compiles with -std=c11 -Wall -Werror, and rlc's is
 * built into a shared object, loaded and checked against bg_eqsys. */
#include <dlfcn.h>
#include <unistd.h>
#include <stdio.h>
#include "harness.h"
#include "eqs_fixture.h"
#include "equations/eqprint.h"

static void test_text(void) {
  efx f;
  OK(efx_load(&f, "rlc", NULL, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_strbuf sb = {0};
  bg_eqprint_text(f.s, &sb);
  const char *t = bg_sb_str(&sb);
  OK(strstr(t, "# form: ODE x' = f(t, x); x = (L1.p, C1.q)") != NULL);
  OK(strstr(t, "e1 = V*step(t)\n") != NULL);
  OK(strstr(t, "f3 = L1.p/L0\n") != NULL);
  OK(strstr(t, "e2 = R0*f2\n") != NULL);
  OK(strstr(t, "e3 = e1 - e2 - e4\n") != NULL);
  OK(strstr(t, "L1.p' = e3\n") != NULL);
  OK(strstr(t, "C1.q' = f4\n") != NULL);
  bg_sb_clear(&sb);
  bg_eqprint_latex(f.s, &sb);
  OK(strstr(bg_sb_str(&sb), "\\dot{p_{\\mathrm{L1}}} &= e_{3}") != NULL);
  bg_sb_free(&sb);
  efx_free(&f);

  OK(efx_load(&f, "bond_loop", NULL, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_eqprint_text(f.s, &sb);
  t = bg_sb_str(&sb);
  OK(strstr(t, "z = (e4, f3)") != NULL);
  OK(strstr(t, "0 = e4 - n*e3    (solved for e4)") != NULL);
  OK(strstr(t, "0 = f3 - n*f4    (solved for f3)") != NULL);
  bg_sb_clear(&sb);
  OK(bg_eqprint(f.s, "json", &sb) == 0);
  OK(strstr(bg_sb_str(&sb), "{\"name\": \"e4\", \"kind\": \"algebraic\", \"initial\": 0, \"signal\": \"e4\"}") != NULL);
  OK(bg_eqprint(f.s, "xml", &sb) == -1);
  bg_sb_free(&sb);
  efx_free(&f);
}

/* A two-port whose modulus reads only states prints as its name, once, at
 * the top (found through the per-expression lookup, not a scan); a TF with
 * a constant modulus and an MTF modulated by a flow print the expression. */
static void test_modulus_names(void) {
  efx f;
  OK(efx_load(&f, "slider_crank", NULL, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_strbuf sb = {0};
  bg_eqprint_text(f.s, &sb);
  const char *t = bg_sb_str(&sb);
  OK(strstr(t, "\nT = rc*sin(phi)*") != NULL);
  OK(strstr(t, "f3 = T*f4\n") != NULL && strstr(t, "e4 = T*e3\n") != NULL);
  bg_sb_free(&sb);
  efx_free(&f);
  const char *src = "model tf2\nparam n = 2\nSe U = 1\n1 j\nTF A = n\nMTF B = 3 + n*j2.f\n"
                    "1 j2\nR R1 = 1\nR R2 = 1\nbond U -> j\nbond j -> A\nbond A -> j2\n"
                    "bond j2 -> R1\nbond j2 -> B\nbond B -> R2\n";
  OK(efx_load(&f, NULL, src, -1, NULL, 0) == 0);
  if (!f.s) return;
  bg_eqprint_text(f.s, &sb);
  t = bg_sb_str(&sb);
  OK(strstr(t, "\nA = ") == NULL && strstr(t, "\nB = ") == NULL);
  OK(strstr(t, "n*") != NULL);
  bg_sb_free(&sb);
  efx_free(&f);
}

static int compile_c(const char *name, const char *flags, const char *outfile) {
  efx f;
  if (efx_load(&f, name, NULL, -1, NULL, 0)) return -1;
  bg_strbuf sb = {0};
  bg_eqprint_c(f.s, &sb);
  char path[256], cmd[1024];
  snprintf(path, sizeof path, "/tmp/bg_eqprint_%d_%s.c", (int)getpid(), name);
  FILE *fp = fopen(path, "w");
  if (!fp) return -1;
  fputs(bg_sb_str(&sb), fp);
  fclose(fp);
  bg_sb_free(&sb);
  efx_free(&f);
  snprintf(cmd, sizeof cmd, "cc -std=c11 -Wall -Werror %s %s -o %s", flags, path, outfile);
  int rc = system(cmd);
  remove(path);
  return rc;
}

static void test_c_compiles(void) {
  const char *ex[] = {"rlc", "bond_loop", "bridge_compliance", "class12_paths", "delta",
                      "hydraulic_bridge", "internal_mod_r", "internal_mod_tf", "loop_class1",
                      "mod_no_loop", "modulated_source", "parallel_conductance",
                      "series_conductances", "series_motor", "series_motor_L", "slider_crank"};
  char obj[256];
  for (size_t i = 0; i < sizeof ex / sizeof *ex; i++) {
    snprintf(obj, sizeof obj, "/tmp/bg_eqprint_%d.o", (int)getpid());
    int rc = compile_c(ex[i], "-c", obj);
    BG_T_REPORT(rc == 0, "generated C of %s compiles", ex[i]);
    remove(obj);
  }
}

static void test_c_rlc_dlopen(void) {
  char so[256];
  snprintf(so, sizeof so, "/tmp/bg_eqprint_%d_rlc.so", (int)getpid());
  OK(compile_c("rlc", "-O1 -shared -fPIC", so) == 0);
  void *h = dlopen(so, RTLD_NOW);
  OK(h != NULL);
  if (!h) return;
  int (*rhs)(double, const double *, double *);
  void (*jac)(double, const double *, const double *, double, double *);
  *(void **)&rhs = dlsym(h, "bg_model_rhs");
  *(void **)&jac = dlsym(h, "bg_model_jacobian");
  OK(rhs && jac);
  efx f;
  OK(efx_load(&f, "rlc", NULL, -1, NULL, 0) == 0);
  unsigned st = 17;
  for (int k = 0; rhs && jac && f.s && k < 5; k++) {
    double t = efx_rand(&st, -1e-3, 1e-3), y[2] = {efx_rand(&st, -1e-3, 1e-3), efx_rand(&st, -1e-6, 1e-6)};
    double a[2], b[2], Ja[4], Jb[4];
    OK(rhs(t, y, a) == 0);
    OK(bg_eqsys_rhs(f.s, t, y, b) == 0);
    DBL_NEAR(a[0], b[0], 0);
    DBL_NEAR(a[1], b[1], 0);
    jac(t, y, y, 0, Ja);
    OK(bg_eqsys_jac_dense(f.s, t, y, y, 0, Jb) == 0);
    for (int q = 0; q < 4; q++) DBL_NEAR(Ja[q], Jb[q], 0);
  }
  efx_free(&f);
  dlclose(h);
  remove(so);
}

int main(void) {
  test_text();
  test_modulus_names();
  test_c_compiles();
  test_c_rlc_dlopen();
  return bg_t_done();
}
