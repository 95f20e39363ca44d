/* SPDX-License-Identifier: BSD-3-Clause */
/* The bonds pass: bond lines with their half arrows, causal strokes, bond
 * numbers (or variables) and labels placed beside their bonds, element
 * labels, and the Lagrange causality's artificial flow sources. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

static bg_rgba parse_hex(const char *s, bg_rgba dflt) {
  unsigned v;
  if (!s || s[0] != '#' || strlen(s) != 7 || sscanf(s + 1, "%6x", &v) != 1) return dflt;
  return (bg_rgba){((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0, (v & 255) / 255.0, 1};
}

/* ---------------------------------------------------------------- bonds */
static void draw_bond(bg_diagram *d, int b) {
  const bg_model *m = d->m;
  const bg_style *st = &d->st;
  bg_rgba c = parse_hex(m->bond_color ? m->bond_color[b] : NULL, st->fg);
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "bond %d", m->bond_num[b]);
  it->color = bg_diagram_ink(d, c, d->hot_bond[b]);
  it->width = st->line_width;
  it->round = 1;
  bg_geom_bond_path(d->L, &d->scene, b);
  /* the half arrow: one barb, 45 degrees back from the tip */
  const bg_bond_geom *g = &d->L->bg[b];
  bg_vec barb = bg_barb_tip(d->L, g->head, g->hdir);
  bg_scene_line(&d->scene, barb.x, barb.y);
}

static void stroke_bar(bg_diagram *d, bg_vec e, bg_vec n, double half) {
  bg_scene_move(&d->scene, e.x + n.x * half, e.y + n.y * half);
  bg_scene_line(&d->scene, e.x - n.x * half, e.y - n.y * half);
}

static void draw_stroke(bg_diagram *d, int b) {
  const bg_style *st = &d->st;
  const bg_bond_geom *g = &d->L->bg[b];
  int at_head = d->a->bond_stroke[b] == BG_STROKE_HEAD;
  int conflict = d->a->bond_conflict && d->a->bond_conflict[b];
  int deriv = bg_bond_derivative(d->m, d->a, b);
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "stroke bond=%d%s%s",
                                     d->m->bond_num[b], deriv ? " derivative" : "",
                                     conflict ? " conflict" : "");
  bg_rgba c = conflict ? st->conflict : deriv ? st->derivative : st->fg;
  it->color = bg_diagram_ink(d, c, d->hot_bond[b]);
  it->width = 1.5 * st->line_width;
  bg_vec e = at_head ? g->head : g->tail, dir = at_head ? g->hdir : g->tdir;
  bg_vec n = bg_vleft(dir), back = at_head ? bg_vscale(dir, -1) : dir;
  double half = 4.5 * st->line_width;
  stroke_bar(d, e, n, half);
  if (deriv && st->derivative_double) stroke_bar(d, bg_vadd(e, bg_vscale(back, 2.5 * st->line_width)), n, half);
  if (conflict && st->conflict_cross) {
    bg_vec c1 = bg_vadd(e, bg_vscale(back, 5 * st->line_width));
    stroke_bar(d, c1, bg_vunit(bg_vadd(n, dir)), half * 0.7);
    stroke_bar(d, c1, bg_vunit(bg_vsub(n, dir)), half * 0.7);
  }
}

/* How far text beside bond b on side n (travelling along dir) keeps from
 * the line: 3.5 pt, or beyond the path and loop lines drawn on that side. */
static double layers_beside(const bg_diagram *d, int b, bg_vec dir, bg_vec n) {
  bg_vec left = bg_vleft(dir);
  int fwd = dir.x * d->L->bg[b].hdir.x + dir.y * d->L->bg[b].hdir.y > 0; /* dir is tail → head */
  int on_left = left.x * n.x + left.y * n.y > 0;
  int used = d->side_use[2 * b + (fwd == on_left ? 0 : 1)];
  if (!used) return 3.5;
  return bg_layer_line(&d->st, used - 1) + d->st.layer_width / 2 + 2.5;
}

