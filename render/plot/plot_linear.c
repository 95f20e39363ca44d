/* SPDX-License-Identifier: BSD-3-Clause */
/* Plots of the linear analysis in the simulation plots' look
 * (docs/linear.md#plots): Bode magnitude (dB) and phase (degrees,
 * unwrapped) over a log frequency axis with decade ticks, step and impulse
 * responses over time (both through bg_plot_scene_spec: the data become
 * rows of a result, the panels a small model), and the Nyquist plot, drawn
 * here with the same axes, frame, grid and curve styles. */
#include "plot/plot_linear.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/render.h"
#include "plot/plot.h"
#include "plot/plot_int.h"
#include "base/fileio.h"
#include "base/sort.h"
#include <errno.h>

enum { BODE_POINTS = 400, TIME_POINTS = 401 };
#define WIDTH 540.0

typedef bg_plot_table table;

void bg_plot_table_init(bg_plot_table *T, const char *name, const char *title, int nrow, int ncurve,
                        int npanel) {
  memset(T, 0, sizeof *T);
  T->r.nrows = nrow;
  T->r.nout = ncurve * npanel;
  T->r.t = bg_xcalloc((size_t)nrow + 1, sizeof(double));
  T->r.values = bg_xcalloc((size_t)nrow * T->r.nout + 1, sizeof(double));
  T->names = bg_xcalloc((size_t)T->r.nout + 1, sizeof(char *));
  T->r.names = (const char **)T->names;
  T->expradr = bg_xcalloc((size_t)npanel + 1, sizeof(int));
  T->nexpr = bg_xcalloc((size_t)npanel + 1, sizeof(int));
  T->title = bg_xcalloc((size_t)npanel + 1, sizeof(char *));
  T->own_title = bg_xcalloc((size_t)npanel + 1, sizeof(char *));
  T->ylabel = bg_xcalloc((size_t)npanel + 1, sizeof(char *));
  T->xlabel = bg_xcalloc((size_t)npanel + 1, sizeof(char *));
  T->m.name = name, T->m.title = title;
  T->m.nplot = npanel, T->m.nplotexpr = T->r.nout;
  for (int k = 0; k < npanel; k++) T->expradr[k] = k * ncurve, T->nexpr[k] = ncurve, T->ylabel[k] = "";
  T->m.plot_expradr = T->expradr, T->m.plot_nexpr = T->nexpr;
  T->m.plot_title = T->title, T->m.plot_ylabel = T->ylabel, T->m.plot_xlabel = T->xlabel;
}

void bg_plot_table_free(bg_plot_table *T) {
  for (int k = 0; k < T->r.nout; k++) free(T->names[k]);
  for (int k = 0; k < T->m.nplot; k++) free(T->own_title[k]);
  free(T->names), free(T->r.t), free(T->r.values), free(T->own_title);
  free(T->expradr), free(T->nexpr), free(T->title), free(T->ylabel), free(T->xlabel);
}

/* "vC ← U" for pair p, in every panel. */
static void pair_names(table *T, const bg_linear *l, int npanel) {
  int np = l->ny * l->nu;
  for (int p = 0; p < np; p++)
    for (int k = 0; k < npanel; k++) {
      char buf[256];
      snprintf(buf, sizeof buf, "%s \xe2\x86\x90 %s", l->yname[p / l->nu], l->uname[p % l->nu]);
      T->names[k * np + p] = strdup(buf);
    }
}

