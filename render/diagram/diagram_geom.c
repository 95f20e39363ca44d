/* SPDX-License-Identifier: BSD-3-Clause */
/* Page geometry of the diagram: vectors, where bonds run, barbs, arrowheads. */
#include <math.h>
#include <stdlib.h>

#include "diagram/diagram_int.h"
#include "diagram/diagram_route_int.h"
#include "base/sort.h"

static bg_vec node_centre(const bg_diagram_layout *d, int n) { return bg_v(d->nx[n], d->ny[n]); }

/* The i-th point of bond b's route: its tail node's centre, the corners,
 * its head node's centre (i = 0 .. bendn + 1). */
static bg_vec route_pt(const bg_diagram_layout *d, int b, int i) {
  const bg_bond_geom *g = &d->bg[b];
  if (i == 0) return node_centre(d, d->node_of[d->m->bond_tail[b]]);
  if (i > g->bendn) return node_centre(d, d->node_of[d->m->bond_head[b]]);
  return bg_v(d->lay.bendx[g->bendadr + i - 1], d->lay.bendy[g->bendadr + i - 1]);
}

bg_vec bg_node_end(const bg_diagram_layout *d, int n, bg_vec dir) {
  bg_vec c = node_centre(d, n);
  if (d->jr && d->jr[n] > 0) return bg_vadd(c, bg_vscale(dir, d->jr[n]));
  return bg_box_exit(c, d->nw[n] / 2, d->nh[n] / 2, bg_vadd(c, bg_vscale(dir, 1e4)));
}

/* The radius at which bond b leaves junction n (its end there), 0 if n is
 * not a junction end of b. */
static double *bond_radius(const bg_diagram_layout *d, int b, int n) {
  return &d->bjr[2 * b + (d->m->bond_head[b] == n)];
}

/* Where bond b ends at node n, leaving it in direction dir. */
static bg_vec bond_end(const bg_diagram_layout *d, int b, int n, bg_vec dir) {
  if (d->bjr && n < d->m->nelem && (d->m->bond_tail[b] == n || d->m->bond_head[b] == n)) {
    double r = *bond_radius(d, b, n);
    if (r > 0) return bg_vadd(node_centre(d, n), bg_vscale(dir, r));
  }
  return bg_node_end(d, n, dir);
}

/* A bond's end at a one-port's box, drawn back along the bond until its half
 * arrow (7 line widths, 45 degrees back, on the style's side) stays out of
 * the box: a bond reaching a wide label through its bottom or top edge at a
 * shallow angle (a one-port on a ring's side, bg_layout_ring) had the barb
 * in the text. Where the bond meets the box's edge squarely, nothing moves. */
static bg_vec barb_clear(const bg_diagram_layout *d, int n, bg_vec end, bg_vec dir) {
  double hw = d->nw[n] / 2, hh = d->nh[n] / 2;
  bg_vec c = node_centre(d, n), tip = bg_barb_tip(d, end, dir);
  double x0 = c.x - hw, x1 = c.x + hw, y0 = c.y - hh, y1 = c.y + hh;
  if (tip.x <= x0 || tip.x >= x1 || tip.y <= y0 || tip.y >= y1) return end;
  /* back along -dir: the least way out of the box for the tip, through any edge */
  double back = INFINITY;
  if (dir.x > 1e-9) back = fmin(back, (tip.x - x0) / dir.x);
  if (dir.x < -1e-9) back = fmin(back, (tip.x - x1) / dir.x);
  if (dir.y > 1e-9) back = fmin(back, (tip.y - y0) / dir.y);
  if (dir.y < -1e-9) back = fmin(back, (tip.y - y1) / dir.y);
  return isfinite(back) ? bg_vsub(end, bg_vscale(dir, back + 0.5 * d->st.line_width)) : end;
}

/* Bond end `end` at element n's label (dir: into its box) drawn back
 * along the bond, an eighth of a line width at a time and by at most
 * `most`, until the causal stroke's bar centred there keeps 0.6 pt off the
 * label's text (the box less its padding): a bond at 45 degrees reaches a
 * label wider than tall through its top or bottom edge a little way in
 * from the corner, and the bar's half towards the corner came over the
 * first glyph (`I : L15` in tests/data/figures/diagonals_b.bg; a
 * 1 000-node tree had 61 such bars). Where the bond meets the edge
 * squarely the bar lies along the edge: nothing moves. */
