/* SPDX-License-Identifier: BSD-3-Clause */
/* The causality engine the procedures share (causality_int.h): strokes with
 * per-node counters, worklist propagation, trial assignment with roll-back,
 * the trace, and the names of causalities and reasons.
 * Every node keeps how many of its bonds have their stroke at it (nat) and
 * away from it (naway), so a node's rule is checked in O(1) and a node
 * scans its bonds only when it is about to assign them: propagation is
 * linear in the number of bonds. */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "causality/causality_int.h"
#include "base/sort.h"
#include "base/strbuf.h"

/* ---------------------------------------------------------------- set-up */
/* The tie-break orders (causality_int.h) are functions of the graph, its
 * names and its bond numbers, never of the order of the statements. */
typedef struct { long key; const char *name; int idx; } order_item;

static int by_key(const void *pa, const void *pb) {
  const order_item *a = pa, *b = pb;
  if (a->key != b->key) return a->key < b->key ? -1 : 1;
  int c = a->name && b->name ? bg_natural_cmp(a->name, b->name) : 0;
  if (c) return c;
  return (a->idx > b->idx) - (a->idx < b->idx);
}

static void sort_items(order_item *it, int n, int *out) {
  qsort(it, (size_t)n, sizeof *it, by_key);
  for (int i = 0; i < n; i++) out[i] = it[i].idx;
}

static void make_orders(bg_ceng *E) {
  const bg_model *m = E->m;
  int n = m->nbond > m->nelem ? m->nbond : m->nelem, nref = 0;
  order_item *it = bg_xcalloc(n > 0 ? n : 1, sizeof *it);
  for (int b = 0; b < m->nbond; b++) it[b] = (order_item){m->bond_num[b], NULL, b};
  sort_items(it, m->nbond, E->bond_order);
  for (int e = 0; e < m->nelem; e++) {
    int adr = m->elem_bondadr[e], deg = m->elem_nbond[e];
    if (adr + deg > nref) nref = adr + deg;
  }
  E->adj = bg_xcalloc(nref > 0 ? nref : 1, sizeof(int));
  for (int e = 0; e < m->nelem; e++) {
    int adr = m->elem_bondadr[e], deg = m->elem_nbond[e];
    for (int i = 0; i < deg; i++) {
      int b = m->elem_bonds[adr + i];
      it[i] = (order_item){m->bond_num[b], NULL, b};
    }
    sort_items(it, deg, E->adj + adr);
  }
  for (int e = 0; e < m->nelem; e++) {
    long key = 0;
    if (!bg_elem_is_oneport(m->elem_kind[e]))
      key = m->elem_nbond[e] > 0 ? m->bond_num[E->adj[m->elem_bondadr[e]]] : LONG_MAX;
    else if (bg_elem_is_store(m->elem_kind[e]) && m->elem_init && m->elem_init[e] < 0)
      key = 1;
    it[e] = (order_item){key, bg_elem_is_oneport(m->elem_kind[e]) ? m->elem_name[e] : NULL, e};
  }
  sort_items(it, m->nelem, E->elem_order);
  free(it);
}

const int *bg_ceng_bonds(const bg_ceng *E, int e) { return E->adj + E->m->elem_bondadr[e]; }

void bg_ceng_init(bg_ceng *E, const bg_model *m, bg_analysis *a) {
  memset(E, 0, sizeof *E);
  E->m = m;
  E->a = a;
  E->stroke = a->bond_stroke;
  int ne = m->nelem > 0 ? m->nelem : 1, nb = m->nbond > 0 ? m->nbond : 1;
  E->nat = bg_xcalloc(ne, sizeof(int));
  E->naway = bg_xcalloc(ne, sizeof(int));
  E->nblk = bg_xcalloc(ne, sizeof(int));
  E->art = bg_xcalloc(ne, 1);
  E->force_der = bg_xcalloc(ne, 1);
  E->inq = bg_xcalloc(ne, 1);
  E->queue = bg_xcalloc(ne, sizeof(int));
  E->dqueue = bg_xcalloc(ne, sizeof(int));
  E->indq = bg_xcalloc(ne, 1);
  E->blocked = bg_xcalloc(nb, 1);
  E->split = bg_xcalloc(nb, 1);
  E->log = bg_xcalloc(nb, sizeof(int));
  E->bond_order = bg_xcalloc(nb, sizeof(int));
  E->elem_order = bg_xcalloc(ne, sizeof(int));
  make_orders(E);
}

static void trace_clear(bg_ceng *E) {
  for (int i = 0; i < E->ntrace; i++) free(E->trace[i]);
  E->ntrace = 0;
}

