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
 * (route_outside); so the search never fails, and a route is never drawn
 * through a node unless the figure leaves no gap at all.
 *
 * Work is bounded per signal: the grid has at most MAXLINES lines each way
 * (the window's candidates thinned evenly), and what an edge meets is
 * looked up in a uniform grid of cells over the layout (the near index), so
 * routing the signals of a figure stays linear in their number. */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_route_int.h"

enum { MAXLINES = 72 };
/* Costs in points of line length. */
#define COST_BEND 14.0
#define COST_CROSS_BOND 160.0 /* a detour of 160 pt is better than a crossed bond */
#define COST_CROSS_OWN 480.0  /* a bond of the route's own end element: two lines out of one
                                 element never need to cross (a detour past two other bonds
                                 is better) */
#define COST_CROSS_SIGNAL 6.0
#define COST_SHARE 900.0      /* running on another signal: read as one line */
#define COST_BLOCK 1e6       /* through a node box or along a bond: dearer than any detour */
#define COST_HUG 1.5          /* per pt beside a bond, nearer than HUG: read as a doubled bond */
#define COST_CORNER 20.0      /* a port at a box's corner, not on a side */
#define COST_NUMBER 40.0      /* passing a bond's middle, where its number goes */
#define COST_OBLIQUE 2.5      /* times a crossing, for a slanted bond (not at a right angle) */
#define LANE 10.0             /* the channel lines' distance from a box */
/* The whole figure's grid is searched only where thinning it to MAXLINES
 * merged no candidate lines further apart than this: a coarser grid's
 * lines run through the boxes (the 1 000-signal network's whole-figure
 * searches merged lines up to 80 pt apart and found a way for 3 % of its
 * boxed-in signals, at six times a window's work). */
#define FALLBACK_GAP (4 * LANE)             /* the straight run off a port, and onto one */

/* ---------------------------------------------------------------- the near index */

static void cell_range(const near_index *ix, double x0, double y0, double x1, double y1, int r[4]) {
  r[0] = (int)floor((x0 - ix->x0) / ix->cell), r[1] = (int)floor((y0 - ix->y0) / ix->cell);
  r[2] = (int)floor((x1 - ix->x0) / ix->cell), r[3] = (int)floor((y1 - ix->y0) / ix->cell);
  r[0] = r[0] < 0 ? 0 : r[0] >= ix->nx ? ix->nx - 1 : r[0];
  r[2] = r[2] < 0 ? 0 : r[2] >= ix->nx ? ix->nx - 1 : r[2];
  r[1] = r[1] < 0 ? 0 : r[1] >= ix->ny ? ix->ny - 1 : r[1];
  r[3] = r[3] < 0 ? 0 : r[3] >= ix->ny ? ix->ny - 1 : r[3];
}

/* Whether node n is an obstacle: drawn, with a box. */
static int node_drawn(const bg_diagram_layout *L, int n) {
  return bg_node_shown(L, n) && !bg_fields_hidden(L, n) && L->nw[n] > 0 && L->nh[n] > 0;
}

static void item_box(const bg_diagram_layout *L, const near_index *ix, int k, double b[4]) {
  if (k < L->nnode) {
    b[0] = L->nx[k] - L->nw[k] / 2 - 3, b[1] = L->ny[k] - L->nh[k] / 2 - 3;
    b[2] = L->nx[k] + L->nw[k] / 2 + 3, b[3] = L->ny[k] + L->nh[k] / 2 + 3;
    return;
  }
  bg_vec a = ix->la[k - L->nnode], c = ix->lb[k - L->nnode];
  b[0] = fmin(a.x, c.x), b[1] = fmin(a.y, c.y), b[2] = fmax(a.x, c.x), b[3] = fmax(a.y, c.y);
}

/* Whether bond b's legs are left out of the index: hidden in a collapsed
 * box, or about to be routed again (skip, nullable). */
static int leg_skipped(const bg_diagram_layout *L, const unsigned char *skip, int b) {
  return (L->bond_hidden && L->bond_hidden[b]) || (skip && skip[b]);
}

static void near_build(const bg_diagram_layout *L, int nbond, const unsigned char *skip, near_index *ix) {
  memset(ix, 0, sizeof *ix);
  ix->nnode = L->nnode;
  for (int b = 0; b < nbond; b++) ix->nleg += leg_skipped(L, skip, b) ? 0 : L->bg[b].bendn + 1;
  ix->la = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->la), ix->lb = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->lb);
  ix->lmid = bg_xcalloc((size_t)ix->nleg + 1, 1), ix->mid = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->mid);
  ix->lbond = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->lbond);
  for (int b = 0, k = 0; b < nbond; b++) {
    for (int i = 0; !leg_skipped(L, skip, b) && i <= L->bg[b].bendn; i++, k++) {
      ix->lbond[k] = b;
      ix->la[k] = bg_route_leg_end(L, b, i - 1), ix->lb[k] = bg_route_leg_end(L, b, i), ix->mid[k] = L->bg[b].mid;
      double dx = ix->lb[k].x - ix->la[k].x, dy = ix->lb[k].y - ix->la[k].y, l2 = dx * dx + dy * dy;
      double t = l2 > 0 ? ((L->bg[b].mid.x - ix->la[k].x) * dx + (L->bg[b].mid.y - ix->la[k].y) * dy) / l2 : 0;
      t = t < 0 ? 0 : t > 1 ? 1 : t;
      bg_vec f = bg_v(ix->la[k].x + t * dx, ix->la[k].y + t * dy);
      ix->lmid[k] = bg_vlen(bg_vsub(f, L->bg[b].mid)) < 0.5;
    }
  }
  int nitem = L->nnode + ix->nleg;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, area = 0;
  for (int k = 0; k < nitem; k++) {
    if (k < L->nnode && !node_drawn(L, k)) continue;
    double bx[4];
    item_box(L, ix, k, bx);
    x0 = fmin(x0, bx[0]), y0 = fmin(y0, bx[1]), x1 = fmax(x1, bx[2]), y1 = fmax(y1, bx[3]);
    if (k < L->nnode) area += (bx[2] - bx[0]) * (bx[3] - bx[1]);
  }
  if (x0 > x1) x0 = y0 = 0, x1 = y1 = 1;
  /* cells about twice a node's size, at most four per item */
  ix->cell = fmax(8, 2 * sqrt(area / (L->nnode + 1)));
  ix->cell = fmax(ix->cell, sqrt((x1 - x0) * (y1 - y0) / (4.0 * nitem + 4)));
  ix->x0 = x0, ix->y0 = y0;
  ix->nx = (int)((x1 - x0) / ix->cell) + 1, ix->ny = (int)((y1 - y0) / ix->cell) + 1;
  size_t ncell = (size_t)ix->nx * (size_t)ix->ny;
  ix->adr = bg_xcalloc(ncell + 1, sizeof *ix->adr);
  for (int pass = 0; pass < 2; pass++) {
    int *fill = pass ? bg_xcalloc(ncell + 1, sizeof *fill) : NULL;
    for (int k = 0; k < nitem; k++) {
      if (k < L->nnode && !node_drawn(L, k)) continue;
      double bx[4];
      int r[4];
      item_box(L, ix, k, bx);
      cell_range(ix, bx[0], bx[1], bx[2], bx[3], r);
      for (int cy = r[1]; cy <= r[3]; cy++)
        for (int cx = r[0]; cx <= r[2]; cx++) {
          size_t c = (size_t)cy * (size_t)ix->nx + (size_t)cx;
          if (pass) ix->item[ix->adr[c] + fill[c]++] = k;
          else ix->adr[c + 1]++;
        }
    }
    if (!pass) {
      for (size_t c = 0; c < ncell; c++) ix->adr[c + 1] += ix->adr[c];
      ix->item = bg_xcalloc((size_t)ix->adr[ncell] + 1, sizeof *ix->item);
    }
    free(fill);
  }
  ix->stamp = bg_xcalloc((size_t)nitem + 1, sizeof *ix->stamp);
  ix->sig_head = bg_xcalloc(ncell + 1, sizeof *ix->sig_head);
  for (size_t c = 0; c <= ncell; c++) ix->sig_head[c] = -1;
}

