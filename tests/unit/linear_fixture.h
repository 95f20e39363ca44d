/* SPDX-License-Identifier: BSD-3-Clause */
/* Shared by the linear analysis tests: one model and its linearisation at a
 * time (inline text, causality and equations by eqs_fixture.h). */
#ifndef BG_LINEAR_FIXTURE_H
#define BG_LINEAR_FIXTURE_H
#include <math.h>

#include "eqs_fixture.h"
#include "linear/linear.h"

static bg_linear L;
static efx F;

/* Loads inline model text and linearises it (steady < 0: the model's choice). */
static inline int lin(const char *text, int steady) {
  if (efx_load(&F, NULL, text, -1, NULL, 0)) return -1;
  return bg_linear_compute(F.m, &F.a, steady, &L);
}

static inline void done(void) {
  bg_linear_free(&L);
  efx_free(&F);
}
/* Coefficients of tf (iy, iu) against the expected ones (highest first). */
static inline void tf_is(int iy, int iu, const double *num, int nnum, const double *den, int nden, double tol) {
  const bg_lin_tf *t = &L.tf[iy * L.nu + iu];
  INT_EQ(t->nnum, nnum);
  INT_EQ(t->nden, nden);
  for (int k = 0; k < nnum && k < t->nnum; k++) DBL_NEAR(t->num[k], num[k], tol * (1 + fabs(num[k])));
  for (int k = 0; k < nden && k < t->nden; k++) DBL_NEAR(t->den[k], den[k], tol * (1 + fabs(den[k])));
}

#endif
