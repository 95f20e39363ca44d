/* SPDX-License-Identifier: BSD-3-Clause */
/* The render functions the command line calls, loading the render module on
 * first use (cli_render.h): a run that draws nothing starts without mapping
 * Graphviz, cairo, pango and their dependencies. */
#include "cli/cli_render.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_run.h"
#include "scene/style.h"

#ifndef BG_EXE_TO_MODULE
#define BG_EXE_TO_MODULE "../lib/bgdraw"
#endif

/* The running executable's folder + "/" + rel, or "" when unknown. */
static void beside_exe(const char *rel, char *buf, size_t n) {
  char dir[4096];
  buf[0] = 0;
  if (cli_exe_dir(dir, sizeof dir) == 0) snprintf(buf, n, "%s/%s", dir, rel);
}

/* RTLD_LAZY: binding every function of the module and of the libraries it
 * brings (cairo, pango, glib, Graphviz) at once would cost more than the
 * drawing of a small model; the executable carries the whole engine
 * (--whole-archive), so no engine function the module calls is missing. */
static void *open_module(char *tried, size_t n) {
  char installed[4200], here[4200];
  beside_exe(BG_EXE_TO_MODULE "/bgdraw_render.so", installed, sizeof installed);
  beside_exe("bgdraw_render.so", here, sizeof here);
  const char *env = getenv("BGDRAW_RENDER_MODULE");
  const char *cand[] = {env && *env ? env : NULL, installed, here};
  tried[0] = 0;
  for (size_t i = 0; i < sizeof cand / sizeof cand[0]; i++) {
    if (!cand[i] || !cand[i][0]) continue;
    void *h = dlopen(cand[i], RTLD_LAZY | RTLD_LOCAL);
    if (h) return h;
    size_t used = strlen(tried);
    snprintf(tried + used, n - used, "\n  %s", dlerror());
    if (env && *env) break; /* an explicit module is the only one tried */
  }
  return NULL;
}

/* The module's table; a run that cannot draw stops here with status 4, as
 * for any output that cannot be written (nothing half-written: the module
 * is loaded before an output is opened). */
static const bg_render_api *api(void) {
  static const bg_render_api *tab;
  if (tab) return tab;
  char tried[8192];
  void *h = open_module(tried, sizeof tried);
  const bg_render_api *t = h ? dlsym(h, "bg_render_module") : NULL;
  if (!t || t->version != BG_RENDER_API_VERSION) {
    fprintf(stderr, "bgdraw: error: cannot load the renderer module bgdraw_render.so%s%s\n",
            t ? " (it is from another build)" : ":", t ? "" : tried);
    exit(EXIT_WRITE);
  }
  t->fonts_own(); /* nothing else in this process uses fontconfig */
  return tab = t;
}

/* The functions under their usual names, each loading the module first. */
#define WRAP_R(ret, name, params, args) \
  ret bg_##name params { return api()->name args; }
#define WRAP_V(name, params, args) \
  void bg_##name params { api()->name args; }
BG_RENDER_CALLS(WRAP_R, WRAP_V)
