/* SPDX-License-Identifier: BSD-3-Clause */
/* From the engine's strokes to the analysis: element causalities, inverted
 * laws, conflict records (Definitions 4.18, 4.19), completeness, the trace
 * and the Lagrange lists, all allocated in a->arena. */
#include <stdlib.h>
#include <string.h>

#include "causality/causality_int.h"
#include "base/strbuf.h"

static int elem_caus(const bg_ceng *E, int e) {
  const bg_model *m = E->m;
  int kind = m->elem_kind[e];
  if (bg_elem_is_oneport(kind)) return bg_ceng_oneport_caus(E, e);
  int deg = m->elem_nbond[e];
  return deg > 0 && E->nat[e] + E->naway[e] == deg ? BG_CAUS_TRANSFER : BG_CAUS_NONE;
}

/* The law had to be inverted: an R against its law's form, a store with a
 * law in derivative causality. VALUE forms are linear and need no inversion. */
static int elem_inverted(const bg_model *m, int e, int caus) {
  int form = m->elem_form[e], kind = m->elem_kind[e];
  if (form != BG_FORM_LAW_E && form != BG_FORM_LAW_F) return 0;
  if (kind == BG_ELEM_R)
    return caus != BG_CAUS_NONE && caus != bg_ceng_r_natural(m, e);
  return bg_elem_is_store(kind) && caus == BG_CAUS_DERIVATIVE;
}

static int *arena_ints(bg_arena *ar, const bg_ivec *x) {
  int *p = bg_arena_alloc(ar, (x->n ? x->n : 1) * sizeof(int));
  if (x->n) memcpy(p, x->v, x->n * sizeof(int));
  return p;
}

typedef struct conflicts {
  bg_ivec node, type, degree, adr, n, bonds;
} conflicts;

/* One conflict at node e: type 2 lists the k+1 bonds that determine the
 * common variable, type 1 every bond of the node. */
static void add_conflict(const bg_ceng *E, conflicts *c, int e) {
  const bg_model *m = E->m;
  int kind = m->elem_kind[e], deg = m->elem_nbond[e], bad = bg_ceng_badness(E, e);
  const int *bonds = bg_ceng_bonds(E, e); /* by number */
  int type = 2, degree = 1, strong_at = -1; /* -1: list every bond */
  if (bg_elem_is_junction(kind)) {
    int strong = kind == BG_ELEM_J0 ? E->nat[e] : E->naway[e] + E->art[e];
    type = strong >= 2 ? 2 : 1;
    degree = type == 2 ? bad : 0;
    if (type == 2) strong_at = kind == BG_ELEM_J0;
  } else if (kind == BG_ELEM_TF || kind == BG_ELEM_MTF) {
    type = E->nat[e] == 2 ? 2 : 1;
    degree = type == 2;
  }
  bg_ivec_push(&c->node, e);
  bg_ivec_push(&c->type, type);
  bg_ivec_push(&c->degree, degree);
  bg_ivec_push(&c->adr, c->bonds.n);
  for (int i = 0; i < deg; i++)
    if (strong_at < 0 || bg_ceng_at(E, bonds[i], e) == strong_at) bg_ivec_push(&c->bonds, bonds[i]);
  bg_ivec_push(&c->n, c->bonds.n - c->adr.v[c->adr.n - 1]);
}

/* One trace line per conflict, after the steps, so the report says where
 * the rules broke and how many algebraic constraints each one brings. */