static bg_vec stroke_clear(const bg_diagram_layout *d, int n, bg_vec end, bg_vec dir, double most) {
  /* the box less its padding, grown by the bar's half width (1.5 line
   * widths wide) and 0.6 pt */
  double lw = d->st.line_width, grow = 0.75 * lw + 0.6 - d->st.node_pad;
  double x0 = d->nx[n] - d->nw[n] / 2 - grow, x1 = d->nx[n] + d->nw[n] / 2 + grow;
  double y0 = d->ny[n] - d->nh[n] / 2 - grow, y1 = d->ny[n] + d->nh[n] / 2 + grow;
  if (x1 <= x0 || y1 <= y0) return end;
  bg_vec half = bg_vscale(bg_vleft(dir), 4.5 * lw);
  /* by a bar's length at most: a bond meeting the edge at a shallow angle
   * would go far back (the held-out models and examples ask 5.9 line
   * widths at most), and there the half arrow was drawn back already */
  most = fmin(most, 9 * lw);
  for (double back = 0; back <= most; back += 0.125 * lw) {
    bg_vec e = bg_vsub(end, bg_vscale(dir, back)), p = bg_vsub(e, half), q = bg_vadd(e, half);
    const double bar[4] = {p.x, p.y, q.x, q.y};
    if (!bg_seg_hits_box(bar, x0, y0, x1, y1)) return e;
  }
  return end; /* no room on its bond: as it was */
}

/* The length of bond b's route between ltail and lhead (what text beside
 * it is placed along, bg_geom_along). */
static double label_length(const bg_diagram_layout *d, int b) {
  const bg_bond_geom *g = &d->bg[b];
  double len = 0;
  for (int i = 0; i <= g->bendn; i++)
    len += bg_vlen(bg_vsub(i == g->bendn ? g->lhead : route_pt(d, b, i + 1), i == 0 ? g->ltail : route_pt(d, b, i)));
  return len;
}

/* Whether bond b's causal stroke is drawn at its end at node n, an
 * element's label box (not a junction's end circle, not the box of a
 * field or a collapsed instance). */
static int stroke_at_label(const bg_diagram_layout *d, int b, int n, int at_head) {
  const bg_model *m = d->m;
  if (!(d->show & BG_SHOW_STROKES) || !d->a || !d->a->bond_stroke) return 0;
  int st = d->a->bond_stroke[b];
  if (st != (at_head ? BG_STROKE_HEAD : BG_STROKE_TAIL)) return 0;
  return n < m->nelem && n == (at_head ? m->bond_head[b] : m->bond_tail[b]) && !bg_elem_is_junction(m->elem_kind[n]);
}

static void route_geom(const bg_diagram_layout *d, int b, bg_bond_geom *g) {
  /* a bond through a port of a collapsed instance ends on its box */
  int t = d->node_of[d->m->bond_tail[b]], h = d->node_of[d->m->bond_head[b]], n = g->bendn;
  g->tdir = bg_vunit(bg_vsub(route_pt(d, b, 1), route_pt(d, b, 0)));
  g->hdir = bg_vunit(bg_vsub(route_pt(d, b, n + 1), route_pt(d, b, n)));
  g->tail = bond_end(d, b, t, g->tdir);
  g->head = bond_end(d, b, h, bg_vscale(g->hdir, -1));
  if (h < d->m->nelem && d->m->elem_nbond[h] == 1 && !bg_elem_is_junction(d->m->elem_kind[h]))
    g->head = barb_clear(d, h, g->head, g->hdir);
  if (bg_vlen(bg_vsub(node_centre(d, h), node_centre(d, t))) < 1e-9) g->head = g->tail;
  /* the number's places along the bond stay those between the labels
   * (ltail, lhead): the 1-2 pt a stroke draws the end back took a number
   * placed near the one-port (84 % along, in a 45-degree wedge) nearer the
   * junction's axis bond than its own, and 24 of a 1 000-node tree's
   * numbers went elsewhere */
  g->ltail = g->tail, g->lhead = g->head;
  g->mid = bg_geom_along(d, b, 0.5, &g->mdir);
  /* never below 2.5 half arrows, the length the junction's end circle
   * keeps a one-port's bond (junction_radii, from the label's end) */
  int at_h = stroke_at_label(d, b, h, 1), at_t = stroke_at_label(d, b, t, 0);
  if (!at_h && !at_t) return;
  double spare = label_length(d, b) - 2.5 * 7 * d->st.line_width - 0.1; /* 0.1: the SVG's rounding */
  if (at_h) g->head = stroke_clear(d, h, g->head, g->hdir, spare);
  if (at_t) g->tail = stroke_clear(d, t, g->tail, bg_vscale(g->tdir, -1), spare);
}