static int bode_table(const bg_model *m, const bg_linear *l, table *T) {
  int np = l->ny * l->nu, nw = BODE_POINTS;
  double *re = bg_xcalloc((size_t)nw * np + 1, sizeof *re), *im = bg_xcalloc((size_t)nw * np + 1, sizeof *im);
  double *ph = bg_xcalloc((size_t)nw + 1, sizeof *ph);
  bg_plot_table_init(T, m->name, m->title, nw, np, 2);
  bg_linear_freqs(l, m, nw, T->r.t);
  int rc = bg_linear_freqresp(l, nw, T->r.t, re, im);
  for (int p = 0; p < np && rc == 0; p++) {
    for (int k = 0; k < nw; k++) {
      double mag = hypot(re[(size_t)p * nw + k], im[(size_t)p * nw + k]);
      T->r.values[(size_t)k * T->r.nout + p] = mag > 0 ? 20 * log10(mag) : -INFINITY;
    }
    bg_linear_phase(l, p, nw, T->r.t, re + (size_t)p * nw, im + (size_t)p * nw, ph);
    for (int k = 0; k < nw; k++) T->r.values[(size_t)k * T->r.nout + np + p] = ph[k];
  }
  pair_names(T, l, 2);
  T->title[0] = "Bode diagram", T->ylabel[0] = "magnitude [dB]", T->ylabel[1] = "phase [\xc2\xb0]";
  free(re), free(im), free(ph);
  return rc;
}

static int step_table(const bg_model *m, const bg_linear *l, table *T) {
  int np = l->ny * l->nu, nt = TIME_POINTS;
  double t_end = bg_linear_t_end(l, m);
  double *y = bg_xcalloc((size_t)nt * np + 1, sizeof *y);
  bg_plot_table_init(T, m->name, m->title, nt, np, 2);
  int rc = 0;
  for (int imp = 0; imp < 2 && rc == 0; imp++) {
    rc = bg_linear_step(l, t_end, nt, imp, y);
    for (int p = 0; p < np && rc == 0; p++)
      for (int k = 0; k < nt; k++) T->r.values[(size_t)k * T->r.nout + imp * np + p] = y[(size_t)p * nt + k];
  }
  for (int k = 0; k < nt; k++) T->r.t[k] = t_end * k / (nt - 1);
  pair_names(T, l, 2);
  T->title[0] = "Unit step response", T->title[1] = "Unit impulse response";
  T->ylabel[0] = T->ylabel[1] = "";
  free(y);
  return rc;
}

/* ------------------------------------------------------------ Nyquist */
typedef bg_plot_xy nyq;
static double nx(const nyq *N, double v) { return bg_plot_xy_x(N, v); }
static double ny(const nyq *N, double v) { return bg_plot_xy_y(N, v); }

double bg_plot_xy_x(const bg_plot_xy *N, double v) {
  return N->left + (v - N->x.lo) / (N->x.hi - N->x.lo) * (N->right - N->left);
}
double bg_plot_xy_y(const bg_plot_xy *N, double v) {
  return N->bot - (v - N->y.lo) / (N->y.hi - N->y.lo) * (N->bot - N->top);
}

void bg_plot_xy_axes(bg_plot_xy *N, const char *xl, const char *yl) {
  bg_scene_item *it = bg_scene_begin(N->s, BG_ITEM_STROKE, "grid 1");
  it->color = N->st->muted, it->color.a *= 0.45, it->width = 0.5;
  char buf[96];
  for (int i = 0; i < N->x.n; i++)
    bg_scene_move(N->s, nx(N, bg_plot_tick(&N->x, i)), N->top), bg_scene_line(N->s, nx(N, bg_plot_tick(&N->x, i)), N->bot);
  for (int i = 0; i < N->y.n; i++)
    bg_scene_move(N->s, N->left, ny(N, bg_plot_tick(&N->y, i))), bg_scene_line(N->s, N->right, ny(N, bg_plot_tick(&N->y, i)));
  it = bg_scene_begin(N->s, BG_ITEM_STROKE, "panel 1");
  it->color = N->st->fg, it->width = 0.6;
  bg_scene_move(N->s, N->left, N->top), bg_scene_line(N->s, N->right, N->top);
  bg_scene_line(N->s, N->right, N->bot), bg_scene_line(N->s, N->left, N->bot), bg_scene_close(N->s);
  double fs = 0.8 * N->st->font_size;
  for (int i = 0; i < N->x.n; i++)
    bg_scene_text(N->s, bg_plot_tick_label(&N->x, i, buf, sizeof buf), nx(N, bg_plot_tick(&N->x, i)),
                  N->bot + 5, fs, 0.5, 0, N->st->fg, "tick x");
  for (int i = 0; i < N->y.n; i++)
    bg_scene_text(N->s, bg_plot_tick_label(&N->y, i, buf, sizeof buf), N->left - 5,
                  ny(N, bg_plot_tick(&N->y, i)), fs, 1, 0.5, N->st->fg, "tick y 1");
  double fl = 0.9 * N->st->font_size;
  char scale[128], lab[256];
  bg_plot_scale_markup(N->x.exp3, fl, scale, sizeof scale); /* the axes' powers of ten by their names */
  snprintf(lab, sizeof lab, "%s%s%s", xl, *scale ? " " : "", scale);
  bg_scene_text(N->s, lab, (N->left + N->right) / 2, N->bot + 8 + fs * 1.4, fl, 0.5, 0, N->st->fg, "xlabel");
  bg_plot_scale_markup(N->y.exp3, fl, scale, sizeof scale);
  snprintf(lab, sizeof lab, "%s%s%s", yl, *scale ? " " : "", scale);
  bg_scene_text(N->s, lab, 8, N->top - 4, fl, 0, 1, N->st->fg, "ylabel 1");
}

