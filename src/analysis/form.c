/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_analysis_run: what the causal pattern says. Causal paths and loops
 * (paths.c), their topological loops in the signal flow graph (sfg.c),
 * gains, classes, the states, the form of the model, the predicted index
 * with its reason, and first/second-order estimates. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "analysis/paths_int.h"
#include "analysis/sfg_int.h"
#include "base/strbuf.h"

/* Budget of the algebraic-cycle search, in steps. */
#define CYCLE_BUDGET 20000000L

static int out_sig(const bg_model *m, const bg_analysis *a, int node, int b) {
  return bg_paths_effort_in(m, a, node, b) ? BG_SIG_FLOW(b) : BG_SIG_EFFORT(b);
}

static int is_source(int k) { return k <= BG_ELEM_MSF; }

/* ------------------------------------------------------------ topological loops */
typedef struct tl {
  int kind, order, algebraic;
  int adr, n;
  char *gain;
  double value;
  char *cause;
  int mod_elem; /* the modulated element, or -1 */
  int linear;   /* every relation on it is linear */
} tl;

typedef struct tlist {
  const bg_model *m;
  bg_analysis *a;
  const bg_sfg *g;
  tl *v;
  int n, cap, max, omitted, capped;
  int *sig, nsig, capsig; /* signals of all loops */
  int *hash, hcap;        /* open addressing over canonical sequences: loop index + 1 */
  int *mark;              /* per bond: signals used, for flat/open */
} tlist;

static unsigned canon_hash(const int *s, int n, int r) {
  unsigned h = 2166136261u;
  for (int i = 0; i < n; i++) h = (h ^ (unsigned)s[(r + i) % n]) * 16777619u;
  return h;
}

static int canon_rot(const int *s, int n) {
  int r = 0;
  for (int i = 1; i < n; i++) if (s[i] < s[r]) r = i;
  return r; /* a signal occurs once in an elementary cycle */
}

/* Index of an equal loop (same cyclic signal sequence) already listed, or -1;
 * with insert, remembers loop `idx` under this sequence. */
static int tl_lookup(tlist *T, const int *s, int n, int insert, int idx) {
  int r = canon_rot(s, n);
  unsigned h = canon_hash(s, n, r) & (unsigned)(T->hcap - 1);
  for (;; h = (h + 1) & (unsigned)(T->hcap - 1)) {
    int k = T->hash[h] - 1;
    if (k < 0) { if (insert) T->hash[h] = idx + 1; return -1; }
    const tl *x = &T->v[k];
    if (x->n != n) continue;
    const int *y = T->sig + x->adr;
    int ry = canon_rot(y, n), same = 1;
    for (int i = 0; i < n && same; i++) same = y[(ry + i) % n] == s[(r + i) % n];
    if (same) return k;
  }
}

/* Flat: both signals of every internal bond it passes (Definition 4.5).
 * Port bonds do not count: a loop closed by modulation at a source or an
 * R is flat when it crosses the junction structure both ways. */
static int tl_flat(tlist *T, const int *s, int n) {
  const bg_model *m = T->m;
  int flat = 1;
  for (int i = 0; i < n; i++) if (s[i] < 2 * m->nbond) T->mark[s[i] / 2]++;
  for (int i = 0; i < n; i++) {
    if (s[i] >= 2 * m->nbond) continue;
    int b = s[i] / 2;
    if (T->mark[b] == 1 && bg_paths_is_js(m->elem_kind[m->bond_tail[b]]) &&
        bg_paths_is_js(m->elem_kind[m->bond_head[b]]))
      flat = 0;
  }
  for (int i = 0; i < n; i++) if (s[i] < 2 * m->nbond) T->mark[s[i] / 2] = 0;
  return flat;
}

static int tl_linear(const tlist *T, const int *s, int n) {
  for (int i = 0; i < n; i++) {
    int e = bg_sfg_find_edge(T->g, s[i], s[(i + 1) % n]);
    if (e >= 0 && !T->g->edge[e].linear) return 0;
  }
  return 1;
}

/* Adds the closed chain s (if its edges exist and it is new). */
static int tl_add(tlist *T, const int *s, int n, const char *cause) {
  bg_gain gn;
  if (n <= 0 || tl_lookup(T, s, n, 0, 0) >= 0) return 0;
  bg_sfg_cycle_gain(T->g, s, n, &gn);
  if (!gn.ok) { bg_gain_free(&gn); return 0; }
  if (T->n >= T->max) { T->omitted++; bg_gain_free(&gn); return 0; }
  if (T->n == T->cap) { T->cap = T->cap ? 2 * T->cap : 16; T->v = bg_xrealloc(T->v, sizeof *T->v * (size_t)T->cap); }
  while (T->nsig + n > T->capsig) {
    T->capsig = T->capsig ? 2 * T->capsig : 256;
    T->sig = bg_xrealloc(T->sig, sizeof(int) * (size_t)T->capsig);
  }
  memcpy(T->sig + T->nsig, s, sizeof(int) * (size_t)n);
  tl *x = &T->v[T->n];
  x->adr = T->nsig;
  x->n = n;
  T->nsig += n;
  x->order = gn.order;
  x->algebraic = gn.order == 0;
  x->kind = tl_flat(T, s, n) ? BG_TLOOP_FLAT : BG_TLOOP_OPEN;
  x->gain = bg_gain_text(&gn, &T->a->arena);
  x->value = gn.value;
  x->mod_elem = gn.mod_edge >= 0 ? T->g->edge[gn.mod_edge].elem : -1;
  x->linear = tl_linear(T, s, n);
  char buf[160];
  int field = bg_elem_field(T->m, x->mod_elem);
  if (!cause && field >= 0) /* a field's ports read each other: its own coupling */
    snprintf(buf, sizeof buf, "coupling of the ports of field %s", T->m->field_name[field]);
  else if (!cause && x->mod_elem >= 0)
    snprintf(buf, sizeof buf, "internal modulation of %s", T->m->elem_name[x->mod_elem]);
  else
    snprintf(buf, sizeof buf, "%s", cause ? cause : "coupled causal paths");
  x->cause = bg_arena_strdup(&T->a->arena, buf);
  tl_lookup(T, s, n, 1, T->n);
  T->n++;
  bg_gain_free(&gn);
  return 1;
}

/* The flat loop along causal path p: out along one signal, back along the
 * conjugate one, closed through both end elements. */
static void tl_from_path(tlist *T, int p, int *nodes, int *s) {
  const bg_model *m = T->m;
  const bg_analysis *a = T->a;
  const int *b = a->path_bonds + a->path_adr[p];
  int k = a->path_n[p], n = 0;
  if (is_source(m->elem_kind[a->path_end0[p]]) || is_source(m->elem_kind[a->path_end1[p]])) return;
  bg_paths_nodes(m, a, p, nodes);
  for (int i = 0; i < k; i++) s[n++] = out_sig(m, a, nodes[i], b[i]);
  for (int i = k - 1; i >= 0; i--) s[n++] = out_sig(m, a, nodes[i + 1], b[i]);
  char cause[48];
  snprintf(cause, sizeof cause, "causal path %d", p + 1);
  tl_add(T, s, n, cause);
}

