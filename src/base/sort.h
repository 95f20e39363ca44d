/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_sort: qsort with a context argument for the comparison, so that no
 * sort in the engine keeps its context in a global (two runs on two threads
 * must not share one). It is glibc's qsort_r: the same algorithm as qsort,
 * so every order the engine produced with qsort (ties and comparisons with a
 * tolerance included) stays the same byte for byte. qsort_r is a GNU
 * extension; this file is the one place that asks for it. */
#ifndef BG_SORT_H
#define BG_SORT_H
#include <stddef.h>

typedef int (*bg_sort_cmp)(const void *a, const void *b, void *ctx);
void bg_sort(void *base, size_t n, size_t size, bg_sort_cmp cmp, void *ctx);
/* Names in natural order: runs of digits compare as numbers (R2 before R10,
 * x007 as x7). The tie-break of choices that must not follow the order of a
 * model's statements (docs/causality.md, "Ties"). */
int bg_natural_cmp(const char *a, const char *b);
/* v[0..n) in increasing order (NaN-free: the callers drop them). */
void bg_sort_doubles(double *v, size_t n);
/* A value and the index it belongs to; bg_sort_keyed puts v[0..n) in
 * increasing order of key, ties by index (an order that does not depend on
 * the sort's own). */
typedef struct bg_keyed {
  double key;
  int i;
} bg_keyed;
void bg_sort_keyed(bg_keyed *v, size_t n);
#endif
