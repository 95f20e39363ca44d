/* SPDX-License-Identifier: BSD-3-Clause */
/* Why a model must not be handed to a solver (docs/simulation.md): index
 * above 1, a causal loop of gain +1, an algebraic loop that is singular at
 * the current parameter values, incomplete causality. The message names the
 * loop or paths and gives the remedies of the reference text. IDA does not
 * reliably reject such systems, so this is decided here. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "simulate/simulate.h"

/* Remedies differ by cause: van Dijk's causality removes a causal loop of
 * gain +1 but not a class 1 path sharing bonds with a loop (Proposition
 * 5.10), nor a conflict that constrains states. */
static const char *const REMEDIES =
    "Remedies: use --causality vandijk (van Dijk's causality turns the loop into class 1 "
    "paths between stores, index 1); or add a small store (C or I) or a resistor in the "
    "path so the loop gets an integration (Section 4.3).";
static const char *const REMEDIES_SHARED =
    "Remedies: add a small store (C or I) or a resistor in the causal loop or in the class 1 "
    "path so they no longer share bonds without an integration (Section 4.3); if a causal "
    "stroke fixed in the model closes the loop, try the other choice; --causality vandijk "
    "does not help here, the class 1 path stays.";
static const char *const REMEDIES_CONFLICT =
    "Remedies: add a small store (C at a 0-junction, I at a 1-junction) or a resistor at the "
    "junction of the conflict, so its balance gets a variable of its own (Section 4.3).";

static void bonds_list(const bg_model *m, const int *b, int n, bg_strbuf *sb) {
  for (int i = 0; i < n; i++) bg_sb_printf(sb, "%s%d", i ? ", " : "", m->bond_num[b[i]]);
}

/* Gain +1 to within rounding: the loop equation (1 - g) x = ... is singular. */
static int unity(double g) { return fabs(g - 1.0) <= 1e-12; }

/* A class 5 loop costs index only when the analysis says so: when its two
 * constraints determine its two algebraic variables the prediction is 1
 * (src/analysis/form.c, cloop_constrains_states) and the equations are
 * integrated like any other index-1 DAE. */
static int class5_loop(const bg_analysis *a) {
  if (a->index_predicted < 2) return -1;
  for (int l = 0; l < a->ncloop; l++)
    if (a->cloop_class[l] == 5) return l;
  return -1;
}

/* A name that says "reference node" (gnd, ground, ref, earth, com, 0). */
static int ground_like(const char *name) {
  static const char *const words[] = {"gnd", "ground", "ref", "earth", "com", "0"};
  for (size_t i = 0; i < sizeof words / sizeof *words; i++)
    if (strcasecmp(name, words[i]) == 0) return 1;
  return 0;
}

/* A causal loop of gain +1 through 0- and 1-junctions alone is a mesh of a
 * circuit written node by node whose node potentials float: nothing holds
 * any 0-junction's effort, so every potential is free up to a common
 * constant (the junction structure is singular). Holding one node at zero
 * removes it (docs/format.md, "A reference node"). The node to name: one
 * whose name says ground, else the loop's first 0-junction. -1: not a mesh. */
static int floating_node(const bg_model *m, const bg_analysis *a, int l) {
  const int *b = a->cloop_bonds + a->cloop_adr[l];
  int node = -1, has1 = 0;
  for (int i = 0; i < a->cloop_n[l]; i++)
    for (int end = 0; end < 2; end++) {
      int e = end ? m->bond_head[b[i]] : m->bond_tail[b[i]], k = m->elem_kind[e];
      if (k == BG_ELEM_J1) has1 = 1;
      else if (k != BG_ELEM_J0) return -1;
      else if (node < 0 || (ground_like(m->elem_name[e]) && !ground_like(m->elem_name[node])))
        node = e;
    }
  return has1 ? node : -1;
}

/* singular: index reduction found the equations structurally singular. */
static void say_class5(const bg_model *m, const bg_analysis *a, int l, int singular, bg_strbuf *sb) {
  bg_sb_printf(sb, "causal loop %d (bonds ", l + 1);
  bonds_list(m, a->cloop_bonds + a->cloop_adr[l], a->cloop_n[l], sb);
  bg_sb_puts(sb, ") has gain +1 (class 5");
  if (a->cloop_gain[l] && strcmp(a->cloop_gain[l], "1") != 0)
    bg_sb_printf(sb, ": gain %s = 1 at these parameter values", a->cloop_gain[l]);
  bg_sb_puts(sb, "): the junction structure is singular and the index is above 1, so no "
                 "solver can integrate the equations as they stand. ");
  int node = floating_node(m, a, l);
  if (node >= 0) {
    bg_sb_printf(sb, "The loop runs through 0- and 1-junctions alone: if this is a circuit "
                     "written node by node, its node potentials float (nothing holds any "
                     "0-junction's effort). Remedy: hold the reference node at zero, e.g. "
                     "`short %s` (a circuit's ground; docs/format.md, \"A reference node\")",
                 m->elem_name[node]);
    if (singular) { /* no causality changes structurally singular equations */
      bg_sb_puts(sb, "; van Dijk's causality does not help here.");
      return;
    }
    bg_sb_puts(sb, ". Otherwise: ");
    bg_sb_puts(sb, REMEDIES + strlen("Remedies: "));
    return;
  }
  bg_sb_puts(sb, REMEDIES);
}

