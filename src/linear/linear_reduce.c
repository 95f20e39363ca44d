/* SPDX-License-Identifier: BSD-3-Clause */
/* From the descriptor form to a state space A, B, C, D: an ODE's E is the
 * identity (taken as it is, so junction coefficients stay exact); a
 * semi-explicit index-1 DAE (the derivatives' columns of E have full rank)
 * is row-compressed by a QR factorisation of those columns, and the
 * remaining rows, 0 = A2 x + A2z z + B2 u, are solved for the algebraic
 * unknowns z. Dependent stores (E rank deficient on the differential
 * unknowns) and outputs reading an algebraic unknown's rate go to
 * linear_dep.c, which eliminates the states the constraints fix, or keeps
 * the descriptor form when that needs an input's derivative. */
#include <float.h>
#include "base/lapack.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

/* Sub-matrix of rows [r0, r0+nr) and the listed columns of a column-major M (ld rows). */
static double *pick(const double *M, int ld, int r0, int nr, const int *cols, int nc) {
  double *S = bg_xcalloc((size_t)nr * nc + 1, sizeof *S);
  for (int j = 0; j < nc; j++)
    for (int i = 0; i < nr; i++) S[(size_t)j * nr + i] = M[(size_t)cols[j] * ld + r0 + i];
  return S;
}

static int is_identity(const double *E, int N) {
  for (int j = 0; j < N; j++)
    for (int i = 0; i < N; i++)
      if (E[(size_t)j * N + i] != (i == j)) return 0;
  return 1;
}

static void reduce_ode(bg_linear *l) {
  int N = l->N;
  l->n = N;
  l->state = bg_xcalloc((size_t)N + 1, sizeof *l->state);
  for (int i = 0; i < N; i++) l->state[i] = i;
  l->A = bg_xcalloc((size_t)N * N + 1, sizeof *l->A);
  l->B = bg_xcalloc((size_t)N * l->nu + 1, sizeof *l->B);
  memcpy(l->A, l->Ad, (size_t)N * N * sizeof *l->A);
  memcpy(l->B, l->Bd, (size_t)N * l->nu * sizeof *l->B);
  bg_lin_outputs_through(l, l->Cd, l->Cpd, l->Dd);
  l->reduced = 1;
}

/* Columns of E with a nonzero (xs) and without (zs); returns their counts. */
static int split_columns(const bg_linear *l, int *xs, int *zs, int *nz) {
  int N = l->N, d = 0;
  *nz = 0;
  for (int j = 0; j < N; j++) {
    int any = 0;
    for (int i = 0; i < N && !any; i++) any = l->E[(size_t)j * N + i] != 0;
    if (any) xs[d++] = j;
    else zs[(*nz)++] = j;
  }
  return d;
}

/* Q^T [A B] with Q from the QR of E's derivative columns; R in ER (d x d). */
static int compress(bg_linear *l, const int *xs, int d, double *QA, double *QB, double *R) {
  int N = l->N, nu = l->nu;
  double *Ex = pick(l->E, N, 0, N, xs, d), *tau = bg_xcalloc((size_t)d + 1, sizeof *tau);
  LAPACKE_dgeqrf(LAPACK_COL_MAJOR, N, d, Ex, N, tau);
  double rmax = 0;
  for (int i = 0; i < d; i++) rmax = fmax(rmax, fabs(Ex[(size_t)i * N + i]));
  int full = rmax > 0;
  for (int i = 0; i < d && full; i++) full = fabs(Ex[(size_t)i * N + i]) > 1e3 * N * DBL_EPSILON * rmax;
  if (full) {
    memcpy(QA, l->Ad, (size_t)N * N * sizeof *QA);
    memcpy(QB, l->Bd, (size_t)N * nu * sizeof *QB);
    LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', N, N, d, Ex, N, tau, QA, N);
    if (nu) LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', N, nu, d, Ex, N, tau, QB, N);
    for (int j = 0; j < d; j++)
      for (int i = 0; i < d; i++) R[(size_t)j * d + i] = i <= j ? Ex[(size_t)j * N + i] : 0;
  }
  free(Ex), free(tau);
  return full;
}

/* z = -K [x; u] from the last nz compressed rows; K is nz x (d + nu). */
static int solve_algebraic(const bg_linear *l, const double *QA, const double *QB, const int *xs,
                           int d, const int *zs, int nz, double *K) {
  int N = l->N, nu = l->nu;
  double *A2z = pick(QA, N, d, nz, zs, nz), *A2x = pick(QA, N, d, nz, xs, d);
  for (int j = 0; j < d; j++) memcpy(K + (size_t)j * nz, A2x + (size_t)j * nz, (size_t)nz * sizeof *K);
  for (int j = 0; j < nu; j++)
    for (int i = 0; i < nz; i++) K[(size_t)(d + j) * nz + i] = QB[(size_t)j * N + d + i];
  lapack_int *piv = bg_xcalloc((size_t)nz + 1, sizeof *piv);
  double anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, '1', nz, nz, A2z, nz), rcond = 0;
  int info = LAPACKE_dgetrf(LAPACK_COL_MAJOR, nz, nz, A2z, nz, piv);
  if (info == 0) LAPACKE_dgecon(LAPACK_COL_MAJOR, '1', nz, A2z, nz, anorm, &rcond);
  int ok = info == 0 && rcond > 1e3 * nz * DBL_EPSILON;
  if (ok) LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', nz, d + nu, A2z, nz, piv, K, nz);
  free(A2z), free(A2x), free(piv);
  return ok;
}