/* The visible points of one branch in screen coordinates, in the order of
 * increasing frequency (the mirror, w < 0, runs from -w_max to -w_min:
 * backwards through the data); a point outside the axes (or not finite)
 * starts a new run: brk[i] = 1. Returns the count. */
static int nyq_points(const nyq *N, const double *re, const double *im, int nw, int mirror, double *px,
                      double *py, unsigned char *brk) {
  int m = 0, down = 0;
  for (int q = 0; q < nw; q++) {
    int k = mirror ? nw - 1 - q : q;
    double x = re[k], y = mirror ? -im[k] : im[k];
    if (!isfinite(x) || !isfinite(y) || x < N->x.lo || x > N->x.hi || y < N->y.lo || y > N->y.hi) {
      down = 0;
      continue;
    }
    px[m] = nx(N, x), py[m] = ny(N, y), brk[m++] = !down;
    down = 1;
  }
  return m;
}

/* Filled arrowheads pointing along the branch (increasing frequency) at 1/3
 * and 2/3 of its visible length, each centred on the curve. */
static void nyq_arrows(nyq *N, const double *px, const double *py, const unsigned char *brk, int m, int j,
                       int mirror) {
  double total = 0;
  for (int i = 1; i < m; i++) if (!brk[i]) total += hypot(px[i] - px[i - 1], py[i] - py[i - 1]);
  if (!(total > 30)) return; /* too short to carry arrows */
  for (int a = 1; a <= 2; a++) {
    double want = total * a / 3, run = 0;
    for (int i = 1; i < m; i++) {
      if (brk[i]) continue;
      double dx = px[i] - px[i - 1], dy = py[i] - py[i - 1], len = hypot(dx, dy);
      if (run + len < want || len == 0) { run += len; continue; }
      double f = (want - run) / len, cx = px[i - 1] + f * dx, cy = py[i - 1] + f * dy;
      double ux = dx / len, uy = dy / len, h = mirror ? 5 : 7, w = mirror ? 2.2 : 3;
      bg_scene_item *it = bg_scene_begin(N->s, BG_ITEM_FILL, "arrow 1.%d%s", j + 1, mirror ? " mirror" : "");
      bg_plot_curve_style(N->st, j, it);
      it->fill = it->color, it->width = 0, it->dash[0] = it->dash[1] = 0;
      bg_scene_move(N->s, cx + ux * h / 2, cy + uy * h / 2); /* the tip */
      bg_scene_line(N->s, cx - ux * h / 2 - uy * w, cy - uy * h / 2 + ux * w);
      bg_scene_line(N->s, cx - ux * h / 2 + uy * w, cy - uy * h / 2 - ux * w);
      bg_scene_close(N->s);
      break;
    }
  }
}

