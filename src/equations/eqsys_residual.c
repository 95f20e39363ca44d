/* SPDX-License-Identifier: BSD-3-Clause */
/* The system's two plain evaluations (eqsys.h), one tape pass each: the
 * right-hand side f of an ODE and the residual F of a DAE. A leaf of the
 * evaluation entry points (eqsys_eval.c), the consistent start of Lagrange
 * causality (eqsys_lagstart.c) and the event handling (eqsys_events.c),
 * which call it and one another only downwards. */
#include "equations/eqsys_int.h"

int bg_eqsys_rhs(bg_eqsys *s, double t, const double *y, double *ydot) {
  if (bg_eqs_eval(s, t, y, NULL, 0)) return -1;
  for (int i = 0; i < s->nx; i++) ydot[i] = s->v[s->row_slot[i]];
  return 0;
}

int bg_eqsys_residual(bg_eqsys *s, double t, const double *y, const double *yp, double *res) {
  if (bg_eqs_eval(s, t, y, yp, 0)) return -1;
  for (int i = 0; i < s->n; i++) {
    double r = s->v[s->row_slot[i]];
    res[i] = s->row_kind[i] == 0 ? yp[i] - r : r;
  }
  return 0;
}
