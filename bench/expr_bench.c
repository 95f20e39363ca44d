/* SPDX-License-Identifier: BSD-3-Clause */
/* Benchmark (not a test): nanoseconds per linear term of a right-hand side,
 * tree walking (bg_xeval) against the bytecode VM (bg_prog_eval).
 *
 *   expr_bench [N]   N terms (default 1000)
 *
 * Two shapes, both built by hand like tests/unit/test_expr.c:
 *   sum    one root: c_1*x_1 + c_2*x_2 + ... + c_N*x_N
 *   ladder N roots, an RC ladder: dq_i/dt = (q_{i-1}/C - q_i/C)/R - (q_i/C - q_{i+1}/C)/R,
 *          written the way a derivation prints it; 4 linear terms per root. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "model/model.h"

static bg_model *model_new(int nstate, int cap) {
  bg_model *m = calloc(1, sizeof *m);
  m->nstate = nstate;
  m->xnode = calloc((size_t)cap, sizeof(bg_xnode));
  return m;
}

static int push(bg_model *m, int op, int ref, int a0, int a1, double num) {
  bg_xnode *n = &m->xnode[m->nxnode];
  *n = (bg_xnode){.op = (unsigned char)op, .ref = ref, .arg = {a0, a1, 0}, .num = num,
                  .nargs = (unsigned char)(op >= BG_X_NEG ? 2 : 0)};
  return m->nxnode++;
}

static int num(bg_model *m, double v) { return push(m, BG_X_NUM, 0, 0, 0, v); }
static int st(bg_model *m, int i) { return push(m, BG_X_STATE, i, 0, 0, 0); }
static int bin(bg_model *m, int op, int a, int b) { return push(m, op, 0, a, b, 0); }

static int build_sum(bg_model *m, int n) {
  int s = bin(m, BG_X_MUL, num(m, 1.0 + 1e-3), st(m, 0));
  for (int i = 1; i < n; i++)
    s = bin(m, BG_X_ADD, s, bin(m, BG_X_MUL, num(m, 1.0 + 1e-3 * i), st(m, i)));
  return s;
}

/* (q_{i-1}*(1/C) - q_i*(1/C))*(1/R) - ..., ends grounded. */
static int ladder_current(bg_model *m, int i, int n) {
  int a = i > 0 ? bin(m, BG_X_MUL, st(m, i - 1), num(m, 1 / 2e-6)) : num(m, 0);
  int b = i < n ? bin(m, BG_X_MUL, st(m, i), num(m, 1 / 2e-6)) : num(m, 0);
  return bin(m, BG_X_MUL, num(m, 1 / 1e3), bin(m, BG_X_SUB, a, b));
}

static void build_ladder(bg_model *m, int n, int *roots) {
  for (int i = 0; i < n; i++)
    roots[i] = bin(m, BG_X_SUB, ladder_current(m, i, n), ladder_current(m, i + 1, n));
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static volatile double sink;

/* Best of 5 runs of `reps` evaluations of every root; ns per term. */
static double time_tree(const bg_model *m, const int *roots, int nroots, const bg_xenv *env,
                        long reps, long terms) {
  double best = 1e30;
  for (int run = 0; run < 5; run++) {
    double t0 = now(), acc = 0;
    for (long r = 0; r < reps; r++)
      for (int k = 0; k < nroots; k++) acc += bg_xeval(m, roots[k], env);
    double dt = now() - t0;
    sink = acc;
    if (dt < best) best = dt;
  }
  return best * 1e9 / ((double)reps * terms);
}

static double time_prog(bg_prog *p, const double *vars, double *out, int nout, long reps,
                        long terms) {
  double best = 1e30;
  for (int run = 0; run < 5; run++) {
    double t0 = now(), acc = 0;
    for (long r = 0; r < reps; r++) {
      bg_prog_eval(p, vars, out);
      acc += out[r % nout];
    }
    double dt = now() - t0;
    sink = acc;
    if (dt < best) best = dt;
  }
  return best * 1e9 / ((double)reps * terms);
}

static void run(const char *name, bg_model *m, const int *roots, int nroots, int n, long terms) {
  double *x = malloc((size_t)n * sizeof *x), *out = malloc((size_t)nroots * sizeof *out);
  int *slot = malloc((size_t)n * sizeof *slot);
  for (int i = 0; i < n; i++) x[i] = 0.5 + 1e-4 * i, slot[i] = i;
  bg_xenv env = {.state = x};
  bg_slotmap map = {.time_slot = -1, .state_slot = slot};
  bg_prog *p = bg_prog_compile(m, roots, nroots, &map);
  bg_prog_eval(p, x, out);
  int agree = 1;
  for (int k = 0; k < nroots; k++) agree &= out[k] == bg_xeval(m, roots[k], &env);
  long reps = 20000000 / terms + 1;
  double tt = time_tree(m, roots, nroots, &env, reps, terms);
  double tp = time_prog(p, x, out, nroots, reps, terms);
  printf("%-7s %6ld terms %6d instr  tree %6.2f ns/term  vm %6.2f ns/term  ratio %5.2f  %s\n",
         name, terms, bg_prog_ninstr(p), tt, tp, tt / tp, agree ? "agree" : "DISAGREE");
  bg_prog_free(p);
  free(x), free(out), free(slot);
}

int main(int argc, char **argv) {
  int n = argc > 1 ? atoi(argv[1]) : 1000;
  if (n < 2) n = 2;
  bg_model *m = model_new(n, 64 * n + 64);
  int root = build_sum(m, n);
  run("sum", m, &root, 1, n, n);
  int *roots = malloc((size_t)n * sizeof *roots);
  build_ladder(m, n, roots);
  run("ladder", m, roots, n, n, 4L * n - 2);
  free(roots);
  free(m->xnode);
  free(m);
  return 0;
}
