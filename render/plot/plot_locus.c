/* SPDX-License-Identifier: BSD-3-Clause */
/* The root locus of a parameter study (docs/study.md, "Linear studies"):
 * every run's poles in the complex plane, each a dot coloured by the run's
 * value of the first param on a colour scale (logarithmic for a :log
 * range). In a sweep the poles of consecutive values of the first param
 * (the other params of a grid fixed) are joined into branches, each pole
 * to the nearest pole of the next run not yet taken, and an arrowhead
 * halfway along each branch points the way the param grows. A Monte Carlo
 * study draws the cloud of its poles, without branches. The imaginary axis
 * (the stability boundary) is always in view. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "plot/plot.h"
#include "plot/plot_int.h"

enum { LOCUS_MAX_RUNS = 4000, SCALE_STEPS = 48 };

/* A perceptually even scale from dark blue through green to yellow-green
 * (viridis' course, its palest end left out so every dot shows on white). */
static bg_rgba scale_colour(double f) {
  static const double c[][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {200, 220, 50}};
  f = f < 0 ? 0 : f > 1 ? 1 : f;
  double x = f * 4;
  int i = x >= 4 ? 3 : (int)x;
  double u = x - i;
  return (bg_rgba){(c[i][0] + u * (c[i + 1][0] - c[i][0])) / 255,
                   (c[i][1] + u * (c[i + 1][1] - c[i][1])) / 255,
                   (c[i][2] + u * (c[i + 1][2] - c[i][2])) / 255, 1};
}

typedef struct locus {
  const bg_study *st;
  bg_plot_xy N;
  double plo, phi; /* the first param's range */
  int plog;
} locus;

static double scale_pos(const locus *L, double v) {
  if (!(L->phi > L->plo)) return 0.5;
  return L->plog ? (log(v) - log(L->plo)) / (log(L->phi) - log(L->plo)) : (v - L->plo) / (L->phi - L->plo);
}

static int visible(const locus *L, double re, double im) {
  return isfinite(re) && isfinite(im) && re >= L->N.x.lo && re <= L->N.x.hi && im >= L->N.y.lo &&
         im <= L->N.y.hi;
}

/* The branches of one sequence of runs (seq[0..n), the first param growing):
 * at[k] follows pole k of the sequence's first run through the others. */
static void branches(locus *L, const long *seq, int n) {
  const bg_study *st = L->st;
  int np = st->runs[seq[0]].npole;
  if (n < 2 || np == 0) return;
  int *at = bg_xcalloc((size_t)np * n, sizeof *at);
  unsigned char *taken = bg_xcalloc((size_t)np + 1, 1);
  for (int k = 0; k < np; k++) at[k] = k;
  for (int s = 1; s < n; s++) {
    const bg_study_run *a = &st->runs[seq[s - 1]], *b = &st->runs[seq[s]];
    memset(taken, 0, (size_t)np);
    for (int k = 0; k < np; k++) {
      int from = at[(size_t)(s - 1) * np + k], best = -1;
      double bd = HUGE_VAL;
      for (int q = 0; q < b->npole && q < np; q++) {
        double d = hypot(b->pole_re[q] - a->pole_re[from], b->pole_im[q] - a->pole_im[from]);
        if (!taken[q] && d < bd) bd = d, best = q;
      }
      if (best < 0) best = from; /* fewer poles: the branch stops (drawn below up to here) */
      taken[best] = 1;
      at[(size_t)s * np + k] = best;
    }
  }
  bg_plot_xy *N = &L->N;
  for (int k = 0; k < np; k++) {
    bg_scene_item *it = bg_scene_begin(N->s, BG_ITEM_STROKE, "branch %d", k + 1);
    it->color = N->st->muted, it->width = 0.7, it->round = 1;
    double total = 0, *len = bg_xcalloc((size_t)n + 1, sizeof *len);
    for (int s = 0; s < n; s++) {
      const bg_study_run *r = &st->runs[seq[s]];
      int q = at[(size_t)s * np + k];
      double x = bg_plot_xy_x(N, r->pole_re[q]), y = bg_plot_xy_y(N, r->pole_im[q]);
      if (s == 0) bg_scene_move(N->s, x, y);
      else {
        const bg_study_run *p = &st->runs[seq[s - 1]];
        int qp = at[(size_t)(s - 1) * np + k];
        len[s] = hypot(x - bg_plot_xy_x(N, p->pole_re[qp]), y - bg_plot_xy_y(N, p->pole_im[qp]));
        total += len[s];
        bg_scene_line(N->s, x, y);
      }
    }
    /* the arrowhead halfway along the branch's drawn length */
    double half = total / 2, run = 0;
    for (int s = 1; s < n && total > 12; s++) {
      if (run + len[s] < half || len[s] < 1e-9) { run += len[s]; continue; }
      const bg_study_run *p = &st->runs[seq[s - 1]], *r = &st->runs[seq[s]];
      int qp = at[(size_t)(s - 1) * np + k], q = at[(size_t)s * np + k];
      double x0 = bg_plot_xy_x(N, p->pole_re[qp]), y0 = bg_plot_xy_y(N, p->pole_im[qp]);
      double x1 = bg_plot_xy_x(N, r->pole_re[q]), y1 = bg_plot_xy_y(N, r->pole_im[q]);
      double f = (half - run) / len[s], cx = x0 + f * (x1 - x0), cy = y0 + f * (y1 - y0);
      double ux = (x1 - x0) / len[s], uy = (y1 - y0) / len[s], h = 7, w = 3;
      it = bg_scene_begin(N->s, BG_ITEM_FILL, "arrow %d", k + 1);
      it->color = it->fill = N->st->fg, it->width = 0;
      bg_scene_move(N->s, cx + ux * h / 2, cy + uy * h / 2);
      bg_scene_line(N->s, cx - ux * h / 2 - uy * w, cy - uy * h / 2 + ux * w);
      bg_scene_line(N->s, cx - ux * h / 2 + uy * w, cy - uy * h / 2 - ux * w);
      bg_scene_close(N->s);
      break;
    }
    free(len);
  }
  free(at), free(taken);
}

