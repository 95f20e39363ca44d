/* Numeric index (Algorithm 4.1, the shuffle algorithm) and eigenvalues of
 * the linearised model A x' + B x = f. See index.h and docs/equations.md. */
#include <float.h>
#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "index.h"

#define AT(M, n, i, j) (M)[(size_t)(j) * (n) + (i)]

static void hist_add(bg_index_result *r, const char *buf) {
  r->hist = bg_xrealloc(r->hist, (size_t)(r->nhist + 1) * sizeof *r->hist);
  r->hist[r->nhist] = bg_xmalloc(strlen(buf) + 1);
  strcpy(r->hist[r->nhist++], buf);
}

/* Scales rows of [A B] by their max, then columns (both matrices together). */
static void equilibrate_pair(double *A, double *B, int n) {
  for (int i = 0; i < n; i++) {
    double mx = 0;
    for (int j = 0; j < n; j++) mx = fmax(mx, fmax(fabs(AT(A, n, i, j)), fabs(AT(B, n, i, j))));
    if (mx > 0)
      for (int j = 0; j < n; j++) AT(A, n, i, j) /= mx, AT(B, n, i, j) /= mx;
  }
  for (int j = 0; j < n; j++) {
    double mx = 0;
    for (int i = 0; i < n; i++) mx = fmax(mx, fmax(fabs(AT(A, n, i, j)), fabs(AT(B, n, i, j))));
    if (mx > 0)
      for (int i = 0; i < n; i++) AT(A, n, i, j) /= mx, AT(B, n, i, j) /= mx;
  }
}

/* Equilibrated copy of M (rows, then columns, by their max) into E. */
static void equilibrate(const double *M, double *E, int n) {
  memcpy(E, M, (size_t)n * n * sizeof *E);
  for (int i = 0; i < n; i++) {
    double mx = 0;
    for (int j = 0; j < n; j++) mx = fmax(mx, fabs(AT(E, n, i, j)));
    if (mx > 0)
      for (int j = 0; j < n; j++) AT(E, n, i, j) /= mx;
  }
  for (int j = 0; j < n; j++) {
    double mx = 0;
    for (int i = 0; i < n; i++) mx = fmax(mx, fabs(AT(E, n, i, j)));
    if (mx > 0)
      for (int i = 0; i < n; i++) AT(E, n, i, j) /= mx;
  }
}

/* Rank of M by SVD of its equilibrated copy: sigma > 1e3 n eps sigma_max.
 * U (optional, n x n) receives the left singular vectors of the row-scaled
 * matrix' compression, rowscale the row factors used. */
static int svd_rank(const double *M, int n, double *U, double *smin, double *smax) {
  double *E = bg_xmalloc((size_t)n * n * sizeof *E), *S = bg_xmalloc((size_t)n * sizeof *S);
  double *VT = bg_xmalloc(sizeof *VT), *sup = bg_xmalloc((size_t)n * sizeof *sup);
  equilibrate(M, E, n);
  int info = LAPACKE_dgesvd(LAPACK_COL_MAJOR, U ? 'A' : 'N', 'N', n, n, E, n, S, U, n, VT, 1, sup);
  int rank = 0;
  if (info == 0)
    for (int k = 0; k < n; k++)
      if (S[k] > 1e3 * n * DBL_EPSILON * S[0]) rank++;
  *smax = n ? S[0] : 0;
  *smin = n ? S[n - 1] : 0;
  free(E), free(S), free(VT), free(sup);
  return info == 0 ? rank : -1;
}

static int regular(bg_index_result *r, const double *A, const double *B, int n) {
  static const double lam[2] = {0.7316482, -1.9130557}; /* fixed "random" values */
  double *P = bg_xmalloc((size_t)n * n * sizeof *P), smin, smax;
  int full = 0;
  for (int k = 0; k < 2 && !full; k++) {
    for (size_t q = 0; q < (size_t)n * n; q++) P[q] = lam[k] * A[q] + B[q];
    int rk = svd_rank(P, n, NULL, &smin, &smax);
    char buf[200];
    snprintf(buf, sizeof buf, "regularity %d: rank(lambda A + B) = %d of %d (lambda %.7g, sigma_min/sigma_max %.3g)",
             k + 1, rk, n, lam[k], smax > 0 ? smin / smax : 0);
    hist_add(r, buf);
    full = rk == n;
  }
  free(P);
  return full;
}

