/* SPDX-License-Identifier: BSD-3-Clause */
/* Simulation plots: one panel per `plot` statement (or one panel of every
 * output when there is none) stacked over a shared time axis, with 1-2-5
 * ticks, SI prefixes, a light grid, a legend per panel, curves that differ
 * in colour and dash pattern, and a partial run marked where it stopped.
 * Drawn into a bg_scene; conventions in docs/plots.md. */
#include "plot/plot.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>

#include "base/fileio.h"
#include "plot/plot_int.h"
#include "diagram/render.h"
#include "scene/surface.h"

enum { PLOT_MAX_CURVES = 24, LEGEND_TEXT_MAX = 60 };
#define PLOT_WIDTH 540.0 /* --plot files: points */
#define MARGIN 8.0
#define PANEL_GAP 14.0
#define TICK_LEN 3.0
#define SAMPLE_W 24.0

typedef struct panel {
  int col0, ncol, nshown;  /* columns of r drawn; nshown <= PLOT_MAX_CURVES */
  const char *title;       /* nullable */
  const char *ylabel;      /* "" when none */
  double dlo, dhi;         /* range of the finite values shown */
  bg_plot_axis y;
  double top, area_top, area_h, header_h;
} panel;

typedef struct plot {
  const bg_model *m;
  const bg_simresult *r;
  const bg_plot_spec *spec; /* NULL: a simulation over time */
  const bg_style *st;
  bg_scene *s;
  panel *p;
  int np;
  double W, H;
  double left, right; /* x extent of the plot areas */
  double t0, t1;      /* the time axis */
  bg_plot_axis x;
  double fs_tick, fs_legend, fs_label, fs_title;
  double h_tick, h_row, h_title, h_label; /* line heights */
} plot;

/* ---------------------------------------------------------------- text */

/* Markup for a legend text: escaped, cut at LEGEND_TEXT_MAX bytes (on a
 * character boundary) with an ellipsis. */
static void legend_markup(bg_strbuf *b, const char *s) {
  size_t n = strlen(s);
  if (n <= LEGEND_TEXT_MAX) {
    bg_markup_escapen(b, s, n);
    return;
  }
  n = LEGEND_TEXT_MAX;
  while (n > 0 && ((unsigned char)s[n] & 0xC0) == 0x80) n--;
  bg_markup_escapen(b, s, n);
  bg_sb_puts(b, "\xe2\x80\xa6");
}

static double text_width(const plot *P, double size, const char *markup) {
  double w, h;
  bg_text_measure(P->s->font, size, markup, &w, &h);
  return w;
}

static double line_height(const plot *P, double size, const char *markup) {
  double w, h;
  bg_text_measure(P->s->font, size, markup, &w, &h);
  return h;
}

static void text(plot *P, const char *markup, double x, double y, double size, double ha,
                 double va, const char *role) {
  bg_scene_text(P->s, markup, x, y, size, ha, va, P->st->fg, role);
}

/* ---------------------------------------------------------------- data */
static double value(const plot *P, int row, int col) {
  return P->r->values[(size_t)row * (size_t)P->r->nout + (size_t)col];
}

static void data_range(plot *P, panel *q) {
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < P->r->nrows; i++)
    for (int j = 0; j < q->nshown; j++) {
      double v = value(P, i, q->col0 + j);
      if (!isfinite(v)) continue;
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
  q->dlo = lo, q->dhi = hi;
}

/* Panel k shows the columns of plot statement k (simulate.c names the
 * columns after m->plotexpr_text in statement order); without plot
 * statements, one panel of every output (the states). */
static void make_panels(plot *P) {
  const bg_model *m = P->m;
  const bg_simresult *r = P->r;
  int byplot = m->nplot > 0 && m->nplotexpr == r->nout;
  P->np = byplot ? m->nplot : 1;
  P->p = bg_xcalloc((size_t)P->np, sizeof *P->p);
  for (int k = 0; k < P->np; k++) {
    panel *q = &P->p[k];
    q->ylabel = "";
    if (byplot) {
      q->col0 = m->plot_expradr[k], q->ncol = m->plot_nexpr[k];
      q->title = m->plot_title[k] && *m->plot_title[k] ? m->plot_title[k] : NULL;
      q->ylabel = m->plot_ylabel[k] ? m->plot_ylabel[k] : "";
    } else {
      q->col0 = 0, q->ncol = r->nout;
    }
    if (q->col0 < 0 || q->col0 > r->nout) q->col0 = r->nout;
    if (q->ncol > r->nout - q->col0) q->ncol = r->nout - q->col0;
    if (q->ncol < 0) q->ncol = 0;
    q->nshown = q->ncol < PLOT_MAX_CURVES ? q->ncol : PLOT_MAX_CURVES;
    if (!r->values) q->nshown = 0;
    data_range(P, q);
  }
}

