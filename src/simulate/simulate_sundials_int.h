/* SPDX-License-Identifier: BSD-3-Clause */
/* SUNDIALS, loaded on first use (issue 34), as base/lapack.h does for
 * LAPACK. Debian builds the SUNDIALS libraries with BIND_NOW: linked into the
 * executable, the loader resolves their 845 symbol references and puts nine
 * libraries into the global scope at every start, where each later symbol
 * lookup (the render module's thousands) passes them, though a diagram never
 * simulates. So the driver calls SUNDIALS through a table filled by dlopen
 * the first time a run simulates (bg_sundials). Include this header instead
 * of the SUNDIALS headers: the names below are macros over the table, so call
 * sites read as plain SUNDIALS. */
#ifndef BG_SIMULATE_SUNDIALS_INT_H
#define BG_SIMULATE_SUNDIALS_INT_H
#include <cvode/cvode.h>
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunmatrix/sunmatrix_sparse.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

/* The libraries, each with the macro naming its file (its SONAME, from CMake;
 * BGDRAW_SUNDIALS_<LIB> in the environment overrides it, for tests). The
 * generic functions (contexts, destructors) and the fixed-point solver come
 * with CVODE's library (its own copy in 6.x, its dependency sundials_core in
 * 7.x: dlsym on a handle searches the library's dependencies too). */
#define BG_SUNDIALS_LIBS(L)                                                                    \
  L(CVODE) L(IDA) L(NVECSERIAL) L(SUNMATRIXDENSE) L(SUNLINSOLDENSE) L(SUNMATRIXSPARSE)         \
  L(SUNLINSOLKLU)

#if SUNDIALS_VERSION_MAJOR >= 7
#define BG_SUNDIALS_ERR_ROUTINES(X)                                                            \
  X(CVODE, SUNContext_ClearErrHandlers) X(CVODE, SUNContext_PushErrHandler)
#else
#define BG_SUNDIALS_ERR_ROUTINES(X)                                                            \
  X(CVODE, CVodeSetErrHandlerFn) X(IDA, IDASetErrHandlerFn)
#endif

/* The routines the engine uses, each with its library (add one here and a
 * macro below). */
#define BG_SUNDIALS_ROUTINES(X)                                                                \
  BG_SUNDIALS_ERR_ROUTINES(X)                                                                  \
  X(CVODE, CVode) X(CVODE, CVodeCreate) X(CVODE, CVodeFree) X(CVODE, CVodeGetCurrentStep)      \
  X(CVODE, CVodeGetNumErrTestFails) X(CVODE, CVodeGetNumJacEvals)                              \
  X(CVODE, CVodeGetNumNonlinSolvIters) X(CVODE, CVodeGetNumRhsEvals)                           \
  X(CVODE, CVodeGetNumSteps) X(CVODE, CVodeGetReturnFlagName) X(CVODE, CVodeGetRootInfo)       \
  X(CVODE, CVodeInit) X(CVODE, CVodeReInit) X(CVODE, CVodeRootInit)                            \
  X(CVODE, CVodeSVtolerances) X(CVODE, CVodeSetJacFn) X(CVODE, CVodeSetLinearSolver)           \
  X(CVODE, CVodeSetMaxNumSteps) X(CVODE, CVodeSetMaxStep) X(CVODE, CVodeSetNonlinearSolver)    \
  X(CVODE, CVodeSetStopTime) X(CVODE, CVodeSetUserData)                                        \
  X(CVODE, SUNContext_Create) X(CVODE, SUNContext_Free) X(CVODE, SUNLinSolFree)                \
  X(CVODE, SUNMatDestroy) X(CVODE, SUNNonlinSolFree) X(CVODE, SUNNonlinSol_FixedPoint)         \
  X(IDA, IDACalcIC) X(IDA, IDACreate) X(IDA, IDAFree) X(IDA, IDAGetConsistentIC)               \
  X(IDA, IDAGetCurrentStep) X(IDA, IDAGetNumErrTestFails) X(IDA, IDAGetNumJacEvals)            \
  X(IDA, IDAGetNumNonlinSolvIters) X(IDA, IDAGetNumResEvals) X(IDA, IDAGetNumSteps)            \
  X(IDA, IDAGetReturnFlagName) X(IDA, IDAGetRootInfo) X(IDA, IDAInit) X(IDA, IDAReInit)        \
  X(IDA, IDARootInit) X(IDA, IDASVtolerances) X(IDA, IDAWFtolerances) X(IDA, IDASetId)         \
  X(IDA, IDASetJacFn)                                                                          \
  X(IDA, IDASetLinearSolver) X(IDA, IDASetMaxNumSteps) X(IDA, IDASetMaxStep)                   \
  X(IDA, IDASetStopTime) X(IDA, IDASetSuppressAlg) X(IDA, IDASetUserData) X(IDA, IDASolve)     \
  X(NVECSERIAL, N_VConst) X(NVECSERIAL, N_VDestroy) X(NVECSERIAL, N_VGetArrayPointer)          \
  X(NVECSERIAL, N_VNew_Serial)                                                                 \
  X(SUNMATRIXDENSE, SUNDenseMatrix) X(SUNMATRIXDENSE, SUNDenseMatrix_Data)                     \
  X(SUNLINSOLDENSE, SUNLinSol_Dense)                                                           \
  X(SUNMATRIXSPARSE, SUNSparseMatrix) X(SUNMATRIXSPARSE, SUNSparseMatrix_Data)                 \
  X(SUNMATRIXSPARSE, SUNSparseMatrix_IndexPointers)                                            \
  X(SUNMATRIXSPARSE, SUNSparseMatrix_IndexValues)                                              \
  X(SUNLINSOLKLU, SUNLinSol_KLU)

