/* SPDX-License-Identifier: BSD-3-Clause */
/* The analysis JSON writer. Bond references are bond numbers, element
 * references names; lists keep the analysis's (deterministic) order. */
#include "json/json.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "causality/causality.h"
#include "analysis/analysis.h"

/* ---------------------------------------------------------------- small pieces */
static void key(bg_strbuf *o, const char *k) {
  bg_sb_puts(o, "  ");
  bg_sb_json_str(o, k);
  bg_sb_puts(o, ": ");
}

static void str_or_null(bg_strbuf *o, const char *s) {
  if (s) bg_sb_json_str(o, s);
  else bg_sb_puts(o, "null");
}

static void bool_val(bg_strbuf *o, int v) { bg_sb_puts(o, v ? "true" : "false"); }

/* [n1, n2, ...] of bond numbers */
static void bond_list(bg_strbuf *o, const bg_model *m, const int *bonds, int n) {
  bg_sb_putc(o, '[');
  for (int i = 0; i < n; i++) bg_sb_printf(o, "%s%d", i ? ", " : "", m->bond_num[bonds[i]]);
  bg_sb_putc(o, ']');
}

static void string_list(bg_strbuf *o, char *const *s, int n) {
  bg_sb_putc(o, '[');
  for (int i = 0; i < n; i++) {
    if (i) bg_sb_puts(o, ", ");
    str_or_null(o, s ? s[i] : NULL);
  }
  bg_sb_putc(o, ']');
}

/* Opens item i of a list written one item per line. */
static void item(bg_strbuf *o, int i) { bg_sb_puts(o, i ? ",\n    " : "\n    "); }
static void end_list(bg_strbuf *o, int n) { bg_sb_puts(o, n ? "\n  ],\n" : "],\n"); }

/* ---------------------------------------------------------------- components */
static void inst_name_or_null(bg_strbuf *o, const bg_model *m, int inst) {
  str_or_null(o, inst >= 0 ? m->inst_name[inst] : NULL);
}

/* The bonds as written that a flat bond joins through ports, outermost first. */
static void put_bond_origin(bg_strbuf *o, const bg_model *m, int b) {
  bg_sb_puts(o, ", \"origin\": [");
  for (int k = 0; k < m->bond_nseg[b]; k++) {
    int sg = m->bond_segadr[b] + k;
    bg_sb_puts(o, k ? ", {\"instance\": " : "{\"instance\": ");
    inst_name_or_null(o, m, m->seg_inst[sg]);
    bg_sb_printf(o, ", \"bond\": %d}", m->seg_num[sg]);
  }
  bg_sb_putc(o, ']');
}

/* Submodel instances (only for a model that has them). */
static void put_instances(bg_strbuf *o, const bg_model *m) {
  if (!m->ninst) return;
  key(o, "instances");
  bg_sb_putc(o, '[');
  for (int i = 0; i < m->ninst; i++) {
    item(o, i);
    bg_sb_puts(o, "{\"name\": ");
    bg_sb_json_str(o, m->inst_name[i]);
    bg_sb_puts(o, ", \"submodel\": ");
    bg_sb_json_str(o, m->inst_def[i]);
    bg_sb_puts(o, ", \"parent\": ");
    inst_name_or_null(o, m, m->inst_parent[i]);
    bg_sb_printf(o, ", \"bond_offset\": %d, \"bond_span\": %d}", m->inst_bondoff[i],
                 m->inst_bondspan[i]);
  }
  end_list(o, m->ninst);
}

/* Effort and flow detectors (only for a model that has them). */
static void put_detectors(bg_strbuf *o, const bg_model *m) {
  if (!m->ndet) return;
  key(o, "detectors");
  bg_sb_putc(o, '[');
  for (int i = 0; i < m->ndet; i++) {
    item(o, i);
    bg_sb_puts(o, "{\"name\": ");
    bg_sb_json_str(o, m->det_name[i]);
    bg_sb_printf(o, ", \"kind\": \"%s\", \"node\": ", m->det_var[i] == 'e' ? "De" : "Df");
    bg_sb_json_str(o, m->elem_name[m->det_node[i]]);
    bg_sb_puts(o, "}");
  }
  end_list(o, m->ndet);
}

