/* SPDX-License-Identifier: BSD-3-Clause */
/* Read-only queries on a compiled model, and its one-line summary. */
#include <string.h>

#include "model/model.h"

#include "base/strindex.h"

int bg_elem_is_junction(int kind) { return kind == BG_ELEM_J0 || kind == BG_ELEM_J1; }

int bg_elem_is_twoport(int kind) {
  return kind == BG_ELEM_TF || kind == BG_ELEM_MTF || kind == BG_ELEM_GY || kind == BG_ELEM_MGY;
}

int bg_elem_is_source(int kind) {
  return kind == BG_ELEM_SE || kind == BG_ELEM_SF || kind == BG_ELEM_MSE || kind == BG_ELEM_MSF;
}

int bg_elem_is_store(int kind) { return kind == BG_ELEM_C || kind == BG_ELEM_I; }

int bg_elem_is_oneport(int kind) {
  return bg_elem_is_source(kind) || bg_elem_is_store(kind) || kind == BG_ELEM_R;
}

const char *bg_elem_display_kind(const bg_model *m, int elem) {
  int kind = m->elem_kind[elem];
  if (m->elem_modulated[elem]) {
    if (kind == BG_ELEM_C) return "MC";
    if (kind == BG_ELEM_I) return "MI";
    if (kind == BG_ELEM_R) return "MR";
  }
  return bg_elem_kind_name(kind);
}

int bg_elem_port_bond(const bg_model *m, int elem) {
  return m->elem_nbond[elem] >= 1 ? m->elem_bonds[m->elem_bondadr[elem]] : -1;
}

/* The first bond of elem whose head (in = 1) or tail (in = 0) is elem. */
static int bond_at_end(const bg_model *m, int elem, int in) {
  for (int i = 0; i < m->elem_nbond[elem]; i++) {
    int b = m->elem_bonds[m->elem_bondadr[elem] + i];
    if ((in ? m->bond_head[b] : m->bond_tail[b]) == elem) return b;
  }
  return -1;
}

int bg_elem_in_bond(const bg_model *m, int elem) { return bond_at_end(m, elem, 1); }
int bg_elem_out_bond(const bg_model *m, int elem) { return bond_at_end(m, elem, 0); }

int bg_elem_field(const bg_model *m, int elem) {
  return m->nfield > 0 && m->elem_field && elem >= 0 && elem < m->nelem ? m->elem_field[elem] : -1;
}

const char *bg_elem_port_name(const bg_model *m, int elem) {
  int f = bg_elem_field(m, elem);
  if (f < 0) return NULL;
  return m->elem_name[elem] + strlen(m->field_name[f]) + 1;
}

int bg_bond_other(const bg_model *m, int b, int e) {
  return m->bond_tail[b] == e ? m->bond_head[b] : m->bond_tail[b];
}

void bg_model_hash_names(bg_model *m) {
  int cap = bg_strindex_size(m->nelem);
  m->elem_hash = bg_arena_alloc(&m->arena, (size_t)cap * sizeof *m->elem_hash);
  m->elem_hashcap = cap;
  bg_strindex_fill(m->elem_hash, cap, BG_STRKEYS_ARRAY(m->elem_name), m->nelem);
  cap = 16;
  while (cap < 2 * m->nbond + 2) cap *= 2;
  m->bond_hash = bg_arena_alloc(&m->arena, (size_t)cap * sizeof *m->bond_hash);
  m->bond_hashcap = cap;
  for (int i = 0; i < cap; i++) m->bond_hash[i] = -1;
  for (int b = 0; b < m->nbond; b++) {
    unsigned h = ((unsigned)m->bond_num[b] * 2654435761u) & (unsigned)(cap - 1);
    while (m->bond_hash[h] >= 0) h = (h + 1) & (unsigned)(cap - 1);
    m->bond_hash[h] = b;
  }
}

int bg_model_find_elem(const bg_model *m, const char *name) {
  if (!m->elem_hash) {
    for (int e = 0; e < m->nelem; e++)
      if (strcmp(m->elem_name[e], name) == 0) return e;
    return -1;
  }
  return bg_strindex_find(m->elem_hash, m->elem_hashcap, BG_STRKEYS_ARRAY(m->elem_name), name);
}

