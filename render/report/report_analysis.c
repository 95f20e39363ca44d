/* SPDX-License-Identifier: BSD-3-Clause */
/* Report sections 4, 5, 6 and 8: the causality trace, the tables of causal
 * paths, causal loops, topological loops and conflicts, the model form and
 * index with the rank history, the estimates beside the eigenvalues. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report/report_int.h"
#include "analysis/analysis.h"

#define MAX_ROWS 400 /* per table; the JSON lists everything */
#define MAX_EIGS 60

static void para(rp_ctx *c, const char *markup) {
  rp_para(&c->body, markup, RP_SIZE_BODY, 0, 0, rp_ink);
  rp_gap(&c->body, 3);
}

static void more_rows(rp_ctx *c, int shown, int total, int omitted, const char *what) {
  if (shown >= total && !omitted) return;
  bg_strbuf b = {0};
  if (shown < total) bg_sb_printf(&b, "The first %d of %d %s are listed; ", shown, total, what);
  if (omitted) bg_sb_printf(&b, "%s%d more %s were found but not enumerated (listing cap); ",
                            shown < total ? "" : "", omitted, what);
  bg_sb_puts(&b, "the JSON output (<tt>-o model.json</tt>) has every listed one.");
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_SMALL, 0, 0, rp_grey);
  rp_gap(&c->body, 3);
  bg_sb_free(&b);
}

static int cap_rows(int n) { return n < MAX_ROWS ? n : MAX_ROWS; }

/* ---------------------------------------------------------------- 4 trace */
void rp_sec_trace(rp_ctx *c) {
  const bg_analysis *a = c->a;
  rp_section(&c->body, "Causality trace", 1, 0, 80);
  bg_strbuf b = {0};
  bg_sb_printf(&b, "Method: <b>%s</b>. Each step of the assignment in order, with the bonds whose "
                   "strokes it fixed.", bg_method_name(a->method));
  if (!a->complete) bg_sb_puts(&b, " The causality is <b>incomplete</b>: some bonds have no stroke.");
  para(c, bg_sb_str(&b));
  bg_sb_free(&b);
  if (a->ntrace == 0) {
    para(c, "No steps were recorded.");
    return;
  }
  static const char *head[] = {"Step", "What happened", "Bonds"};
  rp_table t;
  rp_table_init(&t, 3, head, "rll");
  int n = cap_rows(a->ntrace);
  for (int k = 0; k < n; k++) {
    rp_table_cell(&t, "%d", k + 1);
    rp_table_text(&t, a->trace_text[k]);
    bg_strbuf bl = {0};
    for (int i = 0; i < c->m->nbond; i++)
      if (a->bond_step[i] == k + 1) bg_sb_printf(&bl, "%s%d", bl.len ? ", " : "", c->m->bond_num[i]);
    rp_table_cell(&t, "%s", bg_sb_str(&bl));
    bg_sb_free(&bl);
  }
  rp_table_emit(&c->body, &t);
  more_rows(c, n, a->ntrace, 0, "steps");
}

/* ---------------------------------------------------------------- 5 tables */
static void eq_cell(rp_table *t, const char *plain) {
  bg_strbuf b = {0};
  rp_eq_markup(plain ? plain : "", t->size, &b);
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_free(&b);
}

static void num_cell(rp_table *t, double v) {
  bg_strbuf b = {0};
  rp_num(&b, v);
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_free(&b);
}

static void bonds_cell(rp_ctx *c, rp_table *t, const int *bonds, int n) {
  bg_strbuf b = {0};
  rp_bond_list(&b, c->m, bonds, n);
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_free(&b);
}