/* Class 1 paths sharing bonds with a causal loop, and any other index-2
 * pattern the analysis found: its reason text already names them. */
static void say_index2(const bg_model *m, const bg_analysis *a, bg_strbuf *sb) {
  bg_sb_printf(sb, "predicted index above 1: %s. ",
               a->index_reason ? a->index_reason : "the causal pattern gives index 2");
  for (int l = 0; l < a->ncloop; l++) {
    bg_sb_printf(sb, "Causal loop %d runs through bonds ", l + 1);
    bonds_list(m, a->cloop_bonds + a->cloop_adr[l], a->cloop_n[l], sb);
    bg_sb_puts(sb, ". ");
  }
  for (int p = 0; p < a->npath; p++) {
    if (a->path_class[p] != 1) continue;
    bg_sb_printf(sb, "Class 1 causal path %d (%s to %s) runs through bonds ", p + 1,
                 m->elem_name[a->path_end0[p]], m->elem_name[a->path_end1[p]]);
    bonds_list(m, a->path_bonds + a->path_adr[p], a->path_n[p], sb);
    bg_sb_puts(sb, ". ");
  }
  bg_sb_puts(sb, "IDA cannot integrate index-2 equations reliably. ");
  const char *why = a->index_reason ? a->index_reason : "";
  if (strncmp(why, "class 1 causal path", 19) == 0) bg_sb_puts(sb, REMEDIES_SHARED);
  else if (strstr(why, "conflict at")) bg_sb_puts(sb, REMEDIES_CONFLICT);
  else bg_sb_puts(sb, REMEDIES);
}

/* The prediction said 1 or less but the equations, linearised at the start,
 * have index 2 or more (or none): the numeric index is the one to trust
 * (bg_index_disagreement), and IDA would integrate them unreliably. */
static int numeric_above_1(const bg_analysis *a, const bg_index_facts *f) {
  if (!bg_index_facts_numeric_set(f)) return 0;
  int k = f->numeric->index;
  return a->index_predicted < 2 && (k >= 2 || k < 0);
}

static void say_numeric(const bg_analysis *a, const bg_index_facts *f, bg_strbuf *sb) {
  if (f->numeric->index >= 0)
    bg_sb_printf(sb, "the equations have numeric index %d (Algorithm 4.1 at the initial point), ",
                 f->numeric->index);
  else bg_sb_puts(sb, "the linearised equations are singular (no index), ");
  bg_sb_printf(sb, "although the causal pattern predicts %d; the numeric index, computed from the "
                   "equations themselves, is the one to trust%s. IDA cannot integrate index-2 "
                   "equations reliably. ", a->index_predicted,
               a->method == BG_METHOD_LAGRANGE ? " (under Lagrange causality the balances at the "
                                                 "artificial flow sources are not causal paths)" : "");
  bg_sb_puts(sb, "Remedies: another causality method (--causality scap or vandijk), or a small "
                 "store (C or I) or a resistor where the states are constrained, so the constraint "
                 "gets an integration (Section 4.3).");
}

/* The equations linearised at the initial point have numeric index 0 or 1
 * (computed, not skipped): the fact both exceptions below rest on. */
static int numeric_at_most_1(const bg_index_facts *f) {
  return f && bg_index_facts_numeric_set(f) && f->numeric->index >= 0 && f->numeric->index <= 1;
}

/* An algebraic loop of gain 1 at the initial point makes its own loop
 * equation singular, but the algebraic equations are singular only when
 * the determinant of all the loops that touch it is (Mason's rule: two
 * open loops through one gyrator, of gains +1 and -1, cancel: property
 * seed 8, docs/property.md finding 17a). The numeric index, from the
 * equations linearised at the same point, decides: 0 or 1 computed there
 * means the algebraic rows are regular, and nothing is refused for the loop. */
