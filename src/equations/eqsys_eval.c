/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_eqsys evaluation entry points: initial values, right-hand side,
 * residual, exact Jacobians, linearisation, outputs, breakpoints. */
#include "base/lapack.h"
#include "base/sort.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsys_int.h"
#include "model/model.h"

int bg_eqsys_jac_dense(bg_eqsys *s, double t, const double *y, const double *yp, double cj,
                       double *J) {
  int ode = bg_eqsys_is_ode(s);
  if (bg_eqs_eval(s, t, y, ode ? NULL : yp, 0)) return -1;
  bg_eqs_jac(s, cj, !ode, J, 0, ode, 0);
  return 0;
}

int bg_eqsys_jac_nnz(const bg_eqsys *s) { return s->nnz; }

void bg_eqsys_jac_pattern(const bg_eqsys *s, int *colptr, int *rowind) {
  memcpy(colptr, s->colptr, (size_t)(s->n + 1) * sizeof(int));
  memcpy(rowind, s->rowind, (size_t)s->nnz * sizeof(int));
}

int bg_eqsys_jac_sparse(bg_eqsys *s, double t, const double *y, const double *yp, double cj,
                        double *values) {
  int ode = bg_eqsys_is_ode(s);
  if (bg_eqs_eval(s, t, y, ode ? NULL : yp, 0)) return -1;
  bg_eqs_jac(s, cj, !ode, values, 1, ode, 0);
  return 0;
}

int bg_eqsys_linearise(bg_eqsys *s, double t, const double *y, const double *yp, double *A,
                       double *B) {
  if (bg_eqs_eval(s, t, y, yp, 0)) return -1;
  bg_eqs_jac(s, 0, 1, A, 0, 0, 1);
  bg_eqs_jac(s, 0, 1, B, 0, 1, 0);
  return 0;
}

int bg_eqsys_outputs(bg_eqsys *s, double t, const double *y, const double *yp, double *out) {
  if (bg_eqs_eval_outputs(s, t, y, yp)) return -1;
  for (int k = 0; k < s->nout; k++) out[k] = s->v[s->out_slot[k]];
  return 0;
}

int bg_eqsys_signals(bg_eqsys *s, double t, const double *y, const double *yp, double *e,
                     double *f) {
  if (bg_eqs_eval(s, t, y, yp, 0)) return -1;
  for (int b = 0; b < s->m->nbond; b++) e[b] = s->v[s->sig_slot[2 * b]], f[b] = s->v[s->sig_slot[2 * b + 1]];
  return 0;
}

/* ------------------------------------------------------------ initial values */
static double init_value(const bg_model *m, int root, double t0) {
  if (root < 0) return 0;
  bg_xenv env = {t0, NULL, NULL, NULL, NULL, NULL};
  return bg_xeval(m, root, &env);
}

static double max_abs_alg(const bg_eqsys *s, const double *r) {
  double mx = 0;
  for (int i = 0; i < s->n; i++)
    if (s->row_kind[i] == 1 && fabs(r[i]) > mx) mx = fabs(r[i]);
  return mx;
}

/* Newton on the algebraic rows (constraints of dependent stores and the
 * residuals of torn variables) in their unknowns, states held, yp = 0:
 * the exact Jacobian, a dense solve, step halving when the residual grows. */