static void paths_table(rp_ctx *c) {
  const bg_analysis *a = c->a;
  rp_subsection(&c->body, "Causal paths", 90);
  if (a->npath == 0) {
    para(c, "No causal paths between ports of one-port elements.");
    return;
  }
  para(c, "Between ports of one-port elements, bonds from the first end to the second. Class 1: "
          "independent to dependent store of one type; class 2: between resistive ports; order: "
          "integrations left in the loop the path closes (0 = algebraic, \u2013 for a source end).");
  static const char *head[] = {"#", "Bonds", "Ends", "Kind", "Class", "Order"};
  rp_table t;
  rp_table_init(&t, 6, head, "rlllrr");
  int n = cap_rows(a->npath);
  for (int p = 0; p < n; p++) {
    rp_table_cell(&t, "P%d", p + 1);
    bonds_cell(c, &t, a->path_bonds + a->path_adr[p], a->path_n[p]);
    bg_strbuf e = {0};
    rp_esc(&e, c->m->elem_name[a->path_end0[p]]);
    bg_sb_puts(&e, " \u2192 ");
    rp_esc(&e, c->m->elem_name[a->path_end1[p]]);
    rp_table_cell(&t, "%s", bg_sb_str(&e));
    bg_sb_free(&e);
    rp_table_text(&t, a->path_kind[p]);
    if (a->path_class[p]) rp_table_cell(&t, "%d", a->path_class[p]);
    else rp_table_cell(&t, "\u2013");
    if (a->path_order[p] == BG_PATH_ORDER_NONE) rp_table_cell(&t, "\u2013");
    else rp_table_cell(&t, "%d", a->path_order[p]);
  }
  rp_table_emit(&c->body, &t);
  more_rows(c, n, a->npath, a->npath_omitted, "causal paths");
}

static void cloops_table(rp_ctx *c) {
  const bg_analysis *a = c->a;
  rp_subsection(&c->body, "Causal loops", 60);
  if (a->ncloop == 0) {
    para(c, "No causal loops (closed causal paths).");
    return;
  }
  static const char *head[] = {"#", "Bonds", "Gain", "Value", "Class"};
  rp_table t;
  rp_table_init(&t, 5, head, "rllrr");
  int n = cap_rows(a->ncloop);
  for (int k = 0; k < n; k++) {
    rp_table_cell(&t, "%d", k + 1);
    bonds_cell(c, &t, a->cloop_bonds + a->cloop_adr[k], a->cloop_n[k]);
    eq_cell(&t, a->cloop_gain[k]);
    num_cell(&t, a->cloop_gain_value[k]);
    rp_table_cell(&t, "%d", a->cloop_class[k]);
  }
  rp_table_emit(&c->body, &t);
  more_rows(c, n, a->ncloop, a->ncloop_omitted, "causal loops");
  bg_strbuf b = {0};
  bg_sb_printf(&b, "Class 4: gain other than +1; class 5: gain +1 (singular junction structure). "
                   "The causal loops are %spairwise disjoint; the Rosenberg\u2013Andry condition "
                   "(disjoint loops, none of gain +1) is <b>%s</b>.",
               a->cloops_disjoint ? "" : "not ", a->rosenberg_andry ? "satisfied" : "not satisfied");
  para(c, bg_sb_str(&b));
  bg_sb_free(&b);
}

static void signals_cell(rp_table *t, const bg_model *m, const int *sig, int n) {
  bg_strbuf plain = {0};
  for (int i = 0; i < n; i++)
    bg_sb_printf(&plain, "%s%c%d", i ? ", " : "", sig[i] & 1 ? 'f' : 'e', m->bond_num[sig[i] / 2]);
  eq_cell(t, bg_sb_str(&plain));
  bg_sb_free(&plain);
}

