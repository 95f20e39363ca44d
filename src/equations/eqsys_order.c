/* SPDX-License-Identifier: BSD-3-Clause */
/* Computational order of the bond variables (Tarjan's strongly connected
 * components, base/scc.h, on "signal reads signal") and tearing of algebraic
 * blocks: each cyclic block gives up algebraic unknowns (the analysis'
 * algebraic variables first, then the vertex with most edges inside the
 * block) until the rest is acyclic. Implicit equations are always torn. */
#include <stdlib.h>
#include <string.h>

#include "base/scc.h"
#include "equations/eqsys_int.h"
#include "model/model.h"

/* Signals read by a model expression (recursion bounded by the parser's
 * nesting limit). */
static void x_sigs(const bg_model *m, int root, bg_ivec *out) {
  const bg_xnode *n = &m->xnode[root];
  if (n->op == BG_X_EFFORT) bg_ivec_push(out, 2 * n->ref);
  else if (n->op == BG_X_FLOW) bg_ivec_push(out, 2 * n->ref + 1);
  else if (n->op == BG_X_INPUT) x_sigs(m, m->input_expr[n->ref], out);
  else
    for (int k = 0; k < n->nargs && n->op != BG_X_NUM; k++) x_sigs(m, n->arg[k], out);
}

static void eq_sigs(const bg_eqsys *s, int nd, bg_ivec *out) {
  const eq_node *n = &s->node[nd];
  switch (n->kind) {
  case EQ_SIG: bg_ivec_push(out, n->a); break;
  case EQ_X: x_sigs(s->m, n->a, out); break;
  case EQ_LIN:
    for (int k = 0; k < n->b; k++) eq_sigs(s, s->lin_node[n->a + k], out);
    break;
  case EQ_MUL: case EQ_DIV: eq_sigs(s, n->a, out), eq_sigs(s, n->b, out); break;
  default: break;
  }
}

void bg_eqs_deps(bg_eqsys *s) {
  int ns = s->nsig;
  bg_ivec all = {0}, tmp = {0};
  int *mark = bg_xcalloc((size_t)ns + 1, sizeof(int));
  s->dep_adr = bg_arena_alloc(&s->arena, (size_t)(ns + 1) * sizeof(int));
  s->dep_n = bg_arena_alloc(&s->arena, (size_t)(ns + 1) * sizeof(int));
  for (int v = 0; v < ns; v++) {
    tmp.n = 0;
    eq_sigs(s, s->sig_root[v], &tmp);
    s->dep_adr[v] = all.n;
    for (int k = 0; k < tmp.n; k++)
      if (mark[tmp.v[k]] != v + 1) mark[tmp.v[k]] = v + 1, bg_ivec_push(&all, tmp.v[k]);
    s->dep_n[v] = all.n - s->dep_adr[v];
  }
  s->dep = bg_arena_alloc(&s->arena, (size_t)(all.n + 1) * sizeof(int));
  if (all.n) memcpy(s->dep, all.v, (size_t)all.n * sizeof(int));
  free(all.v), free(tmp.v), free(mark);
}

/* ------------------------------------------------------------ components */
typedef struct tarjan {
  int *deg, *comp;
  int *ord, *cadr; /* emission order; component k is ord[cadr[k] .. cadr[k+1]) */
  int ncomp;
} tarjan;

/* Edges v -> deps of v, none out of torn vertices. Components come out with
 * their dependencies first: a computational order. */
static void tarjan_run(const bg_eqsys *s, const int *torn, tarjan *T) {
  for (int v = 0; v < s->nsig; v++) T->deg[v] = torn[v] ? 0 : s->dep_n[v];
  T->ncomp = bg_scc(s->nsig, s->dep_adr, T->deg, s->dep, T->comp, T->ord, T->cadr);
}

static int self_dep(const bg_eqsys *s, int v) {
  for (int k = 0; k < s->dep_n[v]; k++)
    if (s->dep[s->dep_adr[v] + k] == v) return 1;
  return 0;
}

/* Signal v before signal u in a tie: by bond number, the effort first. The
 * signals' indices follow the order of the bond statements, and a tie
 * broken by them tore e4 in one order of a model and e9 in another: the
 * equations differed by the conflict's constraint, a switching condition
 * identically 0 read rounding noise in one order and chattered
 * (docs/property.md, finding 20). */
static int sig_before(const bg_eqsys *s, int v, int u) {
  int bv = s->m->bond_num[v / 2], bu = s->m->bond_num[u / 2];
  return bv != bu ? bv < bu : v % 2 < u % 2;
}

