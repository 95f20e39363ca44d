/* SPDX-License-Identifier: BSD-3-Clause */
/* The "rows" layout: bgdraw's own, linear in nodes and edges, for graphs
 * too large for Graphviz to lay out quickly (dot and sfdp take tens of
 * seconds at 10 000 nodes). Nodes are ranked by breadth-first distance from
 * the roots (the same ranks dot is given), each rank is a column in the
 * order the search reached its nodes, and the columns are cut into even
 * bands that stack top to bottom, alternately left to right and right to
 * left, each starting under the last one's end, so a long chain folds into
 * a page about 1.4 times as wide as high with one vertical bond at each
 * fold (place). A one-port hangs straight above or below its junction, in
 * its column, on the side out of a fold's way and facing its signals
 * (hang_leaves, face_hangers); more than eight round it on a ring
 * (rows_one). Disconnected parts are laid out each on its
 * own and packed on a skyline; with frames, a band folds where it splits the
 * fewest. Bonds are straight lines (docs/drawing.md, Layout). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "diagram/layout.h"

/* One-ports hang off their junction, as books draw them: a node with one
 * edge (not a rank's first, such as a root), whose neighbour has more, is
 * placed directly above that neighbour, in its column, with a vertical bond;
 * a second such node below it. A third and further stay in the next column
 * as other nodes (stacked on one side, a bond would run through the nearer
 * one's box). host[v]: the node v hangs off, or -1; above[u], below[u]:
 * what hangs off u, or -1. */
typedef struct hangers {
  int *host, *above, *below;
  double *gap; /* per junction: between it and what hangs off it */
} hangers;

static void hang_leaves(const bg_layout_in *in, const int *depth, const int *order, hangers *hg) {
  int n = in->nnode;
  int *deg = bg_xcalloc((size_t)n + 1, sizeof *deg), *nb = bg_xcalloc((size_t)n + 1, sizeof *nb);
  hg->host = bg_xcalloc((size_t)n + 1, sizeof *hg->host);
  hg->above = bg_xcalloc((size_t)n + 1, sizeof *hg->above), hg->below = bg_xcalloc((size_t)n + 1, sizeof *hg->below);
  for (int e = 0; e < in->nedge; e++) {
    int t = in->tail[e], h = in->head[e];
    deg[t]++, deg[h]++, nb[t] = h, nb[h] = t;
  }
  /* A junction of more than three bonds draws its bonds' ends on a circle
   * that grows, up to its box's size, when two bonds leave it at a small
   * angle (diagram_geom.c, junction_radii), which the layout does not
   * control here: the gap grows by that much, so a hung bond keeps at
   * least node_sep of line. */
  hg->gap = bg_xcalloc((size_t)n + 1, sizeof *hg->gap);
  for (int v = 0; v < n; v++) hg->gap[v] = in->node_sep + (deg[v] > 3 ? fmax(in->w[v], in->h[v]) : 0);
  for (int v = 0; v < n; v++) hg->host[v] = hg->above[v] = hg->below[v] = -1;
  for (int k = 0; k < n; k++) { /* in search order: the same choice every run */
    int v = order[k], u = nb[v];
    if (deg[v] != 1 || depth[v] == 0 || u == v || deg[u] < 2) continue;
    if (hg->above[u] < 0) hg->above[u] = v, hg->host[v] = u;
    else if (hg->below[u] < 0) hg->below[u] = v, hg->host[v] = u;
  }
  free(deg), free(nb);
}

static void hangers_free(hangers *hg) {
  free(hg->host), free(hg->above), free(hg->below), free(hg->gap);
}

/* A node's slot in its column: its own box and those hanging off it, each
 * its gap apart (the hangers' bonds as long as the gap between nodes). */
static double slot_height(const bg_layout_in *in, const hangers *hg, int v) {
  double h = in->h[v];
  if (hg->above[v] >= 0) h += in->h[hg->above[v]] + hg->gap[v];
  if (hg->below[v] >= 0) h += in->h[hg->below[v]] + hg->gap[v];
  return h;
}

/* Cluster k's depth: 0 for none (-1), 1 for a top-level frame. */
static int cluster_depth(const bg_layout_in *in, int k) {
  int d = 0;
  for (; k >= 0 && d <= in->ncluster; k = in->cluster_parent[k]) d++;
  return d;
}