/* The two open loops of causal loop l; returns their gains through g1, g2. */
static void tl_from_cloop(tlist *T, int l, int *nodes, int *s, bg_gain *g1, bg_gain *g2) {
  const bg_model *m = T->m;
  const bg_analysis *a = T->a;
  const int *b = a->cloop_bonds + a->cloop_adr[l];
  int k = a->cloop_n[l];
  bg_cloops_nodes(m, a, l, nodes);
  char cause[48];
  snprintf(cause, sizeof cause, "causal loop %d", l + 1);
  for (int i = 0; i < k; i++) s[i] = out_sig(m, a, nodes[i], b[i]);
  bg_sfg_cycle_gain(T->g, s, k, g1);
  tl_add(T, s, k, cause);
  for (int i = 0; i < k; i++) s[i] = out_sig(m, a, nodes[(k - i) % k], b[k - 1 - i]);
  bg_sfg_cycle_gain(T->g, s, k, g2);
  tl_add(T, s, k, cause);
}

static int on_cycle(void *ctx, const int *node, int n) {
  tlist *T = ctx;
  tl_add(T, node, n, NULL);
  /* Stop at the cap: what is left is not counted, only flagged. */
  return T->capped = T->n >= T->max;
}

static int nearly_one(double g) { return fabs(g - 1.0) <= 16 * DBL_EPSILON * fmax(1.0, fabs(g)); }

static void cloop_fill(tlist *T, int l, const bg_gain *g1, const bg_gain *g2) {
  bg_analysis *a = T->a;
  bg_gain tmp = *g1;
  a->cloop_gain[l] = g1->ok ? bg_gain_text(&tmp, &a->arena) : bg_arena_strdup(&a->arena, "?");
  a->cloop_gain_value[l] = g1->ok ? g1->value : NAN;
  /* class 5 when an open loop has gain +1 (the two are equal without
   * gyrators, Definition 4.16; either one at +1 makes the loop singular) */
  a->cloop_class[l] = (g1->ok && nearly_one(g1->value)) || (g2->ok && nearly_one(g2->value)) ? 5 : 4;
  /* No causal mesh classification (Brown's even / odd / neutral): a closed
   * causal path passes an even number of gyrators (docs/analysis.md). */
}

static void cloops_disjoint(const bg_model *m, bg_analysis *a) {
  char *used = bg_xcalloc((size_t)m->nbond + 1, 1);
  a->cloops_disjoint = 1;
  a->rosenberg_andry = 1;
  for (int l = 0; l < a->ncloop; l++) {
    for (int i = 0; i < a->cloop_n[l]; i++) {
      int b = a->cloop_bonds[a->cloop_adr[l] + i];
      if (used[b]) a->cloops_disjoint = 0;
      used[b] = 1;
    }
    if (a->cloop_class[l] == 5) a->rosenberg_andry = 0;
  }
  if (!a->cloops_disjoint) a->rosenberg_andry = 0;
  free(used);
}

static void tl_store(tlist *T) {
  bg_analysis *a = T->a;
  bg_arena *ar = &a->arena;
  int n = T->n;
  a->ntloop = n;
  a->ntloop_omitted = T->omitted;
  /* Loops along omitted causal paths are not found either. */
  a->tloop_capped = T->capped || T->omitted || a->npath_omitted || a->ncloop_omitted;
  a->tloop_kind = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->tloop_order = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->tloop_adr = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->tloop_n = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->tloop_signals = bg_arena_alloc(ar, sizeof(int) * (size_t)(T->nsig + 1));
  a->tloop_gain = bg_arena_alloc(ar, sizeof(char *) * (size_t)(n + 1));
  a->tloop_gain_value = bg_arena_alloc(ar, sizeof(double) * (size_t)(n + 1));
  a->tloop_algebraic = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->tloop_cause = bg_arena_alloc(ar, sizeof(char *) * (size_t)(n + 1));
  if (T->nsig) memcpy(a->tloop_signals, T->sig, sizeof(int) * (size_t)T->nsig);
  for (int i = 0; i < n; i++) {
    const tl *x = &T->v[i];
    a->tloop_kind[i] = x->kind;
    a->tloop_order[i] = x->order;
    a->tloop_adr[i] = x->adr;
    a->tloop_n[i] = x->n;
    a->tloop_gain[i] = x->gain;
    a->tloop_gain_value[i] = x->value;
    a->tloop_algebraic[i] = x->algebraic;
    a->tloop_cause[i] = x->cause;
  }
}

/* Paths' flat loops, causal loops' open loops (with the causal loops'
 * gains and classes), then any other algebraic cycle (internal modulation). */
static void find_tloops(tlist *T) {
  const bg_model *m = T->m;
  bg_analysis *a = T->a;
  int maxlen = 2 * m->nbond + m->nstate + 2;
  int *nodes = bg_xcalloc((size_t)maxlen, sizeof(int)), *s = bg_xcalloc((size_t)maxlen, sizeof(int));
  for (int p = 0; p < a->npath; p++) tl_from_path(T, p, nodes, s);
  for (int l = 0; l < a->ncloop; l++) {
    bg_gain g1, g2;
    tl_from_cloop(T, l, nodes, s, &g1, &g2);
    cloop_fill(T, l, &g1, &g2);
    bg_gain_free(&g1);
    bg_gain_free(&g2);
  }
  cloops_disjoint(m, a);
  if (T->n < T->max) bg_sfg_algebraic_cycles(T->g, on_cycle, T, CYCLE_BUDGET);
  else T->capped = 1;
  free(nodes);
  free(s);
}

/* ------------------------------------------------------------ summary lists */
typedef struct slist { char **v; int n, cap; } slist;

/* Names are unique where this is called (states) or deduplicated by the
 * caller (signals, by id): no search here, the lists can be long. */
static void sl_add(slist *l, bg_arena *ar, const char *s) {
  if (l->n == l->cap) { l->cap = l->cap ? 2 * l->cap : 16; l->v = bg_xrealloc(l->v, sizeof(char *) * (size_t)l->cap); }
  l->v[l->n++] = bg_arena_strdup(ar, s);
}

static char **sl_keep(slist *l, bg_arena *ar, int *n) {
  char **r = bg_arena_alloc(ar, sizeof(char *) * (size_t)(l->n + 1));
  if (l->n) memcpy(r, l->v, sizeof(char *) * (size_t)l->n);
  *n = l->n;
  free(l->v);
  return r;
}

