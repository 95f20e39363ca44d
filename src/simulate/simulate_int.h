/* SPDX-License-Identifier: BSD-3-Clause */
/* Internal to src/simulate*.c: the plan bg_simulate makes (solver, tolerances,
 * output grid, input breakpoints) and the SUNDIALS driver that carries it out. */
#ifndef BG_SIMULATE_INT_H
#define BG_SIMULATE_INT_H
#include "simulate/simulate.h"

enum { BG_SIM_BDF, BG_SIM_ADAMS, BG_SIM_IDA };

/* Steps per output interval a fixed-point run may take before the whole run
 * is made again with Newton's method: more means the model is stiffer than
 * its estimate said, where the iteration only converges at tiny steps. */
#define BG_SIM_FP_MAX_STEPS 2000

typedef struct bg_simplan {
  int kind;         /* BG_SIM_* */
  int sparse;       /* KLU with the eqsys sparsity pattern (else dense) */
  int fixed_point;  /* CVODE Adams: fixed-point iteration, no Jacobian and no
                       linear solver (docs/simulation.md, "Nonlinear iteration"),
                       at most BG_SIM_FP_MAX_STEPS steps per output interval */
  double t0, t_end; /* t_end > t0 */
  double rtol, max_step; /* max_step 0: no limit */
  long max_steps;   /* per output interval */
  const double *atol; /* n, per unknown */
  int nrows;
  const double *times; /* nrows output times, times[0] = t0, last = t_end */
  int nbp;
  const double *bp;    /* sorted breakpoints strictly inside (t0, t_end) */
  const bg_log *log; /* progress (-v) and solver messages (-vv); nullable */
  int verbose;       /* what log wants: 0, 1 progress, 2 solver messages too */
  int events;          /* find state events (root functions; docs/simulation.md) */
  double progress_every; /* -v: seconds of wall time between progress lines */
} bg_simplan;

/* Two runs of one model compared (simulate_compare.c): the largest deviation
 * of any output or state (when both runs kept them) relative to its range in
 * b, what it is (a name borrowed from r or the eqsys) and when; the output
 * column when it is an output (else -1); the event counts and the largest
 * difference of their times (-1 when the counts differ; event_part_t is then
 * the first time where the two lists part). */
typedef struct bg_simcmp {
  double worst, worst_t;
  const char *worst_name;
  int worst_col, states_compared;
  double state_worst;
  int events_a, events_b;
  double event_dt, event_part_t;
} bg_simcmp;
void bg_sim_compare(const bg_simresult *a, const bg_simresult *b, const bg_eqsys *s, double *out_dev,
                    bg_simcmp *c);

/* Integrates; fills r->t, r->values (preallocated for p->nrows rows), nrows,
 * the statistics, t_reached, partial and message, after clearing what an
 * earlier call into r wrote. Returns 0 or 2 (failed). */
int bg_sim_integrate(bg_eqsys *s, const bg_simplan *p, bg_simresult *r);
/* A model without unknowns (purely algebraic: sources and resistors): no
 * solver, the outputs evaluated at each output time. Same contract. */
int bg_sim_algebraic(bg_eqsys *s, const bg_simplan *p, bg_simresult *r);
#endif
