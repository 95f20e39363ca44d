/* SPDX-License-Identifier: BSD-3-Clause */
/* A route that crosses the bond of a one-port (an element with this one
 * bond, so the bond leads nowhere else) at a right angle can go round the
 * one-port instead: a U off the crossing segment, along the bond past the
 * element's box (3, 6 or 9 pt clear), across and back (issue 31: crossings a
 * detour of bounded length avoids, tests/unit/figure_check.h
 * fc_avoidable). The search misses some (its lines lie LANE off the boxes,
 * its window ends, a bend costs); this takes those whose U adds at most
 * DETOUR_MAX pt, stays within the segment, and crosses no bond and no box. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_route_int.h"

#define DETOUR_MAX 160.0 /* COST_CROSS_BOND: a detour no longer than the crossing's price */

/* The one-port element whose bond leg `leg` reaches, with the leg's
 * direction towards it (*w), or -1. */
static int leg_one_port(const bg_router *r, int leg, bg_vec *w) {
  const bg_diagram_layout *L = r->L;
  const bg_model *m = L->m;
  int b = r->ix.lbond[leg];
  for (int head = 0; head < 2; head++) {
    int e = head ? m->bond_head[b] : m->bond_tail[b];
    bg_vec end = head ? L->bg[b].head : L->bg[b].tail, far = head ? r->ix.la[leg] : r->ix.lb[leg];
    bg_vec near = head ? r->ix.lb[leg] : r->ix.la[leg];
    if (e >= m->nelem || m->elem_nbond[e] != 1 || bg_route_end_node(L, b, head) != e || !bg_route_node_drawn(L, e)) continue;
    if (bg_vlen(bg_vsub(near, end)) > 0.01 || e == r->from_node || e == r->to_node) continue;
    *w = bg_vunit(bg_vsub(near, far));
    return e;
  }
  return -1;
}

/* Whether a later route of the same source branches off the stretch p-q
 * (a segment of another route of r->group starts or ends on it): a U there
 * would leave the branch's dot beside the line. */
static int branch_off(bg_router *r, bg_vec p, bg_vec q) {
  if (r->group < 0) return 0;
  bg_near_signals(&r->ix, fmin(p.x, q.x) - 1, fmin(p.y, q.y) - 1, fmax(p.x, q.x) + 1, fmax(p.y, q.y) + 1, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int s = r->nl.k[j];
    if (r->ix.sgrp[s] != r->group || bg_route_own_segment(r, s)) continue;
    if (bg_point_seg(r->ix.sa[s], p, q) < 0.01 || bg_point_seg(r->ix.sb[s], p, q) < 0.01) return 1;
  }
  return 0;
}

/* The U off p-q (unit u, length len) round the one-port whose bond leg
 * `leg` it crosses, into u4, the nearest clear of 3, 6 or 9 pt; returns
 * where along p-q it starts, or -1 when none is clear. */
static double leg_detour(bg_router *r, bg_vec p, bg_vec u, double len, int leg, bg_vec u4[4]) {
  const bg_diagram_layout *L = r->L;
  bg_vec w;
  int e = leg_one_port(r, leg, &w);
  if (e < 0 || fabs(u.x * w.x + u.y * w.y) > 0.01 || (fabs(u.x) > 1e-9 && fabs(u.y) > 1e-9)) return -1;
  bg_vec a = r->ix.la[leg], z = r->ix.lb[leg];
  double den = u.x * w.y - u.y * w.x, t = ((a.x - p.x) * w.y - (a.y - p.y) * w.x) / den; /* the crossing along p-q */
  bg_vec X = bg_vadd(p, bg_vscale(u, t)), n = bg_v(-u.y, u.x);
  w = n.x * w.x + n.y * w.y > 0 ? n : bg_vscale(n, -1); /* the U's legs on the axes, as the route's */
  double a0 = 1e300, a1 = -1e300, depth = 0;
  for (int k = 0; k < 6; k++) { /* the element's box and the bond's end must lie inside the U */
    bg_vec c = k == 4 ? a : k == 5 ? z
               : bg_v(L->nx[e] + (k & 1 ? 0.5 : -0.5) * L->nw[e], L->ny[e] + (k & 2 ? 0.5 : -0.5) * L->nh[e]);
    double du = (c.x - X.x) * u.x + (c.y - X.y) * u.y, dw = (c.x - X.x) * w.x + (c.y - X.y) * w.y;
    if (k >= 4 && dw < 0) continue; /* the leg's other end, behind the crossing */
    a0 = fmin(a0, du), a1 = fmax(a1, du), depth = fmax(depth, dw);
  }
  for (int g = 0; g < 3; g++) { /* the nearest clear U first, off other lines */
    static const double gap[3] = {3, 6, 9};
    double d = depth + gap[g];
    if (t + a0 - gap[g] < 1 || t + a1 + gap[g] > len - 1 || 2 * d > DETOUR_MAX) continue;
    u4[0] = bg_vadd(X, bg_vscale(u, a0 - gap[g])), u4[3] = bg_vadd(X, bg_vscale(u, a1 + gap[g]));
    u4[1] = bg_vadd(u4[0], bg_vscale(w, d)), u4[2] = bg_vadd(u4[3], bg_vscale(w, d));
    if (branch_off(r, u4[0], u4[3])) continue;
    if (bg_route_path_penalty(r, u4, 3) < COST_CROSS_BOND / 2) return t + a0 - gap[g]; /* no bond crossed, no box run through, no line run on */
  }
  return -1;
}

