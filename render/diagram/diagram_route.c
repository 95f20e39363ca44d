/* SPDX-License-Identifier: BSD-3-Clause */
/* Orthogonal routing of signal lines (issue 31): each signal becomes a
 * polyline of horizontal and vertical segments, leaving its source at right
 * angles to a free side and entering its target the same way, found by a
 * shortest-path search (A*) over a grid of candidate lines — the channels
 * beside the node boxes in a window around the two ends — where a bend, a
 * crossed bond, a crossed or shared signal and a run through a node box
 * each cost. A run through a box or along a bond costs so much that the
 * search takes any other way, round the outside of the figure when the
 * window has none, and when the whole figure's grid is too coarse, over a
 * grid of the lanes near the two ends and a ring outside the figure
 * (bg_route_outside); so the search never fails, and a route is never drawn
 * through a node unless the figure leaves no gap at all.
 *
 * Work is bounded per signal: the grid has at most MAXLINES lines each way
 * (the window's candidates thinned evenly), and what an edge meets is
 * looked up in a uniform grid of cells over the layout (the near index), so
 * routing the signals of a figure stays linear in their number.
 *
 * This file holds the ports, the searches tried in turn and the router;
 * the near index, the costs, the grid, the search, branches and the U round
 * a one-port are files of their own (diagram_route_int.h lists them). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_route_int.h"

/* The whole figure's grid is searched only where thinning it to MAXLINES
 * merged no candidate lines further apart than this: a coarser grid's
 * lines run through the boxes (the 1 000-signal network's whole-figure
 * searches merged lines up to 80 pt apart and found a way for 3 % of its
 * boxed-in signals, at six times a window's work). */
#define FALLBACK_GAP (4 * LANE)

/* ---------------------------------------------------------------- the router */

bg_router *bg_router_new(const bg_diagram_layout *L, int nbond, const unsigned char *skip, int ends_clear) {
  bg_router *r = bg_xcalloc(1, sizeof *r);
  r->L = L, r->group = r->branch_k = r->bond = r->own = -1, r->ends_clear = ends_clear;
  bg_near_build(L, nbond, skip, ends_clear, &r->ix);
  r->fx0 = r->fx1 = r->ix.x0, r->fy0 = r->fy1 = r->ix.y0;
  for (int k = 0; k < L->nnode; k++)
    if (bg_route_node_drawn(L, k)) {
      double b[4];
      bg_near_item_box(L, &r->ix, k, b);
      r->fx1 = fmax(r->fx1, b[2]), r->fy1 = fmax(r->fy1, b[3]);
    }
  for (int k = 0; k < r->ix.nleg; k++) {
    double b[4];
    bg_near_item_box(L, &r->ix, L->nnode + k, b);
    r->fx1 = fmax(r->fx1, b[2]), r->fy1 = fmax(r->fy1, b[3]);
  }
  return r;
}

void bg_router_free(bg_router *r) {
  if (!r) return;
  bg_near_free(&r->ix);
  free(r->nl.k), free(r->X), free(r->Y), free(r->prio_x), free(r->prio_y), free(r->hcost), free(r->vcost), free(r->hv);
  free(r->route), free(r->g), free(r->parent), free(r->heap), free(r->cx), free(r->cy), free(r->cpx), free(r->cpy);
  free(r->end_adr), free(r->end_list);
  free(r);
}

/* Whether a point of node n's box side is clear of the bonds that end there
 * (6 pt from a bond's end on the box). */
static int end_near(const bg_diagram_layout *L, const bg_model *m, int b, int n, bg_vec p) {
  if (L->bond_hidden && L->bond_hidden[b]) return 0;
  int t = m->bond_tail[b], h = m->bond_head[b];
  if (L->node_of) t = L->node_of[t], h = L->node_of[h];
  return (t == n && bg_vlen(bg_vsub(L->bg[b].tail, p)) < 6) || (h == n && bg_vlen(bg_vsub(L->bg[b].head, p)) < 6);
}

