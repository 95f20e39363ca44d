/* SPDX-License-Identifier: BSD-3-Clause */
/* Bonds round the labels (issue 31). A bond is drawn straight between its
 * nodes' centres by the rows layout and the other engines, and where the
 * grid pass finds no free cells; such a line can run through another node's
 * label (issue 31: 130 of the
 * 300-signal reaction network's bonds in the rows layout, the reaction
 * rings' chords). Those bonds are routed like the signals, orthogonally
 * round the boxes: out of a free side's middle, so the first and last legs
 * run straight out of the centre as a bond's do, or, from a box whose four
 * sides are taken, out of a corner on a short diagonal. Where two bonds of
 * one node then cross, a second pass routes a slanted one of them too
 * (second_pass). */
#include <math.h>
#include <stdlib.h>

#include "base/sort.h"
#include "diagram/diagram_route_int.h"

#define COST_DIAG 60.0 /* a bond's diagonal way out: a slanted leg */
#define COST_CORNER_TAKEN COST_BLOCK /* out of a corner an earlier route took: two routes side by side */
#define COST_CORNER_NEAR 2000.0  /* out of a corner within 25 degrees of another bond: strokes touch */

/* Whether segment a-b meets the box [x0,x1]×[y0,y1] (bg_seg_hits_box). */
static int seg_hits(bg_vec a, bg_vec b, double x0, double y0, double x1, double y1) {
  const double s[4] = {a.x, a.y, b.x, b.y};
  return bg_seg_hits_box(s, x0, y0, x1, y1);
}

/* Whether bond b's line runs through a node box other than its ends' (the
 * box 0.5 pt inside, so a line along its edge is clear). */
static int bond_blocked(bg_router *r, int b) {
  const bg_diagram_layout *L = r->L;
  if ((L->bond_hidden && L->bond_hidden[b]) || L->bg[b].spln) return 0;
  int t = bg_route_end_node(L, b, 0), h = bg_route_end_node(L, b, 1);
  for (int i = 0; i <= L->bg[b].bendn; i++) {
    bg_vec a = bg_route_leg_end(L, b, i - 1), c = bg_route_leg_end(L, b, i);
    bg_near_box(&r->ix, fmin(a.x, c.x), fmin(a.y, c.y), fmax(a.x, c.x), fmax(a.y, c.y), &r->nl);
    for (int j = 0; j < r->nl.n; j++) {
      int k = r->nl.k[j];
      if (k >= L->nnode || k == t || k == h || (L->rep && L->rep[k] != k)) continue;
      double hw = L->nw[k] / 2 - 0.5, hh = L->nh[k] / 2 - 0.5;
      if (hw > 0 && hh > 0 && seg_hits(a, c, L->nx[k] - hw, L->ny[k] - hh, L->nx[k] + hw, L->ny[k] + hh)) return 1;
    }
  }
  return 0;
}

/* Whether no other bond of node n (but b and the blocked ones, which are
 * routed again and move) leaves its centre within the angle whose cosine
 * is cosmax of direction d (by direction, not by where it ends: a
 * junction's end circle can lie far out). */
static int bond_way_free(const bg_diagram_layout *L, const bg_model *m, int n, int b, const unsigned char *blocked,
                         bg_vec d, double cosmax) {
  int nb = n < m->nelem ? m->elem_nbond[n] : m->nbond;
  for (int i = 0; i < nb; i++) {
    int ob = n < m->nelem ? m->elem_bonds[m->elem_bondadr[n] + i] : i;
    if (ob == b || blocked[ob] || (L->bond_hidden && L->bond_hidden[ob])) continue;
    const bg_bond_geom *g = &L->bg[ob];
    int t = L->node_of[m->bond_tail[ob]], h = L->node_of[m->bond_head[ob]];
    for (int k = 0; k < 2; k++) {
      if ((k ? h : t) != n) continue;
      bg_vec u = k ? bg_vscale(g->hdir, -1) : g->tdir;
      if (u.x * d.x + u.y * d.y > cosmax) return 0;
    }
  }
  return 1;
}

/* Whether side dir of node n is clear of the node's other bonds: none
 * leaves within 30 degrees of the side's normal. */
static int bond_side_free(const bg_diagram_layout *L, const bg_model *m, int n, int b, const unsigned char *blocked,
                          int dir) {
  return bond_way_free(L, m, n, b, blocked, DIRV[dir], 0.866);
}

