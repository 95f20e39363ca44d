/* SPDX-License-Identifier: BSD-3-Clause */
/* The reusable C export (src/export/export_c.c): every example's export
 * compiles with -std=c11 -Wall -Wextra -Werror, and for an ODE, a DAE, a model
 * with a table and one with a param defined by another, the shared object
 * computes exactly what bg_eqsys computes (right-hand side, residual, sparse
 * Jacobian, outputs, initial values), also after a param is changed in the
 * record (against a model compiled with --set). */
#include <dlfcn.h>
#include <stdio.h>
#include <unistd.h>
#include "harness.h"
#include "eqs_fixture.h"
#include "export/export.h"

static const char *TABLE_MODEL =
    "model tab\nparam k = 2, g = 3 * k\nSe U = table(t, [0, 0; 1, 1; 2, 0.5])\n1 j\n"
    "R R1 : e = g * f + table(f, [-1, -1; 0, 0; 1, 4])\nC C1 = k [q0 = g / 10]\n"
    "bond U -> j\nbond j -> R1\nbond j -> C1\nsimulate t_end = 2\nplot C1.e, R1.f * g\n";

/* tests/data/switch_kinds.bg: every kind of switching instruction in one law. */
static const char *SWITCH_KINDS =
    "model switch_kinds\nparam k = 2, lo = -0.1, hi = 0.2, w = 0.3\nSe U = sin(3*t) + 0.2*step(sin(7*t))\n1 j\n"
    "R R1 : f = e/k + 0.1*sat(e, -0.5, 0.5) + 0.1*abs(e) + 0.05*sign(e) + 0.1*min(e, 0.1) + 0.1*max(e, -0.2) + "
    "0.1*pulse(e, w) + floor(4*e)/40 + ceil(2*e)/20 + 0.3*hyst(e, lo, hi) + 0.1*table(e, [-1, -1; 0, 0; 1, 4]) + "
    "if(e > 0.05, 0.1, 0)\nC C1 = 1 [q0 = 0.1]\nbond U -> j\nbond j -> R1\nbond j -> C1\nsimulate t_end = 2, dt = 0.01\n"
    "plot C1.e, R1.f\n";

/* Writes the export of f's model (export build) as NAME.c/NAME.h in dir. */
static int export_to(efx *f, const char *dir, const char *prefix) {
  bg_eqsys *s = bg_eqsys_build_export(f->m, &f->a, &f->dg);
  if (!s) return -1;
  bg_strbuf h = {0}, c = {0};
  char hn[64], path[512];
  snprintf(hn, sizeof hn, "%s.h", prefix);
  bg_export_c(s, prefix, hn, &h, &c);
  snprintf(path, sizeof path, "%s/%s.h", dir, prefix);
  FILE *fp = fopen(path, "w");
  if (fp) fputs(bg_sb_str(&h), fp), fclose(fp);
  snprintf(path, sizeof path, "%s/%s.c", dir, prefix);
  fp = fopen(path, "w");
  if (fp) fputs(bg_sb_str(&c), fp), fclose(fp);
  bg_sb_free(&h), bg_sb_free(&c), bg_eqsys_free(s);
  return fp ? 0 : -1;
}

static char dir[256];

static void test_examples_compile(void) {
  const char *ex[] = {"rlc", "bond_loop", "bridge_compliance", "class12_paths", "delta",
                      "hydraulic_bridge", "internal_mod_r", "internal_mod_tf", "loop_class1",
                      "mod_no_loop", "modulated_source", "parallel_conductance", "lagrange_rlc",
                      "series_conductances", "series_motor", "series_motor_L", "slider_crank"};
  char cmd[1024];
  for (size_t i = 0; i < sizeof ex / sizeof *ex; i++) {
    efx f;
    int ok = efx_load(&f, ex[i], NULL, -1, NULL, 0) == 0 && export_to(&f, dir, "m_x") == 0;
    snprintf(cmd, sizeof cmd, "cc -std=c11 -Wall -Wextra -Werror -c %s/m_x.c -o %s/m_x.o", dir, dir);
    BG_T_REPORT(ok && system(cmd) == 0, "exported C of %s compiles cleanly", ex[i]);
    efx_free(&f);
  }
}

