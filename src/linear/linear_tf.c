/* SPDX-License-Identifier: BSD-3-Clause */
/* Poles and transfer functions. Poles are the eigenvalues of A (reduced) or
 * the finite generalised eigenvalues of (A, E) (descriptor). The zeros of
 * pair (y_i, u_j) are the finite generalised eigenvalues of the system
 * matrix P(s) = [sE - A, -b; c + s cp, d] (det P = det(sE - A) H(s)); zeros
 * equal to a pole within rounding are modes that pair does not see
 * (uncontrollable or unobservable) and cancel. The gain comes from H at one
 * point off the axes: K = H(s0) prod(s0 - p) / prod(s0 - z). */
#include <float.h>
#include "base/lapack.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

typedef struct { double re, im; } cplx;

static int cmp_cplx(const void *a, const void *b) {
  const cplx *x = a, *y = b;
  if (x->re != y->re) return x->re < y->re ? -1 : 1;
  return (x->im > y->im) - (x->im < y->im);
}

/* Finite generalised eigenvalues of (A, B) (n x n, destroyed) into ev;
 * returns their count, or -1 when the pencil is singular (alpha = beta = 0). */
static int gen_eig(double *A, double *B, int n, cplx *ev) {
  double *ar = bg_xcalloc((size_t)n + 1, sizeof *ar), *ai = bg_xcalloc((size_t)n + 1, sizeof *ai);
  double *be = bg_xcalloc((size_t)n + 1, sizeof *be);
  int info = LAPACKE_dggev(LAPACK_COL_MAJOR, 'N', 'N', n, A, n, B, n, ar, ai, be, NULL, 1, NULL, 1);
  int k = 0, singular = 0;
  double big = 0;
  for (int i = 0; i < n; i++) big = fmax(big, fmax(hypot(ar[i], ai[i]), fabs(be[i])));
  for (int i = 0; i < n && info == 0; i++) {
    double mag = fmax(hypot(ar[i], ai[i]), fabs(be[i]));
    if (mag <= 1e3 * n * DBL_EPSILON * big) singular = 1;
    else if (fabs(be[i]) > 1e3 * n * DBL_EPSILON * mag) ev[k++] = (cplx){ar[i] / be[i], ai[i] / be[i]};
  }
  free(ar), free(ai), free(be);
  return info || singular ? -1 : k;
}

static int std_eig(const double *A, int n, cplx *ev) {
  double *M = bg_xmalloc((size_t)n * n * sizeof *M + 1), *wr = bg_xcalloc((size_t)n + 1, sizeof *wr);
  double *wi = bg_xcalloc((size_t)n + 1, sizeof *wi);
  memcpy(M, A, (size_t)n * n * sizeof *M);
  int info = LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'N', n, M, n, wr, wi, NULL, 1, NULL, 1);
  for (int i = 0; i < n; i++) ev[i] = (cplx){wr[i] + 0.0, wi[i] + 0.0};
  free(M), free(wr), free(wi);
  return info ? -1 : n;
}

/* Size of the system in use and its matrices. */
static int sys_size(const bg_linear *l) { return l->reduced ? l->n : l->N; }

void bg_lin_poles(bg_linear *l) {
  int n = sys_size(l);
  if (n > 500 || n == 0) return; /* dense eigenvalues; docs/linear.md (none without states) */
  cplx *ev = bg_xcalloc((size_t)n + 1, sizeof *ev);
  int k;
  if (l->reduced) k = std_eig(l->A, n, ev);
  else {
    double *A = bg_xmalloc((size_t)n * n * sizeof *A + 1), *E = bg_xmalloc((size_t)n * n * sizeof *E + 1);
    memcpy(A, l->Ad, (size_t)n * n * sizeof *A), memcpy(E, l->E, (size_t)n * n * sizeof *E);
    k = gen_eig(A, E, n, ev);
    free(A), free(E);
  }
  if (k >= 0) {
    qsort(ev, (size_t)k, sizeof *ev, cmp_cplx);
    l->npole = k;
    l->pole_re = bg_xcalloc((size_t)k + 1, sizeof *l->pole_re);
    l->pole_im = bg_xcalloc((size_t)k + 1, sizeof *l->pole_im);
    for (int i = 0; i < k; i++) l->pole_re[i] = ev[i].re, l->pole_im[i] = ev[i].im;
  }
  free(ev);
}

