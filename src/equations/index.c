/* SPDX-License-Identifier: BSD-3-Clause */
/* Numeric index (Algorithm 4.1, the shuffle algorithm) and eigenvalues of
 * the linearised model A x' + B x = f. See index.h and docs/equations.md. */
#include <float.h>
#include "base/lapack.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/index.h"

#define AT(M, n, i, j) (M)[(size_t)(j) * (n) + (i)]

static void hist_add(bg_index_result *r, const char *buf) {
  r->hist = bg_xrealloc(r->hist, (size_t)(r->nhist + 1) * sizeof *r->hist);
  r->hist[r->nhist] = bg_xmalloc(strlen(buf) + 1);
  strcpy(r->hist[r->nhist++], buf);
}

/* Curtis-Reid scaling of the pencil: row factors r, column factors c (shared
 * by A and B: they act on the same unknowns) and a time scale t for A that
 * make every nonzero of diag(r) [t A, B] diag(c) as close to 1 as possible
 * in the least-squares sense of the logarithms. Max-norm equilibration is
 * not enough: with C = 1e-9 and R = 1e6 a matrix can have every row and
 * column max equal to 1 and still keep its information in entries of 1e-15
 * (the rows of a class 2 block cancel to rounding). Factors are powers of 2,
 * so the scaling itself is exact. Gauss-Seidel sweeps, O(nnz) each.
 * Returns the time scale t: eigenvalues of the scaled pencil are lambda / t. */
typedef struct lent { int i, j, a; double lg; } lent;

static double curtis_reid(double *A, double *B, int n) {
  lent *L = bg_xmalloc(((size_t)2 * n * n + 1) * sizeof *L);
  int nz = 0, na = 0;
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++)
      for (int a = 0; a < 2; a++) {
        double v = fabs(AT(a ? A : B, n, i, j));
        if (v > 0 && isfinite(v)) L[nz++] = (lent){i, j, a, log2(v)}, na += a;
      }
  double *r = bg_xcalloc((size_t)n + 1, sizeof *r), *c = bg_xcalloc((size_t)n + 1, sizeof *c);
  double *acc = bg_xcalloc((size_t)n + 1, sizeof *acc), t = 0;
  int *cnt = bg_xcalloc((size_t)n + 1, sizeof *cnt);
  for (int sweep = 0; sweep < 60 && nz; sweep++) {
    for (int pass = 0; pass < 3; pass++) { /* rows, columns, time scale */
      if (pass == 2) {
        double sum = 0;
        for (int k = 0; k < nz; k++)
          if (L[k].a) sum += L[k].lg + r[L[k].i] + c[L[k].j];
        if (na) t = -sum / na;
        continue;
      }
      memset(acc, 0, (size_t)n * sizeof *acc), memset(cnt, 0, (size_t)n * sizeof *cnt);
      for (int k = 0; k < nz; k++) {
        int who = pass ? L[k].j : L[k].i;
        acc[who] += L[k].lg + (pass ? r[L[k].i] : c[L[k].j]) + (L[k].a ? t : 0);
        cnt[who]++;
      }
      for (int q = 0; q < n; q++)
        if (cnt[q]) (pass ? c : r)[q] = -acc[q] / cnt[q];
    }
  }
  /* each factor rounded on its own: a diagonal scaling, exactly */
  double ts = ldexp(1.0, (int)lround(t));
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) {
      double f = ldexp(1.0, (int)lround(r[i])) * ldexp(1.0, (int)lround(c[j]));
      AT(A, n, i, j) *= f * ts, AT(B, n, i, j) *= f;
    }
  free(L), free(r), free(c), free(acc), free(cnt);
  return ts;
}

/* Scales rows of [A B] by their max, then columns (both matrices together),
 * after the Curtis-Reid scaling: entries at most 1 for the rank tests.
 * Returns the time scale applied to A. */
static double equilibrate_pair(double *A, double *B, int n) {
  double ts = curtis_reid(A, B, n);
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
  return ts;
}

/* Equilibrated copy of M into E: rows by their max (only when `rows`), then
 * columns. Column scaling leaves the left null space unchanged. */
