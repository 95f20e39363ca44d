/* SPDX-License-Identifier: BSD-3-Clause */
/* The signal router's near index (diagram_route.c; its struct in
 * diagram_route_int.h): a uniform grid of cells over the layout listing the
 * node boxes and bond legs each cell meets, and the routed signal segments
 * as they are added, so a query finds what is near a segment or a grid
 * instead of testing every node, bond and route. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_route_int.h"

void bg_near_cells(const near_index *ix, double x0, double y0, double x1, double y1, int r[4]) {
  r[0] = (int)floor((x0 - ix->x0) / ix->cell), r[1] = (int)floor((y0 - ix->y0) / ix->cell);
  r[2] = (int)floor((x1 - ix->x0) / ix->cell), r[3] = (int)floor((y1 - ix->y0) / ix->cell);
  r[0] = r[0] < 0 ? 0 : r[0] >= ix->nx ? ix->nx - 1 : r[0];
  r[2] = r[2] < 0 ? 0 : r[2] >= ix->nx ? ix->nx - 1 : r[2];
  r[1] = r[1] < 0 ? 0 : r[1] >= ix->ny ? ix->ny - 1 : r[1];
  r[3] = r[3] < 0 ? 0 : r[3] >= ix->ny ? ix->ny - 1 : r[3];
}

/* Whether node n is an obstacle: drawn, with a box. */
int bg_route_node_drawn(const bg_diagram_layout *L, int n) {
  return bg_node_shown(L, n) && !bg_fields_hidden(L, n) && L->nw[n] > 0 && L->nh[n] > 0;
}

