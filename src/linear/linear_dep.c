/* SPDX-License-Identifier: BSD-3-Clause */
/* The state space of a descriptor system with dependent stores
 * (docs/linear.md#matrices): E is rank deficient on the differential
 * unknowns, so some stores' states are fixed by constraints (derivative
 * causality, or an output reading the rate of an algebraic unknown).
 *  1. A QR factorisation of E with column pivoting compresses its rows:
 *     Q^T E = [E1; 0] (rank r), Q^T A = [A1; A2], Q^T B = [B1; B2].
 *  2. The N - r constraints 0 = A2 x + B2 u are solved for N - r unknowns
 *     picked greedily in the order of preference (algebraic unknowns, stores
 *     in derivative causality, then the others from the last): x_d = K x_i +
 *     L u, so x = P x_i + Q u.
 *  3. E1 P x_i' + E1 Q u' = A1 P x_i + (A1 Q + B1) u. E1 Q != 0 needs the
 *     derivative of an input in the state equations, Cp Q != 0 in an output
 *     (an improper transfer function): refused with the input named, the
 *     descriptor form stays. Else x_i' = (E1 P)^-1 (A1 P x_i + (A1 Q + B1) u)
 *     and y = (C P + Cp P A) x_i + (D + C Q + Cp P B) u. */
#include <float.h>
#include "base/lapack.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

typedef struct dep {
  bg_linear *l;
  int N, nu, ny, r, nc;   /* unknowns, inputs, outputs, rank of E, constraints */
  double *QE, *QA, *QB;   /* Q^T E, Q^T A, Q^T B (N rows) */
  int *elim, *keep;       /* eliminated unknowns (nc), kept ones (r), ascending */
  double *P, *Qu;         /* x = P x_i + Qu u: N x r, N x nu */
} dep;

static double max_abs(const double *v, size_t n) {
  double m = 0;
  for (size_t k = 0; k < n; k++) m = fmax(m, fabs(v[k]));
  return m;
}

/* Step 1; returns the rank of E. */
static int compress_rows(dep *D) {
  bg_linear *l = D->l;
  int N = D->N;
  size_t NN = (size_t)N * N;
  double *R = bg_xmalloc(NN * sizeof *R + 1), *tau = bg_xcalloc((size_t)N + 1, sizeof *tau);
  lapack_int *jp = bg_xcalloc((size_t)N + 1, sizeof *jp);
  memcpy(R, l->E, NN * sizeof *R);
  LAPACKE_dgeqp3(LAPACK_COL_MAJOR, N, N, R, N, jp, tau);
  int r = 0;
  double r0 = fabs(R[0]);
  while (r < N && fabs(R[(size_t)r * N + r]) > 1e3 * N * DBL_EPSILON * r0) r++;
  D->QE = bg_xmalloc(NN * sizeof *D->QE + 1), D->QA = bg_xmalloc(NN * sizeof *D->QA + 1);
  D->QB = bg_xcalloc((size_t)N * D->nu + 1, sizeof *D->QB);
  memcpy(D->QE, l->E, NN * sizeof *D->QE), memcpy(D->QA, l->Ad, NN * sizeof *D->QA);
  memcpy(D->QB, l->Bd, (size_t)N * D->nu * sizeof *D->QB);
  LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', N, N, N, R, N, tau, D->QE, N);
  LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', N, N, N, R, N, tau, D->QA, N);
  if (D->nu) LAPACKE_dormqr(LAPACK_COL_MAJOR, 'L', 'T', N, D->nu, N, R, N, tau, D->QB, N);
  for (int j = 0; j < N; j++) /* the rows below the rank are rounding */
    for (int i = r; i < N; i++) D->QE[(size_t)j * N + i] = 0;
  free(R), free(tau), free(jp);
  return r;
}

/* Step 2: nc columns of A2 (rows r..N-1 of QA) that are independent, in
 * the order `order`, by Gram-Schmidt (twice) on the columns; 0 when A2 has
 * a smaller rank (the constraints do not fix that many unknowns). */
static int pick_eliminated(dep *D, const int *order) {
  int N = D->N, nc = D->nc, got = 0;
  double *basis = bg_xcalloc((size_t)nc * nc + 1, sizeof *basis), *v = bg_xcalloc((size_t)nc + 1, sizeof *v);
  double scale = 0;
  for (int j = 0; j < N; j++)
    for (int i = D->r; i < N; i++) scale = fmax(scale, fabs(D->QA[(size_t)j * N + i]));
  unsigned char *used = bg_xcalloc((size_t)N + 1, 1);
  for (int k = 0; k < N && got < nc; k++) {
    int j = order[k];
    for (int i = 0; i < nc; i++) v[i] = D->QA[(size_t)j * N + D->r + i];
    for (int pass = 0; pass < 2; pass++)
      for (int b = 0; b < got; b++) {
        double dot = 0, *q = basis + (size_t)b * nc;
        for (int i = 0; i < nc; i++) dot += q[i] * v[i];
        for (int i = 0; i < nc; i++) v[i] -= dot * q[i];
      }
    double nv = 0;
    for (int i = 0; i < nc; i++) nv += v[i] * v[i];
    nv = sqrt(nv);
    if (!(nv > 1e3 * N * DBL_EPSILON * scale)) continue;
    for (int i = 0; i < nc; i++) basis[(size_t)got * nc + i] = v[i] / nv;
    used[j] = 1, got++;
  }
  int e = 0, kept = 0;
  for (int j = 0; j < N; j++) {
    if (used[j]) D->elim[e++] = j;
    else D->keep[kept++] = j;
  }
  free(basis), free(v), free(used);
  return got == nc;
}

