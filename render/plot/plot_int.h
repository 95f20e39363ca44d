/* SPDX-License-Identifier: BSD-3-Clause */
/* Axis maths of the simulation plots (render/plot_axis.c), shared by
 * plot.c and the unit tests: "nice" tick steps (1, 2, 5 x 10^k), axis
 * limits and tick labels with SI prefixes. Conventions: docs/plots.md. */
#ifndef BG_PLOT_INT_H
#define BG_PLOT_INT_H
#include <stddef.h>

#include "scene/scene.h"
#include "scene/style.h"

/* exp3 of an axis whose values are too large or small for an SI prefix
 * (beyond 10^±24): labels are written in e-notation. */
enum { BG_PLOT_NO_PREFIX = 999 };

typedef struct bg_plot_axis {
  double lo, hi;   /* axis limits */
  double step;     /* tick spacing: 1, 2 or 5 x 10^k */
  double k0;       /* first tick = k0 * step (an integer), so ticks are exact multiples */
  int n;           /* ticks: (k0 + i) * step, i = 0 .. n-1, all within [lo, hi] (to 1e-9 step) */
  int exp3;        /* the labels' SI prefix as a power of ten (multiple of 3), or
                      BG_PLOT_NO_PREFIX */
  int decimals;    /* digits after the point, the same on every label */
} bg_plot_axis;

/* The smallest step of the form 1, 2 or 5 x 10^k that is >= raw (raw > 0;
 * anything else gives 1); near DBL_MAX the largest finite one below. */
double bg_plot_nice_step(double raw);

/* Ticks for data in [lo, hi] (either order; non-finite ends are ignored; an
 * empty or zero-width range gets a sensible one around the value: ±10 %, or
 * ±1 around 0) with at most about maxn intervals and at least two ticks where
 * possible. pad: the limits are the data range plus 5 % on either side (value
 * axes); else exactly lo, hi (the time axis). The ticks are multiples of the
 * step within the limits. */
void bg_plot_axis_make(double lo, double hi, int maxn, int pad, bg_plot_axis *ax);

/* Ticks for angles in degrees over [lo, hi]: multiples of 45 (90 when the
 * range is large, doubling further to stay within maxn intervals); the
 * limits are the enclosing multiples of the step. */
void bg_plot_axis_degrees(double lo, double hi, int maxn, bg_plot_axis *ax);

/* Value of tick i. */
double bg_plot_tick(const bg_plot_axis *ax, int i);

/* Label of tick i: the value divided by 10^exp3 with ax->decimals digits,
 * U+2212 for minus, "0" for zero; the scale belongs in the axis' name (the
 * time axis' prefix "t [ms]", a value axis' bg_plot_scale_markup). Returns
 * buf. */
char *bg_plot_tick_label(const bg_plot_axis *ax, int i, char *buf, size_t n);

/* A value axis' scale as pango markup for text of fs points: "×10" and the
 * exponent exp3 as a superscript ("×10⁻³"); "" for exp3 0 or e-notation
 * labels. Returns buf. */
char *bg_plot_scale_markup(int exp3, double fs, char *buf, size_t n);

/* before, "10" and k as a superscript for text of fs points (a log axis'
 * decade "10⁻³", a value axis' scale "×10⁻³"). Returns buf. */
char *bg_plot_power_markup(const char *before, int k, double fs, char *buf, size_t n);

/* "µ", "m", "", "k", ... for exp3 in -24 .. 24 (multiple of 3), else "". */
const char *bg_plot_si_prefix(int exp3);

/* A value formatted with the axis' prefix and %.6g ("772.578 m"); used for
 * the time where a partial run stopped. Returns buf. */
char *bg_plot_format_value(double v, int exp3, char *buf, size_t n);

/* An x-y plot area with its two value axes (the Nyquist diagram, the root
 * locus; plot_linear.c): the data's x and y in page points, and the grid,
 * frame, tick labels and axis names drawn in the simulation plots' look. */
typedef struct bg_plot_xy {
  const bg_style *st;
  bg_scene *s;
  double left, right, top, bot;
  bg_plot_axis x, y;
} bg_plot_xy;
double bg_plot_xy_x(const bg_plot_xy *N, double v);
double bg_plot_xy_y(const bg_plot_xy *N, double v);
void bg_plot_xy_axes(bg_plot_xy *N, const char *xlabel, const char *ylabel);
#endif
