/* SPDX-License-Identifier: BSD-3-Clause */
/* Two signals from different sources that the search laid side by side a
 * few points apart read as one double line (randnet30_1's c3 -> k4 and
 * c13 -> k15 ran 4 pt apart for 1 100 pt, issue 31). The search does not
 * see it: priced there, the routes stepped sideways to keep clear for part
 * of the way (more steps and crossings than pairs mended). Once every
 * route is drawn, a segment that runs within SIG_BESIDE of another
 * source's signal is moved across, whole, to SIG_NEAR off it (its two
 * neighbours stretch, or at a route's end its port slides along the box),
 * where that crosses and passes nothing it did not. Then a small step (two
 * legs going the same way a few points apart) is straightened, by a route's
 * end (unstep_end) or inside it (unstep_mid), where that passes nothing more. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_route_int.h"

#define SIG_BESIDE 6.0 /* nearer than this beside another source's signal: one double line (the
                          checker's 5 and a point: 5 moved fewer, with more steps) */
#define SIG_NEAR 6.0   /* where a moved segment goes */
#define NUDGE_PRICE 60.0 /* the most a move may add to a route's price to end a double line: COST_HUG
                            a point of the run it ends, up to this (no crossed bond, touch or shared
                            run fits; reactions20's 2-pt move priced 41 pt by a bond's layer lines) */
#define MIN_LEG 8.0    /* a stretched neighbour keeps at least this (shorter, between two parallel
                          legs, reads as a step; the arrow's leg 10) */

/* How far segment p-q (axis-parallel) runs within SIG_BESIDE of other
 * sources' signals (group >= 0, not `group`), summed; *nearest gets the
 * offset of the nearest of them across p-q (along its left normal). */
static double near_run(bg_router *r, bg_vec p, bg_vec q, int group, double *nearest) {
  double len = bg_vlen(bg_vsub(q, p)), total = 0;
  *nearest = INFINITY;
  if (len <= 0) return 0;
  bg_vec u = bg_vscale(bg_vsub(q, p), 1 / len), nrm = bg_v(-u.y, u.x);
  bg_near_signals(&r->ix, fmin(p.x, q.x) - SIG_BESIDE, fmin(p.y, q.y) - SIG_BESIDE, fmax(p.x, q.x) + SIG_BESIDE,
                  fmax(p.y, q.y) + SIG_BESIDE, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int s = r->nl.k[j], g = r->ix.sgrp[s];
    if (g < 0 || g == group) continue;
    bg_vec a = r->ix.sa[s], b = r->ix.sb[s], v = bg_vsub(b, a);
    double lv = bg_vlen(v);
    if (lv <= 0 || fabs(v.x * u.y - v.y * u.x) > 0.02 * lv) continue; /* not parallel */
    double off = (a.x - p.x) * nrm.x + (a.y - p.y) * nrm.y;
    if (fabs(off) >= SIG_BESIDE - 1e-6) continue; /* SIG_NEAR off is clear (rounding aside) */
    double t0 = (a.x - p.x) * u.x + (a.y - p.y) * u.y, t1 = (b.x - p.x) * u.x + (b.y - p.y) * u.y;
    double shared = fmin(len, fmax(t0, t1)) - fmax(0, fmin(t0, t1));
    if (shared <= 1) continue;
    total += shared;
    if (fabs(off) < fabs(*nearest)) *nearest = off;
  }
  return total;
}

/* Where other routes of the route's source (a branch, or the trunk a
 * branch is taken off) meet segment a-b, whose end `moving` (a, b, or
 * neither: NULL) moves: their ends on a-b go into feet[] (at most
 * MAX_FEET). Returns how many, or -1 where they cannot follow: one runs
 * on a-b, or meets it at the moving end. */
