/* SPDX-License-Identifier: BSD-3-Clause */
/* The A* search over the grid of channel lines (diagram_route_grid.c),
 * its edges costed by diagram_route_cost.c: in a window round a route's two
 * ends (bg_route_in_window) or round the outside of the figure
 * (bg_route_outside). */
#include <math.h>
#include <stdlib.h>

#include "diagram/diagram_route_int.h"

static int entry_less(const heap_entry *a, const heap_entry *b) {
  return a->f < b->f || (a->f == b->f && a->s < b->s);
}

static void heap_push(bg_router *r, int s, double f, double g) {
  if (r->nheap == r->capheap) r->capheap = 2 * r->capheap + 64, r->heap = bg_xrealloc(r->heap, (size_t)r->capheap * sizeof *r->heap);
  heap_entry e = {f, g, s};
  int i = r->nheap++;
  while (i > 0 && entry_less(&e, &r->heap[(i - 1) / 2])) r->heap[i] = r->heap[(i - 1) / 2], i = (i - 1) / 2;
  r->heap[i] = e;
}

static heap_entry heap_pop(bg_router *r) {
  heap_entry top = r->heap[0], last = r->heap[--r->nheap];
  int i = 0;
  for (;;) {
    int c = 2 * i + 1;
    if (c >= r->nheap) break;
    if (c + 1 < r->nheap && entry_less(&r->heap[c + 1], &r->heap[c])) c++;
    if (!entry_less(&r->heap[c], &last)) break;
    r->heap[i] = r->heap[c], i = c;
  }
  if (r->nheap) r->heap[i] = last;
  return top;
}

/* A branch's start (parent[] of a state seeded by seed_branches; a port's is -2 - port). */
enum { FROM_BRANCH = -1000 };
/* How far from an earlier route's arrow tip a branch may leave it: clear
 * of the arrowhead, so the branch is not read as coming out of the target. */
#define TIP_CLEAR 16.0

/* The vertices of the grid on the earlier routes of the current route's
 * source (r->group) as starts of the search: a signal is taken off the
 * line of another from the same source at a right angle, as block diagrams
 * draw a fan-out, paying COST_BEND for the branch and nothing for the line
 * already drawn (running along it from the source costs its length: the
 * fan's signals were drawn as parallel lines side by side, 8 pt apart, out
 * of one side of the source). The lines of those routes are the grid's
 * (add_group_lines keeps them whole), so their vertices lie on them. */
static void seed_branches(bg_router *r) {
  if (r->group < 0 || r->whole) return;
  int nx = r->nxl, ny = r->nyl;
  bg_near_signals(&r->ix, r->X[0] - 1, r->Y[0] - 1, r->X[nx - 1] + 1, r->Y[ny - 1] + 1, &r->nl);
  for (int jj = 0; jj < r->nl.n; jj++) {
    int s = r->nl.k[jj];
    if (r->ix.sgrp[s] != r->group) continue;
    bg_vec a = r->ix.sa[s], b = r->ix.sb[s];
    int horiz = fabs(a.y - b.y) < 1e-9;
    if (!horiz && fabs(a.x - b.x) >= 1e-9) continue;
    const double *A = horiz ? r->X : r->Y, *C = horiz ? r->Y : r->X;
    int na = horiz ? nx : ny, nc = horiz ? ny : nx, j = bg_route_nearest_line(C, nc, horiz ? a.y : a.x);
    if (fabs(C[j] - (horiz ? a.y : a.x)) > 1e-6) continue;
    double lo = fmin(horiz ? a.x : a.y, horiz ? b.x : b.y), hi = fmax(horiz ? a.x : a.y, horiz ? b.x : b.y);
    for (int i = bg_route_nearest_line(A, na, lo); i < na && A[i] <= hi + 1e-6; i++) {
      if (A[i] < lo - 1e-6) continue;
      int v = horiz ? j * nx + i : i * nx + j;
      bg_vec p = bg_v(r->X[v % nx], r->Y[v / nx]);
      if (r->ix.slast[s] && bg_vlen(bg_vsub(p, b)) < TIP_CLEAR) continue;
      for (int k = 0; k < 2; k++) { /* across the line, either way */
        int st = 4 * v + (horiz ? 2 + k : k);
        if (COST_BEND < r->g[st]) r->g[st] = COST_BEND, r->parent[st] = FROM_BRANCH, heap_push(r, st, COST_BEND, COST_BEND);
      }
    }
  }
}

