/* SPDX-License-Identifier: BSD-3-Clause */
/* Lagrange causality (Karnopp, Section 4.10.1): sources, then artificial
 * flow sources at undetermined 1-junctions (by name), then, when bonds
 * are still open and no 1-junction is undetermined, a 1-junction inserted
 * into the open bond of the smallest number. Generalised forces (4.10.2) as text. */
#include <string.h>

#include "causality/causality_int.h"
#include "model/model.h"
#include "base/strbuf.h"

static void lag_push(bg_ceng *E, int junction, int bond) {
  if (E->nlag == E->caplag) {
    E->caplag = E->caplag ? 2 * E->caplag : 8;
    E->lag_junction = bg_xrealloc(E->lag_junction, E->caplag * sizeof(int));
    E->lag_bond = bg_xrealloc(E->lag_bond, E->caplag * sizeof(int));
  }
  E->lag_junction[E->nlag] = junction;
  E->lag_bond[E->nlag++] = bond;
}

static int j1_undetermined(const bg_ceng *E, int e) {
  return E->m->elem_kind[e] == BG_ELEM_J1 && E->naway[e] + E->art[e] == 0;
}

/* The artificial source imposes the flow: every real bond of the junction
 * gets its stroke at it (weak); propagation does the rest. */
static void attach(bg_ceng *E, int j) {
  const bg_model *m = E->m;
  const int *bonds = bg_ceng_bonds(E, j);
  int mark = E->nlog;
  E->step = E->ntrace + 1;
  E->art[j] = 1;
  lag_push(E, j, -1);
  for (int i = 0; i < m->elem_nbond[j]; i++)
    if (bg_ceng_open(E, bonds[i]))
      bg_ceng_set(E, bonds[i], bg_ceng_stroke_for(E, bonds[i], j, 1), BG_REASON_LAGRANGE);
  int first_prop = E->nlog;
  bg_ceng_propagate(E);
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "lagrange: artificial flow source at 1-junction %s (generalised coordinate q%d)",
               m->elem_name[j], E->nlag);
  for (int i = mark; i < first_prop; i++)
    bg_sb_printf(&sb, "%s%d", i == mark ? "; strokes at it on bonds " : ", ",
                 m->bond_num[E->log[i]]);
  bg_ceng_prop_list(E, first_prop, &sb);
  bg_ceng_trace(E, bg_sb_str(&sb));
  bg_sb_free(&sb);
}

static void insert(bg_ceng *E, int b) {
  int mark = E->nlog;
  E->step = E->ntrace + 1;
  lag_push(E, -1, b);
  bg_ceng_split(E, b);
  bg_ceng_propagate(E);
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "lagrange: no undetermined 1-junction left; a 1-junction with an artificial "
               "flow source is inserted into bond %d (generalised coordinate q%d)",
               E->m->bond_num[b], E->nlag);
  bg_ceng_prop_list(E, mark, &sb);
  bg_ceng_trace(E, bg_sb_str(&sb));
  bg_sb_free(&sb);
}

void bg_ceng_lagrange(bg_ceng *E) {
  const bg_model *m = E->m;
  bg_ceng_block(E, 0);
  bg_ceng_fixed(E);
  bg_ceng_sources(E);
  /* Both cursors only move forward: a determined junction stays determined
   * and an assigned bond stays assigned. */
  int j = 0, b = 0;
  for (;;) {
    while (j < m->nelem && !j1_undetermined(E, E->elem_order[j])) j++;
    if (j < m->nelem) {
      attach(E, E->elem_order[j]);
      continue;
    }
    while (b < m->nbond && !bg_ceng_open(E, E->bond_order[b])) b++;
    if (b == m->nbond) break;
    insert(E, E->bond_order[b]);
  }
}

/* ---------------------------------------------------------------- generalised forces */
static void put_value(const bg_model *m, int e, bg_strbuf *sb) {
  bg_strbuf v = {0};
  bg_xprint(m, m->elem_expr[e], &v);
  const char *s = bg_sb_str(&v);
  int compound = strpbrk(s + 1, "+-") != NULL;
  bg_sb_printf(sb, compound ? "(%s)" : "%s", s);
  bg_sb_free(&v);
}

/* The effort element `other` puts on bond b, or 0 when it is neither a
 * source nor an R (those are left out of the generalised force). */
static int put_term(const bg_ceng *E, int other, int b, int sign, int first, bg_strbuf *sb) {
  const bg_model *m = E->m;
  int kind = m->elem_kind[other];
  if (!bg_elem_is_source(kind) && kind != BG_ELEM_R) return 0;
  if (sign < 0) bg_sb_puts(sb, first ? "-" : " - ");
  else if (!first) bg_sb_puts(sb, " + ");
  if (kind == BG_ELEM_SE || kind == BG_ELEM_MSE) bg_sb_puts(sb, m->elem_name[other]);
  else if (kind == BG_ELEM_R && m->elem_form[other] == BG_FORM_VALUE && m->elem_expr[other] >= 0 &&
           bg_ceng_oneport_caus(E, other) == BG_CAUS_RESISTANCE) {
    put_value(m, other, sb);
    bg_sb_printf(sb, "*f%d", m->bond_num[b]);
  } else
    bg_sb_printf(sb, "e%d", m->bond_num[b]);
  return 1;
}

/* Sum of source and resistor efforts at the junction, + for bonds pointing
 * into it (the artificial source's half arrow points out of it). */
void bg_ceng_lag_force(const bg_ceng *E, int i, bg_strbuf *sb) {
  const bg_model *m = E->m;
  int j = E->lag_junction[i], n = 0;
  if (j >= 0) {
    const int *bonds = m->elem_bonds + m->elem_bondadr[j];
    for (int k = 0; k < m->elem_nbond[j]; k++) {
      int b = bonds[k], into = m->bond_head[b] == j;
      n += put_term(E, bg_bond_other(m, b, j), b, into ? 1 : -1, n == 0, sb);
    }
  } else {
    int b = E->lag_bond[i];
    n += put_term(E, m->bond_tail[b], b, 1, n == 0, sb);
    n += put_term(E, m->bond_head[b], b, -1, n == 0, sb);
  }
  if (n == 0) bg_sb_puts(sb, "0");
}