/* ---------------------------------------------------------------- a one-port moved aside */
/* A routed bond whose end node has no free side towards the other end
 * enters it from the far side and crosses the node's own row next to it
 * (issue 31: reactions20's bonds 94 and 87 crossed bonds 57 and 60 beside
 * their 0-junctions). Two bonds of one node never need to cross: when a
 * one-port (an element with this one bond, drawn straight) takes the side
 * facing the other end and the opposite side is free, the one-port is
 * mirrored through the node's centre to that side, where it is clear of
 * every box, line and moved one-port, and the bond takes its side. Its
 * signals move with it: one going to the old side then crosses the row
 * (a signal across a bond, which the graph may need) instead of the bond
 * crossing its own junction's (which it never needs). */
typedef struct moved_box {
  double b[4];
} moved_box;

/* Whether the box b is clear of the nodes (but n and e) and legs the index
 * holds, of the one-ports moved so far, and inside the figure. */
static int place_clear(bg_router *all, int n, int e, const double b[4], const moved_box *mv, int nmv) {
  const bg_diagram_layout *L = all->L;
  if (b[0] < all->fx0 || b[1] < all->fy0 || b[2] > all->fx1 || b[3] > all->fy1) return 0;
  for (int i = 0; i < nmv; i++)
    if (bg_boxes_meet(b, mv[i].b)) return 0;
  bg_near_box(&all->ix, b[0], b[1], b[2], b[3], &all->nl);
  for (int j = 0; j < all->nl.n; j++) {
    int k = all->nl.k[j];
    if (k < L->nnode) {
      if (k == n || k == e || !bg_node_shown(L, k) || L->nw[k] <= 0) continue;
      double o[4] = {L->nx[k] - L->nw[k] / 2, L->ny[k] - L->nh[k] / 2, L->nx[k] + L->nw[k] / 2, L->ny[k] + L->nh[k] / 2};
      if (bg_boxes_meet(b, o)) return 0;
    } else if (seg_hits(all->ix.la[k - L->nnode], all->ix.lb[k - L->nnode], b[0], b[1], b[2], b[3])) {
      return 0;
    }
  }
  return 1;
}

/* At end n of blocked bond b (its other end o): the one-port moved off the
 * side facing o when no side facing o is free. Returns whether it moved. */
static int move_one_port(bg_router *all, const bg_model *m, int n, int o, int b, const unsigned char *blocked,
                         moved_box *mv, int *nmv) {
  bg_diagram_layout *L = (bg_diagram_layout *)all->L;
  if (n >= m->nelem || (L->rep && L->rep[n] != n)) return 0;
  bg_vec to = bg_vsub(bg_v(L->nx[o], L->ny[o]), bg_v(L->nx[n], L->ny[n]));
  for (int dir = 0; dir < 4; dir++)
    if (to.x * DIRV[dir].x + to.y * DIRV[dir].y > 1 && bond_side_free(L, m, n, b, blocked, dir)) return 0;
  int best = -1;
  double best_dot = 1;
  for (int i = 0; i < m->elem_nbond[n]; i++) {
    int ob = m->elem_bonds[m->elem_bondadr[n] + i];
    const bg_bond_geom *g = &L->bg[ob];
    if (blocked[ob] || (L->bond_hidden && L->bond_hidden[ob]) || g->spln || g->bendn) continue;
    int tail = m->bond_tail[ob] == n, e = tail ? m->bond_head[ob] : m->bond_tail[ob];
    if (m->elem_nbond[e] != 1 || L->node_of[e] != e || (L->rep && L->rep[e] != e) || !bg_node_shown(L, e)) continue;
    bg_vec u = tail ? g->tdir : bg_vscale(g->hdir, -1);
    for (int dir = 0; dir < 4; dir++) {
      double facing = to.x * DIRV[dir].x + to.y * DIRV[dir].y;
      if (u.x * DIRV[dir].x + u.y * DIRV[dir].y <= 0.866 || facing <= best_dot) continue;
      if (!bond_side_free(L, m, n, ob, blocked, dir) || !bond_side_free(L, m, n, ob, blocked, dir ^ 1)) continue;
      best = ob, best_dot = facing;
    }
  }
  if (best < 0) return 0;
  int e = m->bond_tail[best] == n ? m->bond_head[best] : m->bond_tail[best];
  bg_vec c = bg_v(L->nx[n], L->ny[n]), at = bg_vsub(bg_vscale(c, 2), bg_v(L->nx[e], L->ny[e]));
  moved_box nb = {{at.x - L->nw[e] / 2 - 3, at.y - L->nh[e] / 2 - 3, at.x + L->nw[e] / 2 + 3, at.y + L->nh[e] / 2 + 3}};
  if (!place_clear(all, n, e, nb.b, mv, *nmv)) return 0;
  L->nx[e] = at.x, L->ny[e] = at.y;
  bg_bond_geom *g = &L->bg[best]; /* mirrored through c: every point, every direction turned */
  g->tail = bg_vsub(bg_vscale(c, 2), g->tail), g->head = bg_vsub(bg_vscale(c, 2), g->head);
  g->ltail = bg_vsub(bg_vscale(c, 2), g->ltail), g->lhead = bg_vsub(bg_vscale(c, 2), g->lhead);
  g->mid = bg_vsub(bg_vscale(c, 2), g->mid);
  g->tdir = bg_vscale(g->tdir, -1), g->hdir = bg_vscale(g->hdir, -1), g->mdir = bg_vscale(g->mdir, -1);
  mv[(*nmv)++] = nb;
  return 1;
}