/* x_d = K x_i + L u into P and Qu; 0 when A2d is singular. */
static int solve_constraints(dep *D) {
  int N = D->N, nc = D->nc, r = D->r, nu = D->nu, w = r + nu;
  double *A2d = bg_xcalloc((size_t)nc * nc + 1, sizeof *A2d), *rhs = bg_xcalloc((size_t)nc * w + 1, sizeof *rhs);
  for (int c = 0; c < nc; c++)
    for (int i = 0; i < nc; i++) A2d[(size_t)c * nc + i] = D->QA[(size_t)D->elim[c] * N + r + i];
  for (int c = 0; c < r; c++)
    for (int i = 0; i < nc; i++) rhs[(size_t)c * nc + i] = -D->QA[(size_t)D->keep[c] * N + r + i];
  for (int j = 0; j < nu; j++)
    for (int i = 0; i < nc; i++) rhs[(size_t)(r + j) * nc + i] = -D->QB[(size_t)j * N + r + i];
  lapack_int *piv = bg_xcalloc((size_t)nc + 1, sizeof *piv);
  double rcond = 1;
  int ok = 1;
  if (nc > 0) {
    double anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, '1', nc, nc, A2d, nc);
    ok = LAPACKE_dgetrf(LAPACK_COL_MAJOR, nc, nc, A2d, nc, piv) == 0;
    if (ok) LAPACKE_dgecon(LAPACK_COL_MAJOR, '1', nc, A2d, nc, anorm, &rcond);
    ok = ok && rcond > 1e3 * nc * DBL_EPSILON;
    if (ok && w) LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', nc, w, A2d, nc, piv, rhs, nc);
  }
  D->P = bg_xcalloc((size_t)N * r + 1, sizeof *D->P), D->Qu = bg_xcalloc((size_t)N * nu + 1, sizeof *D->Qu);
  for (int c = 0; c < r; c++) {
    D->P[(size_t)c * N + D->keep[c]] = 1;
    for (int i = 0; i < nc; i++) D->P[(size_t)c * N + D->elim[i]] = rhs[(size_t)c * nc + i];
  }
  for (int j = 0; j < nu; j++)
    for (int i = 0; i < nc; i++) D->Qu[(size_t)j * N + D->elim[i]] = rhs[(size_t)(r + j) * nc + i];
  free(A2d), free(rhs), free(piv);
  return ok;
}

/* The first input column of M (rows x nu) that is not rounding against
 * `scale`, or -1. */
static int nonzero_input(const double *M, int rows, int nu, double scale, int *row) {
  for (int j = 0; j < nu; j++)
    for (int i = 0; i < rows; i++)
      if (fabs(M[(size_t)j * rows + i]) > 1e-9 * scale) return *row = i, j;
  return -1;
}

static void note(bg_linear *l, const char *msg) {
  free(l->reduce_note);
  l->reduce_note = strdup(msg);
}

/* Step 3's test for input derivatives: 0, or -1 with the note. */
static int needs_input_rate(dep *D, const double *E1Q) {
  bg_linear *l = D->l;
  int N = D->N, ny = D->ny, nu = D->nu, row;
  double *CpQ = bg_xcalloc((size_t)ny * nu + 1, sizeof *CpQ), sq = max_abs(D->Qu, (size_t)N * nu);
  bg_lin_matmul(ny, N, nu, l->Cpd, D->Qu, CpQ);
  char buf[320];
  int j = nonzero_input(E1Q, D->r, nu, max_abs(l->E, (size_t)N * N) * sq, &row);
  if (j >= 0)
    snprintf(buf, sizeof buf, "not reduced: the states would need the derivative of input %s (a "
             "dependent store follows it); the descriptor form is used", l->uname[j]);
  else if ((j = nonzero_input(CpQ, ny, nu, max_abs(l->Cpd, (size_t)ny * N) * sq, &row)) >= 0)
    snprintf(buf, sizeof buf, "not reduced: output %s needs the derivative of input %s (an improper "
             "transfer function); the descriptor form is used", l->yname[row], l->uname[j]);
  free(CpQ);
  if (j >= 0) note(l, buf);
  return j >= 0 ? -1 : 0;
}

/* Rows 0..r-1 of a column-major N-row matrix M with `cols` columns. */
static double *top_rows(const double *M, int N, int r, int cols) {
  double *T = bg_xcalloc((size_t)r * cols + 1, sizeof *T);
  for (int j = 0; j < cols; j++) memcpy(T + (size_t)j * r, M + (size_t)j * N, (size_t)r * sizeof *T);
  return T;
}

