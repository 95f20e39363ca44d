/* SPDX-License-Identifier: BSD-3-Clause */
/* A signal branching off the line of another from the same source, as
 * block diagrams draw it: the point of the source's earlier routes nearest
 * a target (where the router first looks for a branch), where a route
 * leaves the earlier routes that it starts on, and whether it runs on them
 * again after (then it is no branch, and diagram_route.c routes it again
 * keeping off them). The search starts branches off those routes itself
 * (diagram_route_search.c, seed_branches). */
#include <math.h>

#include "diagram/diagram_route_int.h"

/* How far along segment p-q, from p, the earlier routes of the current
 * route's source cover it (collinear, within 0.01 pt), in pt. */
static double group_reach(bg_router *r, bg_vec p, bg_vec q) {
  double len = bg_vlen(bg_vsub(q, p)), reach = 0;
  if (len <= 0) return 0;
  bg_vec u = bg_vscale(bg_vsub(q, p), 1 / len);
  bg_near_signals(&r->ix, fmin(p.x, q.x) - 1, fmin(p.y, q.y) - 1, fmax(p.x, q.x) + 1, fmax(p.y, q.y) + 1, &r->nl);
  for (int grew = 1; grew;) {
    grew = 0;
    for (int j = 0; j < r->nl.n; j++) {
      int s = r->nl.k[j];
      if (r->ix.sgrp[s] != r->group) continue;
      bg_vec a = bg_vsub(r->ix.sa[s], p), b = bg_vsub(r->ix.sb[s], p);
      if (fabs(a.x * u.y - a.y * u.x) > 0.01 || fabs(b.x * u.y - b.y * u.x) > 0.01) continue;
      double t0 = fmin(a.x * u.x + a.y * u.y, b.x * u.x + b.y * u.y), t1 = fmax(a.x * u.x + a.y * u.y, b.x * u.x + b.y * u.y);
      if (t0 <= reach + 0.01 && fmin(t1, len) > reach + 0.01) reach = fmin(t1, len), grew = 1;
    }
  }
  return reach;
}

/* Whether segment p-q runs on an earlier route of the current source for
 * more than 1 pt anywhere (collinear, within 0.01 pt). */
int bg_route_group_runs_on(bg_router *r, bg_vec p, bg_vec q) {
  double len = bg_vlen(bg_vsub(q, p));
  if (len <= 1) return 0;
  bg_vec u = bg_vscale(bg_vsub(q, p), 1 / len);
  bg_near_signals(&r->ix, fmin(p.x, q.x) - 1, fmin(p.y, q.y) - 1, fmax(p.x, q.x) + 1, fmax(p.y, q.y) + 1, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int s = r->nl.k[j];
    if (r->ix.sgrp[s] != r->group || bg_route_own_segment(r, s)) continue;
    bg_vec a = bg_vsub(r->ix.sa[s], p), b = bg_vsub(r->ix.sb[s], p);
    if (fabs(a.x * u.y - a.y * u.x) > 0.01 || fabs(b.x * u.y - b.y * u.x) > 0.01) continue;
    double ta = a.x * u.x + a.y * u.y, tb = b.x * u.x + b.y * u.y;
    if (fmin(len, fmax(ta, tb)) - fmax(0, fmin(ta, tb)) > 1) return 1;
  }
  return 0;
}

/* Whether the route, after where it leaves its source's earlier routes
 * (k, at from bg_route_shared_prefix; k -1: from its start), runs on them again:
 * then it cannot be drawn as a branch. */
int bg_route_group_rejoins(bg_router *r, const bg_vec *pts, int n, int k, bg_vec at) {
  if (r->group < 0 || r->whole) return 0;
  for (int i = k < 0 ? 0 : k; i + 1 < n; i++)
    if (bg_route_group_runs_on(r, i == k ? at : pts[i], pts[i + 1])) return 1;
  return 0;
}

/* Where route pts[0..n-1] of the current source leaves the routes of that
 * source before it, when it starts on them (a signal branching off the
 * line of another from the same source, as block diagrams draw it): the
 * index k of the segment it leaves on and the point *at, or -1 when it
 * does not start on them or keeps on them to within 10 pt of its tip
 * (then it is drawn whole). */
int bg_route_shared_prefix(bg_router *r, const bg_vec *pts, int n, bg_vec *at) {
  if (r->group < 0 || r->whole || n < 2) return -1;
  for (int i = 0; i + 1 < n; i++) {
    double len = bg_vlen(bg_vsub(pts[i + 1], pts[i])), reach = group_reach(r, pts[i], pts[i + 1]);
    if (reach >= len - 0.01) continue;
    if (i == 0 && reach <= 0.01) return -1;
    *at = bg_vadd(pts[i], bg_vscale(bg_vsub(pts[i + 1], pts[i]), reach / len));
    double rest = len - reach;
    for (int k = i + 1; k + 1 < n; k++) rest += bg_vlen(bg_vsub(pts[k + 1], pts[k]));
    return rest >= 10 ? i : -1;
  }
  return -1;
}

int bg_route_branch(const bg_router *r, bg_vec *at) {
  if (r->branch_k >= 0) *at = r->branch_at;
  return r->branch_k;
}

/* The point of the current source's earlier routes nearest c (*out), looked
 * for in rings of the near index's cells round c, at most NEAREST_RINGS
 * out (so the work is bounded whatever the figure); 0 when there is none
 * that near. */
enum { NEAREST_RINGS = 12 };
int bg_route_group_nearest(bg_router *r, bg_vec c, bg_vec *out) {
  const near_index *ix = &r->ix;
  if (r->group < 0 || r->whole || !ix->nseg) return 0;
  int cc[4];
  bg_near_cells(ix, c.x, c.y, c.x, c.y, cc);
  double best = INFINITY;
  for (int ring = 0; ring <= NEAREST_RINGS && best > (ring - 1) * ix->cell; ring++)
    for (int cy = cc[1] - ring; cy <= cc[1] + ring; cy++)
      for (int cx = cc[0] - ring; cx <= cc[0] + ring; cx += (cy == cc[1] - ring || cy == cc[1] + ring) ? 1 : 2 * ring) {
        if (cx < 0 || cy < 0 || cx >= ix->nx || cy >= ix->ny) continue;
        for (int j = ix->sig_head[(size_t)cy * (size_t)ix->nx + (size_t)cx]; j >= 0; j = ix->sig_next[j]) {
          int s = ix->sig_seg[j];
          if (ix->sgrp[s] != r->group) continue;
          bg_vec p = bg_seg_nearest(c, ix->sa[s], ix->sb[s]);
          double dist = bg_vlen(bg_vsub(p, c));
          if (dist < best) best = dist, *out = p;
        }
        if (ring == 0) break;
      }
  return best < INFINITY;
}
