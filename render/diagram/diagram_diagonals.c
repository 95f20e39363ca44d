/* SPDX-License-Identifier: BSD-3-Clause */
/* One-ports at 45 degrees once the bonds run where they will (issue 31). A
 * one-port on a diagonal cell of a junction whose four sides are taken
 * hangs at whatever angle the column and row sizes give (27 to 31 degrees
 * in most grids); the grid pass moves it to 45 degrees (diagonal_leaves,
 * diagram_grid.c) only where no later route can need the room: not in a
 * quadrant that may hold a half arrow, nor where a bond the grid left
 * unrouted may come out. Of 100 held-out property models' 311 slanted
 * bonds, 208 were such one-ports. Here, after the bond router, what is in
 * the way is known: a one-port moves along the longer axis towards its
 * junction (or out along the shorter one, as the grid pass does, for its
 * label to clear the junction's bonds and its bond to keep 2.5 half
 * arrows) when its box, its new bond and the ink round them stay clear of
 * every other box and line. Signals are routed after this, round the
 * one-ports where they now stand.
 *
 * One arrangement for every style: which one-ports move is chosen in the
 * reference style's layout (diagram.c, reference_diagonals), each label's
 * box grown by a quarter there so that a larger style's label fits too;
 * another style moves those of them that are clear in its own sizes, by
 * the same share of the way, out of their rows where the reference moved
 * them out (diagonal_place). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "diagram/diagram_route_int.h"

#define BOX_GAP 3.0  /* pt between the moved label's box and another box or a line */
#define LINE_GAP 4.0 /* pt between its new bond and another line (a stroke's half length and a gap) */
#define REF_GROW 1.25 /* a moved label's box, grown by this about its centre, clear where the move is chosen */
#define LEVEL_GROW 1.5 /* what a one-port's room to stay level with its row is grown by where it is chosen */
#define FURTHER_STEP 4.0 /* pt further out a chosen one-port is tried where its place is not clear */
#define FURTHER_STEPS 5
#define FURTHER_GROW 1.75 /* REF_GROW for those: chosen with a quarter, 7 label pairs more in another
                             order in slides over 100 held-out models (room in the reference, none in
                             slides' larger labels); with three quarters, none */
#define OUT_LEAST 5.0 /* pt a one-port moved out of its row or column moves at least (diagonal_place) */

/* A one-port's place at 45 degrees: w off junction v, its centre c and
 * box, its bond's line from v's end circle (p0; p a little past it) to
 * where it enters the box (q). */
typedef struct slide {
  int w, v;
  double at; /* its new distance from v along the longer axis, of its old
                (negative: level with its row or column still) */
  bg_vec c;
  double box[4];
  bg_vec p0, p, q;
} slide;

/* The distance of segment p-q from box b (0 inside it). */
static double seg_box(bg_vec p, bg_vec q, const double b[4]) {
  const double s[4] = {p.x, p.y, q.x, q.y};
  if (bg_seg_hits_box(s, b[0], b[1], b[2], b[3])) return 0;
  bg_vec c[4] = {bg_v(b[0], b[1]), bg_v(b[2], b[1]), bg_v(b[2], b[3]), bg_v(b[0], b[3])};
  double d = 1e300;
  for (int k = 0; k < 4; k++) d = fmin(d, bg_seg_seg(p, q, c[k], c[(k + 1) % 4]));
  return d;
}

/* The one-port of bond b hanging off a junction, as *w and *v: its node
 * and the junction's; 0 when b is not such a bond or either end is drawn
 * as something else (a collapsed box, a field's node, another frame). */
static int one_port_bond(const bg_diagram_layout *L, int b, int *w, int *v) {
  const bg_model *m = L->m;
  if (L->bond_hidden && L->bond_hidden[b]) return 0;
  for (int end = 0; end < 2; end++) {
    int e = end ? m->bond_head[b] : m->bond_tail[b], j = end ? m->bond_tail[b] : m->bond_head[b];
    if (m->elem_nbond[e] != 1 || !bg_elem_is_junction(m->elem_kind[j])) continue;
    if (L->node_of[e] != e || L->node_of[j] != j || (L->rep && (L->rep[e] != e || L->rep[j] != j))) return 0;
    if (L->box_inst && L->box_inst[e] >= 0) return 0;
    if (m->elem_inst[e] != m->elem_inst[j] || !bg_route_node_drawn(L, e)) return 0;
    *w = e, *v = j;
    return 1;
  }
  return 0;
}

/* Whether one-port sl->w of bond b at its new place keeps clear of every
 * other box and line round it, those of the one-ports moved before (mv,
 * nmv of them: the index holds where they stood) included: its box by
 * BOX_GAP, its bond by LINE_GAP from past v's end circle, and other than
 * v's straight bonds (junction_radii keeps those strokes apart) by a
 * stroke's half length from the circle. */
static int place_clear(const bg_diagram_layout *L, near_index *ix, near_list *nl, int b, const slide *sl,
                       const slide *mv, int nmv, double grow) {
  const bg_model *m = L->m;
  const double *nb = sl->box;
  int w = sl->w, v = sl->v;
  bg_vec p0 = sl->p0, p = sl->p, q = sl->q;
  double stroke = 4.5 * L->st.line_width + 1.5; /* a causal stroke's half length and a gap */
  double gx = (grow - 1) * (nb[2] - nb[0]) / 2 + BOX_GAP, gy = (grow - 1) * (nb[3] - nb[1]) / 2 + BOX_GAP;
  double g[4] = {nb[0] - gx, nb[1] - gy, nb[2] + gx, nb[3] + gy};
  double x0 = fmin(g[0], fmin(p0.x, q.x) - stroke), y0 = fmin(g[1], fmin(p0.y, q.y) - stroke);
  double x1 = fmax(g[2], fmax(p0.x, q.x) + stroke), y1 = fmax(g[3], fmax(p0.y, q.y) + stroke);
  bg_near_box(ix, x0, y0, x1, y1, nl);
  for (int j = 0; j < nl->n; j++) {
    int k = nl->k[j];
    if (k < L->nnode) {
      if (k == w || k == v) continue;
      double o[4] = {L->nx[k] - L->nw[k] / 2, L->ny[k] - L->nh[k] / 2, L->nx[k] + L->nw[k] / 2,
                     L->ny[k] + L->nh[k] / 2};
      if (bg_boxes_meet(g, o) || seg_box(p, q, o) < 1) return 0;
      continue;
    }
    int leg = k - L->nnode, o = ix->lbond[leg];
    if (o == b) continue;
    if (seg_box(ix->la[leg], ix->lb[leg], g) <= 0) return 0;
    int own = (m->bond_tail[o] == v || m->bond_head[o] == v) && !L->bg[o].bendn && !L->bg[o].spln;
    if (own ? bg_seg_seg(p, q, ix->la[leg], ix->lb[leg]) < LINE_GAP
            : bg_seg_seg(p0, q, ix->la[leg], ix->lb[leg]) < stroke)
      return 0;
  }
  for (int i = 0; i < nmv; i++) {
    const double *o = mv[i].box;
    double og[4] = {o[0] - BOX_GAP, o[1] - BOX_GAP, o[2] + BOX_GAP, o[3] + BOX_GAP};
    if (bg_boxes_meet(g, o) || seg_box(p, q, og) <= 0 || seg_box(mv[i].p, mv[i].q, g) <= 0 ||
        bg_seg_seg(p, q, mv[i].p, mv[i].q) < LINE_GAP)
      return 0;
  }
  return 1;
}

/* Per node: whether a signal shown starts or ends there, or NULL when none
 * is shown. Such a one-port stays: its signals' ways in and out were
 * chosen where it stands (the grid pass's face_signals), and moved into
 * its junction's corner it sent them across more bonds (nine held-out
 * reaction networks: 25 signal crossings more, 2 signals touching). */
static unsigned char *signal_ends(const bg_diagram_layout *L) {
  return (L->show & BG_SHOW_SIGNALS) && L->m->nsignal ? bg_signal_end_nodes(L) : NULL;
}

/* Whether a bond of junction v has path or loop lines beside it (layered:
 * bg_layer_use, nullable): they run round the junction too, and the wider
 * angle keeps their room (as the grid pass keeps its one-ports where they
 * are with the layers shown). */
static int layered_junction(const bg_model *m, const int *layered, int v) {
  for (int i = 0; layered && i < m->elem_nbond[v]; i++)
    if (layered[m->elem_bonds[m->elem_bondadr[v] + i]]) return 1;
  return 0;
}

/* How far from its junction's centre the middle of bond b at 45 degrees
 * must lie for its number beside it (diagram_bonds.c: half its box's
 * extent across the bond and a gap out) to stay nearer its own bond than
 * the junction's bond along the axis 45 degrees off: out by D from a point
 * r along the diagonal, it is (r - D) / sqrt 2 off that bond, so r must
 * reach D (1 + sqrt 2). A randomly grown tree's one-ports moved with only
 * their 2.5 half arrows had five 4-digit numbers 0.4 pt nearer the other
 * bond than their own. 0 without numbers. */
static double number_reach(const bg_diagram_layout *L, int b) {
  if (!(L->show & (BG_SHOW_NUMBERS | BG_SHOW_VARIABLES))) return 0;
  char num[32];
  snprintf(num, sizeof num, (L->show & BG_SHOW_VARIABLES) ? "e%d" : "%d", L->m->bond_num[b]);
  double w, h;
  bg_text_measure(L->st.font, L->st.font_size * L->st.number_scale, num, &w, &h);
  double out = BG_SQRT1_2 * (w + 1 + 0.8 * h) / 2 + 5; /* a gap, and one step out (4 pt) past a stroke */
  return out * (1 + 2 * BG_SQRT1_2);
}

/* Whether bond b is a straight one from junction v to one-port w (into
 * *w, *v) that may move: no path or loop lines round v, no signal at w, v
 * not ringed by its one-ports, and hanging 15 to 44 degrees off an axis. */
static int slanted_one_port(const bg_diagram_layout *L, const int *layered, const unsigned char *signalled,
                            int b, int *w, int *v) {
  const bg_model *m = L->m;
  const bg_bond_geom *bg = &L->bg[b];
  if (bg->bendn || bg->spln || !one_port_bond(L, b, w, v) || layered_junction(m, layered, *v)) return 0;
  if (signalled && signalled[*w]) return 0;
  if (m->elem_nbond[*v] > 8) return 0; /* a ring of one-ports round it (layout_ring.c): 45 degrees cannot hold them all */
  double ax = fabs(L->nx[*w] - L->nx[*v]), ay = fabs(L->ny[*w] - L->ny[*v]);
  double ang = atan2(fmin(ax, ay), fmax(ax, ay)) * 180 / BG_PI;
  return ang >= 15 && ang <= 44; /* not along an axis, nor at 45 degrees already */
}

int bg_diagonal_any(const bg_diagram_layout *L) {
  int *layered = bg_layer_use(L);
  unsigned char *signalled = signal_ends(L);
  int any = 0, w, v;
  for (int b = 0; b < L->m->nbond && !any; b++) any = slanted_one_port(L, layered, signalled, b, &w, &v);
  free(layered), free(signalled);
  return any;
}

/* Where bond b's one-port would stand at 45 degrees off its junction: 0
 * when b is not such a bond, the junction is not one it may move at, it
 * hangs at 45 degrees (or along an axis) already, or it has no room. It
 * moves along the longer axis towards its junction, and out along the
 * shorter one where its label, its bond or its number need more room; out
 * by OUT_LEAST at least, and `further` pt more where it moves out (0
 * where it stays level with its row: no such place). Choosing (at 0),
 * so; else as the reference style's layout chose (at: its share of the
 * old distance along the longer axis, negative where it stayed level with
 * its row or column) where this style's sizes allow it. Moved out by
 * 2.8 pt in one style and not at all in another, a label came to lie
 * above a label of its row in one style and below it in the other; moved
 * by as much as each style's sizes allowed, it came to lie left of a label
 * of another row in one style and right of it in another (a 1 400-node
 * tree: 909 label pairs in another order in slides). */
static int diagonal_place(const bg_diagram_layout *L, const int *layered, const unsigned char *signalled,
                          int b, double at, double further, slide *sl) {
  int w, v;
  if (!slanted_one_port(L, layered, signalled, b, &w, &v)) return 0;
  double dx = L->nx[w] - L->nx[v], dy = L->ny[w] - L->ny[v], ax = fabs(dx), ay = fabs(dy);
  double lw = L->st.line_width, clear = 4.5 * lw + 3, least = 2.5 * 7 * lw + 3;
  double along = fmax(ax, ay), across = fmin(ax, ay), most = along - 0.5;
  double half_along = ax > ay ? L->nw[w] / 2 : L->nh[w] / 2, s = fmin(L->nw[w], L->nh[w]) / 2;
  double jr = L->jr[v] > 0 ? L->jr[v] : 7.5 * lw;
  /* its label an axis bond's stroke and a gap off the junction's bonds
   * along the longer axis; its bond 2.5 half arrows long from the end
   * circle to where it enters the box; its number's room (number_reach) */
  double need = fmax(half_along + clear, s + (least + jr) / (2 * BG_SQRT1_2));
  if (at == 0) need = fmax(need, s + (2 * number_reach(L, b) - jr) / (2 * BG_SQRT1_2));
  /* where it is chosen, it stays level with its row only where half as
   * much room again would let it (LEVEL_GROW: so it can in a larger
   * style; 100 held-out models had 72 label pairs in another order in
   * slides without it, 40 with it); where it stayed level in the
   * reference and this style's sizes do not let it, it stays where it was */
  double level = at == 0 ? LEVEL_GROW * need : need;
  double t = across;
  if (at < 0 && need > across) return 0;
  if (at > 0 || level > across) t = fmax(fmax(need, across + OUT_LEAST), at > 0 ? fmin(at * along, most) : 0);
  if (further > 0 && t == across) return 0; /* staying level: no further place */
  t += further;
  if (t > most) return 0;
  double cx = L->nx[v] + (dx > 0 ? t : -t), cy = L->ny[v] + (dy > 0 ? t : -t);
  bg_vec u = bg_v(dx > 0 ? BG_SQRT1_2 : -BG_SQRT1_2, dy > 0 ? BG_SQRT1_2 : -BG_SQRT1_2);
  sl->w = w, sl->v = v, sl->at = t > across ? t / along : -t / along, sl->c = bg_v(cx, cy);
  sl->box[0] = cx - L->nw[w] / 2, sl->box[1] = cy - L->nh[w] / 2;
  sl->box[2] = cx + L->nw[w] / 2, sl->box[3] = cy + L->nh[w] / 2;
  sl->p0 = bg_vadd(bg_v(L->nx[v], L->ny[v]), bg_vscale(u, jr)), sl->p = bg_vadd(sl->p0, bg_vscale(u, LINE_GAP));
  sl->q = bg_vsub(sl->c, bg_vscale(u, s * (2 * BG_SQRT1_2)));
  return 1;
}

/* The one-ports of L that may move, per bond (their share, as
 * bg_diagonal_choose gives it): each placed as diagonal_place puts it (by
 * the share in ref, when given: those ref chose, the others stay) and kept
 * only where clear of what lies round it and of those moved before it
 * (place_clear, in L's own sizes). */
static double *clear_moves(const bg_diagram_layout *L, const double *ref) {
  int nb = L->m->nbond, nmv = 0;
  double *at = bg_xcalloc((size_t)nb + 1, sizeof *at);
  if (nb == 0) return at;
  int *layered = bg_layer_use(L);
  unsigned char *signalled = signal_ends(L);
  near_index ix;
  near_list nl = {0};
  bg_near_build(L, nb, NULL, 0, &ix);
  slide *mv = bg_xcalloc((size_t)nb, sizeof *mv);
  for (int b = 0; b < nb; b++) {
    if (ref && ref[b] == 0) continue;
    /* choosing, where the least move out is not clear, FURTHER_STEP pt
     * further out at a time (up to FURTHER_STEPS times, while the one-port
     * still comes nearer its junction along the longer axis): a second
     * one-port beside its junction's first (a tree's I : p48_1 beside
     * I : p48_0 above their junction, 36 of a 1 000-node tree's 47 slanted
     * bonds) stayed at 24 degrees where the nearest place at 45 degrees
     * met the other's label, and a few points further out did not */
    for (int k = 0; k <= (ref ? 0 : FURTHER_STEPS); k++)
      if (diagonal_place(L, layered, signalled, b, ref ? ref[b] : 0, k * FURTHER_STEP, &mv[nmv])) {
        if (place_clear(L, &ix, &nl, b, &mv[nmv], mv, nmv, ref ? 1 : k ? FURTHER_GROW : REF_GROW)) {
          at[b] = mv[nmv++].at;
          break;
        }
      } else break;
  }
  free(mv), free(nl.k), free(layered), free(signalled);
  bg_near_free(&ix);
  return at;
}

double *bg_diagonal_choose(const bg_diagram_layout *L) { return clear_moves(L, NULL); }

int bg_diagonal_one_ports(bg_diagram_layout *L, const double *chosen) {
  /* in the reference style's sizes the choice is L's own; in another
   * style's, the one-ports the reference chose that are clear here too
   * (moved where this style's bigger labels or other routes leave no room,
   * a slides drawing had a stroke touching and a false T more) */
  double *at = clear_moves(L, chosen);
  int n = 0;
  for (int b = 0; b < L->m->nbond; b++) {
    if (at[b] == 0) continue;
    int w, v;
    one_port_bond(L, b, &w, &v);
    double dx = L->nx[w] - L->nx[v], dy = L->ny[w] - L->ny[v], t = fabs(at[b]) * fmax(fabs(dx), fabs(dy));
    L->nx[w] = L->nx[v] + (dx > 0 ? t : -t), L->ny[w] = L->ny[v] + (dy > 0 ? t : -t), n++;
  }
  if (n) L->jr_least = L->jr; /* the bonds were routed for these circles: none shrinks */
  free(at);
  return n;
}
