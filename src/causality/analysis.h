/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_analysis: what causality assignment and causal analysis found in a model.
 * Written by bg_causality_assign and bg_analysis_run, read by the equations,
 * the renderers and the JSON writer. Never modifies the model. Lists are
 * flat arrays addressed by <list>_adr / <list>_n (MuJoCo style). */
#ifndef BG_ANALYSIS_H
#define BG_ANALYSIS_H
#include "base/arena.h"
#include "base/diag.h"
#include "model/model.h"

/* Where the causal stroke of a bond sits. */
typedef enum { BG_STROKE_NONE, BG_STROKE_HEAD, BG_STROKE_TAIL } bg_stroke;

/* Why a bond got its stroke (JSON bonds[].reason). */
typedef enum {
  BG_REASON_NONE, BG_REASON_SOURCE, BG_REASON_STORE, BG_REASON_RESISTOR,
  BG_REASON_CHOICE, BG_REASON_PROPAGATION, BG_REASON_USER, BG_REASON_LAGRANGE
} bg_reason;

/* Causality of an element (JSON elements[].causality). */
typedef enum {
  BG_CAUS_NONE, BG_CAUS_FIXED, BG_CAUS_INTEGRAL, BG_CAUS_DERIVATIVE,
  BG_CAUS_RESISTANCE, BG_CAUS_CONDUCTANCE, BG_CAUS_TRANSFER /* junctions, TF, GY */
} bg_causality;

typedef enum { BG_FORM_ODE, BG_FORM_DAE, BG_FORM_INCOMPLETE } bg_model_form;
typedef enum { BG_TLOOP_FLAT, BG_TLOOP_OPEN } bg_tloop_kind;
/* path_order of a path with a source end: it closes no loop (Remark 4.1);
 * the JSON writes null. */
#define BG_PATH_ORDER_NONE (-1000000)

/* A signal of the signal flow graph: 2*bond + 0 for its effort, + 1 for its flow. */
#define BG_SIG_EFFORT(b) (2 * (b))
#define BG_SIG_FLOW(b) (2 * (b) + 1)

typedef struct bg_analysis_limits {
  int max_paths;  /* listing caps (output-sensitive enumeration); 0 = default */
  int max_loops;
} bg_analysis_limits;

typedef struct bg_analysis {
  int method;   /* bg_method actually used */
  int complete; /* every bond has a stroke */

  /* per bond (model ids) */
  int *bond_stroke; /* bg_stroke */
  int *bond_reason; /* bg_reason */
  int *bond_step;   /* trace step (1-based) that assigned it; 0 = none */
  int *bond_conflict; /* the stroke violates a rule at one of its ends */

  /* per element */
  int *elem_caus;     /* bg_causality */
  int *elem_inverted; /* the law had to be inverted (or solved implicitly) */

  /* Lagrange causality: artificial flow sources, at a 1-junction or, where a
   * 1-junction had to be inserted, splitting a bond. */
  int nlag;
  int *lag_junction; /* element id of the 1-junction, or -1 */
  int *lag_bond;     /* bond split by an inserted 1-junction, or -1 */
  char **lag_force;  /* generalised force in words, e.g. "-R*f4" */

  /* the causality trace, one entry a step */
  int ntrace;
  char **trace_text;

  /* causal conflicts (Definitions 4.18, 4.19) */
  int nconflict;
  int *conflict_node;   /* element id */
  int *conflict_type;   /* 1 or 2 */
  int *conflict_degree; /* k for type 2, 0 for type 1 */
  int *conflict_adr, *conflict_n; /* into conflict_bonds */
  int *conflict_bonds;

  /* causal paths between ports of 1-port elements (including source ends) */
  int npath, npath_omitted;
  int *path_adr, *path_n; /* bonds in order from end 0 to end 1, into path_bonds */
  int *path_bonds;
  int *path_end0, *path_end1; /* element ids of the 1-port ends */
  const char **path_kind;     /* "R-R", "C-I", "S-*", ... */
  int *path_class;            /* 1, 2, or 0 for none (JSON null) */
  int *path_order;            /* integrations left in the loop it closes */

  /* causal loops (closed causal paths) */
  int ncloop, ncloop_omitted;
  int *cloop_adr, *cloop_n;
  int *cloop_bonds;
  char **cloop_gain;        /* symbolic */
  double *cloop_gain_value;
  int *cloop_class;         /* 4 or 5 */
  int cloops_disjoint;      /* pairwise disjoint */
  int rosenberg_andry;      /* disjoint and no gain +1 */

  /* topological loops of the signal flow graph */
  int ntloop, ntloop_omitted; /* omitted: a lower bound (see tloop_capped) */
  int tloop_capped;            /* the cycle enumeration stopped at the listing cap */
  int *tloop_kind;          /* bg_tloop_kind */
  int *tloop_order;
  int *tloop_adr, *tloop_n; /* signals in order, into tloop_signals (BG_SIG_*) */
  int *tloop_signals;
  char **tloop_gain;
  double *tloop_gain_value;
  int *tloop_algebraic;
  char **tloop_cause;       /* "causal path 1", "causal loop 1", "internal modulation of T" */

  /* summary */
  int nstates, ndependent, nalgebraic;
  char **states;             /* "m.p", "phi" */
  char **dependent_stores;   /* element names */
  char **algebraic_variables;
  int form;                  /* bg_model_form */
  int index_predicted;       /* 0, 1, 2 (2 = "above 1"); -1 unknown */
  char *index_reason;
  int form_parameter_dependent; /* Equation 4.45 case */
  /* estimates from first- and second-order paths, linearised at the initial point */
  int nestimate;
  int *estimate_kind;  /* 0 time constant [s], 1 natural frequency [rad/s] */
  int *estimate_path;  /* path id (0-based) */
  double *estimate_value;

  bg_arena arena; /* owns everything above */
} bg_analysis;

/* Bond b was split by a 1-junction that Lagrange causality inserted: it has
 * no stroke of its own, and both its original ends receive the inserted
 * junction's flow (the stroke is "away" from both; docs/causality.md). */
static inline int bg_analysis_bond_split(const bg_analysis *a, int b) {
  return a->bond_stroke[b] == BG_STROKE_NONE && a->bond_reason[b] == BG_REASON_LAGRANGE;
}
#endif