bg_vec bg_geom_along(const bg_diagram_layout *d, int b, double t, bg_vec *dir) {
  const bg_bond_geom *g = &d->bg[b];
  int n = g->bendn;
  double want = t * label_length(d, b);
  for (int i = 0; i <= n; i++) {
    bg_vec p = i == 0 ? g->ltail : route_pt(d, b, i), q = i == n ? g->lhead : route_pt(d, b, i + 1);
    double l = bg_vlen(bg_vsub(q, p));
    if (want <= l || i == n) {
      if (dir) *dir = l > 1e-9 ? bg_vunit(bg_vsub(q, p)) : g->hdir;
      return bg_vadd(p, bg_vscale(bg_vsub(q, p), l > 1e-9 ? fmin(1, want / l) : 0));
    }
    want -= l;
  }
  return g->mid;
}

void bg_geom_longest_leg(const bg_diagram_layout *d, int b, bg_vec *p, bg_vec *q) {
  const bg_bond_geom *g = &d->bg[b];
  double best = -1;
  for (int i = 0; i <= g->bendn; i++) {
    bg_vec a = i == 0 ? g->ltail : route_pt(d, b, i), c = i == g->bendn ? g->lhead : route_pt(d, b, i + 1);
    if (bg_vlen(bg_vsub(c, a)) > best) best = bg_vlen(bg_vsub(c, a)), *p = a, *q = c;
  }
}

/* Direction in which edge (bond or Sf* bond) k leaves node n. */
static bg_vec leave_dir(const bg_diagram_layout *d, int b, int n) {
  const bg_bond_geom *g = &d->bg[b];
  return d->m->bond_tail[b] == n ? g->tdir : bg_vscale(g->hdir, -1);
}

/* The bars of bond b's causal stroke at junction j when it is there, bond b
 * ending at radius r: their ends in e0[], e1[] (a derivative stroke that the
 * style doubles has its second bar 2.5 line widths further out). Returns how
 * many: 0 when the stroke is at b's other end. */
static int stroke_bars(const bg_diagram_layout *d, int j, int b, double r, bg_vec e0[2], bg_vec e1[2]) {
  const bg_model *m = d->m;
  int st = d->a->bond_stroke[b];
  if (!((st == BG_STROKE_HEAD && m->bond_head[b] == j) || (st == BG_STROKE_TAIL && m->bond_tail[b] == j))) return 0;
  double w = d->st.line_width;
  bg_vec c = bg_v(d->nx[j], d->ny[j]), v = leave_dir(d, b, j), n = bg_vscale(bg_vleft(v), 4.5 * w);
  int bars = d->st.derivative_double && bg_bond_derivative(m, d->a, b) ? 2 : 1;
  for (int k = 0; k < bars; k++) {
    bg_vec e = bg_vadd(c, bg_vscale(v, r + 2.5 * w * k));
    e0[k] = bg_vadd(e, n), e1[k] = bg_vsub(e, n);
  }
  return bars;
}

/* Whether bond bk's causal stroke, at radius rk from junction j's centre,
 * comes within its own and a bond's half width (and half a line width
 * more) of the half arrow of bond bi ending at j at radius ri: the angle
 * rule below keeps a stroke off the neighbouring lines, but a barb leans
 * back from its end towards one neighbour (a one-port at 45 degrees
 * between two bonds whose barbs lean its way: reactions12's s0), and a
 * doubled derivative stroke's second bar is nearer a barb leaning that
 * way (a junction of many inertias in print, issue 31). */
static int stroke_on_barb(const bg_diagram_layout *d, int j, int bi, double ri, int bk, double rk) {
  if (d->m->bond_head[bi] != j) return 0;
  bg_vec e0[2], e1[2];
  int bars = stroke_bars(d, j, bk, rk, e0, e1);
  double w = d->st.line_width;
  bg_vec u = leave_dir(d, bi, j), h = bg_vadd(bg_v(d->nx[j], d->ny[j]), bg_vscale(u, ri));
  bg_vec tip = bg_barb_tip(d, h, bg_vscale(u, -1));
  for (int k = 0; k < bars; k++)
    if (bg_seg_seg(e0[k], e1[k], h, tip) < 1.75 * w) return 1;
  return 0;
}

/* Whether the causal strokes of bonds bi and bk at junction j (radii ri,
 * rk) come within their width and half a line width of each other: two
 * bonds 45 degrees apart or less, both strokes at the junction, drew their
 * bars end to end (issue 31: a tree's junction of eight bonds ringed by its
 * strokes, an octagon; 720 such pairs in 38 of the 85 held-out models). */
static int stroke_on_stroke(const bg_diagram_layout *d, int j, int bi, double ri, int bk, double rk) {
  bg_vec a0[2], a1[2], b0[2], b1[2];
  int na = stroke_bars(d, j, bi, ri, a0, a1), nk = na ? stroke_bars(d, j, bk, rk, b0, b1) : 0;
  for (int p = 0; p < na; p++)
    for (int q = 0; q < nk; q++)
      if (bg_seg_seg(a0[p], a1[p], b0[q], b1[q]) < 2 * d->st.line_width) return 1;
  return 0;
}