/* Places text beside bond b, on the barb side (side 1) or opposite (-1),
 * 3.5 pt clear of the line: at the middle if that is free, else a little
 * along the bond or 4, 8, 12 pt further out, and last 84 % along (a
 * four-digit number beside a one-port's diagonal bond, in the wedge it
 * makes with an axis bond, is clear of that bond only near the one-port);
 * the first place that touches
 * nothing and whose nearest bond is b, else the one touching least (a
 * place nearer another bond costs as much as a line crossed, so the text
 * never reads as another bond's when there is room). With flip (a bond
 * number on a bond without a label) the other side is tried when no place
 * on its own side is free: a slanted bond in a narrow wedge. On a bent bond
 * the places are along its longest leg, on that leg's side. */
#define NEARER 1.0 /* pt nearer its own bond than any other, or the text reads as either's (a tree's
                      numbers in a 45-degree wedge: 11.8 pt from their own, 11.4 from the next) */
static void text_beside(bg_diagram *d, const char *markup, int b, int side, int flip, double size,
                        bg_rgba c, const char *role) {
  static const double ts[] = {0.5, 0.4, 0.6, 0.32, 0.68, 0.25, 0.75, 0.84};
  enum { NT = sizeof ts / sizeof ts[0], NOUT = 4, NC = 2 * NOUT * NT };
  double w, h;
  bg_text_measure(d->st.font, size, markup, &w, &h);
  h *= 0.8;
  bg_vec cand[NC];
  double reach[NC];
  bg_vec p0, p1;
  bg_geom_longest_leg(d->L, b, &p0, &p1);
  for (int k = 0; k < NT; k++) {
    bg_vec dir, at = ts[k] == 0.5 ? d->L->bg[b].mid : bg_geom_along(d->L, b, ts[k], &dir);
    if (ts[k] == 0.5) dir = d->L->bg[b].mdir;
    if (d->L->bg[b].bendn) /* a bent bond: along its longest leg */
      at = bg_vadd(p0, bg_vscale(bg_vsub(p1, p0), ts[k])), dir = bg_vunit(bg_vsub(p1, p0));
    for (int f = 0; f < 2; f++) {
      bg_vec n = bg_vscale(bg_barb_side_at(d->L, dir), f ? -side : side);
      double extent = fabs(n.x) * w / 2 + fabs(n.y) * h / 2, gap = layers_beside(d, b, dir, n);
      for (int j = 0; j < NOUT; j++) {
        /* per side: the places along the bond at each distance out, then
         * the last one along (84 %) at each: the far place only when no
         * other is clear */
        int i = f * NOUT * NT + (k < NT - 1 ? j * (NT - 1) + k : NOUT * (NT - 1) + j);
        cand[i] = bg_vadd(at, bg_vscale(n, gap + extent + 4 * j));
        reach[i] = gap + extent + 4 * j + 1;
      }
    }
  }
  int best = 0, best_cost = -1;
  double best_margin = 0;
  /* cost: 4 a line or box touched (20 a box), 2 flipped, 3 the far place
   * along the bond (after a flipped middle one: a number near its bond's
   * end reads less well), 4 nearer another bond, 2 less than NEARER nearer
   * its own than another; of equal costs the first, or while that one is
   * less than NEARER nearer its own, the one nearest its own by the most */
  for (int k = 0; k < (flip ? 2 : 1) * NOUT * NT && best_cost != 0 && (best_cost != 2 || best_margin < NEARER); k++) {
    int flipped = k >= NOUT * NT, far = k - flipped * NOUT * NT >= NOUT * (NT - 1), extra = 2 * flipped + 3 * far;
    int limit = best_cost < 0 ? INT_MAX : (best_cost - extra) / 4 + 1; /* at it, cost > best_cost */
    int cost = 4 * bg_place_score_below(d, cand[k], w + 1, h, limit) + extra;
    if (best_cost >= 0 && cost > best_cost) continue;
    double margin;
    int nearest = bg_place_nearest_bond(d, cand[k], reach[k], NEARER, &margin);
    if (nearest != b) margin = -1;
    cost += nearest != b ? 4 : margin < NEARER ? 2 : 0;
    if (best_cost < 0 || cost < best_cost || (cost == best_cost && best_margin < NEARER && margin > best_margin))
      best = k, best_cost = cost, best_margin = margin;
  }
  bg_vec p = cand[best];
  /* 2 pt more each side: a text placed later beside it read as one with it
   * ("12" beside "1" as 121 at a junction of many one-ports) */
  bg_obstacle_rect(d, p.x - (w + 1) / 2 - 2, p.y - h / 2, p.x + (w + 1) / 2 + 2, p.y + h / 2);
  if (d->show & (BG_SHOW_PATHS | BG_SHOW_LOOPS) || d->o.highlight_kind)
    bg_text_halo(d, markup, p, size);
  bg_scene_text(&d->scene, markup, p.x, p.y, size, 0.5, 0.5, c, role);
}

