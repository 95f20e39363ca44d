/* SPDX-License-Identifier: BSD-3-Clause */
/* --report FILE.pdf: the multi-page A4 analysis report. The body (sections
 * 2 to 9) is laid out first, then the title page with the summary and the
 * contents, whose page numbers are known by then; pages get their running
 * header and footer and go to one PDF with outlines. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"
#include "base/fileio.h"
#include "report/report_int.h"

static void progress(const rp_ctx *c, const char *what) { rp_progress(c, "%s", what); }

static void body(rp_ctx *c) {
  c->body.section = 1; /* 1 is the summary on the title page */
  progress(c, "diagram");
  rp_sec_diagram(c);
  if (c->failed) return;
  progress(c, "highlighted diagrams");
  rp_sec_highlights(c);
  if (c->failed) return;
  progress(c, "trace, tables, index");
  rp_sec_components(c);
  rp_sec_fields(c);
  rp_sec_trace(c);
  rp_sec_tables(c);
  rp_sec_index(c);
  progress(c, "equations");
  rp_sec_equations(c);
  rp_sec_estimates(c);
  progress(c, "simulation");
  rp_sec_simulation(c);
  if (c->in->lin) progress(c, "linear analysis");
  rp_sec_linear(c);
  if (c->in->study) progress(c, "parameter study");
  rp_sec_study(c);
  if (c->in->tx) progress(c, "transformation");
  rp_sec_transform(c);
}

static void free_ctx(rp_ctx *c) {
  for (int i = 0; i < c->ndiag; i++) bg_diagram_free(c->diag[i]);
  free(c->diag);
  for (int i = 0; i < c->nhl; i++) bg_scene_free(c->hl[i]), free(c->hl[i]);
  free(c->hl);
  if (c->plot) bg_scene_free(c->plot), free(c->plot);
  for (int i = 0; i < c->nlin_plot; i++) bg_scene_free(c->lin_plot[i]), free(c->lin_plot[i]);
  for (int i = 0; i < c->nstudy_plot; i++) bg_scene_free(c->study_plot[i]), free(c->study_plot[i]);
  rp_doc_free(&c->body);
}

/* Front and body as one PDF in out; 0 or -1. */
static int assemble(rp_ctx *c, bg_strbuf *out) {
  rp_doc front;
  rp_doc_init(&front, c->st.font);
  rp_front(c, &front);
  int total = front.npage + c->body.npage;
  bg_strbuf head = {0};
  bg_sb_puts(&head, c->m->name);
  if (c->m->title) bg_sb_printf(&head, " \u2014 %s", c->m->title);
  bg_strbuf esc = {0};
  rp_esc(&esc, bg_sb_str(&head));
  rp_decorate(&front, bg_sb_str(&esc), 1, 0, total);
  rp_decorate(&c->body, bg_sb_str(&esc), 0, front.npage, total);
  rp_doc *docs[2] = {&front, &c->body};
  rp_progress(c, "writing %d pages", total);
  bg_sb_printf(&head, " \u2014 analysis report");
  int rc = rp_write_pdf(docs, 2, bg_sb_str(&head), out);
  bg_sb_free(&head);
  bg_sb_free(&esc);
  rp_doc_free(&front);
  return rc;
}

bg_report_input rp_input(const bg_run *r, const bg_report_opts *ro) {
  bg_report_input in = {r->model, &r->analysis, r->eqsys, r->eqsys_problem, &r->facts,
                        r->facts.numeric, r->facts.numeric_skipped,
                        bg_run_has(r, BG_STAGE_SIMULATION) ? &r->sim : NULL, r->sim_status,
                        ro ? ro->ropts : NULL, bg_run_has(r, BG_STAGE_LINEAR) ? &r->lin : NULL,
                        ro && ro->tx ? ro->tx_name : NULL, ro ? ro->tx : NULL,
                        ro ? ro->study : NULL, ro ? ro->bode : NULL};
  return in;
}

int bg_report_render(const bg_run *r, const bg_report_opts *ro, bg_strbuf *pdf, bg_diags *dg) {
  bg_report_input input = rp_input(r, ro);
  const bg_report_input *in = &input;
  rp_ctx c;
  memset(&c, 0, sizeof c);
  c.in = in, c.m = in->m, c.a = in->a, c.dg = dg;
  const bg_render_opts *o = in->ropts;
  if (bg_style_load(&c.st, o ? o->style : NULL, o ? o->style_dir : NULL, dg) != 0) return BG_RENDER_ERROR;
  rp_doc_init(&c.body, c.st.font);
  body(&c);
  if (c.failed) {
    free_ctx(&c);
    return BG_RENDER_ERROR;
  }
  int rc = BG_RENDER_OK;
  if (assemble(&c, pdf) != 0) {
    bg_diag_error(dg, (bg_srcloc){0}, "cairo could not draw the report");
    rc = BG_RENDER_ERROR;
  }
  free_ctx(&c);
  return rc;
}
