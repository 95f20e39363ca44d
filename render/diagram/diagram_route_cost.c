/* SPDX-License-Identifier: BSD-3-Clause */
/* What a route costs (issue 31; the costs in diagram_route_int.h): a
 * segment against the node boxes, bond legs and routed signals near it
 * (bg_route_seg_cost), and every edge of the search's grid at once, the
 * same as segment by segment (bg_route_grid_costs). */
#include <math.h>

#include "diagram/diagram_route_int.h"

/* ---------------------------------------------------------------- segment tests */
/* The distance of point a from the line through p and q. */
static double line_dist(bg_vec p, bg_vec q, bg_vec a) {
  bg_vec u = bg_vsub(q, p);
  return fabs((a.x - p.x) * u.y - (a.y - p.y) * u.x) / bg_vlen(u);
}

/* Segment p-q (axis-parallel, from the grid) against segment a-b: 1 when
 * they cross at a point inside a-b (not within 0.5 pt of its ends) and in
 * p-q's half-open extent [lower end, upper end), so a crossing at a grid
 * vertex counts for one edge only (ends: also through a-b's ends and
 * 0.5 pt past them, as a routed bond must not pass another bond's end:
 * it would read as that bond ending on it, a false T); 2 when they run on
 * one line (parallel, nearer than `near` pt, sharing more than 1 pt); 3
 * when they run side by side within `hug` pt (*run: for how long); 4 (ends
 * 2, a bond in end_zone) when they cross within END_NEAR pt of one of a-b's
 * ends, inside or past it, which reads as a-b ending on p-q whichever side
 * it falls; else 0. On a crossing (1 or 4) *run is where: how far along
 * a-b from a. */
int bg_route_seg_meet(bg_vec p, bg_vec q, bg_vec a, bg_vec b, double near, double hug, double *run, int ends) {
  bg_vec u = bg_vsub(q, p), v = bg_vsub(b, a);
  double lu = bg_vlen(u), lv = bg_vlen(v);
  if (lu <= 0 || lv <= 0) return 0;
  double den = u.x * v.y - u.y * v.x;
  if (fabs(den) < 0.02 * lu * lv) { /* parallel: on one line? */
    double dist = line_dist(p, q, a);
    if (dist >= hug) return 0;
    double t0 = ((a.x - p.x) * u.x + (a.y - p.y) * u.y) / lu, t1 = ((b.x - p.x) * u.x + (b.y - p.y) * u.y) / lu;
    double lo = fmax(0, fmin(t0, t1)), hi = fmin(lu, fmax(t0, t1));
    if (hi - lo <= 1) return 0;
    if (run) *run = hi - lo;
    return dist < near ? 2 : 3;
  }
  bg_vec w = bg_vsub(a, p);
  double t = (w.x * v.y - w.y * v.x) / den; /* along p-q */
  double s = (w.x * u.y - w.y * u.x) / den; /* along a-b */
  double keep = ends == 2 ? -END_NEAR : ends ? -0.5 : 0.5, from_end = fmin(s * lv, (1 - s) * lv);
  if (from_end < keep) return 0;
  /* half-open along the grid edge, by coordinate: [min, max) */
  int forward = u.x > 0 || (u.x == 0 && u.y > 0);
  double tl = forward ? t : 1 - t;
  if (!(tl >= 0 && tl < 1)) return 0;
  if (run) *run = s * lv;
  return ends == 2 && from_end <= END_NEAR ? 4 : 1;
}

/* Whether bond b is one of the current route's own: a bond of its source's
 * or target's node (not the routed bond itself). */
static int own_bond(const bg_router *r, int b) {
  if (b < 0 || b == r->bond) return 0;
  for (int k = 0; k < 2; k++) {
    int n = bg_route_end_node(r->L, b, k);
    if (n >= 0 && (n == r->from_node || n == r->to_node)) return 1;
  }
  return 0;
}

/* How far the path and loop lines beside leg k's bond reach (0: none). */
static double leg_ring(const bg_router *r, int leg) { return r->ring ? r->ring[r->ix.lbond[leg]] : 0; }

/* How far beside leg k a parallel run costs (hug_cost): HUG, or beside a
 * bond with path and loop lines (bg_router_rings) HUG past the outermost of
 * them, as they move its number out. */
double bg_route_leg_hug(const bg_router *r, int leg) { return leg_ring(r, leg) + HUG; }

