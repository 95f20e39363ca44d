/* SPDX-License-Identifier: BSD-3-Clause */
/* Report section for a model with multiport fields (docs/format.md,
 * "Multiport fields"): per field its ports, the element and bond of each,
 * the port's causality (mixed causality said) and its law as compiled. A
 * model without fields has no such section. */
#include <stdio.h>

#include "causality/causality.h"
#include "sym/sym.h"
#include "report/report_int.h"

static void field_table(rp_ctx *c, int f) {
  const bg_model *m = c->m;
  static const char *head[] = {"Port", "Element", "Bond", "Causality", "Law"};
  rp_table t;
  rp_table_init(&t, 5, head, "llrll");
  for (int k = 0; k < m->field_nport[f]; k++) {
    int e = m->field_elemadr[f] + k, b = bg_elem_port_bond(m, e);
    rp_table_text(&t, bg_elem_port_name(m, e));
    rp_table_text(&t, m->elem_name[e]);
    rp_table_cell(&t, "%d", b >= 0 ? m->bond_num[b] : 0);
    rp_table_text(&t, bg_caus_name(c->a->elem_caus[e]));
    bg_strbuf law = {0};
    bg_sb_puts(&law, m->elem_form[e] == BG_FORM_LAW_F ? "f = " : "e = ");
    bg_sym_print_model_expr(m, m->elem_expr[e], &law);
    rp_table_text(&t, bg_sb_str(&law));
    bg_sb_free(&law);
  }
  rp_table_emit(&c->body, &t);
}

void rp_sec_fields(rp_ctx *c) {
  const bg_model *m = c->m;
  if (!m->nfield) return;
  rp_section(&c->body, "Multiport fields", 1, 0, 80);
  rp_para(&c->body, "Each port of a field is an element of its own (<tt>K.el</tt>) with its "
          "port's law for the port's own variables (power into the field positive); causality "
          "is assigned per port.", RP_SIZE_BODY, 0, 0, rp_ink);
  rp_gap(&c->body, 3);
  for (int f = 0; f < m->nfield; f++) {
    int p1 = m->field_elemadr[f], mixed = 0;
    for (int k = 1; k < m->field_nport[f]; k++) mixed |= c->a->elem_caus[p1 + k] != c->a->elem_caus[p1];
    bg_strbuf h = {0};
    bg_sb_printf(&h, "%s field %s: %d ports%s", bg_elem_kind_name(m->field_kind[f]),
                 m->field_name[f], m->field_nport[f], mixed ? ", mixed causality" : "");
    rp_subsection(&c->body, bg_sb_str(&h), 40);
    bg_sb_free(&h);
    if (m->field_energy[f] >= 0) {
      bg_strbuf w = {0}, p = {0};
      bg_sym_print_model_expr(m, m->field_energy[f], &w);
      bg_sb_puts(&p, "Energy <tt>");
      bg_markup_escapen(&p, bg_sb_str(&w), w.len);
      bg_sb_puts(&p, "</tt>: each port's effort is the energy's derivative by the port's q (its gradient).");
      rp_para(&c->body, bg_sb_str(&p), RP_SIZE_BODY, 0, 0, rp_ink);
      rp_gap(&c->body, 3);
      bg_sb_free(&w), bg_sb_free(&p);
    }
    field_table(c, f);
  }
}
