/* SPDX-License-Identifier: BSD-3-Clause */
/* The cheapest orthogonal route over a grid of cells (issue 31): a leaf
 * under the grid pass (diagram_grid.c), for a bond between hubs that found
 * no straight run and no route of one or two corners. Such a bond was
 * drawn as one slanted line across whatever lay between: in a bridge (a
 * Wheatstone bridge, a diode bridge, an H-bridge) the fourth arm ran
 * diagonally through the middle and across another arm.
 *
 * Dijkstra over (cell, heading) in a window: each step costs 1 plus the
 * cell's extra cost, each corner `bend`, each crossing `cross`. A cell is
 * free, blocked, or another route's straight run that may be crossed at a
 * right angle only; a route turns only on a free cell, never back on
 * itself. The search is bounded by the window (the caller's: ends plus a
 * margin, at most a fixed number of cells), so the work per route is
 * O(cells log cells). */
#include <stdlib.h>

#include "base/arena.h"
#include "diagram/layout.h"

static const int step_x[4] = {1, 0, -1, 0}, step_y[4] = {0, 1, 0, -1};

typedef struct maze_heap {
  long long *k; /* cost << 32 | state: the least cost first, then the lower state (deterministic) */
  int n, cap;
} maze_heap;

static void heap_push(maze_heap *h, long long key) {
  if (h->n == h->cap) h->cap = h->cap ? 2 * h->cap : 256, h->k = bg_xrealloc(h->k, (size_t)h->cap * sizeof *h->k);
  int i = h->n++;
  while (i > 0 && h->k[(i - 1) / 2] > key) h->k[i] = h->k[(i - 1) / 2], i = (i - 1) / 2;
  h->k[i] = key;
}

static long long heap_pop(maze_heap *h) {
  long long top = h->k[0], last = h->k[--h->n];
  int i = 0;
  for (;;) {
    int c = 2 * i + 1;
    if (c >= h->n) break;
    if (c + 1 < h->n && h->k[c + 1] < h->k[c]) c++;
    if (h->k[c] >= last) break;
    h->k[i] = h->k[c], i = c;
  }
  if (h->n) h->k[i] = last;
  return top;
}

/* Whether a step heading dir may enter a cell of this kind. */
static int enterable(int kind, int dir) {
  return kind == BG_MAZE_FREE || (kind == BG_MAZE_CROSS_H && dir % 2 == 0) || (kind == BG_MAZE_CROSS_V && dir % 2 == 1);
}

int bg_maze_route(const bg_maze *mz, int sx, int sy, int sdirs, int tx, int ty, int tdirs, int (*corner)[2],
                  int max_corner, int *ncross) {
  int w = mz->w, h = mz->h;
  long long ncell = (long long)w * h;
  if (w <= 0 || h <= 0 || ncell > 1 << 22) return -1;
  int *dist = bg_xmalloc((size_t)ncell * 4 * sizeof(int)), *prev = bg_xmalloc((size_t)ncell * 4 * sizeof(int));
  int *kind = bg_xmalloc((size_t)ncell * sizeof(int)), *extra = bg_xmalloc((size_t)ncell * sizeof(int));
  for (long long c = 0; c < ncell; c++) {
    int x = mz->x0 + (int)(c % w), y = mz->y0 + (int)(c / w);
    kind[c] = (x == tx && y == ty) ? BG_MAZE_BLOCKED : mz->cell(mz->ctx, x, y, &extra[c]);
  }
  for (long long s = 0; s < 4 * ncell; s++) dist[s] = -1, prev[s] = -1;
  maze_heap hp = {0};
  int found = -1, tcell = (ty - mz->y0) * w + (tx - mz->x0);
  for (int d = 0; d < 4; d++) { /* the first step off the start, any heading it allows */
    int x = sx + step_x[d] - mz->x0, y = sy + step_y[d] - mz->y0;
    if (!(sdirs >> d & 1) || x < 0 || y < 0 || x >= w || y >= h) continue;
    int c = y * w + x;
    if (c == tcell && (tdirs >> d & 1)) { /* the ends side by side */
      found = 4 * c + d, dist[found] = 1;
      break;
    }
    if (!enterable(kind[c], d)) continue;
    int cost = 1 + extra[c] + (kind[c] != BG_MAZE_FREE ? mz->cross : 0), s = 4 * c + d;
    if (dist[s] < 0 || cost < dist[s]) dist[s] = cost, heap_push(&hp, (long long)cost << 32 | s);
  }
  while (found < 0 && hp.n) {
    long long top = heap_pop(&hp);
    int s = (int)(top & 0xffffffff), cost = (int)(top >> 32), c = s / 4, d = s % 4;
    if (cost != dist[s]) continue; /* a stale entry */
    if (c == tcell) {
      found = s;
      break;
    }
    int x = c % w, y = c / w;
    for (int nd = 0; nd < 4; nd++) {
      if (nd == (d + 2) % 4 || (nd != d && kind[c] != BG_MAZE_FREE)) continue; /* never back; turn on free cells */
      int nx = x + step_x[nd], ny = y + step_y[nd];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      int n = ny * w + nx, ns = 4 * n + nd;
      if (n == tcell ? !(tdirs >> nd & 1) : !enterable(kind[n], nd)) continue;
      int nc = cost + 1 + (nd != d ? mz->bend : 0) + (n == tcell ? 0 : extra[n]) +
               (n != tcell && kind[n] != BG_MAZE_FREE ? mz->cross : 0);
      if (dist[ns] >= 0 && dist[ns] <= nc) continue;
      dist[ns] = nc, prev[ns] = s;
      heap_push(&hp, (long long)nc << 32 | ns);
    }
  }
  int nc = -1;
  if (found >= 0) { /* back from the end: a corner wherever the heading changes */
    nc = 0;
    int crossings = 0;
    for (int s = found; s >= 0 && nc >= 0; s = prev[s]) {
      crossings += s / 4 != tcell && kind[s / 4] != BG_MAZE_FREE;
      int p = prev[s], pc = p / 4;
      if (p < 0) break;
      if (p % 4 != s % 4) {
        if (nc == max_corner)
          nc = -1;
        else
          corner[nc][0] = mz->x0 + pc % w, corner[nc++][1] = mz->y0 + pc / w;
      }
    }
    for (int i = 0; nc > 0 && i < nc / 2; i++) { /* start to end */
      int t0 = corner[i][0], t1 = corner[i][1];
      corner[i][0] = corner[nc - 1 - i][0], corner[i][1] = corner[nc - 1 - i][1];
      corner[nc - 1 - i][0] = t0, corner[nc - 1 - i][1] = t1;
    }
    if (ncross) *ncross = crossings;
  }
  free(hp.k), free(dist), free(prev), free(kind), free(extra);
  return nc;
}