/* The ways out of node n for bond b: the middles of its free sides (not
 * taken by another bond's end or an earlier route, taken: a bit per side),
 * else its four corners on a diagonal, COST_DIAG dearer, a block dearer
 * for a corner an earlier route took (taken: bits 4-7) and COST_CORNER_NEAR
 * for one another bond leaves by. */
static int bond_ports(bg_router *r, const bg_model *m, int n, int b, const unsigned char *blocked,
                      const unsigned char *taken, port *out) {
  const bg_diagram_layout *L = r->L;
  double hw = L->nw[n] / 2, hh = L->nh[n] / 2;
  bg_vec c = bg_v(L->nx[n], L->ny[n]);
  int np = 0;
  for (int dir = 0; dir < 4; dir++) {
    bg_vec at = bg_vadd(c, bg_v(DIRV[dir].x * hw, DIRV[dir].y * hh));
    if ((taken[n] >> dir & 1) || !bond_side_free(L, m, n, b, blocked, dir)) continue;
    out[np++] = (port){at, bg_vadd(at, bg_vscale(DIRV[dir], STUB)), dir, 0, 0, 0};
  }
  for (int k = 0, sides = np; !sides && k < 4; k++) { /* all four (the loop once stopped at the first) */
    double sx = k & 1 ? -1 : 1, sy = k & 2 ? -1 : 1;
    bg_vec q = bg_vadd(c, bg_v(sx * (hw + STUB), sy * (hh + STUB)));
    double base = COST_DIAG + bg_route_seg_cost(r, c, q, n) - bg_vlen(bg_vsub(q, c));
    /* a corner an earlier route took, or one another bond already leaves
     * by (a one-port on the diagonal), costs more: the two would leave
     * within degrees of each other, the one's causal stroke on the other
     * (issue 31: a held-out network's feed junction). The second is not a
     * block: as one, every corner of a junction of twelve one-ports was
     * alike and two routes left one corner side by side */
    if (taken[n] >> (4 + k) & 1) base += COST_CORNER_TAKEN;
    else if (!bond_way_free(L, m, n, b, blocked, bg_vunit(bg_vsub(q, c)), 0.9)) base += COST_CORNER_NEAR;
    out[np++] = (port){q, q, sx > 0 ? 0 : 1, base, 0, 1};
    out[np++] = (port){q, q, sy > 0 ? 2 : 3, base, 0, 1};
  }
  return np;
}

/* Puts the route's end at node n straight out of its centre: a side port's
 * first leg moved onto the centre's line (the grid may have snapped it
 * off), the side (or the corner) marked taken. end: pts[0] (next: pts[1]) or the last
 * point. Returns whether the end is a diagonal way out (a corner of its own). */
static int bond_end(const bg_diagram_layout *L, int n, bg_vec *end, bg_vec *next, unsigned char *taken) {
  double dx = end->x - L->nx[n], dy = end->y - L->ny[n], hw = L->nw[n] / 2, hh = L->nh[n] / 2;
  if (fabs(dx) > hw + 0.01 || fabs(dy) > hh + 0.01) { /* a corner: taken too (bits 4-7) */
    taken[n] |= (unsigned char)(16 << ((dx < 0 ? 1 : 0) | (dy < 0 ? 2 : 0)));
    return 1;
  }
  if (fabs(dx) >= hw - 0.01) {
    end->y = next->y = L->ny[n];
    taken[n] |= (unsigned char)(1 << (dx > 0 ? 0 : 1));
  } else {
    end->x = next->x = L->nx[n];
    taken[n] |= (unsigned char)(1 << (dy > 0 ? 2 : 3));
  }
  return 0;
}

/* Routes bond b round the boxes; its corners into bx, by (at most cap).
 * Returns their number. */