static void fill_states(const bg_model *m, bg_analysis *a) {
  slist st = {0}, dep = {0};
  char buf[256];
  for (int e = 0; e < m->nelem; e++) {
    int k = m->elem_kind[e];
    if ((k != BG_ELEM_C && k != BG_ELEM_I) || m->elem_nbond[e] != 1) continue;
    int pb = m->elem_bonds[m->elem_bondadr[e]];
    if (a->bond_stroke[pb] == BG_STROKE_NONE && !bg_analysis_bond_split(a, pb)) continue;
    if (bg_paths_store_integral(m, a, e)) {
      snprintf(buf, sizeof buf, "%s.%c", m->elem_name[e], k == BG_ELEM_C ? 'q' : 'p');
      sl_add(&st, &a->arena, buf);
    } else {
      sl_add(&dep, &a->arena, m->elem_name[e]);
    }
  }
  for (int s = 0; s < m->nstate; s++) sl_add(&st, &a->arena, m->state_name[s]);
  a->states = sl_keep(&st, &a->arena, &a->nstates);
  a->dependent_stores = sl_keep(&dep, &a->arena, &a->ndependent);
}

/* seen: per signal, listed already (so each name comes once) */
static void add_sig_name(const bg_model *m, slist *l, bg_arena *ar, char *seen, int sig) {
  char buf[128];
  if (seen[sig]) return;
  seen[sig] = 1;
  bg_sfg_node_name(m, sig, buf, sizeof buf);
  sl_add(l, ar, buf);
}

/* An R whose law (`: e = ...` / `: f = ...`) the causality inverts: its
 * equation is an implicit algebraic one (Section 4.9), whatever the law. */
static int inverted_law(const bg_model *m, const bg_analysis *a, int e) {
  return m->elem_kind[e] == BG_ELEM_R && m->elem_form[e] != BG_FORM_VALUE && a->elem_inverted[e];
}

static int ninverted_laws(const bg_model *m, const bg_analysis *a, int *first) {
  int n = 0;
  for (int e = m->nelem - 1; e >= 0; e--)
    if (inverted_law(m, a, e)) n++, *first = e;
  return n;
}

/* Rank of bond b at junction j as a carrier of an algebraic state variable
 * (Section 4.9): a nonlinear R port first, then a store in integral
 * causality, then any R, then the rest. */
static int carrier_rank(const bg_model *m, const bg_analysis *a, int j, int b) {
  int o = bg_bond_other(m, b, j), k = m->elem_kind[o];
  if (k == BG_ELEM_R) return m->elem_form[o] != BG_FORM_VALUE && !m->elem_linear[o] ? 0 : 2;
  if ((k == BG_ELEM_C || k == BG_ELEM_I) && bg_paths_store_integral(m, a, o)) return 1;
  return 3;
}

/* The algebraic state variables of the conflicts at junctions (Section 4.9,
 * Equations 4.46 to 4.51): type 1, one: the common variable (effort at a
 * 0-junction, flow at a 1-junction) of the best carrier bond; type 2 of
 * degree k, k: of the k+1 bonds that determine the common variable, one is
 * taken as the input (a store's state if there is one, else a bond that is
 * not a nonlinear R port, else the first) and the others' conjugate
 * variables (flow at a 0-junction, effort at a 1-junction) are unknown. */
static void conflict_algebraic(const bg_model *m, bg_analysis *a, slist *l, char *seen) {
  for (int c = 0; c < a->nconflict; c++) {
    int j = a->conflict_node[c], kind = m->elem_kind[j];
    if (kind != BG_ELEM_J0 && kind != BG_ELEM_J1) continue;
    const int *cb = a->conflict_bonds + a->conflict_adr[c];
    int n = a->conflict_n[c], best = 0;
    if (a->conflict_type[c] == 1) {
      for (int i = 1; i < n; i++)
        if (carrier_rank(m, a, j, cb[i]) < carrier_rank(m, a, j, cb[best])) best = i;
      int b = cb[best];
      add_sig_name(m, l, &a->arena, seen, kind == BG_ELEM_J0 ? BG_SIG_EFFORT(b) : BG_SIG_FLOW(b));
      continue;
    }
    int input = -1;
    for (int i = 0; i < n && input < 0; i++)
      if (carrier_rank(m, a, j, cb[i]) == 1) input = i;
    for (int i = 0; i < n && input < 0; i++)
      if (carrier_rank(m, a, j, cb[i]) != 0) input = i;
    if (input < 0) input = 0;
    for (int i = 0; i < n; i++)
      if (i != input)
        add_sig_name(m, l, &a->arena, seen, kind == BG_ELEM_J0 ? BG_SIG_FLOW(cb[i]) : BG_SIG_EFFORT(cb[i]));
  }
}

/* One unknown per algebraic relation: both resistor outputs of a class 2
 * path; for a causal loop, the outputs on the loop of one of its nodes (a
 * TF or GY when there is one, as in Equations 4.26); for a conflict at a
 * junction, its algebraic state variables (conflict_algebraic); for a loop
 * from internal modulation, the modulated element's output on it. */
static void fill_algebraic(const bg_model *m, bg_analysis *a, const bg_sfg *g) {
  slist l = {0};
  int *nodes = bg_xcalloc((size_t)m->nbond + 2, sizeof(int));
  char *seen = bg_xcalloc((size_t)(2 * m->nbond + m->nstate + 1), 1);
  for (int p = 0; p < a->npath; p++) {
    if (a->path_class[p] != 2) continue;
    const int *b = a->path_bonds + a->path_adr[p];
    int s0 = out_sig(m, a, a->path_end0[p], b[0]);
    int s1 = out_sig(m, a, a->path_end1[p], b[a->path_n[p] - 1]);
    int first = a->path_end0[p] < a->path_end1[p]; /* resistors in file order */
    add_sig_name(m, &l, &a->arena, seen, first ? s0 : s1);
    add_sig_name(m, &l, &a->arena, seen, first ? s1 : s0);
  }
  for (int c = 0; c < a->ncloop; c++) {
    const int *b = a->cloop_bonds + a->cloop_adr[c];
    int k = a->cloop_n[c], at = 0;
    bg_cloops_nodes(m, a, c, nodes);
    for (int i = 0; i < k; i++)
      if (m->elem_kind[nodes[i]] >= BG_ELEM_TF && m->elem_kind[nodes[i]] <= BG_ELEM_MGY) { at = i; break; }
    int s1 = out_sig(m, a, nodes[at], b[(at + k - 1) % k]), s2 = out_sig(m, a, nodes[at], b[at]);
    add_sig_name(m, &l, &a->arena, seen, s1 % 2 ? s2 : s1); /* the effort first */
    add_sig_name(m, &l, &a->arena, seen, s1 % 2 ? s1 : s2);
  }
  conflict_algebraic(m, a, &l, seen);
  for (int e = 0; e < m->nelem; e++) /* inverted laws are solved implicitly */
    if (inverted_law(m, a, e))
      add_sig_name(m, &l, &a->arena, seen, out_sig(m, a, e, m->elem_bonds[m->elem_bondadr[e]]));
  for (int t = 0; t < a->ntloop; t++) {
    if (!a->tloop_algebraic[t] || strncmp(a->tloop_cause[t], "internal", 8) != 0) continue;
    const int *s = a->tloop_signals + a->tloop_adr[t];
    int n = a->tloop_n[t];
    for (int i = 0; i < n; i++) {
      int e = bg_sfg_find_edge(g, s[i], s[(i + 1) % n]);
      if (e >= 0 && g->edge[e].kind == BG_SFGE_MOD) { add_sig_name(m, &l, &a->arena, seen, s[(i + 1) % n]); break; }
    }
  }
  free(nodes);
  free(seen);
  a->algebraic_variables = sl_keep(&l, &a->arena, &a->nalgebraic);
}

