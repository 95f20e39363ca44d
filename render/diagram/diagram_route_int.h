/* SPDX-License-Identifier: BSD-3-Clause */
/* The router's insides, shared by the signal router's files and the bond
 * router built on it (diagram_route_bonds.c); nothing else in the diagram
 * stage reads them (its interface is diagram_int.h's bg_router). The signal
 * router: diagram_route.c (the ports, the routes tried in turn, the router),
 * diagram_route_near.c (the near index), diagram_route_cost.c (what a
 * segment and the grid's edges cost), diagram_route_grid.c (the grid of
 * channel lines), diagram_route_search.c (the A* search over it),
 * diagram_route_branch.c (a route branching off its source's earlier ones),
 * diagram_route_detour.c (a U round a one-port instead of crossing its bond),
 * diagram_route_adjacent.c (crossings of one node's bonds, for the bond
 * router's second pass). */
#ifndef BG_DIAGRAM_ROUTE_INT_H
#define BG_DIAGRAM_ROUTE_INT_H

#include <limits.h>

#include "diagram/diagram_int.h"

#define STUB 10.0 /* a port's straight run out of its box, to its grid vertex */
/* Costs in points of line length. */
#define COST_BEND 14.0
#define COST_CROSS_BOND 160.0 /* a detour of 160 pt is better than a crossed bond */
#define COST_CROSS_OWN 480.0  /* a bond of the route's own end element: two lines out of one
                                 element never need to cross (a detour past two other bonds
                                 is better) */
#define COST_CROSS_SIGNAL 6.0
#define GROUP_FENCE INT_MIN /* near_index.sgrp of a frame's border (bg_route_fence) */
#define COST_SHARE 900.0      /* running on another signal: read as one line */
#define COST_TOUCH 120.0      /* (touch_cost) through another source's signal's corner or end, or
                                 across its arrowhead: read as one line turning into the other, a
                                 branch or a T, so which source feeds which arrow cannot be told */
#define TOUCH_NEAR 1.5        /* how near a corner or an end counts as through it */
#define TIP_ZONE (BG_SIGNAL_ARROW + 1.0) /* a route's last pt before its tip: its arrowhead and 1 pt */
#define COST_BLOCK 1e6       /* through a node box or along a bond: dearer than any detour */
#define COST_END 2000.0       /* (end_zone) a bond crossing another bond within END_NEAR pt of its
                                 end, inside or past it: read as that bond ending on it (a false
                                 T); dearer than a dozen crossings, yet not a block (a block sends
                                 the route round the whole figure) */
#define END_NEAR 1.5
#define COST_HUG 1.5          /* per pt beside a bond, nearer than HUG: read as a doubled bond */
#define COST_RING 4.0         /* per pt beside a bond with path or loop lines (bg_route_leg_hug):
                                 read as one of them */