/* x' = R^-1 (A1x - A1z K_x) x + R^-1 (B1 - A1z K_u) u; outputs likewise. */
static void assemble(bg_linear *l, const double *QA, const double *QB, const double *R,
                     const int *xs, int d, const int *zs, int nz, const double *K) {
  int N = l->N, nu = l->nu, ny = l->ny;
  double *A1z = pick(QA, N, 0, d, zs, nz), *T = bg_xcalloc((size_t)d * (d + nu) + 1, sizeof *T);
  bg_lin_matmul(d, nz, d + nu, A1z, K, T);
  l->n = d;
  l->state = bg_xcalloc((size_t)d + 1, sizeof *l->state);
  memcpy(l->state, xs, (size_t)d * sizeof *xs);
  l->A = bg_xcalloc((size_t)d * d + 1, sizeof *l->A);
  l->B = bg_xcalloc((size_t)d * nu + 1, sizeof *l->B);
  for (int j = 0; j < d; j++)
    for (int i = 0; i < d; i++) l->A[(size_t)j * d + i] = QA[(size_t)xs[j] * N + i] - T[(size_t)j * d + i];
  for (int j = 0; j < nu; j++)
    for (int i = 0; i < d; i++) l->B[(size_t)j * d + i] = QB[(size_t)j * N + i] - T[(size_t)(d + j) * d + i];
  LAPACKE_dtrtrs(LAPACK_COL_MAJOR, 'U', 'N', 'N', d, d, R, d, l->A, d);
  if (nu) LAPACKE_dtrtrs(LAPACK_COL_MAJOR, 'U', 'N', 'N', d, nu, R, d, l->B, d);
  /* outputs: y = Cx x + Cz z + Cp x' + D u with z = -K [x; u] */
  double *Cz = pick(l->Cd, ny, 0, ny, zs, nz), *Cx = pick(l->Cd, ny, 0, ny, xs, d);
  double *Cp = pick(l->Cpd, ny, 0, ny, xs, d), *CK = bg_xcalloc((size_t)ny * (d + nu) + 1, sizeof *CK);
  double *Dd = bg_xcalloc((size_t)ny * nu + 1, sizeof *Dd);
  bg_lin_matmul(ny, nz, d + nu, Cz, K, CK);
  for (size_t k = 0; k < (size_t)ny * d; k++) Cx[k] -= CK[k];
  for (size_t k = 0; k < (size_t)ny * nu; k++) Dd[k] = l->Dd[k] - CK[(size_t)ny * d + k];
  bg_lin_outputs_through(l, Cx, Cp, Dd);
  l->reduced = 1;
  free(A1z), free(T), free(Cz), free(Cx), free(Cp), free(CK), free(Dd);
}

static int reads_dz(const bg_linear *l, const int *zs, int nz) {
  for (int j = 0; j < nz; j++)
    for (int i = 0; i < l->ny; i++)
      if (l->Cpd[(size_t)zs[j] * l->ny + i] != 0) return 1;
  return 0;
}

void bg_lin_reduce(bg_linear *l, const int *order) {
  int N = l->N, nz = 0;
  if (is_identity(l->E, N)) {
    reduce_ode(l);
    return;
  }
  int *xs = bg_xcalloc((size_t)N + 1, sizeof *xs), *zs = bg_xcalloc((size_t)N + 1, sizeof *zs);
  int d = split_columns(l, xs, zs, &nz);
  double *QA = bg_xcalloc((size_t)N * N + 1, sizeof *QA), *QB = bg_xcalloc((size_t)N * l->nu + 1, sizeof *QB);
  double *R = bg_xcalloc((size_t)d * d + 1, sizeof *R), *K = bg_xcalloc((size_t)nz * (d + l->nu) + 1, sizeof *K);
  /* the semi-explicit form when it applies (exact junction coefficients);
   * else dependent stores, or an output reading an algebraic rate:
   * linear_dep.c eliminates what the constraints fix, or says why not */
  if (compress(l, xs, d, QA, QB, R) && solve_algebraic(l, QA, QB, xs, d, zs, nz, K) && !reads_dz(l, zs, nz))
    assemble(l, QA, QB, R, xs, d, zs, nz, K);
  else bg_lin_reduce_dependent(l, order);
  free(xs), free(zs), free(QA), free(QB), free(R), free(K);
}
