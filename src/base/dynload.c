/* SPDX-License-Identifier: BSD-3-Clause */
/* Opening a library on first use and looking its routines up (base/dynload.h). */
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/dynload.h"

static void fail(const char *what, const char *lib, const char *why, const char *sym) {
  fprintf(stderr, "bgdraw: error: cannot load %s (%s): %s%s\n", what, lib, sym ? "no " : "",
          sym ? sym : why ? why : "unknown reason");
  exit(4);
}

void *bg_dynload_open(const char *what, const char *env, const char *soname, const char **name) {
  const char *lib = getenv(env);
  if (!lib || !*lib) lib = soname;
  *name = lib;
  void *h = dlopen(lib, RTLD_NOW | RTLD_LOCAL);
  if (!h) fail(what, lib, dlerror(), NULL);
  return h;
}

void bg_dynload_sym(void *h, const char *what, const char *name, const char *sym, void *fn) {
  void *f = dlsym(h, sym);
  if (!f) fail(what, name, NULL, sym);
  /* dlsym returns an object pointer; POSIX guarantees it converts to a
   * function pointer, which the copy spells without a cast warning */
  memcpy(fn, &f, sizeof f);
}
