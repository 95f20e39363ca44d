/* SPDX-License-Identifier: BSD-3-Clause */
/* Step and impulse responses of the state space, exact at the sample
 * times: with h = t_end / (nt - 1), exp([A B; 0 0] h) = [Phi Gamma; 0 I]
 * (scaling and squaring with a degree-6 Pade approximant), then
 * x_{k+1} = Phi x_k + Gamma u for a unit step from x = 0, and
 * x_0 = B, x_{k+1} = Phi x_k for a unit impulse (the D term's Dirac pulse at
 * t = 0 is not drawn). Dense: up to BG_LIN_MAX_TIME states. */
#include <float.h>
#include "base/lapack.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

/* 1, 2 or 5 x 10^k at or above v. */
static double round_up(double v) {
  double p = pow(10, floor(log10(v)));
  return v <= p ? p : v <= 2 * p ? 2 * p : v <= 5 * p ? 5 * p : 10 * p;
}

double bg_linear_t_end(const bg_linear *l, const bg_model *m) {
  if (m->linear.t_end > 0) return m->linear.t_end;
  double slow = 0, rho = 0, osc = 0;
  for (int i = 0; i < l->npole; i++) rho = fmax(rho, hypot(l->pole_re[i], l->pole_im[i]));
  for (int i = 0; i < l->npole; i++) {
    double re = l->pole_re[i], im = fabs(l->pole_im[i]);
    if (re < -1e-9 * rho) slow = fmax(slow, 1 / -re); /* a decaying mode's time constant */
    if (im > 1e-9 * rho) osc = fmax(osc, 2 * 3.141592653589793 / im);
  }
  double t = slow > 0 ? 5 * slow : osc > 0 ? 3 * osc : rho > 0 ? 5 / rho : 1;
  if (osc > 0 && t < 3 * osc && slow == 0) t = 3 * osc;
  return round_up(t);
}

static double norm1(const double *M, int n) {
  double best = 0;
  for (int j = 0; j < n; j++) {
    double s = 0;
    for (int i = 0; i < n; i++) s += fabs(M[(size_t)j * n + i]);
    best = fmax(best, s);
  }
  return best;
}

/* E = exp(M), n x n; 0, or -1 when the Pade denominator is singular. */
static int expm(const double *M, int n, double *E) {
  size_t nn = (size_t)n * n;
  double nm = norm1(M, n);
  int s = nm > 0.5 ? (int)ceil(log2(nm / 0.5)) : 0;
  double scale = ldexp(1.0, -s), c = 1;
  double *X = bg_xmalloc(nn * sizeof *X + 8), *P = bg_xmalloc(nn * sizeof *P + 8);
  double *N = bg_xcalloc(nn + 1, sizeof *N), *D = bg_xcalloc(nn + 1, sizeof *D), *T = bg_xmalloc(nn * sizeof *T + 8);
  for (size_t k = 0; k < nn; k++) X[k] = M[k] * scale;
  for (int i = 0; i < n; i++) N[(size_t)i * n + i] = D[(size_t)i * n + i] = 1;
  memcpy(P, X, nn * sizeof *P);
  for (int k = 1; k <= 6; k++) {
    c *= (6.0 - k + 1) / (k * (12.0 - k + 1));
    for (size_t q = 0; q < nn; q++) N[q] += c * P[q], D[q] += (k % 2 ? -c : c) * P[q];
    if (k < 6) bg_lin_matmul(n, n, n, P, X, T), memcpy(P, T, nn * sizeof *P);
  }
  lapack_int *piv = bg_xcalloc((size_t)n + 1, sizeof *piv);
  int info = LAPACKE_dgesv(LAPACK_COL_MAJOR, n, n, D, n, piv, N, n);
  for (int k = 0; k < s && info == 0; k++) bg_lin_matmul(n, n, n, N, N, T), memcpy(N, T, nn * sizeof *N);
  memcpy(E, N, nn * sizeof *E);
  free(X), free(P), free(N), free(D), free(T), free(piv);
  return info ? -1 : 0;
}

/* Phi (n x n) and Gamma (n x nu) for step h. */
static int discretise(const bg_linear *l, double h, double *Phi, double *Gam) {
  int n = l->n, nu = l->nu, m = n + nu;
  double *M = bg_xcalloc((size_t)m * m + 1, sizeof *M), *E = bg_xcalloc((size_t)m * m + 1, sizeof *E);
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) M[(size_t)j * m + i] = l->A[(size_t)j * n + i] * h;
  for (int j = 0; j < nu; j++)
    for (int i = 0; i < n; i++) M[(size_t)(n + j) * m + i] = l->B[(size_t)j * n + i] * h;
  int rc = expm(M, m, E);
  for (int j = 0; j < n; j++) memcpy(Phi + (size_t)j * n, E + (size_t)j * m, (size_t)n * sizeof *Phi);
  for (int j = 0; j < nu; j++) memcpy(Gam + (size_t)j * n, E + (size_t)(n + j) * m, (size_t)n * sizeof *Gam);
  free(M), free(E);
  return rc;
}

/* y[(iy * nu + iu) * nt + k] = C X[:, iu] (+ D for a step). */
static void sample(const bg_linear *l, const double *X, int k, int nt, int impulse, double *y) {
  int n = l->n, nu = l->nu, ny = l->ny;
  for (int iy = 0; iy < ny; iy++)
    for (int iu = 0; iu < nu; iu++) {
      double v = impulse ? 0 : l->D[(size_t)iu * ny + iy];
      for (int i = 0; i < n; i++) v += l->C[(size_t)i * ny + iy] * X[(size_t)iu * n + i];
      y[(size_t)(iy * nu + iu) * nt + k] = v;
    }
}

int bg_linear_step(const bg_linear *l, double t_end, int nt, int impulse, double *y) {
  if (!l->ok || !l->reduced || l->n > BG_LIN_MAX_TIME || nt < 2 || !(t_end > 0)) return -1;
  int n = l->n, nu = l->nu;
  double *Phi = bg_xcalloc((size_t)n * n + 1, sizeof *Phi), *Gam = bg_xcalloc((size_t)n * nu + 1, sizeof *Gam);
  double *X = bg_xcalloc((size_t)n * nu + 1, sizeof *X), *T = bg_xcalloc((size_t)n * nu + 1, sizeof *T);
  int rc = discretise(l, t_end / (nt - 1), Phi, Gam);
  if (impulse) memcpy(X, l->B, (size_t)n * nu * sizeof *X);
  for (int k = 0; k < nt && rc == 0; k++) {
    sample(l, X, k, nt, impulse, y);
    bg_lin_matmul(n, n, nu, Phi, X, T);
    for (size_t q = 0; q < (size_t)n * nu; q++) X[q] = T[q] + (impulse ? 0 : Gam[q]);
  }
  free(Phi), free(Gam), free(X), free(T);
  return rc;
}
