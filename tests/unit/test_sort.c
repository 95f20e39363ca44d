/* SPDX-License-Identifier: BSD-3-Clause */
/* The sorts of src/base/sort.c against their definitions: bg_sort_keyed
 * (by value, ties by index, whatever order the input came in), checked on
 * random values with many ties against an insertion sort written out here;
 * bg_sort_doubles; bg_natural_cmp on names with digits. */
#include <stdlib.h>

#include "base/sort.h"
#include "harness.h"

static unsigned seed = 12345u;
static unsigned next(void) { return seed = seed * 1103515245u + 12345u, (seed >> 16) & 0x7fff; }

/* Whether a comes before b by the definition: key, then index. */
static int before(const bg_keyed *a, const bg_keyed *b) { return a->key < b->key || (a->key == b->key && a->i < b->i); }

static void keyed_against_reference(int n, int distinct) {
  bg_keyed *v = malloc((size_t)n * sizeof *v), *w = malloc((size_t)n * sizeof *w);
  for (int k = 0; k < n; k++) v[k] = w[k] = (bg_keyed){(double)(next() % (unsigned)distinct) - distinct / 2.0, k};
  for (int k = n - 1; k > 0; k--) { /* shuffled: the order in must not matter */
    int j = (int)(next() % (unsigned)(k + 1));
    bg_keyed t = v[k];
    v[k] = v[j], v[j] = t;
  }
  bg_sort_keyed(v, (size_t)n);
  for (int k = 1; k < n; k++) { /* the reference: an insertion sort by the definition */
    bg_keyed x = w[k];
    int j = k - 1;
    for (; j >= 0 && before(&x, &w[j]); j--) w[j + 1] = w[j];
    w[j + 1] = x;
  }
  int same = 1;
  for (int k = 0; k < n; k++) same &= v[k].key == w[k].key && v[k].i == w[k].i;
  BG_T_REPORT(same, "bg_sort_keyed of %d values, %d distinct, as the definition orders them", n, distinct);
  free(v), free(w);
}

int main(void) {
  keyed_against_reference(0, 1);
  keyed_against_reference(1, 1);
  keyed_against_reference(2, 1); /* one tie: by index */
  for (int n = 3; n <= 600; n = n * 3 + 1) {
    keyed_against_reference(n, 1);
    keyed_against_reference(n, 5);
    keyed_against_reference(n, 10 * n);
  }
  double d[] = {3, -1, 2.5, -1, 0, 7};
  bg_sort_doubles(d, sizeof d / sizeof d[0]);
  OK(d[0] == -1 && d[1] == -1 && d[2] == 0 && d[3] == 2.5 && d[4] == 3 && d[5] == 7);
  OK(bg_natural_cmp("R2", "R10") < 0);
  OK(bg_natural_cmp("x007", "x7") == 0);
  OK(bg_natural_cmp("C1a", "C1b") < 0);
  OK(bg_natural_cmp("k", "k1") < 0);
  printf("%d passed, %d failed\n", bg_t_pass, bg_t_fail);
  return bg_t_fail != 0;
}
