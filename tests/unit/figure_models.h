/* SPDX-License-Identifier: BSD-3-Clause */
/* Models the figure tests generate (issue 31: measure on models nobody
 * tuned the drawing to): chains, ladders, grids of RC cells, random trees,
 * reaction networks with many modulating signals and three-level
 * submodels, as .bg text, compiled and analysed like an example (fm_load:
 * include after analysis_fixture.h). */
#ifndef BG_TEST_FIGURE_MODELS_H
#define BG_TEST_FIGURE_MODELS_H
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/strbuf.h"

#ifdef BG_TEST_ANALYSIS_FIXTURE_H /* the generators alone elsewhere (test_report.c) */
/* Compiles and analyses `text` as if it were examples/NAME.bg. */
static int fm_load(fx *f, const char *name, const char *text) {
  memset(f, 0, sizeof *f);
  f->src = strdup(text);
  size_t len = strlen(text);
  bg_diags_init(&f->dg, name, f->src, len);
  bg_ast *ast = bg_parse_string(name, f->src, len, &f->dg);
  if (ast && !f->dg.nerrors) f->m = bg_model_compile(ast, NULL, 0, &f->dg);
  if (ast) bg_ast_free(ast);
  if (!f->m) { bg_diags_print(&f->dg, stderr); return -1; }
  fx_init_analysis(&f->a, f->m);
  bg_causality_assign(f->m, f->m->method, &f->a, &f->dg);
  bg_analysis_run(f->m, &f->a, NULL);
  return 0;
}
#endif

/* A source, then n elements, each on its own junction (1, 0, 1, ...): R, I,
 * C in turn. */
__attribute__((unused)) static void fm_chain(bg_strbuf *b, int n) {
  static const char *kind[] = {"R r", "I m", "C c"};
  bg_sb_printf(b, "model chain%d\nSe U = 1\n", n);
  for (int i = 0; i < n; i++) bg_sb_printf(b, "%d j%d\n%s%d = 1\n", i % 2 ? 0 : 1, i, kind[i % 3], i);
  bg_sb_puts(b, "bond U -> j0\n");
  for (int i = 0; i < n; i++) {
    bg_sb_printf(b, "bond j%d -> %c%d\n", i, kind[i % 3][2], i);
    if (i + 1 < n) bg_sb_printf(b, "bond j%d -> j%d\n", i, i + 1);
  }
}

/* An RC ladder of k sections (series R on a 1-junction, shunt C on a 0-junction) and a load. */
__attribute__((unused)) static void fm_ladder(bg_strbuf *b, int k) {
  bg_sb_printf(b, "model ladder%d\nSe U = 1\nR load = 10\n", k);
  for (int i = 0; i < k; i++) bg_sb_printf(b, "1 s%d\nR R%d = 1\n0 n%d\nC C%d = 1\n", i, i, i, i);
  bg_sb_puts(b, "bond U -> s0\n");
  for (int i = 0; i < k; i++) {
    bg_sb_printf(b, "bond s%d -> R%d\nbond s%d -> n%d\nbond n%d -> C%d\n", i, i, i, i, i, i);
    if (i + 1 < k) bg_sb_printf(b, "bond n%d -> s%d\n", i, i + 1);
  }
  bg_sb_printf(b, "bond n%d -> load\n", k - 1);
}

/* A chain of n masses (a 1-junction with an I and an R, then a
 * 0-junction with a C: the spring to the next), from a force: 5 n + 1
 * nodes, so above 400 masses a model the rows layout draws by default. */
__attribute__((unused)) static void fm_masses(bg_strbuf *b, int n) {
  bg_sb_printf(b, "model masses%d\nSe F = 1\n", n);
  for (int i = 0; i < n; i++) bg_sb_printf(b, "1 v%d\nI m%d = 1\nR r%d = 1\n0 s%d\nC k%d = 1\n", i, i, i, i, i);
  bg_sb_puts(b, "bond F -> v0\n");
  for (int i = 0; i < n; i++) {
    bg_sb_printf(b, "bond v%d -> m%d\nbond v%d -> r%d\nbond v%d -> s%d\nbond s%d -> k%d\n", i, i, i, i, i, i, i, i);
    if (i + 1 < n) bg_sb_printf(b, "bond s%d -> v%d\n", i, i + 1);
  }
}

/* Two chains of n masses each (an I on a 1-junction, a C on the
 * 0-junction to the next), not joined: 8 n + 2 nodes in two parts. */
__attribute__((unused)) static void fm_two_chains(bg_strbuf *b, int n) {
  bg_sb_printf(b, "model two%d\n", n);
  for (int p = 0; p < 2; p++) {
    bg_sb_printf(b, "Se F%d = 1\n", p);
    for (int i = 0; i < n; i++) bg_sb_printf(b, "1 v%d_%d\nI m%d_%d = 1\n0 s%d_%d\nC k%d_%d = 1\n", p, i, p, i, p, i, p, i);
    bg_sb_printf(b, "bond F%d -> v%d_0\n", p, p);
    for (int i = 0; i < n; i++) {
      bg_sb_printf(b, "bond v%d_%d -> m%d_%d\nbond v%d_%d -> s%d_%d\nbond s%d_%d -> k%d_%d\n", p, i, p, i, p, i, p, i, p, i, p, i);
      if (i + 1 < n) bg_sb_printf(b, "bond s%d_%d -> v%d_%d\n", p, i, p, i + 1);
    }
  }
}