/* What a point of a run beside leg k, `dist` pt off it, costs: COST_HUG
 * within HUG (read as a doubled bond, over its number); beside a bond with
 * path and loop lines COST_RING among them or within RING_NEAR of the
 * outermost (read as one of them: randnet30_1's signal 12.6 pt off a bond
 * with two loop lines a side, 2.6 pt beside the outer one, issue 31), then
 * COST_HUG for HUG more (over its number, which they moved out). */
static double hug_cost(const bg_router *r, int leg, double dist) {
  double ring = leg_ring(r, leg);
  if (ring > 0 && dist < ring + RING_NEAR) return COST_RING;
  return dist < bg_route_leg_hug(r, leg) ? COST_HUG : 0;
}

/* What crossing leg k of the near index costs the current route. */
static double leg_cross_cost(const bg_router *r, int leg) {
  bg_vec a = r->ix.la[leg], b = r->ix.lb[leg];
  int slanted = fmin(fabs(b.x - a.x), fabs(b.y - a.y)) > 0.09 * fmax(fabs(b.x - a.x), fabs(b.y - a.y));
  return (own_bond(r, r->ix.lbond[leg]) ? COST_CROSS_OWN : COST_CROSS_BOND) * (slanted ? COST_OBLIQUE : 1);
}

/* How near a crossing may come to a bond's end: its half arrow reaches 7
 * line widths back, its causal stroke as far across, 3 pt more keep a line
 * crossing there off them; on a short bond no nearer than 0.35 of its length
 * (its middle is the best a crossing can do). */
static double arrow_zone(const bg_router *r, double bond_len) {
  return fmin(7 * r->L->st.line_width + 3, 0.35 * bond_len);
}

/* What more a crossing of leg k costs `at` pt along it from its start:
 * COST_AT_END among the bond's half arrow or stroke (read as a line
 * through the arrow), else nothing. */
static double at_end_cost(const bg_router *r, int leg, double at) {
  if (!r->ends_clear) return 0;
  double along = r->ix.lpos[leg] + at, len = r->ix.llen[leg];
  return fmin(along, len - along) < arrow_zone(r, len) ? COST_AT_END : 0;
}

double bg_route_path_penalty(bg_router *r, const bg_vec *q, int m) {
  double c = 0;
  for (int k = 0; k < m; k++) c += bg_route_seg_cost(r, q[k], q[k + 1], -1) - bg_vlen(bg_vsub(q[k + 1], q[k]));
  return c;
}

/* Whether index segment s is the current route's own (bg_route_detour:
 * its first segments and those it added since). */
int bg_route_own_segment(const bg_router *r, int s) {
  return r->own >= 0 && r->ix.sroute[s] == r->own;
}

/* What crossing routed segment s costs: a signal's, or a bond routed
 * before this one (group -2 - b), the route's own bond's dearest. */
static double seg_cross_cost(const bg_router *r, int s) {
  int g = r->ix.sgrp[s];
  return g <= -2 && g != GROUP_FENCE && own_bond(r, -2 - g) ? COST_CROSS_OWN : COST_CROSS_SIGNAL;
}

/* What running on routed segment s costs: COST_SHARE (two signals read
 * as one line), but for a bond's route on another routed bond's, which
 * reads as one bond (issue 31: a held-out model's bonds 60 and 73 shared
 * 95 pt into a crowded junction's corner, one's neighbour ending on both):
 * COST_BLOCK, as along a bond's own line. */
static double share_cost(const bg_router *r, int s) {
  int g = r->ix.sgrp[s];
  return r->bond >= 0 && g <= -2 && g != GROUP_FENCE && r->ix.sroute[s] >= 0 ? COST_BLOCK : COST_SHARE;
}

/* Whether routed segment s is a line of another signal than the current
 * route's source's (a signal route's only), whose ends, corners and
 * arrowhead the route keeps off (touch_cost): a signal's (sgrp its source:
 * every signal route keeps one, a route drawn whole too), not a fence's or
 * a bond's; a segment left as a point (bg_route_nudge's dropped step) has
 * none. */
static int other_signal(const bg_router *r, int s) {
  int g = r->ix.sgrp[s];
  if (r->bond >= 0 || g < 0 || g == r->group) return 0;
  return r->ix.sb[s].x != r->ix.sa[s].x || r->ix.sb[s].y != r->ix.sa[s].y;
}

/* Where the last TIP_ZONE pt of leg from-tip start (from itself on a
 * shorter leg): the arrowhead and the 1 pt behind it. */
