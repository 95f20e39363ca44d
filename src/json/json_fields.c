/* SPDX-License-Identifier: BSD-3-Clause */
/* The `fields` list of the analysis JSON (docs/json.md): each multiport C or
 * R field with its ports, their elements, bonds and causalities, and whether
 * the causality is mixed. Written only for a model that has fields. */
#include "json/json.h"

#include "causality/causality.h"
#include "sym/sym.h"

/* 1 when the ports of field f do not all have one causality. */
int bg_json_field_mixed(const bg_model *m, const bg_analysis *a, int f) {
  int p1 = m->field_elemadr[f];
  for (int k = 1; k < m->field_nport[f]; k++)
    if (a->elem_caus[p1 + k] != a->elem_caus[p1]) return 1;
  return 0;
}

static void put_port(bg_strbuf *o, const bg_model *m, const bg_analysis *a, int e) {
  int b = bg_elem_port_bond(m, e);
  bg_sb_puts(o, "{\"name\": ");
  bg_sb_json_str(o, bg_elem_port_name(m, e));
  bg_sb_printf(o, ", \"number\": %d, \"element\": ", m->elem_fport[e]);
  bg_sb_json_str(o, m->elem_name[e]);
  bg_sb_printf(o, ", \"bond\": %d, \"causality\": ", b >= 0 ? m->bond_num[b] : 0);
  bg_sb_json_str(o, bg_caus_name(a->elem_caus[e]));
  bg_sb_puts(o, ", \"law\": ");
  bg_strbuf law = {0};
  bg_sym_print_model_expr(m, m->elem_expr[e], &law);
  bg_sb_json_str(o, law.s ? law.s : "");
  bg_sb_free(&law);
  bg_sb_puts(o, ", \"law_form\": ");
  bg_sb_json_str(o, m->elem_form[e] == BG_FORM_LAW_F ? "f" : "e");
  bg_sb_putc(o, '}');
}

void bg_json_put_fields(bg_strbuf *o, const bg_model *m, const bg_analysis *a) {
  if (!m->nfield) return;
  bg_sb_puts(o, "  \"fields\": [");
  for (int f = 0; f < m->nfield; f++) {
    bg_sb_puts(o, f ? ",\n    " : "\n    ");
    bg_sb_puts(o, "{\"name\": ");
    bg_sb_json_str(o, m->field_name[f]);
    bg_sb_puts(o, ", \"kind\": ");
    bg_sb_json_str(o, bg_elem_kind_name(m->field_kind[f]));
    bg_sb_puts(o, ", \"energy\": ");
    if (m->field_energy[f] < 0) bg_sb_puts(o, "null");
    else {
      bg_strbuf w = {0};
      bg_sym_print_model_expr(m, m->field_energy[f], &w);
      bg_sb_json_str(o, w.s ? w.s : "");
      bg_sb_free(&w);
    }
    bg_sb_printf(o, ", \"mixed_causality\": %s, \"ports\": [",
                 bg_json_field_mixed(m, a, f) ? "true" : "false");
    for (int k = 0; k < m->field_nport[f]; k++) {
      bg_sb_puts(o, k ? ",\n      " : "\n      ");
      put_port(o, m, a, m->field_elemadr[f] + k);
    }
    bg_sb_puts(o, "\n    ]}");
  }
  bg_sb_puts(o, "\n  ],\n");
}
