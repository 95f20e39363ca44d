/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_simulate: decides whether and how to simulate (refusal, solver choice
 * and why, tolerances, output grid, input breakpoints), then hands the plan
 * to the SUNDIALS driver (simulate_run.c). */
#include "base/lapack.h"
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "model/model.h"
#include "simulate/simulate_int.h"
#include "base/sort.h"

#define SIM_DEFAULT_ATOL 1e-9
#define SIM_DEFAULT_ROWS 500
#define SIM_SPARSE_ABOVE 200   /* unknowns: KLU above, dense up to (docs/simulation.md) */
#define SIM_EIG_MAX 200        /* eigenvalues for the stiffness test up to this size */
#define SIM_STIFF_RATIO 1e3
#define SIM_MAX_STEPS 100000L  /* per output interval; SUNDIALS' 500 is far too few */
#define SIM_PROGRESS_EVERY 1.0 /* -v: seconds between progress lines */
#define SIM_MAX_ROWS 1000000   /* output rows at most (docs/simulation.md) */
#define SIM_MAX_CELLS 5e7      /* rows x columns at most: 400 MB of results */

static char *xstrdup_sb(bg_strbuf *sb) {
  char *s = strdup(bg_sb_str(sb));
  bg_sb_free(sb);
  return s;
}

/* ------------------------------------------------------------------ stiffness */
typedef struct scales {
  double fast, slow; /* smallest and largest time scale [s]; 0 when none */
  double decay;      /* fastest decay time scale [s] (1 / largest -Re lambda); 0: none */
  const char *from;  /* where they came from */
} scales;

static void scale_add(scales *sc, double tau) {
  if (!(tau > 0) || !isfinite(tau)) return;
  if (sc->fast == 0 || tau < sc->fast) sc->fast = tau;
  if (tau > sc->slow) sc->slow = tau;
}

/* Time scales 1/|lambda| of the Jacobian's eigenvalues at the initial point
 * (eigenvalues that are zero to rounding, pure integrators, are left out). */
static int scales_eig(bg_eqsys *s, double t0, const double *y0, scales *sc) {
  int n = bg_eqsys_n(s), ok = 0;
  double *J = bg_xmalloc((size_t)n * n * sizeof(double));
  double *wr = bg_xmalloc((size_t)n * sizeof(double)), *wi = bg_xmalloc((size_t)n * sizeof(double));
  if (bg_eqsys_jac_dense(s, t0, y0, NULL, 0.0, J) == 0 &&
      LAPACKE_dgeev(LAPACK_COL_MAJOR, 'N', 'N', n, J, n, wr, wi, NULL, 1, NULL, 1) == 0) {
    double big = 0;
    for (int i = 0; i < n; i++) big = fmax(big, hypot(wr[i], wi[i]));
    for (int i = 0; i < n; i++) {
      double mag = hypot(wr[i], wi[i]);
      if (mag > 1e-10 * big) scale_add(sc, 1.0 / mag);
      if (-wr[i] > 1e-10 * big && (sc->decay == 0 || -1.0 / wr[i] < sc->decay)) sc->decay = -1.0 / wr[i];
    }
    sc->from = "eigenvalues of the Jacobian at t0";
    ok = 1;
  }
  free(J), free(wr), free(wi);
  return ok;
}

/* Time constants and 1/omega0 of the analysis' first- and second-order paths. */
static void scales_estimates(const bg_analysis *a, scales *sc) {
  for (int i = 0; i < a->nestimate; i++) {
    double v = a->estimate_value[i];
    scale_add(sc, a->estimate_kind[i] == 0 ? v : 1.0 / v);
    if (a->estimate_kind[i] == 0 && v > 0 && (sc->decay == 0 || v < sc->decay)) sc->decay = v;
  }
  sc->from = "time constants and natural frequencies of the causal paths";
}

/* Auto choice for an ODE: BDF when the time scales spread over more than
 * SIM_STIFF_RATIO, or when the simulated span is more than SIM_STIFF_RATIO
 * times the fastest decay (a single fast decay over a long run is stiff too:
 * Adams would be held to steps of that size long after it died out). */
static int choose_ode(const bg_analysis *a, bg_eqsys *s, const bg_simspec *sp, const double *y0,
                      bg_strbuf *why) {
  scales sc = {0, 0, 0, NULL};
  double span = sp->t_end - sp->t0;
  if (bg_eqsys_n(s) > SIM_EIG_MAX || !scales_eig(s, sp->t0, y0, &sc)) scales_estimates(a, &sc);
  if (sc.fast == 0) {
    int big = bg_eqsys_n(s) > SIM_EIG_MAX;
    bg_sb_printf(why, "auto: no time scale known (%s); %s", big ? "large system" : "none found",
                 big ? "BDF is the safe choice for a large system" : "non-stiff Adams");
    return big ? BG_SIM_BDF : BG_SIM_ADAMS;
  }
  double ratio = sc.slow / sc.fast, sratio = sc.decay > 0 ? span / sc.decay : 0;
  int stiff = ratio > SIM_STIFF_RATIO || sratio > SIM_STIFF_RATIO;
  bg_sb_printf(why, "auto: time scales from %.3g s to %.3g s (%s), ratio %.3g; span %.3g s / "
                    "fastest decay %.3g s = %.3g; %s than %.0e: %s", sc.fast, sc.slow, sc.from,
               ratio, span, sc.decay, sratio, stiff ? "more" : "neither more", SIM_STIFF_RATIO,
               stiff ? "stiff, BDF" : "not stiff, Adams");
  return stiff ? BG_SIM_BDF : BG_SIM_ADAMS;
}