/* The radius the angle rule asks of a bond at junction j whose smallest
 * angle to another bond there is amin (see junction_radii), at most cap;
 * angles below `least` count as that. */
static double angle_radius(const bg_diagram_layout *d, int j, double amin, double least, double cap) {
  double base = 0.5 * fmax(d->nw[j], d->nh[j]), w = d->st.line_width;
  amin = fmax(amin, least);
  return fmin(fmax(base, (4.5 * cos(amin) + 2) * w / sin(amin)), cap);
}

/* The end circle's largest radius at junction j: one and a half times its
 * label, or at a junction of more than eight one-ports (round it on a ring,
 * bg_layout_ring: bonds a few degrees apart whose strokes a small circle
 * leaves on each other, a star of 40 one-ports on a 1-junction had 34
 * touching) four tenths of its shortest bond (to its far end or first
 * corner), and angles down to 2 degrees count. Junctions of many bonds to
 * other junctions keep the small circle (a random graph's: a larger one
 * brought touching strokes and false T's). */
#define RING_ONE_PORTS 8

/* One and a half times junction j's label: the end circle's usual cap. */
static double label_radius(const bg_diagram_layout *d, int j) { return 1.5 * fmax(d->nw[j], d->nh[j]); }

static double radius_cap(const bg_diagram_layout *d, int j, double *sharpest, int *ring) {
  const bg_model *m = d->m;
  double cap = label_radius(d, j), shortest = INFINITY;
  int nb = m->elem_nbond[j], *bs = m->elem_bonds + m->elem_bondadr[j], one_ports = 0;
  *sharpest = BG_PI / 12; /* a tiny angle is not cured by distance */
  *ring = 0;
  for (int i = 0; i < nb; i++) {
    int o = m->bond_tail[bs[i]] == j ? m->bond_head[bs[i]] : m->bond_tail[bs[i]];
    one_ports += m->elem_nbond[o] == 1;
  }
  if (one_ports <= RING_ONE_PORTS) return cap;
  bg_vec c = bg_v(d->nx[j], d->ny[j]);
  for (int i = 0; i < nb; i++) {
    int b = bs[i], tail = m->bond_tail[b] == j;
    const bg_bond_geom *g = &d->bg[b];
    if (g->spln) return cap; /* a curve: its length is not its chord */
    if (g->bendn) continue;  /* routed: its first leg bounds only its own radius (bent_radius) */
    shortest = fmin(shortest, bg_vlen(bg_vsub(tail ? g->lhead : g->ltail, c)));
  }
  *sharpest = BG_PI / 90, *ring = 1;
  return shortest < INFINITY ? fmax(cap, 0.4 * shortest) : cap;
}

/* A routed bond at a junction whose circle grew past one and a half times
 * its label (radius_cap): its own end stays within four tenths of its
 * first leg, as the circle's would. The first leg had bounded every bond's
 * end: in the rows layout a fold's bond routed round a one-port's label
 * left the hub 20 pt before its first corner, and the 24 strokes round a
 * ring's 1-junction stayed on a circle of 24 pt, 21 of them touching. */
static void bent_radius(bg_diagram_layout *d, int j, double r) {
  const bg_model *m = d->m;
  double label = label_radius(d, j);
  if (r <= label) return;
  int nb = m->elem_nbond[j], *bs = m->elem_bonds + m->elem_bondadr[j];
  bg_vec c = bg_v(d->nx[j], d->ny[j]);
  for (int i = 0; i < nb; i++) {
    int b = bs[i], tail = m->bond_tail[b] == j;
    const bg_bond_geom *g = &d->bg[b];
    if (!g->bendn) continue;
    double leg = bg_vlen(bg_vsub(route_pt(d, b, tail ? 1 : g->bendn), c));
    *bond_radius(d, b, j) = fmin(r, fmax(label, 0.4 * leg));
  }
}

/* Junction j's bonds (their places in its bond list) in the order of the
 * directions they leave it by: strokes are checked against their
 * neighbours in it alone (two bars at one radius touch only at a small
 * angle; a junction of thousands of one-ports checked every pair). */
static int *bonds_by_angle(const bg_diagram_layout *d, int j) {
  int nb = d->m->elem_nbond[j], *bs = d->m->elem_bonds + d->m->elem_bondadr[j];
  bg_keyed *r = bg_xcalloc((size_t)nb + 1, sizeof *r);
  for (int i = 0; i < nb; i++) {
    bg_vec u = leave_dir(d, bs[i], j);
    r[i] = (bg_keyed){atan2(u.y, u.x), i};
  }
  bg_sort_keyed(r, (size_t)nb);
  int *order = bg_xcalloc((size_t)nb + 1, sizeof *order);
  for (int i = 0; i < nb; i++) order[i] = r[i].i;
  free(r);
  return order;
}

