/* SPDX-License-Identifier: BSD-3-Clause */
/* The CSV number printer (issue 34): bg_num_format (src/base/numfmt.c, exact
 * big-integer arithmetic for every finite double) against the reference
 * definition, the loop it replaced ("%.Ng" with N from 15 up, until strtod
 * reads the same double back), on N random doubles of each of six kinds.
 * Prints ns a number for both (CPU time, each function once on every value,
 * in chunks), the ratio, and the count of texts that differ: every text is
 * compared (0: the same bytes). NUMFMT_SRC in numfmt_bench.sh builds it with
 * another printer (the one before, for a before/after table). */
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
static uint64_t next(void) { /* xorshift64: the same numbers on every machine */
  rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
  return rng;
}
static double uniform(void) { return (double)(next() >> 11) / 9007199254740992.0; }

static double from_bits(uint64_t b) {
  double v;
  memcpy(&v, &b, sizeof v);
  return v;
}

static double draw(int kind) {
  switch (kind) {
  case 0: return (uniform() - 0.5) * pow(10, (int)(uniform() * 20) - 10); /* a simulation's values */
  case 1: return (uniform() - 0.5) * 1e-18;                               /* round-off near zero */
  case 2: return floor(uniform() * 1e6);                                  /* integers (time steps) */
  case 3: { /* random bit patterns of every finite exponent, subnormals included */
    uint64_t b;
    do b = next(); while (((b >> 52) & 0x7ff) == 0x7ff);
    return from_bits(b);
  }
  case 4: return from_bits(next() & ((1ull << 52) - 1)) * (next() & 1 ? 1 : -1); /* subnormals */
  default: return (uniform() - 0.5) * pow(10, 16 + (int)(uniform() * 290)); /* huge, 1e16..1e306 */
  }
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

enum { CHUNK = 65536, TEXT = 40 };

/* numfmt_bench [N [KIND...]]: KIND 0 to 5 (the rows below), all when none
 * is given; a kind's numbers are the same in any selection */
int main(int argc, char **argv) {
  long n = argc > 1 ? atol(argv[1]) : 10000000L;
  int want[6] = {0}, any = 0;
  for (int i = 2; i < argc; i++)
    if (atoi(argv[i]) >= 0 && atoi(argv[i]) < 6) want[atoi(argv[i])] = any = 1;
  static const char *names[] = {"values 1e-10..1e10", "tiny (< 1e-15)", "integers",
                                "all exponents", "subnormals", "huge (> 1e16)"};
  printf("%-20s %12s %12s %8s %10s\n", "doubles", "bg_num ns", "loop ns", "ratio", "differ");
  double *v = malloc(CHUNK * sizeof *v);
  char *a = malloc((size_t)CHUNK * TEXT), *b = malloc((size_t)CHUNK * TEXT);
  if (!v || !a || !b) return 1;
  for (int kind = 0; kind < 6; kind++) {
    if (any && !want[kind]) continue;
    rng = 88172645463325252ull + (uint64_t)kind; /* each kind its own stream */
    double t_fast = 0, t_loop = 0;
    long differ = 0;
    for (long done = 0; done < n; done += CHUNK) {
      long c = n - done < CHUNK ? n - done : CHUNK;
      for (long i = 0; i < c; i++) v[i] = draw(kind);
      double t0 = now();
      for (long i = 0; i < c; i++) bg_num_format(a + i * TEXT, TEXT, v[i], 15);
      double t1 = now();
      for (long i = 0; i < c; i++) reference(b + i * TEXT, TEXT, v[i]);
      double t2 = now();
      t_fast += t1 - t0, t_loop += t2 - t1;
      for (long i = 0; i < c; i++) {
        if (strcmp(a + i * TEXT, b + i * TEXT) == 0) continue;
        if (differ++ < 5) fprintf(stderr, "%a: %s, loop %s\n", v[i], a + i * TEXT, b + i * TEXT);
      }
    }
    printf("%-20s %12.1f %12.1f %7.1fx %10ld\n", names[kind], 1e9 * t_fast / n, 1e9 * t_loop / n,
           t_loop / t_fast, differ);
    fflush(stdout);
  }
  free(v), free(a), free(b);
  return 0;
}
