/* SPDX-License-Identifier: BSD-3-Clause */
/* Van Dijk's modification of SCAP (Sections 4.7, 4.11). SCAP runs; when a
 * choice of step 4 closed a causal loop of gain +1, or SCAP ended with a
 * conflict, the junction structure imposes a constraint among stores (a
 * nodicity or cut-set law). The stores on the loop's nodes (or at the
 * conflicting node) are the candidates: the first one by name (those without a given initial value first) whose
 * derivative causality lowers the number of such problems gets it, and SCAP
 * runs again, until none is left or no candidate helps.
 *
 * The unity-gain check is a breadth-first search in the signal graph of the
 * internal bonds (efforts and flows, edges from each input to each output of
 * a junction, TF or GY relation), from the effort of the chosen bond back to
 * itself; the gain is the product of the influence coefficients (Definition
 * 4.14): +-1 at junctions from the power orientation, n or 1/n at TF, r or
 * 1/r at GY. Modulated two-ports make the gain unknown (never +1). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "causality/causality_int.h"
#include "model/model.h"
#include "base/strbuf.h"

typedef struct vd {
  bg_ceng *E;
  int nsig;
  int *parent, *queue;
  double *coef;
  unsigned char *cand; /* per element: candidate store */
  int reach;           /* searching dependence (every bond, through R) rather than a loop */
  int ncand, nloops;   /* candidates; unity loops found while recording */
  bg_strbuf why;       /* what the first problem was, for the trace */
} vd;

static int is_js(int kind) { return bg_elem_is_junction(kind) || bg_elem_is_twoport(kind); }

static int internal(const bg_model *m, int b) {
  return is_js(m->elem_kind[m->bond_tail[b]]) && is_js(m->elem_kind[m->bond_head[b]]);
}

/* The node where signal s is an input: the effort at the stroke end, the
 * flow at the other end. */
static int sig_node(const bg_ceng *E, int s) {
  int b = s / 2, head_has = E->stroke[b] == BG_STROKE_HEAD;
  int stroke_end = head_has ? E->m->bond_head[b] : E->m->bond_tail[b];
  int other = head_has ? E->m->bond_tail[b] : E->m->bond_head[b];
  return (s & 1) ? other : stroke_end;
}

/* Modulus of a TF or ratio of a GY; NAN when it is not a constant. */
static double modulus(const bg_model *m, int e) {
  int k = m->elem_kind[e];
  if (k == BG_ELEM_MTF || k == BG_ELEM_MGY || m->elem_modulated[e] || m->elem_expr[e] < 0)
    return NAN;
  bg_xenv env;
  memset(&env, 0, sizeof env);
  env.t = m->sim.t0;
  return bg_xeval(m, m->elem_expr[e], &env);
}

static int sign_at(const bg_model *m, int x, int b, int w) {
  return (m->bond_head[b] == x) != (m->bond_head[w] == x) ? 1 : -1;
}

/* Visits successor t of u with coefficient c; returns 1 when t closes the cycle. */
static int visit(vd *V, int u, int t, double c, int s0, int *qt) {
  if ((!V->reach && !internal(V->E->m, t / 2)) || V->E->stroke[t / 2] == BG_STROKE_NONE) return 0;
  if (t == s0) {
    V->parent[s0] = u;
    V->coef[s0] = c;
    return 1;
  }
  if (V->parent[t] != -2) return 0;
  V->parent[t] = u;
  V->coef[t] = c;
  V->queue[(*qt)++] = t;
  return 0;
}

