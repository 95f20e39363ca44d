/* SPDX-License-Identifier: BSD-3-Clause */
/* In-process time of every stage for one model, as the CLI runs them:
 * parse, compile, causality, analysis (paths, loops, form), equations, the
 * reduced form, each equation printer, the analysis JSON, the simulation
 * (its set-up and the model's simulate block), the diagram (layout and
 * scene), its SVG, and the report. One line a stage: name, CPU seconds, peak
 * resident memory so far (MB). Built and run by bench/sweep.sh.
 * Usage: stage_time MODEL.bg STYLE_DIR [STAGES]   STAGES: a comma list of
 * "eq", "sim", "diagram", "report" (default eq,sim,diagram); the engine
 * stages before them always run. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "analysis/analysis.h"
#include "causality/causality.h"
#include "diagram/render.h"
#include "equations/equations.h"
#include "json/json.h"
#include "lang/lang.h"
#include "report/report.h"
#include "simulate/simulate.h"

static double t_last;

/* CPU time of the process (all threads): on a shared machine the wall
 * clock would measure the other programs too, and growth exponents from it
 * mean nothing. */
static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Prints the time since the previous mark and the peak memory so far. */
static void mark(const char *stage) {
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  double t = now();
  printf("%-12s %9.4f %8.1f\n", stage, t - t_last, ru.ru_maxrss / 1024.0);
  fflush(stdout);
  t_last = now();
}

static int wants(const char *list, const char *stage) {
  char buf[256];
  snprintf(buf, sizeof buf, ",%s,", list);
  char key[32];
  snprintf(key, sizeof key, ",%s,", stage);
  return strstr(buf, key) != NULL;
}

static void printers(const bg_eqsys *s) {
  static const char *const forms[] = {"text", "latex", "json", "c"};
  for (int k = 0; k < 4; k++) {
    bg_strbuf sb = {0};
    bg_eqprint(s, forms[k], &sb);
    bg_sb_free(&sb);
    char name[32];
    snprintf(name, sizeof name, "print_%s", forms[k]);
    mark(name);
  }
}

static void draw(const bg_model *m, const bg_analysis *a, bg_render_opts *ro, bg_diags *dg) {
  bg_diagram *d = bg_diagram_build(m, a, ro, dg);
  mark("diagram");
  if (!d) return;
  bg_strbuf out = {0};
  bg_diagram_render(d, "svg", &out, dg);
  bg_sb_free(&out);
  mark("svg");
  bg_diagram_free(d);
}

int main(int argc, char **argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: stage_time MODEL.bg STYLE_DIR [eq,sim,diagram,report]\n");
    return 2;
  }
  const char *stages = argc > 3 ? argv[3] : "eq,sim,diagram";
  t_last = now();
  size_t len;
  char *src = bg_read_file(argv[1], &len);
  bg_diags dg;
  bg_diags_init(&dg, argv[1], src, len);
  bg_ast *ast = src ? bg_parse_string(argv[1], src, len, &dg) : NULL;
  mark("parse");
  bg_model *m = ast && !dg.nerrors ? bg_model_compile(ast, NULL, 0, &dg) : NULL;
  bg_ast_free(ast);
  if (!m) {
    bg_diags_print(&dg, stderr);
    return 1;
  }
  mark("compile");
  bg_analysis a;
  bg_analysis_init(&a, m);
  bg_causality_assign(m, m->method, &a, &dg);
  mark("causality");
  bg_analysis_limits lim = {1000, 1000};
  bg_analysis_run(m, &a, &lim);
  mark("analysis");
  bg_eqsys *s = NULL;
  if (wants(stages, "eq") || wants(stages, "sim") || wants(stages, "report")) {
    s = bg_eqsys_build(m, &a, &dg);
    mark("equations");
    if (s) bg_eqred_form(s), mark("reduced");
  }
  if (s && wants(stages, "eq")) printers(s);
  bg_strbuf js = {0};
  bg_json_write_analysis(m, &a, NULL, &js);
  bg_sb_free(&js);
  mark("json");
  bg_simresult sim;
  int simrc = -1;
  if (s && (wants(stages, "sim") || wants(stages, "report"))) {
    bg_sim_opts so = {0};
    simrc = bg_simulate(m, &a, s, &so, &sim);
    mark("simulate");
  }
  bg_render_opts ro = {0};
  ro.style_dir = argv[2];
  if (wants(stages, "diagram")) draw(m, &a, &ro, &dg);
  if (wants(stages, "report")) {
    /* the report takes a run: its stages again (timed apart), then the PDF */
    bg_run *r = bg_run_new(NULL);
    bg_run_load_file(r, argv[1]);
    bg_run_need(r, BG_STAGE_REDUCTION);
    if (m->sim.present) bg_run_need(r, BG_STAGE_SIMULATION);
    mark("report_run");
    bg_report_opts rro = {&ro, NULL, NULL};
    bg_strbuf pdf = {0};
    bg_report_render(r, &rro, &pdf, &dg);
    bg_sb_free(&pdf);
    bg_run_free(r);
    mark("report");
  }
  if (simrc >= 0) bg_simresult_free(&sim);
  bg_eqsys_free(s);
  bg_analysis_free(&a);
  bg_model_free(m);
  bg_diags_free(&dg);
  free(src);
  return 0;
}
