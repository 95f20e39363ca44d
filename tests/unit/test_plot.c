/* SPDX-License-Identifier: BSD-3-Clause */
/* Simulation plots (issue 7): the 1-2-5 tick maths on many ranges (tiny,
 * huge, negative, zero-width, non-finite), SI-prefixed labels, and scenes
 * of real simulations (rlc, a model with two plot statements, one without
 * any, a partial run) and of hand-made results with NaN, inf, one row and
 * no rows, counted from their role tags; bg_plot_write's errors. */
#include "harness.h"

#include <stdlib.h>

#include "causality/causality.h"
#include "equations/equations.h"
#include "base/fileio.h"
#include "lang/lang.h"
#include "analysis/analysis.h"
#include "plot/plot.h"
#include "plot/plot_int.h"
#include "diagram/render.h"
#include "simulate/simulate.h"

/* ---------------------------------------------------------------- fixture */
typedef struct fx {
  bg_model *m;
  bg_analysis a;
  bg_eqsys *s;
  bg_diags dg;
  char *src;
  bg_simresult r;
  int rc;
} fx;

/* Compiles, analyses and simulates the model text (path for messages). */
static int fx_text(fx *f, const char *path, const char *text) {
  memset(f, 0, sizeof *f);
  f->src = strdup(text);
  size_t len = strlen(f->src);
  bg_diags_init(&f->dg, path, f->src, len);
  bg_ast *ast = bg_parse_string(path, f->src, len, &f->dg);
  if (ast && !f->dg.nerrors) f->m = bg_model_compile(ast, NULL, 0, &f->dg);
  if (ast) bg_ast_free(ast);
  if (!f->m) {
    bg_diags_print(&f->dg, stderr);
    return -1;
  }
  bg_analysis_init(&f->a, f->m);
  bg_causality_assign(f->m, BG_METHOD_SCAP, &f->a, &f->dg);
  bg_analysis_run(f->m, &f->a, NULL);
  if (f->a.complete) f->s = bg_eqsys_build(f->m, &f->a, &f->dg);
  f->rc = bg_simulate(f->m, &f->a, f->s, NULL, &f->r);
  return 0;
}

/* examples/NAME.bg, with the first `from` replaced by `to` when given. */
static int fx_example(fx *f, const char *name, const char *from, const char *to) {
  char path[512];
  size_t len;
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  char *src = bg_read_file(path, &len);
  if (!src) {
    fprintf(stderr, "cannot read %s\n", path);
    return -1;
  }
  bg_strbuf b = {0};
  char *p = from ? strstr(src, from) : NULL;
  if (p) {
    bg_sb_putn(&b, src, (size_t)(p - src));
    bg_sb_puts(&b, to);
    bg_sb_puts(&b, p + strlen(from));
  } else {
    bg_sb_puts(&b, src);
  }
  int rc = fx_text(f, path, bg_sb_str(&b));
  bg_sb_free(&b);
  free(src);
  return rc;
}

static void fx_free(fx *f) {
  bg_simresult_free(&f->r);
  if (f->s) bg_eqsys_free(f->s);
  if (f->m) bg_analysis_free(&f->a);
  if (f->m) bg_model_free(f->m);
  bg_diags_free(&f->dg);
  free(f->src);
}

static void scene_of(const bg_model *m, const bg_simresult *r, const char *style, bg_scene *s) {
  bg_style st;
  bg_diags dg;
  bg_diags_init(&dg, "test", NULL, 0);
  if (bg_style_load(&st, style, BG_SOURCE_DIR "/styles", &dg) != 0) bg_style_default(&st);
  bg_diags_free(&dg);
  bg_scene_init(s, st.font);
  bg_plot_scene(m, r, &st, 540, 0, s);
}

static const bg_scene_item *find_item(const bg_scene *s, const char *role) {
  for (int i = 0; i < s->nitem; i++)
    if (!strcmp(s->item[i].role, role)) return &s->item[i];
  return NULL;
}

