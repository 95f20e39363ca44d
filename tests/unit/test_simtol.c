/* SPDX-License-Identifier: BSD-3-Clause */
/* Default tolerances (issue 19): the relative tolerance shrinks with the
 * number of unknowns (bg_sim_default_rtol), so a mass-spring-damper chain
 * simulated at the defaults stays within 2e-6 of the largest value of each
 * kind of state (momenta, spring charges) against the same chain run at
 * rtol 1e-12, at 2, 40 and 150 masses; the result records what was used. */
#include <stdlib.h>
#include <string.h>

#include "analysis/analysis.h"
#include "causality/causality.h"
#include "harness.h"
#include "lang/lang.h"
#include "simulate/simulate.h"

static char *chain_text(int n) {
  bg_strbuf sb = {0};
  bg_sb_puts(&sb, "model chain\nparam m0 = 1, k0 = 100, b0 = 2\nSe F = step(t)\n");
  for (int i = 1; i <= n; i++) {
    bg_sb_printf(&sb, "1 v%d\nI m%d = m0\nR d%d = b0\n", i, i, i);
    if (i < n) bg_sb_printf(&sb, "0 s%d\nC k%d = 1/k0\n", i, i);
  }
  bg_sb_puts(&sb, "bond F -> v1\n");
  for (int i = 1; i <= n; i++) {
    bg_sb_printf(&sb, "bond v%d -> m%d\nbond v%d -> d%d\n", i, i, i, i);
    if (i < n) bg_sb_printf(&sb, "bond v%d -> s%d\nbond s%d -> k%d\nbond s%d -> v%d\n", i, i, i, i, i, i + 1);
  }
  bg_sb_puts(&sb, "simulate t_end = 2, dt = 0.01\n");
  char *s = strdup(bg_sb_str(&sb));
  bg_sb_free(&sb);
  return s;
}

typedef struct run {
  bg_model *m;
  bg_analysis a;
  bg_eqsys *s;
  bg_simresult r;
  int rc;
} run;

static int simulate(const char *src, const bg_sim_opts *o, run *u, bg_diags *dg) {
  memset(u, 0, sizeof *u);
  bg_ast *ast = bg_parse_string("chain.bg", src, strlen(src), dg);
  u->m = ast ? bg_model_compile(ast, NULL, 0, dg) : NULL;
  bg_ast_free(ast);
  if (!u->m) return -1;
  bg_analysis_init(&u->a, u->m);
  bg_causality_assign(u->m, BG_METHOD_SCAP, &u->a, dg);
  bg_analysis_run(u->m, &u->a, NULL);
  u->s = bg_eqsys_build(u->m, &u->a, dg);
  u->rc = bg_simulate(u->m, &u->a, u->s, o, &u->r);
  return u->rc;
}

static void run_free(run *u) {
  bg_simresult_free(&u->r);
  bg_eqsys_free(u->s);
  if (u->m) bg_analysis_free(&u->a), bg_model_free(u->m);
}

/* Largest |difference| over the largest |reference value|, per kind of
 * column (".p" momenta, ".q" charges); the worse of the two. */
static double rel_error(const bg_simresult *a, const bg_simresult *b) {
  double err[2] = {0, 0}, big[2] = {0, 0};
  for (int k = 0; k < a->nout; k++) {
    int kind = strstr(a->names[k], ".q") != NULL;
    for (int i = 0; i < a->nrows && i < b->nrows; i++) {
      double x = a->values[(size_t)i * a->nout + k], y = b->values[(size_t)i * b->nout + k];
      err[kind] = fmax(err[kind], fabs(x - y)), big[kind] = fmax(big[kind], fabs(y));
    }
  }
  return fmax(err[0] / big[0], err[1] / big[1]);
}

static void check_chain(int masses) {
  char *src = chain_text(masses);
  bg_diags dg;
  bg_diags_init(&dg, "chain.bg", src, strlen(src));
  run def, ref;
  bg_sim_opts tight = {.rtol = 1e-12, .atol = 1e-15};
  INT_EQ(simulate(src, NULL, &def, &dg), 0);
  INT_EQ(simulate(src, &tight, &ref, &dg), 0);
  int n = 2 * masses - 1;
  DBL_NEAR(def.r.rtol, bg_sim_default_rtol(n), 0);
  INT_EQ(def.r.nout, n); /* every state, no time column */
  INT_EQ(def.r.nrows, ref.r.nrows);
  double e = rel_error(&def.r, &ref.r);
  BG_T_REPORT(e < 2e-6, "%d masses: error %.3g of the largest value at the defaults", masses, e);
  run_free(&def), run_free(&ref);
  bg_diags_free(&dg);
  free(src);
}

int main(void) {
  DBL_NEAR(bg_sim_default_rtol(1), 1e-7, 0);
  DBL_NEAR(bg_sim_default_rtol(100), 1e-7, 0);
  DBL_NEAR(bg_sim_default_rtol(400), 5e-8, 1e-22);
  DBL_NEAR(bg_sim_default_rtol(20000), 1e-7 * sqrt(100.0 / 20000), 1e-22);
  DBL_NEAR(bg_sim_default_rtol(1000000000), 1e-10, 0);
  /* switching models: 100 times tighter, never below 1e-10 */
  DBL_NEAR(bg_sim_default_rtol_switching(1), 1e-9, 1e-24);
  DBL_NEAR(bg_sim_default_rtol_switching(400), 5e-10, 1e-24);
  DBL_NEAR(bg_sim_default_rtol_switching(1000000), 1e-10, 0);
  check_chain(2);
  check_chain(40);
  check_chain(150);
  return bg_t_done();
}
