/* SPDX-License-Identifier: BSD-3-Clause */
/* Hand-written reference for bench/sim_bench.sh: the RC ladder of
 * bench/sim_bench.sh (Se U = 1 into N stages of series R and shunt C) with a
 * hand-coded right-hand side and sparse Jacobian, integrated with the same
 * settings bgdraw uses (CVODE BDF, KLU with explicit diagonal, rtol 1e-6,
 * atol 1e-9 * C on the charges, at most 100000 steps per output interval,
 * 500 output intervals, the last capacitor's effort recorded at each).
 * Build: cc -O2 rc_ladder_hand.c -I/usr/include/suitesparse -lsundials_cvode
 *   -lsundials_nvecserial -lsundials_sunmatrixsparse -lsundials_sunlinsolklu -lm
 * Run: rc_ladder_hand N T_END  -> prints "seconds steps last_value cpu_seconds". */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#define R0 1.0
#define C0 1.0
#define U0 1.0

static int n_st;

/* q_k' = (e_{k-1} - e_k)/R - (e_k - e_{k+1})/R with e_0 = U, e_k = q_k/C,
 * and no current beyond the last stage. */
static int rhs(sunrealtype t, N_Vector y, N_Vector yd, void *ud) {
  const double *q = N_VGetArrayPointer(y);
  double *d = N_VGetArrayPointer(yd);
  int n = n_st;
  (void)t, (void)ud;
  for (int k = 0; k < n; k++) {
    double e = q[k] / C0, el = k ? q[k - 1] / C0 : U0;
    double in = (el - e) / R0, out = k + 1 < n ? (e - q[k + 1] / C0) / R0 : 0.0;
    d[k] = in - out;
  }
  return 0;
}

static int jac(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *ud, N_Vector a,
               N_Vector b, N_Vector c) {
  sunindextype *cp = SUNSparseMatrix_IndexPointers(J), *ri = SUNSparseMatrix_IndexValues(J);
  double *v = SUNSparseMatrix_Data(J);
  int n = n_st, k = 0;
  (void)t, (void)y, (void)fy, (void)ud, (void)a, (void)b, (void)c;
  for (int j = 0; j < n; j++) { /* column j: rows j-1, j, j+1 */
    cp[j] = k;
    if (j) ri[k] = j - 1, v[k++] = 1.0 / (R0 * C0);
    ri[k] = j, v[k++] = (j + 1 < n ? -2.0 : -1.0) / (R0 * C0);
    if (j + 1 < n) ri[k] = j + 1, v[k++] = 1.0 / (R0 * C0);
  }
  cp[n] = k;
  return 0;
}

int main(int argc, char **argv) {
  n_st = argc > 1 ? atoi(argv[1]) : 10000;
  double t_end = argc > 2 ? atof(argv[2]) : 10.0, last = 0;
  struct timespec t0, t1, u0, u1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &u0);
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  N_Vector y = N_VNew_Serial(n_st, ctx);
  N_VConst(0.0, y);
  void *mem = CVodeCreate(CV_BDF, ctx);
  SUNMatrix A = SUNSparseMatrix(n_st, n_st, 3 * n_st - 2, CSC_MAT, ctx);
  SUNLinearSolver LS = SUNLinSol_KLU(y, A, ctx);
  CVodeInit(mem, rhs, 0.0, y);
  CVodeSStolerances(mem, 1e-6, 1e-9 * C0);
  CVodeSetMaxNumSteps(mem, 100000);
  CVodeSetLinearSolver(mem, LS, A);
  CVodeSetJacFn(mem, jac);
  int rows = 500, f = 0;
  for (int i = 1; i <= rows && f >= 0; i++) {
    double tret, tout = i == rows ? t_end : t_end * i / rows;
    CVodeSetStopTime(mem, t_end);
    f = CVode(mem, tout, y, &tret, CV_NORMAL);
    last = N_VGetArrayPointer(y)[n_st - 1] / C0;
  }
  long steps = 0;
  CVodeGetNumSteps(mem, &steps);
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &u1);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  printf("%.3f %ld %.9g %.3f\n", (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec), steps,
         last, (u1.tv_sec - u0.tv_sec) + 1e-9 * (u1.tv_nsec - u0.tv_nsec));
  CVodeFree(&mem);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
  return f < 0;
}
