/* SPDX-License-Identifier: BSD-3-Clause */
/* The SUNDIALS driver: CVODE (BDF/Adams) or IDA over a bg_eqsys, dense or
 * KLU linear algebra with the eqsys' exact Jacobian, output on a fixed grid,
 * never stepping over an input discontinuity (stop just before each
 * breakpoint, re-initialise at it). Failures are put into words here.
 * With src/simulate_words.c, the only place that includes SUNDIALS headers
 * (through simulate_sundials_int.h, which loads the libraries on first use). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/arena.h"
#include "simulate/simulate_int.h"
#include "simulate/simulate_sundials_int.h"
#include "simulate/simulate_words_int.h"

typedef struct simrun {
  bg_eqsys *s;
  const bg_simplan *p;
  int n, ode;
  SUNContext ctx;
  void *mem;
  N_Vector y, yp, atol, id;
  SUNMatrix A;
  SUNLinearSolver LS;
  SUNNonlinearSolver NLS;        /* fixed-point iteration (p->fixed_point), else NULL */
  sunindextype *colptr, *rowind; /* the sparse pattern, copied in at each evaluation */
  int nnz, *diagpos;             /* position of each diagonal entry in the pattern */
  double tcur;                   /* where the solution is known */
  int nfunc_err;                 /* equation evaluation failures since the last output */
  char err[400];                 /* the last evaluation failure, in words */
  char sunmsg[400];              /* the last SUNDIALS message */
  long st[5];                    /* statistics of earlier segments (counters reset on ReInit) */
  /* IDA: the algebraic rows every output row must satisfy, the residual
   * buffer, and the last recorded point (to redo an interval from) */
  int nalg, *alg;
  double *res, *ylast, *yplast, tlast, *coef; /* coef: |dF_i/dy_i| at the start */
  /* An index-reduced DAE: error weights from the size of each algebraic
   * unknown's terms (ewt_rows): the unknowns j its row reads and |dF_i/dy_j|
   * / |dF_i/dy_i| at the start, term_adr[i] .. term_adr[i + 1] - 1 */
  int row_ewt, *term_adr, *term_j;
  double *term_c;
  /* -v progress: wall clock at the start and at the last line, evaluations
   * since the last clock reading, latest time shown */
  double wall0, wall_last, t_shown;
  unsigned ncall;
  /* state events: root functions, which fired, the stop time to set again
   * after a restart, the modes at the last row (to redo an interval from),
   * events since the last row, events printed with -v, the log's capacity */
  int nroot, *rootsfound, nev_last, nev_interval, nev_shown, evcap;
  int last_root; /* the root function that fired last (-1 none): for the words of a failure */
  int starting;  /* 1 until the start is consistent (run_start): no row before */
  int exact_rows; /* IDA steps to each output time (first_step_again) */
  /* IDA: the statistics at the last row, and the remedies of an interval
   * whose error test failed at most of its steps (untrap) */
  long st_row[5];
  int trapped; /* untrap's remedy taken (mask, terms_always): once a run */
  int terms_always; /* ewt_rows: every algebraic unknown held to its largest term */
  int trap_hit;     /* ewt_rows stopped IDA in a trapped interval (untrap) */
  int trap_watch;   /* 1 while an output interval runs under untrap: ewt_rows may stop it */
  N_Vector mask;    /* IDASetSuppressAlg's id while IDACalcIC is not running (untrap) */
  double tstop, *modes_last, *modes_before, *modes_ev;
  unsigned char *back; /* per root: crossed back at this event (continuous switches) */
  double tseg; /* the end of the segment being run (an input's breakpoint), INFINITY on the last */
  bg_simresult *r;
} simrun;

static void progress(simrun *R, double t);

static double wall(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}


/* ------------------------------------------------------------------ callbacks
 * They run inside the solver: no allocation. An evaluation failure (NaN, a
 * law outside its domain) is recoverable at first: a Newton iterate or a
 * too-long step may overshoot into a region the solution never visits, and
 * the solver retries with a smaller step. When failures keep coming, the
 * solution itself has left the law's domain: creeping along the edge with
 * ever smaller steps would only produce wrong values, so the failure
 * becomes unrecoverable. Its text is kept for the message. */
#define SIM_MAX_EVAL_FAILS 25 /* per output interval */

static int keep_error(simrun *R) {
  const char *e = bg_eqsys_error(R->s);
  R->nfunc_err++;
  snprintf(R->err, sizeof R->err, "%s", e ? e : "an equation evaluated to NaN or infinity");
  return R->nfunc_err > SIM_MAX_EVAL_FAILS ? -1 : 1;
}

/* -v: a long output interval still shows progress; the clock is read every
 * 256 evaluations only, and not at all without -v. */
#define PROGRESS_POLL(R, t) \
  do { if ((R)->p->verbose && (++(R)->ncall & 255u) == 0) progress((R), (t)); } while (0)

static int cv_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *ud) {
  simrun *R = ud;
  PROGRESS_POLL(R, t);
  if (bg_eqsys_rhs(R->s, t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot)) == 0) return 0;
  return keep_error(R);
}

static int ida_res(sunrealtype t, N_Vector y, N_Vector yp, N_Vector rr, void *ud) {
  simrun *R = ud;
  PROGRESS_POLL(R, t);
  if (bg_eqsys_residual(R->s, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp),
                        N_VGetArrayPointer(rr)) == 0)
    return 0;
  return keep_error(R);
}

/* Jacobian into J. For an ODE the eqsys gives df/dy (yp NULL); IDA on an ODE
 * wants dF/dy + cj dF/dyp = cj I - df/dy, built here from it. */
static int fill_jac(simrun *R, double t, N_Vector y, N_Vector yp, double cj, SUNMatrix J) {
  const double *yv = N_VGetArrayPointer(y);
  const double *ypv = R->ode ? NULL : N_VGetArrayPointer(yp);
  int n = R->n, rc;
  double *v;
  if (R->p->sparse) {
    memcpy(SUNSparseMatrix_IndexPointers(J), R->colptr, (size_t)(n + 1) * sizeof(sunindextype));
    memcpy(SUNSparseMatrix_IndexValues(J), R->rowind, (size_t)R->nnz * sizeof(sunindextype));
    v = SUNSparseMatrix_Data(J);
    rc = bg_eqsys_jac_sparse(R->s, t, yv, ypv, R->ode ? 0.0 : cj, v);
  } else {
    v = SUNDenseMatrix_Data(J);
    rc = bg_eqsys_jac_dense(R->s, t, yv, ypv, R->ode ? 0.0 : cj, v);
  }
  if (rc) return keep_error(R);
  if (R->ode && yp) { /* IDA on an ODE */
    long len = R->p->sparse ? R->nnz : (long)n * n;
    for (long k = 0; k < len; k++) v[k] = -v[k];
    for (int i = 0; i < n; i++) v[R->p->sparse ? R->diagpos[i] : (long)i * n + i] += cj;
  }
  return 0;
}

static int cv_jac(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud, N_Vector t1,
                  N_Vector t2, N_Vector t3) {
  (void)fy, (void)t1, (void)t2, (void)t3;
  return fill_jac(ud, t, y, NULL, 0.0, J);
}

static int ida_jac(sunrealtype t, sunrealtype cj, N_Vector y, N_Vector yp, N_Vector r,
                   SUNMatrix J, void *ud, N_Vector t1, N_Vector t2, N_Vector t3) {
  (void)r, (void)t1, (void)t2, (void)t3;
  return fill_jac(ud, t, y, yp, cj, J);
}

/* Root functions of the state events (docs/simulation.md, "State events").
 * One that is not a number stops the solver (SUNDIALS does not recover from
 * it): its cause, in the user's terms, is kept for the message. */
static int cv_g(sunrealtype t, N_Vector y, sunrealtype *g, void *ud) {
  simrun *R = ud;
  if (!bg_eqsys_roots(R->s, t, N_VGetArrayPointer(y), NULL, g)) return 0;
  keep_error(R);
  return -1;
}

static int ida_g(sunrealtype t, N_Vector y, N_Vector yp, sunrealtype *g, void *ud) {
  simrun *R = ud;
  if (!bg_eqsys_roots(R->s, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), g)) return 0;
  keep_error(R);
  return -1;
}

/* SUNDIALS would print to stderr; keep the text for our own message. */
/* SUNDIALS 6.4 (Debian 12) reports solver errors through a handler set per
 * solver (CVodeSetErrHandlerFn, IDASetErrHandlerFn); 7.x removed those and
 * takes handlers on the context instead. Both keep the last message. */
static void keep_sunmsg(simrun *R, const char *module, const char *fn, const char *msg) {
  snprintf(R->sunmsg, sizeof R->sunmsg, "%s/%s: %s", module, fn, msg);
  bg_logf(R->p->log, BG_LOG_DETAIL, "%s", R->sunmsg);
}

#if SUNDIALS_VERSION_MAJOR >= 7
static void on_sunerr(int line, const char *fn, const char *file, const char *msg,
                      SUNErrCode code, void *ud, SUNContext ctx) {
  (void)line, (void)code, (void)ctx;
  keep_sunmsg(ud, file, fn, msg);
}
#define BG_SUN_COMM_NULL SUN_COMM_NULL
#else
static void on_sunerr(int code, const char *module, const char *fn, char *msg, void *ud) {
  (void)code;
  keep_sunmsg(ud, module, fn, msg);
}
#define BG_SUN_COMM_NULL NULL
#endif