static void near_free(near_index *ix) {
  free(ix->adr), free(ix->item), free(ix->la), free(ix->lb), free(ix->lbond), free(ix->lmid), free(ix->mid), free(ix->stamp);
  free(ix->sig_head), free(ix->sig_next), free(ix->sig_seg), free(ix->sa), free(ix->sb), free(ix->sgrp), free(ix->seg_stamp);
}


void bg_near_box(near_index *ix, double x0, double y0, double x1, double y1, near_list *out) {
  int r[4];
  cell_range(ix, x0, y0, x1, y1, r);
  ix->tick++;
  out->n = 0;
  for (int cy = r[1]; cy <= r[3]; cy++)
    for (int cx = r[0]; cx <= r[2]; cx++) {
      size_t c = (size_t)cy * (size_t)ix->nx + (size_t)cx;
      for (int j = ix->adr[c]; j < ix->adr[c + 1]; j++) {
        int k = ix->item[j];
        if (ix->stamp[k] == ix->tick) continue;
        ix->stamp[k] = ix->tick;
        if (out->n == out->cap) out->cap = 2 * out->cap + 16, out->k = bg_xrealloc(out->k, (size_t)out->cap * sizeof *out->k);
        out->k[out->n++] = k;
      }
    }
}

/* The routed signal segments listed in the cells box meets, each once. */
static void near_signals(near_index *ix, double x0, double y0, double x1, double y1, near_list *out) {
  int r[4];
  cell_range(ix, x0, y0, x1, y1, r);
  out->n = 0;
  if (ix->capstamp < ix->nseg) {
    ix->seg_stamp = bg_xrealloc(ix->seg_stamp, (size_t)ix->capseg * sizeof *ix->seg_stamp);
    for (int s = ix->capstamp; s < ix->capseg; s++) ix->seg_stamp[s] = 0;
    ix->capstamp = ix->capseg;
  }
  ix->tick++;
  for (int cy = r[1]; cy <= r[3]; cy++)
    for (int cx = r[0]; cx <= r[2]; cx++)
      for (int j = ix->sig_head[(size_t)cy * (size_t)ix->nx + (size_t)cx]; j >= 0; j = ix->sig_next[j]) {
        int s = ix->sig_seg[j];
        if (ix->seg_stamp[s] == ix->tick) continue;
        ix->seg_stamp[s] = ix->tick;
        if (out->n == out->cap) out->cap = 2 * out->cap + 16, out->k = bg_xrealloc(out->k, (size_t)out->cap * sizeof *out->k);
        out->k[out->n++] = s;
      }
}

static void near_add_signal(near_index *ix, bg_vec a, bg_vec b, int group) {
  if (ix->nseg == ix->capseg) {
    ix->capseg = 2 * ix->capseg + 16;
    ix->sa = bg_xrealloc(ix->sa, (size_t)ix->capseg * sizeof *ix->sa);
    ix->sb = bg_xrealloc(ix->sb, (size_t)ix->capseg * sizeof *ix->sb);
    ix->sgrp = bg_xrealloc(ix->sgrp, (size_t)ix->capseg * sizeof *ix->sgrp);
  }
  int s = ix->nseg++;
  ix->sa[s] = a, ix->sb[s] = b, ix->sgrp[s] = group;
  int r[4];
  cell_range(ix, fmin(a.x, b.x), fmin(a.y, b.y), fmax(a.x, b.x), fmax(a.y, b.y), r);
  for (int cy = r[1]; cy <= r[3]; cy++)
    for (int cx = r[0]; cx <= r[2]; cx++) {
      if (ix->nsig == ix->capsig) {
        ix->capsig = 2 * ix->capsig + 16;
        ix->sig_next = bg_xrealloc(ix->sig_next, (size_t)ix->capsig * sizeof *ix->sig_next);
        ix->sig_seg = bg_xrealloc(ix->sig_seg, (size_t)ix->capsig * sizeof *ix->sig_seg);
      }
      size_t c = (size_t)cy * (size_t)ix->nx + (size_t)cx;
      ix->sig_seg[ix->nsig] = s, ix->sig_next[ix->nsig] = ix->sig_head[c], ix->sig_head[c] = ix->nsig++;
    }
}

