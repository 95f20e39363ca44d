/* SPDX-License-Identifier: BSD-3-Clause */
/* A purely algebraic model (no states, no algebraic unknowns) has nothing
 * to integrate: its outputs are functions of t alone. They are evaluated at
 * each output time, and no solver or LAPACK routine sees an empty system. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "simulate/simulate_int.h"

int bg_sim_algebraic(bg_eqsys *s, const bg_simplan *p, bg_simresult *r) {
  double none[1] = {0}; /* y and y' have no entries */
  r->t_reached = p->t0;
  for (int k = 0; k < p->nrows; k++) {
    double *out = r->values + (size_t)r->nrows * (size_t)r->nout;
    if (bg_eqsys_outputs(s, p->times[k], none, NULL, out)) {
      const char *e = bg_eqsys_error(s);
      char msg[512];
      snprintf(msg, sizeof msg, "simulation failed at t = %.6g: %s", p->times[k],
               e ? e : "an equation evaluated to NaN or infinity");
      r->message = strdup(msg);
      r->partial = 1;
      return 2;
    }
    r->t[r->nrows++] = p->times[k];
    r->t_reached = p->times[k];
  }
  return 0;
}