static int route_bond(bg_router *r, const bg_model *m, int b, const unsigned char *blocked, unsigned char *taken,
                      double *bx, double *by, int cap) {
  const bg_diagram_layout *L = r->L;
  int t = L->node_of[m->bond_tail[b]], h = L->node_of[m->bond_head[b]];
  port ps[8], pt[8];
  r->from_node = t, r->to_node = h, r->group = -1, r->bond = b;
  int nps = bond_ports(r, m, t, b, blocked, taken, ps), npt = bond_ports(r, m, h, b, blocked, taken, pt);
  double a[4] = {L->nx[t] - L->nw[t] / 2, L->ny[t] - L->nh[t] / 2, L->nx[t] + L->nw[t] / 2, L->ny[t] + L->nh[t] / 2};
  double z[4] = {L->nx[h] - L->nw[h] / 2, L->ny[h] - L->nh[h] / 2, L->nx[h] + L->nw[h] / 2, L->ny[h] + L->nh[h] / 2};
  bg_vec pts[256];
  int n = bg_route_ports(r, ps, nps, pt, npt, a, z, pts, 256), nc = 0;
  /* one straight leg on the centres' line: drawn straight; off it (two
   * corner ports, a twin's way beside its partner) the corners are kept */
  bg_vec ct = bg_v(L->nx[t], L->ny[t]), ch = bg_v(L->nx[h], L->ny[h]);
  if (n < 2 || (n == 2 && bg_point_seg(pts[0], ct, ch) < 0.5 && bg_point_seg(pts[1], ct, ch) < 0.5)) return 0;
  int dt = bond_end(L, t, &pts[0], &pts[1], taken), dh = bond_end(L, h, &pts[n - 1], &pts[n - 2], taken);
  for (int i = dt ? 0 : 1; i <= (dh ? n - 1 : n - 2) && nc < cap; i++) bx[nc] = pts[i].x, by[nc++] = pts[i].y;
  return nc;
}

/* ---------------------------------------------------------------- the routes of a pass */
/* Where every bond runs after a pass: its corners (the layout's for a bond
 * not routed), as the layout holds them (lay.bendadr, bendn, bendx, bendy). */
typedef struct bond_routes {
  int *adr, *cnt, used;
  double *bx, *by;
} bond_routes;

static void routes_free(bond_routes *p) { free(p->adr), free(p->cnt), free(p->bx), free(p->by); }

/* Routes kept CLEAR pt off bond b, a diagonal the second pass drew
 * straight: b's line, 6 pt short of either end, added to the router twice
 * more, CLEAR pt either side, as a route of b's (group -2 - b), so passing
 * nearer costs what crossing does (COST_CROSS_OWN for a route of one of
 * b's nodes). The router prices a crossing only, and the route of a bond
 * of b's node put its corner 1.0 pt beside such a diagonal (reactions60's
 * bond 256 beside bond 284), where the two read as touching. */
#define CLEAR 4.0
static void keep_clear(bg_router *r, int b) {
  bg_vec t = r->L->bg[b].tail, h = r->L->bg[b].head, d = bg_vsub(h, t);
  double len = bg_vlen(d);
  if (len <= 12) return;
  bg_vec u = bg_vscale(d, 1 / len), n = bg_v(-u.y * CLEAR, u.x * CLEAR);
  bg_vec a = bg_vadd(t, bg_vscale(u, 6)), z = bg_vsub(h, bg_vscale(u, 6));
  for (int k = -1; k <= 1; k += 2)
    bg_near_add_signal(&r->ix, bg_vadd(a, bg_vscale(n, k)), bg_vadd(z, bg_vscale(n, k)), -2 - b, -1);
}

/* Routes the bonds marked in route[]: those marked 1 in the bonds' order,
 * then those marked 2 (the second pass's: they keep off the others'
 * routes), kept off the bonds marked in clear (nullable, keep_clear), off
 * the other bonds' ends too with end_zone (the router's); the others keep
 * the layout's corners. */
