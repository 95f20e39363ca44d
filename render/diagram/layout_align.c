/* SPDX-License-Identifier: BSD-3-Clause */
/* Boxes in a fixed order along a line, each as near its wish as the order
 * and the gaps allow: a leaf under layout_rows.c, which lines each column's
 * nodes up with their parents so that bonds run level where they can.
 *
 * With c[i] the gaps summed up to box i, x[i] = z[i] + c[i] keeps every gap
 * exactly when z is non-decreasing, so the placement is an isotonic
 * regression of target[i] - c[i]. It minimises the summed distance |x - wish|
 * (not its square): the median of a pooled block is one of its members'
 * wishes, so in every block at least one box sits exactly where it wanted
 * (a bond exactly level) rather than every box a little off. Pool adjacent
 * violators: each box a block; while a block's median lies above the next
 * one's, the two merge (their wishes kept sorted, merged in O(size)).
 * Limits on the first and the last box's place bound every z alike, and
 * for an isotonic regression the bounded optimum is the free one clamped. */
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "diagram/layout.h"

/* Merges the sorted runs v[a..b) and v[b..e) in place, through tmp. */
static void merge_runs(double *v, int a, int b, int e, double *tmp) {
  memcpy(tmp, v + a, (size_t)(b - a) * sizeof *tmp);
  int i = 0, j = b, k = a, ni = b - a;
  while (i < ni && j < e) v[k++] = tmp[i] <= v[j] ? tmp[i++] : v[j++];
  while (i < ni) v[k++] = tmp[i++];
}

void bg_layout_align(int n, const double *wish, const double *gap, double lo, double hi, double *x) {
  if (n <= 0) return;
  double *c = bg_xcalloc((size_t)n, sizeof *c), *pool = bg_xcalloc((size_t)n, sizeof *pool);
  double *tmp = bg_xcalloc((size_t)n, sizeof *tmp), *med = bg_xcalloc((size_t)n, sizeof *med);
  int *start = bg_xcalloc((size_t)n + 1, sizeof *start), nb = 0;
  for (int i = 0; i < n; i++) {
    c[i] = i ? c[i - 1] + gap[i] : 0;
    pool[i] = wish[i] - c[i];
    start[nb] = i, med[nb] = pool[i], nb++;
    while (nb > 1 && med[nb - 2] > med[nb - 1]) {
      merge_runs(pool, start[nb - 2], start[nb - 1], i + 1, tmp);
      nb--;
      med[nb - 1] = pool[start[nb - 1] + (i + 1 - start[nb - 1]) / 2]; /* the upper median: a tie
                                                                          leaves the earlier box at its wish */
    }
  }
  start[nb] = n;
  /* within the limits: the isotonic optimum clamped (every z between
   * the first's floor and the last's ceiling), the floor first */
  double ceil = hi - c[n - 1];
  for (int b = 0; b < nb; b++) {
    double z = med[b] > ceil ? ceil : med[b];
    z = z < lo ? lo : z;
    for (int i = start[b]; i < start[b + 1]; i++) x[i] = z + c[i];
  }
  free(c), free(pool), free(tmp), free(med), free(start);
}
