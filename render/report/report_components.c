/* SPDX-License-Identifier: BSD-3-Clause */
/* Report section for a model built from submodels (language version 2): the
 * instances with their blocks of flat bond numbers, and for every flat bond
 * the bonds as written it came from ("bond 2 of the model + bond 1 of M1").
 * A version 1 model has no such section. */
#include <stdio.h>

#include "report/report_int.h"

#define MAX_ROWS 400 /* per table; the JSON (origin, instances) lists everything */

static void small_note(rp_ctx *c, int shown, int total, const char *what) {
  if (shown >= total) return;
  bg_strbuf b = {0};
  bg_sb_printf(&b, "The first %d of %d %s are listed; the JSON output (<tt>-o model.json</tt>: "
                   "<tt>instances</tt>, <tt>origin</tt>) has them all.", shown, total, what);
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_SMALL, 0, 0, rp_grey);
  rp_gap(&c->body, 3);
  bg_sb_free(&b);
}

static void instances_table(rp_ctx *c) {
  const bg_model *m = c->m;
  static const char *head[] = {"Instance", "Submodel", "Inside", "Flat bond numbers"};
  rp_table t;
  rp_table_init(&t, 4, head, "lllr");
  int n = m->ninst < MAX_ROWS ? m->ninst : MAX_ROWS;
  for (int i = 0; i < n; i++) {
    rp_table_text(&t, m->inst_name[i]);
    rp_table_text(&t, m->inst_def[i]);
    rp_table_text(&t, m->inst_parent[i] >= 0 ? m->inst_name[m->inst_parent[i]] : "the model");
    if (m->inst_bondspan[i] > 0)
      rp_table_cell(&t, "%d\u2013%d", m->inst_bondoff[i] + 1, m->inst_bondoff[i] + m->inst_bondspan[i]);
    else rp_table_cell(&t, "\u2013");
  }
  rp_table_emit(&c->body, &t);
  small_note(c, n, m->ninst, "instances");
}

/* "bond 2 of the model + bond 1 of M1" */
static void origin_text(const bg_model *m, int b, bg_strbuf *out) {
  for (int k = 0; k < m->bond_nseg[b]; k++) {
    int s = m->bond_segadr[b] + k;
    bg_sb_printf(out, "%sbond %d of %s", k ? " + " : "", m->seg_num[s],
                 m->seg_inst[s] >= 0 ? m->inst_name[m->seg_inst[s]] : "the model");
  }
}

static void bonds_table(rp_ctx *c) {
  const bg_model *m = c->m;
  static const char *head[] = {"Bond", "From", "To", "Written as"};
  rp_table t;
  rp_table_init(&t, 4, head, "rlll");
  int n = m->nbond < MAX_ROWS ? m->nbond : MAX_ROWS;
  for (int b = 0; b < n; b++) {
    rp_table_cell(&t, "%d", m->bond_num[b]);
    rp_table_text(&t, m->elem_name[m->bond_tail[b]]);
    rp_table_text(&t, m->elem_name[m->bond_head[b]]);
    bg_strbuf o = {0};
    origin_text(m, b, &o);
    rp_table_text(&t, bg_sb_str(&o));
    bg_sb_free(&o);
  }
  rp_table_emit(&c->body, &t);
  small_note(c, n, m->nbond, "bonds");
}

void rp_sec_components(rp_ctx *c) {
  if (!c->m->ninst) return;
  rp_section(&c->body, "Submodel instances", 1, 0, 80);
  rp_para(&c->body, "The model is flattened from submodel instances; names inside an instance "
          "are qualified by its path (<tt>M1.Ra</tt>). Bond <i>k</i> inside an instance is flat "
          "bond <i>offset + k</i>, in the instance's block of numbers; a bond joined through a "
          "port takes the number of its outermost part.", RP_SIZE_BODY, 0, 0, rp_ink);
  rp_gap(&c->body, 3);
  instances_table(c);
  rp_subsection(&c->body, "Bonds and where they are written", 40);
  bonds_table(c);
}