/* Routes the solver's error messages to on_sunerr (not to stderr). */
static int catch_sunerr(simrun *R) {
#if SUNDIALS_VERSION_MAJOR >= 7
  int f = SUNContext_ClearErrHandlers(R->ctx);
  return f | SUNContext_PushErrHandler(R->ctx, on_sunerr, R);
#else
  if (R->p->kind == BG_SIM_IDA) return IDASetErrHandlerFn(R->mem, on_sunerr, R);
  return CVodeSetErrHandlerFn(R->mem, on_sunerr, R);
#endif
}

const char *bg_simulate_sundials_version(void) { return SUNDIALS_VERSION; }

/* ------------------------------------------------------------------ set-up */
static int make_pattern(simrun *R) {
  int n = R->n;
  R->nnz = bg_eqsys_jac_nnz(R->s);
  int *cp = bg_xmalloc((size_t)(n + 1) * sizeof(int));
  int *ri = bg_xmalloc((size_t)(R->nnz > 0 ? R->nnz : 1) * sizeof(int));
  bg_eqsys_jac_pattern(R->s, cp, ri);
  R->colptr = bg_xmalloc((size_t)(n + 1) * sizeof(sunindextype));
  R->rowind = bg_xmalloc((size_t)(R->nnz > 0 ? R->nnz : 1) * sizeof(sunindextype));
  R->diagpos = bg_xmalloc((size_t)(n > 0 ? n : 1) * sizeof(int));
  int ok = 1;
  for (int j = 0; j <= n; j++) R->colptr[j] = cp[j];
  for (int k = 0; k < R->nnz; k++) R->rowind[k] = ri[k];
  for (int j = 0; j < n; j++) {
    R->diagpos[j] = -1;
    for (int k = cp[j]; k < cp[j + 1]; k++)
      if (ri[k] == j) R->diagpos[j] = k;
    ok &= R->diagpos[j] >= 0; /* the contract: every diagonal entry is stored */
  }
  free(cp);
  free(ri);
  return ok ? 0 : -1;
}

static int make_linsol(simrun *R) {
  if (R->p->sparse) {
    if (make_pattern(R)) return -1;
    R->A = SUNSparseMatrix(R->n, R->n, R->nnz, CSC_MAT, R->ctx);
    R->LS = SUNLinSol_KLU(R->y, R->A, R->ctx);
  } else {
    R->A = SUNDenseMatrix(R->n, R->n, R->ctx);
    R->LS = SUNLinSol_Dense(R->y, R->A, R->ctx);
  }
  return R->A && R->LS ? 0 : -1;
}

static int setup_cvode(simrun *R) {
  const bg_simplan *p = R->p;
  R->mem = CVodeCreate(p->kind == BG_SIM_ADAMS ? CV_ADAMS : CV_BDF, R->ctx);
  if (!R->mem) return -1;
  int f = catch_sunerr(R);
  f |= CVodeInit(R->mem, cv_rhs, p->t0, R->y);
  f |= CVodeSVtolerances(R->mem, p->rtol, R->atol);
  f |= CVodeSetUserData(R->mem, R);
  long max_steps = p->fixed_point && p->max_steps > BG_SIM_FP_MAX_STEPS ? BG_SIM_FP_MAX_STEPS : p->max_steps;
  f |= CVodeSetMaxNumSteps(R->mem, max_steps);
  if (p->max_step > 0) f |= CVodeSetMaxStep(R->mem, p->max_step);
  if (p->fixed_point) {
    R->NLS = SUNNonlinSol_FixedPoint(R->y, 0, R->ctx);
    f |= !R->NLS || CVodeSetNonlinearSolver(R->mem, R->NLS);
  } else {
    f |= CVodeSetLinearSolver(R->mem, R->LS, R->A);
    f |= CVodeSetJacFn(R->mem, cv_jac);
  }
  if (R->nroot) f |= CVodeRootInit(R->mem, R->nroot, cv_g);
  return f ? -1 : 0;
}

static int ewt_rows(N_Vector yv, N_Vector wv, void *ud);

static int setup_ida(simrun *R) {
  const bg_simplan *p = R->p;
  R->mem = IDACreate(R->ctx);
  if (!R->mem) return -1;
  R->id = N_VNew_Serial(R->n, R->ctx);
  double *id = N_VGetArrayPointer(R->id);
  for (int i = 0; i < R->n; i++) id[i] = R->ode || bg_eqsys_is_differential(R->s, i) ? 1.0 : 0.0;
  int f = catch_sunerr(R);
  f |= IDAInit(R->mem, ida_res, p->t0, R->y, R->yp);
  R->row_ewt = !R->ode && bg_eqsys_is_reduced(R->s);
  f |= R->row_ewt ? IDAWFtolerances(R->mem, ewt_rows) : IDASVtolerances(R->mem, p->rtol, R->atol);
  f |= IDASetUserData(R->mem, R);
  f |= IDASetId(R->mem, R->id);
  f |= IDASetMaxNumSteps(R->mem, p->max_steps);
  if (p->max_step > 0) f |= IDASetMaxStep(R->mem, p->max_step);
  f |= IDASetLinearSolver(R->mem, R->LS, R->A);
  f |= IDASetJacFn(R->mem, ida_jac);
  if (R->nroot) f |= IDARootInit(R->mem, R->nroot, ida_g);
  return f ? -1 : 0;
}

static void alg_open(simrun *R) {
  size_t sz = (size_t)(R->n > 0 ? R->n : 1);
  R->alg = bg_xmalloc(sz * sizeof(int));
  for (int i = 0; i < R->n; i++)
    if (bg_eqsys_is_algebraic_row(R->s, i)) R->alg[R->nalg++] = i;
  R->res = bg_xmalloc(sz * sizeof(double));
  R->ylast = bg_xmalloc(sz * sizeof(double));
  R->yplast = bg_xmalloc(sz * sizeof(double));
}

static int run_open(simrun *R, bg_eqsys *s, const bg_simplan *p) {
  memset(R, 0, sizeof *R);
  R->s = s;
  R->p = p;
  R->n = bg_eqsys_n(s);
  R->ode = bg_eqsys_is_ode(s);
  if (SUNContext_Create(BG_SUN_COMM_NULL, &R->ctx)) return -1;
  R->y = N_VNew_Serial(R->n, R->ctx);
  R->yp = N_VNew_Serial(R->n, R->ctx);
  R->atol = N_VNew_Serial(R->n, R->ctx);
  memcpy(N_VGetArrayPointer(R->atol), p->atol, (size_t)R->n * sizeof(double));
  bg_eqsys_initial_yp(s, N_VGetArrayPointer(R->y), N_VGetArrayPointer(R->yp));
  R->tcur = p->t0;
  R->t_shown = p->t0;
  R->wall0 = R->wall_last = wall();
  if (!p->fixed_point && make_linsol(R)) return -1;
  if (p->kind == BG_SIM_IDA) alg_open(R);
  R->nroot = p->events ? bg_eqsys_nroots(s) : 0;
  R->last_root = -1;
  if (R->nroot) {
    R->rootsfound = bg_xcalloc((size_t)R->nroot, sizeof(int));
    R->modes_last = bg_xcalloc((size_t)bg_eqsys_nmodes(s), sizeof(double));
    R->modes_before = bg_xcalloc((size_t)bg_eqsys_nmodes(s), sizeof(double));
    R->modes_ev = bg_xcalloc((size_t)bg_eqsys_nmodes(s), sizeof(double));
    R->back = bg_xcalloc((size_t)R->nroot, 1);
  }
  return p->kind == BG_SIM_IDA ? setup_ida(R) : setup_cvode(R);
}

static void run_close(simrun *R) {
  if (R->mem) {
    if (R->p->kind == BG_SIM_IDA) IDAFree(&R->mem);
    else CVodeFree(&R->mem);
  }
  if (R->NLS) SUNNonlinSolFree(R->NLS);
  if (R->LS) SUNLinSolFree(R->LS);
  if (R->A) SUNMatDestroy(R->A);
  N_Vector v[] = {R->y, R->yp, R->atol, R->id, R->mask};
  for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
    if (v[i]) N_VDestroy(v[i]);
  free(R->colptr);
  free(R->rowind);
  free(R->diagpos);
  free(R->alg), free(R->res), free(R->ylast), free(R->yplast), free(R->coef);
  free(R->term_adr), free(R->term_j), free(R->term_c);
  free(R->rootsfound), free(R->modes_last), free(R->modes_before), free(R->modes_ev), free(R->back);
  bg_eqsys_modes_freeze(R->s, 0); /* later users of the eqsys evaluate it as compiled */
  if (R->ctx) SUNContext_Free(&R->ctx);
}

/* ------------------------------------------------------------------ stepping */
static void stats_now(simrun *R, long st[5]) {
  long v[5] = {0, 0, 0, 0, 0};
  if (R->p->kind == BG_SIM_IDA) {
    IDAGetNumSteps(R->mem, &v[0]);
    IDAGetNumResEvals(R->mem, &v[1]);
    IDAGetNumJacEvals(R->mem, &v[2]);
    IDAGetNumErrTestFails(R->mem, &v[3]);
    IDAGetNumNonlinSolvIters(R->mem, &v[4]);
  } else {
    CVodeGetNumSteps(R->mem, &v[0]);
    CVodeGetNumRhsEvals(R->mem, &v[1]);
    CVodeGetNumJacEvals(R->mem, &v[2]);
    CVodeGetNumErrTestFails(R->mem, &v[3]);
    CVodeGetNumNonlinSolvIters(R->mem, &v[4]);
  }
  for (int i = 0; i < 5; i++) st[i] = R->st[i] + v[i];
}