static int count_ops(const bg_scene *s, const bg_scene_item *it, int code) {
  int n = 0;
  for (int i = 0; it && i < it->nop; i++) n += s->code[it->opadr + i] == code;
  return n;
}

static int has_text(const bg_scene *s, const char *role, const char *text) {
  for (int i = 0; i < s->nitem; i++)
    if (!strcmp(s->item[i].role, role) && s->item[i].text && strstr(s->item[i].text, text))
      return 1;
  return 0;
}

/* ---------------------------------------------------------------- ticks */
static void test_nice_step(void) {
  DBL_NEAR(bg_plot_nice_step(0.23), 0.5, 1e-15);
  DBL_NEAR(bg_plot_nice_step(1), 1, 0);
  DBL_NEAR(bg_plot_nice_step(1.01), 2, 0);
  DBL_NEAR(bg_plot_nice_step(3), 5, 0);
  DBL_NEAR(bg_plot_nice_step(7), 10, 0);
  DBL_NEAR(bg_plot_nice_step(0.2), 0.2, 1e-16);
  DBL_NEAR(bg_plot_nice_step(7e-4), 1e-3, 1e-18);
  DBL_NEAR(bg_plot_nice_step(1.5e-300) / 2e-300, 1, 1e-12);
  DBL_NEAR(bg_plot_nice_step(4e307) / 5e307, 1, 1e-12);
  DBL_NEAR(bg_plot_nice_step(0), 1, 0);
  DBL_NEAR(bg_plot_nice_step(-3), 1, 0);
  DBL_NEAR(bg_plot_nice_step(NAN), 1, 0);
  DBL_NEAR(bg_plot_nice_step(INFINITY), 1, 0);
}

/* mantissa of a 1-2-5 step */
static int is_125(double step) {
  double e = floor(log10(step) + 1e-9), m = step / pow(10, e);
  return fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 5) < 1e-9;
}

/* Invariants of one axis. */
static void check_axis(double lo, double hi, int maxn, int pad) {
  bg_plot_axis ax;
  bg_plot_axis_make(lo, hi, maxn, pad, &ax);
  int ok = ax.n >= 1 && ax.n <= maxn + 2 && ax.lo < ax.hi && isfinite(ax.lo) && isfinite(ax.hi) &&
           ax.step > 0 && isfinite(ax.step);
  for (int i = 0; ok && i < ax.n; i++) {
    double t = bg_plot_tick(&ax, i);
    ok = isfinite(t) && t >= ax.lo - 1e-9 * ax.step && t <= ax.hi + 1e-9 * ax.step &&
         (i == 0 || t > bg_plot_tick(&ax, i - 1));
  }
  BG_T_REPORT(ok, "axis of [%g, %g] maxn %d pad %d: n %d lo %g hi %g step %g", lo, hi, maxn,
              pad, ax.n, ax.lo, ax.hi, ax.step);
  BG_T_REPORT(is_125(ax.step) || ax.n == 1, "1-2-5 step for [%g, %g]: %g", lo, hi, ax.step);
  if (isfinite(lo) && isfinite(hi) && lo != hi) {
    double a = fmin(lo, hi), b = fmax(lo, hi);
    BG_T_REPORT(ax.lo <= a && ax.hi >= b, "[%g, %g] covers [%g, %g]", ax.lo, ax.hi, a, b);
    if (b - a > 1e-9 * fmax(fabs(a), fabs(b)))
      BG_T_REPORT(ax.n >= 2, "at least two ticks on [%g, %g] (maxn %d): %d", lo, hi, maxn, ax.n);
  }
  char buf[96];
  for (int i = 0; i < ax.n; i++) /* every label is printable and short */
    BG_T_REPORT(strlen(bg_plot_tick_label(&ax, i, buf, sizeof buf)) < 40, "label %s", buf);
}

