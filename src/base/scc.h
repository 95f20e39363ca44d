/* SPDX-License-Identifier: BSD-3-Clause */
/* Strongly connected components of a directed graph (Tarjan, iterative: no
 * recursion on the graph's depth). The one copy used by the signal flow graph
 * (algebraic blocks, Johnson's cycle search) and the equation ordering. */
#ifndef BG_SCC_H
#define BG_SCC_H

/* The graph has nn vertices; the edges of v are out[adr[v] .. adr[v] + deg[v]).
 * Roots are taken in vertex order and edges in list order, so the result is
 * deterministic. Components are numbered in the order they complete: every
 * component reachable from component k has a number below k (dependencies
 * first). comp[v] receives v's component. ord and cadr may be NULL; else ord
 * (nn entries) lists the vertices of component k at ord[cadr[k] .. cadr[k+1])
 * in the order Tarjan's stack releases them, and cadr needs ncomp + 1 entries
 * (nn + 1 always suffice). Returns the number of components. */
int bg_scc(int nn, const int *adr, const int *deg, const int *out, int *comp, int *ord,
           int *cadr);

#endif