/* Step 3: A, B of the kept unknowns and the outputs; 0, or -1 with the note. */
static int assemble_dep(dep *D) {
  bg_linear *l = D->l;
  int N = D->N, r = D->r, nu = D->nu, ny = D->ny, rc = -1;
  double *E1 = top_rows(D->QE, N, r, N), *A1 = top_rows(D->QA, N, r, N), *B1 = top_rows(D->QB, N, r, nu);
  double *E1P = bg_xcalloc((size_t)r * r + 1, sizeof *E1P), *E1Q = bg_xcalloc((size_t)r * nu + 1, sizeof *E1Q);
  double *AB = bg_xcalloc((size_t)r * (r + nu) + 1, sizeof *AB);
  bg_lin_matmul(r, N, r, E1, D->P, E1P);
  bg_lin_matmul(r, N, nu, E1, D->Qu, E1Q);
  bg_lin_matmul(r, N, r, A1, D->P, AB);
  bg_lin_matmul(r, N, nu, A1, D->Qu, AB + (size_t)r * r);
  for (size_t k = 0; k < (size_t)r * nu; k++) AB[(size_t)r * r + k] += B1[k];
  lapack_int *piv = bg_xcalloc((size_t)r + 1, sizeof *piv);
  double rcond = 1; /* r = 0: every state is fixed, y = D u */
  int ok = 1;
  if (r > 0) {
    double anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, '1', r, r, E1P, r);
    ok = LAPACKE_dgetrf(LAPACK_COL_MAJOR, r, r, E1P, r, piv) == 0;
    if (ok) LAPACKE_dgecon(LAPACK_COL_MAJOR, '1', r, E1P, r, anorm, &rcond);
  }
  if (!(ok && rcond > 1e3 * (r + 1) * DBL_EPSILON))
    note(l, "not reduced: the dependent stores' constraints leave the rates of the other "
            "states undetermined (index above 1); the descriptor form is used");
  else if (needs_input_rate(D, E1Q) == 0) {
    if (r > 0) LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', r, r + nu, E1P, r, piv, AB, r);
    l->n = r;
    l->state = bg_xcalloc((size_t)r + 1, sizeof *l->state);
    memcpy(l->state, D->keep, (size_t)r * sizeof *l->state);
    l->A = bg_xcalloc((size_t)r * r + 1, sizeof *l->A), l->B = bg_xcalloc((size_t)r * nu + 1, sizeof *l->B);
    memcpy(l->A, AB, (size_t)r * r * sizeof *l->A);
    memcpy(l->B, AB + (size_t)r * r, (size_t)r * nu * sizeof *l->B);
    double *Cx = bg_xcalloc((size_t)ny * r + 1, sizeof *Cx), *CpP = bg_xcalloc((size_t)ny * r + 1, sizeof *CpP);
    double *Dd = bg_xcalloc((size_t)ny * nu + 1, sizeof *Dd);
    bg_lin_matmul(ny, N, r, l->Cd, D->P, Cx);
    bg_lin_matmul(ny, N, r, l->Cpd, D->P, CpP);
    bg_lin_matmul(ny, N, nu, l->Cd, D->Qu, Dd);
    for (size_t k = 0; k < (size_t)ny * nu; k++) Dd[k] += l->Dd[k];
    bg_lin_outputs_through(l, Cx, CpP, Dd);
    free(Cx), free(CpP), free(Dd);
    l->reduced = 1, rc = 0;
  }
  free(E1), free(A1), free(B1), free(E1P), free(E1Q), free(AB), free(piv);
  return rc;
}

/* The differential unknowns among the eliminated ones: the dependent stores. */
static void record_eliminated(dep *D) {
  bg_linear *l = D->l;
  l->elim = bg_xcalloc((size_t)D->nc + 1, sizeof *l->elim);
  for (int c = 0; c < D->nc; c++) {
    int j = D->elim[c], any = 0;
    for (int i = 0; i < D->N && !any; i++) any = l->E[(size_t)j * D->N + i] != 0;
    if (any) l->elim[l->nelim++] = j;
  }
}

int bg_lin_reduce_dependent(bg_linear *l, const int *order) {
  dep D = {.l = l, .N = l->N, .nu = l->nu, .ny = l->ny};
  D.r = compress_rows(&D);
  D.nc = D.N - D.r;
  D.elim = bg_xcalloc((size_t)D.N + 1, sizeof *D.elim), D.keep = bg_xcalloc((size_t)D.N + 1, sizeof *D.keep);
  int rc = -1;
  if (!pick_eliminated(&D, order))
    note(l, "not reduced: the constraints do not fix the dependent stores and algebraic unknowns "
            "(index above 1); the descriptor form is used");
  else if (!solve_constraints(&D))
    note(l, "not reduced: the constraints cannot be solved for the dependent stores and algebraic "
            "unknowns; the descriptor form is used");
  else if ((rc = assemble_dep(&D)) == 0) {
    record_eliminated(&D);
    free(l->reduce_note), l->reduce_note = NULL;
  }
  free(D.QE), free(D.QA), free(D.QB), free(D.elim), free(D.keep), free(D.P), free(D.Qu);
  return rc;
}