/* ------------------------------------------------------------ form and index */
static int class1_shares_loop(const bg_model *m, const bg_analysis *a, int *pp, int *ll) {
  int *loop_of = bg_xcalloc((size_t)m->nbond + 1, sizeof(int)), found = 0;
  for (int l = 0; l < a->ncloop; l++)
    for (int i = 0; i < a->cloop_n[l]; i++) loop_of[a->cloop_bonds[a->cloop_adr[l] + i]] = l + 1;
  for (int p = 0; p < a->npath && !found; p++) {
    if (a->path_class[p] != 1) continue;
    for (int i = 0; i < a->path_n[p] && !found; i++) {
      int l = loop_of[a->path_bonds[a->path_adr[p] + i]];
      if (l) { found = 1; *pp = p; *ll = l - 1; }
    }
  }
  free(loop_of);
  return found;
}

static void sb_sep(bg_strbuf *sb) { if (sb->len) bg_sb_puts(sb, "; "); }

/* Reasons for index 1, in words. */
static void reasons_index1(const bg_model *m, bg_analysis *a, bg_strbuf *sb) {
  int c1 = 0, c2 = 0;
  for (int p = 0; p < a->npath; p++) { c1 += a->path_class[p] == 1; c2 += a->path_class[p] == 2; }
  /* a capped listing (--max-list, the search budget) counts only what it kept */
  const char *pmin = a->npath_omitted > 0 ? "at least " : "", *lmin = a->ncloop_omitted > 0 ? "at least " : "";
  if (c1) { sb_sep(sb); bg_sb_printf(sb, "%s%d class 1 causal path%s (dependent stores)", pmin, c1, c1 > 1 ? "s" : ""); }
  if (c2) { sb_sep(sb); bg_sb_printf(sb, "%s%d class 2 causal path%s between resistors", pmin, c2, c2 > 1 ? "s" : ""); }
  if (a->ncloop) {
    int c5 = 0;
    for (int l = 0; l < a->ncloop; l++) c5 += a->cloop_class[l] == 5;
    sb_sep(sb);
    if (!c5)
      bg_sb_printf(sb, "%s%d causal loop%s, pairwise disjoint, gain other than +1 (Rosenberg-Andry)",
                   lmin, a->ncloop, a->ncloop > 1 ? "s" : "");
    else
      bg_sb_printf(sb, "%s%d causal loop%s, pairwise disjoint; %d of gain +1 (class 5), whose two "
                       "open-loop constraints each read the other loop variable, so they determine "
                       "both (Figure 4.18 otherwise)", lmin, a->ncloop, a->ncloop > 1 ? "s" : "", c5);
  }
  if (a->ndependent && !c1) { sb_sep(sb); bg_sb_puts(sb, "dependent stores"); }
  if (a->nlag) {
    sb_sep(sb);
    bg_sb_printf(sb, "Lagrange causality: %d generalised velocit%s (artificial flow sources) as "
                     "algebraic unknowns, their balances the Lagrange equations (Section 4.10)",
                 a->nlag, a->nlag > 1 ? "ies" : "y");
  }
  if (a->nconflict) { sb_sep(sb); bg_sb_puts(sb, "causal conflicts give algebraic constraints"); }
  int inv = 0, ninv = ninverted_laws(m, a, &inv);
  if (ninv) {
    sb_sep(sb);
    bg_sb_printf(sb, "%d inverted resistor law%s solved implicitly (%s%s)", ninv, ninv > 1 ? "s" : "",
                 m->elem_name[inv], ninv > 1 ? ", ..." : "");
  }
  for (int t = 0; t < a->ntloop; t++) {
    if (!a->tloop_algebraic[t] || strncmp(a->tloop_cause[t], "internal", 8) != 0) continue;
    sb_sep(sb);
    bg_sb_printf(sb, "algebraic loop %d from %s, gain %s = %g", t + 1, a->tloop_cause[t],
                 a->tloop_gain[t], a->tloop_gain_value[t] + 0.0); /* + 0.0: -0 printed as 0 */
    if (a->tloop_kind[t] == BG_TLOOP_FLAT && a->form_parameter_dependent)
      bg_sb_printf(sb, ": linear, solvable iff its gain differs from 1 (Equation 4.45), so the "
                       "form depends on parameter values%s",
                   nearly_one(a->tloop_gain_value[t]) ? "; singular at these values" : "");
  }
}

static int any_zero_order_path(const bg_model *m, const bg_analysis *a) {
  for (int p = 0; p < a->npath; p++)
    if (a->path_order[p] == 0 && !is_source(m->elem_kind[a->path_end0[p]]) &&
        !is_source(m->elem_kind[a->path_end1[p]]))
      return 1;
  return 0;
}

/* ------------------------------------------------------------ conflicts' constraints
 * A conflict at a junction adds algebraic equations in its algebraic state
 * variables (conflict_algebraic). They determine those variables only when
 * the constrained signals depend on them without integration: type 1, the
 * balance of the junction's conjugate variables must depend on its common
 * variable; type 2, each determining bond other than the input must have
 * its common variable depend on its own conjugate (the R law of Equation
 * 4.48). Otherwise the equations constrain states or inputs alone and the
 * index is above 1 (delta with R1 in conductance causality, Figure 4.17:
 * the balance at nC is the cut-set law, iL2 = Is - iL1, because R1's flow
 * enters it twice with opposite signs). The dependence is the linearised
 * derivative along the signal flow graph without integrator and
 * differentiator edges, summed over all paths (in topological order); when
 * that part of the graph has a cycle or the work budget runs out, the
 * conflict is taken as solvable. */
typedef struct lindep {
  const bg_sfg *g;
  int *stamp, *queue, *indeg, cur;
  double *d, *abs_d;
  long work;
  int cut1; /* 1 + a node whose out-edges are ignored (a loop cut open), or 0 */
  double sum; /* the last decided derivative */
} lindep;

#define LINDEP_BUDGET 20000000L

/* The same with algebraic loops in the reached part (its nodes are
 * L->queue[0 .. nr)): solve (I - M) d = [v in from] densely, M[v][u] the
 * edge value u -> v; -1 when the part is too large or the system singular. */