/* The bonds drawn ending at each node past the elements (r->end_adr,
 * end_list): a bond of a collapsed instance's element ends at its box.
 * Looked for among every bond for each port of such a node, a chain of
 * 2 000 sections with a user state each took 1.5 s to lay out, 4 000 5 s. */
static void box_bonds(bg_router *r, const bg_model *m) {
  const bg_diagram_layout *L = r->L;
  int extra = L->nnode - m->nelem, *fill = bg_xcalloc((size_t)extra + 1, sizeof(int));
  r->end_adr = bg_xcalloc((size_t)extra + 2, sizeof(int));
  for (int pass = 0; pass < 2; pass++) {
    for (int b = 0; b < m->nbond; b++)
      for (int end = 0; end < 2; end++) {
        int v = end ? m->bond_head[b] : m->bond_tail[b], n = L->node_of ? L->node_of[v] : v;
        if (n < m->nelem || n >= L->nnode) continue;
        if (pass) r->end_list[r->end_adr[n - m->nelem] + fill[n - m->nelem]++] = b;
        else r->end_adr[n - m->nelem + 1]++;
      }
    if (!pass) {
      for (int k = 0; k < extra; k++) r->end_adr[k + 1] += r->end_adr[k];
      r->end_list = bg_xcalloc((size_t)r->end_adr[extra] + 1, sizeof(int));
    }
  }
  free(fill);
}

/* The bonds drawn ending at node n (*list, their number returned): an
 * element's own, or those box_bonds found for a box or an integrator. */
static int node_bonds(bg_router *r, const bg_model *m, int n, const int **list) {
  if (n < m->nelem) {
    *list = &m->elem_bonds[m->elem_bondadr[n]];
    return m->elem_nbond[n];
  }
  if (!r->end_adr) box_bonds(r, m);
  *list = &r->end_list[r->end_adr[n - m->nelem]];
  return r->end_adr[n - m->nelem + 1] - r->end_adr[n - m->nelem];
}

static int side_clear(bg_router *r, const bg_model *m, int n, bg_vec p) {
  const int *list;
  int nb = node_bonds(r, m, n, &list);
  for (int i = 0; i < nb; i++)
    if (end_near(r->L, m, list[i], n, p)) return 0;
  return 1;
}

void bg_router_rings(bg_router *r, const double *ring) {
  r->ring = ring, r->ring_hug = 0;
  for (int k = 0; ring && k < r->ix.nleg; k++) r->ring_hug = fmax(r->ring_hug, bg_route_leg_hug(r, k));
}

/* Node n's bonds that leave it through side dir (within 25 degrees of its
 * normal) and have path or loop lines beside them, against point p: whether
 * p lies among those lines or within RING_NEAR of the outermost (the return
 * value), and *need, how far past p (across the bond) RING_GAP past them
 * lies (the most over those bonds; 0 for none). */
static int side_rings(bg_router *r, const bg_model *m, int n, int dir, bg_vec p, double *need) {
  const bg_diagram_layout *L = r->L;
  const int *list;
  int nb = node_bonds(r, m, n, &list), among = 0;
  *need = 0;
  for (int i = 0; i < nb; i++) {
    int b = list[i];
    if ((L->bond_hidden && L->bond_hidden[b]) || r->ring[b] <= 0) continue;
    for (int head = 0; head < 2; head++) {
      int e = head ? m->bond_head[b] : m->bond_tail[b];
      if ((L->node_of ? L->node_of[e] : e) != n) continue;
      bg_vec at = head ? L->bg[b].head : L->bg[b].tail, out = head ? bg_vscale(L->bg[b].hdir, -1) : L->bg[b].tdir;
      if (out.x * DIRV[dir].x + out.y * DIRV[dir].y < 0.9) continue;
      bg_vec w = bg_vsub(p, at);
      double across = fabs(w.x * out.y - w.y * out.x);
      among |= across < r->ring[b] + RING_NEAR;
      *need = fmax(*need, r->ring[b] + RING_GAP - across);
    }
  }
  return among;
}

