/* SPDX-License-Identifier: BSD-3-Clause */
/* The signal router's parts (render/diagram/diagram_route_*.c), white-box:
 * the grid's lines are thinned to at most 72 a way for any candidates,
 * however many of them are ports' lines kept whole (before, more than 72
 * distinct port lines in one window looped for ever); and the detour pass
 * keeps its index equal to what it draws when two U's fall on one segment
 * (before, the first U's remainder stayed whole in the index, so later
 * detours paid for a line that is not drawn); a run beside a bond's
 * path and loop lines is priced (bg_router_rings); and a signal a few
 * points beside another source's is moved off it (bg_route_nudge), a
 * branch's foot on a neighbour moving with it; the detour pass takes a
 * segment's U's nearest first and knows its earlier U's on a second call;
 * a small step by a route's end is straightened (unstep_end), and one
 * inside a route (unstep_mid); and a route pays for passing through
 * another source's corner or across its arrowhead (touch_cost), and for
 * another's line across its own arrowhead (bg_route_tip_cost). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "analysis_fixture.h"
#include "figure_models.h"
#include "diagram/diagram_int.h"
#include "diagram/diagram_route_int.h"

enum { MAXL = 72 };

/* Sorted, at most 72, and every line within the candidates' range. */
static int lines_sane(const double *out, int m, double lo, double hi) {
  int ok = m >= 1 && m <= MAXL;
  for (int i = 0; i < m; i++) ok &= out[i] >= lo - 1e-9 && out[i] <= hi + 1e-9 && (i == 0 || out[i] > out[i - 1]);
  return ok;
}

static void test_axis_lines_bounded(void) {
  enum { N = 400 };
  double v[N], out[N + MAXL], gap = 0;
  unsigned char pr[N], op[N + MAXL];
  /* 64 ports' lines (today's most: 20 ports each end, 24 group lines)
   * among 300 lanes: every port's line kept exactly */
  for (int i = 0; i < 300; i++) v[i] = (i * 7919 % 300) * 0.37, pr[i] = 0;
  for (int i = 0; i < 64; i++) v[300 + i] = 3.3 + 1.5 * i, pr[300 + i] = 1;
  int m = bg_route_axis_lines(v, pr, 364, out, op, &gap);
  OK(lines_sane(out, m, 0, 299 * 0.37));
  int kept = 0;
  for (int i = 0; i < 64; i++)
    for (int j = 0; j < m; j++) kept += out[j] == v[300 + i] && op[j];
  INT_EQ(kept, 64);
  /* 100, then 400 ports' lines 1 pt apart, and 400 at one place but for
   * 0.02 pt: more than the grid holds, thinned all the same */
  for (int i = 0; i < N; i++) v[i] = i, pr[i] = 1;
  m = bg_route_axis_lines(v, pr, 100, out, op, &gap);
  OK(lines_sane(out, m, 0, 99));
  m = bg_route_axis_lines(v, pr, N, out, op, &gap);
  OK(lines_sane(out, m, 0, N - 1));
  OK(gap > 1);
  for (int i = 0; i < N; i++) v[i] = 10 + 0.02 * (i % 200), pr[i] = 1;
  m = bg_route_axis_lines(v, pr, N, out, op, &gap);
  OK(lines_sane(out, m, 10, 10 + 0.02 * 199));
  /* ports' lines and lanes mixed, the ports' many: a port's line wins
   * where they merge, so every line left is a port's */
  for (int i = 0; i < N; i++) v[i] = (i * 37 % N) * 0.5, pr[i] = i % 3 != 0;
  m = bg_route_axis_lines(v, pr, N, out, op, &gap);
  OK(lines_sane(out, m, 0, (N - 1) * 0.5));
  int ports = 0;
  for (int j = 0; j < m; j++) ports += op[j];
  OK(ports >= m - 1); /* the channels' middles merge into ports' lines too */
  /* no candidate: no line, no hang */
  INT_EQ(bg_route_axis_lines(v, pr, 0, out, op, &gap), 0);
}