static int run_stop_at(simrun *R, double tstop) {
  R->tstop = tstop;
  return R->p->kind == BG_SIM_IDA ? IDASetStopTime(R->mem, tstop) : CVodeSetStopTime(R->mem, tstop);
}

/* Advances to tout; returns the solver flag (< 0 failure) with R->tcur set. */
static int run_to(simrun *R, double tout) {
  double tret = R->tcur;
  int f;
  /* the algebraic unknowns out of the error test: a row between two steps
   * would be an interpolation nothing controls, so every row is a step */
  int stop = R->exact_rows && tout < R->tstop;
  if (stop) IDASetStopTime(R->mem, tout);
  if (R->p->kind == BG_SIM_IDA)
    f = IDASolve(R->mem, tout, &tret, R->y, R->yp, IDA_NORMAL);
  else
    f = CVode(R->mem, tout, R->y, &tret, CV_NORMAL);
  if (stop && f >= 0 && tret < R->tstop) IDASetStopTime(R->mem, R->tstop);
  R->tcur = tret;
  return f;
}

#define SIM_RATES (-1002) /* run_calcic: the start's rates break a constraint's time derivative */

/* A restart of a DAE with dependent stores whose IDACalcIC failed and whose
 * constraints' time derivatives could not be used (bg_eqsys_restart_rates
 * refuses a constraint that reads an algebraic unknown): IDACalcIC moves a
 * dependent store's rate, not its value, so it cannot reduce a constraint's
 * residual, which after a step is the solver's tolerance, not 0 (property
 * seed 7607, docs/property.md finding 31). As at the start (bg_eqsys_initial): the algebraic rows
 * solved first with the states held, then IDACalcIC for the rest. Returns
 * IDACalcIC's flag, or f (the first failure) when Newton could not. */
static int constraints_then_calcic(simrun *R, double tnext, int f) {
  if (bg_eqsys_is_reduced(R->s)) return f;
  int nd = 0;
  for (int i = 0; i < R->n; i++) nd += bg_eqsys_is_differential(R->s, i) && bg_eqsys_is_algebraic_row(R->s, i);
  double *y = N_VGetArrayPointer(R->y);
  if (nd == 0 || bg_eqsys_consistent(R->s, R->tcur, y, 30)) return f;
  stats_now(R, R->st); /* IDAReInit resets the counters */
  if (IDAReInit(R->mem, R->tcur, R->y, R->yp) < 0) return f;
  return IDACalcIC(R->mem, IDA_YA_YDP_INIT, tnext);
}

/* IDA: consistent algebraic values and derivatives at R->tcur, looking
 * ahead to tnext. Returns the IDA flag. */
static int run_calcic(simrun *R, double tnext) {
  /* a look-ahead that is R->tcur itself but for rounding is a thousandth of
   * the span instead: rows at multiples of dt meet an input's breakpoint one
   * ulp late (0.15000000000000002 after a step at 0.15), IDA refuses a tout1
   * that close ("too close to t0"), and the run stopped there (property
   * seeds 1423, 1731, 6951) */
  double span = R->p->t_end - R->p->t0;
  if (fabs(tnext - R->tcur) <= 1e-9 * span) tnext = R->tcur + 1e-3 * span;
  if (R->mask) IDASetId(R->mem, R->id); /* which unknowns are algebraic, for IDACalcIC */
  int f = IDACalcIC(R->mem, IDA_YA_YDP_INIT, tnext);
  if (R->mask) IDASetId(R->mem, R->mask); /* which are in the error test (untrap) */
  double h = 1e-5 * (R->p->t_end - R->p->t0);
  /* a restart of a DAE with dependent stores: IDACalcIC cannot reduce a
   * constraint's residual (it reads no rate) and failed or not by rounding,
   * so by the order of the equations (docs/property.md, findings 2c, 4, 9):
   * the constraints' time derivatives in their place (eqsys.h) */
  if (f < 0 && R->tcur > R->p->t0 &&
      bg_eqsys_restart_rates(R->s, R->tcur, N_VGetArrayPointer(R->y), N_VGetArrayPointer(R->yp), h) == 0) {
    stats_now(R, R->st); /* IDAReInit resets the counters */
    return IDAReInit(R->mem, R->tcur, R->y, R->yp);
  }
  if (f < 0 && R->tcur > R->p->t0) f = constraints_then_calcic(R, tnext, f);
  if (f >= 0) f = IDAGetConsistentIC(R->mem, R->y, R->yp);
  /* IDACalcIC cannot see a dependent store's rate (its row holds no yp):
   * from the constraints' time derivative, then IDA restarts from it */
  /* IDACalcIC leaves the algebraic unknowns' rates as guessed (0 at the
   * start): a switching model's modes are decided by where the solution is a
   * moment later, y + delta y', and IDA's first steps on tight tolerances
   * failed their error test from that wrong y' (the rectifier with a series
   * resistor at atol 1e-12). Only at the start (a restart keeps the rates IDA
   * interpolated there: computed again after the rectifier's third event,
   * they left IDA 150 000 steps with an error test failure each; not
   * understood) and only for switching models (on bond_loop the computed
   * rates made IDA's result 10 times less accurate, 4.3e-6 instead of
   * 4.3e-7; not understood either): docs/simulation.md. */
  int moved = f >= 0 && R->nroot && R->tcur == R->p->t0 &&
              bg_eqsys_algebraic_rates(R->s, R->tcur, N_VGetArrayPointer(R->y), N_VGetArrayPointer(R->yp), h) > 0;
  if (f >= 0 && (bg_eqsys_dependent_rates(R->s, R->tcur, N_VGetArrayPointer(R->y), N_VGetArrayPointer(R->yp), h) > 0 || moved)) {
    stats_now(R, R->st); /* IDAReInit resets the counters */
    f = IDAReInit(R->mem, R->tcur, R->y, R->yp);
  }
  /* the rates must satisfy the constraints' time derivatives too, which no
   * row above reads (eqsys.h, bg_eqsys_start_rates); the first row is
   * written from a consistent start only (docs/simulation.md) */
  int g = f >= 0 ? bg_eqsys_start_rates(R->s, R->tcur, N_VGetArrayPointer(R->y), N_VGetArrayPointer(R->yp), h) : 0;
  if (g > 0) {
    stats_now(R, R->st);
    f = IDAReInit(R->mem, R->tcur, R->y, R->yp);
  } else if (g < 0 && R->starting)
    f = SIM_RATES;
  return f;
}

/* ------------------------------------------------------------------ state events
 * docs/simulation.md, "State events": the solver stops at each root of a
 * switching function, the modes are set from the values there, and it
 * starts again (CVodeReInit; IDA: IDAReInit and consistent values again,
 * until the modes agree with them). */
#define SIM_ROW_TOL 100.0 /* allowed residual, in units of rtol |y_i| + atol_i (docs/simulation.md) */
#define SIM_EVENTS_PER_INTERVAL 1000 /* more in one output interval: chattering */
#define SIM_EVENTS_SHOWN 100         /* -v prints the first ones */
#define SIM_MODE_SETTLE 8            /* IDA: consistent values and modes, rounds at most */
#define SIM_CHATTER (-1000)          /* run_to's flag: too many events */
#define SIM_UNSETTLED (-1001)        /* the modes and consistent values disagree */
#define SIM_SLIDING (-1002)          /* a switching function at 0 that no mode holds */

/* The look-ahead of a switching function exactly zero at a restart. */
static double ev_delta(const simrun *R) { return 1e-9 * (R->p->t_end - R->p->t0); }

static int modes_now(simrun *R, const int *dir) {
  if (!R->nroot) return 0;
  int ida = R->p->kind == BG_SIM_IDA;
  return bg_eqsys_modes_update(R->s, R->tcur, N_VGetArrayPointer(R->y), ida ? N_VGetArrayPointer(R->yp) : NULL,
                               dir, ev_delta(R));
}

/* After modes_now of an ODE: SIM_SLIDING when a switching function sat at 0
 * and neither side holds (bg_eqsys_mode_sliding; R->last_root names it), else 0. */
/* SIM_SLIDING for mode e; R->last_root its first root, which the failure names. */
static int slid(simrun *R, int e) {
  int first;
  bg_eqsys_mode_roots(R->s, e, &first);
  R->last_root = first;
  return SIM_SLIDING;
}

static int sliding_now(simrun *R) {
  int e = R->nroot && R->p->kind != BG_SIM_IDA ? bg_eqsys_mode_sliding(R->s) : -1;
  return e < 0 ? 0 : slid(R, e);
}

/* How far the rows of two sides of a switch may differ and still be one
 * law (docs/simulation.md, "Continuous switches"): an algebraic row within
 * the row check's SIM_ROW_TOL units of its unknown's tolerance (times
 * |dF_i/dy_i|, 1 before the start's coefficients exist), a rate row by so
 * little that over the whole span it moves its state by less than that. */
static double *row_tolerances(const simrun *R) {
  int n = R->n, ida = R->p->kind == BG_SIM_IDA;
  const double *y = N_VGetArrayPointer(R->y), *atol = N_VGetArrayPointer(R->atol);
  double *tol = bg_xmalloc((size_t)(n > 0 ? n : 1) * sizeof(double)), span = R->p->t_end - R->p->t0;
  for (int k = 0; k < n; k++) {
    double u = SIM_ROW_TOL * (R->p->rtol * fabs(y[k]) + atol[k]);
    tol[k] = ida && bg_eqsys_is_algebraic_row(R->s, k) ? u * (R->coef ? R->coef[k] : 1) : u / span;
  }
  return tol;
}