int bg_eqsys_consistent(bg_eqsys *s, double t, double *y, int maxit) {
  int n = s->n, na = 0;
  if (n == 0 || n > 3000 || s->reduced) return 0; /* reduced: bg_eqsys_initial_yp solves every row */
  int *ix = malloc((size_t)n * sizeof(int)), *piv = malloc((size_t)n * sizeof(int));
  double *yp = calloc((size_t)n, sizeof(double)), *r = malloc((size_t)n * sizeof(double));
  double *J = malloc((size_t)n * n * sizeof(double)), *M = malloc((size_t)n * n * sizeof(double));
  double *y1 = malloc((size_t)n * sizeof(double)), *rb = malloc((size_t)n * sizeof(double));
  for (int i = 0; i < n; i++)
    if (s->row_kind[i] == 1) ix[na++] = i;
  int ok = na == 0 || !bg_eqsys_residual(s, t, y, yp, r);
  for (int it = 0; ok && na && it < maxit && max_abs_alg(s, r) > 0; it++) {
    bg_eqs_jac(s, 0, 1, J, 0, 1, 0);
    for (int a = 0; a < na; a++) {
      rb[a] = -r[ix[a]];
      for (int b = 0; b < na; b++) M[(size_t)b * na + a] = J[(size_t)ix[b] * n + ix[a]];
    }
    if (LAPACKE_dgesv(LAPACK_COL_MAJOR, na, 1, M, na, piv, rb, na) != 0) break;
    double r0 = max_abs_alg(s, r), lam = 1, step = 0, ymax = 0;
    for (int a = 0; a < na; a++) step = fmax(step, fabs(rb[a])), ymax = fmax(ymax, fabs(y[ix[a]]));
    for (int h = 0; h < 12; h++, lam /= 2) {
      memcpy(y1, y, (size_t)n * sizeof *y);
      for (int a = 0; a < na; a++) y1[ix[a]] += lam * rb[a];
      if (!bg_eqsys_residual(s, t, y1, yp, r) && max_abs_alg(s, r) < r0 * (1 + 1e-12) + 1e-300) break;
    }
    memcpy(y, y1, (size_t)n * sizeof *y);
    ok = !bg_eqsys_residual(s, t, y, yp, r);
    if (max_abs_alg(s, r) >= r0 || step <= 1e-15 * (1 + ymax)) break;
  }
  /* a component whose solution is 0 at 0, not at Newton's 1e-32, whatever
   * the order of the equations (eqsys_lagstart.c; docs/property.md, finding
   * 26); this Newton steps down to 1e-15 of the largest, so from 1e-18,
   * of the largest alone: from rest every value a moment later is small, and
   * an absolute floor set the switching functions the modes' look-ahead
   * reads to 0 (finding 29: a law held on the wrong side for a whole run) */
  if (ok && na > 0) { /* (na > 0: GCC's -O1 could not see that a count is not negative) */
    double **u = bg_xmalloc((size_t)na * sizeof(double *));
    for (int a = 0; a < na; a++) u[a] = &y[ix[a]];
    bg_eqs_snap_zeros(s, t, y, yp, r, u, na, ix, na, 1e-18, 0.0);
    free(u);
  }
  free(ix), free(piv), free(yp), free(r), free(J), free(M), free(y1), free(rb);
  return ok ? 0 : -1;
}

void bg_eqsys_initial(const bg_eqsys *cs, double *y0) {
  double *yp0 = bg_xcalloc((size_t)cs->n + 1, sizeof *yp0);
  bg_eqsys_initial_yp(cs, y0, yp0);
  free(yp0);
}

void bg_eqsys_initial_yp(const bg_eqsys *cs, double *y0, double *yp0) {
  const bg_model *m = cs->m;
  double t0 = m->sim.present ? m->sim.t0 : 0;
  for (int i = 0; i < cs->n; i++) {
    y0[i] = 0, yp0[i] = 0;
    if (cs->u_elem[i] >= 0) y0[i] = init_value(m, m->elem_init[cs->u_elem[i]], t0);
    else if (cs->u_state[i] >= 0) y0[i] = init_value(m, m->state_init[cs->u_state[i]], t0);
  }
  /* The evaluation scratch is not observable state: solving for consistent
   * algebraic values leaves the system as it was. */
  bg_eqsys *s = (bg_eqsys *)cs;
  /* a reduced system holds its states and solves every row, the
   * differentiated constraints included, for the rest (like Lagrange's) */
  if (s->reduced) bg_eqs_lagrange_start(s, t0, y0, yp0, 30);
  else if (s->a->nlag == 0 || bg_eqs_lagrange_start(s, t0, y0, yp0, 30))
    bg_eqsys_consistent(s, t0, y0, 30);
  s->has_err = 0;
}

/* ------------------------------------------------------------ breakpoints */
typedef struct bpl { double *v; int n, cap; } bpl;
static void bp_add(bpl *L, double x) {
  if (!isfinite(x)) return;
  if (L->n == L->cap) {
    L->cap = L->cap ? 2 * L->cap : 16;
    L->v = bg_xrealloc(L->v, (size_t)L->cap * sizeof *L->v);
  }
  L->v[L->n++] = x;
}

