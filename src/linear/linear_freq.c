/* SPDX-License-Identifier: BSD-3-Clause */
/* Frequency responses H(jw) = C (jwI - A)^-1 B + D. A is brought to upper
 * Hessenberg form once (A = Q H Q^T, dgehrd; skipped when A already is
 * Hessenberg, as the states of a chain of stores usually are), B and C are
 * transformed with the same reflectors (dormhr), and each frequency costs
 * one Hessenberg elimination with partial pivoting between neighbouring
 * rows: O(n^2) for a dense H, O(n) for a banded one (each row is swept only
 * up to its last nonzero). Descriptor-only systems take a dense complex
 * solve per frequency. */
#include <complex.h>
#include <float.h>
#include "base/lapack.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

typedef struct hess {
  int n, nu, ny;
  double *H;          /* column-major n x n, upper Hessenberg */
  double *QB, *CQ;    /* Q^T B (n x nu), C Q (ny x n) */
  int *last;          /* last nonzero column of each row of H */
} hess;

static int is_hessenberg(const double *A, int n) {
  for (int j = 0; j < n; j++)
    for (int i = j + 2; i < n; i++)
      if (A[(size_t)j * n + i] != 0) return 0;
  return 1;
}

static void hess_build(const bg_linear *l, hess *h) {
  int n = l->n, nu = l->nu, ny = l->ny;
  h->n = n, h->nu = nu, h->ny = ny;
  h->H = bg_xmalloc((size_t)n * n * sizeof *h->H + 1);
  h->QB = bg_xmalloc((size_t)n * nu * sizeof *h->QB + 1);
  h->CQ = bg_xmalloc((size_t)ny * n * sizeof *h->CQ + 1);
  memcpy(h->H, l->A, (size_t)n * n * sizeof *h->H);
  memcpy(h->QB, l->B, (size_t)n * nu * sizeof *h->QB);
  memcpy(h->CQ, l->C, (size_t)ny * n * sizeof *h->CQ);
  if (n > 2 && !is_hessenberg(l->A, n)) {
    double *tau = bg_xcalloc((size_t)n, sizeof *tau);
    LAPACKE_dgehrd(LAPACK_COL_MAJOR, n, 1, n, h->H, n, tau);
    if (nu) LAPACKE_dormhr(LAPACK_COL_MAJOR, 'L', 'T', n, nu, 1, n, h->H, n, tau, h->QB, n);
    if (ny) LAPACKE_dormhr(LAPACK_COL_MAJOR, 'R', 'N', ny, n, 1, n, h->H, n, tau, h->CQ, ny);
    for (int j = 0; j < n; j++) /* the reflectors below the subdiagonal */
      for (int i = j + 2; i < n; i++) h->H[(size_t)j * n + i] = 0;
    free(tau);
  }
  h->last = bg_xcalloc((size_t)n + 1, sizeof *h->last);
  for (int i = 0; i < n; i++) {
    h->last[i] = i;
    for (int j = n - 1; j > i; j--)
      if (h->H[(size_t)j * n + i] != 0) { h->last[i] = j; break; }
  }
}

static void hess_free(hess *h) { free(h->H), free(h->QB), free(h->CQ), free(h->last); }

/* Solves (jw I - H) X = QB (nu right-hand sides) into X (n x nu, row-major).
 * M is n x n row-major scratch, ext per-row extents. */
