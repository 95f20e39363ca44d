/* SPDX-License-Identifier: BSD-3-Clause */
/* SCAP (Karnopp–Rosenberg) and relaxed causality (Joseph–Martens) on the
 * engine of causality.c. Ties never follow the order of the statements:
 * fixed strokes by bond number, then sources, stores and resistors by name
 * (natural order: R2 before R10), then internal bonds by number
 * (E->bond_order, E->elem_order; docs/causality.md, "Ties"). */
#include <stdlib.h>

#include "causality/causality_int.h"
#include "base/strbuf.h"

static const char *end_name(const bg_ceng *E, int b) {
  const bg_model *m = E->m;
  return m->elem_name[E->stroke[b] == BG_STROKE_HEAD ? m->bond_head[b] : m->bond_tail[b]];
}

/* Appends the propagation list to sb, records the step, frees nothing. */
static void finish_step(bg_ceng *E, int mark, bg_strbuf *sb) {
  bg_ceng_prop_list(E, mark, sb);
  bg_ceng_trace(E, bg_sb_str(sb));
  bg_sb_free(sb);
}

static void begin_step(bg_ceng *E) { E->step = E->ntrace + 1; }

/* Propagation must not take bonds that a later step assigns explicitly:
 * sources and fixed strokes (so that two effort sources on one 0-junction
 * show as a conflict at the junction), and, in relaxed mode, nonlinear R. */
void bg_ceng_block(bg_ceng *E, int relaxed) {
  const bg_model *m = E->m;
  for (int b = 0; b < m->nbond; b++)
    if (m->bond_fix[b] != BG_FIX_NONE) E->blocked[b] = 1;
  for (int e = 0; e < m->nelem; e++) {
    int k = m->elem_kind[e], b = bg_ceng_port(E, e);
    if (b < 0) continue;
    if (bg_elem_is_source(k) || (relaxed && bg_ceng_r_nonlinear(m, e))) E->blocked[b] = 1;
  }
  for (int b = 0; b < m->nbond; b++)
    if (E->blocked[b]) {
      E->nblk[m->bond_tail[b]]++;
      E->nblk[m->bond_head[b]]++;
    }
}

/* Step 1a: strokes written in the model, by bond number. */
void bg_ceng_fixed(bg_ceng *E) {
  const bg_model *m = E->m;
  for (int i = 0; i < m->nbond; i++) {
    int b = E->bond_order[i];
    if (m->bond_fix[b] == BG_FIX_NONE || !bg_ceng_open(E, b)) continue;
    bg_strbuf sb = {0};
    int mark = E->nlog;
    begin_step(E);
    bg_ceng_set(E, b, m->bond_fix[b] == BG_FIX_HEAD ? BG_STROKE_HEAD : BG_STROKE_TAIL,
                BG_REASON_USER);
    bg_ceng_propagate(E);
    bg_sb_printf(&sb, "bond %d has its stroke fixed by the model at %s", m->bond_num[b],
                 end_name(E, b));
    finish_step(E, mark + 1, &sb);
  }
}

/* Step 1b: every source, by name. */
void bg_ceng_sources(bg_ceng *E) {
  const bg_model *m = E->m;
  for (int i = 0; i < m->nelem; i++) {
    int e = E->elem_order[i], b = bg_ceng_port(E, e);
    if (!bg_elem_is_source(m->elem_kind[e]) || b < 0) continue;
    bg_strbuf sb = {0};
    if (!bg_ceng_open(E, b)) {
      bg_sb_printf(&sb, "%s %s: bond %d already has its stroke at %s%s",
                   bg_elem_kind_name(m->elem_kind[e]), m->elem_name[e], m->bond_num[b],
                   end_name(E, b), bg_ceng_badness(E, e) ? " (conflict with the source)" : "");
      bg_ceng_trace(E, bg_sb_str(&sb));
      bg_sb_free(&sb);
      continue;
    }
    int mark = E->nlog;
    begin_step(E);
    bg_ceng_set(E, b, bg_ceng_oneport_stroke(E, e, BG_CAUS_FIXED), BG_REASON_SOURCE);
    bg_ceng_propagate(E);
    bg_sb_printf(&sb, "%s %s fixes bond %d (stroke at %s)", bg_elem_kind_name(m->elem_kind[e]),
                 m->elem_name[e], m->bond_num[b], end_name(E, b));
    finish_step(E, mark + 1, &sb);
  }
}

/* A store already causal when its turn comes: say so when it is dependent
 * or when propagation went against its option. */