static int kind_parse(const char *name) {
  if (!strcmp(name, "cvode_bdf")) return BG_SIM_BDF;
  if (!strcmp(name, "cvode_adams")) return BG_SIM_ADAMS;
  if (!strcmp(name, "ida")) return BG_SIM_IDA;
  return -1;
}

static const char *kind_name(int kind) {
  return kind == BG_SIM_BDF ? "cvode_bdf" : kind == BG_SIM_ADAMS ? "cvode_adams" : "ida";
}

/* Returns the solver kind, or -1 with r->message when the choice is impossible. */
static int choose(const bg_model *m, const bg_analysis *a, bg_eqsys *s, const bg_sim_opts *o,
                  const double *y0, bg_simresult *r) {
  const char *forced = o && o->solver ? o->solver : m->sim.solver;
  bg_strbuf why = {0};
  int kind = -1, ode = bg_eqsys_is_ode(s);
  if (forced && strcmp(forced, "auto") != 0) {
    kind = kind_parse(forced);
    if (kind < 0) {
      bg_sb_printf(&why, "unknown solver '%s' (auto, cvode_bdf, cvode_adams or ida)", forced);
      r->message = xstrdup_sb(&why);
      return -1;
    }
    if (kind != BG_SIM_IDA && !ode) {
      bg_sb_printf(&why, "solver %s cannot integrate this model: its equations are a DAE "
                         "(%d algebraic unknowns, %d dependent stores); use ida or auto",
                   forced, bg_eqsys_n(s) - bg_eqsys_nx(s), a->ndependent);
      r->message = xstrdup_sb(&why);
      return -1;
    }
    bg_sb_printf(&why, "forced by %s", o && o->solver ? "the command line" : "the model's solver =");
  } else if (!ode && bg_eqsys_is_reduced(s)) {
    kind = BG_SIM_IDA;
    bg_sb_printf(&why, "auto: index reduction (Pantelides, dummy derivatives) gave a DAE of index "
                       "%d (%d algebraic unknowns): IDA",
                 o && o->facts && o->facts->reduction ? o->facts->reduction->index : -1,
                 bg_eqsys_n(s) - bg_eqsys_nx(s));
  } else if (!ode) {
    kind = BG_SIM_IDA;
    bg_sb_printf(&why, "auto: the equations are a DAE (%d algebraic unknown%s, %d dependent "
                       "store%s), index %d: IDA", bg_eqsys_n(s) - bg_eqsys_nx(s),
                 bg_eqsys_n(s) - bg_eqsys_nx(s) == 1 ? "" : "s", a->ndependent,
                 a->ndependent == 1 ? "" : "s", a->index_predicted > 0 ? a->index_predicted : 1);
  } else {
    kind = choose_ode(a, s, &m->sim, y0, &why);
  }
  r->solver_used = kind_name(kind);
  r->solver_reason = xstrdup_sb(&why);
  return kind;
}

/* ------------------------------------------------------------------ tolerances */
/* CVODE and IDA bound the weighted RMS of the local error over all unknowns,
 * so one unknown's error may reach sqrt(n) times the tolerance, and the
 * global error grows with the model: on the mass chain, rtol 1e-6 gave 8e-6
 * of the largest value at 2 masses and 3e-5 at 1000. 1e-7 up to 100
 * unknowns and 1e-7 sqrt(100 / n) above keep it near 1e-6 at any size
 * (measured in docs/simulation.md); tighter than 1e-10 it never goes. */
double bg_sim_default_rtol(int n) {
  double r = n > 100 ? 1e-7 * sqrt(100.0 / n) : 1e-7;
  return r < 1e-10 ? 1e-10 : r;
}

double bg_sim_default_rtol_switching(int n) {
  double r = bg_sim_default_rtol(n) / BG_SIM_SWITCH_TIGHTER;
  return r < 1e-10 ? 1e-10 : r;
}

/* atol is meant for efforts and flows: a linear store's state q = C e (p = I f)
 * gets atol times its capacitance (inertance), so that 1e-9 on a 1 uF
 * capacitor's charge does not mean 1e-3 V. Other unknowns get atol as is. */
