/* SPDX-License-Identifier: BSD-3-Clause */
/* Report section 1: the title page with the verdict and the summary, then
 * the contents with page numbers (filled in once the front pages are
 * counted). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "report/report_int.h"
#include "analysis/analysis.h"

/* ---------------------------------------------------------------- verdict */
static int numeric_index(const rp_ctx *c) {
  const bg_index_result *r = c->in->index;
  if (r && (r->index >= 0 || r->index == BG_INDEX_SINGULAR)) return r->index;
  return BG_INDEX_FAILED;
}

/* The first sentence of s, without a leading "predicted index above 1: ". */
static void first_sentence(bg_strbuf *out, const char *s) {
  const char *pre = "predicted index above 1: ";
  if (!strncmp(s, pre, strlen(pre))) s += strlen(pre);
  const char *end = strstr(s, ". ");
  size_t n = end ? (size_t)(end - s) : strlen(s);
  if (n > 0 && s[n - 1] == '.') n--;
  bg_sb_putn(out, s, n);
}

static int starts(const char *s, const char *prefix) { return s && !strncmp(s, prefix, strlen(prefix)); }

/* "two algebraic loops between resistors and one dependent store" */
static int index1_causes(const rp_ctx *c, bg_strbuf *out) {
  const bg_analysis *a = c->a;
  int c2 = 0, c4 = 0, im = 0, n = 0;
  for (int p = 0; p < a->npath; p++) c2 += a->path_class[p] == 2;
  for (int k = 0; k < a->ncloop; k++) c4 += a->cloop_class[k] == 4;
  for (int l = 0; l < a->ntloop; l++)
    im += a->tloop_algebraic[l] && starts(a->tloop_cause ? a->tloop_cause[l] : NULL, "internal modulation");
  const char *sep[] = {"", " and ", ", "};
  struct { int k; const char *one, *many; } part[] = {
      {c2, "algebraic loop between resistors", "algebraic loops between resistors"},
      {a->ndependent, "dependent store", "dependent stores"},
      {c4, "causal loop with a gain other than +1", "causal loops with gains other than +1"},
      {im, "algebraic loop from internal modulation", "algebraic loops from internal modulation"},
      {a->nconflict, "causal conflict", "causal conflicts"}};
  int total = 0;
  for (size_t i = 0; i < sizeof part / sizeof part[0]; i++) total += part[i].k > 0;
  for (size_t i = 0; i < sizeof part / sizeof part[0]; i++) {
    if (!part[i].k) continue;
    bg_sb_printf(out, "%s%s %s", n == 0 ? "" : n == total - 1 ? sep[1] : sep[2],
                 rp_count_word(part[i].k), part[i].k == 1 ? part[i].one : part[i].many);
    n++;
  }
  return n;
}

static void sim_clause(const rp_ctx *c, bg_strbuf *out, int said_refusal) {
  const bg_report_input *in = c->in;
  const bg_simresult *r = in->sim;
  if (!c->m->sim.present || !r) return;
  if (in->sim_status == 0)
    bg_sb_printf(out, "; simulated to t = %g s with %s in %ld steps", c->m->sim.t_end,
                 r->solver_used ? r->solver_used : "?", r->steps);
  else if (in->sim_status == 1 && !said_refusal && r->message)
    bg_sb_puts(out, "; simulation refused: "), first_sentence(out, r->message);
  else if (in->sim_status == 2)
    bg_sb_printf(out, "; the simulation failed at t = %.6g s", r->t_reached);
}

