/* SPDX-License-Identifier: BSD-3-Clause */
/* parasitic (chapter Figure 4.5, Sections 4.3 and 4.9): a small C at a
 * 0-junction (I at a 1-junction) takes the junction's common variable as a
 * state, which breaks an algebraic loop between resistors through it
 * (class 2 causal path) or a causal loop, or gives a junction in a type 1
 * conflict the variable no bond gave; in a type 2 conflict each extra bond
 * gets a junction of the other type with the store. The parameter is chosen from the model's time
 * scales: the new store's own estimates (causal paths from it to the
 * resistors and stores around it) are BG_TX_PARASITIC_FACTOR times faster
 * than the fastest estimate of the original model. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "causality/causality.h"
#include "equations/equations.h"
#include "transform/tx_int.h"

enum { MAX_TARGET = 32 };

typedef struct target {
  int junction;     /* element id in the original model */
  int bond;         /* a type 2 conflict's bond split by a new junction; -1: none */
  char split[64];   /* the new junction on it */
  int kind;         /* BG_ELEM_C or BG_ELEM_I */
  char elem[64];    /* the new store */
  char param[64];   /* its parameter */
  char cause[160];  /* why, in words */
  double value;
  double start;     /* the junction's variable at t0 in the original model */
  int start_known;
} target;

typedef struct plan {
  target t[MAX_TARGET];
  int n;
} plan;

/* A store at junction j, or (bond >= 0) at a new junction of the other
 * type splitting bond b of junction j. */
static void add_target(tx_ctx *c, plan *p, int j, int bond, const char *cause) {
  for (int i = 0; i < p->n && bond < 0; i++)
    if (p->t[i].junction == j && p->t[i].bond < 0) return; /* one store serves j */
  if (p->n == MAX_TARGET) return;
  target *t = &p->t[p->n++];
  memset(t, 0, sizeof *t);
  t->junction = j;
  t->bond = bond;
  int zero = c->m->elem_kind[j] == BG_ELEM_J0;
  t->kind = (bond < 0) == zero ? BG_ELEM_C : BG_ELEM_I;
  char base[64];
  const char *at = c->m->elem_name[j];
  if (bond >= 0) { /* named after the element at the bond's other end */
    at = c->m->elem_name[bg_bond_other(c->m, bond, j)];
    snprintf(base, sizeof base, "jp_%s", at);
    tx_fresh_name(c, base, t->split, sizeof t->split);
  }
  snprintf(base, sizeof base, "%sp_%s", t->kind == BG_ELEM_C ? "C" : "I", at);
  tx_fresh_name(c, base, t->elem, sizeof t->elem);
  snprintf(base, sizeof base, "%s_0", t->elem);
  tx_fresh_name(c, base, t->param, sizeof t->param);
  snprintf(t->cause, sizeof t->cause, "%s", cause);
}

/* The junction where the store goes on the chain of n bonds at bonds
 * (closed: a causal loop, whose last and first bonds meet too): its first
 * 0-junction (a compliance, as in Figure 4.5), else its first 1-junction;
 * -1 when it passes none. */
static int chain_junction(const bg_model *m, const int *bonds, int n, int closed) {
  for (int want = BG_ELEM_J0; want <= BG_ELEM_J1; want++)
    for (int i = 0; i + 1 < n + closed; i++) {
      int b1 = bonds[i], b2 = bonds[(i + 1) % n];
      int x = m->bond_tail[b1] == m->bond_tail[b2] || m->bond_tail[b1] == m->bond_head[b2]
                  ? m->bond_tail[b1] : m->bond_head[b1];
      if (m->elem_kind[x] == want) return x;
    }
  return -1;
}

