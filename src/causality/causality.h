/* SPDX-License-Identifier: BSD-3-Clause */
/* Causality assignment: SCAP, relaxed causality (Joseph–Martens), van Dijk's
 * modification and Lagrange causality (docs/causality.md).
 *
 * The stage's front door: the bg_analysis record (causality/analysis.h, its
 * life cycle in analysis.c) and bg_causality_assign. The engine the
 * causality_*.c files share is in causality_int.h. */
#ifndef BG_CAUSALITY_H
#define BG_CAUSALITY_H
#include "causality/analysis.h"
#include "base/diag.h"
#include "model/model.h"

/* Per-bond/per-element arrays of a allocated in a->arena and zeroed;
 * index_predicted = -1, form = incomplete until the analysis fills them. */
void bg_analysis_init(bg_analysis *a, const bg_model *m);
void bg_analysis_free(bg_analysis *a);

/* Assigns causality with `method` (bg_method). Fills bond_stroke,
 * bond_reason, bond_step, bond_conflict, elem_caus, elem_inverted, the
 * trace, the conflicts, the lag_* lists and complete. a must have been
 * initialised for m. Returns 0 (conflicts are results, not errors). */
int bg_causality_assign(const bg_model *m, int method, bg_analysis *a, bg_diags *dg);

/* Names used by the JSON writer and the report. */
const char *bg_caus_name(int caus);     /* "integral", ... ("transfer" for the junction structure) */
const char *bg_reason_name(int reason); /* "source", ... NULL for none */
#endif