static void tloops_table(rp_ctx *c) {
  const bg_analysis *a = c->a;
  rp_subsection(&c->body, "Topological loops", 90);
  if (a->ntloop == 0) {
    para(c, "No loops in the signal flow graph.");
    return;
  }
  para(c, "Loops of the signal flow graph: flat loops run out along a causal path and back, "
          "open loops along one side of a bond loop. Order: integrations (s<sup>\u22121</sup>) in "
          "the loop; order 0 loops are algebraic.");
  static const char *head[] = {"#", "Kind", "Order", "Signals", "Gain", "Value", "Cause"};
  rp_table t;
  rp_table_init(&t, 7, head, "rlrllrl");
  int n = cap_rows(a->ntloop);
  for (int l = 0; l < n; l++) {
    rp_table_cell(&t, "L%d", l + 1);
    rp_table_cell(&t, "%s%s", a->tloop_kind[l] == BG_TLOOP_FLAT ? "flat" : "open",
                  a->tloop_algebraic[l] ? ", algebraic" : "");
    rp_table_cell(&t, "%d", a->tloop_order[l]);
    signals_cell(&t, c->m, a->tloop_signals + a->tloop_adr[l], a->tloop_n[l]);
    eq_cell(&t, a->tloop_gain[l]);
    bg_strbuf v = {0};
    rp_gain_value(&v, a->tloop_gain_value[l], a->tloop_order[l]);
    rp_table_cell(&t, "%s", bg_sb_str(&v));
    bg_sb_free(&v);
    rp_table_text(&t, a->tloop_cause && a->tloop_cause[l] ? a->tloop_cause[l] : "");
  }
  rp_table_emit(&c->body, &t);
  more_rows(c, n, a->ntloop, a->ntloop_omitted, "topological loops");
}

static void conflicts_table(rp_ctx *c) {
  const bg_analysis *a = c->a;
  rp_subsection(&c->body, "Causal conflicts", 60);
  if (a->nconflict == 0) {
    para(c, "No causal conflicts.");
    return;
  }
  para(c, "Type 1: no bond determines the junction's common variable; type 2: k + 1 bonds "
          "determine it (degree k).");
  static const char *head[] = {"#", "Junction", "Type", "Degree", "Bonds"};
  rp_table t;
  rp_table_init(&t, 5, head, "rlrrl");
  int n = cap_rows(a->nconflict);
  for (int k = 0; k < n; k++) {
    rp_table_cell(&t, "%d", k + 1);
    rp_table_text(&t, c->m->elem_name[a->conflict_node[k]]);
    rp_table_cell(&t, "%d", a->conflict_type[k]);
    if (a->conflict_type[k] == 2) rp_table_cell(&t, "%d", a->conflict_degree[k]);
    else rp_table_cell(&t, "\u2013");
    bonds_cell(c, &t, a->conflict_bonds + a->conflict_adr[k], a->conflict_n[k]);
  }
  rp_table_emit(&c->body, &t);
  more_rows(c, n, a->nconflict, 0, "conflicts");
}

void rp_sec_tables(rp_ctx *c) {
  rp_section(&c->body, "Paths, loops and conflicts", 1, 0, 100);
  paths_table(c);
  cloops_table(c);
  tloops_table(c);
  conflicts_table(c);
}

/* ---------------------------------------------------------------- 6 form and index */
static void names_line(rp_ctx *c, const char *label, char **names, int n) {
  bg_strbuf b = {0};
  bg_sb_printf(&b, "<b>%s (%d):</b> ", label, n);
  if (n == 0) bg_sb_puts(&b, "none");
  for (int i = 0; i < n && i < 200; i++) {
    if (i) bg_sb_puts(&b, ", ");
    rp_eq_markup(names[i], RP_SIZE_BODY, &b);
  }
  if (n > 200) bg_sb_printf(&b, ", \u2026 (%d more)", n - 200);
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_BODY, 0, 12, rp_ink);
  rp_gap(&c->body, 2);
  bg_sb_free(&b);
}

static const char *form_words(int form) {
  switch (form) {
  case BG_FORM_ODE: return "explicit ODE";
  case BG_FORM_DAE: return "semi-explicit DAE (algebraic loops, dependent stores or conflicts)";
  default: return "incomplete (the causality could not be completed)";
  }
}

/* "<b>Label:</b> text." as a paragraph, the text escaped. */
static void labelled(rp_ctx *c, const char *label, const char *text) {
  bg_strbuf b = {0};
  bg_sb_printf(&b, "<b>%s:</b> ", label);
  rp_esc(&b, text);
  bg_sb_puts(&b, ".");
  para(c, bg_sb_str(&b));
  bg_sb_free(&b);
}