/* ---------------------------------------------------------------- sections */
static void put_bonds(bg_strbuf *o, const bg_model *m, const bg_analysis *a) {
  key(o, "bonds");
  bg_sb_putc(o, '[');
  for (int b = 0; b < m->nbond; b++) {
    int s = a->bond_stroke[b];
    item(o, b);
    bg_sb_printf(o, "{\"id\": %d, \"from\": ", m->bond_num[b]);
    bg_sb_json_str(o, m->elem_name[m->bond_tail[b]]);
    bg_sb_puts(o, ", \"to\": ");
    bg_sb_json_str(o, m->elem_name[m->bond_head[b]]);
    bg_sb_puts(o, ", \"stroke\": ");
    str_or_null(o, s == BG_STROKE_HEAD ? "to" : s == BG_STROKE_TAIL ? "from" : NULL);
    bg_sb_puts(o, ", \"reason\": ");
    str_or_null(o, bg_reason_name(a->bond_reason[b]));
    bg_sb_printf(o, ", \"step\": %d, \"conflict\": ", a->bond_step[b]);
    bool_val(o, a->bond_conflict[b]);
    if (m->ninst) put_bond_origin(o, m, b);
    bg_sb_putc(o, '}');
  }
  end_list(o, m->nbond);
}

static void put_elements(bg_strbuf *o, const bg_model *m, const bg_analysis *a) {
  key(o, "elements");
  bg_sb_putc(o, '[');
  for (int e = 0; e < m->nelem; e++) {
    item(o, e);
    bg_sb_puts(o, "{\"name\": ");
    bg_sb_json_str(o, m->elem_name[e]);
    bg_sb_puts(o, ", \"kind\": ");
    bg_sb_json_str(o, bg_elem_kind_name(m->elem_kind[e]));
    /* docs/json.md's vocabulary is that of 1-ports; a junction-structure node has
     * no causality of its own (its bonds' strokes are in bonds[]): none */
    int c = a->elem_caus[e];
    bg_sb_puts(o, ", \"causality\": ");
    bg_sb_json_str(o, c == BG_CAUS_TRANSFER ? "none" : bg_caus_name(c));
    bg_sb_puts(o, ", \"inverted\": ");
    bool_val(o, a->elem_inverted[e]);
    if (m->ninst) {
      bg_sb_puts(o, ", \"instance\": ");
      inst_name_or_null(o, m, m->elem_inst[e]);
    }
    if (m->nfield) { /* a port of a multiport field: its field and port */
      int f = bg_elem_field(m, e);
      bg_sb_puts(o, ", \"field\": ");
      str_or_null(o, f >= 0 ? m->field_name[f] : NULL);
      bg_sb_puts(o, ", \"port\": ");
      str_or_null(o, bg_elem_port_name(m, e));
    }
    bg_sb_putc(o, '}');
  }
  end_list(o, m->nelem);
}

static void put_trace(bg_strbuf *o, const bg_analysis *a) {
  key(o, "trace");
  bg_sb_putc(o, '[');
  for (int i = 0; i < a->ntrace; i++) {
    item(o, i);
    bg_sb_printf(o, "{\"step\": %d, \"text\": ", i + 1);
    bg_sb_json_str(o, a->trace_text[i]);
    bg_sb_putc(o, '}');
  }
  end_list(o, a->ntrace);
}

static void put_conflicts(bg_strbuf *o, const bg_model *m, const bg_analysis *a) {
  key(o, "conflicts");
  bg_sb_putc(o, '[');
  for (int i = 0; i < a->nconflict; i++) {
    item(o, i);
    bg_sb_puts(o, "{\"node\": ");
    bg_sb_json_str(o, m->elem_name[a->conflict_node[i]]);
    bg_sb_printf(o, ", \"type\": %d, \"degree\": %d, \"bonds\": ", a->conflict_type[i],
                 a->conflict_degree[i]);
    bond_list(o, m, a->conflict_bonds + a->conflict_adr[i], a->conflict_n[i]);
    bg_sb_putc(o, '}');
  }
  end_list(o, a->nconflict);
}