#define LINDEP_DENSE_MAX 300
static int lin_depends_dense(lindep *L, int nr, const int *from, int n1, const int *to,
                             const double *w, int n2) {
  const bg_sfg *g = L->g;
  if (nr > LINDEP_DENSE_MAX) return -1;
  L->work += (long)nr * nr * nr / 4; /* the solve counts against the budget */
  if (L->work > LINDEP_BUDGET) return -1;
  double *A = bg_xcalloc((size_t)nr * (size_t)(nr + 1), sizeof(double)); /* row v: [nr | rhs] */
  int *pos = L->indeg; /* reuse: node -> row */
  for (int i = 0; i < nr; i++) pos[L->queue[i]] = i;
  for (int i = 0; i < nr; i++) A[(size_t)i * (nr + 1) + i] = 1;
  for (int i = 0; i < n1; i++) A[(size_t)pos[from[i]] * (nr + 1) + nr] = 1;
  for (int i = 0; i < nr; i++) {
    int u = L->queue[i];
    if (u == L->cut1 - 1) continue;
    for (int k = 0; k < g->n[u]; k++) {
      const bg_sfg_edge *e = &g->edge[g->out[g->adr[u] + k]];
      if (e->order != 0 || L->stamp[e->dst] != L->cur) continue;
      int is_from = 0;
      for (int f = 0; f < n1 && !is_from; f++) is_from = from[f] == e->dst;
      if (!is_from) A[(size_t)pos[e->dst] * (nr + 1) + i] -= e->value;
    }
  }
  int ok = 1;
  for (int c = 0; c < nr && ok; c++) { /* Gauss-Jordan, partial pivoting */
    int piv = c;
    for (int r = c + 1; r < nr; r++)
      if (fabs(A[(size_t)r * (nr + 1) + c]) > fabs(A[(size_t)piv * (nr + 1) + c])) piv = r;
    if (fabs(A[(size_t)piv * (nr + 1) + c]) < 1e-12) { ok = 0; break; }
    if (piv != c)
      for (int k = 0; k <= nr; k++) {
        double t = A[(size_t)c * (nr + 1) + k];
        A[(size_t)c * (nr + 1) + k] = A[(size_t)piv * (nr + 1) + k];
        A[(size_t)piv * (nr + 1) + k] = t;
      }
    for (int r = 0; r < nr; r++) {
      if (r == c) continue;
      double f = A[(size_t)r * (nr + 1) + c] / A[(size_t)c * (nr + 1) + c];
      if (f != 0)
        for (int k = c; k <= nr; k++) A[(size_t)r * (nr + 1) + k] -= f * A[(size_t)c * (nr + 1) + k];
    }
  }
  double sum = 0, scale = 0;
  for (int i = 0; ok && i < n2; i++) {
    if (L->stamp[to[i]] != L->cur) continue;
    int r = pos[to[i]];
    double d = A[(size_t)r * (nr + 1) + nr] / A[(size_t)r * (nr + 1) + r];
    sum += w[i] * d;
    scale += fabs(w[i] * d);
  }
  free(A);
  if (!ok || !isfinite(sum)) return -1;
  L->sum = sum;
  return fabs(sum) > 1e-12 * scale;
}

/* d(sum_i w_i to_i)/d(from) where every from[i] is the same unknown:
 * 1 when it is not zero, 0 when it is (or nothing is reached), -1 when
 * undecided. */
static int lin_depends(lindep *L, const int *from, int n1, const int *to, const double *w, int n2) {
  const bg_sfg *g = L->g;
  int tail = 0, head = 0;
  L->cur++;
  for (int i = 0; i < n1; i++)
    if (L->stamp[from[i]] != L->cur) {
      L->stamp[from[i]] = L->cur;
      L->queue[tail++] = from[i];
    }
  /* the part of the graph reachable from the unknown, with in-degrees */
  while (head < tail) {
    int v = L->queue[head++];
    L->indeg[v] = 0;
    L->d[v] = L->abs_d[v] = 0;
    if (v == L->cut1 - 1) continue;
    for (int k = 0; k < g->n[v]; k++) {
      const bg_sfg_edge *e = &g->edge[g->out[g->adr[v] + k]];
      if (++L->work > LINDEP_BUDGET) return -1;
      if (e->order != 0 || L->stamp[e->dst] == L->cur) continue;
      L->stamp[e->dst] = L->cur;
      L->queue[tail++] = e->dst;
    }
  }
  int nreach = tail;
  for (int i = 0; i < nreach; i++) {
    int v = L->queue[i];
    if (v == L->cut1 - 1) continue;
    for (int k = 0; k < g->n[v]; k++) {
      const bg_sfg_edge *e = &g->edge[g->out[g->adr[v] + k]];
      if (e->order == 0) L->indeg[e->dst]++;
    }
  }
  for (int i = 0; i < n1; i++) L->d[from[i]] = L->abs_d[from[i]] = 1;
  /* Kahn's order over the reached part; queue is reused from its start */
  head = tail = 0;
  int *order = L->queue + nreach; /* second half of the buffer */
  for (int i = 0; i < nreach; i++)
    if (L->indeg[L->queue[i]] == 0) order[tail++] = L->queue[i];
  while (head < tail) {
    int v = order[head++];
    if (v == L->cut1 - 1) continue;
    for (int k = 0; k < g->n[v]; k++) {
      const bg_sfg_edge *e = &g->edge[g->out[g->adr[v] + k]];
      if (e->order != 0) continue;
      L->d[e->dst] += e->value * L->d[v];
      L->abs_d[e->dst] += fabs(e->value) * L->abs_d[v];
      if (--L->indeg[e->dst] == 0) order[tail++] = e->dst;
    }
  }
  if (tail < nreach) return lin_depends_dense(L, nreach, from, n1, to, w, n2);
  double sum = 0, scale = 0;
  for (int i = 0; i < n2; i++) {
    if (L->stamp[to[i]] != L->cur) continue;
    sum += w[i] * L->d[to[i]];
    scale += fabs(w[i]) * L->abs_d[to[i]];
  }
  if (!isfinite(sum) || !isfinite(scale)) return -1;
  L->sum = sum;
  return fabs(sum) > 1e-12 * scale;
}

/* Equation eq (0 .. elem_nbond - 1) of conflict node j as sum_i w[i] to[i]
 * = 0 over bond signals; returns the number of terms. A junction: the
 * common variable of bond eq + 1 equals bond 0's, the last its balance. A
 * two-port a -> T -> b, modulus n at the operating point (g->ratio): TF
 * e_b - n e_a and f_a - n f_b; GY e_a - r f_b and e_b - r f_a. */
static int node_equation(const bg_model *m, const bg_sfg *g, int j, int eq, int *to, double *w) {
  int k = m->elem_kind[j], nb = m->elem_nbond[j];
  const int *bs = m->elem_bonds + m->elem_bondadr[j];
  if (k == BG_ELEM_J0 || k == BG_ELEM_J1) {
    int j0 = k == BG_ELEM_J0, nt;
    if (eq < nb - 1) {
      to[0] = j0 ? BG_SIG_EFFORT(bs[eq + 1]) : BG_SIG_FLOW(bs[eq + 1]), w[0] = 1;
      to[1] = j0 ? BG_SIG_EFFORT(bs[0]) : BG_SIG_FLOW(bs[0]), w[1] = -1;
      return 2;
    }
    for (nt = 0; nt < nb; nt++)
      to[nt] = j0 ? BG_SIG_FLOW(bs[nt]) : BG_SIG_EFFORT(bs[nt]), w[nt] = m->bond_head[bs[nt]] == j ? 1 : -1;
    return nt;
  }
  int a = m->bond_head[bs[0]] == j ? bs[0] : bs[1], b = a == bs[0] ? bs[1] : bs[0];
  double n = g->ratio[j];
  if (k == BG_ELEM_TF || k == BG_ELEM_MTF) {
    to[0] = eq ? BG_SIG_FLOW(a) : BG_SIG_EFFORT(b);
    to[1] = eq ? BG_SIG_FLOW(b) : BG_SIG_EFFORT(a);
  } else {
    to[0] = eq ? BG_SIG_EFFORT(b) : BG_SIG_EFFORT(a);
    to[1] = eq ? BG_SIG_FLOW(a) : BG_SIG_FLOW(b);
  }
  w[0] = 1, w[1] = -n;
  return 2;
}

