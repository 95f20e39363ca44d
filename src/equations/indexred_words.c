/* SPDX-License-Identifier: BSD-3-Clause */
/* What the index reduction did, in bond-graph terms: which constraint was
 * differentiated (a dependent store's constraint and the causal paths that
 * end at it, the residual of a causal loop or of a conflict, a store's
 * balance), which stores lost their state (their derivative became a dummy
 * derivative: the store behaves as one in derivative causality). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsym.h"
#include "equations/indexred_int.h"

static void bonds_list(const bg_model *m, const int *b, int n, bg_strbuf *sb) {
  for (int i = 0; i < n; i++) bg_sb_printf(sb, "%s%d", i ? ", " : "", m->bond_num[b[i]]);
}

static int has_bond(const int *b, int n, int bond) {
  for (int i = 0; i < n; i++)
    if (b[i] == bond) return 1;
  return 0;
}

/* The causal paths that end at store e (a dependent store's constraint). */
static void say_paths(const bg_model *m, const bg_analysis *a, int e, bg_strbuf *sb) {
  for (int p = 0; p < a->npath; p++) {
    if (a->path_end0[p] != e && a->path_end1[p] != e) continue;
    bg_sb_printf(sb, "; causal path %d from %s to %s (bonds ", p + 1, m->elem_name[a->path_end0[p]],
                 m->elem_name[a->path_end1[p]]);
    bonds_list(m, a->path_bonds + a->path_adr[p], a->path_n[p], sb);
    bg_sb_puts(sb, ")");
  }
}

/* The causal loops through the bond of signal sig, and a conflict at elem. */
static void say_loops(const bg_model *m, const bg_analysis *a, int sig, int elem, bg_strbuf *sb) {
  int cloops = 0;
  for (int l = 0; l < a->ncloop; l++) {
    if (!has_bond(a->cloop_bonds + a->cloop_adr[l], a->cloop_n[l], sig / 2)) continue;
    cloops++;
    bg_sb_printf(sb, "; it closes causal loop %d (bonds ", l + 1);
    bonds_list(m, a->cloop_bonds + a->cloop_adr[l], a->cloop_n[l], sb);
    bg_sb_printf(sb, ", gain %s, class %d)", a->cloop_gain[l] ? a->cloop_gain[l] : "?", a->cloop_class[l]);
  }
  for (int t = 0; t < a->ntloop && !cloops; t++) /* an algebraic loop of gain +1 (Equation 4.45) */
    if (a->tloop_algebraic[t] && fabs(a->tloop_gain_value[t] - 1.0) <= 1e-12 &&
        has_bond(a->tloop_signals + a->tloop_adr[t], a->tloop_n[t], sig))
      bg_sb_printf(sb, "; it closes algebraic loop %d (from %s), whose gain %s is 1 at these parameter values",
                   t + 1, a->tloop_cause[t] ? a->tloop_cause[t] : "the signal flow graph",
                   a->tloop_gain[t] ? a->tloop_gain[t] : "?");
  for (int k = 0; k < a->nconflict; k++)
    if (a->conflict_node[k] == elem)
      bg_sb_printf(sb, "; the causal conflict (type %d) at %s", a->conflict_type[k], m->elem_name[elem]);
}

static void say_row(ir_work *W, int i, bg_strbuf *sb) {
  const bg_eqsys *s = W->s;
  const bg_model *m = s->m;
  if (i < s->nx && s->row_kind[i] == 1) {
    int e = s->u_elem[i];
    bg_sb_printf(sb, "the constraint of the dependent store %s", m->elem_name[e]);
    say_paths(m, s->a, e, sb);
  } else if (i < s->nx) {
    if (s->u_elem[i] >= 0) bg_sb_printf(sb, "the balance of the store %s", m->elem_name[s->u_elem[i]]);
    else bg_sb_printf(sb, "the equation of the state %s", bg_eqsys_name(s, i));
  } else {
    int sig = s->u_sig[i], elem = sig >= 0 ? s->sig_elem[sig] : -1;
    bg_sb_printf(sb, "the residual of %s", bg_eqsys_name(s, i));
    if (elem >= 0) bg_sb_printf(sb, " (the %s of %s)", s->sig_what[sig], m->elem_name[elem]);
    if (sig >= 0) say_loops(m, s->a, sig, elem, sb);
  }
  bg_sb_puts(sb, ": 0 = ");
  int r = W->row_sym[i];
  bg_sym_print(W->S, r, 0, bg_eqsym_name, (void *)s, sb);
}

