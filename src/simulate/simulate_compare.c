/* SPDX-License-Identifier: BSD-3-Clause */
/* Two runs of one model compared row by row: every output, every state (when
 * both kept them) and the state events' times. --verify and the accuracy
 * control of switching models (docs/simulation.md) both measure a run by its
 * deviation from a run at tighter tolerances; this is that measure. */
#include <math.h>
#include <string.h>

#include "simulate/simulate_int.h"

/* max - min of a column of b (stride apart); the largest magnitude when
 * constant, 1 when all zero: the scale a deviation is measured against. */
static double range_of(const double *v, int nrows, size_t stride) {
  double lo = INFINITY, hi = -INFINITY, big = 0;
  for (int i = 0; i < nrows; i++) {
    double x = v[(size_t)i * stride];
    lo = fmin(lo, x), hi = fmax(hi, x), big = fmax(big, fabs(x));
  }
  return hi > lo ? hi - lo : big > 0 ? big : 1.0;
}

/* Largest |a - b| of one column over its range in b; *at gets the row. */
static double column_dev(const double *a, const double *b, int nrows, size_t stride, int *at) {
  double d = -1, range = range_of(b, nrows, stride);
  *at = 0;
  for (int i = 0; i < nrows; i++) {
    double x = fabs(a[(size_t)i * stride] - b[(size_t)i * stride]);
    if (!(x <= d)) d = x, *at = i; /* a NaN counts as the worst */
  }
  return d / range;
}

static void consider(bg_simcmp *c, double d, const char *name, double t) {
  if (c->worst_name && !(d > c->worst)) return;
  c->worst = d, c->worst_name = name, c->worst_t = t;
}

void bg_sim_compare(const bg_simresult *a, const bg_simresult *b, const bg_eqsys *s, double *out_dev,
                    bg_simcmp *c) {
  memset(c, 0, sizeof *c);
  c->worst_col = -1;
  int nrows = a->nrows < b->nrows ? a->nrows : b->nrows, at;
  for (int k = 0; k < a->nout && k < b->nout; k++) {
    double d = column_dev(a->values + k, b->values + k, nrows, (size_t)a->nout, &at);
    if (out_dev) out_dev[k] = d;
    if (c->worst_col < 0 || d > c->worst) c->worst_col = k;
    consider(c, d, a->names[k], a->t[at]);
  }
  c->states_compared = a->states && b->states && a->n == b->n;
  for (int i = 0; c->states_compared && i < a->n; i++) {
    double d = column_dev(a->states + i, b->states + i, nrows, (size_t)a->n, &at);
    c->state_worst = fmax(c->state_worst, d);
    consider(c, d, bg_eqsys_name(s, i), a->t[at]);
  }
  if (c->worst_name && c->worst_col >= 0 && strcmp(c->worst_name, a->names[c->worst_col])) c->worst_col = -1;
  /* events: per condition, the same count and the largest difference of
   * their times (several conditions at one instant may be logged in either
   * order); else where the two lists part */
  c->events_a = a->nevents, c->events_b = b->nevents;
  c->event_dt = 0, c->event_part_t = INFINITY;
  int nc = a->nconditions > b->nconditions ? a->nconditions : b->nconditions;
  for (int cond = 0; cond < nc; cond++) {
    int i = 0, j = 0;
    for (;;) {
      while (i < a->nevents && a->event_cond[i] != cond) i++;
      while (j < b->nevents && b->event_cond[j] != cond) j++;
      if (i == a->nevents || j == b->nevents) {
        if (i < a->nevents || j < b->nevents) /* one run has more of this condition's events */
          c->event_part_t = fmin(c->event_part_t, i < a->nevents ? a->event_t[i] : b->event_t[j]);
        break;
      }
      c->event_dt = fmax(c->event_dt, fabs(a->event_t[i] - b->event_t[j]));
      i++, j++;
    }
  }
  if (isfinite(c->event_part_t)) c->event_dt = -1;
  else c->event_part_t = 0;
}