static void route_pass(bg_diagram_layout *L, const unsigned char *route, const unsigned char *clear, int end_zone,
                       bond_routes *out) {
  const bg_model *m = L->m;
  int nb = m->nbond, nroute = 0;
  for (int b = 0; b < nb; b++) nroute += route[b] != 0;
  /* the other bonds' ends kept clear, as for signals: a route through the
   * gap between a bond's end and its junction hid a crossing in the end
   * circle, read as a T where a style's thinner lines drew the circle
   * smaller (issue 31: 15 such in 100 held-out models; bond crossings 72 ->
   * 87, strokes touching 8 -> 1, false T's 2 -> 0) */
  bg_router *r = nroute ? bg_router_new(L, nb, route, 1) : NULL;
  if (r) r->end_zone = end_zone;
  for (int b = 0; r && clear && b < nb; b++)
    if (clear[b]) keep_clear(r, b);
  unsigned char *taken = bg_xcalloc((size_t)L->nnode + 1, 1);
  const bg_layout *lay = &L->lay;
  int nedge = lay->nedge > nb ? lay->nedge : nb, cap = lay->nbend + 64 * nroute;
  int *padr = bg_xcalloc((size_t)nb + 1, sizeof *padr), *pcnt = bg_xcalloc((size_t)nb + 1, sizeof *pcnt), pused = 0;
  double *px = bg_xcalloc((size_t)64 * nroute + 1, sizeof *px), *py = bg_xcalloc((size_t)64 * nroute + 1, sizeof *py);
  for (int pass = 1; pass <= 2; pass++)
    for (int b = 0; b < nb; b++)
      if (route[b] == pass) {
        padr[b] = pused;
        pcnt[b] = route_bond(r, m, b, route, taken, px + pused, py + pused, 64);
        pused += pcnt[b];
      }
  bg_router_free(r);
  out->adr = bg_xcalloc((size_t)nedge + 1, sizeof *out->adr);
  out->cnt = bg_xcalloc((size_t)nedge + 1, sizeof *out->cnt);
  out->bx = bg_xcalloc((size_t)cap + 1, sizeof *out->bx), out->by = bg_xcalloc((size_t)cap + 1, sizeof *out->by);
  int used = 0;
  for (int b = 0; b < nb; b++) {
    out->adr[b] = used;
    if (route[b]) {
      for (int i = 0; i < pcnt[b]; i++) out->bx[used + i] = px[padr[b] + i], out->by[used + i] = py[padr[b] + i];
      out->cnt[b] = pcnt[b];
    } else {
      const bg_bond_geom *g = &L->bg[b];
      for (int i = 0; i < g->bendn; i++)
        out->bx[used + i] = lay->bendx[g->bendadr + i], out->by[used + i] = lay->bendy[g->bendadr + i];
      out->cnt[b] = g->bendn;
    }
    used += out->cnt[b];
  }
  out->used = used;
  free(padr), free(pcnt), free(px), free(py), free(taken);
}

/* ---------------------------------------------------------------- the second pass */
/* Routes p put in the layout, its bonds' geometry computed again. */
static void install(bg_diagram_layout *L, const bond_routes *p) {
  bg_layout *lay = &L->lay;
  lay->bendadr = p->adr, lay->bendn = p->cnt, lay->bendx = p->bx, lay->bendy = p->by, lay->nbend = p->used;
  bg_geom_bonds(L);
}

/* Whether bond b is drawn differently in the layout than by corners p and ends t, h. */
static int drawn_apart(const bg_diagram_layout *L, const bond_routes *p, const bg_vec *t, const bg_vec *h, int b) {
  const bg_bond_geom *g = &L->bg[b];
  if (g->bendn != p->cnt[b] || bg_vlen(bg_vsub(g->tail, t[b])) > 1e-6 || bg_vlen(bg_vsub(g->head, h[b])) > 1e-6)
    return 1;
  for (int i = 0; i < g->bendn; i++)
    if (L->lay.bendx[g->bendadr + i] != p->bx[p->adr[b] + i] || L->lay.bendy[g->bendadr + i] != p->by[p->adr[b] + i])
      return 1;
  return 0;
}

/* The layout holding routes tried against routes p (whose bonds' ends
 * were t, h): how many other bonds cross the bonds drawn differently from
 * p, as the layout holds them (*with_q) and under p (*with_p); the layout
 * holds p after. */
static void crossings_both(bg_diagram_layout *L, const bond_routes *p, const bg_vec *t, const bg_vec *h, int *with_q,
                           int *with_p) {
  int nb = L->m->nbond;
  unsigned char *changed = bg_xcalloc((size_t)nb + 1, 1);
  for (int b = 0; b < nb; b++) changed[b] = (unsigned char)drawn_apart(L, p, t, h, b);
  *with_q = bg_route_crossings_of(L, changed);
  install(L, p);
  *with_p = bg_route_crossings_of(L, changed);
  free(changed);
}

/* Routes q when keep, put in the layout, else p (which it holds); the
 * other's arrays freed (never the layout's own, orig's). */
static bond_routes kept(bg_diagram_layout *L, int keep, bond_routes p, bond_routes q, const bond_routes *orig) {
  if (!keep) {
    routes_free(&q);
    return p;
  }
  install(L, &q);
  if (p.adr != orig->adr) routes_free(&p);
  return q;
}

/* The layout's own corners (orig) with the bonds marked BG_STRAIGHTEN drawn
 * straight, put in the layout; a bond whose straight line would run
 * through another node's label keeps its corners. */
