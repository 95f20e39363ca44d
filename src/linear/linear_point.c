/* SPDX-License-Identifier: BSD-3-Clause */
/* The operating point of the linear analysis: the initial point (consistent
 * initial values) or a steady state, Newton on F(t, y, 0) = 0 with the
 * inputs held at their values at t and the exact Jacobian dF/dy. A singular
 * Jacobian takes the minimum-norm step (dgelsd), so a family of steady
 * states (a free integrator) gives the member nearest the start, and the
 * message says so; two other starts tell whether other steady states are
 * likely (nonlinear models). */
#include <float.h>
#include "base/lapack.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

static double max_abs(const double *v, int n) {
  double r = 0;
  for (int i = 0; i < n; i++) r = fmax(r, fabs(v[i]));
  return r;
}

/* One Newton step dy solving Fy dy = -F; *singular set when the Jacobian has
 * rank below n (minimum-norm least-squares step then). */
static int newton_step(double *Fy, const double *F, int n, double *dy, int *singular) {
  *singular = 0;
  if (n == 0) return 0; /* LAPACK refuses n = 0 (its leading dimension must be >= 1) */
  double *J = bg_xmalloc((size_t)n * n * sizeof *J), *rhs = bg_xmalloc((size_t)n * sizeof *rhs);
  lapack_int *piv = bg_xmalloc((size_t)n * sizeof *piv);
  memcpy(J, Fy, (size_t)n * n * sizeof *J);
  for (int i = 0; i < n; i++) rhs[i] = -F[i];
  double anorm = LAPACKE_dlange(LAPACK_COL_MAJOR, '1', n, n, J, n), rcond = 0;
  int info = LAPACKE_dgetrf(LAPACK_COL_MAJOR, n, n, J, n, piv);
  if (info == 0) LAPACKE_dgecon(LAPACK_COL_MAJOR, '1', n, J, n, anorm, &rcond);
  *singular = info != 0 || rcond < 1e3 * n * DBL_EPSILON;
  if (!*singular) {
    LAPACKE_dgetrs(LAPACK_COL_MAJOR, 'N', n, 1, J, n, piv, rhs, n);
  } else { /* minimum-norm step: singular values below the rank threshold dropped */
    memcpy(J, Fy, (size_t)n * n * sizeof *J);
    double *sv = bg_xmalloc((size_t)n * sizeof *sv);
    lapack_int rank;
    info = LAPACKE_dgelsd(LAPACK_COL_MAJOR, n, n, 1, J, n, rhs, n, sv, 1e3 * n * DBL_EPSILON, &rank);
    free(sv);
  }
  memcpy(dy, rhs, (size_t)n * sizeof *dy);
  free(J), free(rhs), free(piv);
  return info == 0 ? 0 : -1;
}

static double resid_norm(bg_eqsys *s, double t, const double *y, const double *yp, double *F) {
  if (bg_eqsys_residual(s, t, y, yp, F)) return HUGE_VAL;
  return max_abs(F, bg_eqsys_n(s));
}