typedef struct byname {
  const bg_model *m;
  int *ids; /* element ids sorted by name: the look-up per unknown must not be linear */
} byname;

static int cmp_elem(const void *x, const void *y, void *ctx) {
  const bg_model *m = ctx;
  return strcmp(m->elem_name[*(const int *)x], m->elem_name[*(const int *)y]);
}

static int find_elem(const byname *bn, const char *name, size_t len) {
  int lo = 0, hi = bn->m->nelem - 1;
  while (lo <= hi) {
    int mid = (lo + hi) / 2;
    const char *s = bn->m->elem_name[bn->ids[mid]];
    int c = strncmp(s, name, len);
    if (c == 0) c = s[len] != 0; /* s longer than the prefix sorts after it */
    if (c == 0) return bn->ids[mid];
    if (c < 0) lo = mid + 1;
    else hi = mid - 1;
  }
  return -1;
}

/* A port of a C or I field whose law is linear in its own state (an
 * inertance matrix, linear laws): the inverse of the law's coefficient of
 * that state, the port's own capacitance or inertance seen with the other
 * ports held (coupled coils: 1/(L^-1)_kk); 1 when the law reads more than
 * the field's states. */
static double field_scale(const bg_model *m, int e) {
  double *q = bg_xcalloc((size_t)m->nelem, sizeof(double));
  bg_xenv env = {m->sim.t0, NULL, NULL, NULL, NULL, q};
  double f0 = bg_xeval(m, m->elem_expr[e], &env);
  q[e] = 1;
  double c = fabs(bg_xeval(m, m->elem_expr[e], &env) - f0);
  free(q);
  return isfinite(c) && c > 0 ? 1 / c : 1.0;
}

static double store_scale(const byname *bn, const char *name) {
  const bg_model *m = bn->m;
  const char *dot = name ? strrchr(name, '.') : NULL;
  if (!dot || (strcmp(dot, ".q") && strcmp(dot, ".p"))) return 1.0;
  int e = find_elem(bn, name, (size_t)(dot - name));
  if (e >= 0 && bg_elem_is_store(m->elem_kind[e]) && m->elem_form[e] != BG_FORM_VALUE &&
      m->elem_field[e] >= 0 && m->elem_linear[e] && !m->elem_modulated[e] && m->elem_expr[e] >= 0)
    return field_scale(m, e);
  if (e < 0 || !bg_elem_is_store(m->elem_kind[e]) || m->elem_form[e] != BG_FORM_VALUE ||
      m->elem_modulated[e] || m->elem_expr[e] < 0)
    return 1.0;
  bg_xenv env = {m->sim.t0, NULL, NULL, NULL, NULL, NULL};
  double v = fabs(bg_xeval(m, m->elem_expr[e], &env));
  return isfinite(v) && v > 0 ? v : 1.0;
}

static byname byname_make(const bg_model *m) {
  byname bn = {m, bg_xmalloc((size_t)(m->nelem > 0 ? m->nelem : 1) * sizeof(int))};
  for (int e = 0; e < m->nelem; e++) bn.ids[e] = e;
  bg_sort(bn.ids, (size_t)m->nelem, sizeof(int), cmp_elem, (void *)m);
  return bn;
}

static double *make_atol(const byname *bn, bg_eqsys *s, double atol) {
  int n = bg_eqsys_n(s);
  double *v = bg_xmalloc((size_t)(n > 0 ? n : 1) * sizeof(double));
  for (int i = 0; i < n; i++) v[i] = atol * store_scale(bn, bg_eqsys_name(s, i));
  return v;
}

/* ------------------------------------------------------------------ initial values */
static double init_of(const bg_model *m, int root) {
  if (root < 0) return 0;
  bg_xenv env = {m->sim.t0, NULL, NULL, NULL, NULL, NULL};
  return bg_xeval(m, root, &env);
}

/* What the model says unknown i starts at: a store's q0/p0, a state's init
 * (0 when not given). NAN for algebraic unknowns: the model gives none,
 * their starting value is only a guess; but a store or state that lost its
 * state to an index reduction keeps the model's value to compare with. */
static double model_start(const byname *bn, bg_eqsys *s, int i) {
  const bg_model *m = bn->m;
  const char *name = bg_eqsys_name(s, i), *dot = name ? strrchr(name, '.') : NULL;
  if (!name || (!bg_eqsys_is_differential(s, i) && !bg_eqsys_is_reduced(s))) return NAN;
  if (dot && (!strcmp(dot, ".q") || !strcmp(dot, ".p"))) {
    int e = find_elem(bn, name, (size_t)(dot - name));
    if (e >= 0 && bg_elem_is_store(m->elem_kind[e])) return init_of(m, m->elem_init[e]);
  }
  for (int k = 0; k < m->nstate; k++)
    if (!strcmp(m->state_name[k], name)) return init_of(m, m->state_init[k]);
  return NAN;
}