/* The innermost cluster holding both a and b (-1: none). */
static int common_cluster(const bg_layout_in *in, int a, int b) {
  int da = cluster_depth(in, a), db = cluster_depth(in, b);
  for (; da > db; da--) a = in->cluster_parent[a];
  for (; db > da; db--) b = in->cluster_parent[b];
  while (a != b && a >= 0 && b >= 0) a = in->cluster_parent[a], b = in->cluster_parent[b];
  return a == b ? a : -1;
}

typedef struct rank_cols {
  int nrank;
  int *adr, *node;  /* nodes of rank r: node[adr[r] .. adr[r+1]) in search order (hung nodes not) */
  double *w, *h;    /* column width (widest node) and stacked height */
  double *mid;      /* the middle of the column's nodes' centres, from the column's top */
  int *band;        /* the band the column went to (place) */
  int *cl;          /* the innermost cluster (frame) holding every node of the column, -1: none;
                       NULL without clusters */
  int *parent;      /* per node: the neighbour one column back that the search reached it
                       from (its first reached), -1: none (a root, a hung one-port) */
  double *cy;       /* per node: its centre's height in its band, while the band is placed */
} rank_cols;

static void rank_cols_free(rank_cols *c) {
  free(c->adr), free(c->node), free(c->w), free(c->h), free(c->mid), free(c->band), free(c->cl);
  free(c->parent), free(c->cy);
}

/* Each column node's parent: of its neighbours one rank nearer the roots,
 * the one the search reached first. A breadth-first search reaches a
 * parent's children together, so in a column they follow one another, in
 * the order of their parents in the column before. */
static void find_parents(const bg_layout_in *in, const int *depth, const int *order, const hangers *hg,
                         rank_cols *c) {
  int n = in->nnode, *pos = bg_xcalloc((size_t)n + 1, sizeof *pos);
  c->parent = bg_xcalloc((size_t)n + 1, sizeof *c->parent);
  for (int k = 0; k < n; k++) pos[order[k]] = k;
  for (int v = 0; v < n; v++) c->parent[v] = -1;
  for (int e = 0; e < in->nedge; e++)
    for (int k = 0; k < 2; k++) {
      int u = k ? in->head[e] : in->tail[e], v = k ? in->tail[e] : in->head[e];
      if (depth[u] + 1 != depth[v] || hg->host[u] >= 0 || hg->host[v] >= 0) continue;
      if (c->parent[v] < 0 || pos[u] < pos[c->parent[v]]) c->parent[v] = u;
    }
  free(pos);
}