/* Does the index hold segment a-b of group g (either way)? */
static int indexed(const bg_router *r, int g, bg_vec a, bg_vec b) {
  for (int s = 0; s < r->ix.nseg; s++) {
    if (r->ix.sgrp[s] != g) continue;
    bg_vec p = r->ix.sa[s], q = r->ix.sb[s];
    if ((bg_vlen(bg_vsub(p, a)) < 1e-6 && bg_vlen(bg_vsub(q, b)) < 1e-6) ||
        (bg_vlen(bg_vsub(p, b)) < 1e-6 && bg_vlen(bg_vsub(q, a)) < 1e-6))
      return 1;
  }
  return 0;
}

/* A four-section RC ladder (figure_models.h) compiled into f and drawn in
 * the default style: the layout the router tests run on. */
static bg_diagram *ladder_drawing(fx *f) {
  bg_strbuf src = {0};
  fm_ladder(&src, 4);
  OK(fm_load(f, "ladder4", bg_sb_str(&src)) == 0);
  bg_sb_free(&src);
  bg_render_opts o = {.style = "default", .style_dir = BG_SOURCE_DIR "/styles"};
  bg_diagram *d = bg_diagram_build(f->m, &f->a, &o, &f->dg);
  OK(d != NULL);
  return d;
}

/* The ladder's elements the detour tests go round (C0 and R1, above their
 * junctions n0 and s2) and the height between C0's box and n0's where a
 * line under them runs; 0 when the layout is not the one they are written
 * for. */
typedef struct ladder_row {
  int c0, r1, n0, s2;
  double y;
} ladder_row;

static int ladder_row_of(const bg_model *m, const bg_diagram_layout *L, ladder_row *w) {
  w->c0 = bg_model_find_elem(m, "C0"), w->r1 = bg_model_find_elem(m, "R1");
  w->n0 = bg_model_find_elem(m, "n0"), w->s2 = bg_model_find_elem(m, "s2");
  if (w->c0 < 0 || w->r1 < 0 || w->n0 < 0 || w->s2 < 0) return 0;
  w->y = (L->ny[w->c0] + L->nh[w->c0] / 2 + L->ny[w->n0] - L->nh[w->n0] / 2) / 2;
  return L->ny[w->c0] < L->ny[w->n0] - 20 && fabs(L->ny[w->r1] - L->ny[w->c0]) < 1 && L->nx[w->r1] > L->nx[w->c0] + 60;
}

/* Drawn and indexed segments of group g agree: every drawn segment in the
 * index, and no other live one (a U's remainder left whole besides). */
static void index_matches(const bg_router *r, int g, const bg_vec *pts, int n) {
  int drawn = 0, live = 0;
  for (int i = 0; i + 1 < n; i++) drawn += indexed(r, g, pts[i], pts[i + 1]);
  for (int s = 0; s < r->ix.nseg; s++) live += r->ix.sgrp[s] == g && bg_vlen(bg_vsub(r->ix.sa[s], r->ix.sb[s])) > 1e-9;
  INT_EQ(drawn, n - 1);
  INT_EQ(live, n - 1);
}

/* A signal router over d's layout whose routes are kept as group g's, with
 * no end nodes; *x0, *y0 (when given) a point clear of the figure, 100 pt
 * right of it at its top. */
static bg_router *router_for(const bg_diagram *d, const fx *f, int g, double *x0, double *y0) {
  bg_router *r = bg_router_new(d->L, f->m->nbond, NULL, 1);
  r->from_node = r->to_node = -1, r->bond = -1, r->group = g;
  if (x0) *x0 = r->fx1 + 100, *y0 = r->fy0;
  return r;
}

/* A straight route across two one-ports' bonds of an RC ladder (the R's
 * and C's above the junction row) goes round both; the index then holds
 * exactly the drawn segments of the route's group, none else. */
static void test_two_detours_on_one_segment(void) {
  fx f;
  bg_diagram *d = ladder_drawing(&f);
  const bg_diagram_layout *L = d->L;
  ladder_row w;
  OK(ladder_row_of(f.m, L, &w));
  bg_vec pts[16] = {bg_v(L->nx[w.c0] - 30, w.y), bg_v(L->nx[w.r1] + 30, w.y)};
  bg_router *r = bg_router_new(L, f.m->nbond, NULL, 1);
  const int g = 5;
  r->from_node = w.n0, r->to_node = w.s2, r->group = g, r->bond = -1;
  bg_route_keep(r, pts, 2);
  int n = bg_route_detour(r, 0, 0, pts, 2, 16);
  INT_EQ(n, 10); /* two U's of four points each */
  if (n == 10) {
    /* each U lies above its element's box */
    OK(pts[2].y < L->ny[w.c0] - L->nh[w.c0] / 2 && pts[6].y < L->ny[w.r1] - L->nh[w.r1] / 2);
    OK(pts[1].x < L->nx[w.c0] && pts[4].x > L->nx[w.c0] && pts[5].x < L->nx[w.r1] && pts[8].x > L->nx[w.r1]);
    index_matches(r, g, pts, n); /* not the first U's remainder whole besides */
    OK(!indexed(r, g, pts[4], pts[9]));
  }
  bg_router_free(r);
  bg_diagram_free(d);
  fx_free(&f);
}

