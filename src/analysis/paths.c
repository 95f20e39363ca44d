/* SPDX-License-Identifier: BSD-3-Clause */
/* Causal paths and causal loops: depth-first searches over the junction
 * structure with explicit stacks. A search moves from bond to bond through a
 * node only where the two bonds have opposite causal orientation with
 * respect to it (the same one at a gyrator): that is exactly where one
 * signal continues through the node, so each search step follows a signal.
 * Per node, bonds are pre-sorted by orientation, so a step only looks at
 * bonds it may take (a 0-junction entered on a weak bond offers only its
 * strong bond): the work is proportional to what is found, plus a budget. */
#include <stdlib.h>
#include <string.h>

#include "analysis/paths_int.h"
#include "base/sort.h"

/* Work budget of one search, in steps; past it the omitted counts are lower
 * bounds. Generous: real models need far fewer steps than this. */
#define WORK_BUDGET 20000000L

static int is_oneport(int k) { return k <= BG_ELEM_R; }
static int is_gy(int k) { return k == BG_ELEM_GY || k == BG_ELEM_MGY; }
int bg_paths_is_js(int k) { return k >= BG_ELEM_TF && k <= BG_ELEM_J1; }

int bg_paths_effort_in(const bg_model *m, const bg_analysis *a, int elem, int b) {
  int s = a->bond_stroke[b];
  if (s == BG_STROKE_HEAD) return m->bond_head[b] == elem;
  if (s == BG_STROKE_TAIL) return m->bond_tail[b] == elem;
  return 0;
}

int bg_paths_store_integral(const bg_model *m, const bg_analysis *a, int elem) {
  int b = m->elem_bonds[m->elem_bondadr[elem]];
  if (a->bond_stroke[b] == BG_STROKE_NONE && !bg_analysis_bond_split(a, b)) return 0;
  int in = bg_paths_effort_in(m, a, elem, b); /* 0 on a split bond: it gets the flow */
  return m->elem_kind[elem] == BG_ELEM_C ? !in : in;
}

static int other_end(const bg_model *m, int b, int e) {
  return m->bond_tail[b] == e ? m->bond_head[b] : m->bond_tail[b];
}

/* ------------------------------------------------------------ adjacency
 * For each junction-structure node, its stroked bonds in file order, split
 * by orientation: list 1 = bonds whose effort the node receives. */
typedef struct adj { int *adr, *cnt, *item; } adj;

static void adj_build(const bg_model *m, const bg_analysis *a, adj *g) {
  g->adr = bg_xcalloc((size_t)2 * m->nelem + 1, sizeof(int));
  g->cnt = bg_xcalloc((size_t)2 * m->nelem + 1, sizeof(int));
  g->item = bg_xcalloc((size_t)m->nbondref + 1, sizeof(int));
  int pos = 0;
  for (int e = 0; e < m->nelem; e++) {
    for (int o = 0; o < 2; o++) {
      g->adr[2 * e + o] = pos;
      if (!bg_paths_is_js(m->elem_kind[e])) continue;
      for (int i = 0; i < m->elem_nbond[e]; i++) {
        int b = m->elem_bonds[m->elem_bondadr[e] + i];
        if (a->bond_stroke[b] == BG_STROKE_NONE) continue;
        if (bg_paths_effort_in(m, a, e, b) == o) g->item[pos++] = b;
      }
      g->cnt[2 * e + o] = pos - g->adr[2 * e + o];
    }
  }
}

static void adj_free(adj *g) { free(g->adr); free(g->cnt); free(g->item); }

/* The list of bonds a signal arriving on bond b may leave node v by. */
static int adj_next_list(const bg_model *m, const bg_analysis *a, int v, int b) {
  int o = bg_paths_effort_in(m, a, v, b);
  return 2 * v + (is_gy(m->elem_kind[v]) ? o : !o);
}

/* One depth-first search frame: at node v, arrived by bond bin, next
 * candidate at position pos of list lst. */
typedef struct frame { int v, bin, lst, pos; } frame;

typedef struct search {
  const bg_model *m;
  const bg_analysis *a;
  adj g;
  frame *st;
  int depth;
  char *on; /* node on the current path */
  long work;
} search;

static void search_init(search *s, const bg_model *m, const bg_analysis *a) {
  memset(s, 0, sizeof *s);
  s->m = m;
  s->a = a;
  adj_build(m, a, &s->g);
  s->st = bg_xcalloc((size_t)m->nelem + 2, sizeof *s->st);
  s->on = bg_xcalloc((size_t)m->nelem + 1, 1);
}

static void search_free(search *s) { adj_free(&s->g); free(s->st); free(s->on); }

static void push(search *s, int v, int bin) {
  s->on[v] = 1;
  s->st[s->depth++] = (frame){v, bin, adj_next_list(s->m, s->a, v, bin), 0};
}