static int expand_junction(vd *V, int u, int x, int s0, int *qt) {
  const bg_ceng *E = V->E;
  const bg_model *m = E->m;
  int b = u / 2, flow = u & 1, j0 = m->elem_kind[x] == BG_ELEM_J0;
  /* an input effort at a 0-junction (or input flow at a 1-junction) comes
   * from the strong bond and goes out unchanged on every weak bond; the
   * other signal goes from a weak bond to the strong one with a sign */
  int fan_out = j0 != flow;
  const int *bonds = bg_ceng_bonds(E, x);
  for (int i = 0; i < m->elem_nbond[x]; i++) {
    int w = bonds[i];
    if (w == b || bg_ceng_at(E, w, x) < 0) continue;
    int w_strong = bg_ceng_at(E, w, x) == j0;
    if (fan_out && !w_strong && visit(V, u, 2 * w + flow, 1.0, s0, qt)) return 1;
    if (!fan_out && w_strong && visit(V, u, 2 * w + flow, sign_at(m, x, b, w), s0, qt)) return 1;
  }
  return 0;
}

static int expand_twoport(vd *V, int u, int x, int s0, int *qt) {
  const bg_model *m = V->E->m;
  if (m->elem_nbond[x] != 2) return 0;
  const int *bonds = m->elem_bonds + m->elem_bondadr[x];
  int b = u / 2, flow = u & 1, c = bonds[0] == b ? bonds[1] : bonds[0];
  double n = modulus(m, x);
  int is_in = m->bond_head[b] == x;
  if (m->elem_kind[x] == BG_ELEM_GY || m->elem_kind[x] == BG_ELEM_MGY)
    return visit(V, u, 2 * c + !flow, flow ? n : 1.0 / n, s0, qt);
  /* TF, a -> TF -> c: e_c = n e_a, f_a = n f_c */
  return visit(V, u, 2 * c + flow, is_in != flow ? n : 1.0 / n, s0, qt);
}

/* In a dependence search: an R's output depends on its input without
 * integration, and an R field's on every port's input. Stores (integrators
 * or differentiators), sources and detectors end the search, as the
 * analysis stage's dependence test has it. */
static int expand_oneport(vd *V, int u, int x, int s0, int *qt) {
  const bg_model *m = V->E->m;
  if (m->elem_kind[x] != BG_ELEM_R) return 0;
  int f = bg_elem_field(m, x);
  if (f < 0) return visit(V, u, u ^ 1, 1.0, s0, qt);
  for (int p = 0; p < m->field_nport[f]; p++) {
    int e = m->field_elemadr[f] + p, b = bg_ceng_port(V->E, e);
    if (b < 0) continue;
    int in = sig_node(V->E, 2 * b) == e ? 2 * b : 2 * b + 1;
    if (visit(V, u, in ^ 1, 1.0, s0, qt)) return 1;
  }
  return 0;
}

/* Breadth-first search from signal `from` to signal s0 (a cycle when they
 * are the same); returns the length of the parent chain from s0, or 0. */
static int search(vd *V, int from, int s0) {
  const bg_model *m = V->E->m;
  for (int i = 0; i < V->nsig; i++) V->parent[i] = -2;
  int qh = 0, qt = 0;
  V->queue[qt++] = from;
  V->parent[from] = -1;
  while (qh < qt) {
    int u = V->queue[qh++], x = sig_node(V->E, u), k = m->elem_kind[x];
    int closed = bg_elem_is_junction(k) ? expand_junction(V, u, x, s0, &qt)
                 : bg_elem_is_twoport(k) ? expand_twoport(V, u, x, s0, &qt)
                 : V->reach ? expand_oneport(V, u, x, s0, &qt) : 0;
    if (closed) {
      int n = 1;
      for (int t = V->parent[s0]; t != from && t >= 0; t = V->parent[t]) n++;
      return n;
    }
  }
  return 0;
}

/* Breadth-first search for a cycle through signal s0. */
static int find_cycle(vd *V, int s0) { return search(V, s0, s0); }

/* Whether the two constraints of a unity loop through bond b determine its
 * two variables (docs/property.md, finding 5): the effort loop cut open at
 * e_b is reached from f_b and the flow loop cut open at f_b from e_b, along
 * the junction structure and through resistors (not through stores). Then
 * the loop is an algebraic loop of the model's resistors, not a constraint
 * among stores, and no store is dependent for it. Structural: a dependence
 * that cancels numerically is left to the analysis stage's test, which then
 * predicts the index from SCAP's pattern. */