static bg_vec tip_start(bg_vec from, bg_vec tip) {
  bg_vec d = bg_vsub(tip, from);
  double len = bg_vlen(d);
  return len <= TIP_ZONE ? from : bg_vsub(tip, bg_vscale(d, TIP_ZONE / len));
}

/* Routed segment s's arrowhead zone (tip_start to its tip, when it ends
 * its route): 1 and *a-*b, else 0. */
static int tip_zone(const near_index *ix, int s, bg_vec *a, bg_vec *b) {
  if (!ix->slast[s] || bg_vlen(bg_vsub(ix->sb[s], ix->sa[s])) <= 0) return 0;
  *b = ix->sb[s], *a = tip_start(ix->sa[s], ix->sb[s]);
  return 1;
}

/* Whether point e lies within TOUCH_NEAR of segment p-q (its box first: most do not). */
static int touches(bg_vec e, bg_vec p, bg_vec q) {
  if (e.x < fmin(p.x, q.x) - TOUCH_NEAR || e.x > fmax(p.x, q.x) + TOUCH_NEAR || e.y < fmin(p.y, q.y) - TOUCH_NEAR ||
      e.y > fmax(p.y, q.y) + TOUCH_NEAR)
    return 0;
  return bg_point_seg(e, p, q) < TOUCH_NEAR;
}

/* What segment p-q pays for touching routed segment s of another signal
 * (other_signal): COST_TOUCH for passing within TOUCH_NEAR of s's start (a
 * corner, or the route's start: each corner once, as the start of the
 * segment after it) or, when s ends its route, of its tip, and for
 * crossing s's arrowhead. Two signals meeting at a corner or end to end,
 * or one through another's arrowhead, read as one line turning, a branch
 * or a T (reactions20's c4 -> k3 and c11 -> k4 had one corner, each
 * turning onto the other's line: a cross of two arrows and two sources,
 * issue 31). */
static double touch_cost(const bg_router *r, int s, bg_vec p, bg_vec q) {
  double c = 0;
  if (touches(r->ix.sa[s], p, q)) c += COST_TOUCH;
  if (r->ix.slast[s] && touches(r->ix.sb[s], p, q)) c += COST_TOUCH;
  bg_vec a, b;
  if (tip_zone(&r->ix, s, &a, &b) && bg_route_seg_meet(p, q, a, b, 3, HUG, NULL, 0) == 1) c += COST_TOUCH;
  return c;
}

double bg_route_tip_cost(bg_router *r, bg_vec stub, bg_vec at) {
  double c = 0;
  if (r->bond >= 0 || bg_vlen(bg_vsub(at, stub)) <= 0) return 0;
  bg_vec a = tip_start(stub, at);
  bg_near_signals(&r->ix, fmin(a.x, at.x) - 1, fmin(a.y, at.y) - 1, fmax(a.x, at.x) + 1, fmax(a.y, at.y) + 1, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int s = r->nl.k[j];
    if (other_signal(r, s) && !bg_route_own_segment(r, s) && bg_route_seg_meet(a, at, r->ix.sa[s], r->ix.sb[s], 3, HUG, NULL, 0) == 1)
      c += COST_TOUCH;
  }
  return c;
}