/* Row scaling of [A B] by the rows' max, so the compression sees equal rows. */
static void scale_rows(double *A, double *B, int n) {
  for (int i = 0; i < n; i++) {
    double mx = 0;
    for (int j = 0; j < n; j++) mx = fmax(mx, fmax(fabs(AT(A, n, i, j)), fabs(AT(B, n, i, j))));
    if (mx > 0)
      for (int j = 0; j < n; j++) AT(A, n, i, j) /= mx, AT(B, n, i, j) /= mx;
  }
}

/* One shuffle step: U^T [A B] = [A1 B1; ~0 B2] -> A = [A1; B2], B = [B1; 0]. */
static void shuffle(double *A, double *B, const double *U, int n, int rank, double *T) {
  for (int pass = 0; pass < 2; pass++) {
    double *M = pass ? B : A;
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++) {
        double acc = 0;
        for (int k = 0; k < n; k++) acc += AT(U, n, k, i) * AT(M, n, k, j);
        AT(T, n, i, j) = acc;
      }
    memcpy(M, T, (size_t)n * n * sizeof *T);
  }
  for (int i = rank; i < n; i++)
    for (int j = 0; j < n; j++) AT(A, n, i, j) = AT(B, n, i, j), AT(B, n, i, j) = 0;
}

static int cmp_eig(const void *pa, const void *pb) {
  const double *a = pa, *b = pb;
  if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
  return a[1] < b[1] ? -1 : a[1] > b[1];
}

/* Finite generalized eigenvalues of lambda A v = -B v. */
static void eigen(bg_index_result *r, const double *A0, const double *B0, int n) {
  double *A = bg_xmalloc((size_t)n * n * sizeof *A), *B = bg_xmalloc((size_t)n * n * sizeof *B);
  double *ar = bg_xmalloc((size_t)n * sizeof *ar), *ai = bg_xmalloc((size_t)n * sizeof *ai);
  double *be = bg_xmalloc((size_t)n * sizeof *be), *pairs = bg_xmalloc((size_t)2 * n * sizeof *pairs);
  for (size_t q = 0; q < (size_t)n * n; q++) A[q] = A0[q], B[q] = -B0[q];
  int info = LAPACKE_dggev(LAPACK_COL_MAJOR, 'N', 'N', n, B, n, A, n, ar, ai, be, NULL, 1, NULL, 1);
  r->neig = 0;
  for (int k = 0; info == 0 && k < n; k++) {
    double mag = fmax(hypot(ar[k], ai[k]), fabs(be[k]));
    if (fabs(be[k]) <= 1e3 * n * DBL_EPSILON * mag) continue; /* infinite */
    double re = ar[k] / be[k], im = ai[k] / be[k];
    if (fabs(im) <= 1e-13 * fabs(re)) im = 0;
    re += 0.0, im += 0.0; /* no -0 in reports */
    pairs[2 * r->neig] = re, pairs[2 * r->neig + 1] = im, r->neig++;
  }
  qsort(pairs, (size_t)r->neig, 2 * sizeof *pairs, cmp_eig);
  r->eig_re = bg_xmalloc((size_t)(r->neig + 1) * sizeof(double));
  r->eig_im = bg_xmalloc((size_t)(r->neig + 1) * sizeof(double));
  for (int k = 0; k < r->neig; k++) r->eig_re[k] = pairs[2 * k], r->eig_im[k] = pairs[2 * k + 1];
  free(A), free(B), free(ar), free(ai), free(be), free(pairs);
}

static void set_msg(bg_index_result *r, const char *msg) {
  free(r->message);
  r->message = bg_xmalloc(strlen(msg) + 1);
  strcpy(r->message, msg);
}

