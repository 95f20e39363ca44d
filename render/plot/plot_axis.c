/* SPDX-License-Identifier: BSD-3-Clause */
/* Axis maths of the simulation plots: 1-2-5 tick steps, axis limits that
 * survive zero-width, non-finite, tiny and huge ranges, tick labels scaled by
 * a power of ten (an SI prefix on the time axis, x10^k by a value axis' name). Pure functions (no text measurement), tested directly. */
#include "plot/plot_int.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---------------------------------------------------------------- steps */
/* m x 10^e computed so that negative powers are exact decimals (2/10, not 2*0.1). */
static double scaled(double m, int e) { return e >= 0 ? m * pow(10, e) : m / pow(10, -e); }

double bg_plot_nice_step(double raw) {
  if (!(raw > 0) || !isfinite(raw)) return 1;
  int e = (int)floor(log10(raw));
  static const double mant[] = {1, 2, 5, 10};
  for (int i = 0; i < 4; i++) {
    double s = scaled(mant[i], e);
    if (!isfinite(s)) return i > 0 ? scaled(mant[i - 1], e) : raw; /* beyond DBL_MAX */
    if (s > 0 && s >= raw * (1 - 1e-12)) return s;
  }
  return raw; /* subnormal corner cases */
}

/* The next smaller 1-2-5 step (10 -> 5 -> 2 -> 1). */
static double step_down(double step) {
  double e = floor(log10(step) + 1e-9), m = step / pow(10, e);
  return m > 4 ? step * 0.4 : step * 0.5;
}

/* ---------------------------------------------------------------- limits */
/* Puts the data range in order and gives empty, non-finite and zero-width
 * ranges a sensible width around their value. */
static void sane_range(double *lo, double *hi) {
  double a = *lo, b = *hi;
  if (!isfinite(a) && !isfinite(b)) a = 0, b = 1;
  else if (!isfinite(a)) a = b;
  else if (!isfinite(b)) b = a;
  if (a > b) { double t = a; a = b; b = t; }
  double mag = fmax(fabs(a), fabs(b));
  if (b * 0.5 - a * 0.5 > 0.5e-12 * mag && b - a > DBL_MIN) {
    *lo = a, *hi = b;
    return;
  }
  /* constant (or equal to the last few bits): ±10 % of the value, ±1 around 0 */
  double v = a * 0.5 + b * 0.5, d = v == 0 ? 1 : 0.1 * fabs(v);
  *lo = v - d, *hi = v + d;
  if (!isfinite(*lo)) *lo = -DBL_MAX;
  if (!isfinite(*hi)) *hi = DBL_MAX;
}

/* Tick indices within [lo, hi] for step; returns the count (may be 0). */
static double tick_range(double lo, double hi, double step, double *k0) {
  double kf = ceil(lo / step - 1e-9), kl = floor(hi / step + 1e-9);
  *k0 = kf;
  return kl - kf + 1;
}

/* Value axes: 5 % of the range on either side, so curves keep off the frame. */
static void pad_range(double *lo, double *hi) {
  double pad = 0.05 * (*hi * 0.5 - *lo * 0.5) * 2;
  double a = *lo - pad, b = *hi + pad;
  *lo = isfinite(a) ? a : -DBL_MAX;
  *hi = isfinite(b) ? b : DBL_MAX;
}

/* The labels' power of ten: a multiple of 3 (the SI prefix of the time axis'
 * unit); a value axis (plain) prints its numbers as they are from 0.01 to
 * 9999 ("0.25", "1500") and takes a power of ten only outside. */
static void label_format(bg_plot_axis *ax, int plain) {
  double a = fabs(bg_plot_tick(ax, 0)), b = fabs(bg_plot_tick(ax, ax->n - 1));
  double mag = fmax(a, b);
  if (!(mag > 0)) mag = ax->step;
  int e = (int)floor(log10(mag) + 1e-9), es = (int)floor(log10(ax->step) + 1e-9);
  int exp3 = plain && e >= -2 && e <= 3 ? 0 : 3 * (int)floor(e / 3.0);
  if (exp3 < -24 || exp3 > 24) {
    ax->exp3 = BG_PLOT_NO_PREFIX;
    ax->decimals = e - es > 0 ? e - es : 0; /* significant digits after the first */
    return;
  }
  ax->exp3 = exp3;
  ax->decimals = exp3 - es > 0 ? exp3 - es : 0;
}

void bg_plot_axis_make(double lo, double hi, int maxn, int pad, bg_plot_axis *ax) {
  memset(ax, 0, sizeof *ax);
  sane_range(&lo, &hi);
  if (pad) pad_range(&lo, &hi);
  if (maxn < 1) maxn = 1;
  if (maxn > 50) maxn = 50;
  double half = (hi * 0.5 - lo * 0.5) / maxn; /* half the raw step: no overflow */
  double step = bg_plot_nice_step(isfinite(2 * half) ? 2 * half : half), k0 = 0;
  double n = tick_range(lo, hi, step, &k0);
  /* a narrow range may hold fewer than two ticks of the first step: take smaller ones */
  for (int i = 0; i < 8 && n < 2 && step > 0; i++) {
    step = step_down(step);
    n = tick_range(lo, hi, step, &k0);
  }
  if (!(n >= 1 && n <= 1000)) { /* cannot happen for sane ranges; stay drawable */
    double mid = lo * 0.5 + hi * 0.5;
    step = mid != 0 ? fabs(mid) : hi;
    k0 = mid < 0 ? -1 : mid > 0 ? 1 : 0, n = 1;
  }
  ax->step = step, ax->k0 = k0, ax->n = (int)n;
  ax->lo = lo, ax->hi = hi;
  label_format(ax, pad);
}