/* Everything but force_der (van Dijk's choices survive a restart). */
void bg_ceng_reset(bg_ceng *E) {
  const bg_model *m = E->m;
  size_t ne = m->nelem, nb = m->nbond;
  memset(E->nat, 0, ne * sizeof(int));
  memset(E->naway, 0, ne * sizeof(int));
  memset(E->nblk, 0, ne * sizeof(int));
  memset(E->art, 0, ne);
  memset(E->inq, 0, ne);
  memset(E->indq, 0, ne);
  memset(E->blocked, 0, nb);
  memset(E->split, 0, nb);
  for (int b = 0; b < m->nbond; b++) {
    E->stroke[b] = BG_STROKE_NONE;
    E->a->bond_reason[b] = BG_REASON_NONE;
    E->a->bond_step[b] = 0;
  }
  E->qhead = E->qlen = E->dhead = E->dlen = E->nlog = E->trial = E->bad = E->step = 0;
  E->nlag = 0;
  trace_clear(E);
}

void bg_ceng_free(bg_ceng *E) {
  trace_clear(E);
  free(E->trace);
  free(E->nat); free(E->naway); free(E->nblk); free(E->art); free(E->force_der);
  free(E->inq); free(E->queue); free(E->indq); free(E->dqueue); free(E->blocked); free(E->split); free(E->log);
  free(E->lag_junction); free(E->lag_bond);
  free(E->bond_order); free(E->elem_order); free(E->adj);
  memset(E, 0, sizeof *E);
}

/* ---------------------------------------------------------------- queries */
int bg_ceng_stroke_for(const bg_ceng *E, int b, int e, int at) {
  int head_is_e = E->m->bond_head[b] == e;
  return (head_is_e == (at != 0)) ? BG_STROKE_HEAD : BG_STROKE_TAIL;
}

int bg_ceng_at(const bg_ceng *E, int b, int e) {
  if (E->split[b]) return 0;
  int s = E->stroke[b];
  if (s == BG_STROKE_NONE) return -1;
  int end = s == BG_STROKE_HEAD ? E->m->bond_head[b] : E->m->bond_tail[b];
  return end == e;
}

int bg_ceng_open(const bg_ceng *E, int b) {
  return E->stroke[b] == BG_STROKE_NONE && !E->split[b];
}

int bg_ceng_port(const bg_ceng *E, int e) {
  return E->m->elem_nbond[e] > 0 ? E->m->elem_bonds[E->m->elem_bondadr[e]] : -1;
}

int bg_ceng_r_nonlinear(const bg_model *m, int e) {
  return m->elem_kind[e] == BG_ELEM_R && m->elem_form[e] != BG_FORM_VALUE &&
         m->elem_form[e] != BG_FORM_NONE && !m->elem_linear[e];
}

int bg_ceng_r_natural(const bg_model *m, int e) {
  return m->elem_form[e] == BG_FORM_LAW_F ? BG_CAUS_CONDUCTANCE : BG_CAUS_RESISTANCE;
}

/* Is the stroke of a one-port's bond at the element for causality caus? */
static int caus_wants_at(int kind, int caus) {
  switch (kind) {
  case BG_ELEM_C: return caus == BG_CAUS_DERIVATIVE;
  case BG_ELEM_I: return caus == BG_CAUS_INTEGRAL;
  case BG_ELEM_R: return caus == BG_CAUS_CONDUCTANCE;
  case BG_ELEM_SF: case BG_ELEM_MSF: return 1;
  default: return 0; /* Se: effort out */
  }
}

int bg_ceng_oneport_stroke(const bg_ceng *E, int e, int caus) {
  int b = bg_ceng_port(E, e);
  return bg_ceng_stroke_for(E, b, e, caus_wants_at(E->m->elem_kind[e], caus));
}

int bg_ceng_oneport_caus(const bg_ceng *E, int e) {
  int b = bg_ceng_port(E, e), kind = E->m->elem_kind[e];
  int at = b < 0 ? -1 : bg_ceng_at(E, b, e);
  if (at < 0) return BG_CAUS_NONE;
  switch (kind) {
  case BG_ELEM_C: return at ? BG_CAUS_DERIVATIVE : BG_CAUS_INTEGRAL;
  case BG_ELEM_I: return at ? BG_CAUS_INTEGRAL : BG_CAUS_DERIVATIVE;
  case BG_ELEM_R: return at ? BG_CAUS_CONDUCTANCE : BG_CAUS_RESISTANCE;
  default: return BG_CAUS_FIXED;
  }
}

/* The causality a store or R must have (option, or van Dijk's choice); NONE if free. */
static int required_caus(const bg_ceng *E, int e) {
  if (E->force_der[e]) return BG_CAUS_DERIVATIVE;
  switch (E->m->elem_causopt[e]) {
  case BG_CAUS_OPT_INTEGRAL: return BG_CAUS_INTEGRAL;
  case BG_CAUS_OPT_DERIVATIVE: return BG_CAUS_DERIVATIVE;
  case BG_CAUS_OPT_RESISTANCE: return BG_CAUS_RESISTANCE;
  case BG_CAUS_OPT_CONDUCTANCE: return BG_CAUS_CONDUCTANCE;
  default: return BG_CAUS_NONE;
  }
}