/* The states the solver started from that differ from the model's initial
 * values (a dependent store's q/p follows from the independent ones; the
 * model's default 0 is then replaced): r->ic_report, "L1.p 0 -> 1, ...". */
static void report_start(const byname *bn, bg_eqsys *s, const double *atol, double rtol,
                         bg_simresult *r) {
  if (!r->y0) return;
  bg_strbuf sb = {0};
  int nchanged = 0;
  for (int i = 0; i < r->n; i++) {
    double v0 = model_start(bn, s, i), y = r->y0[i];
    if (isnan(v0) || !(fabs(y - v0) > rtol * fabs(v0) + atol[i])) continue;
    if (nchanged++ < 8)
      bg_sb_printf(&sb, "%s%s %.6g -> %.6g", nchanged > 1 ? ", " : "", bg_eqsys_name(s, i), v0, y);
  }
  if (nchanged > 8) bg_sb_printf(&sb, " and %d more", nchanged - 8);
  r->consistent_ic_changed = nchanged > 0;
  if (nchanged) r->ic_report = strdup(bg_sb_str(&sb));
  bg_sb_free(&sb);
}

/* ------------------------------------------------------------------ grid */
static int refuse(bg_simresult *r, char *msg);

/* The grid's rows: t0, t0 + dt, ..., t_end (dt 0: SIM_DEFAULT_ROWS intervals). */
static double grid_rows(const bg_simspec *sp) {
  double span = sp->t_end - sp->t0;
  double dt = sp->dt > 0 ? sp->dt : span / SIM_DEFAULT_ROWS;
  double steps = ceil(span / dt - 1e-9);
  return (steps < 1 ? 1 : steps) + 1;
}

/* A grid beyond the row limits is refused before anything runs (never
 * capped silently): the message says how many rows and the dt that fits. */
static int check_grid(const bg_simspec *sp, int nout, bg_simresult *r) {
  double rows = grid_rows(sp), cols = nout > 0 ? nout : 1;
  double limit = fmin(SIM_MAX_ROWS, SIM_MAX_CELLS / cols);
  if (rows <= limit) return 0;
  char buf[400], why[160] = "";
  if (limit < SIM_MAX_ROWS)
    snprintf(why, sizeof why, " for %d columns (at most %.0f values in all)", nout, SIM_MAX_CELLS);
  /* the smallest dt that fits, rounded up to three digits so it still fits */
  double fit = (sp->t_end - sp->t0) / (floor(limit) - 1), unit = pow(10, floor(log10(fit)) - 2);
  fit = ceil(fit / unit * (1 - 1e-12)) * unit;
  snprintf(buf, sizeof buf, "dt = %g gives %.3g output rows over [%g, %g], more than the limit "
           "of %.0f rows%s; use dt >= %.3g (or leave dt out for %d intervals)", sp->dt, rows,
           sp->t0, sp->t_end, floor(limit), why, fit, SIM_DEFAULT_ROWS);
  return refuse(r, strdup(buf));
}

static double *make_times(const bg_simspec *sp, int *nrows) {
  double dt = sp->dt > 0 ? sp->dt : (sp->t_end - sp->t0) / SIM_DEFAULT_ROWS;
  int n = (int)grid_rows(sp); /* within the limits: check_grid */
  double *t = bg_xmalloc((size_t)n * sizeof(double));
  for (int k = 0; k < n - 1; k++) t[k] = sp->t0 + k * dt;
  t[n - 1] = sp->t_end;
  *nrows = n;
  return t;
}

static double *make_breakpoints(bg_eqsys *s, const bg_simspec *sp, int *nbp) {
  int cap = 256, n;
  double *bp = NULL;
  for (;;) {
    bp = bg_xrealloc(bp, (size_t)cap * sizeof(double));
    n = bg_eqsys_breakpoints(s, sp->t0, sp->t_end, bp, cap);
    if (n < cap) break;
    cap *= 4;
  }
  int w = 0; /* keep the contract's promise locally: inside (t0, t_end), increasing */
  for (int i = 0; i < n; i++)
    if (bp[i] > sp->t0 && bp[i] < sp->t_end && (w == 0 || bp[i] > bp[w - 1])) bp[w++] = bp[i];
  *nbp = w;
  return bp;
}

/* ------------------------------------------------------------------ entry */
/* States are kept at every row (for comparing runs state by state) when
 * asked or when they take at most this many values (16 MB) */
#define SIM_KEEP_STATES 2000000.0

static void result_alloc(bg_eqsys *s, int nrows, int keep_states, bg_simresult *r) {
  int n = bg_eqsys_n(s);
  if (n > 0 && (keep_states || (double)n * nrows <= SIM_KEEP_STATES))
    r->states = bg_xmalloc((size_t)nrows * (size_t)n * sizeof(double));
  r->nout = bg_eqsys_noutput(s);
  r->names = bg_xmalloc((size_t)(r->nout > 0 ? r->nout : 1) * sizeof(char *));
  for (int k = 0; k < r->nout; k++) r->names[k] = bg_eqsys_output_name(s, k);
  r->t = bg_xmalloc((size_t)nrows * sizeof(double));
  r->values = bg_xmalloc((size_t)nrows * (size_t)(r->nout > 0 ? r->nout : 1) * sizeof(double));
}