double complex bg_lin_eval(const bg_linear *l, int iy, int iu, double complex s) {
  int n = sys_size(l), ny = l->ny;
  const double *A = l->reduced ? l->A : l->Ad, *B = l->reduced ? l->B : l->Bd;
  const double *C = l->reduced ? l->C : l->Cd;
  double D = (l->reduced ? l->D : l->Dd)[(size_t)iu * ny + iy];
  if (n == 0) return D;
  lapack_complex_double *M = bg_xcalloc((size_t)n * n + 1, sizeof *M), *x = bg_xcalloc((size_t)n + 1, sizeof *x);
  lapack_int *piv = bg_xcalloc((size_t)n + 1, sizeof *piv);
  for (size_t k = 0; k < (size_t)n * n; k++) M[k] = -A[k] + (l->reduced ? 0 : s * l->E[k]);
  for (int i = 0; l->reduced && i < n; i++) M[(size_t)i * n + i] += s;
  for (int i = 0; i < n; i++) x[i] = B[(size_t)iu * n + i];
  double complex h = D;
  if (LAPACKE_zgesv(LAPACK_COL_MAJOR, n, 1, M, n, piv, x, n) != 0) h = NAN;
  else
    for (int i = 0; i < n; i++) {
      double complex c = C[(size_t)i * ny + iy] + (l->reduced ? 0 : s * l->Cpd[(size_t)i * ny + iy]);
      h += c * x[i];
    }
  free(M), free(x), free(piv);
  return h;
}

/* Zeros of pair (iy, iu) with cancellations against the poles removed. */
static int pair_zeros(const bg_linear *l, int iy, int iu, cplx *z) {
  int n = sys_size(l), M = n + 1, ny = l->ny;
  double *P0 = bg_xcalloc((size_t)M * M + 1, sizeof *P0), *P1 = bg_xcalloc((size_t)M * M + 1, sizeof *P1);
  const double *A = l->reduced ? l->A : l->Ad, *B = l->reduced ? l->B : l->Bd;
  const double *C = l->reduced ? l->C : l->Cd, *D = l->reduced ? l->D : l->Dd;
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < n; i++) {
      P0[(size_t)j * M + i] = A[(size_t)j * n + i];
      P1[(size_t)j * M + i] = l->reduced ? (i == j) : l->E[(size_t)j * n + i];
    }
    P0[(size_t)j * M + n] = -C[(size_t)j * ny + iy];
    P1[(size_t)j * M + n] = l->reduced ? 0 : l->Cpd[(size_t)j * ny + iy];
    P0[(size_t)n * M + j] = B[(size_t)iu * n + j];
  }
  P0[(size_t)n * M + n] = -D[(size_t)iu * ny + iy];
  int k = gen_eig(P0, P1, M, z);
  free(P0), free(P1);
  return k;
}

/* Removes zero/pole pairs that coincide within rounding; returns cancellations. */
static int cancel(cplx *p, int *np, cplx *z, int *nz) {
  double rho = 0;
  for (int i = 0; i < *np; i++) rho = fmax(rho, hypot(p[i].re, p[i].im));
  int nc = 0;
  for (int i = 0; i < *nz; i++) {
    int best = -1;
    double bd = HUGE_VAL;
    for (int j = 0; j < *np; j++) {
      double d = hypot(z[i].re - p[j].re, z[i].im - p[j].im);
      if (d < bd) bd = d, best = j;
    }
    if (best < 0 || bd > 1e-7 * hypot(p[best].re, p[best].im) + 1e-10 * rho) continue;
    p[best] = p[--*np];
    z[i--] = z[--*nz];
    nc++;
  }
  qsort(p, (size_t)*np, sizeof *p, cmp_cplx);
  qsort(z, (size_t)*nz, sizeof *z, cmp_cplx);
  return nc;
}

