/* SPDX-License-Identifier: BSD-3-Clause */
/* Plots of a parameter study (docs/study.md) in the simulation plots' look,
 * through bg_plot_scene_spec (the data become rows of a result, the panels
 * a small model, as plot_linear.c does):
 * - the family of curves: one panel per collected output; a sweep draws
 *   its runs (at most FAMILY_MAX, evenly chosen, the first and the last
 *   among them), named by their param values in the legend; a Monte Carlo
 *   study draws the envelope of its runs: minimum, 5 % quantile, mean,
 *   95 % quantile and maximum at each time;
 * - the quantities against the swept param: one panel per quantity, one
 *   curve per combination of the other params of a grid. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/sort.h"
#include "plot/plot.h"
#include "plot/plot_linear.h"
#include "diagram/render.h"

enum { FAMILY_MAX = 12, QUANTITY_CURVES_MAX = 12 };
#define WIDTH 540.0

typedef bg_plot_table table;

/* A param's value in a legend: six significant digits (a Monte Carlo
 * draw's full digits are in the table). */
static char *fmt_num(double v) {
  char buf[40];
  snprintf(buf, sizeof buf, "%.6g", v);
  return strdup(buf);
}

/* "R0 = 5, L0 = 0.001" for the params from index from on */
static char *param_words(const bg_study *st, const bg_study_run *r, int from) {
  bg_strbuf b = {0};
  for (int k = from; k < st->spec->nparams; k++) {
    char *v = fmt_num(r->param[k]);
    bg_sb_printf(&b, "%s%s = %s", k > from ? ", " : "", st->spec->params[k].name, v);
    free(v);
  }
  return b.s ? b.s : strdup("");
}

/* The runs that have trajectories on the first such run's time grid. */
static int grid_runs(const bg_study *st, long *idx) {
  int n = 0;
  const bg_study_run *ref = NULL;
  for (long i = 0; i < st->count; i++) {
    const bg_study_run *r = &st->runs[i];
    if (r->status != BG_STUDY_OK || !r->nrows) continue;
    if (!ref) ref = r;
    if (r->nrows != ref->nrows || memcmp(r->t, ref->t, (size_t)r->nrows * sizeof(double))) continue;
    idx[n++] = i;
  }
  return n;
}

/* Quantile q of sorted v[0..n) (linear between order statistics). */
static double quantile(const double *v, int n, double q) {
  double h = (n - 1) * q;
  int lo = (int)floor(h);
  return lo + 1 < n ? v[lo] + (h - lo) * (v[lo + 1] - v[lo]) : v[n - 1];
}

static int family_table(const bg_study *st, table *T, char *why, size_t nwhy) {
  long *idx = bg_xcalloc((size_t)st->count + 1, sizeof(long));
  int n = grid_runs(st, idx);
  if (n == 0) {
    snprintf(why, nwhy, "no run of the study succeeded");
    free(idx);
    return -1;
  }
  int mc = st->spec->kind == BG_STUDY_MONTE_CARLO, nc = st->ncurve;
  int ncurve = mc ? 5 : n < FAMILY_MAX ? n : FAMILY_MAX;
  const bg_study_run *ref = &st->runs[idx[0]];
  int rows = ref->nrows;
  bg_plot_table_init(T, st->title, st->title, rows, ncurve, nc);
  memcpy(T->r.t, ref->t, (size_t)rows * sizeof(double));
  double *col = bg_xcalloc((size_t)n + 1, sizeof(double));
  for (int c = 0; c < nc; c++) {
    /* the panel says what it shows: the figure may stand alone in a document */
    bg_strbuf tb = {0};
    bg_sb_printf(&tb, "%s: ", st->curve_name[c]);
    if (mc) bg_sb_printf(&tb, "envelope of %d runs", n);
    else if (ncurve < n) bg_sb_printf(&tb, "%d of %d runs", ncurve, n);
    else bg_sb_printf(&tb, "%d run%s", n, n == 1 ? "" : "s");
    if (n < st->count) bg_sb_printf(&tb, " (%ld in the study)", st->count); /* failed or off the grid */
    T->title[c] = T->own_title[c] = tb.s;
    if (mc) {
      static const char *names[] = {"minimum", "5 % quantile", "mean", "95 % quantile", "maximum"};
      for (int j = 0; j < 5; j++) T->names[c * 5 + j] = strdup(names[j]);
      for (int row = 0; row < rows; row++) {
        double sum = 0;
        for (int i = 0; i < n; i++) col[i] = st->runs[idx[i]].curve[(size_t)row * nc + c], sum += col[i];
        bg_sort_doubles(col, (size_t)n);
        double *out = &T->r.values[(size_t)row * T->r.nout + c * 5];
        out[0] = col[0], out[1] = quantile(col, n, 0.05), out[2] = sum / n;
        out[3] = quantile(col, n, 0.95), out[4] = col[n - 1];
      }
    } else {
      for (int j = 0; j < ncurve; j++) {
        /* evenly chosen: the first and the last run always among them */
        long i = ncurve == 1 ? 0 : (long)((double)j * (n - 1) / (ncurve - 1) + 0.5);
        const bg_study_run *r = &st->runs[idx[i]];
        T->names[c * ncurve + j] = param_words(st, r, 0);
        for (int row = 0; row < rows; row++)
          T->r.values[(size_t)row * T->r.nout + c * ncurve + j] = r->curve[(size_t)row * nc + c];
      }
    }
  }
  free(col), free(idx);
  return 0;
}

/* The quantities against the first param: runs in the grid's order, so for
 * each combination of the other params the first param's values are
 * consecutive rows (stride = the other params' count). */