/* ---------------------------------------------------------------- segment tests */
/* Segment p-q (axis-parallel, from the grid) against segment a-b: 1 when
 * they cross at a point inside a-b (not within 0.5 pt of its ends) and in
 * p-q's half-open extent [lower end, upper end), so a crossing at a grid
 * vertex counts for one edge only (ends: also through a-b's ends and
 * 0.5 pt past them, as a routed bond must not pass another bond's end:
 * it would read as that bond ending on it, a false T); 2 when they run on
 * one line (parallel, nearer than `near` pt, sharing more than 1 pt); 3
 * when they run side by side within HUG pt (*run: for how long); else 0. */
#define HUG 12.0
static int seg_meet(bg_vec p, bg_vec q, bg_vec a, bg_vec b, double near, double *run, int ends) {
  bg_vec u = bg_vsub(q, p), v = bg_vsub(b, a);
  double lu = bg_vlen(u), lv = bg_vlen(v);
  if (lu <= 0 || lv <= 0) return 0;
  double den = u.x * v.y - u.y * v.x;
  if (fabs(den) < 0.02 * lu * lv) { /* parallel: on one line? */
    double dist = fabs((a.x - p.x) * u.y - (a.y - p.y) * u.x) / lu;
    if (dist >= HUG) return 0;
    double t0 = ((a.x - p.x) * u.x + (a.y - p.y) * u.y) / lu, t1 = ((b.x - p.x) * u.x + (b.y - p.y) * u.y) / lu;
    double lo = fmax(0, fmin(t0, t1)), hi = fmin(lu, fmax(t0, t1));
    if (hi - lo <= 1) return 0;
    if (run) *run = hi - lo;
    return dist < near ? 2 : 3;
  }
  bg_vec w = bg_vsub(a, p);
  double t = (w.x * v.y - w.y * v.x) / den; /* along p-q */
  double s = (w.x * u.y - w.y * u.x) / den; /* along a-b */
  double keep = ends ? -0.5 : 0.5;
  if (s * lv < keep || (1 - s) * lv < keep) return 0;
  /* half-open along the grid edge, by coordinate: [min, max) */
  int forward = u.x > 0 || (u.x == 0 && u.y > 0);
  double tl = forward ? t : 1 - t;
  return tl >= 0 && tl < 1 ? 1 : 0;
}

/* ---------------------------------------------------------------- the router */


bg_router *bg_router_new(const bg_diagram_layout *L, int nbond, const unsigned char *skip) {
  bg_router *r = bg_xcalloc(1, sizeof *r);
  r->L = L, r->group = r->branch_k = r->bond = -1, r->skip2 = INT_MAX;
  near_build(L, nbond, skip, &r->ix);
  r->fx0 = r->fx1 = r->ix.x0, r->fy0 = r->fy1 = r->ix.y0;
  for (int k = 0; k < L->nnode; k++)
    if (node_drawn(L, k)) {
      double b[4];
      item_box(L, &r->ix, k, b);
      r->fx1 = fmax(r->fx1, b[2]), r->fy1 = fmax(r->fy1, b[3]);
    }
  for (int k = 0; k < r->ix.nleg; k++) {
    double b[4];
    item_box(L, &r->ix, L->nnode + k, b);
    r->fx1 = fmax(r->fx1, b[2]), r->fy1 = fmax(r->fy1, b[3]);
  }
  return r;
}

void bg_router_free(bg_router *r) {
  if (!r) return;
  near_free(&r->ix);
  free(r->nl.k), free(r->X), free(r->Y), free(r->prio_x), free(r->prio_y), free(r->hcost), free(r->vcost), free(r->hv);
  free(r->route), free(r->g), free(r->parent), free(r->heap), free(r->cx), free(r->cy), free(r->cpx), free(r->cpy);
  free(r);
}

static void add_cand(bg_router *r, double x, double y, int prio) {
  if (r->ncx == r->capc || r->ncy == r->capc) {
    r->capc = 2 * r->capc + 64;
    r->cx = bg_xrealloc(r->cx, (size_t)r->capc * sizeof *r->cx), r->cy = bg_xrealloc(r->cy, (size_t)r->capc * sizeof *r->cy);
    r->cpx = bg_xrealloc(r->cpx, (size_t)r->capc), r->cpy = bg_xrealloc(r->cpy, (size_t)r->capc);
  }
  if (!isnan(x)) r->cx[r->ncx] = x, r->cpx[r->ncx++] = (unsigned char)prio;
  if (!isnan(y)) r->cy[r->ncy] = y, r->cpy[r->ncy++] = (unsigned char)prio;
}

typedef struct cand {
  double v;
  int prio;
} cand;

static int cand_cmp(const void *a, const void *b) {
  const cand *p = a, *q = b;
  if (p->v != q->v) return p->v < q->v ? -1 : 1;
  return q->prio - p->prio;
}

/* Lines from sorted candidates: those nearer than `gap` to a kept one
 * dropped (a port's line is always kept), the gap grown until at most
 * MAXLINES remain (*gap_used). */
static int merge_lines(const cand *c, int n, double *out, unsigned char *oprio, double *gap_used) {
  int m = 0;
  for (double gap = 1.5;; gap *= 1.6) {
    m = 0;
    for (int i = 0; i < n; i++) {
      if (m && c[i].v - out[m - 1] < gap) {
        if (c[i].prio && !oprio[m - 1]) out[m - 1] = c[i].v, oprio[m - 1] = 1; /* the port's line wins */
        else if (c[i].prio && c[i].v - out[m - 1] >= 0.01) out[m] = c[i].v, oprio[m++] = 1;
        continue;
      }
      out[m] = c[i].v, oprio[m++] = (unsigned char)c[i].prio;
    }
    if (m <= MAXLINES) {
      *gap_used = gap;
      return m;
    }
  }
}

/* One axis of the grid (out must hold n + MAXLINES): the candidates'
 * lines, then again with the channels' middles between neighbouring lines
 * added. The candidates are sorted once; the middles come sorted and are
 * merged in. Returns the number of lines, *gap_used the final gap. */