#define MAX_FEET 8
static int branch_feet(bg_router *r, bg_vec a, bg_vec b, const bg_vec *moving, int group, int route, bg_vec *feet) {
  int nf = 0;
  bg_near_signals(&r->ix, fmin(a.x, b.x) - 1, fmin(a.y, b.y) - 1, fmax(a.x, b.x) + 1, fmax(a.y, b.y) + 1, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int s = r->nl.k[j];
    bg_vec sa = r->ix.sa[s], sb = r->ix.sb[s];
    if (r->ix.sgrp[s] != group || bg_vlen(bg_vsub(sb, sa)) <= 0 || r->ix.sroute[s] == route) continue;
    int on_a = bg_point_seg(sa, a, b) < 0.01, on_b = bg_point_seg(sb, a, b) < 0.01;
    if (on_a && on_b) return -1; /* runs on it */
    if (moving && bg_point_seg(*moving, sa, sb) < 0.01) return -1;
    if ((on_a || on_b) && nf == MAX_FEET) return -1;
    if (on_a || on_b) feet[nf++] = on_a ? sa : sb;
  }
  return nf;
}

/* The index segment of route k that runs from a to b, or -1: its own
 * (seg0 .. seg1) or one added since (a U round a one-port, bg_route_detour). */
static int index_segment(const bg_router *r, int k, bg_vec a, bg_vec b) {
  return bg_near_route_segment(&r->ix, r->route[k].seg0, k, a, b);
}

/* The route's index segments seg[0..m) parked (a point each, their old
 * ends into keep) while a move is priced, so it does not meet itself;
 * then put back. */
static void park(bg_router *r, const int *seg, int m, bg_vec *keep) {
  for (int k = 0; k < m; k++) keep[k] = r->ix.sb[seg[k]], r->ix.sb[seg[k]] = r->ix.sa[seg[k]];
}

static void unpark(bg_router *r, const int *seg, int m, const bg_vec *keep) {
  for (int k = 0; k < m; k++) r->ix.sb[seg[k]] = keep[k];
}

/* How far the segments q[0..m] run beside other sources' signals, summed:
 * a move counts what its stretched neighbours come to run beside too. */
static double beside_all(bg_router *r, const bg_vec *q, int m, int group) {
  double total = 0, nearest;
  for (int k = 0; k < m; k++) total += near_run(r, q[k], q[k + 1], group, &nearest);
  return total;
}

/* Whether a-b runs along unit vector w (either way). */
static int along(bg_vec a, bg_vec b, bg_vec w) {
  bg_vec v = bg_vsub(b, a);
  return fabs(v.x * w.y - v.y * w.x) < 1e-6;
}

/* Whether route end e (on node n's box side, or 1.5 pt off it at a target)
 * may slide along the side to e + shift w: it stays on the side, 1 pt in
 * from its corners (a target's arrow over the text: the pad and 1.5 pt in,
 * as node_ports puts it), its segment leaving at right angles (along u). */
static int slides(const bg_router *r, int n, bg_vec e, bg_vec u, bg_vec w, double shift, int target) {
  const bg_diagram_layout *L = r->L;
  if (n < 0 || n >= L->nnode) return 0;
  double hw = L->nw[n] / 2, hh = L->nh[n] / 2, gap = target ? 1.5 : 0, out = fabs(u.x) > 0.5 ? hw : hh;
  bg_vec c = bg_v(L->nx[n], L->ny[n]);
  double off = fabs(u.x) > 0.5 ? fabs(e.x - c.x) : fabs(e.y - c.y); /* the side's distance from the centre */
  if (fabs(off - out - gap) > 0.01) return 0;                         /* not on a side at right angles */
  double half = fabs(u.x) > 0.5 ? hh : hw, inset = target ? L->st.node_pad + 1.5 : 1;
  double along_side = (fabs(u.x) > 0.5 ? e.y + w.y * shift - c.y : e.x + w.x * shift - c.x);
  return fabs(along_side) <= half - inset;
}

/* Segment pts[i]-pts[i+1] of a route, its neighbours at right angles to
 * it (or, at the route's ends, its port sliding along the box's side),
 * moved across to SIG_NEAR (or 3 pt more) off the nearest signal beside
 * it, on its side or past it, where that crosses and passes nothing it did
 * not and runs less beside others; pts and the index follow. Returns
 * whether it moved. */
