/* SPDX-License-Identifier: BSD-3-Clause */
/* HTML report sections with figures and formulas: the diagram as the inline
 * SVG the diagram stage writes (its classes and <title>s; layer toggles),
 * the equations as MathML (bg_eqprint_mathml: the LaTeX printer's symbolic
 * tree), the simulation plots as inline SVG with the data of their readout,
 * the solver statistics, the linear analysis and the transformation. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "html/html_int.h"
#include "plot/plot.h"
#include "plot/plot_linear.h"

#define HT_MAX_READOUT_ROWS 4000 /* rows of a plot's readout data; more are strided */

/* An SVG document as an inline element: the XML prolog dropped, attributes
 * (role, aria, id) added to <svg>. */
static void ht_inline_svg(ht_ctx *c, const char *svg, size_t n, const char *attrs) {
  const char *end = svg + n, *p = svg;
  while (p + 4 < end && strncmp(p, "<svg", 4) != 0) p++; /* past the XML prolog */
  if (p + 4 >= end) return;
  bg_sb_puts(c->out, "<svg ");
  bg_sb_puts(c->out, attrs);
  bg_sb_putn(c->out, p + 4, (size_t)(end - p - 4));
  if (n && end[-1] != '\n') bg_sb_putc(c->out, '\n');
}

static bg_render_opts render_opts(const ht_ctx *c, unsigned show) {
  bg_render_opts o = {0};
  if (c->in->ropts) o = *c->in->ropts;
  o.show = show, o.highlight_kind = 0, o.highlight_index = 0;
  return o;
}

/* One diagram as inline SVG into c->out; 0, or -1 with errors in dg. */
static int diagram_svg(ht_ctx *c, const bg_model *m, const bg_analysis *a, unsigned show, const char *attrs) {
  bg_render_opts o = render_opts(c, show);
  bg_diagram *d = bg_diagram_build(m, a, &o, c->dg);
  if (!d) return -1;
  bg_strbuf svg = {0};
  int rc = bg_diagram_render(d, "svg", &svg, c->dg);
  if (rc == BG_RENDER_OK) ht_inline_svg(c, svg.s, svg.len, attrs);
  bg_sb_free(&svg);
  bg_diagram_free(d);
  return rc == BG_RENDER_OK ? 0 : -1;
}

/* ---------------------------------------------------------------- diagram */
static const struct {
  const char *name, *label;
} layers[] = {{"strokes", "Causal strokes"}, {"numbers", "Bond numbers"}, {"paths", "Causal paths"},
              {"loops", "Loops"},           {"conflicts", "Conflicts"},  {"signals", "Signals"},
              {"labels", "Bond labels"},    {"legend", "Legend"}};

void ht_diagram(ht_ctx *c) {
  ht_section(c, "diagram", "Diagram");
  bg_sb_puts(c->out, "<p>Every layer drawn (as the PDF's section 2); the check boxes hide one. Each bond "
                     "and element says what it is when pointed at (its <code>title</code>).</p>\n"
                     "<fieldset class=\"layers\"><legend>Layers</legend>\n");
  for (size_t k = 0; k < sizeof layers / sizeof layers[0]; k++)
    bg_sb_printf(c->out, "<label><input type=\"checkbox\" checked=\"checked\" data-layer=\"%s\"/> %s</label>\n",
                 layers[k].name, layers[k].label);
  bg_sb_puts(c->out, "</fieldset>\n<figure class=\"diagram\" id=\"diagram-figure\">\n");
  bg_strbuf attrs = {0};
  bg_sb_puts(&attrs, "id=\"bg-diagram\" role=\"img\" aria-label=\"Bond graph of ");
  ht_esc(&attrs, c->m->name);
  bg_sb_puts(&attrs, " with its causal strokes, paths, loops and conflicts\"");
  if (diagram_svg(c, c->m, c->a, BG_SHOW_ALL, bg_sb_str(&attrs)) != 0) c->failed = 1;
  bg_sb_free(&attrs);
  bg_sb_puts(c->out, "<figcaption>The bond graph with every layer. Selected: <output id=\"selection\">"
                     "nothing</output></figcaption>\n</figure>\n");
  ht_section_end(c);
}