/* The time axis spans the simulate block (t0 .. t_end), so that a partial
 * run shows the gap; else the rows' times. */
static void time_range(plot *P) {
  const bg_simspec *sp = &P->m->sim;
  const bg_simresult *r = P->r;
  double a = 0, b = 1;
  if (sp->present && isfinite(sp->t0) && isfinite(sp->t_end) && sp->t_end > sp->t0)
    a = sp->t0, b = sp->t_end;
  else if (r->nrows > 0 && r->t && isfinite(r->t[0]) && isfinite(r->t[r->nrows - 1]))
    a = r->t[0], b = r->t[r->nrows - 1];
  if (r->partial && isfinite(r->t_reached) && r->t_reached > b) b = r->t_reached;
  if (!(b > a)) b = a + (a != 0 ? 0.1 * fabs(a) : 1);
  P->t0 = a, P->t1 = b;
}

/* ---------------------------------------------------------------- mapping */
static double map(double v, double lo, double hi, double a, double b) {
  double f = (0.5 * v - 0.5 * lo) / (0.5 * hi - 0.5 * lo); /* no overflow near DBL_MAX */
  return a + f * (b - a);
}

static int xlog(const plot *P) { return P->spec && P->spec->xlog; }

static double X(const plot *P, double t) {
  if (xlog(P)) return map(log10(t), log10(P->t0), log10(P->t1), P->left, P->right);
  return map(t, P->t0, P->t1, P->left, P->right);
}

/* Value of x tick i: 1-2-5 steps, or every x.step-th decade on a log axis. */
static double xtick(const plot *P, int i) {
  return xlog(P) ? pow(10, P->x.k0 + i * P->x.step) : bg_plot_tick(&P->x, i);
}

/* Label of x tick i: the value, or 10 to the decade as markup. */
static const char *xtick_label(const plot *P, int i, char *buf, size_t n) {
  if (!xlog(P)) return bg_plot_tick_label(&P->x, i, buf, n);
  int k = (int)(P->x.k0 + i * P->x.step); /* |k| <= 324: x_axis_log keeps t0, t1 finite */
  if (k == 0 || k == 1) snprintf(buf, n, "%s", k ? "10" : "1");
  else bg_plot_power_markup("", k, P->fs_tick, buf, n);
  return buf;
}

/* Decade ticks between t0 and t1 (a log axis), every decade up to 13 of
 * them, else every 2nd, 3rd, ...: at most 13 labels. The range is made
 * positive and finite first (frequencies that overflowed, a zero), so no
 * infinite logarithm reaches an int. */
static void x_axis_log(plot *P) {
  if (!(P->t1 > 0) || !isfinite(P->t1)) P->t1 = DBL_MAX;
  if (!(P->t0 > 0) || !isfinite(P->t0) || !(P->t0 < P->t1)) P->t0 = P->t1 / 10 > 0 ? P->t1 / 10 : DBL_MIN;
  double a = log10(P->t0), b = log10(P->t1);
  double k0 = ceil(a - 1e-9), k1 = floor(b + 1e-9), step = 1;
  if (k1 - k0 > 12) step = ceil((k1 - k0) / 12);
  P->x = (bg_plot_axis){P->t0, P->t1, step, k0, 0, BG_PLOT_NO_PREFIX, 0};
  P->x.n = k1 >= k0 ? (int)floor((k1 - k0) / step) + 1 : 0;
}

static double Y(const panel *q, double v) {
  return map(v, q->y.lo, q->y.hi, q->area_top + q->area_h, q->area_top);
}

