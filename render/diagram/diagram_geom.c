/* SPDX-License-Identifier: BSD-3-Clause */
/* Page geometry of the diagram: vectors, where bonds run, barbs, arrowheads. */
#include <math.h>
#include <stdlib.h>

#include "diagram/diagram_int.h"

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
  g->mid = bg_geom_along(d, b, 0.5, &g->mdir);
}

bg_vec bg_geom_along(const bg_diagram_layout *d, int b, double t, bg_vec *dir) {
  const bg_bond_geom *g = &d->bg[b];
  int n = g->bendn;
  double len = 0, want;
  for (int i = 0; i <= n; i++) {
    bg_vec p = i == 0 ? g->tail : route_pt(d, b, i), q = i == n ? g->head : route_pt(d, b, i + 1);
    len += bg_vlen(bg_vsub(q, p));
  }
  want = t * len;
  for (int i = 0; i <= n; i++) {
    bg_vec p = i == 0 ? g->tail : route_pt(d, b, i), q = i == n ? g->head : route_pt(d, b, i + 1);
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
    bg_vec a = i == 0 ? g->tail : route_pt(d, b, i), c = i == g->bendn ? g->head : route_pt(d, b, i + 1);
    if (bg_vlen(bg_vsub(c, a)) > best) best = bg_vlen(bg_vsub(c, a)), *p = a, *q = c;
  }
}

/* Direction in which edge (bond or Sf* bond) k leaves node n. */
static bg_vec leave_dir(const bg_diagram_layout *d, int b, int n) {
  const bg_bond_geom *g = &d->bg[b];
  return d->m->bond_tail[b] == n ? g->tdir : bg_vscale(g->hdir, -1);
}

/* Whether bond bk's causal stroke, at radius rk from junction j's centre,
 * comes within its own and a bond's half width (and half a line width
 * more) of the half arrow of bond bi ending at j at radius ri: the angle
 * rule below keeps a stroke off the neighbouring lines, but a barb leans
 * back from its end towards one neighbour (a one-port at 45 degrees
 * between two bonds whose barbs lean its way: reactions12's s0). A
 * derivative stroke that the style doubles has its second bar 2.5 line
 * widths further out, nearer a barb leaning that way (a junction of many
 * inertias in print, issue 31). */
static int stroke_on_barb(const bg_diagram_layout *d, int j, int bi, double ri, int bk, double rk) {
  const bg_model *m = d->m;
  int st = d->a->bond_stroke[bk];
  if (m->bond_head[bi] != j || !((st == BG_STROKE_HEAD && m->bond_head[bk] == j) || (st == BG_STROKE_TAIL && m->bond_tail[bk] == j)))
    return 0;
  double w = d->st.line_width, half = 4.5 * w;
  bg_vec c = bg_v(d->nx[j], d->ny[j]);
  bg_vec u = leave_dir(d, bi, j), h = bg_vadd(c, bg_vscale(u, ri)), tip = bg_barb_tip(d, h, bg_vscale(u, -1));
  bg_vec v = leave_dir(d, bk, j), n = bg_vscale(bg_vleft(v), half);
  int bars = d->st.derivative_double && bg_bond_derivative(m, d->a, bk) ? 2 : 1;
  for (int k = 0; k < bars; k++) {
    bg_vec e = bg_vadd(c, bg_vscale(v, rk + 2.5 * w * k)), e0 = bg_vadd(e, n), e1 = bg_vsub(e, n);
    double dist = fmin(fmin(bg_point_seg(e0, h, tip), bg_point_seg(e1, h, tip)),
                       fmin(bg_point_seg(h, e0, e1), bg_point_seg(tip, e0, e1)));
    if (dist < 1.75 * w) return 1;
  }
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
static double radius_cap(const bg_diagram_layout *d, int j, double *sharpest) {
  const bg_model *m = d->m;
  double cap = 1.5 * fmax(d->nw[j], d->nh[j]), shortest = INFINITY;
  int nb = m->elem_nbond[j], *bs = m->elem_bonds + m->elem_bondadr[j], one_ports = 0;
  *sharpest = BG_PI / 12; /* a tiny angle is not cured by distance */
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
    shortest = fmin(shortest, bg_vlen(bg_vsub(tail ? g->head : g->tail, c)));
  }
  *sharpest = BG_PI / 90;
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
  double label = 1.5 * fmax(d->nw[j], d->nh[j]);
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

/* Whether some stroke and barb at junction j are too close with the bonds'
 * radii as they are (stroke_on_barb); with only >= 0 only the pairs with
 * bond `only` in them. */
static int any_stroke_on_barb(const bg_diagram_layout *d, int j, int only) {
  const bg_model *m = d->m;
  if (!d->a || !d->a->bond_stroke) return 0;
  int nb = m->elem_nbond[j], *bs = m->elem_bonds + m->elem_bondadr[j];
  for (int i = 0; i < nb; i++)
    for (int k = 0; k < nb; k++)
      if (k != i && (only < 0 || bs[i] == only || bs[k] == only) &&
          stroke_on_barb(d, j, bs[i], *bond_radius(d, bs[i], j), bs[k], *bond_radius(d, bs[k], j)))
        return 1;
  return 0;
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
  for (int j = 0; j < m->nelem; j++) {
    if (!bg_elem_is_junction(m->elem_kind[j]) || !bg_node_shown(d, j)) continue;
    double sharpest, cap = radius_cap(d, j, &sharpest), amin = BG_PI / 2;
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
    for (int i = 0; i < nb; i++) *bond_radius(d, bs[i], j) = r;
    while (r < cap && any_stroke_on_barb(d, j, -1)) {
      r = fmin(cap, r + 0.25 * w);
      for (int i = 0; i < nb; i++) *bond_radius(d, bs[i], j) = r;
    }
    d->jr[j] = r;
    bent_radius(d, j, r);
    for (int i = 0; i < nb; i++) {
      int b = bs[i], o = m->bond_tail[b] == j ? m->bond_head[b] : m->bond_tail[b];
      if (bg_elem_is_junction(m->elem_kind[o]) || d->bg[b].bendn || d->bg[b].spln) continue;
      bg_vec c = bg_v(d->nx[j], d->ny[j]), u = leave_dir(d, b, j);
      bg_vec far = m->bond_tail[b] == j ? d->bg[b].head : d->bg[b].tail; /* the one-port's end (pass 0) */
      if (bg_vlen(bg_vsub(far, bg_vadd(c, bg_vscale(u, r)))) >= least) continue;
      double *rb = bond_radius(d, b, j);
      *rb = fmin(r, angle_radius(d, j, own[i], sharpest, cap));
      while (*rb < r && any_stroke_on_barb(d, j, b)) *rb = fmin(r, *rb + 0.25 * w);
    }
    free(own);
  }
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