static int nudge_segment(bg_router *r, const struct routed *rt, bg_vec *pts, int n, int i, int from_port) {
  bg_vec p = pts[i], q = pts[i + 1];
  double len = bg_vlen(bg_vsub(q, p)), nearest;
  int group = rt->group, route = (int)(rt - r->route);
  if (len <= 8 || (fabs(p.x - q.x) > 1e-9 && fabs(p.y - q.y) > 1e-9)) return 0;
  double best = near_run(r, p, q, group, &nearest); /* its own segments are not counted: parking them changes nothing */
  if (best <= 8) return 0;
  bg_vec u = bg_vscale(bg_vsub(q, p), 1 / len), nrm = bg_v(-u.y, u.x);
  int lo = i > 0 ? i - 1 : 0, hi = i + 2 < n ? i + 2 : n - 1, m = hi - lo, mid = i - lo;
  if (i == 0 && !from_port) return 0; /* a branch's start on its trunk stays */
  if ((i > 0 && !along(pts[i - 1], p, nrm)) || (i + 2 < n && !along(q, pts[i + 2], nrm))) return 0;
  /* a branch may leave a neighbour where the neighbour, stretched or
   * shortened at its moving end, still passes; none may leave the segment */
  int own[3], nfeet[3];
  bg_vec feet[3][MAX_FEET];
  for (int k = 0; k < m; k++) {
    const bg_vec *moving = k == mid ? NULL : k < mid ? &pts[lo + k + 1] : &pts[lo + k];
    if ((own[k] = index_segment(r, route, pts[lo + k], pts[lo + k + 1])) < 0) return 0;
    nfeet[k] = branch_feet(r, pts[lo + k], pts[lo + k + 1], moving, group, route, feet[k]);
    if (nfeet[k] < 0 || (k == mid && nfeet[k] > 0)) return 0;
  }
  bg_vec keep[3], old[4], chosen[4];
  memcpy(old, pts + lo, (size_t)(m + 1) * sizeof *old);
  park(r, own, m, keep);
  double pen0 = bg_route_path_penalty(r, old, m), side = nearest > 0 ? 1 : -1;
  best = beside_all(r, old, m, group);
  int found = 0;
  for (int t = 0; t < 4; t++) { /* away from the nearest by what it takes, or 3 pt more; then past it */
    double shift = t < 2 ? -side * (SIG_NEAR + 3 * t - fabs(nearest)) : side * (fabs(nearest) + SIG_NEAR + 3 * (t - 2));
    bg_vec moved[4];
    memcpy(moved, old, sizeof moved);
    moved[mid] = bg_vadd(p, bg_vscale(nrm, shift)), moved[mid + 1] = bg_vadd(q, bg_vscale(nrm, shift));
    if (i == 0 && !slides(r, rt->from, p, u, nrm, shift, 0)) continue;
    if (i + 2 == n && !slides(r, rt->to, q, bg_vscale(u, -1), nrm, shift, 1)) continue;
    int ok = 1;
    for (int k = 0; k < m; k++) { /* a neighbour neither turned round nor left shorter than MIN_LEG */
      if (k == mid) continue;
      bg_vec a = bg_vsub(moved[k + 1], moved[k]), a0 = bg_vsub(old[k + 1], old[k]);
      double least = lo + k + 2 == n ? 10 : MIN_LEG; /* the arrow's leg */
      ok &= a.x * a0.x + a.y * a0.y > 0 && bg_vlen(a) >= least;
      for (int f = 0; f < nfeet[k]; f++) ok &= bg_point_seg(feet[k][f], moved[k], moved[k + 1]) < 0.01;
    }
    if (!ok) continue;
    double near = beside_all(r, moved, m, group), pen = bg_route_path_penalty(r, moved, m);
    /* nothing crossed or passed that was not before, and less beside others (its neighbours too) */
    if (pen <= pen0 + fmin(COST_HUG * (best - near), NUDGE_PRICE) + 0.01 && near < best - 8) best = near, memcpy(chosen, moved, sizeof chosen), found = 1;
  }
  unpark(r, own, m, keep);
  if (!found) return 0;
  for (int k = 0; k < m; k++) bg_near_move_signal(&r->ix, own[k], chosen[k], chosen[k + 1]);
  pts[i] = chosen[mid], pts[i + 1] = chosen[mid + 1];
  return 1;
}