/* IDA, when the modes from the values at t flip back and forth (switching
 * functions at 0 together: a diode bridge at a zero of its source): the
 * modes of the limit from the right (the algebraic equations solved a
 * moment later under them, until they agree), then consistent values at t
 * under those modes, kept as they are: at t itself the switching functions
 * sit at 0 and cannot decide them (docs/simulation.md). */
static int settle_right(simrun *R, double tnext) {
  /* A moment later by 1e-9 of the span first; when the modes do not agree
   * there, later: the state at a located root carries the tolerance's
   * error, and a moment so short moves the switching functions less than
   * that (the bridge at rtol 1e-9: 1e-7 V in 4e-11 s against 1e-8 V of
   * error, and the modes cycled) */
  int nm = bg_eqsys_nmodes(R->s), g = 1;
  double *m0 = bg_xmalloc((size_t)nm * sizeof(double)), used = 0;
  bg_eqsys_modes_get(R->s, m0);
  for (double d = ev_delta(R); g && d <= 1e4 * ev_delta(R); d *= 100) {
    bg_eqsys_modes_set(R->s, m0);
    g = bg_eqsys_modes_right(R->s, R->tcur, N_VGetArrayPointer(R->y), N_VGetArrayPointer(R->yp), d,
                             SIM_MODE_SETTLE + 2 * nm);
    used = d;
  }
  free(m0);
  if (g) return SIM_UNSETTLED;
  stats_now(R, R->st);
  int f = IDAReInit(R->mem, R->tcur, R->y, R->yp), e;
  f = f < 0 ? f : run_calcic(R, tnext);
  /* the modes chosen from the rates under the modes before: do their own
   * rates keep them? (a sliding mode at its start has no mode that does) */
  double *tol = f >= 0 ? row_tolerances(R) : NULL;
  e = tol ? bg_eqsys_modes_slide(R->s, R->tcur, N_VGetArrayPointer(R->y), N_VGetArrayPointer(R->yp), used, tol) : 0;
  free(tol);
  return e > 0 ? slid(R, e - 1) : f;
}

/* IDA: consistent values under the current modes, then the modes from
 * those values, until nothing changes; else the limit from the right. */
static int settle(simrun *R, double tnext) {
  int f = run_calcic(R, tnext);
  for (int k = 0; f >= 0 && R->nroot && k < SIM_MODE_SETTLE; k++) {
    if (!modes_now(R, NULL)) return f;
    stats_now(R, R->st);
    f = IDAReInit(R->mem, R->tcur, R->y, R->yp);
    if (f >= 0) f = run_calcic(R, tnext);
  }
  if (f >= 0 && R->nroot) f = settle_right(R, tnext);
  return f;
}

/* The same condition crossing the same way again within this fraction of
 * the span is the same switching found again (after the mode search of the
 * limit from the right it may be found a few 1e-10 s later): logged once;
 * crossing back within it, the two cancel (no switching took place) */
#define SIM_EVENT_SAME 1e-6

/* Takes entry k out of the event log. */
static void unlog(bg_simresult *r, int k) {
  r->nevents--;
  memmove(r->event_t + k, r->event_t + k + 1, (size_t)(r->nevents - k) * sizeof(double));
  memmove(r->event_cond + k, r->event_cond + k + 1, (size_t)(r->nevents - k) * sizeof(int));
  memmove(r->event_dir + k, r->event_dir + k + 1, (size_t)(r->nevents - k));
}

/* Logs root i's crossing; 1 when it crossed back (an entry cancelled). */
static int log_event(simrun *R, int i, int dir) {
  bg_simresult *r = R->r;
  double near = SIM_EVENT_SAME * (R->p->t_end - R->p->t0);
  for (int k = r->nevents - 1; k >= 0 && R->tcur - r->event_t[k] <= near; k--)
    if (r->event_cond[k] == i) {
      if ((r->event_dir[k] > 0) == (dir > 0)) return 0;
      unlog(r, k); /* there and back at once: no switching */
      return 1;
    }
  if (r->nevents == R->evcap) {
    R->evcap = R->evcap ? 2 * R->evcap : 64;
    r->event_t = bg_xrealloc(r->event_t, (size_t)R->evcap * sizeof(double));
    r->event_cond = bg_xrealloc(r->event_cond, (size_t)R->evcap * sizeof(int));
    r->event_dir = bg_xrealloc(r->event_dir, (size_t)R->evcap);
  }
  r->event_t[r->nevents] = R->tcur, r->event_cond[r->nevents] = i;
  r->event_dir[r->nevents++] = (signed char)(dir > 0 ? 1 : -1);
  return 0;
}

/* -v: the events logged since the last call (a redone interval logs its
 * events again: they are not shown twice). */
static void show_events(simrun *R) {
  const bg_simresult *r = R->r;
  for (; R->p->verbose && R->nev_shown < r->nevents; R->nev_shown++) {
    int k = R->nev_shown;
    if (k < SIM_EVENTS_SHOWN)
      bg_logf(R->p->log, BG_LOG_PROGRESS, "simulate: state event at t = %.10g: %s (%s)", r->event_t[k],
              bg_eqsys_root_text(R->s, r->event_cond[k]), r->event_dir[k] > 0 ? "rising" : "falling");
    else if (k == SIM_EVENTS_SHOWN)
      bg_logf(R->p->log, BG_LOG_PROGRESS, "simulate: more state events (not shown; the JSON lists them all)");
  }
}

/* Modes that changed at an event without a root of their own (the mode
 * search of the limit from the right turns the second diode of a series
 * pair off with the first): logged too, so the log says every switching;
 * the direction from the mode's change. */
static void log_silent(simrun *R) {
  int nm = bg_eqsys_nmodes(R->s), first;
  for (int e = 0; e < nm; e++) {
    if (R->modes_ev[e] == R->modes_before[e]) continue;
    int nr = bg_eqsys_mode_roots(R->s, e, &first), fired = 0;
    for (int j = 0; j < nr; j++) fired |= R->rootsfound[first + j] != 0;
    if (!fired) log_event(R, first, bg_eqsys_mode_direction(R->s, e, R->modes_before[e], R->modes_ev[e]));
  }
}

/* A memory function's root that left its mode as it was (stick: the
 * velocity crossed 0 where the force is beyond the limit, so it slips on)
 * switched nothing: its entry logged at this event is taken back. */
static void unlog_memory(simrun *R, int nlogged) {
  bg_simresult *r = R->r;
  int nm = bg_eqsys_nmodes(R->s), first;
  for (int e = 0; e < nm; e++) {
    if (!bg_eqsys_mode_memory(R->s, e) || R->modes_ev[e] != R->modes_before[e]) continue;
    int nr = bg_eqsys_mode_roots(R->s, e, &first);
    for (int k = r->nevents - 1; k >= nlogged; k--)
      if (r->event_cond[k] >= first && r->event_cond[k] < first + nr) unlog(r, k);
  }
}

/* Continuous switches (docs/simulation.md): a mode whose switching
 * function crossed back at once is let loose when its two sides are one law
 * here, to the rows' tolerance: an algebraic row within the row check's
 * SIM_ROW_TOL units of its unknown's tolerance, a rate row by so little that
 * over the whole span it moves its state by less than that. */
static void loosen_continuous(simrun *R) {
  int n = R->n, ida = R->p->kind == BG_SIM_IDA;
  const double *y = N_VGetArrayPointer(R->y), *atol = N_VGetArrayPointer(R->atol);
  double *tol = NULL, amax = 0;
  for (int i = 0; i < R->nroot; i++) {
    int e = bg_eqsys_root_mode(R->s, i);
    if (!R->back[i] || bg_eqsys_mode_loose(R->s, e)) continue;
    if (!tol) {
      tol = row_tolerances(R);
      for (int k = 0; k < n; k++) amax = fmax(amax, atol[k]);
    }
    /* the crossing back set its mode; the other side is the one held before */
    bg_eqsys_mode_loosen(R->s, e, R->modes_before[e], R->tcur, y, ida ? N_VGetArrayPointer(R->yp) : NULL, tol,
                         R->p->rtol, amax);
  }
  free(tol);
}

/* At a root: log what fired, set the modes, restart there. A loose mode's
 * root is its switching function leaving its band: a mode again, set from
 * the values here and logged by log_silent if it switched. */
static int on_event(simrun *R, double tnext) {
  int ida = R->p->kind == BG_SIM_IDA, f;
  f = ida ? IDAGetRootInfo(R->mem, R->rootsfound) : CVodeGetRootInfo(R->mem, R->rootsfound);
  if (f < 0) return f;
  int nlogged = R->r->nevents;
  bg_eqsys_modes_get(R->s, R->modes_before);
  for (int i = 0; i < R->nroot; i++) {
    R->back[i] = 0;
    if (R->rootsfound[i] && bg_eqsys_mode_loose(R->s, bg_eqsys_root_mode(R->s, i)))
      bg_eqsys_mode_tighten(R->s, bg_eqsys_root_mode(R->s, i)), R->rootsfound[i] = 0;
    else if (R->rootsfound[i])
      R->back[i] = (unsigned char)log_event(R, i, R->rootsfound[i]), R->last_root = i;
  }
  if (++R->nev_interval > SIM_EVENTS_PER_INTERVAL) return SIM_CHATTER;
  stats_now(R, R->st); /* ReInit resets the counters */
  modes_now(R, R->rootsfound);
  if ((f = sliding_now(R))) return f;
  loosen_continuous(R);
  if (!ida) f = CVodeReInit(R->mem, R->tcur, R->y);
  else if ((f = IDAReInit(R->mem, R->tcur, R->y, R->yp)) >= 0) f = settle(R, tnext);
  bg_eqsys_modes_get(R->s, R->modes_ev);
  if (f >= 0) log_silent(R), unlog_memory(R, nlogged);
  /* IDA finds the root on interpolated algebraic values; when the
   * consistent ones at that time say no condition has switched yet (every
   * mode as before), it was not an event: it is found again a moment later. */
  if (f >= 0 && ida && !memcmp(R->modes_ev, R->modes_before, (size_t)bg_eqsys_nmodes(R->s) * sizeof(double)))
    R->r->nevents = nlogged;
  show_events(R);
  return f < 0 ? f : run_stop_at(R, R->tstop);
}

