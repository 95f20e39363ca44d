/* SPDX-License-Identifier: BSD-3-Clause */
/* Tooltips of the SVG diagram (<title>): for a bond its number, power
 * direction, effort and flow and which end computes each (from the causal
 * stroke), for an element its kind, constitutive law and causality. Found
 * from an item's role ("bond 3", "stroke bond=3", "number bond=3", "node R1")
 * through the model's hashed lookups: one tip per item, so a scan of the
 * bonds or names per tip made the SVG of 16 000 bonds quadratic. */
#include <stdlib.h>
#include <string.h>

#include "causality/causality.h"
#include "diagram/diagram_int.h"
#include "model/model.h"

/* "e = R0 * f": the law as the element computes it, from its value or law. */
static void law(const bg_model *m, int e, bg_strbuf *out) {
  int kind = m->elem_kind[e], form = m->elem_form[e], root = m->elem_expr[e];
  if (root < 0) return;
  const char *name = bg_elem_kind_name(kind);
  bg_strbuf x = {0};
  bg_xprint(m, root, &x);
  const char *v = bg_sb_str(&x);
  if (form == BG_FORM_LAW_E) bg_sb_printf(out, "e = %s", v);
  else if (form == BG_FORM_LAW_F) bg_sb_printf(out, "f = %s", v);
  else if (!strcmp(name, "C")) bg_sb_printf(out, "e = q / (%s)", v);
  else if (!strcmp(name, "I")) bg_sb_printf(out, "f = p / (%s)", v);
  else if (!strcmp(name, "R")) bg_sb_printf(out, "e = (%s) * f", v);
  else if (!strcmp(name, "Se") || !strcmp(name, "MSe")) bg_sb_printf(out, "e = %s", v);
  else if (!strcmp(name, "Sf") || !strcmp(name, "MSf")) bg_sb_printf(out, "f = %s", v);
  else if (strstr(name, "TF")) bg_sb_printf(out, "modulus n = %s", v);
  else if (strstr(name, "GY")) bg_sb_printf(out, "ratio r = %s", v);
  bg_sb_free(&x);
}

static void elem_tip(const bg_diagram *d, int e, bg_strbuf *out) {
  const bg_model *m = d->m;
  bg_sb_printf(out, "%s %s", bg_elem_display_kind(m, e), m->elem_name[e]);
  bg_strbuf l = {0};
  law(m, e, &l);
  if (l.len) bg_sb_printf(out, ": %s", bg_sb_str(&l));
  bg_sb_free(&l);
  if (d->a && d->a->elem_caus) bg_sb_printf(out, " (%s causality)", bg_caus_name(d->a->elem_caus[e]));
}

/* With the stroke at end X, the other end imposes the effort on X and X
 * answers with the flow. */
static void bond_tip(const bg_diagram *d, int k, bg_strbuf *out) {
  const bg_model *m = d->m;
  int num = m->bond_num[k], tail = m->bond_tail[k], head = m->bond_head[k];
  bg_sb_printf(out, "bond %d: %s \u2192 %s, effort e%d, flow f%d", num, m->elem_name[tail],
               m->elem_name[head], num, num);
  int st = d->a && d->a->bond_stroke ? d->a->bond_stroke[k] : BG_STROKE_NONE;
  if (st == BG_STROKE_NONE) return;
  int at = st == BG_STROKE_HEAD ? head : tail, other = st == BG_STROKE_HEAD ? tail : head;
  bg_sb_printf(out, "; stroke at %s: e%d computed by %s, f%d by %s", m->elem_name[at], num,
               m->elem_name[other], num, m->elem_name[at]);
  int ends[2] = {other, at};
  for (int i = 0; i < 2; i++) {
    if (!bg_elem_is_oneport(m->elem_kind[ends[i]])) continue;
    bg_strbuf l = {0};
    law(m, ends[i], &l);
    if (l.len) bg_sb_printf(out, "; %s: %s", m->elem_name[ends[i]], bg_sb_str(&l));
    bg_sb_free(&l);
  }
}

void bg_diagram_tip(void *ctx, const char *role, bg_strbuf *out) {
  const bg_diagram *d = ctx;
  const char *num = !strncmp(role, "bond ", 5) ? role + 5 : strstr(role, "bond=");
  if (num && num != role + 5) num += 5; /* "stroke bond=3", "number bond=3" */
  if (!strncmp(role, "node ", 5)) {
    int e = bg_model_find_elem(d->m, role + 5);
    if (e >= 0) elem_tip(d, e, out);
  } else if (num) {
    int k = bg_model_find_bond(d->m, atoi(num));
    if (k >= 0) bond_tip(d, k, out);
  }
}
