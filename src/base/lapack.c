/* SPDX-License-Identifier: BSD-3-Clause */
/* The LAPACKE table of base/lapack.h, filled by dlopen on first use. The
 * library's name is its SONAME, read by CMake from the liblapacke it found
 * (BG_LAPACKE_SONAME); BGDRAW_LAPACKE overrides it (tests). */
#include <pthread.h>

#include "base/dynload.h"
#include "base/lapack.h"

#ifndef BG_LAPACKE_SONAME
#define BG_LAPACKE_SONAME "liblapacke.so.3"
#endif

static bg_lapacke_table table;
static pthread_once_t once = PTHREAD_ONCE_INIT;

static void load(void) {
  const char *lib;
  void *h = bg_dynload_open("LAPACK", "BGDRAW_LAPACKE", BG_LAPACKE_SONAME, &lib);
#define BG_LAPACKE_LOAD(name) bg_dynload_sym(h, "LAPACK", lib, "LAPACKE_" #name, &table.name);
  BG_LAPACKE_ROUTINES(BG_LAPACKE_LOAD)
#undef BG_LAPACKE_LOAD
}

const bg_lapacke_table *bg_lapacke(void) {
  pthread_once(&once, load);
  return &table;
}