/* A source's corner port (at, on side dir, its corner towards sx, sy) of a
 * node with path and loop lines round its bonds: its straight stub would
 * run among them beside a bond leaving through that side (a signal out of
 * a junction read as part of a path: internal_mod_r, series_motor_L,
 * slider_crank, issue 31), so it leaves on a 45 degree stub instead, out
 * to RING_GAP past the outermost line of the bonds through either side of
 * the corner; it crosses them there at once. Returns whether it did (*p
 * the port). Not at a target: an arrow into a corner at 45 degrees points
 * past the node's text. */
static int ring_escape(bg_router *r, const bg_model *m, int n, int dir, double sx, double sy, bg_vec at, port *p) {
  double need, need_other;
  if (!r->ring || !side_rings(r, m, n, dir, at, &need)) return 0;
  side_rings(r, m, n, dir < 2 ? (sy > 0 ? 2 : 3) : (sx > 0 ? 0 : 1), at, &need_other);
  double d = fmax(6, fmax(need, need_other)); /* at least 6 pt each way: a shorter diagonal reads as a kink */
  *p = (port){at, bg_vadd(at, bg_vscale(bg_v(sx, sy), d)), dir, COST_CORNER, 0, 2};
  return 1;
}

/* How far inside a node's box its text ends, and 1.5 pt more: where an
 * arrow ending over the text still points at it (node_ports' target
 * corners, aligned_ports' common line). */
static double text_inset(const bg_diagram_layout *L) { return L->st.node_pad + 1.5; }

/* The ports of node n: the middle of each side, its corners, and on long
 * sides the points halfway between, those clear of the node's bonds (a
 * junction with a bond on every side is left at a corner); gap: how far out
 * of the box the line ends (the arrow's tip stops 1.5 pt short). */
static int node_ports(bg_router *r, const bg_model *m, int n, double gap, port *out) {
  const bg_diagram_layout *L = r->L;
  double hw = L->nw[n] / 2, hh = L->nh[n] / 2;
  bg_vec c = bg_v(L->nx[n], L->ny[n]);
  int np = 0;
  for (int dir = 0; dir < 4; dir++) {
    double half = dir < 2 ? hh : hw;
    /* An arrow at the box's very corner points past the label, whose text
     * ends the pad inside it: a target's corner ports stand 1.5 pt over
     * the text (not on a box too small for it: a junction's digit). */
    double corner = gap > 0 && half - text_inset(L) >= 2 ? half - text_inset(L) : half;
    for (int k = 0; k < 5; k++) { /* the middle, halfway to the corners, the corners */
      static const double frac[5] = {0, -0.5, 0.5, -1, 1};
      double off = frac[k] * (k >= 3 ? corner : half);
      if ((k == 1 || k == 2) && (half < 8 || half / 2 > corner - 2)) continue;
      bg_vec at = dir < 2 ? bg_v(c.x + (dir == 0 ? hw : -hw), c.y + off) : bg_v(c.x + off, c.y + (dir == 2 ? hh : -hh));
      if (!side_clear(r, m, n, at)) continue;
      double sx = dir < 2 ? DIRV[dir].x : off > 0 ? 1 : -1, sy = dir < 2 ? (off > 0 ? 1 : -1) : DIRV[dir].y;
      if (k >= 3 && gap == 0 && ring_escape(r, m, n, dir, sx, sy, at, &out[np])) {
        np++;
        continue;
      }
      at = bg_vadd(at, bg_vscale(DIRV[dir], gap));
      out[np++] = (port){at, bg_vadd(at, bg_vscale(DIRV[dir], STUB)), dir, k >= 3 ? COST_CORNER : 0, 0, 0};
    }
  }
  if (!np) /* every side taken by bonds: the sides' middles all the same */
    for (int dir = 0; dir < 4; dir++) {
      bg_vec at = bg_vadd(c, bg_v(DIRV[dir].x * (hw + gap), DIRV[dir].y * (hh + gap)));
      out[np++] = (port){at, bg_vadd(at, bg_vscale(DIRV[dir], STUB)), dir, 0, 0, 0};
    }
  return np;
}