static void collect(tx_ctx *c, plan *p) {
  const bg_model *m = c->m;
  const bg_analysis *a = c->a;
  char cause[160];
  for (int k = 0; k < a->npath; k++) {
    if (a->path_class[k] != 2) continue;
    int j = chain_junction(m, a->path_bonds + a->path_adr[k], a->path_n[k], 0);
    if (j < 0) continue;
    snprintf(cause, sizeof cause, "on class 2 causal path %d (an algebraic loop between the "
             "resistors %s and %s)", k + 1, m->elem_name[a->path_end0[k]],
             m->elem_name[a->path_end1[k]]);
    add_target(c, p, j, -1, cause);
  }
  for (int k = 0; k < a->ncloop; k++) {
    int j = chain_junction(m, a->cloop_bonds + a->cloop_adr[k], a->cloop_n[k], 1);
    if (j < 0) continue;
    snprintf(cause, sizeof cause, "on causal loop %d (an algebraic loop of the junction "
             "structure, gain %s%s)", k + 1, a->cloop_gain[k],
             a->cloop_class[k] == 5 ? " = +1: index above 1" : "");
    add_target(c, p, j, -1, cause);
  }
  for (int k = 0; k < a->nconflict; k++) {
    int j = a->conflict_node[k];
    /* a conflict at a TF or GY (both ports want the same variable) has no
     * junction to carry a store: a bond to the two-port would make it a
     * three-port, which does not compile (property campaign, seed 170) */
    if (m->elem_kind[j] != BG_ELEM_J0 && m->elem_kind[j] != BG_ELEM_J1) continue;
    if (a->conflict_type[k] != 1) {
      /* type 2 of degree d: d + 1 bonds want to set the common variable; the
       * first stays, each other one gets a junction of the other type with a
       * store, which takes that bond's variable as a state (Figure 4.25's
       * remedy at the end of Section 4.9) */
      for (int i = 1; i < a->conflict_n[k]; i++) {
        int b = a->conflict_bonds[a->conflict_adr[k] + i];
        snprintf(cause, sizeof cause, "for the type 2 conflict %d at %s (bond %d is one of the "
                 "%d that want to set its %s)", k + 1, m->elem_name[j], m->bond_num[b],
                 a->conflict_n[k], m->elem_kind[j] == BG_ELEM_J0 ? "effort" : "flow");
        add_target(c, p, j, b, cause);
      }
      continue;
    }
    snprintf(cause, sizeof cause, "for the type 1 conflict %d at %s (no bond determines its %s)",
             k + 1, m->elem_name[a->conflict_node[k]],
             m->elem_kind[a->conflict_node[k]] == BG_ELEM_J0 ? "effort" : "flow");
    add_target(c, p, a->conflict_node[k], -1, cause);
  }
}

/* The new params, stores and bonds written into d. */
static void emit(const tx_ctx *c, const plan *p, tx_doc *d) {
  int pline = tx_param_line(c), bline = tx_last_bond_line(c);
  bg_strbuf s = {0};
  for (int i = 0; i < p->n; i++) {
    const target *t = &p->t[i];
    const char *jn = t->bond >= 0 ? t->split : c->m->elem_name[t->junction];
    if (t->bond >= 0) { /* the new junction, in the bond it splits */
      bg_sb_clear(&s);
      bg_sb_printf(&s, "%-3s %s", t->kind == BG_ELEM_C ? "0" : "1", t->split);
      tx_insert_after(d, tx_elem_line(c, t->junction), bg_sb_str(&s));
      tx_split_bond(c, d, t->bond, t->split, c->next_bond + p->n + i);
    }
    bg_sb_clear(&s);
    bg_sb_printf(&s, "param %s = %.3g \"parasitic %s at %s (bgdraw --transform parasitic)\"",
                 t->param, t->value, t->kind == BG_ELEM_C ? "capacitance" : "inertance", jn);
    tx_insert_after(d, pline, bg_sb_str(&s));
    bg_sb_clear(&s);
    bg_sb_printf(&s, "%-3s %s = %s", t->kind == BG_ELEM_C ? "C" : "I", t->elem, t->param);
    if (t->start_known && t->start != 0) {
      bg_sb_printf(&s, "  [%s = %s*", t->kind == BG_ELEM_C ? "q0" : "p0", t->param);
      bg_sb_num(&s, t->start);
      bg_sb_putc(&s, ']');
    }
    tx_insert_after(d, tx_elem_line(c, t->junction), bg_sb_str(&s));
    bg_sb_clear(&s);
    tx_print_bond(&s, c->next_bond + i, jn, BG_ARROW_PLAIN, t->elem, NULL);
    tx_insert_after(d, bline, bg_sb_str(&s));
  }
  bg_sb_free(&s);
}

/* The simulate statement of a new ODE asks for a stiff solver unless it names one: the
 * solver's automatic choice looks at the Jacobian at t0, where a store on a
 * resistor whose law is flat there (a cubic conductance at e = 0) shows no
 * fast decay yet. 1 when it was rewritten. */
static int ask_stiff_solver(tx_ctx *c) {
  const bg_ast *ast = c->in->ast;
  for (int i = 0; i < ast->nstmts; i++) {
    const bg_ast_stmt *s = &ast->stmts[i];
    if (s->kind != BG_ST_SIMULATE) continue;
    for (int k = 0; k < s->nopts; k++)
      if (!strcmp(s->opts[k].key, "solver")) return 0;
    bg_strbuf t = {0};
    bg_sb_puts(&t, "simulate");
    tx_print_options(&t, s, "solver", "cvode_bdf");
    tx_replace_stmt(&c->doc, s->loc.line, bg_sb_str(&t));
    bg_sb_free(&t);
    return 1;
  }
  return 0;
}

/* The fastest time scale of the original model: its smallest estimate,
 * else the simulated span; *what says which. 0 when there is neither. */