typedef struct api {
  void *h;
  int (*rhs)(const void *, double, const double *, double *, double *);
  int (*res)(const void *, double, const double *, const double *, double *, double *);
  int (*jac)(const void *, double, const double *, const double *, double, double *, double *);
  int (*outp)(const void *, double, const double *, const double *, double *, double *);
  void (*init)(const void *, double, double *, double *);
  const void *defaults;
  const int *colptr, *rowind, *isd;
  const char *const *pnames;
  /* a model with state events (docs/export.md): the same under the modes md */
  int (*rhs_m)(const void *, void *, double, const double *, double *, double *);
  int (*res_m)(const void *, void *, double, const double *, const double *, double *, double *);
  int (*jac_m)(const void *, void *, double, const double *, const double *, double, double *, double *);
  int (*outp_m)(const void *, void *, double, const double *, const double *, double *, double *);
  void (*modes_start)(const void *, double, const double *, const double *, double, void *, double *);
  int (*roots)(const void *, const void *, double, const double *, const double *, double *, double *);
  int (*event)(const void *, double, const double *, const double *, const int *, double, void *, double *);
} api;

static int load(api *A, const char *name, const char *prefix) {
  char cmd[1024], so[512], sym[128];
  snprintf(so, sizeof so, "%s/%s.so", dir, name);
  snprintf(cmd, sizeof cmd, "cc -std=c11 -O1 -shared -fPIC %s/%s.c -o %s -lm", dir, prefix, so);
  if (system(cmd)) return -1;
  A->h = dlopen(so, RTLD_NOW | RTLD_LOCAL);
  if (!A->h) return -1;
#define SYM(field, s) snprintf(sym, sizeof sym, "%s_%s", prefix, s), *(void **)&A->field = dlsym(A->h, sym)
  SYM(rhs, "rhs"), SYM(res, "residual"), SYM(jac, "jacobian"), SYM(outp, "outputs"), SYM(init, "initial");
  SYM(defaults, "default_params"), SYM(colptr, "jac_colptr"), SYM(rowind, "jac_rowind");
  SYM(isd, "is_differential"), SYM(pnames, "param_names");
  SYM(modes_start, "modes_start"), SYM(roots, "roots"), SYM(event, "event");
  if (A->modes_start) { /* the functions take the modes */
    A->rhs_m = (void *)A->rhs, A->res_m = (void *)A->res, A->jac_m = (void *)A->jac, A->outp_m = (void *)A->outp;
    A->rhs = NULL, A->res = NULL, A->jac = NULL, A->outp = NULL;
    return A->res_m && A->jac_m && A->outp_m && A->roots && A->event && A->init && A->defaults ? 0 : -1;
  }
#undef SYM
  return A->res && A->jac && A->outp && A->init && A->defaults ? 0 : -1;
}

/* The export at p against the engine's system e (built with the same values). */
/* changed: the record differs from the defaults, so algebraic unknowns start
 * from their consistent values at the defaults (docs/export.md) and only the
 * states' initial values are compared. */
