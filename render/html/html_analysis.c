/* SPDX-License-Identifier: BSD-3-Clause */
/* HTML report sections from the analysis: the summary with the verdict (the
 * PDF's words, report_summary.c), the causality trace, the tables of causal
 * paths, causal loops, topological loops and conflicts (each row carries its
 * bonds and the diagram's marks it lights: html_assets.c's script), the
 * model form and index, the estimates beside the eigenvalues. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/analysis.h"
#include "html/html_int.h"

/* ---------------------------------------------------------------- summary */
void ht_summary(ht_ctx *c) {
  ht_section(c, "summary", "Summary");
  bg_strbuf v = {0};
  rp_verdict(&c->rp, &v);
  bg_sb_puts(c->out, "<p class=\"verdict\" role=\"note\">");
  ht_esc(c->out, bg_sb_str(&v));
  bg_sb_puts(c->out, "</p>\n<div class=\"scroll\"><table class=\"summary\"><caption>Summary</caption>\n<tbody>\n");
  rp_summary_rows(&c->rp, ht_row, c->out);
  bg_sb_puts(c->out, "</tbody></table></div>\n");
  bg_sb_free(&v);
  ht_section_end(c);
}

/* ---------------------------------------------------------------- trace */
void ht_trace(ht_ctx *c) {
  const bg_analysis *a = c->a;
  ht_section(c, "trace", "Causality trace");
  bg_sb_puts(c->out, "<p>Method: <b>");
  ht_esc(c->out, bg_method_name(a->method));
  bg_sb_puts(c->out, "</b>. Each step of the assignment in order, with the bonds whose strokes it fixed "
                     "(a row lights them in the diagram).");
  if (!a->complete) bg_sb_puts(c->out, " The causality is <b>incomplete</b>: some bonds have no stroke.");
  bg_sb_puts(c->out, "</p>\n");
  if (a->ntrace == 0) {
    ht_para(c, "No steps were recorded.");
    ht_section_end(c);
    return;
  }
  static const char *const head[] = {"Step", "What happened", "Bonds"};
  ht_table(c, "items", "Causality trace", 3, head);
  int n = a->ntrace < HT_MAX_ROWS ? a->ntrace : HT_MAX_ROWS;
  /* the bonds of every step in one pass over the bonds */
  bg_strbuf *steps = bg_xcalloc((size_t)n, sizeof *steps);
  for (int i = 0; i < c->m->nbond; i++) {
    int k = a->bond_step[i] - 1;
    if (k >= 0 && k < n) bg_sb_printf(&steps[k], "%s%d", steps[k].len ? " " : "", c->m->bond_num[i]);
  }
  for (int k = 0; k < n; k++) {
    bg_sb_printf(c->out, "<tr id=\"step-%d\" tabindex=\"0\" data-bonds=\"%s\"><td>%d</td><td>", k + 1,
                 bg_sb_str(&steps[k]), k + 1);
    ht_esc(c->out, a->trace_text[k]);
    bg_sb_puts(c->out, "</td><td>");
    for (const char *p = bg_sb_str(&steps[k]); *p; p++) bg_sb_puts(c->out, *p == ' ' ? ", " : (char[]){*p, 0});
    bg_sb_puts(c->out, "</td></tr>\n");
    bg_sb_free(&steps[k]);
  }
  free(steps);
  ht_table_end(c);
  ht_more_rows(c, n, a->ntrace, 0, "steps");
  ht_section_end(c);
}

/* ---------------------------------------------------------------- tables */
/* <tr id="ID-N" tabindex=0 data-bonds="1 2" data-mark="p3"> for a row that
 * lights bonds (numbers) and the diagram's marks of class mark. */
static void item_row(ht_ctx *c, const char *id, int n, const int *bonds, int nb, const char *mark) {
  bg_sb_printf(c->out, "<tr id=\"%s-%d\" tabindex=\"0\" data-bonds=\"", id, n);
  for (int i = 0; i < nb; i++) bg_sb_printf(c->out, "%s%d", i ? " " : "", c->m->bond_num[bonds[i]]);
  bg_sb_puts(c->out, "\"");
  if (mark && *mark) bg_sb_printf(c->out, " data-mark=\"%s\"", mark);
  bg_sb_printf(c->out, "><th scope=\"row\"><a href=\"#%s-%d\">", id, n);
}