static int conflict_node_testable(const bg_model *m, int j) {
  int k = m->elem_kind[j];
  return k == BG_ELEM_J0 || k == BG_ELEM_J1 ||
         ((k == BG_ELEM_TF || k == BG_ELEM_MTF || k == BG_ELEM_GY || k == BG_ELEM_MGY) &&
          m->elem_nbond[j] == 2 && m->elem_expr[j] >= 0);
}

/* Whether the equations of the conflict nodes node[0 .. nj), taken together,
 * determine the variables those nodes put out: 1 yes, 0 no, -1 undecided. The
 * signal flow graph has no edges at a conflict node (sfg.c), so its equations
 * are written here (node_equation) and the unknowns are the variables each
 * node puts out on its bonds (the conjugates of the ones it receives): one per
 * bond, as many as the node has equations. The linearised Jacobian of the
 * equations in the unknowns (the received variables through the graph without
 * integrator edges) must have full rank. Alone, a type 2 conflict's system is
 * Equations 4.47 and 4.48 (each determining bond's common variable against
 * the input bond's, which reads the others' conjugates through the balance;
 * seed 1088, docs/property.md finding 14), a two-port's its two relations
 * (both ports receiving efforts: e_b = n e_a must depend on the flows it
 * puts out; seeds 170, 231, finding 13). Together they see a dependence that
 * passes through another conflict node: seed 1710 (finding 6), a 1-junction
 * joined to a 0-junction in conflict by two bonds, whose balance of efforts
 * fixes the 0-junction's effort and, through its flow balance, its own flow.
 * Undecided: a cycle the dense solve cannot pass, the budget, more than 64
 * unknowns. */
#define JUNCTION_UNKNOWNS_MAX 64
static int conflict_nodes_solvable(const bg_model *m, const bg_analysis *a, lindep *L,
                                   const int *node, int nj) {
  int n = 0;
  for (int q = 0; q < nj; q++) n += m->elem_nbond[node[q]];
  if (n > JUNCTION_UNKNOWNS_MAX) return -1;
  if (!n) return 1;
  int *unk = bg_xcalloc((size_t)n, sizeof(int)), to[JUNCTION_UNKNOWNS_MAX];
  double *M = bg_xcalloc((size_t)n * (size_t)n, sizeof(double)), w[JUNCTION_UNKNOWNS_MAX];
  int nu = 0, ok = 1;
  for (int q = 0; q < nj; q++)
    for (int i = 0; i < m->elem_nbond[node[q]]; i++)
      unk[nu++] = out_sig(m, a, node[q], m->elem_bonds[m->elem_bondadr[node[q]] + i]);
  for (int q = 0, row = 0; q < nj && ok > 0; q++)
    for (int eq = 0; eq < m->elem_nbond[node[q]] && ok > 0; eq++, row++) {
      int nt = node_equation(m, L->g, node[q], eq, to, w);
      for (int u = 0; u < n && ok > 0; u++) {
        int d = lin_depends(L, unk + u, 1, to, w, nt);
        if (d < 0) ok = -1;
        M[(size_t)row * n + u] = d == 1 ? L->sum : 0;
      }
    }
  /* Rank by elimination, each entry carrying the scale of what was summed
   * into it (the sum of magnitudes): an entry is zero when it cancels to
   * 1e-9 of that scale, as lin_depends decides its entries. A small slope is
   * not a zero (a conductance f = G e^3 at e = 0, series_conductances under
   * relaxed causality: index 1); a cancellation is (seed 1088, two bonds
   * setting one effort: e2 - e1 = 0 whatever the flows). Rows, then columns,
   * are scaled to a largest entry of 1 first, so that the pivots compare
   * (the unknowns mix efforts and flows, the entries conductances of 1e-10
   * and ones: the hydraulic bridge under relaxed causality). */
  double *S = bg_xcalloc((size_t)n * (size_t)n, sizeof(double));
  for (int i = 0; i < n * n; i++) S[i] = fabs(M[i]);
  for (int pass = 0; pass < 2 && ok > 0; pass++)
    for (int r = 0; r < n; r++) {
      double mx = 0;
      for (int u = 0; u < n; u++) mx = fmax(mx, fabs(pass ? M[(size_t)u * n + r] : M[(size_t)r * n + u]));
      if (mx == 0) { ok = 0; break; }
      for (int u = 0; u < n; u++) {
        size_t x = pass ? (size_t)u * n + r : (size_t)r * n + u;
        M[x] /= mx, S[x] /= mx;
      }
    }
  for (int c = 0; c < n && ok > 0; c++) { /* Gaussian elimination, partial pivoting */
    int piv = -1;
    for (int i = c; i < n; i++)
      if (fabs(M[(size_t)i * n + c]) > 1e-9 * S[(size_t)i * n + c] &&
          (piv < 0 || fabs(M[(size_t)i * n + c]) > fabs(M[(size_t)piv * n + c])))
        piv = i;
    if (piv < 0) { ok = 0; break; }
    for (int k = 0; k < n; k++) {
      size_t x = (size_t)c * n + k, y = (size_t)piv * n + k;
      double t = M[x], ts = S[x];
      M[x] = M[y], S[x] = S[y], M[y] = t, S[y] = ts;
    }
    for (int i = c + 1; i < n; i++) {
      double f = M[(size_t)i * n + c] / M[(size_t)c * n + c];
      if (f == 0) continue;
      for (int k = c; k < n; k++) {
        M[(size_t)i * n + k] -= f * M[(size_t)c * n + k];
        S[(size_t)i * n + k] += fabs(f) * S[(size_t)c * n + k];
      }
    }
  }
  free(S);
  free(unk), free(M);
  return ok;
}

/* The first conflict whose equations do not determine its algebraic
 * variables, or -1. A type 1 conflict at a junction: its balance must depend
 * on its common variable; a type 2 conflict or one at a two-port: its own
 * equations must determine what it puts out (conflict_nodes_solvable; an
 * undecided test counts as solvable). The equations of all conflict nodes
 * together decide when that test is decided: a conflict that fails its own
 * test counts only when they do not determine their variables either
 * (seed 1710, finding 6), and conflicts that each pass their own test count
 * when together they do not (seed 7596: two type 2 conflicts at 0-junctions
 * of a triangle of 0-junctions each read the third one's effort, the same
 * equation twice; its circulating flow is undetermined, the pencil singular:
 * *together is set and the first testable conflict returned). */