static void int_or_null(bg_strbuf *o, int v, int is_null) {
  if (is_null) bg_sb_puts(o, "null");
  else bg_sb_printf(o, "%d", v);
}

static void put_paths(bg_strbuf *o, const bg_model *m, const bg_analysis *a) {
  key(o, "causal_paths");
  bg_sb_putc(o, '[');
  for (int i = 0; i < a->npath; i++) {
    item(o, i);
    bg_sb_printf(o, "{\"id\": %d, \"bonds\": ", i + 1);
    bond_list(o, m, a->path_bonds + a->path_adr[i], a->path_n[i]);
    bg_sb_puts(o, ", \"ends\": [");
    bg_sb_json_str(o, m->elem_name[a->path_end0[i]]);
    bg_sb_puts(o, ", ");
    bg_sb_json_str(o, m->elem_name[a->path_end1[i]]);
    bg_sb_puts(o, "], \"kind\": ");
    str_or_null(o, a->path_kind ? a->path_kind[i] : NULL);
    bg_sb_puts(o, ", \"class\": ");
    int_or_null(o, a->path_class[i], a->path_class[i] == 0);
    if (a->path_order[i] == BG_PATH_ORDER_NONE) bg_sb_puts(o, ", \"order\": null}");
    else bg_sb_printf(o, ", \"order\": %d}", a->path_order[i]);
  }
  end_list(o, a->npath);
}

static void put_cloops(bg_strbuf *o, const bg_model *m, const bg_analysis *a) {
  key(o, "causal_loops");
  bg_sb_putc(o, '[');
  for (int i = 0; i < a->ncloop; i++) {
    item(o, i);
    bg_sb_printf(o, "{\"id\": %d, \"bonds\": ", i + 1);
    bond_list(o, m, a->cloop_bonds + a->cloop_adr[i], a->cloop_n[i]);
    bg_sb_puts(o, ", \"gain\": ");
    str_or_null(o, a->cloop_gain ? a->cloop_gain[i] : NULL);
    bg_sb_puts(o, ", \"gain_value\": ");
    bg_sb_json_num(o, a->cloop_gain_value ? a->cloop_gain_value[i] : NAN);
    bg_sb_puts(o, ", \"class\": ");
    int_or_null(o, a->cloop_class ? a->cloop_class[i] : 0, !a->cloop_class);
    bg_sb_putc(o, '}'); /* no "mesh": a causal loop never passes an odd number of
                           gyrators (docs/analysis.md, "Causal meshes") */
  }
  end_list(o, a->ncloop);
}

/* A signal of the signal flow graph: e7 / f7 for bonds, the state's name after. */
static void signal_name(bg_strbuf *o, const bg_model *m, int s) {
  char buf[64];
  if (s < 2 * m->nbond) snprintf(buf, sizeof buf, "%c%d", s & 1 ? 'f' : 'e', m->bond_num[s / 2]);
  else if (s - 2 * m->nbond < m->nstate) snprintf(buf, sizeof buf, "%s", m->state_name[s - 2 * m->nbond]);
  else snprintf(buf, sizeof buf, "x%d", s);
  bg_sb_json_str(o, buf);
}

/* The bonds a topological loop passes, in order of first appearance;
 * seen[b] == stamp marks a bond already written (linear in the loop). */
static void tloop_bonds(bg_strbuf *o, const bg_model *m, const int *sig, int n, int *seen,
                        int stamp) {
  bg_sb_putc(o, '[');
  int k = 0;
  for (int i = 0; i < n; i++) {
    if (sig[i] >= 2 * m->nbond || seen[sig[i] / 2] == stamp) continue;
    seen[sig[i] / 2] = stamp;
    bg_sb_printf(o, "%s%d", k++ ? ", " : "", m->bond_num[sig[i] / 2]);
  }
  bg_sb_putc(o, ']');
}