/* Two nodes almost in line — one above the other, their texts overlapping
 * across, or side by side overlapping in height — whose ports are not at
 * one place: the search drew a small step between the two ports' lines
 * (slider_crank's signal from the integrator of phi into MTF : T, 2 pt
 * across at its stubs). A port on each facing side at the middle of the
 * overlap of their texts (1.5 pt in from the text's ends, as a target's
 * corners: node_ports) gives the straight line, where the sides are clear
 * of the nodes' bonds; between nodes closer than two stubs both stubs end
 * at one vertex halfway. */
static void aligned_ports(bg_router *r, const bg_model *m, int a, int b, port *ps, int *nps, port *pt, int *npt) {
  const bg_diagram_layout *L = r->L;
  double in = text_inset(L);
  for (int axis = 0; axis < 2; axis++) { /* 0: a vertical line, one above the other; 1: a level one */
    double ha = (axis ? L->nh[a] : L->nw[a]) / 2 - in, hb = (axis ? L->nh[b] : L->nw[b]) / 2 - in;
    double ca = axis ? L->ny[a] : L->nx[a], cb = axis ? L->ny[b] : L->nx[b];
    double lo = fmax(ca - ha, cb - hb), hi = fmin(ca + ha, cb + hb);
    double along = axis ? L->nx[b] - L->nx[a] : L->ny[b] - L->ny[a];
    double room = fabs(along) - (axis ? L->nw[a] + L->nw[b] : L->nh[a] + L->nh[b]) / 2;
    double stub = fmin(STUB, (room - 1.5) / 2); /* close nodes: both stubs at one vertex between */
    if (ha <= 0 || hb <= 0 || hi < lo || stub < 4) continue;
    double v = (lo + hi) / 2, sa = along > 0 ? 1 : -1;
    int dir_a = axis ? (along > 0 ? 0 : 1) : (along > 0 ? 2 : 3), dir_b = dir_a ^ 1;
    bg_vec at_a = axis ? bg_v(L->nx[a] + sa * L->nw[a] / 2, v) : bg_v(v, L->ny[a] + sa * L->nh[a] / 2);
    bg_vec at_b = axis ? bg_v(L->nx[b] - sa * L->nw[b] / 2, v) : bg_v(v, L->ny[b] - sa * L->nh[b] / 2);
    if (!side_clear(r, m, a, at_a) || !side_clear(r, m, b, at_b)) continue;
    at_b = bg_vadd(at_b, bg_vscale(DIRV[dir_b], 1.5)); /* the arrow's tip 1.5 pt off the box */
    ps[(*nps)++] = (port){at_a, bg_vadd(at_a, bg_vscale(DIRV[dir_a], stub)), dir_a, 0, 0, 0};
    pt[(*npt)++] = (port){at_b, bg_vadd(at_b, bg_vscale(DIRV[dir_b], stub)), dir_b, 0, 0, 0};
  }
}

/* Drops repeated points and the middle one of three on a line. */
static int simplify(bg_vec *p, int n) {
  int m = 0;
  for (int i = 0; i < n; i++) {
    if (m && fabs(p[i].x - p[m - 1].x) < 1e-9 && fabs(p[i].y - p[m - 1].y) < 1e-9) continue;
    if (m >= 2) {
      bg_vec a = bg_vsub(p[m - 1], p[m - 2]), b = bg_vsub(p[i], p[m - 1]);
      if (fabs(a.x * b.y - a.y * b.x) < 1e-6 && a.x * b.x + a.y * b.y > 0) {
        p[m - 1] = p[i];
        continue;
      }
    }
    p[m++] = p[i];
  }
  return m;
}

/* Whether p lies on bond b's line (within 0.5 pt), its half arrow not counted. */
static int on_bond(const bg_diagram_layout *L, int b, bg_vec p) {
  for (int i = 0; i <= L->bg[b].bendn; i++)
    if (bg_point_seg(p, bg_route_leg_end(L, b, i - 1), bg_route_leg_end(L, b, i)) < 0.5) return 1;
  return 0;
}

