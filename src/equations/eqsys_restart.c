/* SPDX-License-Identifier: BSD-3-Clause */
/* Consistent rates at a restart of a DAE with dependent stores (eqsys.h,
 * bg_eqsys_restart_rates; docs/simulation.md, "Restarts"). IDACalcIC holds
 * every differential unknown and moves the rates: a dependent store's
 * constraint reads no rate, so its residual, however small, is a part of
 * the Newton residual nothing can reduce, and IDACalcIC scales it by 1/h of
 * its look-ahead; after an input step or a state event it then reports a
 * failed line search or slow convergence, depending on rounding (the
 * order of the equations: docs/property.md, findings 2c, 4 and 9). Here
 * the constraints are replaced by their time derivatives, which read the
 * rates, and the rates and algebraic unknowns are solved for with the
 * states held. */
#include "base/lapack.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsys_int.h"

typedef struct rates {
  bg_eqsys *s;
  int n, nx;
  double t, *y, *yp, *J0, *J1, *dgdt, *G, *M, *du;
  int *piv;
} rates;

static int is_constraint(const rates *W, int i) { return i < W->nx && W->s->row_kind[i] == 1; }

/* The unknown k of the solve: the rate of differential unknown k, or the
 * algebraic unknown k itself. */
static double *unknown(rates *W, int k) { return k < W->nx ? &W->yp[k] : &W->y[k]; }

/* G at the current point: the rows, the constraints' time derivatives in
 * their place (J0 = dF/dy there). Also the Jacobians at that point. */
static int eval(rates *W) {
  int n = W->n;
  if (bg_eqsys_jac_dense(W->s, W->t, W->y, W->yp, 0.0, W->J0) ||
      bg_eqsys_jac_dense(W->s, W->t, W->y, W->yp, 1.0, W->J1) ||
      bg_eqsys_residual(W->s, W->t, W->y, W->yp, W->G))
    return -1;
  for (int i = 0; i < n; i++) {
    if (!is_constraint(W, i)) continue;
    double d = W->dgdt[i];
    for (int j = 0; j < W->nx; j++) d += W->J0[(size_t)j * n + i] * W->yp[j];
    W->G[i] = d;
  }
  return 0;
}

static double max_abs(const double *v, int n) {
  double mx = 0;
  for (int i = 0; i < n; i++) mx = fmax(mx, fabs(v[i]));
  return mx;
}

/* The constraints' partial derivative in time at fixed y, one-sided from
 * the right (a restart sits at an input's jump), second order; from the
 * left for h < 0 (an output row just before a jump). */
static int constraints_dt(rates *W, double h) {
  int n = W->n;
  double *r0 = bg_xmalloc((size_t)n * sizeof(double)), *r1 = bg_xmalloc((size_t)n * sizeof(double));
  double *r2 = bg_xmalloc((size_t)n * sizeof(double));
  int rc = bg_eqsys_residual(W->s, W->t, W->y, W->yp, r0) || bg_eqsys_residual(W->s, W->t + h, W->y, W->yp, r1) ||
           bg_eqsys_residual(W->s, W->t + 2 * h, W->y, W->yp, r2);
  for (int i = 0; i < n && !rc; i++) W->dgdt[i] = is_constraint(W, i) ? (-3 * r0[i] + 4 * r1[i] - r2[i]) / (2 * h) : 0;
  free(r0), free(r1), free(r2);
  return rc ? -1 : 0;
}

/* Newton on G with step halving; 0 when it converged. */
static int solve(rates *W) {
  int n = W->n;
  if (eval(W)) return -1;
  for (int it = 0; it < 20; it++) {
    double g0 = max_abs(W->G, n);
    for (int i = 0; i < n; i++) {
      for (int k = 0; k < n; k++) { /* column k: d G_i / d unknown k */
        double dy = W->J0[(size_t)k * n + i], dyp = W->J1[(size_t)k * n + i] - dy;
        W->M[(size_t)k * n + i] = k < W->nx ? (is_constraint(W, i) ? dy : dyp) : (is_constraint(W, i) ? 0 : dy);
      }
      W->du[i] = -W->G[i];
    }
    if (LAPACKE_dgesv(LAPACK_COL_MAJOR, n, 1, W->M, n, W->piv, W->du, n) != 0) return -1;
    double step = max_abs(W->du, n), umax = 0, lam = 1;
    for (int k = 0; k < n; k++) umax = fmax(umax, fabs(*unknown(W, k)));
    for (int hv = 0;; hv++, lam /= 2) {
      for (int k = 0; k < n; k++) *unknown(W, k) += lam * W->du[k];
      if (eval(W) == 0 && max_abs(W->G, n) < g0 * (1 + 1e-12) + 1e-300) break;
      for (int k = 0; k < n; k++) *unknown(W, k) -= lam * W->du[k];
      if (hv == 11) return eval(W) == 0 && g0 <= 1e-12 * (1 + umax) ? 0 : -1;
    }
    if (lam * step <= 1e-13 * (1 + umax)) return max_abs(W->G, n) <= 1e-8 * (1 + umax) ? 0 : -1;
  }
  return -1;
}

