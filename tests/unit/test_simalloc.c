/* SPDX-License-Identifier: BSD-3-Clause */
/* Issue 5, speed: "RHS evaluation allocates nothing". The engine is linked
 * with -Wl,--wrap=malloc,--wrap=calloc,--wrap=realloc (tests/tests.cmake),
 * so every allocation it makes passes through the counters below; the
 * right-hand side, residual, Jacobians (dense and sparse) and outputs are
 * evaluated many times and must not allocate, not even on the first call
 * after the equations are built. */
#include "harness.h"

#include <stdlib.h>

#include "causality/causality.h"
#include "equations/equations.h"
#include "base/fileio.h"
#include "lang/lang.h"
#include "analysis/analysis.h"

static long nalloc;
static int counting;

void *__real_malloc(size_t n);
void *__real_calloc(size_t n, size_t k);
void *__real_realloc(void *p, size_t n);
void *__wrap_malloc(size_t n) {
  nalloc += counting;
  return __real_malloc(n);
}
void *__wrap_calloc(size_t n, size_t k) {
  nalloc += counting;
  return __real_calloc(n, k);
}
void *__wrap_realloc(void *p, size_t n) {
  nalloc += counting;
  return __real_realloc(p, n);
}

/* Builds the example's equations and evaluates everything 200 times. */
static void check(const char *name, int method) {
  char path[512];
  size_t len;
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  char *src = bg_read_file(path, &len);
  if (!src) { OK(0); return; }
  bg_diags dg;
  bg_diags_init(&dg, path, src, len);
  bg_ast *ast = bg_parse_string(path, src, len, &dg);
  bg_model *m = ast ? bg_model_compile(ast, NULL, 0, &dg) : NULL;
  if (ast) bg_ast_free(ast);
  bg_analysis a;
  bg_eqsys *s = NULL;
  if (m) {
    bg_analysis_init(&a, m);
    bg_causality_assign(m, method, &a, &dg);
    bg_analysis_run(m, &a, NULL);
    s = bg_eqsys_build(m, &a, &dg);
  }
  OK(s != NULL);
  if (s) {
    int n = bg_eqsys_n(s), nnz = bg_eqsys_jac_nnz(s), nout = bg_eqsys_noutput(s), ode = bg_eqsys_is_ode(s);
    double *y = calloc((size_t)n, sizeof(double)), *yp = calloc((size_t)n, sizeof(double));
    double *r = calloc((size_t)n, sizeof(double)), *J = calloc((size_t)n * n, sizeof(double));
    double *v = calloc((size_t)nnz + 1, sizeof(double)), *out = calloc((size_t)nout + 1, sizeof(double));
    bg_eqsys_initial(s, y);
    long before = nalloc;
    int fails = 0;
    counting = 1;
    for (int it = 0; it < 200; it++) {
      double t = 1e-3 * it;
      if (ode) fails += bg_eqsys_rhs(s, t, y, yp) != 0;
      fails += bg_eqsys_residual(s, t, y, yp, r) != 0;
      fails += bg_eqsys_jac_dense(s, t, y, ode ? NULL : yp, ode ? 0.0 : 1.0, J) != 0;
      fails += bg_eqsys_jac_sparse(s, t, y, ode ? NULL : yp, ode ? 0.0 : 1.0, v) != 0;
      fails += bg_eqsys_outputs(s, t, y, yp, out) != 0;
    }
    counting = 0;
    INT_EQ(fails, 0);
    if (nalloc != before) fprintf(stderr, "%s: %ld allocations in 200 evaluations\n", name, nalloc - before);
    INT_EQ(nalloc - before, 0);
    free(y), free(yp), free(r), free(J), free(v), free(out);
    bg_eqsys_free(s);
  }
  if (m) {
    bg_analysis_free(&a);
    bg_model_free(m);
  }
  bg_diags_free(&dg);
  free(src);
}

int main(void) {
  /* the counters see the engine's allocations at all */
  counting = 1;
  void *p = bg_xmalloc(16);
  counting = 0;
  free(p);
  OK(nalloc == 1);
  check("rlc", BG_METHOD_SCAP);              /* ODE */
  check("hydraulic_bridge", BG_METHOD_SCAP); /* DAE, nonlinear laws, an input */
  check("slider_crank", BG_METHOD_SCAP);     /* dependent store, modulated TF */
  check("bond_loop", BG_METHOD_SCAP);        /* causal loop */
  check("delta", BG_METHOD_VANDIJK);
  check("modulated_source", BG_METHOD_SCAP); /* internal modulation */
  return bg_t_done();
}
