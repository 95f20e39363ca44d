/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_num_format (strbuf.h): the shortest "%.Ng", N from min_digits to 17,
 * that reads back as the same double. The definition is the loop of snprintf
 * and strtod (glibc's printf rounds the exact binary value half to even, its
 * strtod rounds to nearest, ties to even); that loop costs 1 000 to 10 000
 * instructions a number, most of a simulation's CSV, so it is only the tests'
 * reference (tests/unit/test_numfmt.c, bench/numfmt_bench.c). Here the same
 * text is computed directly and exactly for every finite double, subnormals
 * included:
 * - |v| = m 2^e, and a power of ten 10^k puts X = |v| 10^k in [1e16, 1e17).
 *   X, and the two half-way points to the neighbouring doubles (H above,
 *   L below: a quarter of the way down at a power of two, where the double
 *   below is half as far), are fractions c S / D of big integers (S and D
 *   hold 5^|k| and the power of two, c is 4m, 4m + 2, 4m - 2 or 4m - 1), at
 *   most about 850 bits, so a fixed array of 64-bit limbs holds them. A
 *   division with a quotient below 2^62 gives floor(X) (17 digits), whether
 *   X has a fraction and how it compares with 1/2, and floor(H), floor(L):
 *   a shift when D is a power of two (every |v| < 1e17), in 128 bits when S
 *   fits in 64 (1e-11 < |v| < 1e17 about), else one long division of limbs.
 * - For each N: the N-digit rounding of floor(X) with that fraction, half to
 *   even, is printf's; it reads back as v when it lies strictly between L
 *   and H, or on one of them when m is even (strtod's tie goes to the even
 *   mantissa). Integer comparisons with floor(H) and floor(L) decide it. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/strbuf.h"

typedef unsigned __int128 u128;

static const uint64_t pow10_u64[18] = {
    1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000,
    10000000000ull, 100000000000ull, 1000000000000ull, 10000000000000ull,
    100000000000000ull, 1000000000000000ull, 10000000000000000ull,
    100000000000000000ull};

/* A non-negative integer in 64-bit limbs, least significant first; n limbs
 * used, the top one non-zero (n = 0 is zero). The numerators c S stay below
 * 2^850 (5^341 4m: 5^340 at the smallest subnormal and a margin of one), the
 * denominators below 2^690 (4 5^293 near DBL_MAX): 20 limbs (1 280 bits)
 * leave room for the products and shifts in bn_div. */
enum { BN_LIMBS = 20 };
typedef struct bn { uint64_t d[BN_LIMBS]; int n; } bn;

static void bn_set(bn *x, uint64_t v) { x->d[0] = v, x->n = v != 0; }

static void bn_copy(bn *to, const bn *from) {
  to->n = from->n;
  memcpy(to->d, from->d, (size_t)from->n * sizeof from->d[0]);
}

static void bn_mul(bn *x, uint64_t v) { /* x *= v */
  if (v == 0) { x->n = 0; return; }
  u128 c = 0;
  for (int i = 0; i < x->n; i++) c += (u128)x->d[i] * v, x->d[i] = (uint64_t)c, c >>= 64;
  if (c) x->d[x->n++] = (uint64_t)c;
}

static void bn_shl(bn *x, int s) { /* x *= 2^s */
  int n = x->n, w = s / 64, b = s % 64;
  if (n == 0) return;
  uint64_t top = b ? x->d[n - 1] >> (64 - b) : 0;
  for (int i = n - 1; i >= 0; i--) /* downwards: d[i - 1] is read before it is written */
    x->d[i + w] = b ? (x->d[i] << b) | (i > 0 ? x->d[i - 1] >> (64 - b) : 0) : x->d[i];
  for (int i = 0; i < w; i++) x->d[i] = 0;
  x->n = n + w;
  if (top) x->d[x->n++] = top;
}

static int bn_cmp(const bn *a, const bn *b) {
  if (a->n != b->n) return a->n < b->n ? -1 : 1;
  for (int i = a->n - 1; i >= 0; i--)
    if (a->d[i] != b->d[i]) return a->d[i] < b->d[i] ? -1 : 1;
  return 0;
}

static void bn_sub(bn *a, const bn *b) { /* a -= b, a >= b */
  uint64_t borrow = 0;
  for (int i = 0; i < a->n; i++) {
    uint64_t bi = i < b->n ? b->d[i] : 0, ai = a->d[i];
    a->d[i] = ai - bi - borrow;
    borrow = ai < bi || (ai == bi && borrow);
  }
  while (a->n > 0 && a->d[a->n - 1] == 0) a->n--;
}