/* The colour bar under the plot: the first param's range, its ends named. */
static double colour_bar(locus *L, double y) {
  bg_plot_xy *N = &L->N;
  const bg_style *sty = N->st;
  double x0 = N->left, w = fmin(260, N->right - N->left), h = 9, fs = 0.8 * sty->font_size;
  for (int i = 0; i < SCALE_STEPS; i++) {
    bg_scene_item *it = bg_scene_begin(N->s, BG_ITEM_FILL, "scale");
    it->fill = it->color = scale_colour((i + 0.5) / SCALE_STEPS), it->width = 0;
    double a = x0 + w * i / SCALE_STEPS, b = x0 + w * (i + 1) / SCALE_STEPS + 0.3;
    bg_scene_move(N->s, a, y), bg_scene_line(N->s, b, y), bg_scene_line(N->s, b, y + h);
    bg_scene_line(N->s, a, y + h), bg_scene_close(N->s);
  }
  char lo[40], hi[40];
  snprintf(lo, sizeof lo, "%.6g", L->plo), snprintf(hi, sizeof hi, "%.6g", L->phi);
  bg_strbuf b = {0};
  bg_markup_escape(&b, L->st->spec->params[0].name);
  bg_sb_printf(&b, "%s", L->plog ? " (log scale)" : "");
  if (L->st->spec->kind == BG_STUDY_SWEEP) bg_sb_puts(&b, "; arrows: as it grows");
  bg_scene_text(N->s, lo, x0, y + h + 3, fs, 0, 0, sty->fg, "scale-label lo");
  bg_scene_text(N->s, hi, x0 + w, y + h + 3, fs, 1, 0, sty->fg, "scale-label hi");
  bg_scene_text(N->s, bg_sb_str(&b), x0 + w + 10, y + h / 2, fs, 0, 0.5, sty->fg, "scale-name");
  bg_sb_free(&b);
  return y + h + 3 + 1.4 * fs;
}