#define HUG 12.0
#define RING_NEAR 3.5         /* a signal nearer a bond's outermost path or loop line runs beside it
                                 (the figures checker's "beside": 3 pt; bg_router_rings) */
#define RING_GAP 6.0          /* how far past a bond's outermost layer line a diagonal stub out of a
                                 corner ends (ring_escape) */
#define COST_CORNER 20.0      /* a port at a box's corner, not on a side */
#define COST_NUMBER 40.0      /* passing a bond's middle, where its number goes */
#define COST_OBLIQUE 2.5      /* times a crossing, for a slanted bond (not at a right angle) */
#define COST_AT_END 80.0      /* more for a crossing at a bond's end, among its half arrow or
                                 causal stroke (at_end_cost, arrow_zone): a few points along the
                                 bond cost less */
#define LANE 10.0             /* the channel lines' distance from a box */

/* A uniform grid of cells over the layout, each listing the nodes whose box
 * (grown by 3 pt) and the bond legs that pass within 1 pt of it, so a query
 * tests what is near a segment instead of every node and bond. Routed
 * signal segments are added as they are drawn (a list per cell). */
typedef struct near_index {
  double x0, y0, cell;
  int nx, ny;
  int *adr, *item; /* per cell (CSR): nodes k as k, legs as nnode + leg */
  int nnode, nleg;
  bg_vec *la, *lb; /* legs' ends */
  int *lbond;      /* legs' bonds */
  unsigned char *lmid; /* the leg holds its bond's middle (where the number goes) */
  bg_vec *mid;
  double *lpos, *llen; /* how far along its bond the leg starts, and the bond's length (at_end_cost) */
  int *stamp, tick;
  /* routed signal segments: per cell a chain through sig_next */
  int *sig_head, *sig_next, *sig_seg, nsig, capsig;
  bg_vec *sa, *sb;
  int *sgrp; /* per segment: its signal's source (bg_route's group), -1 none;
                a routed bond b's: -2 - b (seg_cross_cost: dear when it is one of
                the current route's own); a frame's border: GROUP_FENCE */
  int *sroute;          /* per segment: the route it is drawn for (bg_router's route[]), -1 none */
  unsigned char *slast; /* per segment: the last of its route (it ends in the arrowhead) */
  int nseg, capseg;
  int *seg_stamp, capstamp;
} near_index;

/* A query's answer: the items (or signal segments) found, each once. */
typedef struct near_list {
  int *k, n, cap;
} near_list;

typedef struct heap_entry {
  double f, g; /* estimate, cost so far */
  int s;       /* state */
} heap_entry;

struct bg_router {
  const bg_diagram_layout *L;
  /* per node past the elements (a box, an integrator, a detector): the
   * bonds drawn ending there, end_list[end_adr[n - nelem] ..] (NULL until
   * a port of such a node is first asked for) */
  int *end_adr, *end_list;
  near_index ix;
  near_list nl;
  double fx0, fy0, fx1, fy1; /* the figure's box */
  /* the current search */
  double *X, *Y;
  int nxl, nyl;
  unsigned char *prio_x, *prio_y;
  double *hcost, *vcost; /* per edge (grid_costs) */
  double *hv;            /* per vertex: the search's estimate, NAN until asked */
  double *g;
  int *parent;
  struct heap_entry *heap;
  int nheap, capheap;
  int cap_states, cap_lines;
  /* candidates */
  double *cx, *cy;
  unsigned char *cpx, *cpy;
  int ncx, ncy, capc;
  double gap;             /* the grid's lines: candidates nearer than this were merged */
  int from_node, to_node; /* their boxes are no obstacle to their own stubs (-1: none);
                             their bonds are the route's own (COST_CROSS_OWN) */
  int bond;               /* the bond being routed (bg_route_blocked_bonds), -1: a signal */
  int ends_clear;         /* bonds' ends kept clear (bg_router_new): signals, bonds routed again */
  const double *ring;     /* per bond: the reach of the layer lines beside it (bg_router_rings) */
  double ring_hug;        /* the largest bg_route_leg_hug over the rings */
  int end_zone;           /* a bond route pays COST_END within END_NEAR of another bond's end
                             (the repair of false T's, bg_route_blocked_bonds), else a crossing */
  int group;              /* the current route's source: a route may start off the earlier
                             routes of the same one (a signal branching), -1: none */
  int whole;              /* the current route is drawn whole, no branch (it ran on its
                             source's earlier routes again after leaving them) */
  int branch_k;           /* the last route's shared stretch (bg_route_branch) */
  int seeded;             /* the last search's route starts on its source's earlier routes
                             (seed_branches: a branch taken off them) */
  bg_vec branch_at;
  /* every route so far (bg_route_detour): its segments in the index, ends, group */
  struct routed {
    int seg0, seg1, from, to, group;
  } *route;
  int nroute, caproute;
  int own; /* the route whose index segments are the current route's own (bg_route_detour), -1 none */
};

/* An end of a signal: where it leaves (or enters) a box, or a point on a bond. */
typedef struct port {
  bg_vec at;    /* on the box (or the bond) */
  bg_vec stub;  /* STUB pt out along the normal: a grid vertex */
  int dir;      /* the normal: 0 +x, 1 -x, 2 +y, 3 -y */
  double base;  /* of the port itself (a corner) */
  double cost;  /* and of its stub */
  int diag;     /* 1: a bond's diagonal way out of a box whose sides are taken: at is stub;
                   2: a signal's diagonal stub out of a corner past the layer lines (ring_escape) */
} port;

static const bg_vec DIRV[4] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

/* The end of leg i of bond b's route (-1: its tail; bendn: its head). */
static inline bg_vec bg_route_leg_end(const bg_diagram_layout *L, int b, int i) {
  const bg_bond_geom *g = &L->bg[b];
  if (i < 0) return g->tail;
  return i == g->bendn ? g->head : bg_v(L->lay.bendx[g->bendadr + i], L->lay.bendy[g->bendadr + i]);
}

/* The node bond b's end (0 tail, 1 head) is drawn at: a collapsed box, a field's node. */
static inline int bg_route_end_node(const bg_diagram_layout *L, int b, int head) {
  int n = L->node_of[head ? L->m->bond_head[b] : L->m->bond_tail[b]];
  return L->rep ? L->rep[n] : n;
}

/* The near index (diagram_route_near.c). */
/* The cells r[0]..r[2] by r[1]..r[3] that box [x0,x1]×[y0,y1] meets, clamped to the grid. */
void bg_near_cells(const near_index *ix, double x0, double y0, double x1, double y1, int r[4]);
/* Whether node n is an obstacle: drawn, with a box. */
int bg_route_node_drawn(const bg_diagram_layout *L, int n);
/* Item k's box: node k's grown by 3 pt, or leg k - nnode's bounding box. */
void bg_near_item_box(const bg_diagram_layout *L, const near_index *ix, int k, double b[4]);
/* The index of the drawn nodes and the legs of bonds 0..nbond-1, but those
 * hidden or marked in skip (nullable); to_nodes: each bond's ends carried
 * on to its nodes' boxes (a signal router's). */
void bg_near_build(const bg_diagram_layout *L, int nbond, const unsigned char *skip, int to_nodes, near_index *ix);
void bg_near_free(near_index *ix);
/* The items (node k as k, leg j as nnode + j) in the cells the box meets. */
void bg_near_box(near_index *ix, double x0, double y0, double x1, double y1, near_list *out);
/* The routed signal segments listed in the cells box meets, each once. */
void bg_near_signals(near_index *ix, double x0, double y0, double x1, double y1, near_list *out);
/* A routed segment a-b added, of source group (sgrp), drawn for route
 * `route` (bg_router's route[]; -1 none: a fence, a bond's clearance). */
void bg_near_add_signal(near_index *ix, bg_vec a, bg_vec b, int group, int route);
/* The segment of route `route` that runs from a to b (within 1e-9 pt), of
 * those from index segment `from` on (the route's first: later ones are
 * its U's, bg_route_detour), or -1. */
int bg_near_route_segment(const near_index *ix, int from, int route, bg_vec a, bg_vec b);
/* Routed segment s moved to a-b (bg_route_nudge): its index entry keeps its
 * number, so a route's range of segments still holds it. */
void bg_near_move_signal(near_index *ix, int s, bg_vec a, bg_vec b);

/* What a route costs (diagram_route_cost.c). */
/* Segment p-q against segment a-b: 1 crossing, 2 on one line, 3 side by
 * side (*run: for how long), else 0 (in full at its definition). */
int bg_route_seg_meet(bg_vec p, bg_vec q, bg_vec a, bg_vec b, double near, double hug, double *run, int ends);
double bg_route_leg_hug(const bg_router *r, int leg);
/* What the current route's `ends` argument is: 0 a signal, 1 a bond, 2 a bond in end_zone. */
static inline int bg_route_ends(const bg_router *r) { return r->bond < 0 ? 0 : r->end_zone ? 2 : 1; }
/* Whether index segment s is the current route's own (bg_route_detour). */
int bg_route_own_segment(const bg_router *r, int s);
/* The cost of segment p-q against the nodes and legs near it (node skip's
 * box no obstacle). */
double bg_route_seg_cost(bg_router *r, bg_vec p, bg_vec q, int skip);
/* What the polyline q[0..m] costs past its length (bg_route_seg_cost, no
 * box skipped: crossings, runs through boxes or beside bonds, a bond's
 * number or end passed). */
double bg_route_path_penalty(bg_router *r, const bg_vec *q, int m);
/* What a route ending at `at` from its target port's stub pays for the
 * other signals that cross its arrowhead (its last TIP_ZONE pt):
 * COST_TOUCH each (the later route's side of touch_cost). */
double bg_route_tip_cost(bg_router *r, bg_vec stub, bg_vec at);
/* Every edge of the grid's cost into r->hcost and r->vcost. */
void bg_route_grid_costs(bg_router *r);

/* The grid of channel lines (diagram_route_grid.c). */
/* Candidate lines x and y (NAN: none), a port's (prio) kept whole. */
void bg_route_add_cand(bg_router *r, double x, double y, int prio);
/* The index of the line of the sorted a[0..n-1] nearest v. */
int bg_route_nearest_line(const double *a, int n, double v);
/* One axis's lines from n candidates v (pr: a port's, kept whole while at
 * most MAXLINES = 72 lines remain), merged and thinned to at most 72 with
 * the channels' middles added, sorted, into out (room for n + 72; oprio:
 * which are ports'); *gap_used the merging gap. Ends for any input. */
int bg_route_axis_lines(const double *v, const unsigned char *pr, int n, double *out, unsigned char *oprio,
                        double *gap_used);
/* The lanes beside every node box in window [wx0,wx1]×[wy0,wy1] as candidate lines. */
void bg_route_add_lanes(bg_router *r, double wx0, double wy0, double wx1, double wy1);
/* The grid's lines r->X, r->Y from the candidates (r->gap: the gap used). */
void bg_route_make_lines(bg_router *r);
/* The ports' lines as the first candidates. */
void bg_route_add_ports(bg_router *r, const port *ps, int nps, const port *pt, int npt);
/* The grid over window [wx0,wx1]×[wy0,wy1]. */
void bg_route_build_grid(bg_router *r, double wx0, double wy0, double wx1, double wy1, const port *ps, int nps,
                         const port *pt, int npt);
/* The ports' stubs snapped onto the grid's lines. */
void bg_route_snap_ports(const bg_router *r, port *p, int n);

/* The search (diagram_route_search.c): the cheapest route over the grid of
 * window [wx0,wx1]×[wy0,wy1], or round the outside of the figure (a and b:
 * the ends' boxes); 0 points when the grid's lines were merged more than
 * max_gap apart. Returns the number of points, *cost the route's cost. */
int bg_route_in_window(bg_router *r, port *ps, int nps, port *pt, int npt, double wx0, double wy0, double wx1,
                       double wy1, double max_gap, bg_vec *pts, int cap, double *cost);
int bg_route_outside(bg_router *r, port *ps, int nps, port *pt, int npt, const double a[4], const double b[4],
                     bg_vec *pts, int cap, double *cost);

/* A route branching off its source's earlier routes (diagram_route_branch.c). */
/* Whether segment p-q runs on an earlier route of the current source. */
int bg_route_group_runs_on(bg_router *r, bg_vec p, bg_vec q);
/* Whether route pts[0..n-1], after it leaves them (k, at), runs on them again. */
int bg_route_group_rejoins(bg_router *r, const bg_vec *pts, int n, int k, bg_vec at);
/* Where route pts[0..n-1] leaves them: the segment k, the point *at; -1: it is drawn whole. */
int bg_route_shared_prefix(bg_router *r, const bg_vec *pts, int n, bg_vec *at);
/* The point of the current source's earlier routes nearest c, within a
 * few cells of the near index: 1 and *out, else 0. */
int bg_route_group_nearest(bg_router *r, bg_vec c, bg_vec *out);

/* Crossings of two bonds of one node (diagram_route_adjacent.c). */
/* What the bond router's second pass does to a bond (todo[] below). */
enum { BG_KEEP, BG_ROUTE, BG_STRAIGHTEN };
/* The pairs of bonds of one node that cross as the layout draws them;
 * todo (nullable): of each pair, a slanted straight bond not routed
 * (route[] 0) marked BG_ROUTE, its partner with corners BG_STRAIGHTEN. */
int bg_route_adjacent_crossings(const bg_diagram_layout *L, const unsigned char *route, unsigned char *todo);
/* The pairs of crossing bonds as drawn of which one is marked in changed
 * (a pair on one line counted as 1 000). */
int bg_route_crossings_of(const bg_diagram_layout *L, const unsigned char *changed);

/* The cheapest route between ports ps and pt whose boxes are a and b (see
 * diagram_route.c), remembered for later routes; returns its points. */
int bg_route_ports(bg_router *r, port *ps, int nps, port *pt, int npt, const double a[4], const double b[4],
                   bg_vec *pts, int cap);
/* Remembers route pts[0..n-1] (from r->from_node to r->to_node, of
 * r->group, or bond r->bond's) in the index, so later routes keep off it,
 * and among the routes bg_route_detour takes. */
void bg_route_keep(bg_router *r, const bg_vec *pts, int n);

#endif