static int loop_solvable(vd *V, int b) {
  V->reach = 1;
  int solvable = search(V, 2 * b + 1, 2 * b) > 0 && search(V, 2 * b, 2 * b + 1) > 0;
  V->reach = 0;
  return solvable;
}

/* Marks the integral stores attached to node x as candidates. */
static void mark_stores_at(vd *V, int x) {
  const bg_model *m = V->E->m;
  const int *bonds = m->elem_bonds + m->elem_bondadr[x];
  for (int i = 0; i < m->elem_nbond[x]; i++) {
    int o = bg_bond_other(m, bonds[i], x);
    if (o >= 0 && bg_elem_is_store(m->elem_kind[o]) && !V->cand[o] && !V->E->force_der[o] &&
        bg_ceng_oneport_caus(V->E, o) == BG_CAUS_INTEGRAL) {
      V->cand[o] = 1;
      V->ncand++;
    }
  }
}

/* Is there a unity-gain causal loop through chosen bond b? Marks its stores. */
static int unity_loop(vd *V, int b, int record) {
  for (int flow = 0; flow < 2; flow++) {
    int s0 = 2 * b + flow, n = find_cycle(V, s0);
    if (!n) continue;
    double g = V->coef[s0];
    for (int t = V->parent[s0]; t != s0; t = V->parent[t]) g *= V->coef[t];
    if (!(fabs(g - 1.0) < 1e-9)) return 0;
    if (loop_solvable(V, b)) return 0;
    if (!record) return 1;
    find_cycle(V, s0); /* the dependence search reused the parent chain */
    V->nloops++;
    for (int t = V->parent[s0];; t = V->parent[t]) {
      mark_stores_at(V, sig_node(V->E, t));
      if (t == s0) break;
    }
    if (V->why.len == 0) { /* the chain runs backwards: reverse it into queue */
      int k = 0;
      for (int t = V->parent[s0]; t != s0; t = V->parent[t]) V->queue[k++] = t;
      bg_sb_printf(&V->why, "a causal loop of gain +1 through bonds %d", V->E->m->bond_num[b]);
      while (k > 0) bg_sb_printf(&V->why, ", %d", V->E->m->bond_num[V->queue[--k] / 2]);
    }
    return 1;
  }
  return 0;
}

/* Number of problems of the current assignment: unity loops closed by
 * choices plus conflicts. With record, collects the candidate stores. */
static int problems(vd *V, int record) {
  bg_ceng *E = V->E;
  const bg_model *m = E->m;
  int n = 0;
  for (int i = 0; i < m->nbond; i++)
    if (E->a->bond_reason[E->bond_order[i]] == BG_REASON_CHOICE)
      n += unity_loop(V, E->bond_order[i], record);
  for (int i = 0; i < m->nelem; i++) {
    int e = E->elem_order[i];
    if (!bg_ceng_badness(E, e)) continue;
    n++;
    if (!record) continue;
    mark_stores_at(V, e);
    if (V->why.len == 0) bg_sb_printf(&V->why, "a causal conflict at %s", m->elem_name[e]);
  }
  return n;
}

static void run_scap(bg_ceng *E) {
  bg_ceng_reset(E);
  bg_ceng_scap(E, 0);
}

/* Fallback when the problem touches no store directly: every integral store. */
static void all_integral_stores(vd *V) {
  const bg_model *m = V->E->m;
  for (int e = 0; e < m->nelem; e++)
    if (bg_elem_is_store(m->elem_kind[e]) && !V->E->force_der[e] &&
        bg_ceng_oneport_caus(V->E, e) == BG_CAUS_INTEGRAL)
      V->cand[e] = 1, V->ncand++;
}

