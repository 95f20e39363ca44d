/* SPDX-License-Identifier: BSD-3-Clause */
/* Breadth-first ranks for the layouts: a leaf under layout.c (dot's ranks)
 * and layout_rows.c (its columns), so neither calls the other's helpers. */
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "diagram/layout.h"

/* The outermost frame (cluster) of every node, -1 for the model's own;
 * NULL without frames. */
static int *outer_frames(const bg_layout_in *in) {
  if (!in->cluster || !in->cluster_parent) return NULL;
  int *top = bg_xcalloc((size_t)in->nnode + 1, sizeof *top);
  for (int v = 0; v < in->nnode; v++) {
    int c = in->cluster[v], guard = in->ncluster;
    while (c >= 0 && in->cluster_parent[c] >= 0 && guard-- > 0) c = in->cluster_parent[c];
    top[v] = c;
  }
  return top;
}

/* Breadth-first distance of every node from the roots (all at once; in->root
 * may be NULL); a component without a root starts from its
 * first node. order (nullable) receives the nodes in the order reached.
 * With frames (in->cluster), an instance is reached whole from where the
 * search first enters it: a later way in from outside is taken only once
 * the search has nothing else left (an instance not connected inside).
 * So where two ways round a ring meet, they meet between instances, not
 * in one: a ring of cells drawn as two rows had a cell's frame across both
 * rows, round its neighbour's nodes (issue 31). A tree has one way to each
 * node and keeps its plain distances. A dead end (a user state's
 * integrator, joined to the bonds it reads and the elements it modulates)
 * is reached but not gone through: its edges made a feedback loop a short
 * cut, and the power chain folded back (a loudspeaker under PI control
 * drew its cone under its coil). */
int *bg_layout_depths(const bg_layout_in *in, int *order) {
  int n = in->nnode, m = in->nedge;
  int *adr = bg_xcalloc((size_t)n + 1, sizeof *adr), *adj = bg_xcalloc(2 * (size_t)m + 1, sizeof *adj);
  int *fill = bg_xcalloc((size_t)n + 1, sizeof *fill), *depth = bg_xcalloc((size_t)n + 1, sizeof *depth);
  int *queue = bg_xcalloc((size_t)n + 1, sizeof *queue);
  int *top = outer_frames(in), *entered = NULL, *later = NULL, *later_d = NULL, nlater = 0;
  if (top) {
    entered = bg_xcalloc((size_t)in->ncluster + 1, sizeof *entered);
    later = bg_xcalloc(2 * (size_t)m + 1, sizeof *later), later_d = bg_xcalloc(2 * (size_t)m + 1, sizeof *later_d);
    for (int c = 0; c < in->ncluster; c++) entered[c] = -1;
  }
  for (int i = 0; i < m; i++) adr[in->tail[i] + 1]++, adr[in->head[i] + 1]++;
  for (int v = 0; v < n; v++) adr[v + 1] += adr[v];
  for (int i = 0; i < m; i++) {
    adj[adr[in->tail[i]] + fill[in->tail[i]]++] = in->head[i];
    adj[adr[in->head[i]] + fill[in->head[i]]++] = in->tail[i];
  }
  for (int v = 0; v < n; v++) depth[v] = -1;
  int qh = 0, qt = 0;
#define REACH(v, dv)                                                                                   \
  do {                                                                                                 \
    depth[v] = (dv), queue[qt++] = (v);                                                                \
    if (top && top[v] >= 0 && entered[top[v]] < 0) entered[top[v]] = (dv);                            \
  } while (0)
  for (int s = 0; s < n; s++)
    if (in->root && in->root[s]) REACH(s, 0); /* one search from all roots */
  for (int s = 0; s <= n; s++) {
    for (;;) {
      for (; qh < qt; qh++) {
        int u = queue[qh];
        if (in->dead_end && in->dead_end[u] && !(in->root && in->root[u])) continue;
        for (int k = adr[u]; k < adr[u + 1]; k++) {
          int w = adj[k], c = top ? top[w] : -1;
          if (depth[w] >= 0) continue;
          if (c >= 0 && c != top[u] && entered[c] >= 0 && entered[c] != depth[u] + 1)
            later[nlater] = w, later_d[nlater++] = depth[u] + 1; /* into an instance entered elsewhere */
          else
            REACH(w, depth[u] + 1);
        }
      }
      int more = 0; /* the ways in held back, for what the search did not reach from inside */
      for (int i = 0; i < nlater; i++)
        if (depth[later[i]] < 0) {
          REACH(later[i], later_d[i]);
          more = 1;
        }
      nlater = 0;
      if (!more) break;
    }
    if (s < n && depth[s] < 0) REACH(s, 0); /* a component without roots */
  }
#undef REACH
  if (order) memcpy(order, queue, (size_t)n * sizeof *order);
  free(adr), free(adj), free(fill), free(queue), free(top), free(entered), free(later), free(later_d);
  return depth;
}
