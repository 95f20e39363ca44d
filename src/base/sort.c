/* SPDX-License-Identifier: BSD-3-Clause */
/* glibc's qsort_r behind a portable name (see sort.h). */
#define _GNU_SOURCE
#include <stdlib.h>

#include "base/sort.h"

void bg_sort(void *base, size_t n, size_t size, bg_sort_cmp cmp, void *ctx) {
  if (n > 1) qsort_r(base, n, size, cmp, ctx);
}