/* x = t + off? Constants are what evaluates without any variable. */
static int affine_t(const bg_model *m, int x, double *off) {
  const bg_xnode *n = &m->xnode[x];
  if (n->op == BG_X_TIME) return *off = 0, 1;
  if (n->op != BG_X_ADD && n->op != BG_X_SUB) return 0;
  const bg_xnode *l = &m->xnode[n->arg[0]], *r = &m->xnode[n->arg[1]];
  if (l->op == BG_X_TIME) {
    double c = bg_xeval(m, n->arg[1], NULL);
    if (!isfinite(c)) return 0;
    *off = n->op == BG_X_SUB ? c : -c;
    return 1;
  }
  if (r->op == BG_X_TIME && n->op == BG_X_ADD) {
    double c = bg_xeval(m, n->arg[0], NULL);
    if (!isfinite(c)) return 0;
    *off = -c;
    return 1;
  }
  return 0;
}

static void bp_walk(const bg_model *m, int root, bpl *L) {
  const bg_xnode *n = &m->xnode[root];
  double off;
  if (n->op == BG_X_CALL && n->nargs >= 1 && affine_t(m, n->arg[0], &off)) {
    if (n->ref == BG_FN_STEP || n->ref == BG_FN_RAMP || n->ref == BG_FN_PULSE) bp_add(L, off);
    if (n->ref == BG_FN_PULSE) bp_add(L, off + bg_xeval(m, n->arg[1], NULL));
  }
  if (n->op == BG_X_TABLE && affine_t(m, n->arg[0], &off))
    for (int k = 0; k < m->table_n[n->ref]; k++) bp_add(L, off + m->table_x[m->table_adr[n->ref] + k]);
  if (n->op == BG_X_INPUT) bp_walk(m, m->input_expr[n->ref], L);
  else if (n->op != BG_X_NUM)
    for (int k = 0; k < n->nargs; k++) bp_walk(m, n->arg[k], L);
}

int bg_eqsys_breakpoints(const bg_eqsys *s, double t0, double t1, double *times, int max) {
  const bg_model *m = s->m;
  bpl L = {0};
  for (int e = 0; e < m->nelem; e++)
    if (bg_elem_is_source(m->elem_kind[e]) && m->elem_expr[e] >= 0) bp_walk(m, m->elem_expr[e], &L);
  for (int k = 0; k < m->ninput; k++) bp_walk(m, m->input_expr[k], &L);
  if (L.n) bg_sort_doubles(L.v, (size_t)L.n);
  int cnt = 0;
  for (int i = 0; i < L.n; i++) {
    if (!(L.v[i] > t0 && L.v[i] < t1)) continue;
    if (cnt && times[cnt - 1] == L.v[i]) continue;
    if (cnt < max) times[cnt++] = L.v[i];
  }
  free(L.v);
  return cnt;
}

/* ------------------------------------------------------------ input periods */
/* The angular rate |d arg/dt| of a periodic function of time at t, by a
 * central difference; NaN when arg reads more than t and params. */
static double rate_at(const bg_model *m, int arg, double t, double h) {
  bg_xenv a = {t - h, NULL, NULL, NULL, NULL, NULL}, b = a;
  b.t = t + h;
  return fabs(bg_xeval(m, arg, &b) - bg_xeval(m, arg, &a)) / (2 * h);
}

static void period_walk(const bg_model *m, int root, double t0, double t1, double *best) {
  const bg_xnode *n = &m->xnode[root];
  if (n->op == BG_X_CALL && n->nargs == 1 &&
      (n->ref == BG_FN_SIN || n->ref == BG_FN_COS || n->ref == BG_FN_TAN)) {
    double h = 1e-6 * fmax(t1 - t0, 1e-300), half = (n->ref == BG_FN_TAN ? 1 : 2) * 3.14159265358979323846;
    double w = fmax(rate_at(m, n->arg[0], t0, h), rate_at(m, n->arg[0], t1, h));
    if (isfinite(w) && w > 0 && (*best == 0 || half / w < *best)) *best = half / w;
  }
  if (n->op == BG_X_INPUT) period_walk(m, m->input_expr[n->ref], t0, t1, best);
  else if (n->op != BG_X_NUM)
    for (int k = 0; k < n->nargs; k++) period_walk(m, n->arg[k], t0, t1, best);
}

double bg_eqsys_input_period(const bg_eqsys *s, double t0, double t1) {
  const bg_model *m = s->m;
  double best = 0;
  for (int e = 0; e < m->nelem; e++)
    if (bg_elem_is_source(m->elem_kind[e]) && m->elem_expr[e] >= 0) period_walk(m, m->elem_expr[e], t0, t1, &best);
  for (int k = 0; k < m->ninput; k++) period_walk(m, m->input_expr[k], t0, t1, &best);
  return best;
}