/* A segment crossing two one-ports' bonds goes round both whichever way it
 * runs: the U nearest its start first, as the pass goes on along the rest
 * (right to left it took R1's U only when C0's bond came first in the
 * index's order and the part before it was passed over). A second call,
 * once a line on R1's U has moved (bg_route_nudge), takes that U too, on
 * the remainder the first call's U round C0 left, and cuts it in the index
 * (the index knows each segment's route; before, the first call's U's
 * were another line to the second, the remainder left whole beside the U). */
static void test_detours_nearest_first_and_again(void) {
  fx f;
  bg_diagram *d = ladder_drawing(&f);
  const bg_diagram_layout *L = d->L;
  ladder_row w;
  OK(ladder_row_of(f.m, L, &w));
  const int c0 = w.c0, r1 = w.r1, n0 = w.n0, s2 = w.s2, g = 5;
  const double y = w.y;
  { /* right to left */
    bg_vec pts[16] = {bg_v(L->nx[r1] + 30, y), bg_v(L->nx[c0] - 30, y)};
    bg_router *r = bg_router_new(L, f.m->nbond, NULL, 1);
    r->from_node = n0, r->to_node = s2, r->group = g, r->bond = -1;
    bg_route_keep(r, pts, 2);
    int n = bg_route_detour(r, 0, 0, pts, 2, 16);
    INT_EQ(n, 10);
    if (n == 10) {
      OK(pts[1].x > L->nx[r1] && pts[4].x < L->nx[r1] && pts[5].x > L->nx[c0] && pts[8].x < L->nx[c0]);
      index_matches(r, g, pts, n);
    }
    bg_router_free(r);
  }
  { /* left to right, R1's U first blocked by lines on its three tops */
    bg_vec pts[16] = {bg_v(L->nx[c0] - 30, y), bg_v(L->nx[r1] + 30, y)};
    bg_router *r = router_for(d, &f, 9, NULL, NULL);
    double top = L->ny[r1] - L->nh[r1] / 2;
    for (int k = 1; k <= 3; k++) {
      bg_vec line[2] = {bg_v(L->nx[r1] - 60, top - 3 * k), bg_v(L->nx[r1] + 60, top - 3 * k)};
      bg_route_keep(r, line, 2);
    }
    r->from_node = n0, r->to_node = s2, r->group = g;
    bg_route_keep(r, pts, 2);
    int n = bg_route_detour(r, 3, 0, pts, 2, 16);
    INT_EQ(n, 6); /* C0's U only */
    OK(n == 6 && pts[1].x < L->nx[c0] && pts[4].x > L->nx[c0]);
    for (int s = 0; s < r->ix.nseg; s++) /* the lines moved well clear */
      if (r->ix.sgrp[s] == 9) bg_near_move_signal(&r->ix, s, bg_vadd(r->ix.sa[s], bg_v(0, -200)), bg_vadd(r->ix.sb[s], bg_v(0, -200)));
    n = bg_route_detour(r, 3, 0, pts, n, 16);
    INT_EQ(n, 10);
    if (n == 10) {
      OK(pts[1].x < L->nx[c0] && pts[4].x > L->nx[c0] && pts[5].x < L->nx[r1] && pts[8].x > L->nx[r1]);
      index_matches(r, g, pts, n);
    }
    bg_router_free(r);
  }
  bg_diagram_free(d);
  fx_free(&f);
}

/* A run beside a bond with path and loop lines (bg_router_rings): among
 * them or within RING_NEAR of the outermost it costs COST_RING a point,
 * beyond that COST_HUG up to HUG past them (where the bond's number goes),
 * and nothing further out; without lines 13 pt off is free. */