static int singular_tloop(const bg_analysis *a, const bg_index_facts *f) {
  if (numeric_at_most_1(f)) return -1;
  for (int t = 0; t < a->ntloop; t++) {
    /* the open loop of a class 5 causal loop the analysis found harmless
     * (class5_loop): its constraint determines the other loop variable */
    if (a->index_predicted < 2 && a->tloop_cause[t] && strncmp(a->tloop_cause[t], "causal loop", 11) == 0)
      continue;
    if (a->tloop_algebraic[t] && unity(a->tloop_gain_value[t])) return t;
  }
  return -1;
}

static void say_tloop(const bg_analysis *a, int t, bg_strbuf *sb) {
  const char *cause = a->tloop_cause[t] ? a->tloop_cause[t] : "the signal flow graph";
  bg_sb_printf(sb, "algebraic loop %d (from %s) has gain %s = 1 at these parameter values: "
                   "the loop equation (1 - gain) x = ... cannot be solved for x (Equation 4.45)"
                   ", the equations are singular. ", t + 1, cause, a->tloop_gain[t]);
  if (a->tloop_cause[t] && strncmp(a->tloop_cause[t], "internal", 8) == 0)
    bg_sb_puts(sb, "Remedies: change the parameters so the loop gain differs from 1, or add "
                   "a small store (C or I) in the loop (Section 4.3).");
  else
    bg_sb_puts(sb, REMEDIES);
}

/* The index reduction that was tried and failed, with its reason, or NULL. */
static const bg_indexred *failed_reduction(const bg_index_facts *f) {
  const bg_indexred *ir = f ? f->reduction : NULL;
  return ir && ir->status < 0 && ir->message ? ir : NULL;
}

static int structurally_singular(const bg_index_facts *f) {
  const bg_indexred *ir = failed_reduction(f);
  return ir && strstr(ir->message, "structurally singular");
}

/* A predicted index above 1 that two independent measures contradict: the
 * structure of the equations has index 0 or 1 (Pantelides differentiated
 * nothing) and the equations linearised at the initial point have numeric
 * index 0 or 1. Only the causal pattern says more, reading structure that
 * cancels in the equations at these values (property seed 4692: the loops of
 * junctions closed through an MTF share bonds; (1 - n - 1/1.35) f = 0 holds
 * only at f = 0 for n(t) >= 1.44). The numeric index is the one to use, as
 * the warning of the disagreement says; IDA integrates an index-1 DAE, and a
 * point on the trajectory where the equations become singular stops the run
 * with the solver's reason. Without both facts (no reduction tried, the
 * numeric index not computed) the prediction stands. */
static int prediction_contradicted(const bg_index_facts *f) {
  const bg_indexred *ir = f ? f->reduction : NULL;
  return ir && ir->status < 0 && ir->structural_le1 && numeric_at_most_1(f);
}

/* Refusals an index reduction can lift: a class 5 loop, an algebraic loop of
 * gain +1, a predicted or numeric index above 1. */
int bg_simulate_index_problem(const bg_analysis *a, const bg_index_facts *f) {
  if (!a->complete || a->form == BG_FORM_INCOMPLETE) return 0;
  return class5_loop(a) >= 0 || singular_tloop(a, f) >= 0 || a->index_predicted >= 2 ||
         numeric_above_1(a, f);
}

char *bg_simulate_refusal_reduced(const bg_model *m, const bg_analysis *a, const bg_index_facts *f,
                                  int reduced) {
  bg_strbuf sb = {0};
  int l, t;
  if (!a->complete || a->form == BG_FORM_INCOMPLETE)
    bg_sb_puts(&sb, "causality is incomplete: some bonds have no causal stroke, so the "
                    "equations cannot be formed. Fix the conflicts the analysis reports "
                    "(or use --causality relaxed or vandijk).");
  else if (reduced) /* the index problem below is what the reduction removed */
    return NULL;
  else if ((l = class5_loop(a)) >= 0)
    say_class5(m, a, l, structurally_singular(f), &sb);
  else if ((t = singular_tloop(a, f)) >= 0) /* before the index: its own remedies */
    say_tloop(a, t, &sb);
  else if (a->index_predicted >= 2 && !prediction_contradicted(f))
    say_index2(m, a, &sb);
  else if (numeric_above_1(a, f))
    say_numeric(a, f, &sb);
  if (!sb.len) return NULL;
  const bg_indexred *ir = failed_reduction(f);
  if (ir && bg_simulate_index_problem(a, f)) {
    const char *why = ir->message, *pre = "index reduction failed: ";
    if (!strncmp(why, pre, strlen(pre))) why += strlen(pre);
    bg_sb_printf(&sb, " Index reduction (Pantelides, dummy derivatives) was tried and failed: %s.", why);
  }
  char *msg = strdup(bg_sb_str(&sb));
  bg_sb_free(&sb);
  return msg;
}
