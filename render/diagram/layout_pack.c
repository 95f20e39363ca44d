/* SPDX-License-Identifier: BSD-3-Clause */
/* Disconnected parts packed on a page (issue 31): a leaf under the grid
 * pass (diagram_grid.c, whose units are grid cells) and the rows layout
 * (layout_rows.c, points), which had each written the same skyline and
 * the same choice of order.
 *
 * Each part, in the order given, goes where it sits highest on the outline
 * of those placed (then leftmost), so a part beside a taller one fills the
 * room below its shorter neighbours, where shelves left it empty. The
 * outline is a list of segments [x0, x1) at height top. The highest place
 * for a part is always at a segment's start: moved left within a segment,
 * a part covers no higher ground than before and can only leave higher
 * ground on its right; so only the starts are tried. Work: parts ×
 * segments, each part adding at most two segments. */
#include <math.h>
#include <stdlib.h>

#include "base/arena.h"
#include "base/sort.h"
#include "diagram/layout.h"

typedef struct sky_seg {
  double x0, x1, top;
} sky_seg;

/* Part order[i] (of n) where it sits highest on the outline of those
 * placed, then leftmost, hgap to its right and vgap below it kept free; its
 * corner into x[p], y[p]. Returns the area of the box the parts fill. */
static double skyline(int n, const int *order, const double *w, const double *h, double page, double hgap,
                      double vgap, double *x, double *y) {
  int cap = 2 * n + 2, ns = 1;
  sky_seg *sky = bg_xcalloc((size_t)cap, sizeof *sky), *next = bg_xcalloc((size_t)cap, sizeof *next);
  sky[0] = (sky_seg){0, 1e300, 0};
  double used_w = 0, used_h = 0;
  for (int i = 0; i < n; i++) {
    int p = order[i];
    double span = w[p] + hgap, best_y = 1e300, best_x = 0;
    for (int a = 0; a < ns; a++) {
      double at = sky[a].x0, top = 0;
      if (a > 0 && at + w[p] > page) break; /* past the page's right edge (the first always goes) */
      for (int z = a; z < ns && sky[z].x0 < at + span && top < best_y; z++) top = fmax(top, sky[z].top);
      if (top < best_y) best_y = top, best_x = at;
    }
    x[p] = best_x, y[p] = best_y;
    used_w = fmax(used_w, best_x + w[p]), used_h = fmax(used_h, best_y + h[p]);
    /* the segments under [best_x, best_x + span) become one at the part's top */
    sky_seg put = {best_x, best_x + span, best_y + h[p] + vgap};
    int nn = 0, done = 0;
    for (int a = 0; a < ns; a++) {
      sky_seg s = sky[a];
      if (s.x1 <= put.x0 || s.x0 >= put.x1) {
        if (s.x0 >= put.x1 && !done) next[nn++] = put, done = 1;
        next[nn++] = s;
        continue;
      }
      if (s.x0 < put.x0) next[nn++] = (sky_seg){s.x0, put.x0, s.top};
      if (!done) next[nn++] = put, done = 1;
      if (s.x1 > put.x1) next[nn++] = (sky_seg){put.x1, s.x1, s.top};
    }
    sky_seg *t = sky;
    sky = next, next = t, ns = nn;
  }
  free(sky), free(next);
  return used_w * used_h;
}

/* Larger key first, then the lower index. */
static int larger_first(const void *a, const void *b, void *ctx) {
  const double *key = ctx;
  int p = *(const int *)a, q = *(const int *)b;
  return key[p] != key[q] ? (key[p] > key[q] ? -1 : 1) : p - q;
}

/* The tallest first, then the widest first: the order that fills the
 * smaller box is kept (neither wins on every model: docs/drawing.md,
 * "disconnected parts packed"). */
double bg_layout_pack(int n, const double *w, const double *h, double page, double hgap, double vgap, double *x,
                      double *y) {
  int *order = bg_xcalloc((size_t)n + 1, sizeof *order);
  double *wx = bg_xcalloc((size_t)n + 1, sizeof *wx), *wy = bg_xcalloc((size_t)n + 1, sizeof *wy);
  for (int i = 0; i < n; i++) order[i] = i;
  bg_sort(order, (size_t)n, sizeof *order, larger_first, (void *)h);
  double area = skyline(n, order, w, h, page, hgap, vgap, x, y);
  for (int i = 0; i < n; i++) order[i] = i;
  bg_sort(order, (size_t)n, sizeof *order, larger_first, (void *)w);
  double wide = skyline(n, order, w, h, page, hgap, vgap, wx, wy);
  if (wide < area) {
    for (int i = 0; i < n; i++) x[i] = wx[i], y[i] = wy[i];
    area = wide;
  }
  free(order), free(wx), free(wy);
  return area;
}
