/* SPDX-License-Identifier: BSD-3-Clause */
/* relax-junction (chapter Section 4.9, Figure 4.26): a source whose fixed
 * causality reaches a resistor directly (or through two-ports) forces it
 * against its law, which then has to be solved implicitly. An extra
 * junction in the resistor's bond lets the method of relaxed causalities
 * give the resistor the causality of its law; the violation moves to the
 * junction, a type 1 conflict whose balance determines the variable. */
#include <string.h>

#include "transform/tx_int.h"

/* The source that reaches R through two-ports only; -1 for none. */
static int forcing_source(const bg_model *m, int r) {
  int e = r, b = bg_elem_port_bond(m, r);
  for (int steps = 0; steps <= m->nelem; steps++) {
    int x = bg_bond_other(m, b, e);
    if (bg_elem_is_source(m->elem_kind[x])) return x;
    if (!bg_elem_is_twoport(m->elem_kind[x])) return -1;
    int in = bg_elem_in_bond(m, x), out = bg_elem_out_bond(m, x);
    b = b == in ? out : in;
    e = x;
  }
  return -1;
}

/* causality relaxed: the statement rewritten, else one after `model`. */
static void ask_relaxed(tx_ctx *c) {
  const bg_ast *ast = c->in->ast;
  int after = 0;
  for (int i = 0; i < ast->nstmts; i++) {
    if (ast->stmts[i].kind == BG_ST_CAUSALITY) {
      tx_replace_stmt(&c->doc, ast->stmts[i].loc.line, "causality relaxed");
      return;
    }
    if (ast->stmts[i].kind == BG_ST_MODEL) after = ast->stmts[i].loc.line;
  }
  tx_insert_after(&c->doc, after, "causality relaxed");
}

static void say_relax(tx_ctx *c, int r, int src, const char *j, int law_f) {
  const bg_model *m = c->m;
  if (c->why.len) bg_sb_putc(&c->why, ' ');
  bg_sb_printf(&c->why, "The source %s forces the resistor %s against its law (written %s, "
               "it wants the %s as input), so the law had to be solved for the %s implicitly. "
               "A %d-junction %s inserted in bond %d lets the method of relaxed causalities "
               "give %s the causality of its law; the causal violation moves to %s, a type 1 "
               "conflict whose balance determines the %s, an algebraic state variable "
               "(chapter Section 4.9, Figure 4.26).", m->elem_name[src], m->elem_name[r],
               law_f ? "f = G(e)" : "e = F(f)", law_f ? "effort" : "flow",
               law_f ? "effort" : "flow", law_f ? 0 : 1, j,
               m->bond_num[bg_elem_port_bond(m, r)], m->elem_name[r], j,
               law_f ? "effort" : "flow");
}

int tx_relax_junction(tx_ctx *c) {
  const bg_model *m = c->m;
  int n = 0;
  for (int r = 0; r < m->nelem; r++) {
    if (m->elem_kind[r] != BG_ELEM_R || !c->a->elem_inverted[r]) continue;
    int form = m->elem_form[r];
    int src = forcing_source(m, r);
    if ((form != BG_FORM_LAW_E && form != BG_FORM_LAW_F) || src < 0) continue;
    char base[64], j[64];
    snprintf(base, sizeof base, "j%s", m->elem_name[r]);
    tx_fresh_name(c, base, j, sizeof j);
    int law_f = form == BG_FORM_LAW_F;
    bg_strbuf t = {0};
    bg_sb_printf(&t, "%-3s %s", law_f ? "0" : "1", j);
    tx_insert_after(&c->doc, tx_elem_line(c, r), bg_sb_str(&t));
    bg_sb_free(&t);
    tx_split_bond(c, &c->doc, bg_elem_port_bond(m, r), j, c->next_bond++);
    say_relax(c, r, src, j, law_f);
    n++;
  }
  if (!n) {
    bg_sb_puts(&c->problem, "no source forces a resistor against its law (no resistor with a "
                            "law whose causality was inverted, reached from a source directly "
                            "or through transformers and gyrators)");
    return -1;
  }
  if (m->method != BG_METHOD_RELAXED) {
    ask_relaxed(c);
    bg_sb_puts(&c->why, " The model asks for causality relaxed.");
  }
  return 0;
}
