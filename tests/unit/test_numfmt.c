/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_num_format against its definition, written out here independently: the
 * shortest "%.Ng" (N from min_digits to 17) that strtod reads back as the
 * same double. The fast integer path (src/base/numfmt.c) must give the same
 * text on random bit patterns, short decimals (the values models write),
 * exact decimal ties (ties to even), powers of two and ten and their
 * neighbours, and the edges of its range; plus spot checks of the spelling. */
#include <float.h>
#include <stdint.h>

#include "base/strbuf.h"
#include "harness.h"

static void reference(char *buf, size_t n, double v, int min_digits) {
  for (int p = min_digits; p <= 17; p++) {
    snprintf(buf, n, "%.*g", p, v);
    if (strtod(buf, NULL) == v) return;
  }
}

static int nbad;

static void same(double v, int min_digits) {
  char want[64], got[64];
  reference(want, sizeof want, v, min_digits);
  bg_num_format(got, sizeof got, v, min_digits);
  if (strcmp(want, got) != 0 && nbad++ < 10)
    fprintf(stderr, "%.17g (min %d): want %s, got %s\n", v, min_digits, want, got);
}

static void both_signs(double v) {
  same(v, 15), same(-v, 15), same(v, 6), same(v, 1);
}

static uint64_t rng = 88172645463325252ull;
static uint64_t next(void) { /* xorshift64: the same values on every run */
  rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
  return rng;
}

static double from_bits(uint64_t b) {
  double v;
  memcpy(&v, &b, sizeof v);
  return v;
}

int main(void) {
  /* random doubles in [1e-17, 1e18): every binade of the fast range and past its edges */
  for (int i = 0; i < 200000; i++) {
    uint64_t ex = 1023 - 57 + next() % 118, b = (ex << 52) | (next() & ((1ull << 52) - 1));
    same(from_bits(b), 15);
    if (i % 8 == 0) same(from_bits(b), 1 + (int)(i / 8 % 17));
  }
  /* short decimals: k / 10^d, and solver-like values k * 1e-6 */
  for (int d = 0; d <= 17; d++)
    for (int k = 1; k < 2000; k += 7) both_signs(k / pow(10, d));
  for (int k = 1; k < 20000; k++) same(k * 1e-6, 15), same(k * 0.001, 15);
  /* exact decimal ties at 15 and 16 digits: n + 1/2, n/4 of 16 and 17 digits */
  for (int i = 0; i < 20000; i++) {
    double n = (double)(100000000000000ll + (int64_t)(next() % 900000000000000ll));
    same(n + 0.5, 15), same(n / 4, 15), same(n * 0.125, 15), same(n / 2 + 0.25, 16);
  }
  /* powers of two (the double below is half as far) and ten, and their neighbours */
  for (int e = -60; e <= 60; e++) {
    double p2 = ldexp(1, e), p10 = pow(10, e / 4.0 * 1.0);
    both_signs(p2), both_signs(nextafter(p2, 0)), both_signs(nextafter(p2, 1e300));
    both_signs(p10), both_signs(nextafter(p10, 0)), both_signs(nextafter(p10, 1e300));
  }
  for (int e = -17; e <= 17; e++) {
    double p = pow(10, e);
    both_signs(p), both_signs(nextafter(p, 0)), both_signs(nextafter(p, 1e300));
  }
  both_signs(1e-15), both_signs(1e16), both_signs(DBL_MIN), both_signs(DBL_MAX);
  both_signs(5e-324), both_signs(0.1), both_signs(1.0 / 3), both_signs(2.0 / 3);
  INT_EQ(nbad, 0);

  char b[64];
  bg_num_format(b, sizeof b, 0.1, 15);
  STR_EQ(b, "0.1");
  bg_num_format(b, sizeof b, 0.1 + 0.2, 15);
  STR_EQ(b, "0.30000000000000004");
  bg_num_format(b, sizeof b, 1e-5, 15);
  STR_EQ(b, "1e-05");
  bg_num_format(b, sizeof b, 1e6, 6);
  STR_EQ(b, "1e+06");
  bg_num_format(b, sizeof b, 1e6, 15);
  STR_EQ(b, "1000000");
  bg_num_format(b, sizeof b, -0.0, 15);
  STR_EQ(b, "-0");
  bg_num_format(b, sizeof b, 0.0, 15);
  STR_EQ(b, "0");
  bg_num_format(b, sizeof b, 123456789012345680.0, 15);
  STR_EQ(b, "1.2345678901234568e+17");
  printf("%d passed, %d failed\n", bg_t_pass, bg_t_fail);
  return bg_t_fail != 0;
}
