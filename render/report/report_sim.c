/* SPDX-License-Identifier: BSD-3-Clause */
/* Report section 9: the simulation plots and the solver's statistics, or
 * the reason there is no simulation. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot.h"
#include "report/report_int.h"

static void para(rp_ctx *c, const char *markup) {
  rp_para(&c->body, markup, RP_SIZE_BODY, 0, 0, rp_ink);
  rp_gap(&c->body, 3);
}

static void row(rp_row_fn fn, void *ctx, const char *key, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static void row(rp_row_fn fn, void *ctx, const char *key, const char *fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  fn(ctx, key, buf);
}

static void table_row(void *ctx, const char *key, const char *plain) {
  rp_table_cell(ctx, "%s", key);
  rp_table_text(ctx, plain);
}

void rp_sim_stat_rows(const rp_ctx *c, const bg_simresult *r, rp_row_fn fn, void *ctx) {
  const bg_simspec *sp = &c->m->sim;
  int fp = r->linear_solver && !strcmp(r->linear_solver, "none");
  row(fn, ctx, "Solver", "%s%s%s", r->solver_used ? r->solver_used : "none",
      fp ? ", fixed-point iteration (no Jacobian)" : r->linear_solver ? ", linear algebra " : "",
      !fp && r->linear_solver ? r->linear_solver : "");
  if (r->solver_reason) row(fn, ctx, "Why this solver", "%s", r->solver_reason);
  row(fn, ctx, "Time span", "%g to %g s%s", sp->t0, sp->t_end, r->partial ? " (stopped early)" : "");
  if (r->partial) row(fn, ctx, "Time reached", "%.8g s", r->t_reached);
  row(fn, ctx, "Output rows", "%d", r->nrows);
  if (r->rtol > 0) row(fn, ctx, "Tolerances", "rtol %g, atol %g", r->rtol, r->atol);
  row(fn, ctx, "Steps", "%ld", r->steps);
  row(fn, ctx, "Function evaluations", "%ld", r->rhs_evals);
  row(fn, ctx, "Jacobian evaluations", "%ld", r->jac_evals);
  row(fn, ctx, "Error test failures", "%ld", r->err_test_fails);
  row(fn, ctx, "Nonlinear iterations", "%ld", r->nonlin_iters);
  if (r->ic_report && *r->ic_report) row(fn, ctx, "Initial values changed", "%s", r->ic_report);
  if (r->ic_retries) row(fn, ctx, "Initial guesses retried", "%d", r->ic_retries);
  if (r->max_step > 0) row(fn, ctx, "Largest step allowed", "%g s", r->max_step);
  if (r->nconditions)
    row(fn, ctx, "State events", "%d at %d switching condition%s%s", r->nevents, r->nconditions,
        r->nconditions == 1 ? "" : "s", r->events_searched ? "" : " (not searched)");
  if (r->rows_redone) row(fn, ctx, "Intervals integrated again", "%d (an output row violated the algebraic equations)", r->rows_redone);
  bg_strbuf w = {0};
  if (bg_simresult_row_warning(r, &w)) row(fn, ctx, "Warning", "%s", bg_sb_str(&w));
  bg_sb_clear(&w);
  if (bg_sim_verify_text(r, &w)) row(fn, ctx, "Verification", "%s", bg_sb_str(&w));
  bg_sb_free(&w);
}

static void stats(rp_ctx *c, const bg_simresult *r) {
  static const char *head[] = {"Solver statistics", ""};
  rp_table t;
  rp_table_init(&t, 2, head, "ll");
  rp_sim_stat_rows(c, r, table_row, &t);
  rp_table_emit(&c->body, &t);
}

/* The first state events: time, condition, direction (the JSON has all). */
#define RP_EVENTS_SHOWN 12
static void events(rp_ctx *c, const bg_simresult *r) {
  if (r->nevents <= 0) return;
  static const char *head[] = {"t [s]", "Condition", "Switching function"};
  rp_table t;
  rp_table_init(&t, 3, head, "rll");
  for (int k = 0; k < r->nevents && k < RP_EVENTS_SHOWN; k++) {
    rp_table_cell(&t, "%.10g", r->event_t[k]);
    rp_table_text(&t, r->condition_text[r->event_cond[k]]);
    rp_table_text(&t, r->event_dir[k] > 0 ? "rising" : "falling");
  }
  rp_subsection(&c->body, "State events", 60);
  rp_table_emit(&c->body, &t);
  if (r->nevents > RP_EVENTS_SHOWN) {
    char buf[120];
    snprintf(buf, sizeof buf, "and %d more (the JSON lists them all).", r->nevents - RP_EVENTS_SHOWN);
    para(c, buf);
  }
}

