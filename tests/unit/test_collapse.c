/* SPDX-License-Identifier: BSD-3-Clause */
/* Collapsed instances (--collapse) and detectors in the diagram, measured on
 * the scene (docs/drawing.md, "Collapsed instances", "Detectors"): one box per
 * collapsed instance, the bonds through its ports ending on the box with their
 * strokes there, nothing of its inside drawn, paths and loops that enter it
 * ending at the box, unknown names refused with a suggestion; a detector as
 * its own node joined by an activated bond, the rest of the drawing as
 * without it. */
#include "harness.h"
#include "analysis_fixture.h"
#include "figure_check.h"
#include "diagram/render.h"

static int load_text(fx *f, const char *src) {
  memset(f, 0, sizeof *f);
  f->src = strdup(src);
  bg_diags_init(&f->dg, "t.bg", f->src, strlen(f->src));
  bg_ast *ast = bg_parse_string("t.bg", f->src, strlen(f->src), &f->dg);
  if (ast && !f->dg.nerrors) f->m = bg_model_compile(ast, NULL, 0, &f->dg);
  if (ast) bg_ast_free(ast);
  if (!f->m) { bg_diags_print(&f->dg, stderr); return -1; }
  fx_init_analysis(&f->a, f->m);
  bg_causality_assign(f->m, f->m->method, &f->a, &f->dg);
  bg_analysis_run(f->m, &f->a, NULL);
  return 0;
}

static bg_diagram *draw(fx *f, const char *const *names, int n, unsigned show) {
  bg_render_opts o = {.show = show, .style_dir = BG_SOURCE_DIR "/styles", .collapse = names,
                      .ncollapse = n};
  return bg_diagram_build(f->m, &f->a, &o, &f->dg);
}

static int count_role(const bg_scene *s, const char *prefix) {
  int n = 0;
  for (int i = 0; i < s->nitem; i++) n += fc_starts(s->item[i].role, prefix);
  return n;
}

static const bg_scene_item *item(const bg_scene *s, const char *role) {
  for (int i = 0; i < s->nitem; i++)
    if (!strcmp(s->item[i].role, role)) return &s->item[i];
  return NULL;
}

typedef struct rect { double x0, y0, x1, y1; } rect;

/* The box of "box NAME": the corners of its path. */
static rect box_of(const bg_scene *s, const char *name) {
  char role[64];
  snprintf(role, sizeof role, "box %s", name);
  rect r = {1e300, 1e300, -1e300, -1e300};
  const bg_scene_item *it = item(s, role);
  for (int k = 0; it && k < it->nop; k++) {
    const bg_scene_pt *o = &s->pt[it->opadr + k];
    if (s->code[it->opadr + k] == BG_OP_CLOSE) continue;
    r.x0 = fmin(r.x0, o->x), r.x1 = fmax(r.x1, o->x);
    r.y0 = fmin(r.y0, o->y), r.y1 = fmax(r.y1, o->y);
  }
  return r;
}

static double border_dist(rect r, double x, double y) {
  double dx = fmax(fmax(r.x0 - x, x - r.x1), 0), dy = fmax(fmax(r.y0 - y, y - r.y1), 0);
  if (dx > 0 || dy > 0) return hypot(dx, dy);
  return fmin(fmin(x - r.x0, r.x1 - x), fmin(y - r.y0, r.y1 - y)); /* inside: to the nearest side */
}

static int strictly_inside(rect r, double x, double y) {
  return x > r.x0 + 1 && x < r.x1 - 1 && y > r.y0 + 1 && y < r.y1 - 1;
}

/* Whether bond b has an end inside instance `in` (by its qualified name). */
static int in_inst(const bg_model *m, int e, const char *in) {
  size_t n = strlen(in);
  return !strncmp(m->elem_name[e], in, n) && m->elem_name[e][n] == '.';
}

