/* SPDX-License-Identifier: BSD-3-Clause */
/* The analysis stage's front door: what the causal pattern says, after
 * causality assignment (docs/analysis.md). bg_analysis_run (form.c) fills
 * the causal paths and loops, the signal flow graph's algebraic loops, the
 * topological loops, states, form, predicted index and estimates of the
 * bg_analysis record (causality/analysis.h); summary.c writes the --check
 * summary. The stage's internals are paths_int.h and sfg_int.h. */
#ifndef BG_ANALYSIS_STAGE_H
#define BG_ANALYSIS_STAGE_H
#include "base/strbuf.h"
#include "causality/causality.h"
#include "model/model.h"

#define BG_DEFAULT_MAX_PATHS 1000
#define BG_DEFAULT_MAX_LOOPS 1000

/* Runs after bg_causality_assign: fills the path, cloop, tloop, summary,
 * form, index and estimate fields of a, allocating in a->arena. lim may be
 * NULL (defaults). Never modifies the model. */
void bg_analysis_run(const bg_model *m, bg_analysis *a, const bg_analysis_limits *lim);

/* Does element `elem` (one end of bond b) receive the effort of b, i.e. is
 * the causal stroke at its end? 0 when b has no stroke. */
int bg_paths_effort_in(const bg_model *m, const bg_analysis *a, int elem, int b);
/* An integral store (C with its stroke away, I with its stroke at it). */
int bg_paths_store_integral(const bg_model *m, const bg_analysis *a, int elem);

/* A few lines: method, states, dependent stores, conflicts, paths by class,
 * loops, form and predicted index with its reason (--check and -v). */
void bg_analysis_summary(const bg_model *m, const bg_analysis *a, bg_strbuf *out);
const char *bg_form_name(int form);
#endif