/* The plots' scene (kept in c until the PDF is written) and its scale on a
 * page; NULL when there is nothing to plot. */
static const bg_scene *plot_scene(rp_ctx *c, const bg_simresult *r, double *scale) {
  if (!r || r->nrows < 1 || r->nout < 1) return NULL;
  rp_doc *d = &c->body;
  bg_scene *s = bg_xcalloc(1, sizeof *s);
  bg_scene_init(s, c->st.font);
  bg_plot_scene(c->m, r, &c->st, rp_content_w(d), 0, s);
  s->background.a = 0;
  c->plot = s;
  double room = rp_page_room(d) - 30;
  *scale = rp_content_w(d) / s->width;
  if (s->height * *scale > room) *scale = room / s->height;
  return s;
}

static void plots(rp_ctx *c, const bg_simresult *r, const bg_scene *s, double sc) {
  if (!s) return;
  rp_doc *d = &c->body;
  double w = s->width, h = s->height;
  rp_subsection(d, r->partial ? "Plots (partial results)" : "Plots", h * sc);
  rp_place(d, s, 0, 0, w, h, rp_left() + (rp_content_w(d) - w * sc) / 2, d->y, sc);
  d->y += h * sc + 8;
}

void rp_sec_simulation(rp_ctx *c) {
  const bg_report_input *in = c->in;
  const bg_simresult *r = in->sim;
  double sc = 1;
  const bg_scene *ps = in->sim_status != 1 ? plot_scene(c, r, &sc) : NULL;
  double keep = ps ? ps->height * sc + 60 : 80;
  if (keep > rp_page_room(&c->body) - 40) keep = rp_page_room(&c->body) - 40;
  rp_section(&c->body, "Simulation", 1, 0, keep);
  if (!c->m->sim.present) {
    para(c, "The model has no <tt>simulate</tt> block, so there is nothing to plot. Add one, e.g. "
            "<tt>simulate t_end = 1, dt = 0.01</tt>, and the report shows the plots here.");
    return;
  }
  if (!r) {
    para(c, "The simulation was not run.");
    return;
  }
  bg_strbuf b = {0};
  if (in->sim_status == 1) {
    bg_sb_puts(&b, "<b>Simulation refused</b> (no solver was called). ");
    const char *why = r->message ? r->message : in->eqs_problem ? in->eqs_problem : "no reason given";
    size_t at = b.len;
    rp_esc(&b, why);
    if (b.s[at] >= 'a' && b.s[at] <= 'z') b.s[at] = (char)(b.s[at] - 'a' + 'A');
    para(c, bg_sb_str(&b));
    bg_sb_free(&b);
    return;
  }
  if (in->sim_status == 2) {
    const char *msg = r->message ? r->message : "no reason given", *pre = "simulation failed";
    int same = !strncmp(msg, pre, strlen(pre));
    bg_sb_puts(&b, same ? "<b>Simulation failed</b>" : "<b>Simulation failed</b>: ");
    rp_esc(&b, same ? msg + strlen(pre) : msg);
    bg_sb_puts(&b, r->nrows ? " The plots show the results up to the time reached." : "");
    para(c, bg_sb_str(&b));
  } else {
    bg_sb_printf(&b, "From t = %g to %g s with <b>%s</b>: %d output rows.", c->m->sim.t0,
                 c->m->sim.t_end, r->solver_used ? r->solver_used : "?", r->nrows);
    para(c, bg_sb_str(&b));
  }
  bg_sb_free(&b);
  plots(c, r, ps, sc);
  stats(c, r);
  events(c, r);
}