/* Angles: the step is 45 degrees, or 90 (and 180, 360, ... doubling) when
 * 45 would give more than maxn intervals or the range spans more than 360;
 * the limits snap outward to multiples of the step, so the frame starts and
 * ends on a tick (a constant phase of 0 gets -45 .. 45). */
void bg_plot_axis_degrees(double lo, double hi, int maxn, bg_plot_axis *ax) {
  memset(ax, 0, sizeof *ax);
  sane_range(&lo, &hi);
  if (maxn < 2) maxn = 2;
  double step = 45;
  if (hi - lo > 360) step = 90;
  while ((ceil(hi / step - 1e-9) - floor(lo / step + 1e-9)) > maxn && step < 1e300) step *= 2;
  double k0 = floor(lo / step + 1e-9), k1 = ceil(hi / step - 1e-9);
  if (k1 <= k0) k1 = k0 + 1;
  ax->lo = k0 * step, ax->hi = k1 * step;
  ax->step = step, ax->k0 = k0, ax->n = (int)(k1 - k0 + 1);
  ax->exp3 = 0, ax->decimals = 0; /* whole degrees, no SI prefix */
}

double bg_plot_tick(const bg_plot_axis *ax, int i) {
  double k = ax->k0 + i;
  return k == 0 ? 0 : k * ax->step;
}

/* ---------------------------------------------------------------- labels */
const char *bg_plot_si_prefix(int exp3) {
  static const char *const p[] = {"y", "z", "a", "f", "p", "n", "\xc2\xb5", "m", "",
                                  "k", "M", "G", "T", "P", "E", "Z", "Y"};
  if (exp3 < -24 || exp3 > 24 || exp3 % 3) return "";
  return p[exp3 / 3 + 8];
}

/* Copies src to buf replacing '-' by U+2212 (the typographic minus). */
static void put_minus(char *buf, size_t n, const char *src) {
  size_t w = 0;
  for (const char *p = src; *p && w + 4 < n; p++) {
    if (*p == '-') memcpy(buf + w, "\xe2\x88\x92", 3), w += 3;
    else buf[w++] = *p;
  }
  buf[w] = 0;
}

char *bg_plot_tick_label(const bg_plot_axis *ax, int i, char *buf, size_t n) {
  char tmp[96];
  double v = bg_plot_tick(ax, i);
  if (v == 0) snprintf(tmp, sizeof tmp, "0");
  else if (ax->exp3 == BG_PLOT_NO_PREFIX) snprintf(tmp, sizeof tmp, "%.*e", ax->decimals, v);
  else {
    double s = ax->exp3 >= 0 ? v / pow(10, ax->exp3) : v * pow(10, -ax->exp3);
    snprintf(tmp, sizeof tmp, "%.*f", ax->decimals, s);
  }
  put_minus(buf, n, tmp);
  return buf;
}

/* A value axis says its power of ten once, by its name, and its labels are
 * plain numbers: a prefix on each label ("6 m" for 0.006) reads as a unit
 * (6 metres) on the positions and lengths bond graphs plot. */
char *bg_plot_scale_markup(int exp3, double fs, char *buf, size_t n) {
  if (exp3 == 0 || exp3 == BG_PLOT_NO_PREFIX || exp3 < -24 || exp3 > 24) {
    if (n) buf[0] = 0;
    return buf;
  }
  return bg_plot_power_markup("\xc3\x97", exp3, fs, buf, n);
}

char *bg_plot_power_markup(const char *before, int k, double fs, char *buf, size_t n) {
  /* a superscript in points: pango's <sup> scales from the default font, not the label's */
  snprintf(buf, n, "%s10<span size=\"%d\" rise=\"%d\">%s%d</span>", before, (int)(0.72 * fs * 1024),
           (int)(0.42 * fs * 1024), k < 0 ? "\xe2\x88\x92" : "", k < 0 ? -k : k);
  return buf;
}

char *bg_plot_format_value(double v, int exp3, char *buf, size_t n) {
  char tmp[96];
  if (exp3 == BG_PLOT_NO_PREFIX || exp3 < -24 || exp3 > 24) snprintf(tmp, sizeof tmp, "%.6g ", v);
  else {
    double s = exp3 >= 0 ? v / pow(10, exp3) : v * pow(10, -exp3);
    snprintf(tmp, sizeof tmp, "%.6g %s", s, bg_plot_si_prefix(exp3));
  }
  put_minus(buf, n, tmp);
  return buf;
}
