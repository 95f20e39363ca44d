/* SPDX-License-Identifier: BSD-3-Clause */
/* Test driver for a switching model's C export (tests/export_events.sh,
 * docs/export.md "State events"): CVODE with root finding on the exported
 * root functions; at each root the exported event function sets the modes
 * and CVODE restarts there (the states do not jump). Writes the outputs at
 * the times of a bgdraw CSV and every switching: time, root, direction.
 * Usage: events_driver REF.csv OUT.csv EVENTS.txt   (the model's prefix is ev) */
#include <cvode/cvode.h>
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "driver_times.h"
#include "ev.h"

static ev_params P;
static ev_modes MD;
static double W[EV_NWORK], JV[EV_NNZ + 1];

static int f_ode(sunrealtype t, N_Vector y, N_Vector yd, void *u) {
  (void)u;
#if EV_IS_ODE
  return ev_rhs(&P, &MD, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yd), W) ? 1 : 0;
#else
  (void)t, (void)y, (void)yd;
  return -1; /* a DAE runs with IDA */
#endif
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

static int f_dae(sunrealtype t, N_Vector y, N_Vector yp, N_Vector r, void *u) {
  (void)u;
  return ev_residual(&P, &MD, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), N_VGetArrayPointer(r), W) ? 1 : 0;
}

static int j_dae(sunrealtype t, sunrealtype cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix J, void *u,
                 N_Vector a, N_Vector b, N_Vector c) {
  (void)r, (void)u, (void)a, (void)b, (void)c;
  if (ev_jacobian(&P, &MD, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), cj, JV, W)) return 1;
  SUNMatZero(J);
  for (int j = 0; j < EV_N; j++)
    for (int k = ev_jac_colptr[j]; k < ev_jac_colptr[j + 1]; k++) SM_ELEMENT_D(J, ev_jac_rowind[k], j) = JV[k];
  return 0;
}

static int g_dae(sunrealtype t, N_Vector y, N_Vector yp, sunrealtype *g, void *u) {
  (void)u;
  return ev_roots(&P, &MD, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), g, W) ? 1 : 0;
}

/* IDA: consistent values under the modes, the modes from them, until they agree. */
static int settle(void *mem, double t, double tnext, N_Vector y, N_Vector yp, double delta) {
  for (int k = 0; k < 8; k++) {
    if (IDAReInit(mem, t, y, yp) < 0 || IDACalcIC(mem, IDA_YA_YDP_INIT, tnext) < 0) return -1;
    IDAGetConsistentIC(mem, y, yp);
    if (!ev_event(&P, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), NULL, delta, &MD, W)) return 0;
  }
  return -1;
}

int main(int argc, char **argv) {
  if (argc < 4 || read_times(argv[1])) return 2;
  P = ev_default_params;
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  double y0[EV_N + 1], yp0[EV_N + 1] = {0}, id0[EV_N + 1], o[EV_NOUT + 1], delta = 1e-9 * (times[ntimes - 1] - times[0]);
  int dir[EV_NROOT + 1];
  double before[EV_NMODE + 1];
  ev_initial(&P, times[0], y0, W);
  for (int i = 0; i < EV_N; i++) id0[i] = ev_is_differential[i];
  N_Vector y = N_VMake_Serial(EV_N, y0, ctx), yp = N_VMake_Serial(EV_N, yp0, ctx), id = N_VMake_Serial(EV_N, id0, ctx);
  SUNMatrix A = SUNDenseMatrix(EV_N, EV_N, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  void *mem;
  if (EV_IS_ODE) {
    ev_modes_start(&P, times[0], y0, NULL, delta, &MD, W);
    mem = CVodeCreate(CV_BDF, ctx);
    CVodeInit(mem, f_ode, times[0], y);
    CVodeSStolerances(mem, 1e-11, 1e-13);
    CVodeSetLinearSolver(mem, LS, A);
    CVodeSetJacFn(mem, j_ode);
    CVodeSetMaxNumSteps(mem, 1000000);
    CVodeRootInit(mem, EV_NROOT, g_ode);
  } else {
    mem = IDACreate(ctx);
    IDAInit(mem, f_dae, times[0], y, yp);
    IDASStolerances(mem, 1e-11, 1e-13);
    IDASetLinearSolver(mem, LS, A);
    IDASetJacFn(mem, j_dae);
    IDASetId(mem, id);
    IDASetMaxNumSteps(mem, 1000000);
    IDARootInit(mem, EV_NROOT, g_dae);
    ev_modes_start(&P, times[0], y0, yp0, delta, &MD, W);
    if (settle(mem, times[0], times[1], y, yp, delta)) return fprintf(stderr, "no consistent start\n"), 1;
  }
  FILE *f = fopen(argv[2], "w"), *fe = fopen(argv[3], "w");
  fputs("t", f);
  for (int k = 0; k < EV_NOUT; k++) fprintf(f, ",%s", ev_output_names[k]);
  fputs("\n", f);
  double t = times[0];
  for (int k = 0; k < ntimes; k++) {
    while (k > 0 && t < times[k]) {
      int flag = EV_IS_ODE ? CVode(mem, times[k], y, &t, CV_NORMAL) : IDASolve(mem, times[k], &t, y, yp, IDA_NORMAL);
      if (flag < 0) return fprintf(stderr, "the solver failed at t = %g: %d\n", t, flag), 1;
      if (flag != CV_ROOT_RETURN) break;
      if (EV_IS_ODE) CVodeGetRootInfo(mem, dir);
      else IDAGetRootInfo(mem, dir);
      memcpy(before, MD.m, sizeof MD.m);
      ev_event(&P, t, N_VGetArrayPointer(y), EV_IS_ODE ? NULL : N_VGetArrayPointer(yp), dir, delta, &MD, W);
      if (EV_IS_ODE) CVodeReInit(mem, t, y);
      else if (settle(mem, t, times[k] > t ? times[k] : t + delta, y, yp, delta))
        return fprintf(stderr, "the modes do not settle at t = %g\n", t), 1;
      /* IDA finds a root on interpolated algebraic values: when the consistent
       * ones leave every mode as it was, nothing switched (found again later) */
      if (!EV_IS_ODE && !memcmp(before, MD.m, sizeof MD.m)) continue;
      for (int i = 0; i < EV_NROOT; i++) /* memory whose mode stayed: no switching */
        if (dir[i] && !(ev_mode_is_memory[ev_root_mode[i]] && MD.m[ev_root_mode[i]] == before[ev_root_mode[i]]))
          fprintf(fe, "%.17g %d %d\n", t, i, dir[i]);
    }
    ev_outputs(&P, &MD, times[k], N_VGetArrayPointer(y), EV_IS_ODE ? NULL : N_VGetArrayPointer(yp), o, W);
    fprintf(f, "%.17g", times[k]);
    for (int q = 0; q < EV_NOUT; q++) fprintf(f, ",%.17g", o[q]);
    fputs("\n", f);
  }
  fclose(f), fclose(fe);
  if (EV_IS_ODE) CVodeFree(&mem);
  else IDAFree(&mem);
  SUNLinSolFree(LS), SUNMatDestroy(A), N_VDestroy(y), N_VDestroy(yp), N_VDestroy(id);
  SUNContext_Free(&ctx);
  return 0;
}
