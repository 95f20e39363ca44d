/* Analysis layers: causal paths and topological loops as offset dashed
 * polylines with direction arrows, conflicts as lightning flashes. A layer
 * always runs on the left of its direction of travel, so a flat loop (out
 * along the path and back) surrounds its bonds and the two open loops of a
 * causal loop, which run in opposite directions, fall on opposite sides. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram_int.h"

/* Bond b traversed from node u to node v. */
typedef struct seg {
  int b, u, v;
  double off;
  bg_vec dir, n;
} seg;

/* How the polyline passes a node: entry point p0, exit p1 (kind 0: p1 = p0;
 * 1: a straight link; 2: a half-turn curve with controls c1, c2). */
typedef struct joint {
  int kind;
  bg_vec p0, p1, c1, c2;
} joint;

static bg_vec centre(const bg_diagram *d, int n) { return bg_v(d->nx[n], d->ny[n]); }

static int other_end(const bg_model *m, int b, int e) {
  return m->bond_tail[b] == e ? m->bond_head[b] : m->bond_tail[b];
}

static void seg_geom(bg_diagram *d, seg *s) {
  const bg_model *m = d->m;
  s->dir = bg_vunit(bg_vsub(centre(d, s->v), centre(d, s->u)));
  s->n = bg_vleft(s->dir);
  int side = s->u == m->bond_tail[s->b] ? 0 : 1;
  s->off = d->st.layer_offset + 3 * d->side_use[2 * s->b + side];
}

static void claim_sides(bg_diagram *d, const seg *s, int n) {
  for (int i = 0; i < n; i++) d->side_use[2 * s[i].b + (s[i].u == d->m->bond_tail[s[i].b] ? 0 : 1)]++;
}

static double cross(bg_vec a, bg_vec b) { return a.x * b.y - a.y * b.x; }

/* A half turn around the end of bond s->b at node s->v. */
static joint turn(const bg_diagram *d, const seg *s) {
  int v = s->v;
  bg_vec e = bg_box_exit(centre(d, v), d->nw[v] / 2, d->nh[v] / 2, centre(d, s->u));
  bg_vec t = bg_vsub(e, bg_vscale(s->dir, s->off + 1));
  bg_vec k = bg_vscale(s->dir, 4.0 / 3 * s->off);
  joint j = {2, bg_vadd(t, bg_vscale(s->n, s->off)), bg_vsub(t, bg_vscale(s->n, s->off)), {0, 0}, {0, 0}};
  j.c1 = bg_vadd(j.p0, k), j.c2 = bg_vadd(j.p1, k);
  return j;
}

/* Where the polyline of s meets the one of t at their common node. */
static joint join(const bg_diagram *d, const seg *s, const seg *t) {
  int v = s->v;
  bg_vec c = centre(d, v);
  if (t->b == s->b && t->u == s->v && t->v == s->u) return turn(d, s);
  bg_vec a = bg_vadd(c, bg_vscale(s->n, s->off)), b = bg_vadd(c, bg_vscale(t->n, t->off));
  joint j = {1, a, b, {0, 0}, {0, 0}};
  if (!bg_elem_is_junction(v < d->m->nelem ? d->m->elem_kind[v] : BG_ELEM_J1)) {
    /* keep off the label: leave and re-enter at the box, grown by the offset */
    double hw = d->nw[v] / 2 + 2, hh = d->nh[v] / 2 + 2;
    j.p0 = bg_vadd(bg_box_exit(c, hw, hh, centre(d, s->u)), bg_vscale(s->n, s->off));
    j.p1 = bg_vadd(bg_box_exit(c, hw, hh, centre(d, t->v)), bg_vscale(t->n, t->off));
    return j;
  }
  double den = cross(s->dir, t->dir);
  if (fabs(den) < 0.05) return j;
  double u = cross(bg_vsub(b, a), t->dir) / den;
  bg_vec x = bg_vadd(a, bg_vscale(s->dir, u));
  double off = s->off > t->off ? s->off : t->off, dist = bg_vlen(bg_vsub(x, c));
  /* y grows downwards: den < 0 turns towards the left, where the layer runs */
  int inside = den < 0;
  if (dist <= 1.3 * off || (inside && dist <= 4 * off)) {
    j.kind = 0, j.p0 = j.p1 = x;
  } else if (!inside) {
    /* round the outside of a sharp turn with an arc about the junction */
    double ang = acos(fmax(-1, fmin(1, s->n.x * t->n.x + s->n.y * t->n.y)));
    double k = 4.0 / 3 * tan(ang / 4) * off;
    j.kind = 2, j.c1 = bg_vadd(a, bg_vscale(s->dir, k)), j.c2 = bg_vsub(b, bg_vscale(t->dir, k));
  }
  return j;
}

