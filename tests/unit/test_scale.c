/* SPDX-License-Identifier: BSD-3-Clause */
/* The lookups that keep large models linear give the same answers as the
 * scans they replace: element names and bond numbers through the
 * compile-time hashes (and linearly in a hand-built model), remembered text measurements, the label
 * obstacle grid once it has grown, and a placed scene that skips the items
 * outside its clip rectangle writes exactly the PDF it wrote with those
 * items absent, and so does a scene cropped to that rectangle. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"
#include "harness.h"
#include "lang/lang.h"
#include "scene/surface.h"

/* The model of the text in sb, compiled (NULL on errors); dg is initialised
 * and stays the caller's to free (it points into sb). */
static bg_model *compile_text(const bg_strbuf *sb, const char *file, bg_diags *dg) {
  const char *src = bg_sb_str(sb);
  bg_diags_init(dg, file, src, strlen(src));
  bg_ast *ast = bg_parse_string(file, src, strlen(src), dg);
  bg_model *m = ast ? bg_model_compile(ast, NULL, 0, dg) : NULL;
  bg_ast_free(ast);
  return m;
}

static void test_find_elem(void) {
  bg_strbuf sb = {0};
  bg_sb_puts(&sb, "model names\nSe U = 1\n1 j\n");
  for (int i = 0; i < 300; i++) bg_sb_printf(&sb, "R r%d = 1\n", i);
  for (int i = 0; i < 300; i++) bg_sb_printf(&sb, "bond j -> r%d\n", i);
  bg_sb_puts(&sb, "bond U -> j\n");
  bg_diags dg;
  bg_model *m = compile_text(&sb, "names.bg", &dg);
  OK(m && m->elem_hash);
  if (m) {
    int all = 1;
    for (int e = 0; e < m->nelem; e++) all &= bg_model_find_elem(m, m->elem_name[e]) == e;
    OK(all);
    INT_EQ(bg_model_find_elem(m, "r300"), -1);
    INT_EQ(bg_model_find_elem(m, ""), -1);
    int *hash = m->elem_hash; /* a model without the table is searched linearly */
    m->elem_hash = NULL;
    INT_EQ(bg_model_find_elem(m, "r299"), bg_model_find_elem(m, "U") + 301);
    m->elem_hash = hash;
    INT_EQ(bg_model_find_elem(m, "r299"), bg_model_find_elem(m, "U") + 301);
    bg_model_free(m);
  }
  bg_diags_free(&dg);
  bg_sb_free(&sb);
}

/* Explicit bond numbers out of file order miss the 1..n fast path and go
 * through the number hash; a hand-built model without it scans. */
static void test_find_bond(void) {
  bg_strbuf sb = {0};
  bg_sb_puts(&sb, "model numbers\nSe U = 1\n1 j\n");
  for (int i = 0; i < 300; i++) bg_sb_printf(&sb, "R r%d = 1\n", i);
  for (int i = 0; i < 300; i++) bg_sb_printf(&sb, "bond %d j -> r%d\n", 7 * (300 - i), i);
  bg_sb_puts(&sb, "bond U -> j\n");
  bg_diags dg;
  bg_model *m = compile_text(&sb, "numbers.bg", &dg);
  OK(m && m->bond_hash);
  if (m) {
    int all = 1;
    for (int b = 0; b < m->nbond; b++) all &= bg_model_find_bond(m, m->bond_num[b]) == b;
    OK(all);
    INT_EQ(bg_model_find_bond(m, 2100), 0);  /* r0's bond, the first in the file */
    INT_EQ(bg_model_find_bond(m, 1), 300);   /* U's bond takes the smallest free number */
    INT_EQ(bg_model_find_bond(m, 8), -1);
    INT_EQ(bg_model_find_bond(m, -7), -1);
    int *hash = m->bond_hash;
    m->bond_hash = NULL;
    INT_EQ(bg_model_find_bond(m, 7), 299);
    m->bond_hash = hash;
    INT_EQ(bg_model_find_bond(m, 7), 299);
    bg_model_free(m);
  }
  bg_diags_free(&dg);
  bg_sb_free(&sb);
}