/* The index reduction (Pantelides, dummy derivatives) in bond-graph terms:
 * what was differentiated, which stores lost their state. */
static void reduction_lines(rp_ctx *c) {
  const bg_indexred *ir = c->in->facts->reduction;
  if (!ir || !ir->status) return;
  labelled(c, "Index reduction", ir->message ? ir->message : "");
  for (int k = 0; k < ir->nconstraint; k++) labelled(c, "Differentiated", ir->constraint[k]);
  for (int k = 0; k < ir->nlost; k++) labelled(c, "Lost its state", ir->lost[k]);
}

static void index_lines(rp_ctx *c) {
  const bg_analysis *a = c->a;
  const bg_report_input *in = c->in;
  bg_strbuf b = {0};
  bg_sb_puts(&b, "<b>Predicted index:</b> ");
  if (a->index_predicted < 0) bg_sb_puts(&b, "unknown");
  else if (a->index_predicted >= 2) bg_sb_puts(&b, "above 1");
  else bg_sb_printf(&b, "%d", a->index_predicted);
  if (a->index_reason) bg_sb_puts(&b, " \u2014 "), rp_esc(&b, a->index_reason);
  bg_sb_puts(&b, ".");
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_BODY, 0, 12, rp_ink);
  rp_gap(&c->body, 2);
  bg_sb_clear(&b);
  bg_sb_puts(&b, "<b>Numeric index</b> (Algorithm 4.1 on the equations linearised at the initial point): ");
  if (in->index) {
    if (in->index->index >= 0) bg_sb_printf(&b, "<b>%d</b>", in->index->index);
    else bg_sb_puts(&b, in->index->index == BG_INDEX_SINGULAR ? "singular pencil" : "not computed");
    if (in->index->message) bg_sb_puts(&b, " \u2014 "), rp_esc(&b, in->index->message);
  } else {
    bg_sb_puts(&b, "not computed");
    const char *why = in->index_skipped ? in->index_skipped : in->eqs_problem;
    if (why) bg_sb_puts(&b, ": "), rp_esc(&b, why);
  }
  bg_sb_puts(&b, ".");
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_BODY, 0, 12, rp_ink);
  rp_gap(&c->body, 2);
  bg_sb_free(&b);
  if (c->in->facts->disagreement) {
    bg_strbuf w = {0};
    bg_sb_puts(&w, "<b>Warning:</b> ");
    rp_esc(&w, c->in->facts->disagreement);
    bg_sb_puts(&w, ".");
    para(c, bg_sb_str(&w));
    bg_sb_free(&w);
  }
  reduction_lines(c);
}

static void history_table(rp_ctx *c) {
  const bg_index_result *r = c->in->index;
  if (!r || r->nhist == 0) return;
  rp_subsection(&c->body, "Rank history of Algorithm 4.1", 80);
  para(c, "Regularity of the pencil \u03bbA + B first, then one line per reduction step: the rank "
          "of A decided by SVD on the equilibrated matrices; when A is rank deficient its null "
          "rows are replaced by the differentiated algebraic constraints.");
  static const char *head[] = {"#", "Decision"};
  rp_table t;
  rp_table_init(&t, 2, head, "rl");
  for (int k = 0; k < r->nhist; k++) {
    rp_table_cell(&t, "%d", k + 1);
    rp_table_text(&t, r->hist[k]);
  }
  rp_table_emit(&c->body, &t);
}

