/* SPDX-License-Identifier: BSD-3-Clause */
/* Test driver for a switching model's C export (tests/export_events.sh,
 * docs/export.md "State events"): CVODE with root finding on the exported
 * root functions; at each root the exported event function sets the modes
 * and CVODE restarts there (the states do not jump). Writes the outputs at
 * the times of a bgdraw CSV and every switching: time, root, direction.
 * Usage: events_driver REF.csv OUT.csv EVENTS.txt   (the model's prefix is ev) */
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "ev.h"

static double times[200000];
static int ntimes;
static ev_params P;
static ev_modes MD;
static double W[EV_NWORK], JV[EV_NNZ + 1];

static int read_times(const char *csv) {
  FILE *f = fopen(csv, "r");
  char line[65536];
  if (!f || !fgets(line, sizeof line, f)) return -1;
  while (ntimes < 200000 && fgets(line, sizeof line, f))
    if (line[0] != '#') times[ntimes++] = strtod(line, NULL);
  fclose(f);
  return ntimes > 1 ? 0 : -1;
}

static int f_ode(sunrealtype t, N_Vector y, N_Vector yd, void *u) {
  (void)u;
  return ev_rhs(&P, &MD, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yd), W) ? 1 : 0;
}

static int j_ode(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *u, N_Vector a, N_Vector b,
                 N_Vector c) {
  (void)fy, (void)u, (void)a, (void)b, (void)c;
  if (ev_jacobian(&P, &MD, t, N_VGetArrayPointer(y), NULL, 0, JV, W)) return 1;
  SUNMatZero(J);
  for (int j = 0; j < EV_N; j++)
    for (int k = ev_jac_colptr[j]; k < ev_jac_colptr[j + 1]; k++) SM_ELEMENT_D(J, ev_jac_rowind[k], j) = JV[k];
  return 0;
}

static int g_ode(sunrealtype t, N_Vector y, sunrealtype *g, void *u) {
  (void)u;
  return ev_roots(&P, &MD, t, N_VGetArrayPointer(y), NULL, g, W) ? 1 : 0;
}

int main(int argc, char **argv) {
  if (argc < 4 || read_times(argv[1])) return 2;
  P = ev_default_params;
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  double y0[EV_N + 1], o[EV_NOUT + 1], delta = 1e-9 * (times[ntimes - 1] - times[0]);
  int dir[EV_NROOT + 1];
  double before[EV_NMODE + 1];
  ev_initial(&P, times[0], y0, W);
  ev_modes_start(&P, times[0], y0, NULL, delta, &MD, W);
  N_Vector y = N_VMake_Serial(EV_N, y0, ctx);
  void *mem = CVodeCreate(CV_BDF, ctx);
  SUNMatrix A = SUNDenseMatrix(EV_N, EV_N, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  CVodeInit(mem, f_ode, times[0], y);
  CVodeSStolerances(mem, 1e-11, 1e-13);
  CVodeSetLinearSolver(mem, LS, A);
  CVodeSetJacFn(mem, j_ode);
  CVodeSetMaxNumSteps(mem, 1000000);
  CVodeRootInit(mem, EV_NROOT, g_ode);
  FILE *f = fopen(argv[2], "w"), *fe = fopen(argv[3], "w");
  fputs("t", f);
  for (int k = 0; k < EV_NOUT; k++) fprintf(f, ",%s", ev_output_names[k]);
  fputs("\n", f);
  double t = times[0];
  for (int k = 0; k < ntimes; k++) {
    while (k > 0 && t < times[k]) {
      int flag = CVode(mem, times[k], y, &t, CV_NORMAL);
      if (flag < 0) return fprintf(stderr, "CVode failed at t = %g: %d\n", t, flag), 1;
      if (flag != CV_ROOT_RETURN) break;
      CVodeGetRootInfo(mem, dir);
      memcpy(before, MD.m, sizeof MD.m);
      ev_event(&P, t, N_VGetArrayPointer(y), NULL, dir, delta, &MD, W);
      for (int i = 0; i < EV_NROOT; i++) /* memory whose mode stayed: no switching */
        if (dir[i] && !(ev_mode_is_memory[ev_root_mode[i]] && MD.m[ev_root_mode[i]] == before[ev_root_mode[i]]))
          fprintf(fe, "%.17g %d %d\n", t, i, dir[i]);
      CVodeReInit(mem, t, y);
    }
    ev_outputs(&P, &MD, times[k], N_VGetArrayPointer(y), NULL, o, W);
    fprintf(f, "%.17g", times[k]);
    for (int q = 0; q < EV_NOUT; q++) fprintf(f, ",%.17g", o[q]);
    fputs("\n", f);
  }
  fclose(f), fclose(fe);
  CVodeFree(&mem), SUNLinSolFree(LS), SUNMatDestroy(A), N_VDestroy(y);
  SUNContext_Free(&ctx);
  return 0;
}
