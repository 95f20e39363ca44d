/* SPDX-License-Identifier: BSD-3-Clause */
/* Symbolic transfer functions of a state space whose entries are symbols
 * (docs/linear.md#symbolic-form): den = det(sI - A) and, per pair, the
 * numerator det [sI - A, -b; c, d] (= det(sI - A) H(s), the Schur
 * complement), both by expanding the determinant along its rows with the
 * minors memoised by their column sets (Laplace expansion over subsets,
 * O(m 2^m) products for an m x m matrix). No division happens, so every
 * coefficient is a sum of products of the entries with integer weights:
 * terms of a bond graph's sparse matrices cancel exactly and nothing swells
 * through intermediate quotients (Faddeev-LeVerrier divides by k at every
 * step and builds n^2 dense intermediate entries). The rows of [sI - A, -b]
 * are shared by every output of one input: one expansion per input, then
 * one row per output. Each coefficient is expanded into monomials and
 * capped at `max_terms` terms (the caller's size limit). */
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

typedef struct det {
  bg_sym *S;
  int n, m;           /* states; columns in use (n + 1 with the input column) */
  const int *A, *b;   /* n x n column-major ids, the input column (n ids) */
  int max_terms;
  int *poly;          /* per column mask: m + 1 coefficient ids (s^0 first), -1 absent */
  int too_big;
} det;

/* Entry (row i, column j) of [sI - A, -b] as c0 + c1 s; returns 0 when it is zero. */
static int entry(det *D, int i, int j, int *c0, int *c1) {
  bg_sym *S = D->S;
  *c0 = bg_sym_neg(S, j < D->n ? D->A[(size_t)j * D->n + i] : D->b[i]);
  *c1 = bg_sym_num(S, j == i);
  return !(S->node[*c0].kind == SYM_NUM && S->node[*c0].c == 0 && j != i);
}

static int is_zero(const bg_sym *S, int e) { return S->node[e].kind == SYM_NUM && S->node[e].c == 0; }

/* The sum of products a_p * x_q over the terms of a and x, expanded into
 * monomials; -1 (and D->too_big) beyond max_terms. */
static int times(det *D, int a, int x) {
  bg_sym *S = D->S;
  return bg_sym_expand(S, bg_sym_mul(S, a, x), D->max_terms);
}

static int nterms(const bg_sym *S, int e) { return S->node[e].kind == SYM_ADD ? S->node[e].n : 1; }

/* Adds sign * (c0 + c1 s) * poly[from] into acc (m + 1 coefficients). */
static void accumulate(det *D, int from, int c0, int c1, double sign, int *acc) {
  bg_sym *S = D->S;
  const int *p = D->poly + (size_t)from * (D->m + 1);
  for (int k = D->m; k >= 0; k--) {
    if (p[k] < 0 || is_zero(S, p[k])) continue;
    int lo = times(D, c0, p[k]);
    acc[k] = bg_sym_add(S, acc[k], bg_sym_scale(S, sign, lo));
    if (!is_zero(S, c1) && k < D->m) acc[k + 1] = bg_sym_add(S, acc[k + 1], bg_sym_scale(S, sign, times(D, c1, p[k])));
  }
  for (int k = 0; k <= D->m; k++)
    if (nterms(S, acc[k]) > D->max_terms) D->too_big = 1;
}

static int popcount(unsigned x) {
  int c = 0;
  for (; x; x &= x - 1) c++;
  return c;
}

/* The minors of rows 0..rows-1 over every column set of that size. */
static void expand_rows(det *D, int rows) {
  bg_sym *S = D->S;
  unsigned full = 1u << D->m;
  int w = D->m + 1;
  for (size_t q = 0; q < (size_t)full * w; q++) D->poly[q] = -1;
  D->poly[0] = bg_sym_num(S, 1);
  for (int r = 0; r < rows && !D->too_big; r++)
    for (unsigned mask = 0; mask < full && !D->too_big; mask++) {
      if (popcount(mask) != r || D->poly[(size_t)mask * w] < 0) continue;
      for (int j = 0; j < D->m; j++) {
        int c0, c1;
        if ((mask >> j & 1) || !entry(D, r, j, &c0, &c1)) continue;
        unsigned to = mask | 1u << j;
        int *acc = D->poly + (size_t)to * w;
        if (acc[0] < 0)
          for (int k = 0; k < w; k++) acc[k] = bg_sym_num(S, 0);
        double sign = (r + popcount(mask & ((1u << j) - 1))) % 2 ? -1 : 1;
        accumulate(D, (int)mask, c0, c1, sign, acc);
      }
    }
}

/* det of the n x n rows above with the last row (c, d) appended, columns all m. */
static void last_row(det *D, const int *c, int d, int *out) {
  bg_sym *S = D->S;
  int w = D->m + 1, n = D->n;
  for (int k = 0; k < w; k++) out[k] = bg_sym_num(S, 0);
  unsigned full = (1u << D->m) - 1;
  for (int j = 0; j < D->m; j++) {
    int e = j < n ? c[j] : d, from = (int)(full & ~(1u << j));
    if (is_zero(S, e) || D->poly[(size_t)from * w] < 0) continue;
    double sign = (n + j) % 2 ? -1 : 1;
    accumulate(D, from, e, bg_sym_num(S, 0), sign, out);
  }
}

int bg_lin_sym_tfs(bg_sym *S, int n, int nu, int ny, const int *A, const int *B, const int *C,
                   const int *Dm, int max_terms, int *den, int *num) {
  det D = {S, n, n + 1, A, NULL, max_terms, NULL, 0};
  D.poly = bg_xmalloc(((size_t)1 << (n + 1)) * (n + 2) * sizeof *D.poly);
  int *c = bg_xcalloc((size_t)n + 1, sizeof *c), *out = bg_xcalloc((size_t)n + 2, sizeof *out);
  for (int k = 0; k <= n; k++) den[k] = bg_sym_num(S, 0);
  for (int j = 0; j < nu && !D.too_big; j++) {
    D.b = B + (size_t)j * n;
    expand_rows(&D, n);
    const int *dp = D.poly + (size_t)((1u << n) - 1) * (n + 2); /* columns 0..n-1: det(sI - A) */
    for (int k = 0; k <= n && j == 0; k++) den[n - k] = dp[k] < 0 ? bg_sym_num(S, 0) : dp[k];
    for (int i = 0; i < ny && !D.too_big; i++) {
      for (int q = 0; q < n; q++) c[q] = C[(size_t)q * ny + i];
      last_row(&D, c, Dm[(size_t)j * ny + i], out);
      for (int k = 0; k <= n; k++) num[((size_t)i * nu + j) * (n + 1) + (n - k)] = out[k];
    }
  }
  if (nu == 0) { /* no input: the denominator alone */
    D.b = NULL, D.m = n;
    expand_rows(&D, n);
    const int *dp = D.poly + (size_t)((1u << n) - 1) * (n + 1);
    for (int k = 0; k <= n; k++) den[n - k] = dp[k] < 0 ? bg_sym_num(S, 0) : dp[k];
  }
  free(D.poly), free(c), free(out);
  return D.too_big ? -1 : 0;
}