/* What a segment p-q costs: its length, and the penalties for what it meets. */
double bg_route_seg_cost(bg_router *r, bg_vec p, bg_vec q, int skip) {
  const bg_diagram_layout *L = r->L;
  double cost = bg_vlen(bg_vsub(q, p)), x0 = fmin(p.x, q.x), x1 = fmax(p.x, q.x), y0 = fmin(p.y, q.y), y1 = fmax(p.y, q.y);
  /* the legs whose lines it may run among (a bare bond's 4 pt: its hug is
   * priced over the grid, bg_route_grid_costs; 12 moved bench_reactions300's
   * routes by one fault either way) */
  double m = fmax(4, r->ring_hug);
  bg_near_box(&r->ix, x0 - m, y0 - m, x1 + m, y1 + m, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int k = r->nl.k[j];
    if (k < L->nnode) {
      if (k == skip) continue;
      /* a box grown by 2 pt: the segment runs through it */
      double bx0 = L->nx[k] - L->nw[k] / 2 - 2, bx1 = L->nx[k] + L->nw[k] / 2 + 2;
      double by0 = L->ny[k] - L->nh[k] / 2 - 2, by1 = L->ny[k] + L->nh[k] / 2 + 2;
      if (x0 < bx1 && x1 > bx0 && y0 < by1 && y1 > by0) cost += COST_BLOCK;
      continue;
    }
    double run = 0;
    int hit = bg_route_seg_meet(p, q, r->ix.la[k - L->nnode], r->ix.lb[k - L->nnode], 3, bg_route_leg_hug(r, k - L->nnode),
                                &run, bg_route_ends(r));
    if (hit == 1) cost += leg_cross_cost(r, k - L->nnode) + at_end_cost(r, k - L->nnode, run);
    if (hit == 3) cost += hug_cost(r, k - L->nnode, line_dist(p, q, r->ix.la[k - L->nnode])) * run;
    cost += hit == 2 ? COST_BLOCK : hit == 4 ? COST_END : 0;
    if (r->ix.lmid[k - L->nnode] && bg_point_seg(r->ix.mid[k - L->nnode], p, q) < 10) cost += COST_NUMBER;
  }
  bg_near_signals(&r->ix, x0 - 4, y0 - 4, x1 + 4, y1 + 4, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int s = r->nl.k[j];
    if (bg_route_own_segment(r, s)) continue; /* the route itself (bg_route_detour) */
    int hit = bg_route_seg_meet(p, q, r->ix.sa[s], r->ix.sb[s], 3, HUG, NULL, 0);
    cost += hit == 1 ? seg_cross_cost(r, s) : hit == 2 ? share_cost(r, s) : 0;
    if (other_signal(r, s)) cost += touch_cost(r, s, p, q);
  }
  return cost;
}

/* The edges of one grid line that overlap the open interval (lo, hi) along
 * it: *i0 .. *i1 (empty when *i0 > *i1). A: the line's vertices, n of them. */
static void edge_range(const double *A, int n, double lo, double hi, int *i0, int *i1) {
  int a = 0, b = n - 1; /* first edge i with A[i + 1] > lo */
  while (a < b) {
    int mid = (a + b) / 2;
    if (A[mid + 1] > lo) b = mid;
    else a = mid + 1;
  }
  int c = -1, d = n - 2; /* last edge i with A[i] < hi */
  while (c < d) {
    int mid = (c + d + 1) / 2;
    if (A[mid] < hi) c = mid;
    else d = mid - 1;
  }
  *i0 = a, *i1 = c;
}

/* The edge i whose half-open extent [A[i], A[i+1]) holds v, or -1. */
static int edge_at(const double *A, int n, double v) {
  if (n < 2 || v < A[0] || v >= A[n - 1]) return -1;
  int a = 0, b = n - 2;
  while (a < b) {
    int mid = (a + b + 1) / 2;
    if (A[mid] <= v) a = mid;
    else b = mid - 1;
  }
  return a;
}

/* A point's coordinates along a grid line and across it. */
static double along(bg_vec p, int horiz) { return horiz ? p.x : p.y; }
static double across(bg_vec p, int horiz) { return horiz ? p.y : p.x; }

/* Segment a-b against grid line (horizontal when horiz) at `at` over the
 * vertices A[0..n-1]: a crossing adds `cross` to the edge it falls in (half
 * open, as bg_route_seg_meet counts it, ends as there, COST_END near an
 * end), and for bond leg `leg` (else -1) at_end_cost; a parallel run within
 * HUG pt (a leg's bg_route_leg_hug) adds to each edge it shares more than
 * 1 pt with `block` when nearer than 3 pt, else for bond leg `leg`
 * hug_cost per pt of the shared run. */
static void line_meet(const double *A, int n, int horiz, double at, bg_vec a, bg_vec b, double cross, double block,
                      int ends, const bg_router *r, int leg, double *out) {
  double va = along(b, horiz) - along(a, horiz), vc = across(b, horiz) - across(a, horiz);
  double lv = sqrt(va * va + vc * vc);
  if (lv <= 0) return;
  if (fabs(vc) < 0.02 * lv) { /* parallel: on one line? */
    double dist = fabs(across(a, horiz) - at);
    double hug = leg >= 0 && dist >= 3 ? hug_cost(r, leg, dist) : 0;
    if (dist >= 3 && hug <= 0) return;
    double t0 = fmin(along(a, horiz), along(b, horiz)), t1 = fmax(along(a, horiz), along(b, horiz));
    int i0, i1;
    edge_range(A, n, t0, t1, &i0, &i1);
    for (int i = i0; i <= i1; i++) {
      double run = fmin(A[i + 1], t1) - fmax(A[i], t0);
      if (run > 1) out[i] += dist < 3 ? block : hug * run;
    }
    return;
  }
  double s = (at - across(a, horiz)) / vc, keep = ends == 2 ? -END_NEAR : ends ? -0.5 : 0.5;
  double from_end = fmin(s * lv, (1 - s) * lv);
  if (from_end < keep) return;
  int i = edge_at(A, n, along(a, horiz) + s * va);
  if (i < 0) return;
  double extra = leg >= 0 ? at_end_cost(r, leg, s * lv) : 0;
  out[i] += (ends == 2 && from_end <= END_NEAR ? COST_END : cross) + extra;
}