/* The search in a window round boxes a and b, their box with a margin
 * that grows with their distance. */
static int route_window(bg_router *r, port *ps, int nps, port *pt, int npt, const double a[4], const double b[4],
                        bg_vec *pts, int cap, double *cost) {
  double wx0 = fmin(a[0], b[0]), wx1 = fmax(a[2], b[2]), wy0 = fmin(a[1], b[1]), wy1 = fmax(a[3], b[3]);
  double margin = 40 + 0.25 * fmax(wx1 - wx0, wy1 - wy0);
  return bg_route_in_window(r, ps, nps, pt, npt, wx0 - margin, wy0 - margin, wx1 + margin, wy1 + margin, INFINITY, pts,
                            cap, cost);
}

/* The route between the ports ps and pt, whose boxes are a and b: the
 * cheapest in a window round both ends (their boxes with a margin that
 * grows with their distance); boxed in, over the whole figure with a ring
 * round it, where its grid keeps the lanes (the window's grid, over less of
 * the figure, was as fine); still through a box, round the outside. The
 * route is simplified and remembered, so later routes keep off it. Returns
 * the number of points: pts[0] on a source port, the last on a target's. */
int bg_route_ports(bg_router *r, port *ps, int nps, port *pt, int npt, const double a[4], const double b[4],
                       bg_vec *pts, int cap) {
  double cost = INFINITY;
  int n = 0, seeded = 0; /* the route chosen starts on its source's earlier routes */
  bg_vec near;
  if (bg_route_group_nearest(r, bg_v((b[0] + b[2]) / 2, (b[1] + b[3]) / 2), &near)) {
    /* a branch off the nearest stretch of its source's earlier routes, in
     * a window round the two (not the source's: a fan of n signals
     * searched the whole figure n times), taken when it costs less than a
     * crossed bond: shorter than about 160 pt, no bond crossed */
    double nb[4] = {near.x, near.y, near.x, near.y};
    n = route_window(r, NULL, 0, pt, npt, nb, b, pts, cap, &cost);
    seeded = r->seeded;
    if (!(cost < COST_BEND + COST_CROSS_BOND)) n = 0, cost = INFINITY;
  }
  if (!n) n = route_window(r, ps, nps, pt, npt, a, b, pts, cap, &cost), seeded = r->seeded;
  if (!(cost < COST_BLOCK) && r->gap <= FALLBACK_GAP) {
    double c2 = INFINITY;
    bg_vec *alt = bg_xcalloc((size_t)cap, sizeof *alt);
    int n2 = bg_route_in_window(r, ps, nps, pt, npt, r->fx0 - 2 * LANE, r->fy0 - 2 * LANE, r->fx1 + 2 * LANE,
                                r->fy1 + 2 * LANE, FALLBACK_GAP, alt, cap, &c2);
    if (n2 >= 2 && c2 < cost) memcpy(pts, alt, (size_t)n2 * sizeof *pts), n = n2, cost = c2, seeded = r->seeded;
    free(alt);
  }
  if (!(cost < COST_BLOCK)) {
    double c3 = INFINITY;
    bg_vec *alt = bg_xcalloc((size_t)cap, sizeof *alt);
    int n3 = bg_route_outside(r, ps, nps, pt, npt, a, b, alt, cap, &c3);
    if (n3 >= 2 && c3 < cost) memcpy(pts, alt, (size_t)n3 * sizeof *pts), n = n3, cost = c3, seeded = r->seeded;
    free(alt);
  }
  if (n < 2) { /* no grid at all (cannot happen: the grid holds every port) */
    pts[0] = ps[0].at, pts[1] = pt[0].at;
    n = 2, seeded = 0;
  }
  n = simplify(pts, n);
  if (seeded) r->branch_k = 0, r->branch_at = pts[0]; /* taken off an earlier route where it starts */
  else r->branch_k = bg_route_shared_prefix(r, pts, n, &r->branch_at);
  if (bg_route_group_rejoins(r, pts, n, r->branch_k, r->branch_at)) { /* not a branch: again, keeping off them */
    r->whole = 1;
    return bg_route_ports(r, ps, nps, pt, npt, a, b, pts, cap);
  }
  bg_route_keep(r, pts, n);
  return n;
}

