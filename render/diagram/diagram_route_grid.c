/* SPDX-License-Identifier: BSD-3-Clause */
/* The search's grid of channel lines: the candidate lines (the ports'
 * lines, the lanes beside the node boxes in a window, the lines of earlier
 * routes of the route's source, a ring round the window), sorted, merged
 * and thinned to at most MAXLINES each way with the channels' middles
 * added; and the ports snapped onto the lines they were merged into. */
#include <math.h>
#include <stdlib.h>

#include "diagram/diagram_route_int.h"

enum { MAXLINES = 72 };

void bg_route_add_cand(bg_router *r, double x, double y, int prio) {
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
 * MAXLINES remain (*gap_used). The ports' and the group's lines are at most
 * 2 * 20 + GROUP_LINES = 64 a way today, so keeping them whole always
 * ends; should more ever come, once the gap spans every candidate (no
 * larger gap changes anything) they are merged like the others, the gap
 * starting again, so the loop ends for any input (the result for every
 * input that ended before is unchanged). */
static int merge_lines(const cand *c, int n, double *out, unsigned char *oprio, double *gap_used) {
  double span = n ? c[n - 1].v - c[0].v : 0;
  int whole = 1; /* ports' lines kept whole */
  for (double gap = 1.5;; gap *= 1.6) {
    int m = 0;
    for (int i = 0; i < n; i++) {
      if (m && c[i].v - out[m - 1] < gap) {
        if (c[i].prio && !oprio[m - 1]) out[m - 1] = c[i].v, oprio[m - 1] = 1; /* the port's line wins */
        else if (whole && c[i].prio && c[i].v - out[m - 1] >= 0.01) out[m] = c[i].v, oprio[m++] = 1;
        continue;
      }
      out[m] = c[i].v, oprio[m++] = (unsigned char)c[i].prio;
    }
    if (m <= MAXLINES) {
      *gap_used = gap;
      return m;
    }
    if (whole && gap > span) whole = 0, gap = 1.5 / 1.6; /* more ports' lines than MAXLINES */
  }
}

/* One axis of the grid (out must hold n + MAXLINES): the candidates'
 * lines, then again with the channels' middles between neighbouring lines
 * added. The candidates are sorted once; the middles come sorted and are
 * merged in. Returns the number of lines, *gap_used the final gap. */
int bg_route_axis_lines(const double *v, const unsigned char *pr, int n, double *out, unsigned char *oprio,
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

int bg_route_nearest_line(const double *a, int n, double v) {
  int lo = 0, hi = n - 1;
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (a[mid] < v) lo = mid + 1;
    else hi = mid;
  }
  if (lo > 0 && fabs(a[lo - 1] - v) <= fabs(a[lo] - v)) lo--;
  return lo;
}

/* The lanes beside every node box in window [wx0,wx1]×[wy0,wy1] as
 * candidate lines, and with layer lines drawn (bg_router_rings) those
 * HUG past the outermost beside each axis-parallel bond (where a run beside
 * it is free: hug_cost). */
void bg_route_add_lanes(bg_router *r, double wx0, double wy0, double wx1, double wy1) {
  const bg_diagram_layout *L = r->L;
  /* the nodes in the window's cells; in a window of more than 1 024 cells
   * those of every stride-th cell each way (the lines are thinned to
   * MAXLINES anyway), so the work per signal stays bounded */
  int cr[4];
  bg_near_cells(&r->ix, wx0, wy0, wx1, wy1, cr);
  double ncell = (double)(cr[2] - cr[0] + 1) * (cr[3] - cr[1] + 1);
  int stride = ncell > 1024 ? (int)ceil(sqrt(ncell / 1024)) : 1;
  r->ix.tick++;
  r->nl.n = 0;
  for (int cy = cr[1]; cy <= cr[3]; cy += stride)
    for (int cx = cr[0]; cx <= cr[2]; cx += stride) {
      size_t c = (size_t)cy * (size_t)r->ix.nx + (size_t)cx;
      for (int j = r->ix.adr[c]; j < r->ix.adr[c + 1]; j++) {
        int k = r->ix.item[j];
        if ((k >= L->nnode && !r->ring) || r->ix.stamp[k] == r->ix.tick) continue;
        r->ix.stamp[k] = r->ix.tick;
        if (r->nl.n == r->nl.cap) r->nl.cap = 2 * r->nl.cap + 16, r->nl.k = bg_xrealloc(r->nl.k, (size_t)r->nl.cap * sizeof *r->nl.k);
        r->nl.k[r->nl.n++] = k;
      }
    }
  for (int j = 0; j < r->nl.n; j++) {
    int k = r->nl.k[j];
    if (k >= L->nnode) { /* an axis-parallel bond leg with layer lines: the lanes just past them */
      bg_vec a = r->ix.la[k - L->nnode], b = r->ix.lb[k - L->nnode];
      double ring = r->ring[r->ix.lbond[k - L->nnode]], out = ring + HUG;
      if (ring <= 0) continue;
      if (fabs(a.y - b.y) < 0.5) bg_route_add_cand(r, NAN, a.y - out, 0), bg_route_add_cand(r, NAN, a.y + out, 0);
      else if (fabs(a.x - b.x) < 0.5) bg_route_add_cand(r, a.x - out, NAN, 0), bg_route_add_cand(r, a.x + out, NAN, 0);
      continue;
    }
    double bx0 = L->nx[k] - L->nw[k] / 2, bx1 = L->nx[k] + L->nw[k] / 2;
    double by0 = L->ny[k] - L->nh[k] / 2, by1 = L->ny[k] + L->nh[k] / 2;
    if (bx1 < wx0 || bx0 > wx1 || by1 < wy0 || by0 > wy1) continue;
    bg_route_add_cand(r, bx0 - LANE, by0 - LANE, 0), bg_route_add_cand(r, bx1 + LANE, by1 + LANE, 0);
  }
}

/* The grid's lines from the candidates: sorted, merged, thinned to
 * MAXLINES each way, the channels' middles added (r->gap: the gap used). */
void bg_route_make_lines(bg_router *r) {
  if (r->cap_lines < r->ncx + r->ncy + 2 * MAXLINES) {
    r->cap_lines = 2 * (r->ncx + r->ncy) + 2 * MAXLINES;
    r->X = bg_xrealloc(r->X, (size_t)r->cap_lines * sizeof *r->X), r->Y = bg_xrealloc(r->Y, (size_t)r->cap_lines * sizeof *r->Y);
    r->prio_x = bg_xrealloc(r->prio_x, (size_t)r->cap_lines), r->prio_y = bg_xrealloc(r->prio_y, (size_t)r->cap_lines);
  }
  double gx = 0, gy = 0;
  r->nxl = bg_route_axis_lines(r->cx, r->cpx, r->ncx, r->X, r->prio_x, &gx);
  r->nyl = bg_route_axis_lines(r->cy, r->cpy, r->ncy, r->Y, r->prio_y, &gy);
  r->gap = fmax(gx, gy);
}

/* The ports' lines as candidates (a port's line is kept whole). */
void bg_route_add_ports(bg_router *r, const port *ps, int nps, const port *pt, int npt) {
  r->ncx = r->ncy = 0;
  for (int i = 0; i < nps; i++) bg_route_add_cand(r, ps[i].stub.x, ps[i].stub.y, 1);
  for (int i = 0; i < npt; i++) bg_route_add_cand(r, pt[i].stub.x, pt[i].stub.y, 1);
}

/* The lines of the earlier routes of the current route's source in the
 * window, kept whole like a port's (at most GROUP_LINES, the earliest:
 * the trunk nearest the source), so a route can run on them and branch
 * off. */
enum { GROUP_LINES = 24 };
static void add_group_lines(bg_router *r, double wx0, double wy0, double wx1, double wy1) {
  if (r->group < 0 || r->whole) return;
  bg_near_signals(&r->ix, wx0, wy0, wx1, wy1, &r->nl);
  int added = 0;
  for (int j = 0; j < r->nl.n && added < GROUP_LINES; j++) {
    int s = r->nl.k[j];
    if (r->ix.sgrp[s] != r->group) continue;
    bg_vec a = r->ix.sa[s], b = r->ix.sb[s];
    if (fabs(a.y - b.y) < 1e-9) bg_route_add_cand(r, NAN, a.y, 1), added++;
    else if (fabs(a.x - b.x) < 1e-9) bg_route_add_cand(r, a.x, NAN, 1), added++;
  }
}

/* The grid over window [wx0,wx1]×[wy0,wy1]: the ports' lines, the lanes
 * beside every node box in it, the lines between neighbouring lanes, and a
 * ring round the window. */
void bg_route_build_grid(bg_router *r, double wx0, double wy0, double wx1, double wy1, const port *ps, int nps,
                         const port *pt, int npt) {
  bg_route_add_ports(r, ps, nps, pt, npt);
  add_group_lines(r, wx0, wy0, wx1, wy1);
  bg_route_add_cand(r, wx0, wy0, 0), bg_route_add_cand(r, wx1, wy1, 0);
  bg_route_add_lanes(r, wx0, wy0, wx1, wy1);
  bg_route_make_lines(r);
}

/* Snaps the ports' stubs onto the grid lines they were merged into, moving
 * the port with them along its side. */
void bg_route_snap_ports(const bg_router *r, port *p, int n) {
  for (int i = 0; i < n; i++) {
    double x = r->X[bg_route_nearest_line(r->X, r->nxl, p[i].stub.x)], y = r->Y[bg_route_nearest_line(r->Y, r->nyl, p[i].stub.y)];
    if (p[i].diag == 2) { /* a diagonal stub: its port stays at the corner */
      p[i].stub = bg_v(x, y);
      continue;
    }
    if (p[i].dir < 2) p[i].at.y = y;
    else p[i].at.x = x;
    p[i].stub = bg_v(x, y);
    if (p[i].diag) p[i].at = p[i].stub;
  }
}