/* ---------------------------------------------------------------- styles */
static bg_rgba mix(bg_rgba a, bg_rgba b, double f) {
  return (bg_rgba){a.r + (b.r - a.r) * f, a.g + (b.g - a.g) * f, a.b + (b.b - a.b) * f,
                   a.a + (b.a - a.a) * f};
}

/* Curve j: colour j mod the style's layer colours, dash pattern j mod 5, so
 * that neighbours differ in both and a grey print still tells them apart. */
void bg_plot_curve_style(const bg_style *st, int j, bg_scene_item *it) {
  static const double dash[][2] = {{0, 0}, {6, 3}, {0, 2.6}, {12, 3.5}, {3, 2}};
  double w = fmax(1.1, 1.4 * st->line_width);
  it->color = st->nlayer_color > 0 ? st->layer_color[j % st->nlayer_color] : st->fg;
  it->width = w;
  it->round = 1;
  const double *d = dash[j % 5];
  if (d[1] > 0) { /* round caps add w to every dash: compensate */
    it->dash[0] = fmax(0.01, d[0] - w);
    it->dash[1] = d[1] + w;
  }
}

/* The header's y label as markup: the panel's ylabel and its axis' scale
 * ("x1 [m] ×10⁻³"; the scale alone without a ylabel); "" when neither. */
static const char *ylabel_markup(const plot *P, const panel *q, bg_strbuf *b) {
  char scale[128];
  bg_plot_scale_markup(q->y.exp3, P->fs_label, scale, sizeof scale);
  bg_markup_escapen(b, q->ylabel, strlen(q->ylabel));
  if (*scale) bg_sb_printf(b, "%s%s", *q->ylabel ? " " : "", scale);
  return bg_sb_str(b);
}

/* ---------------------------------------------------------------- legend */
/* Lays out (draw = 0: counts the rows) or draws the legend of panel k:
 * entries flow into rows right-aligned at the plot area's right edge, left
 * of which only the y label goes. */
static int legend_pass(plot *P, int k, int draw) {
  panel *q = &P->p[k];
  double x0 = P->left;
  bg_strbuf yl = {0};
  int has_ylabel = *ylabel_markup(P, q, &yl) != 0;
  if (has_ylabel) x0 = fmax(x0, MARGIN + text_width(P, P->fs_label, bg_sb_str(&yl)) + 16);
  bg_sb_free(&yl);
  double avail = P->right - x0, gap = 14, pad = 4;
  int n = q->nshown + (q->ncol > q->nshown), rows = 0, start = 0;
  if (P->spec && P->spec->legend_once && k > 0) n = 0; /* the first panel's says it */
  bg_strbuf *mk = bg_xcalloc((size_t)(n > 0 ? n : 1), sizeof *mk);
  double *w = bg_xcalloc((size_t)(n > 0 ? n : 1), sizeof *w);
  for (int j = 0; j < n; j++) {
    if (j < q->nshown) legend_markup(&mk[j], P->r->names[q->col0 + j] ? P->r->names[q->col0 + j] : "?");
    else bg_sb_printf(&mk[j], "\xe2\x80\xa6 and %d more, not drawn", q->ncol - q->nshown);
    w[j] = text_width(P, P->fs_legend, bg_sb_str(&mk[j])) + (j < q->nshown ? SAMPLE_W + pad : 0);
  }
  while (start < n) {
    double roww = w[start];
    int end = start + 1;
    while (end < n && roww + gap + w[end] <= avail) roww += gap + w[end++];
    if (draw) {
      double x = roww <= avail ? P->right - roww : x0;
      double y = q->top + (q->title ? P->h_title : 0) + (rows + 0.5) * P->h_row;
      char role[48];
      for (int j = start; j < end; j++) {
        if (j < q->nshown) {
          bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_STROKE, "legend-sample %d", k + 1);
          bg_plot_curve_style(P->st, j, it);
          bg_scene_move(P->s, x, y);
          bg_scene_line(P->s, x + SAMPLE_W, y);
          snprintf(role, sizeof role, "legend %d", k + 1);
          text(P, bg_sb_str(&mk[j]), x + SAMPLE_W + pad, y, P->fs_legend, 0, 0.5, role);
        } else {
          text(P, bg_sb_str(&mk[j]), x, y, P->fs_legend, 0, 0.5, "legend-more");
        }
        x += w[j] + gap;
      }
    }
    rows++;
    start = end;
  }
  for (int j = 0; j < n; j++) bg_sb_free(&mk[j]);
  free(mk);
  free(w);
  if (rows == 0 && has_ylabel) rows = 1;
  return rows;
}