static void test_runs_beside_rings(void) {
  fx f;
  bg_diagram *d = ladder_drawing(&f);
  const bg_diagram_layout *L = d->L;
  int b = -1; /* the longest level bond */
  double len = 0;
  for (int k = 0; k < f.m->nbond; k++) {
    bg_vec t = L->bg[k].tail, h = L->bg[k].head;
    if (L->bg[k].bendn == 0 && fabs(t.y - h.y) < 0.01 && fabs(h.x - t.x) > len) b = k, len = fabs(h.x - t.x);
  }
  OK(b >= 0 && len > 60);
  if (b >= 0) {
    double *ring = calloc((size_t)f.m->nbond, sizeof *ring), x0 = fmin(L->bg[b].tail.x, L->bg[b].head.x) + 20;
    ring[b] = 10;
    bg_router *r = bg_router_new(L, f.m->nbond, NULL, 1);
    r->from_node = r->to_node = r->group = r->bond = -1;
    double y = L->bg[b].tail.y, run = 30;
    /* the extra cost of a 30 pt run at `off` pt below the bond (nothing else is that near) */
#define EXTRA(off) (bg_route_seg_cost(r, bg_v(x0, y + (off)), bg_v(x0 + run, y + (off)), -1) - run)
    double bare = EXTRA(13);
    bg_router_rings(r, ring);
    double among = EXTRA(12), past = EXTRA(16), far = EXTRA(23);
#undef EXTRA
    OK(fabs(bare) < 1e-6);                    /* no lines: 13 pt off is free */
    OK(fabs(among - COST_RING * run) < 1e-6); /* 2 pt past the outermost line: beside it */
    OK(fabs(past - COST_HUG * run) < 1e-6);   /* past it, where the number goes */
    OK(fabs(far) < 1e-6);                     /* HUG past the lines: free */
    bg_router_free(r);
    free(ring);
  }
  bg_diagram_free(d);
  fx_free(&f);
}

/* Two signals of different sources 4 pt apart for 200 pt: the later
 * route's segment between two bends moves across, whole, to 6 pt off the
 * other (its neighbours stretch, its ends stay), and the index follows; a
 * route of the same source beside it stays (a branch runs off its trunk). */
static void test_nudge_apart(void) {
  fx f;
  bg_diagram *d = ladder_drawing(&f);
  if (d) {
    for (int same = 0; same < 2; same++) {
      double x0, y0;
      bg_router *r = router_for(d, &f, 7, &x0, &y0);
      bg_vec other[2] = {bg_v(x0 + 104, y0 - 50), bg_v(x0 + 104, y0 + 250)};
      bg_route_keep(r, other, 2);
      bg_vec pts[4] = {bg_v(x0, y0), bg_v(x0 + 100, y0), bg_v(x0 + 100, y0 + 200), bg_v(x0 + 200, y0 + 200)};
      r->group = same ? 7 : 3;
      bg_route_keep(r, pts, 4);
      int n = 4, moved = bg_route_nudge(r, 1, 0, pts, &n);
      if (same) {
        INT_EQ(moved, 0);
        OK(pts[1].x == x0 + 100);
      } else {
        INT_EQ(moved, 1);
        OK(fabs(pts[1].x - (x0 + 98)) < 1e-9 && fabs(pts[2].x - (x0 + 98)) < 1e-9); /* 6 pt off, away */
        OK(pts[1].y == y0 && pts[2].y == y0 + 200 && pts[0].x == x0 && pts[3].x == x0 + 200);
        OK(indexed(r, 3, pts[1], pts[2]) && indexed(r, 3, pts[0], pts[1]) && indexed(r, 3, pts[2], pts[3]));
      }
      bg_router_free(r);
    }
  }
  bg_diagram_free(d);
  fx_free(&f);
}

/* A branch of the route's source taken off a neighbour of the segment
 * moves nothing where its foot stays on the neighbour once stretched or
 * cut short: the segment moves (before, any branch on a neighbour held it,
 * as reactions20's c11 -> k4 beside c15 -> k16 for 97 pt); a foot on the
 * part a move away would cut off sends it past the other line instead (the
 * leg stretched), and one on the segment itself holds it. */