static void test_axis_ranges(void) {
  static const double r[][2] = {
      {0, 1},      {0, 2e-3},   {-1, 1},      {-5e-7, 3e-7}, {1e-300, 3e-300}, {-1e308, 1e308},
      {0, 1e300},  {-3, -2},    {5, 5},       {0, 0},        {-7.5, -7.5},     {1, 1 + 1e-15},
      {1e9, 1e9 + 1}, {2, 1},   {0.77, 0.78}, {0.11, 0.14},  {123456, 123457}, {-1e-30, 1e-30},
      {1e24, 5e25}, {0, 4.9e-324}, {1.7e308, 1.79e308}, {-2e-9, 7e-6}};
  int maxn[] = {1, 2, 5, 8, 20};
  for (size_t i = 0; i < sizeof r / sizeof r[0]; i++)
    for (size_t k = 0; k < sizeof maxn / sizeof maxn[0]; k++)
      for (int pad = 0; pad < 2; pad++) check_axis(r[i][0], r[i][1], maxn[k], pad);
  /* non-finite ends */
  check_axis(NAN, NAN, 5, 1);
  check_axis(INFINITY, 3, 5, 1);
  check_axis(-INFINITY, INFINITY, 5, 0);
  bg_plot_axis ax;
  bg_plot_axis_make(NAN, NAN, 5, 0, &ax);
  OK(ax.lo == 0 && ax.hi == 1);
  bg_plot_axis_make(5, 5, 5, 0, &ax); /* constant: ±10 % */
  DBL_NEAR(ax.lo, 4.5, 1e-12);
  DBL_NEAR(ax.hi, 5.5, 1e-12);
  bg_plot_axis_make(0, 0, 5, 0, &ax); /* zero: ±1 */
  DBL_NEAR(ax.lo, -1, 0);
  DBL_NEAR(ax.hi, 1, 0);
  bg_plot_axis_make(1, 1 + 1e-15, 5, 0, &ax); /* the last bits only: constant */
  OK(ax.lo < 0.95 && ax.hi > 1.05);
  bg_plot_axis_make(0, 2e-3, 5, 0, &ax); /* the time axis keeps its limits */
  DBL_NEAR(ax.lo, 0, 0);
  DBL_NEAR(ax.hi, 2e-3, 0);
  DBL_NEAR(ax.step, 5e-4, 1e-18);
  INT_EQ(ax.n, 5);
  bg_plot_axis_make(0, 1, 5, 1, &ax); /* value axes: 5 % padding */
  DBL_NEAR(ax.lo, -0.05, 1e-12);
  DBL_NEAR(ax.hi, 1.05, 1e-12);
  DBL_NEAR(bg_plot_tick(&ax, 0), 0, 0);
  DBL_NEAR(bg_plot_tick(&ax, ax.n - 1), 1, 1e-12);
}