/* COST_TOUCH added to every edge of the grid line at `at` (over the
 * vertices A[0..n-1], horizontal when horiz) that passes within TOUCH_NEAR
 * of point e (touch_cost's corners and tips, edge by edge). */
static void touch_line(const double *A, int n, int horiz, double at, bg_vec e, double *out) {
  double dc = fabs(across(e, horiz) - at);
  if (dc >= TOUCH_NEAR) return;
  double half = sqrt(TOUCH_NEAR * TOUCH_NEAR - dc * dc);
  int i0, i1;
  edge_range(A, n, along(e, horiz) - half, along(e, horiz) + half, &i0, &i1);
  for (int i = i0; i <= i1; i++) out[i] += COST_TOUCH;
}

/* The grid lines (of A[0..n-1]) at lo..hi, both included: *j0 .. *j1. */
static void line_range(const double *A, int n, double lo, double hi, int *j0, int *j1) {
  int a = 0, b = n; /* first j with A[j] >= lo */
  while (a < b) {
    int mid = (a + b) / 2;
    if (A[mid] >= lo) b = mid;
    else a = mid + 1;
  }
  int c = -1, d = n - 1; /* last j with A[j] <= hi */
  while (c < d) {
    int mid = (c + d + 1) / 2;
    if (A[mid] <= hi) c = mid;
    else d = mid - 1;
  }
  *j0 = a, *j1 = c;
}

/* What every edge of the grid costs, the same as bg_route_seg_cost would say edge by
 * edge: the edges' lengths, then each item near the grid (from one query of
 * the near index over the whole window) added to the lines it comes near
 * and there to the edges it meets (found by bisection). One pass over the
 * window's items instead of a query per edge: an item is looked at once,
 * not once for every edge near it. hcost holds the horizontal lines' edges
 * (line j's edge i at j * nx + i), vcost the vertical ones' (line j's edge
 * i at j * ny + i). */