static int refuse(bg_simresult *r, char *msg) {
  r->message = msg;
  return 1;
}

static int check_spec(const bg_simspec *sp, bg_simresult *r) {
  char buf[240];
  if (sp->t_end > sp->t0 && isfinite(sp->t_end) && isfinite(sp->t0) && !isfinite(sp->t_end - sp->t0)) {
    snprintf(buf, sizeof buf, "the span from t0 = %g to t_end = %g is larger than the largest "
             "number (%g): no time axis holds it", sp->t0, sp->t_end, DBL_MAX);
    return refuse(r, strdup(buf));
  }
  if (sp->t_end > sp->t0 && isfinite(sp->t_end) && isfinite(sp->t0)) return 0;
  if (!sp->present) return refuse(r, strdup("the model has no simulate block (simulate t_end = ...)"));
  snprintf(buf, sizeof buf, "nothing to simulate: t_end (%g) must be greater than t0 (%g)",
           sp->t_end, sp->t0);
  return refuse(r, strdup(buf));
}

/* A fixed-point run that failed: most often more than BG_SIM_FP_MAX_STEPS
 * steps in an output interval (the model is stiffer than its estimate, or
 * turned stiff after t0, and the iteration converges only at tiny steps).
 * The whole run again with Newton's method and KLU (bg_sim_integrate starts
 * from a clean result). */
static int integrate_newton_again(bg_eqsys *s, bg_simplan *p, bg_simresult *r) {
  if (p->verbose)
    bg_logf(p->log, BG_LOG_PROGRESS, "simulate: fixed-point iteration failed (%s); again with Newton's "
                    "method and KLU", r->message ? r->message : "no message");
  p->fixed_point = 0;
  return bg_sim_integrate(s, p, r);
}

/* No unknowns: the outputs over the grid, without a solver. */
static int simulate_algebraic(const bg_model *m, bg_eqsys *s, bg_simresult *r) {
  bg_simplan p = {0};
  p.t0 = m->sim.t0, p.t_end = m->sim.t_end;
  double *times = make_times(&m->sim, &p.nrows);
  p.times = times;
  result_alloc(s, p.nrows, 0, r);
  r->solver_used = "none";
  r->solver_reason = strdup("no states and no algebraic unknowns: the outputs are functions of "
                            "t alone, evaluated at each output time");
  int rc = bg_sim_algebraic(s, &p, r);
  free(times);
  return rc;
}

/* The switching conditions of the state events (names borrowed). */
static void conditions_keep(bg_eqsys *s, int searched, bg_simresult *r) {
  r->nconditions = bg_eqsys_nroots(s);
  r->events_searched = searched && r->nconditions > 0;
  if (!r->nconditions) return;
  r->condition_text = bg_xmalloc((size_t)r->nconditions * sizeof(char *));
  for (int i = 0; i < r->nconditions; i++) r->condition_text[i] = bg_eqsys_root_text(s, i);
}

/* The model's max_step, and at most 1/SIM_STEPS_PER_PERIOD of the shortest
 * period of a periodic input: the error test only sees the solution at the
 * steps, and a model whose states barely move while a diode is off lets the
 * step grow over a whole conduction interval (docs/simulation.md). */
#define SIM_STEPS_PER_PERIOD 20
static double step_limit(bg_eqsys *s, const bg_model *m, const bg_sim_opts *o) {
  double h = m->sim.max_step, per = bg_eqsys_input_period(s, m->sim.t0, m->sim.t_end);
  double lim = per / SIM_STEPS_PER_PERIOD;
  if (per > 0 && (h <= 0 || lim < h)) {
    h = lim;
    if (o)
      bg_logf(o->log, BG_LOG_PROGRESS, "simulate: steps of at most %.6g s (1/%d of the shortest input "
                      "period, %.6g s)", h, SIM_STEPS_PER_PERIOD, per);
  }
  return h;
}

