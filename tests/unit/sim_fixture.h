/* SPDX-License-Identifier: BSD-3-Clause */
/* Shared by test_simulate.c and test_simtrust.c: parse, compile, analyse,
 * build the equations and simulate a model (an example, an edited example or
 * inline text); columns of the result by name. */
#ifndef BG_SIM_FIXTURE_H
#define BG_SIM_FIXTURE_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "causality/causality.h"
#include "equations/equations.h"
#include "base/fileio.h"
#include "lang/lang.h"
#include "analysis/analysis.h"
#include "simulate/simulate.h"
#include "run_fixture.h"

typedef struct fx {
  bg_run *run;    /* owns the model, its analysis and its equations; NULL when
                     a test builds the model itself */
  bg_model *m;
  bg_analysis a;  /* the run's analysis (a view: freed with the run) */
  bg_eqsys *s;
  bg_diags dg;    /* the test's own diagnostics over src */
  char *src;
  bg_simresult r;
  int rc;
} fx;

/* Replaces the first `from` in f->src by `to` (model variants). */
static inline int fx_edit(fx *f, const char *from, const char *to) { return bg_t_replace(&f->src, from, to); }

/* A run of f->src (path names it) with an optional --set, up to its
 * equations (none when causality is incomplete), then the simulation with o. */
static inline int fx_run(fx *f, const char *path, int method, const char *set_name, double set_value,
                  const bg_sim_opts *o) {
  bg_diags_init(&f->dg, path, f->src, strlen(f->src));
  bg_t_model mm = {NULL, f->src, path, NULL, NULL, method, set_name, set_value};
  f->run = bg_t_run(&mm, BG_STAGE_EQUATIONS);
  if (!f->run || !f->run->model) return -1;
  f->m = f->run->model;
  f->a = f->run->analysis;
  if (f->a.complete) f->s = f->run->eqsys;
  f->rc = bg_simulate(f->m, &f->a, f->s, o, &f->r);
  if (f->r.message) fprintf(stderr, "%s: %s\n", path, f->r.message);
  return 0;
}

static inline int fx_load(fx *f, const char *name, int method, const char *set_name, double set_value,
                   const char *from, const char *to, const bg_sim_opts *o) {
  char path[512];
  size_t len;
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  memset(f, 0, sizeof *f);
  f->src = bg_read_file(path, &len);
  if (!f->src) { fprintf(stderr, "cannot read %s\n", path); return -1; }
  if (from && fx_edit(f, from, to)) return -1;
  return fx_run(f, path, method, set_name, set_value, o);
}

static inline int fx_text(fx *f, const char *text, const bg_sim_opts *o) {
  memset(f, 0, sizeof *f);
  f->src = strdup(text);
  return fx_run(f, "inline.bg", BG_METHOD_SCAP, NULL, 0, o);
}

static inline void fx_free(fx *f) {
  bg_simresult_free(&f->r); /* before the equations its names point into */
  if (f->run) {
    bg_run_free(f->run);
  } else { /* what a test built itself */
    if (f->s) bg_eqsys_free(f->s);
    bg_analysis_free(&f->a);
    if (f->m) bg_model_free(f->m);
  }
  bg_diags_free(&f->dg);
  free(f->src);
}

static inline int col(const bg_simresult *r, const char *name) {
  for (int k = 0; k < r->nout; k++)
    if (r->names[k] && !strcmp(r->names[k], name)) return k;
  return -1;
}

static inline double val(const bg_simresult *r, int i, int k) { return r->values[(size_t)i * r->nout + k]; }

static inline int has(const char *s, const char *sub) { return s && strstr(s, sub) != NULL; }

#endif
