/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_num_format against its definition, written out here independently: the
 * shortest "%.Ng" (N from min_digits to 17) that strtod reads back as the
 * same double. The exact big-integer printer (src/base/numfmt.c) must give
 * the same text on random bit patterns of every exponent, subnormals, short
 * decimals (the values models write), exact decimal ties (ties to even),
 * every power of two and of ten and their neighbours, DBL_MIN, DBL_MAX and
 * the smallest subnormal, values whose text needs all 17 digits, and every
 * min_digits; plus spot checks of the spelling. */
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

static int nbad, n17; /* texts that differ; texts of 17 digits */

static void same(double v, int min_digits) {
  char want[64], got[64];
  reference(want, sizeof want, v, min_digits);
  bg_num_format(got, sizeof got, v, min_digits);
  if (strcmp(want, got) != 0 && nbad++ < 10)
    fprintf(stderr, "%a = %.17g (min %d): want %s, got %s\n", v, v, min_digits, want, got);
  int digits = 0; /* significant digits: from the first non-zero one */
  for (const char *c = got; *c && *c != 'e'; c++) digits += (digits || (*c >= '1' && *c <= '9')) && *c != '.';
  n17 += digits == 17;
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

  /* every exponent: random bit patterns over all 2047 binades, subnormals
   * included (biased exponent 0), with every min_digits now and then */
  for (int i = 0; i < 60000; i++) {
    uint64_t b = next() & 0x7fffffffffffffffull;
    if ((b >> 52) == 0x7ff) continue; /* not finite */
    same(from_bits(b), 15), same(-from_bits(b), 15);
    if (i % 4 == 0) same(from_bits(b), 1 + (int)(i / 4 % 17));
  }
  /* subnormals: random mantissas, the smallest ones, the largest, and the
   * edge to DBL_MIN */
  for (int i = 0; i < 20000; i++) same(from_bits(next() & ((1ull << 52) - 1)), 15);
  for (uint64_t b = 1; b < 3000; b++) same(from_bits(b), 15), same(from_bits(b), 1);
  for (uint64_t b = (1ull << 52) - 2000; b < (1ull << 52) + 2000; b++) same(from_bits(b), 15);
  /* every power of two and its neighbours: 2^-1074 (the smallest subnormal) to 2^1023 */
  for (int e = -1074; e <= 1023; e++) {
    double p2 = ldexp(1, e);
    both_signs(p2), both_signs(nextafter(p2, 0)), both_signs(nextafter(p2, INFINITY));
  }
  /* every power of ten and its neighbours: 1e-323 to 1e308, as strtod reads them */
  for (int e = -323; e <= 308; e++) {
    char t[16];
    snprintf(t, sizeof t, "1e%d", e);
    double p10 = strtod(t, NULL);
    both_signs(p10), both_signs(nextafter(p10, 0)), both_signs(nextafter(p10, INFINITY));
  }
  /* the ends of the range */
  double ends[] = {DBL_MIN, DBL_MAX, nextafter(DBL_MAX, 0), nextafter(DBL_MIN, 0),
                   nextafter(DBL_MIN, 1), 4.9406564584124654e-324, 9.8813129168249309e-324,
                   2.2250738585072009e-308, 1.7976931348623157e308, 8.9884656743115795e307};
  for (size_t i = 0; i < sizeof ends / sizeof ends[0]; i++)
    for (int d = 1; d <= 17; d++) same(ends[i], d), same(-ends[i], d);
  /* exact decimal ties of p + 1 digits (ending in 5) at every scale: n + 1/2
   * (n of 15 and 16 digits), n 2^-j for j = 1..20 (their last digit is 5),
   * (10 d + 5) 10^s exactly representable, each with min_digits p */
  for (int i = 0; i < 3000; i++) {
    double n16 = (double)(1000000000000000ll + (int64_t)(next() % 3500000000000000ll));
    same(n16 + 0.5, 16), same(n16 + 0.5, 15);
    for (int j = 1; j <= 20; j++) {
      double v = ldexp((double)(next() % 1000000 * 2 + 1), -j);
      same(v, 1 + (int)(next() % 17));
    }
    for (int s = 0; s <= 14; s += 1 + (int)(next() % 4)) {
      uint64_t d = next() % 100000;
      double v = (double)(10 * d + 5) * pow(10, s); /* exact: (2d + 1) 5^(s+1) 2^s, below 2^53 */
      same(v, 1 + (int)(next() % 17));
    }
  }
  INT_EQ(nbad, 0);
  /* the texts above that needed all 17 digits (the read-back limit) */
  INT_EQ(n17 > 10000, 1);

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