/* A* from the source ports to the target ports over the grid; the states
 * are (vertex, direction of travel). Returns the cost and the route's
 * vertices from source to target in pts (at most cap), *npts. */
static double search(bg_router *r, port *ps, int nps, port *pt, int npt, bg_vec *pts, int cap, int *npts) {
  int nx = r->nxl, ny = r->nyl, nv = nx * ny, ns = 4 * nv;
  if (r->cap_states < ns) {
    r->cap_states = ns;
    r->g = bg_xrealloc(r->g, (size_t)ns * sizeof *r->g), r->parent = bg_xrealloc(r->parent, (size_t)ns * sizeof *r->parent);
    r->hcost = bg_xrealloc(r->hcost, (size_t)nv * sizeof *r->hcost), r->vcost = bg_xrealloc(r->vcost, (size_t)nv * sizeof *r->vcost);
    r->hv = bg_xrealloc(r->hv, (size_t)nv * sizeof *r->hv);
  }
  for (int s = 0; s < ns; s++) r->g[s] = INFINITY, r->parent[s] = -1;
  for (int v = 0; v < nv; v++) r->hv[v] = NAN;
  bg_route_grid_costs(r);
  /* goal vertices: each target port's stub, entered along its inward normal */
  int *goal_dir = bg_xcalloc((size_t)nv, sizeof *goal_dir); /* bit mask of inward directions + 1 */
  double *goal_cost = bg_xcalloc((size_t)nv * 4, sizeof *goal_cost);
  int *goal_port = bg_xcalloc((size_t)nv * 4, sizeof *goal_port);
  for (int i = 0; i < npt; i++) {
    int gx = bg_route_nearest_line(r->X, nx, pt[i].stub.x), gy = bg_route_nearest_line(r->Y, ny, pt[i].stub.y), v = gy * nx + gx;
    int in = pt[i].dir ^ 1; /* travel toward the box: opposite the normal */
    if (!(goal_dir[v] & (1 << in)) || pt[i].cost < goal_cost[v * 4 + in])
      goal_dir[v] |= 1 << in, goal_cost[v * 4 + in] = pt[i].cost, goal_port[v * 4 + in] = i;
  }
  r->nheap = 0;
  for (int i = 0; i < nps; i++) {
    int gx = bg_route_nearest_line(r->X, nx, ps[i].stub.x), gy = bg_route_nearest_line(r->Y, ny, ps[i].stub.y);
    int s = 4 * (gy * nx + gx) + ps[i].dir;
    if (ps[i].cost < r->g[s]) r->g[s] = ps[i].cost, r->parent[s] = -2 - i, heap_push(r, s, ps[i].cost, ps[i].cost);
  }
  seed_branches(r);
  double best = INFINITY;
  int best_s = -1, best_port = -1;
  while (r->nheap) {
    heap_entry e = heap_pop(r);
    int s = e.s;
    double gs = r->g[s];
    if (e.g > gs) continue; /* a state reached more cheaply since */
    if (e.f >= best) break; /* the heuristic is admissible: nothing left is cheaper */
    int v = s / 4, dir = s % 4, vx = v % nx, vy = v / nx;
    for (int in = 0; goal_dir[v] && in < 4; in++) { /* onto a port's stub, turning onto it or not */
      if (!(goal_dir[v] & (1 << in)) || dir == (in ^ 1)) continue;
      double c = gs + goal_cost[v * 4 + in] + (dir != in ? COST_BEND : 0);
      if (c < best) best = c, best_s = s, best_port = goal_port[v * 4 + in];
    }
    for (int nd = 0; nd < 4; nd++) {
      if (nd == (dir ^ 1)) continue; /* no turning back */
      int wx = vx + (nd == 0) - (nd == 1), wy = vy + (nd == 2) - (nd == 3);
      if (wx < 0 || wy < 0 || wx >= nx || wy >= ny) continue;
      int w = wy * nx + wx;
      double ec = nd < 2 ? r->hcost[vy * nx + (nd == 0 ? vx : wx)] : r->vcost[vx * ny + (nd == 2 ? vy : wy)];
      double c = gs + ec + (nd != dir ? COST_BEND : 0);
      int t = 4 * w + nd;
      if (c < r->g[t]) {
        r->g[t] = c, r->parent[t] = s;
        double h = r->hv[w];
        if (isnan(h)) {
          h = INFINITY;
          for (int i = 0; i < npt; i++) h = fmin(h, fabs(pt[i].stub.x - r->X[wx]) + fabs(pt[i].stub.y - r->Y[wy]));
          r->hv[w] = h;
        }
        heap_push(r, t, c + h, c);
      }
    }
  }
  *npts = 0;
  r->seeded = 0;
  if (best_s >= 0) {
    /* walk back, then reverse: source port, its stub, corners..., target stub, target port */
    int n = 0;
    pts[n++] = pt[best_port].at;
    int s = best_s, prev_dir = -1;
    while (s >= 0 && n < cap - 2) {
      int v = s / 4, dir = s % 4;
      if (dir != prev_dir || r->parent[s] < 0) pts[n++] = bg_v(r->X[v % nx], r->Y[v / nx]);
      prev_dir = dir;
      if (r->parent[s] < 0) {
        if (r->parent[s] != FROM_BRANCH) pts[n++] = ps[-2 - r->parent[s]].at;
        r->seeded = r->parent[s] == FROM_BRANCH;
        break;
      }
      s = r->parent[s];
    }
    for (int i = 0; i < n / 2; i++) {
      bg_vec t = pts[i];
      pts[i] = pts[n - 1 - i], pts[n - 1 - i] = t;
    }
    *npts = n;
  }
  free(goal_dir), free(goal_cost), free(goal_port);
  return best;
}