/* The one-sentence verdict, plain text. */
void rp_verdict(const rp_ctx *c, bg_strbuf *out) {
  const bg_analysis *a = c->a;
  const bg_report_input *in = c->in;
  if (!a->complete || a->form == BG_FORM_INCOMPLETE) {
    int n = 0;
    for (int b = 0; b < c->m->nbond; b++) n += a->bond_stroke[b] == BG_STROKE_NONE;
    bg_sb_printf(out, "Causality incomplete: %s without a stroke, so there are no equations and no index.",
                 n == 1 ? "one bond" : "bonds");
    return;
  }
  int idx = numeric_index(c);
  if (idx == BG_INDEX_FAILED) idx = a->index_predicted; /* 2 means "above 1" */
  /* a model without a simulate block has no simulation to refuse (as in
   * sim_clause): the library, asked for its CSV first, said "refused" in
   * the report where the command line described the index reduction */
  int refused = c->m->sim.present && in->sim && in->sim_status == 1 && in->sim->message;
  if (idx == BG_INDEX_SINGULAR) {
    bg_sb_puts(out, "Singular: the linearised equations have no unique solution (singular pencil)");
  } else if (idx == 0 && a->form == BG_FORM_ODE) {
    bg_sb_printf(out, "Explicit ODE of order %d", a->nstates);
  } else if (idx <= 1 && idx >= 0) {
    bg_sb_printf(out, "Index-%d DAE with %d state%s", idx, a->nstates, a->nstates == 1 ? "" : "s");
    bg_strbuf causes = {0};
    if (index1_causes(c, &causes)) bg_sb_printf(out, ": %s", bg_sb_str(&causes));
    bg_sb_free(&causes);
    if (c->in->facts->reduced_form && !strcmp(c->in->facts->reduced_form, "ode"))
      bg_sb_puts(out, " (an explicit ODE after symbolic elimination)");
  } else if (idx >= 2) {
    if (numeric_index(c) >= 2) bg_sb_printf(out, "Index-%d DAE", idx);
    else bg_sb_puts(out, "DAE of index above 1");
    if (refused) bg_sb_puts(out, ": simulation refused because "), first_sentence(out, in->sim->message);
    else if (c->in->facts->reduction && c->in->facts->reduction->status > 0)
      bg_sb_printf(out, ", reduced to index %d by differentiating %d constraint%s (Pantelides, dummy "
                        "derivatives)", c->in->facts->reduction->index, c->in->facts->reduction->nconstraint,
                   c->in->facts->reduction->nconstraint == 1 ? "" : "s");
    else if (a->index_reason) bg_sb_puts(out, ": "), first_sentence(out, a->index_reason);
    sim_clause(c, out, refused);
    bg_sb_puts(out, ".");
    return;
  } else {
    bg_sb_printf(out, "%s form, index unknown", bg_form_name(a->form));
  }
  sim_clause(c, out, 0);
  bg_sb_puts(out, ".");
}

/* "ode", "DAE", index words. */
static void index_text(const rp_ctx *c, bg_strbuf *out) {
  const bg_report_input *in = c->in;
  if (in->index && in->index->index >= 0) bg_sb_printf(out, "%d", in->index->index);
  else if (in->index && in->index->index == BG_INDEX_SINGULAR) bg_sb_puts(out, "singular pencil");
  else bg_sb_puts(out, "not computed");
  if (in->index && in->index->message) bg_sb_printf(out, " (%s)", in->index->message);
  else if (!in->index && (in->index_skipped || in->eqs_problem))
    bg_sb_printf(out, " (%s)", in->index_skipped ? in->index_skipped : in->eqs_problem);
}

/* ---------------------------------------------------------------- summary table */
static void row(void *ctx, const char *key, const char *plain) {
  rp_table *t = ctx;
  rp_table_cell(t, "%s", key);
  rp_table_text(t, plain);
}

static void names(bg_strbuf *b, char **v, int n) {
  if (n == 0) bg_sb_puts(b, "none");
  for (int i = 0; i < n && i < 30; i++) bg_sb_printf(b, "%s%s", i ? ", " : "", v[i]);
  if (n > 30) bg_sb_printf(b, ", ... (%d in all)", n);
}

static void counts_row(const rp_ctx *c, rp_row_fn row, void *t) {
  const bg_analysis *a = c->a;
  int c1 = 0, c2 = 0, alg = 0;
  for (int p = 0; p < a->npath; p++) c1 += a->path_class[p] == 1, c2 += a->path_class[p] == 2;
  for (int l = 0; l < a->ntloop; l++) alg += a->tloop_algebraic[l] != 0;
  bg_strbuf b = {0};
  rp_count(&b, a->npath + a->npath_omitted, "causal path");
  bg_sb_printf(&b, " (class 1: %d, class 2: %d), ", c1, c2);
  rp_count(&b, a->ncloop + a->ncloop_omitted, "causal loop");
  bg_sb_puts(&b, ", ");
  rp_count(&b, a->ntloop + a->ntloop_omitted, "topological loop");
  bg_sb_printf(&b, " (%d algebraic), ", alg);
  rp_count(&b, a->nconflict, "conflict");
  row(t, "Analysis", bg_sb_str(&b));
  bg_sb_free(&b);
}