static void rank_columns(const bg_layout_in *in, const int *depth, const int *order, const hangers *hg,
                         rank_cols *c) {
  int n = in->nnode;
  c->nrank = 0;
  for (int v = 0; v < n; v++)
    if (hg->host[v] < 0) c->nrank = depth[v] + 1 > c->nrank ? depth[v] + 1 : c->nrank;
  c->adr = bg_xcalloc((size_t)c->nrank + 2, sizeof *c->adr);
  c->node = bg_xcalloc((size_t)n + 1, sizeof *c->node);
  c->w = bg_xcalloc((size_t)c->nrank + 1, sizeof *c->w);
  c->h = bg_xcalloc((size_t)c->nrank + 1, sizeof *c->h);
  c->mid = bg_xcalloc((size_t)c->nrank + 1, sizeof *c->mid);
  c->band = bg_xcalloc((size_t)c->nrank + 1, sizeof *c->band);
  c->cy = bg_xcalloc((size_t)n + 1, sizeof *c->cy);
  c->cl = NULL;
  if (in->cluster && in->ncluster > 0) {
    c->cl = bg_xcalloc((size_t)c->nrank + 1, sizeof *c->cl);
    for (int r = 0; r < c->nrank; r++) c->cl[r] = -3; /* none seen yet */
    for (int v = 0; v < n; v++) {
      int r = depth[hg->host[v] >= 0 ? hg->host[v] : v];
      if (r >= c->nrank) continue;
      c->cl[r] = c->cl[r] == -3 ? in->cluster[v] : common_cluster(in, c->cl[r], in->cluster[v]);
    }
    for (int r = 0; r < c->nrank; r++) c->cl[r] = c->cl[r] == -3 ? -1 : c->cl[r];
  }
  double *first = bg_xcalloc((size_t)c->nrank + 1, sizeof *first), *last = bg_xcalloc((size_t)c->nrank + 1, sizeof *last);
  for (int v = 0; v < n; v++)
    if (hg->host[v] < 0) c->adr[depth[v] + 1]++;
  for (int r = 0; r < c->nrank; r++) c->adr[r + 1] += c->adr[r];
  int *fill = bg_xcalloc((size_t)c->nrank + 1, sizeof *fill);
  for (int k = 0; k < n; k++) { /* search order keeps a node near its parent's row */
    int v = order[k], r = depth[v];
    if (hg->host[v] >= 0) continue;
    c->node[c->adr[r] + fill[r]++] = v;
    for (int j = 0; j < 3; j++) {
      int u = j == 0 ? v : j == 1 ? hg->above[v] : hg->below[v];
      if (u >= 0 && in->w[u] > c->w[r]) c->w[r] = in->w[u];
    }
    if (fill[r] > 1) c->h[r] += in->node_sep;
    double centre = c->h[r] + (hg->above[v] >= 0 ? in->h[hg->above[v]] + hg->gap[v] : 0) + in->h[v] / 2;
    if (fill[r] == 1) first[r] = centre;
    last[r] = centre;
    c->h[r] += slot_height(in, hg, v);
  }
  for (int r = 0; r < c->nrank; r++) c->mid[r] = (first[r] + last[r]) / 2;
  free(fill), free(first), free(last);
  find_parents(in, depth, order, hg, c);
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

/* How far node v's slot (its box and those hung off it) reaches above and
 * below its centre. */
static double reach_above(const bg_layout_in *in, const hangers *hg, int v) {
  return in->h[v] / 2 + (hg->above[v] >= 0 ? in->h[hg->above[v]] + hg->gap[v] : 0);
}
static double reach_below(const bg_layout_in *in, const hangers *hg, int v) {
  return in->h[v] / 2 + (hg->below[v] >= 0 ? in->h[hg->below[v]] + hg->gap[v] : 0);
}

/* The centres of column r's nodes in their band (c->cy, the band's line at
 * 0), in the column's order, node_sep between slots. A band's first column
 * is stacked with its nodes' middle on the line; every later one is lined
 * up with its parents (issue 31: in a network's wide columns, stacked from
 * the top, hardly a bond ran level): a parent's children, consecutive in
 * the column, wish to lie stacked with the middle one level with their
 * parent, and bg_layout_align keeps the order and the gaps and places them
 * as near that as it can (a chain, one node a column, runs straight along
 * the line as before) within the band's reach above and below its line
 * (up, down: its tallest stacks'), so a band is as high as when its
 * columns were stacked (unbounded, each column spread both ways from its
 * parents' and the bands grew by half, the page to 1.7 times the area).
 * wish, gap, y: scratch of the column's length. */
static void column_heights(const bg_layout_in *in, const hangers *hg, rank_cols *c, int r, int first, double up,
                           double down, double *wish, double *gap, double *y) {
  const int *node = c->node + c->adr[r];
  int m = c->adr[r + 1] - c->adr[r];
  double run = 0; /* the gaps summed: a stack's centre i at y[i] */
  for (int i = 0; i < m; i++) {
    gap[i] = i ? reach_below(in, hg, node[i - 1]) + in->node_sep + reach_above(in, hg, node[i]) : 0;
    run += gap[i], y[i] = run;
  }
  if (first) {
    for (int i = 0; i < m; i++) y[i] += reach_above(in, hg, node[0]) - c->mid[r];
  } else {
    for (int i0 = 0, i1; i0 < m; i0 = i1) {
      int p = c->parent[node[i0]];
      for (i1 = i0 + 1; i1 < m && c->parent[node[i1]] == p; i1++) {}
      double level = y[i0 + (i1 - i0 - 1) / 2]; /* the middle child's place in the stack */
      for (int i = i0; i < i1; i++)
        wish[i] = p >= 0 ? c->cy[p] + y[i] - level : i ? wish[i - 1] + gap[i] : 0;
    }
    bg_layout_align(m, wish, gap, reach_above(in, hg, node[0]) - up, down - reach_below(in, hg, node[m - 1]), y);
  }
  for (int i = 0; i < m; i++) c->cy[node[i]] = y[i];
}

/* Columns cut into bands, each band's columns placed by column_heights and
 * the band moved down under the last one. */
static int place_bands(const bg_layout_in *in, const hangers *hg, rank_cols *c, double bw, bg_layout *out) {
  double top = 0, maxw = 0, edge = -1;
  int band = 0, n = in->nnode;
  double *wish = bg_xcalloc((size_t)n + 1, sizeof *wish), *gap = bg_xcalloc((size_t)n + 1, sizeof *gap);
  double *y = bg_xcalloc((size_t)n + 1, sizeof *y);
  for (int r0 = 0; r0 < c->nrank; band++) {
    /* a band starts under the previous one's last column (edge: its
     * centre), so the bond of the fold runs straight down, and runs the
     * other way as far as the page's width allows */
    int rtl = band % 2;
    double first = edge < 0 ? c->w[r0] / 2 : edge;
    double outer = rtl ? first + c->w[r0] / 2 : first - c->w[r0] / 2, room = rtl ? outer : bw - outer;
    double len = 0;
    int r1 = r0;
    while (r1 < c->nrank && (r1 == r0 || len + c->w[r1] <= room)) len += c->w[r1] + in->rank_sep, r1++;
    if (c->cl && r1 < c->nrank) { /* a fold splits the frames round both its columns: */
      /* fold earlier where it splits fewer, the band still half full */
      int best = r1, fewest = cluster_depth(in, common_cluster(in, c->cl[r1 - 1], c->cl[r1]));
      double at = len;
      for (int r = r1 - 1; r > r0 && fewest > 0; r--) {
        at -= c->w[r] + in->rank_sep;
        if (at < room / 2) break;
        int d = cluster_depth(in, common_cluster(in, c->cl[r - 1], c->cl[r]));
        if (d < fewest) best = r, fewest = d;
      }
      r1 = best;
    }
    len = 0;
    double up = 0, down = 0; /* the band's reach above and below its line: its columns' stacks' */
    for (int r = r0; r < r1; r++) {
      len += c->w[r] + in->rank_sep;
      up = fmax(up, c->mid[r]), down = fmax(down, c->h[r] - c->mid[r]);
    }
    len -= in->rank_sep;
    maxw = len > maxw ? len : maxw;
    double x = 0, lo = 1e300, hi = -1e300;
    for (int r = r0; r < r1; r++) {
      double cx = rtl ? outer - x - c->w[r] / 2 : outer + x + c->w[r] / 2;
      edge = cx, c->band[r] = band;
      column_heights(in, hg, c, r, r == r0, up, down, wish, gap, y);
      for (int k = c->adr[r]; k < c->adr[r + 1]; k++) {
        int v = c->node[k];
        lo = fmin(lo, c->cy[v] - reach_above(in, hg, v)), hi = fmax(hi, c->cy[v] + reach_below(in, hg, v));
      }
      x += c->w[r] + in->rank_sep;
    }
    x = 0;
    for (int r = r0; r < r1; r++) { /* the band's top at `top` */
      double cx = rtl ? outer - x - c->w[r] / 2 : outer + x + c->w[r] / 2;
      for (int k = c->adr[r]; k < c->adr[r + 1]; k++) {
        int v = c->node[k], a = hg->above[v], b = hg->below[v];
        out->x[v] = cx, out->y[v] = top - lo + c->cy[v];
        if (a >= 0) out->x[a] = cx, out->y[a] = out->y[v] - in->h[v] / 2 - hg->gap[v] - in->h[a] / 2;
        if (b >= 0) out->x[b] = cx, out->y[b] = out->y[v] + in->h[v] / 2 + hg->gap[v] + in->h[b] / 2;
      }
      x += c->w[r] + in->rank_sep;
    }
    top += hi - lo + 2 * in->rank_sep;
    r0 = r1;
  }
  free(wish), free(gap), free(y);
  out->width = band > 1 ? bw : maxw;
  out->height = top > 2 * in->rank_sep ? top - 2 * in->rank_sep : 0;
  return band;
}

/* The bands' width: the page's when given (page > 0), else first from the
 * columns' stacked area (band_width);
 * placed, the page's real height (the gaps between bands, the one-ports
 * hung above and below) gives the width for a page 1.4 times as wide as
 * high; then the columns are spread evenly over as many bands as that
 * width needs, so the last band is about as long as the others (not a
 * stub of a column or two). */
static void place(const bg_layout_in *in, const hangers *hg, rank_cols *c, double page, bg_layout *out) {
  double total = -in->rank_sep, widest = 0;
  for (int r = 0; r < c->nrank; r++) total += c->w[r] + in->rank_sep, widest = fmax(widest, c->w[r]);
  double bw = page > 0 ? fmax(widest, fmin(page, total)) : band_width(in, c);
  int nb = place_bands(in, hg, c, bw, out);
  if (nb < 2) return;
  double shaped = bw;
  for (int extra = 0; extra < 4; extra++) { /* even bands: the least width that needs no more than nb */
    double even = total / nb + extra * widest / 2;
    if (place_bands(in, hg, c, even + 1e-9, out) <= nb) return;
  }
  place_bands(in, hg, c, shaped, out);
}

/* Each one-port to the side where it is out of its junction's other
 * bonds' way and faces its signals (out: the layout with every one-port
 * above, the second below). A junction with a bond from a node of the
 * band above, higher by more than it lies aside (a fold's), hangs a lone
 * one-port below, one with a bond down to the next band above: on that
 * side the bond would run through the one-port's label. Otherwise the side facing most of the
 * nodes its links (signals) join: a partner lower than its junction by
 * more than the junction's height counts for below, higher for above, a
 * hung partner by its own junction's place. A junction's two one-ports swap
 * when the lower one wants up more; a lone one-port goes below only when
 * more of its partners lie below than above, so a chain's one-ports stay
 * on one side unless their signals lead across a row (a fold), where
 * crossing it is what the signal would otherwise pay. */
static void face_hangers(const bg_layout_in *in, const int *depth, const rank_cols *c, const bg_layout *out,
                         hangers *hg) {
  int n = in->nnode;
  int *vote = bg_xcalloc((size_t)n + 1, sizeof *vote); /* below minus above */
  unsigned char *steep = bg_xcalloc((size_t)n + 1, 1);  /* 1: a bond from above, 2: one below */
  for (int k = 0; k < in->nlink; k++)
    for (int e = 0; e < 2; e++) {
      int v = e ? in->link_b[k] : in->link_a[k], p = e ? in->link_a[k] : in->link_b[k];
      if (v < 0 || p < 0 || v >= n || p >= n || hg->host[v] < 0) continue;
      int u = hg->host[v], pu = hg->host[p] >= 0 ? hg->host[p] : p;
      if (pu == u) continue;
      double d = out->y[pu] - out->y[u];
      vote[v] += d > in->h[u] ? 1 : d < -in->h[u] ? -1 : 0;
    }
  for (int e = 0; e < in->nedge; e++)
    for (int k = 0; k < 2; k++) {
      int u = k ? in->head[e] : in->tail[e], v = k ? in->tail[e] : in->head[e];
      if (hg->host[u] >= 0 || hg->host[v] >= 0 || u == v || c->band[depth[u]] == c->band[depth[v]]) continue;
      double dy = out->y[v] - out->y[u], dx = fabs(out->x[v] - out->x[u]);
      if (fabs(dy) > in->h[u] && fabs(dy) > dx) steep[u] |= dy < 0 ? 1 : 2;
    }
  for (int u = 0; u < n; u++) {
    int a = hg->above[u], b = hg->below[u];
    if (a < 0) continue;
    int down;
    if (b < 0 && (steep[u] == 1 || steep[u] == 2)) down = steep[u] == 1; /* a fold's bond decides */
    else down = b < 0 ? vote[a] > 0 : vote[a] > vote[b];
    if (down) hg->above[u] = b, hg->below[u] = a;
  }
  free(vote), free(steep);
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

/* One connected graph (or any graph, its parts mixed in the columns): the
 * positions into out->x, out->y (allocated), its box from (0, 0); its
 * bands at most `page` wide when that is given (> 0). */
static void rows_core(const bg_layout_in *in, double page, bg_layout *out) {
  int n = in->nnode;
  int *order = bg_xcalloc((size_t)n + 1, sizeof *order);
  int *depth = bg_layout_depths(in, order);
  hangers hg;
  hang_leaves(in, depth, order, &hg);
  rank_cols c;
  rank_columns(in, depth, order, &hg, &c);
  place(in, &hg, &c, page, out);
  { /* again with the one-ports out of their bonds' way and facing their signals (the bands stay) */
    face_hangers(in, depth, &c, out, &hg);
    rank_cols_free(&c);
    rank_columns(in, depth, order, &hg, &c);
    place(in, &hg, &c, page, out);
  }
  fit_box(in, out);
  rank_cols_free(&c);
  hangers_free(&hg);
  free(order), free(depth);
}

/* Part p of `in` as a graph of its own: its nodes (node[0..nnode), in
 * order), their edges and links renumbered; the arrays are the part's. */
typedef struct part_in {
  bg_layout_in in;
  const int *node;
} part_in;

static void part_input(const bg_layout_in *in, const int *node, int pn, const int *edge, int pe, const int *link,
                       int pl, const int *local, part_in *pi) {
  double *w = bg_xcalloc((size_t)pn + 1, sizeof *w), *h = bg_xcalloc((size_t)pn + 1, sizeof *h);
  int *t = bg_xcalloc((size_t)pe + 1, sizeof *t), *hd = bg_xcalloc((size_t)pe + 1, sizeof *hd);
  int *la = bg_xcalloc((size_t)pl + 1, sizeof *la), *lb = bg_xcalloc((size_t)pl + 1, sizeof *lb);
  unsigned char *root = in->root ? bg_xcalloc((size_t)pn + 1, 1) : NULL;
  int *cl = in->cluster ? bg_xcalloc((size_t)pn + 1, sizeof *cl) : NULL;
  for (int i = 0; i < pn; i++) {
    w[i] = in->w[node[i]], h[i] = in->h[node[i]];
    if (root) root[i] = in->root[node[i]];
    if (cl) cl[i] = in->cluster[node[i]];
  }
  for (int i = 0; i < pe; i++) t[i] = local[in->tail[edge[i]]], hd[i] = local[in->head[edge[i]]];
  for (int i = 0; i < pl; i++) la[i] = local[in->link_a[link[i]]], lb[i] = local[in->link_b[link[i]]];
  pi->in = *in, pi->node = node;
  pi->in.nnode = pn, pi->in.w = w, pi->in.h = h, pi->in.nedge = pe, pi->in.tail = t, pi->in.head = hd;
  pi->in.root = root, pi->in.cluster = cl, pi->in.nlink = pl, pi->in.link_a = la, pi->in.link_b = lb;
  pi->in.weight = NULL, pi->in.pinned = NULL, pi->in.px = pi->in.py = NULL;
}

static void part_input_free(part_in *pi) {
  free((void *)pi->in.w), free((void *)pi->in.h), free((void *)pi->in.tail), free((void *)pi->in.head);
  free((void *)pi->in.link_a), free((void *)pi->in.link_b), free((void *)pi->in.root), free((void *)pi->in.cluster);
}

/* Junctions of many one-ports: a node with more than RING_LEAVES
 * neighbours of one edge each (not roots) has them round it on a ring
 * (bg_layout_ring, as the grid pass does for dot's layouts), its box as
 * large as the ring's, and the columns are laid out without them. In
 * columns, the third and further one-ports of such a hub went to the next
 * column as other nodes: a column of 6 000 resistors 90 000 pt tall, the
 * bonds to the nearer ones blocking the fan to the rest, which the bond
 * router then took round the figure (a star of 60 forced into rows had 59
 * bonds routed; a star of 6 000, 40 s). The ring's four side middles stay
 * free for the hub's other bonds: to its parent and children in the
 * columns beside it, and a fold's vertical bond. */
#define RING_LEAVES 8

static void rows_one(const bg_layout_in *in, double page, bg_layout *out) {
  int n = in->nnode;
  int *deg = bg_xcalloc((size_t)n + 1, sizeof *deg), *nb = bg_xcalloc((size_t)n + 1, sizeof *nb);
  for (int e = 0; e < in->nedge; e++) {
    int t = in->tail[e], h = in->head[e];
    deg[t]++, deg[h]++, nb[t] = h, nb[h] = t;
  }
  int *leaves = bg_xcalloc((size_t)n + 1, sizeof *leaves), hubs = 0;
  unsigned char *ringed = bg_xcalloc((size_t)n + 1, 1); /* first: a one-port, not a root */
  for (int v = 0; v < n; v++)
    if ((ringed[v] = deg[v] == 1 && !(in->root && in->root[v]) && nb[v] != v && deg[nb[v]] >= 2)) leaves[nb[v]]++;
  for (int u = 0; u < n; u++) hubs += leaves[u] > RING_LEAVES;
  if (!hubs) {
    free(deg), free(nb), free(leaves), free(ringed);
    rows_core(in, page, out);
    return;
  }
  /* the graph without the ringed one-ports (in order), each hub's ring */
  int *node = bg_xcalloc((size_t)n + 1, sizeof *node), *local = bg_xcalloc((size_t)n + 1, sizeof *local), pn = 0;
  for (int v = 0; v < n; v++) {
    ringed[v] = ringed[v] && leaves[nb[v]] > RING_LEAVES; /* then: a one-port of a hub with a ring */
    if (!ringed[v]) local[v] = pn, node[pn++] = v;
  }
  int *edge = bg_xcalloc((size_t)in->nedge + 1, sizeof *edge), *link = bg_xcalloc((size_t)in->nlink + 1, sizeof *link);
  int pe = 0, pl = 0;
  for (int e = 0; e < in->nedge; e++)
    if (!ringed[in->tail[e]] && !ringed[in->head[e]]) edge[pe++] = e;
  for (int k = 0; k < in->nlink; k++)
    if (!ringed[in->link_a[k]] && !ringed[in->link_b[k]]) link[pl++] = k;
  part_in pi;
  part_input(in, node, pn, edge, pe, link, pl, local, &pi);
  /* each hub's one-ports, in node order, round it evenly (no position is
   * known yet to order them by) */
  int *adr = bg_xcalloc((size_t)n + 2, sizeof *adr), *member = bg_xcalloc((size_t)n + 1, sizeof *member);
  for (int v = 0; v < n; v++) adr[(ringed[v] ? nb[v] : n) + 1] += ringed[v];
  for (int u = 0; u < n; u++) adr[u + 1] += adr[u];
  int *fill = bg_xcalloc((size_t)n + 1, sizeof *fill);
  for (int v = 0; v < n; v++)
    if (ringed[v]) member[adr[nb[v]] + fill[nb[v]]++] = v;
  double *ox = bg_xcalloc((size_t)n + 1, sizeof *ox), *oy = bg_xcalloc((size_t)n + 1, sizeof *oy);
  double *ang = bg_xcalloc((size_t)n + 1, sizeof *ang), *rx = bg_xcalloc((size_t)n + 1, sizeof *rx);
  double *ry = bg_xcalloc((size_t)n + 1, sizeof *ry);
  for (int u = 0; u < n; u++) {
    int k = adr[u + 1] - adr[u];
    if (k == 0) continue;
    double w = 0, h = 0, hx, hy;
    for (int i = 0; i < k; i++) {
      int v = member[adr[u] + i];
      w = fmax(w, in->w[v]), h = fmax(h, in->h[v]);
      ang[i] = remainder(2 * 3.14159265358979323846 * (i + 0.5) / k, 2 * 3.14159265358979323846);
    }
    bg_layout_ring(k, ang, w, h, in->node_sep, in->node_sep, 15, rx, ry, &hx, &hy);
    for (int i = 0; i < k; i++) ox[member[adr[u] + i]] = rx[i], oy[member[adr[u] + i]] = ry[i];
    ((double *)pi.in.w)[local[u]] = fmax(in->w[u], 2 * hx);
    ((double *)pi.in.h)[local[u]] = fmax(in->h[u], 2 * hy);
  }
  bg_layout lay = {0};
  lay.x = bg_xcalloc((size_t)pn + 1, sizeof *lay.x), lay.y = bg_xcalloc((size_t)pn + 1, sizeof *lay.y);
  rows_core(&pi.in, page, &lay);
  for (int i = 0; i < pn; i++) out->x[node[i]] = lay.x[i], out->y[node[i]] = lay.y[i];
  for (int v = 0; v < n; v++)
    if (ringed[v]) out->x[v] = out->x[nb[v]] + ox[v], out->y[v] = out->y[nb[v]] + oy[v];
  out->width = lay.width, out->height = lay.height;
  free(lay.x), free(lay.y);
  part_input_free(&pi);
  free(deg), free(nb), free(leaves), free(ringed), free(node), free(local), free(edge), free(link);
  free(adr), free(member), free(fill), free(ox), free(oy), free(ang), free(rx), free(ry);
}

/* Each node's connected part, numbered by its lowest node; returns the count. */
static int parts_of(const bg_layout_in *in, int *part) {
  int n = in->nnode, *up = bg_xcalloc((size_t)n + 1, sizeof *up), np = 0;
  for (int v = 0; v < n; v++) up[v] = v;
  for (int e = 0; e < in->nedge; e++) {
    int a = in->tail[e], b = in->head[e];
    while (up[a] != a) a = up[a] = up[up[a]];
    while (up[b] != b) b = up[b] = up[up[b]];
    if (a != b) up[a > b ? a : b] = a < b ? a : b; /* the lower stays the root */
  }
  for (int v = 0; v < n; v++) {
    int r = v;
    while (up[r] != r) r = up[r] = up[up[r]];
    part[v] = r == v ? np++ : part[r]; /* a root is its part's lowest node: numbered first */
  }
  free(up);
  return np;
}

/* Disconnected parts are laid out each on its own (in one set of columns
 * their bands would interleave, and a part's folds cross the other's rows)
 * and packed on a skyline (bg_layout_pack), 2 × rank_sep apart, on a page
 * about 1.4 times as wide as high (at least the widest part). */
int bg_layout_rows(const bg_layout_in *in, bg_layout *out) {
  int n = in->nnode;
  out->x = bg_xcalloc((size_t)n + 1, sizeof *out->x);
  out->y = bg_xcalloc((size_t)n + 1, sizeof *out->y);
  out->spladr = bg_xcalloc((size_t)in->nedge + 1, sizeof *out->spladr);
  out->spln = bg_xcalloc((size_t)in->nedge + 1, sizeof *out->spln);
  int *part = bg_xcalloc((size_t)n + 1, sizeof *part), np = parts_of(in, part);
  if (np <= 1) {
    free(part);
    rows_one(in, 0, out);
    return 0;
  }
  /* each part's nodes, edges and links, in order (CSR by part) */
  int *nadr = bg_xcalloc((size_t)np + 2, sizeof *nadr), *eadr = bg_xcalloc((size_t)np + 2, sizeof *eadr);
  int *ladr = bg_xcalloc((size_t)np + 2, sizeof *ladr), *local = bg_xcalloc((size_t)n + 1, sizeof *local);
  for (int v = 0; v < n; v++) local[v] = nadr[part[v] + 1]++;
  for (int e = 0; e < in->nedge; e++) eadr[part[in->tail[e]] + 1]++;
  for (int k = 0; k < in->nlink; k++)
    if (part[in->link_a[k]] == part[in->link_b[k]]) ladr[part[in->link_a[k]] + 1]++;
  for (int p = 0; p < np; p++) nadr[p + 1] += nadr[p], eadr[p + 1] += eadr[p], ladr[p + 1] += ladr[p];
  int *node = bg_xcalloc((size_t)n + 1, sizeof *node), *edge = bg_xcalloc((size_t)in->nedge + 1, sizeof *edge);
  int *link = bg_xcalloc((size_t)in->nlink + 1, sizeof *link), *fill = bg_xcalloc((size_t)np + 1, sizeof *fill);
  for (int v = 0; v < n; v++) node[nadr[part[v]] + local[v]] = v;
  for (int e = 0; e < in->nedge; e++) edge[eadr[part[in->tail[e]]] + fill[part[in->tail[e]]]++] = e;
  for (int p = 0; p < np; p++) fill[p] = 0;
  for (int k = 0; k < in->nlink; k++)
    if (part[in->link_a[k]] == part[in->link_b[k]]) link[ladr[part[in->link_a[k]]] + fill[part[in->link_a[k]]]++] = k;
  part_in *pi = bg_xcalloc((size_t)np + 1, sizeof *pi);
  for (int p = 0; p < np; p++)
    part_input(in, node + nadr[p], nadr[p + 1] - nadr[p], edge + eadr[p], eadr[p + 1] - eadr[p], link + ladr[p],
               ladr[p + 1] - ladr[p], local, &pi[p]);
  double *partw = bg_xcalloc((size_t)np + 1, sizeof *partw), *parth = bg_xcalloc((size_t)np + 1, sizeof *parth);
  double area = 0, widest = 0, gap = 2 * in->rank_sep, page = 0;
  for (int pass = 0; pass < 2; pass++) { /* each part alone, then each with bands as wide as the page */
    area = widest = 0;
    for (int p = 0; p < np; p++) {
      int pn = pi[p].in.nnode;
      bg_layout lay = {0};
      lay.x = bg_xcalloc((size_t)pn + 1, sizeof *lay.x), lay.y = bg_xcalloc((size_t)pn + 1, sizeof *lay.y);
      rows_one(&pi[p].in, page, &lay);
      for (int i = 0; i < pn; i++) out->x[pi[p].node[i]] = lay.x[i], out->y[pi[p].node[i]] = lay.y[i];
      partw[p] = lay.width, parth[p] = lay.height;
      area += (lay.width + gap) * (lay.height + gap), widest = fmax(widest, lay.width);
      free(lay.x), free(lay.y);
    }
    page = sqrt(1.4 * area);
  }
  for (int p = 0; p < np; p++) part_input_free(&pi[p]);
  free(pi);
  double *dx = bg_xcalloc((size_t)np + 1, sizeof *dx), *dy = bg_xcalloc((size_t)np + 1, sizeof *dy);
  bg_layout_pack(np, partw, parth, fmax(widest, sqrt(1.4 * area)), gap, gap, dx, dy);
  for (int v = 0; v < n; v++) out->x[v] += dx[part[v]], out->y[v] += dy[part[v]];
  fit_box(in, out);
  free(part), free(nadr), free(eadr), free(ladr), free(local), free(node), free(edge), free(link), free(fill);
  free(partw), free(parth), free(dx), free(dy);
  return 0;
}