/* motor_drive_lib: M (DCMotor) and G (Gearbox) collapsed. */
static void test_boxes(void) {
  fx f;
  OK(fx_load(&f, "components/motor_drive_lib", -1, NULL, 0, NULL, NULL) == 0);
  const char *names[] = {"M", "G"};
  bg_diagram *d = draw(&f, names, 2, BG_SHOW_DEFAULT | BG_SHOW_PATHS | BG_SHOW_LOOPS);
  OK(d != NULL);
  if (!d) { fx_free(&f); return; }
  const bg_model *m = f.m;
  const bg_scene *s = bg_diagram_scene(d);
  INT_EQ(count_role(s, "box"), 2);
  INT_EQ(count_role(s, "box-label"), 2);
  OK(item(s, "box-label M") && strstr(item(s, "box-label M")->text, "DCMotor"));
  OK(item(s, "frame S1") != NULL && item(s, "frame M") == NULL && item(s, "frame G") == NULL);
  rect box[2] = {box_of(s, "M"), box_of(s, "G")};
  int ports = 0, strokes_at_box = 0;
  for (int b = 0; b < m->nbond; b++) {
    int t = m->bond_tail[b], h = m->bond_head[b];
    char role[32];
    snprintf(role, sizeof role, "bond %d", m->bond_num[b]);
    const bg_scene_item *bi = item(s, role);
    for (int k = 0; k < 2; k++) {
      int it = in_inst(m, t, names[k]), ih = in_inst(m, h, names[k]);
      if (it && ih) OK(bi == NULL); /* inside the box: not drawn */
      if (it == ih || !bi) continue;
      /* a port bond: its inner end on the box's border */
      ports++;
      const bg_scene_pt *end = &s->pt[bi->opadr + (it ? 0 : bi->nop - 2)];
      OK(border_dist(box[k], end->x, end->y) < 0.5);
      snprintf(role, sizeof role, "stroke bond=%d", m->bond_num[b]);
      const bg_scene_item *st = item(s, role);
      OK(st != NULL); /* every bond of this model has a stroke */
      if (!st) continue;
      const bg_scene_pt *a = &s->pt[st->opadr], *z = &s->pt[st->opadr + 1];
      double cx = (a->x + z->x) / 2, cy = (a->y + z->y) / 2;
      int at_inner = (f.a.bond_stroke[b] == BG_STROKE_HEAD) == ih;
      if (at_inner) {
        strokes_at_box++;
        OK(border_dist(box[k], cx, cy) < 0.5);
      }
    }
  }
  INT_EQ(ports, 4);            /* M: a, shaft; G: a, b */
  OK(strokes_at_box >= 2);     /* U imposes the effort on M; the shaft flows */
  INT_EQ(count_role(s, "number"), count_role(s, "bond"));
  for (int i = 0; i < s->nitem; i++) /* nothing of M's or G's inside */
    if (fc_starts(s->item[i].role, "node"))
      OK(strncmp(s->item[i].role, "node M.", 7) && strncmp(s->item[i].role, "node G.", 7));
  /* paths: P2 (M.Ra - M.La, inside M) is not drawn; P5 (M.Jm - S1.spring)
   * is, and ends at M's box: none of its points inside it */
  const bg_analysis *a = &f.a;
  for (int p = 0; p < a->npath; p++) {
    int inside = 1;
    for (int k = 0; k < a->path_n[p]; k++) {
      int b = a->path_bonds[a->path_adr[p] + k];
      inside &= in_inst(m, m->bond_tail[b], "M") && in_inst(m, m->bond_head[b], "M");
    }
    char role[32];
    snprintf(role, sizeof role, "path %d", p + 1);
    int drawn = 0;
    for (int i = 0; i < s->nitem; i++) {
      const bg_scene_item *it = &s->item[i];
      if (!fc_starts(it->role, "path") || atoi(it->role + 5) != p + 1) continue;
      drawn = 1;
      fc_seg *sg;
      int ns = fc_flatten(s, it, &sg); /* curves as chords */
      for (int k = 0; k < ns; k++)
        for (int q = 0; q < 2; q++)
          for (int j = 0; j <= 4; j++) /* the line stays out of the boxes */
            OK(!strictly_inside(box[q], sg[k].x0 + j / 4.0 * (sg[k].x1 - sg[k].x0),
                                sg[k].y0 + j / 4.0 * (sg[k].y1 - sg[k].y0)));
      free(sg);
    }
    if (inside) OK(!drawn);
    else if (!in_inst(m, m->bond_tail[a->path_bonds[a->path_adr[p]]], "G")) OK(drawn || a->path_n[p] == 0);
  }
  /* a redraw keeps the boxes */
  bg_diagram *r = bg_diagram_redraw(d, BG_SHOW_DEFAULT, 0, 0, &f.dg);
  OK(r && count_role(bg_diagram_scene(r), "box") == 2);
  bg_diagram_free(r);
  bg_diagram_free(d);
  /* all: one box per top-level instance, and only the model's own bonds */
  const char *all[] = {"all"};
  d = draw(&f, all, 1, 0);
  OK(d != NULL);
  if (d) {
    s = bg_diagram_scene(d);
    INT_EQ(count_role(s, "box"), 4);
    INT_EQ(count_role(s, "bond"), 7);   /* U->M, M->S1, S1->G, G->S2, S2->jl, jl->Jl, jl->bl */
    INT_EQ(count_role(s, "stroke"), 7);
    INT_EQ(count_role(s, "frame"), 0);
  }
  bg_diagram_free(d);
  fx_free(&f);
}

static void test_unknown_name(void) {
  fx f;
  OK(fx_load(&f, "components/motor_drive_lib", -1, NULL, 0, NULL, NULL) == 0);
  const char *names[] = {"S3"};
  int e0 = f.dg.nerrors;
  OK(draw(&f, names, 1, 0) == NULL);
  OK(f.dg.nerrors == e0 + 1);
  OK(f.dg.n > 0 && strstr(f.dg.items[f.dg.n - 1].msg, "--collapse S3: no instance 'S3' (did you mean 'S1'?)"));
  fx_free(&f);
  OK(fx_load(&f, "rlc", -1, NULL, 0, NULL, NULL) == 0);
  names[0] = "M1";
  OK(draw(&f, names, 1, 0) == NULL);
  OK(strstr(f.dg.items[f.dg.n - 1].msg, "the model has no submodel instances"));
  fx_free(&f);
}

