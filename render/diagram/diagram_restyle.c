/* SPDX-License-Identifier: BSD-3-Clause */
/* One arrangement in every style: the bond routes of the reference style's
 * layout drawn in another style's sizes (issue 31). The grid pass and rows
 * lay a model out in the reference style's boxes, so every style puts the
 * nodes in the same rows and columns; the bond router (diagram_route_bonds.c)
 * ran again in each style's own sizes, and there a route could take another
 * corner of its junction (a held-out model's bond 53 left the left-hand
 * junction upwards in the default style and downwards in slides) and push
 * a one-port to its other side: of 100 held-out property models, 48 label
 * pairs in another order in print or slides. Here the routes of the
 * reference are carried over instead, corner for corner.
 *
 * A corner of a route lies among the nodes: beside a box, in a channel
 * between two columns, round the outside. Along each axis, the reference's
 * coordinates map to the style's by a piecewise linear function through
 * the boxes' edges and centres in both (the knots), so a corner just right
 * of a box's edge there is just right of it here and one between two
 * columns stays between them. Nodes the two layouts place differently (a
 * one-port a style could not move where the reference did) would bend that
 * function back on itself: the knots kept are the longest run that rises in
 * both, the others dropped. Each connected part has its own function (the
 * parts are packed in each style's sizes, not in one order). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

typedef struct knot {
  int part;
  double r, s; /* a coordinate in the reference, the same place in the style */
} knot;

static int by_part_then_r(const void *a, const void *b) {
  const knot *p = a, *q = b;
  if (p->part != q->part) return p->part < q->part ? -1 : 1;
  if (p->r != q->r) return p->r < q->r ? -1 : 1;
  return (p->s > q->s) - (p->s < q->s);
}

static int find(int *up, int v) {
  while (up[v] != v) v = up[v] = up[up[v]];
  return v;
}

/* Per node its connected part (the root of its drawn bonds' union-find). */
static int *parts_of(const bg_diagram_layout *L) {
  const bg_model *m = L->m;
  int *up = bg_xmalloc(((size_t)L->nnode + 1) * sizeof *up);
  for (int v = 0; v < L->nnode; v++) up[v] = v;
  for (int b = 0; b < m->nbond; b++) {
    int t = find(up, L->node_of[m->bond_tail[b]]), h = find(up, L->node_of[m->bond_head[b]]);
    if (t != h) up[t < h ? h : t] = t < h ? t : h;
  }
  for (int v = 0; v < L->nnode; v++) up[v] = find(up, v);
  return up;
}

/* Whether node v is drawn with a box of its own in L. */
static int own_box(const bg_diagram_layout *L, int v) {
  return L->node_of[v] == v && (!L->rep || L->rep[v] == v) && bg_node_shown(L, v) && L->nw[v] > 0 && L->nh[v] > 0;
}

/* The knots along one axis (y: the vertical one), sorted by part and then
 * by reference coordinate, equal coordinates merged, the longest run that
 * rises in both kept (patience sorting: O(n log n)). Returns how many. */
static int axis_knots(const bg_diagram_layout *L, const bg_diagram_layout *R, const int *part, int y, knot **out) {
  int n = 0;
  knot *k = bg_xmalloc((3 * (size_t)L->nnode + 1) * sizeof *k);
  for (int v = 0; v < L->nnode; v++) {
    if (!own_box(L, v) || !own_box(R, v)) continue;
    double rc = y ? R->ny[v] : R->nx[v], rh = (y ? R->nh[v] : R->nw[v]) / 2;
    double sc = y ? L->ny[v] : L->nx[v], sh = (y ? L->nh[v] : L->nw[v]) / 2;
    for (int e = -1; e <= 1; e++) k[n++] = (knot){part[v], rc + e * rh, sc + e * sh};
  }
  qsort(k, (size_t)n, sizeof *k, by_part_then_r);
  int m = 0;
  for (int i = 0; i < n;) { /* one knot per reference coordinate: the mean of its places */
    int j = i;
    double sum = 0;
    for (; j < n && k[j].part == k[i].part && k[j].r == k[i].r; j++) sum += k[j].s;
    k[m] = k[i], k[m++].s = sum / (j - i), i = j;
  }
  /* per part the longest run rising in s: tail[l] the last knot of the
   * best run of length l + 1, prev[] its chain */
  int *tail = bg_xmalloc(((size_t)m + 1) * sizeof *tail), *prev = bg_xmalloc(((size_t)m + 1) * sizeof *prev);
  unsigned char *keep = bg_xcalloc((size_t)m + 1, 1);
  for (int i = 0; i < m;) {
    int j = i, len = 0;
    for (; j < m && k[j].part == k[i].part; j++) {
      int lo = 0, hi = len;
      while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (k[tail[mid]].s < k[j].s) lo = mid + 1;
        else hi = mid;
      }
      prev[j] = lo > 0 ? tail[lo - 1] : -1, tail[lo] = j;
      if (lo == len) len++;
    }
    for (int c = len ? tail[len - 1] : -1; c >= 0; c = prev[c]) keep[c] = 1;
    i = j;
  }
  n = 0;
  for (int i = 0; i < m; i++)
    if (keep[i]) k[n++] = k[i];
  free(tail), free(prev), free(keep);
  *out = k;
  return n;
}

