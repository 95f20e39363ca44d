/* SPDX-License-Identifier: BSD-3-Clause */
/* Report section: a parameter study of the model (docs/study.md, "In the
 * report"), when the report is written by a study's call: what was varied
 * and how, the summary table (the first runs, the first quantities), the
 * family of runs or the Monte Carlo envelope, the quantities against the
 * swept param, the root locus and the Bode family, each when the study has
 * what it needs. The rest of the report is the model at its own values. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot.h"
#include "report/report_int.h"

enum { MAX_ROWS = 60, MAX_QUANTITIES = 6 };

static void para(rp_ctx *c, const char *markup) {
  rp_para(&c->body, markup, RP_SIZE_BODY, 0, 0, rp_ink);
  rp_gap(&c->body, 3);
}

/* "A sweep of R0 over 5:125:7 (7 values) ...: 14 runs, 1 failed." */
static void describe(rp_ctx *c, const bg_study *st) {
  const bg_study_spec *s = st->spec;
  bg_strbuf b = {0};
  if (s->kind == BG_STUDY_SWEEP) {
    bg_sb_puts(&b, s->nparams > 1 ? "A sweep over the grid of " : "A sweep of ");
    for (int k = 0; k < s->nparams; k++) {
      bg_sb_puts(&b, k == 0 ? "" : k == s->nparams - 1 ? " and " : ", ");
      bg_sb_puts(&b, "<i>"), rp_esc(&b, s->params[k].name), bg_sb_puts(&b, "</i> over ");
      rp_esc(&b, s->params[k].spec);
      bg_sb_printf(&b, " (%d value%s)", s->params[k].nvalues, s->params[k].nvalues == 1 ? "" : "s");
    }
    bg_sb_printf(&b, ": %ld runs%s", st->nruns, s->nparams > 1 ? ", the first param varying slowest" : "");
  } else {
    bg_sb_printf(&b, "A Monte Carlo study of %ld runs, seed %llu: ", st->nruns, (unsigned long long)s->seed);
    for (int k = 0; k < s->nparams; k++) {
      bg_sb_puts(&b, k == 0 ? "" : k == s->nparams - 1 ? " and " : ", ");
      bg_sb_puts(&b, "<i>"), rp_esc(&b, s->params[k].name), bg_sb_puts(&b, "</i> drawn from ");
      rp_esc(&b, s->params[k].spec);
    }
  }
  if (st->count != st->nruns) bg_sb_printf(&b, " (runs %ld to %ld here)", st->first, st->first + st->count - 1);
  bg_sb_printf(&b, "; %ld %s. Each run is the model with the run's values in place of the params' "
               "own (as --set gives them); the other sections show the model at its own values.",
               st->nfailed, st->nfailed == 1 ? "run failed" : "runs failed");
  para(c, bg_sb_str(&b));
  bg_sb_free(&b);
}

static void summary_table(rp_ctx *c, const bg_study *st) {
  const bg_study_spec *s = st->spec;
  int nq = st->ncollect < MAX_QUANTITIES ? st->ncollect : MAX_QUANTITIES, reasons = st->nfailed > 0;
  int ncol = 2 + s->nparams + nq + reasons;
  const char **head = bg_xcalloc((size_t)ncol, sizeof *head);
  char *align = bg_xcalloc((size_t)ncol + 1, 1);
  bg_strbuf h = {0};
  int col = 0;
  head[col] = "Run", align[col++] = 'r';
  for (int k = 0; k < s->nparams; k++) head[col] = s->params[k].name, align[col++] = 'r';
  head[col] = "Status", align[col++] = 'l';
  for (int k = 0; k < nq; k++) head[col] = st->collect[k].label, align[col++] = 'r';
  if (reasons) head[col] = "Reason", align[col++] = 'l';
  /* the headers are markup: names escaped into one buffer, then pointed at */
  size_t *at = bg_xcalloc((size_t)ncol, sizeof *at);
  for (int k = 0; k < ncol; k++) at[k] = h.len, rp_esc(&h, head[k]), bg_sb_putc(&h, '\0');
  for (int k = 0; k < ncol; k++) head[k] = h.s + at[k];
  rp_table t;
  rp_table_init(&t, ncol, head, align);
  long rows = st->count < MAX_ROWS ? st->count : MAX_ROWS;
  for (long i = 0; i < rows; i++) {
    const bg_study_run *r = &st->runs[i];
    bg_strbuf b = {0};
    rp_table_cell(&t, "%ld", st->first + i);
    for (int k = 0; k < s->nparams; k++) bg_sb_clear(&b), rp_num(&b, r->param[k]), rp_table_cell(&t, "%s", bg_sb_str(&b));
    rp_table_text(&t, bg_study_status_name(r->status));
    for (int k = 0; k < nq; k++) {
      bg_sb_clear(&b);
      if (isfinite(r->value[k])) rp_num(&b, r->value[k]);
      else bg_sb_puts(&b, "\u2013");
      rp_table_cell(&t, "%s", bg_sb_str(&b));
    }
    if (reasons) rp_table_text(&t, r->reason ? r->reason : "");
    bg_sb_free(&b);
  }
  rp_table_emit(&c->body, &t);
  free(head), free(align), free(at), bg_sb_free(&h);
  bg_strbuf b = {0};
  if (st->count > rows) bg_sb_printf(&b, "%ld more runs in the study's table. ", st->count - rows);
  if (st->ncollect > nq) bg_sb_printf(&b, "%d more quantities in the study's table. ", st->ncollect - nq);
  if (b.len) bg_sb_puts(&b, "(--study FILE.csv or .json writes it whole.)"), para(c, bg_sb_str(&b));
  bg_sb_free(&b);
}

/* Plot kind of the study, placed at the page width and kept until the PDF
 * is written; nothing when the study has nothing for it. */
static void place(rp_ctx *c, int kind, const char *title) {
  const bg_study *st = c->in->study;
  bg_scene *s = bg_xcalloc(1, sizeof *s);
  bg_scene_init(s, c->st.font);
  char why[200];
  if (c->nstudy_plot == 4 ||
      bg_study_plot_scene(st, kind, c->in->bode, &c->st, rp_content_w(&c->body), s, why, sizeof why)) {
    bg_scene_free(s), free(s);
    return;
  }
  s->background.a = 0;
  c->study_plot[c->nstudy_plot++] = s;
  rp_figure(&c->body, s, title);
}

void rp_sec_study(rp_ctx *c) {
  const bg_study *st = c->in->study;
  if (!st) return;
  rp_section(&c->body, "Parameter study", 1, 0, 80);
  describe(c, st);
  rp_subsection(&c->body, "Runs and collected quantities", 30);
  summary_table(c, st);
  int curves = 0, poles = 0;
  for (long i = 0; i < st->count; i++) curves |= st->runs[i].nrows > 0, poles |= st->runs[i].npole > 0;
  int mc = st->spec->kind == BG_STUDY_MONTE_CARLO;
  if (curves) place(c, BG_STUDY_PLOT_FAMILY, mc ? "Monte Carlo envelope" : "Family of runs");
  if (!mc && st->count == st->nruns) {
    bg_strbuf b = {0};
    bg_sb_puts(&b, "Collected quantities against "), bg_sb_puts(&b, st->spec->params[0].name);
    place(c, BG_STUDY_PLOT_QUANTITIES, bg_sb_str(&b));
    bg_sb_free(&b);
  }
  if (poles) place(c, BG_STUDY_PLOT_LOCUS, "Root locus");
  if (c->in->bode && c->in->bode->nrun) place(c, BG_STUDY_PLOT_BODE, "Bode family");
}