/* Nested: the outermost collapsed instance is the box; a collapsed child sits
 * in its parent's frame. */
static void test_nested(void) {
  static const char *src =
      "submodel Cell(R = 1, C = 1)\n  port a\n  0 n\n  R r = R\n  C c = C\n"
      "  bond a -> n\n  bond n -> r\n  bond n -> c\nend\n"
      "submodel Pair\n  port a\n  1 j\n  Cell X\n  Cell Y\n  bond a -> j\n"
      "  bond j -> X.a\n  bond j -> Y.a\nend\n"
      "Se U = 1\nPair P\nbond U -> P.a\n";
  fx f;
  OK(load_text(&f, src) == 0);
  const char *one[] = {"P.X"};
  bg_diagram *d = draw(&f, one, 1, 0);
  OK(d != NULL);
  if (d) {
    const bg_scene *s = bg_diagram_scene(d);
    INT_EQ(count_role(s, "box"), 1);
    OK(item(s, "box P.X") != NULL && item(s, "frame P") != NULL && item(s, "frame P.X") == NULL);
    rect fr = {1e300, 1e300, -1e300, -1e300}, bx = box_of(s, "P.X");
    const bg_scene_item *it = item(s, "frame P");
    for (int k = 0; it && k < it->nop; k++)
      if (s->code[it->opadr + k] != BG_OP_CLOSE)
        fr.x0 = fmin(fr.x0, s->pt[it->opadr + k].x), fr.x1 = fmax(fr.x1, s->pt[it->opadr + k].x),
        fr.y0 = fmin(fr.y0, s->pt[it->opadr + k].y), fr.y1 = fmax(fr.y1, s->pt[it->opadr + k].y);
    OK(bx.x0 > fr.x0 && bx.x1 < fr.x1 && bx.y0 > fr.y0 && bx.y1 < fr.y1); /* inside P's frame */
    INT_EQ(count_role(s, "bond"), f.m->nbond - 2);
  }
  bg_diagram_free(d);
  const char *two[] = {"P.X", "P"};
  d = draw(&f, two, 2, 0);
  OK(d != NULL);
  if (d) {
    INT_EQ(count_role(bg_diagram_scene(d), "box"), 1);
    OK(item(bg_diagram_scene(d), "box P") != NULL);
    INT_EQ(count_role(bg_diagram_scene(d), "bond"), 1);
  }
  bg_diagram_free(d);
  fx_free(&f);
}

/* A detector: its node and activated bond, nothing else changes. */
static void test_detector(void) {
  static const char *base =
      "Se U = 1\n1 j\nR R1 = 2\nI L1 = 0.5\n0 n\nC C1 = 0.1\nR R2 = 4\n"
      "bond U -> j\nbond j -> R1\nbond j -> L1\nbond j -> n\nbond n -> C1\nbond n -> R2\n";
  char src[1024];
  snprintf(src, sizeof src, "%sDe vC = n\nDf i = j\n", base);
  fx f, g;
  OK(load_text(&f, src) == 0 && load_text(&g, base) == 0);
  bg_diagram *d = draw(&f, NULL, 0, 0), *e = draw(&g, NULL, 0, 0);
  OK(d && e);
  if (d && e) {
    const bg_scene *s = bg_diagram_scene(d);
    INT_EQ(count_role(s, "detector"), 2);
    INT_EQ(count_role(s, "detector-bond"), 2);
    INT_EQ(count_role(s, "detector-arrow"), 2);
    INT_EQ(count_role(s, "bond"), count_role(bg_diagram_scene(e), "bond"));
    INT_EQ(count_role(s, "stroke"), count_role(bg_diagram_scene(e), "stroke"));
    const bg_scene_item *t = item(s, "detector vC"), *l = item(s, "detector-bond vC");
    OK(t && l && strstr(t->text, "De"));
    if (t && l) {
      /* the line runs from the 0-junction n towards the detector's label */
      const bg_scene_item *n = item(s, "node n");
      const bg_scene_pt *p0 = &s->pt[l->opadr], *p1 = &s->pt[l->opadr + l->nop - 1];
      OK(n && hypot(p0->x - n->x, p0->y - n->y) < 15);
      OK(hypot(p1->x - t->x, p1->y - t->y) < hypot(p0->x - t->x, p0->y - t->y));
    }
  }
  bg_diagram_free(d), bg_diagram_free(e);
  fx_free(&f), fx_free(&g);
}

int main(void) {
  test_boxes();
  test_unknown_name();
  test_nested();
  test_detector();
  return bg_t_done();
}
