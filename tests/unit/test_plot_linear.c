/* SPDX-License-Identifier: BSD-3-Clause */
/* Plots of the linear analysis (docs/linear.md#plots): the Bode diagram's
 * log axis with decade ticks and both panels, the phase unwrapped and equal
 * to the angle of the hand-derived H(jw), the Nyquist diagram with the
 * critical point, step and impulse panels; deterministic scenes; the phase
 * axis' ticks at multiples of 45 (90) degrees; the Nyquist arrows on the
 * curves, pointing towards increasing frequency, at 1/3 and 2/3 of each
 * branch's length, and the dashed mirror. */
#include <complex.h>
#include <math.h>
#include <stdio.h>

#include "harness.h"
#include "eqs_fixture.h"
#include "linear/linear.h"
#include "plot/plot_int.h"
#include "plot/plot_linear.h"

static const char *rlc =
    "param V = 1, R0 = 2, L0 = 0.5, C0 = 0.1\n"
    "Se U = V\n1 j\nR R1 = R0\nI L1 = L0\nC C1 = C0\n"
    "bond U -> j\nbond j -> R1\nbond j -> L1\nbond j -> C1\n"
    "output vC = C1.e, i = L1.f\n";

static efx F;
static bg_linear L;
static bg_style st;

static void scene(int kind, bg_scene *s) {
  bg_scene_init(s, st.font);
  OK(bg_plot_linear_scene(F.m, &L, kind, &st, 540, s) == 0);
}

static void test_bode(void) {
  bg_scene s;
  scene(BG_PLOT_BODE, &s);
  INT_EQ(bg_scene_count(&s, "panel"), 2);
  INT_EQ(bg_scene_count(&s, "curve"), 4);        /* 2 pairs x (magnitude, phase) */
  INT_EQ(bg_scene_count(&s, "tick x"), 4);       /* 0.1, 1, 10, 100 rad/s */
  INT_EQ(bg_scene_count(&s, "grid minor"), 2);
  INT_EQ(bg_scene_count(&s, "xlabel"), 1);
  bg_strbuf a = {0}, b = {0};
  bg_scene_dump(&s, &a);
  OK(strstr(bg_sb_str(&a), "10<span") != NULL);  /* decade labels as powers of ten */
  OK(strstr(bg_sb_str(&a), "rad/s") != NULL);
  bg_scene_free(&s);
  scene(BG_PLOT_BODE, &s);
  bg_scene_dump(&s, &b);
  OK(a.len == b.len && memcmp(a.s, b.s, a.len) == 0);
  bg_sb_free(&a), bg_sb_free(&b);
  bg_scene_free(&s);
}

/* The frequency data behind the plot: |H| and the unwrapped phase of
 * vC/U = 20/(s^2 + 4 s + 20) go from 0 dB, 0 deg to -40 dB/decade, -180 deg. */
static void test_bode_data(void) {
  enum { NW = 400 };
  double w[NW], re[2 * NW], im[2 * NW];
  bg_linear_freqs(&L, F.m, NW, w);
  DBL_NEAR(w[0], 0.1, 1e-15);
  DBL_NEAR(w[NW - 1], 100, 1e-12);
  OK(bg_linear_freqresp(&L, NW, w, re, im) == 0);
  double worst = 0;
  for (int k = 0; k < NW; k++) {
    double complex s = I * w[k], h = 20 / (s * s + 4 * s + 20);
    worst = fmax(worst, cabs(re[k] + I * im[k] - h) / cabs(h));
  }
  OK(worst < 1e-12);
}

static void test_nyquist_step(void) {
  bg_scene s;
  scene(BG_PLOT_NYQUIST, &s);
  INT_EQ(bg_scene_count(&s, "critical point"), 1);
  INT_EQ(bg_scene_count(&s, "curve"), 4); /* each pair: w > 0 and its mirror */
  INT_EQ(bg_scene_count(&s, "legend 1"), 2);
  bg_scene_free(&s);
  scene(BG_PLOT_STEP, &s);
  INT_EQ(bg_scene_count(&s, "panel"), 2);
  INT_EQ(bg_scene_count(&s, "title"), 2);
  INT_EQ(bg_scene_count(&s, "curve"), 4);
  bg_scene_free(&s);
}