/* "e₃": a bond variable with its bond number as a subscript. */
static void var_markup(bg_strbuf *t, char v, int num, double size) {
  bg_sb_printf(t, "%c<span size=\"%d%%\" rise=\"%.1fpt\">%d</span>", v, bg_sub_percent(size), -0.27 * size, num);
}

static void draw_number(bg_diagram *d, int b) {
  const bg_model *m = d->m;
  double size = d->st.font_size * d->st.number_scale;
  bg_rgba ink = bg_diagram_ink(d, d->st.fg, d->hot_bond[b]);
  char role[48];
  if (d->show & BG_SHOW_VARIABLES) {
    /* effort on the barb side, flow opposite (docs/drawing.md) */
    bg_strbuf t = {0};
    var_markup(&t, 'f', m->bond_num[b], size);
    snprintf(role, sizeof role, "variable bond=%d f", m->bond_num[b]);
    text_beside(d, bg_sb_str(&t), b, -1, 0, size, ink, role);
    bg_sb_clear(&t);
    var_markup(&t, 'e', m->bond_num[b], size);
    snprintf(role, sizeof role, "variable bond=%d e", m->bond_num[b]);
    text_beside(d, bg_sb_str(&t), b, 1, 0, size, ink, role);
    bg_sb_free(&t);
    return;
  }
  char num[32];
  snprintf(num, sizeof num, "%d", m->bond_num[b]);
  snprintf(role, sizeof role, "number bond=%d", m->bond_num[b]);
  text_beside(d, num, b, -1, !(m->bond_label && m->bond_label[b] && (d->show & BG_SHOW_LABELS)), size, ink, role);
}

static void draw_bond_label(bg_diagram *d, int b) {
  const bg_model *m = d->m;
  if (!m->bond_label || !m->bond_label[b]) return;
  bg_strbuf t = {0};
  bg_markup_escapen(&t, m->bond_label[b], strlen(m->bond_label[b]));
  char role[48];
  snprintf(role, sizeof role, "bondlabel bond=%d", m->bond_num[b]);
  text_beside(d, bg_sb_str(&t), b, 1, 0, d->st.font_size * d->st.number_scale,
              bg_diagram_ink(d, d->st.fg, d->hot_bond[b]), role);
  bg_sb_free(&t);
}

void bg_draw_bonds(bg_diagram *d) {
  const bg_model *m = d->m;
  for (int b = 0; b < m->nbond; b++) {
    if (d->L->bond_hidden[b]) continue; /* inside a collapsed box */
    draw_bond(d, b);
    bg_obstacle_owned(d, d->scene.nitem - 1, -1 - b);
  }
  if (d->a && (d->show & BG_SHOW_STROKES))
    for (int b = 0; b < m->nbond; b++)
      if (d->a->bond_stroke[b] != BG_STROKE_NONE && !d->L->bond_hidden[b]) draw_stroke(d, b);
}

void bg_draw_numbers(bg_diagram *d) {
  const bg_model *m = d->m;
  for (int b = 0; b < m->nbond; b++) {
    if (d->L->bond_hidden[b]) continue;
    if (d->show & (BG_SHOW_NUMBERS | BG_SHOW_VARIABLES)) draw_number(d, b);
    if (d->show & BG_SHOW_LABELS) draw_bond_label(d, b);
  }
}

