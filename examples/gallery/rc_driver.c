/* SPDX-License-Identifier: BSD-3-Clause */
/* rc_driver.c — gallery: a program that uses the C export of rc_filter.bg
 * (bgdraw rc_filter.bg -o rc_filter.c) with its own integrator (classical Runge-Kutta)
 * and a resistance changed at run time; prints t and the output voltage. */
#include <stdio.h>
#include "rc_filter.h"

int main(void) {
  rc_filter_params p = rc_filter_default_params;
  p.R0 = 2e3; /* twice the model's resistance: the time constant becomes 2 ms */
  double y[RC_FILTER_N], k[4][RC_FILTER_N], tmp[RC_FILTER_N], out[RC_FILTER_NOUT];
  double work[RC_FILTER_NWORK], h = 1e-5;
  rc_filter_initial(&p, 0, y, work);
  for (int step = 0; step <= 1000; step++) {
    double t = step * h;
    if (step % 100 == 0) {
      rc_filter_outputs(&p, t, y, NULL, out, work);
      printf("%g %.9f\n", t, out[0]);
    }
    rc_filter_rhs(&p, t, y, k[0], work);
    for (int i = 0; i < RC_FILTER_N; i++) tmp[i] = y[i] + h / 2 * k[0][i];
    rc_filter_rhs(&p, t + h / 2, tmp, k[1], work);
    for (int i = 0; i < RC_FILTER_N; i++) tmp[i] = y[i] + h / 2 * k[1][i];
    rc_filter_rhs(&p, t + h / 2, tmp, k[2], work);
    for (int i = 0; i < RC_FILTER_N; i++) tmp[i] = y[i] + h * k[2][i];
    rc_filter_rhs(&p, t + h, tmp, k[3], work);
    for (int i = 0; i < RC_FILTER_N; i++)
      y[i] += h / 6 * (k[0][i] + 2 * k[1][i] + 2 * k[2][i] + k[3][i]);
  }
  return 0;
}
