/* Two runs on two threads do not interfere: each thread takes the whole
 * engine (parse, compile, causality, analysis, equations in every printer,
 * numeric index, index reduction, simulation) and a diagram (SVG and PNG) of
 * different example models, many times over, and every result must equal the
 * one the same model gives on one thread, byte for byte. The sorts that kept
 * their context in globals, the inputs set, the atomic writes' temporary
 * file, text measurement and Graphviz are what this exercises
 * (docs/architecture.md, "Threads"); run it under ThreadSanitizer with
 * cmake -DCMAKE_BUILD_TYPE=Tsan. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/analysis.h"
#include "base/fileio.h"
#include "base/strbuf.h"
#include "causality/causality.h"
#include "diagram/render.h"
#include "equations/equations.h"
#include "harness.h"
#include "json/json.h"
#include "lang/lang.h"
#include "model/model.h"
#include "simulate/simulate.h"

/* Models with different stages in play: paths and loops (ladder, bridge),
 * index reduction (delta, slider_crank), Lagrange causality, submodels from
 * used files (components/), algebraic loops (bond_loop). */
static const char *const models[] = {
    "rlc",          "bond_loop",         "delta",       "slider_crank",
    "lagrange_rlc", "hydraulic_bridge",  "class12_paths", "components/motor_drive",
};
enum { NMODEL = sizeof models / sizeof *models, ROUNDS = 6 };

static void section(bg_strbuf *out, const char *name) { bg_sb_printf(out, "\n== %s\n", name); }

/* Everything one run of model `name` produces, as one text. */
static char *run_model(const char *name, const char *outdir) {
  char path[600];
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  bg_strbuf out = {0};
  size_t len;
  char *src = bg_read_file(path, &len);
  if (!src) return strdup("cannot read the model");
  bg_diags dg;
  bg_diags_init(&dg, path, src, len);
  bg_ast *ast = bg_parse_string(path, src, len, &dg);
  bg_model *m = ast && !dg.nerrors ? bg_model_compile(ast, NULL, 0, &dg) : NULL;
  if (ast) bg_ast_free(ast);
  if (!m) {
    bg_sb_printf(&out, "no model (%d errors)", dg.nerrors);
  } else {
    bg_analysis a;
    bg_analysis_init(&a, m);
    bg_causality_assign(m, m->method, &a, &dg);
    bg_analysis_run(m, &a, NULL);
    section(&out, "summary");
    bg_analysis_summary(m, &a, &out);
    section(&out, "json");
    bg_json_write_analysis(m, &a, &out);
    bg_eqsys *s = a.complete ? bg_eqsys_build(m, &a, &dg) : NULL;
    bg_indexred ired;
    int reduced = 0;
    if (s) {
      section(&out, "equations");
      bg_eqprint_text(s, &out);
      bg_eqprint_latex(s, &out);
      bg_eqprint_json(s, &out);
      bg_index_result ix;
      bg_index_compute(s, m, &ix);
      section(&out, "index");
      bg_index_report(&ix, &out);
      bg_index_free(&ix);
      if (bg_simulate_index_problem(&a)) {
        reduced = 1;
        bg_indexred_run(s, &ired);
        section(&out, "index reduction");
        bg_indexred_text(&ired, "", &out);
      }
    }
    if (m->sim.present) {
      bg_sim_opts o = {0};
      bg_simresult r = {0};
      bg_eqsys *run = reduced && ired.status == 1 ? ired.reduced : s;
      int rc = bg_simulate(m, &a, run, &o, &r);
      section(&out, "simulation");
      bg_sb_printf(&out, "status %d %s\n", rc, r.message ? r.message : "");
      bg_csv_write(&r, &out);
      bg_simresult_free(&r);
    }
    bg_render_opts ro = {0};
    ro.show = BG_SHOW_ALL;
    ro.style_dir = BG_SOURCE_DIR "/styles";
    bg_diagram *d = bg_diagram_build(m, &a, &ro, &dg);
    if (d) {
      section(&out, "svg");
      bg_diagram_render(d, "svg", &out, &dg);
      bg_strbuf png = {0};
      bg_diagram_render(d, "png", &png, &dg);
      unsigned long sum = 0;
      for (size_t i = 0; i < png.len; i++) sum = sum * 31 + (unsigned char)png.s[i];
      bg_sb_printf(&out, "\n== png: %zu bytes, hash %lu\n", png.len, sum);
      /* an atomic write of a file (the temporary file and its clean-up) */
      char file[700];
      snprintf(file, sizeof file, "%s/%s.svg", outdir, strchr(name, '/') ? strchr(name, '/') + 1 : name);
      bg_sb_printf(&out, "write %d\n", bg_diagram_write(d, file, NULL, &dg));
      free(png.s);
      bg_diagram_free(d);
    }
    if (reduced) bg_indexred_free(&ired);
    if (s) bg_eqsys_free(s);
    bg_analysis_free(&a);
    bg_model_free(m);
  }
  section(&out, "diagnostics");
  bg_sb_printf(&out, "%d errors, %d warnings\n", dg.nerrors, dg.nwarnings);
  bg_diags_free(&dg);
  free(src);
  return out.s ? out.s : strdup("");
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
    OK(strstr(expect[k], "== svg\n<?xml") || strstr(expect[k], "== svg\n<svg"));
    OK(strstr(expect[k], "== equations") != NULL);
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