static void store_note(bg_ceng *E, int e) {
  const bg_model *m = E->m;
  int caus = bg_ceng_oneport_caus(E, e);
  bg_strbuf sb = {0};
  if (bg_ceng_badness(E, e))
    bg_sb_printf(&sb, "%s forced to %s causality by propagation against its option (conflict)",
                 m->elem_name[e], bg_caus_name(caus));
  else if (caus == BG_CAUS_DERIVATIVE)
    bg_sb_printf(&sb, "%s forced to derivative causality by propagation (dependent store)",
                 m->elem_name[e]);
  if (sb.len) bg_ceng_trace(E, bg_sb_str(&sb));
  bg_sb_free(&sb);
}

/* Step 2: integral causality (or the option, or van Dijk's derivative) for
 * each store not yet causal, by name. */
static void stores(bg_ceng *E) {
  const bg_model *m = E->m;
  for (int i = 0; i < m->nelem; i++) {
    int e = E->elem_order[i], b = bg_ceng_port(E, e);
    if (!bg_elem_is_store(m->elem_kind[e]) || b < 0) continue;
    if (!bg_ceng_open(E, b)) {
      store_note(E, e);
      continue;
    }
    int caus = BG_CAUS_INTEGRAL;
    const char *why = "preferred";
    if (E->force_der[e]) caus = BG_CAUS_DERIVATIVE, why = "van Dijk: its state depends on others";
    else if (m->elem_causopt[e] == BG_CAUS_OPT_DERIVATIVE) caus = BG_CAUS_DERIVATIVE, why = "option";
    else if (m->elem_causopt[e] == BG_CAUS_OPT_INTEGRAL) why = "option";
    bg_strbuf sb = {0};
    int mark = E->nlog;
    begin_step(E);
    bg_ceng_set(E, b, bg_ceng_oneport_stroke(E, e, caus), BG_REASON_STORE);
    bg_ceng_propagate(E);
    bg_sb_printf(&sb, "%s %s gets %s causality (%s; bond %d, stroke at %s)",
                 bg_elem_kind_name(m->elem_kind[e]), m->elem_name[e], bg_caus_name(caus), why,
                 m->bond_num[b], end_name(E, b));
    finish_step(E, mark + 1, &sb);
  }
}

static int other_caus(int caus) {
  return caus == BG_CAUS_RESISTANCE ? BG_CAUS_CONDUCTANCE : BG_CAUS_RESISTANCE;
}

/* Step 3 for one R: option; else its law's causality if it propagates
 * without conflict, else the other; when both conflict, the law's (the
 * conflict is recorded, never repaired). VALUE form tries resistance first. */
static void resistor(bg_ceng *E, int e) {
  const bg_model *m = E->m;
  int b = bg_ceng_port(E, e), mark = E->nlog, opt = m->elem_causopt[e];
  int first = bg_ceng_r_natural(m, e), caus = first;
  const char *why = m->elem_form[e] == BG_FORM_VALUE ? "tried first" : "its law's";
  begin_step(E);
  if (opt == BG_CAUS_OPT_RESISTANCE || opt == BG_CAUS_OPT_CONDUCTANCE) {
    caus = opt == BG_CAUS_OPT_RESISTANCE ? BG_CAUS_RESISTANCE : BG_CAUS_CONDUCTANCE;
    bg_ceng_set(E, b, bg_ceng_oneport_stroke(E, e, caus), BG_REASON_RESISTOR);
    bg_ceng_propagate(E);
    why = "option";
  } else if (!bg_ceng_try(E, b, bg_ceng_oneport_stroke(E, e, first), BG_REASON_RESISTOR)) {
    caus = other_caus(first);
    why = "the other one conflicts";
    if (!bg_ceng_try(E, b, bg_ceng_oneport_stroke(E, e, caus), BG_REASON_RESISTOR)) {
      caus = first;
      why = "both conflict; conflict recorded";
      bg_ceng_set(E, b, bg_ceng_oneport_stroke(E, e, caus), BG_REASON_RESISTOR);
      bg_ceng_propagate(E);
    }
  }
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "R %s gets %s causality (%s%s; bond %d, stroke at %s)", m->elem_name[e],
               bg_caus_name(caus), why,
               m->elem_form[e] != BG_FORM_VALUE && caus != first ? ", law inverted" : "",
               m->bond_num[b], end_name(E, b));
  finish_step(E, mark + 1, &sb);
}

static void resistor_note(bg_ceng *E, int e) {
  const bg_model *m = E->m;
  int caus = bg_ceng_oneport_caus(E, e);
  if (m->elem_form[e] == BG_FORM_VALUE || caus == bg_ceng_r_natural(m, e)) return;
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "R %s got %s causality by propagation (law inverted)", m->elem_name[e],
               bg_caus_name(caus));
  bg_ceng_trace(E, bg_sb_str(&sb));
  bg_sb_free(&sb);
}