static void sim_row(const rp_ctx *c, rp_row_fn row, void *t) {
  const bg_report_input *in = c->in;
  bg_strbuf b = {0};
  if (!c->m->sim.present) bg_sb_puts(&b, "no simulate block");
  else if (!in->sim) bg_sb_puts(&b, "not run");
  else if (in->sim_status == 0)
    bg_sb_printf(&b, "%s, t = %g to %g s, %d rows, %ld steps", in->sim->solver_used ? in->sim->solver_used : "?",
                 c->m->sim.t0, c->m->sim.t_end, in->sim->nrows, in->sim->steps);
  else if (in->sim_status == 1) bg_sb_puts(&b, "refused (section Simulation says why)");
  else bg_sb_printf(&b, "failed at t = %.6g s (partial results)", in->sim->t_reached);
  row(t, "Simulation", bg_sb_str(&b));
  bg_sb_free(&b);
}

void rp_summary_rows(const rp_ctx *c, rp_row_fn row, void *t) {
  const bg_model *m = c->m;
  const bg_analysis *a = c->a;
  bg_strbuf b = {0};
  bg_model_summary(m, &b);
  row(t, "Model", bg_sb_str(&b));
  bg_sb_clear(&b);
  bg_sb_printf(&b, "%s%s", bg_method_name(a->method), a->complete ? "" : " (incomplete)");
  row(t, "Causality", bg_sb_str(&b));
  bg_sb_clear(&b);
  bg_sb_printf(&b, "%d: ", a->nstates), names(&b, a->states, a->nstates);
  row(t, "States", bg_sb_str(&b));
  bg_sb_clear(&b);
  names(&b, a->dependent_stores, a->ndependent);
  row(t, "Dependent stores", bg_sb_str(&b));
  counts_row(c, row, t);
  bg_sb_clear(&b);
  bg_sb_puts(&b, bg_form_name(a->form));
  if (c->in->facts->reduced_form)
    bg_sb_printf(&b, " (after elimination: %s)", c->in->facts->reduced_form);
  else if (c->in->facts->reduced_note) bg_sb_puts(&b, " (symbolic elimination skipped: work budget)");
  row(t, "Form", bg_sb_str(&b));
  bg_sb_clear(&b);
  if (a->index_predicted < 0) bg_sb_puts(&b, "unknown");
  else if (a->index_predicted >= 2) bg_sb_puts(&b, "above 1");
  else bg_sb_printf(&b, "%d", a->index_predicted);
  if (a->index_reason) bg_sb_printf(&b, " (%s)", a->index_reason);
  row(t, "Predicted index", bg_sb_str(&b));
  bg_sb_clear(&b);
  index_text(c, &b);
  row(t, "Numeric index", bg_sb_str(&b));
  bg_sb_free(&b);
  sim_row(c, row, t);
}

static void summary_table(const rp_ctx *c, rp_doc *d) {
  static const char *head[] = {"Summary", ""};
  rp_table t;
  rp_table_init(&t, 2, head, "ll");
  t.size = RP_SIZE_BODY;
  rp_summary_rows(c, row, &t);
  rp_table_emit(d, &t);
}

/* ---------------------------------------------------------------- title */
/* The model's path as the report shows it: relative to the current
 * directory, else only its file name, so a report built in CI does not
 * carry the build machine's folders (and reruns elsewhere are identical). */
static const char *shown_path(const char *path, char *buf, size_t n) {
  if (path[0] != '/') return path;
  char cwd[4096];
  size_t k = getcwd(cwd, sizeof cwd) ? strlen(cwd) : 0;
  if (k > 1 && !strncmp(path, cwd, k) && path[k] == '/') return path + k + 1;
  const char *base = strrchr(path, '/');
  snprintf(buf, n, "%s", base + 1);
  return buf;
}

static void title_block(const rp_ctx *c, rp_doc *d) {
  const bg_model *m = c->m;
  rp_text(d, "bgdraw analysis report", rp_left(), d->y, RP_SIZE_H2, 0, rp_grey);
  d->y += 24;
  bg_strbuf b = {0};
  bg_sb_puts(&b, "<b>");
  rp_esc(&b, m->title ? m->title : m->name);
  bg_sb_puts(&b, "</b>");
  rp_para(d, bg_sb_str(&b), RP_SIZE_TITLE, 0, 0, rp_accent);
  d->y += 4;
  bg_sb_clear(&b);
  bg_sb_puts(&b, "Model <b>");
  rp_esc(&b, m->name);
  bg_sb_puts(&b, "</b>");
  char buf[4096];
  if (m->path)
    bg_sb_puts(&b, " from <tt>"), rp_esc(&b, shown_path(m->path, buf, sizeof buf)),
        bg_sb_puts(&b, "</tt>");
  d->y += 4;
  rp_para(d, bg_sb_str(&b), RP_SIZE_BODY + 1, 0, 0, rp_ink);
  bg_sb_free(&b);
  d->y += 14;
}