/* H(jw) for w > 0 in the pair's style, its mirror (w < 0) thinner and
 * dashed; arrows in the direction of increasing frequency on both. */
static void nyq_curve(nyq *N, const double *re, const double *im, int nw, int j) {
  double *px = bg_xcalloc((size_t)nw + 1, sizeof *px), *py = bg_xcalloc((size_t)nw + 1, sizeof *py);
  unsigned char *brk = bg_xcalloc((size_t)nw + 1, 1);
  for (int mirror = 0; mirror < 2; mirror++) {
    int m = nyq_points(N, re, im, nw, mirror, px, py, brk);
    bg_scene_item *it = bg_scene_begin(N->s, BG_ITEM_STROKE, "curve 1.%d%s", j + 1, mirror ? " mirror" : "");
    bg_plot_curve_style(N->st, j, it);
    if (mirror) it->width *= 0.6, it->round = 0, it->dash[0] = 3, it->dash[1] = 2.5;
    for (int i = 0; i < m; i++) {
      if (brk[i]) bg_scene_move(N->s, px[i], py[i]);
      else bg_scene_line(N->s, px[i], py[i]);
    }
    nyq_arrows(N, px, py, brk, m, j, mirror);
  }
  free(px), free(py), free(brk);
}

/* The data range with the critical point -1 + 0j, clipped to a few times
 * the median magnitude so that a pole on the axis does not flatten the rest. */
static void nyq_range(const double *re, const double *im, int n, double *lim) {
  double *mag = bg_xcalloc((size_t)n + 1, sizeof *mag);
  int k = 0;
  for (int i = 0; i < n; i++) if (isfinite(re[i]) && isfinite(im[i])) mag[k++] = hypot(re[i], im[i]);
  double cap = HUGE_VAL;
  if (k) {
    bg_sort_doubles(mag, (size_t)k); /* by insertion: 6 s for 61 200 magnitudes (153 pairs) */
    cap = 20 * fmax(mag[k / 2], 1e-300);
  }
  lim[0] = lim[2] = -1, lim[1] = lim[3] = 0;
  for (int i = 0; i < n; i++) {
    if (!isfinite(re[i]) || !isfinite(im[i]) || hypot(re[i], im[i]) > cap) continue;
    lim[0] = fmin(lim[0], re[i]), lim[1] = fmax(lim[1], re[i]);
    lim[2] = fmin(lim[2], -fabs(im[i])), lim[3] = fmax(lim[3], fabs(im[i]));
  }
  free(mag);
}

static int nyquist_scene(const bg_model *m, const bg_linear *l, const bg_style *st, double W, bg_scene *out) {
  int np = l->ny * l->nu, nw = BODE_POINTS;
  double *w = bg_xcalloc(nw + 1, sizeof *w), *re = bg_xcalloc((size_t)nw * np + 1, sizeof *re);
  double *im = bg_xcalloc((size_t)nw * np + 1, sizeof *im), lim[4];
  bg_linear_freqs(l, m, nw, w);
  int rc = bg_linear_freqresp(l, nw, w, re, im);
  nyq_range(re, im, nw * np, lim);
  nyq N = {.st = st, .s = out, .left = 50, .right = W - 14, .top = 40, .bot = W * 0.62};
  bg_plot_axis_make(lim[0], lim[1], 8, 1, &N.x);
  bg_plot_axis_make(lim[2], lim[3], 7, 1, &N.y);
  bg_scene_text(out, "<b>Nyquist diagram</b>", W / 2, 8, st->font_size, 0.5, 0, st->fg, "title 1");
  bg_plot_xy_axes(&N, "Re H(j\xcf\x89)", "Im H(j\xcf\x89)");
  for (int p = 0; p < np && rc == 0; p++) nyq_curve(&N, re + (size_t)p * nw, im + (size_t)p * nw, nw, p);
  bg_scene_item *it = bg_scene_begin(out, BG_ITEM_STROKE, "critical point");
  it->color = st->conflict, it->width = 1.2;
  double cx = nx(&N, -1), cy = ny(&N, 0);
  bg_scene_move(out, cx - 4, cy), bg_scene_line(out, cx + 4, cy);
  bg_scene_move(out, cx, cy - 4), bg_scene_line(out, cx, cy + 4);
  for (int p = 0; p < np; p++) { /* legend below the axis name */
    char buf[256];
    double y = N.bot + 44 + 14 * p;
    it = bg_scene_begin(out, BG_ITEM_STROKE, "legend-sample 1");
    bg_plot_curve_style(st, p, it);
    bg_scene_move(out, N.left, y), bg_scene_line(out, N.left + 24, y);
    bg_strbuf b = {0};
    snprintf(buf, sizeof buf, "%s \xe2\x86\x90 %s", l->yname[p / l->nu], l->uname[p % l->nu]);
    bg_markup_escapen(&b, buf, strlen(buf));
    bg_scene_text(out, bg_sb_str(&b), N.left + 28, y, 0.85 * st->font_size, 0, 0.5, st->fg, "legend 1");
    bg_sb_free(&b);
  }
  if (out->width < W) out->width = W;
  double h = N.bot + 52 + 14 * np;
  if (out->height < h) out->height = ceil(h);
  free(w), free(re), free(im);
  return rc;
}