static void test_measure_memo(void) {
  double w1, h1, w2, h2, w3, h3, w4, h4;
  bg_text_measure("DejaVu Sans", 11, "R : R<sub>1</sub>", &w1, &h1);
  bg_text_measure("DejaVu Sans", 22, "R : R<sub>1</sub>", &w2, &h2);
  bg_text_measure("DejaVu Sans", 11, "R : R<sub>12</sub>", &w3, &h3);
  for (int i = 0; i < 3000; i++) { /* grow the table past several doublings */
    char s[32];
    snprintf(s, sizeof s, "%d", i);
    bg_text_measure("DejaVu Sans", 8, s, &w4, &h4);
  }
  bg_text_measure("DejaVu Sans", 11, "R : R<sub>1</sub>", &w4, &h4);
  OK(w1 > 0 && h1 > 0);
  OK(w4 == w1 && h4 == h1);
  /* the baseline is remembered beside the size: asked before and after the
   * table has grown, the same; below the top and above the bottom of the box;
   * twice the size, twice as far down */
  double b1 = bg_text_baseline("DejaVu Sans", 11, "R : R<sub>1</sub>");
  double b2 = bg_text_baseline("DejaVu Sans", 22, "R : R<sub>1</sub>");
  for (int i = 3000; i < 6000; i++) {
    char s[32];
    snprintf(s, sizeof s, "%d", i);
    bg_text_baseline("DejaVu Sans", 8, s);
  }
  OK(b1 > 0 && b1 < h1);
  OK(bg_text_baseline("DejaVu Sans", 11, "R : R<sub>1</sub>") == b1);
  OK(b2 > 1.9 * b1 && b2 < 2.1 * b1);
  OK(bg_text_baseline("DejaVu Sans", 11, "new text") > 0);
  OK(w2 > 1.9 * w1 && w2 < 2.1 * w1);
  OK(w3 > w1);
}

/* Obstacles spread over many cells: scores after the grid has grown many
 * times equal a direct count over every obstacle. */
static void test_obstacle_grid(void) {
  bg_diagram d;
  memset(&d, 0, sizeof d);
  enum { NB = 20000 };
  static double box[NB][4];
  unsigned st = 12345;
  for (int i = 0; i < NB; i++) {
    st = st * 1103515245u + 12345u;
    double x = (st >> 8) % 20000, y = (st >> 3) % 3000;
    box[i][0] = x, box[i][1] = y, box[i][2] = x + 5 + i % 40, box[i][3] = y + 4 + i % 7;
    bg_obstacle_rect(&d, box[i][0], box[i][1], box[i][2], box[i][3]);
  }
  int same = 1;
  for (int q = 0; q < 200; q++) {
    double x = 100 * q, y = 15 * q, w = 60, h = 20;
    int direct = 0;
    for (int i = 0; i < NB; i++)
      direct += x - w / 2 < box[i][2] && box[i][0] < x + w / 2 && y - h / 2 < box[i][3] &&
                box[i][1] < y + h / 2;
    same &= bg_place_score(&d, bg_v(x, y), w, h) == 10 * direct;
  }
  OK(same);
  bg_obstacles_free(d.obs);
}

static void page_pdf(const bg_scene *s, double clip_x, bg_strbuf *out) {
  bg_scene page;
  bg_scene_init(&page, "DejaVu Sans");
  page.width = 300, page.height = 300;
  bg_surface_place pl = {s, clip_x, 0, 100, 100, 10, 10, 1, 0};
  bg_surface_page pg = {&page, &pl, 1};
  OK(bg_surface_pdf_pages(&pg, 1, NULL, 0, NULL, out) == 0);
  bg_scene_free(&page);
}

static void line_item(bg_scene *s, double x0, double x1, const char *role) {
  bg_scene_item *it = bg_scene_begin(s, BG_ITEM_STROKE, "%s", role);
  it->width = 1, it->color = (bg_rgba){0, 0, 0, 1};
  bg_scene_move(s, x0, 50);
  bg_scene_line(s, x1, 50);
}

/* Whether segment a-b meets the closed box, by separating axes (the box's
 * two and the segment's normal): independent of the grid's Liang-Barsky. */
