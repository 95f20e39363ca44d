/* SPDX-License-Identifier: BSD-3-Clause */
/* In-process timing of the diagram stages for one model: analysis, then
 * bg_diagram_build (pango measuring, Graphviz layout, scene) and each output
 * format, best of 3. Built and run by bench/render_bench.sh.
 * Usage: render_time MODEL.bg STYLE_DIR [--build-only [ENGINE]]   (--build-only:
 * the default layers' bg_diagram_build alone, with ENGINE if given:
 * bench/layout_bench.sh) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "causality/causality.h"
#include "lang/lang.h"
#include "analysis/analysis.h"
#include "diagram/render.h"

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

typedef struct bench {
  const bg_model *m;
  const bg_analysis *a;
  bg_render_opts o;
  bg_diags *dg;
} bench;

static double best_build(bench *b, unsigned show, bg_diagram **keep) {
  double best = 1e300;
  for (int k = 0; k < 3; k++) {
    b->o.show = show;
    double t0 = now();
    bg_diagram *d = bg_diagram_build(b->m, b->a, &b->o, b->dg);
    double t = now() - t0;
    if (!d) exit(1);
    if (t < best) best = t;
    if (k == 2) *keep = d;
    else bg_diagram_free(d);
  }
  return best;
}

static double best_render(bg_diagram *d, const char *fmt, bg_diags *dg, size_t *bytes) {
  double best = 1e300;
  for (int k = 0; k < 3; k++) {
    bg_strbuf out = {0};
    double t0 = now();
    if (bg_diagram_render(d, fmt, &out, dg) != 0) exit(1);
    double t = now() - t0;
    if (t < best) best = t;
    *bytes = out.len;
    bg_sb_free(&out);
  }
  return best;
}

int main(int argc, char **argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: render_time MODEL.bg STYLE_DIR\n");
    return 2;
  }
  size_t len;
  char *src = bg_read_file(argv[1], &len);
  bg_diags dg;
  bg_diags_init(&dg, argv[1], src, len);
  double t0 = now();
  bg_ast *ast = src ? bg_parse_string(argv[1], src, len, &dg) : NULL;
  bg_model *m = ast && !dg.nerrors ? bg_model_compile(ast, NULL, 0, &dg) : NULL;
  bg_ast_free(ast);
  if (!m) {
    bg_diags_print(&dg, stderr);
    return 1;
  }
  bg_analysis a;
  bg_analysis_init(&a, m);
  bg_causality_assign(m, m->method, &a, &dg);
  bg_analysis_run(m, &a, NULL);
  printf("  %-34s %7.3f s  (%d paths, %d topological loops)\n", "parse + causality + paths/loops",
         now() - t0, a.npath, a.ntloop);
  bench b = {m, &a, {0}, &dg};
  b.o.style_dir = argv[2];
  static const struct { const char *name; unsigned show; } sets[] = {
      {"default layers", 0}, {"--show all", BG_SHOW_ALL}};
  static const char *const formats[] = {"svg", "pdf", "png", "dot"};
  int build_only = argc > 3 && !strcmp(argv[3], "--build-only");
  if (build_only && argc > 4) b.o.layout = argv[4];
  for (int s = 0; s < (build_only ? 1 : 2); s++) {
    bg_diagram *d = NULL;
    double tb = best_build(&b, sets[s].show, &d);
    double w, h;
    bg_diagram_size(d, &w, &h);
    printf("  %s: layout (%s) + scene %22.3f s  (page %.0f x %.0f pt)\n", sets[s].name,
           bg_diagram_engine(d), tb, w, h);
    for (int f = 0; f < (build_only ? 0 : 4); f++) {
      size_t bytes = 0;
      double tr = best_render(d, formats[f], &dg, &bytes);
      printf("    %-32s %7.3f s  (%zu bytes)\n", formats[f], tr, bytes);
    }
    bg_diagram_free(d);
  }
  bg_analysis_free(&a);
  bg_model_free(m);
  bg_diags_free(&dg);
  free(src);
  return 0;
}