static int conflict_unsolvable(const bg_model *m, const bg_analysis *a, const bg_sfg *g, int *together) {
  size_t nn = (size_t)g->nnode + 1;
  lindep L = {g, bg_xcalloc(nn, sizeof(int)), bg_xcalloc(2 * nn, sizeof(int)),
              bg_xcalloc(nn, sizeof(int)), 0, bg_xcalloc(nn, sizeof(double)),
              bg_xcalloc(nn, sizeof(double)), 0, 0, 0};
  int *from = bg_xcalloc((size_t)m->nbondref + 2, sizeof(int));
  int *to = bg_xcalloc((size_t)m->nbondref + 2, sizeof(int)), found = -1;
  int *node = bg_xcalloc((size_t)a->nconflict + 1, sizeof(int)), nj = 0;
  double *w = bg_xcalloc((size_t)m->nbondref + 2, sizeof(double));
  for (int c = 0; c < a->nconflict; c++) {
    int j = a->conflict_node[c], dup = 0;
    for (int i = 0; i < nj; i++) dup |= node[i] == j;
    if (conflict_node_testable(m, j) && !dup) node[nj++] = j;
  }
  for (int c = 0; c < a->nconflict && found < 0; c++) {
    int j = a->conflict_node[c], kind = m->elem_kind[j], r = 1;
    if (!conflict_node_testable(m, j)) continue;
    if ((kind == BG_ELEM_J0 || kind == BG_ELEM_J1) && a->conflict_type[c] == 1) {
      int j0 = kind == BG_ELEM_J0, n = m->elem_nbond[j];
      const int *bs = m->elem_bonds + m->elem_bondadr[j];
      for (int i = 0; i < n; i++) {
        from[i] = j0 ? BG_SIG_EFFORT(bs[i]) : BG_SIG_FLOW(bs[i]);
        to[i] = j0 ? BG_SIG_FLOW(bs[i]) : BG_SIG_EFFORT(bs[i]);
        w[i] = m->bond_head[bs[i]] == j ? 1 : -1; /* the balance: sum of sigma x = 0 */
      }
      r = lin_depends(&L, from, n, to, w, n);
    } else {
      r = conflict_nodes_solvable(m, a, &L, &j, 1);
    }
    if (r == 0) found = c;
    if (L.work > LINDEP_BUDGET) break; /* out of budget: the rest taken as solvable */
  }
  int all = nj > 1 || found >= 0 ? conflict_nodes_solvable(m, a, &L, node, nj) : -1;
  if (found >= 0 && all == 1) found = -1;
  if (found < 0 && all == 0) {
    for (int c = 0; c < a->nconflict && found < 0; c++)
      if (conflict_node_testable(m, a->conflict_node[c])) found = c;
    *together = 1;
  }
  free(L.stamp), free(L.queue), free(L.indeg), free(L.d), free(L.abs_d);
  free(from), free(to), free(w), free(node);
  return found;
}

/* Whether causal loop l of gain +1 constrains states or inputs alone. Its two
 * open loops (Figure 4.18) give two constraints, "e_x = e_x + rest" and
 * "f_x = f_x + rest" at any bond x of the loop (Equations 4.36, 4.37). The
 * loop's algebraic variables are e_x and f_x; a constraint whose rest does
 * not depend on the other one reads states and inputs alone (the delta's
 * cut-set law 4.38): the index is above 1. When both depend on it, the two
 * constraints determine the two variables and the junction structure's
 * singularity (Rosenberg-Andry) costs no index (Proposition 5.7 is
 * sufficient for index 1, not necessary; docs/property.md, finding 3).
 * Undecided (a cycle the dense solve cannot pass, the budget) counts as
 * constraining, the prediction of before. */
static int cloop_constrains_states(const bg_model *m, const bg_analysis *a, const bg_sfg *g, int l) {
  size_t nn = (size_t)g->nnode + 1;
  lindep L = {g, bg_xcalloc(nn, sizeof(int)), bg_xcalloc(2 * nn, sizeof(int)),
              bg_xcalloc(nn, sizeof(int)), 0, bg_xcalloc(nn, sizeof(double)),
              bg_xcalloc(nn, sizeof(double)), 0, 0, 0};
  int x = a->cloop_bonds[a->cloop_adr[l]], e = BG_SIG_EFFORT(x), f = BG_SIG_FLOW(x);
  double w = 1;
  L.cut1 = 1 + e; /* the effort loop cut open at e_x: what reaches it from f_x */
  int r1 = lin_depends(&L, &f, 1, &e, &w, 1);
  L.cut1 = 1 + f;
  int r2 = r1 == 1 ? lin_depends(&L, &e, 1, &f, &w, 1) : 0;
  free(L.stamp), free(L.queue), free(L.indeg), free(L.d), free(L.abs_d);
  (void)m;
  return !(r1 == 1 && r2 == 1);
}

/* A linear flat algebraic loop from internal modulation (Equation 4.45)
 * whose gain is 1 at the current parameter values, or -1. */
static int singular_modulation_loop(const bg_analysis *a) {
  if (!a->form_parameter_dependent) return -1;
  for (int t = 0; t < a->ntloop; t++)
    if (a->tloop_algebraic[t] && a->tloop_kind[t] == BG_TLOOP_FLAT &&
        strncmp(a->tloop_cause[t], "internal", 8) == 0 && nearly_one(a->tloop_gain_value[t]))
      return t;
  return -1;
}

/* Loops that share bonds, or a class 5 loop whose constraints read states
 * and inputs alone: the junction structure costs index (above 1). */
static int cloops_constrain_states(const bg_model *m, const bg_analysis *a, const bg_sfg *g) {
  if (!a->cloops_disjoint) return 1;
  for (int l = 0; l < a->ncloop; l++)
    if (a->cloop_class[l] == 5 && cloop_constrains_states(m, a, g, l)) return 1;
  return 0;
}