/* r × c nodes (0-junctions with a C each), joined along rows and columns by
 * resistors on 1-junctions; a source at the first node. */
static void fm_grid(bg_strbuf *b, int r, int c) {
  bg_sb_printf(b, "model grid%dx%d\nSe U = 1\n", r, c);
  for (int i = 0; i < r; i++)
    for (int j = 0; j < c; j++) {
      bg_sb_printf(b, "0 n%d_%d\nC C%d_%d = 1\n", i, j, i, j);
      if (j + 1 < c) bg_sb_printf(b, "1 h%d_%d\nR Rh%d_%d = 1\n", i, j, i, j);
      if (i + 1 < r) bg_sb_printf(b, "1 v%d_%d\nR Rv%d_%d = 1\n", i, j, i, j);
    }
  bg_sb_puts(b, "bond U -> n0_0\n");
  for (int i = 0; i < r; i++)
    for (int j = 0; j < c; j++) {
      bg_sb_printf(b, "bond n%d_%d -> C%d_%d\n", i, j, i, j);
      if (j + 1 < c)
        bg_sb_printf(b, "bond n%d_%d -> h%d_%d\nbond h%d_%d -> Rh%d_%d\nbond h%d_%d -> n%d_%d\n", i, j, i, j, i, j, i,
                     j, i, j, i, j + 1);
      if (i + 1 < r)
        bg_sb_printf(b, "bond n%d_%d -> v%d_%d\nbond v%d_%d -> Rv%d_%d\nbond v%d_%d -> n%d_%d\n", i, j, i, j, i, j, i,
                     j, i, j, i + 1, j);
    }
}

/* A chain of n hubs hanging off node `at` (1- and 0-junctions in turn,
 * an R on each), ended by an Se: a load or a probe on a mesh's edge. */
__attribute__((unused)) static void fm_chain_off(bg_strbuf *b, const char *name, const char *at, int n) {
  const char *prev = at;
  char cur[64], last[64] = "";
  for (int k = 0; k < n; k++) {
    snprintf(cur, sizeof cur, "%s%d", name, k);
    bg_sb_printf(b, "%d %s\nR %sr%d = 1\nbond %s -> %s\nbond %s -> %sr%d\n", k % 2 ? 0 : 1, cur, name, k, prev, cur, cur,
                 name, k);
    memcpy(last, cur, sizeof last), prev = last;
  }
  bg_sb_printf(b, "Se %sE = 0\nbond %sE -> %s\n", name, name, prev);
}

static unsigned fm_rand(unsigned *s) { return *s = *s * 1103515245u + 12345u, (*s >> 16) & 0x7fff; }

/* A random tree of n junctions (each joined to an earlier one, the kind
 * opposite its parent's) with a one-port (R, I or C) on each junction that
 * has fewer than three bonds, and a source at the root. */
static void fm_tree(bg_strbuf *b, int n, unsigned seed) {
  static const char *kind[] = {"R", "I", "C"};
  int *parent = calloc((size_t)n, sizeof *parent), *deg = calloc((size_t)n, sizeof *deg), *type = calloc((size_t)n, sizeof *type);
  bg_sb_printf(b, "model tree%u\nSe U = 1\n", seed);
  deg[0] = 1;
  for (int i = 1; i < n; i++) {
    int p;
    do p = (int)(fm_rand(&seed) % (unsigned)i);
    while (deg[p] >= 4);
    parent[i] = p, deg[p]++, deg[i]++, type[i] = !type[p];
  }
  for (int i = 0; i < n; i++) {
    bg_sb_printf(b, "%d j%d\n", type[i], i);
    if (deg[i] < 3) bg_sb_printf(b, "%s w%d = 1\n", kind[fm_rand(&seed) % 3], i);
  }
  bg_sb_puts(b, "bond U -> j0\n");
  for (int i = 1; i < n; i++) bg_sb_printf(b, "bond j%d -> j%d\n", parent[i], i);
  for (int i = 0; i < n; i++)
    if (deg[i] < 3) bg_sb_printf(b, "bond j%d -> w%d\n", i, i);
  free(parent), free(deg), free(type);
}

/* n species (a C on a 0-junction each) in a ring of reactions (an R on a
 * 1-junction between neighbours, every third reaction across the ring),
 * each reaction's rate modulated by the concentration of another species:
 * as many modulating signals as reactions. */
__attribute__((unused)) static void fm_reactions(bg_strbuf *b, int n) {
  bg_sb_printf(b, "model reactions%d\nSf feed = 1\n", n);
  for (int i = 0; i < n; i++) bg_sb_printf(b, "0 s%d\nC c%d = 1\n", i, i);
  int nr = n + n / 3;
  for (int k = 0; k < nr; k++) bg_sb_printf(b, "1 r%d\nR k%d : f = (1 + c%d.e) * e\n", k, k, (k * 7 + 3) % n);
  bg_sb_puts(b, "bond feed -> s0\n");
  for (int i = 0; i < n; i++) bg_sb_printf(b, "bond s%d -> c%d\n", i, i);
  for (int k = 0; k < nr; k++) {
    int from = k < n ? k : (3 * (k - n)) % n, to = k < n ? (k + 1) % n : (from + n / 2) % n;
    bg_sb_printf(b, "bond s%d -> r%d\nbond r%d -> k%d\nbond r%d -> s%d\n", from, k, k, k, k, to);
  }
}