static int simulate_once(const bg_model *m, const bg_analysis *a, bg_eqsys *s, const bg_sim_opts *o,
                         bg_simresult *r) {
  memset(r, 0, sizeof *r);
  char *why = bg_simulate_refusal_reduced(m, a, o ? o->facts : NULL, s && bg_eqsys_is_reduced(s));
  if (why) return refuse(r, why);
  if (!s) {
    bg_strbuf sb = {0};
    bg_sb_puts(&sb, "the equations could not be formed");
    if (o && o->eqs_problem) bg_sb_printf(&sb, ": %s", o->eqs_problem);
    else bg_sb_puts(&sb, " (see the diagnostics)");
    return refuse(r, xstrdup_sb(&sb));
  }
  if (check_spec(&m->sim, r) || check_grid(&m->sim, bg_eqsys_noutput(s), r)) return 1;
  int n = bg_eqsys_n(s), rc;
  if (n == 0) return simulate_algebraic(m, s, r);
  double *y0 = bg_xmalloc((size_t)(n > 0 ? n : 1) * sizeof(double));
  bg_eqsys_initial(s, y0);
  int kind = choose(m, a, s, o, y0, r);
  free(y0);
  if (kind < 0) return 1;
  bg_simplan p = {0};
  p.kind = kind;
  p.sparse = n > SIM_SPARSE_ABOVE;
  /* Adams on a large system: fixed-point iteration, the pairing for
   * non-stiff problems (no Jacobian, no factorisation: a sparse LU of a 2-D
   * mesh grows as n^1.5); Newton again if it fails (integrate_newton_again) */
  p.fixed_point = kind == BG_SIM_ADAMS && p.sparse;
  if (o)
    bg_logf(o->log, BG_LOG_PROGRESS, "simulate: %d unknowns, solver %s, %s (%s)", n, r->solver_used,
            p.fixed_point ? "fixed-point iteration (no Jacobian)"
            : p.sparse    ? "sparse Jacobian, KLU"
                          : "dense Jacobian", r->solver_reason);
  p.t0 = m->sim.t0, p.t_end = m->sim.t_end;
  double rtol_default = bg_eqsys_nroots(s) ? bg_sim_default_rtol_switching(n) : bg_sim_default_rtol(n);
  p.rtol = o && o->rtol > 0 ? o->rtol : m->sim.rtol > 0 ? m->sim.rtol : rtol_default;
  double atol = o && o->atol > 0 ? o->atol : m->sim.atol > 0 ? m->sim.atol : SIM_DEFAULT_ATOL;
  p.max_step = step_limit(s, m, o);
  r->max_step = p.max_step;
  p.max_steps = o && o->max_steps > 0 ? o->max_steps : SIM_MAX_STEPS;
  p.log = o ? o->log : NULL;
  p.verbose = bg_log_on(p.log, BG_LOG_DETAIL) ? 2 : bg_log_on(p.log, BG_LOG_PROGRESS);
  p.events = !(o && o->no_events);
  conditions_keep(s, p.events, r);
  p.progress_every = o && o->progress_every > 0 ? o->progress_every : SIM_PROGRESS_EVERY;
  r->rtol = p.rtol, r->atol = atol;
  byname bn = byname_make(m);
  double *atolv = make_atol(&bn, s, atol), *times = make_times(&m->sim, &p.nrows);
  double *bp = make_breakpoints(s, &m->sim, &p.nbp);
  p.atol = atolv, p.times = times, p.bp = bp;
  result_alloc(s, p.nrows, o && o->keep_states, r);
  /* wall and CPU time (-v; bench/sim_bench.sh compares the CPU time: on
   * a shared machine the wall clock measures the other programs too) */
  struct timespec c0, c1, u0, u1;
  clock_gettime(CLOCK_MONOTONIC, &c0);
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &u0);
  rc = bg_sim_integrate(s, &p, r);
  if (rc && p.fixed_point) rc = integrate_newton_again(s, &p, r);
  r->linear_solver = p.fixed_point ? "none" : p.sparse ? "klu" : "dense"; /* of the run kept */
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &u1);
  clock_gettime(CLOCK_MONOTONIC, &c1);
  if (r->nrows) report_start(&bn, s, atolv, p.rtol, r);
  if (p.verbose && r->ic_report)
    bg_logf(p.log, BG_LOG_PROGRESS, "simulate: initial values made consistent: %s", r->ic_report);
  if (p.verbose)
    bg_logf(p.log, BG_LOG_PROGRESS, "simulate: %s in %.3f s (CPU %.3f s): %d rows, %ld steps, %ld "
                    "function and %ld Jacobian evaluations, %ld error test failures, %ld "
                    "nonlinear iterations",
            rc ? "failed" : "done", (double)(c1.tv_sec - c0.tv_sec) + 1e-9 * (double)(c1.tv_nsec - c0.tv_nsec),
            (double)(u1.tv_sec - u0.tv_sec) + 1e-9 * (double)(u1.tv_nsec - u0.tv_nsec),
            r->nrows, r->steps, r->rhs_evals, r->jac_evals, r->err_test_fails, r->nonlin_iters);
  if (p.verbose && r->nconditions)
    bg_logf(p.log, BG_LOG_PROGRESS, "simulate: %d state event%s at %d switching condition%s%s", r->nevents,
            r->nevents == 1 ? "" : "s", r->nconditions, r->nconditions == 1 ? "" : "s",
            r->events_searched ? "" : " (not searched)");
  if (p.verbose && r->rows_redone)
    bg_logf(p.log, BG_LOG_PROGRESS, "simulate: %d output interval%s integrated again with short steps: "
                    "the row violated the algebraic equations", r->rows_redone, r->rows_redone == 1 ? "" : "s");
  free(atolv), free(times), free(bp), free(bn.ids);
  return rc;
}

