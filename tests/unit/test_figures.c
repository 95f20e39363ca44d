/* Figure geometry, measured from the scene (figure_check.h): the checker on
 * a hand-made scene with one of each fault, then every example in every
 * shipped style, with the default layers and with --show all, against the
 * limits of docs/drawing.md ("Measured geometry"). BG_FIGURES_VERBOSE=1
 * prints each diagram's counts. */
#include "harness.h"
#include "analysis_fixture.h"
#include "examples_list.h"
#include "figure_check.h"
#include "diagram/render.h"

/* ---------------------------------------------------------------- the checker itself */
static void line(bg_scene *s, const char *role, double x0, double y0, double x1, double y1) {
  bg_scene_begin(s, BG_ITEM_STROKE, "%s", role);
  bg_scene_move(s, x0, y0);
  bg_scene_line(s, x1, y1);
}

/* A bond with its barb as the last segment, like diagram.c draws it. */
static void bond(bg_scene *s, int num, double x0, double y0, double x1, double y1) {
  char role[32];
  snprintf(role, sizeof role, "bond %d", num);
  line(s, role, x0, y0, x1, y1);
  bg_scene_line(s, x1 - 5, y1 - 5);
}

static void test_checker(void) {
  bg_scene s;
  bg_scene_init(&s, "DejaVu Sans");
  bond(&s, 1, 0, 0, 100, 0);      /* horizontal */
  bond(&s, 2, 100, 0.5, 200, 50); /* slanted (0.3 degrees would count too) */
  bond(&s, 3, 150, -50, 150, 60); /* vertical, crosses bond 2 */
  bond(&s, 4, 300, 0, 300, 100);  /* vertical, alone */
  line(&s, "stroke bond=1", 100, -4.5, 100, 4.5); /* touches bond 2's start */
  line(&s, "stroke bond=4", 295.5, 0, 304.5, 0);  /* clear */
  line(&s, "path 1", 0, -7, 100, -7);
  line(&s, "path 2", 250, 40, 350, 40);            /* through the label of node X */
  bg_rgba ink = {0, 0, 0, 1};
  bg_scene_text(&s, "1", 50, 8, 8, 0.5, 0.5, ink, "number bond=1");     /* clear, own bond nearest */
  bg_scene_text(&s, "4", 148, 20, 8, 0.5, 0.5, ink, "number bond=4");   /* over bond 3, nearer to it */
  bg_scene_text(&s, "X : x", 300, 40, 11, 0.5, 0.5, ink, "node X");     /* bond 4 runs through it */
  bg_scene_text(&s, "P1", 50, -12, 8, 0.5, 0.5, ink, "path-tag 1");     /* beside its path */
  bg_scene_text(&s, "P2", 50, -30, 8, 0.5, 0.5, ink, "path-tag 2");     /* nearer path 1 */
  fc_stats st = {0};
  fc_count(&s, &st);
  INT_EQ(st.bonds, 4);
  INT_EQ(st.slanted, 1);
  INT_EQ(st.crossings, 1);
  INT_EQ(st.strokes, 2);
  INT_EQ(st.touching, 1);
  INT_EQ(st.labels, 4);
  INT_EQ(st.over, 1);
  INT_EQ(st.numbers, 2);
  INT_EQ(st.astray, 1);
  INT_EQ(st.tags, 2);
  INT_EQ(st.tags_far, 1);
  INT_EQ(st.through, 1);
  INT_EQ(st.lines_through, 1);
  bg_scene_free(&s);
}

/* ---------------------------------------------------------------- the examples */
static const char *const styles[] = {"default", "print", "slides"};
static const unsigned shows[] = {BG_SHOW_DEFAULT, BG_SHOW_ALL};
static const char *const show_names[] = {"default", "all"};