/* The layout benchmark's reaction network (bench/gen_layout_models.py):
 * n reactions, each modulated by a species' concentration, on a ring of
 * 3n/4 species; the reactions beyond the ring's join a species to the one
 * opposite, from neighbouring species (their chords side by side). */
__attribute__((unused)) static void fm_reactions_bench(bg_strbuf *b, int n) {
  int ns = 3 * n / 4 > 4 ? 3 * n / 4 : 4;
  bg_sb_printf(b, "model reactions%d\nSf feed = 1\n", n);
  for (int i = 0; i < ns; i++) bg_sb_printf(b, "0 s%d\nC c%d = 1\n", i, i);
  for (int k = 0; k < n; k++) bg_sb_printf(b, "1 r%d\nR k%d : f = (1 + c%d.e) * e\n", k, k, (k * 7 + 3) % ns);
  bg_sb_puts(b, "bond feed -> s0\n");
  for (int i = 0; i < ns; i++) bg_sb_printf(b, "bond s%d -> c%d\n", i, i);
  for (int k = 0; k < n; k++) {
    int from = k % ns, to = k < ns ? (from + 1) % ns : (from + ns / 2) % ns;
    bg_sb_printf(b, "bond s%d -> r%d\nbond r%d -> k%d\nbond r%d -> s%d\n", from, k, k, k, k, to);
  }
}

/* A held-out signal model (not used to tune the router): an RC ladder of k
 * sections whose resistors are each modulated by the voltage two sections
 * on (a C's effort) and, every third section, by the source's flow (a bond
 * variable): signals that run along the ladder against the power. */
__attribute__((unused)) static void fm_modladder(bg_strbuf *b, int k) {
  bg_sb_printf(b, "model modladder%d\nSe U = 1\nR load = 10\n", k);
  for (int i = 0; i < k; i++) {
    bg_sb_printf(b, "1 s%d\n0 n%d\nC C%d = 1\n", i, i, i);
    if (i % 3 == 2) bg_sb_printf(b, "R R%d : e = (1 + f1) * f\n", i);
    else bg_sb_printf(b, "R R%d : e = (1 + C%d.e) * f\n", i, (i + 2) % k);
  }
  bg_sb_puts(b, "bond 1 U -> s0\n");
  for (int i = 0; i < k; i++) {
    bg_sb_printf(b, "bond s%d -> R%d\nbond s%d -> n%d\nbond n%d -> C%d\n", i, i, i, i, i, i);
    if (i + 1 < k) bg_sb_printf(b, "bond n%d -> s%d\n", i, i + 1);
  }
  bg_sb_printf(b, "bond n%d -> load\n", k - 1);
}

/* Three levels of submodels: Outer holds two Middles, each Middle two
 * Inners (an R and a C); the model chains two Outers between a source and
 * a load. */
/* n instances of fm_nested's Outer in a chain (20 nodes each): above 100,
 * a model the rows layout draws by default, its frames three deep. */
__attribute__((unused)) static void fm_outers(bg_strbuf *b, int n) {
  bg_sb_printf(b, "model outers%d\n", n);
  bg_sb_puts(b, "submodel Inner\n  port p, n\n  1 js\n  R r = 1\n  0 jc\n  C c = 1\n"
                "  bond p -> js\n  bond js -> r\n  bond js -> jc\n  bond jc -> c\n  bond jc -> n\nend\n"
                "submodel Middle\n  port p, n\n  Inner S1\n  Inner S2\n  0 jm\n  I m = 1\n"
                "  bond p -> S1.p\n  bond S1.n -> jm\n  bond jm -> m\n  bond jm -> S2.p\n  bond S2.n -> n\nend\n"
                "submodel Outer\n  port p, n\n  Middle M1\n  Middle M2\n"
                "  bond p -> M1.p\n  bond M1.n -> M2.p\n  bond M2.n -> n\nend\nSe U = 1\nR load = 1\n");
  for (int i = 0; i < n; i++) bg_sb_printf(b, "Outer O%d\n", i);
  bg_sb_puts(b, "bond U -> O0.p\n");
  for (int i = 0; i + 1 < n; i++) bg_sb_printf(b, "bond O%d.n -> O%d.p\n", i, i + 1);
  bg_sb_printf(b, "bond O%d.n -> load\n", n - 1);
}

/* A chain of n damped masses (issue 31, one-ports at 45 degrees beside a
 * label): each a 1-junction with its inertia, damper and force, the next
 * one through a 0-junction with a spring. Five bonds a mass: its four
 * sides taken, one one-port on a diagonal cell, beside the cell above or
 * below the junction that another one-port's label holds. */