int bg_study_locus_scene(const bg_study *st, const bg_style *sty, double W, bg_scene *out, char *why,
                         size_t nwhy) {
  long *idx = bg_xcalloc(LOCUS_MAX_RUNS, sizeof *idx);
  int n = bg_study_pick(st, LOCUS_MAX_RUNS, idx), m = 0;
  for (int j = 0; j < n; j++) if (st->runs[idx[j]].npole > 0) idx[m++] = idx[j];
  if (m == 0) {
    snprintf(why, nwhy, "no run has poles (add --collect poles to a merged study)");
    free(idx);
    return -1;
  }
  locus L = {.st = st};
  const bg_study_param *p0 = &st->spec->params[0];
  size_t ls = strlen(p0->spec);
  L.plog = ls > 4 && !strcmp(p0->spec + ls - 4, ":log");
  double xlo = 0, xhi = 0, ymax = 0; /* the imaginary axis always in view */
  L.plo = HUGE_VAL, L.phi = -HUGE_VAL;
  for (int j = 0; j < m; j++) {
    const bg_study_run *r = &st->runs[idx[j]];
    L.plo = fmin(L.plo, r->param[0]), L.phi = fmax(L.phi, r->param[0]);
    for (int q = 0; q < r->npole; q++) {
      if (!isfinite(r->pole_re[q]) || !isfinite(r->pole_im[q])) continue;
      xlo = fmin(xlo, r->pole_re[q]), xhi = fmax(xhi, r->pole_re[q]);
      ymax = fmax(ymax, fabs(r->pole_im[q]));
    }
  }
  if (ymax == 0) ymax = 0.25 * fmax(xhi - xlo, 1e-300); /* real poles only: a band around the axis */
  L.N = (bg_plot_xy){.st = sty, .s = out, .left = 62, .right = W - 14, .top = 40, .bot = W * 0.62};
  bg_plot_axis_make(xlo, xhi, 8, 1, &L.N.x);
  bg_plot_axis_make(-ymax, ymax, 7, 1, &L.N.y);
  bg_scene_text(out, "<b>Root locus</b>", W / 2, 8, sty->font_size, 0.5, 0, sty->fg, "title 1");
  bg_plot_xy_axes(&L.N, "Re s [1/s]", "Im s [1/s]");
  bg_scene_item *it = bg_scene_begin(out, BG_ITEM_STROKE, "imaginary-axis");
  it->color = sty->fg, it->width = 0.6, it->dash[0] = 3, it->dash[1] = 2;
  bg_scene_move(out, bg_plot_xy_x(&L.N, 0), L.N.top), bg_scene_line(out, bg_plot_xy_x(&L.N, 0), L.N.bot);
  /* branches: the whole sweep, each combination of the other params in turn */
  const bg_study_spec *s = st->spec;
  if (s->kind == BG_STUDY_SWEEP && st->count == st->nruns && st->count <= LOCUS_MAX_RUNS) {
    long stride = st->nruns / s->params[0].nvalues;
    long *seq = bg_xcalloc((size_t)s->params[0].nvalues + 1, sizeof *seq);
    for (long j = 0; j < stride; j++) {
      int k = 0;
      for (int x = 0; x < s->params[0].nvalues; x++) {
        long i = (long)x * stride + j;
        const bg_study_run *r = &st->runs[i];
        if (r->status != BG_STUDY_OK || r->npole == 0 || (k && r->npole != st->runs[seq[0]].npole)) {
          branches(&L, seq, k), k = 0; /* a failed run, or a pole more or less, ends them */
          if (r->status != BG_STUDY_OK || r->npole == 0) continue;
        }
        seq[k++] = i;
      }
      branches(&L, seq, k);
    }
    free(seq);
  }
  for (int j = 0; j < m; j++) {
    const bg_study_run *r = &st->runs[idx[j]];
    bg_rgba c = scale_colour(scale_pos(&L, r->param[0]));
    for (int q = 0; q < r->npole; q++) {
      if (!visible(&L, r->pole_re[q], r->pole_im[q])) continue;
      it = bg_scene_begin(out, BG_ITEM_FILL, "pole run=%ld", st->first + idx[j]);
      it->fill = c, it->color = c, it->color.a = 0, it->width = 0;
      bg_scene_circle(out, bg_plot_xy_x(&L.N, r->pole_re[q]), bg_plot_xy_y(&L.N, r->pole_im[q]), 2.3);
    }
  }
  double y = colour_bar(&L, L.N.bot + 44);
  if (out->width < W) out->width = W;
  if (out->height < y + 8) out->height = ceil(y + 8);
  free(idx);
  return 0;
}
