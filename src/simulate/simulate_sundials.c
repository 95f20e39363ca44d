/* SPDX-License-Identifier: BSD-3-Clause */
/* The SUNDIALS table of simulate/simulate_sundials_int.h, filled by dlopen on
 * first use. Each library's name is its SONAME, read by CMake from the
 * library it found (BG_SUNDIALS_SONAME_<LIB>); BGDRAW_SUNDIALS_<LIB> in the
 * environment overrides it (tests). Each library is opened RTLD_LOCAL, so
 * its symbols never join the global scope later lookups pass through. */
#include <pthread.h>

#include "base/dynload.h"
#include "simulate/simulate_sundials_int.h"

enum {
#define BG_SUNDIALS_LIB_ENUM(lib) LIB_##lib,
  BG_SUNDIALS_LIBS(BG_SUNDIALS_LIB_ENUM)
#undef BG_SUNDIALS_LIB_ENUM
      NLIBS
};

static bg_sundials_table table;
static pthread_once_t once = PTHREAD_ONCE_INIT;

static void load(void) {
  void *h[NLIBS];
  const char *name[NLIBS];
#define BG_SUNDIALS_OPEN(lib)                                                                  \
  h[LIB_##lib] = bg_dynload_open("SUNDIALS", "BGDRAW_SUNDIALS_" #lib, BG_SUNDIALS_SONAME_##lib, \
                                 &name[LIB_##lib]);
  BG_SUNDIALS_LIBS(BG_SUNDIALS_OPEN)
#undef BG_SUNDIALS_OPEN
  /* the macros over the routines' names are not expanded inside #fn */
#define BG_SUNDIALS_LOAD(lib, fn)                                                              \
  bg_dynload_sym(h[LIB_##lib], "SUNDIALS", name[LIB_##lib], #fn, &table.fn);
  BG_SUNDIALS_ROUTINES(BG_SUNDIALS_LOAD)
#undef BG_SUNDIALS_LOAD
}

const bg_sundials_table *bg_sundials(void) {
  pthread_once(&once, load);
  return &table;
}