#define STROKE_NEIGHBOURS 2 /* each way round: the next bond's bar, or the one after over a bond with none */

/* Whether some stroke at junction j is too close to a barb (stroke_on_barb)
 * or, with order (nullable), to another stroke (stroke_on_stroke, among
 * neighbours in order) with the bonds' radii as they are; with only >= 0
 * only the pairs with bond `only` in them (its bonds' count of tests, not
 * their square: a ring of thousands of one-ports staggers each). */
static int any_stroke_clash(const bg_diagram_layout *d, int j, const int *order, int only) {
  const bg_model *m = d->m;
  if (!d->a || !d->a->bond_stroke) return 0;
  int nb = m->elem_nbond[j], *bs = m->elem_bonds + m->elem_bondadr[j];
  if (only >= 0) {
    double ro = *bond_radius(d, only, j);
    for (int k = 0; k < nb; k++) {
      double rk = *bond_radius(d, bs[k], j);
      if (bs[k] != only && (stroke_on_barb(d, j, bs[k], rk, only, ro) || stroke_on_barb(d, j, only, ro, bs[k], rk)))
        return 1;
    }
    int at = -1;
    for (int p = 0; order && p < nb && at < 0; p++)
      if (bs[order[p]] == only) at = p;
    for (int s = -STROKE_NEIGHBOURS; at >= 0 && s <= STROKE_NEIGHBOURS; s++) {
      int bk = bs[order[((at + s) % nb + nb) % nb]];
      if (bk != only && stroke_on_stroke(d, j, only, ro, bk, *bond_radius(d, bk, j))) return 1;
    }
    return 0;
  }
  for (int i = 0; i < nb; i++)
    for (int k = 0; k < nb; k++)
      if (k != i && stroke_on_barb(d, j, bs[i], *bond_radius(d, bs[i], j), bs[k], *bond_radius(d, bs[k], j)))
        return 1;
  for (int p = 0; order && p < nb; p++)
    for (int s = 1; s <= STROKE_NEIGHBOURS && s < nb; s++) { /* a pair twice when nb <= 4: only time */
      int bi = bs[order[p]], bk = bs[order[(p + s) % nb]];
      if (stroke_on_stroke(d, j, bi, *bond_radius(d, bi, j), bk, *bond_radius(d, bk, j))) return 1;
    }
  return 0;
}

/* The bonds' lines near a point, for off_the_lines: the router's near
 * index of the legs as pass 0 holds them, built when first asked. */
typedef struct lines_near {
  near_index ix;
  near_list nl;
  int built;
} lines_near;

/* Whether point e and bars e0-e1 (bars of them) keep 1.75 line widths off
 * segment p-q. */
static int clear_of(const bg_diagram_layout *d, bg_vec e, const bg_vec *e0, const bg_vec *e1, int bars, bg_vec p,
                    bg_vec q) {
  double w = d->st.line_width;
  if (bg_point_seg(e, p, q) < 1.75 * w) return 0;
  for (int a = 0; a < bars; a++)
    if (bg_seg_seg(e0[a], e1[a], p, q) < 1.75 * w) return 0;
  return 1;
}

/* Whether bond b's end at junction j and its stroke's bars there keep 1.75
 * line widths off every other bond's line (a bond moved out along its own
 * may come to end on a neighbour that leaves j off the radial, a routed
 * bond's or the rows layout's, or on a routed bond passing the junction:
 * a false T). j's own bonds from their ends on its circle; the others'
 * legs from the index (ln), as pass 0 holds them. */
static int off_the_lines(bg_diagram_layout *d, int j, int b, lines_near *ln) {
  const bg_model *m = d->m;
  int nb = m->elem_nbond[j], *bs = m->elem_bonds + m->elem_bondadr[j];
  double w = d->st.line_width, rb = *bond_radius(d, b, j);
  bg_vec c = bg_v(d->nx[j], d->ny[j]), e = bg_vadd(c, bg_vscale(leave_dir(d, b, j), rb)), e0[2], e1[2];
  int bars = stroke_bars(d, j, b, rb, e0, e1);
  for (int i = 0; i < nb; i++) {
    int k = bs[i], tail = m->bond_tail[k] == j;
    if (k == b || d->bg[k].spln) continue;
    bg_vec p = bg_vadd(c, bg_vscale(leave_dir(d, k, j), *bond_radius(d, k, j)));
    bg_vec q = d->bg[k].bendn ? route_pt(d, k, tail ? 1 : d->bg[k].bendn) : tail ? d->bg[k].head : d->bg[k].tail;
    if (!clear_of(d, e, e0, e1, bars, p, q)) return 0;
  }
  if (!ln->built) bg_near_build(d, m->nbond, NULL, 0, &ln->ix), ln->built = 1;
  double reach = 4.5 * w + 2 * w;
  bg_near_box(&ln->ix, e.x - reach, e.y - reach, e.x + reach, e.y + reach, &ln->nl);
  for (int i = 0; i < ln->nl.n; i++) {
    int leg = ln->nl.k[i] - d->nnode, k = leg >= 0 ? ln->ix.lbond[leg] : -1;
    if (k < 0 || k == b || m->bond_tail[k] == j || m->bond_head[k] == j) continue;
    if (!clear_of(d, e, e0, e1, bars, ln->ix.la[leg], ln->ix.lb[leg])) return 0;
  }
  return 1;
}