static void straighten(bg_diagram_layout *L, const bond_routes *orig, unsigned char *todo, int *cnt) {
  int nb = L->m->nbond;
  bond_routes o = *orig;
  for (int b = 0; b < nb; b++) cnt[b] = todo[b] == BG_STRAIGHTEN || !orig->cnt ? 0 : orig->cnt[b];
  o.cnt = cnt;
  install(L, &o);
  bg_router *chk = bg_router_new(L, nb, NULL, 0);
  int back = 0;
  for (int b = 0; b < nb; b++)
    if (todo[b] == BG_STRAIGHTEN && bond_blocked(chk, b))
      todo[b] = BG_KEEP, cnt[b] = orig->cnt ? orig->cnt[b] : 0, back = 1;
  bg_router_free(chk);
  if (back) install(L, &o);
}

/* Issue 31, two bonds of one node crossing after the first pass (routes p,
 * its routed bonds marked in blocked, the layout holding them). The first
 * pass routes against the other bonds' lines as drawn before it, from a
 * junction's end circle that a blocked bond's straight line at a small
 * angle had grown (to 24 pt in modladder120): the route passed just beyond
 * such a line's end, and once routed the circle shrank and the line
 * reached into the route. Where one bond of such a pair is a slanted
 * straight line, it is routed too, after the others, in a second pass from
 * the layout's own corners (orig); where the other is a layout's elbow
 * (the grid pass's diagonal beside its own elbow, reactions60), the elbow
 * is drawn straight instead, so the diagonal changes hands
 * (bg_route_adjacent_crossings). The second pass is kept when fewer bonds
 * of one node cross and the bonds it draws differently cross no more
 * bonds than before. Returns the routes kept, which the layout holds;
 * *nmore: the bonds it routed or straightened besides p's. */
static bond_routes second_pass(bg_diagram_layout *L, const unsigned char *blocked, bond_routes p,
                               const bond_routes *orig, int *nmore) {
  int nb = L->m->nbond, ntodo = 0;
  unsigned char *todo = bg_xcalloc((size_t)nb + 1, 1);
  int adj = bg_route_adjacent_crossings(L, blocked, todo);
  for (int b = 0; b < nb; b++) ntodo += todo[b] != BG_KEEP;
  *nmore = 0;
  if (!ntodo) {
    free(todo);
    return p;
  }
  unsigned char *route = bg_xcalloc((size_t)nb + 1, 1), *changed = bg_xcalloc((size_t)nb + 1, 1);
  bg_vec *t = bg_xcalloc((size_t)nb + 1, sizeof *t), *h = bg_xcalloc((size_t)nb + 1, sizeof *h);
  int *cnt = bg_xcalloc((size_t)nb + 1, sizeof *cnt);
  for (int b = 0; b < nb; b++) t[b] = L->bg[b].tail, h[b] = L->bg[b].head;
  straighten(L, orig, todo, cnt);
  for (int b = 0; b < nb; b++) route[b] = blocked[b] ? 1 : todo[b] == BG_ROUTE ? 2 : 0;
  bond_routes q = {0};
  for (int b = 0; b < nb; b++) changed[b] = todo[b] == BG_STRAIGHTEN;
  route_pass(L, route, changed, 0, &q);
  install(L, &q);
  int adj2 = bg_route_adjacent_crossings(L, route, NULL), with_q, with_p;
  crossings_both(L, &p, t, h, &with_q, &with_p);
  int keep = adj2 < adj && with_q <= with_p;
  for (int b = 0; keep && b < nb; b++) *nmore += todo[b] != BG_KEEP;
  free(todo), free(route), free(changed), free(t), free(h), free(cnt);
  return kept(L, keep, p, q, orig);
}

/* ---------------------------------------------------------------- false T's */
/* Bond ends (as drawn) lying on the line of a bond marked in routed[]
 * (within 1 pt, more than 3 pt from that bond's own ends), where the end's
 * bond reads as ending on it: how many; the routed bonds holding them
 * marked 1 in out (nullable). */
static int false_tees(const bg_diagram_layout *L, const unsigned char *routed, unsigned char *out) {
  int nb = L->m->nbond, n = 0;
  bg_router *r = bg_router_new(L, nb, NULL, 0);
  for (int a = 0; a < nb; a++)
    for (int k = 0; k < 2; k++) {
      bg_vec e = k ? L->bg[a].head : L->bg[a].tail;
      bg_near_box(&r->ix, e.x - 1, e.y - 1, e.x + 1, e.y + 1, &r->nl);
      for (int j = 0; j < r->nl.n; j++) {
        int leg = r->nl.k[j] - L->nnode, b = leg >= 0 ? r->ix.lbond[leg] : -1;
        if (b < 0 || b == a || !routed[b] || bg_point_seg(e, r->ix.la[leg], r->ix.lb[leg]) >= 1) continue;
        if (bg_vlen(bg_vsub(e, L->bg[b].tail)) <= 3 || bg_vlen(bg_vsub(e, L->bg[b].head)) <= 3) continue;
        n++;
        if (out) out[b] = 1;
        break;
      }
    }
  bg_router_free(r);
  return n;
}