static void hess_solve(const hess *h, double w, double complex *M, int *ext, double complex *X) {
  int n = h->n, nu = h->nu;
  for (int i = 0; i < n; i++) {
    ext[i] = h->last[i];
    for (int j = i > 0 ? i - 1 : 0; j <= ext[i]; j++) M[(size_t)i * n + j] = -h->H[(size_t)j * n + i];
    M[(size_t)i * n + i] += I * w;
    for (int k = 0; k < nu; k++) X[(size_t)i * nu + k] = h->QB[(size_t)k * n + i];
  }
  for (int i = 0; i + 1 < n; i++) {
    double complex *p = M + (size_t)i * n, *q = M + (size_t)(i + 1) * n;
    int e = ext[i] > ext[i + 1] ? ext[i] : ext[i + 1];
    for (int j = ext[i] + 1; j <= e; j++) p[j] = 0; /* widen both rows to e */
    for (int j = ext[i + 1] + 1; j <= e; j++) q[j] = 0;
    ext[i] = ext[i + 1] = e;
    if (cabs(q[i]) > cabs(p[i])) { /* partial pivoting between the two rows */
      for (int j = i; j <= e; j++) { double complex t = p[j]; p[j] = q[j], q[j] = t; }
      for (int k = 0; k < nu; k++) {
        double complex t = X[(size_t)i * nu + k];
        X[(size_t)i * nu + k] = X[(size_t)(i + 1) * nu + k], X[(size_t)(i + 1) * nu + k] = t;
      }
    }
    if (p[i] == 0) continue; /* singular: a pole on the axis; gives inf below */
    double complex f = q[i] / p[i];
    q[i] = 0;
    for (int j = i + 1; j <= e; j++) q[j] -= f * p[j];
    for (int k = 0; k < nu; k++) X[(size_t)(i + 1) * nu + k] -= f * X[(size_t)i * nu + k];
  }
  for (int i = n - 1; i >= 0; i--) {
    const double complex *r = M + (size_t)i * n;
    for (int k = 0; k < nu; k++) {
      double complex s = X[(size_t)i * nu + k];
      for (int j = i + 1; j <= ext[i]; j++) s -= r[j] * X[(size_t)j * nu + k];
      X[(size_t)i * nu + k] = s / r[i];
    }
  }
}

static int freq_reduced(const bg_linear *l, int nw, const double *w, double *re, double *im) {
  hess h;
  hess_build(l, &h);
  int n = h.n, nu = h.nu, ny = h.ny;
  double complex *M = bg_xmalloc((size_t)n * n * sizeof *M + 1), *X = bg_xmalloc((size_t)n * nu * sizeof *X + 1);
  int *ext = bg_xcalloc((size_t)n + 1, sizeof *ext);
  for (int k = 0; k < nw; k++) {
    if (n) hess_solve(&h, w[k], M, ext, X);
    for (int iy = 0; iy < ny; iy++)
      for (int iu = 0; iu < nu; iu++) {
        double complex y = l->D[(size_t)iu * ny + iy];
        for (int i = 0; i < n; i++) y += h.CQ[(size_t)i * ny + iy] * X[(size_t)i * nu + iu];
        size_t at = (size_t)(iy * nu + iu) * nw + k;
        re[at] = creal(y), im[at] = cimag(y);
      }
  }
  free(M), free(X), free(ext);
  hess_free(&h);
  return 0;
}

static int freq_descriptor(const bg_linear *l, int nw, const double *w, double *re, double *im) {
  if (l->N > 300) return -1;
  for (int k = 0; k < nw; k++)
    for (int iy = 0; iy < l->ny; iy++)
      for (int iu = 0; iu < l->nu; iu++) {
        double complex y = bg_lin_eval(l, iy, iu, I * w[k]);
        size_t at = (size_t)(iy * l->nu + iu) * nw + k;
        re[at] = creal(y), im[at] = cimag(y);
      }
  return 0;
}

int bg_linear_freqresp(const bg_linear *l, int nw, const double *w, double *re, double *im) {
  if (!l->ok) return -1;
  return l->reduced ? freq_reduced(l, nw, w, re, im) : freq_descriptor(l, nw, w, re, im);
}

/* Magnitudes of the nonzero poles and zeros: [lo, hi]; 0 when there are none. */
static int root_range(const bg_linear *l, double *lo, double *hi) {
  *lo = HUGE_VAL, *hi = 0;
  for (int i = 0; i < l->npole; i++) {
    double r = hypot(l->pole_re[i], l->pole_im[i]);
    if (r > 0) *lo = fmin(*lo, r), *hi = fmax(*hi, r);
  }
  for (int k = 0; k < l->ntf; k++)
    for (int i = 0; i < l->tf[k].nzero; i++) {
      double r = hypot(l->tf[k].zero_re[i], l->tf[k].zero_im[i]);
      if (r > 0) *lo = fmin(*lo, r), *hi = fmax(*hi, r);
    }
  return *hi > 0;
}