_Static_assert(CV_ROOT_RETURN == IDA_ROOT_RETURN, "one flag for both solvers' roots");

/* Advances to tout through the state events on the way. */
static int run_to_events(simrun *R, double tout) {
  int f;
  while ((f = run_to(R, tout)) == CV_ROOT_RETURN) { /* == IDA_ROOT_RETURN */
    double span = R->p->t_end - R->p->t0;
    f = on_event(R, tout > R->tcur + 1e-9 * span ? tout : R->tcur + 1e-6 * span);
    if (f < 0) return f;
    if (R->tcur >= tout) return 0;
  }
  return f;
}

/* Restart after a breakpoint: the inputs jump, the states do not. */
static int run_restart(simrun *R, double tb, double tnext) {
  stats_now(R, R->st);
  R->tcur = tb;
  modes_now(R, NULL);
  if (sliding_now(R)) return SIM_SLIDING;
  if (R->p->kind != BG_SIM_IDA) return CVodeReInit(R->mem, tb, R->y);
  /* the algebraic rows at the inputs' new values first, as at the start
   * (bg_eqsys_initial): IDACalcIC's Newton has no rate of a dependent store
   * to move, and from the old values it failed on a DAE of dependent stores
   * driven by a step (property campaign, docs/property.md finding 7) */
  bg_eqsys_consistent(R->s, tb, N_VGetArrayPointer(R->y), 30);
  int f = IDAReInit(R->mem, tb, R->y, R->yp);
  return f < 0 ? f : settle(R, tnext);
}

/* ------------------------------------------------------------------ results */
static int record(simrun *R, bg_simresult *r, double t) {
  double *out = r->values + (size_t)r->nrows * (size_t)r->nout;
  double *y = N_VGetArrayPointer(R->y), *yp = N_VGetArrayPointer(R->yp);
  /* An ODE's outputs are functions of (t, y) alone: no derivative needed
   * (one evaluation per row instead of two; rows can outnumber steps). */
  if (R->p->kind != BG_SIM_IDA) yp = NULL;
  /* IDA's rate of a dependent store is the BDF's derivative estimate, whose
   * error is that of the states over the step (2e-5 of a flow's range where
   * the states had 6e-9, at rtol 1e-9: docs/property.md, finding 19). The
   * row takes the rates from the constraints' time derivatives at the row's
   * states instead (bg_eqsys_restart_rates, the states held; -1: nothing
   * changed), differenced away from the segment's end. Dense, like the run
   * (up to 200 unknowns); the solver's own vectors stay as they are. */
  double *yr = NULL, *ypr = NULL;
  if (yp && !R->p->sparse && R->n > 0) {
    double h = 1e-5 * (R->p->t_end - R->p->t0);
    yr = bg_xmalloc((size_t)R->n * sizeof(double)), ypr = bg_xmalloc((size_t)R->n * sizeof(double));
    memcpy(yr, y, (size_t)R->n * sizeof(double)), memcpy(ypr, yp, (size_t)R->n * sizeof(double));
    if (bg_eqsys_restart_rates(R->s, R->tcur, yr, ypr, R->tcur + 2 * h < R->tseg ? h : -h) == 0) y = yr, yp = ypr;
  }
  int rc = bg_eqsys_outputs(R->s, R->tcur, y, yp, out);
  free(yr), free(ypr);
  if (rc) {
    keep_error(R);
    return -1;
  }
  if (r->states) memcpy(r->states + (size_t)r->nrows * (size_t)R->n, N_VGetArrayPointer(R->y),
                        (size_t)R->n * sizeof(double));
  r->t[r->nrows++] = t;
  r->t_reached = t;
  R->nfunc_err = 0;
  return 0;
}

static void fail_events(simrun *R, bg_simresult *r, int flag) {
  bg_strbuf sb = {0};
  const char *what = R->last_root >= 0 ? bg_eqsys_root_text(R->s, R->last_root) : "?";
  if (flag == SIM_CHATTER)
    bg_sb_printf(&sb, "simulation failed at t = %.9g: more than %d state events in one output interval, "
                      "the last at %s: the condition switches back and forth (chattering, a sliding "
                      "mode such as friction at rest) and the equations have no mode that holds there",
                 R->tcur, SIM_EVENTS_PER_INTERVAL, what);
  else if (flag == SIM_SLIDING)
    bg_sb_printf(&sb, "simulation failed at t = %.9g: the switching condition %s sits exactly at its "
                      "switching point and neither side holds (under each, the rates move the state to "
                      "the other side: a sliding mode such as friction at rest, which the equations "
                      "have no mode for)", R->tcur, what);
  else
    bg_sb_printf(&sb, "simulation failed at t = %.9g: at a switching point (%s) no modes of the conditions "
                      "agree with consistent values, neither at t (%d rounds of IDACalcIC) nor a moment later "
                      "(the limit from the right, searched one mode at a time): the switching conditions "
                      "contradict each other there. Try a smaller rtol, or give a law a small smooth transition "
                      "(e.g. a resistance instead of a jump) where it switches", R->tcur, what, SIM_MODE_SETTLE);
  r->partial = 1;
  if (R->tcur > r->t_reached) r->t_reached = R->tcur;
  free(r->message);
  r->message = strdup(bg_sb_str(&sb));
  bg_sb_free(&sb);
}

/* A failure at a switch: right after a state event, or at the start of a
 * model with switching conditions (where they may sit at their switching
 * points): said in words, with what works (docs/simulation.md). */
static void at_switch_words(const simrun *R, const bg_simresult *r, double t, bg_strbuf *sb) {
  double span = R->p->t_end - R->p->t0, near = 1e-6 * span;
  if (!R->nroot) return;
  double since = r->nevents > 0 ? t - r->event_t[r->nevents - 1] : INFINITY;
  if (since <= 0)
    bg_sb_printf(sb, ". This is at a state event (%s): the run failed at a switch",
                 bg_eqsys_root_text(R->s, r->event_cond[r->nevents - 1]));
  else if (since <= near)
    bg_sb_printf(sb, ". This is %.3g s after a state event (%s): the run failed at a switch", since,
                 bg_eqsys_root_text(R->s, r->event_cond[r->nevents - 1]));
  else if (t - R->p->t0 <= near)
    bg_sb_puts(sb, ". This is at the start, where switching conditions may sit exactly at their switching points");
  else
    return;
  bg_sb_printf(sb, "; what may work: a looser atol (the algebraic values there are tiny: atol = 1e-6), a "
                   "smaller or larger rtol than %g, or a law with a smooth transition at the switch", R->p->rtol);
}

/* A failure whose step is below the spacing of the time values at t (t + h
 * == t: times this large cannot resolve the model's time scale), or whose
 * first step, guessed from a vast output interval, never came down to the
 * model's time scale: the real cause, instead of the flag's usual words.
 * 1 when it was one of them. */
static int time_axis_words(simrun *R, double t, bg_strbuf *sb) {
  int ida = R->p->kind == BG_SIM_IDA;
  sunrealtype h = 0;
  long steps = 0;
  if (ida) IDAGetCurrentStep(R->mem, &h), IDAGetNumSteps(R->mem, &steps);
  else CVodeGetCurrentStep(R->mem, &h), CVodeGetNumSteps(R->mem, &steps);
  double gap = nextafter(fabs(t), INFINITY) - fabs(t), span = R->p->t_end - R->p->t0;
  if (!(h > 0) || !isfinite(gap)) return 0;
  if (h <= 4 * gap)
    bg_sb_printf(sb, "the time step (%.3g) is below the spacing of the time values at t = %.9g "
                 "(adjacent doubles there are %.3g apart, so t + h == t): a time axis this far "
                 "from 0 cannot resolve the model's time scale; start it nearer 0 (t0 = 0, "
                 "t_end = %.6g)", h, t, gap, span);
  else if (steps == 0 && h < 1e-20 * span)
    bg_sb_printf(sb, "the first step, guessed from the span (%.3g), failed again and again down to "
                 "h = %.3g: the model's time scale is far shorter than a span this long; simulate "
                 "a shorter span (or give max_step)", span, h);
  else return 0;
  return 1;
}

