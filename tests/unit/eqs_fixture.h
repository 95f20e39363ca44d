/* SPDX-License-Identifier: BSD-3-Clause */
/* Shared by test_eqsys.c, test_index.c, test_eqprint.c: loads an example
 * (or inline source), runs causality and analysis, builds the equations. */
#ifndef BG_EQS_FIXTURE_H
#define BG_EQS_FIXTURE_H
#include "base/lapack.h"
#include <stdlib.h>
#include <string.h>
#include "causality/causality.h"
#include "equations/equations.h"
#include "lang/lang.h"
#include "analysis/analysis.h"
#include "run_fixture.h"

typedef struct efx {
  bg_run *run;    /* owns the model, its analysis and its equations */
  bg_model *m;
  bg_analysis a;  /* the run's analysis (a view: freed with the run) */
  bg_diags dg;    /* the test's own diagnostics over the source */
  char *src;      /* a copy of the source */
  bg_eqsys *s;
} efx;

/* name: example stem, or NULL with inline text; method -1: the model's own. */
static inline int efx_load(efx *f, const char *name, const char *text, int method, const char *set_name,
                    double set_value) {
  memset(f, 0, sizeof *f);
  bg_t_model mm = {name, text, NULL, NULL, NULL, method, set_name, set_value};
  f->run = bg_t_run(&mm, BG_STAGE_EQUATIONS);
  if (!f->run) return -1;
  if (bg_t_view(f->run, &f->src, &f->dg, &f->m, &f->a)) return -1;
  f->s = f->run->eqsys;
  if (!f->s) fprintf(stderr, "%s: %s\n", f->run->name, f->run->eqsys_problem);
  return f->s ? 0 : -1;
}

static inline void efx_free(efx *f) {
  bg_run_free(f->run);
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
