/* SPDX-License-Identifier: BSD-3-Clause */
/* The one way the unit tests load a model: a run (src/run), as the command
 * line and the library load theirs, from an example (examples/NAME.bg) or
 * from inline text, with an optional text edit (a variant of the example)
 * and an optional --set, up to a stage. The fixtures of the analysis,
 * equation, simulation and linear tests (analysis_fixture.h,
 * eqs_fixture.h, sim_fixture.h, linear_fixture.h) keep their own handles
 * over this run. Include after harness.h. */
#ifndef BG_RUN_FIXTURE_H
#define BG_RUN_FIXTURE_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/fileio.h"
#include "run/run.h"

typedef struct bg_t_model {
  const char *example;         /* examples/NAME.bg, or NULL with text */
  const char *text;            /* inline model text */
  const char *name;            /* the text's name in diagnostics; NULL: "inline.bg" */
  const char *from, *to;       /* replace the first `from` by `to`; NULL: no edit */
  int method;                  /* bg_method; -1: the model's own */
  const char *set_name;        /* one --set NAME=VALUE; NULL: none */
  double set_value;
} bg_t_model;

/* A run of the model with the stages up to upto done; NULL when the source
 * cannot be read or edited. A model with errors gives a run whose model is
 * NULL, its diagnostics printed. */
static inline bg_run *bg_t_run(const bg_t_model *mm, bg_stage upto) {
  char path[512];
  char *src = NULL;
  size_t len = 0;
  if (mm->example) {
    snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, mm->example);
    src = bg_read_file(path, &len);
  } else if (mm->text) {
    snprintf(path, sizeof path, "%s", mm->name ? mm->name : "inline.bg");
    src = strdup(mm->text);
  }
  if (!src) {
    fprintf(stderr, "cannot read the model %s\n", mm->example ? path : "(no text)");
    return NULL;
  }
  if (mm->from && bg_t_replace(&src, mm->from, mm->to)) {
    free(src);
    return NULL;
  }
  bg_run_opts o;
  bg_run_opts_init(&o);
  o.method = mm->method;
  bg_param_override ov = {mm->set_name, mm->set_value};
  if (mm->set_name) o.sets = &ov, o.nsets = 1;
  bg_run *r = bg_run_new(&o);
  if (bg_run_load(r, path, src, strlen(src)) != 0) {
    bg_diags_print(&r->dg, stderr);
    return r;
  }
  bg_run_need(r, upto);
  return r;
}
/* What a fixture keeps beside its run: a copy of the source with its own
 * diagnostics over it (the test's sink), and views of the model and its
 * analysis (freed with the run). 0 when the model loaded. */
static inline int bg_t_view(const bg_run *r, char **src, bg_diags *dg, bg_model **m,
                            bg_analysis *a) {
  *src = strdup(r->src ? r->src : "");
  bg_diags_init(dg, r->name, *src, strlen(*src));
  if (!r->model) return -1;
  *m = r->model;
  *a = r->analysis;
  return 0;
}
#endif
