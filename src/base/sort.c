/* SPDX-License-Identifier: BSD-3-Clause */
/* glibc's qsort_r behind a portable name (see sort.h). */
#define _GNU_SOURCE
#include <stdlib.h>

#include "base/sort.h"

void bg_sort(void *base, size_t n, size_t size, bg_sort_cmp cmp, void *ctx) {
  if (n > 1) qsort_r(base, n, size, cmp, ctx);
}

static int is_digit(char c) { return c >= '0' && c <= '9'; }

int bg_natural_cmp(const char *a, const char *b) {
  while (*a && *b) {
    if (is_digit(*a) && is_digit(*b)) {
      while (*a == '0') a++;
      while (*b == '0') b++;
      size_t na = 0, nb = 0;
      while (is_digit(a[na])) na++;
      while (is_digit(b[nb])) nb++;
      if (na != nb) return na < nb ? -1 : 1;
      for (size_t i = 0; i < na; i++)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
      a += na, b += nb;
    } else {
      if (*a != *b) return (unsigned char)*a < (unsigned char)*b ? -1 : 1;
      a++, b++;
    }
  }
  return (*a != 0) - (*b != 0);
}

static int by_value(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

void bg_sort_doubles(double *v, size_t n) {
  if (n > 1) qsort(v, n, sizeof *v, by_value);
}

static int by_key(const void *a, const void *b, void *ctx) {
  (void)ctx;
  const bg_keyed *p = a, *q = b;
  if (p->key != q->key) return (p->key > q->key) - (p->key < q->key);
  return p->i - q->i;
}

void bg_sort_keyed(bg_keyed *v, size_t n) { bg_sort(v, n, sizeof *v, by_key, NULL); }