/* ---------------------------------------------------------------- layout */
static double ytick_width(plot *P, const panel *q) {
  double wmax = 0;
  char buf[96];
  for (int i = 0; i < q->y.n; i++)
    wmax = fmax(wmax, text_width(P, P->fs_tick, bg_plot_tick_label(&q->y, i, buf, sizeof buf)));
  return wmax;
}

/* Time ticks: as many as fit with their labels 12 pt apart. */
static void x_axis(plot *P) {
  if (xlog(P)) {
    x_axis_log(P);
    return;
  }
  double w = P->right - P->left;
  int maxn = (int)(w / 45);
  if (maxn < 1) maxn = 1;
  char buf[96];
  for (;;) {
    bg_plot_axis_make(P->t0, P->t1, maxn, 0, &P->x);
    double widest = 0;
    for (int i = 0; i < P->x.n; i++)
      widest = fmax(widest, text_width(P, P->fs_tick, bg_plot_tick_label(&P->x, i, buf, sizeof buf)));
    double px = map(P->x.step, 0, P->t1 - P->t0, 0, w);
    if (px >= widest + 12 || maxn == 1) break;
    int fit = (int)(w / (widest + 12));
    maxn = fit < maxn - 1 ? fit : maxn - 1;
    if (maxn < 1) maxn = 1;
  }
}

/* Keeps the last time label inside the box. */
static void x_axis_fit(plot *P) {
  x_axis(P);
  if (P->x.n < 1) return;
  char buf[96];
  double hw = text_width(P, P->fs_tick, xtick_label(P, P->x.n - 1, buf, sizeof buf)) / 2;
  double over = X(P, xtick(P, P->x.n - 1)) + hw - (P->W - 1);
  if (over > 0) {
    P->right -= over;
    x_axis(P);
  }
}

static double bottom_height(const plot *P) {
  return TICK_LEN + 3 + P->h_tick + 4 + P->h_label;
}

static void layout_pass(plot *P) {
  double headers = 0;
  for (int k = 0; k < P->np; k++) {
    panel *q = &P->p[k];
    int rows = legend_pass(P, k, 0);
    q->header_h = (q->title ? P->h_title : 0) + rows * P->h_row + P->h_tick / 2 + 3;
    headers += q->header_h;
  }
  double area = P->np == 1 ? 190 : P->np == 2 ? 150 : 120;
  if (P->H > 0) {
    double avail = P->H - 2 * MARGIN - headers - (P->np - 1) * PANEL_GAP - bottom_height(P);
    area = fmax(30, avail / P->np);
  }
  double yw = 0;
  for (int k = 0; k < P->np; k++) {
    panel *q = &P->p[k];
    q->area_h = area;
    int maxn = (int)(area / (2.2 * P->h_tick));
    if (P->spec && (P->spec->angle_panel == k + 1 || (k < 32 && (P->spec->angle_mask >> k & 1))))
      /* short labels: two more intervals fit */
      bg_plot_axis_degrees(q->dlo, q->dhi, maxn + 2, &q->y);
    else bg_plot_axis_make(q->dlo, q->dhi, maxn < 2 ? 2 : maxn, 1, &q->y);
    yw = fmax(yw, ytick_width(P, q));
  }
  P->left = MARGIN + yw + TICK_LEN + 3;
  P->right = P->W - MARGIN - 6;
  if (P->right < P->left + 20) P->right = P->left + 20; /* absurdly narrow boxes */
  x_axis_fit(P);
}