static void verdict_box(const rp_ctx *c, rp_doc *d) {
  bg_strbuf v = {0}, mk = {0};
  rp_verdict(c, &v);
  rp_esc(&mk, bg_sb_str(&v));
  double size = RP_SIZE_H2, pad = 10, w = rp_content_w(d) - 2 * pad;
  rp_lines l;
  rp_wrap(d->font, size, bg_sb_str(&mk), w, w, &l);
  double lh = rp_line_height(d->font, size);
  rp_outline(d, "1  Summary", 0, d->y);
  rp_fill_rect(rp_scene(d), rp_left(), d->y, rp_content_w(d), l.n * lh + 2 * pad,
               (bg_rgba){0.90, 0.93, 0.98, 1}, "verdict");
  rp_fill_rect(rp_scene(d), rp_left(), d->y, 3, l.n * lh + 2 * pad, rp_accent, "verdict-bar");
  for (int i = 0; i < l.n; i++) rp_text(d, l.line[i], rp_left() + pad, d->y + pad + i * lh, size, 0, rp_ink);
  d->y += l.n * lh + 2 * pad + 16;
  rp_lines_free(&l);
  bg_sb_free(&v);
  bg_sb_free(&mk);
}

/* ---------------------------------------------------------------- contents */
typedef struct centry {
  int page;  /* front page the line is on */
  double y;
  int head;  /* body heading */
} centry;

static void contents(const rp_ctx *c, rp_doc *d) {
  const rp_doc *body = &c->body;
  double size = RP_SIZE_BODY, lh = rp_line_height(d->font, size) + 2.5, all = 0, top = 0;
  for (int i = 0; i < body->nhead; i++) {
    all += lh + (body->head[i].level == 0 ? 2 : 0);
    top += body->head[i].level == 0 ? lh + 2 : 0;
  }
  /* on the title page when it fits there whole, or with the sections only
   * (the PDF outline has the rest); else on pages of its own */
  double room = rp_room(d) - 50;
  int maxlevel = all <= room ? 1 : top <= room ? 0 : 1;
  rp_section(d, "Contents", 0, all > room && top > room, 3 * lh);
  centry *e = bg_xmalloc(((size_t)body->nhead + 1) * sizeof *e);
  int ne = 0;
  for (int i = 0; i < body->nhead; i++) {
    const rp_head *h = &body->head[i];
    if (h->level > maxlevel) continue;
    rp_need(d, lh);
    bg_strbuf b = {0};
    bg_sb_puts(&b, h->level == 0 ? "<b>" : "");
    rp_esc(&b, h->title);
    bg_sb_puts(&b, h->level == 0 ? "</b>" : "");
    double x = rp_left() + (h->level ? 18 : 0);
    double tw = rp_text(d, bg_sb_str(&b), x, d->y, size, 0, rp_ink)->tw; /* the item moves */
    double right = rp_left() + rp_content_w(d) - 30;
    if (x + tw + 6 < right) {
      bg_scene_item *dots = bg_scene_begin(rp_scene(d), BG_ITEM_STROKE, "leader");
      dots->color = rp_rule, dots->width = 0.8, dots->round = 1;
      dots->dash[0] = 0.01, dots->dash[1] = 3.5;
      bg_scene_move(rp_scene(d), x + tw + 6, d->y + 0.75 * lh);
      bg_scene_line(rp_scene(d), right, d->y + 0.75 * lh);
    }
    e[ne++] = (centry){d->npage - 1, d->y, i};
    d->y += lh + (h->level == 0 ? 2 : 0);
    bg_sb_free(&b);
  }
  /* page numbers: the front is complete, so body pages are known */
  for (int i = 0; i < ne; i++) {
    char num[16];
    snprintf(num, sizeof num, "%d", d->npage + body->head[e[i].head].page + 1);
    bg_scene_text(&d->page[e[i].page]->sc, num, rp_left() + rp_content_w(d), e[i].y, size, 1, 0,
                  rp_ink, "contents-page");
  }
  free(e);
}

void rp_front(rp_ctx *c, rp_doc *front) {
  rp_new_page(front, 0);
  front->y = 80;
  title_block(c, front);
  verdict_box(c, front);
  summary_table(c, front);
  rp_gap(front, 10);
  contents(c, front);
}
