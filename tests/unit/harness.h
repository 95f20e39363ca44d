/* SPDX-License-Identifier: BSD-3-Clause */
/* Minimal test harness: OK, INT_EQ, STR_EQ, DBL_NEAR; a test binary returns
 * non-zero when any check failed and prints "N passed, N failed". */
#ifndef BG_TEST_HARNESS_H
#define BG_TEST_HARNESS_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int bg_t_pass, bg_t_fail;

#define BG_T_REPORT(ok, ...)                                                   \
  do {                                                                         \
    if (ok) {                                                                  \
      bg_t_pass++;                                                             \
    } else {                                                                   \
      bg_t_fail++;                                                             \
      fprintf(stderr, "%s:%d: check failed: ", __FILE__, __LINE__);            \
      fprintf(stderr, __VA_ARGS__);                                            \
      fputc('\n', stderr);                                                     \
    }                                                                          \
  } while (0)

#define OK(c) BG_T_REPORT((c), "%s", #c)
#define INT_EQ(a, b)                                                           \
  do {                                                                         \
    long long a_ = (a), b_ = (b);                                              \
    BG_T_REPORT(a_ == b_, "%s == %s (%lld vs %lld)", #a, #b, a_, b_);          \
  } while (0)
#define STR_EQ(a, b)                                                           \
  do {                                                                         \
    const char *a_ = (a), *b_ = (b);                                           \
    BG_T_REPORT(a_ && b_ && strcmp(a_, b_) == 0, "%s == %s (\"%s\" vs \"%s\")", \
                #a, #b, a_ ? a_ : "(null)", b_ ? b_ : "(null)");               \
  } while (0)
#define DBL_NEAR(a, b, tol)                                                    \
  do {                                                                         \
    double a_ = (a), b_ = (b);                                                 \
    BG_T_REPORT(fabs(a_ - b_) <= (tol), "%s ~ %s (%.17g vs %.17g, tol %g)",    \
                #a, #b, a_, b_, (double)(tol));                                \
  } while (0)

/* Replaces the first `from` in the malloc'd text *src by `to` (model
 * variants); -1 with a message when `from` is not there. */
static inline int bg_t_replace(char **src, const char *from, const char *to) {
  char *p = strstr(*src, from);
  if (!p) { fprintf(stderr, "no '%s' in the model\n", from); return -1; }
  size_t nf = strlen(from), nt = strlen(to), len = strlen(*src), at = (size_t)(p - *src);
  char *s = malloc(len - nf + nt + 1);
  if (!s) return -1;
  memcpy(s, *src, at);
  memcpy(s + at, to, nt);
  strcpy(s + at + nt, p + nf);
  free(*src);
  *src = s;
  return 0;
}

static inline int bg_t_done(void) {
  printf("%d passed, %d failed\n", bg_t_pass, bg_t_fail);
  return bg_t_fail ? 1 : 0;
}
#endif