static void layout(plot *P) {
  P->fs_tick = 0.8 * P->st->font_size;
  P->fs_legend = 0.85 * P->st->font_size;
  P->fs_label = 0.9 * P->st->font_size;
  P->fs_title = P->st->font_size;
  P->h_tick = line_height(P, P->fs_tick, "0");
  P->h_label = line_height(P, P->fs_label, "t");
  P->h_row = fmax(line_height(P, P->fs_legend, "0"), P->h_label) + 2;
  P->h_title = line_height(P, P->fs_title, "<b>0</b>") + 3;
  P->left = MARGIN + 30, P->right = P->W - MARGIN;
  int passes = 1;
  /* twice: the legend's room depends on the y labels' width and the y axes'
   * scales (by the y label); a third time in the rare case a scale changed */
  layout_pass(P);
  int *exp3 = bg_xcalloc((size_t)P->np + 1, sizeof *exp3);
  for (;;) {
    for (int k = 0; k < P->np; k++) exp3[k] = P->p[k].y.exp3;
    layout_pass(P);
    int same = 1;
    for (int k = 0; k < P->np; k++) same &= exp3[k] == P->p[k].y.exp3;
    if (same || ++passes >= 3) break;
  }
  free(exp3);
  double y = MARGIN;
  for (int k = 0; k < P->np; k++) {
    panel *q = &P->p[k];
    q->top = y;
    q->area_top = y + q->header_h;
    y = q->area_top + q->area_h + PANEL_GAP;
  }
}

/* ---------------------------------------------------------------- drawing */
/* A log axis: fainter lines at 2 .. 9 times each decade. */
static void draw_minor_grid(plot *P, const panel *q, int k) {
  bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_STROKE, "grid minor %d", k + 1);
  it->color = mix(P->st->muted, P->st->background, 0.75);
  it->width = 0.35;
  if (P->x.step != 1) return; /* decades too close together */
  for (double d = floor(log10(P->t0)); d <= log10(P->t1); d++)
    for (int m = 2; m <= 9; m++) {
      double v = m * pow(10, d);
      if (v <= P->t0 || v >= P->t1) continue;
      bg_scene_move(P->s, X(P, v), q->area_top);
      bg_scene_line(P->s, X(P, v), q->area_top + q->area_h);
    }
}

static void draw_grid(plot *P, const panel *q, int k) {
  bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_STROKE, "grid %d", k + 1);
  it->color = mix(P->st->muted, P->st->background, 0.45);
  it->width = 0.5;
  double bot = q->area_top + q->area_h;
  for (int i = 0; i < P->x.n; i++) {
    double x = X(P, xtick(P, i));
    bg_scene_move(P->s, x, q->area_top);
    bg_scene_line(P->s, x, bot);
  }
  if (xlog(P)) draw_minor_grid(P, q, k);
  for (int i = 0; i < q->y.n; i++) {
    double y = Y(q, bg_plot_tick(&q->y, i));
    bg_scene_move(P->s, P->left, y);
    bg_scene_line(P->s, P->right, y);
  }
}

static void rect(bg_scene *s, double x0, double y0, double x1, double y1) {
  bg_scene_move(s, x0, y0);
  bg_scene_line(s, x1, y0);
  bg_scene_line(s, x1, y1);
  bg_scene_line(s, x0, y1);
  bg_scene_close(s);
}

static void draw_frame(plot *P, const panel *q, int k) {
  bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_STROKE, "panel %d", k + 1);
  it->color = P->st->fg;
  it->width = 0.6;
  rect(P->s, P->left, q->area_top, P->right, q->area_top + q->area_h);
}

static void draw_yticks(plot *P, const panel *q, int k) {
  bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_STROKE, "ticks y %d", k + 1);
  it->color = P->st->fg;
  it->width = 0.6;
  for (int i = 0; i < q->y.n; i++) {
    double y = Y(q, bg_plot_tick(&q->y, i));
    bg_scene_move(P->s, P->left - TICK_LEN, y);
    bg_scene_line(P->s, P->left, y);
  }
  char buf[96], role[32];
  snprintf(role, sizeof role, "tick y %d", k + 1);
  for (int i = 0; i < q->y.n; i++)
    text(P, bg_plot_tick_label(&q->y, i, buf, sizeof buf), P->left - TICK_LEN - 2,
         Y(q, bg_plot_tick(&q->y, i)), P->fs_tick, 1, 0.5, role);
}