/* ------------------------------------------------------------ API */
int bg_plot_linear_scene(const bg_model *m, const bg_linear *l, int kind, const bg_style *st,
                         double width, bg_scene *out) {
  if (!l->ok || l->nu * l->ny == 0) return -1;
  if (kind == BG_PLOT_NYQUIST) return nyquist_scene(m, l, st, width, out);
  table T;
  int rc = kind == BG_PLOT_BODE ? bode_table(m, l, &T) : step_table(m, l, &T);
  static const bg_plot_spec bode = {1, "\xcf\x89", "rad/s", 2, 0, 0}, time = {0, "t", NULL, 0, 0, 0};
  if (rc == 0) bg_plot_scene_spec(&T.m, &T.r, kind == BG_PLOT_BODE ? &bode : &time, st, width, 0, out);
  bg_plot_table_free(&T);
  return rc;
}

int bg_plot_linear_table(const bg_model *m, const bg_linear *l, int kind, bg_plot_table *T) {
  if (!l->ok || l->nu * l->ny == 0 || kind == BG_PLOT_NYQUIST) return -1;
  int rc = kind == BG_PLOT_BODE ? bode_table(m, l, T) : step_table(m, l, T);
  if (rc != 0) bg_plot_table_free(T);
  return rc;
}

int bg_plot_linear_render(const bg_model *m, const bg_linear *l, int kind, const char *style,
                          const char *style_dir, const char *fmt, const char *path,
                          bg_strbuf *out, bg_diags *dg) {
  static const char *const what[] = {"Bode diagram", "Nyquist diagram", "step and impulse responses"};
  bg_style st;
  if (bg_style_load(&st, style, style_dir, dg) != 0) return BG_RENDER_ERROR;
  bg_scene sc;
  bg_scene_init(&sc, st.font);
  sc.background = st.background;
  char title[300];
  snprintf(title, sizeof title, "%s: %s", m->title ? m->title : m->name, what[kind]);
  sc.title = bg_arena_strdup(&sc.arena, title);
  int rc = BG_RENDER_ERROR;
  if (bg_plot_linear_scene(m, l, kind, &st, WIDTH, &sc) != 0)
    bg_diag_error(dg, (bg_srcloc){0}, "no %s for '%s': %s", what[kind], path ? path : "the plot",
                  !l->reduced && kind == BG_PLOT_STEP ? "no state space (descriptor form only)"
                  : l->nu * l->ny == 0 ? "no inputs or no outputs" : "the responses could not be computed");
  else rc = bg_plot_render_scene(&sc, fmt, st.png_scale, out, dg);
  bg_scene_free(&sc);
  return rc;
}