static double fastest_scale(const tx_ctx *c, bg_strbuf *what) {
  const bg_analysis *a = c->a;
  double best = INFINITY;
  int kbest = -1;
  for (int k = 0; k < a->nestimate; k++) {
    double s = tx_estimate_scale(a, k);
    if (isfinite(s) && s > 0 && s < best) best = s, kbest = k;
  }
  if (kbest >= 0) {
    bg_sb_printf(what, "the %s of causal path %d, %.3g s", a->estimate_kind[kbest] == 0
                 ? "time constant" : "period 1/omega0", a->estimate_path[kbest] + 1, best);
    return best;
  }
  if (c->m->sim.present) {
    best = c->m->sim.t_end - c->m->sim.t0;
    bg_sb_printf(what, "the simulated span %.3g s (the model has no time scale estimate)", best);
    return best;
  }
  return 0;
}

/* The junctions' variables at t0 in the original model (consistent initial
 * values), so each new store starts where its junction was and adds no
 * start-up transient: q0 = C e0 at a 0-junction, p0 = I f0 at a 1-junction.
 * Left at 0 when the original's equations cannot be formed or its index is
 * above 1 (consistent values would need the hidden constraints). */
static void initial_values(const tx_ctx *c, plan *p) {
  /* above index 1 the algebraic rows do not fix the junctions' variables: no start */
  if (c->a->index_predicted < 0 || c->a->index_predicted > 1) return;
  bg_diags dg;
  bg_diags_init(&dg, c->in->path, NULL, 0);
  bg_eqsys *s = bg_eqsys_build(c->m, c->a, &dg);
  bg_diags_free(&dg);
  if (!s) return;
  int n = bg_eqsys_n(s), nb = c->m->nbond;
  double *y = calloc((size_t)n + 1, sizeof *y), *e = calloc((size_t)nb, sizeof *e),
         *f = calloc((size_t)nb, sizeof *f);
  double t0 = c->m->sim.present ? c->m->sim.t0 : 0;
  bg_eqsys_initial(s, y);
  if (bg_eqsys_consistent(s, t0, y, 50) == 0 && bg_eqsys_signals(s, t0, y, NULL, e, f) == 0)
    for (int i = 0; i < p->n; i++) {
      int b = p->t[i].bond >= 0 ? p->t[i].bond
                                : c->m->elem_bonds[c->m->elem_bondadr[p->t[i].junction]];
      p->t[i].start = p->t[i].kind == BG_ELEM_C ? e[b] : f[b];
      p->t[i].start_known = isfinite(p->t[i].start);
    }
  free(y);
  free(e);
  free(f);
  bg_eqsys_free(s);
}

/* Rounded down to three significant digits, so that the store stays at
 * least as fast as asked once its value is printed. */
static double round_down3(double v) {
  double q = pow(10, floor(log10(v)) - 2);
  return floor(v / q * (1 + 1e-12)) * q;
}

/* Each store's parameter from the trial model (every parameter 1): a time
 * constant scales with it, the period of an oscillation with its square
 * root. -1 with c->problem when a store has no estimate of its own. */
static int size_stores(tx_ctx *c, plan *p, const bg_model *tm, const bg_analysis *ta,
                       double want, bg_strbuf *said) {
  for (int i = 0; i < p->n; i++) {
    target *t = &p->t[i];
    int e = bg_model_find_elem(tm, t->elem), kbest = -1;
    double best = INFINITY;
    for (int k = 0; k < ta->nestimate; k++) {
      int q = ta->estimate_path[k], e0 = ta->path_end0[q], e1 = ta->path_end1[q];
      if (e0 != e && e1 != e) continue;
      int other = e0 == e ? e1 : e0;
      int new_store = 0;
      for (int q2 = 0; q2 < p->n; q2++) new_store |= !strcmp(tm->elem_name[other], p->t[q2].elem);
      if (new_store) continue; /* two new stores: neither sizes the other */
      double s = tx_estimate_scale(ta, k);
      if (!(isfinite(s) && s > 0)) continue;
      double v = ta->estimate_kind[k] == 0 ? want / s : (want / s) * (want / s);
      if (v < best) best = v, kbest = k;
    }
    if (kbest < 0) {
      bg_sb_printf(&c->problem, "the store %s at %s has no time scale estimate of its own "
                   "(no linear first- or second-order causal path from it), so its value "
                   "cannot be chosen", t->elem, c->m->elem_name[t->junction]);
      return -1;
    }
    t->value = round_down3(best);
    bg_sb_printf(said, "%s%s = %.3g (%s of causal path %d)", i ? ", " : "", t->param, t->value,
                 ta->estimate_kind[kbest] == 0 ? "its time constant" : "its period 1/omega0",
                 ta->estimate_path[kbest] + 1);
  }
  return 0;
}

