/* SPDX-License-Identifier: BSD-3-Clause */
/* Report section 11 (with --transform): what the transformation changed and
 * why (the new file's header comment), the analysis before and after side by
 * side, and the bond graph before and after, each drawn with the default
 * layers so that strokes, numbers and conflicts can be compared. */
#include <stdio.h>

#include "diagram/diagram_int.h"
#include "report/report_int.h"

static void count_row(rp_cmp_fn fn, void *ctx, const char *what, int before, int after) {
  char a[16], b[16];
  snprintf(a, sizeof a, "%d", before);
  snprintf(b, sizeof b, "%d", after);
  fn(ctx, what, a, b);
}

static int count_class(const bg_analysis *a, int cls) {
  int n = 0;
  for (int p = 0; p < a->npath; p++) n += a->path_class[p] == cls;
  return n;
}

static const char *form_word(const bg_analysis *a) {
  return a->form == BG_FORM_ODE ? "ODE" : a->form == BG_FORM_DAE ? "DAE" : "incomplete";
}

static void index_word(const bg_analysis *a, char *buf, size_t n) {
  if (a->index_predicted < 0) snprintf(buf, n, "unknown");
  else if (a->index_predicted >= 2) snprintf(buf, n, "above 1");
  else snprintf(buf, n, "%d", a->index_predicted);
}

void rp_transform_rows(const bg_analysis *a, const bg_analysis *b, rp_cmp_fn fn, void *ctx) {
  count_row(fn, ctx, "states", a->nstates, b->nstates);
  count_row(fn, ctx, "dependent stores", a->ndependent, b->ndependent);
  count_row(fn, ctx, "class 1 causal paths", count_class(a, 1), count_class(b, 1));
  count_row(fn, ctx, "class 2 causal paths", count_class(a, 2), count_class(b, 2));
  count_row(fn, ctx, "causal loops", a->ncloop, b->ncloop);
  count_row(fn, ctx, "conflicts", a->nconflict, b->nconflict);
  fn(ctx, "form", form_word(a), form_word(b));
  char ia[32], ib[32];
  index_word(a, ia, sizeof ia);
  index_word(b, ib, sizeof ib);
  fn(ctx, "predicted index", ia, ib);
}

static void table_row(void *ctx, const char *what, const char *before, const char *after) {
  rp_table_text(ctx, what);
  rp_table_text(ctx, before);
  rp_table_text(ctx, after);
}

static void compare(rp_ctx *c, const bg_analysis *a, const bg_analysis *b) {
  static const char *const head[] = {"", "before", "after"};
  rp_table t;
  rp_table_init(&t, 3, head, "lrr");
  rp_transform_rows(a, b, table_row, &t);
  rp_table_emit(&c->body, &t);
}

/* One diagram with the default layers, scaled into the width and at most h high. */
static void drawing(rp_ctx *c, const char *title, const bg_model *m, const bg_analysis *a, double h) {
  bg_render_opts o = {0};
  if (c->in->ropts) o = *c->in->ropts;
  o.show = BG_SHOW_DEFAULT, o.highlight_kind = 0, o.highlight_index = 0;
  bg_diagram *dg = rp_keep(c, bg_diagram_build(m, a, &o, c->dg));
  if (!dg) return;
  rp_doc *d = &c->body;
  const bg_scene *s = &dg->scene;
  double cw = rp_content_w(d), sc = cw / s->width;
  if (s->height * sc > h) sc = h / s->height;
  if (sc > 1.25) sc = 1.25;
  rp_subsection(d, title, s->height * sc + 8);
  rp_place(d, s, 0, 0, s->width, s->height, rp_left() + (cw - s->width * sc) / 2, d->y, sc);
  d->y += s->height * sc + 6;
}

void rp_sec_transform(rp_ctx *c) {
  const bg_transform_result *tx = c->in->tx;
  if (!tx) return;
  rp_doc *d = &c->body;
  rp_section(d, "Transformation", 1, 1, 80);
  bg_strbuf b = {0};
  bg_sb_printf(&b, "<tt>--transform %s</tt> wrote a new model. ", c->in->tx_name);
  rp_esc(&b, tx->summary);
  rp_para(d, bg_sb_str(&b), RP_SIZE_BODY, 0, 0, rp_ink);
  bg_sb_free(&b);
  rp_gap(d, 6);
  compare(c, c->a, &tx->run->analysis);
  rp_gap(d, 6);
  /* both drawings below the table when each gets 150 points there, else on a new page */
  double h = (rp_room(d) - 90) / 2;
  if (h < 150) h = (rp_page_room(d) - 90) / 2;
  drawing(c, "Before", c->m, c->a, h);
  drawing(c, "After", tx->run->model, &tx->run->analysis, h);
}
