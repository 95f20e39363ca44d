/* Shared by test_eqsys.c, test_index.c, test_eqprint.c: loads an example
 * (or inline source), runs causality and analysis, builds the equations. */
#ifndef BG_EQS_FIXTURE_H
#define BG_EQS_FIXTURE_H
#include <lapacke.h>
#include <stdlib.h>
#include <string.h>
#include "causality/causality.h"
#include "equations/equations.h"
#include "lang/lang.h"
#include "analysis/analysis.h"

typedef struct efx {
  bg_model *m;
  bg_analysis a;
  bg_diags dg;
  char *src;
  bg_eqsys *s;
  int analysed;
} efx;

/* name: example stem, or NULL with inline text; method -1: the model's own. */
static inline int efx_load(efx *f, const char *name, const char *text, int method, const char *set_name,
                    double set_value) {
  char path[512];
  size_t len = 0;
  memset(f, 0, sizeof *f);
  if (name) {
    snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
    f->src = bg_read_file(path, &len);
  } else {
    if (!text) return -1; /* neither an example nor inline text */
    snprintf(path, sizeof path, "inline.bg");
    len = strlen(text);
    f->src = malloc(len + 1);
    memcpy(f->src, text, len + 1);
  }
  bg_diags_init(&f->dg, path, f->src, len);
  if (!f->src) return -1;
  bg_ast *ast = bg_parse_string(path, f->src, len, &f->dg);
  if (!ast) return -1;
  bg_param_override ov = {set_name, set_value};
  f->m = bg_model_compile(ast, &ov, set_name ? 1 : 0, &f->dg);
  bg_ast_free(ast);
  if (!f->m) return -1;
  bg_analysis_init(&f->a, f->m);
  f->analysed = 1;
  bg_causality_assign(f->m, method < 0 ? f->m->method : method, &f->a, &f->dg);
  bg_analysis_run(f->m, &f->a, NULL);
  f->s = bg_eqsys_build(f->m, &f->a, &f->dg);
  if (!f->s) bg_diags_print(&f->dg, stderr);
  return f->s ? 0 : -1;
}

static inline void efx_free(efx *f) {
  bg_eqsys_free(f->s);
  if (f->analysed) bg_analysis_free(&f->a);
  if (f->m) bg_model_free(f->m);
  bg_diags_free(&f->dg);
  free(f->src);
}

/* Index of unknown `name`, or -1. */
static inline int efx_u(const efx *f, const char *name) {
  for (int i = 0; i < bg_eqsys_n(f->s); i++)
    if (!strcmp(bg_eqsys_name(f->s, i), name)) return i;
  return -1;
}

/* Deterministic pseudo-random numbers in [lo, hi). */
static inline double efx_rand(unsigned *st, double lo, double hi) {
  *st = *st * 1103515245u + 12345u;
  return lo + (hi - lo) * ((*st >> 8) & 0xffffff) / 16777216.0;
}

/* Solves the residuals of the algebraic unknowns (rows nx..n) for them, with
 * the differential unknowns and yp held (Newton, exact Jacobian). */
static inline int efx_solve_alg(efx *f, double t, double *y, const double *yp) {
  bg_eqsys *s = f->s;
  int n = bg_eqsys_n(s), nx = bg_eqsys_nx(s), nz = n - nx, rc = 0;
  if (!nz) return 0;
  double *r = malloc(n * sizeof *r), *A = malloc((size_t)n * n * sizeof *A),
         *B = malloc((size_t)n * n * sizeof *B), *M = malloc((size_t)nz * nz * sizeof *M);
  int *piv = malloc(nz * sizeof *piv);
  for (int it = 0; it < 30 && !rc; it++) {
    if (bg_eqsys_residual(s, t, y, yp, r) || bg_eqsys_linearise(s, t, y, yp, A, B)) { rc = -1; break; }
    double mx = 0;
    for (int i = 0; i < nz; i++) {
      mx = fmax(mx, fabs(r[nx + i]));
      for (int j = 0; j < nz; j++) M[(size_t)j * nz + i] = B[(size_t)(nx + j) * n + nx + i];
      r[i] = -r[nx + i];
    }
    if (mx == 0) break;
    if (LAPACKE_dgesv(LAPACK_COL_MAJOR, nz, 1, M, nz, piv, r, nz)) { rc = -1; break; }
    for (int i = 0; i < nz; i++) y[nx + i] += r[i];
  }
  free(r), free(A), free(B), free(M), free(piv);
  return rc;
}
#endif
