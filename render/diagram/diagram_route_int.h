/* SPDX-License-Identifier: BSD-3-Clause */
/* The router's insides, shared by the signal router (diagram_route.c) and
 * the bond router built on it (diagram_route_bonds.c); nothing else in the
 * diagram stage reads them (its interface is diagram_int.h's bg_router). */
#ifndef BG_DIAGRAM_ROUTE_INT_H
#define BG_DIAGRAM_ROUTE_INT_H

#include "diagram/diagram_int.h"

#define STUB 10.0 /* a port's straight run out of its box, to its grid vertex */

/* A uniform grid of cells over the layout, each listing the nodes whose box
 * (grown by 3 pt) and the bond legs whose bounding box meet it, so a query
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
  int *stamp, tick;
  /* routed signal segments: per cell a chain through sig_next */
  int *sig_head, *sig_next, *sig_seg, nsig, capsig;
  bg_vec *sa, *sb;
  int *sgrp; /* per segment: its signal's source (bg_route's group), -1 none;
                a routed bond b's: -2 - b (seg_cross_cost: dear when it is one of
                the current route's own) */
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
  int group;              /* the current route's source: routes of the same one may share
                             its lines (a signal branching), -1: none */
  int branch_k;           /* the last route's shared stretch (bg_route_branch) */
  bg_vec branch_at;
  /* every route so far (bg_route_detour): its segments in the index, ends, group */
  struct routed {
    int seg0, seg1, from, to, group;
  } *route;
  int nroute, caproute;
  int skip0, skip1, skip2; /* index segments of the current route (bg_route_detour): skip0
                              to skip1, and from skip2 on (INT_MAX: none) */
};

/* An end of a signal: where it leaves (or enters) a box, or a point on a bond. */
typedef struct port {
  bg_vec at;    /* on the box (or the bond) */
  bg_vec stub;  /* STUB pt out along the normal: a grid vertex */
  int dir;      /* the normal: 0 +x, 1 -x, 2 +y, 3 -y */
  double base;  /* of the port itself (a corner) */
  double cost;  /* and of its stub */
  int diag;     /* a bond's diagonal way out of a box whose sides are taken: at is stub */
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

/* The items (node k as k, leg j as nnode + j) in the cells the box meets. */
void bg_near_box(near_index *ix, double x0, double y0, double x1, double y1, near_list *out);
/* The cost of segment p-q against the nodes and legs near it (node skip's
 * box no obstacle). */
double bg_route_seg_cost(bg_router *r, bg_vec p, bg_vec q, int skip);
/* The cheapest route between ports ps and pt whose boxes are a and b (see
 * diagram_route.c), remembered for later routes; returns its points. */
int bg_route_ports(bg_router *r, port *ps, int nps, port *pt, int npt, const double a[4], const double b[4],
                   bg_vec *pts, int cap);

#endif