static void fail(simrun *R, bg_simresult *r, int flag, const char *during) {
  if (flag == SIM_CHATTER || flag == SIM_UNSETTLED || flag == SIM_SLIDING) { fail_events(R, r, flag); return; }
  if (flag == SIM_RATES) {
    bg_strbuf sb = {0};
    bg_sb_printf(&sb, "simulation failed at t = %.9g%s: the rates found there do not satisfy the time derivative "
                      "of a dependent store's constraint (its input or modulus changes), and no rates that do "
                      "were found (the constraint reads an algebraic unknown, or Newton did not converge): "
                      "the first row would not be a solution", R->tcur, during);
    r->partial = 1;
    free(r->message);
    r->message = strdup(bg_sb_str(&sb));
    bg_sb_free(&sb);
    return;
  }
  bg_strbuf sb = {0};
  int ida = R->p->kind == BG_SIM_IDA;
  char *fname = ida ? IDAGetReturnFlagName(flag) : CVodeGetReturnFlagName(flag);
  double t = R->tcur > r->t_reached ? R->tcur : r->t_reached;
  bg_sb_printf(&sb, "simulation failed at t = %.9g%s: ", t, during);
  if (R->nfunc_err || !time_axis_words(R, t, &sb))
    bg_sim_explain(ida, flag, R->nfunc_err ? R->err : NULL, &sb);
  bg_sb_printf(&sb, " (%s %s", ida ? "IDA" : "CVODE", fname ? fname : "?");
  int rtfunc = flag == (ida ? IDA_RTFUNC_FAIL : CV_RTFUNC_FAIL); /* its text says no more */
  if (R->sunmsg[0] && !rtfunc) bg_sb_printf(&sb, ": %s", R->sunmsg);
  bg_sb_puts(&sb, ")");
  at_switch_words(R, r, t, &sb);
  free(fname); /* allocated by SUNDIALS */
  r->partial = 1;
  if (t > r->t_reached) r->t_reached = t;
  free(r->message);
  r->message = strdup(bg_sb_str(&sb));
  bg_sb_free(&sb);
}

static void fail_eval(simrun *R, bg_simresult *r) {
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "simulation failed at t = %.9g: the equations could not be evaluated: %s",
               R->tcur, R->err);
  r->partial = 1;
  free(r->message);
  r->message = strdup(bg_sb_str(&sb));
  bg_sb_free(&sb);
}

/* -v: one line with the time reached as a percentage of the span, at most
 * one per p->progress_every seconds of wall time (a short run prints none;
 * bg_simulate prints the summary). Called at output rows and, every 256
 * evaluations, from the callbacks (t is then the solver's trial time). */
static void progress(simrun *R, double t) {
  const bg_simplan *p = R->p;
  double now = wall();
  if (!p->verbose || now - R->wall_last < p->progress_every) return;
  R->wall_last = now;
  if (t > R->t_shown) R->t_shown = t;
  long st[5];
  stats_now(R, st);
  bg_logf(R->p->log, BG_LOG_PROGRESS, "simulate: t = %.6g (%.1f%% of the span), %ld steps, %.1f s",
          R->t_shown, 100.0 * (R->t_shown - p->t0) / (p->t_end - p->t0), st[0], now - R->wall0);
}

/* ------------------------------------------------------------------ row checks
 * IDA interpolates between its steps, and a step can cover a fast change the
 * error test never saw: a diode that conducts between two steps at which it
 * is off (docs/simulation.md, "Every row satisfies the equations"). Each
 * output row's algebraic residuals are measured in units of the tolerance of
 * their unknown; a row beyond it is integrated again from the last row with
 * steps of at most a tenth of the interval, and what still fails is counted
 * and reported, never silent. */
#define SIM_REDO_STEPS 10 /* a redone interval takes at least this many steps */

/* Largest residual of the algebraic rows at the current point, in units of
 * the tolerance; *row gets its row. Infinity when the evaluation fails. */
static double row_violation(simrun *R, int *row) {
  const double *y = N_VGetArrayPointer(R->y), *atol = N_VGetArrayPointer(R->atol);
  *row = -1;
  if (bg_eqsys_residual(R->s, R->tcur, y, N_VGetArrayPointer(R->yp), R->res)) return INFINITY;
  double worst = 0;
  for (int k = 0; k < R->nalg; k++) {
    int i = R->alg[k];
    double v = fabs(R->res[i]) / (R->coef[i] * (R->p->rtol * fabs(y[i]) + atol[i]));
    if (!(v <= worst)) worst = v, *row = i;
  }
  return worst;
}

/* The residual of row i is in the units of its equation, not of its
 * unknown: divided by |dF_i/dy_i| (the coefficient of the unknown it is
 * solved for, from the Jacobian at the start; 1 where that is 0) it is the
 * Newton correction of that unknown alone, comparable with its tolerance. */
static void row_terms(simrun *R, const double *J);

static void row_coefficients(simrun *R) {
  int n = R->n;
  R->coef = bg_xmalloc((size_t)(n > 0 ? n : 1) * sizeof(double));
  for (int i = 0; i < n; i++) R->coef[i] = 1;
  if ((!R->nalg && !R->row_ewt) || n > 1000) return; /* dense n x n below (8 MB at 1000) */
  double *J = bg_xmalloc((size_t)n * (size_t)n * sizeof(double));
  if (bg_eqsys_jac_dense(R->s, R->tcur, N_VGetArrayPointer(R->y), N_VGetArrayPointer(R->yp), 0.0, J) == 0) {
    for (int k = 0; k < R->nalg; k++) {
      int i = R->alg[k];
      double c = fabs(J[(size_t)i * (size_t)n + (size_t)i]);
      if (c > 0 && isfinite(c)) R->coef[i] = c;
    }
    if (R->row_ewt) row_terms(R, J);
  }
  free(J);
}

/* ------------------------------------------------------------------ error weights
 * An index-reduced DAE (docs/simulation.md, "Error weights of a reduced
 * DAE"; docs/property.md, finding 25): its dummy derivatives and the
 * unknowns its differentiated constraints fix can be identically 0 (the
 * flow an MTF with both ports on one junction holds at 0, the rate of a
 * store that lost its state to it) and computed as a sum of terms of order
 * 1 that cancel. Newton leaves such an unknown with the error of its terms,
 * rtol times their size, but IDA's weight 1 / (rtol |y_i| + atol_i) measures
 * it against atol alone: that noise failed the error test at every third
 * step and held IDA at order 1 with steps of 1e-5 (90 885 steps for 2 s),
 * whose errors in every other unknown added up far beyond the tolerance.
 * An algebraic unknown below SIM_NOISE_RTOLS rtol of its largest term
 * |dF_i/dy_j| |y_j| / |dF_i/dy_i| (the coefficients from the start's
 * Jacobian) is such noise: its relative tolerance is taken of that term,
 * the accuracy its equation can give it. Every other unknown keeps IDA's
 * weight (taking the terms' size always made seed 5817's reduced run 60
 * times less accurate, 7.7e-9 instead of 1.2e-10). IDA calls this at every
 * step. */
#define SIM_NOISE_RTOLS 100.0
static int trapped_now(simrun *R);
static int ewt_rows(N_Vector yv, N_Vector wv, void *ud) {
  simrun *R = ud;
  /* a trapped interval is stopped here, at the start of a step, rather
   * than at its row or at IDA's limit of steps (untrap) */
  if (trapped_now(R)) return R->trap_hit = 1, -1;
  const double *y = N_VGetArrayPointer(yv), *atol = N_VGetArrayPointer(R->atol);
  double *w = N_VGetArrayPointer(wv), rtol = R->p->rtol;
  for (int i = 0; i < R->n; i++) {
    double m = fabs(y[i]), big = 0;
    for (int q = R->term_adr ? R->term_adr[i] : 0; R->term_adr && q < R->term_adr[i + 1]; q++) {
      double t = R->term_c[q] * fabs(y[R->term_j[q]]);
      if (t > big) big = t;
    }
    if (m < (R->terms_always ? big : SIM_NOISE_RTOLS * rtol * big)) m = big;
    double d = rtol * m + atol[i];
    if (!(d > 0)) return -1;
    w[i] = 1.0 / d;
  }
  return 0;
}

/* The terms of each algebraic unknown's row from the start's Jacobian J
 * (dF/dy, dense, column-major): until they are known (IDACalcIC at the
 * start) the weights are IDA's own. */
static void row_terms(simrun *R, const double *J) {
  int n = R->n, m = 0;
  for (int pass = 0; pass < 2; pass++) {
    if (pass) {
      R->term_adr = bg_xmalloc((size_t)(n + 1) * sizeof(int));
      R->term_j = bg_xmalloc((size_t)(m > 0 ? m : 1) * sizeof(int));
      R->term_c = bg_xmalloc((size_t)(m > 0 ? m : 1) * sizeof(double));
      m = 0;
    }
    for (int i = 0; i < n; i++) {
      if (pass) R->term_adr[i] = m;
      if (bg_eqsys_is_differential(R->s, i)) continue;
      double d = fabs(J[(size_t)i * (size_t)n + (size_t)i]);
      if (!(d > 0 && isfinite(d))) d = 1;
      for (int j = 0; j < n; j++) {
        double c = fabs(J[(size_t)j * (size_t)n + (size_t)i]) / d;
        if (j == i || !(c > 0 && isfinite(c))) continue;
        if (pass) R->term_j[m] = j, R->term_c[m] = c;
        m++;
      }
    }
  }
  R->term_adr[n] = m;
}

static void keep_last(simrun *R) {
  R->nev_interval = 0;
  if (R->row_ewt) stats_now(R, R->st_row); /* (only a reduced DAE is watched: untrap) */
  if (!R->nalg) return;
  if (R->nroot) bg_eqsys_modes_get(R->s, R->modes_last), R->nev_last = R->r->nevents;
  memcpy(R->ylast, N_VGetArrayPointer(R->y), (size_t)R->n * sizeof(double));
  memcpy(R->yplast, N_VGetArrayPointer(R->yp), (size_t)R->n * sizeof(double));
  R->tlast = R->tcur;
}