static int axis_lines(const double *v, const unsigned char *pr, int n, double *out, unsigned char *oprio,
                      double *gap_used) {
  cand *c = bg_xcalloc((size_t)n + 1, sizeof *c), *all = bg_xcalloc((size_t)n + MAXLINES + 1, sizeof *all);
  for (int i = 0; i < n; i++) c[i] = (cand){v[i], pr[i]};
  qsort(c, (size_t)n, sizeof *c, cand_cmp);
  int m = merge_lines(c, n, out, oprio, gap_used), na = 0;
  for (int i = 0, k = 0; i < n || k + 1 < m;) { /* merge: candidates and middles, in cand_cmp's order */
    cand mid = k + 1 < m ? (cand){(out[k] + out[k + 1]) / 2, 0} : (cand){0, 0};
    if (k + 1 < m && (i == n || cand_cmp(&mid, &c[i]) < 0)) all[na++] = mid, k++;
    else all[na++] = c[i++];
  }
  m = merge_lines(all, na, out, oprio, gap_used);
  free(c), free(all);
  return m;
}

static int nearest_line(const double *a, int n, double v) {
  int lo = 0, hi = n - 1;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (a[mid] < v) lo = mid + 1;
    else hi = mid;
  }
  if (lo > 0 && fabs(a[lo - 1] - v) <= fabs(a[lo] - v)) lo--;
  return lo;
}