static void test_nudge_carries_branches(void) {
  fx f;
  bg_diagram *d = ladder_drawing(&f);
  if (d) {
    const double foot[3] = {50, 99, -1}; /* along the first leg; -1: on the segment */
    for (int c = 0; c < 3; c++) {
      double x0, y0;
      bg_router *r = router_for(d, &f, 7, &x0, &y0);
      bg_vec other[2] = {bg_v(x0 + 104, y0 - 50), bg_v(x0 + 104, y0 + 250)};
      bg_route_keep(r, other, 2);
      bg_vec pts[4] = {bg_v(x0, y0), bg_v(x0 + 100, y0), bg_v(x0 + 100, y0 + 200), bg_v(x0 + 200, y0 + 200)};
      r->group = 3;
      bg_route_keep(r, pts, 4);
      bg_vec at = foot[c] < 0 ? bg_v(x0 + 100, y0 + 80) : bg_v(x0 + foot[c], y0);
      bg_vec branch[2] = {at, foot[c] < 0 ? bg_vadd(at, bg_v(-60, 0)) : bg_vadd(at, bg_v(0, -60))};
      bg_route_keep(r, branch, 2);
      int n = 4, moved = bg_route_nudge(r, 1, 0, pts, &n);
      INT_EQ(moved, c < 2);
      OK(fabs(pts[1].x - (x0 + (c == 0 ? 98 : c == 1 ? 110 : 100))) < 1e-9 && pts[2].x == pts[1].x);
      OK(bg_point_seg(at, pts[0], pts[1]) < 1e-9 || c == 2); /* the foot on the leg still */
      bg_router_free(r);
    }
  }
  bg_diagram_free(d);
  fx_free(&f);
}

/* A step by a route's end (unstep_end): the arrow's leg 3 pt across from
 * the leg before it, both going down onto C0's top. Where the port may
 * slide along the top by 3 pt it does, and the route is one straight line;
 * where it may not (the port at the side's end), the leg before moves
 * across by 3 pt instead, the leg before that stretching. Before, both
 * were drawn with the step (tower_damper's I : m3 -> act, print and
 * slides). */
static void test_unstep_at_the_arrow(void) {
  fx f;
  bg_diagram *d = ladder_drawing(&f);
  const bg_diagram_layout *L = d->L;
  ladder_row w;
  OK(ladder_row_of(f.m, L, &w));
  double top = L->ny[w.c0] - L->nh[w.c0] / 2, tip = top - 1.5, edge = L->nx[w.c0] - (L->nw[w.c0] / 2 - L->st.node_pad - 1.5);
  for (int at_edge = 0; at_edge < 2; at_edge++) {
    bg_router *r = bg_router_new(L, f.m->nbond, NULL, 1);
    double x = at_edge ? edge : L->nx[w.c0] - 2, y0 = top - 160, y1 = top - 40;
    bg_vec pts[5] = {bg_v(x - 43, y0), bg_v(x - 3, y0), bg_v(x - 3, y1), bg_v(x, y1), bg_v(x, tip)};
    r->from_node = -1, r->to_node = w.c0, r->group = 3, r->bond = -1;
    bg_route_keep(r, pts, 5);
    int n = 5;
    bg_route_nudge(r, 0, 0, pts, &n);
    INT_EQ(n, 3);
    if (n == 3) {
      if (at_edge) /* the leg moved over to the port */
        OK(pts[0].x == x - 43 && pts[1].x == x && pts[1].y == y0 && pts[2].x == x && pts[2].y == tip);
      else /* the port slid under the leg */
        OK(pts[1].x == x - 3 && pts[1].y == y0 && pts[2].x == x - 3 && pts[2].y == tip);
      index_matches(r, 3, pts, n);
    }
    bg_router_free(r);
  }
  bg_diagram_free(d);
  fx_free(&f);
}

/* What a segment pays for touching another source's signal: an L from
 * (x0, y0) right 100 pt, then down 100 pt to its tip. Meeting its corner
 * end to end (the line carried on up from it) costs COST_TOUCH; crossing
 * its last leg 3 pt above the tip, through the arrowhead, COST_TOUCH more
 * than a crossing; in the leg's middle a crossing's COST_CROSS_SIGNAL only;
 * the same lines of the L's own source cost no touch. A route's own
 * arrowhead: a target stub whose last 7 pt another signal crosses pays
 * COST_TOUCH, one crossed 8 pt back nothing. */