void rp_sec_index(rp_ctx *c) {
  const bg_analysis *a = c->a;
  rp_section(&c->body, "Model form and index", 1, 0, 80);
  bg_strbuf b = {0};
  bg_sb_printf(&b, "<b>Form:</b> %s", form_words(a->form));
  if (c->in->facts->reduced_form)
    bg_sb_printf(&b, "; after symbolic elimination: %s", c->in->facts->reduced_form);
  bg_sb_puts(&b, ".");
  if (c->in->facts->reduced_note) bg_sb_printf(&b, " Symbolic elimination: %s.", c->in->facts->reduced_note);
  if (a->form_parameter_dependent)
    bg_sb_puts(&b, " The form depends on parameter values: an algebraic loop is linear and solvable "
                   "only while its gain differs from 1 (Equation 4.45).");
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_BODY, 0, 12, rp_ink);
  rp_gap(&c->body, 2);
  bg_sb_free(&b);
  names_line(c, "States", a->states, a->nstates);
  names_line(c, "Dependent stores", a->dependent_stores, a->ndependent);
  names_line(c, "Algebraic variables", a->algebraic_variables, a->nalgebraic);
  index_lines(c);
  history_table(c);
}

/* ---------------------------------------------------------------- 8 estimates */
static void complex_text(bg_strbuf *b, double re, double im) {
  rp_num(b, re);
  if (im != 0) bg_sb_puts(b, " \u00b1 "), rp_num(b, fabs(im)), bg_sb_puts(b, "<i>i</i>");
}

/* The eigenvalue closest in magnitude to an estimate: 1/tau for a time
 * constant (real eigenvalues first), omega for a frequency (complex first). */
int rp_nearest_eig(const bg_index_result *r, int kind, double value) {
  int best = -1;
  double bestd = 0;
  for (int pass = 0; pass < 2 && best < 0; pass++)
    for (int k = 0; k < r->neig; k++) {
      int complex = r->eig_im[k] != 0;
      if (pass == 0 && complex != (kind == 1)) continue;
      if (complex && r->eig_im[k] < 0) continue;
      double mag = hypot(r->eig_re[k], r->eig_im[k]);
      double want = kind == 0 ? 1 / value : value;
      if (!(mag > 0) || !(want > 0)) continue;
      double dist = fabs(log(mag / want));
      if (best < 0 || dist < bestd) best = k, bestd = dist;
    }
  return best;
}

static void estimates_table(rp_ctx *c) {
  const bg_analysis *a = c->a;
  const bg_index_result *r = c->in->index;
  if (a->nestimate == 0) {
    para(c, "No first- or second-order causal paths give an estimate.");
    return;
  }
  static const char *head[] = {"#", "Estimate", "From", "Value", "Derived", "Nearest eigenvalue"};
  rp_table t;
  rp_table_init(&t, 6, head, "rllrll");
  for (int k = 0; k < a->nestimate; k++) {
    int kind = a->estimate_kind[k];
    double v = a->estimate_value[k];
    rp_table_cell(&t, "%d", k + 1);
    rp_table_cell(&t, "%s", kind == 0 ? "time constant \u03c4" : "natural frequency \u03c9<sub>0</sub>");
    rp_table_cell(&t, "path P%d", a->estimate_path[k] + 1);
    bg_strbuf b = {0};
    rp_num(&b, v);
    bg_sb_puts(&b, kind == 0 ? " s" : " rad/s");
    rp_table_cell(&t, "%s", bg_sb_str(&b));
    bg_sb_clear(&b);
    if (kind == 0) bg_sb_puts(&b, "1/\u03c4 = "), rp_num(&b, 1 / v), bg_sb_puts(&b, " rad/s");
    else bg_sb_puts(&b, "period 2\u03c0/\u03c9<sub>0</sub> = "), rp_num(&b, 2 * 3.14159265358979 / v), bg_sb_puts(&b, " s");
    rp_table_cell(&t, "%s", bg_sb_str(&b));
    bg_sb_clear(&b);
    int e = r ? rp_nearest_eig(r, kind, v) : -1;
    if (e >= 0) {
      bg_sb_puts(&b, "\u03bb = ");
      complex_text(&b, r->eig_re[e], r->eig_im[e]);
      bg_sb_puts(&b, ", |\u03bb| = ");
      rp_num(&b, hypot(r->eig_re[e], r->eig_im[e]));
    } else {
      bg_sb_puts(&b, "\u2013");
    }
    rp_table_cell(&t, "%s", bg_sb_str(&b));
    bg_sb_free(&b);
  }
  rp_table_emit(&c->body, &t);
}