/* One round: returns the store that helps, or -1. E holds the SCAP result. */
static int round_once(vd *V, int nprob) {
  bg_ceng *E = V->E;
  const bg_model *m = E->m;
  memset(V->cand, 0, m->nelem);
  V->ncand = V->nloops = 0;
  bg_sb_clear(&V->why);
  problems(V, 1);
  if (V->ncand == 0 && V->nloops > 0) all_integral_stores(V);
  /* a store whose initial value the model gives is tried last: its value
   * stays the one the user wrote when another store can be the dependent one */
  for (int given = 0; given < 2; given++)
    for (int i = 0; i < m->nelem; i++) {
      int e = E->elem_order[i];
      if (!V->cand[e] || (m->elem_init && m->elem_init[e] >= 0) != given) continue;
      E->force_der[e] = 1;
      run_scap(E);
      int better = problems(V, 0) < nprob;
      E->force_der[e] = 0;
      if (better) return e;
    }
  return -1;
}

static void note(bg_strbuf *notes, int *nnotes, const char *text) {
  bg_sb_puts(notes, text);
  bg_sb_putc(notes, '\n');
  (*nnotes)++;
}

/* Puts the notes before the final run's steps, renumbering bond steps. */
static void prepend_notes(bg_ceng *E, const bg_strbuf *notes, int nnotes) {
  if (nnotes == 0) return;
  char **old = E->trace;
  int nold = E->ntrace;
  E->trace = NULL;
  E->ntrace = E->captrace = 0;
  const char *s = bg_sb_str(notes);
  for (const char *nl; (nl = strchr(s, '\n')); s = nl + 1) {
    char *line = bg_xmalloc(nl - s + 1);
    memcpy(line, s, nl - s);
    line[nl - s] = 0;
    bg_ceng_trace(E, line);
    free(line);
  }
  for (int i = 0; i < nold; i++) bg_ceng_trace(E, old[i]), free(old[i]);
  free(old);
  for (int b = 0; b < E->m->nbond; b++)
    if (E->a->bond_step[b]) E->a->bond_step[b] += nnotes;
}

void bg_ceng_vandijk(bg_ceng *E) {
  const bg_model *m = E->m;
  vd V;
  memset(&V, 0, sizeof V);
  V.E = E;
  V.nsig = 2 * (m->nbond > 0 ? m->nbond : 1);
  V.parent = bg_xcalloc(V.nsig, sizeof(int));
  V.queue = bg_xcalloc(V.nsig, sizeof(int));
  V.coef = bg_xcalloc(V.nsig, sizeof(double));
  V.cand = bg_xcalloc(m->nelem > 0 ? m->nelem : 1, 1);
  bg_strbuf notes = {0};
  int nnotes = 0;
  run_scap(E);
  for (int nprob; (nprob = problems(&V, 0)) > 0;) {
    int s = round_once(&V, nprob);
    bg_strbuf sb = {0};
    if (s < 0) {
      bg_sb_printf(&sb, "van Dijk: SCAP gave %s; no store's derivative causality removes it, "
                   "so SCAP's result stands", bg_sb_str(&V.why));
      note(&notes, &nnotes, bg_sb_str(&sb));
      bg_sb_free(&sb);
      run_scap(E);
      break;
    }
    bg_sb_printf(&sb, "van Dijk: SCAP gave %s: the junction structure imposes a constraint "
                 "among stores; %s %s gets derivative causality and SCAP runs again",
                 bg_sb_str(&V.why), bg_elem_kind_name(m->elem_kind[s]), m->elem_name[s]);
    note(&notes, &nnotes, bg_sb_str(&sb));
    bg_sb_free(&sb);
    E->force_der[s] = 1;
    run_scap(E);
  }
  prepend_notes(E, &notes, nnotes);
  bg_sb_free(&notes);
  bg_sb_free(&V.why);
  free(V.parent); free(V.queue); free(V.coef); free(V.cand);
}