static void cell(ht_ctx *c, const char *text) {
  bg_sb_puts(c->out, "<td>");
  ht_esc(c->out, text);
  bg_sb_puts(c->out, "</td>");
}

static void expr_cell(ht_ctx *c, const char *text) {
  bg_sb_puts(c->out, "<td><code class=\"expr\">");
  ht_esc(c->out, text ? text : "");
  bg_sb_puts(c->out, "</code></td>");
}

static void int_cell(ht_ctx *c, int v) { bg_sb_printf(c->out, "<td class=\"n\">%d</td>", v); }

static void num_cell(ht_ctx *c, double v) {
  bg_sb_puts(c->out, "<td class=\"n\">");
  ht_num(c->out, v);
  bg_sb_puts(c->out, "</td>");
}

static void bonds_cell(ht_ctx *c, const int *bonds, int n) {
  bg_strbuf b = {0};
  ht_bonds(&b, c->m, bonds, n);
  cell(c, bg_sb_str(&b));
  bg_sb_free(&b);
}

static void paths_table(ht_ctx *c) {
  const bg_analysis *a = c->a;
  ht_sub(c, "causal-paths", "Causal paths");
  if (a->npath == 0) {
    ht_para(c, "No causal paths between ports of one-port elements.");
    return;
  }
  ht_para(c, "Between ports of one-port elements, bonds from the first end to the second. Class 1: "
             "independent to dependent store of one type; class 2: between resistive ports; order: "
             "integrations left in the loop the path closes (0 = algebraic, \u2013 for a source end).");
  static const char *const head[] = {"#", "Bonds", "Ends", "Kind", "Class", "Order"};
  ht_table(c, "items", "Causal paths", 6, head);
  int n = a->npath < HT_MAX_ROWS ? a->npath : HT_MAX_ROWS;
  for (int p = 0; p < n; p++) {
    char mark[32];
    snprintf(mark, sizeof mark, "p%d", p + 1);
    item_row(c, "path", p + 1, a->path_bonds + a->path_adr[p], a->path_n[p], mark);
    bg_sb_printf(c->out, "P%d</a></th>", p + 1);
    bonds_cell(c, a->path_bonds + a->path_adr[p], a->path_n[p]);
    bg_strbuf e = {0};
    bg_sb_printf(&e, "%s \u2192 %s", c->m->elem_name[a->path_end0[p]], c->m->elem_name[a->path_end1[p]]);
    cell(c, bg_sb_str(&e));
    bg_sb_free(&e);
    cell(c, a->path_kind[p]);
    if (a->path_class[p]) int_cell(c, a->path_class[p]);
    else bg_sb_puts(c->out, "<td class=\"n\">\u2013</td>");
    if (a->path_order[p] == BG_PATH_ORDER_NONE) bg_sb_puts(c->out, "<td class=\"n\">\u2013</td>");
    else int_cell(c, a->path_order[p]);
    bg_sb_puts(c->out, "</tr>\n");
  }
  ht_table_end(c);
  ht_more_rows(c, n, a->npath, a->npath_omitted, "causal paths");
}

/* The first open topological loop a causal loop caused, which the diagram
 * draws for it (as the PDF's highlight); 0 when none. */
static int cloop_tloop(const bg_analysis *a, int k) {
  char want[48];
  snprintf(want, sizeof want, "causal loop %d", k + 1);
  for (int l = 0; l < a->ntloop; l++)
    if (a->tloop_kind[l] == BG_TLOOP_OPEN && a->tloop_cause && a->tloop_cause[l] &&
        !strcmp(a->tloop_cause[l], want))
      return l + 1;
  return 0;
}