int bg_eqsys_is_algebraic_row(const bg_eqsys *s, int i) {
  return s->row_alg ? s->row_alg[i] : s->row_kind[i] != 0;
}

/* ------------------------------------------------------------ dependent stores' rates */
/* A dependent store's state is fixed by its constraint (q = C e(t)); its
 * rate q' is what the derivative-causality quantities read (C1.f = q'), but
 * when no residual contains it no initial-value solver can find it
 * (IDACalcIC left it 0: the first row of `Se U = 1 + t` on a C read f = 0).
 * It is the time derivative of the consistent solution: the constraints are
 * solved at t - h and t + h with the independent states moved along their
 * rates, and the central difference taken. Stores whose rate some residual
 * reads are left to the solver, and nothing is set unless both solves
 * converged (a cubic law at e = 0 stops Newton: a rate from there is noise). */
static int dep_rate_wanted(bg_eqsys *s, int i, const double *J0, const double *J1) {
  if (s->row_kind[i] != 1 || i >= s->nx) return 0;
  for (int r = 0; r < s->n; r++)
    if (J1[(size_t)i * s->n + r] != J0[(size_t)i * s->n + r]) return 0; /* dF_r/dyp_i != 0 */
  return 1;
}

static int solved(bg_eqsys *s, double t, double *y) {
  double *r = bg_xmalloc((size_t)s->n * sizeof(double)), *yp = bg_xcalloc((size_t)s->n, sizeof(double));
  int ok = bg_eqsys_consistent(s, t, y, 30) == 0 && bg_eqsys_residual(s, t, y, yp, r) == 0;
  for (int i = 0; ok && i < s->n; i++)
    if (s->row_kind[i] == 1 && !(fabs(r[i]) <= 1e-10 * (1 + fabs(y[i])))) ok = 0;
  free(r), free(yp);
  return ok;
}

int bg_eqsys_algebraic_rates(bg_eqsys *s, double t, const double *y, double *yp, double h) {
  int n = s->n, nz = 0;
  for (int i = s->nx; i < n && !s->reduced; i++) nz += s->row_kind[i] == 1;
  if (nz == 0 || !(h > 0) || n > 1000) return 0;
  /* one-sided, on the right of t: a restart sits at an input's jump or a
   * switch, and what is wanted is the limit from the right */
  double *y1 = bg_xmalloc((size_t)n * sizeof(double)), *y2 = bg_xmalloc((size_t)n * sizeof(double));
  int set = 0;
  for (int i = 0; i < n; i++) {
    double move = i < s->nx && s->row_kind[i] == 0 ? h * yp[i] : 0;
    y1[i] = y[i] + move, y2[i] = y[i] + 2 * move;
  }
  if (solved(s, t + h, y1) && solved(s, t + 2 * h, y2))
    for (int i = s->nx; i < n; i++)
      if (s->row_kind[i] == 1) yp[i] = (-3 * y[i] + 4 * y1[i] - y2[i]) / (2 * h), set++;
  free(y1), free(y2);
  s->has_err = 0;
  return set;
}

int bg_eqsys_dependent_rates(bg_eqsys *s, double t, const double *y, double *yp, double h) {
  int n = s->n, nd = 0;
  for (int i = 0; i < s->nx && !s->reduced; i++) nd += s->row_kind[i] == 1;
  if (nd == 0 || !(h > 0) || n > 1000) return 0;
  double *J0 = bg_xmalloc((size_t)n * n * sizeof(double)), *J1 = bg_xmalloc((size_t)n * n * sizeof(double));
  double *lo = bg_xmalloc((size_t)n * sizeof(double)), *hi = bg_xmalloc((size_t)n * sizeof(double));
  int set = -1;
  if (bg_eqsys_jac_dense(s, t, y, yp, 0.0, J0) == 0 && bg_eqsys_jac_dense(s, t, y, yp, 1.0, J1) == 0) {
    for (int i = 0; i < n; i++) {
      double move = i < s->nx && s->row_kind[i] == 0 ? h * yp[i] : 0;
      lo[i] = y[i] - move, hi[i] = y[i] + move;
    }
    if (solved(s, t - h, lo) && solved(s, t + h, hi)) {
      set = 0;
      for (int i = 0; i < s->nx; i++)
        if (dep_rate_wanted(s, i, J0, J1)) yp[i] = (hi[i] - lo[i]) / (2 * h), set++;
    }
  }
  free(J0), free(J1), free(lo), free(hi);
  s->has_err = 0;
  return set;
}