/* Tick marks under every panel; labels and the axis name under the last. */
static void draw_xticks(plot *P, const panel *q, int k, int labels) {
  double bot = q->area_top + q->area_h;
  bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_STROKE, "ticks x %d", k + 1);
  it->color = P->st->fg;
  it->width = 0.6;
  for (int i = 0; i < P->x.n; i++) {
    double x = X(P, xtick(P, i));
    bg_scene_move(P->s, x, bot);
    bg_scene_line(P->s, x, bot + TICK_LEN);
  }
  if (!labels) return;
  char buf[96];
  for (int i = 0; i < P->x.n; i++)
    text(P, xtick_label(P, i, buf, sizeof buf), X(P, xtick(P, i)), bot + TICK_LEN + 2,
         P->fs_tick, 0.5, 0, "tick x");
  /* the axis name: the first xlabel other than the default "t" */
  const char *name = "t";
  for (int j = 0; j < P->m->nplot && P->np == P->m->nplot; j++)
    if (P->m->plot_xlabel[j] && *P->m->plot_xlabel[j] && strcmp(P->m->plot_xlabel[j], "t")) {
      name = P->m->plot_xlabel[j];
      break;
    }
  if (P->spec && P->spec->xname) name = P->spec->xname;
  bg_strbuf b = {0};
  bg_markup_escapen(&b, name, strlen(name));
  if (!P->spec || !P->spec->xunit)
    bg_sb_printf(&b, " [%ss]", P->x.exp3 == BG_PLOT_NO_PREFIX ? "" : bg_plot_si_prefix(P->x.exp3));
  else if (*P->spec->xunit) bg_sb_printf(&b, " [%s]", P->spec->xunit);
  else if (P->x.exp3 != BG_PLOT_NO_PREFIX && P->x.exp3) /* a unitless axis: its prefix alone */
    bg_sb_printf(&b, " [%s]", bg_plot_si_prefix(P->x.exp3));
  text(P, bg_sb_str(&b), (P->left + P->right) / 2, bot + TICK_LEN + 2 + P->h_tick + 3,
       P->fs_label, 0.5, 0, "xlabel");
  bg_sb_free(&b);
}

static void draw_header(plot *P, const panel *q, int k) {
  char role[32];
  bg_strbuf b = {0};
  if (q->title) {
    bg_sb_puts(&b, "<b>");
    bg_markup_escapen(&b, q->title, strlen(q->title));
    bg_sb_puts(&b, "</b>");
    snprintf(role, sizeof role, "title %d", k + 1);
    text(P, bg_sb_str(&b), (P->left + P->right) / 2, q->top, P->fs_title, 0.5, 0, role);
    bg_sb_clear(&b);
  }
  if (*ylabel_markup(P, q, &b)) {
    snprintf(role, sizeof role, "ylabel %d", k + 1);
    text(P, bg_sb_str(&b), MARGIN, q->top + (q->title ? P->h_title : 0) + P->h_row / 2,
         P->fs_label, 0, 0.5, role);
  }
  bg_sb_free(&b);
  legend_pass(P, k, 1);
}

/* ------------------------------------------------------------ curves */
/* Lines through the points; a non-finite value lifts the pen, and a lone
 * point between two gaps is drawn as a dot. */
typedef struct pen {
  bg_scene *s;
  int down, npt;
  double x, y;
} pen;

static void pen_to(pen *p, double x, double y) {
  if (p->down) bg_scene_line(p->s, x, y);
  else bg_scene_move(p->s, x, y);
  p->down = 1, p->npt++, p->x = x, p->y = y;
}

static void pen_up(pen *p) {
  if (p->down && p->npt == 1) bg_scene_line(p->s, p->x, p->y);
  p->down = 0, p->npt = 0;
}

/* Rows falling into one half-point column: only the first, lowest, highest
 * and last are drawn (in time order), which looks the same and keeps long
 * runs small. */
typedef struct bucket {
  long id;
  int n, first, lo, hi, last;
} bucket;

static void bucket_flush(const plot *P, const panel *q, int col, bucket *b, pen *p) {
  if (!b->n) return;
  int idx[4] = {b->first, b->lo, b->hi, b->last};
  for (int i = 1; i < 4; i++) /* insertion sort of four */
    for (int j = i; j > 0 && idx[j] < idx[j - 1]; j--) {
      int t = idx[j];
      idx[j] = idx[j - 1], idx[j - 1] = t;
    }
  for (int i = 0; i < 4; i++)
    if (i == 0 || idx[i] != idx[i - 1])
      pen_to(p, X(P, P->r->t[idx[i]]), Y(q, value(P, idx[i], col)));
  b->n = 0;
}