int bg_index_pencil(const double *A0, const double *B0, int n, bg_index_result *r) {
  memset(r, 0, sizeof *r);
  r->n = n;
  size_t nn = (size_t)n * n + 1;
  double *A = bg_xmalloc(nn * sizeof *A), *B = bg_xmalloc(nn * sizeof *B);
  double *U = bg_xmalloc(nn * sizeof *U), *T = bg_xmalloc(nn * sizeof *T), smin, smax;
  memcpy(A, A0, (nn - 1) * sizeof *A), memcpy(B, B0, (nn - 1) * sizeof *B);
  equilibrate_pair(A, B, n);
  r->index = BG_INDEX_SINGULAR;
  if (n == 0) r->index = 0;
  else if (!regular(r, A, B, n)) {
    set_msg(r, "singular pencil: lambda A + B is rank deficient for every lambda tried");
  } else {
    double *A1 = bg_xmalloc(nn * sizeof *A1), *B1 = bg_xmalloc(nn * sizeof *B1);
    memcpy(A1, A, nn * sizeof *A), memcpy(B1, B, nn * sizeof *B);
    for (int k = 0; k <= n; k++) {
      scale_rows(A1, B1, n);
      int rk = svd_rank(A1, n, U, &smin, &smax);
      char buf[200];
      snprintf(buf, sizeof buf, "step %d: rank A = %d of %d (sigma_min/sigma_max %.3g)", k, rk, n,
               smax > 0 ? smin / smax : 0);
      hist_add(r, buf);
      if (rk < 0) break;
      if (rk == n) {
        r->index = k;
        break;
      }
      shuffle(A1, B1, U, n, rk, T);
    }
    free(A1), free(B1);
    char buf[128];
    if (r->index >= 0) snprintf(buf, sizeof buf, "A of full rank after %d reduction step%s; %d unknowns",
                             r->index, r->index == 1 ? "" : "s", n);
    else snprintf(buf, sizeof buf, "no index found within %d steps: singular", n + 1);
    set_msg(r, buf);
    if (r->index == 0 || r->index == 1) eigen(r, A, B, n);
  }
  free(A), free(B), free(U), free(T);
  return r->index;
}

int bg_index_compute(bg_eqsys *s, const bg_model *m, bg_index_result *out) {
  int n = bg_eqsys_n(s);
  double t0 = m->sim.present ? m->sim.t0 : 0;
  size_t nn = (size_t)n * n + 1;
  double *y = bg_xcalloc((size_t)n + 1, sizeof *y), *yp = bg_xcalloc((size_t)n + 1, sizeof *yp);
  double *A = bg_xmalloc(nn * sizeof *A), *B = bg_xmalloc(nn * sizeof *B);
  bg_eqsys_initial(s, y);
  if (bg_eqsys_linearise(s, t0, y, yp, A, B)) {
    memset(out, 0, sizeof *out);
    out->n = n;
    out->index = BG_INDEX_FAILED;
    char buf[400];
    snprintf(buf, sizeof buf, "cannot linearise at the initial point: %s", bg_eqsys_error(s));
    set_msg(out, buf);
  } else {
    bg_index_pencil(A, B, n, out);
  }
  free(y), free(yp), free(A), free(B);
  return out->index;
}

void bg_index_free(bg_index_result *r) {
  for (int k = 0; k < r->nhist; k++) free(r->hist[k]);
  free(r->hist), free(r->eig_re), free(r->eig_im), free(r->message);
  memset(r, 0, sizeof *r);
}

void bg_index_report(const bg_index_result *r, bg_strbuf *out) {
  bg_sb_printf(out, "%s\n", r->message ? r->message : "");
  for (int k = 0; k < r->nhist; k++) bg_sb_printf(out, "  %s\n", r->hist[k]);
  for (int k = 0; k < r->neig; k++) {
    if (r->eig_im[k] == 0) bg_sb_printf(out, "  eigenvalue %.6g\n", r->eig_re[k]);
    else bg_sb_printf(out, "  eigenvalue %.6g %c %.6gi\n", r->eig_re[k], r->eig_im[k] < 0 ? '-' : '+', fabs(r->eig_im[k]));
  }
}
