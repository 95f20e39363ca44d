/* SPDX-License-Identifier: BSD-3-Clause */
/* Test driver for exported C (tests/export_cli.sh): links two exported models
 * into one program, integrates the ODE one with CVODE and the DAE one with
 * IDA using the exported right-hand side, residual, sparse Jacobian and
 * initial values, and writes each model's outputs at the times of a bgdraw
 * CSV. Usage: driver ODE.csv DAE.csv OUT_ODE.csv OUT_DAE.csv [NAME=VALUE]
 * (a changed parameter of the ODE model, set in its parameter record). */
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
#include "ode.h"
#include "dae.h"

static void header(FILE *o, const char *const *names, int n) {
  fputs("t", o);
  for (int k = 0; k < n; k++) fprintf(o, ",%s", names[k]);
  fputs("\n", o);
}

/* ------------------------------------------------------------ ODE, CVODE */
static ode_params P;
static double W[ODE_NWORK], JV[ODE_NNZ + 1];

static int f_ode(sunrealtype t, N_Vector y, N_Vector yd, void *u) {
  (void)u;
  return ode_rhs(&P, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yd), W) ? 1 : 0;
}

static int j_ode(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *u, N_Vector a, N_Vector b,
                 N_Vector c) {
  (void)fy, (void)u, (void)a, (void)b, (void)c;
  if (ode_jacobian(&P, t, N_VGetArrayPointer(y), NULL, 0, JV, W)) return 1;
  SUNMatZero(J);
  for (int j = 0; j < ODE_N; j++)
    for (int k = ode_jac_colptr[j]; k < ode_jac_colptr[j + 1]; k++) SM_ELEMENT_D(J, ode_jac_rowind[k], j) = JV[k];
  return 0;
}

static int run_ode(SUNContext ctx, const char *out) {
  double y0[ODE_N + 1], o[ODE_NOUT + 1];
  ode_initial(&P, times[0], y0, W);
  N_Vector y = N_VMake_Serial(ODE_N, y0, ctx);
  void *mem = CVodeCreate(CV_BDF, ctx);
  SUNMatrix A = SUNDenseMatrix(ODE_N, ODE_N, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  CVodeInit(mem, f_ode, times[0], y);
  CVodeSStolerances(mem, 1e-10, 1e-14);
  CVodeSetLinearSolver(mem, LS, A);
  CVodeSetJacFn(mem, j_ode);
  CVodeSetMaxNumSteps(mem, 1000000);
  FILE *f = fopen(out, "w");
  header(f, ode_output_names, ODE_NOUT);
  for (int k = 0; k < ntimes; k++) {
    double t = times[0];
    if (k > 0 && CVode(mem, times[k], y, &t, CV_NORMAL) < 0) return 1;
    ode_outputs(&P, times[k], N_VGetArrayPointer(y), NULL, o, W);
    fprintf(f, "%.17g", times[k]);
    for (int q = 0; q < ODE_NOUT; q++) fprintf(f, ",%.17g", o[q]);
    fputs("\n", f);
  }
  fclose(f);
  CVodeFree(&mem), SUNLinSolFree(LS), SUNMatDestroy(A), N_VDestroy(y);
  return 0;
}

/* ------------------------------------------------------------ DAE, IDA */
static double WD[DAE_NWORK], JD[DAE_NNZ + 1];

static int f_dae(sunrealtype t, N_Vector y, N_Vector yp, N_Vector r, void *u) {
  (void)u;
  return dae_residual(&dae_default_params, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp),
                      N_VGetArrayPointer(r), WD) ? 1 : 0;
}

static int j_dae(sunrealtype t, sunrealtype cj, N_Vector y, N_Vector yp, N_Vector r, SUNMatrix J, void *u,
                 N_Vector a, N_Vector b, N_Vector c) {
  (void)r, (void)u, (void)a, (void)b, (void)c;
  if (dae_jacobian(&dae_default_params, t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), cj, JD, WD)) return 1;
  SUNMatZero(J);
  for (int j = 0; j < DAE_N; j++)
    for (int k = dae_jac_colptr[j]; k < dae_jac_colptr[j + 1]; k++) SM_ELEMENT_D(J, dae_jac_rowind[k], j) = JD[k];
  return 0;
}

static int run_dae(SUNContext ctx, const char *out) {
  double y0[DAE_N + 1], yp0[DAE_N + 1] = {0}, id0[DAE_N + 1], o[DAE_NOUT + 1];
  dae_initial(&dae_default_params, times[0], y0, WD);
  for (int i = 0; i < DAE_N; i++) id0[i] = dae_is_differential[i];
  N_Vector y = N_VMake_Serial(DAE_N, y0, ctx), yp = N_VMake_Serial(DAE_N, yp0, ctx);
  N_Vector id = N_VMake_Serial(DAE_N, id0, ctx);
  void *mem = IDACreate(ctx);
  SUNMatrix A = SUNDenseMatrix(DAE_N, DAE_N, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  IDAInit(mem, f_dae, times[0], y, yp);
  IDASStolerances(mem, 1e-10, 1e-14);
  IDASetLinearSolver(mem, LS, A);
  IDASetJacFn(mem, j_dae);
  IDASetId(mem, id);
  IDASetMaxNumSteps(mem, 1000000);
  if (IDACalcIC(mem, IDA_YA_YDP_INIT, times[1]) < 0) return 1;
  IDAGetConsistentIC(mem, y, yp);
  FILE *f = fopen(out, "w");
  header(f, dae_output_names, DAE_NOUT);
  for (int k = 0; k < ntimes; k++) {
    double t = times[0];
    if (k > 0 && IDASolve(mem, times[k], &t, y, yp, IDA_NORMAL) < 0) return 1;
    dae_outputs(&dae_default_params, times[k], N_VGetArrayPointer(y), N_VGetArrayPointer(yp), o, WD);
    fprintf(f, "%.17g", times[k]);
    for (int q = 0; q < DAE_NOUT; q++) fprintf(f, ",%.17g", o[q]);
    fputs("\n", f);
  }
  fclose(f);
  IDAFree(&mem), SUNLinSolFree(LS), SUNMatDestroy(A), N_VDestroy(y), N_VDestroy(yp), N_VDestroy(id);
  return 0;
}

/* NAME=VALUE into the ODE model's parameter record, by its name list. */
static int set_param(const char *arg) {
  const char *eq = strchr(arg, '=');
  if (!eq) return -1;
  double *fields = (double *)&P;
  for (int k = 0; k < ODE_NPARAM; k++)
    if (strlen(ode_param_names[k]) == (size_t)(eq - arg) && !strncmp(ode_param_names[k], arg, (size_t)(eq - arg)))
      return fields[k] = strtod(eq + 1, NULL), 0;
  return -1;
}

int main(int argc, char **argv) {
  if (argc < 5) return 2;
  P = ode_default_params;
  if (argc > 5 && set_param(argv[5])) return 2;
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  ntimes = 0;
  if (read_times(argv[1]) || run_ode(ctx, argv[3])) return 1;
  ntimes = 0;
  if (read_times(argv[2]) || run_dae(ctx, argv[4])) return 1;
  SUNContext_Free(&ctx);
  return 0;
}