static void put_tloop(bg_strbuf *o, const bg_model *m, const bg_analysis *a, int i, int *seen) {
  const int *sig = a->tloop_signals + a->tloop_adr[i];
  int n = a->tloop_n[i];
  bg_sb_printf(o, "{\"id\": %d, \"kind\": \"%s\", \"order\": %d, \"bonds\": ", i + 1,
               a->tloop_kind[i] == BG_TLOOP_FLAT ? "flat" : "open", a->tloop_order[i]);
  tloop_bonds(o, m, sig, n, seen, i + 1);
  bg_sb_puts(o, ", \"signals\": [");
  for (int k = 0; k < n; k++) {
    if (k) bg_sb_puts(o, ", ");
    signal_name(o, m, sig[k]);
  }
  bg_sb_puts(o, "], \"gain\": ");
  str_or_null(o, a->tloop_gain ? a->tloop_gain[i] : NULL);
  bg_sb_puts(o, ", \"gain_value\": ");
  bg_sb_json_num(o, a->tloop_gain_value ? a->tloop_gain_value[i] : NAN);
  bg_sb_puts(o, ", \"algebraic\": ");
  bool_val(o, a->tloop_algebraic && a->tloop_algebraic[i]);
  bg_sb_puts(o, ", \"cause\": ");
  str_or_null(o, a->tloop_cause ? a->tloop_cause[i] : NULL);
  bg_sb_putc(o, '}');
}

static void put_tloops(bg_strbuf *o, const bg_model *m, const bg_analysis *a) {
  key(o, "topological_loops");
  bg_sb_putc(o, '[');
  int *seen = a->ntloop ? bg_xcalloc((size_t)m->nbond + 1, sizeof(int)) : NULL;
  for (int i = 0; i < a->ntloop; i++) {
    item(o, i);
    put_tloop(o, m, a, i, seen);
  }
  free(seen);
  end_list(o, a->ntloop);
}

/* index.reduction: only when an index reduction was tried (the index is above 1). */
static void put_reduction(bg_strbuf *o, const bg_indexred *r) {
  if (!r || !r->status) return;
  bg_sb_printf(o, ", \"reduction\": {\"status\": \"%s\", \"message\": ", r->status > 0 ? "reduced" : "failed");
  str_or_null(o, r->message ? r->message : "");
  bg_sb_puts(o, ", \"index\": ");
  int_or_null(o, r->index, r->status < 0 || r->index < 0);
  bg_sb_puts(o, ", \"differentiated\": ");
  string_list(o, r->constraint, r->nconstraint);
  bg_sb_puts(o, ", \"lost_states\": ");
  string_list(o, r->lost, r->nlost);
  bg_sb_puts(o, ", \"dummy_derivatives\": ");
  string_list(o, r->dummy, r->ndummy);
  bg_sb_putc(o, '}');
}

static void put_summary(bg_strbuf *o, const bg_analysis *a, const bg_index_facts *f) {
  key(o, "states");
  string_list(o, a->states, a->nstates);
  bg_sb_puts(o, ",\n");
  key(o, "dependent_stores");
  string_list(o, a->dependent_stores, a->ndependent);
  bg_sb_puts(o, ",\n");
  key(o, "algebraic_variables");
  string_list(o, a->algebraic_variables, a->nalgebraic);
  bg_sb_puts(o, ",\n");
  key(o, "form");
  bg_sb_json_str(o, bg_form_name(a->form));
  bg_sb_puts(o, ",\n");
  key(o, "index");
  bg_sb_puts(o, "{\"predicted\": ");
  int_or_null(o, a->index_predicted, a->index_predicted < 0);
  /* The numeric index needs the equations (a later stage): null until it is
   * computed, and null for a singular pencil, which has no index; the extra
   * key numeric_status tells the two apart. */
  int set = bg_index_facts_numeric_set(f), computed = set && f->numeric->index >= 0;
  bg_sb_puts(o, ", \"numeric\": ");
  int_or_null(o, computed ? f->numeric->index : 0, !computed);
  bg_sb_puts(o, ", \"reason\": ");
  str_or_null(o, a->index_reason);
  bg_sb_printf(o, ", \"numeric_status\": \"%s\", \"disagreement\": ",
               computed ? "computed" : set ? "singular" : "not computed");
  str_or_null(o, f ? f->disagreement : NULL);
  put_reduction(o, f ? f->reduction : NULL);
  bg_sb_puts(o, "},\n");
}