/* Whether v runs along an axis. */
static int axial(bg_vec v) { return fabs(v.x) < 1e-9 || fabs(v.y) < 1e-9; }

/* Whether Q-R is a small step between legs P-Q and R-S: all three on the
 * axes (a diagonal stub stays), P-Q and R-S going the same way, Q-R across
 * them and under MIN_LEG. */
static int small_step(bg_vec P, bg_vec Q, bg_vec R, bg_vec S) {
  bg_vec a = bg_vsub(Q, P), b = bg_vsub(R, Q), c = bg_vsub(S, R);
  double la = bg_vlen(a), lb = bg_vlen(b), lc = bg_vlen(c);
  if (la <= 0 || lc <= 0 || lb <= 0 || lb >= MIN_LEG || !axial(a) || !axial(b) || !axial(c)) return 0;
  return a.x * c.x + a.y * c.y >= 0.999 * la * lc && fabs(a.x * b.x + a.y * b.y) <= 0.01 * la * lb;
}

/* A step by a route's end: the leg into the port (the arrow's, or at a
 * source the stub, not a branch's start) a few points across from the leg
 * before it, both going the same way (tower_damper's I : m3 -> act in
 * print: round its junction on the corner's line, then 3.2 pt across to the
 * arrow's port). Points from the interior towards the port: O (the one
 * before, if any), P, Q (the leg before), R (the step's end), E the port.
 * Either the port slides along its side by the step, or the leg before
 * moves across by it (O-P stretching or shrinking, never under MIN_LEG),
 * where the one straight leg left crosses and passes nothing the legs
 * before did not: the step and its corner are dropped. Returns the new
 * number of points. */