static int problems(const bg_analysis *a) {
  int n = a->nconflict + a->ncloop;
  for (int k = 0; k < a->npath; k++) n += a->path_class[k] == 2;
  return n;
}

static void say_targets(tx_ctx *c, const plan *p) {
  for (int i = 0; i < p->n; i++) {
    const target *t = &p->t[i];
    int is_c = t->kind == BG_ELEM_C;
    if (c->why.len) bg_sb_putc(&c->why, ' ');
    char where[160];
    if (t->bond >= 0)
      snprintf(where, sizeof where, "a new %d-junction %s splitting bond %d", is_c ? 0 : 1,
               t->split, c->m->bond_num[t->bond]);
    else
      snprintf(where, sizeof where, "the %d-junction %s", is_c ? 0 : 1,
               c->m->elem_name[t->junction]);
    bg_sb_printf(&c->why, "A small %s store %s at %s, %s, takes the junction's %s as a state "
                 "(chapter Figure 4.5: a parasitic %s that was neglected)", is_c ? "C" : "I",
                 t->elem, where, t->cause, is_c ? "effort" : "flow",
                 is_c ? "compliance" : "inertia");
    if (t->start_known && t->start != 0)
      bg_sb_printf(&c->why, "; it starts at the junction's initial %s, %.6g", is_c ? "effort"
                   : "flow", t->start);
    bg_sb_putc(&c->why, '.');
  }
}

/* The trial model (every parameter 1) sizes the stores; then the real one. */
/* The model with every planned store at value 1 (their estimates are then
 * measured and the values sized), compiled and analysed; -1 with the
 * reason in c->problem when it does not compile. */
static int trial_model(tx_ctx *c, plan *p, bg_run **trial_run) {
  for (int i = 0; i < p->n; i++) p->t[i].value = 1;
  initial_values(c, p);
  tx_doc trial;
  tx_doc_init(&trial, c->in->src, c->in->srclen);
  emit(c, p, &trial);
  char *text = tx_doc_text(&trial), *why = NULL;
  tx_doc_free(&trial);
  int rc = tx_compile(c, text, trial_run, &why);
  free(text);
  if (rc != 0) {
    bg_sb_puts(&c->problem, why);
    free(why);
    return -1;
  }
  return 0;
}

int tx_parasitic(tx_ctx *c) {
  plan p = {.n = 0};
  collect(c, &p);
  if (!p.n) {
    if (!c->problem.len)
      bg_sb_puts(&c->problem, "it has no algebraic loop between resistors (class 2 causal "
                              "path), no causal loop and no conflict for a store to "
                              "break");
    return -1;
  }
  bg_strbuf what = {0}, said = {0};
  double scale = fastest_scale(c, &what);
  int rc = -1;
  if (scale <= 0) {
    bg_sb_puts(&c->problem, "the model has no time scale (no estimate, no simulate block) to "
                            "choose the stores' values from");
    goto out;
  }
  bg_run *trial;
  if (trial_model(c, &p, &trial) != 0) goto out;
  const bg_analysis *ta = &trial->analysis;
  double want = scale / BG_TX_PARASITIC_FACTOR;
  rc = size_stores(c, &p, trial->model, ta, want, &said);
  /* better: a lower predicted index, or fewer algebraic loops and conflicts */
  int ia = c->a->index_predicted, ib = ta->index_predicted;
  int new_ode = ta->form == BG_FORM_ODE;
  int fixed = (ib >= 0 && ia >= 0 && ib < ia) || (ib <= ia && problems(ta) < problems(c->a));
  char after[160];
  snprintf(after, sizeof after, " The new model is %s with predicted index %s.",
           ta->form == BG_FORM_ODE ? "an explicit ODE" : ta->form == BG_FORM_DAE ? "a DAE"
           : "causally incomplete", ib < 0 ? "unknown" : ib >= 2 ? "above 1" : ib ? "1" : "0");
  bg_run_free(trial);
  if (rc == 0 && !fixed) {
    bg_sb_puts(&c->problem, "the stores would not remove a class 2 causal path, a causal loop "
                            "or a conflict");
    rc = -1;
  }
  if (rc == 0) {
    emit(c, &p, &c->doc);
    say_targets(c, &p);
    bg_sb_printf(&c->why, " Each parameter makes the store's own estimates %g times faster "
                 "than the fastest estimate of the original model, %s: %s. The new model has "
                 "fast dynamics and wants a stiff solver%s.", BG_TX_PARASITIC_FACTOR,
                 bg_sb_str(&what), bg_sb_str(&said),
                 new_ode && ask_stiff_solver(c) ? ": the simulate statement asks for cvode_bdf"
                 : "");
    bg_sb_puts(&c->why, after);
  }
out:
  bg_sb_free(&what);
  bg_sb_free(&said);
  return rc;
}