static int junction_badness(const bg_ceng *E, int e) {
  int kind = E->m->elem_kind[e], deg = E->m->elem_nbond[e];
  int strong = kind == BG_ELEM_J0 ? E->nat[e] : E->naway[e] + E->art[e];
  if (strong >= 2) return strong - 1;
  if (strong == 0 && deg > 0 && E->nat[e] + E->naway[e] == deg) return 1;
  return 0;
}

int bg_ceng_badness(const bg_ceng *E, int e) {
  int kind = E->m->elem_kind[e];
  switch (kind) {
  case BG_ELEM_J0: case BG_ELEM_J1: return junction_badness(E, e);
  case BG_ELEM_TF: case BG_ELEM_MTF: return E->nat[e] == 2 || E->naway[e] == 2;
  case BG_ELEM_GY: case BG_ELEM_MGY: return E->nat[e] == 1 && E->naway[e] == 1;
  case BG_ELEM_SE: case BG_ELEM_MSE: return E->nat[e] > 0;
  case BG_ELEM_SF: case BG_ELEM_MSF: return E->naway[e] > 0;
  default: {
    int want = required_caus(E, e), have = bg_ceng_oneport_caus(E, e);
    return want != BG_CAUS_NONE && have != BG_CAUS_NONE && want != have;
  }
  }
}

/* ---------------------------------------------------------------- assignment */
static int pop(const int *q, int *head, int *len, int cap) {
  int e = q[*head];
  *head = (*head + 1) % cap;
  (*len)--;
  return e;
}

static void queue_node(bg_ceng *E, int e) {
  if (e < 0 || E->inq[e]) return;
  E->inq[e] = 1;
  E->queue[(E->qhead + E->qlen++) % E->m->nelem] = e;
}

static void count_stroke(bg_ceng *E, int b, int s, int d) {
  int at_end = s == BG_STROKE_HEAD ? E->m->bond_head[b] : E->m->bond_tail[b];
  int other = s == BG_STROKE_HEAD ? E->m->bond_tail[b] : E->m->bond_head[b];
  E->nat[at_end] += d;
  E->naway[other] += d;
  if (E->blocked[b]) {
    E->nblk[at_end] -= d;
    E->nblk[other] -= d;
  }
}

void bg_ceng_set(bg_ceng *E, int b, int stroke, int reason) {
  const bg_model *m = E->m;
  int t = m->bond_tail[b], h = m->bond_head[b];
  if (!bg_ceng_open(E, b)) BG_FATAL("bond %d assigned twice", m->bond_num[b]);
  int bt = E->trial ? bg_ceng_badness(E, t) : 0, bh = E->trial ? bg_ceng_badness(E, h) : 0;
  E->stroke[b] = stroke;
  count_stroke(E, b, stroke, 1);
  E->a->bond_reason[b] = reason;
  E->a->bond_step[b] = E->step;
  E->log[E->nlog++] = b;
  if (E->trial && (bg_ceng_badness(E, t) > bt || bg_ceng_badness(E, h) > bh)) E->bad++;
  queue_node(E, t);
  queue_node(E, h);
}

void bg_ceng_split(bg_ceng *E, int b) {
  int t = E->m->bond_tail[b], h = E->m->bond_head[b];
  E->split[b] = 1;
  E->naway[t]++;
  E->naway[h]++;
  if (E->blocked[b]) {
    E->nblk[t]--;
    E->nblk[h]--;
  }
  E->a->bond_reason[b] = BG_REASON_LAGRANGE;
  E->a->bond_step[b] = E->step;
  queue_node(E, t);
  queue_node(E, h);
}

static void rollback(bg_ceng *E, int mark) {
  while (E->nlog > mark) {
    int b = E->log[--E->nlog];
    count_stroke(E, b, E->stroke[b], -1);
    E->stroke[b] = BG_STROKE_NONE;
    E->a->bond_reason[b] = BG_REASON_NONE;
    E->a->bond_step[b] = 0;
  }
  while (E->qlen) E->inq[pop(E->queue, &E->qhead, &E->qlen, E->m->nelem)] = 0;
  while (E->dlen) E->indq[pop(E->dqueue, &E->dhead, &E->dlen, E->m->nelem)] = 0;
}

/* ---------------------------------------------------------------- propagation */
/* A junction: strong bond known -> every other open bond weak; all but one
 * bond weak -> the last one strong. Blocked bonds stay open. */