static void cloops_table(ht_ctx *c) {
  const bg_analysis *a = c->a;
  ht_sub(c, "causal-loops", "Causal loops");
  if (a->ncloop == 0) {
    ht_para(c, "No causal loops (closed causal paths).");
    return;
  }
  static const char *const head[] = {"#", "Bonds", "Gain", "Value", "Class"};
  ht_table(c, "items", "Causal loops", 5, head);
  int n = a->ncloop < HT_MAX_ROWS ? a->ncloop : HT_MAX_ROWS;
  for (int k = 0; k < n; k++) {
    char mark[32] = "";
    int l = cloop_tloop(a, k);
    if (l) snprintf(mark, sizeof mark, "l%d", l);
    item_row(c, "cloop", k + 1, a->cloop_bonds + a->cloop_adr[k], a->cloop_n[k], mark);
    bg_sb_printf(c->out, "%d</a></th>", k + 1);
    bonds_cell(c, a->cloop_bonds + a->cloop_adr[k], a->cloop_n[k]);
    expr_cell(c, a->cloop_gain[k]);
    num_cell(c, a->cloop_gain_value[k]);
    int_cell(c, a->cloop_class[k]);
    bg_sb_puts(c->out, "</tr>\n");
  }
  ht_table_end(c);
  ht_more_rows(c, n, a->ncloop, a->ncloop_omitted, "causal loops");
  bg_sb_printf(c->out, "<p>Class 4: gain other than +1; class 5: gain +1 (singular junction structure). "
                       "The causal loops are %spairwise disjoint; the Rosenberg\u2013Andry condition "
                       "(disjoint loops, none of gain +1) is <b>%s</b>.</p>\n",
               a->cloops_disjoint ? "" : "not ", a->rosenberg_andry ? "satisfied" : "not satisfied");
}

static void tloops_table(ht_ctx *c) {
  const bg_analysis *a = c->a;
  ht_sub(c, "topological-loops", "Topological loops");
  if (a->ntloop == 0) {
    ht_para(c, "No loops in the signal flow graph.");
    return;
  }
  ht_para(c, "Loops of the signal flow graph: flat loops run out along a causal path and back, open "
             "loops along one side of a bond loop. Order: integrations (s\u207b\u00b9) in the loop; "
             "order 0 loops are algebraic.");
  static const char *const head[] = {"#", "Kind", "Order", "Signals", "Gain", "Value", "Cause"};
  ht_table(c, "items", "Topological loops", 7, head);
  int n = a->ntloop < HT_MAX_ROWS ? a->ntloop : HT_MAX_ROWS;
  for (int l = 0; l < n; l++) {
    const int *sig = a->tloop_signals + a->tloop_adr[l];
    int ns = a->tloop_n[l], nb = 0;
    int *bonds = bg_xmalloc((size_t)(ns + 1) * sizeof *bonds);
    for (int i = 0; i < ns; i++) { /* each bond once, in the loop's order */
      int b = sig[i] / 2, seen = 0;
      for (int j = 0; j < nb && !seen; j++) seen = bonds[j] == b;
      if (!seen) bonds[nb++] = b;
    }
    char mark[32];
    snprintf(mark, sizeof mark, "l%d", l + 1);
    item_row(c, "loop", l + 1, bonds, nb, mark);
    free(bonds);
    bg_sb_printf(c->out, "L%d</a></th>", l + 1);
    bg_sb_printf(c->out, "<td>%s%s</td>", a->tloop_kind[l] == BG_TLOOP_FLAT ? "flat" : "open",
                 a->tloop_algebraic[l] ? ", algebraic" : "");
    int_cell(c, a->tloop_order[l]);
    bg_strbuf s = {0};
    for (int i = 0; i < ns; i++)
      bg_sb_printf(&s, "%s%c%d", i ? ", " : "", sig[i] & 1 ? 'f' : 'e', c->m->bond_num[sig[i] / 2]);
    expr_cell(c, bg_sb_str(&s));
    bg_sb_free(&s);
    expr_cell(c, a->tloop_gain[l]);
    bg_sb_puts(c->out, "<td class=\"n\">");
    rp_gain_value(c->out, a->tloop_gain_value[l], a->tloop_order[l]);
    bg_sb_puts(c->out, "</td>");
    cell(c, a->tloop_cause && a->tloop_cause[l] ? a->tloop_cause[l] : "");
    bg_sb_puts(c->out, "</tr>\n");
  }
  ht_table_end(c);
  ht_more_rows(c, n, a->ntloop, a->ntloop_omitted, "topological loops");
}