static int seg_meets_box(const double *s, double x0, double y0, double x1, double y1) {
  if (fmax(s[0], s[2]) < x0 || fmin(s[0], s[2]) > x1 || fmax(s[1], s[3]) < y0 || fmin(s[1], s[3]) > y1)
    return 0;
  double nx = s[3] - s[1], ny = s[0] - s[2], c = nx * s[0] + ny * s[1];
  double v[4] = {nx * x0 + ny * y0 - c, nx * x1 + ny * y0 - c, nx * x0 + ny * y1 - c, nx * x1 + ny * y1 - c};
  return fmin(fmin(v[0], v[1]), fmin(v[2], v[3])) <= 0 && fmax(fmax(v[0], v[1]), fmax(v[2], v[3])) >= 0;
}

/* Long slanted lines are entered only in the cells along them: every query
 * still counts exactly the segments its box meets (and the slanted lines
 * do not fill their bounding boxes with entries). */
static void test_obstacle_segments(void) {
  bg_diagram d;
  memset(&d, 0, sizeof d);
  bg_scene_init(&d.scene, "DejaVu Sans");
  enum { NS = 400 };
  static double seg[NS][4];
  unsigned st = 777;
  for (int i = 0; i < NS; i++) {
    for (int k = 0; k < 4; k++) st = st * 1103515245u + 12345u, seg[i][k] = (st >> 9) % 4000 + 0.37 * k;
    if (i % 7 == 0) seg[i][3] = seg[i][1];  /* some horizontal */
    if (i % 11 == 0) seg[i][2] = seg[i][0]; /* some vertical */
    line_item(&d.scene, 0, 0, "segment");
    bg_scene_item *it = &d.scene.item[d.scene.nitem - 1];
    d.scene.pt[it->opadr].x = seg[i][0], d.scene.pt[it->opadr].y = seg[i][1];
    d.scene.pt[it->opadr + 1].x = seg[i][2], d.scene.pt[it->opadr + 1].y = seg[i][3];
    bg_obstacle_item(&d, d.scene.nitem - 1);
  }
  int same = 1;
  for (int q = 0; q < 2000; q++) {
    st = st * 1103515245u + 12345u;
    double x = (st >> 8) % 4000 + 0.5, y = (st >> 3) % 4000 + 0.25, w = 10 + q % 90, h = 6 + q % 30;
    int direct = 0;
    for (int i = 0; i < NS; i++) direct += seg_meets_box(seg[i], x - w / 2, y - h / 2, x + w / 2, y + h / 2);
    same &= bg_place_score(&d, bg_v(x, y), w, h) == direct;
  }
  OK(same);
  bg_obstacles_free(d.obs);
  bg_scene_free(&d.scene);
}

static void test_clipped_place(void) {
  bg_scene a, b;
  bg_scene_init(&a, "DejaVu Sans"), bg_scene_init(&b, "DejaVu Sans");
  a.width = b.width = 1000, a.height = b.height = 100;
  line_item(&a, 10, 90, "inside"), line_item(&b, 10, 90, "inside");
  line_item(&a, 500, 600, "far outside"); /* only in a */
  bg_scene_text(&a, "far", 800, 50, 11, 0, 0, (bg_rgba){0, 0, 0, 1}, "far text");
  bg_strbuf pa = {0}, pb = {0};
  page_pdf(&a, 0, &pa);
  page_pdf(&b, 0, &pb);
  OK(pa.len == pb.len && !memcmp(pa.s, pb.s, pa.len));
  bg_sb_clear(&pa), bg_sb_clear(&pb);
  page_pdf(&a, 480, &pa); /* a's second line is inside this clip, b has none there */
  page_pdf(&b, 480, &pb);
  OK(pa.len != pb.len || memcmp(pa.s, pb.s, pa.len));
  bg_sb_free(&pa), bg_sb_free(&pb);
  double box[4];
  bg_scene_item_box(&a, &a.item[0], box);
  OK(box[0] <= 10 - 0.5 && box[2] >= 90 + 0.5 && box[1] <= 49.5 && box[3] >= 50.5);
  bg_scene_free(&a), bg_scene_free(&b);
}

/* A scene cropped to a placed rectangle plus the cull margin places into
 * the same PDF as the whole scene, and keeps only the items near it. */