__attribute__((unused)) static void fm_damped_masses(bg_strbuf *b, int n) {
  bg_sb_printf(b, "model damped%d\nSe U = 1\n", n);
  for (int i = 0; i < n; i++) {
    bg_sb_printf(b, "1 v%d\nI m%d = 1\nR b%d = 0.1\nSe F%d = 1\n", i, i, i, i);
    if (i + 1 < n) bg_sb_printf(b, "0 s%d\nC k%d = 1\n", i, i);
  }
  bg_sb_puts(b, "bond U -> v0\n");
  for (int i = 0; i < n; i++) {
    bg_sb_printf(b, "bond v%d -> m%d\nbond v%d -> b%d\nbond F%d -> v%d\n", i, i, i, i, i, i);
    if (i + 1 < n) bg_sb_printf(b, "bond v%d -> s%d\nbond s%d -> k%d\nbond s%d -> v%d\n", i, i, i, i, i, i + 1);
  }
}

static void fm_nested(bg_strbuf *b) {
  bg_sb_puts(b, "model nested\n"
                "submodel Inner\n  port p, n\n  1 js\n  R r = 1\n  0 jc\n  C c = 1\n"
                "  bond p -> js\n  bond js -> r\n  bond js -> jc\n  bond jc -> c\n  bond jc -> n\nend\n"
                "submodel Middle\n  port p, n\n  Inner S1\n  Inner S2\n  0 jm\n  I m = 1\n"
                "  bond p -> S1.p\n  bond S1.n -> jm\n  bond jm -> m\n  bond jm -> S2.p\n  bond S2.n -> n\nend\n"
                "submodel Outer\n  port p, n\n  Middle M1\n  Middle M2\n"
                "  bond p -> M1.p\n  bond M1.n -> M2.p\n  bond M2.n -> n\nend\n"
                "Se U = 1\nOuter O1\nOuter O2\nR load = 1\n"
                "bond U -> O1.p\nbond O1.n -> O2.p\nbond O2.n -> load\n");
}
/* Held out from the frame work (issue 31, kept whole when a long chain
 * folds): n stages in a row, each three cells in series with a branch
 * instance on a 0-junction between its second and third cell, a load on
 * the last stage's port. Two levels, frames side by side and one hanging
 * below its junction. */
static void fm_stages(bg_strbuf *b, int n) {
  bg_sb_puts(b, "model stages\n"
                "submodel Cell\n  port p, n\n  1 j\n  R r = 1\n  0 k\n  I l = 1\n"
                "  bond p -> j\n  bond j -> r\n  bond j -> k\n  bond k -> l\n  bond k -> n\nend\n"
                "submodel Shunt\n  port p\n  1 s\n  C c = 1\n  R g = 2\n  bond p -> s\n  bond s -> c\n  bond s -> g\nend\n"
                "submodel Stage\n  port p, n\n  Cell A\n  Cell B\n  Cell D\n  Shunt H\n  0 m\n"
                "  bond p -> A.p\n  bond A.n -> B.p\n  bond B.n -> m\n  bond m -> H.p\n  bond m -> D.p\n  bond D.n -> n\nend\n"
                "Se U = 1\n");
  for (int i = 1; i <= n; i++) bg_sb_printf(b, "Stage T%d\n", i);
  bg_sb_puts(b, "R load = 1\nbond U -> T1.p\n");
  for (int i = 1; i < n; i++) bg_sb_printf(b, "bond T%d.n -> T%d.p\n", i, i + 1);
  bg_sb_printf(b, "bond T%d.n -> load\n", n);
}

/* A battery pack as a ring (issue 31, frames in rings): 3 to 12 instances
 * of three submodels (a cell with one or two RC pairs and its own source,
 * a wire) in series, closed through the model's own load junction, with a
 * charger or a wire inductance there or neither; the seed picks. The ring
 * drawing splits where it starts and where its two ways meet: each split
 * must fall between instances, so every frame stays whole. */
__attribute__((unused)) static void fm_ring_pack(bg_strbuf *b, int seed) {
  static const char *const body[3] = {
      "  port p, n\n  Se ocv = E\n  1 s\n  R r0 = 0.01\n  0 a\n  C c1 = 1000\n  R r1 = 0.02\n"
      "  bond p -> s\n  bond ocv -> s\n  bond s -> r0\n  bond s -> a\n  bond a -> c1\n  bond a -> r1\n"
      "  bond a -> n\n",
      "  port p, n\n  Se ocv = E\n  1 s\n  R r0 = 0.01\n  0 a\n  C c1 = 1000\n  R r1 = 0.02\n  1 t\n  0 b\n"
      "  C c2 = 5000\n  R r2 = 0.05\n  bond p -> s\n  bond ocv -> s\n  bond s -> r0\n  bond s -> a\n"
      "  bond a -> c1\n  bond a -> r1\n  bond a -> t\n  bond t -> b\n  bond b -> c2\n  bond b -> r2\n"
      "  bond b -> n\n",
      "  port p, n\n  1 s\n  R r = 0.001\n  I l = 1e-6\n  bond p -> s\n  bond s -> r\n  bond s -> l\n"
      "  bond s -> n\n"};
  static const char *const name[3] = {"Cell", "Cell2", "Wire"};
  unsigned s = (unsigned)seed * 7919u + 17u;
  int n = 3 + (int)(fm_rand(&s) % 10u), own = (int)(fm_rand(&s) % 3u);
  bg_sb_printf(b, "model pack%d\n", seed);
  for (int k = 0; k < 3; k++) bg_sb_printf(b, "submodel %s%s\n%send\n", name[k], k < 2 ? "(E = 3.7)" : "", body[k]);
  for (int i = 0; i < n; i++) bg_sb_printf(b, "%s K%d\n", name[fm_rand(&s) % 3u], i);
  bg_sb_puts(b, "R load = 1\n1 loop\n");
  if (own == 1) bg_sb_puts(b, "Se charger = 15\nbond charger -> loop\n");
  if (own == 2) bg_sb_puts(b, "I wire = 1e-6\nbond loop -> wire\n");
  for (int i = 0; i + 1 < n; i++) bg_sb_printf(b, "bond K%d.n -> K%d.p\n", i, i + 1);
  bg_sb_printf(b, "bond K%d.n -> loop\nbond loop -> load\nbond loop -> K0.p\n", n - 1);
}