static void resistors(bg_ceng *E) {
  const bg_model *m = E->m;
  for (int i = 0; i < m->nelem; i++) {
    int e = E->elem_order[i], b = bg_ceng_port(E, e);
    if (m->elem_kind[e] != BG_ELEM_R || b < 0) continue;
    if (bg_ceng_open(E, b)) resistor(E, e);
    else resistor_note(E, e);
  }
}

/* Relaxed (Joseph-Martens, Section 4.9): each nonlinear R still open gets
 * its law's causality, one at a time by name ("assigned in the order
 * R1, R2, R3, R4"), each followed by propagation, which may complete a
 * junction by elimination before the next resistor is assigned; the
 * resistors not yet assigned stay blocked, so propagation never decides
 * them. Junction rules broken here stay broken. (Assigning all of them in
 * one step would leave every junction between two of them to whichever
 * resistor's stroke propagated first: on the hydraulic bridge two type 1
 * conflicts instead of Figure 4.25's type 1 and type 2.) */
static void nonlinear_resistors(bg_ceng *E) {
  const bg_model *m = E->m;
  for (int i = 0; i < m->nelem; i++) { /* decided earlier by a fixed stroke or a source */
    int e = E->elem_order[i];
    if (bg_ceng_r_nonlinear(m, e) && bg_ceng_port(E, e) >= 0 &&
        !bg_ceng_open(E, bg_ceng_port(E, e)))
      resistor_note(E, e);
  }
  for (int i = 0; i < m->nelem; i++) {
    int e = E->elem_order[i], b = bg_ceng_port(E, e);
    if (b < 0 || !bg_ceng_r_nonlinear(m, e) || !bg_ceng_open(E, b)) continue;
    int caus = bg_ceng_r_natural(m, e);
    bg_strbuf sb = {0};
    begin_step(E);
    int mark = E->nlog;
    bg_ceng_set(E, b, bg_ceng_oneport_stroke(E, e, caus), BG_REASON_RESISTOR);
    bg_ceng_propagate(E);
    bg_sb_printf(&sb, "relaxed: nonlinear %s gets its law's %s causality (bond %d)",
                 m->elem_name[e], bg_caus_name(caus), m->bond_num[b]);
    finish_step(E, mark + 1, &sb);
  }
}

/* Step 4: the first open internal bond (both ends junction-structure nodes)
 * by bond number gets its stroke at its head if that propagates without
 * conflict, else at its tail (else at its head, conflict recorded). A bond
 * cursor only moves forward: bonds never lose their stroke outside a trial. */
static int is_js(int kind) { return bg_elem_is_junction(kind) || bg_elem_is_twoport(kind); }

static void choose_one(bg_ceng *E, int b, int internal) {
  const bg_model *m = E->m;
  int mark = E->nlog;
  const char *why = "";
  begin_step(E);
  if (!bg_ceng_try(E, b, BG_STROKE_HEAD, BG_REASON_CHOICE)) {
    why = " (stroke at the head conflicts)";
    if (!bg_ceng_try(E, b, BG_STROKE_TAIL, BG_REASON_CHOICE)) {
      why = " (both orientations conflict; conflict recorded)";
      bg_ceng_set(E, b, BG_STROKE_HEAD, BG_REASON_CHOICE);
      bg_ceng_propagate(E);
    }
  }
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "choice: %sbond %d gets its stroke at %s%s", internal ? "internal " : "",
               m->bond_num[b], end_name(E, b), why);
  finish_step(E, mark + 1, &sb);
}

static void choices(bg_ceng *E) {
  const bg_model *m = E->m;
  for (int i = 0; i < m->nbond; i++) {
    int b = E->bond_order[i];
    if (bg_ceng_open(E, b) && is_js(m->elem_kind[m->bond_tail[b]]) &&
        is_js(m->elem_kind[m->bond_head[b]]))
      choose_one(E, b, 1);
  }
  /* Only reachable when a one-port was left open (it cannot be after steps
   * 1-3); kept so that the result is always complete. */
  for (int i = 0; i < m->nbond; i++)
    if (bg_ceng_open(E, E->bond_order[i])) choose_one(E, E->bond_order[i], 0);
}

void bg_ceng_scap(bg_ceng *E, int relaxed) {
  bg_ceng_block(E, relaxed);
  bg_ceng_fixed(E);
  bg_ceng_sources(E);
  stores(E);
  if (relaxed) nonlinear_resistors(E);
  resistors(E);
  choices(E);
}