/* ---------------------------------------------------------------- equations */
void ht_equations(ht_ctx *c) {
  ht_section(c, "equations", "Equations");
  if (!c->in->eqs) {
    ht_para(c, "No equations: %s.", c->in->eqs_problem ? c->in->eqs_problem : "they were not derived");
    ht_section_end(c);
    return;
  }
  ht_para(c, "The equations as MathML (the symbolic tree the LaTeX printer reads), in computational order; "
             "--equations text, latex or mathml prints them.");
  bg_strbuf eq = {0};
  bg_eqprint_mathml(c->in->eqs, &eq);
  /* at most HT_MAX_EQ_ROWS equations (one a line): a page stays readable */
  size_t cut = eq.len;
  int rows = 0;
  for (size_t i = 0; i < eq.len; i++)
    if (eq.s[i] == '\n' && ++rows == HT_MAX_EQ_ROWS) {
      cut = i + 1;
      break;
    }
  bg_sb_puts(c->out, "<div class=\"equations\">\n");
  bg_sb_putn(c->out, eq.s, cut);
  bg_sb_puts(c->out, "</div>\n");
  if (cut < eq.len)
    bg_sb_printf(c->out, "<p class=\"note\">The first %d lines are shown; <code>--equations mathml</code> "
                         "prints every equation.</p>\n", HT_MAX_EQ_ROWS);
  bg_sb_free(&eq);
  ht_section_end(c);
}

/* ---------------------------------------------------------------- simulation */
static void json_num(bg_strbuf *b, double v) {
  if (!isfinite(v)) bg_sb_puts(b, "null");
  else bg_sb_printf(b, "%.6g", v);
}

/* A name inside a <script> block of JSON: quotes, backslashes and '<' escaped. */
static void json_name(bg_strbuf *b, const char *s) {
  bg_sb_putc(b, '"');
  for (; s && *s; s++) {
    if (*s == '"' || *s == '\\') bg_sb_printf(b, "\\%c", *s);
    else if (*s == '<') bg_sb_puts(b, "\\u003c");
    else if ((unsigned char)*s < 0x20) bg_sb_printf(b, "\\u%04x", *s);
    else bg_sb_putc(b, *s);
  }
  bg_sb_putc(b, '"');
}

/* The plots' data for the readout: the abscissa's span (as plot.c's
 * time_range: the simulate block's, else the rows'), whether it is a log
 * axis (Bode), the abscissae and, per panel, the columns it draws (plot.c's
 * make_panels: a panel per plot statement of m, else one of every output;
 * at most 24 curves a panel). */
static void readout_data(ht_ctx *c, const bg_model *m, const bg_simresult *r, int xlog) {
  const bg_simspec *sp = &m->sim;
  double t0 = r->t[0], t1 = r->t[r->nrows - 1];
  if (sp->present && isfinite(sp->t0) && isfinite(sp->t_end) && sp->t_end > sp->t0) t0 = sp->t0, t1 = sp->t_end;
  if (r->partial && isfinite(r->t_reached) && r->t_reached > t1) t1 = r->t_reached;
  int stride = (r->nrows + HT_MAX_READOUT_ROWS - 1) / HT_MAX_READOUT_ROWS;
  bg_strbuf *o = c->out;
  bg_sb_puts(o, "<script type=\"application/json\" class=\"plot-data\">{\"t0\": ");
  json_num(o, t0), bg_sb_puts(o, ", \"t1\": "), json_num(o, t1);
  bg_sb_printf(o, ", \"xlog\": %d", xlog);
  bg_sb_puts(o, ", \"t\": [");
  for (int i = 0, k = 0; i < r->nrows; i += stride, k++) bg_sb_puts(o, k ? "," : ""), json_num(o, r->t[i]);
  bg_sb_puts(o, "], \"panels\": [");
  int byplot = m->nplot > 0 && m->nplotexpr == r->nout, np = byplot ? m->nplot : 1;
  for (int k = 0; k < np; k++) {
    int col0 = byplot ? m->plot_expradr[k] : 0, ncol = byplot ? m->plot_nexpr[k] : r->nout;
    if (col0 < 0 || col0 > r->nout) col0 = r->nout;
    if (ncol > r->nout - col0) ncol = r->nout - col0;
    if (ncol > 24) ncol = 24;
    if (ncol < 0 || !r->values) ncol = 0;
    bg_sb_puts(o, k ? ", {\"names\": [" : "{\"names\": [");
    for (int j = 0; j < ncol; j++) bg_sb_puts(o, j ? ", " : ""), json_name(o, r->names[col0 + j]);
    bg_sb_puts(o, "], \"values\": [");
    for (int j = 0; j < ncol; j++) {
      bg_sb_puts(o, j ? ", [" : "[");
      for (int i = 0, n = 0; i < r->nrows; i += stride, n++)
        bg_sb_puts(o, n ? "," : ""), json_num(o, r->values[(size_t)i * (size_t)r->nout + (size_t)(col0 + j)]);
      bg_sb_puts(o, "]");
    }
    bg_sb_puts(o, "]}");
  }
  bg_sb_puts(o, "]}</script>\n");
}