static void conflicts_table(ht_ctx *c) {
  const bg_analysis *a = c->a;
  ht_sub(c, "causal-conflicts", "Causal conflicts");
  if (a->nconflict == 0) {
    ht_para(c, "No causal conflicts.");
    return;
  }
  ht_para(c, "Type 1: no bond determines the junction's common variable; type 2: k + 1 bonds "
             "determine it (degree k).");
  static const char *const head[] = {"#", "Junction", "Type", "Degree", "Bonds"};
  ht_table(c, "items", "Causal conflicts", 5, head);
  int n = a->nconflict < HT_MAX_ROWS ? a->nconflict : HT_MAX_ROWS;
  for (int k = 0; k < n; k++) {
    char mark[32];
    snprintf(mark, sizeof mark, "c%d", k + 1);
    const int *b = a->conflict_bonds + a->conflict_adr[k];
    item_row(c, "conflict", k + 1, b, a->conflict_n[k], mark);
    bg_sb_printf(c->out, "%d</a></th>", k + 1);
    cell(c, c->m->elem_name[a->conflict_node[k]]);
    int_cell(c, a->conflict_type[k]);
    if (a->conflict_type[k] == 2) int_cell(c, a->conflict_degree[k]);
    else bg_sb_puts(c->out, "<td class=\"n\">\u2013</td>");
    bonds_cell(c, b, a->conflict_n[k]);
    bg_sb_puts(c->out, "</tr>\n");
  }
  ht_table_end(c);
  ht_more_rows(c, n, a->nconflict, 0, "conflicts");
}

void ht_tables(ht_ctx *c) {
  ht_section(c, "paths-loops-conflicts", "Paths, loops and conflicts");
  ht_para(c, "Point at a row, or move to it with the Tab key, to light its bonds in the diagram; a "
             "link such as #path-3 selects a row.");
  paths_table(c);
  cloops_table(c);
  tloops_table(c);
  conflicts_table(c);
  ht_section_end(c);
}

/* ---------------------------------------------------------------- form and index */
static void names_line(ht_ctx *c, const char *label, char **names, int n) {
  bg_sb_printf(c->out, "<p><b>%s (%d):</b> ", label, n);
  if (n == 0) bg_sb_puts(c->out, "none");
  for (int i = 0; i < n && i < 200; i++) {
    if (i) bg_sb_puts(c->out, ", ");
    ht_esc(c->out, names[i]);
  }
  if (n > 200) bg_sb_printf(c->out, ", \u2026 (%d more)", n - 200);
  bg_sb_puts(c->out, "</p>\n");
}

static const char *form_words(int form) {
  switch (form) {
  case BG_FORM_ODE: return "explicit ODE";
  case BG_FORM_DAE: return "semi-explicit DAE (algebraic loops, dependent stores or conflicts)";
  default: return "incomplete (the causality could not be completed)";
  }
}

static void labelled(ht_ctx *c, const char *label, const char *text) {
  bg_sb_printf(c->out, "<p><b>%s:</b> ", label);
  ht_esc(c->out, text);
  bg_sb_puts(c->out, ".</p>\n");
}