static char *take(bg_strbuf *sb) {
  char *t = strdup(bg_sb_str(sb));
  bg_sb_clear(sb);
  return t;
}

static void constraints(ir_work *W, bg_indexred *out, bg_strbuf *sb) {
  out->constraint = bg_xmalloc((size_t)(W->s->n + 1) * sizeof(char *));
  for (int e = 0; e < W->s->n; e++) {
    int times = 0;
    for (int d = W->e_der[e]; d >= 0; d = W->e_der[d]) times++;
    if (!times) continue;
    say_row(W, W->e_row[e], sb);
    static const char *const word[] = {"", "once", "twice"};
    if (times <= 2) bg_sb_printf(sb, " (differentiated %s)", word[times]);
    else bg_sb_printf(sb, " (differentiated %d times)", times);
    out->constraint[out->nconstraint++] = take(sb);
  }
}

/* States whose first derivative became a dummy, and algebraic unknowns whose
 * derivative did not (they became states). */
static void lost_states(ir_work *W, bg_indexred *out, bg_strbuf *sb) {
  const bg_eqsys *s = W->s;
  const bg_model *m = s->m;
  out->lost = bg_xmalloc((size_t)(s->n + 1) * sizeof(char *));
  for (int j = 0; j < s->n; j++) {
    int d1 = W->v_der[j];
    if (d1 < 0) continue;
    const char *nm = bg_eqsys_name(s, j);
    if (j < s->nx && W->v_dummy[d1]) {
      if (s->u_elem[j] >= 0 && s->row_kind[j] == 1)
        bg_sb_printf(sb, "%s (a dependent store already): %s is an algebraic unknown, %s' a dummy derivative",
                     m->elem_name[s->u_elem[j]], nm, nm);
      else if (s->u_elem[j] >= 0)
        bg_sb_printf(sb, "%s: %s is no longer a state, %s' is a dummy derivative (an algebraic unknown): "
                     "the store now acts as one in derivative causality", m->elem_name[s->u_elem[j]], nm, nm);
      else bg_sb_printf(sb, "the state %s: %s' is a dummy derivative, %s algebraic", nm, nm, nm);
    } else if (j >= s->nx && !W->v_dummy[d1]) {
      bg_sb_printf(sb, "none: the algebraic unknown %s became a state (its derivative is no dummy)", nm);
    } else continue;
    out->lost[out->nlost++] = take(sb);
  }
}

void ir_describe(ir_work *W, bg_indexred *out) {
  bg_strbuf sb = {0};
  constraints(W, out, &sb);
  lost_states(W, out, &sb);
  out->dummy = bg_xmalloc((size_t)(W->nv + 1) * sizeof(char *));
  for (int v = 0; v < W->nv; v++) {
    if (!W->v_dummy[v]) continue;
    bg_sb_printf(&sb, "%s%.*s", bg_eqsys_name(W->s, W->v_unk[v]), W->v_ord[v], "''''''''");
    out->dummy[out->ndummy++] = take(&sb);
  }
  bg_sb_printf(&sb, "index reduced (Pantelides, dummy derivatives): %d equation%s differentiated, "
               "%d dummy derivative%s (", out->ndiff, out->ndiff == 1 ? "" : "s", out->ndummy,
               out->ndummy == 1 ? "" : "s");
  for (int k = 0; k < out->ndummy; k++) bg_sb_printf(&sb, "%s%s", k ? ", " : "", out->dummy[k]);
  bg_sb_printf(&sb, "); the reduced equations (%d unknowns) have numeric index %d",
               bg_eqsys_n(out->reduced), out->index);
  out->message = take(&sb);
  bg_sb_free(&sb);
}