static void plots(ht_ctx *c, const bg_simresult *r) {
  const bg_render_opts *o = c->in->ropts;
  bg_strbuf svg = {0};
  if (bg_plot_render(c->m, r, o ? o->style : NULL, o ? o->style_dir : NULL, "svg", NULL, &svg, c->dg) !=
      BG_RENDER_OK) {
    c->failed = 1;
    bg_sb_free(&svg);
    return;
  }
  ht_sub(c, "plots", r->partial ? "Plots (partial results)" : "Plots");
  bg_sb_puts(c->out, "<figure class=\"plot\" data-readout=\"1\">\n");
  ht_inline_svg(c, svg.s, svg.len, "role=\"img\" aria-label=\"Simulation plots: the outputs against time\"");
  readout_data(c, c->m, r, 0);
  bg_sb_puts(c->out, "<figcaption>The outputs against time. Under the pointer: <output class=\"readout\" "
                     "aria-live=\"polite\">point at a plot</output></figcaption>\n</figure>\n");
  bg_sb_free(&svg);
}

static void events(ht_ctx *c, const bg_simresult *r) {
  if (r->nevents <= 0) return;
  ht_sub(c, "state-events", "State events");
  static const char *const head[] = {"t [s]", "Condition", "Switching function"};
  ht_table(c, NULL, "State events", 3, head);
  for (int k = 0; k < r->nevents && k < 12; k++) {
    bg_sb_printf(c->out, "<tr><td class=\"n\">%.10g</td><td>", r->event_t[k]);
    ht_esc(c->out, r->condition_text[r->event_cond[k]]);
    bg_sb_printf(c->out, "</td><td>%s</td></tr>\n", r->event_dir[k] > 0 ? "rising" : "falling");
  }
  ht_table_end(c);
  if (r->nevents > 12) ht_para(c, "and %d more (the JSON lists them all).", r->nevents - 12);
}

void ht_simulation(ht_ctx *c) {
  const bg_report_input *in = c->in;
  const bg_simresult *r = in->sim;
  ht_section(c, "simulation", "Simulation");
  if (!c->m->sim.present) {
    bg_sb_puts(c->out, "<p>The model has no <code>simulate</code> block, so there is nothing to plot. Add "
                       "one, e.g. <code>simulate t_end = 1, dt = 0.01</code>, and the report shows the "
                       "plots here.</p>\n");
  } else if (!r) {
    ht_para(c, "The simulation was not run.");
  } else if (in->sim_status == 1) {
    const char *why = r->message ? r->message : in->eqs_problem ? in->eqs_problem : "no reason given";
    bg_sb_puts(c->out, "<p><b>Simulation refused</b> (no solver was called). ");
    ht_esc(c->out, why);
    bg_sb_puts(c->out, "</p>\n");
  } else {
    if (in->sim_status == 2) {
      bg_sb_puts(c->out, "<p><b>Simulation failed</b>: ");
      ht_esc(c->out, r->message ? r->message : "no reason given");
      bg_sb_puts(c->out, r->nrows ? " The plots show the results up to the time reached.</p>\n" : "</p>\n");
    } else {
      bg_sb_printf(c->out, "<p>From t = %g to %g s with <b>", c->m->sim.t0, c->m->sim.t_end);
      ht_esc(c->out, r->solver_used ? r->solver_used : "?");
      bg_sb_printf(c->out, "</b>: %d output rows.</p>\n", r->nrows);
    }
    if (r->nrows >= 1 && r->nout >= 1) plots(c, r);
    bg_sb_puts(c->out, "<div class=\"scroll\"><table class=\"stats\"><caption>Solver statistics</caption>\n<tbody>\n");
    rp_sim_stat_rows(&c->rp, r, ht_row, c->out);
    bg_sb_puts(c->out, "</tbody></table></div>\n");
    events(c, r);
  }
  ht_section_end(c);
}