static void equilibrate(const double *M, double *E, int n, int rows) {
  memcpy(E, M, (size_t)n * n * sizeof *E);
  for (int i = 0; i < n && rows; i++) {
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
 * U (optional, n x n) receives the left singular vectors; the copy is then
 * scaled by columns only (the caller has scaled the rows), so that U^T M
 * has (numerically) zero rows below the rank. */
static int svd_rank(const double *M, int n, double *U, double *smin, double *smax) {
  double *E = bg_xmalloc((size_t)n * n * sizeof *E), *S = bg_xmalloc((size_t)n * sizeof *S);
  double *VT = bg_xmalloc(sizeof *VT), *sup = bg_xmalloc((size_t)n * sizeof *sup);
  equilibrate(M, E, n, U == NULL);
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

/* Finite generalized eigenvalues of lambda A v = -B v, for A scaled by ts
 * (the eigenvalues of the unscaled pencil are ts times those of this one). */
static void eigen(bg_index_result *r, const double *A0, const double *B0, int n, double ts) {
  double *A = bg_xmalloc((size_t)n * n * sizeof *A), *B = bg_xmalloc((size_t)n * n * sizeof *B);
  double *ar = bg_xmalloc((size_t)n * sizeof *ar), *ai = bg_xmalloc((size_t)n * sizeof *ai);
  double *be = bg_xmalloc((size_t)n * sizeof *be), *pairs = bg_xmalloc((size_t)2 * n * sizeof *pairs);
  for (size_t q = 0; q < (size_t)n * n; q++) A[q] = A0[q], B[q] = -B0[q];
  int info = LAPACKE_dggev(LAPACK_COL_MAJOR, 'N', 'N', n, B, n, A, n, ar, ai, be, NULL, 1, NULL, 1);
  r->neig = 0;
  for (int k = 0; info == 0 && k < n; k++) {
    double mag = fmax(hypot(ar[k], ai[k]), fabs(be[k]));
    /* dggev gives a complex pair as (k, k+1) with alphai(k) > 0; each has its
     * own beta, so the two quotients can differ in the last bits and sort
     * apart. One quotient for both keeps the pair exactly conjugate. */
    int pair = ai[k] > 0 && k + 1 < n;
    if (fabs(be[k]) <= 1e3 * n * DBL_EPSILON * mag) { k += pair; continue; } /* infinite */
    double re = ts * ar[k] / be[k], im = ts * ai[k] / be[k];
    if (fabs(im) <= 1e-13 * fabs(re)) im = 0;
    re += 0.0, im += 0.0; /* no -0 in reports */
    pairs[2 * r->neig] = re, pairs[2 * r->neig + 1] = im, r->neig++;
    if (pair) pairs[2 * r->neig] = re, pairs[2 * r->neig + 1] = -im + 0.0, r->neig++, k++;
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
  double ts = equilibrate_pair(A, B, n);
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
    if (r->index == 0 || r->index == 1) eigen(r, A, B, n, ts);
  }
  free(A), free(B), free(U), free(T);
  return r->index;
}

/* Largest residual of the algebraic rows (constraints, algebraic unknowns)
 * relative to 1 + |y|; HUGE_VAL when the residual cannot be evaluated. */
static double alg_residual(bg_eqsys *s, double t, const double *y, double *yp, double *r) {
  int n = bg_eqsys_n(s);
  memset(yp, 0, (size_t)n * sizeof *yp);
  if (bg_eqsys_residual(s, t, y, yp, r)) return HUGE_VAL;
  double mx = 0;
  for (int i = bg_eqsys_nx(s); i < n; i++) mx = fmax(mx, fabs(r[i]) / (1 + fabs(y[i])));
  return mx;
}

/* Consistent initial values for the linearisation. When Newton from the
 * model's guess stops at an exactly singular matrix (a cubic conductance at
 * e = 0, a symmetric start), the algebraic unknowns are moved off the point
 * deterministically and Newton runs again, a few times at most: linearised
 * at an inconsistent point, f = e^3 has slope 0 and the index would read 2. */
static void start_point(bg_eqsys *s, double t0, double *y, double *yp) {
  int n = bg_eqsys_n(s), nx = bg_eqsys_nx(s);
  double *r = bg_xmalloc(((size_t)n + 1) * sizeof *r), *best = bg_xmalloc(((size_t)n + 1) * sizeof *best);
  bg_eqsys_initial(s, y);
  double rb = alg_residual(s, t0, y, yp, r);
  memcpy(best, y, (size_t)n * sizeof *y);
  unsigned seed = 12345u;
  for (int k = 0; k < 3 && rb > 1e-10 && n > nx; k++) {
    for (int i = nx; i < n; i++) {
      seed = seed * 1103515245u + 12345u;
      y[i] = best[i] + (0.05 + 0.1 * ((seed >> 8) & 0xffff) / 65536.0) * (1 + fabs(best[i]));
    }
    bg_eqsys_consistent(s, t0, y, 30);
    double rk = alg_residual(s, t0, y, yp, r);
    if (rk < rb) rb = rk, memcpy(best, y, (size_t)n * sizeof *y);
  }
  memcpy(y, best, (size_t)n * sizeof *y);
  memset(yp, 0, (size_t)n * sizeof *yp);
  free(r), free(best);
}

int bg_index_compute(bg_eqsys *s, const bg_model *m, bg_index_result *out) {
  int n = bg_eqsys_n(s);
  double t0 = m->sim.present ? m->sim.t0 : 0;
  size_t nn = (size_t)n * n + 1;
  double *y = bg_xcalloc((size_t)n + 1, sizeof *y), *yp = bg_xcalloc((size_t)n + 1, sizeof *yp);
  double *A = bg_xmalloc(nn * sizeof *A), *B = bg_xmalloc(nn * sizeof *B);
  start_point(s, t0, y, yp);
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

bg_eig_kind bg_index_eig_kind(const bg_index_result *r, int k) {
  double big = 0;
  for (int j = 0; j < r->neig; j++) big = fmax(big, hypot(r->eig_re[j], r->eig_im[j]));
  double tol = BG_EIG_ZERO_REL * big, re = r->eig_re[k];
  if (hypot(re, r->eig_im[k]) <= tol) return BG_EIG_ZERO;
  if (fabs(re) <= tol) return BG_EIG_UNDAMPED;
  return re > 0 ? BG_EIG_UNSTABLE : BG_EIG_DECAYING;
}

const char *bg_index_eig_word(bg_eig_kind kind) {
  switch (kind) {
  case BG_EIG_ZERO: return "zero (a conserved quantity)";
  case BG_EIG_UNDAMPED: return "undamped";
  case BG_EIG_UNSTABLE: return "unstable";
  default: return "decaying";
  }
}

void bg_index_report(const bg_index_result *r, bg_strbuf *out) {
  bg_sb_printf(out, "%s\n", r->message ? r->message : "");
  for (int k = 0; k < r->nhist; k++) bg_sb_printf(out, "  %s\n", r->hist[k]);
  for (int k = 0; k < r->neig; k++) {
    bg_eig_kind kind = bg_index_eig_kind(r, k);
    if (r->eig_im[k] == 0) bg_sb_printf(out, "  eigenvalue %.6g", r->eig_re[k]);
    else bg_sb_printf(out, "  eigenvalue %.6g %c %.6gi", r->eig_re[k], r->eig_im[k] < 0 ? '-' : '+', fabs(r->eig_im[k]));
    bg_sb_printf(out, kind == BG_EIG_DECAYING ? "\n" : " (%s)\n", bg_index_eig_word(kind));
  }
}

/* The numeric index is computed from the equations themselves (Algorithm
 * 4.1 at the initial point); the prediction reads the causal pattern, which
 * cannot see every constraint: under Lagrange causality the balances at the
 * artificial sources are not causal paths, so a constraint among the states
 * that forms through them (loop_class1: both balances determine L.p' alone)
 * shows only in the equations. So the numeric index is the one to use. */
char *bg_index_disagreement(const bg_analysis *a, const bg_index_result *r) {
  int p = a->index_predicted, k = r->index;
  if (p < 0 || k == BG_INDEX_FAILED || k == p || (p >= 2 && k >= 2)) return NULL;
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "the index predicted from the causal pattern is %s, the numeric index of the "
                    "equations ", p >= 2 ? "above 1" : p == 1 ? "1" : "0");
  if (k == BG_INDEX_SINGULAR) bg_sb_puts(&sb, "is undefined (a singular pencil)");
  else bg_sb_printf(&sb, "is %d", k);
  bg_sb_puts(&sb, "; the numeric index is computed from the equations themselves and is the one "
                  "to use");
  if (k > p && a->method == BG_METHOD_LAGRANGE)
    bg_sb_puts(&sb, " (under Lagrange causality the balances at the artificial flow sources are "
                    "not causal paths, so a constraint among the states that forms through them "
                    "is not in the causal pattern)");
  else if (k > p)
    bg_sb_puts(&sb, " (the equations hold a constraint the causal paths and loops do not show)");
  else
    bg_sb_puts(&sb, " (the structure the prediction reads cancels in the equations at these values)");
  if (k >= 2 || k == BG_INDEX_SINGULAR) bg_sb_puts(&sb, "; a simulation is refused");
  char *msg = strdup(bg_sb_str(&sb));
  bg_sb_free(&sb);
  return msg;
}

int bg_index_facts_numeric_set(const bg_index_facts *f) {
  return f && f->numeric && f->numeric->index != BG_INDEX_FAILED;
}
