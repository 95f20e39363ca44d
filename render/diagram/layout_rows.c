/* SPDX-License-Identifier: BSD-3-Clause */
/* The "rows" layout: bgdraw's own, linear in nodes and edges, for graphs
 * too large for Graphviz to lay out quickly (dot and sfdp take tens of
 * seconds at 10 000 nodes). Nodes are ranked by breadth-first distance from
 * the roots (the same ranks dot is given), each rank is a column in the
 * order the search reached its nodes, and the columns are cut into bands
 * that stack top to bottom, alternately left to right and right to left,
 * so a long chain folds into a roughly A4-landscape page with short bonds
 * at the folds. Bonds are straight lines. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "diagram/layout.h"

typedef struct rank_cols {
  int nrank;
  int *adr, *node;  /* nodes of rank r: node[adr[r] .. adr[r+1]) in search order */
  double *w, *h;    /* column width (widest node) and stacked height */
} rank_cols;

static void rank_columns(const bg_layout_in *in, const int *depth, const int *order, rank_cols *c) {
  int n = in->nnode;
  c->nrank = 0;
  for (int v = 0; v < n; v++) c->nrank = depth[v] + 1 > c->nrank ? depth[v] + 1 : c->nrank;
  c->adr = bg_xcalloc((size_t)c->nrank + 2, sizeof *c->adr);
  c->node = bg_xcalloc((size_t)n + 1, sizeof *c->node);
  c->w = bg_xcalloc((size_t)c->nrank + 1, sizeof *c->w);
  c->h = bg_xcalloc((size_t)c->nrank + 1, sizeof *c->h);
  for (int v = 0; v < n; v++) c->adr[depth[v] + 1]++;
  for (int r = 0; r < c->nrank; r++) c->adr[r + 1] += c->adr[r];
  int *fill = bg_xcalloc((size_t)c->nrank + 1, sizeof *fill);
  for (int k = 0; k < n; k++) { /* search order keeps a node near its parent's row */
    int v = order[k], r = depth[v];
    c->node[c->adr[r] + fill[r]++] = v;
    if (in->w[v] > c->w[r]) c->w[r] = in->w[v];
    c->h[r] += in->h[v] + (fill[r] > 1 ? in->node_sep : 0);
  }
  free(fill);
}

/* Band width: the columns' total length folded so that the page is about
 * 1.4 times as wide as it is high (at least the widest column). */
static double band_width(const bg_layout_in *in, const rank_cols *c) {
  double len = 0, area = 0, widest = 0;
  for (int r = 0; r < c->nrank; r++) {
    len += c->w[r] + in->rank_sep;
    area += (c->w[r] + in->rank_sep) * (c->h[r] + in->rank_sep);
    widest = c->w[r] > widest ? c->w[r] : widest;
  }
  double bw = sqrt(1.4 * area);
  return bw < widest ? widest : bw > len ? len : bw;
}

static void place(const bg_layout_in *in, const rank_cols *c, bg_layout *out) {
  double bw = band_width(in, c), top = 0, maxw = 0;
  int band = 0;
  for (int r0 = 0; r0 < c->nrank; band++) {
    double len = 0, bh = 0;
    int r1 = r0;
    while (r1 < c->nrank && (r1 == r0 || len + c->w[r1] <= bw)) {
      len += c->w[r1] + in->rank_sep;
      bh = c->h[r1] > bh ? c->h[r1] : bh;
      r1++;
    }
    len -= in->rank_sep;
    maxw = len > maxw ? len : maxw;
    double x = 0;
    for (int r = r0; r < r1; r++) {
      double cx = band % 2 ? bw - x - c->w[r] / 2 : x + c->w[r] / 2;
      double y = top + (bh - c->h[r]) / 2; /* columns centred in the band */
      for (int k = c->adr[r]; k < c->adr[r + 1]; k++) {
        int v = c->node[k];
        out->x[v] = cx;
        out->y[v] = y + in->h[v] / 2;
        y += in->h[v] + in->node_sep;
      }
      x += c->w[r] + in->rank_sep;
    }
    top += bh + 2 * in->rank_sep;
    r0 = r1;
  }
  out->width = band > 1 ? bw : maxw;
  out->height = top > 2 * in->rank_sep ? top - 2 * in->rank_sep : 0;
}

/* Moves the nodes so their boxes start at (0, 0) and sets the box size. */
static void fit_box(const bg_layout_in *in, bg_layout *out) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (int v = 0; v < in->nnode; v++) {
    x0 = fmin(x0, out->x[v] - in->w[v] / 2), x1 = fmax(x1, out->x[v] + in->w[v] / 2);
    y0 = fmin(y0, out->y[v] - in->h[v] / 2), y1 = fmax(y1, out->y[v] + in->h[v] / 2);
  }
  if (in->nnode == 0) x0 = y0 = x1 = y1 = 0;
  for (int v = 0; v < in->nnode; v++) out->x[v] -= x0, out->y[v] -= y0;
  out->width = x1 - x0, out->height = y1 - y0;
}

int bg_layout_rows(const bg_layout_in *in, bg_layout *out) {
  int n = in->nnode;
  int *order = bg_xcalloc((size_t)n + 1, sizeof *order);
  int *depth = bg_layout_depths(in, order);
  rank_cols c;
  rank_columns(in, depth, order, &c);
  out->x = bg_xcalloc((size_t)n + 1, sizeof *out->x);
  out->y = bg_xcalloc((size_t)n + 1, sizeof *out->y);
  out->spladr = bg_xcalloc((size_t)in->nedge + 1, sizeof *out->spladr);
  out->spln = bg_xcalloc((size_t)in->nedge + 1, sizeof *out->spln);
  place(in, &c, out);
  fit_box(in, out);
  free(c.adr), free(c.node), free(c.w), free(c.h);
  free(order), free(depth);
  return 0;
}