static int quantity_table(const bg_study *st, table *T, char *why, size_t nwhy) {
  const bg_study_spec *s = st->spec;
  if (s->kind != BG_STUDY_SWEEP || st->count != st->nruns) {
    snprintf(why, nwhy, "%s", s->kind != BG_STUDY_SWEEP
                                  ? "the quantities are drawn against a swept param (--sweep), "
                                    "not against Monte Carlo draws"
                                  : "the quantities are drawn from the whole study, not a part");
    return -1;
  }
  int nx = s->params[0].nvalues;
  long stride = st->nruns / nx;
  int ncurve = stride < QUANTITY_CURVES_MAX ? (int)stride : QUANTITY_CURVES_MAX;
  bg_plot_table_init(T, st->title, st->title, nx, ncurve, st->ncollect);
  for (int x = 0; x < nx; x++) T->r.t[x] = s->params[0].values[x];
  for (int q = 0; q < st->ncollect; q++) {
    T->title[q] = st->collect[q].label;
    T->xlabel[q] = s->params[0].name;
    for (int j = 0; j < ncurve; j++) {
      T->names[q * ncurve + j] = stride > 1 ? param_words(st, &st->runs[j], 1) : strdup(st->collect[q].label);
      for (int x = 0; x < nx; x++) {
        const bg_study_run *r = &st->runs[(long)x * stride + j];
        T->r.values[(size_t)x * T->r.nout + q * ncurve + j] = r->status == BG_STUDY_OK ? r->value[q] : NAN;
      }
    }
  }
  return 0;
}

/* The Bode family: for each input/output pair a magnitude and a phase
 * panel, one curve per run drawn, named by its param values. */
static int bode_table(const bg_study *st, const bg_study_bode *b, table *T, char *why, size_t nwhy) {
  if (!b || !b->nrun) {
    snprintf(why, nwhy, "no Bode family was computed");
    return -1;
  }
  int nr = b->nrun, np = b->npair, nw = b->nw;
  bg_plot_table_init(T, st->title, st->title, nw, nr, 2 * np);
  memcpy(T->r.t, b->w, (size_t)nw * sizeof(double));
  for (int p = 0; p < np; p++)
    for (int half = 0; half < 2; half++) {
      int panel = 2 * p + half;
      T->title[panel] = half ? NULL : b->pair_name[p];
      T->ylabel[panel] = half ? "phase [\xc2\xb0]" : "magnitude [dB]";
      for (int j = 0; j < nr; j++) {
        T->names[panel * nr + j] = param_words(st, &st->runs[b->run[j]], 0);
        const double *src = (half ? b->phase : b->mag) + ((size_t)j * np + p) * nw;
        for (int k = 0; k < nw; k++) T->r.values[(size_t)k * T->r.nout + panel * nr + j] = src[k];
      }
    }
  return 0;
}

int bg_study_plot_scene(const bg_study *st, int kind, const bg_study_bode *bode, const bg_style *sty,
                        double width, bg_scene *out, char *why, size_t nwhy) {
  if (kind == BG_STUDY_PLOT_LOCUS) return bg_study_locus_scene(st, sty, width, out, why, nwhy);
  table T;
  int rc = kind == BG_STUDY_PLOT_FAMILY ? family_table(st, &T, why, nwhy)
         : kind == BG_STUDY_PLOT_BODE   ? bode_table(st, bode, &T, why, nwhy)
                                        : quantity_table(st, &T, why, nwhy);
  if (rc) return -1;
  const bg_study_param *p0 = &st->spec->params[0];
  size_t ls = strlen(p0->spec);
  bg_plot_spec spec = {0};
  spec.legend_once = 1; /* every panel shows the same runs (or envelope lines) */
  if (kind == BG_STUDY_PLOT_QUANTITIES) {
    spec.xlog = ls > 4 && !strcmp(p0->spec + ls - 4, ":log");
    spec.xname = p0->name, spec.xunit = "";
  } else if (kind == BG_STUDY_PLOT_BODE) {
    spec.xlog = 1, spec.xname = "\xcf\x89", spec.xunit = "rad/s";
    for (int p = 0; p < bode->npair && 2 * p + 1 < 32; p++) spec.angle_mask |= 1u << (2 * p + 1);
  }
  bg_plot_scene_spec(&T.m, &T.r, &spec, sty, width, 0, out);
  bg_plot_table_free(&T);
  return 0;
}

int bg_study_plot_render(const bg_study *st, int kind, const bg_study_bode *bode, const char *style,
                         const char *style_dir, const char *fmt, const char *path, bg_strbuf *out,
                         bg_diags *dg) {
  bg_style sty;
  if (bg_style_load(&sty, style, style_dir, dg) != 0) return BG_RENDER_ERROR;
  bg_scene sc;
  bg_scene_init(&sc, sty.font);
  sc.background = sty.background;
  static const char *const what[] = {"collected quantities", "family of runs", "root locus",
                                     "Bode family"};
  char title[300], why[200];
  snprintf(title, sizeof title, "%s: %s", st->title,
           kind == BG_STUDY_PLOT_FAMILY && st->spec->kind == BG_STUDY_MONTE_CARLO
               ? "Monte Carlo envelope" : what[kind]);
  sc.title = bg_arena_strdup(&sc.arena, title);
  int rc = BG_RENDER_ERROR;
  if (bg_study_plot_scene(st, kind, bode, &sty, WIDTH, &sc, why, sizeof why))
    bg_diag_error(dg, (bg_srcloc){0}, "no study plot for '%s': %s", path ? path : "the plot", why);
  else rc = bg_plot_render_scene(&sc, fmt, sty.png_scale, out, dg);
  bg_scene_free(&sc);
  return rc;
}