static void emit_joint(bg_scene *sc, const joint *j) {
  bg_scene_line(sc, j->p0.x, j->p0.y);
  if (j->kind == 1) bg_scene_line(sc, j->p1.x, j->p1.y);
  if (j->kind == 2) bg_scene_curve(sc, j->c1.x, j->c1.y, j->c2.x, j->c2.y, j->p1.x, j->p1.y);
}

bg_rgba bg_layer_color(const bg_diagram *d, int kind, int i) {
  int k = kind == 'p' ? i : (d->a ? d->a->npath : 0) + i;
  return d->st.layer_color[k % d->st.nlayer_color];
}

static void layer_dash(const bg_diagram *d, int kind, int i, double dash[2]) {
  static const double pat[4][2] = {{5, 2.5}, {1.5, 2}, {8, 3}, {3, 3}};
  int k = kind == 'p' ? i : (d->a ? d->a->npath : 0) + i;
  const double *p = d->st.layer_patterns ? pat[k % 4] : pat[0];
  dash[0] = p[0], dash[1] = p[1];
}

static int layer_hot(const bg_diagram *d, int kind, int i) {
  return !d->o.highlight_kind || (d->o.highlight_kind == kind && d->o.highlight_index == i + 1);
}

/* Draws a closed layer polyline through the segments, with an arrow at the
 * middle of each; returns the centroid of its corners. */
static bg_vec draw_polyline(bg_diagram *d, seg *s, int n, int kind, int i) {
  const char *name = kind == 'p' ? "path" : "loop";
  joint *j = bg_xcalloc((size_t)n, sizeof *j);
  for (int k = 0; k < n; k++) j[k] = join(d, &s[k], &s[(k + 1) % n]);
  bg_rgba c = bg_diagram_ink(d, bg_layer_color(d, kind, i), layer_hot(d, kind, i));
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "%s %d", name, i + 1);
  it->color = c, it->width = d->st.layer_width, it->round = 1;
  layer_dash(d, kind, i, it->dash);
  bg_scene_move(&d->scene, j[n - 1].p1.x, j[n - 1].p1.y);
  bg_vec sum = bg_v(0, 0);
  for (int k = 0; k < n; k++) emit_joint(&d->scene, &j[k]), sum = bg_vadd(sum, j[k].p0);
  bg_scene_close(&d->scene);
  for (int k = 0; k < n; k++) {
    bg_vec a = j[(k + n - 1) % n].p1, b = j[k].p0;
    if (bg_vlen(bg_vsub(b, a)) < 14) continue; /* no room for an arrow */
    bg_vec mid = bg_vadd(bg_vscale(bg_vadd(a, b), 0.5), bg_vscale(s[k].dir, 2.5));
    it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "%s-arrow %d", name, i + 1);
    it->fill = it->color = c, it->width = 0;
    bg_geom_arrowhead(&d->scene, mid, s[k].dir, 5, 4);
  }
  free(j);
  return bg_vscale(sum, 1.0 / n);
}

/* ---------------------------------------------------------------- paths */
static int path_segs(const bg_diagram *d, int p, seg *s) {
  const bg_analysis *a = d->a;
  int n = a->path_n[p], cur = a->path_end0[p];
  for (int k = 0; k < n; k++) {
    int b = a->path_bonds[a->path_adr[p] + k], nxt = other_end(d->m, b, cur);
    s[k] = (seg){b, cur, nxt, 0, {0, 0}, {0, 0}};
    s[2 * n - 1 - k] = (seg){b, nxt, cur, 0, {0, 0}, {0, 0}};
    cur = nxt;
  }
  return 2 * n;
}

/* Order of drawing: a highlighted layer goes last, on top of the greyed ones. */
static int layer_at(const bg_diagram *d, int kind, int k, int n) {
  if (d->o.highlight_kind != kind) return k;
  int hot = d->o.highlight_index - 1;
  if (k == n - 1) return hot;
  return k < hot ? k : k + 1;
}