/* The limits each total must stay within, per style and layer set (rows:
 * default, print, slides; each with the default layers, then --show all),
 * as measured with the grid placement pass (issue 15; the numbers before
 * it are in docs/drawing.md, "Measured geometry"). The targets are
 * met for strokes (0 touching), numbers (0 nearer another bond), crossings
 * (0) and slanted bonds (2 of 136, 1.5 %); labels over lines are 0 with the
 * default layers. Order: bonds, slanted, strokes, touching, labels, over,
 * numbers, astray, tags, tags_far, through, lines_through, crossings;
 * bonds, strokes and labels must be equal (every bond of every example,
 * the two Sf* bonds of lagrange_rlc included). */
static const fc_stats limits[3][2] = {
    {{136, 2, 136, 0, 136, 0, 134, 0, 0, 0, 0, 0, 0}, {136, 2, 136, 0, 220, 4, 134, 0, 84, 46, 1, 0, 0}},
    {{136, 2, 136, 0, 136, 0, 134, 0, 0, 0, 0, 0, 0}, {136, 2, 136, 0, 220, 6, 134, 0, 84, 48, 1, 0, 0}},
    {{136, 2, 136, 0, 136, 0, 134, 0, 0, 0, 0, 1, 0}, {136, 2, 136, 0, 220, 6, 134, 1, 84, 47, 2, 0, 0}},
};

static void print_row(const char *what, const fc_stats *t) {
  printf("%-34s %4d %4d %4d %4d %4d %4d %4d %4d %4d %4d %4d %4d %4d\n", what, t->bonds, t->slanted,
         t->strokes, t->touching, t->labels, t->over, t->numbers, t->astray, t->tags, t->tags_far,
         t->through, t->lines_through, t->crossings);
}

static void measure(fc_stats tot[3][2]) {
  char *names[256];
  int n = bg_t_list_examples(names, 256), verbose = getenv("BG_FIGURES_VERBOSE") != NULL;
  OK(n >= 17);
  for (int i = 0; i < n; i++) {
    fx f;
    names[i][strlen(names[i]) - 3] = 0;
    OK(fx_load(&f, names[i], -1, NULL, 0, NULL, NULL) == 0);
    for (int si = 0; f.m && si < 3; si++)
      for (int k = 0; k < 2; k++) {
        bg_render_opts o = {.show = shows[k], .style = styles[si], .style_dir = BG_SOURCE_DIR "/styles"};
        bg_diagram *d = bg_diagram_build(f.m, &f.a, &o, &f.dg);
        OK(d != NULL);
        if (!d) continue;
        fc_stats st = {0};
        fc_count(bg_diagram_scene(d), &st);
        fc_add(&tot[si][k], &st);
        char what[128];
        snprintf(what, sizeof what, "%s %s %s", names[i], styles[si], show_names[k]);
        if (verbose) print_row(what, &st);
        bg_diagram_free(d);
      }
    fx_free(&f);
    free(names[i]);
  }
}

static void test_examples(void) {
  fc_stats tot[3][2] = {{{0}}};
  measure(tot);
  printf("%-34s bond slnt strk touc labl over numb astr tags tfar thru lthr cros\n", "");
  for (int si = 0; si < 3; si++)
    for (int k = 0; k < 2; k++) {
      char what[64];
      snprintf(what, sizeof what, "all examples %s %s", styles[si], show_names[k]);
      print_row(what, &tot[si][k]);
      const int *got = (const int *)&tot[si][k], *lim = (const int *)&limits[si][k];
      INT_EQ(got[0], lim[0]); /* bonds */
      INT_EQ(got[2], lim[2]); /* strokes */
      INT_EQ(got[4], lim[4]); /* labels */
      for (size_t c = 0; c < sizeof(fc_stats) / sizeof(int); c++)
        BG_T_REPORT(got[c] <= lim[c], "%s: column %zu: %d > limit %d", what, c, got[c], lim[c]);
    }
}

int main(void) {
  test_checker();
  test_examples();
  return bg_t_done();
}
