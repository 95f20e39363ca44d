/* SPDX-License-Identifier: BSD-3-Clause */
#include "analysis/analysis.h"

#include <stdio.h>
#include <string.h>

#include "causality/causality.h"

const char *bg_form_name(int form) {
  switch (form) {
  case BG_FORM_ODE: return "ode";
  case BG_FORM_DAE: return "dae";
  default: return "incomplete";
  }
}

/* The summary is short: long lists show their first names and a count
 * (the JSON has them all). */
enum { MAX_NAMES = 12 };

/* "a, b, c", "a, b, ... and 9 more" or "none" */
static void put_names(bg_strbuf *out, char **names, int n) {
  if (n == 0) bg_sb_puts(out, "none");
  int shown = n > MAX_NAMES ? MAX_NAMES - 2 : n;
  for (int i = 0; i < shown; i++) bg_sb_printf(out, "%s%s", i ? ", " : "", names[i]);
  if (shown < n) bg_sb_printf(out, ", ... and %d more", n - shown);
}

static void put_conflicts(const bg_model *m, const bg_analysis *a, bg_strbuf *out) {
  bg_sb_printf(out, "conflicts: %d", a->nconflict);
  for (int i = 0; i < a->nconflict && i < MAX_NAMES; i++) {
    bg_sb_printf(out, "%stype %d at %s", i ? ", " : " (", a->conflict_type[i],
                 m->elem_name[a->conflict_node[i]]);
    if (a->conflict_type[i] == 2) bg_sb_printf(out, " degree %d", a->conflict_degree[i]);
  }
  if (a->nconflict > MAX_NAMES) bg_sb_printf(out, ", ... and %d more", a->nconflict - MAX_NAMES);
  bg_sb_puts(out, a->nconflict ? ")\n" : "\n");
}

static void put_paths(const bg_analysis *a, bg_strbuf *out) {
  int by_class[3] = {0, 0, 0};
  for (int i = 0; i < a->npath; i++)
    if (a->path_class[i] >= 0 && a->path_class[i] <= 2) by_class[a->path_class[i]]++;
  bg_sb_printf(out, "causal paths: %d (class 1: %d, class 2: %d, other: %d)", a->npath,
               by_class[1], by_class[2], by_class[0]);
  if (a->npath_omitted) bg_sb_printf(out, ", %d more not listed", a->npath_omitted);
  bg_sb_putc(out, '\n');
}

static void put_loops(const bg_analysis *a, bg_strbuf *out) {
  int algebraic = 0;
  for (int i = 0; i < a->ntloop; i++) algebraic += a->tloop_algebraic[i] != 0;
  bg_sb_printf(out, "causal loops: %d", a->ncloop);
  for (int i = 0; i < a->ncloop && i < MAX_NAMES; i++) {
    char num[32];
    snprintf(num, sizeof num, "%g", a->cloop_gain_value[i]);
    bg_sb_printf(out, "%sgain %s", i ? "; " : " (", a->cloop_gain[i]);
    if (strcmp(num, a->cloop_gain[i]) != 0) bg_sb_printf(out, " = %s", num); /* not "1 = 1" */
    bg_sb_printf(out, ", class %d", a->cloop_class[i]);
  }
  if (a->ncloop > MAX_NAMES) bg_sb_printf(out, "; ... and %d more", a->ncloop - MAX_NAMES);
  bg_sb_puts(out, a->ncloop ? ")" : "");
  if (a->ncloop_omitted) bg_sb_printf(out, ", %d more not listed", a->ncloop_omitted);
  bg_sb_printf(out, "\ntopological loops: %d (%d algebraic)", a->ntloop, algebraic);
  if (a->ntloop_omitted) bg_sb_printf(out, ", at least %d more not listed", a->ntloop_omitted);
  else if (a->tloop_capped) bg_sb_puts(out, ", listing stopped at the cap (--max-list): more may exist");
  bg_sb_putc(out, '\n');
}

/* One line per multiport field: its ports' causalities, "mixed" when they differ. */
static void put_fields(const bg_model *m, const bg_analysis *a, bg_strbuf *out) {
  for (int f = 0; f < m->nfield && f < MAX_NAMES; f++) {
    int p1 = m->field_elemadr[f], mixed = 0;
    bg_sb_printf(out, "field %s (%s, %d ports):", m->field_name[f],
                 bg_elem_kind_name(m->field_kind[f]), m->field_nport[f]);
    for (int k = 0; k < m->field_nport[f]; k++) {
      bg_sb_printf(out, "%s %s %s", k ? "," : "", m->elem_name[p1 + k],
                   bg_caus_name(a->elem_caus[p1 + k]));
      mixed |= a->elem_caus[p1 + k] != a->elem_caus[p1];
    }
    bg_sb_puts(out, mixed ? " (mixed causality)\n" : "\n");
  }
  if (m->nfield > MAX_NAMES) bg_sb_printf(out, "fields: ... and %d more\n", m->nfield - MAX_NAMES);
}

void bg_analysis_summary(const bg_model *m, const bg_analysis *a, bg_strbuf *out) {
  bg_sb_printf(out, "method: %s%s\n", bg_method_name(a->method),
               a->complete ? "" : " (causality incomplete)");
  bg_sb_printf(out, "states (%d): ", a->nstates);
  put_names(out, a->states, a->nstates);
  bg_sb_puts(out, "\ndependent stores: ");
  put_names(out, a->dependent_stores, a->ndependent);
  bg_sb_putc(out, '\n');
  put_fields(m, a, out);
  put_conflicts(m, a, out);
  put_paths(a, out);
  put_loops(a, out);
  bg_sb_printf(out, "form: %s; predicted index: ", bg_form_name(a->form));
  if (a->index_predicted < 0) bg_sb_puts(out, "unknown");
  else if (a->index_predicted >= 2) bg_sb_puts(out, "above 1");
  else bg_sb_printf(out, "%d", a->index_predicted);
  if (a->index_reason) bg_sb_printf(out, " (%s)", a->index_reason);
  bg_sb_putc(out, '\n');
}