static void put_estimates(bg_strbuf *o, const bg_analysis *a) {
  key(o, "estimates");
  bg_sb_putc(o, '[');
  for (int i = 0; i < a->nestimate; i++) {
    item(o, i);
    bg_sb_printf(o, "{\"kind\": \"%s\", \"path\": %d, \"value\": ",
                 a->estimate_kind[i] ? "natural_frequency" : "time_constant",
                 a->estimate_path[i] + 1);
    bg_sb_json_num(o, a->estimate_value[i]);
    bg_sb_putc(o, '}');
  }
  end_list(o, a->nestimate);
}

/* Coordinates by the 1-junction that carries the artificial source ("bond 7"
 * when a 1-junction was inserted into bond 7); forces in the same order. */
static void put_lagrange(bg_strbuf *o, const bg_model *m, const bg_analysis *a) {
  key(o, "lagrange");
  bg_sb_puts(o, "{\"coordinates\": [");
  for (int i = 0; i < a->nlag; i++) {
    char buf[64];
    if (i) bg_sb_puts(o, ", ");
    if (a->lag_junction[i] >= 0) bg_sb_json_str(o, m->elem_name[a->lag_junction[i]]);
    else {
      snprintf(buf, sizeof buf, "bond %d", m->bond_num[a->lag_bond[i]]);
      bg_sb_json_str(o, buf);
    }
  }
  bg_sb_puts(o, "], \"forces\": ");
  string_list(o, a->lag_force, a->nlag);
  bg_sb_puts(o, "}");
}

void bg_json_write_analysis(const bg_model *m, const bg_analysis *a, const bg_index_facts *f,
                            bg_strbuf *o) {
  bg_sb_puts(o, "{\n");
  key(o, "format");
  bg_sb_puts(o, "\"bgdraw-analysis\",\n");
  key(o, "version");
  bg_sb_puts(o, "1,\n");
  key(o, "model");
  str_or_null(o, m->name);
  bg_sb_puts(o, ",\n");
  key(o, "method");
  bg_sb_json_str(o, bg_method_name(a->method));
  bg_sb_puts(o, ",\n");
  key(o, "complete");
  bool_val(o, a->complete);
  bg_sb_puts(o, ",\n");
  put_bonds(o, m, a);
  put_elements(o, m, a);
  put_trace(o, a);
  put_conflicts(o, m, a);
  put_paths(o, m, a);
  put_cloops(o, m, a);
  put_tloops(o, m, a);
  put_summary(o, a, f);
  put_estimates(o, a);
  put_lagrange(o, m, a);
  bg_sb_puts(o, ",\n");
  key(o, "rosenberg_andry");
  bg_sb_puts(o, "{\"disjoint\": ");
  bool_val(o, a->cloops_disjoint);
  bg_sb_puts(o, ", \"satisfied\": ");
  bool_val(o, a->rosenberg_andry);
  bg_sb_puts(o, "},\n");
  key(o, "form_parameter_dependent");
  bool_val(o, a->form_parameter_dependent);
  bg_sb_puts(o, ",\n");
  put_instances(o, m);
  put_detectors(o, m);
  bg_json_put_fields(o, m, a);
  /* what the listing caps left out (lower bounds when a search budget ran out) */
  key(o, "omitted");
  bg_sb_printf(o, "{\"causal_paths\": %d, \"causal_loops\": %d, \"topological_loops\": %d, "
                 "\"topological_loops_complete\": %s},\n",
               a->npath_omitted, a->ncloop_omitted, a->ntloop_omitted,
               a->tloop_capped ? "false" : "true");
  /* set by the equations stage after symbolic elimination; null until then */
  key(o, "reduced_form");
  str_or_null(o, f ? f->reduced_form : NULL);
  if (f && f->reduced_note) { /* only when the symbolic work budget ran out */
    bg_sb_puts(o, ",\n");
    key(o, "reduced_note");
    bg_sb_json_str(o, f->reduced_note);
  }
  bg_sb_puts(o, "\n}\n");
}