/* Spine models (issue 31: the power chain from source to load is the main
 * row, side branches hang off it). A π filter of n sections: a source
 * resistance, then per section a shunt branch (a 1-junction with a C and
 * its series resistance) on a 0-junction and a series inductor on a
 * 1-junction, a last shunt and a load. */
__attribute__((unused)) static void fm_pifilter(bg_strbuf *b, int n) {
  bg_sb_printf(b, "model pifilter%d\nSe U = 1\n1 src\nR Rs = 1\nR load = 10\n", n);
  for (int i = 0; i <= n; i++) {
    bg_sb_printf(b, "0 p%d\n1 h%d\nC Cp%d = 1\nR Re%d = 0.1\n", i, i, i, i);
    if (i < n) bg_sb_printf(b, "1 l%d\nI L%d = 1\n", i, i);
  }
  bg_sb_puts(b, "bond U -> src\nbond src -> Rs\nbond src -> p0\n");
  for (int i = 0; i <= n; i++) {
    bg_sb_printf(b, "bond p%d -> h%d\nbond h%d -> Cp%d\nbond h%d -> Re%d\n", i, i, i, i, i, i);
    if (i < n) bg_sb_printf(b, "bond p%d -> l%d\nbond l%d -> L%d\nbond l%d -> p%d\n", i, i, i, i, i, i + 1);
  }
  bg_sb_printf(b, "bond p%d -> load\n", n);
}

/* A power chain of n junctions (1, 0, ... with an R, I or C each) from a
 * source to a load, with random side branches: from a junction, a chain of
 * one to three junctions (each with a one-port), shorter than what is left
 * of the main chain; a branch's junction may branch once more. */
static void fm_branchy(bg_strbuf *b, int n, unsigned seed) {
  static const char *kind[] = {"R", "I", "C"};
  bg_sb_printf(b, "model branchy%u\nSe U = 1\nR load = 1\n", seed);
  for (int i = 0; i < n; i++) bg_sb_printf(b, "%d j%d\n%s w%d = 1\n", i % 2, i, kind[fm_rand(&seed) % 3], i);
  bg_sb_puts(b, "bond U -> j0\n");
  for (int i = 0; i < n; i++) {
    bg_sb_printf(b, "bond j%d -> w%d\n", i, i);
    if (i + 1 < n) bg_sb_printf(b, "bond j%d -> j%d\n", i, i + 1);
    int left = n - 1 - i;
    if (left < 2 || fm_rand(&seed) % 3) continue;
    int len = 1 + (int)(fm_rand(&seed) % 3), prev = -1;
    if (len >= left) len = left - 1;
    for (int k = 0; k < len; k++) { /* the branch's junctions: b<i>_<k>, kinds alternating from j<i>'s */
      bg_sb_printf(b, "%d b%d_%d\n%s x%d_%d = 1\n", (i + k + 1) % 2, i, k, kind[fm_rand(&seed) % 3], i, k);
      if (prev < 0) bg_sb_printf(b, "bond j%d -> b%d_%d\n", i, i, k);
      else bg_sb_printf(b, "bond b%d_%d -> b%d_%d\n", i, prev, i, k);
      bg_sb_printf(b, "bond b%d_%d -> x%d_%d\n", i, k, i, k);
      if (k == 0 && len == 1 && fm_rand(&seed) % 2) /* a second one-port on a one-junction branch */
        bg_sb_printf(b, "%s y%d = 1\nbond b%d_0 -> y%d\n", kind[fm_rand(&seed) % 3], i, i, i);
      prev = k;
    }
  }
  bg_sb_printf(b, "bond j%d -> load\n", n - 1);
}

/* Disconnected parts (issue 31: parts packed side by side, not stacked
 * with gaps or placed diagonally): k parts of random shapes and sizes,
 * each a chain of 2-12 elements, a ladder of 1-5 sections or a tree of
 * 3-12 junctions, names prefixed per part. */