/* ------------------------------------------------------------------ accuracy control
 * A switching model amplifies what the integrator leaves: each event's time
 * moves with the state before it, and what follows moves with the event
 * (docs/simulation.md, "Accuracy through events": a backlash whose error is
 * 300 times rtol, another 2e5 times). No single default tolerance holds a
 * stated accuracy on all of them, so at the default tolerances a run with
 * events is compared with one at tolerances BG_VERIFY_FACTOR times tighter,
 * and the tighter is kept (and compared again) until two runs agree to
 * BG_SIM_SWITCH_TARGET of every output's and state's range; never tighter
 * than SIM_CONTROL_FLOOR. */
#define SIM_CONTROL_FLOOR 1e-13

static int control_wanted(const bg_model *m, bg_eqsys *s, const bg_sim_opts *o) {
  return s && bg_eqsys_nroots(s) > 0 && !(m->sim.rtol > 0) &&
         !(o && (o->rtol > 0 || o->no_control || o->no_events));
}

static void control_say(const bg_sim_opts *o, const bg_simresult *a, const bg_simcmp *c, double rtol_b) {
  if (!o || !bg_log_on(o->log, BG_LOG_PROGRESS)) return;
  bg_logf(o->log, BG_LOG_PROGRESS, "simulate: accuracy control (state events at default tolerances): "
          "rtol %g deviates %.2g of the range (%s at t = %.6g) from rtol %g; %d and %d events, times %.2g s apart",
          a->rtol, c->worst, c->worst_name ? c->worst_name : "?", c->worst_t, rtol_b, c->events_a, c->events_b,
          c->event_dt);
}

/* Runs tighter until two runs agree; r holds the run kept. */
static void control(const bg_model *m, const bg_analysis *a, bg_eqsys *s, const bg_sim_opts *o,
                    bg_simresult *r) {
  bg_sim_opts tight = o ? *o : (bg_sim_opts){0};
  tight.log = NULL, tight.keep_states = 1, tight.no_control = 1;
  int runs = 1;
  for (;;) {
    tight.rtol = r->rtol / BG_VERIFY_FACTOR, tight.atol = r->atol / BG_VERIFY_FACTOR;
    if (tight.rtol < SIM_CONTROL_FLOOR * (1 - 1e-9)) { r->control_short = 1; break; }
    bg_simresult t;
    int rc = simulate_once(m, a, s, &tight, &t);
    runs++;
    if (rc) { /* the tighter run failed: the one we have is the best there is */
      bg_simresult_free(&t);
      r->control_short = 1;
      break;
    }
    bg_simcmp c;
    bg_sim_compare(r, &t, s, NULL, &c);
    control_say(o, r, &c, t.rtol);
    r->control_dev = c.worst;
    if (c.worst <= BG_SIM_SWITCH_TARGET) { bg_simresult_free(&t); break; }
    t.control_dev = c.worst; /* what is known of it until it is compared itself */
    bg_simresult_free(r);
    *r = t;
  }
  r->control_runs = runs;
  if (r->control_short && o)
    bg_logf(o->log, BG_LOG_WARNING, "state events: the accuracy control kept its tightest run (rtol %g), "
            "which deviates by %.2g of the range from the run before it, more than the %g the default "
            "tolerances aim at; no tighter run was made (rtol is not made smaller than %g or the run failed), "
            "so its own error is not measured: check with --verify or a smaller rtol",
            r->rtol, r->control_dev, BG_SIM_SWITCH_TARGET, SIM_CONTROL_FLOOR);
}

int bg_simulate(const bg_model *m, const bg_analysis *a, bg_eqsys *s, const bg_sim_opts *o,
                bg_simresult *r) {
  int want = control_wanted(m, s, o);
  bg_sim_opts first = o ? *o : (bg_sim_opts){0};
  first.keep_states |= want;
  int rc = simulate_once(m, a, s, &first, r);
  if (rc == 0 && want && r->n > 0 && r->nevents > 0) control(m, a, s, o, r);
  return rc;
}

void bg_simresult_free(bg_simresult *r) {
  free(r->names);
  free(r->t);
  free(r->values);
  free(r->message);
  free(r->solver_reason);
  free(r->ic_report);
  free(r->y0);
  free(r->yp0);
  free(r->verify_dev);
  free(r->verify_message);
  free(r->condition_text), free(r->event_t), free(r->event_cond), free(r->event_dir);
  free(r->states);
  memset(r, 0, sizeof *r);
}