/* The interval from the last row to tout again, with short steps or not. */
static int redo_interval(simrun *R, double tout, double tstop, int short_steps) {
  stats_now(R, R->st);
  memcpy(N_VGetArrayPointer(R->y), R->ylast, (size_t)R->n * sizeof(double));
  memcpy(N_VGetArrayPointer(R->yp), R->yplast, (size_t)R->n * sizeof(double));
  R->tcur = R->tlast;
  if (R->nroot) bg_eqsys_modes_set(R->s, R->modes_last), R->r->nevents = R->nev_last;
  /* the kept yp is interpolated: consistent derivatives again (IDACalcIC) */
  int f = IDAReInit(R->mem, R->tlast, R->y, R->yp);
  if (f >= 0) f = run_calcic(R, tout);
  double h = (tout - R->tlast) / SIM_REDO_STEPS;
  if (f >= 0 && short_steps) f = IDASetMaxStep(R->mem, R->p->max_step > 0 && R->p->max_step < h ? R->p->max_step : h);
  if (f >= 0) f = run_stop_at(R, tstop);
  if (f >= 0) f = run_to_events(R, tout);
  int g = IDASetMaxStep(R->mem, R->p->max_step > 0 ? R->p->max_step : 0.0);
  return f < 0 ? f : g;
}

/* Checks the row at tout (IDA), redoing its interval once when it violates
 * the equations; what remains is counted in r. Returns the solver flag. */
static int check_row(simrun *R, bg_simresult *r, double tout, double tstop) {
  int row, f = 0;
  if (!R->nalg || R->tcur <= R->tlast) return 0;
  double v = row_violation(R, &row);
  if (v <= SIM_ROW_TOL) return 0;
  f = redo_interval(R, tout, tstop, 1);
  if (f < 0) return f;
  r->rows_redone++;
  v = row_violation(R, &row);
  if (v <= SIM_ROW_TOL) return 0;
  if (r->rows_violating++ == 0 || v > r->row_worst) {
    r->row_worst = v, r->row_worst_t = tout;
    r->row_worst_unknown = row >= 0 ? bg_eqsys_name(R->s, row) : NULL;
  }
  return 0;
}

/* The trap of a reduced DAE (docs/simulation.md, "Steps that cannot grow";
 * docs/property.md, finding 30): an algebraic unknown computed from the
 * states' rates (a dummy derivative) carries the BDF rates' error, of order
 * h at order 1, which cancels in IDA's error estimate while the step stays
 * the same and shows up whole when it changes. Every step twice the last
 * then failed the test; back at the last size it passed, and the step and
 * the order never grew (seed 5044's variant: 306 180 steps with 305 509
 * failures, 37 s, 2.9e-5 of the range off). An interval of at least
 * SIM_TRAP_STEPS steps that failed the test at half of them or more is run
 * again from the last row with the remedy, kept for the rest of the run:
 * the unknowns whose rows read the states' rates out of the error test
 * (rate_readers), which cannot hold them, and every algebraic unknown held
 * to its largest term (ewt_rows). A run never trapped is not touched. */
#define SIM_TRAP_STEPS 500

/* The mask of the algebraic unknowns whose rows read a state's rate
 * (dF_i/dy'_j != 0: J with cj = 1 against cj = 0, dense, at the point
 * reached), then those whose rows read one of them, and so on (a queue: each
 * column looked at once): 0 out of the error test, 1 in. NULL when there is
 * none or the Jacobian cannot be had. */
static N_Vector rate_readers(simrun *R) {
  int n = R->n, nq = 0;
  if (n > 1000) return NULL; /* dense n x n, twice (16 MB at 1000) */
  size_t nn = (size_t)n * (size_t)n;
  double *J0 = bg_xmalloc(nn * sizeof(double)), *J1 = bg_xmalloc(nn * sizeof(double));
  int *queue = bg_xmalloc((size_t)n * sizeof(int));
  N_Vector mask = N_VNew_Serial(n, R->ctx);
  double *m = N_VGetArrayPointer(mask), *y = N_VGetArrayPointer(R->y), *yp = N_VGetArrayPointer(R->yp);
  N_VConst(1.0, mask);
  if (bg_eqsys_jac_dense(R->s, R->tcur, y, yp, 0.0, J0) == 0 && bg_eqsys_jac_dense(R->s, R->tcur, y, yp, 1.0, J1) == 0)
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n && !bg_eqsys_is_differential(R->s, i); j++)
        if (bg_eqsys_is_differential(R->s, j) && J1[(size_t)j * (size_t)n + (size_t)i] != J0[(size_t)j * (size_t)n + (size_t)i]) {
          m[i] = 0, queue[nq++] = i;
          break;
        }
  for (int k = 0; k < nq; k++) {
    size_t col = (size_t)queue[k] * (size_t)n;
    for (int i = 0; i < n; i++)
      if (m[i] != 0 && !bg_eqsys_is_differential(R->s, i) && J0[col + (size_t)i] != 0) m[i] = 0, queue[nq++] = i;
  }
  free(J0), free(J1), free(queue);
  if (!nq) N_VDestroy(mask), mask = NULL;
  return mask;
}

/* 1 when the steps since the last row are trapped: at least SIM_TRAP_STEPS,
 * the error test failed at half of them or more (IDA's counters since its
 * last ReInit on top of R->st) and a remedy is left. */
static int trapped_now(simrun *R) {
  if (!R->trap_watch || R->trapped || !R->row_ewt || !R->nalg || R->exact_rows || R->starting) return 0;
  long ns = 0, ne = 0;
  if (IDAGetNumSteps(R->mem, &ns) < 0 || IDAGetNumErrTestFails(R->mem, &ne) < 0) return 0;
  long steps = R->st[0] + ns - R->st_row[0], fails = R->st[3] + ne - R->st_row[3];
  return steps >= SIM_TRAP_STEPS && 2 * fails >= steps;
}

/* Runs the interval to tout, watched (trap_watch: ewt_rows may stop it;
 * a restart at an input's breakpoint or a row's redo never is). Trapped (it
 * ends where ewt_rows stopped it, at IDA's limit of steps, or at its row),
 * it is run again with the remedy, once a run; with none to take (no
 * unknown reads a rate, or more than 1 000 unknowns) the run goes on as it
 * would have. Returns the solver flag. */
static int untrap(simrun *R, double tout, double tstop) {
  R->trap_watch = 1;
  int f = run_to_events(R, tout), hit = R->trap_hit;
  R->trap_hit = 0;
  /* (stopped by ewt_rows: IDASolve's flag, or IDACalcIC's at an event) */
  if ((f >= 0 || f == IDA_TOO_MUCH_WORK || hit) && R->tcur > R->tlast && trapped_now(R)) {
    N_Vector mask = rate_readers(R);
    if (mask && (IDASetId(R->mem, mask) < 0 || IDASetSuppressAlg(R->mem, SUNTRUE) < 0))
      IDASetId(R->mem, R->id), N_VDestroy(mask), mask = NULL;
    R->trapped = 1;
    long st[5];
    stats_now(R, st);
    if (mask && R->p->verbose)
      bg_logf(R->p->log, BG_LOG_PROGRESS, "simulate: from t = %.6g to %.6g the error test failed at %ld of %ld steps "
              "(the step could not grow); again with the unknowns computed from the states' rates out of the "
              "error test", R->tlast, tout, st[3] - R->st_row[3], st[0] - R->st_row[0]);
    if (mask) R->mask = mask, R->terms_always = 1;
    if (mask || hit) {
      R->sunmsg[0] = 0; /* (the stop's words) */
      stats_now(R, R->st_row); /* the interval run again counts from here */
      f = redo_interval(R, tout, tstop, 0);
    }
  }
  R->trap_watch = 0;
  return f;
}

/* ------------------------------------------------------------------ the run */
/* One segment between input discontinuities: every output time before its
 * end, then (unless it is the last) up to just before the breakpoint. */
static int run_segment(simrun *R, bg_simresult *r, int *k, double tb, int last) {
  const bg_simplan *p = R->p;
  double span = p->t_end - p->t0;
  /* Stopping a hair before tb keeps every evaluation on the left of the jump
   * (a step at tb evaluates to its new value at tb itself). */
  double tstop = last ? p->t_end : tb - 1e-12 * fmax(fabs(tb), span);
  R->tseg = last ? INFINITY : tstop;
  int f = run_stop_at(R, tstop);
  while (f >= 0 && *k < p->nrows && (last || p->times[*k] < tstop)) {
    double tout = last && *k == p->nrows - 1 ? p->t_end : p->times[*k];
    if (tout > R->tcur + 1e-14 * span) {
      f = untrap(R, tout, tstop); /* run_to_events, watched */
      if (f >= 0) f = check_row(R, r, tout, tstop);
      if (f < 0) { fail(R, r, f, ""); return -1; }
    }
    if (record(R, r, p->times[*k])) { fail_eval(R, r); return -1; }
    keep_last(R);
    (*k)++;
    if (p->verbose) progress(R, R->tcur);
  }
  if (last) return 0;
  if (R->tcur < tstop && (f = run_to_events(R, tstop)) < 0) { fail(R, r, f, ""); return -1; }
  double tnext = *k < p->nrows && p->times[*k] > tb ? p->times[*k] : tb + 1e-3 * span;
  f = run_restart(R, tb, tnext);
  if (f < 0) { fail(R, r, f, " (restarting after an input discontinuity)"); return -1; }
  keep_last(R);
  return 0;
}

/* Keeps the initial point the solver starts from (reports, tests). */
static void keep_start(simrun *R, bg_simresult *r) {
  size_t sz = (size_t)(R->n > 0 ? R->n : 1) * sizeof(double);
  r->n = R->n;
  r->y0 = bg_xmalloc(sz);
  r->yp0 = bg_xmalloc(sz);
  memcpy(r->y0, N_VGetArrayPointer(R->y), (size_t)R->n * sizeof(double));
  if (R->p->kind != BG_SIM_IDA && bg_eqsys_rhs(R->s, R->tcur, r->y0, r->yp0)) memset(r->yp0, 0, sz);
  else if (R->p->kind == BG_SIM_IDA) memcpy(r->yp0, N_VGetArrayPointer(R->yp), (size_t)R->n * sizeof(double));
}