static double point_seg(bg_vec c, bg_vec p, bg_vec q) {
  bg_vec u = bg_vsub(q, p);
  double l2 = u.x * u.x + u.y * u.y, t = l2 > 0 ? ((c.x - p.x) * u.x + (c.y - p.y) * u.y) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return bg_vlen(bg_vsub(c, bg_vadd(p, bg_vscale(u, t))));
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

/* What crossing leg k of the near index costs the current route. */
static double leg_cross_cost(const bg_router *r, int leg) {
  bg_vec a = r->ix.la[leg], b = r->ix.lb[leg];
  int slanted = fmin(fabs(b.x - a.x), fabs(b.y - a.y)) > 0.09 * fmax(fabs(b.x - a.x), fabs(b.y - a.y));
  return (own_bond(r, r->ix.lbond[leg]) ? COST_CROSS_OWN : COST_CROSS_BOND) * (slanted ? COST_OBLIQUE : 1);
}

/* Whether index segment s is the current route's own (bg_route_detour:
 * its first segments and those it added since). */
static int own_segment(const bg_router *r, int s) {
  return (s >= r->skip0 && s < r->skip1) || s >= r->skip2;
}

/* What crossing routed segment s costs: a signal's, or a bond routed
 * before this one (group -2 - b), the route's own bond's dearest. */
static double seg_cross_cost(const bg_router *r, int s) {
  int g = r->ix.sgrp[s];
  return g <= -2 && own_bond(r, -2 - g) ? COST_CROSS_OWN : COST_CROSS_SIGNAL;
}

/* What a segment p-q costs: its length, and the penalties for what it meets. */
double bg_route_seg_cost(bg_router *r, bg_vec p, bg_vec q, int skip) {
  const bg_diagram_layout *L = r->L;
  double cost = bg_vlen(bg_vsub(q, p)), x0 = fmin(p.x, q.x), x1 = fmax(p.x, q.x), y0 = fmin(p.y, q.y), y1 = fmax(p.y, q.y);
  bg_near_box(&r->ix, x0 - 4, y0 - 4, x1 + 4, y1 + 4, &r->nl);
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
    int hit = seg_meet(p, q, r->ix.la[k - L->nnode], r->ix.lb[k - L->nnode], 3, &run, r->bond >= 0);
    if (hit == 1) cost += leg_cross_cost(r, k - L->nnode);
    cost += hit == 2 ? COST_BLOCK : hit == 3 ? COST_HUG * run : 0;
    if (r->ix.lmid[k - L->nnode] && point_seg(r->ix.mid[k - L->nnode], p, q) < 10) cost += COST_NUMBER;
  }
  near_signals(&r->ix, x0 - 4, y0 - 4, x1 + 4, y1 + 4, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int s = r->nl.k[j];
    if (r->group >= 0 && r->ix.sgrp[s] == r->group) continue; /* its own source's: a branch */
    if (own_segment(r, s)) continue;                           /* the route itself (bg_route_detour) */
    int hit = seg_meet(p, q, r->ix.sa[s], r->ix.sb[s], 3, NULL, 0);
    cost += hit == 1 ? seg_cross_cost(r, s) : hit == 2 ? COST_SHARE : 0;
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
 * open, as seg_meet counts it, ends as there); a parallel run within HUG pt adds to each
 * edge it shares more than 1 pt with `block` when nearer than 3 pt, else
 * `hug` per pt of the shared run. */
static void line_meet(const double *A, int n, int horiz, double at, bg_vec a, bg_vec b, double cross, double block,
                      double hug, int ends, double *out) {
  double va = along(b, horiz) - along(a, horiz), vc = across(b, horiz) - across(a, horiz);
  double lv = sqrt(va * va + vc * vc);
  if (lv <= 0) return;
  if (fabs(vc) < 0.02 * lv) { /* parallel: on one line? */
    double dist = fabs(across(a, horiz) - at);
    if (dist >= HUG || (dist >= 3 && hug <= 0)) return;
    double t0 = fmin(along(a, horiz), along(b, horiz)), t1 = fmax(along(a, horiz), along(b, horiz));
    int i0, i1;
    edge_range(A, n, t0, t1, &i0, &i1);
    for (int i = i0; i <= i1; i++) {
      double run = fmin(A[i + 1], t1) - fmax(A[i], t0);
      if (run > 1) out[i] += dist < 3 ? block : hug * run;
    }
    return;
  }
  double s = (at - across(a, horiz)) / vc, keep = ends ? -0.5 : 0.5;
  if (s * lv < keep || (1 - s) * lv < keep) return;
  int i = edge_at(A, n, along(a, horiz) + s * va);
  if (i >= 0) out[i] += cross;
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

/* What every edge of the grid costs, the same as seg_cost would say edge by
 * edge: the edges' lengths, then each item near the grid (from one query of
 * the near index over the whole window) added to the lines it comes near
 * and there to the edges it meets (found by bisection). One pass over the
 * window's items instead of a query per edge: an item is looked at once,
 * not once for every edge near it. hcost holds the horizontal lines' edges
 * (line j's edge i at j * nx + i), vcost the vertical ones' (line j's edge
 * i at j * ny + i). */
static void grid_costs(bg_router *r) {
  const bg_diagram_layout *L = r->L;
  const double *X = r->X, *Y = r->Y;
  int nx = r->nxl, ny = r->nyl;
  for (int j = 0; j < ny; j++)
    for (int i = 0; i + 1 < nx; i++) r->hcost[j * nx + i] = X[i + 1] - X[i];
  for (int j = 0; j < nx; j++)
    for (int i = 0; i + 1 < ny; i++) r->vcost[j * ny + i] = Y[i + 1] - Y[i];
  bg_near_box(&r->ix, X[0] - HUG, Y[0] - HUG, X[nx - 1] + HUG, Y[ny - 1] + HUG, &r->nl);
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
    double cross = leg_cross_cost(r, leg);
    line_range(Y, ny, fmin(a.y, b.y) - HUG, fmax(a.y, b.y) + HUG, &j0, &j1);
    for (int j = j0; j <= j1; j++) line_meet(X, nx, 1, Y[j], a, b, cross, COST_BLOCK, COST_HUG, r->bond >= 0, &r->hcost[j * nx]);
    line_range(X, nx, fmin(a.x, b.x) - HUG, fmax(a.x, b.x) + HUG, &j0, &j1);
    for (int j = j0; j <= j1; j++) line_meet(Y, ny, 0, X[j], a, b, cross, COST_BLOCK, COST_HUG, r->bond >= 0, &r->vcost[j * ny]);
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
  near_signals(&r->ix, X[0] - 3, Y[0] - 3, X[nx - 1] + 3, Y[ny - 1] + 3, &r->nl);
  for (int jj = 0; jj < r->nl.n; jj++) { /* routed signals: crossed, or run on (within 3 pt) */
    if (r->group >= 0 && r->ix.sgrp[r->nl.k[jj]] == r->group) continue; /* its own source's: a branch */
    bg_vec a = r->ix.sa[r->nl.k[jj]], b = r->ix.sb[r->nl.k[jj]];
    double cross = seg_cross_cost(r, r->nl.k[jj]);
    int j0, j1;
    line_range(Y, ny, fmin(a.y, b.y) - 3, fmax(a.y, b.y) + 3, &j0, &j1);
    for (int j = j0; j <= j1; j++) line_meet(X, nx, 1, Y[j], a, b, cross, COST_SHARE, 0, 0, &r->hcost[j * nx]);
    line_range(X, nx, fmin(a.x, b.x) - 3, fmax(a.x, b.x) + 3, &j0, &j1);
    for (int j = j0; j <= j1; j++) line_meet(Y, ny, 0, X[j], a, b, cross, COST_SHARE, 0, 0, &r->vcost[j * ny]);
  }
}



/* Whether a point of node n's box side is clear of the bonds that end there
 * (6 pt from a bond's end on the box). */
static int end_near(const bg_diagram_layout *L, const bg_model *m, int b, int n, bg_vec p) {
  if (L->bond_hidden && L->bond_hidden[b]) return 0;
  int t = m->bond_tail[b], h = m->bond_head[b];
  if (L->node_of) t = L->node_of[t], h = L->node_of[h];
  return (t == n && bg_vlen(bg_vsub(L->bg[b].tail, p)) < 6) || (h == n && bg_vlen(bg_vsub(L->bg[b].head, p)) < 6);
}

static int side_clear(const bg_diagram_layout *L, const bg_model *m, int n, bg_vec p) {
  if (n < m->nelem) { /* an element: its own bonds */
    for (int i = 0; i < m->elem_nbond[n]; i++)
      if (end_near(L, m, m->elem_bonds[m->elem_bondadr[n] + i], n, p)) return 0;
    return 1;
  }
  for (int b = 0; b < m->nbond; b++) /* a box or an integrator: any bond may end there */
    if (end_near(L, m, b, n, p)) return 0;
  return 1;
}

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
    for (int k = 0; k < 5; k++) { /* the middle, halfway to the corners, the corners */
      static const double frac[5] = {0, -0.5, 0.5, -1, 1};
      double off = frac[k] * half;
      if ((k == 1 || k == 2) && half < 8) continue;
      bg_vec at = dir < 2 ? bg_v(c.x + (dir == 0 ? hw : -hw), c.y + off) : bg_v(c.x + off, c.y + (dir == 2 ? hh : -hh));
      if (!side_clear(L, m, n, at)) continue;
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

/* ---------------------------------------------------------------- search */
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

/* The lanes beside every node box in window [wx0,wx1]×[wy0,wy1] as
 * candidate lines. */
static void add_lanes(bg_router *r, double wx0, double wy0, double wx1, double wy1) {
  const bg_diagram_layout *L = r->L;
  /* the nodes in the window's cells; in a window of more than 1 024 cells
   * those of every stride-th cell each way (the lines are thinned to
   * MAXLINES anyway), so the work per signal stays bounded */
  int cr[4];
  cell_range(&r->ix, wx0, wy0, wx1, wy1, cr);
  double ncell = (double)(cr[2] - cr[0] + 1) * (cr[3] - cr[1] + 1);
  int stride = ncell > 1024 ? (int)ceil(sqrt(ncell / 1024)) : 1;
  r->ix.tick++;
  r->nl.n = 0;
  for (int cy = cr[1]; cy <= cr[3]; cy += stride)
    for (int cx = cr[0]; cx <= cr[2]; cx += stride) {
      size_t c = (size_t)cy * (size_t)r->ix.nx + (size_t)cx;
      for (int j = r->ix.adr[c]; j < r->ix.adr[c + 1]; j++) {
        int k = r->ix.item[j];
        if (k >= L->nnode || r->ix.stamp[k] == r->ix.tick) continue;
        r->ix.stamp[k] = r->ix.tick;
        if (r->nl.n == r->nl.cap) r->nl.cap = 2 * r->nl.cap + 16, r->nl.k = bg_xrealloc(r->nl.k, (size_t)r->nl.cap * sizeof *r->nl.k);
        r->nl.k[r->nl.n++] = k;
      }
    }
  for (int j = 0; j < r->nl.n; j++) {
    int k = r->nl.k[j];
    double bx0 = L->nx[k] - L->nw[k] / 2, bx1 = L->nx[k] + L->nw[k] / 2;
    double by0 = L->ny[k] - L->nh[k] / 2, by1 = L->ny[k] + L->nh[k] / 2;
    if (bx1 < wx0 || bx0 > wx1 || by1 < wy0 || by0 > wy1) continue;
    add_cand(r, bx0 - LANE, by0 - LANE, 0), add_cand(r, bx1 + LANE, by1 + LANE, 0);
  }
}

/* The grid's lines from the candidates: sorted, merged, thinned to
 * MAXLINES each way, the channels' middles added (r->gap: the gap used). */
static void make_lines(bg_router *r) {
  if (r->cap_lines < r->ncx + r->ncy + 2 * MAXLINES) {
    r->cap_lines = 2 * (r->ncx + r->ncy) + 2 * MAXLINES;
    r->X = bg_xrealloc(r->X, (size_t)r->cap_lines * sizeof *r->X), r->Y = bg_xrealloc(r->Y, (size_t)r->cap_lines * sizeof *r->Y);
    r->prio_x = bg_xrealloc(r->prio_x, (size_t)r->cap_lines), r->prio_y = bg_xrealloc(r->prio_y, (size_t)r->cap_lines);
  }
  double gx = 0, gy = 0;
  r->nxl = axis_lines(r->cx, r->cpx, r->ncx, r->X, r->prio_x, &gx);
  r->nyl = axis_lines(r->cy, r->cpy, r->ncy, r->Y, r->prio_y, &gy);
  r->gap = fmax(gx, gy);
}

/* The ports' lines as candidates (a port's line is kept whole). */
static void add_ports(bg_router *r, const port *ps, int nps, const port *pt, int npt) {
  r->ncx = r->ncy = 0;
  for (int i = 0; i < nps; i++) add_cand(r, ps[i].stub.x, ps[i].stub.y, 1);
  for (int i = 0; i < npt; i++) add_cand(r, pt[i].stub.x, pt[i].stub.y, 1);
}

/* The lines of the earlier routes of the current route's source in the
 * window, kept whole like a port's (at most GROUP_LINES, the earliest:
 * the trunk nearest the source), so a route can run on them and branch
 * off. */
enum { GROUP_LINES = 24 };
static void add_group_lines(bg_router *r, double wx0, double wy0, double wx1, double wy1) {
  if (r->group < 0) return;
  near_signals(&r->ix, wx0, wy0, wx1, wy1, &r->nl);
  int added = 0;
  for (int j = 0; j < r->nl.n && added < GROUP_LINES; j++) {
    int s = r->nl.k[j];
    if (r->ix.sgrp[s] != r->group) continue;
    bg_vec a = r->ix.sa[s], b = r->ix.sb[s];
    if (fabs(a.y - b.y) < 1e-9) add_cand(r, NAN, a.y, 1), added++;
    else if (fabs(a.x - b.x) < 1e-9) add_cand(r, a.x, NAN, 1), added++;
  }
}

/* The grid over window [wx0,wx1]×[wy0,wy1]: the ports' lines, the lanes
 * beside every node box in it, the lines between neighbouring lanes, and a
 * ring round the window. */
static void build_grid(bg_router *r, double wx0, double wy0, double wx1, double wy1, const port *ps, int nps,
                       const port *pt, int npt) {
  add_ports(r, ps, nps, pt, npt);
  add_group_lines(r, wx0, wy0, wx1, wy1);
  add_cand(r, wx0, wy0, 0), add_cand(r, wx1, wy1, 0);
  add_lanes(r, wx0, wy0, wx1, wy1);
  make_lines(r);
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
  grid_costs(r);
  /* goal vertices: each target port's stub, entered along its inward normal */
  int *goal_dir = bg_xcalloc((size_t)nv, sizeof *goal_dir); /* bit mask of inward directions + 1 */
  double *goal_cost = bg_xcalloc((size_t)nv * 4, sizeof *goal_cost);
  int *goal_port = bg_xcalloc((size_t)nv * 4, sizeof *goal_port);
  for (int i = 0; i < npt; i++) {
    int gx = nearest_line(r->X, nx, pt[i].stub.x), gy = nearest_line(r->Y, ny, pt[i].stub.y), v = gy * nx + gx;
    int in = pt[i].dir ^ 1; /* travel toward the box: opposite the normal */
    if (!(goal_dir[v] & (1 << in)) || pt[i].cost < goal_cost[v * 4 + in])
      goal_dir[v] |= 1 << in, goal_cost[v * 4 + in] = pt[i].cost, goal_port[v * 4 + in] = i;
  }
  r->nheap = 0;
  for (int i = 0; i < nps; i++) {
    int gx = nearest_line(r->X, nx, ps[i].stub.x), gy = nearest_line(r->Y, ny, ps[i].stub.y);
    int s = 4 * (gy * nx + gx) + ps[i].dir;
    if (ps[i].cost < r->g[s]) r->g[s] = ps[i].cost, r->parent[s] = -2 - i, heap_push(r, s, ps[i].cost, ps[i].cost);
  }
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
        pts[n++] = ps[-2 - r->parent[s]].at;
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

/* Snaps the ports' stubs onto the grid lines they were merged into, moving
 * the port with them along its side. */
static void snap_ports(const bg_router *r, port *p, int n) {
  for (int i = 0; i < n; i++) {
    double x = r->X[nearest_line(r->X, r->nxl, p[i].stub.x)], y = r->Y[nearest_line(r->Y, r->nyl, p[i].stub.y)];
    if (p[i].dir < 2) p[i].at.y = y;
    else p[i].at.x = x;
    p[i].stub = bg_v(x, y);
    if (p[i].diag) p[i].at = p[i].stub;
  }
}

/* The search over the grid built (route_in, route_outside), refused when
 * its lines were merged more than max_gap apart. */
static int route_grid(bg_router *r, port *ps, int nps, port *pt, int npt, double max_gap, bg_vec *pts, int cap,
                      double *cost) {
  *cost = INFINITY;
  if (r->gap > max_gap) return 0;
  snap_ports(r, ps, nps), snap_ports(r, pt, npt);
  for (int i = 0; i < nps; i++) ps[i].cost = ps[i].base + bg_route_seg_cost(r, ps[i].at, ps[i].stub, r->from_node);
  for (int i = 0; i < npt; i++) pt[i].cost = pt[i].base + bg_route_seg_cost(r, pt[i].stub, pt[i].at, r->to_node);
  int n = 0;
  *cost = search(r, ps, nps, pt, npt, pts, cap, &n);
  return n;
}

static int route_in(bg_router *r, port *ps, int nps, port *pt, int npt, double wx0, double wy0, double wx1,
                    double wy1, double max_gap, bg_vec *pts, int cap, double *cost) {
  build_grid(r, wx0, wy0, wx1, wy1, ps, nps, pt, npt);
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
static int route_outside(bg_router *r, port *ps, int nps, port *pt, int npt, const double a[4], const double b[4],
                         bg_vec *pts, int cap, double *cost) {
  add_ports(r, ps, nps, pt, npt);
  add_cand(r, r->fx0 - OUT_RING, r->fy0 - OUT_RING, 0), add_cand(r, r->fx1 + OUT_RING, r->fy1 + OUT_RING, 0);
  add_lanes(r, a[0] - OUT_NEAR, a[1] - OUT_NEAR, a[2] + OUT_NEAR, a[3] + OUT_NEAR);
  add_lanes(r, b[0] - OUT_NEAR, b[1] - OUT_NEAR, b[2] + OUT_NEAR, b[3] + OUT_NEAR);
  make_lines(r);
  return route_grid(r, ps, nps, pt, npt, INFINITY, pts, cap, cost);
}

/* Whether p lies on bond b's line (within 0.5 pt), its half arrow not counted. */
static int on_bond(const bg_diagram_layout *L, int b, bg_vec p) {
  for (int i = 0; i <= L->bg[b].bendn; i++)
    if (point_seg(p, bg_route_leg_end(L, b, i - 1), bg_route_leg_end(L, b, i)) < 0.5) return 1;
  return 0;
}

/* How far along segment p-q, from p, the earlier routes of the current
 * route's source cover it (collinear, within 0.01 pt), in pt. */
static double group_reach(bg_router *r, bg_vec p, bg_vec q) {
  double len = bg_vlen(bg_vsub(q, p)), reach = 0;
  if (len <= 0) return 0;
  bg_vec u = bg_vscale(bg_vsub(q, p), 1 / len);
  near_signals(&r->ix, fmin(p.x, q.x) - 1, fmin(p.y, q.y) - 1, fmax(p.x, q.x) + 1, fmax(p.y, q.y) + 1, &r->nl);
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
static int group_runs_on(bg_router *r, bg_vec p, bg_vec q) {
  double len = bg_vlen(bg_vsub(q, p));
  if (len <= 1) return 0;
  bg_vec u = bg_vscale(bg_vsub(q, p), 1 / len);
  near_signals(&r->ix, fmin(p.x, q.x) - 1, fmin(p.y, q.y) - 1, fmax(p.x, q.x) + 1, fmax(p.y, q.y) + 1, &r->nl);
  for (int j = 0; j < r->nl.n; j++) {
    int s = r->nl.k[j];
    if (r->ix.sgrp[s] != r->group || own_segment(r, s)) continue;
    bg_vec a = bg_vsub(r->ix.sa[s], p), b = bg_vsub(r->ix.sb[s], p);
    if (fabs(a.x * u.y - a.y * u.x) > 0.01 || fabs(b.x * u.y - b.y * u.x) > 0.01) continue;
    double ta = a.x * u.x + a.y * u.y, tb = b.x * u.x + b.y * u.y;
    if (fmin(len, fmax(ta, tb)) - fmax(0, fmin(ta, tb)) > 1) return 1;
  }
  return 0;
}

/* Whether the route, after where it leaves its source's earlier routes
 * (k, at from shared_prefix; k -1: from its start), runs on them again:
 * then it cannot be drawn as a branch. */
static int group_rejoins(bg_router *r, const bg_vec *pts, int n, int k, bg_vec at) {
  if (r->group < 0) return 0;
  for (int i = k < 0 ? 0 : k; i + 1 < n; i++)
    if (group_runs_on(r, i == k ? at : pts[i], pts[i + 1])) return 1;
  return 0;
}

/* Where route pts[0..n-1] of the current source leaves the routes of that
 * source before it, when it starts on them (a signal branching off the
 * line of another from the same source, as block diagrams draw it): the
 * index k of the segment it leaves on and the point *at, or -1 when it
 * does not start on them or keeps on them to within 10 pt of its tip
 * (then it is drawn whole). */
static int shared_prefix(bg_router *r, const bg_vec *pts, int n, bg_vec *at) {
  if (r->group < 0 || n < 2) return -1;
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

/* ---------------------------------------------------------------- round a one-port */
/* A route that crosses the bond of a one-port (an element with this one
 * bond, so the bond leads nowhere else) at a right angle can go round the
 * one-port instead: a U off the crossing segment, along the bond past the
 * element's box (3, 6 or 9 pt clear), across and back (issue 31: crossings a
 * detour of bounded length avoids, tests/unit/figure_check.h
 * fc_avoidable). The search misses some (its lines lie LANE off the boxes,
 * its window ends, a bend costs); this takes those whose U adds at most
 * DETOUR_MAX pt, stays within the segment, and crosses no bond and no box. */
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
    if (e >= m->nelem || m->elem_nbond[e] != 1 || bg_route_end_node(L, b, head) != e || !node_drawn(L, e)) continue;
    if (bg_vlen(bg_vsub(near, end)) > 0.01 || e == r->from_node || e == r->to_node) continue;
    *w = bg_vunit(bg_vsub(near, far));
    return e;
  }
  return -1;
}

/* Segment pts[i]-pts[i+1] round one one-port whose bond it crosses: the U's
 * four points into u (returns 1), else 0. */
static int detour_segment(bg_router *r, const bg_vec *pts, int i, bg_vec u4[4]) {
  const bg_diagram_layout *L = r->L;
  bg_vec p = pts[i], q = pts[i + 1];
  double len = bg_vlen(bg_vsub(q, p));
  if (len <= 0 || (r->group >= 0 && group_runs_on(r, p, q))) return 0;
  bg_vec u = bg_vscale(bg_vsub(q, p), 1 / len);
  bg_near_box(&r->ix, fmin(p.x, q.x), fmin(p.y, q.y), fmax(p.x, q.x), fmax(p.y, q.y), &r->nl);
  int nk = r->nl.n, *legs = bg_xcalloc((size_t)nk + 1, sizeof *legs);
  for (int j = 0; j < nk; j++) legs[j] = r->nl.k[j];
  int found = 0;
  for (int j = 0; j < nk && !found; j++) {
    int leg = legs[j] - L->nnode;
    bg_vec w;
    if (leg < 0 || seg_meet(p, q, r->ix.la[leg], r->ix.lb[leg], 3, NULL, 0) != 1) continue;
    int e = leg_one_port(r, leg, &w);
    if (e < 0 || fabs(u.x * w.x + u.y * w.y) > 0.01 || (fabs(u.x) > 1e-9 && fabs(u.y) > 1e-9)) continue;
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
    for (int g = 0; g < 3 && !found; g++) { /* the nearest clear U first, off other lines */
      static const double gap[3] = {3, 6, 9};
      double d = depth + gap[g];
      if (t + a0 - gap[g] < 1 || t + a1 + gap[g] > len - 1 || 2 * d > DETOUR_MAX) continue;
      u4[0] = bg_vadd(X, bg_vscale(u, a0 - gap[g])), u4[3] = bg_vadd(X, bg_vscale(u, a1 + gap[g]));
      u4[1] = bg_vadd(u4[0], bg_vscale(w, d)), u4[2] = bg_vadd(u4[3], bg_vscale(w, d));
      double extra = 0;
      int group = r->group;
      r->group = -1; /* the U is no branch: its own source's other lines are in its way too */
      for (int k = 0; k < 3; k++) extra += bg_route_seg_cost(r, u4[k], u4[k + 1], -1) - bg_vlen(bg_vsub(u4[k + 1], u4[k]));
      r->group = group;
      found = extra < COST_CROSS_BOND / 2; /* no bond crossed, no box run through, no line run on */
    }
  }
  free(legs);
  return found;
}

int bg_route_detour(bg_router *r, int k, int first, bg_vec *pts, int n, int cap) {
  if (k < 0 || k >= r->nroute) return n;
  const struct routed *rt = &r->route[k];
  r->from_node = rt->from, r->to_node = rt->to, r->group = rt->group, r->bond = -1;
  r->skip0 = rt->seg0, r->skip1 = rt->seg1, r->skip2 = r->ix.nseg;
  for (int i = first < 0 ? 0 : first; i + 1 < n && n + 4 <= cap; i++) {
    bg_vec u4[4];
    if (!detour_segment(r, pts, i, u4)) continue;
    /* the index: the crossing segment cut short at the U, the rest added */
    for (int s = rt->seg0; s < rt->seg1; s++)
      if (bg_vlen(bg_vsub(r->ix.sa[s], pts[i])) < 1e-9 && bg_vlen(bg_vsub(r->ix.sb[s], pts[i + 1])) < 1e-9) {
        r->ix.sb[s] = u4[0];
        break;
      }
    for (int j = 0; j < 3; j++) near_add_signal(&r->ix, u4[j], u4[j + 1], rt->group);
    near_add_signal(&r->ix, u4[3], pts[i + 1], rt->group);
    memmove(pts + i + 5, pts + i + 1, (size_t)(n - i - 1) * sizeof *pts);
    memcpy(pts + i + 1, u4, sizeof u4);
    n += 4, i += 3; /* on with the rest of the crossing segment */
  }
  r->skip0 = r->skip1 = 0, r->skip2 = INT_MAX;
  return n;
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
  double wx0 = fmin(a[0], b[0]), wx1 = fmax(a[2], b[2]), wy0 = fmin(a[1], b[1]), wy1 = fmax(a[3], b[3]);
  double margin = 40 + 0.25 * fmax(wx1 - wx0, wy1 - wy0);
  double cost = INFINITY;
  int n = route_in(r, ps, nps, pt, npt, wx0 - margin, wy0 - margin, wx1 + margin, wy1 + margin, INFINITY, pts, cap,
                   &cost);
  if (!(cost < COST_BLOCK) && r->gap <= FALLBACK_GAP) {
    double c2 = INFINITY;
    bg_vec *alt = bg_xcalloc((size_t)cap, sizeof *alt);
    int n2 = route_in(r, ps, nps, pt, npt, r->fx0 - 2 * LANE, r->fy0 - 2 * LANE, r->fx1 + 2 * LANE,
                      r->fy1 + 2 * LANE, FALLBACK_GAP, alt, cap, &c2);
    if (n2 >= 2 && c2 < cost) memcpy(pts, alt, (size_t)n2 * sizeof *pts), n = n2, cost = c2;
    free(alt);
  }
  if (!(cost < COST_BLOCK)) {
    double c3 = INFINITY;
    bg_vec *alt = bg_xcalloc((size_t)cap, sizeof *alt);
    int n3 = route_outside(r, ps, nps, pt, npt, a, b, alt, cap, &c3);
    if (n3 >= 2 && c3 < cost) memcpy(pts, alt, (size_t)n3 * sizeof *pts), n = n3, cost = c3;
    free(alt);
  }
  if (n < 2) { /* no grid at all (cannot happen: the grid holds every port) */
    pts[0] = ps[0].at, pts[1] = pt[0].at;
    n = 2;
  }
  n = simplify(pts, n);
  r->branch_k = shared_prefix(r, pts, n, &r->branch_at);
  if (group_rejoins(r, pts, n, r->branch_k, r->branch_at)) { /* not a branch: again, keeping off them */
    r->group = -1;
    return bg_route_ports(r, ps, nps, pt, npt, a, b, pts, cap);
  }
  if (r->nroute == r->caproute) {
    r->caproute = 2 * r->caproute + 16;
    r->route = bg_xrealloc(r->route, (size_t)r->caproute * sizeof *r->route);
  }
  r->route[r->nroute++] = (struct routed){r->ix.nseg, r->ix.nseg + n - 1, r->from_node, r->to_node, r->group};
  for (int i = 0; i + 1 < n; i++) near_add_signal(&r->ix, pts[i], pts[i + 1], r->bond >= 0 ? -2 - r->bond : r->group);
  return n;
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
  port ps[20], pt[20];
  r->from_node = from_node, r->to_node = to, r->group = group, r->bond = -1;
  int nps = 0, npt = node_ports(r, m, to, 1.5, pt);
  if (from_node >= 0) {
    nps = node_ports(r, m, from_node, 0, ps);
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

int bg_route_branch(const bg_router *r, bg_vec *at) {
  if (r->branch_k >= 0) *at = r->branch_at;
  return r->branch_k;
}