/* ---------------------------------------------------------------- linear */
static void linear_plot(ht_ctx *c, int kind, const char *id, const char *title) {
  const bg_render_opts *o = c->in->ropts;
  bg_strbuf svg = {0};
  bg_diags quiet;
  bg_diags_init(&quiet, "bgdraw", NULL, 0); /* nothing to draw is not an error here */
  if (bg_plot_linear_render(c->m, c->in->lin, kind, o ? o->style : NULL, o ? o->style_dir : NULL, "svg", NULL,
                            &svg, &quiet) == BG_RENDER_OK && svg.len) {
    ht_sub(c, id, title);
    bg_strbuf a = {0};
    bg_sb_puts(&a, "role=\"img\" aria-label=\"");
    ht_esc(&a, title);
    bg_sb_puts(&a, "\"");
    bg_plot_table T;
    int data = bg_plot_linear_table(c->m, c->in->lin, kind, &T) == 0;
    bg_sb_puts(c->out, data ? "<figure class=\"plot\" data-readout=\"1\">\n" : "<figure class=\"plot\">\n");
    ht_inline_svg(c, svg.s, svg.len, bg_sb_str(&a));
    if (data) {
      readout_data(c, &T.m, &T.r, kind == BG_PLOT_BODE);
      bg_sb_puts(c->out, "<figcaption>Under the pointer: <output class=\"readout\" aria-live=\"polite\">"
                         "point at a plot</output></figcaption>\n");
      bg_plot_table_free(&T);
    }
    bg_sb_puts(c->out, "</figure>\n");
    bg_sb_free(&a);
  }
  bg_diags_free(&quiet);
  bg_sb_free(&svg);
}

void ht_linear(ht_ctx *c) {
  if (!c->in->lin) return;
  ht_section(c, "linear", "Linear analysis");
  bg_strbuf t = {0};
  bg_linear_print(c->in->lin, c->m, "text", &t);
  bg_sb_puts(c->out, "<pre class=\"linear\">");
  ht_esc(c->out, bg_sb_str(&t));
  bg_sb_puts(c->out, "</pre>\n");
  bg_sb_free(&t);
  linear_plot(c, BG_PLOT_BODE, "bode", "Bode diagram");
  linear_plot(c, BG_PLOT_STEP, "step", "Step and impulse responses");
  ht_section_end(c);
}

/* ---------------------------------------------------------------- transformation */
static void compare_row(void *ctx, const char *what, const char *before, const char *after) {
  bg_strbuf *b = ctx;
  bg_sb_puts(b, "<tr><th scope=\"row\">");
  ht_esc(b, what);
  bg_sb_puts(b, "</th><td class=\"n\">");
  ht_esc(b, before);
  bg_sb_puts(b, "</td><td class=\"n\">");
  ht_esc(b, after);
  bg_sb_puts(b, "</td></tr>\n");
}

void ht_transform(ht_ctx *c) {
  const bg_transform_result *tx = c->in->tx;
  if (!tx) return;
  ht_section(c, "transformation", "Transformation");
  bg_sb_puts(c->out, "<p><code>--transform ");
  ht_esc(c->out, c->in->tx_name);
  bg_sb_puts(c->out, "</code> wrote a new model. ");
  ht_esc(c->out, tx->summary);
  bg_sb_puts(c->out, "</p>\n");
  static const char *const head[] = {"", "Before", "After"};
  ht_table(c, NULL, "The analysis before and after", 3, head);
  rp_transform_rows(c->a, &tx->run->analysis, compare_row, c->out);
  ht_table_end(c);
  ht_sub(c, "transform-before", "Before");
  bg_sb_puts(c->out, "<figure class=\"diagram-small\">\n");
  if (diagram_svg(c, c->m, c->a, BG_SHOW_DEFAULT, "role=\"img\" aria-label=\"The bond graph before\"")) c->failed = 1;
  bg_sb_puts(c->out, "</figure>\n");
  ht_sub(c, "transform-after", "After");
  bg_sb_puts(c->out, "<figure class=\"diagram-small\">\n");
  if (diagram_svg(c, tx->run->model, &tx->run->analysis, BG_SHOW_DEFAULT,
                  "role=\"img\" aria-label=\"The bond graph after\""))
    c->failed = 1;
  bg_sb_puts(c->out, "</figure>\n<details><summary>The new model</summary><pre>");
  ht_esc(c->out, tx->text);
  bg_sb_puts(c->out, "</pre></details>\n");
  ht_section_end(c);
}