/* ---------------------------------------------------------------- nodes */
void bg_draw_nodes(bg_diagram *d) {
  const bg_model *m = d->m;
  for (int e = 0; e < m->nelem; e++) {
    if (!bg_node_shown(d->L, e)) continue; /* inside a collapsed box */
    if (bg_fields_hidden(d->L, e)) continue; /* its field's node is drawn */
    bg_rgba c = parse_hex(m->elem_color ? m->elem_color[e] : NULL, d->st.fg);
    char role[160];
    snprintf(role, sizeof role, "node %s", m->elem_name[e]);
    bg_scene_text(&d->scene, d->L->nlabel[e], d->L->nx[e], d->L->ny[e], d->st.font_size, 0.5, 0.5,
                  bg_diagram_ink(d, c, d->hot_elem[e]), role);
  }
}

/* A dashed artificial flow source Sf* at c and its dashed bond from p: the
 * half arrow points toward the source (the chapter, Section 4.10.2: the
 * generalised force is the effort into it), the stroke at the source (a
 * flow source takes the effort). A highlight mutes all of it. */
static void draw_lagrange_source(bg_diagram *d, int i, bg_vec c, double hw, double hh, bg_vec p) {
  const bg_style *st = &d->st;
  bg_rgba ink = bg_diagram_ink(d, st->fg, 0);
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "lagrange %d", i + 1);
  it->width = 0.6, it->dash[0] = 2, it->dash[1] = 1.5, it->color = ink;
  bg_scene_move(&d->scene, c.x - hw, c.y - hh);
  bg_scene_line(&d->scene, c.x + hw, c.y - hh);
  bg_scene_line(&d->scene, c.x + hw, c.y + hh);
  bg_scene_line(&d->scene, c.x - hw, c.y + hh);
  bg_scene_close(&d->scene);
  bg_scene_text(&d->scene, "Sf*", c.x, c.y, st->font_size, 0.5, 0.5, ink, "lagrange-label");
  bg_vec t = bg_box_exit(c, hw, hh, p), dir = bg_vunit(bg_vsub(t, p));
  it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "lagrange-bond %d", i + 1);
  it->width = st->line_width, it->dash[0] = 4, it->dash[1] = 2, it->round = 1, it->color = ink;
  bg_vec barb = bg_barb_tip(d->L, t, dir);
  bg_scene_move(&d->scene, p.x, p.y);
  bg_scene_line(&d->scene, t.x, t.y);
  bg_scene_line(&d->scene, barb.x, barb.y);
  /* the barb again, solid: the bond's dashes would cut it wherever its length falls in a gap */
  it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "lagrange-barb %d", i + 1);
  it->width = st->line_width, it->round = 1, it->color = ink;
  bg_scene_move(&d->scene, t.x, t.y);
  bg_scene_line(&d->scene, barb.x, barb.y);
  it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "lagrange-stroke %d", i + 1);
  it->width = 1.5 * st->line_width, it->color = ink;
  stroke_bar(d, t, bg_vleft(dir), 4.5 * st->line_width);
}

void bg_draw_lagrange(bg_diagram *d) {
  const bg_analysis *a = d->a;
  for (int i = 0; a && i < a->nlag; i++) {
    int n = d->L->lag_node[i];
    if (n >= 0) {
      int j = a->lag_junction[i];
      bg_vec cn = bg_v(d->L->nx[n], d->L->ny[n]), cj = bg_v(d->L->nx[j], d->L->ny[j]);
      draw_lagrange_source(d, i, cn, d->L->nw[n] / 2, d->L->nh[n] / 2, bg_node_end(d->L, j, bg_vunit(bg_vsub(cn, cj))));
    } else if (a->lag_bond[i] >= 0) {
      /* the inserted 1-junction sits on the split bond: attach beside it */
      int b = a->lag_bond[i];
      bg_vec side = bg_vscale(bg_barb_side(d->L, b), -1), mid = d->L->bg[b].mid;
      double w, h;
      bg_text_measure(d->st.font, d->st.font_size, "Sf*", &w, &h);
      bg_vec c = bg_vadd(mid, bg_vscale(side, 30 + h / 2));
      draw_lagrange_source(d, i, c, w / 2 + d->st.node_pad, 0.4 * h + d->st.node_pad,
                           bg_vadd(mid, bg_vscale(side, 2)));
    }
  }
}