/* The next bond out of the top frame, or -1 (the frame is then popped). */
static int next_bond(search *s) {
  frame *f = &s->st[s->depth - 1];
  while (f->pos < s->g.cnt[f->lst]) {
    int b = s->g.item[s->g.adr[f->lst] + f->pos++];
    s->work++;
    if (b != f->bin) return b;
  }
  s->on[f->v] = 0;
  s->depth--;
  return -1;
}

/* ------------------------------------------------------------ records */
typedef struct recs {
  bg_ivec meta;  /* per record: end0, end1, adr, n */
  bg_ivec bonds;
  int nrec, omitted, cap;
} recs;

static void rec_add(recs *r, const search *s, int end0, int end1, int last) {
  if (r->nrec >= r->cap) { r->omitted++; return; }
  bg_ivec_push(&r->meta, end0);
  bg_ivec_push(&r->meta, end1);
  bg_ivec_push(&r->meta, r->bonds.n);
  bg_ivec_push(&r->meta, s->depth + 1);
  for (int i = 0; i < s->depth; i++) bg_ivec_push(&r->bonds, s->st[i].bin);
  bg_ivec_push(&r->bonds, last);
  r->nrec++;
}

static int imin(int a, int b) { return a < b ? a : b; }
static int imax(int a, int b) { return a > b ? a : b; }

/* By the pair of ends (lower element id first, whichever end the bonds
 * start from), then by bond numbers in listed order. */
typedef struct rec_sort {
  const recs *r;
  const bg_model *m;
} rec_sort;

static int rec_cmp(const void *pa, const void *pb, void *ctx) {
  const recs *r = ((const rec_sort *)ctx)->r;
  const bg_model *m = ((const rec_sort *)ctx)->m;
  const int *x = &r->meta.v[4 * *(const int *)pa];
  const int *y = &r->meta.v[4 * *(const int *)pb];
  int x0 = imin(x[0], x[1]), y0 = imin(y[0], y[1]), x1 = imax(x[0], x[1]), y1 = imax(y[0], y[1]);
  if (x0 != y0) return x0 < y0 ? -1 : 1;
  if (x1 != y1) return x1 < y1 ? -1 : 1;
  for (int i = 0; i < x[3] && i < y[3]; i++) {
    int bx = m->bond_num[r->bonds.v[x[2] + i]];
    int by = m->bond_num[r->bonds.v[y[2] + i]];
    if (bx != by) return bx < by ? -1 : 1;
  }
  return (x[3] > y[3]) - (x[3] < y[3]);
}

/* Sorted order of the records (caller frees). */
static int *rec_order(const bg_model *m, const recs *r) {
  int *ord = bg_xcalloc((size_t)r->nrec + 1, sizeof(int));
  for (int i = 0; i < r->nrec; i++) ord[i] = i;
  rec_sort ctx = {r, m};
  bg_sort(ord, (size_t)r->nrec, sizeof(int), rec_cmp, &ctx);
  return ord;
}

static void rec_free(recs *r) { free(r->meta.v); free(r->bonds.v); }

/* ------------------------------------------------------------ causal paths */
/* All causal paths from 1-port x to 1-port elements of higher id. */
static void paths_from(search *s, recs *r, int x) {
  const bg_model *m = s->m;
  int b0 = m->elem_bonds[m->elem_bondadr[x]];
  if (m->elem_nbond[x] != 1 || s->a->bond_stroke[b0] == BG_STROKE_NONE) return;
  int v0 = other_end(m, b0, x);
  if (is_oneport(m->elem_kind[v0])) { /* a bare bond between two 1-ports */
    if (v0 > x) rec_add(r, s, x, v0, b0);
    return;
  }
  push(s, v0, b0);
  while (s->depth > 0 && s->work < WORK_BUDGET) {
    int c = next_bond(s);
    if (c < 0) continue;
    int w = other_end(m, c, s->st[s->depth - 1].v);
    if (is_oneport(m->elem_kind[w])) {
      if (w > x) rec_add(r, s, x, w, c);
    } else if (!s->on[w]) {
      push(s, w, c);
    }
  }
  while (s->depth > 0) s->on[s->st[--s->depth].v] = 0;
}

static const char *end_letter(int kind) {
  switch (kind) {
  case BG_ELEM_C: return "C";
  case BG_ELEM_I: return "I";
  case BG_ELEM_R: return "R";
  default: return "S";
  }
}