static uint64_t bn_limb(const bn *x, int i) { return i < x->n ? x->d[i] : 0; }

static u128 bn_bits_from(const bn *x, int s) { /* floor(x / 2^s) mod 2^128 */
  int w = s / 64, b = s % 64;
  uint64_t l0 = bn_limb(x, w), l1 = bn_limb(x, w + 1), l2 = bn_limb(x, w + 2);
  if (b) l0 = (l0 >> b) | (l1 << (64 - b)), l1 = (l1 >> b) | (l2 << (64 - b));
  return (u128)l1 << 64 | l0;
}

static int bn_bit_length(const bn *x) {
  return x->n ? 64 * x->n - __builtin_clzll(x->d[x->n - 1]) : 0;
}

/* floor(num / den), which the callers know to be below 2^62; *exact is 1 when
 * den divides num, *half (if asked) the sign of 2 (num mod den) - den. */
static uint64_t bn_div(const bn *num, const bn *den, int *exact, int *half) {
  int nd = bn_bit_length(den), s = nd > 64 ? nd - 64 : 0;
  uint64_t dt = (uint64_t)bn_bits_from(den, s);
  u128 nt = bn_bits_from(num, s); /* num < 2^62 den < 2^(s + 126): all of it */
  /* With s > 0, dt >= 2^63 and nt / (dt + 1) is at most 3 below the quotient */
  uint64_t q = (uint64_t)(s ? nt / ((u128)dt + 1) : nt / dt);
  bn r, t;
  bn_copy(&r, num), bn_copy(&t, den), bn_mul(&t, q), bn_sub(&r, &t);
  while (bn_cmp(&r, den) >= 0) bn_sub(&r, den), q++;
  *exact = r.n == 0;
  if (half) bn_shl(&r, 1), *half = bn_cmp(&r, den);
  return q;
}

static void bn_mul_pow5(bn *x, int k) { /* x *= 5^k */
  static const uint64_t pow5[28] = {
      1ull, 5ull, 25ull, 125ull, 625ull, 3125ull, 15625ull, 78125ull, 390625ull,
      1953125ull, 9765625ull, 48828125ull, 244140625ull, 1220703125ull, 6103515625ull,
      30517578125ull, 152587890625ull, 762939453125ull, 3814697265625ull,
      19073486328125ull, 95367431640625ull, 476837158203125ull, 2384185791015625ull,
      11920928955078125ull, 59604644775390625ull, 298023223876953125ull,
      1490116119384765625ull, 7450580596923828125ull}; /* 5^27 < 2^64 */
  for (; k >= 27; k -= 27) bn_mul(x, pow5[27]);
  bn_mul(x, pow5[k]);
}

static int bn_bit(const bn *x, int s) { return (int)(bn_limb(x, s / 64) >> (s % 64) & 1); }

static int bn_any_below(const bn *x, int s) { /* a bit below 2^s is set */
  int w = s / 64, b = s % 64;
  for (int i = 0; i < w && i < x->n; i++)
    if (x->d[i]) return 1;
  return b && (bn_limb(x, w) & ((1ull << b) - 1)) != 0;
}

/* bn_div by 2^s, by picking bits (the denominator of every |v| < 1e17) */
static uint64_t bn_shift_div(const bn *num, int s, int *exact, int *half) {
  int hb = s > 0 && bn_bit(num, s - 1), low = s > 1 && bn_any_below(num, s - 1);
  *exact = !hb && !low;
  if (half) *half = hb ? low : -1;
  return (uint64_t)bn_bits_from(num, s);
}

/* floor(c S / D), and whether c S / D is an integer (D = 2^d_shift when
 * d_shift >= 0) */
static uint64_t scaled_floor(const bn *S, uint64_t c, const bn *D, int d_shift, int *exact,
                             int *half) {
  if (S->n == 1 && d_shift >= 0 && d_shift < 128) { /* c S < 2^119: the same in 128 bits */
    u128 num = (u128)S->d[0] * c, low = num & (((u128)1 << d_shift) - 1);
    u128 halfway = d_shift ? (u128)1 << (d_shift - 1) : 0;
    *exact = low == 0;
    if (half) *half = d_shift == 0 ? -1 : low < halfway ? -1 : low > halfway;
    return (uint64_t)(num >> d_shift);
  }
  bn num;
  bn_copy(&num, S), bn_mul(&num, c);
  return d_shift >= 0 ? bn_shift_div(&num, d_shift, exact, half) : bn_div(&num, D, exact, half);
}

/* %g's text for the p-digit decimal q 10^(E - p + 1) (q of exactly p
 * digits), written by hand: snprintf would cost more than the rest. */
