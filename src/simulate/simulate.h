/* SPDX-License-Identifier: BSD-3-Clause */
/* Simulation: integrates a model's equation system (bg_eqsys) over its
 * `simulate` block with SUNDIALS (CVODE BDF or Adams for ODEs, IDA for
 * index-1 DAEs). Refuses, without calling a solver, models whose index is
 * above 1 or whose junction structure / algebraic loop is singular at the
 * current parameter values, and says why and what to do.
 *
 * Only src/simulate*.c include SUNDIALS headers. */
#ifndef BG_SIMULATE_H
#define BG_SIMULATE_H
#include "causality/causality.h"
#include "equations/equations.h"
#include "model/model.h"
#include "base/log.h"
#include "base/strbuf.h"

typedef struct bg_sim_opts {
  const char *solver; /* NULL: the model's `solver =` (default "auto") */
  const bg_log *log;  /* progress and the solver choice (-v); nullable: silent */
  /* Overrides of the model's simulate block (0: the model's value). */
  double rtol, atol;
  /* -v progress: at most one line per this many seconds of wall time
   * (0: 1 s); a run shorter than that prints only its summary. */
  double progress_every;
  /* Steps per output interval at most (0: 100 000); the fuzzer's short runs. */
  long max_steps;
  /* Why the equations could not be formed when bg_simulate gets s == NULL
   * (the eqsys diagnostic), for the refusal message; nullable. */
  const char *eqs_problem;
  /* What the equations stage found about the index (the run's facts):
   * a numeric index above 1 refuses the run, a failed reduction says why;
   * nullable: the causal prediction alone */
  const bg_index_facts *facts;
  /* 1: integrate straight over the switching conditions, as before state
   * events existed (tests show what root finding changes) */
  int no_events;
  /* 1: keep every state at every output row (bg_simresult.states), for
   * comparing two runs state by state (--verify, the accuracy control) */
  int keep_states;
  /* 1: no accuracy control of a switching model (one run at the default
   * tolerances; docs/simulation.md, "Accuracy through events") */
  int no_control;
} bg_sim_opts;

typedef struct bg_simresult {
  int nout;            /* output columns (without t) */
  const char **names;  /* nout names, borrowed from the eqsys (valid while it lives) */
  int nrows;           /* rows actually computed */
  double *t;           /* nrows times */
  double *values;      /* nrows x nout, row-major */
  int partial;         /* the run stopped before t_end */
  double t_reached;    /* last time the solution is known at */
  char *message;       /* why it was refused or failed, in words; NULL when ok */
  const char *solver_used; /* "cvode_bdf", "cvode_adams", "ida"; NULL when refused */
  char *solver_reason;     /* why this solver ("auto: ...", "forced by ...") */
  char *ic_report;         /* states whose start differs from the model's initial
                              values (q0, p0, init; 0 when not given), e.g. a
                              dependent store's: "L1.p 0 -> 1"; nullable */
  long steps, rhs_evals, jac_evals, err_test_fails, nonlin_iters;
  int consistent_ic_changed; /* ic_report is not empty */
  int n;               /* unknowns of the equation system */
  double *y0, *yp0;    /* n: the initial values and derivatives the solver started
                          from (after IDACalcIC for IDA); NULL when refused */
  const char *linear_solver; /* "dense" or "klu"; NULL when refused */
  double rtol, atol;   /* the tolerances used (atol before the per-store scaling) */
  /* IDA: output rows whose algebraic residuals exceeded the tolerance after
   * the interval was integrated again with short steps (docs/simulation.md);
   * the worst of them in units of the tolerance, its time and unknown */
  int rows_redone, rows_violating;
  double row_worst, row_worst_t, max_step; /* max_step: the limit used, 0 none */
  const char *row_worst_unknown; /* borrowed from the eqsys */
  /* --verify (bg_sim_verify): the run again at tolerances 100 times tighter;
   * per output the largest deviation relative to its range (nout values) */
  int verified;             /* 1 compared, -1 the tighter run failed or was refused */
  double verify_rtol, verify_atol, verify_worst;
  int verify_worst_col;     /* output of the worst deviation, -1 none */
  double *verify_dev;       /* nout; NULL unless verified == 1 */
  char *verify_message;     /* why the comparison could not be made; nullable */
  /* what verify_worst is the deviation of: an output or a state (the name,
   * borrowed from the eqsys), at which time */
  const char *verify_worst_name;
  double verify_worst_t;
  /* states compared (0 when n == 0), the largest deviation among them; the
   * events: the tighter run's count, the largest difference of their times
   * in seconds (-1 when the counts differ: then verify_event_t is the first
   * time where the two lists part) */
  double verify_state_worst, verify_event_dt, verify_event_t;
  int verify_events_other;
  double *states;      /* nrows x n, row-major, when opts.keep_states; else NULL */
  /* The accuracy control of a switching model at default tolerances
   * (docs/simulation.md, "Accuracy through events"): runs made (0: none),
   * the deviation of the kept run from the next tighter one (relative to
   * the range, outputs and states), and 1 when even the tightest run kept
   * did not reach BG_SIM_SWITCH_TARGET against its tighter one */
  int control_runs, control_short;
  double control_dev;
  int ic_retries;      /* IDA: initial guesses of the algebraic unknowns tried
                          after the model's own failed (0: the model's worked) */
  /* State events (docs/simulation.md): the switching conditions of the
   * equations (condition_text borrowed from the eqsys: "law of D: e2 > 0"),
   * whether they were searched, and each event found in time order: its
   * time, condition and the direction its switching function crossed 0 */
  int nconditions, events_searched;
  const char **condition_text;
  int nevents;
  double *event_t;
  int *event_cond;
  signed char *event_dir; /* +1 rising, -1 falling */
} bg_simresult;