static void path_classify(const bg_model *m, bg_analysis *a, int p) {
  int e[2] = {a->path_end0[p], a->path_end1[p]};
  const char *l0 = end_letter(m->elem_kind[e[0]]), *l1 = end_letter(m->elem_kind[e[1]]);
  if (*l0 == 'S' || *l1 == 'S') a->path_kind[p] = "S-*";
  else {
    if (strcmp(l0, l1) > 0) { const char *t = l0; l0 = l1; l1 = t; }
    char buf[4] = {l0[0], '-', l1[0], 0};
    a->path_kind[p] = bg_arena_strdup(&a->arena, buf);
  }
  int order = 0, nint = 0, nstore = 0;
  for (int i = 0; i < 2; i++) {
    int k = m->elem_kind[e[i]];
    if (k != BG_ELEM_C && k != BG_ELEM_I) continue;
    nstore++;
    int in = bg_paths_store_integral(m, a, e[i]);
    nint += in;
    order += in ? 1 : -1;
  }
  a->path_order[p] = *l0 == 'S' || *l1 == 'S' ? BG_PATH_ORDER_NONE : order;
  /* class 1: an independent and a dependent storage port. Without
   * gyrators they are of one type (C-C, I-I); through an odd number of
   * gyrators, which swap effort and flow, a C and an I (mesh1 in test_paths) */
  if (nstore == 2 && nint == 1) a->path_class[p] = 1;
  else if (m->elem_kind[e[0]] == BG_ELEM_R && m->elem_kind[e[1]] == BG_ELEM_R)
    a->path_class[p] = 2;
  else a->path_class[p] = 0;
}

/* Each path starts from the end whose port bond has the lower bond number
 * (hydraulic_bridge: {4,5,6} from R4 to R3, as the reference writes it). */
static void paths_orient(const bg_model *m, recs *r) {
  for (int i = 0; i < r->nrec; i++) {
    int *x = &r->meta.v[4 * i], *b = r->bonds.v + x[2], k = x[3];
    if (m->bond_num[b[k - 1]] >= m->bond_num[b[0]]) continue;
    for (int lo = 0, hi = k - 1; lo < hi; lo++, hi--) { int t = b[lo]; b[lo] = b[hi]; b[hi] = t; }
    int t = x[0];
    x[0] = x[1];
    x[1] = t;
  }
}

static void paths_store(const bg_model *m, bg_analysis *a, recs *r) {
  int n = r->nrec, nb = r->bonds.n;
  paths_orient(m, r);
  bg_arena *ar = &a->arena;
  a->npath = n;
  a->npath_omitted = r->omitted;
  a->path_adr = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->path_n = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->path_bonds = bg_arena_alloc(ar, sizeof(int) * (size_t)(nb + 1));
  a->path_end0 = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->path_end1 = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->path_kind = bg_arena_alloc(ar, sizeof(char *) * (size_t)(n + 1));
  a->path_class = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->path_order = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  int *ord = rec_order(m, r), pos = 0;
  for (int i = 0; i < n; i++) {
    const int *x = &r->meta.v[4 * ord[i]];
    a->path_end0[i] = x[0];
    a->path_end1[i] = x[1];
    a->path_adr[i] = pos;
    a->path_n[i] = x[3];
    memcpy(a->path_bonds + pos, r->bonds.v + x[2], sizeof(int) * (size_t)x[3]);
    pos += x[3];
    path_classify(m, a, i);
  }
  free(ord);
}

void bg_paths_find(const bg_model *m, bg_analysis *a, int max_paths) {
  search s;
  recs r = {0};
  r.cap = max_paths > 0 ? max_paths : BG_DEFAULT_MAX_PATHS;
  search_init(&s, m, a);
  for (int x = 0; x < m->nelem && s.work < WORK_BUDGET; x++)
    if (is_oneport(m->elem_kind[x])) paths_from(&s, &r, x);
  paths_store(m, a, &r);
  search_free(&s);
  rec_free(&r);
}

/* ------------------------------------------------------------ causal loops */
static int is_internal(const bg_model *m, const bg_analysis *a, int b) {
  return a->bond_stroke[b] != BG_STROKE_NONE && bg_paths_is_js(m->elem_kind[m->bond_tail[b]]) &&
         bg_paths_is_js(m->elem_kind[m->bond_head[b]]);
}

/* May a signal arriving at v on bond bin leave by bond bout? */
static int passes(const bg_model *m, const bg_analysis *a, int v, int bin, int bout) {
  int same = bg_paths_effort_in(m, a, v, bin) == bg_paths_effort_in(m, a, v, bout);
  return is_gy(m->elem_kind[v]) ? same : !same;
}

/* All causal loops whose lowest-ranked bond is s0, each found once: the
 * search leaves s0's tail node along s0 and must come back to it. */
static void loops_from(search *s, recs *r, const int *rank, int s0) {
  const bg_model *m = s->m;
  int t = m->bond_tail[s0];
  s->on[t] = 1;
  push(s, m->bond_head[s0], s0);
  while (s->depth > 0 && s->work < WORK_BUDGET) {
    int c = next_bond(s);
    if (c < 0 || !is_internal(m, s->a, c) || rank[c] <= rank[s0]) continue;
    int w = other_end(m, c, s->st[s->depth - 1].v);
    if (w == t) {
      if (passes(m, s->a, t, c, s0)) rec_add(r, s, t, t, c);
    } else if (!s->on[w]) {
      push(s, w, c);
    }
  }
  while (s->depth > 0) s->on[s->st[--s->depth].v] = 0;
  s->on[t] = 0;
}

