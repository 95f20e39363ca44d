/* SPDX-License-Identifier: BSD-3-Clause */
/* The SVG writer (render/scene/svg_writer.c): searchable <text> in the chosen
 * font with a fallback list, <title> tooltips on every bond and element, CSS
 * classes per role, a viewBox and no fixed size; and the picture is the one
 * cairo's SVG shows: both are rasterised with rsvg-convert and compared pixel
 * by pixel (cairo reads the PNGs back). */
#include <cairo.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "analysis/analysis.h"
#include "base/fileio.h"
#include "causality/causality.h"
#include "diagram/render.h"
#include "harness.h"
#include "lang/lang.h"

typedef struct loaded {
  char *src;
  bg_model *m;
  bg_analysis a;
} loaded;

static int load(const char *path, loaded *L) {
  size_t n;
  bg_diags dg;
  L->src = bg_read_file(path, &n);
  bg_diags_init(&dg, path, L->src, n);
  bg_ast *ast = bg_parse_string(path, L->src, n, &dg);
  L->m = ast && !dg.nerrors ? bg_model_compile(ast, NULL, 0, &dg) : NULL;
  bg_ast_free(ast);
  if (L->m) {
    bg_analysis_init(&L->a, L->m);
    bg_causality_assign(L->m, L->m->method, &L->a, &dg);
    bg_analysis_limits lim = {0, 0};
    bg_analysis_run(L->m, &L->a, &lim);
  }
  bg_diags_free(&dg);
  return L->m ? 0 : -1;
}

static void unload(loaded *L) {
  bg_analysis_free(&L->a);
  bg_model_free(L->m);
  free(L->src);
}

static int count(const char *s, const char *needle) {
  int n = 0;
  for (const char *p = strstr(s, needle); p; p = strstr(p + 1, needle)) n++;
  return n;
}

/* The text of every <text> element with its tags removed, one a line. */
static void text_contents(const char *svg, bg_strbuf *out) {
  for (const char *p = strstr(svg, "<text"); p; p = strstr(p, "<text")) {
    const char *end = strstr(p, "</text>");
    const char *q = strchr(p, '>') + 1;
    const char *t = strstr(q, "</title>");
    if (t && t < end) q = t + 8; /* the tooltip is not the text */
    for (int in_tag = 0; q < end; q++) {
      if (*q == '<') in_tag = 1;
      else if (*q == '>') in_tag = 0;
      else if (!in_tag) bg_sb_putc(out, *q);
    }
    bg_sb_putc(out, '\n');
    p = end;
  }
}

/* The example's diagram with these layers (NULL after a failed check). */
static bg_diagram *diagram(const char *example, unsigned show, loaded *L, bg_diags *dg) {
  bg_diags_init(dg, "t", NULL, 0);
  if (load(example, L) != 0) {
    BG_T_REPORT(0, "%s loads", example);
    return NULL;
  }
  bg_render_opts o = {.show = show, .style_dir = BG_SOURCE_DIR "/styles"};
  bg_diagram *d = bg_diagram_build(L->m, &L->a, &o, dg);
  BG_T_REPORT(d != NULL, "%s: diagram built", example);
  return d;
}

static void structure(const char *example, unsigned show) {
  loaded L;
  bg_diags dg;
  bg_diagram *d = diagram(example, show, &L, &dg);
  if (!d) return;
  bg_strbuf svg = {0}, texts = {0};
  INT_EQ(bg_diagram_render(d, "svg", &svg, &dg), BG_RENDER_OK);
  const char *s = bg_sb_str(&svg);
  OK(strstr(s, "viewBox=\"0 0 ") != NULL);
  char *svgtag = strndup(s, (size_t)(strchr(strstr(s, "<svg"), '>') - s));
  BG_T_REPORT(!strstr(svgtag, " width=") && !strstr(svgtag, " height="),
              "%s: no fixed size on <svg>", example);
  BG_T_REPORT(strstr(svgtag, "font-family=\"'DejaVu Sans', 'DejaVu Sans', Verdana") != NULL,
              "%s: the style's font then a fallback list", example);
  free(svgtag);
  bg_strbuf dump = {0};
  bg_diagram_dump(d, &dump); /* one line per item: "role\tkind ..." */
  BG_T_REPORT(count(s, "<text") == count(bg_sb_str(&dump), "\ttext "),
              "%s: one <text> per text item (%d vs %d)", example, count(s, "<text"),
              count(bg_sb_str(&dump), "\ttext "));
  BG_T_REPORT(count(s, "<path") == count(bg_sb_str(&dump), "\tstroke ") +
                                       count(bg_sb_str(&dump), "\tfill "),
              "%s: one <path> per drawn shape", example);
  bg_sb_free(&dump);
  text_contents(s, &texts);
  for (int e = 0; e < L.m->nelem; e++) { /* every name is text: "R : R1" (subscript in a tspan) */
    if (bg_elem_is_junction(L.m->elem_kind[e])) continue;
    char want[128];
    snprintf(want, sizeof want, "%s : %s\n", bg_elem_display_kind(L.m, e), L.m->elem_name[e]);
    BG_T_REPORT(strstr(bg_sb_str(&texts), want) != NULL, "%s: text '%s'", example, L.m->elem_name[e]);
  }
  for (int k = 0; k < L.m->nbond; k++) { /* the bond line, its stroke and its number */
    char want[64];
    snprintf(want, sizeof want, "<title>bond %d: ", L.m->bond_num[k]);
    BG_T_REPORT(count(s, want) == 3, "%s: bond %d has 3 tooltips (got %d)", example,
                L.m->bond_num[k], count(s, want));
    snprintf(want, sizeof want, "class=\"bond b%d\"", L.m->bond_num[k]);
    INT_EQ(count(s, want), 1);
  }
  /* the page title (the model title), then one per bond item and node */
  INT_EQ(count(s, "<title>"), (L.m->title ? 1 : 0) + 3 * L.m->nbond + bg_diagram_count(d, "node"));
  INT_EQ(count(s, "class=\"stroke "), bg_diagram_count(d, "stroke"));
  INT_EQ(count(s, "class=\"path p"), bg_diagram_count(d, "path"));
  INT_EQ(count(s, "class=\"loop l"), bg_diagram_count(d, "loop"));
  INT_EQ(count(s, "class=\"flash conflict c"), bg_diagram_count(d, "flash"));
  bg_sb_free(&svg), bg_sb_free(&texts);
  bg_diagram_free(d);
  bg_diags_free(&dg);
  unload(&L);
}