static void fill_form(const bg_model *m, bg_analysis *a, const bg_sfg *g, int nblocks) {
  bg_strbuf sb = {0};
  int p = 0, l = 0, together = 0, c = a->complete ? conflict_unsolvable(m, a, g, &together) : -1;
  /* Lagrange causality: each artificial flow source's velocity is an
   * algebraic unknown whose balance is a Lagrange equation (Section 4.10) */
  int inv = 0, dae = a->ndependent || nblocks || a->nconflict || a->ncloop || a->nlag ||
                     any_zero_order_path(m, a) || ninverted_laws(m, a, &inv);
  a->form = !a->complete ? BG_FORM_INCOMPLETE : dae ? BG_FORM_DAE : BG_FORM_ODE;
  if (!a->complete) {
    a->index_predicted = -1;
    bg_sb_puts(&sb, "causality is incomplete");
  } else if (class1_shares_loop(m, a, &p, &l)) {
    a->index_predicted = 2;
    bg_sb_printf(&sb, "class 1 causal path %d shares bonds with causal loop %d: index above 1 "
                      "(Proposition 5.10)", p + 1, l + 1);
  } else if (!a->rosenberg_andry && a->ncloop && cloops_constrain_states(m, a, g)) {
    a->index_predicted = 2;
    for (l = 0; l < a->ncloop && a->cloop_class[l] != 5; l++) {}
    if (l < a->ncloop)
      bg_sb_printf(&sb, "causal loop %d has gain +1 (class 5): the junction structure is "
                        "singular, index above 1", l + 1);
    else
      bg_sb_puts(&sb, "causal loops share bonds (Rosenberg-Andry not satisfied): index above 1");
  } else if (c >= 0) {
    a->index_predicted = 2;
    int n = a->conflict_node[c], k = m->elem_kind[n], j0 = k == BG_ELEM_J0;
    const char *j = m->elem_name[n];
    if (together) {
      bg_sb_puts(&sb, "conflicts at ");
      for (int q = 0, said = 0; q < a->nconflict; q++) {
        int nq = a->conflict_node[q], dup = 0;
        for (int r = 0; r < q; r++) dup |= a->conflict_node[r] == nq;
        if (dup || !conflict_node_testable(m, nq)) continue;
        bg_sb_printf(&sb, "%s%s", said++ ? ", " : "", m->elem_name[nq]);
      }
      bg_sb_puts(&sb, ": the equations of each determine the variables it puts out, but together "
                      "they do not (their linearised equations are singular), so they constrain "
                      "states or inputs: index above 1");
    } else if (k != BG_ELEM_J0 && k != BG_ELEM_J1)
      bg_sb_printf(&sb, "conflict at the two-port %s: its two relations do not determine the "
                        "variables it puts out on its bonds, so they constrain states or inputs: "
                        "index above 1", j);
    else if (a->conflict_type[c] == 1)
      bg_sb_printf(&sb, "type 1 conflict at %s: the balance of its %s does not depend on its "
                        "%s, so it constrains states or inputs: index above 1", j,
                   j0 ? "flows" : "efforts", j0 ? "effort" : "flow");
    else
      bg_sb_printf(&sb, "type 2 conflict at %s: the %s its %d bonds set and the balance of its "
                        "%s do not determine those bonds' %s (Equations 4.47, 4.48), so they "
                        "constrain states or inputs: index above 1", j, j0 ? "efforts" : "flows",
                   a->conflict_n[c], j0 ? "flows" : "efforts", j0 ? "flows" : "efforts");
  } else if ((l = singular_modulation_loop(a)) >= 0) {
    /* The analogue of a class 5 causal loop (Figure 4.18) for Equation 4.45. */
    a->index_predicted = 2;
    bg_sb_printf(&sb, "algebraic loop %d from %s has gain %s = 1 at these parameter values: "
                      "singular, (1 - gain) x = ... cannot be solved (Equation 4.45), index above 1; "
                      "with another gain the index is 1", l + 1, a->tloop_cause[l], a->tloop_gain[l]);
  } else if (a->form == BG_FORM_ODE) {
    a->index_predicted = 0;
    bg_sb_puts(&sb, "explicit ODE: no zero-order causal path, no causal loop, no algebraic loop");
  } else {
    a->index_predicted = 1;
    reasons_index1(m, a, &sb);
    if (!sb.len) bg_sb_puts(&sb, "algebraic blocks in the signal flow graph");
  }
  a->index_reason = bg_arena_strdup(&a->arena, bg_sb_str(&sb));
  bg_sb_free(&sb);
}

/* Equation 4.45: a flat algebraic loop from internal modulation whose
 * relations are all linear is solvable iff its gain differs from 1, a
 * condition on parameter values. */
static int param_dependent(const tlist *T) {
  for (int i = 0; i < T->n; i++)
    if (T->v[i].algebraic && T->v[i].mod_elem >= 0 && T->v[i].kind == BG_TLOOP_FLAT && T->v[i].linear)
      return 1;
  return 0;
}

/* ------------------------------------------------------------ estimates */
static void fill_estimates(const bg_model *m, bg_analysis *a, const bg_sfg *g) {
  int n = 0, cap = a->npath + 1;
  a->estimate_kind = bg_arena_alloc(&a->arena, sizeof(int) * (size_t)cap);
  a->estimate_path = bg_arena_alloc(&a->arena, sizeof(int) * (size_t)cap);
  a->estimate_value = bg_arena_alloc(&a->arena, sizeof(double) * (size_t)cap);
  int *nodes = bg_xcalloc((size_t)m->nbond + 2, sizeof(int)), *s = bg_xcalloc((size_t)2 * m->nbond + 2, sizeof(int));
  for (int p = 0; p < a->npath; p++) {
    const char *k = a->path_kind[p];
    int first = a->path_order[p] == 1 && (!strcmp(k, "C-R") || !strcmp(k, "I-R"));
    int second = a->path_order[p] == 2 && !strcmp(k, "C-I");
    if (!first && !second) continue;
    const int *b = a->path_bonds + a->path_adr[p];
    int kk = a->path_n[p], ns = 0;
    bg_paths_nodes(m, a, p, nodes);
    for (int i = 0; i < kk; i++) s[ns++] = out_sig(m, a, nodes[i], b[i]);
    for (int i = kk - 1; i >= 0; i--) s[ns++] = out_sig(m, a, nodes[i + 1], b[i]);
    bg_gain gn;
    bg_sfg_cycle_gain(g, s, ns, &gn);
    if (gn.ok && gn.value != 0 && isfinite(gn.value)) {
      a->estimate_kind[n] = second;
      a->estimate_path[n] = p;
      a->estimate_value[n++] = second ? sqrt(fabs(gn.value)) : fabs(1.0 / gn.value);
    }
    bg_gain_free(&gn);
  }
  a->nestimate = n;
  free(nodes);
  free(s);
}

/* ------------------------------------------------------------ entry point */
void bg_analysis_run(const bg_model *m, bg_analysis *a, const bg_analysis_limits *lim) {
  int maxp = lim && lim->max_paths > 0 ? lim->max_paths : BG_DEFAULT_MAX_PATHS;
  int maxl = lim && lim->max_loops > 0 ? lim->max_loops : BG_DEFAULT_MAX_LOOPS;
  bg_paths_find(m, a, maxp);
  bg_cloops_find(m, a, maxl);
  bg_sfg g;
  bg_sfg_build(m, a, &g);
  tlist T = {m, a, &g, NULL, 0, 0, maxl, 0, 0, NULL, 0, 0, NULL, 0, NULL};
  T.hcap = 64;
  while (T.hcap < 4 * maxl) T.hcap *= 2;
  T.hash = bg_xcalloc((size_t)T.hcap, sizeof(int));
  T.mark = bg_xcalloc((size_t)m->nbond + 1, sizeof(int));
  find_tloops(&T);
  a->form_parameter_dependent = param_dependent(&T);
  tl_store(&T);
  fill_states(m, a);
  fill_algebraic(m, a, &g);
  int nblocks = bg_sfg_algebraic_blocks(&g, NULL);
  fill_form(m, a, &g, nblocks);
  fill_estimates(m, a, &g);
  free(T.v);
  free(T.sig);
  free(T.hash);
  free(T.mark);
  bg_sfg_free(&g);
}