static void test_crop(void) {
  bg_scene a;
  bg_scene_init(&a, "DejaVu Sans");
  a.width = 1000, a.height = 100;
  a.title = bg_arena_strdup(&a.arena, "crop");
  line_item(&a, 10, 90, "inside");
  line_item(&a, 500, 600, "far outside");
  line_item(&a, 120, 130, "within the margin");
  bg_scene_text(&a, "near", 105, 50, 11, 0, 0.5, (bg_rgba){0, 0, 0, 1}, "near text");
  bg_scene_text(&a, "far", 800, 50, 11, 0, 0, (bg_rgba){0, 0, 0, 1}, "far text");
  const double pad = BG_PLACE_CULL_PAD, clip[4] = {-pad, -pad, 100 + pad, 100 + pad};
  bg_scene k;
  bg_scene_crop(&a, clip, &k);
  INT_EQ(k.nitem, 3);
  OK(k.nitem == 3 && !strcmp(k.item[0].role, "inside") && !strcmp(k.item[1].role, "within the margin") &&
     !strcmp(k.item[2].text, "near") && k.item[1].nop == 2 && k.pt[k.item[1].opadr].x == 120);
  OK(k.width == a.width && k.height == a.height && !strcmp(k.title, "crop"));
  bg_strbuf pa = {0}, pk = {0};
  page_pdf(&a, 0, &pa);
  page_pdf(&k, 0, &pk);
  OK(pa.len > 0 && pa.len == pk.len && !memcmp(pa.s, pk.s, pa.len));
  bg_sb_free(&pa), bg_sb_free(&pk);
  bg_scene_free(&a), bg_scene_free(&k);
}

static int has_image(const bg_strbuf *b) {
  const char *key = "/Subtype /Image";
  size_t n = strlen(key);
  for (size_t i = 0; i + n <= b->len; i++)
    if (!memcmp(b->s + i, key, n)) return 1;
  return 0;
}

static void raster_pdf(const bg_scene *s, double raster, bg_strbuf *out) {
  bg_scene page;
  bg_scene_init(&page, "DejaVu Sans");
  page.width = 300, page.height = 300;
  bg_surface_place pl = {s, 0, 0, 100, 100, 10, 10, 1, raster};
  bg_surface_page pg = {&page, &pl, 1};
  OK(bg_surface_pdf_pages(&pg, 1, NULL, 0, NULL, out) == 0);
  bg_scene_free(&page);
}

/* A placement drawn as an image (the report's map of a huge diagram):
 * the page holds one image whatever the number of items, where the vector
 * placement holds every item; and raster 0 is the vector placement. */
static void test_raster_place(void) {
  size_t vec[2], ras[2];
  for (int k = 0; k < 2; k++) {
    bg_scene a;
    bg_scene_init(&a, "DejaVu Sans");
    a.width = a.height = 100;
    int n = k ? 4000 : 200;
    for (int i = 0; i < n; i++) { /* lines at scattered heights, so they do not compress away */
      line_item(&a, (i * 37) % 90, (i * 37) % 90 + 10, "line");
      a.pt[a.nop - 1].y = a.pt[a.nop - 2].y = (i * 7919) % 1000 / 10.0;
    }
    bg_scene_text(&a, "big", 50, 20, 11, 0.5, 0, (bg_rgba){0, 0, 0, 1}, "text");
    bg_strbuf pv = {0}, pr = {0}, p0 = {0}, pp = {0};
    raster_pdf(&a, 3, &pr);
    raster_pdf(&a, 0, &pv);
    page_pdf(&a, 0, &pp);
    OK(pv.len == pp.len && !memcmp(pv.s, pp.s, pv.len));
    OK(pr.len > 0 && has_image(&pr));
    OK(!has_image(&pv));
    vec[k] = pv.len, ras[k] = pr.len;
    bg_sb_free(&pv), bg_sb_free(&pr), bg_sb_free(&p0), bg_sb_free(&pp);
    bg_scene_free(&a);
  }
  fprintf(stderr, "raster place: vectors %zu -> %zu bytes, image %zu -> %zu\n", vec[0], vec[1], ras[0], ras[1]);
  OK(vec[1] > 3 * vec[0]);     /* vectors: every item on the page */
  OK(ras[1] < ras[0] + 20000); /* an image: bounded by its pixels */
}

int main(void) {
  test_find_elem();
  test_find_bond();
  test_measure_memo();
  test_obstacle_grid();
  test_obstacle_segments();
  test_clipped_place();
  test_crop();
  test_raster_place();
  return bg_t_done();
}