static void test_touch_costs(void) {
  fx f;
  bg_diagram *d = ladder_drawing(&f);
  if (d) {
    double x0, y0;
    bg_router *r = router_for(d, &f, 7, &x0, &y0);
    bg_vec ell[3] = {bg_v(x0, y0), bg_v(x0 + 100, y0), bg_v(x0 + 100, y0 + 100)};
    bg_route_keep(r, ell, 3);
    for (int same = 0; same < 2; same++) {
      r->group = same ? 7 : 3;
#define EXTRA(ax, ay, bx, by) (bg_route_seg_cost(r, bg_v(ax, ay), bg_v(bx, by), -1) - hypot((bx) - (ax), (by) - (ay)))
      double end_to_end = EXTRA(x0 + 100, y0 - 60, x0 + 100, y0 - 1);
      double head = EXTRA(x0 + 50, y0 + 97, x0 + 150, y0 + 97), middle = EXTRA(x0 + 50, y0 + 50, x0 + 150, y0 + 50);
#undef EXTRA
      OK(fabs(end_to_end - (same ? 0 : COST_TOUCH)) < 1e-6);
      OK(fabs(head - COST_CROSS_SIGNAL - (same ? 0 : COST_TOUCH)) < 1e-6);
      OK(fabs(middle - COST_CROSS_SIGNAL) < 1e-6);
    }
    r->group = 3;
    OK(fabs(bg_route_tip_cost(r, bg_v(x0 + 107, y0 + 50), bg_v(x0 + 97, y0 + 50)) - COST_TOUCH) < 1e-6);
    OK(fabs(bg_route_tip_cost(r, bg_v(x0 + 118, y0 + 50), bg_v(x0 + 108, y0 + 50))) < 1e-6);
    r->group = 7;
    OK(fabs(bg_route_tip_cost(r, bg_v(x0 + 107, y0 + 50), bg_v(x0 + 97, y0 + 50))) < 1e-6);
    bg_router_free(r);
  }
  bg_diagram_free(d);
  fx_free(&f);
}

/* A step inside a route (unstep_mid): legs at y0 and y0 + 5 joined by a
 * 5 pt leg. In the clear the leg before moves down onto the leg after's
 * line (the first leg stretching by 5 pt); where another source's line
 * below would be crossed, the leg after moves up instead (the last leg
 * stretching); the two corners of the step dropped, the index following. */
static void test_unstep_inside(void) {
  fx f;
  bg_diagram *d = ladder_drawing(&f);
  if (d) {
    for (int blocked = 0; blocked < 2; blocked++) {
      double x0, y0;
      bg_router *r = router_for(d, &f, 9, &x0, &y0);
      y0 += 100;
      bg_vec other[2] = {bg_v(x0 + 50, y0 + 2), bg_v(x0 + 50, y0 + 40)};
      if (blocked) bg_route_keep(r, other, 2);
      bg_vec pts[6] = {bg_v(x0, y0 - 60), bg_v(x0, y0), bg_v(x0 + 100, y0), bg_v(x0 + 100, y0 + 5),
                       bg_v(x0 + 200, y0 + 5), bg_v(x0 + 200, y0 + 100)};
      r->group = 3;
      bg_route_keep(r, pts, 6);
      int n = 6;
      bg_route_nudge(r, blocked, 0, pts, &n);
      INT_EQ(n, 4);
      if (n == 4) {
        OK(pts[0].x == x0 && pts[0].y == y0 - 60 && pts[3].x == x0 + 200 && pts[3].y == y0 + 100);
        if (blocked) /* the leg after moved up */
          OK(pts[1].x == x0 && pts[1].y == y0 && pts[2].x == x0 + 200 && pts[2].y == y0);
        else /* the leg before moved down */
          OK(pts[1].x == x0 && pts[1].y == y0 + 5 && pts[2].x == x0 + 200 && pts[2].y == y0 + 5);
        index_matches(r, 3, pts, n);
      }
      bg_router_free(r);
    }
  }
  bg_diagram_free(d);
  fx_free(&f);
}

int main(void) {
  test_axis_lines_bounded();
  test_two_detours_on_one_segment();
  test_runs_beside_rings();
  test_nudge_apart();
  test_detours_nearest_first_and_again();
  test_nudge_carries_branches();
  test_unstep_at_the_arrow();
  test_touch_costs();
  test_unstep_inside();
  return bg_t_done();
}