__attribute__((unused)) static void fm_parts(bg_strbuf *b, int k) {
  static const char *kind[] = {"R", "I", "C"};
  unsigned seed = 91u + (unsigned)k;
  bg_sb_printf(b, "model parts%d\n", k);
  for (int p = 0; p < k; p++) {
    int shape = (int)(fm_rand(&seed) % 3), n = 0;
    bg_sb_printf(b, "Se U%d = 1\n", p);
    if (shape == 0) { /* a chain */
      n = 2 + (int)(fm_rand(&seed) % 11);
      for (int i = 0; i < n; i++) bg_sb_printf(b, "%d p%dj%d\n%s p%dw%d = 1\n", i % 2, p, i, kind[i % 3], p, i);
      bg_sb_printf(b, "bond U%d -> p%dj0\n", p, p);
      for (int i = 0; i < n; i++) {
        bg_sb_printf(b, "bond p%dj%d -> p%dw%d\n", p, i, p, i);
        if (i + 1 < n) bg_sb_printf(b, "bond p%dj%d -> p%dj%d\n", p, i, p, i + 1);
      }
    } else if (shape == 1) { /* a ladder */
      n = 1 + (int)(fm_rand(&seed) % 5);
      bg_sb_printf(b, "R p%dload = 1\n", p);
      for (int i = 0; i < n; i++) bg_sb_printf(b, "1 p%ds%d\nR p%dR%d = 1\n0 p%dn%d\nC p%dC%d = 1\n", p, i, p, i, p, i, p, i);
      bg_sb_printf(b, "bond U%d -> p%ds0\n", p, p);
      for (int i = 0; i < n; i++) {
        bg_sb_printf(b, "bond p%ds%d -> p%dR%d\nbond p%ds%d -> p%dn%d\nbond p%dn%d -> p%dC%d\n", p, i, p, i, p, i, p, i, p, i,
                     p, i);
        if (i + 1 < n) bg_sb_printf(b, "bond p%dn%d -> p%ds%d\n", p, i, p, i + 1);
      }
      bg_sb_printf(b, "bond p%dn%d -> p%dload\n", p, n - 1, p);
    } else { /* a tree */
      n = 3 + (int)(fm_rand(&seed) % 10);
      int par[12], deg[12] = {1}, type[12] = {0};
      for (int i = 1; i < n; i++) {
        int q;
        do q = (int)(fm_rand(&seed) % (unsigned)i);
        while (deg[q] >= 4);
        par[i] = q, deg[q]++, deg[i] = 1, type[i] = !type[q];
      }
      for (int i = 0; i < n; i++) {
        bg_sb_printf(b, "%d p%dj%d\n", type[i], p, i);
        if (deg[i] < 3) bg_sb_printf(b, "%s p%dw%d = 1\nbond p%dj%d -> p%dw%d\n", kind[fm_rand(&seed) % 3], p, i, p, i, p, i);
      }
      bg_sb_printf(b, "bond U%d -> p%dj0\n", p, p);
      for (int i = 1; i < n; i++) bg_sb_printf(b, "bond p%dj%d -> p%dj%d\n", p, par[i], p, i);
    }
  }
}

/* The model `text` with some of its bonds turned round: each bond line
 * (`bond A -> B`, no number or options) turned with probability one half.
 * Users write bonds the way power flows in their model, a source's on a
 * branch pointing at the main chain; the generators above point every bond
 * away from the source. A junction takes bonds either way and a one-port's
 * law keeps its physics (docs/format.md), so the model stays valid. */
__attribute__((unused)) static void fm_flip_bonds(bg_strbuf *b, const char *text, unsigned seed) {
  for (const char *p = text; *p;) {
    const char *eol = strchr(p, '\n'), *end = eol ? eol : p + strlen(p);
    char a[64], h[64];
    int len = (int)(end - p), used = 0;
    if (len < 120 && sscanf(p, "bond %63s -> %63[^ \n]%n", a, h, &used) == 2 && used == len && fm_rand(&seed) % 2)
      bg_sb_printf(b, "bond %s -> %s\n", h, a);
    else
      bg_sb_printf(b, "%.*s\n", len, p);
    p = eol ? eol + 1 : end;
  }
}

/* A generated model for a table of them: its name and its maker with n. */
typedef struct fm_model {
  const char *name;
  void (*make)(bg_strbuf *b, int n);
  int n;
} fm_model;

/* Makers of that shape for the models with other parameters (the seeds
 * are the figure tests'). */
/* A held-out reaction network (bench/gen_layout_models.py randnet, with
 * this file's random numbers): species (C on a 0-junction), one reaction
 * (R on a 1-junction) a signal, each between the species it is numbered
 * by (while there are species) or a random one and another random
 * species, its rate modulated by a random species. Nothing in the drawing
 * was tuned to these. */
__attribute__((unused)) static void fm_randnet(bg_strbuf *b, int n, unsigned seed) {
  unsigned s = seed;
  int ns = 3 * n / 4 > 4 ? 3 * n / 4 : 4;
  bg_sb_printf(b, "model randnet%d_%u\nSf feed = 1\n", n, seed);
  for (int i = 0; i < ns; i++) bg_sb_printf(b, "0 s%d\nC c%d = 1\n", i, i);
  for (int k = 0; k < n; k++) bg_sb_printf(b, "1 r%d\nR k%d : f = (1 + c%d.e) * e\n", k, k, (int)(fm_rand(&s) % (unsigned)ns));
  bg_sb_puts(b, "bond feed -> s0\n");
  for (int i = 0; i < ns; i++) bg_sb_printf(b, "bond s%d -> c%d\n", i, i);
  for (int k = 0; k < n; k++) {
    int a = k < ns ? k : (int)(fm_rand(&s) % (unsigned)ns), z = (int)(fm_rand(&s) % (unsigned)(ns - 1));
    z += z >= a;
    bg_sb_printf(b, "bond s%d -> r%d\nbond r%d -> k%d\nbond r%d -> s%d\n", a, k, k, k, k, z);
  }
}

