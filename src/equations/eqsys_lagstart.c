/* SPDX-License-Identifier: BSD-3-Clause */
/* Consistent initial values under Lagrange causality. The model's initial
 * state is what its stores hold (q0, p0), dependent stores included: under
 * Lagrange causality a store in derivative causality is fed by the
 * generalised velocities, and its initial value is what fixes them
 * (parallel_conductance: Lk.p0 = 0 means the inserted junction's flow starts
 * at the source current). So every differential unknown is held and Newton
 * solves all n rows for the algebraic unknowns and the derivatives, the
 * square system IDA's IDACalcIC solves, but with the exact Jacobian and
 * deterministic restarts when the start is a singular point (a cubic law at
 * e = 0). The general Newton of eqsys_eval.c, which moves dependent stores
 * onto their constraints with yp = 0, would instead start such a model at a
 * steady state. */
#include "base/lapack.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsys_int.h"

typedef struct lagnewton {
  bg_eqsys *s;
  int n, nx;
  double *y, *yp, *r, *A, *B, *M, *du;
  int *piv;
} lagnewton;

static double max_abs(const double *v, int n) {
  double mx = 0;
  for (int i = 0; i < n; i++) mx = fmax(mx, fabs(v[i]));
  return mx;
}

/* Unknown k: k < nz the algebraic unknown nx + k, else the derivative of
 * differential unknown k - nz. */
static double *unknown(lagnewton *L, int k) {
  int nz = L->n - L->nx;
  return k < nz ? &L->y[L->nx + k] : &L->yp[k - nz];
}

/* One Newton step with step halving; 1 when converged, 0 to go on, -1 stuck. */
static int newton_step(lagnewton *L, double t) {
  int n = L->n, nz = n - L->nx;
  bg_eqsys *s = L->s;
  double r0 = max_abs(L->r, n);
  if (r0 == 0) return 1;
  bg_eqs_jac(s, 0, 1, L->A, 0, 0, 1); /* dF/dyp */
  bg_eqs_jac(s, 0, 1, L->B, 0, 1, 0); /* dF/dy */
  for (int k = 0; k < n; k++) {
    const double *col = k < nz ? L->B + (size_t)(L->nx + k) * n : L->A + (size_t)(k - nz) * n;
    memcpy(L->M + (size_t)k * n, col, (size_t)n * sizeof(double));
    L->du[k] = -L->r[k];
  }
  if (LAPACKE_dgesv(LAPACK_COL_MAJOR, n, 1, L->M, n, L->piv, L->du, n) != 0) return -1;
  double step = 0, umax = 0, lam = 1;
  for (int k = 0; k < n; k++) step = fmax(step, fabs(L->du[k])), umax = fmax(umax, fabs(*unknown(L, k)));
  for (int h = 0; h < 12; h++, lam /= 2) {
    for (int k = 0; k < n; k++) *unknown(L, k) += lam * L->du[k];
    if (!bg_eqsys_residual(s, t, L->y, L->yp, L->r) && max_abs(L->r, n) < r0 * (1 + 1e-12)) break;
    for (int k = 0; k < n; k++) *unknown(L, k) -= lam * L->du[k];
    if (h == 11) return -1;
  }
  return step <= 1e-12 * (1 + umax) ? 1 : 0;
}

/* Newton from the current guess; 0 when it converged. */
static int solve(lagnewton *L, double t, int maxit) {
  if (bg_eqsys_residual(L->s, t, L->y, L->yp, L->r)) return -1;
  for (int it = 0; it < maxit; it++) {
    int rc = newton_step(L, t);
    if (rc) return rc > 0 ? 0 : -1;
  }
  return -1;
}

/* Newton's rounding leaves a component whose solution is 0 (a store that a
 * constraint fixes at 0) at values like 1e-27 or 1e-49 rather than 0,
 * different for each order of the equations; a cubic law's slope there is
 * 1e-53 or 1e-98, which the scaling of the index check at the initial point
 * took for a real entry: one order of a model reduced its index and the
 * other failed (docs/property.md, findings 2c and 20); a switching law read
 * a flow of 1e-32 instead of 0 and chattered in one order (finding 26).
 * Newton stops when its step is below 1e-12 of the largest unknown, so a
 * component below that is not known to differ from 0. The components below
 * a level are set to 0 together when the residual stays as small (within
 * the rows' rounding), the levels from Newton's own tolerance down (1e-12,
 * 1e-18, 1e-24, 1e-30 of the largest): the first that holds decides. A
 * level is a set of components, the same in every order of the equations;
 * one component that the residual needs (a rate of 1e-13 that is real)
 * keeps the level's others too, and the next level down is tried. A
 * caller whose Newton resolves more than 1e-12 starts lower (first). */
