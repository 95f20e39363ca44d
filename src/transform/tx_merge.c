/* SPDX-License-Identifier: BSD-3-Clause */
/* merge-stores (chapter Section 4.4 and Conclusion): an independent and a
 * dependent linear store of the same type, joined by a class 1 causal path
 * through junctions that share the stores' variable and constant
 * transformers, are one store. The dependent store's variable is the
 * independent one's times the path's modulus k, so its energy adds k^2
 * times its parameter to the independent store's: J = J1 + k^2 J2. */
#include <stdlib.h>
#include <string.h>

#include "transform/tx_int.h"

/* Text as a factor: names and numbers bare, anything else in parentheses. */
static void put_factor(bg_strbuf *b, const char *t) {
  int simple = 1;
  for (const char *s = t; *s; s++)
    if (!(s[0] == '.' || s[0] == '_' || (s[0] >= '0' && s[0] <= '9') ||
          (s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z')))
      simple = 0;
  bg_sb_printf(b, simple ? "%s" : "(%s)", t);
}

static const char *expr_text(const tx_ctx *c, int e) { return tx_elem_stmt(c, e)->expr->text; }

/* A linear store with a constant parameter written as a value. */
static int plain_store(const tx_ctx *c, int e) {
  const bg_model *m = c->m;
  return m->elem_form[e] == BG_FORM_VALUE && !m->elem_modulated[e] &&
         tx_expr_constant(m, m->elem_expr[e]) && expr_text(c, e);
}

/* The node path p passes between its bonds i and i+1. */
static int path_node(const bg_model *m, const bg_analysis *a, int p, int i) {
  int b1 = a->path_bonds[a->path_adr[p] + i], b2 = a->path_bonds[a->path_adr[p] + i + 1];
  int t = m->bond_tail[b1], h = m->bond_head[b1];
  return t == m->bond_tail[b2] || t == m->bond_head[b2] ? t : h;
}

/* The factor of the dependent store's parameter ("*(n)^2/(m)^2") along
 * path p walked from the independent store; 0 with c->problem when the
 * path is not one of junctions sharing the variable and constant TFs. */
static int path_factor(tx_ctx *c, int p, int from_end0, bg_strbuf *f, int *mtf, int *inverse) {
  const bg_model *m = c->m;
  const bg_analysis *a = c->a;
  int n = a->path_n[p], is_i = m->elem_kind[a->path_end0[p]] == BG_ELEM_I;
  for (int k = 0; k + 1 < n; k++) {
    int i = from_end0 ? k : n - 2 - k;
    int x = path_node(m, a, p, i);
    int kind = m->elem_kind[x];
    int bA = a->path_bonds[a->path_adr[p] + (from_end0 ? i : i + 1)];
    if (kind == (is_i ? BG_ELEM_J1 : BG_ELEM_J0)) continue;
    if (bg_elem_is_junction(kind)) {
      bg_sb_printf(&c->problem, "causal path %d passes the %s-junction %s, where the %s of the "
                   "dependent store is a sum and not a multiple of the independent one's", p + 1,
                   bg_elem_kind_name(kind), m->elem_name[x], is_i ? "flow" : "effort");
      return 0;
    }
    int a_side1 = bA == bg_elem_in_bond(m, x);
    if (kind == BG_ELEM_MTF && is_i && *mtf < 0 && tx_modulus_of_coordinates(m, m->elem_expr[x])) {
      *mtf = x; /* the virtual inertia of Figure 4.30 */
      *inverse = a_side1;
      continue;
    }
    if (kind != BG_ELEM_TF || !tx_expr_constant(m, m->elem_expr[x])) {
      bg_sb_printf(&c->problem, "causal path %d passes %s %s, which is not a transformer with a "
                   "constant modulus%s", p + 1, bg_elem_kind_name(kind), m->elem_name[x],
                   kind == BG_ELEM_MTF ? " or a modulated one depending on generalised "
                   "coordinates (user states) only, the only one on a path between inertias" : "");
      return 0;
    }
    /* e2 = n e1, f1 = n f2: an I beyond side 2 moves with f/n, a C beyond side 2 with n e */
    bg_sb_puts(f, a_side1 == is_i ? "/" : "*");
    put_factor(f, expr_text(c, x));
    bg_sb_puts(f, "^2");
  }
  if (*mtf >= 0 && f->len) {
    bg_sb_printf(&c->problem, "causal path %d passes the modulated transformer %s and constant "
                 "ones: a virtual inertia through both is not done", p + 1, m->elem_name[*mtf]);
    return 0;
  }
  return 1;
}

/* The first place an expression reads store d or its bond; -1 for none. */
static int reference_to(const bg_model *m, int d) {
  int b = bg_elem_port_bond(m, d);
  for (int x = 0; x < m->nxnode; x++) {
    const bg_xnode *n = &m->xnode[x];
    if ((n->op == BG_X_STORE && n->ref == d) ||
        ((n->op == BG_X_EFFORT || n->op == BG_X_FLOW) && n->ref == b))
      return x;
  }
  return -1;
}

/* Path p can be merged: checks in the chapter's terms, reasons in c->problem. */
static int mergeable(tx_ctx *c, int p, int *keep, int *drop, bg_strbuf *f, int *mtf,
                     int *inverse) {
  const bg_model *m = c->m;
  const bg_analysis *a = c->a;
  int e0 = a->path_end0[p], e1 = a->path_end1[p];
  int end0_indep = a->elem_caus[e0] == BG_CAUS_INTEGRAL;
  *keep = end0_indep ? e0 : e1;
  *drop = end0_indep ? e1 : e0;
  if (m->elem_kind[e0] != m->elem_kind[e1]) {
    bg_sb_printf(&c->problem, "causal path %d joins a C and an I through gyrators", p + 1);
    return 0;
  }
  for (int k = 0; k < 2; k++) {
    int e = k ? *drop : *keep;
    if (!plain_store(c, e)) {
      bg_sb_printf(&c->problem, "%s is not a linear store with a constant parameter written "
                   "as a value", m->elem_name[e]);
      return 0;
    }
  }
  int nclass1 = 0;
  for (int q = 0; q < a->npath; q++)
    nclass1 += a->path_class[q] == 1 && (a->path_end0[q] == *drop || a->path_end1[q] == *drop);
  if (nclass1 != 1) {
    bg_sb_printf(&c->problem, "the dependent store %s ends %d class 1 causal paths: its "
                 "variable is not a multiple of one store's", m->elem_name[*drop], nclass1);
    return 0;
  }
  if (!path_factor(c, p, end0_indep, f, mtf, inverse)) return 0;
  int j = bg_bond_other(m, bg_elem_port_bond(m, *drop), *drop);
  if (m->elem_nbond[j] < 3) {
    bg_sb_printf(&c->problem, "removing %s would leave %s with one bond", m->elem_name[*drop],
                 m->elem_name[j]);
    return 0;
  }
  int x = reference_to(m, *drop);
  if (x >= 0) {
    bg_sb_printf(&c->problem, "line %d reads a variable of %s, which the merge removes",
                 m->xnode[x].loc.line, m->elem_name[*drop]);
    return 0;
  }
  /* the kept store's state becomes both stores' (p1 + p2): a reader of it
   * would change the dynamics (its flow or effort keeps its value) */
  for (x = 0; x < m->nxnode; x++)
    if (m->xnode[x].op == BG_X_STORE && m->xnode[x].ref == *keep) {
      bg_sb_printf(&c->problem, "line %d reads the state of %s, which the merge makes the sum of "
                   "both stores' states", m->xnode[x].loc.line, m->elem_name[*keep]);
      return 0;
    }
  return 1;
}

static const char *option_text(const bg_ast_stmt *s, const char *key) {
  for (int i = 0; i < s->nopts; i++)
    if (!strcmp(s->opts[i].key, key)) return s->opts[i].value->text;
  return NULL;
}

/* The independent store's statement with its merged parameter; its initial
 * state scaled so that its flow (I) or effort (C) starts where it did. */
static void rewrite_keep(tx_ctx *c, int e, const char *value) {
  const bg_ast_stmt *s = tx_elem_stmt(c, e);
  const char *key = c->m->elem_kind[e] == BG_ELEM_I ? "p0" : "q0";
  const char *init = option_text(s, key);
  bg_strbuf t = {0}, v = {0};
  if (init) {
    put_factor(&v, init);
    bg_sb_printf(&v, "*(%s)/", value);
    put_factor(&v, expr_text(c, e));
  }
  tx_print_element(&t, s, value, init ? key : NULL, bg_sb_str(&v));
  tx_replace_stmt(&c->doc, s->loc.line, bg_sb_str(&t));
  bg_sb_free(&t);
  bg_sb_free(&v);
}

static void say_merge(tx_ctx *c, int p, int keep, int drop, const char *value) {
  const bg_model *m = c->m;
  const bg_analysis *a = c->a;
  int is_i = m->elem_kind[keep] == BG_ELEM_I;
  bg_strbuf *w = &c->why;
  if (w->len) bg_sb_putc(w, ' ');
  bg_sb_printf(w, "%s %s, in derivative causality, is tied to %s by class 1 causal path %d "
               "(bonds", bg_elem_kind_name(m->elem_kind[drop]), m->elem_name[drop],
               m->elem_name[keep], p + 1);
  for (int i = 0; i < a->path_n[p]; i++)
    bg_sb_printf(w, "%s %d", i ? "," : "", m->bond_num[a->path_bonds[a->path_adr[p] + i]]);
  bg_sb_printf(w, ") through junctions and constant transformers only: its %s is a fixed "
               "multiple of %s's, so both are one store whose parameter takes the other's "
               "times the square of the modulus (chapter Section 4.4): %s = %s. %s and its "
               "bond %d are removed; %s keeps integral causality.", is_i ? "flow" : "effort",
               m->elem_name[keep], m->elem_name[keep], value, m->elem_name[drop],
               m->bond_num[bg_elem_port_bond(m, drop)], m->elem_name[keep]);
}

int tx_merge_stores(tx_ctx *c) {
  const bg_model *m = c->m;
  const bg_analysis *a = c->a;
  bg_strbuf *value = calloc((size_t)m->nelem, sizeof *value);
  int nmerged = 0, nclass1 = 0;
  for (int p = 0; p < a->npath; p++) {
    if (a->path_class[p] != 1) continue;
    nclass1++;
    size_t mark = c->problem.len;
    if (mark) bg_sb_puts(&c->problem, "; ");
    bg_strbuf f = {0};
    int keep, drop, mtf = -1, inverse = 0;
    int ok = mergeable(c, p, &keep, &drop, &f, &mtf, &inverse);
    if (ok && mtf >= 0 && value[keep].len) {
      bg_sb_printf(&c->problem, "%s takes a constant merge already", c->m->elem_name[keep]);
      ok = 0;
    } else if (ok && mtf >= 0) {
      ok = tx_virtual_inertia(c, p, keep, drop, mtf, inverse) == 0;
    } else if (ok) {
      if (!value[keep].len) put_factor(&value[keep], expr_text(c, keep));
      bg_sb_puts(&value[keep], " + ");
      put_factor(&value[keep], expr_text(c, drop));
      bg_sb_puts(&value[keep], bg_sb_str(&f));
      say_merge(c, p, keep, drop, bg_sb_str(&value[keep]));
      tx_delete_stmt(&c->doc, tx_elem_line(c, drop));
      tx_remove_bond(c, bg_elem_port_bond(m, drop));
    }
    /* no reason to give for this path, or the same one as for an earlier path */
    const char *why = c->problem.s ? c->problem.s + mark + (mark ? 2 : 0) : NULL;
    char *seen = why && mark ? strndup(c->problem.s, mark) : NULL;
    int repeated = !ok && seen && strstr(seen, why);
    free(seen);
    if (ok || repeated) {
      c->problem.len = mark;
      if (c->problem.s) c->problem.s[mark] = '\0';
      nmerged += ok;
    }
    bg_sb_free(&f);
  }
  for (int e = 0; e < m->nelem; e++) {
    if (value[e].len) rewrite_keep(c, e, bg_sb_str(&value[e]));
    bg_sb_free(&value[e]);
  }
  free(value);
  if (!nclass1)
    bg_sb_puts(&c->problem, "it has no class 1 causal path (no store in derivative causality "
                            "tied to an independent one)");
  return nmerged ? 0 : -1;
}