static void compare(const api *A, const void *p, efx *e, const char *what, int changed) {
  bg_eqsys *s = e->s;
  int n = bg_eqsys_n(s), nout = bg_eqsys_noutput(s), nnz = bg_eqsys_jac_nnz(s), ode = bg_eqsys_is_ode(s);
  double *w = calloc(1 << 16, sizeof(double)), y0a[64], y0b[64], res_a[64], res_b[64];
  double ja[512], jb[512], oa[64], ob[64], yp[64];
  int cp[65], ri[512];
  bg_eqsys_jac_pattern(s, cp, ri);
  for (int j = 0; j <= n; j++) BG_T_REPORT(cp[j] == A->colptr[j], "%s: colptr[%d]", what, j);
  for (int k = 0; k < nnz; k++) BG_T_REPORT(ri[k] == A->rowind[k], "%s: rowind[%d]", what, k);
  for (int i = 0; i < n; i++) BG_T_REPORT(A->isd[i] == bg_eqsys_is_differential(s, i), "%s: id[%d]", what, i);
  A->init(p, 0, y0a, w);
  bg_eqsys_initial(s, y0b);
  for (int i = 0; i < n; i++)
    if (!changed || A->isd[i]) DBL_NEAR(y0a[i], y0b[i], 1e-12 * (1 + fabs(y0b[i])));
  unsigned st = 5;
  for (int k = 0; k < 6; k++) {
    double t = efx_rand(&st, 0, 1.5), y[64];
    for (int i = 0; i < n; i++) y[i] = y0b[i] + efx_rand(&st, -0.3, 0.3), yp[i] = efx_rand(&st, -1, 1);
    OK(A->res(p, t, y, yp, res_a, w) == 0 && bg_eqsys_residual(s, t, y, yp, res_b) == 0);
    for (int i = 0; i < n; i++) BG_T_REPORT(res_a[i] == res_b[i], "%s: residual %d: %.17g vs %.17g", what, i, res_a[i], res_b[i]);
    double cj = ode ? 0 : 3.5;
    OK(A->jac(p, t, y, yp, cj, ja, w) == 0 && bg_eqsys_jac_sparse(s, t, y, yp, cj, jb) == 0);
    for (int q = 0; q < nnz; q++) BG_T_REPORT(ja[q] == jb[q], "%s: jacobian %d: %.17g vs %.17g", what, q, ja[q], jb[q]);
    OK(A->outp(p, t, y, yp, oa, w) == 0 && bg_eqsys_outputs(s, t, y, yp, ob) == 0);
    for (int q = 0; q < nout; q++) BG_T_REPORT(oa[q] == ob[q], "%s: output %d: %.17g vs %.17g", what, q, oa[q], ob[q]);
    if (ode && A->rhs) {
      OK(A->rhs(p, t, y, oa, w) == 0 && bg_eqsys_rhs(s, t, y, ob) == 0);
      for (int i = 0; i < n; i++) BG_T_REPORT(oa[i] == ob[i], "%s: rhs %d", what, i);
    }
  }
  free(w);
}

/* A model with state events: the modes set by the export's modes_start and
 * event against the engine's bg_eqsys_modes_update (fresh start, then at
 * random points), and under those modes, at another random point (so the
 * held branches are continued past their switching points), the residual,
 * Jacobian, outputs, right-hand side and root functions bit for bit. */
static void compare_modes(const api *A, const void *p, efx *e, const char *what) {
  bg_eqsys *s = e->s;
  int n = bg_eqsys_n(s), nout = bg_eqsys_noutput(s), nnz = bg_eqsys_jac_nnz(s), ode = bg_eqsys_is_ode(s);
  int nm = bg_eqsys_nmodes(s), nr = bg_eqsys_nroots(s);
  double *w = calloc(1 << 16, sizeof(double)), *md = calloc(4096, sizeof(double));
  double y0[64], mb[256], ra[256], rb[256], ja[512], jb[512], yp[64], y[64], y2[64];
  const double delta = 2e-9;
  BG_T_REPORT(nm > 0 && nm <= 256 && nr <= 256, "%s: %d modes, %d root functions", what, nm, nr);
  bg_eqsys_initial(s, y0);
  A->modes_start(p, 0, y0, NULL, delta, md, w);
  bg_eqsys_modes_reset(s);
  bg_eqsys_modes_update(s, 0, y0, NULL, NULL, delta);
  bg_eqsys_modes_get(s, mb);
  for (int q = 0; q < nm; q++) BG_T_REPORT(md[q] == mb[q], "%s: start mode %d: %g vs %g", what, q, md[q], mb[q]);
  bg_eqsys_modes_freeze(s, 1);
  unsigned st = 7;
  int changes = 0;
  for (int k = 0; k < 40; k++) {
    double t = efx_rand(&st, 0, 1.5), t2 = efx_rand(&st, 0, 1.5), cj = ode ? 0 : 3.5;
    int dir[256];
    for (int i = 0; i < n; i++)
      y[i] = y0[i] + efx_rand(&st, -0.8, 0.8), y2[i] = y0[i] + efx_rand(&st, -0.8, 0.8), yp[i] = efx_rand(&st, -1, 1);
    for (int i = 0; i < nr; i++) dir[i] = k % 3 ? 0 : (int)efx_rand(&st, -1.5, 1.5);
    int ca = A->event(p, t, y, ode ? NULL : yp, k % 2 ? dir : NULL, delta, md, w);
    int cb = bg_eqsys_modes_update(s, t, y, ode ? NULL : yp, k % 2 ? dir : NULL, delta);
    bg_eqsys_modes_get(s, mb);
    changes += cb;
    BG_T_REPORT(ca == cb, "%s: event %d changes %d modes, the engine %d", what, k, ca, cb);
    for (int q = 0; q < nm; q++) BG_T_REPORT(md[q] == mb[q], "%s: event %d, mode %d: %g vs %g", what, k, q, md[q], mb[q]);
    OK(A->res_m(p, md, t2, y2, yp, ra, w) == 0 && bg_eqsys_residual(s, t2, y2, yp, rb) == 0);
    for (int i = 0; i < n; i++) BG_T_REPORT(ra[i] == rb[i], "%s: held residual %d: %.17g vs %.17g", what, i, ra[i], rb[i]);
    OK(A->jac_m(p, md, t2, y2, yp, cj, ja, w) == 0 && bg_eqsys_jac_sparse(s, t2, y2, yp, cj, jb) == 0);
    for (int q = 0; q < nnz; q++) BG_T_REPORT(ja[q] == jb[q], "%s: held jacobian %d: %.17g vs %.17g", what, q, ja[q], jb[q]);
    OK(A->outp_m(p, md, t2, y2, yp, ra, w) == 0 && bg_eqsys_outputs(s, t2, y2, yp, rb) == 0);
    for (int q = 0; q < nout; q++) BG_T_REPORT(ra[q] == rb[q], "%s: held output %d: %.17g vs %.17g", what, q, ra[q], rb[q]);
    if (ode) {
      OK(A->rhs_m(p, md, t2, y2, ra, w) == 0 && bg_eqsys_rhs(s, t2, y2, rb) == 0);
      for (int i = 0; i < n; i++) BG_T_REPORT(ra[i] == rb[i], "%s: held rhs %d", what, i);
    }
    OK(A->roots(p, md, t2, y2, ode ? NULL : yp, ra, w) == 0 && bg_eqsys_roots(s, t2, y2, ode ? NULL : yp, rb) == 0);
    for (int i = 0; i < nr; i++) BG_T_REPORT(ra[i] == rb[i], "%s: root %d: %.17g vs %.17g", what, i, ra[i], rb[i]);
  }
  BG_T_REPORT(changes >= 10, "%s: the random events change modes (%d changes)", what, changes);
  bg_eqsys_modes_freeze(s, 0);
  free(w), free(md);
}

