/* SPDX-License-Identifier: BSD-3-Clause */
/* Breadth-first ranks for the layouts: a leaf under layout.c (dot's ranks)
 * and layout_rows.c (its columns), so neither calls the other's helpers. */
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "diagram/layout.h"

/* Breadth-first distance of every node from the roots (all at once; in->root
 * may be NULL); a component without a root starts from its
 * first node. order (nullable) receives the nodes in the order reached. */
int *bg_layout_depths(const bg_layout_in *in, int *order) {
  int n = in->nnode, m = in->nedge;
  int *adr = bg_xcalloc((size_t)n + 1, sizeof *adr), *adj = bg_xcalloc(2 * (size_t)m + 1, sizeof *adj);
  int *fill = bg_xcalloc((size_t)n + 1, sizeof *fill), *depth = bg_xcalloc((size_t)n + 1, sizeof *depth);
  int *queue = bg_xcalloc((size_t)n + 1, sizeof *queue);
  for (int i = 0; i < m; i++) adr[in->tail[i] + 1]++, adr[in->head[i] + 1]++;
  for (int v = 0; v < n; v++) adr[v + 1] += adr[v];
  for (int i = 0; i < m; i++) {
    adj[adr[in->tail[i]] + fill[in->tail[i]]++] = in->head[i];
    adj[adr[in->head[i]] + fill[in->head[i]]++] = in->tail[i];
  }
  for (int v = 0; v < n; v++) depth[v] = -1;
  int qh = 0, qt = 0;
  for (int s = 0; s < n; s++)
    if (in->root && in->root[s]) depth[s] = 0, queue[qt++] = s; /* one search from all roots */
  for (int s = 0; s <= n; s++) {
    for (; qh < qt; qh++)
      for (int k = adr[queue[qh]]; k < adr[queue[qh] + 1]; k++)
        if (depth[adj[k]] < 0) depth[adj[k]] = depth[queue[qh]] + 1, queue[qt++] = adj[k];
    if (s < n && depth[s] < 0) depth[s] = 0, queue[qt++] = s; /* a component without roots */
  }
  if (order) memcpy(order, queue, (size_t)n * sizeof *order);
  free(adr), free(adj), free(fill), free(queue);
  return depth;
}
