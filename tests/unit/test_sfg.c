/* SPDX-License-Identifier: BSD-3-Clause */
/* Signal flow graph: Johnson and Tarjan on hand-built graphs, then the
 * topological loops of the reference examples (docs/examples.md). */
#include "harness.h"

#include "analysis_fixture.h"

/* ------------------------------------------------------------ hand-built graphs */
static void hand_graph(bg_sfg *g, int nn, const int (*e)[3], int ne) {
  memset(g, 0, sizeof *g);
  g->nnode = nn;
  g->nedge = ne;
  g->edge = bg_arena_alloc(&g->arena, sizeof *g->edge * (size_t)(ne + 1));
  g->adr = bg_arena_alloc(&g->arena, sizeof(int) * (size_t)(nn + 1));
  g->n = bg_arena_alloc(&g->arena, sizeof(int) * (size_t)(nn + 1));
  g->out = bg_arena_alloc(&g->arena, sizeof(int) * (size_t)(ne + 1));
  for (int i = 0; i < ne; i++) {
    g->edge[i] = (bg_sfg_edge){e[i][0], e[i][1], BG_SFGE_JUNCTION, -1, e[i][2], 2.0, 1,
                               {"k", NULL}, {NULL, NULL}, 1};
    g->n[e[i][0]]++;
  }
  for (int v = 1; v < nn; v++) g->adr[v] = g->adr[v - 1] + g->n[v - 1];
  int fill[16] = {0};
  for (int i = 0; i < ne; i++) g->out[g->adr[e[i][0]] + fill[e[i][0]]++] = i;
}

static int count_cycle(void *ctx, const int *node, int n) {
  (void)node;
  (void)n;
  ++*(int *)ctx;
  return 0;
}

static int stop_at_3(void *ctx, const int *node, int n) {
  (void)node;
  (void)n;
  return ++*(int *)ctx >= 3;
}

static void test_johnson_tarjan(void) {
  /* the complete digraph on 4 nodes has 6 + 8 + 6 = 20 elementary cycles */
  int e[13][3], ne = 0;
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      if (i != j) { e[ne][0] = i; e[ne][1] = j; e[ne++][2] = 0; }
  bg_sfg g;
  hand_graph(&g, 4, (const int(*)[3])e, ne);
  int n = 0;
  INT_EQ(bg_sfg_algebraic_cycles(&g, count_cycle, &n, 0), 0);
  INT_EQ(n, 20);
  n = 0;
  bg_sfg_algebraic_cycles(&g, stop_at_3, &n, 0);
  INT_EQ(n, 3);
  INT_EQ(bg_sfg_algebraic_blocks(&g, NULL), 1);
  bg_sfg_free(&g);
  /* plus a self-loop: one more cycle */
  e[ne][0] = 2; e[ne][1] = 2; e[ne++][2] = 0;
  hand_graph(&g, 4, (const int(*)[3])e, ne);
  n = 0;
  bg_sfg_algebraic_cycles(&g, count_cycle, &n, 0);
  INT_EQ(n, 21);
  /* the work budget stops the search and says so */
  n = 0;
  INT_EQ(bg_sfg_algebraic_cycles(&g, count_cycle, &n, 5), 1);
  bg_sfg_free(&g);
  /* an integrator breaks the loop for blocks and algebraic cycles */
  const int f[3][3] = {{0, 1, 0}, {1, 0, 1}, {1, 2, 0}};
  hand_graph(&g, 3, f, 3);
  n = 0;
  bg_sfg_algebraic_cycles(&g, count_cycle, &n, 0);
  INT_EQ(n, 0);
  INT_EQ(bg_sfg_algebraic_blocks(&g, NULL), 0);
  bg_gain gn;
  int cyc[2] = {0, 1};
  bg_sfg_cycle_gain(&g, cyc, 2, &gn);
  OK(gn.ok);
  INT_EQ(gn.order, 1);
  DBL_NEAR(gn.value, 4.0, 1e-15);
  bg_arena ar = {0};
  STR_EQ(bg_gain_text(&gn, &ar), "k^2");
  bg_gain_free(&gn);
  bg_arena_free(&ar);
  bg_sfg_free(&g);
}

/* ------------------------------------------------------------ examples */
static const char *tl_line(const fx *f, int t) {
  static char buf[4][1400];
  static int k;
  const bg_analysis *a = &f->a;
  char *s = buf[k++ % 4];
  snprintf(s, 1400, "%s %d [%s] %s | %s", a->tloop_kind[t] == BG_TLOOP_FLAT ? "flat" : "open",
           a->tloop_order[t], fx_sigs(f->m, a->tloop_signals + a->tloop_adr[t], a->tloop_n[t]),
           a->tloop_gain[t], a->tloop_cause[t]);
  return s;
}