static void draw_curve(plot *P, const panel *q, int k, int j) {
  bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_STROKE, "curve %d.%d", k + 1, j + 1);
  bg_plot_curve_style(P->st, j, it);
  int col = q->col0 + j;
  pen p = {P->s, 0, 0, 0, 0};
  bucket b = {0};
  for (int i = 0; i < P->r->nrows; i++) {
    double t = P->r->t[i], v = value(P, i, col);
    if (!isfinite(t) || !isfinite(v)) {
      bucket_flush(P, q, col, &b, &p);
      pen_up(&p);
      continue;
    }
    double c = floor((X(P, t) - P->left) * 2);
    long id = c < -1e6 ? -1000000 : c > 1e6 ? 1000000 : (long)c;
    if (b.n && id != b.id) bucket_flush(P, q, col, &b, &p);
    if (!b.n) b = (bucket){id, 1, i, i, i, i};
    else {
      b.n++, b.last = i;
      if (v < value(P, b.lo, col)) b.lo = i;
      if (v > value(P, b.hi, col)) b.hi = i;
    }
  }
  bucket_flush(P, q, col, &b, &p);
  pen_up(&p);
}

/* ------------------------------------------------------------ partial */
static double partial_x(const plot *P) {
  double t = P->r->t_reached;
  if (!isfinite(t) || t < P->t0) t = P->t0;
  if (t > P->t1) t = P->t1;
  return X(P, t);
}

/* The time after the run stopped, shaded (before the curves). */
static void draw_partial_gap(plot *P, const panel *q, int k) {
  double x = partial_x(P);
  if (x >= P->right) return;
  bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_FILL, "partial-gap %d", k + 1);
  it->fill = P->st->muted;
  it->fill.a *= 0.3;
  it->width = 0;
  rect(P->s, x, q->area_top, P->right, q->area_top + q->area_h);
}

/* How many points of the panel's curves fall in the box (x, y, w, h). */
static int points_in(const plot *P, const panel *q, double x, double y, double w, double h) {
  int n = 0;
  for (int i = 0; i < P->r->nrows; i++) {
    double px = X(P, P->r->t[i]);
    if (!(px >= x - 2 && px <= x + w + 2)) continue;
    for (int j = 0; j < q->nshown; j++) {
      double py = Y(q, value(P, i, q->col0 + j));
      n += py >= y - 2 && py <= y + h + 2;
    }
  }
  return n;
}

static void draw_partial(plot *P, const panel *q, int k) {
  double x = partial_x(P), bot = q->area_top + q->area_h;
  bg_scene_item *it = bg_scene_begin(P->s, BG_ITEM_STROKE, "partial %d", k + 1);
  it->color = P->st->conflict;
  it->width = 1;
  it->dash[0] = 4, it->dash[1] = 3;
  bg_scene_move(P->s, x, q->area_top);
  bg_scene_line(P->s, x, bot);
  if (k != 0) return;
  char val[96];
  bg_plot_format_value(P->r->t_reached, P->x.exp3, val, sizeof val);
  bg_strbuf b = {0};
  bg_sb_printf(&b, "simulation stopped at t = %ss", val);
  double tw, th;
  bg_text_measure(P->s->font, P->fs_tick, bg_sb_str(&b), &tw, &th);
  int right = x + 4 + tw <= P->right - 2 || x - 4 - tw < P->left;
  double tx = right ? x + 4 : x - 4 - tw, ty = q->area_top + 3;
  double by = q->area_top + q->area_h - 3 - th; /* left of the mark: top or bottom, */
  if (!right && points_in(P, q, tx, by, tw, th) < points_in(P, q, tx, ty, tw, th))
    ty = by; /* whichever hides fewer points */
  it = bg_scene_begin(P->s, BG_ITEM_FILL, "partial-halo");
  it->fill = P->st->background;
  it->fill.a *= 0.85;
  it->width = 0;
  rect(P->s, tx - 1.5, ty - 0.5, tx + tw + 1.5, ty + th + 0.5);
  bg_scene_text(P->s, bg_sb_str(&b), tx, ty, P->fs_tick, 0, 0, P->st->conflict, "partial-label");
  bg_sb_free(&b);
}