typedef struct bg_sundials_table {
#define BG_SUNDIALS_FIELD(lib, name) __typeof__(&name) name;
  BG_SUNDIALS_ROUTINES(BG_SUNDIALS_FIELD)
#undef BG_SUNDIALS_FIELD
} bg_sundials_table;

/* The table, loaded once (thread-safe). When a library cannot be loaded or
 * lacks a routine (a broken installation: the package depends on them) the
 * process stops with status 4 and a message naming the library and the
 * loader's reason, as a missing library at start-up would. */
const bg_sundials_table *bg_sundials(void);

#if SUNDIALS_VERSION_MAJOR >= 7
#define SUNContext_ClearErrHandlers(...) (bg_sundials()->SUNContext_ClearErrHandlers(__VA_ARGS__))
#define SUNContext_PushErrHandler(...) (bg_sundials()->SUNContext_PushErrHandler(__VA_ARGS__))
#else
#define CVodeSetErrHandlerFn(...) (bg_sundials()->CVodeSetErrHandlerFn(__VA_ARGS__))
#define IDASetErrHandlerFn(...) (bg_sundials()->IDASetErrHandlerFn(__VA_ARGS__))
#endif
#define CVode(...) (bg_sundials()->CVode(__VA_ARGS__))
#define CVodeCreate(...) (bg_sundials()->CVodeCreate(__VA_ARGS__))
#define CVodeFree(...) (bg_sundials()->CVodeFree(__VA_ARGS__))
#define CVodeGetCurrentStep(...) (bg_sundials()->CVodeGetCurrentStep(__VA_ARGS__))
#define CVodeGetNumErrTestFails(...) (bg_sundials()->CVodeGetNumErrTestFails(__VA_ARGS__))
#define CVodeGetNumJacEvals(...) (bg_sundials()->CVodeGetNumJacEvals(__VA_ARGS__))
#define CVodeGetNumNonlinSolvIters(...) (bg_sundials()->CVodeGetNumNonlinSolvIters(__VA_ARGS__))
#define CVodeGetNumRhsEvals(...) (bg_sundials()->CVodeGetNumRhsEvals(__VA_ARGS__))
#define CVodeGetNumSteps(...) (bg_sundials()->CVodeGetNumSteps(__VA_ARGS__))
#define CVodeGetReturnFlagName(...) (bg_sundials()->CVodeGetReturnFlagName(__VA_ARGS__))
#define CVodeGetRootInfo(...) (bg_sundials()->CVodeGetRootInfo(__VA_ARGS__))
#define CVodeInit(...) (bg_sundials()->CVodeInit(__VA_ARGS__))
#define CVodeReInit(...) (bg_sundials()->CVodeReInit(__VA_ARGS__))
#define CVodeRootInit(...) (bg_sundials()->CVodeRootInit(__VA_ARGS__))
#define CVodeSVtolerances(...) (bg_sundials()->CVodeSVtolerances(__VA_ARGS__))
#define CVodeSetJacFn(...) (bg_sundials()->CVodeSetJacFn(__VA_ARGS__))
#define CVodeSetLinearSolver(...) (bg_sundials()->CVodeSetLinearSolver(__VA_ARGS__))
#define CVodeSetMaxNumSteps(...) (bg_sundials()->CVodeSetMaxNumSteps(__VA_ARGS__))
#define CVodeSetMaxStep(...) (bg_sundials()->CVodeSetMaxStep(__VA_ARGS__))
#define CVodeSetNonlinearSolver(...) (bg_sundials()->CVodeSetNonlinearSolver(__VA_ARGS__))
#define CVodeSetStopTime(...) (bg_sundials()->CVodeSetStopTime(__VA_ARGS__))
#define CVodeSetUserData(...) (bg_sundials()->CVodeSetUserData(__VA_ARGS__))
#define SUNContext_Create(...) (bg_sundials()->SUNContext_Create(__VA_ARGS__))
#define SUNContext_Free(...) (bg_sundials()->SUNContext_Free(__VA_ARGS__))
#define SUNLinSolFree(...) (bg_sundials()->SUNLinSolFree(__VA_ARGS__))
#define SUNMatDestroy(...) (bg_sundials()->SUNMatDestroy(__VA_ARGS__))
#define SUNNonlinSolFree(...) (bg_sundials()->SUNNonlinSolFree(__VA_ARGS__))
#define SUNNonlinSol_FixedPoint(...) (bg_sundials()->SUNNonlinSol_FixedPoint(__VA_ARGS__))
#define IDACalcIC(...) (bg_sundials()->IDACalcIC(__VA_ARGS__))
#define IDACreate(...) (bg_sundials()->IDACreate(__VA_ARGS__))
#define IDAFree(...) (bg_sundials()->IDAFree(__VA_ARGS__))
#define IDAGetConsistentIC(...) (bg_sundials()->IDAGetConsistentIC(__VA_ARGS__))
#define IDAGetCurrentStep(...) (bg_sundials()->IDAGetCurrentStep(__VA_ARGS__))
#define IDAGetNumErrTestFails(...) (bg_sundials()->IDAGetNumErrTestFails(__VA_ARGS__))
#define IDAGetNumJacEvals(...) (bg_sundials()->IDAGetNumJacEvals(__VA_ARGS__))
#define IDAGetNumNonlinSolvIters(...) (bg_sundials()->IDAGetNumNonlinSolvIters(__VA_ARGS__))
#define IDAGetNumResEvals(...) (bg_sundials()->IDAGetNumResEvals(__VA_ARGS__))
#define IDAGetNumSteps(...) (bg_sundials()->IDAGetNumSteps(__VA_ARGS__))
#define IDAGetReturnFlagName(...) (bg_sundials()->IDAGetReturnFlagName(__VA_ARGS__))
#define IDAGetRootInfo(...) (bg_sundials()->IDAGetRootInfo(__VA_ARGS__))
#define IDAInit(...) (bg_sundials()->IDAInit(__VA_ARGS__))
#define IDAReInit(...) (bg_sundials()->IDAReInit(__VA_ARGS__))
#define IDARootInit(...) (bg_sundials()->IDARootInit(__VA_ARGS__))
#define IDASVtolerances(...) (bg_sundials()->IDASVtolerances(__VA_ARGS__))
#define IDAWFtolerances(...) (bg_sundials()->IDAWFtolerances(__VA_ARGS__))
#define IDASetId(...) (bg_sundials()->IDASetId(__VA_ARGS__))
#define IDASetJacFn(...) (bg_sundials()->IDASetJacFn(__VA_ARGS__))
#define IDASetLinearSolver(...) (bg_sundials()->IDASetLinearSolver(__VA_ARGS__))
#define IDASetMaxNumSteps(...) (bg_sundials()->IDASetMaxNumSteps(__VA_ARGS__))
#define IDASetMaxStep(...) (bg_sundials()->IDASetMaxStep(__VA_ARGS__))
#define IDASetStopTime(...) (bg_sundials()->IDASetStopTime(__VA_ARGS__))
#define IDASetSuppressAlg(...) (bg_sundials()->IDASetSuppressAlg(__VA_ARGS__))
#define IDASetUserData(...) (bg_sundials()->IDASetUserData(__VA_ARGS__))
#define IDASolve(...) (bg_sundials()->IDASolve(__VA_ARGS__))
#define N_VConst(...) (bg_sundials()->N_VConst(__VA_ARGS__))
#define N_VDestroy(...) (bg_sundials()->N_VDestroy(__VA_ARGS__))
#define N_VGetArrayPointer(...) (bg_sundials()->N_VGetArrayPointer(__VA_ARGS__))
#define N_VNew_Serial(...) (bg_sundials()->N_VNew_Serial(__VA_ARGS__))
#define SUNDenseMatrix(...) (bg_sundials()->SUNDenseMatrix(__VA_ARGS__))
#define SUNDenseMatrix_Data(...) (bg_sundials()->SUNDenseMatrix_Data(__VA_ARGS__))
#define SUNLinSol_Dense(...) (bg_sundials()->SUNLinSol_Dense(__VA_ARGS__))
#define SUNSparseMatrix(...) (bg_sundials()->SUNSparseMatrix(__VA_ARGS__))
#define SUNSparseMatrix_Data(...) (bg_sundials()->SUNSparseMatrix_Data(__VA_ARGS__))
#define SUNSparseMatrix_IndexPointers(...) (bg_sundials()->SUNSparseMatrix_IndexPointers(__VA_ARGS__))
#define SUNSparseMatrix_IndexValues(...) (bg_sundials()->SUNSparseMatrix_IndexValues(__VA_ARGS__))
#define SUNLinSol_KLU(...) (bg_sundials()->SUNLinSol_KLU(__VA_ARGS__))
#endif