/* Segment pts[i]-pts[i+1] round the first one-port along it whose bond it
 * crosses and a U avoids (the caller goes on along the rest, so a U
 * further on is not taken before a nearer one): the U's four points into
 * u4 (returns 1), else 0. */
static int detour_segment(bg_router *r, const bg_vec *pts, int i, bg_vec u4[4]) {
  const bg_diagram_layout *L = r->L;
  bg_vec p = pts[i], q = pts[i + 1];
  double len = bg_vlen(bg_vsub(q, p)), first = INFINITY;
  if (len <= 0 || (r->group >= 0 && bg_route_group_runs_on(r, p, q))) return 0;
  bg_vec u = bg_vscale(bg_vsub(q, p), 1 / len);
  bg_near_box(&r->ix, fmin(p.x, q.x), fmin(p.y, q.y), fmax(p.x, q.x), fmax(p.y, q.y), &r->nl);
  int nk = r->nl.n, *legs = bg_xcalloc((size_t)nk + 1, sizeof *legs);
  for (int j = 0; j < nk; j++) legs[j] = r->nl.k[j];
  for (int j = 0; j < nk; j++) {
    int leg = legs[j] - L->nnode;
    bg_vec cand[4];
    if (leg < 0 || bg_route_seg_meet(p, q, r->ix.la[leg], r->ix.lb[leg], 3, HUG, NULL, 0) != 1) continue;
    double at = leg_detour(r, p, u, len, leg, cand);
    if (at >= 0 && at < first) first = at, memcpy(u4, cand, sizeof cand);
  }
  free(legs);
  return first < INFINITY;
}

int bg_route_detour(bg_router *r, int k, int first, bg_vec *pts, int n, int cap) {
  if (k < 0 || k >= r->nroute) return n;
  const struct routed *rt = &r->route[k];
  r->from_node = rt->from, r->to_node = rt->to, r->group = rt->group, r->bond = -1, r->own = k;
  for (int i = first < 0 ? 0 : first; i + 1 < n && n + 4 <= cap; i++) {
    bg_vec u4[4];
    if (!detour_segment(r, pts, i, u4)) continue;
    /* the index: the crossing segment (the route's own, or the rest an
     * earlier U added, in this call or an earlier one) cut short at the U,
     * the rest added */
    int s = bg_near_route_segment(&r->ix, rt->seg0, k, pts[i], pts[i + 1]);
    if (s >= 0) r->ix.sb[s] = u4[0];
    for (int j = 0; j < 3; j++) bg_near_add_signal(&r->ix, u4[j], u4[j + 1], rt->group, k);
    bg_near_add_signal(&r->ix, u4[3], pts[i + 1], rt->group, k);
    memmove(pts + i + 5, pts + i + 1, (size_t)(n - i - 1) * sizeof *pts);
    memcpy(pts + i + 1, u4, sizeof u4);
    n += 4, i += 3; /* on with the rest of the crossing segment */
  }
  r->own = -1;
  return n;
}