static void draw_panel(plot *P, int k) {
  const panel *q = &P->p[k];
  draw_grid(P, q, k);
  if (P->r->partial) draw_partial_gap(P, q, k);
  if (P->r->nrows > 0 && P->r->t)
    for (int j = 0; j < q->nshown; j++) draw_curve(P, q, k, j);
  draw_frame(P, q, k);
  draw_yticks(P, q, k);
  draw_xticks(P, q, k, k == P->np - 1);
  draw_header(P, q, k);
  if (P->r->partial) draw_partial(P, q, k);
}

/* ---------------------------------------------------------------- API */
void bg_plot_scene(const bg_model *m, const bg_simresult *r, const bg_style *st, double width,
                   double height, bg_scene *out) {
  bg_plot_scene_spec(m, r, NULL, st, width, height, out);
}

void bg_plot_scene_spec(const bg_model *m, const bg_simresult *r, const bg_plot_spec *spec,
                        const bg_style *st, double width, double height, bg_scene *out) {
  plot P = {0};
  P.m = m, P.r = r, P.spec = spec, P.st = st, P.s = out;
  P.W = width > 100 ? width : 100;
  P.H = height;
  make_panels(&P);
  time_range(&P);
  layout(&P);
  for (int k = 0; k < P.np; k++) draw_panel(&P, k);
  const panel *last = &P.p[P.np - 1];
  double h = last->area_top + last->area_h + bottom_height(&P) + MARGIN;
  if (height > 0 && h < height) h = height;
  if (out->width < P.W) out->width = P.W;
  if (out->height < ceil(h)) out->height = ceil(h);
  free(P.p);
}

static int render_format(const bg_scene *s, const char *fmt, double png_scale, bg_strbuf *out) {
  if (!strcmp(fmt, "svg")) return bg_surface_svg_write(s, out);
  if (!strcmp(fmt, "pdf")) return bg_surface_pdf_write(s, out);
  return bg_surface_png_write(s, png_scale, out);
}

int bg_plot_render_scene(const bg_scene *sc, const char *fmt, double png_scale, bg_strbuf *out,
                         bg_diags *dg) {
  if (render_format(sc, fmt, png_scale, out) == 0) return BG_RENDER_OK;
  bg_diag_error(dg, (bg_srcloc){0}, "cairo could not draw the %s plot", fmt);
  return BG_RENDER_ERROR;
}

int bg_plot_write(const bg_model *m, const bg_simresult *r, const char *style,
                  const char *style_dir, const char *path, bg_diags *dg) {
  bg_strbuf out = {0};
  int rc = bg_plot_render(m, r, style, style_dir, bg_path_ext(path), path, &out, dg);
  if (rc == BG_RENDER_OK && bg_write_file_atomic(path, out.s ? out.s : "", out.len) != 0) {
    bg_diag_error(dg, (bg_srcloc){0}, "cannot write '%s': %s", path, bg_file_strerror(errno));
    rc = BG_RENDER_EWRITE;
  }
  bg_sb_free(&out);
  return rc;
}

int bg_plot_render(const bg_model *m, const bg_simresult *r, const char *style,
                   const char *style_dir, const char *fmt, const char *path, bg_strbuf *out,
                   bg_diags *dg) {
  if (strcmp(fmt, "svg") && strcmp(fmt, "pdf") && strcmp(fmt, "png")) {
    bg_diag_error(dg, (bg_srcloc){0}, "unknown plot format '%s' for '%s' (svg, pdf, png)",
                  fmt, path ? path : "the plot");
    return BG_RENDER_ERROR;
  }
  bg_style st;
  if (bg_style_load(&st, style, style_dir, dg) != 0) return BG_RENDER_ERROR;
  bg_scene sc;
  bg_scene_init(&sc, st.font);
  sc.background = st.background;
  bg_strbuf t = {0};
  bg_sb_printf(&t, "%s: simulation", m->title ? m->title : m->name ? m->name : "model");
  sc.title = bg_arena_strdup(&sc.arena, bg_sb_str(&t));
  bg_sb_free(&t);
  bg_plot_scene(m, r, &st, PLOT_WIDTH, 0, &sc);
  int rc = bg_plot_render_scene(&sc, fmt, st.png_scale, out, dg);
  bg_scene_free(&sc);
  return rc;
}