/* The search over the grid built (bg_route_in_window, bg_route_outside),
 * refused when its lines were merged more than max_gap apart. */
static int route_grid(bg_router *r, port *ps, int nps, port *pt, int npt, double max_gap, bg_vec *pts, int cap,
                      double *cost) {
  *cost = INFINITY;
  if (r->gap > max_gap) return 0;
  bg_route_snap_ports(r, ps, nps), bg_route_snap_ports(r, pt, npt);
  for (int i = 0; i < nps; i++) ps[i].cost = ps[i].base + bg_route_seg_cost(r, ps[i].at, ps[i].stub, r->from_node);
  for (int i = 0; i < npt; i++)
    pt[i].cost = pt[i].base + bg_route_seg_cost(r, pt[i].stub, pt[i].at, r->to_node) + bg_route_tip_cost(r, pt[i].stub, pt[i].at);
  int n = 0;
  *cost = search(r, ps, nps, pt, npt, pts, cap, &n);
  return n;
}

int bg_route_in_window(bg_router *r, port *ps, int nps, port *pt, int npt, double wx0, double wy0, double wx1,
                       double wy1, double max_gap, bg_vec *pts, int cap, double *cost) {
  bg_route_build_grid(r, wx0, wy0, wx1, wy1, ps, nps, pt, npt);
  return route_grid(r, ps, nps, pt, npt, max_gap, pts, cap, cost);
}

/* Round the outside, when the window's search found no way clear of the
 * boxes and the whole figure's grid is too coarse to search: a grid of the
 * lanes near each end (OUT_NEAR pt round its box) and a ring OUT_RING pt
 * outside the figure's box. The lanes' lines run across the figure, so the
 * route leaves along a channel next to its source, runs round the ring and
 * comes in along a channel next to its target; the grid's edges are costed
 * as any, so a run through a box still costs COST_BLOCK and is taken only
 * when no channel leads out. */
#define OUT_NEAR (6 * LANE)
#define OUT_RING (2 * LANE)
int bg_route_outside(bg_router *r, port *ps, int nps, port *pt, int npt, const double a[4], const double b[4],
                     bg_vec *pts, int cap, double *cost) {
  bg_route_add_ports(r, ps, nps, pt, npt);
  bg_route_add_cand(r, r->fx0 - OUT_RING, r->fy0 - OUT_RING, 0), bg_route_add_cand(r, r->fx1 + OUT_RING, r->fy1 + OUT_RING, 0);
  bg_route_add_lanes(r, a[0] - OUT_NEAR, a[1] - OUT_NEAR, a[2] + OUT_NEAR, a[3] + OUT_NEAR);
  bg_route_add_lanes(r, b[0] - OUT_NEAR, b[1] - OUT_NEAR, b[2] + OUT_NEAR, b[3] + OUT_NEAR);
  bg_route_make_lines(r);
  return route_grid(r, ps, nps, pt, npt, INFINITY, pts, cap, cost);
}