static void test_labels(void) {
  STR_EQ(bg_plot_si_prefix(-6), "\xc2\xb5");
  STR_EQ(bg_plot_si_prefix(-3), "m");
  STR_EQ(bg_plot_si_prefix(0), "");
  STR_EQ(bg_plot_si_prefix(3), "k");
  STR_EQ(bg_plot_si_prefix(-24), "y");
  STR_EQ(bg_plot_si_prefix(24), "Y");
  STR_EQ(bg_plot_si_prefix(27), "");
  char b[96];
  bg_plot_axis ax;
  bg_plot_axis_make(0, 2e-3, 5, 0, &ax); /* "t [ms]": 0, 0.5, ..., 2.0 */
  INT_EQ(ax.exp3, -3);
  STR_EQ(bg_plot_tick_label(&ax, 0, b, sizeof b), "0");
  STR_EQ(bg_plot_tick_label(&ax, 1, b, sizeof b), "0.5");
  STR_EQ(bg_plot_tick_label(&ax, 4, b, sizeof b), "2.0");
  bg_plot_axis_make(0, 1500, 3, 0, &ax); /* "t [ks]": 0, 0.5, 1.0, 1.5 */
  STR_EQ(bg_plot_tick_label(&ax, 3, b, sizeof b), "1.5");
  /* value axes (padded): plain numbers from 0.01 to 9999, else a power of ten
   * said once by the axis' name, never a prefix on a label ("6 m" for 0.006
   * reads as 6 metres) */
  bg_plot_axis_make(0, 10, 5, 1, &ax); /* 0, 5, 10 */
  STR_EQ(bg_plot_tick_label(&ax, 2, b, sizeof b), "10");
  STR_EQ(bg_plot_scale_markup(ax.exp3, 9, b, sizeof b), ""); /* no scale at 10^0 */
  bg_plot_axis_make(0, 1400, 3, 1, &ax); /* 0, 1000 */
  STR_EQ(bg_plot_tick_label(&ax, 1, b, sizeof b), "1000");
  INT_EQ(ax.exp3, 0);
  bg_plot_axis_make(0, 0.3, 3, 1, &ax); /* 0, 0.2 */
  STR_EQ(bg_plot_tick_label(&ax, 1, b, sizeof b), "0.2");
  INT_EQ(ax.exp3, 0);
  bg_plot_axis_make(0, 0.014, 3, 1, &ax); /* 0, 0.01 */
  STR_EQ(bg_plot_tick_label(&ax, 1, b, sizeof b), "0.01");
  bg_plot_axis_make(-0.006, 0.006, 4, 1, &ax); /* −5, 0, 5 ×10⁻³ */
  INT_EQ(ax.exp3, -3);
  STR_EQ(bg_plot_tick_label(&ax, 2, b, sizeof b), "5");
  STR_EQ(bg_plot_tick_label(&ax, 0, b, sizeof b), "\xe2\x88\x92" "5");
  STR_EQ(bg_plot_scale_markup(ax.exp3, 10, b, sizeof b),
         "\xc3\x97" "10<span size=\"7372\" rise=\"4300\">\xe2\x88\x92" "3</span>");
  bg_plot_axis_make(0, 4e-4, 2, 1, &ax); /* 0, 200, 400 ×10⁻⁶ */
  STR_EQ(bg_plot_tick_label(&ax, 1, b, sizeof b), "200");
  INT_EQ(ax.exp3, -6);
  bg_plot_axis_make(0, 2.4e5, 3, 1, &ax); /* 0, 100, 200 ×10³ */
  INT_EQ(ax.exp3, 3);
  OK(strstr(bg_plot_scale_markup(ax.exp3, 10, b, sizeof b), ">3</span>") != NULL);
  bg_plot_axis_make(1e-300, 3e-300, 2, 1, &ax); /* beyond the prefixes: e-notation */
  INT_EQ(ax.exp3, BG_PLOT_NO_PREFIX);
  OK(strstr(bg_plot_tick_label(&ax, 0, b, sizeof b), "e") != NULL);
  STR_EQ(bg_plot_scale_markup(ax.exp3, 10, b, sizeof b), "");
  STR_EQ(bg_plot_format_value(0.772578, -3, b, sizeof b), "772.578 m");
  STR_EQ(bg_plot_format_value(-2, 0, b, sizeof b), "\xe2\x88\x92" "2 ");
}