/* Strokes that still clash at junction j once its circle (radius r) has
 * grown as far as it may (junction_radii): a straight bond of the pair
 * leaves further out, by up to a bar's length, while it stays 2.5 half
 * arrows long and its end and bars keep off every line (off_the_lines),
 * so the two bars lie one beyond the other (issue 31: one-ports 15 to 25
 * degrees apart round a ring of one-ports or a large tree's junction, hub
 * bonds slanted a few degrees apart in a random graph, their bars end to
 * end). The first clashing bond in the junction's list moves. */
static void stagger_strokes(bg_diagram_layout *d, int j, const int *order, double r, lines_near *ln) {
  const bg_model *m = d->m;
  double w = d->st.line_width, least = 2.5 * 7 * w, most = r + 9 * w;
  int nb = m->elem_nbond[j], *bs = m->elem_bonds + m->elem_bondadr[j];
  bg_vec c = bg_v(d->nx[j], d->ny[j]);
  for (int i = 0; i < nb; i++) {
    int b = bs[i];
    if (d->bg[b].bendn || d->bg[b].spln) continue;
    double *rb = bond_radius(d, b, j);
    if (!any_stroke_clash(d, j, order, b)) continue;
    /* its other end (pass 0), at the label: a stroke drawing it back off
     * the text (stroke_clear) left a 45-degree source's bond unstaggered
     * across a routed bond (a held-out model) */
    bg_vec far = m->bond_tail[b] == j ? d->bg[b].lhead : d->bg[b].ltail;
    double top = fmin(most, bg_vlen(bg_vsub(far, c)) - least), was = *rb;
    while (*rb < top && any_stroke_clash(d, j, order, b)) *rb = fmin(top, *rb + 0.25 * w);
    if (any_stroke_clash(d, j, order, b) || !off_the_lines(d, j, b, ln)) *rb = was; /* no place clear: as it was */
  }
}

/* Junction j's common radius r grown a quarter line width at a time, up to
 * top, while its strokes clash (any_stroke_clash with order, nullable);
 * every bond's end put on it. Returns the radius. */
static double grow_circle(bg_diagram_layout *d, int j, const int *order, double r, double top) {
  int nb = d->m->elem_nbond[j], *bs = d->m->elem_bonds + d->m->elem_bondadr[j];
  while (r < top && any_stroke_clash(d, j, order, -1)) {
    r = fmin(top, r + 0.25 * d->st.line_width);
    for (int i = 0; i < nb; i++) *bond_radius(d, bs[i], j) = r;
  }
  return r;
}

/* Junction end circles: around the label, and far enough out that a causal
 * stroke (4.5 line widths each side) clears the nearest neighbouring bond
 * by half a line width: r sin(a) >= (4.5 cos(a) + 2) w for the smallest
 * angle a between two bonds at the junction (capped: a tiny angle cannot
 * be cured by distance); then grown a quarter line width at a time while a
 * stroke and a barb there are too close (stroke_on_barb). One circle for
 * the junction's bonds, but a one-port's bond it would leave shorter than
 * 2.5 half arrows leaves at the radius its own smallest angle asks (issue
 * 31: the circle sized for the narrowest pair cut series_conductances'
 * bonds 2 and 4 to 17 pt for a 7 pt barb beside its diagonal, and
 * reactions12's c3 below its half arrow in slides). Per bond end in
 * d->bjr; d->jr keeps the circle (an Sf* or a box port drawn from it). */