/* The vertex with the most edges inside its component; ties by bond number. */
static int best_tear(const bg_eqsys *s, const tarjan *T, int k, int *cnt) {
  int a0 = T->cadr[k], a1 = T->cadr[k + 1], best = -1, bestc = -1;
  for (int i = a0; i < a1; i++) cnt[T->ord[i]] = 0;
  for (int i = a0; i < a1; i++) {
    int v = T->ord[i];
    for (int j = 0; j < s->dep_n[v]; j++) {
      int u = s->dep[s->dep_adr[v] + j];
      if (T->comp[u] == k) cnt[u]++, cnt[v]++;
    }
  }
  for (int i = a0; i < a1; i++) {
    int v = T->ord[i];
    if (cnt[v] > bestc || (cnt[v] == bestc && sig_before(s, v, best))) best = v, bestc = cnt[v];
  }
  return best;
}

/* Signal named by an analysis algebraic variable ("e4", "R1.f", "T.f2"), or -1. */
static int sig_by_name(const bg_eqsys *s, const char *name) {
  const bg_model *m = s->m;
  const char *dot = strrchr(name, '.');
  if (!dot) {
    if ((name[0] != 'e' && name[0] != 'f') || !name[1]) return -1;
    int b = bg_model_find_bond(m, atoi(name + 1));
    return b < 0 ? -1 : 2 * b + (name[0] == 'f');
  }
  char el[256];
  size_t len = (size_t)(dot - name);
  if (len >= sizeof el) return -1;
  memcpy(el, name, len), el[len] = 0;
  int e = bg_model_find_elem(m, el), v = dot[1] == 'f', b = -1;
  if (e < 0 || (dot[1] != 'e' && dot[1] != 'f')) return -1;
  int kind = m->elem_kind[e];
  if (bg_elem_is_oneport(kind)) b = bg_elem_port_bond(m, e);
  else if (bg_elem_is_twoport(kind)) b = dot[2] == '1' ? bg_elem_in_bond(m, e) : bg_elem_out_bond(m, e);
  return b < 0 ? -1 : 2 * b + v;
}

static int tear_round(bg_eqsys *s, tarjan *T, int *torn, const int *pref, int *cnt) {
  int changed = 0;
  tarjan_run(s, torn, T);
  for (int k = 0; k < T->ncomp; k++) {
    int a0 = T->cadr[k], a1 = T->cadr[k + 1], v0 = T->ord[a0];
    if (a1 - a0 == 1 && (torn[v0] || !self_dep(s, v0))) continue;
    int np = 0;
    for (int i = a0; i < a1; i++)
      if (pref[T->ord[i]] && !torn[T->ord[i]]) torn[T->ord[i]] = 1, np++;
    if (!np) torn[best_tear(s, T, k, cnt)] = 1;
    changed = 1;
  }
  return changed;
}

int bg_eqs_sort(bg_eqsys *s, int *torn_out) {
  int ns = s->nsig, nn = ns + 1;
  tarjan T;
  int **arrs[] = {&T.deg, &T.comp, &T.ord, &T.cadr};
  for (size_t i = 0; i < sizeof arrs / sizeof *arrs; i++) *arrs[i] = bg_xcalloc((size_t)nn + 1, sizeof(int));
  int *torn = bg_xcalloc((size_t)nn, sizeof(int)), *pref = bg_xcalloc((size_t)nn, sizeof(int));
  int *cnt = bg_xcalloc((size_t)nn, sizeof(int));
  for (int v = 0; v < ns; v++) torn[v] = s->sig_form[v] == EQF_IMPLICIT;
  for (int k = 0; k < s->a->nalgebraic; k++) {
    int v = sig_by_name(s, s->a->algebraic_variables[k]);
    if (v >= 0) pref[v] = 1;
  }
  while (tear_round(s, &T, torn, pref, cnt)) {
  }
  /* algebraic unknowns: the analysis' algebraic variables in its order, then
   * by signal; the caller (eqsys.c) makes them unknowns in this order */
  int nt = 0;
  unsigned char *listed = bg_xcalloc((size_t)nn, 1);
  for (int k = 0; k < s->a->nalgebraic; k++) {
    int v = sig_by_name(s, s->a->algebraic_variables[k]);
    if (v >= 0 && torn[v] && !s->sig_torn[v] && !listed[v]) listed[v] = 1, torn_out[nt++] = v;
  }
  for (int v = 0; v < ns; v++)
    if (torn[v] && !s->sig_torn[v] && !listed[v]) listed[v] = 1, torn_out[nt++] = v;
  free(listed);
  s->order = bg_arena_alloc(&s->arena, (size_t)nn * sizeof(int));
  s->norder = 0;
  for (int i = 0; i < ns; i++)
    if (!torn[T.ord[i]]) s->order[s->norder++] = T.ord[i];
  for (size_t i = 0; i < sizeof arrs / sizeof *arrs; i++) free(*arrs[i]);
  free(torn), free(pref), free(cnt);
  return nt;
}