int bg_model_find_bond(const bg_model *m, int number) {
  /* fast path: bonds numbered 1..n in file order */
  if (number >= 1 && number <= m->nbond && m->bond_num[number - 1] == number) return number - 1;
  if (!m->bond_hash) {
    for (int b = 0; b < m->nbond; b++)
      if (m->bond_num[b] == number) return b;
    return -1;
  }
  unsigned mask = (unsigned)(m->bond_hashcap - 1);
  for (unsigned h = ((unsigned)number * 2654435761u) & mask; m->bond_hash[h] >= 0; h = (h + 1) & mask)
    if (m->bond_num[m->bond_hash[h]] == number) return m->bond_hash[h];
  return -1;
}

static const char *const method_names[] = {"scap", "relaxed", "vandijk", "lagrange"};

const char *bg_method_name(int method) {
  return method >= 0 && method < 4 ? method_names[method] : "?";
}

int bg_method_parse(const char *s) {
  for (int i = 0; i < 4; i++)
    if (strcmp(s, method_names[i]) == 0) return i;
  return -1;
}

static const char *plural(int n) { return n == 1 ? "" : "s"; }

void bg_model_summary(const bg_model *m, bg_strbuf *out) {
  const char *kinds[2 * BG_ELEM_COUNT];
  int counts[2 * BG_ELEM_COUNT], nk = 0, nelem = 0, njunc = 0, nstore = 0, nsrc = 0;
  for (int e = 0; e < m->nelem; e++) {
    int kind = m->elem_kind[e];
    if (bg_elem_is_junction(kind)) { njunc++; continue; }
    nelem++;
    nstore += bg_elem_is_store(kind);
    nsrc += bg_elem_is_source(kind);
    const char *dk = bg_elem_display_kind(m, e);
    int k = 0;
    while (k < nk && strcmp(kinds[k], dk) != 0) k++;
    if (k == nk) { kinds[nk] = dk; counts[nk++] = 0; }
    counts[k]++;
  }
  bg_sb_printf(out, "%s: %d element%s", m->name, nelem, plural(nelem));
  for (int k = 0; k < nk; k++) bg_sb_printf(out, "%s%s %d", k ? ", " : " (", kinds[k], counts[k]);
  bg_sb_printf(out, "%s, %d junction%s, %d bond%s; %d store%s, %d source%s", nk ? ")" : "", njunc,
               plural(njunc), m->nbond, plural(m->nbond), nstore, plural(nstore), nsrc,
               plural(nsrc));
}

/* ---------------------------------------------------------------- kind names */
static const char *const kind_names[BG_ELEM_COUNT] = {
    [BG_ELEM_SE] = "Se", [BG_ELEM_SF] = "Sf", [BG_ELEM_MSE] = "MSe", [BG_ELEM_MSF] = "MSf",
    [BG_ELEM_C] = "C",   [BG_ELEM_I] = "I",   [BG_ELEM_R] = "R",     [BG_ELEM_TF] = "TF",
    [BG_ELEM_MTF] = "MTF", [BG_ELEM_GY] = "GY", [BG_ELEM_MGY] = "MGY",
    [BG_ELEM_J0] = "0",  [BG_ELEM_J1] = "1"};

const char *bg_elem_kind_name(int kind) {
  return kind >= 0 && kind < BG_ELEM_COUNT ? kind_names[kind] : "?";
}

const char *bg_elem_kind_article(int kind) {
  static const char *const texts[BG_ELEM_COUNT] = {
      [BG_ELEM_SE] = "an Se", [BG_ELEM_SF] = "an Sf", [BG_ELEM_MSE] = "an MSe",
      [BG_ELEM_MSF] = "an MSf", [BG_ELEM_C] = "a C", [BG_ELEM_I] = "an I", [BG_ELEM_R] = "an R",
      [BG_ELEM_TF] = "a TF", [BG_ELEM_MTF] = "an MTF", [BG_ELEM_GY] = "a GY",
      [BG_ELEM_MGY] = "an MGY", [BG_ELEM_J0] = "a 0-junction", [BG_ELEM_J1] = "a 1-junction"};
  return kind >= 0 && kind < BG_ELEM_COUNT ? texts[kind] : "?";
}