/* The algebraic topological loops, exactly, in list order. */
static void check_algebraic(const fx *f, const char **want, const double *val, int n) {
  int k = 0;
  for (int t = 0; t < f->a.ntloop; t++) {
    if (!f->a.tloop_algebraic[t]) continue;
    if (k < n) {
      STR_EQ(tl_line(f, t), want[k]);
      DBL_NEAR(f->a.tloop_gain_value[t], val[k], 1e-12 * fmax(1, fabs(val[k])));
    }
    k++;
  }
  INT_EQ(k, n);
  INT_EQ(f->a.ntloop_omitted, 0);
}

#define LOAD(f, name, method)                                                  \
  if (fx_load(&f, name, method, NULL, 0, NULL, NULL)) { OK(0); return; }

static void test_hydraulic_bridge(void) {
  fx f;
  LOAD(f, "hydraulic_bridge", BG_METHOD_SCAP);
  const char *w[] = {"flat 0 [R1.f f2 R2.f R2.e e2 R1.e] -R1'/R2' | causal path 4",
                     "flat 0 [R4.e e5 R3.e R3.f f5 R4.f] -R3'/R4' | causal path 6"};
  double v[] = {-1.5, -1.5};
  check_algebraic(&f, w, v, 2);
  fx_free(&f);
}

static void test_bond_loop(void) {
  fx f;
  LOAD(f, "bond_loop", BG_METHOD_SCAP);
  /* opposite orientation: efforts 1-2-3-4 one way, flows 4-3-2-1 the other */
  const char *w[] = {"open 0 [e1 e2 e3 e4] n | causal loop 1", "open 0 [f4 f3 f2 f1] n | causal loop 1"};
  double v[] = {2, 2};
  check_algebraic(&f, w, v, 2);
  fx_free(&f);
}

static void test_delta(void) {
  fx f;
  LOAD(f, "delta", BG_METHOD_SCAP);
  /* mesh law (efforts, Equation 4.36) and cut-set law (flows, Equation 4.37) */
  const char *w[] = {"open 0 [e2 e3 e8 e9 e6 e5] 1 | causal loop 1",
                     "open 0 [f5 f6 f9 f8 f3 f2] 1 | causal loop 1"};
  double v[] = {1, 1};
  check_algebraic(&f, w, v, 2);
  fx_free(&f);
}

static void test_internal_modulation(void) {
  fx f;
  LOAD(f, "internal_mod_tf", BG_METHOD_SCAP);
  const char *w1[] = {"open 0 [f2] dT/df2 | internal modulation of T"};
  double v0[] = {0, 0};
  check_algebraic(&f, w1, v0, 1);
  fx_free(&f);
  LOAD(f, "internal_mod_r", BG_METHOD_SCAP);
  const char *w2[] = {"open 0 [E.f Ra.f f3] dRa/dE.f | internal modulation of Ra"};
  check_algebraic(&f, w2, v0, 1);
  fx_free(&f);
  LOAD(f, "mod_no_loop", BG_METHOD_SCAP);
  check_algebraic(&f, NULL, NULL, 0);
  fx_free(&f);
  /* i -> r -> u -> i */
  LOAD(f, "series_motor", BG_METHOD_SCAP);
  const char *w3[] = {"open 0 [E.f e3 Ra.e Ra.f] -dK/dE.f/Ra0 | internal modulation of K"};
  double v3[] = {-0.25};
  check_algebraic(&f, w3, v3, 1);
  fx_free(&f);
  LOAD(f, "series_motor_L", BG_METHOD_SCAP);
  check_algebraic(&f, NULL, NULL, 0);
  fx_free(&f);
}

static void test_modulated_source(void) {
  fx f;
  LOAD(f, "modulated_source", BG_METHOD_SCAP);
  const char *w[] = {"flat 0 [U.e R2.e R2.f] k/R20 | internal modulation of U"};
  double v[] = {0.5};
  check_algebraic(&f, w, v, 1);
  OK(f.a.form_parameter_dependent);
  fx_free(&f);
  if (fx_load(&f, "modulated_source", BG_METHOD_SCAP, "k", 2.0, NULL, NULL)) { OK(0); return; }
  double v2[] = {1.0};
  check_algebraic(&f, w, v2, 1);
  OK(strstr(f.a.index_reason, "singular") != NULL);
  fx_free(&f);
}

/* Class 1 flat loops close through an integrator and a differentiator:
 * order 0, listed as algebraic; the store-R loops have order +-1. */
static void test_class12_orders(void) {
  fx f;
  LOAD(f, "class12_paths", BG_METHOD_SCAP);
  int nalg = 0, nflat = 0;
  for (int t = 0; t < f.a.ntloop; t++) {
    nalg += f.a.tloop_algebraic[t];
    nflat += f.a.tloop_kind[t] == BG_TLOOP_FLAT;
  }
  INT_EQ(nalg, 3);
  INT_EQ(nflat, f.a.ntloop);
  fx_free(&f);
}

int main(void) {
  test_johnson_tarjan();
  test_hydraulic_bridge();
  test_bond_loop();
  test_delta();
  test_internal_modulation();
  test_modulated_source();
  test_class12_orders();
  return bg_t_done();
}
