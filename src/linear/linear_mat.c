/* SPDX-License-Identifier: BSD-3-Clause */
/* Leaf helpers of the reduction to a state space (linear_reduce.c) and of
 * the dependent-store elimination (linear_dep.c), which call each other
 * through these: a column-major matrix product and the outputs that read a
 * state's rate. */
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

void bg_lin_matmul(int m, int k, int n, const double *A, const double *B, double *C) {
  memset(C, 0, (size_t)m * n * sizeof *C);
  for (int j = 0; j < n; j++)
    for (int p = 0; p < k; p++) {
      double b = B[(size_t)j * k + p];
      if (b == 0) continue;
      for (int i = 0; i < m; i++) C[(size_t)j * m + i] += A[(size_t)p * m + i] * b;
    }
}

/* C = Cx + Cp A, D = Dd + Cp B for outputs reading x' (rows ny). */
void bg_lin_outputs_through(bg_linear *l, const double *Cx, const double *Cp, const double *Dd) {
  int n = l->n, ny = l->ny, nu = l->nu;
  l->C = bg_xcalloc((size_t)ny * n + 1, sizeof *l->C);
  l->D = bg_xcalloc((size_t)ny * nu + 1, sizeof *l->D);
  bg_lin_matmul(ny, n, n, Cp, l->A, l->C);
  bg_lin_matmul(ny, n, nu, Cp, l->B, l->D);
  for (size_t k = 0; k < (size_t)ny * n; k++) l->C[k] += Cx[k];
  for (size_t k = 0; k < (size_t)ny * nu; k++) l->D[k] += Dd[k];
}