/* Runs the model's simulation. s may be the index reduction's system
 * (bg_eqsys_is_reduced), which lifts the index refusals. s may be NULL when the equations could not
 * be built (the result is then a refusal). Returns 0 ok, 1 refused (no
 * solver was called; r->message names the loop or paths and the remedies),
 * 2 failed (r->message says what went wrong and at which time; the rows up
 * to r->t_reached are kept and r->partial is set). r is always filled and
 * must be freed with bg_simresult_free. */
int bg_simulate(const bg_model *m, const bg_analysis *a, bg_eqsys *s, const bg_sim_opts *o,
                bg_simresult *r);
void bg_simresult_free(bg_simresult *r);
/* --verify: reruns r's simulation at rtol and atol 100 times tighter and keeps,
 * per output, max |value - tighter value| over the rows divided by the
 * tighter run's range of that output (max - min; max |value| when constant,
 * 1 when all zero). r must be a complete run (status 0). */
#define BG_VERIFY_FACTOR 100.0
/* The error bound --verify states: this many times the deviation (the tighter
 * run has an error of its own, about 1/BG_VERIFY_FACTOR of the first's when
 * the error is proportional to the tolerance, but not always exactly so:
 * docs/simulation.md, "Verification"). */
#define BG_VERIFY_BOUND 2.0
/* The accuracy the default tolerances hold on a switching model: of each
 * output's and state's range (docs/simulation.md, "Accuracy through events") */
#define BG_SIM_SWITCH_TARGET 1e-6
#define BG_VERIFY_LOOSE 1e-3 /* a worse deviation flags the tolerances as too loose */
void bg_sim_verify(const bg_model *m, const bg_analysis *a, bg_eqsys *s, const bg_sim_opts *o,
                   bg_simresult *r);
/* The --verify summary (and, when the deviation exceeds BG_VERIFY_LOOSE, a
 * warning) in words; 0 when nothing was verified. */
int bg_sim_verify_text(const bg_simresult *r, bg_strbuf *out);
/* The warning for output rows that violate the algebraic equations beyond
 * the tolerance (r->rows_violating): appends it to out and returns 1, else 0. */
int bg_simresult_row_warning(const bg_simresult *r, bg_strbuf *out);
/* The SUNDIALS version bgdraw was built with ("6.4.1"); 6.4 and 7.x are supported. */
const char *bg_simulate_sundials_version(void);
/* The relative tolerance used when neither the options nor the model give
 * one, for n unknowns: 1e-7 up to 100, 1e-7 sqrt(100 / n) above. */
double bg_sim_default_rtol(int n);
/* The same for a model with switching conditions (state events):
 * BG_SIM_SWITCH_TIGHTER times smaller, never below 1e-10. A switching model
 * amplifies what the integrator leaves (the time of each contact moves with
 * the state before it): measured on a backlash, the error is about 300
 * times rtol however many events (docs/simulation.md, "Accuracy through
 * events"). */
#define BG_SIM_SWITCH_TIGHTER 100.0
double bg_sim_default_rtol_switching(int n);

/* Why the analysis forbids simulating this model (index above 1, a class 5
 * causal loop, a singular algebraic loop, incomplete causality), as a
 * malloc'd message with remedies; NULL when nothing forbids it. The same for
 * a system that is (reduced = 1) the index reduction's
 * (equations/indexred.h): the index problems no longer forbid the run. When
 * the reduction was tried and failed (f->reduction->status < 0) the refusal ends
 * with its reason. */
char *bg_simulate_refusal_reduced(const bg_model *m, const bg_analysis *a, const bg_index_facts *f,
                                  int reduced);
/* 1 when what forbids the run is the index (a class 5 causal loop, an
 * algebraic loop of gain +1, a predicted or numeric index above 1): an
 * index reduction may lift it. */
int bg_simulate_index_problem(const bg_analysis *a, const bg_index_facts *f);

/* The results as CSV: header "t,<names...>" (a name containing a comma or a
 * quote is quoted CSV-style), one row per output time, numbers in the shortest round-trip form (bg_sb_num).
 * A partial run ends with one comment line "# partial: <message>". */
void bg_csv_write(const bg_simresult *r, bg_strbuf *out);
#endif