static void junction_radii(bg_diagram_layout *d) {
  const bg_model *m = d->m;
  d->jr = bg_arena_alloc(&d->arena, ((size_t)d->nnode + 1) * sizeof(double));
  d->bjr = bg_arena_alloc(&d->arena, (2 * (size_t)m->nbond + 2) * sizeof(double));
  double w = d->st.line_width, least = 2.5 * 7 * w;
  lines_near ln = {0};
  for (int j = 0; j < m->nelem; j++) {
    if (!bg_elem_is_junction(m->elem_kind[j]) || !bg_node_shown(d, j)) continue;
    int ring;
    double sharpest, cap = radius_cap(d, j, &sharpest, &ring), amin = BG_PI / 2;
    int nb = m->elem_nbond[j], *bs = m->elem_bonds + m->elem_bondadr[j];
    double *own = bg_xcalloc((size_t)nb + 1, sizeof *own);
    for (int i = 0; i < nb; i++) {
      own[i] = BG_PI / 2;
      for (int k = 0; k < nb; k++) {
        if (k == i) continue;
        bg_vec u = leave_dir(d, bs[i], j), v = leave_dir(d, bs[k], j);
        own[i] = fmin(own[i], acos(fmax(-1, fmin(1, u.x * v.x + u.y * v.y))));
      }
      amin = fmin(amin, own[i]);
    }
    double r = angle_radius(d, j, amin, sharpest, cap);
    if (d->jr_least) r = fmax(r, d->jr_least[j]); /* the routes keep their ends */
    int *order = bonds_by_angle(d, j);
    for (int i = 0; i < nb; i++) *bond_radius(d, bs[i], j) = r;
    /* strokes on barbs up to the cap; strokes on strokes up to one and a
     * half times the label, but not round a ring of one-ports (grown for
     * them, a ring's circle put its bonds' ends 35 pt out, read as not
     * joined, and moved the routes of a tree's bonds onto other ends):
     * those are staggered (stagger_strokes) */
    r = grow_circle(d, j, NULL, r, cap);
    if (!ring) r = grow_circle(d, j, order, r, fmin(cap, label_radius(d, j)));
    d->jr[j] = r;
    bent_radius(d, j, r);
    for (int i = 0; i < nb; i++) {
      int b = bs[i], o = m->bond_tail[b] == j ? m->bond_head[b] : m->bond_tail[b];
      if (bg_elem_is_junction(m->elem_kind[o]) || d->bg[b].bendn || d->bg[b].spln) continue;
      bg_vec c = bg_v(d->nx[j], d->ny[j]), u = leave_dir(d, b, j);
      bg_vec far = m->bond_tail[b] == j ? d->bg[b].lhead : d->bg[b].ltail; /* the one-port's label (pass 0) */
      if (bg_vlen(bg_vsub(far, bg_vadd(c, bg_vscale(u, r)))) >= least) continue;
      double *rb = bond_radius(d, b, j);
      *rb = fmin(r, angle_radius(d, j, own[i], sharpest, cap));
      while (*rb < r && any_stroke_clash(d, j, order, b)) *rb = fmin(r, *rb + 0.25 * w);
    }
    stagger_strokes(d, j, order, r, &ln);
    free(own), free(order);
  }
  if (ln.built) bg_near_free(&ln.ix);
  free(ln.nl.k);
}

static bg_vec spl_pt(const bg_diagram_layout *d, int i) { return bg_v(d->splx[i], d->sply[i]); }

/* Point and derivative of one cubic piece at t. */
static void bezier_eval(const bg_vec p[4], double t, bg_vec *pt, bg_vec *dt) {
  double u = 1 - t;
  pt->x = u * u * u * p[0].x + 3 * u * u * t * p[1].x + 3 * u * t * t * p[2].x + t * t * t * p[3].x;
  pt->y = u * u * u * p[0].y + 3 * u * u * t * p[1].y + 3 * u * t * t * p[2].y + t * t * t * p[3].y;
  dt->x = 3 * u * u * (p[1].x - p[0].x) + 6 * u * t * (p[2].x - p[1].x) + 3 * t * t * (p[3].x - p[2].x);
  dt->y = 3 * u * u * (p[1].y - p[0].y) + 6 * u * t * (p[2].y - p[1].y) + 3 * t * t * (p[3].y - p[2].y);
}

static void spline_geom(const bg_diagram_layout *d, int adr, int n, bg_bond_geom *g) {
  g->spladr = adr, g->spln = n;
  g->tail = spl_pt(d, adr);
  g->head = spl_pt(d, adr + n - 1);
  g->ltail = g->tail, g->lhead = g->head;
  g->tdir = bg_vunit(bg_vsub(spl_pt(d, adr + 1), g->tail));
  g->hdir = bg_vunit(bg_vsub(g->head, spl_pt(d, adr + n - 2)));
  int pieces = (n - 1) / 3, piece = pieces / 2;
  bg_vec p[4], dt;
  for (int k = 0; k < 4; k++) p[k] = spl_pt(d, adr + 3 * piece + k);
  bezier_eval(p, pieces % 2 ? 0.5 : 0.0, &g->mid, &dt);
  g->mdir = bg_vlen(dt) > 1e-9 ? bg_vunit(dt) : bg_vunit(bg_vsub(g->head, g->tail));
}