/* Fraction of pixels of two same-size PNGs that differ by more than 1/4 in a
 * channel; 1 when they cannot be read or differ in size. */
static double png_difference(const char *a, const char *b) {
  cairo_surface_t *x = cairo_image_surface_create_from_png(a);
  cairo_surface_t *y = cairo_image_surface_create_from_png(b);
  double frac = 1;
  int w = cairo_image_surface_get_width(x), h = cairo_image_surface_get_height(x);
  if (cairo_surface_status(x) == 0 && cairo_surface_status(y) == 0 && w > 0 &&
      w == cairo_image_surface_get_width(y) && h == cairo_image_surface_get_height(y)) {
    const unsigned char *p = cairo_image_surface_get_data(x), *q = cairo_image_surface_get_data(y);
    int sx = cairo_image_surface_get_stride(x), sy = cairo_image_surface_get_stride(y);
    long bad = 0;
    for (int r = 0; r < h; r++)
      for (int c = 0; c < 4 * w; c++) bad += abs(p[r * sx + c] - q[r * sy + c]) > 64;
    frac = (double)bad / (4.0 * w * h);
  }
  cairo_surface_destroy(x);
  cairo_surface_destroy(y);
  return frac;
}

static void looks_the_same(const char *example, unsigned show) {
  loaded L;
  bg_diags dg;
  bg_diagram *d = diagram(example, show, &L, &dg);
  if (!d) return;
  double w, h;
  bg_diagram_size(d, &w, &h);
  const char *fmt[2] = {"svg", "svg-cairo"};
  char dir[] = "/tmp/bgsvgXXXXXX", path[2][300], png[2][300];
  OK(mkdtemp(dir) != NULL);
  for (int i = 0; i < 2; i++) {
    bg_strbuf b = {0};
    bg_diagram_render(d, fmt[i], &b, &dg);
    snprintf(path[i], sizeof path[i], "%s/%d.svg", dir, i);
    snprintf(png[i], sizeof png[i], "%s/%d.png", dir, i);
    bg_write_file_atomic(path[i], b.s, b.len);
    bg_sb_free(&b);
    char cmd[1400];
    snprintf(cmd, sizeof cmd, "rsvg-convert -w %d -h %d -b white -o '%s' '%s'", (int)(2 * w),
             (int)(2 * h), png[i], path[i]);
    BG_T_REPORT(system(cmd) == 0, "%s: rsvg-convert (tools/deps.sh installs librsvg2-bin)", cmd);
  }
  double diff = png_difference(png[0], png[1]);
  printf("%s (show %#x): %.4f%% of the pixels differ\n", example, show, 100 * diff);
  BG_T_REPORT(diff < 0.005, "%s: the written SVG looks as cairo's (%.3f%% differ)", example,
              100 * diff);
  for (int i = 0; i < 2; i++) unlink(path[i]), unlink(png[i]);
  rmdir(dir);
  bg_diagram_free(d);
  bg_diags_free(&dg);
  unload(&L);
}

int main(void) {
  static const char *const examples[] = {"examples/rlc.bg", "examples/hydraulic_bridge.bg",
                                         "examples/delta.bg", "examples/internal_mod_tf.bg"};
  for (int i = 0; i < 4; i++) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s", BG_SOURCE_DIR, examples[i]);
    structure(path, 0);
    structure(path, BG_SHOW_ALL);
    looks_the_same(path, 0);
    looks_the_same(path, BG_SHOW_ALL | BG_SHOW_VARIABLES);
  }
  return bg_t_done();
}
