/* SPDX-License-Identifier: BSD-3-Clause */
/* The CSV number printer (issue 34): bg_num_format (src/base/numfmt.c, exact
 * integer arithmetic for normal doubles 1e-15 <= |v| < 1e16, the
 * print-and-read-back loop outside that range) against the reference
 * definition, the loop itself ("%.Ng" with N from 15 up, until strtod reads
 * the same double back), on N random doubles of three kinds. Prints ns a
 * number for both, the ratio, and the count of texts that differ (0: the
 * same bytes). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/strbuf.h"

static void reference(char *buf, size_t size, double v) {
  if (v == 0) {
    snprintf(buf, size, "%s", signbit(v) ? "-0" : "0");
    return;
  }
  for (int prec = 15; prec <= 17; prec++) {
    snprintf(buf, size, "%.*g", prec, v);
    if (strtod(buf, NULL) == v) return;
  }
}

static uint64_t rng = 88172645463325252ull;
static double uniform(void) { /* xorshift64: the same numbers on every machine */
  rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
  return (double)(rng >> 11) / 9007199254740992.0;
}

static double draw(int kind) {
  switch (kind) {
  case 0: return (uniform() - 0.5) * pow(10, (int)(uniform() * 20) - 10); /* a simulation's values */
  case 1: return (uniform() - 0.5) * 1e-18;                               /* round-off near zero */
  default: return floor(uniform() * 1e6);                                 /* integers (time steps) */
  }
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int main(int argc, char **argv) {
  long n = argc > 1 ? atol(argv[1]) : 10000000L;
  static const char *names[] = {"values 1e-10..1e10", "tiny (< 1e-15)", "integers"};
  printf("%-20s %12s %12s %8s %10s\n", "doubles", "bg_num ns", "loop ns", "ratio", "differ");
  for (int kind = 0; kind < 3; kind++) {
    double *v = malloc((size_t)n * sizeof *v);
    for (long i = 0; i < n; i++) v[i] = draw(kind);
    char a[40], b[40];
    unsigned long sink = 0;
    double t0 = now();
    for (long i = 0; i < n; i++) bg_num_format(a, sizeof a, v[i], 15), sink += (unsigned char)a[0];
    double t1 = now();
    for (long i = 0; i < n; i++) reference(b, sizeof b, v[i]), sink += (unsigned char)b[0];
    double t2 = now();
    long differ = 0;
    for (long i = 0; i < n; i += 1 + n / 1000000) { /* up to a million compared */
      bg_num_format(a, sizeof a, v[i], 15), reference(b, sizeof b, v[i]);
      differ += strcmp(a, b) != 0;
    }
    printf("%-20s %12.1f %12.1f %7.1fx %10ld%s\n", names[kind], 1e9 * (t1 - t0) / n,
           1e9 * (t2 - t1) / n, (t2 - t1) / (t1 - t0), differ, sink == 42 ? " " : "");
    free(v);
  }
  return 0;
}