void bg_route_fence(bg_router *r, bg_vec a, bg_vec b) { bg_near_add_signal(&r->ix, a, b, GROUP_FENCE, -1); }

void bg_route_keep(bg_router *r, const bg_vec *pts, int n) {
  if (r->nroute == r->caproute) {
    r->caproute = 2 * r->caproute + 16;
    r->route = bg_xrealloc(r->route, (size_t)r->caproute * sizeof *r->route);
  }
  r->route[r->nroute++] = (struct routed){r->ix.nseg, r->ix.nseg + n - 1, r->from_node, r->to_node, r->group};
  for (int i = 0; i + 1 < n; i++)
    bg_near_add_signal(&r->ix, pts[i], pts[i + 1], r->bond >= 0 ? -2 - r->bond : r->group, r->nroute - 1);
  if (n >= 2) r->ix.slast[r->ix.nseg - 1] = 1;
}

/* Routes a signal to node `to` from node from_node or, when that is < 0,
 * from bond from_bond's middle (or 8 pt either side of it). pts receives the polyline,
 * its first point on the source, its last the arrow's tip 1.5 pt off the
 * target's box; returns the number of points. The route is remembered, so
 * later signals keep off it. */
int bg_route(bg_router *r, const bg_model *m, int from_node, int from_bond, int to, int group, bg_vec *pts,
             int cap) {
  const bg_diagram_layout *L = r->L;
  bg_vec from_pt = bg_v(0, 0);
  port ps[22], pt[22]; /* node_ports' 20 and aligned_ports' 2 */
  r->from_node = from_node, r->to_node = to, r->group = group, r->bond = -1, r->whole = 0;
  int nps = 0, npt = node_ports(r, m, to, 1.5, pt);
  if (from_node >= 0) {
    nps = node_ports(r, m, from_node, 0, ps);
    aligned_ports(r, m, from_node, to, ps, &nps, pt, &npt);
  } else { /* off the bond's side, either way, at its middle or 8 pt either side on its line */
    bg_vec mid = L->bg[from_bond].mid, bond_dir = L->bg[from_bond].mdir;
    int along_x = fabs(bond_dir.x) >= fabs(bond_dir.y);
    for (int j = 0; j < 3; j++) {
      double off = j == 0 ? 0 : j == 1 ? -8 : 8;
      bg_vec at = bg_vadd(mid, along_x ? bg_v(off, 0) : bg_v(0, off));
      if (j && !on_bond(L, from_bond, at)) continue;
      for (int k = 0; k < 2; k++) {
        int dir = along_x ? (k ? 3 : 2) : (k ? 1 : 0);
        ps[nps++] = (port){at, bg_vadd(at, bg_vscale(DIRV[dir], STUB)), dir, j ? COST_CORNER / 4 : 0, 0, 0};
      }
    }
    from_pt = mid;
  }
  double ax0 = from_pt.x, ay0 = from_pt.y, ax1 = from_pt.x, ay1 = from_pt.y;
  if (from_node >= 0) {
    ax0 = L->nx[from_node] - L->nw[from_node] / 2, ax1 = L->nx[from_node] + L->nw[from_node] / 2;
    ay0 = L->ny[from_node] - L->nh[from_node] / 2, ay1 = L->ny[from_node] + L->nh[from_node] / 2;
  }
  double ends[2][4] = {{ax0, ay0, ax1, ay1},
                       {L->nx[to] - L->nw[to] / 2, L->ny[to] - L->nh[to] / 2, L->nx[to] + L->nw[to] / 2,
                        L->ny[to] + L->nh[to] / 2}};
  return bg_route_ports(r, ps, nps, pt, npt, ends[0], ends[1], pts, cap);
}