static void rates_open(rates *W, bg_eqsys *s, double t, const double *y, const double *yp) {
  int n = s->n;
  size_t nn = (size_t)n * n;
  *W = (rates){s, n, s->nx, t, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
  W->y = bg_xmalloc((size_t)n * sizeof(double)), W->yp = bg_xmalloc((size_t)n * sizeof(double));
  memcpy(W->y, y, (size_t)n * sizeof(double)), memcpy(W->yp, yp, (size_t)n * sizeof(double));
  W->J0 = bg_xmalloc(nn * sizeof(double)), W->J1 = bg_xmalloc(nn * sizeof(double)), W->M = bg_xmalloc(nn * sizeof(double));
  W->dgdt = bg_xmalloc((size_t)n * sizeof(double)), W->G = bg_xmalloc((size_t)n * sizeof(double));
  W->du = bg_xmalloc((size_t)n * sizeof(double)), W->piv = bg_xmalloc((size_t)n * sizeof(int));
}

static void rates_close(rates *W) {
  free(W->y), free(W->yp), free(W->J0), free(W->J1), free(W->M), free(W->dgdt), free(W->G), free(W->du), free(W->piv);
  W->s->has_err = 0;
}

static int dependent_stores(const bg_eqsys *s) {
  int nd = 0;
  for (int i = 0; i < s->nx && !s->reduced; i++) nd += s->row_kind[i] == 1;
  return nd;
}

/* 1 when a constraint reads an algebraic unknown (W->J0 at the point): its
 * time derivative needs that unknown's rate too, which these solves lack. */
static int constraint_reads_algebraic(const rates *W) {
  for (int i = 0; i < W->nx; i++)
    for (int j = W->nx; j < W->n && is_constraint(W, i); j++)
      if (W->J0[(size_t)j * W->n + i] != 0) return 1;
  return 0;
}

/* The rates and algebraic unknowns from the rows that read a rate and the
 * constraints' time derivatives, the states held; 0 when Newton converged. */
static int solve_rates(rates *W, double h) {
  /* a constraint that reads an algebraic unknown would need its rate too:
   * not this solve's (IDACalcIC's failure stands) */
  int rc = bg_eqsys_jac_dense(W->s, W->t, W->y, W->yp, 0.0, W->J0);
  if (!rc && constraint_reads_algebraic(W)) rc = -1;
  if (!rc) rc = constraints_dt(W, h);
  if (!rc) rc = solve(W);
  return rc;
}

int bg_eqsys_restart_rates(bg_eqsys *s, double t, double *y, double *yp, double h) {
  int n = s->n;
  if (dependent_stores(s) == 0 || n > 1000 || !(h != 0) || !isfinite(h)) return -1;
  rates W;
  rates_open(&W, s, t, y, yp);
  int rc = bg_eqsys_consistent(s, t, W.y, 30);
  if (!rc) rc = solve_rates(&W, h);
  if (!rc) memcpy(y, W.y, (size_t)n * sizeof(double)), memcpy(yp, W.yp, (size_t)n * sizeof(double));
  rates_close(&W);
  return rc ? -1 : 0;
}

/* The largest violation of a constraint's time derivative, against the
 * size of its terms: |dg/dt + dg/dy y'| / (|dg/dt| + sum_j |dg/dy_j y'_j|). */
static double worst_rate_violation(rates *W) {
  int n = W->n;
  double worst = 0;
  for (int i = 0; i < n; i++) {
    if (!is_constraint(W, i)) continue;
    double d = W->dgdt[i], size = fabs(d);
    for (int j = 0; j < W->nx; j++) {
      double term = W->J0[(size_t)j * n + i] * W->yp[j];
      d += term, size += fabs(term);
    }
    worst = fmax(worst, fabs(d) / (size + 1e-300));
  }
  return worst;
}

int bg_eqsys_start_rates(bg_eqsys *s, double t, double *y, double *yp, double h) {
  int n = s->n;
  if (dependent_stores(s) == 0 || n > 1000 || !(h > 0)) return 0;
  rates W;
  rates_open(&W, s, t, y, yp);
  /* where the equations cannot be evaluated a moment later nothing is known
   * (0: the solver's own evaluation says why), nor where a constraint reads an
   * algebraic unknown (its time derivative reads that unknown's rate) */
  int rc = 0;
  if (bg_eqsys_jac_dense(s, t, W.y, W.yp, 0.0, W.J0) == 0 && !constraint_reads_algebraic(&W) &&
      constraints_dt(&W, h) == 0 && worst_rate_violation(&W) > BG_EQSYS_RATE_TOL) {
    rc = solve_rates(&W, h) == 0 ? 1 : -1;
    if (rc > 0) memcpy(y, W.y, (size_t)n * sizeof(double)), memcpy(yp, W.yp, (size_t)n * sizeof(double));
  }
  rates_close(&W);
  return rc;
}
