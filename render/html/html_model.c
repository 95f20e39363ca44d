/* SPDX-License-Identifier: BSD-3-Clause */
/* HTML report sections of the model's structure, as the PDF has them for
 * the models that need them (report_components.c, report_fields.c): the
 * submodel instances with each flat bond's origin, and the multiport fields
 * with their ports' causality and laws. Other models have neither. */
#include <stdio.h>

#include "causality/causality.h"
#include "html/html_int.h"
#include "sym/sym.h"

static void cell(ht_ctx *c, const char *text) {
  bg_sb_puts(c->out, "<td>");
  ht_esc(c->out, text);
  bg_sb_puts(c->out, "</td>");
}

void ht_components(ht_ctx *c) {
  const bg_model *m = c->m;
  if (!m->ninst) return;
  ht_section(c, "instances", "Submodel instances");
  bg_sb_puts(c->out, "<p>The model is flattened from submodel instances; names inside an instance are "
                     "qualified by its path (<code>M1.Ra</code>). Bond <i>k</i> inside an instance is flat "
                     "bond <i>offset + k</i>, in the instance's block of numbers; a bond joined through a "
                     "port takes the number of its outermost part.</p>\n");
  static const char *const ihead[] = {"Instance", "Submodel", "Inside", "Flat bond numbers"};
  ht_table(c, NULL, "Submodel instances", 4, ihead);
  int n = m->ninst < HT_MAX_ROWS ? m->ninst : HT_MAX_ROWS;
  for (int i = 0; i < n; i++) {
    bg_sb_puts(c->out, "<tr>");
    cell(c, m->inst_name[i]);
    cell(c, m->inst_def[i]);
    cell(c, m->inst_parent[i] >= 0 ? m->inst_name[m->inst_parent[i]] : "the model");
    if (m->inst_bondspan[i] > 0)
      bg_sb_printf(c->out, "<td class=\"n\">%d\u2013%d</td>", m->inst_bondoff[i] + 1,
                   m->inst_bondoff[i] + m->inst_bondspan[i]);
    else bg_sb_puts(c->out, "<td class=\"n\">\u2013</td>");
    bg_sb_puts(c->out, "</tr>\n");
  }
  ht_table_end(c);
  ht_more_rows(c, n, m->ninst, 0, "instances");
  ht_sub(c, "bond-origins", "Bonds and where they are written");
  static const char *const bhead[] = {"Bond", "From", "To", "Written as"};
  ht_table(c, "items", "Bonds and where they are written", 4, bhead);
  n = m->nbond < HT_MAX_ROWS ? m->nbond : HT_MAX_ROWS;
  for (int b = 0; b < n; b++) { /* a row lights its bond */
    bg_sb_printf(c->out, "<tr id=\"bond-%d\" tabindex=\"0\" data-bonds=\"%d\"><th scope=\"row\">%d</th>",
                 m->bond_num[b], m->bond_num[b], m->bond_num[b]);
    cell(c, m->elem_name[m->bond_tail[b]]);
    cell(c, m->elem_name[m->bond_head[b]]);
    bg_strbuf o = {0};
    for (int k = 0; k < m->bond_nseg[b]; k++) {
      int s = m->bond_segadr[b] + k;
      bg_sb_printf(&o, "%sbond %d of %s", k ? " + " : "", m->seg_num[s],
                   m->seg_inst[s] >= 0 ? m->inst_name[m->seg_inst[s]] : "the model");
    }
    cell(c, bg_sb_str(&o));
    bg_sb_free(&o);
    bg_sb_puts(c->out, "</tr>\n");
  }
  ht_table_end(c);
  ht_more_rows(c, n, m->nbond, 0, "bonds");
  ht_section_end(c);
}

void ht_fields(ht_ctx *c) {
  const bg_model *m = c->m;
  if (!m->nfield) return;
  ht_section(c, "fields", "Multiport fields");
  bg_sb_puts(c->out, "<p>Each port of a field is an element of its own (<code>K.el</code>) with its port's "
                     "law for the port's own variables (power into the field positive); causality is "
                     "assigned per port.</p>\n");
  for (int f = 0; f < m->nfield; f++) {
    int p1 = m->field_elemadr[f], mixed = 0;
    for (int k = 1; k < m->field_nport[f]; k++) mixed |= c->a->elem_caus[p1 + k] != c->a->elem_caus[p1];
    char id[32], title[256];
    snprintf(id, sizeof id, "field-%d", f + 1);
    snprintf(title, sizeof title, "%s field %s: %d ports%s", bg_elem_kind_name(m->field_kind[f]),
             m->field_name[f], m->field_nport[f], mixed ? ", mixed causality" : "");
    ht_sub(c, id, title);
    if (m->field_energy[f] >= 0) {
      bg_strbuf w = {0};
      bg_sym_print_model_expr(m, m->field_energy[f], &w);
      bg_sb_puts(c->out, "<p>Energy <code>");
      ht_esc(c->out, bg_sb_str(&w));
      bg_sb_puts(c->out, "</code>: each port's effort is the energy's derivative by the port's q (its "
                         "gradient).</p>\n");
      bg_sb_free(&w);
    }
    static const char *const head[] = {"Port", "Element", "Bond", "Causality", "Law"};
    ht_table(c, "items", title, 5, head);
    for (int k = 0; k < m->field_nport[f]; k++) {
      int e = p1 + k, b = bg_elem_port_bond(m, e), num = b >= 0 ? m->bond_num[b] : 0;
      bg_sb_printf(c->out, "<tr tabindex=\"0\" data-bonds=\"%d\"><th scope=\"row\">", num);
      ht_esc(c->out, bg_elem_port_name(m, e));
      bg_sb_puts(c->out, "</th>");
      cell(c, m->elem_name[e]);
      bg_sb_printf(c->out, "<td class=\"n\">%d</td>", num);
      cell(c, bg_caus_name(c->a->elem_caus[e]));
      bg_strbuf law = {0};
      bg_sb_puts(&law, m->elem_form[e] == BG_FORM_LAW_F ? "f = " : "e = ");
      bg_sym_print_model_expr(m, m->elem_expr[e], &law);
      bg_sb_puts(c->out, "<td><code class=\"expr\">");
      ht_esc(c->out, bg_sb_str(&law));
      bg_sb_puts(c->out, "</code></td></tr>\n");
      bg_sb_free(&law);
    }
    ht_table_end(c);
  }
  ht_section_end(c);
}