static void index_lines(ht_ctx *c) {
  const bg_analysis *a = c->a;
  const bg_report_input *in = c->in;
  bg_strbuf b = {0};
  if (a->index_predicted < 0) bg_sb_puts(&b, "unknown");
  else if (a->index_predicted >= 2) bg_sb_puts(&b, "above 1");
  else bg_sb_printf(&b, "%d", a->index_predicted);
  if (a->index_reason) bg_sb_printf(&b, " \u2014 %s", a->index_reason);
  labelled(c, "Predicted index", bg_sb_str(&b));
  bg_sb_clear(&b);
  if (in->index) {
    if (in->index->index >= 0) bg_sb_printf(&b, "%d", in->index->index);
    else bg_sb_puts(&b, in->index->index == BG_INDEX_SINGULAR ? "singular pencil" : "not computed");
    if (in->index->message) bg_sb_printf(&b, " \u2014 %s", in->index->message);
  } else {
    bg_sb_puts(&b, "not computed");
    const char *why = in->index_skipped ? in->index_skipped : in->eqs_problem;
    if (why) bg_sb_printf(&b, ": %s", why);
  }
  labelled(c, "Numeric index (Algorithm 4.1 on the equations linearised at the initial point)", bg_sb_str(&b));
  bg_sb_free(&b);
  if (in->facts->disagreement) labelled(c, "Warning", in->facts->disagreement);
  const bg_indexred *ir = in->facts->reduction;
  if (ir && ir->status) {
    ht_sub(c, "index-reduction", "Index reduction");
    labelled(c, "Index reduction", ir->message ? ir->message : "");
    for (int k = 0; k < ir->nconstraint; k++) labelled(c, "Differentiated", ir->constraint[k]);
    for (int k = 0; k < ir->nlost; k++) labelled(c, "Lost its state", ir->lost[k]);
  }
  const bg_index_result *r = in->index;
  if (!r || r->nhist == 0) return;
  ht_sub(c, "rank-history", "Rank history of Algorithm 4.1");
  ht_para(c, "Regularity of the pencil \u03bbA + B first, then one line per reduction step: the rank of "
             "A decided by SVD on the equilibrated matrices; when A is rank deficient its null rows are "
             "replaced by the differentiated algebraic constraints.");
  static const char *const head[] = {"#", "Decision"};
  ht_table(c, NULL, "Rank history", 2, head);
  for (int k = 0; k < r->nhist; k++) {
    bg_sb_printf(c->out, "<tr><td class=\"n\">%d</td>", k + 1);
    cell(c, r->hist[k]);
    bg_sb_puts(c->out, "</tr>\n");
  }
  ht_table_end(c);
}

void ht_index(ht_ctx *c) {
  const bg_analysis *a = c->a;
  ht_section(c, "form-index", "Model form and index");
  bg_sb_printf(c->out, "<p><b>Form:</b> %s", form_words(a->form));
  if (c->in->facts->reduced_form) {
    bg_sb_puts(c->out, "; after symbolic elimination: ");
    ht_esc(c->out, c->in->facts->reduced_form);
  }
  bg_sb_puts(c->out, ".");
  if (c->in->facts->reduced_note) {
    bg_sb_puts(c->out, " Symbolic elimination: ");
    ht_esc(c->out, c->in->facts->reduced_note);
    bg_sb_puts(c->out, ".");
  }
  if (a->form_parameter_dependent)
    bg_sb_puts(c->out, " The form depends on parameter values: an algebraic loop is linear and solvable "
                       "only while its gain differs from 1 (Equation 4.45).");
  bg_sb_puts(c->out, "</p>\n");
  names_line(c, "States", a->states, a->nstates);
  names_line(c, "Dependent stores", a->dependent_stores, a->ndependent);
  names_line(c, "Algebraic variables", a->algebraic_variables, a->nalgebraic);
  index_lines(c);
  ht_section_end(c);
}

/* ---------------------------------------------------------------- estimates */
static void complex_text(bg_strbuf *b, double re, double im) {
  ht_num(b, re);
  if (im != 0) bg_sb_puts(b, " \u00b1 "), ht_num(b, fabs(im)), bg_sb_puts(b, "<i>i</i>");
}

