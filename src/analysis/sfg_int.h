/* SPDX-License-Identifier: BSD-3-Clause */
/* The signal flow graph of a causal bond graph (docs/analysis.md).
 * Nodes are the bond signals (BG_SIG_EFFORT(b), BG_SIG_FLOW(b)) followed by
 * one node per user state (2*nbond + state id). Every constitutive relation
 * and junction equation, read with the causal strokes, gives edges from its
 * inputs to its outputs, labelled with the influence coefficient: a sign, a
 * number (linearised at the initial point) and symbolic factors. Internal to
 * the analysis stage (form.c, summary.c, paths.c). */
#ifndef BG_SFG_INT_H
#define BG_SFG_INT_H
#include "causality/causality.h"
#include "base/arena.h"
#include "model/model.h"

typedef enum {
  BG_SFGE_JUNCTION, BG_SFGE_TF, BG_SFGE_GY, BG_SFGE_R, BG_SFGE_STORE,
  BG_SFGE_MOD, /* modulation: the modulating variable into the modulated output */
  BG_SFGE_STATE /* a user state's right-hand side into the state (integrator) */
} bg_sfg_edge_kind;

typedef struct bg_sfg_edge {
  int src, dst;
  int kind;  /* bg_sfg_edge_kind */
  int elem;  /* element whose relation it is; -1 for user states */
  int order; /* +1 integrator, -1 differentiator, 0 algebraic */
  double value;          /* the coefficient, sign included, without s */
  int sign;              /* sign of the symbolic text: +1 or -1 */
  const char *num[2];    /* symbolic factors over the line (NULL = none) */
  const char *den[2];    /* and under it; "s" stands for d/dt */
  int linear;            /* the relation is linear in src (constant slope) */
} bg_sfg_edge;

typedef struct bg_sfg {
  int nnode, nbondsig, nedge;
  bg_sfg_edge *edge;
  int *adr, *n, *out; /* out edges of node v: edge ids out[adr[v] .. adr[v]+n[v]) */
  double *ratio;      /* per element: a TF's or GY's modulus at the operating point,
                       * in conflict too (form.c's conflict test reads it); else 0 */
  bg_arena arena;     /* owns everything above */
} bg_sfg;

/* Builds the graph from the strokes in a (bonds without a stroke and
 * junctions in conflict contribute no edges). Parameters at their values,
 * t = t0, stores and user states at their initial values, bond variables 0. */
void bg_sfg_build(const bg_model *m, const bg_analysis *a, bg_sfg *g);
void bg_sfg_free(bg_sfg *g);
/* The first edge src -> dst, or -1. */
int bg_sfg_find_edge(const bg_sfg *g, int src, int dst);

/* A product of edge labels: the gain of a chain or loop of edges. */
typedef struct bg_gain {
  int ok;           /* every edge existed */
  int sign, order;  /* order: integrators minus differentiators */
  double value;
  int nnum, nden, cap_num, cap_den;
  const char **num, **den;
  int mod_edge;     /* first modulation edge on it, or -1 */
} bg_gain;

/* Gain of the closed chain sig[0] -> sig[1] -> ... -> sig[n-1] -> sig[0]. */
void bg_sfg_cycle_gain(const bg_sfg *g, const int *sig, int n, bg_gain *out);
/* The symbolic text of a gain ("n", "-n", "1/n", "R0*C0", "1/(L0*C0)"),
 * allocated in arena. Factors that appear over and under the line cancel. */
char *bg_gain_text(bg_gain *gn, bg_arena *arena);
void bg_gain_free(bg_gain *gn);

/* Elementary cycles of the subgraph of edges with order 0 (Johnson's
 * algorithm, iterative, restricted to the non-trivial strongly connected
 * components). fn gets each cycle's nodes in signal-flow order; it returns
 * nonzero to stop. work_budget bounds the steps (0 = unbounded); the
 * return value is 1 when the budget ran out, else 0. */
typedef int (*bg_sfg_cycle_fn)(void *ctx, const int *node, int n);
int bg_sfg_algebraic_cycles(const bg_sfg *g, bg_sfg_cycle_fn fn, void *ctx,
                            long work_budget);

/* Strongly connected components (Tarjan, iterative) of the graph without
 * integrator edges: comp[v] gets a component id; returns the number of
 * non-trivial components (more than one node, or a self-loop): the coupled
 * algebraic blocks. comp may be NULL. */
int bg_sfg_algebraic_blocks(const bg_sfg *g, int *comp);

/* Name of a node: "R1.e" / "L1.f" at the port of a 1-port element, "e4" /
 * "f4" for other bonds (bond numbers), the state's name for a state node. */
void bg_sfg_node_name(const bg_model *m, int node, char *buf, int size);
#endif