/* Tick values of an axis. */
static void ticks_are(const bg_plot_axis *ax, const double *want, int n) {
  INT_EQ(ax->n, n);
  for (int i = 0; i < n && i < ax->n; i++) DBL_NEAR(bg_plot_tick(ax, i), want[i], 0);
}

static void test_degrees(void) {
  bg_plot_axis ax;
  bg_plot_axis_degrees(-179.7, -0.4, 6, &ax); /* the RLC's phase */
  ticks_are(&ax, (double[]){-180, -135, -90, -45, 0}, 5);
  DBL_NEAR(ax.lo, -180, 0);
  DBL_NEAR(ax.hi, 0, 0);
  bg_plot_axis_degrees(-2.5, -0.1, 6, &ax); /* a small range still gets two ticks */
  ticks_are(&ax, (double[]){-45, 0}, 2);
  bg_plot_axis_degrees(0, 0, 6, &ax); /* a constant phase */
  ticks_are(&ax, (double[]){-45, 0, 45}, 3);
  bg_plot_axis_degrees(-539, -1, 8, &ax); /* a large range: 90 */
  ticks_are(&ax, (double[]){-540, -450, -360, -270, -180, -90, 0}, 7);
  bg_plot_axis_degrees(-539, -1, 5, &ax); /* fewer ticks fit: 180 */
  ticks_are(&ax, (double[]){-540, -360, -180, 0}, 4);
  bg_plot_axis_degrees(-300, 0, 6, &ax); /* 45 would need 7 intervals */
  ticks_are(&ax, (double[]){-360, -270, -180, -90, 0}, 5);
  char buf[32];
  bg_plot_axis_degrees(-1000, 10, 6, &ax);
  STR_EQ(bg_plot_tick_label(&ax, 0, buf, sizeof buf), "\xe2\x88\x92" "1080"); /* no SI prefix */
}

/* The Bode scene's phase panel: vC/U goes from 0 to -180, i/U from 90 to
 * -90: labels -180 ... 90 in steps of 45. */
static void test_bode_phase_ticks(void) {
  bg_scene s;
  scene(BG_PLOT_BODE, &s);
  const char *want[] = {"\xe2\x88\x92" "180", "\xe2\x88\x92" "135", "\xe2\x88\x92" "90",
                        "\xe2\x88\x92" "45", "0", "45", "90"};
  int k = 0;
  for (int i = 0; i < s.nitem; i++)
    if (!strcmp(s.item[i].role, "tick y 2")) {
      if (k < 7) STR_EQ(s.item[i].text, want[k]);
      k++;
    }
  INT_EQ(k, 7);
  bg_scene_free(&s);
}

/* The path of item i as points (move/line ops). */
static int item_points(const bg_scene *s, int i, double *x, double *y, int max) {
  const bg_scene_item *it = &s->item[i];
  int n = 0;
  for (int k = 0; k < it->nop && n < max; k++)
    if (s->code[it->opadr + k] != BG_OP_CLOSE) x[n] = s->pt[it->opadr + k].x, y[n++] = s->pt[it->opadr + k].y;
  return n;
}

static int find_item(const bg_scene *s, const char *role, int nth) {
  for (int i = 0; i < s->nitem; i++)
    if (!strcmp(s->item[i].role, role) && nth-- == 0) return i;
  return -1;
}

/* Arrow `nth` of `arole` lies on the curve `crole` at fraction `frac` of its
 * length, pointing along it (forward: in the curve's point order). */
