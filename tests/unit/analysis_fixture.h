/* SPDX-License-Identifier: BSD-3-Clause */
/* Shared by the analysis tests (test_paths.c, test_sfg.c, test_form.c):
 * load an example, assign causality, run the analysis, and print or list
 * what was found. Include after harness.h. */
#ifndef BG_TEST_ANALYSIS_FIXTURE_H
#define BG_TEST_ANALYSIS_FIXTURE_H
/* Loads examples/NAME.bg, assigns causality with `method` and runs the
 * analysis. The per-bond/per-element arrays causality needs are allocated
 * here so the test does not depend on where bg_analysis_init lives. */
#include <stdlib.h>
#include "causality/causality.h"
#include "model/model.h"
#include "lang/lang.h"
#include "analysis/analysis.h"
#include "analysis/paths_int.h" /* white-box: the tests call the stage's parts */
#include "analysis/sfg_int.h"
#include "run_fixture.h"

typedef struct fx {
  bg_run *run;    /* owns the model and its analysis; NULL when a test builds them */
  bg_model *m;
  bg_analysis a;  /* the run's analysis (a view: freed with the run) */
  bg_diags dg;    /* the test's own diagnostics over src */
  char *src;
} fx;

__attribute__((unused)) static void fx_init_analysis(bg_analysis *a, const bg_model *m) {
  memset(a, 0, sizeof *a);
  size_t nb = (size_t)m->nbond + 1, ne = (size_t)m->nelem + 1;
  a->bond_stroke = bg_arena_alloc(&a->arena, nb * sizeof(int));
  a->bond_reason = bg_arena_alloc(&a->arena, nb * sizeof(int));
  a->bond_step = bg_arena_alloc(&a->arena, nb * sizeof(int));
  a->bond_conflict = bg_arena_alloc(&a->arena, nb * sizeof(int));
  a->elem_caus = bg_arena_alloc(&a->arena, ne * sizeof(int));
  a->elem_inverted = bg_arena_alloc(&a->arena, ne * sizeof(int));
  a->index_predicted = -1;
}

/* method < 0: the model's own; edit: optional (from, to) text replacement in
 * the source, for variants */
__attribute__((unused)) static int fx_load(fx *f, const char *name, int method, const char *set_name, double set_value,
                   const char *from, const char *to) {
  memset(f, 0, sizeof *f);
  bg_t_model mm = {name, NULL, NULL, from, to, method, set_name, set_value};
  f->run = bg_t_run(&mm, BG_STAGE_ANALYSIS);
  if (!f->run) return -1;
  return bg_t_view(f->run, &f->src, &f->dg, &f->m, &f->a);
}

static void fx_free(fx *f) {
  if (f->run) {
    bg_run_free(f->run);
  } else { /* what a test built itself (fx_init_analysis) */
    bg_arena_free(&f->a.arena);
    if (f->m) bg_model_free(f->m);
  }
  bg_diags_free(&f->dg);
  free(f->src);
}

/* "1,2,3" from bond numbers of a list */
__attribute__((unused)) static const char *fx_bonds(const bg_model *m, const int *b, int n) {
  static char buf[4][512];
  static int k;
  char *s = buf[k++ % 4];
  s[0] = 0;
  for (int i = 0; i < n; i++)
    snprintf(s + strlen(s), 512 - strlen(s), "%s%d", i ? "," : "", m->bond_num[b[i]]);
  return s;
}

__attribute__((unused)) static const char *fx_sigs(const bg_model *m, const int *sig, int n) {
  static char buf[4][1024];
  static int k;
  char *s = buf[k++ % 4], nm[96];
  s[0] = 0;
  for (int i = 0; i < n; i++) {
    bg_sfg_node_name(m, sig[i], nm, sizeof nm);
    snprintf(s + strlen(s), 1024 - strlen(s), "%s%s", i ? " " : "", nm);
  }
  return s;
}

__attribute__((unused)) static void fx_dump(const fx *f) {
  const bg_model *m = f->m;
  const bg_analysis *a = &f->a;
  printf("== %s complete=%d\n", m->name, a->complete);
  for (int b = 0; b < m->nbond; b++) printf(" b%d:%s", m->bond_num[b], a->bond_stroke[b] == 1 ? "H" : a->bond_stroke[b] == 2 ? "T" : "-");
  printf("\n");
  for (int p = 0; p < a->npath; p++)
    printf(" path %d: {%s} %s-%s %s class %d order %d\n", p + 1,
           fx_bonds(m, a->path_bonds + a->path_adr[p], a->path_n[p]), m->elem_name[a->path_end0[p]],
           m->elem_name[a->path_end1[p]], a->path_kind[p], a->path_class[p], a->path_order[p]);
  for (int l = 0; l < a->ncloop; l++)
    printf(" cloop %d: {%s} gain %s = %g class %d\n", l + 1,
           fx_bonds(m, a->cloop_bonds + a->cloop_adr[l], a->cloop_n[l]), a->cloop_gain[l],
           a->cloop_gain_value[l], a->cloop_class[l]);
  for (int t = 0; t < a->ntloop; t++)
    printf(" tloop %d: %s order %d [%s] gain %s = %g alg %d cause %s\n", t + 1,
           a->tloop_kind[t] ? "open" : "flat", a->tloop_order[t],
           fx_sigs(m, a->tloop_signals + a->tloop_adr[t], a->tloop_n[t]), a->tloop_gain[t],
           a->tloop_gain_value[t], a->tloop_algebraic[t], a->tloop_cause[t]);
  printf(" states:");
  for (int i = 0; i < a->nstates; i++) printf(" %s", a->states[i]);
  printf("\n dependent:");
  for (int i = 0; i < a->ndependent; i++) printf(" %s", a->dependent_stores[i]);
  printf("\n algebraic:");
  for (int i = 0; i < a->nalgebraic; i++) printf(" %s", a->algebraic_variables[i]);
  printf("\n form %d index %d (%s) pdep %d disjoint %d RA %d\n", a->form, a->index_predicted,
         a->index_reason, a->form_parameter_dependent, a->cloops_disjoint, a->rosenberg_andry);
  for (int i = 0; i < a->nestimate; i++)
    printf(" estimate %s path %d = %g\n", a->estimate_kind[i] ? "omega" : "tau", a->estimate_path[i] + 1,
           a->estimate_value[i]);
}
#endif
