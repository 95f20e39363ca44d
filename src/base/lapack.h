/* SPDX-License-Identifier: BSD-3-Clause */
/* LAPACK (through LAPACKE), loaded on first use. liblapacke and liblapack
 * are built with BIND_NOW in Debian: linked into the executable, the loader
 * resolves their 4 000 symbol references at every start, a quarter of a
 * small diagram's instructions (issue 34), though a diagram never calls
 * LAPACK. So the engine calls LAPACKE through a table filled by dlopen the
 * first time a routine is needed (bg_lapacke). Include this header instead
 * of <lapacke.h>: the LAPACKE_x names below are macros over the table, so
 * call sites read as plain LAPACKE. */
#ifndef BG_BASE_LAPACK_H
#define BG_BASE_LAPACK_H
#include <lapacke.h>

/* The routines the engine uses (add one here and in lapack.c's list). */
#define BG_LAPACKE_ROUTINES(X)                                                                 \
  X(dgecon) X(dgeev) X(dgehrd) X(dgelsd) X(dgeqp3) X(dgeqrf) X(dgesv) X(dgesvd) X(dgetrf)     \
  X(dgetrs) X(dggev) X(dlange) X(dormhr) X(dormqr) X(dtrtrs) X(zgesv)

typedef struct bg_lapacke_table {
#define BG_LAPACKE_FIELD(name) __typeof__(&LAPACKE_##name) name;
  BG_LAPACKE_ROUTINES(BG_LAPACKE_FIELD)
#undef BG_LAPACKE_FIELD
} bg_lapacke_table;

/* The table, loaded once (thread-safe). When liblapacke cannot be loaded
 * (a broken installation: the package depends on it) the process stops with
 * a message naming the library and the loader's reason, as a missing library
 * at start-up would. */
const bg_lapacke_table *bg_lapacke(void);

#define LAPACKE_dgecon(...) (bg_lapacke()->dgecon(__VA_ARGS__))
#define LAPACKE_dgeev(...) (bg_lapacke()->dgeev(__VA_ARGS__))
#define LAPACKE_dgehrd(...) (bg_lapacke()->dgehrd(__VA_ARGS__))
#define LAPACKE_dgelsd(...) (bg_lapacke()->dgelsd(__VA_ARGS__))
#define LAPACKE_dgeqp3(...) (bg_lapacke()->dgeqp3(__VA_ARGS__))
#define LAPACKE_dgeqrf(...) (bg_lapacke()->dgeqrf(__VA_ARGS__))
#define LAPACKE_dgesv(...) (bg_lapacke()->dgesv(__VA_ARGS__))
#define LAPACKE_dgesvd(...) (bg_lapacke()->dgesvd(__VA_ARGS__))
#define LAPACKE_dgetrf(...) (bg_lapacke()->dgetrf(__VA_ARGS__))
#define LAPACKE_dgetrs(...) (bg_lapacke()->dgetrs(__VA_ARGS__))
#define LAPACKE_dggev(...) (bg_lapacke()->dggev(__VA_ARGS__))
#define LAPACKE_dlange(...) (bg_lapacke()->dlange(__VA_ARGS__))
#define LAPACKE_dormhr(...) (bg_lapacke()->dormhr(__VA_ARGS__))
#define LAPACKE_dormqr(...) (bg_lapacke()->dormqr(__VA_ARGS__))
#define LAPACKE_dtrtrs(...) (bg_lapacke()->dtrtrs(__VA_ARGS__))
#define LAPACKE_zgesv(...) (bg_lapacke()->zgesv(__VA_ARGS__))
#endif