/* One model: the defaults against the engine, then param `set` changed in
 * the record against the engine's --set. */
static void check_model(const char *name, const char *text, const char *set, double value) {
  efx f, g;
  api A = {0};
  OK(efx_load(&f, text ? NULL : name, text, -1, NULL, 0) == 0);
  if (!f.s || export_to(&f, dir, "m_y") || load(&A, name, "m_y")) {
    BG_T_REPORT(0, "export of %s loads", name);
    efx_free(&f);
    return;
  }
  if (A.modes_start) compare_modes(&A, A.defaults, &f, name);
  else compare(&A, A.defaults, &f, name, 0);
  OK(efx_load(&g, text ? NULL : name, text, -1, set, value) == 0);
  double rec[64];
  int k = 0, np = 0;
  for (; A.pnames[np]; np++) {}
  memcpy(rec, A.defaults, (size_t)np * sizeof(double));
  while (k < np && strcmp(A.pnames[k], set)) k++;
  BG_T_REPORT(k < np, "%s: param %s in the record", name, set);
  rec[k] = value;
  if (g.s && A.modes_start) compare_modes(&A, rec, &g, set);
  else if (g.s) compare(&A, rec, &g, set, 1);
  efx_free(&g);
  efx_free(&f);
  dlclose(A.h);
}

int main(void) {
  snprintf(dir, sizeof dir, "/tmp/bg_export_c_%d", (int)getpid());
  char cmd[600];
  snprintf(cmd, sizeof cmd, "mkdir -p %s", dir);
  if (system(cmd)) return 1;
  test_examples_compile();
  check_model("rlc", NULL, "R0", 25);
  check_model("hydraulic_bridge", NULL, "Kv", 3e-8);
  check_model("tab", TABLE_MODEL, "k", 5); /* g = 3 k follows k */
  check_model("switch_kinds", SWITCH_KINDS, "hi", 0.3); /* every kind of switching instruction */
  snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
  if (system(cmd)) return 1;
  return bg_t_done();
}