static void draw_path(bg_diagram *d, int p) {
  const bg_analysis *a = d->a;
  if (!(d->show & BG_SHOW_PATHS) && !layer_hot(d, 'p', p)) return;
  if (a->path_n[p] < 1) return;
  {
    seg *s = bg_xcalloc(2 * (size_t)a->path_n[p], sizeof *s);
    int n = path_segs(d, p, s);
    for (int k = 0; k < n; k++) seg_geom(d, &s[k]);
    draw_polyline(d, s, n, 'p', p);
    /* tag the path beside its first bond, outside the polyline, clear of
     * the bond number at mid-bond */
    bg_vec at = bg_vadd(bg_vadd(bg_vscale(centre(d, s[0].u), 0.7), bg_vscale(centre(d, s[0].v), 0.3)),
                        bg_vscale(s[0].n, s[0].off + 7));
    char tag[32], role[32];
    snprintf(tag, sizeof tag, "P%d", p + 1);
    double size = d->st.font_size * d->st.number_scale, w, h;
    bg_text_measure(d->st.font, size, tag, &w, &h);
    bg_place_label(d, w + 2, 0.8 * h + 1, &at);
    snprintf(role, sizeof role, "path-tag %d", p + 1);
    bg_scene_text(&d->scene, tag, at.x, at.y, size, 0.5, 0.5,
                  bg_diagram_ink(d, bg_layer_color(d, 'p', p), layer_hot(d, 'p', p)), role);
    claim_sides(d, s, n);
    free(s);
  }
}

void bg_draw_paths(bg_diagram *d) {
  int n = d->a ? d->a->npath : 0;
  for (int k = 0; k < n; k++) draw_path(d, layer_at(d, 'p', k, n));
}

/* ---------------------------------------------------------------- loops */
/* Effort travels towards the stroke end, flow away from it. */
static seg signal_seg(const bg_diagram *d, int sig) {
  const bg_model *m = d->m;
  int b = sig / 2, flow = sig & 1;
  int head_stroke = d->a->bond_stroke[b] != BG_STROKE_TAIL;
  int forward = flow ? !head_stroke : head_stroke;
  int u = forward ? m->bond_tail[b] : m->bond_head[b];
  return (seg){b, u, other_end(m, b, u), 0, {0, 0}, {0, 0}};
}

static void loop_gain_text(bg_diagram *d, int l, bg_vec at) {
  const bg_analysis *a = d->a;
  bg_strbuf t = {0};
  bg_sb_printf(&t, "L%d", l + 1);
  const char *g = a->tloop_gain ? a->tloop_gain[l] : NULL;
  if (g && strlen(g) <= 24) bg_sb_puts(&t, ": G = "), bg_markup_escape(&t, g);
  else if (a->tloop_gain_value) bg_sb_printf(&t, ": G = %.4g", a->tloop_gain_value[l]);
  char role[32];
  snprintf(role, sizeof role, "gain loop=%d", l + 1);
  double size = d->st.font_size * d->st.number_scale, w, h;
  bg_text_measure(d->st.font, size, bg_sb_str(&t), &w, &h);
  bg_place_label(d, w + 2, 0.8 * h + 1, &at); /* loops of one bond loop share a centroid */
  bg_text_halo(d, bg_sb_str(&t), at, size);
  bg_scene_text(&d->scene, bg_sb_str(&t), at.x, at.y, size, 0.5, 0.5,
                bg_diagram_ink(d, bg_layer_color(d, 'l', l), layer_hot(d, 'l', l)), role);
  bg_sb_free(&t);
}

static void draw_loop(bg_diagram *d, int l) {
  const bg_analysis *a = d->a;
  if (!(d->show & BG_SHOW_LOOPS) && !layer_hot(d, 'l', l)) return;
  int n = a->tloop_n[l];
  if (n < 1) return;
  {
    seg *s = bg_xcalloc((size_t)n, sizeof *s);
    for (int k = 0; k < n; k++) {
      s[k] = signal_seg(d, a->tloop_signals[a->tloop_adr[l] + k]);
      seg_geom(d, &s[k]);
    }
    bg_vec c = draw_polyline(d, s, n, 'l', l);
    loop_gain_text(d, l, c);
    claim_sides(d, s, n);
    free(s);
  }
}

void bg_draw_loops(bg_diagram *d) {
  int n = d->a ? d->a->ntloop : 0;
  for (int k = 0; k < n; k++) draw_loop(d, layer_at(d, 'l', k, n));
}