static void estimates_table(ht_ctx *c) {
  const bg_analysis *a = c->a;
  const bg_index_result *r = c->in->index;
  if (a->nestimate == 0) {
    ht_para(c, "No first- or second-order causal paths give an estimate.");
    return;
  }
  static const char *const head[] = {"#", "Estimate", "From", "Value", "Derived", "Nearest eigenvalue"};
  ht_table(c, "items", "Estimates from causal paths", 6, head);
  for (int k = 0; k < a->nestimate; k++) {
    int kind = a->estimate_kind[k], p = a->estimate_path[k];
    double v = a->estimate_value[k];
    char mark[32];
    snprintf(mark, sizeof mark, "p%d", p + 1);
    item_row(c, "estimate", k + 1, a->path_bonds + a->path_adr[p], a->path_n[p], mark);
    bg_sb_printf(c->out, "%d</a></th><td>%s</td><td><a href=\"#path-%d\">path P%d</a></td><td class=\"n\">",
                 k + 1, kind == 0 ? "time constant \u03c4" : "natural frequency \u03c9<sub>0</sub>", p + 1,
                 p + 1);
    ht_num(c->out, v);
    bg_sb_puts(c->out, kind == 0 ? " s</td><td>1/\u03c4 = " : " rad/s</td><td>period 2\u03c0/\u03c9<sub>0</sub> = ");
    ht_num(c->out, kind == 0 ? 1 / v : 2 * 3.14159265358979 / v);
    bg_sb_puts(c->out, kind == 0 ? " rad/s</td><td>" : " s</td><td>");
    int e = r ? rp_nearest_eig(r, kind, v) : -1;
    if (e >= 0) {
      bg_sb_puts(c->out, "\u03bb = ");
      complex_text(c->out, r->eig_re[e], r->eig_im[e]);
      bg_sb_puts(c->out, ", |\u03bb| = ");
      ht_num(c->out, hypot(r->eig_re[e], r->eig_im[e]));
    } else {
      bg_sb_puts(c->out, "\u2013");
    }
    bg_sb_puts(c->out, "</td></tr>\n");
  }
  ht_table_end(c);
}

static void eigen_table(ht_ctx *c) {
  const bg_index_result *r = c->in->index;
  if (!r) {
    const char *why = c->in->index_skipped ? c->in->index_skipped : c->in->eqs_problem;
    ht_para(c, "No eigenvalues: the numeric index was not computed%s%s%s.", why ? " (" : "", why ? why : "",
            why ? ")" : "");
    return;
  }
  if (r->neig == 0) {
    ht_para(c, "%s", r->index == 0 || r->index == 1 ? "The linearised model has no finite eigenvalues."
                                                    : "Eigenvalues are computed for index 0 and 1 only.");
    return;
  }
  static const char *const head[] = {"#", "Eigenvalue \u03bb", "|\u03bb|", "Time constant or frequency"};
  ht_table(c, NULL, "Eigenvalues", 4, head);
  int n = r->neig < 60 ? r->neig : 60, shown = 0;
  for (int k = 0; k < n; k++) {
    if (rp_conjugate_listed(r, k)) continue;
    double re = r->eig_re[k], im = r->eig_im[k], mag = hypot(re, im);
    bg_eig_kind kind = bg_index_eig_kind(r, k);
    bg_sb_printf(c->out, "<tr><td class=\"n\">%d</td><td class=\"n\">", ++shown);
    complex_text(c->out, re, im);
    bg_sb_puts(c->out, "</td><td class=\"n\">");
    ht_num(c->out, mag);
    bg_sb_puts(c->out, "</td><td>");
    if (kind == BG_EIG_ZERO) bg_sb_puts(c->out, "pure integration: ");
    else if (im == 0) bg_sb_puts(c->out, "\u03c4 = "), ht_num(c->out, 1 / fabs(re)), bg_sb_puts(c->out, " s");
    else {
      bg_sb_puts(c->out, "\u03c9 = "), ht_num(c->out, fabs(im)), bg_sb_puts(c->out, " rad/s, \u03b6 = ");
      ht_num(c->out, kind == BG_EIG_UNDAMPED ? 0.0 : -re / mag);
    }
    if (kind == BG_EIG_ZERO) ht_esc(c->out, bg_index_eig_word(kind));
    else if (kind != BG_EIG_DECAYING) bg_sb_puts(c->out, " ("), ht_esc(c->out, bg_index_eig_word(kind)), bg_sb_puts(c->out, ")");
    bg_sb_puts(c->out, "</td></tr>\n");
  }
  ht_table_end(c);
  ht_more_rows(c, n, r->neig, 0, "eigenvalues");
}

void ht_estimates(ht_ctx *c) {
  ht_section(c, "estimates", "Time constants and frequencies");
  ht_para(c, "Estimates from first- and second-order causal paths, linearised at the initial point, "
             "beside the finite eigenvalues of the linearised model (\u03bbAv = \u2212Bv).");
  ht_sub(c, "estimates-paths", "Estimates from causal paths");
  estimates_table(c);
  ht_sub(c, "eigenvalues", "Eigenvalues");
  eigen_table(c);
  ht_section_end(c);
}
