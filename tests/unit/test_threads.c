/* SPDX-License-Identifier: BSD-3-Clause */
/* Two runs on two threads do not interfere: each thread takes a run
 * (src/run: parse, compile, causality, analysis, equations, numeric index,
 * index reduction, simulation, linear analysis) of different example models
 * through every output of the outputs table (src/output: the check summary,
 * JSON, the equations in every printer, the exports, CSV, the diagram as SVG,
 * PNG and DOT, the plot, the PDF and HTML reports, MathML), many times over, and every result must
 * equal the one the same model gives on one thread, byte for byte. The sorts that kept
 * their context in globals, the inputs set, the atomic writes' temporary
 * file, text measurement and Graphviz are what this exercises
 * (docs/architecture.md, "Threads"); run it under ThreadSanitizer with
 * cmake -DCMAKE_BUILD_TYPE=Tsan. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/fileio.h"
#include "base/strbuf.h"
#include "harness.h"
#include "output/output.h"
#include "run/run.h"

/* Models with different stages in play: paths and loops (ladder, bridge),
 * index reduction (delta, slider_crank), Lagrange causality, submodels from
 * used files (components/), algebraic loops (bond_loop). */
static const char *const models[] = {
    "rlc",          "bond_loop",         "delta",       "slider_crank",
    "lagrange_rlc", "hydraulic_bridge",  "class12_paths", "components/motor_drive",
};
enum { NMODEL = sizeof models / sizeof *models, ROUNDS = 4 };

/* Everything one run of model `name` produces through the outputs table
 * (the command line's way), as one text; the report and plots for the models
 * that have a simulate block, every output kind otherwise. */
static char *run_model(const char *name, const char *outdir) {
  static const struct {
    const char *kind, *form;
  } outs[] = {
      {"check", NULL},     {"json", NULL},      {"equations", "text"}, {"equations", "latex"},
      {"equations", "json"}, {"equations", "c"}, {"tex", NULL},        {"c", NULL},
      {"py", NULL},        {"m", NULL},         {"mo", NULL},         {"csv", NULL},
      {"linear", "text"},  {"svg", NULL},       {"png", NULL},        {"dot", NULL},
      {"plot", "svg"},     {"report", NULL},    {"report", "html"},   {"equations", "mathml"},
  };
  char path[600];
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  bg_strbuf all = {0};
  bg_run *r = bg_run_new(NULL);
  if (bg_run_load_file(r, path) != 0) bg_sb_printf(&all, "no model (%d errors)\n", r->dg.nerrors);
  bg_output_opts oo;
  memset(&oo, 0, sizeof oo);
  oo.render.show = BG_SHOW_ALL;
  oo.render.style_dir = BG_SOURCE_DIR "/styles";
  bg_output w;
  bg_output_init(&w, r, &oo);
  for (size_t k = 0; r->model && k < sizeof outs / sizeof *outs; k++) {
    bg_strbuf out = {0};
    int st = bg_output_write(&w, outs[k].kind, outs[k].form, NULL, &out);
    unsigned long hash = 0; /* the bytes of a binary output, short */
    for (size_t i = 0; i < out.len; i++) hash = hash * 31 + (unsigned char)out.s[i];
    bg_sb_printf(&all, "\n== %s %s: status %d, %zu bytes, hash %lu\n", outs[k].kind,
                 outs[k].form ? outs[k].form : "", st, out.len, hash);
    if (strcmp(outs[k].kind, "png") && (strcmp(outs[k].kind, "report") || outs[k].form))
      bg_sb_putn(&all, out.s ? out.s : "", out.len);
    if (!strcmp(outs[k].kind, "svg")) { /* an atomic write (its temporary file) */
      char file[700];
      snprintf(file, sizeof file, "%s/%s.svg", outdir,
               strchr(name, '/') ? strchr(name, '/') + 1 : name);
      bg_sb_printf(&all, "write %d\n", bg_write_file_atomic(file, out.s ? out.s : "", out.len));
    }
    bg_sb_free(&out);
  }
  bg_sb_printf(&all, "\n== diagnostics: %d errors, %d warnings\n", r->dg.nerrors, r->dg.nwarnings);
  bg_output_free(&w);
  bg_run_free(r);
  return all.s ? all.s : strdup("");
}

typedef struct job {
  int first, step; /* the models this thread runs: first, first + step, ... */
  const char *outdir;
  char **expect;
  int mismatches, runs;
} job;

static void *worker(void *arg) {
  job *j = arg;
  for (int round = 0; round < ROUNDS; round++)
    for (int k = j->first; k < NMODEL; k += j->step) {
      char *got = run_model(models[k], j->outdir);
      if (strcmp(got, j->expect[k]) != 0) {
        j->mismatches++;
        fprintf(stderr, "round %d: %s differs from its one-thread run\n", round, models[k]);
      }
      j->runs++;
      free(got);
    }
  return NULL;
}

int main(void) {
  char dir[] = "/tmp/bg_threads_XXXXXX";
  OK(mkdtemp(dir) != NULL);
  char *expect[NMODEL];
  for (int k = 0; k < NMODEL; k++) {
    expect[k] = run_model(models[k], dir);
    /* what the runs must agree on is real output: a diagram and equations */
    OK(strstr(expect[k], "== svg : status 0") != NULL);
    OK(strstr(expect[k], "<svg") != NULL);
    OK(strstr(expect[k], "== equations text: status 0") != NULL);
    OK(strstr(expect[k], "== report : status 0") != NULL);
    OK(strstr(expect[k], "== report html: status 0") != NULL);
  }
  /* one-thread runs repeat themselves (nothing a first run leaves behind
   * changes a second one) */
  for (int k = 0; k < NMODEL; k++) {
    char *again = run_model(models[k], dir);
    BG_T_REPORT(!strcmp(again, expect[k]), "%s: a second run differs", models[k]);
    free(again);
  }
  /* two threads, each on its own half of the models, interleaved */
  job jobs[2] = {{0, 2, dir, expect, 0, 0}, {1, 2, dir, expect, 0, 0}};
  pthread_t th[2];
  for (int i = 0; i < 2; i++) INT_EQ(pthread_create(&th[i], NULL, worker, &jobs[i]), 0);
  for (int i = 0; i < 2; i++) pthread_join(th[i], NULL);
  for (int i = 0; i < 2; i++) {
    INT_EQ(jobs[i].mismatches, 0);
    INT_EQ(jobs[i].runs, ROUNDS * NMODEL / 2);
  }
  /* and two threads on the same model at once */
  job same[2] = {{3, NMODEL, dir, expect, 0, 0}, {3, NMODEL, dir, expect, 0, 0}};
  for (int i = 0; i < 2; i++) INT_EQ(pthread_create(&th[i], NULL, worker, &same[i]), 0);
  for (int i = 0; i < 2; i++) pthread_join(th[i], NULL);
  for (int i = 0; i < 2; i++) INT_EQ(same[i].mismatches, 0);
  for (int k = 0; k < NMODEL; k++) free(expect[k]);
  char cmd[64];
  snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
  OK(system(cmd) == 0);
  return bg_t_done();
}