/* Issue 31, a bond with corners passing through another bond's end: the
 * router counts a crossing inside a bond only up to 0.5 pt past its end, and the
 * ends it routes against move once the routes are in (a junction's end
 * circle is sized by the angles of its bonds as drawn), so a route may
 * come to run within 1 pt of an end, which then reads as ending on it (a
 * false T; a held-out 80-reaction network had 4). The bonds with corners
 * (marked in routed[]: routed here or the layout's elbows; the layout
 * holding routes p) that hold such an end are routed again against the
 * bonds as now drawn, paying COST_END within
 * END_NEAR pt of any end, inside or past it; kept when the false T's fall
 * and the bonds drawn differently cross at most UNTEE_CROSSINGS more other
 * bonds per T removed. Returns the routes kept, which the layout holds;
 * *nmore: the bonds routed again. */
#define UNTEE_CROSSINGS 4 /* crossings a false T removed may cost: a bond read as joined where it is
                             not is worse than a crossing, which a network's graph may need anyway */
static bond_routes untee(bg_diagram_layout *L, const unsigned char *routed, bond_routes p, const bond_routes *orig,
                         int *nmore) {
  int nb = L->m->nbond;
  unsigned char *redo = bg_xcalloc((size_t)nb + 1, 1);
  int before = false_tees(L, routed, redo);
  *nmore = 0;
  if (!before) {
    free(redo);
    return p;
  }
  bg_vec *t = bg_xcalloc((size_t)nb + 1, sizeof *t), *h = bg_xcalloc((size_t)nb + 1, sizeof *h);
  for (int b = 0; b < nb; b++) t[b] = L->bg[b].tail, h[b] = L->bg[b].head;
  bond_routes q = {0};
  route_pass(L, redo, NULL, 1, &q);
  install(L, &q);
  int after = false_tees(L, routed, NULL), with_q, with_p;
  crossings_both(L, &p, t, h, &with_q, &with_p);
  int keep = after < before && with_q <= with_p + UNTEE_CROSSINGS * (before - after);
  for (int b = 0; keep && b < nb; b++) *nmore += redo[b];
  free(redo), free(t), free(h);
  return kept(L, keep, p, q, orig);
}

/* Whether bond b ends at a node of more than FAN_MIN bonds, whose bonds
 * are left as a fan of straight lines: a bound on the work, not a drawing
 * rule (issue 31: a junction of 3 000 one-ports had every bond routed
 * round the others' labels, each route's window the whole figure, 81 s
 * for a 60 kB file; now 15 s; 500 one-ports 2.8 s, now 0.08 s). Such a
 * fan runs bonds through the labels of the one-ports the rings round the
 * junction put behind others (docs/drawing.md); below the bound the routes
 * are kept, a tangle of their own at 40 one-ports but clear of labels. */
#define FAN_MIN 400
static int at_fan(const bg_diagram_layout *L, const bg_model *m, int b) {
  for (int k = 0; k < 2; k++) {
    int n = bg_route_end_node(L, b, k);
    if (n >= 0 && n < m->nelem && m->elem_nbond[n] > FAN_MIN) return 1;
  }
  return 0;
}

/* Whether bond b is one slanted straight line between two hubs leaving one
 * of its nodes within 15 degrees of another bond of that node (issue 31: the grid
 * pass's fallback for a hub bond it found no cells for, three bonds down
 * out of one junction within 7 degrees, each one's causal stroke on the
 * others and the three read as one line). */
static int bond_bundled(const bg_diagram_layout *L, const bg_model *m, int b, const unsigned char *blocked) {
  const bg_bond_geom *g = &L->bg[b];
  if ((L->bond_hidden && L->bond_hidden[b]) || g->spln || g->bendn) return 0;
  for (int k = 0; k < 2; k++) { /* between hubs: a one-port's short diagonal is drawn so on purpose */
    int e = k ? m->bond_head[b] : m->bond_tail[b];
    if (m->elem_nbond[e] < 2) return 0;
  }
  bg_vec d = bg_vsub(g->head, g->tail);
  if (fmin(fabs(d.x), fabs(d.y)) <= 0.02 * fmax(fabs(d.x), fabs(d.y))) return 0; /* along an axis */
  for (int k = 0; k < 2; k++) {
    int n = bg_route_end_node(L, b, k);
    bg_vec u = k ? bg_vscale(g->hdir, -1) : g->tdir;
    if (n >= 0 && !bond_way_free(L, m, n, b, blocked, u, 0.966)) return 1;
  }
  return 0;
}

