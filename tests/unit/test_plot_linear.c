/* Plots of the linear analysis (docs/linear.md#plots): the Bode diagram's
 * log axis with decade ticks and both panels, the phase unwrapped and equal
 * to the angle of the hand-derived H(jw), the Nyquist diagram with the
 * critical point, step and impulse panels; deterministic scenes. */
#include <complex.h>
#include <math.h>
#include <stdio.h>

#include "harness.h"
#include "eqs_fixture.h"
#include "linear/linear.h"
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

int main(void) {
  if (bg_style_load(&st, "default", BG_SOURCE_DIR "/styles", NULL) != 0) bg_style_default(&st);
  OK(efx_load(&F, NULL, rlc, -1, NULL, 0) == 0);
  OK(bg_linear_compute(F.m, &F.a, 0, &L) == 0);
  test_bode();
  test_bode_data();
  test_nyquist_step();
  bg_linear_free(&L);
  efx_free(&F);
  return bg_t_done();
}