static void arrow_on(const bg_scene *s, const char *arole, int nth, const char *crole, double frac, int forward) {
  static double cx[1000], cy[1000];
  double ax[4], ay[4];
  int ia = find_item(s, arole, nth), ic = find_item(s, crole, 0);
  OK(ia >= 0 && ic >= 0);
  if (ia < 0 || ic < 0) return;
  OK(s->item[ia].kind == BG_ITEM_FILL);
  INT_EQ(item_points(s, ia, ax, ay, 4), 3);
  int m = item_points(s, ic, cx, cy, 1000);
  double mx = (ax[0] + (ax[1] + ax[2]) / 2) / 2, my = (ay[0] + (ay[1] + ay[2]) / 2) / 2; /* centre */
  double dx = ax[0] - (ax[1] + ax[2]) / 2, dy = ay[0] - (ay[1] + ay[2]) / 2, dl = hypot(dx, dy);
  double total = 0, at = -1, best = 1e9, dot = 0;
  for (int i = 1; i < m; i++) {
    double sx = cx[i] - cx[i - 1], sy = cy[i] - cy[i - 1], len = hypot(sx, sy);
    if (len > 0) {
      double t = fmax(0, fmin(1, ((mx - cx[i - 1]) * sx + (my - cy[i - 1]) * sy) / (len * len)));
      double d = hypot(cx[i - 1] + t * sx - mx, cy[i - 1] + t * sy - my);
      if (d < best) best = d, at = total + t * len, dot = (sx * dx + sy * dy) / (len * dl);
    }
    total += len;
  }
  OK(best < 1e-6);                   /* centred on the curve */
  OK(fabs(at / total - frac) < 1e-6); /* at that fraction of its length */
  OK(forward ? dot > 0.999 : dot < -0.999);
}

/* vC/U = 20/(s^2 + 4s + 20): from 1 at w = 0 clockwise through -1.118j
 * (w = sqrt 20) to 0; the mirror from 0 through +1.118j back to 1. */
static void test_nyquist_arrows(void) {
  bg_scene s;
  scene(BG_PLOT_NYQUIST, &s);
  INT_EQ(bg_scene_count(&s, "arrow 1.1"), 4); /* two on the branch, two on the mirror */
  INT_EQ(bg_scene_count(&s, "arrow 1.1 mirror"), 2);
  INT_EQ(bg_scene_count(&s, "arrow 1.2"), 4);
  arrow_on(&s, "arrow 1.1", 0, "curve 1.1", 1.0 / 3, 1);
  arrow_on(&s, "arrow 1.1", 1, "curve 1.1", 2.0 / 3, 1);
  arrow_on(&s, "arrow 1.1 mirror", 0, "curve 1.1 mirror", 1.0 / 3, 1);
  arrow_on(&s, "arrow 1.1 mirror", 1, "curve 1.1 mirror", 2.0 / 3, 1);
  /* the w > 0 branch runs in frequency order: its first point is H(j w_min) ~ 1
   * (right), the mirror's first is H(-j w_max) ~ 0; the mirror is dashed, the branch not */
  int c = find_item(&s, "curve 1.1", 0), cm = find_item(&s, "curve 1.1 mirror", 0);
  OK(c >= 0 && cm >= 0);
  if (c >= 0 && cm >= 0) {
    double x[1000], y[1000], xm[1000], ym[1000];
    int n = item_points(&s, c, x, y, 1000), nm = item_points(&s, cm, xm, ym, 1000);
    OK(n > 100 && nm == n);
    OK(x[0] > x[n - 1] && fabs(x[0] - xm[nm - 1]) < 1e-9 && fabs(x[n - 1] - xm[0]) < 1e-9);
    OK(y[n / 2] > y[0] && ym[nm / 2] < ym[0]); /* the branch below the real axis, the mirror above */
    OK(s.item[c].dash[0] == 0 && s.item[cm].dash[0] > 0 && s.item[cm].width < s.item[c].width);
  }
  bg_scene_free(&s);
}

int main(void) {
  if (bg_style_load(&st, "default", BG_SOURCE_DIR "/styles", NULL) != 0) bg_style_default(&st);
  OK(efx_load(&F, NULL, rlc, -1, NULL, 0) == 0);
  OK(bg_linear_compute(F.m, &F.a, 0, &L) == 0);
  test_bode();
  test_bode_data();
  test_nyquist_step();
  test_degrees();
  test_bode_phase_ticks();
  test_nyquist_arrows();
  bg_linear_free(&L);
  efx_free(&F);
  return bg_t_done();
}