static int by_bond_number(const void *a, const void *b, void *ctx) {
  const bg_model *m = ctx;
  int na = m->bond_num[*(const int *)a], nb = m->bond_num[*(const int *)b];
  return (na > nb) - (na < nb);
}

/* Bond ids ordered by bond number, and each bond's rank in that order.
 * Sorted, not bucketed: bond numbers may be as large as 10^9, and no array
 * is sized by one. */
static int *bond_ranks(const bg_model *m, int **order_out) {
  int *ord = bg_xcalloc((size_t)m->nbond + 1, sizeof(int));
  int *rank = bg_xcalloc((size_t)m->nbond + 1, sizeof(int));
  for (int b = 0; b < m->nbond; b++) ord[b] = b;
  bg_sort(ord, (size_t)m->nbond, sizeof *ord, by_bond_number, (void *)m);
  for (int k = 0; k < m->nbond; k++) rank[ord[k]] = k;
  *order_out = ord;
  return rank;
}

/* Canonical direction: after the lowest-numbered bond comes the
 * lower-numbered of its two neighbours on the loop. */
static void loop_orient(const bg_model *m, int *b, int n) {
  if (n < 3 || m->bond_num[b[1]] < m->bond_num[b[n - 1]]) return;
  for (int i = 1, j = n - 1; i < j; i++, j--) { int t = b[i]; b[i] = b[j]; b[j] = t; }
}

static void cloops_store(const bg_model *m, bg_analysis *a, const recs *r) {
  int n = r->nrec;
  bg_arena *ar = &a->arena;
  a->ncloop = n;
  a->ncloop_omitted = r->omitted;
  a->cloop_adr = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->cloop_n = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
  a->cloop_bonds = bg_arena_alloc(ar, sizeof(int) * (size_t)(r->bonds.n + 1));
  for (int i = 0; i < n; i++) {
    const int *x = &r->meta.v[4 * i];
    a->cloop_adr[i] = x[2];
    a->cloop_n[i] = x[3];
    memcpy(a->cloop_bonds + x[2], r->bonds.v + x[2], sizeof(int) * (size_t)x[3]);
    loop_orient(m, a->cloop_bonds + x[2], x[3]);
  }
  a->cloop_gain = bg_arena_alloc(ar, sizeof(char *) * (size_t)(n + 1));
  a->cloop_gain_value = bg_arena_alloc(ar, sizeof(double) * (size_t)(n + 1));
  a->cloop_class = bg_arena_alloc(ar, sizeof(int) * (size_t)(n + 1));
}

void bg_cloops_find(const bg_model *m, bg_analysis *a, int max_loops) {
  search s;
  recs r = {0};
  r.cap = max_loops > 0 ? max_loops : BG_DEFAULT_MAX_LOOPS;
  search_init(&s, m, a);
  int *ord, *rank = bond_ranks(m, &ord);
  /* loops come out ordered by their lowest bond number, as listed */
  for (int k = 0; k < m->nbond && s.work < WORK_BUDGET; k++)
    if (is_internal(m, a, ord[k])) loops_from(&s, &r, rank, ord[k]);
  cloops_store(m, a, &r);
  free(ord);
  free(rank);
  search_free(&s);
  rec_free(&r);
}

/* ------------------------------------------------------------ node sequences */
static int common_node(const bg_model *m, int b, int c) {
  if (m->bond_tail[b] == m->bond_tail[c] || m->bond_tail[b] == m->bond_head[c])
    return m->bond_tail[b];
  return m->bond_head[b];
}

void bg_paths_nodes(const bg_model *m, const bg_analysis *a, int p, int *nodes) {
  const int *b = a->path_bonds + a->path_adr[p];
  int k = a->path_n[p];
  nodes[0] = a->path_end0[p];
  nodes[k] = a->path_end1[p];
  for (int i = 1; i < k; i++) nodes[i] = common_node(m, b[i - 1], b[i]);
}

void bg_cloops_nodes(const bg_model *m, const bg_analysis *a, int l, int *nodes) {
  const int *b = a->cloop_bonds + a->cloop_adr[l];
  int k = a->cloop_n[l];
  if (k == 2) { /* two parallel bonds share both nodes: go along bond 0 */
    nodes[0] = m->bond_tail[b[0]];
    nodes[1] = m->bond_head[b[0]];
    return;
  }
  for (int i = 0; i < k; i++) nodes[i] = common_node(m, b[(i + k - 1) % k], b[i]);
}