/* ---------------------------------------------------------------- scenes */
static void test_rlc(void) {
  fx f;
  if (fx_example(&f, "rlc", NULL, NULL)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  bg_scene s;
  scene_of(f.m, &f.r, NULL, &s);
  INT_EQ(bg_scene_count(&s, "panel"), 1);
  INT_EQ(bg_scene_count(&s, "curve"), 2);
  INT_EQ(bg_scene_count(&s, "curve 1.1"), 1);
  INT_EQ(bg_scene_count(&s, "curve 1.2"), 1);
  INT_EQ(bg_scene_count(&s, "legend 1"), 2);
  OK(has_text(&s, "legend 1", "C1.e") && has_text(&s, "legend 1", "L1.f"));
  INT_EQ(bg_scene_count(&s, "tick x"), 11); /* 0, 0.2, ..., 2.0 ms */
  OK(has_text(&s, "xlabel", "t [ms]"));
  OK(bg_scene_count(&s, "tick y 1") >= 3);
  INT_EQ(bg_scene_count(&s, "partial"), 0);
  INT_EQ(bg_scene_count(&s, "title"), 0);
  /* the two curves differ in colour and dash pattern */
  const bg_scene_item *c1 = find_item(&s, "curve 1.1"), *c2 = find_item(&s, "curve 1.2");
  OK(c1 && c2 && c1->dash[0] != c2->dash[0]);
  OK(c1 && c2 && (c1->color.r != c2->color.r || c1->color.g != c2->color.g));
  /* 2001 rows on a ~500 pt axis: decimated, still one unbroken line each */
  OK(c1 && c1->nop < 2001 && count_ops(&s, c1, BG_OP_MOVE) == 1);
  OK(s.width == 540 && s.height > 150);
  /* deterministic */
  bg_strbuf d1 = {0}, d2 = {0};
  bg_scene_dump(&s, &d1);
  bg_scene s2;
  scene_of(f.m, &f.r, NULL, &s2);
  bg_scene_dump(&s2, &d2);
  OK(d1.len > 0 && !strcmp(bg_sb_str(&d1), bg_sb_str(&d2)));
  bg_sb_free(&d1), bg_sb_free(&d2);
  bg_scene_free(&s2);
  bg_scene_free(&s);
  /* print style: every pair of the first curves differs in its dash pattern */
  scene_of(f.m, &f.r, "print", &s);
  c1 = find_item(&s, "curve 1.1"), c2 = find_item(&s, "curve 1.2");
  OK(c1 && c2 && c1->dash[0] != c2->dash[0]);
  OK(c1 && c1->color.r == 0 && c1->color.g == 0 && c1->color.b == 0);
  bg_scene_free(&s);
  /* a fixed height is kept */
  bg_scene_init(&s, "DejaVu Sans");
  bg_style st;
  bg_style_default(&st);
  bg_plot_scene(f.m, &f.r, &st, 400, 300, &s);
  OK(s.width == 400 && s.height == 300);
  double x0, y0, x1, y1;
  bg_scene_bbox(&s, &x0, &y0, &x1, &y1);
  OK(x0 >= 0 && y0 >= 0 && x1 <= 400 && y1 <= 300);
  bg_scene_free(&s);
  fx_free(&f);
}

static const char *TWO_PLOTS =
    "model two\n"
    "param V = 1, R0 = 10, L0 = 1e-3, C0 = 1e-6\n"
    "Se U = V * step(t)\n1 j\nR R1 = R0\nI L1 = L0\nC C1 = C0\n"
    "bond 1 U -> j\nbond 2 j -> R1\nbond 3 j -> L1\nbond 4 j -> C1\n"
    "simulate t_end = 2e-3, dt = 1e-5\n"
    "plot C1.e [title = \"Voltage <C1>\", ylabel = \"V\"]\n"
    "plot L1.f, R1.e, L1.f*R1.e [title = \"Current & more\", xlabel = \"time\"]\n";

static void test_two_plots(void) {
  fx f;
  if (fx_text(&f, "two.bg", TWO_PLOTS)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  INT_EQ(f.r.nout, 4);
  bg_scene s;
  scene_of(f.m, &f.r, NULL, &s);
  INT_EQ(bg_scene_count(&s, "panel"), 2);
  INT_EQ(bg_scene_count(&s, "curve"), 4);
  INT_EQ(bg_scene_count(&s, "curve 1.1"), 1);
  INT_EQ(bg_scene_count(&s, "curve 2.3"), 1);
  INT_EQ(bg_scene_count(&s, "legend 1"), 1);
  INT_EQ(bg_scene_count(&s, "legend 2"), 3);
  OK(has_text(&s, "legend 2", "L1.f*R1.e"));
  OK(has_text(&s, "title 1", "Voltage &lt;C1&gt;")); /* markup escaped */
  OK(has_text(&s, "title 2", "Current &amp; more"));
  OK(has_text(&s, "ylabel 1", "V"));
  INT_EQ(bg_scene_count(&s, "ylabel 2"), 0);
  OK(has_text(&s, "xlabel", "time [ms]"));
  INT_EQ(bg_scene_count(&s, "xlabel"), 1);
  /* tick marks under both panels, labels under the last only */
  INT_EQ(bg_scene_count(&s, "ticks x"), 2);
  const bg_scene_item *p2 = find_item(&s, "panel 2"), *t = find_item(&s, "tick x");
  OK(p2 && t && t->y > s.pt[p2->opadr + 2].y);
  OK(bg_scene_count(&s, "tick y 1") >= 2 && bg_scene_count(&s, "tick y 2") >= 2);
  /* the panels share the x extent */
  const bg_scene_item *p1 = find_item(&s, "panel 1");
  OK(p1 && p2 && s.pt[p1->opadr].x == s.pt[p2->opadr].x &&
     s.pt[p1->opadr + 1].x == s.pt[p2->opadr + 1].x);
  /* nothing overlaps between the panels: panel 1 ends above panel 2's header */
  const bg_scene_item *ti2 = find_item(&s, "title 2");
  OK(p1 && ti2 && s.pt[p1->opadr + 2].y < ti2->y);
  bg_scene_free(&s);
  fx_free(&f);
}

/* A millimetre-sized value: plain tick numbers and the power of ten once, by
 * the y label (never "6 m" on a tick, which reads as 6 metres). */
static const char *MILLI =
    "model milli\n"
    "Se U = 6e-3 * step(t)\n1 j\nR R1 = 1\nC C1 = 1\n"
    "bond 1 U -> j\nbond 2 j -> R1\nbond 3 j -> C1\n"
    "simulate t_end = 10, dt = 0.01\n"
    "plot C1.e [ylabel = \"x [m]\"]\n"
    "plot C1.q\n";

static void test_value_scale(void) {
  fx f;
  if (fx_text(&f, "milli.bg", MILLI)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  bg_scene s;
  scene_of(f.m, &f.r, NULL, &s);
  const char *scale = "\xc3\x97" "10<span"; /* ×10 and a superscript */
  OK(has_text(&s, "ylabel 1", "x [m] \xc3\x97" "10<span"));
  OK(has_text(&s, "ylabel 1", "\xe2\x88\x92" "3</span>"));
  OK(has_text(&s, "ylabel 2", scale)); /* the scale alone where no ylabel is given */
  int ticks = 0;
  for (int i = 0; i < s.nitem; i++)
    if (!strncmp(s.item[i].role, "tick y", 6) && s.item[i].text) {
      ticks++;
      BG_T_REPORT(!strchr(s.item[i].text, ' ') && !strchr(s.item[i].text, 'm'), "tick label %s",
                  s.item[i].text);
    }
  OK(ticks >= 4);
  /* the largest tick is a whole number of thousandths at most 6 */
  double top = 0;
  for (int i = 0; i < s.nitem; i++)
    if (!strcmp(s.item[i].role, "tick y 1") && s.item[i].text) top = fmax(top, atof(s.item[i].text));
  OK(top >= 4 && top <= 6);
  bg_scene_free(&s);
  fx_free(&f);
}

static void test_no_plot_statement(void) {
  fx f;
  if (fx_example(&f, "rlc", "plot C1.e, L1.f", "")) { OK(0); return; }
  INT_EQ(f.rc, 0);
  INT_EQ(f.m->nplot, 0);
  bg_scene s;
  scene_of(f.m, &f.r, NULL, &s);
  INT_EQ(bg_scene_count(&s, "panel"), 1);
  INT_EQ(bg_scene_count(&s, "curve"), f.r.nout); /* the states */
  INT_EQ(bg_scene_count(&s, "legend 1"), f.r.nout);
  for (int k = 0; k < f.r.nout; k++) OK(has_text(&s, "legend 1", f.r.names[k]));
  bg_scene_free(&s);
  fx_free(&f);
}

static const char *BLOW =
    "model blow\nparam I0 = 2, R0 = 1\nSf S = I0\n0 n\nC C1 : e = sqrt(1 - q)\nR R1 = R0\n"
    "bond 1 S -> n\nbond 2 n -> C1\nbond 3 n -> R1\nsimulate t_end = 2, dt = 0.05\n"
    "plot C1.q\nplot C1.e\n";

static void test_partial(void) {
  fx f;
  if (fx_text(&f, "blow.bg", BLOW)) { OK(0); return; }
  INT_EQ(f.rc, 2);
  OK(f.r.partial && f.r.nrows > 0);
  bg_scene s;
  scene_of(f.m, &f.r, NULL, &s);
  INT_EQ(bg_scene_count(&s, "partial"), 2); /* a line in each panel */
  INT_EQ(bg_scene_count(&s, "partial-gap"), 2);
  INT_EQ(bg_scene_count(&s, "partial-label"), 1);
  OK(has_text(&s, "partial-label", "simulation stopped at t = 0.7725"));
  /* the axis spans the simulate block: the mark sits at 0.77 / 2 of the width */
  const bg_scene_item *p = find_item(&s, "partial 1"), *fr = find_item(&s, "panel 1");
  if (p && fr) {
    double x0 = s.pt[fr->opadr].x, x1 = s.pt[fr->opadr + 1].x;
    DBL_NEAR((s.pt[p->opadr].x - x0) / (x1 - x0), f.r.t_reached / 2, 1e-9);
  } else {
    OK(0);
  }
  OK(has_text(&s, "tick x", "2.0"));
  bg_scene_free(&s);
  fx_free(&f);
}

/* A hand-made result on rlc's model (two plotted columns). */
static void fake_result(bg_simresult *r, int nrows, const double *t, const double *v) {
  static const char *names[] = {"C1.e", "L1.f"};
  memset(r, 0, sizeof *r);
  r->nout = 2, r->names = names, r->nrows = nrows;
  r->t = (double *)t, r->values = (double *)v;
  r->t_reached = nrows ? t[nrows - 1] : 0;
}

static void test_degenerate(void) {
  fx f;
  if (fx_example(&f, "rlc", NULL, NULL)) { OK(0); return; }
  bg_simresult r;
  bg_scene s;
  /* NaN and inf break the line: three finite runs, the middle one a lone point */
  double t[7] = {0, 1e-4, 2e-4, 3e-4, 4e-4, 5e-4, 6e-4};
  double v[14] = {0, 3, 1, 3, NAN, 3, 2, 3, INFINITY, 3, 4, 3, 5, 3};
  fake_result(&r, 7, t, v);
  scene_of(f.m, &r, NULL, &s);
  const bg_scene_item *c1 = find_item(&s, "curve 1.1"), *c2 = find_item(&s, "curve 1.2");
  INT_EQ(count_ops(&s, c1, BG_OP_MOVE), 3);
  INT_EQ(count_ops(&s, c1, BG_OP_LINE), 3); /* 0-1, the dot at 3e-4, 5e-4-6e-4 */
  INT_EQ(count_ops(&s, c2, BG_OP_MOVE), 1); /* constant 3: one line */
  const bg_scene_item *ty = find_item(&s, "tick y 1");
  OK(ty != NULL && bg_scene_count(&s, "tick y 1") >= 2);
  bg_scene_free(&s);
  /* all NaN: the curve has nothing to draw, the axis is still sensible */
  double vn[14];
  for (int i = 0; i < 14; i++) vn[i] = NAN;
  fake_result(&r, 7, t, vn);
  scene_of(f.m, &r, NULL, &s);
  INT_EQ(count_ops(&s, find_item(&s, "curve 1.1"), BG_OP_MOVE), 0);
  OK(bg_scene_count(&s, "tick y 1") >= 2);
  bg_scene_free(&s);
  /* a single row: a dot per curve */
  fake_result(&r, 1, t, v);
  scene_of(f.m, &r, NULL, &s);
  c1 = find_item(&s, "curve 1.1");
  OK(c1 && c1->nop == 2 && count_ops(&s, c1, BG_OP_MOVE) == 1);
  INT_EQ(bg_scene_count(&s, "panel"), 1);
  bg_scene_free(&s);
  /* no rows: the panel, legend and axes, no curves */
  fake_result(&r, 0, t, v);
  scene_of(f.m, &r, NULL, &s);
  INT_EQ(bg_scene_count(&s, "panel"), 1);
  INT_EQ(bg_scene_count(&s, "curve"), 0);
  INT_EQ(bg_scene_count(&s, "legend 1"), 2);
  INT_EQ(bg_scene_count(&s, "tick x"), 11); /* the simulate block's 0 .. 2 ms */
  bg_scene_free(&s);
  /* a partial result with no rows still marks t0 */
  fake_result(&r, 0, t, v);
  r.partial = 1;
  scene_of(f.m, &r, NULL, &s);
  INT_EQ(bg_scene_count(&s, "partial"), 1);
  bg_scene_free(&s);
  fx_free(&f);
}

/* ---------------------------------------------------------------- files */
static void test_write(void) {
  fx f;
  if (fx_example(&f, "rlc", NULL, NULL)) { OK(0); return; }
  bg_diags dg;
  bg_diags_init(&dg, "test", NULL, 0);
  char path[1024];
  snprintf(path, sizeof path, "%s/plot_test.svg", BG_BINARY_DIR);
  INT_EQ(bg_plot_write(f.m, &f.r, NULL, BG_SOURCE_DIR "/styles", path, &dg), BG_RENDER_OK);
  size_t len = 0;
  char *svg = bg_read_file(path, &len);
  OK(svg && strstr(svg, "<svg") != NULL);
  free(svg);
  snprintf(path, sizeof path, "%s/plot_test.png", BG_BINARY_DIR);
  INT_EQ(bg_plot_write(f.m, &f.r, "print", BG_SOURCE_DIR "/styles", path, &dg), BG_RENDER_OK);
  char *png = bg_read_file(path, &len);
  OK(png && len > 8 && !memcmp(png, "\x89PNG", 4));
  free(png);
  INT_EQ(dg.nerrors, 0);
  INT_EQ(bg_plot_write(f.m, &f.r, NULL, NULL, "x.gif", &dg), BG_RENDER_ERROR);
  INT_EQ(dg.nerrors, 1);
  INT_EQ(bg_plot_write(f.m, &f.r, NULL, NULL, "/nonexistent-dir/x.pdf", &dg), BG_RENDER_EWRITE);
  INT_EQ(bg_plot_write(f.m, &f.r, "no-such-style", BG_SOURCE_DIR "/styles", path, &dg),
         BG_RENDER_ERROR);
  bg_diags_free(&dg);
  fx_free(&f);
}

int main(void) {
  test_nice_step();
  test_axis_ranges();
  test_labels();
  test_rlc();
  test_two_plots();
  test_value_scale();
  test_no_plot_statement();
  test_partial();
  test_degenerate();
  test_write();
  return bg_t_done();
}