/* Without poles (large models): |lambda| <= the max row sum of A. */
static double norm_bound(const bg_linear *l) {
  const double *A = l->reduced ? l->A : l->Ad;
  int n = l->reduced ? l->n : l->N;
  double best = 0;
  for (int i = 0; i < n; i++) {
    double s = 0;
    for (int j = 0; j < n; j++) s += fabs(A[(size_t)j * n + i]);
    best = fmax(best, s);
  }
  return best;
}

/* The smallest |lambda| of a reduced A by inverse iteration on its
 * Hessenberg form (30 solves, O(n^2) at most each); 0 when A is singular. */
static double smallest_mode(const bg_linear *l) {
  hess h;
  hess_build(l, &h);
  int n = h.n;
  double complex *M = bg_xmalloc((size_t)n * n * sizeof *M + 1), *x = bg_xcalloc((size_t)n + 1, sizeof *x);
  int *ext = bg_xcalloc((size_t)n + 1, sizeof *ext);
  h.nu = 1;
  free(h.QB);
  h.QB = bg_xcalloc((size_t)n + 1, sizeof *h.QB);
  for (int i = 0; i < n; i++) h.QB[i] = 1 + 0.5 * sin(1.7 * i); /* a fixed start */
  double est = 0;
  for (int it = 0; it < 30; it++) {
    double nv = 0, nx = 0;
    for (int i = 0; i < n; i++) nv += h.QB[i] * h.QB[i];
    hess_solve(&h, 0, M, ext, x); /* x = -H^-1 v */
    for (int i = 0; i < n; i++) nx += creal(x[i]) * creal(x[i]);
    if (!(nx > 0) || !isfinite(nx)) { est = 0; break; }
    est = sqrt(nv / nx);
    for (int i = 0; i < n; i++) h.QB[i] = creal(x[i]) / sqrt(nx);
  }
  free(M), free(x), free(ext);
  hess_free(&h);
  return est;
}

int bg_linear_freqs(const bg_linear *l, const bg_model *m, int nw, double *w) {
  double lo, hi;
  if (l->npole || l->ntf) {
    if (!root_range(l, &lo, &hi)) lo = 0.1, hi = 10;
    lo = pow(10, floor(log10(lo)) - 1), hi = pow(10, ceil(log10(hi)) + 1);
  } else {
    hi = norm_bound(l);
    hi = hi > 0 ? pow(10, ceil(log10(hi)) + 1) : 10;
    double small = l->reduced && l->n > 0 ? smallest_mode(l) : 0;
    lo = small > 0 ? pow(10, floor(log10(small)) - 1) : hi * 1e-7;
  }
  if (hi / lo > 1e12) lo = hi * 1e-12; /* at most 12 decades */
  const bg_linspec *ls = &m->linear; /* the model checked them: positive, finite, ordered */
  if (ls->w_min > 0 && isfinite(ls->w_min)) lo = ls->w_min;
  if (ls->w_max > 0 && isfinite(ls->w_max)) hi = ls->w_max;
  if (!(hi > lo)) hi = lo * 100;
  /* one bound given, the other automatic: at most BG_LIN_MAX_DECADES between them */
  if (hi / lo > BG_LIN_MAX_RANGE) {
    if (ls->w_min > 0) hi = lo * BG_LIN_MAX_RANGE;
    else lo = hi / BG_LIN_MAX_RANGE;
  }
  /* evenly spaced in log space; hi / lo <= 10^30 is finite (1e-200 .. 1e200,
   * refused by the model, overflowed it and made every frequency inf) */
  for (int k = 0; k < nw; k++) w[k] = nw > 1 ? lo * pow(hi / lo, (double)k / (nw - 1)) : lo;
  return nw;
}