/* A held-out tree (bench/gen_layout_models.py randtree, with this file's
 * random numbers): junctions each joined to one of the six before it, so
 * a junction may have many bonds (fm_tree keeps them to four), none to two
 * one-ports each, one at least where a junction would have a single bond. */
__attribute__((unused)) static void fm_randtree(bg_strbuf *b, int n, unsigned seed) {
  static const char *kind[] = {"R", "C", "I"};
  int *parent = calloc((size_t)n + 1, sizeof *parent), *deg = calloc((size_t)n + 1, sizeof *deg);
  bg_sb_printf(b, "model randtree%d_%u\nSe U = 1\n", n, seed);
  deg[0] = 1;
  for (int v = 1; v < n; v++) {
    int back = v < 6 ? v : 6;
    parent[v] = v - 1 - (int)(fm_rand(&seed) % (unsigned)back), deg[parent[v]]++, deg[v]++;
  }
  for (int v = 0; v < n; v++) bg_sb_printf(b, "%d j%d\n", v % 2, v);
  bg_sb_puts(b, "bond U -> j0\n");
  for (int v = 1; v < n; v++) bg_sb_printf(b, "bond j%d -> j%d\n", parent[v], v);
  for (int v = 0; v < n; v++) {
    int k = (int)(fm_rand(&seed) % 3);
    if (k == 0 && deg[v] < 2) k = 1;
    for (int q = 0; q < k; q++)
      bg_sb_printf(b, "%s p%d_%d = 1\nbond j%d -> p%d_%d\n", kind[fm_rand(&seed) % 3], v, q, v, v, q);
  }
  free(parent), free(deg);
}

/* A junction of many one-ports (issue 31, bg_layout_ring): junction kind
 * `one` (1 or 0) with n one-ports of random kinds and names of random
 * lengths (so boxes differ) and an effort source; with `bus` the junction
 * sits in a chain (a source's 1-junction before it, a 1-junction with an
 * inertia, a capacitor's 0-junction and a load after it) and one resistor
 * after it is modulated by the first one-port's effort. */
__attribute__((unused)) static void fm_star(bg_strbuf *b, int n, int one, int bus, unsigned seed) {
  static const char *kind[] = {"R", "C", "I"}, *stem[] = {"", "a", "stage", "compliance"};
  char first[32] = "U";
  bg_sb_printf(b, "model star%d_%d%s\nSe U = 1\n%d hub\n", n, one, bus ? "_bus" : "", one);
  for (int i = 0; i < n; i++) {
    const char *k = kind[fm_rand(&seed) % 3], *st = stem[fm_rand(&seed) % 4];
    bg_sb_printf(b, "%s %s%s%d = 1\nbond hub -> %s%s%d\n", k, k, st, i, k, st, i);
    if (i == 0) snprintf(first, sizeof first, "%s%s%d", k, st, i);
  }
  if (!bus) {
    bg_sb_puts(b, "bond U -> hub\n");
    return;
  }
  bg_sb_printf(b, "1 s0\nR Rs = 1\n1 s1\nI L = 1\n0 n2\nC Cl = 1\nR load = 2\nR g : e = (1 + %s.e) * f\n"
                  "bond U -> s0\nbond s0 -> Rs\nbond s0 -> hub\nbond hub -> s1\nbond s1 -> L\nbond s1 -> n2\n"
                  "bond n2 -> Cl\nbond n2 -> load\nbond s1 -> g\n",
               first);
}

/* A held-out tree with junctions of many one-ports: n junctions, each
 * joined to one of the four before it; every third has 0-12 one-ports, the
 * others 0-2 (one at least where a junction would have a single bond);
 * random kinds and name lengths; three resistors modulated by random
 * capacitors' efforts. */
__attribute__((unused)) static void fm_ringtree(bg_strbuf *b, int n, unsigned seed) {
  static const char *kind[] = {"R", "C", "I"}, *stem[] = {"", "x", "stage"};
  static const int many[] = {0, 1, 2, 3, 5, 9, 12};
  int *deg = calloc((size_t)n + 1, sizeof *deg), ncap = 0;
  char (*cap)[32] = calloc(64, sizeof *cap);
  bg_strbuf bonds = {0};
  bg_sb_printf(b, "model ringtree%d_%u\nSe U = 1\n", n, seed);
  for (int v = 0; v < n; v++) bg_sb_printf(b, "%d j%d\n", v % 2, v);
  bg_sb_puts(&bonds, "bond U -> j0\n"), deg[0]++;
  for (int v = 1; v < n; v++) {
    int p = v - 1 - (int)(fm_rand(&seed) % (unsigned)(v < 4 ? v : 4));
    bg_sb_printf(&bonds, "bond j%d -> j%d\n", p, v), deg[p]++, deg[v]++;
  }
  for (int v = 0; v < n; v++) {
    int cnt = v % 3 == 0 ? many[fm_rand(&seed) % 7] : (int)(fm_rand(&seed) % 3);
    if (deg[v] + cnt < 2) cnt = 1;
    for (int q = 0; q < cnt; q++) {
      const char *k = kind[fm_rand(&seed) % 3], *st = stem[fm_rand(&seed) % 3];
      bg_sb_printf(b, "%s %c%s%d_%d = 1\n", k, k[0] + 32, st, v, q);
      bg_sb_printf(&bonds, "bond j%d -> %c%s%d_%d\n", v, k[0] + 32, st, v, q);
      if (k[0] == 'C' && ncap < 64) snprintf(cap[ncap++], 32, "%c%s%d_%d", k[0] + 32, st, v, q);
    }
  }
  for (int i = 0; i < 3 && ncap; i++) {
    int v = (int)(fm_rand(&seed) % (unsigned)n);
    bg_sb_printf(b, "R m%d : e = (1 + %s.e) * f\n", i, cap[fm_rand(&seed) % (unsigned)ncap]);
    bg_sb_printf(&bonds, "bond j%d -> m%d\n", v, i);
  }
  bg_sb_puts(b, bg_sb_str(&bonds));
  bg_sb_free(&bonds), free(deg), free(cap);
}