void bg_geom_bonds(bg_diagram_layout *d) {
  const bg_model *m = d->m;
  d->jr = NULL, d->bjr = NULL;
  for (int pass = 0; pass < 2; pass++) {
    /* pass 0: directions (with box ends); pass 1: again with junction circles */
    for (int b = 0; b < m->nbond; b++) {
      bg_bond_geom *g = &d->bg[b];
      int n = d->lay.spln ? d->lay.spln[b] : 0;
      g->spln = 0;
      g->bendn = d->lay.bendn ? d->lay.bendn[b] : 0;
      g->bendadr = d->lay.bendadr ? d->lay.bendadr[b] : 0;
      if (n >= 4 && (n - 1) % 3 == 0) spline_geom(d, d->lay.spladr[b], n, g);
      else route_geom(d, b, g);
    }
    if (pass == 0) junction_radii(d);
  }
}

bg_vec bg_barb_side(const bg_diagram_layout *d, int b) { return bg_barb_side_at(d, d->bg[b].hdir); }

bg_vec bg_barb_tip(const bg_diagram_layout *d, bg_vec end, bg_vec dir) {
  return bg_vadd(end, bg_vscale(bg_vsub(bg_barb_side_at(d, dir), dir), 7 * d->st.line_width * BG_SQRT1_2));
}

bg_vec bg_barb_side_at(const bg_diagram_layout *d, bg_vec dir) {
  bg_vec left = bg_vleft(dir);
  if (d->st.harpoon == BG_HARPOON_LEFT) return left;
  /* "down": below horizontal bonds, right of vertical ones (y grows downwards) */
  if (fabs(dir.x) >= fabs(dir.y)) return left.y > 0 ? left : bg_vscale(left, -1);
  return left.x > 0 ? left : bg_vscale(left, -1);
}

void bg_geom_bond_path(const bg_diagram_layout *d, bg_scene *s, int b) {
  const bg_bond_geom *g = &d->bg[b];
  bg_scene_move(s, g->tail.x, g->tail.y);
  if (!g->spln) {
    for (int i = 1; i <= g->bendn; i++) {
      bg_vec p = route_pt(d, b, i);
      bg_scene_line(s, p.x, p.y);
    }
    bg_scene_line(s, g->head.x, g->head.y);
    return;
  }
  for (int i = 1; i + 2 < g->spln; i += 3) {
    bg_vec p1 = spl_pt(d, g->spladr + i), p2 = spl_pt(d, g->spladr + i + 1),
           p3 = spl_pt(d, g->spladr + i + 2);
    bg_scene_curve(s, p1.x, p1.y, p2.x, p2.y, p3.x, p3.y);
  }
}

void bg_geom_arrowhead(bg_scene *s, bg_vec p, bg_vec dir, double len, double wid) {
  bg_vec u = bg_vunit(dir), n = bg_vleft(u);
  bg_vec back = bg_vsub(p, bg_vscale(u, len));
  bg_vec a = bg_vadd(back, bg_vscale(n, wid / 2)), c = bg_vsub(back, bg_vscale(n, wid / 2));
  bg_scene_move(s, p.x, p.y);
  bg_scene_line(s, a.x, a.y);
  bg_scene_line(s, c.x, c.y);
  bg_scene_close(s);
}

/* ---------------------------------------------------------------- conflicts */
bg_vec bg_free_direction(const bg_diagram_layout *d, int j) {
  const bg_model *m = d->m;
  bg_vec c = bg_v(d->nx[j], d->ny[j]), best = bg_v(BG_SQRT1_2, -BG_SQRT1_2);
  double best_gap = -1;
  int nb = j < m->nelem ? m->elem_nbond[j] : 0;
  for (int k = 0; k < 8; k++) {
    double ang = -BG_PI / 4 + k * BG_PI / 4; /* upper right first */
    bg_vec cand = bg_v(cos(ang), sin(ang));
    double gap = BG_PI;
    for (int i = 0; i < nb; i++) {
      int b = m->elem_bonds[m->elem_bondadr[j] + i];
      int o = m->bond_tail[b] == j ? m->bond_head[b] : m->bond_tail[b];
      bg_vec dir = bg_vunit(bg_vsub(bg_v(d->nx[o], d->ny[o]), c));
      double g = acos(fmax(-1, fmin(1, dir.x * cand.x + dir.y * cand.y)));
      if (g < gap) gap = g;
    }
    if (gap > best_gap + 1e-9) best_gap = gap, best = cand;
  }
  return best;
}