static void prop_junction(bg_ceng *E, int e, int deferred) {
  const bg_model *m = E->m;
  int j0 = m->elem_kind[e] == BG_ELEM_J0, deg = m->elem_nbond[e];
  int unassigned = deg - E->nat[e] - E->naway[e];
  int open = unassigned - E->nblk[e];
  if (open <= 0) return;
  int strong = j0 ? E->nat[e] : E->naway[e] + E->art[e];
  if (strong == 0 && unassigned != 1) return;
  if (strong == 0 && !deferred) {
    if (!E->indq[e]) {
      E->indq[e] = 1;
      E->dqueue[(E->dhead + E->dlen++) % m->nelem] = e;
    }
    return;
  }
  /* strong at a 0-junction = stroke at it; at a 1-junction = stroke away */
  int at = strong ? !j0 : j0;
  const int *bonds = bg_ceng_bonds(E, e);
  for (int i = 0; i < deg; i++) {
    int b = bonds[i];
    if (bg_ceng_open(E, b) && !E->blocked[b])
      bg_ceng_set(E, b, bg_ceng_stroke_for(E, b, e, at), BG_REASON_PROPAGATION);
  }
}

/* TF: one stroke at the node, one away; GY: both at or both away. */
static void prop_twoport(bg_ceng *E, int e) {
  const bg_model *m = E->m;
  if (m->elem_nbond[e] != 2 || E->nat[e] + E->naway[e] != 1) return;
  const int *bonds = bg_ceng_bonds(E, e);
  int done = bg_ceng_open(E, bonds[0]) ? bonds[1] : bonds[0];
  int todo = done == bonds[0] ? bonds[1] : bonds[0];
  if (!bg_ceng_open(E, todo) || E->blocked[todo]) return;
  int gy = m->elem_kind[e] == BG_ELEM_GY || m->elem_kind[e] == BG_ELEM_MGY;
  int at = bg_ceng_at(E, done, e);
  bg_ceng_set(E, todo, bg_ceng_stroke_for(E, todo, e, gy ? at : !at), BG_REASON_PROPAGATION);
}

void bg_ceng_propagate(bg_ceng *E) {
  int n = E->m->nelem;
  while (E->qlen || E->dlen) {
    int deferred = E->qlen == 0, e;
    if (deferred) E->indq[e = pop(E->dqueue, &E->dhead, &E->dlen, n)] = 0;
    else E->inq[e = pop(E->queue, &E->qhead, &E->qlen, n)] = 0;
    int kind = E->m->elem_kind[e];
    if (bg_elem_is_junction(kind)) prop_junction(E, e, deferred);
    else if (bg_elem_is_twoport(kind)) prop_twoport(E, e);
  }
}

int bg_ceng_try(bg_ceng *E, int b, int stroke, int reason) {
  int mark = E->nlog, was = E->trial;
  E->trial = 1;
  E->bad = 0;
  bg_ceng_set(E, b, stroke, reason);
  bg_ceng_propagate(E);
  E->trial = was;
  if (E->bad == 0) return 1;
  rollback(E, mark);
  return 0;
}

/* ---------------------------------------------------------------- trace */
void bg_ceng_trace(bg_ceng *E, const char *text) {
  if (E->ntrace == E->captrace) {
    E->captrace = E->captrace ? 2 * E->captrace : 16;
    E->trace = bg_xrealloc(E->trace, E->captrace * sizeof(char *));
  }
  size_t n = strlen(text) + 1;
  E->trace[E->ntrace] = bg_xmalloc(n);
  memcpy(E->trace[E->ntrace++], text, n);
}

/* "; propagated to bonds 8, 9" listing at most 24 bonds, so a trace line
 * stays readable on large models. */
void bg_ceng_prop_list(const bg_ceng *E, int mark, bg_strbuf *sb) {
  int n = E->nlog - mark;
  if (n <= 0) return;
  bg_sb_puts(sb, n == 1 ? "; propagated to bond " : "; propagated to bonds ");
  for (int i = 0; i < n && i < 24; i++)
    bg_sb_printf(sb, "%s%d", i ? ", " : "", E->m->bond_num[E->log[mark + i]]);
  if (n > 24) bg_sb_printf(sb, " and %d more", n - 24);
}

/* ---------------------------------------------------------------- names */
const char *bg_caus_name(int caus) {
  static const char *names[] = {"none", "fixed", "integral", "derivative",
                                "resistance", "conductance", "transfer"};
  return caus >= 0 && caus <= BG_CAUS_TRANSFER ? names[caus] : "none";
}

const char *bg_reason_name(int reason) {
  static const char *names[] = {NULL, "source", "store", "resistor", "choice",
                                "propagation", "user", "lagrange"};
  return reason > 0 && reason <= BG_REASON_LAGRANGE ? names[reason] : NULL;
}