/* Real coefficients of K prod (s - r_k), highest power first. */
static double *poly_from_roots(const cplx *r, int nr, double K) {
  double complex *c = bg_xcalloc((size_t)nr + 2, sizeof *c);
  c[0] = 1;
  for (int k = 0; k < nr; k++) {
    double complex root = r[k].re + I * r[k].im;
    for (int i = k + 1; i > 0; i--) c[i] -= root * c[i - 1];
  }
  double *out = bg_xcalloc((size_t)nr + 2, sizeof *out);
  for (int i = 0; i <= nr; i++) out[i] = K * creal(c[i]) + 0.0;
  free(c);
  return out;
}

static double complex prod_diff(double complex s, const cplx *r, int nr) {
  double complex p = 1;
  for (int k = 0; k < nr; k++) p *= s - (r[k].re + I * r[k].im);
  return p;
}

static void store(bg_lin_tf *t, const cplx *p, int np, const cplx *z, int nz, double K) {
  t->npole = np, t->nzero = nz;
  t->pole_re = bg_xcalloc((size_t)np + 1, sizeof(double)), t->pole_im = bg_xcalloc((size_t)np + 1, sizeof(double));
  t->zero_re = bg_xcalloc((size_t)nz + 1, sizeof(double)), t->zero_im = bg_xcalloc((size_t)nz + 1, sizeof(double));
  for (int i = 0; i < np; i++) t->pole_re[i] = p[i].re, t->pole_im[i] = p[i].im;
  for (int i = 0; i < nz; i++) t->zero_re[i] = z[i].re, t->zero_im[i] = z[i].im;
  t->den = poly_from_roots(p, np, 1), t->nden = np + 1;
  t->num = poly_from_roots(z, nz, K), t->nnum = nz + 1;
  double n0 = t->num[nz], d0 = t->den[np];
  t->dc_gain = d0 != 0 ? n0 / d0 : n0 != 0 ? copysign(INFINITY, n0) : NAN;
}

/* One pair; 0, or -1 when its zeros could not be found. */
static int pair_tf(const bg_linear *l, int iy, int iu, bg_lin_tf *t) {
  int n = sys_size(l), np = l->npole;
  cplx *p = bg_xcalloc((size_t)np + 1, sizeof *p), *z = bg_xcalloc((size_t)n + 2, sizeof *z);
  for (int i = 0; i < np; i++) p[i] = (cplx){l->pole_re[i], l->pole_im[i]};
  double rho = 1;
  for (int i = 0; i < np; i++) rho = fmax(rho, hypot(p[i].re, p[i].im));
  double complex s0 = rho * (0.6180339887 + 1.3247179572 * I), h = bg_lin_eval(l, iy, iu, s0);
  t->iy = iy, t->iu = iu;
  int nz = cabs(h) == 0 ? 0 : pair_zeros(l, iy, iu, z), rc = 0;
  if (cabs(h) == 0) np = 0; /* the input does not reach the output */
  else if (nz < 0 || !isfinite(cabs(h))) rc = -1;
  if (rc == 0) {
    t->ncancel = cancel(p, &np, z, &nz);
    double complex K = h * prod_diff(s0, p, np) / prod_diff(s0, z, nz);
    store(t, p, np, z, nz, cabs(h) == 0 ? 0 : creal(K));
  }
  free(p), free(z);
  return rc;
}

void bg_lin_tfs(bg_linear *l) {
  int n = sys_size(l);
  char buf[160];
  if (n > BG_LIN_MAX_TF || (n > 0 && l->npole == 0 && n > 500)) {
    snprintf(buf, sizeof buf, "%d states: transfer functions not computed (limit %d); the "
             "frequency responses are", n, BG_LIN_MAX_TF);
    l->tf_note = strdup(buf);
    return;
  }
  l->ntf = l->ny * l->nu;
  l->tf = bg_xcalloc((size_t)l->ntf + 1, sizeof *l->tf);
  for (int iy = 0; iy < l->ny; iy++)
    for (int iu = 0; iu < l->nu; iu++)
      if (pair_tf(l, iy, iu, &l->tf[iy * l->nu + iu]) && !l->tf_note) {
        snprintf(buf, sizeof buf, "the zeros of %s/%s could not be computed (singular system "
                 "matrix)", l->yname[iy], l->uname[iu]);
        l->tf_note = strdup(buf);
      }
}
