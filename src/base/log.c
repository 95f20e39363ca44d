/* SPDX-License-Identifier: BSD-3-Clause */
/* The message sink (log.h): formatting once, only when someone listens. */
#include "base/log.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

int bg_log_on(const bg_log *l, bg_log_level level) {
  if (!l || !l->fn) return 0;
  if (level == BG_LOG_PROGRESS) return l->verbose >= 1;
  if (level == BG_LOG_DETAIL) return l->verbose >= 2;
  return 1;
}

void bg_logf(const bg_log *l, bg_log_level level, const char *fmt, ...) {
  if (!bg_log_on(l, level)) return;
  char small[512];
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(small, sizeof small, fmt, ap);
  va_end(ap);
  if (n < 0) return;
  if ((size_t)n < sizeof small) {
    l->fn(l->ctx, level, small);
    return;
  }
  char *big = malloc((size_t)n + 1);
  if (!big) return;
  va_start(ap, fmt);
  vsnprintf(big, (size_t)n + 1, fmt, ap);
  va_end(ap);
  l->fn(l->ctx, level, big);
  free(big);
}