static int unstep_end(bg_router *r, int route, bg_vec *pts, int n, int at_start) {
  const struct routed *rt = &r->route[route];
  if (n < 4) return n;
  int has_o = n >= 5, ix[5]; /* O, P, Q, R, E as indices into pts */
  for (int k = 0; k < 5; k++) ix[k] = at_start ? 4 - k : n - 5 + k;
  bg_vec P = pts[ix[1]], Q = pts[ix[2]], R = pts[ix[3]], E = pts[ix[4]];
  if (!small_step(P, Q, R, E)) return n;
  bg_vec b = bg_vsub(R, Q), c = bg_vsub(E, R);
  double lb = bg_vlen(b), lc = bg_vlen(c);
  /* the index segments O-P, P-Q, Q-R, R-E (each as the route runs); no
   * branch of the source on the step or the port's leg */
  int seg[4] = {-1, -1, -1, -1};
  bg_vec feet[MAX_FEET];
  for (int k = has_o ? 0 : 1; k < 4; k++) {
    int lo = ix[k] < ix[k + 1] ? ix[k] : ix[k + 1];
    if ((seg[k] = index_segment(r, route, pts[lo], pts[lo + 1])) < 0) return n;
  }
  for (int k = 2; k < 4; k++)
    if (branch_feet(r, r->ix.sa[seg[k]], r->ix.sb[seg[k]], NULL, rt->group, route, feet) != 0) return n;
  int moves_leg = !slides(r, at_start ? rt->from : rt->to, E, bg_vscale(c, -1 / lc), bg_vscale(b, -1 / lb), lb, !at_start);
  bg_vec O = has_o ? pts[ix[0]] : P, P2 = moves_leg ? bg_vadd(P, b) : P, E2 = moves_leg ? E : bg_vsub(E, b);
  if (moves_leg) { /* O-P keeps its way and MIN_LEG; no branch on the leg that moves or on O-P */
    bg_vec o = bg_vsub(P, O), o2 = bg_vsub(P2, O);
    if (!has_o || o.x * o2.x + o.y * o2.y <= 0 || bg_vlen(o2) < MIN_LEG) return n;
    for (int k = 0; k < 2; k++)
      if (branch_feet(r, r->ix.sa[seg[k]], r->ix.sb[seg[k]], NULL, rt->group, route, feet) != 0) return n;
  }
  bg_vec keep[4], old[5] = {O, P, Q, R, E}, line[3] = {O, P2, E2};
  int from = has_o ? 0 : 1;
  park(r, seg + from, 4 - from, keep);
  int ok = bg_route_path_penalty(r, line + from, 2 - from) <= bg_route_path_penalty(r, old + from, 4 - from) + 0.01;
  unpark(r, seg + from, 4 - from, keep);
  if (!ok) return n;
  /* the index: O-P to O-P2, P-Q to the straight leg, the step and the
   * port's leg left as points; each as the route runs */
  if (moves_leg) bg_near_move_signal(&r->ix, seg[0], at_start ? P2 : O, at_start ? O : P2);
  bg_near_move_signal(&r->ix, seg[1], at_start ? E2 : P2, at_start ? P2 : E2);
  bg_near_move_signal(&r->ix, seg[2], Q, Q), bg_near_move_signal(&r->ix, seg[3], Q, Q);
  if (!at_start) r->ix.slast[seg[1]] = r->ix.slast[seg[3]], r->ix.slast[seg[3]] = 0;
  pts[ix[1]] = P2, pts[ix[4]] = E2;
  if (!at_start) pts[n - 3] = pts[n - 1];
  else memmove(pts + 1, pts + 3, (size_t)(n - 3) * sizeof *pts);
  return n - 2;
}

/* A step inside a route: legs P-Q and R-S going the same way, joined by
 * Q-R under MIN_LEG across (randnet40_3's c17 -> k38 stepped 5 pt down to
 * pass below an arrowhead, issue 31). Either leg moves across by the step
 * onto the other's line: P-Q (the leg O-P before it stretching or
 * shrinking at P) or R-S (S-T after it at S), each neighbour keeping its
 * way and MIN_LEG (the arrow's leg 10), no branch of the source on a leg
 * that moves or at a corner that moves, where the one straight leg left
 * crosses and passes nothing the legs did not: Q and R dropped. Q is
 * pts[i]; as in nudge_segment, no segment before `first` moves and none
 * before first - 1 stretches. Returns the new number of points. */