void bg_near_item_box(const bg_diagram_layout *L, const near_index *ix, int k, double b[4]) {
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

/* Bond b's end `end` at its tail (head 0) or head carried on along `in`
 * (a unit vector into its node) to the node's box if that is at most
 * END_GAP pt on (a junction's bonds end on a circle round it, farther out in
 * a style of thick lines): a line passing between a bond's end and its node
 * reads as crossing the bond there (among its half arrow or stroke), so the
 * index holds the bond as reaching its node. */
#define END_GAP 40.0
static bg_vec to_node_box(const bg_diagram_layout *L, int b, int head, bg_vec end, bg_vec in) {
  int n = bg_route_end_node(L, b, head);
  if (n < 0 || !bg_route_node_drawn(L, n)) return end;
  double lo[2] = {L->nx[n] - L->nw[n] / 2, L->ny[n] - L->nh[n] / 2};
  double hi[2] = {L->nx[n] + L->nw[n] / 2, L->ny[n] + L->nh[n] / 2};
  double p[2] = {end.x, end.y}, u[2] = {in.x, in.y}, t0 = 0, t1 = END_GAP;
  for (int k = 0; k < 2; k++) { /* the ray's stretch inside the box's slab k */
    if (fabs(u[k]) < 1e-12) {
      if (p[k] < lo[k] || p[k] > hi[k]) return end;
      continue;
    }
    double ta = (lo[k] - p[k]) / u[k], tb = (hi[k] - p[k]) / u[k];
    t0 = fmax(t0, fmin(ta, tb)), t1 = fmin(t1, fmax(ta, tb));
  }
  return t0 > 0 && t0 <= t1 ? bg_vadd(end, bg_vscale(in, t0)) : end;
}

/* The rows *cy0..*cy1 of column cx that leg a-b (a.x <= b.x) passes
 * within 1 pt of: a long slanted leg is listed in the cells it crosses,
 * not in every cell of its bounding box (a star's spokes each filled a
 * quarter of the index, so every query near its hub listed them all). */
static void leg_rows(const near_index *ix, bg_vec a, bg_vec b, int cx, int *cy0, int *cy1) {
  double xa = fmin(fmax(ix->x0 + cx * ix->cell, a.x), b.x), xb = fmin(fmax(ix->x0 + (cx + 1) * ix->cell, a.x), b.x);
  double dx = b.x - a.x, ya = a.y, yb = b.y;
  if (dx > 1e-9) ya = a.y + (xa - a.x) / dx * (b.y - a.y), yb = a.y + (xb - a.x) / dx * (b.y - a.y);
  int r[4];
  bg_near_cells(ix, xa, fmin(ya, yb) - 1, xb, fmax(ya, yb) + 1, r);
  *cy0 = r[1], *cy1 = r[3];
}

void bg_near_build(const bg_diagram_layout *L, int nbond, const unsigned char *skip, int to_nodes, near_index *ix) {
  memset(ix, 0, sizeof *ix);
  ix->nnode = L->nnode;
  for (int b = 0; b < nbond; b++) ix->nleg += leg_skipped(L, skip, b) ? 0 : L->bg[b].bendn + 1;
  ix->la = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->la), ix->lb = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->lb);
  ix->lmid = bg_xcalloc((size_t)ix->nleg + 1, 1), ix->mid = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->mid);
  ix->lbond = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->lbond);
  ix->lpos = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->lpos);
  ix->llen = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->llen);
  for (int b = 0, k = 0; b < nbond; b++) {
    int k0 = k;
    double pos = 0;
    for (int i = 0; !leg_skipped(L, skip, b) && i <= L->bg[b].bendn; i++, k++) {
      ix->lbond[k] = b;
      ix->la[k] = bg_route_leg_end(L, b, i - 1), ix->lb[k] = bg_route_leg_end(L, b, i), ix->mid[k] = L->bg[b].mid;
      ix->lmid[k] = bg_point_seg(L->bg[b].mid, ix->la[k], ix->lb[k]) < 0.5;
      ix->lpos[k] = pos, pos += bg_vlen(bg_vsub(ix->lb[k], ix->la[k]));
    }
    for (int j = k0; j < k; j++) ix->llen[j] = pos;
    if (to_nodes && k > k0) { /* the ends carried on to their nodes' boxes */
      bg_vec a = ix->la[k0], z = ix->lb[k - 1];
      ix->la[k0] = to_node_box(L, b, 0, a, bg_vunit(bg_vsub(a, ix->lb[k0])));
      ix->lb[k - 1] = to_node_box(L, b, 1, z, bg_vunit(bg_vsub(z, ix->la[k - 1])));
      ix->lpos[k0] -= bg_vlen(bg_vsub(a, ix->la[k0]));
    }
  }
  int nitem = L->nnode + ix->nleg;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, area = 0;
  for (int k = 0; k < nitem; k++) {
    if (k < L->nnode && !bg_route_node_drawn(L, k)) continue;
    double bx[4];
    bg_near_item_box(L, ix, k, bx);
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
      if (k < L->nnode && !bg_route_node_drawn(L, k)) continue;
      double bx[4];
      int r[4];
      bg_near_item_box(L, ix, k, bx);
      bg_near_cells(ix, bx[0], bx[1], bx[2], bx[3], r);
      bg_vec a = k < L->nnode ? bg_v(0, 0) : ix->la[k - L->nnode], b = k < L->nnode ? a : ix->lb[k - L->nnode];
      if (a.x > b.x) {
        bg_vec t = a;
        a = b, b = t;
      }
      for (int cx = r[0]; cx <= r[2]; cx++) {
        int cy0 = r[1], cy1 = r[3];
        if (k >= L->nnode) leg_rows(ix, a, b, cx, &cy0, &cy1), cy0 = cy0 > r[1] ? cy0 : r[1], cy1 = cy1 < r[3] ? cy1 : r[3];
        for (int cy = cy0; cy <= cy1; cy++) {
          size_t c = (size_t)cy * (size_t)ix->nx + (size_t)cx;
          if (pass) ix->item[ix->adr[c] + fill[c]++] = k;
          else ix->adr[c + 1]++;
        }
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

void bg_near_free(near_index *ix) {
  free(ix->adr), free(ix->item), free(ix->la), free(ix->lb), free(ix->lbond), free(ix->lmid), free(ix->mid);
  free(ix->lpos), free(ix->llen), free(ix->stamp);
  free(ix->sig_head), free(ix->sig_next), free(ix->sig_seg), free(ix->sa), free(ix->sb), free(ix->sgrp), free(ix->sroute), free(ix->slast), free(ix->seg_stamp);
}

void bg_near_box(near_index *ix, double x0, double y0, double x1, double y1, near_list *out) {
  int r[4];
  bg_near_cells(ix, x0, y0, x1, y1, r);
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
void bg_near_signals(near_index *ix, double x0, double y0, double x1, double y1, near_list *out) {
  int r[4];
  bg_near_cells(ix, x0, y0, x1, y1, r);
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

/* Segment s listed in the cells its box a-b meets (again: a cell that
 * lists it twice is harmless, queries list each segment once). */
static void list_signal(near_index *ix, int s, bg_vec a, bg_vec b) {
  int r[4];
  bg_near_cells(ix, fmin(a.x, b.x), fmin(a.y, b.y), fmax(a.x, b.x), fmax(a.y, b.y), r);
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

void bg_near_move_signal(near_index *ix, int s, bg_vec a, bg_vec b) {
  ix->sa[s] = a, ix->sb[s] = b;
  list_signal(ix, s, a, b); /* the cells it left still list it: it is tested where it is */
}

int bg_near_route_segment(const near_index *ix, int from, int route, bg_vec a, bg_vec b) {
  for (int s = from; s < ix->nseg; s++)
    if (ix->sroute[s] == route && bg_vlen(bg_vsub(ix->sa[s], a)) < 1e-9 && bg_vlen(bg_vsub(ix->sb[s], b)) < 1e-9)
      return s;
  return -1;
}

void bg_near_add_signal(near_index *ix, bg_vec a, bg_vec b, int group, int route) {
  if (ix->nseg == ix->capseg) {
    ix->capseg = 2 * ix->capseg + 16;
    ix->sa = bg_xrealloc(ix->sa, (size_t)ix->capseg * sizeof *ix->sa);
    ix->sb = bg_xrealloc(ix->sb, (size_t)ix->capseg * sizeof *ix->sb);
    ix->sgrp = bg_xrealloc(ix->sgrp, (size_t)ix->capseg * sizeof *ix->sgrp);
    ix->sroute = bg_xrealloc(ix->sroute, (size_t)ix->capseg * sizeof *ix->sroute);
    ix->slast = bg_xrealloc(ix->slast, (size_t)ix->capseg);
  }
  int s = ix->nseg++;
  ix->sa[s] = a, ix->sb[s] = b, ix->sgrp[s] = group, ix->sroute[s] = route, ix->slast[s] = 0;
  list_signal(ix, s, a, b);
}
