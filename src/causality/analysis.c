/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_analysis life cycle: every array lives in a->arena. */
#include <string.h>

#include "causality/causality.h"

#define ALLOC(a, n, type) ((type *)bg_arena_alloc(&(a)->arena, ((n) > 0 ? (size_t)(n) : 1) * sizeof(type)))

void bg_analysis_init(bg_analysis *a, const bg_model *m) {
  memset(a, 0, sizeof *a);
  a->method = m->method;
  a->bond_stroke = ALLOC(a, m->nbond, int);
  a->bond_reason = ALLOC(a, m->nbond, int);
  a->bond_step = ALLOC(a, m->nbond, int);
  a->bond_conflict = ALLOC(a, m->nbond, int);
  a->elem_caus = ALLOC(a, m->nelem, int);
  a->elem_inverted = ALLOC(a, m->nelem, int);
  a->index_predicted = -1; /* unknown until the analysis runs */
  a->form = BG_FORM_INCOMPLETE;
}

void bg_analysis_free(bg_analysis *a) {
  bg_arena_free(&a->arena);
  memset(a, 0, sizeof *a);
}