__attribute__((unused)) static void fm_make_tree(bg_strbuf *b, int n) { fm_tree(b, n, 31u + (unsigned)n); }
__attribute__((unused)) static void fm_make_grid(bg_strbuf *b, int n) { fm_grid(b, n, n); }
__attribute__((unused)) static void fm_make_nested(bg_strbuf *b, int n) { (void)n, fm_nested(b); }
__attribute__((unused)) static void fm_make_branchy(bg_strbuf *b, int n) { fm_branchy(b, n, 7u + (unsigned)n); }
__attribute__((unused)) static void fm_make_stages(bg_strbuf *b, int n) { fm_stages(b, n); }
__attribute__((unused)) static void fm_make_randtree(bg_strbuf *b, int n) { fm_randtree(b, n, 7919u + (unsigned)n); }
/* Twin bonds (issue 31): a random tree of n junctions (1 and 0 in turn)
 * whose every third tree bond is doubled (two bonds between the same
 * junctions, as property-campaign models join a pair twice), one to three
 * one-ports on each junction so that most have every side taken, a source
 * at the root, and every fourth junction with a two-port C field whose both
 * ports are its bonds. */
__attribute__((unused)) static void fm_twins(bg_strbuf *b, int n, unsigned seed) {
  static const char *kind[] = {"R", "I", "C"};
  bg_sb_printf(b, "model twins%d_%u\nSe U = 1\n", n, seed);
  int *parent = calloc((size_t)n, sizeof *parent);
  for (int i = 1; i < n; i++) parent[i] = (int)(fm_rand(&seed) % (unsigned)i);
  for (int i = 0; i < n; i++) {
    bg_sb_printf(b, "%d j%d\n", i % 2, i);
    int k = 1 + (int)(fm_rand(&seed) % 3);
    for (int w = 0; w < k; w++) bg_sb_printf(b, "%s w%d_%d = 1\n", kind[fm_rand(&seed) % 3], i, w);
    if (i % 4 == 3) bg_sb_printf(b, "C K%d(pa, pb) : energy = pa.q^2/2 + pb.q^2/2 + 0.2*pa.q*pb.q\n", i);
    bg_sb_printf(b, "bond j%d -> w%d_0\n", i, i);
    for (int w = 1; w < k; w++) bg_sb_printf(b, "bond w%d_%d -> j%d\n", i, w, i);
    if (i % 4 == 3) bg_sb_printf(b, "bond j%d -> K%d.pa\nbond j%d -> K%d.pb\n", i, i, i, i);
  }
  bg_sb_puts(b, "bond U -> j0\n");
  for (int i = 1; i < n; i++) {
    bg_sb_printf(b, "bond j%d -> j%d\n", parent[i], i);
    if (i % 3 == 0) bg_sb_printf(b, "bond j%d -> j%d\n", i, parent[i]);
  }
  free(parent);
}

/* A chain of n moving-plate transducers (a two-port C field between an
 * electrical 1-junction with a series R and a mechanical one with a mass
 * and a spring), each mechanical junction feeding the next electrical
 * one: a forest through fields, over 2 000 nodes from 300 sections. */
__attribute__((unused)) static void fm_fieldchain(bg_strbuf *b, int n) {
  bg_sb_printf(b, "model fieldchain%d\nSe U = 1\n", n);
  for (int i = 0; i < n; i++)
    bg_sb_printf(b, "1 je%d\nR Rs%d = 1\nC K%d(el, mech) : energy = el.q^2 * mech.q / 2  [q0 = (0, 1)]\n"
                 "1 jm%d\nI mass%d = 1\nC spring%d = 0.25\n", i, i, i, i, i, i);
  bg_sb_puts(b, "bond U -> je0\n");
  for (int i = 0; i < n; i++) {
    bg_sb_printf(b, "bond je%d -> Rs%d\nbond je%d -> K%d.el\nbond jm%d -> K%d.mech\n", i, i, i, i, i, i);
    bg_sb_printf(b, "bond jm%d -> mass%d\nbond jm%d -> spring%d\n", i, i, i, i);
    if (i + 1 < n) bg_sb_printf(b, "bond jm%d -> je%d\n", i, i + 1);
  }
}

#endif