static void trace_conflict(bg_ceng *E, const conflicts *c, int i) {
  const bg_model *m = E->m;
  int e = c->node.v[i], kind = m->elem_kind[e], type = c->type.v[i];
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "conflict at %s: ", m->elem_name[e]);
  if (bg_elem_is_junction(kind)) {
    const char *var = kind == BG_ELEM_J0 ? "effort" : "flow";
    if (type == 1) bg_sb_printf(&sb, "type 1, no bond determines the common %s", var);
    else bg_sb_printf(&sb, "type 2 of degree %d, %d bonds determine the common %s",
                      c->degree.v[i], c->degree.v[i] + 1, var);
  } else if (bg_elem_is_oneport(kind)) {
    bg_sb_printf(&sb, "its bond's stroke goes against its %s",
                 bg_elem_is_source(kind) ? "source type" : "causality option");
  } else {
    bg_sb_puts(&sb, "the two strokes break the two-port's rule");
  }
  bg_sb_puts(&sb, " (bonds ");
  for (int k = 0; k < c->n.v[i]; k++)
    bg_sb_printf(&sb, "%s%d", k ? ", " : "", m->bond_num[c->bonds.v[c->adr.v[i] + k]]);
  bg_sb_putc(&sb, ')');
  bg_ceng_trace(E, bg_sb_str(&sb));
  bg_sb_free(&sb);
}

static void write_conflicts(bg_ceng *E) {
  bg_analysis *a = E->a;
  conflicts c;
  memset(&c, 0, sizeof c);
  for (int e = 0; e < E->m->nelem; e++)
    if (bg_ceng_badness(E, e)) add_conflict(E, &c, e);
  for (int i = 0; i < c.node.n; i++) trace_conflict(E, &c, i);
  a->nconflict = c.node.n;
  a->conflict_node = arena_ints(&a->arena, &c.node);
  a->conflict_type = arena_ints(&a->arena, &c.type);
  a->conflict_degree = arena_ints(&a->arena, &c.degree);
  a->conflict_adr = arena_ints(&a->arena, &c.adr);
  a->conflict_n = arena_ints(&a->arena, &c.n);
  a->conflict_bonds = arena_ints(&a->arena, &c.bonds);
  for (int i = 0; i < E->m->nbond; i++) a->bond_conflict[i] = 0;
  for (int i = 0; i < c.bonds.n; i++) a->bond_conflict[c.bonds.v[i]] = 1;
  free(c.node.v); free(c.type.v); free(c.degree.v);
  free(c.adr.v); free(c.n.v); free(c.bonds.v);
}

static void write_trace(bg_ceng *E) {
  bg_analysis *a = E->a;
  a->ntrace = E->ntrace;
  a->trace_text = bg_arena_alloc(&a->arena, (E->ntrace ? E->ntrace : 1) * sizeof(char *));
  for (int i = 0; i < E->ntrace; i++) a->trace_text[i] = bg_arena_strdup(&a->arena, E->trace[i]);
}

static void write_lagrange(bg_ceng *E) {
  bg_analysis *a = E->a;
  int n = E->nlag;
  a->nlag = n;
  a->lag_junction = bg_arena_alloc(&a->arena, (n ? n : 1) * sizeof(int));
  a->lag_bond = bg_arena_alloc(&a->arena, (n ? n : 1) * sizeof(int));
  a->lag_force = bg_arena_alloc(&a->arena, (n ? n : 1) * sizeof(char *));
  for (int i = 0; i < n; i++) {
    bg_strbuf sb = {0};
    a->lag_junction[i] = E->lag_junction[i];
    a->lag_bond[i] = E->lag_bond[i];
    bg_ceng_lag_force(E, i, &sb);
    a->lag_force[i] = bg_arena_strdup(&a->arena, bg_sb_str(&sb));
    bg_sb_free(&sb);
  }
}

void bg_ceng_finish(bg_ceng *E) {
  const bg_model *m = E->m;
  bg_analysis *a = E->a;
  for (int e = 0; e < m->nelem; e++) {
    a->elem_caus[e] = elem_caus(E, e);
    a->elem_inverted[e] = elem_inverted(m, e, a->elem_caus[e]);
  }
  a->complete = 1;
  for (int b = 0; b < m->nbond; b++)
    if (bg_ceng_open(E, b)) a->complete = 0;
  write_conflicts(E);
  write_trace(E);
  write_lagrange(E);
}