static int unstep_mid(bg_router *r, int route, bg_vec *pts, int n, int i, int first) {
  const struct routed *rt = &r->route[route];
  if (i < 2 || i + 3 >= n) return n; /* a step by an end is unstep_end's */
  bg_vec P = pts[i - 1], Q = pts[i], R = pts[i + 1], S = pts[i + 2];
  if (!small_step(P, Q, R, S)) return n;
  bg_vec a = bg_vsub(Q, P), b = bg_vsub(R, Q);
  double la = bg_vlen(a), best = INFINITY;
  int choice = -1, segs[2][4];
  bg_vec line[4], keep[4], feet[MAX_FEET];
  for (int opt = 0; opt < 2; opt++) {
    /* the points O P Q R S T from lo, the four index segments from lo */
    int lo = opt ? i - 1 : i - 2, *seg = segs[opt];
    if (lo < first - 1) continue;
    int ok = 1;
    for (int k = 0; k < 4 && ok; k++) ok = (seg[k] = index_segment(r, route, pts[lo + k], pts[lo + k + 1])) >= 0;
    if (!ok) continue;
    /* the neighbour that stretches (k 0 for P-Q, 3 for R-S), the legs that move */
    int nb = opt ? 3 : 0;
    bg_vec far = opt ? pts[lo + 4] : pts[lo], corner = opt ? S : P, moved = opt ? bg_vsub(S, b) : bg_vadd(P, b);
    bg_vec o = bg_vsub(corner, far), o2 = bg_vsub(moved, far);
    double least = opt && lo + 4 == n - 1 ? 10 : MIN_LEG;
    if (bg_vlen(o) <= 0 || o.x * o2.x + o.y * o2.y <= 0 || bg_vlen(o2) < least || fabs(o.x * a.x + o.y * a.y) > 0.01 * bg_vlen(o) * la)
      continue; /* the neighbour at right angles, keeping its way */
    for (int k = 0; k < 4 && ok; k++) {
      int stays = opt ? k == 0 : k == 3; /* the leg that keeps its line */
      if (stays) continue;
      if (k == nb) {
        int nf = branch_feet(r, r->ix.sa[seg[k]], r->ix.sb[seg[k]], &corner, rt->group, route, feet);
        for (int f = 0; nf > 0 && f < nf; f++) ok &= bg_point_seg(feet[f], far, moved) < 0.01;
        ok &= nf >= 0;
      } else
        ok &= branch_feet(r, r->ix.sa[seg[k]], r->ix.sb[seg[k]], NULL, rt->group, route, feet) == 0;
    }
    if (!ok) continue;
    bg_vec old[5], now[3];
    for (int k = 0; k < 5; k++) old[k] = pts[lo + k];
    if (opt) now[0] = P, now[1] = moved, now[2] = pts[lo + 4];
    else now[0] = pts[lo], now[1] = moved, now[2] = S;
    park(r, seg, 4, keep);
    double pen = bg_route_path_penalty(r, now, 2), pen0 = bg_route_path_penalty(r, old, 4);
    unpark(r, seg, 4, keep);
    if (pen <= pen0 + 0.01 && pen < best) best = pen, choice = opt, memcpy(line, now, sizeof now);
  }
  if (choice < 0) return n;
  const int *seg = segs[choice];
  /* the index, each as the route runs: the stretched neighbour and the
   * straight leg, the other two left as points on it */
  if (choice) {
    bg_near_move_signal(&r->ix, seg[0], line[0], line[1]);
    bg_near_move_signal(&r->ix, seg[1], line[1], line[1]), bg_near_move_signal(&r->ix, seg[2], line[1], line[1]);
    bg_near_move_signal(&r->ix, seg[3], line[1], line[2]);
  } else {
    bg_near_move_signal(&r->ix, seg[0], line[0], line[1]), bg_near_move_signal(&r->ix, seg[1], line[1], line[2]);
    bg_near_move_signal(&r->ix, seg[2], line[2], line[2]), bg_near_move_signal(&r->ix, seg[3], line[2], line[2]);
    r->ix.slast[seg[1]] = r->ix.slast[seg[3]], r->ix.slast[seg[3]] = 0;
  }
  /* the points: Q and R dropped, the moved corner in place */
  pts[choice ? i + 2 : i - 1] = line[1];
  memmove(pts + i, pts + i + 2, (size_t)(n - i - 2) * sizeof *pts);
  return n - 2;
}

int bg_route_nudge(bg_router *r, int k, int first, bg_vec *pts, int *n) {
  if (k < 0 || k >= r->nroute || r->route[k].group < 0) return 0;
  const struct routed *rt = &r->route[k];
  r->from_node = rt->from, r->to_node = rt->to, r->group = rt->group, r->bond = -1;
  int moved = 0, before = *n;
  for (int i = first < 0 ? 0 : first; i + 1 < *n; i++) moved += nudge_segment(r, rt, pts, *n, i, first <= 0);
  *n = unstep_end(r, k, pts, *n, 0);
  if (first <= 0) *n = unstep_end(r, k, pts, *n, 1);
  for (int i = 2; i + 3 < *n; i++) *n = unstep_mid(r, k, pts, *n, i, first < 0 ? 0 : first);
  return moved + (before - *n) / 2;
}