/* Newton from y (in place): 1 converged, 0 not, -1 evaluation failed. */
static int newton(bg_eqsys *s, double t, double *y, int *singular) {
  int n = bg_eqsys_n(s);
  double *F = bg_xcalloc((size_t)n, sizeof *F), *yp = bg_xcalloc((size_t)n, sizeof *yp);
  double *Fy = bg_xmalloc((size_t)n * n * sizeof *Fy), *dy = bg_xmalloc((size_t)n * sizeof *dy);
  double *yt = bg_xmalloc((size_t)n * sizeof *yt);
  double r = resid_norm(s, t, y, yp, F), r0 = r;
  int conv = r == 0, rc = isfinite(r) ? 0 : -1;
  for (int it = 0; it < 60 && !conv && rc == 0; it++) {
    if (bg_eqsys_jac_io(s, t, y, yp, Fy, NULL, NULL, NULL, NULL, NULL, NULL) ||
        newton_step(Fy, F, n, dy, singular)) { rc = -1; break; }
    double lam = 1, rt = HUGE_VAL;
    for (int h = 0; h < 30; h++, lam /= 2) { /* step halving on max |F| */
      for (int i = 0; i < n; i++) yt[i] = y[i] + lam * dy[i];
      rt = resid_norm(s, t, yt, yp, F);
      if (rt < r) break;
    }
    if (!(rt < r)) break; /* no decrease: stuck */
    memcpy(y, yt, (size_t)n * sizeof *y);
    double step = lam * max_abs(dy, n);
    r = rt;
    conv = r <= 1e-12 * fmax(r0, 1e-300) || r == 0 ||
           (step <= 1e-13 * (1 + max_abs(y, n)) && r <= 1e-9 * fmax(r0, DBL_MIN));
  }
  if (conv) { /* singularity at the solution itself */
    bg_eqsys_jac_io(s, t, y, yp, Fy, NULL, NULL, NULL, NULL, NULL, NULL);
    newton_step(Fy, F, n, dy, singular);
  }
  free(F), free(yp), free(Fy), free(dy), free(yt);
  return rc ? rc : conv;
}

/* Another start: every unknown moved by (1 + |y|) in a fixed pattern. */
static void other_start(const double *y, double *y2, int n, int which) {
  for (int i = 0; i < n; i++)
    y2[i] = which == 0 ? -y[i] - 0.5 * (1 + fabs(y[i])) : y[i] + (i % 2 ? 1.5 : -1.25) * (1 + fabs(y[i]));
}

static int same_point(const double *a, const double *b, int n) {
  for (int i = 0; i < n; i++)
    if (fabs(a[i] - b[i]) > 1e-6 * (1 + fabs(a[i]) + fabs(b[i]))) return 0;
  return 1;
}

/* Other steady states reached from two other starts (a note, or none). */
static void check_unique(bg_eqsys *s, double t, const double *y, bg_strbuf *note) {
  int n = bg_eqsys_n(s), sing = 0;
  double *y2 = bg_xmalloc((size_t)n * sizeof *y2);
  for (int w = 0; w < 2; w++) {
    other_start(y, y2, n, w);
    if (newton(s, t, y2, &sing) == 1 && !same_point(y, y2, n)) {
      int i = 0;
      for (int k = 1; k < n; k++)
        if (fabs(y2[k] - y[k]) > fabs(y2[i] - y[i])) i = k;
      bg_sb_printf(note, "%sseveral steady states are likely: Newton from another start reached "
                   "%s = %.6g (here %.6g); the one reached from the initial point is used",
                   note->len ? "; " : "", bg_eqsys_name(s, i), y2[i], y[i]);
      break;
    }
  }
  free(y2);
}

int bg_lin_point(bg_eqsys *s, double t, int steady, double *y, bg_strbuf *note) {
  int n = bg_eqsys_n(s), sing = 0;
  bg_eqsys_initial(s, y);
  if (!steady || n == 0) return 0; /* no unknowns: the operating point is the inputs alone */
  int rc = newton(s, t, y, &sing);
  if (rc < 0) {
    bg_sb_printf(note, "no steady state found: %s", bg_eqsys_error(s) ? bg_eqsys_error(s)
                 : "the equations could not be evaluated");
    return -1;
  }
  if (rc == 0) {
    bg_sb_printf(note, "no steady state: Newton on F(t, y, 0) = 0 with the inputs held at "
                 "t = %g did not converge from the initial point (is some state driven "
                 "without a restoring term?)", t);
    return -1;
  }
  if (sing)
    bg_sb_printf(note, "the steady state is not unique (dF/dy is singular: a free integrator "
                 "or a floating part); the one nearest the initial point is used");
  else check_unique(s, t, y, note);
  (void)n;
  return 0;
}