int bg_simresult_row_warning(const bg_simresult *r, bg_strbuf *out) {
  if (r->rows_violating <= 0) return 0;
  bg_sb_printf(out, "%d output row%s violate%s the algebraic equations beyond the tolerance even "
                    "after integrating again with short steps (worst: the equation of %s at t = %.9g, "
                    "%.3g times the tolerance); do not trust those rows: tighten rtol or set max_step",
               r->rows_violating, r->rows_violating == 1 ? "" : "s", r->rows_violating == 1 ? "s" : "",
               r->row_worst_unknown ? r->row_worst_unknown : "?", r->row_worst_t, r->row_worst);
  return 1;
}

/* ------------------------------------------------------------------ --verify */
void bg_sim_verify(const bg_model *m, const bg_analysis *a, bg_eqsys *s, const bg_sim_opts *o,
                   bg_simresult *r) {
  bg_sim_opts tight = o ? *o : (bg_sim_opts){0};
  tight.rtol = r->rtol / BG_VERIFY_FACTOR, tight.atol = r->atol / BG_VERIFY_FACTOR;
  tight.log = NULL;
  tight.keep_states = r->states != NULL; /* every state compared when this run kept them */
  r->verify_rtol = tight.rtol, r->verify_atol = tight.atol, r->verify_worst_col = -1;
  bg_simresult t;
  int rc = bg_simulate(m, a, s, &tight, &t);
  if (rc != 0 || t.nrows != r->nrows || t.nout != r->nout) {
    r->verified = -1;
    bg_strbuf sb = {0};
    bg_sb_printf(&sb, "the run at rtol %g, atol %g %s", tight.rtol, tight.atol,
                 rc ? (t.message ? t.message : "failed") : "gave other output rows");
    r->verify_message = xstrdup_sb(&sb);
  } else {
    r->verified = 1;
    r->verify_dev = bg_xmalloc((size_t)(r->nout > 0 ? r->nout : 1) * sizeof(double));
    bg_simcmp c;
    bg_sim_compare(r, &t, s, r->verify_dev, &c);
    r->verify_worst = c.worst, r->verify_worst_col = c.worst_col;
    r->verify_worst_name = c.worst_name, r->verify_worst_t = c.worst_t;
    r->verify_state_worst = c.states_compared ? c.state_worst : -1;
    r->verify_events_other = c.events_b;
    r->verify_event_dt = c.event_dt, r->verify_event_t = c.event_part_t;
  }
  bg_simresult_free(&t);
}

int bg_sim_verify_text(const bg_simresult *r, bg_strbuf *out) {
  if (!r->verified) return 0;
  if (r->verified < 0) {
    bg_sb_printf(out, "verification not possible: %s", r->verify_message ? r->verify_message : "");
    return 1;
  }
  if (r->n == 0) { /* no solver ran: there are no tolerances to tighten */
    bg_sb_printf(out, "verification: nothing was integrated (no states and no algebraic unknowns): "
                      "the outputs are evaluated directly at each output time, exact to round-off");
    return 1;
  }
  bg_sb_printf(out, "verification at rtol %g, atol %g: largest deviation %.2g of the range", r->verify_rtol,
               r->verify_atol, r->verify_worst);
  if (r->verify_worst_name) bg_sb_printf(out, " (%s at t = %.6g)", r->verify_worst_name, r->verify_worst_t);
  bg_sb_printf(out, " over %d output%s", r->nout, r->nout == 1 ? "" : "s");
  if (r->verify_state_worst >= 0) bg_sb_printf(out, " and %d state%s", r->n, r->n == 1 ? "" : "s");
  else bg_sb_puts(out, " (states not kept: too many to compare)");
  if (r->nconditions > 0 && r->verify_event_dt >= 0)
    bg_sb_printf(out, ", %d state event%s at times %.2g s apart", r->nevents, r->nevents == 1 ? "" : "s",
                 r->verify_event_dt);
  bg_sb_printf(out, "; error bound about %.2g (%g times the deviation)", BG_VERIFY_BOUND * r->verify_worst,
               BG_VERIFY_BOUND);
  double w = r->verify_worst, bound = BG_VERIFY_BOUND * w;
  int digits = bound > 0 ? (int)floor(-log10(bound)) : 15;
  bg_sb_printf(out, ": about %d significant digit%s to trust", digits < 0 ? 0 : digits, digits == 1 ? "" : "s");
  if (w > BG_VERIFY_LOOSE)
    bg_sb_printf(out, "; warning: the tolerances (rtol %g, atol %g) are too loose for this model: "
                      "set a smaller rtol", r->rtol, r->atol);
  if (r->nconditions > 0 && r->verify_event_dt < 0)
    bg_sb_printf(out, "; warning: the tighter run has %d state events, this run %d: they part at t = %.9g, "
                      "and the rows after it cannot be trusted: set a smaller rtol",
                 r->verify_events_other, r->nevents, r->verify_event_t);
  return 1;
}