/* The first of knots k[lo..hi) (sorted) that comes after coordinate r of
 * part p: a binary search, O(log n) (a part of 10 000 boxes has 30 000
 * knots, and every corner of its routes is looked up). */
static int after(const knot *k, int lo, int hi, int p, double r) {
  while (lo < hi) {
    int mid = (lo + hi) / 2;
    if (k[mid].part < p || (k[mid].part == p && k[mid].r <= r)) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/* Coordinate r of part p in the reference mapped into the style by the
 * knots k[0..n) (sorted): linear between the two knots round it, beyond
 * the outermost ones at the same distance. */
static double axis_map(const knot *k, int n, int p, double r) {
  int first = after(k, 0, n, p, -INFINITY), last = after(k, first, n, p, INFINITY);
  int at = after(k, first, last, p, r);
  if (first == last) return r; /* no knot: no box in the part */
  if (at == first) return k[first].s + (r - k[first].r);
  if (at == last) return k[last - 1].s + (r - k[last - 1].r);
  const knot *a = &k[at - 1], *b = &k[at];
  return a->s + (b->s - a->s) * (r - a->r) / (b->r - a->r);
}

void bg_restyle_routes(bg_diagram_layout *L, const bg_diagram_layout *R) {
  const bg_model *m = L->m;
  int nb = m->nbond;
  /* the one-ports the reference mirrored through their hubs, first: the
   * knots pair each node's places after that */
  for (int v = 0; v < L->nnode && v < m->nelem; v++) {
    if (!R->mirrored[v] || m->elem_nbond[v] != 1) continue;
    int b = m->elem_bonds[m->elem_bondadr[v]], o = m->bond_tail[b] == v ? m->bond_head[b] : m->bond_tail[b];
    int n = L->node_of[o];
    L->nx[v] = 2 * L->nx[n] - L->nx[v], L->ny[v] = 2 * L->ny[n] - L->ny[v];
  }
  int *part = parts_of(L);
  knot *kx, *ky;
  int nx = axis_knots(L, R, part, 0, &kx), ny = axis_knots(L, R, part, 1, &ky);
  bg_layout *l = &L->lay;
  const bg_layout *rl = &R->lay;
  int ne = l->nedge > nb ? l->nedge : nb, total = 0;
  for (int b = 0; b < ne; b++)
    total += b < nb && R->rerouted[b] ? (rl->bendn ? rl->bendn[b] : 0) : (l->bendn ? l->bendn[b] : 0);
  int *adr = bg_xcalloc((size_t)ne + 1, sizeof *adr), *cnt = bg_xcalloc((size_t)ne + 1, sizeof *cnt);
  double *bx = bg_xcalloc((size_t)total + 1, sizeof *bx), *by = bg_xcalloc((size_t)total + 1, sizeof *by);
  int used = 0;
  for (int b = 0; b < ne; b++) {
    adr[b] = used;
    if (b < nb && R->rerouted[b]) {
      int p = part[L->node_of[m->bond_tail[b]]], n = rl->bendn ? rl->bendn[b] : 0;
      for (int k = 0; k < n; k++, used++) {
        bx[used] = axis_map(kx, nx, p, rl->bendx[rl->bendadr[b] + k]);
        by[used] = axis_map(ky, ny, p, rl->bendy[rl->bendadr[b] + k]);
      }
      cnt[b] = n;
    } else if (l->bendn) {
      for (int k = 0; k < l->bendn[b]; k++, used++)
        bx[used] = l->bendx[l->bendadr[b] + k], by[used] = l->bendy[l->bendadr[b] + k];
      cnt[b] = l->bendn[b];
    }
  }
  free(l->bendadr), free(l->bendn), free(l->bendx), free(l->bendy);
  l->bendadr = adr, l->bendn = cnt, l->bendx = bx, l->bendy = by, l->nbend = used;
  free(kx), free(ky), free(part);
}