static double rows_max(const double *r, const int *rows, int nrows) {
  double mx = 0;
  for (int i = 0; i < nrows; i++) mx = fmax(mx, fabs(r[rows ? rows[i] : i]));
  return mx;
}

void bg_eqs_snap_zeros(bg_eqsys *s, double t, double *y, double *yp, double *r, double *const *u, int nu,
                       const int *rows, int nrows, double first, double unit) {
  static const double level[] = {1e-12, 1e-18, 1e-24, 1e-30};
  double umax = 0;
  if (bg_eqsys_residual(s, t, y, yp, r)) return;
  double r0 = rows_max(r, rows, nrows);
  for (int k = 0; k < nu; k++) umax = fmax(umax, fabs(*u[k]));
  double *keep = bg_xmalloc((size_t)(nu ? nu : 1) * sizeof(double)), tol = fmax(r0, 1e-15 * (1 + umax));
  for (int k = 0; k < nu; k++) keep[k] = *u[k];
  for (size_t q = 0; q < sizeof level / sizeof *level; q++) {
    if (level[q] > first) continue;
    int nsnap = 0;
    for (int k = 0; k < nu; k++) {
      *u[k] = keep[k];
      if (*u[k] != 0 && fabs(*u[k]) <= level[q] * (unit + umax)) *u[k] = 0, nsnap++;
    }
    if (!nsnap) break;
    if (!bg_eqsys_residual(s, t, y, yp, r) && rows_max(r, rows, nrows) <= tol) {
      free(keep);
      return;
    }
  }
  for (int k = 0; k < nu; k++) *u[k] = keep[k];
  bg_eqsys_residual(s, t, y, yp, r);
  free(keep);
}

static void snap_zeros(lagnewton *L, double t) {
  double **u = bg_xmalloc((size_t)L->n * sizeof(double *));
  for (int k = 0; k < L->n; k++) u[k] = unknown(L, k);
  bg_eqs_snap_zeros(L->s, t, L->y, L->yp, L->r, u, L->n, NULL, L->n, 1e-12, 1.0);
  free(u);
}

int bg_eqs_lagrange_start(bg_eqsys *s, double t, double *y, double *yp, int maxit) {
  int n = s->n;
  if (n == 0 || n > 3000) return -1;
  size_t nn = (size_t)n * n;
  lagnewton L = {s, n, s->nx, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
  L.y = bg_xmalloc((size_t)n * sizeof(double)), L.yp = bg_xmalloc((size_t)n * sizeof(double));
  L.r = bg_xmalloc((size_t)n * sizeof(double)), L.du = bg_xmalloc((size_t)n * sizeof(double));
  L.A = bg_xmalloc(nn * sizeof(double)), L.B = bg_xmalloc(nn * sizeof(double));
  L.M = bg_xmalloc(nn * sizeof(double)), L.piv = bg_xmalloc((size_t)n * sizeof(int));
  int rc = -1;
  /* from the given guess, then from guesses of +1 and -1 (spread by up to
   * 10 %, so a symmetric start cannot make the matrix singular) */
  for (int g = 0; g < 3 && rc; g++) {
    memcpy(L.y, y, (size_t)n * sizeof(double));
    memcpy(L.yp, yp, (size_t)n * sizeof(double));
    for (int k = 0; g > 0 && k < n; k++) *unknown(&L, k) = (g == 1 ? 1.0 : -1.0) * (1.0 + 0.1 * k / n);
    rc = solve(&L, t, maxit);
  }
  if (!rc) {
    snap_zeros(&L, t);
    memcpy(y, L.y, (size_t)n * sizeof(double));
    memcpy(yp, L.yp, (size_t)n * sizeof(double));
  }
  free(L.y), free(L.yp), free(L.r), free(L.du), free(L.A), free(L.B), free(L.M), free(L.piv);
  return rc;
}
