/* SPDX-License-Identifier: BSD-3-Clause */
/* The LAPACKE table of base/lapack.h, filled by dlopen on first use. The
 * library's name is its SONAME, read by CMake from the liblapacke it found
 * (BG_LAPACKE_SONAME); BGDRAW_LAPACKE overrides it (tests). */
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

#include "base/lapack.h"

#ifndef BG_LAPACKE_SONAME
#define BG_LAPACKE_SONAME "liblapacke.so.3"
#endif

static bg_lapacke_table table;
static pthread_once_t once = PTHREAD_ONCE_INIT;

static void fail(const char *lib, const char *why) {
  fprintf(stderr, "bgdraw: error: cannot load LAPACK (%s): %s\n", lib, why ? why : "unknown reason");
  exit(4);
}

static void load(void) {
  const char *lib = getenv("BGDRAW_LAPACKE");
  if (!lib || !*lib) lib = BG_LAPACKE_SONAME;
  void *h = dlopen(lib, RTLD_NOW | RTLD_LOCAL);
  if (!h) fail(lib, dlerror());
  /* dlsym returns an object pointer; POSIX guarantees it converts to a
   * function pointer, which the memcpy spells without a cast warning */
#define BG_LAPACKE_LOAD(name)                                                                  \
  {                                                                                            \
    void *f = dlsym(h, "LAPACKE_" #name);                                                      \
    if (!f) fail(lib, "no LAPACKE_" #name);                                                   \
    __builtin_memcpy(&table.name, &f, sizeof f);                                               \
  }
  BG_LAPACKE_ROUTINES(BG_LAPACKE_LOAD)
#undef BG_LAPACKE_LOAD
  /* the handle stays open for the life of the process */
}

const bg_lapacke_table *bg_lapacke(void) {
  pthread_once(&once, load);
  return &table;
}
