/* SPDX-License-Identifier: BSD-3-Clause */
/* Causal paths and causal loops of a causal bond graph (docs/analysis.md):
 * paths.c's functions that form.c and sfg.c call. Not a public interface:
 * other stages include analysis/analysis.h. */
#ifndef BG_PATHS_INT_H
#define BG_PATHS_INT_H
#include "analysis/analysis.h"

/* Junction-structure node: 0, 1, TF, MTF, GY, MGY. */
int bg_paths_is_js(int kind);

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