/* The start's constraints solved further than bg_eqsys_initial's 30 Newton
 * steps. IDACalcIC moves a dependent store's rate, never its value (its
 * constraint reads no rate), so from an unsolved constraint it must fail;
 * and Newton's damped steps toward a far solution of a cubic law are short
 * (property seed 7724's renaming: the capacitor's charge from -0.488 to
 * -3.70 took 35 steps, the residual falling at each; docs/property.md,
 * finding 31). 1 when y0 moved (y0 updated), else 0. */
#define IC_NEWTON_STEPS 300
static int constraints_further(simrun *R, double *y0) {
  size_t sz = (size_t)(R->n > 0 ? R->n : 1) * sizeof(double);
  double *y1 = bg_xmalloc(sz);
  memcpy(y1, y0, (size_t)R->n * sizeof(double));
  int moved = bg_eqsys_consistent(R->s, R->p->t0, y1, IC_NEWTON_STEPS) == 0 &&
              memcmp(y1, y0, (size_t)R->n * sizeof(double)) != 0;
  if (moved) memcpy(y0, y1, (size_t)R->n * sizeof(double));
  free(y1);
  return moved;
}

/* IDACalcIC again from y0 with guess k of the algebraic unknowns: 0 keeps
 * y0's, 1 or 2 set +1 or -1, spread by up to 10 % so that a symmetric guess
 * cannot make Newton's matrix singular (series_conductances: e3 = e4 = 0
 * gives a rank-1 matrix). */
#define IC_GUESSES 2
static int run_calcic_guess(simrun *R, const double *y0, double tnext, int k) {
  double *y = N_VGetArrayPointer(R->y);
  int nz = 0, j = 0;
  for (int i = 0; i < R->n; i++) nz += !bg_eqsys_is_differential(R->s, i);
  for (int i = 0; i < R->n; i++) {
    y[i] = y0[i];
    if (k && !bg_eqsys_is_differential(R->s, i)) y[i] = (k == 1 ? 1.0 : -1.0) * (1.0 + 0.1 * j++ / nz);
  }
  N_VConst(0.0, R->yp);
  stats_now(R, R->st);
  R->nfunc_err = 0;
  R->sunmsg[0] = 0;
  R->tcur = R->p->t0;
  bg_eqsys_modes_reset(R->s);
  modes_now(R, NULL);
  int f = IDAReInit(R->mem, R->p->t0, R->y, R->yp);
  return f < 0 ? f : settle(R, tnext);
}

static int run_start(simrun *R, bg_simresult *r) {
  if (R->nroot) { /* the modes of the state events from the initial point, then held */
    bg_eqsys_modes_reset(R->s);
    modes_now(R, NULL);
    bg_eqsys_modes_freeze(R->s, 1);
  }
  if (R->p->kind != BG_SIM_IDA) {
    keep_start(R, r);
    if (sliding_now(R)) { fail(R, r, SIM_SLIDING, ""); return -1; }
    return 0;
  }
  R->starting = 1;
  int n = R->n, nz = 0;
  double *y0 = bg_xmalloc((size_t)(n > 0 ? n : 1) * sizeof(double));
  memcpy(y0, N_VGetArrayPointer(R->y), (size_t)n * sizeof(double));
  for (int i = 0; i < n && !R->ode; i++) nz += !bg_eqsys_is_differential(R->s, i);
  double tnext = R->p->nrows > 1 ? R->p->times[1] : R->p->t_end;
  if (R->p->nbp && R->p->bp[0] < tnext) tnext = R->p->bp[0];
  int f = settle(R, tnext), f0 = f, k;
  /* The model's guess failed: other guesses; the message is the first failure's. */
  char msg0[sizeof R->sunmsg], err0[sizeof R->err];
  int nerr0 = R->nfunc_err;
  memcpy(msg0, R->sunmsg, sizeof msg0);
  memcpy(err0, R->err, sizeof err0);
  /* (a sliding mode is no failure of the guess) */
  for (k = 1; f < 0 && f != SIM_SLIDING && nz > 0 && k <= IC_GUESSES; k++) f = run_calcic_guess(R, y0, tnext, k);
  /* every guess failed: the constraints solved further, and the guesses
   * again from there (last, so that no start that worked changes) */
  if (f < 0 && f != SIM_SLIDING && constraints_further(R, y0)) {
    if (R->p->verbose)
      bg_logf(R->p->log, BG_LOG_PROGRESS, "simulate: IDACalcIC failed from every guess; again with the "
                                          "constraints of the dependent stores solved further");
    for (k = 0; f < 0 && f != SIM_SLIDING && k <= (nz > 0 ? IC_GUESSES : 0); k++) f = run_calcic_guess(R, y0, tnext, k);
  }
  if (f < 0) {
    memcpy(R->sunmsg, msg0, sizeof msg0);
    memcpy(R->err, err0, sizeof err0);
    R->nfunc_err = nerr0;
    fail(R, r, f0, nz ? " (computing consistent initial values from the model's guess and "
                        "from guesses of +1 and -1 for the algebraic unknowns)"
                      : " (computing consistent initial values)");
  } else {
    r->ic_retries = f0 < 0 ? k - 1 : 0;
    if (r->ic_retries && R->p->verbose)
      bg_logf(R->p->log, BG_LOG_PROGRESS, "simulate: IDACalcIC failed from the model's guess of the "
                      "algebraic unknowns; %s worked", r->ic_retries == 1 ? "+1" : "-1");
  }
  R->starting = 0;
  keep_start(R, r);
  free(y0);
  return f < 0 ? -1 : 0;
}

/* What an earlier bg_sim_integrate into r wrote (a run made again). */
static void result_rewind(bg_simresult *r) {
  free(r->message), free(r->y0), free(r->yp0);
  free(r->event_t), free(r->event_cond), free(r->event_dir);
  r->message = NULL, r->y0 = r->yp0 = NULL;
  r->event_t = NULL, r->event_cond = NULL, r->event_dir = NULL, r->nevents = 0;
  r->nrows = 0, r->partial = 0, r->ic_retries = 0;
  r->rows_redone = r->rows_violating = 0, r->row_worst = r->row_worst_t = 0;
  r->row_worst_unknown = NULL;
}

/* The start and the segments: 0, 2 when it failed (r says why), 3 when the
 * failure came before the solver's first step from a consistent start. */
static int run_all(simrun *R, bg_simresult *r) {
  const bg_simplan *p = R->p;
  int rc = 0, k = 0;
  if (run_start(R, r)) return 2;
  row_coefficients(R);
  keep_last(R);
  for (int j = 0; j <= p->nbp && !rc; j++)
    rc = run_segment(R, r, &k, j < p->nbp ? p->bp[j] : p->t_end, j == p->nbp) ? 2 : 0;
  long st[5];
  stats_now(R, st);
  return rc && st[0] == 0 ? 3 : rc;
}

/* IDA's first step from the start failed its error test: the algebraic
 * unknowns' rates at the start are IDACalcIC's guesses (it computes none),
 * and a start at rest has atol alone for a tolerance, so the predictor's
 * error h (y'_guess - y') failed the test down to the smallest step (property
 * seed 897's merged model, docs/property.md finding 17d). The run starts
 * again with the algebraic unknowns out of the error test (IDASetSuppressAlg:
 * their equations fix them at every step, and every row is checked against
 * them); only runs that failed take this path. */
static int first_step_again(simrun *R, bg_eqsys *s, const bg_simplan *p, bg_simresult *r) {
  int nz = 0;
  for (int i = 0; i < R->n; i++) nz += !bg_eqsys_is_differential(s, i);
  if (p->kind != BG_SIM_IDA || R->ode || nz == 0) return 2;
  if (p->verbose)
    bg_logf(p->log, BG_LOG_PROGRESS, "simulate: the first step from the start failed; again with the "
                                     "algebraic unknowns out of the error test");
  char *first = r->message ? strdup(r->message) : NULL;
  run_close(R);
  result_rewind(r);
  r->t_reached = p->t0;
  int bad = run_open(R, s, p), rc = 2;
  R->r = r;
  R->exact_rows = 1;
  if (!bad && IDASetSuppressAlg(R->mem, SUNTRUE) >= 0) rc = run_all(R, r) ? 2 : 0;
  else { /* the first failure's words stand */
    r->partial = 1;
    r->message = first, first = NULL;
  }
  free(first);
  return rc;
}

int bg_sim_integrate(bg_eqsys *s, const bg_simplan *p, bg_simresult *r) {
  simrun R;
  int rc = 0;
  result_rewind(r);
  r->t_reached = p->t0;
  int bad_open = run_open(&R, s, p);
  R.r = r;
  if (bad_open) {
    r->partial = 1;
    r->message = strdup("simulation failed at the start: the solver could not be set up "
                        "(the Jacobian pattern lacks a diagonal entry, or out of memory)");
    rc = 2;
  } else if ((rc = run_all(&R, r)) == 3) {
    rc = first_step_again(&R, s, p, r);
  }
  if (R.mem) {
    long st[5];
    stats_now(&R, st);
    r->steps = st[0], r->rhs_evals = st[1], r->jac_evals = st[2];
    r->err_test_fails = st[3], r->nonlin_iters = st[4];
  }
  run_close(&R);
  return rc;
}
