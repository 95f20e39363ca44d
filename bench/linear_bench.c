/* SPDX-License-Identifier: BSD-3-Clause */
/* Linear analysis benchmark (not a test): an RC ladder of N sections (N
 * states) read, analysed, linearised (exact Jacobians, operating point,
 * state space, poles up to 500 states) and its frequency response at 200
 * frequencies (A in Hessenberg form once). Prints the times of each step;
 * the sum is the figure (1 000 states: under 2 s). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "analysis/analysis.h"
#include "base/fileio.h"
#include "causality/causality.h"
#include "lang/lang.h"
#include "linear/linear.h"

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv) {
  if (argc < 2) { fprintf(stderr, "usage: linear_bench MODEL.bg\n"); return 2; }
  size_t len;
  char *src = bg_read_file(argv[1], &len);
  if (!src) { perror(argv[1]); return 1; }
  double t0 = now();
  bg_diags dg;
  bg_diags_init(&dg, argv[1], src, len);
  bg_ast *ast = bg_parse_string(argv[1], src, len, &dg);
  bg_model *m = ast ? bg_model_compile(ast, NULL, 0, &dg) : NULL;
  if (!m) { bg_diags_print(&dg, stderr); return 1; }
  bg_analysis a;
  bg_analysis_init(&a, m);
  bg_causality_assign(m, m->method, &a, &dg);
  bg_analysis_run(m, &a, NULL);
  double t1 = now();
  bg_linear l;
  if (bg_linear_compute(m, &a, -1, &l) != 0) { fprintf(stderr, "refused: %s\n", l.message); return 1; }
  double t2 = now();
  enum { NW = 200 };
  double w[NW], *re = malloc(sizeof(double) * NW * l.ny * l.nu), *im = malloc(sizeof(double) * NW * l.ny * l.nu);
  bg_linear_freqs(&l, m, NW, w);
  int rc = bg_linear_freqresp(&l, NW, w, re, im);
  double t3 = now();
  printf("%d states, %d inputs, %d outputs: parse+analysis %.3f s, linearise %.3f s, "
         "Bode (%d frequencies) %.3f s; linearise + Bode %.3f s%s\n", l.n, l.nu, l.ny, t1 - t0,
         t2 - t1, NW, t3 - t2, t3 - t1, rc ? " (frequency response failed)" : "");
  printf("|H| at %.3g rad/s: %.6g\n", w[0], re[0] * re[0] + im[0] * im[0]);
  free(re), free(im), free(src);
  bg_linear_free(&l);
  bg_analysis_free(&a);
  bg_model_free(m);
  bg_ast_free(ast);
  bg_diags_free(&dg);
  return rc;
}