static void put_g(char *buf, size_t size, int neg, uint64_t q, int p, int E) {
  static const char two_digits[201] =
      "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
      "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
      "8081828384858687888990919293949596979899";
  char dig[24], out[48];
  int i = p;
  if (i > 8) { /* the low 8 digits in 32 bits: cheaper divisions */
    uint32_t low = (uint32_t)(q % 100000000);
    q /= 100000000;
    for (int j = 0; j < 4; j++, i -= 2) memcpy(dig + i - 2, two_digits + 2 * (low % 100), 2), low /= 100;
  }
  uint32_t high = (uint32_t)q; /* below 10^9 */
  for (; i >= 2; i -= 2) memcpy(dig + i - 2, two_digits + 2 * (high % 100), 2), high /= 100;
  if (i == 1) dig[0] = (char)('0' + high);
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

/* finite v != 0 */
static void num_format_exact(char *buf, size_t size, double v, int min_digits) {
  uint64_t bits;
  memcpy(&bits, &v, sizeof bits);
  int bexp = (int)((bits >> 52) & 0x7ff);
  uint64_t m = bits & ((1ull << 52) - 1);
  if (bexp) m |= 1ull << 52; /* normal: the hidden bit; subnormal: 2^-1074 units */
  int e = (bexp ? bexp : 1) - 1075;
  int pow2 = bexp > 1 && m == (1ull << 52); /* the double below is half as far */
  /* 2^e2 <= |v| < 2^(e2+1), so floor(log10 |v|) is L or L + 1; L from a
   * double, exact since e2 log10(2) is never within 1e-4 of an integer but
   * at e2 = 0 (cheaper than log10 of v) */
  int e2 = 63 - __builtin_clzll(m) + e;
  int k = 16 - (int)floor(e2 * 0.30102999566398120);
  bn S, D;
  uint64_t X;
  int d_shift;
  int x_exact, x_half;
  for (;;) { /* k moves (once) until 1e16 <= X < 1e17 */
    int t = k + e; /* |v| 10^k = m 5^k 2^t = 4m S / D */
    bn_set(&S, 1), bn_set(&D, 4);
    bn_mul_pow5(k >= 0 ? &S : &D, k >= 0 ? k : -k);
    d_shift = k >= 0 ? 2 + (t < 0 ? -t : 0) : -1; /* D = 2^d_shift: not built */
    if (t >= 0) bn_shl(&S, t);
    else if (d_shift < 0) bn_shl(&D, -t);
    X = scaled_floor(&S, 4 * m, &D, d_shift, &x_exact, &x_half);
    if (X < pow10_u64[16]) k++;
    else if (X >= pow10_u64[17]) k--;
    else break;
  }
  int h_exact, l_exact;
  uint64_t H = scaled_floor(&S, 4 * m + 2, &D, d_shift, &h_exact, NULL);
  uint64_t L = scaled_floor(&S, 4 * m - (pow2 ? 1 : 2), &D, d_shift, &l_exact, NULL);
  int even = (m & 1) == 0;
  if (min_digits < 1) min_digits = 1; /* "%.0g" is "%.1g" */
  for (int p = min_digits > 17 ? 17 : min_digits;; p++) {
    /* X / 10^j rounded half to even: Q and r + f (f the fraction of X) */
    uint64_t P = pow10_u64[17 - p], Q = X / P, r = X % P;
    int64_t d = (int64_t)P - 2 * (int64_t)r; /* round up when 2f > d, or 2f = d and Q odd */
    int up = d < 0 || (d == 0 && (!x_exact || (Q & 1))) || (d == 1 && (x_half > 0 || (x_half == 0 && (Q & 1))));
    Q += (uint64_t)up;
    uint64_t Y = Q * P; /* the text's value, scaled as X */
    int below_h = Y < H || (Y == H && (!h_exact || even));
    int above_l = Y > L || (Y == L && l_exact && even);
    if ((below_h && above_l) || p == 17) { /* 17 digits always read back */
      int carry = Q == pow10_u64[p]; /* 9.99.. rounded up to 10.0.. */
      put_g(buf, size, signbit(v) != 0, carry ? Q / 10 : Q, p, 16 - k + carry);
      return;
    }
  }
}

void bg_num_format(char *buf, size_t size, double v, int min_digits) {
  if (v == 0) snprintf(buf, size, "%s", signbit(v) ? "-0" : "0");
  else if (!isfinite(v)) snprintf(buf, size, "%.17g", v); /* the loop's last text */
  else num_format_exact(buf, size, v, min_digits);
}
