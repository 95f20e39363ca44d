/* Causal paths and causal loops of a causal bond graph (docs/analysis.md),
 * and the entry point of the causal analysis that follows causality
 * assignment (paths, loops, signal flow graph, form, index, estimates). */
#ifndef BG_PATHS_H
#define BG_PATHS_H
#include "causality/analysis.h"
#include "model/model.h"

#define BG_DEFAULT_MAX_PATHS 1000
#define BG_DEFAULT_MAX_LOOPS 1000

/* Runs after bg_causality_assign: fills the path, cloop, tloop, summary,
 * form, index and estimate fields of a, allocating in a->arena. lim may be
 * NULL (defaults). Never modifies the model. */
void bg_analysis_run(const bg_model *m, bg_analysis *a, const bg_analysis_limits *lim);

/* Does element `elem` (one end of bond b) receive the effort of b, i.e. is
 * the causal stroke at its end? 0 when b has no stroke. */
int bg_paths_effort_in(const bg_model *m, const bg_analysis *a, int elem, int b);
/* Junction-structure node: 0, 1, TF, MTF, GY, MGY. */
int bg_paths_is_js(int kind);
/* An integral store (C with its stroke away, I with its stroke at it). */
int bg_paths_store_integral(const bg_model *m, const bg_analysis *a, int elem);

/* Fills npath, npath_omitted and the path_* arrays: every causal path
 * between ports of 1-port elements, once, listed from the end whose port
 * bond has the lower bond number, sorted by the pair of ends (file order)
 * and then bond numbers; at most max_paths listed. */
void bg_paths_find(const bg_model *m, bg_analysis *a, int max_paths);
/* Fills ncloop, ncloop_omitted and cloop_adr/n/bonds (bonds from the
 * lowest-numbered one, in the direction of its lower-numbered neighbour);
 * gains and classes are filled later (bg_analysis_run). */
void bg_cloops_find(const bg_model *m, bg_analysis *a, int max_loops);

/* The junction-structure nodes between consecutive bonds of path p
 * (nodes[0] = end 0, nodes[k] = end 1, k = path_n) or of causal loop l
 * (nodes[i] sits before bonds[i]; k = cloop_n entries). */
void bg_paths_nodes(const bg_model *m, const bg_analysis *a, int p, int *nodes);
void bg_cloops_nodes(const bg_model *m, const bg_analysis *a, int l, int *nodes);
#endif
