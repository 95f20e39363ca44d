/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_num_format (strbuf.h): the shortest "%.Ng", N from min_digits to 17,
 * that reads back as the same double. The reference definition is the loop
 * of snprintf and strtod in num_format_slow; it costs about 9 000
 * instructions a number, most of a small simulation's CSV. num_format_fast
 * gives the same text exactly for the doubles most outputs hold (normal,
 * 1e-15 <= |v| < 1e16) with integer arithmetic: v * 10^k as an exact 128-bit
 * integer A over 2^b, its correct rounding to N digits (ties to even, as
 * glibc's printf), and the read-back test against the half-way points to the
 * neighbouring doubles, which strtod rounds to nearest, ties to even.
 * tests/unit/test_numfmt.c compares the two on a few hundred thousand values. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/strbuf.h"

typedef unsigned __int128 u128;

static void num_format_slow(char *buf, size_t size, double v, int min_digits) {
  /* 17 significant digits always read back (IEEE double), so the loop ends */
  for (int prec = min_digits; prec <= 17; prec++) {
    snprintf(buf, size, "%.*g", prec, v);
    if (strtod(buf, NULL) == v) return;
  }
}

static u128 pow10_u128(int n) {
  static const uint64_t p[18] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000,
                                 100000000, 1000000000, 10000000000ull, 100000000000ull,
                                 1000000000000ull, 10000000000000ull, 100000000000000ull,
                                 1000000000000000ull, 10000000000000000ull,
                                 100000000000000000ull};
  return p[n];
}

/* The double |v| = m 2^e as v 10^k = A / 2^b exactly, with ulp the spacing
 * of the doubles around v in the same units (A +- ulp are the neighbours). */
typedef struct scaled { u128 A, ulp; int b; } scaled;

static int scale_by(uint64_t m, int e, int k, scaled *x) {
  u128 p5 = 1;
  for (int i = 0; i < k; i++) p5 *= 5;
  int s = -(k + e); /* v 10^k = m 5^k 2^(k+e) */
  if (s >= 0) x->A = (u128)m * p5, x->ulp = p5, x->b = s;
  else x->A = ((u128)m * p5) << -s, x->ulp = p5 << -s, x->b = 0;
  return x->b < 100;
}

/* %g's text for the p-digit decimal q 10^(E - p + 1) (q of exactly p
 * digits), written by hand: snprintf would cost more than the rest. */
static void put_g(char *buf, size_t size, int neg, uint64_t q, int p, int E) {
  char dig[24], out[48];
  for (int i = p - 1; i >= 0; i--) dig[i] = (char)('0' + q % 10), q /= 10;
  int nd = p;
  while (nd > 1 && dig[nd - 1] == '0') nd--; /* trailing zeros go */
  size_t o = 0;
  if (neg) out[o++] = '-';
  if (E < -4 || E >= p) {
    out[o++] = dig[0];
    if (nd > 1) out[o++] = '.', memcpy(out + o, dig + 1, (size_t)nd - 1), o += (size_t)nd - 1;
    int ae = E < 0 ? -E : E;
    out[o++] = 'e', out[o++] = E < 0 ? '-' : '+';
    if (ae >= 100) out[o++] = (char)('0' + ae / 100);
    out[o++] = (char)('0' + ae / 10 % 10), out[o++] = (char)('0' + ae % 10);
  } else if (E >= 0) {
    memcpy(out + o, dig, (size_t)E + 1), o += (size_t)E + 1;
    if (nd > E + 1) out[o++] = '.', memcpy(out + o, dig + E + 1, (size_t)(nd - E - 1)), o += (size_t)(nd - E - 1);
  } else {
    out[o++] = '0', out[o++] = '.';
    for (int i = 0; i < -E - 1; i++) out[o++] = '0';
    memcpy(out + o, dig, (size_t)nd), o += (size_t)nd;
  }
  if (o >= size) o = size - 1; /* callers give at least 32 bytes: never cut */
  memcpy(buf, out, o);
  buf[o] = 0;
}

/* Rounds X = A / 2^b to p digits; 1 when the result reads back as v. */
static int round_to(const scaled *x, uint64_t m, int p, uint64_t *q, int *carry) {
  /* floor(A / (10^j 2^b)) = floor(floor(A / 2^b) / 10^j), in 64 bits (< 1e17) */
  uint64_t p10 = (uint64_t)pow10_u128(17 - p);
  u128 D = (u128)p10 << x->b;
  u128 Q = (uint64_t)(x->A >> x->b) / p10, r = x->A - Q * D;
  if (2 * r > D || (2 * r == D && (Q & 1))) Q++;
  u128 Y = Q * D, diff = Y > x->A ? Y - x->A : x->A - Y;
  int below = Y < x->A, even = (m & 1) == 0, ok;
  if (below && m == (1ull << 52)) /* a power of two: the double below is half as far */
    ok = 4 * diff < x->ulp || (4 * diff == x->ulp && even);
  else
    ok = 2 * diff < x->ulp || (2 * diff == x->ulp && even);
  *carry = Q == pow10_u128(p);
  *q = (uint64_t)(*carry ? Q / 10 : Q);
  return ok;
}

static int num_format_fast(char *buf, size_t size, double v, int min_digits) {
  double a = fabs(v);
  if (!(a >= 1e-15 && a < 1e16) || min_digits < 1) return 0;
  uint64_t bits;
  memcpy(&bits, &v, sizeof bits);
  int ex = (int)((bits >> 52) & 0x7ff);
  uint64_t m = (bits & ((1ull << 52) - 1)) | (1ull << 52);
  int e = ex - 1075, k = 16 - (int)floor(log10(a));
  scaled x;
  for (int tries = 0; tries < 3; tries++) { /* log10 may be off by one */
    if (k < 1 || k > 31 || !scale_by(m, e, k, &x)) return 0;
    if (x.A < (pow10_u128(16) << x.b)) k++;
    else if (x.A >= (pow10_u128(17) << x.b)) k--;
    else break;
  }
  if (x.A < (pow10_u128(16) << x.b) || x.A >= (pow10_u128(17) << x.b)) return 0;
  for (int p = min_digits > 17 ? 17 : min_digits; p <= 17; p++) {
    uint64_t q;
    int carry;
    if (!round_to(&x, m, p, &q, &carry)) continue;
    put_g(buf, size, v < 0, q, p, 16 - k + carry);
    return 1;
  }
  return 0;
}

void bg_num_format(char *buf, size_t size, double v, int min_digits) {
  if (v == 0) {
    snprintf(buf, size, "%s", signbit(v) ? "-0" : "0");
    return;
  }
  if (!num_format_fast(buf, size, v, min_digits)) num_format_slow(buf, size, v, min_digits);
}