static void eig_cells(rp_table *t, const bg_index_result *r, int k) {
  double re = r->eig_re[k], im = r->eig_im[k];
  bg_eig_kind kind = bg_index_eig_kind(r, k);
  bg_strbuf b = {0};
  complex_text(&b, re, im);
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_clear(&b);
  double mag = hypot(re, im);
  rp_num(&b, mag);
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_clear(&b);
  if (kind == BG_EIG_ZERO) bg_sb_puts(&b, "pure integration: ");
  else if (im == 0) bg_sb_puts(&b, "\u03c4 = "), rp_num(&b, 1 / fabs(re)), bg_sb_puts(&b, " s");
  else {
    bg_sb_puts(&b, "\u03c9 = "), rp_num(&b, fabs(im)), bg_sb_puts(&b, " rad/s, \u03b6 = ");
    rp_num(&b, kind == BG_EIG_UNDAMPED ? 0.0 : -re / mag);
  }
  if (kind == BG_EIG_ZERO) bg_sb_puts(&b, bg_index_eig_word(kind));
  else if (kind != BG_EIG_DECAYING) bg_sb_printf(&b, " (%s)", bg_index_eig_word(kind));
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_free(&b);
}

/* A pair is one row, "re ± im": the member with im > 0 is skipped when its
 * conjugate is in the list (index.c keeps pairs exactly conjugate). */
int rp_conjugate_listed(const bg_index_result *r, int k) {
  if (r->eig_im[k] <= 0) return 0;
  for (int j = 0; j < r->neig; j++)
    if (r->eig_im[j] == -r->eig_im[k] && r->eig_re[j] == r->eig_re[k]) return 1;
  return 0;
}

static void eigen_table(rp_ctx *c) {
  const bg_index_result *r = c->in->index;
  if (!r) {
    bg_strbuf b = {0};
    bg_sb_puts(&b, "No eigenvalues: the numeric index was not computed");
    const char *why = c->in->index_skipped ? c->in->index_skipped : c->in->eqs_problem;
    if (why) bg_sb_puts(&b, " (") , rp_esc(&b, why), bg_sb_puts(&b, ")");
    bg_sb_puts(&b, ".");
    para(c, bg_sb_str(&b));
    bg_sb_free(&b);
    return;
  }
  if (r->neig == 0) {
    para(c, r->index == 0 || r->index == 1 ? "The linearised model has no finite eigenvalues."
                                           : "Eigenvalues are computed for index 0 and 1 only.");
    return;
  }
  static const char *head[] = {"#", "Eigenvalue \u03bb", "|\u03bb|", "Time constant or frequency"};
  rp_table t;
  rp_table_init(&t, 4, head, "rrrl");
  int n = r->neig < MAX_EIGS ? r->neig : MAX_EIGS;
  int shown = 0;
  for (int k = 0; k < n; k++) {
    if (rp_conjugate_listed(r, k)) continue; /* listed as ± with its conjugate */
    rp_table_cell(&t, "%d", ++shown);
    eig_cells(&t, r, k);
  }
  rp_table_emit(&c->body, &t);
  more_rows(c, n, r->neig, 0, "eigenvalues");
}

void rp_sec_estimates(rp_ctx *c) {
  rp_section(&c->body, "Time constants and frequencies", 1, 0, 80);
  para(c, "Estimates from first- and second-order causal paths, linearised at the initial point, "
          "beside the finite eigenvalues of the linearised model (\u03bbAv = \u2212Bv).");
  rp_subsection(&c->body, "Estimates from causal paths", 30);
  estimates_table(c);
  rp_subsection(&c->body, "Eigenvalues", 30);
  eigen_table(c);
}