/* Twin bonds: two straight bonds between the same two nodes (a junction
 * pair joined twice, a two-port field's both ports on one junction) are one
 * line, read as one bond with two numbers (issue 31: a generated model's
 * bonds 6 and 22 on one line; 12 of 60 property-campaign models join a pair
 * twice, the layout's elbows and the passes above part the others). Each
 * pair's straight bonds after its first are marked in twin; how many.
 * Pairs found by sorting (linear after the sort). */
static int mark_twins(const bg_diagram_layout *L, unsigned char *twin) {
  int nb = L->m->nbond, n = 0;
  bg_keyed *v = bg_xcalloc((size_t)nb + 1, sizeof *v);
  for (int b = 0; b < nb; b++) {
    const bg_bond_geom *g = &L->bg[b];
    if ((L->bond_hidden && L->bond_hidden[b]) || g->spln || g->bendn) continue;
    int t = bg_route_end_node(L, b, 0), h = bg_route_end_node(L, b, 1);
    if (t < 0 || h < 0 || t == h) continue;
    v[n].key = (double)(t < h ? t : h) * ((double)L->nnode + 1) + (t < h ? h : t), v[n++].i = b;
  }
  bg_sort_keyed(v, (size_t)n);
  int found = 0;
  for (int k = 1; k < n; k++)
    if (v[k].key == v[k - 1].key) twin[v[k].i] = 1, found++;
  free(v);
  return found;
}

/* The twins left after the passes (the layout holding routes p) routed
 * round, against the bonds as drawn, off their ends; kept whatever they
 * cross (two bonds on one line read as one: a crossing reads right).
 * Returns the routes kept; *nmore: the bonds routed. */
static bond_routes untwin(bg_diagram_layout *L, bond_routes p, const bond_routes *orig, int *nmore) {
  unsigned char *twin = bg_xcalloc((size_t)L->m->nbond + 1, 1);
  *nmore = mark_twins(L, twin);
  if (*nmore) {
    bond_routes q = {0};
    route_pass(L, twin, NULL, 1, &q);
    p = kept(L, 1, p, q, orig);
  }
  free(twin);
  return p;
}

int bg_route_blocked_bonds(bg_diagram_layout *L) {
  const bg_model *m = L->m;
  int nb = m->nbond, nblocked = 0;
  unsigned char *blocked = bg_xcalloc((size_t)nb + 1, 1);
  bg_router *all = bg_router_new(L, nb, NULL, 0);
  for (int b = 0; b < nb; b++) blocked[b] = (unsigned char)(!at_fan(L, m, b) && bond_blocked(all, b));
  for (int b = 0; b < nb; b++) blocked[b] |= (unsigned char)(!at_fan(L, m, b) && bond_bundled(L, m, b, blocked));
  for (int b = 0; b < nb; b++) nblocked += blocked[b];
  moved_box *mv = bg_xcalloc((size_t)2 * nblocked + 1, sizeof *mv);
  int nmv = 0;
  for (int b = 0; b < nb; b++) {
    if (!blocked[b]) continue;
    int t = L->node_of[m->bond_tail[b]], h = L->node_of[m->bond_head[b]];
    move_one_port(all, m, t, h, b, blocked, mv, &nmv);
    move_one_port(all, m, h, t, b, blocked, mv, &nmv);
  }
  free(mv);
  bg_router_free(all);
  bg_layout *lay = &L->lay;
  bond_routes orig = {lay->bendadr, lay->bendn, lay->nbend, lay->bendx, lay->bendy}, p = orig;
  if (nblocked) {
    route_pass(L, blocked, NULL, 0, &p);
    install(L, &p);
  }
  int nlifted = 0, nuntee = 0;
  p = second_pass(L, blocked, p, &orig, &nlifted);
  int ntwins = 0;
  p = untwin(L, p, &orig, &ntwins);
  unsigned char *routed = bg_xcalloc((size_t)nb + 1, 1);
  for (int b = 0; b < nb; b++) routed[b] = L->bg[b].bendn > 0; /* routed here, or the layout's elbows */
  for (int round = 0, more = 1; round < 3 && more; round++) { /* each round's routes move other ends */
    p = untee(L, routed, p, &orig, &more);
    nuntee += more;
  }
  free(blocked), free(routed);
  if (p.adr != orig.adr) routes_free(&orig);
  return nblocked + nlifted + nuntee + ntwins;
}