void bg_route_grid_costs(bg_router *r) {
  const bg_diagram_layout *L = r->L;
  const double *X = r->X, *Y = r->Y;
  int nx = r->nxl, ny = r->nyl;
  for (int j = 0; j < ny; j++)
    for (int i = 0; i + 1 < nx; i++) r->hcost[j * nx + i] = X[i + 1] - X[i];
  for (int j = 0; j < nx; j++)
    for (int i = 0; i + 1 < ny; i++) r->vcost[j * ny + i] = Y[i + 1] - Y[i];
  double far = fmax(HUG, r->ring_hug); /* the farthest a leg's hug reaches */
  bg_near_box(&r->ix, X[0] - far, Y[0] - far, X[nx - 1] + far, Y[ny - 1] + far, &r->nl);
  for (int jj = 0; jj < r->nl.n; jj++) {
    int k = r->nl.k[jj], j0, j1, i0, i1;
    if (k < L->nnode) { /* a box grown by 2 pt: the lines through it */
      double bx0 = L->nx[k] - L->nw[k] / 2 - 2, bx1 = L->nx[k] + L->nw[k] / 2 + 2;
      double by0 = L->ny[k] - L->nh[k] / 2 - 2, by1 = L->ny[k] + L->nh[k] / 2 + 2;
      line_range(Y, ny, by0, by1, &j0, &j1);
      edge_range(X, nx, bx0, bx1, &i0, &i1);
      for (int j = j0; j <= j1; j++)
        for (int i = i0; Y[j] > by0 && Y[j] < by1 && i <= i1; i++) r->hcost[j * nx + i] += COST_BLOCK;
      line_range(X, nx, bx0, bx1, &j0, &j1);
      edge_range(Y, ny, by0, by1, &i0, &i1);
      for (int j = j0; j <= j1; j++)
        for (int i = i0; X[j] > bx0 && X[j] < bx1 && i <= i1; i++) r->vcost[j * ny + i] += COST_BLOCK;
      continue;
    }
    int leg = k - L->nnode;
    bg_vec a = r->ix.la[leg], b = r->ix.lb[leg];
    double cross = leg_cross_cost(r, leg), hug = bg_route_leg_hug(r, leg);
    line_range(Y, ny, fmin(a.y, b.y) - hug, fmax(a.y, b.y) + hug, &j0, &j1);
    for (int j = j0; j <= j1; j++)
      line_meet(X, nx, 1, Y[j], a, b, cross, COST_BLOCK, bg_route_ends(r), r, leg, &r->hcost[j * nx]);
    line_range(X, nx, fmin(a.x, b.x) - hug, fmax(a.x, b.x) + hug, &j0, &j1);
    for (int j = j0; j <= j1; j++)
      line_meet(Y, ny, 0, X[j], a, b, cross, COST_BLOCK, bg_route_ends(r), r, leg, &r->vcost[j * ny]);
    if (r->ix.lmid[leg]) { /* the edges within 10 pt of the bond's middle */
      bg_vec mid = r->ix.mid[leg];
      line_range(Y, ny, mid.y - 10, mid.y + 10, &j0, &j1);
      for (int j = j0; j <= j1; j++) {
        double dc = fabs(mid.y - Y[j]), half = dc < 10 ? sqrt(100 - dc * dc) : 0;
        edge_range(X, nx, mid.x - half, mid.x + half, &i0, &i1);
        for (int i = i0; half > 0 && i <= i1; i++) r->hcost[j * nx + i] += COST_NUMBER;
      }
      line_range(X, nx, mid.x - 10, mid.x + 10, &j0, &j1);
      for (int j = j0; j <= j1; j++) {
        double dc = fabs(mid.x - X[j]), half = dc < 10 ? sqrt(100 - dc * dc) : 0;
        edge_range(Y, ny, mid.y - half, mid.y + half, &i0, &i1);
        for (int i = i0; half > 0 && i <= i1; i++) r->vcost[j * ny + i] += COST_NUMBER;
      }
    }
  }
  bg_near_signals(&r->ix, X[0] - 3, Y[0] - 3, X[nx - 1] + 3, Y[ny - 1] + 3, &r->nl);
  for (int jj = 0; jj < r->nl.n; jj++) { /* routed signals: crossed, or run on (within 3 pt) */
    int s = r->nl.k[jj], other = other_signal(r, s), tip = other && r->ix.slast[s];
    bg_vec a = r->ix.sa[s], b = r->ix.sb[s];
    double cross = seg_cross_cost(r, s), share = share_cost(r, s);
    int j0, j1; /* touch_cost's corners and tips: lines within TOUCH_NEAR (< 3) of them are among these */
    line_range(Y, ny, fmin(a.y, b.y) - 3, fmax(a.y, b.y) + 3, &j0, &j1);
    for (int j = j0; j <= j1; j++) {
      line_meet(X, nx, 1, Y[j], a, b, cross, share, 0, r, -1, &r->hcost[j * nx]);
      if (other) touch_line(X, nx, 1, Y[j], a, &r->hcost[j * nx]);
      if (tip) touch_line(X, nx, 1, Y[j], b, &r->hcost[j * nx]);
    }
    line_range(X, nx, fmin(a.x, b.x) - 3, fmax(a.x, b.x) + 3, &j0, &j1);
    for (int j = j0; j <= j1; j++) {
      line_meet(Y, ny, 0, X[j], a, b, cross, share, 0, r, -1, &r->vcost[j * ny]);
      if (other) touch_line(Y, ny, 0, X[j], a, &r->vcost[j * ny]);
      if (tip) touch_line(Y, ny, 0, X[j], b, &r->vcost[j * ny]);
    }
    bg_vec za, zb; /* the arrowhead's zone, crossed (touch_cost) */
    if (!tip || !tip_zone(&r->ix, s, &za, &zb)) continue;
    line_range(Y, ny, fmin(za.y, zb.y), fmax(za.y, zb.y), &j0, &j1);
    for (int j = j0; j <= j1; j++) line_meet(X, nx, 1, Y[j], za, zb, COST_TOUCH, 0, 0, r, -1, &r->hcost[j * nx]);
    line_range(X, nx, fmin(za.x, zb.x), fmax(za.x, zb.x), &j0, &j1);
    for (int j = j0; j <= j1; j++) line_meet(Y, ny, 0, X[j], za, zb, COST_TOUCH, 0, 0, r, -1, &r->vcost[j * ny]);
  }
}
