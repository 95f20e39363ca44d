/* SPDX-License-Identifier: BSD-3-Clause */
/* A compiled model as BondGraphTools YAML (-o model.yaml; docs/import.md):
 * the reader's conventions backwards, for the models BondGraphTools can
 * express. Anything it cannot carry with the same equations (laws, modulated
 * elements, fields, sources that vary in time, inputs and states) is a
 * refusal that names the first such thing; a model with submodels is written
 * flat. What bgdraw alone reads (simulate, plot) goes under bgdraw:, which
 * BondGraphTools' load ignores. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/strbuf.h"
#include "import/import.h"
#include "model/model.h" /* with expr.h: bg_xeval */

/* 1 when expression root reads only numbers and params. */
static int is_constant(const bg_model *m, int root) {
  if (root < 0) return 0;
  bg_ivec stack = {0};
  bg_ivec_push(&stack, root);
  int ok = 1;
  while (stack.n && ok) {
    const bg_xnode *x = &m->xnode[stack.v[--stack.n]];
    if (x->op != BG_X_NUM && x->op != BG_X_PARAM && x->op != BG_X_NEG && x->op < BG_X_ADD) ok = 0;
    if (x->op == BG_X_TABLE) ok = 0;
    for (int i = 0; i < x->nargs; i++) bg_ivec_push(&stack, x->arg[i]);
  }
  free(stack.v);
  return ok;
}

static double value_of(const bg_model *m, int root) {
  bg_xenv env = {0};
  return bg_xeval(m, root, &env);
}

/* A .bg name as a BondGraphTools name: instance paths joined by '_'. */
static void put_name(bg_strbuf *out, const char *name) {
  for (const char *s = name; *s; s++) bg_sb_putc(out, *s == '.' ? '_' : *s);
}

static void put_num(bg_strbuf *out, double v) {
  char buf[40];
  bg_num_format(buf, sizeof buf, v == 0 ? 0 : v, 15);
  bg_sb_puts(out, buf);
}

static char *why_not(const bg_model *m, int e, const char *what) {
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "%s %s %s, which BondGraphTools' components cannot say (docs/import.md)",
               bg_elem_display_kind(m, e), m->elem_name[e], what);
  return sb.s;
}

/* The first thing of m the format cannot carry, in words (owned), or NULL. */
static char *cannot_carry(const bg_model *m) {
  bg_strbuf sb = {0};
  if (m->nfield) bg_sb_printf(&sb, "field %s is a multiport field", m->field_name[0]);
  else if (m->ninput) bg_sb_printf(&sb, "input %s is a function of time", m->input_name[0]);
  else if (m->nstate) bg_sb_printf(&sb, "state %s is a signal integrator", m->state_name[0]);
  else if (m->nsignal) bg_sb_printf(&sb, "%s reads %s, a signal", m->elem_name[m->signal_to[0]],
                                    m->signal_var[0]);
  if (sb.s) {
    bg_sb_puts(&sb, ", which BondGraphTools' components cannot say (docs/import.md)");
    return sb.s;
  }
  for (int e = 0; e < m->nelem; e++) {
    int k = m->elem_kind[e];
    if (k == BG_ELEM_MSE || k == BG_ELEM_MSF || k == BG_ELEM_MTF || k == BG_ELEM_MGY || m->elem_modulated[e])
      return why_not(m, e, "is modulated");
    if (k == BG_ELEM_J0 || k == BG_ELEM_J1) continue;
    if (m->elem_form[e] != BG_FORM_VALUE) return why_not(m, e, "has a law");
    if (!is_constant(m, m->elem_expr[e])) return why_not(m, e, "has a value that varies in time");
    if (!isfinite(value_of(m, m->elem_expr[e]))) return why_not(m, e, "has a value that is not finite");
  }
  return NULL;
}

/* One end of bond b at element e as a netlist word. */
static void put_end(bg_strbuf *out, const bg_model *m, int b, int e) {
  put_name(out, m->elem_name[e]);
  int head = m->bond_head[b] == e;
  switch (m->elem_kind[e]) {
  case BG_ELEM_J1: bg_sb_puts(out, head ? ".non_inverting" : ".inverting"); break;
  case BG_ELEM_TF:
  case BG_ELEM_GY: bg_sb_puts(out, head ? ".0" : ".1"); break;
  default: break;
  }
}

static void put_component(bg_strbuf *out, const bg_model *m, int e) {
  static const char *const comp[BG_ELEM_COUNT] = {
      [BG_ELEM_SE] = "base/Se e", [BG_ELEM_SF] = "base/Sf f", [BG_ELEM_C] = "base/C C",
      [BG_ELEM_I] = "base/I L",   [BG_ELEM_R] = "base/R r",   [BG_ELEM_TF] = "base/TF r",
      [BG_ELEM_GY] = "base/GY R", [BG_ELEM_J0] = "base/0",    [BG_ELEM_J1] = "base/1"};
  int k = m->elem_kind[e];
  bg_sb_puts(out, "      - ");
  put_name(out, m->elem_name[e]);
  bg_sb_printf(out, " %s", comp[k]);
  if (k == BG_ELEM_J0 || k == BG_ELEM_J1) {
    bg_sb_putc(out, '\n');
    return;
  }
  double v = value_of(m, m->elem_expr[e]);
  if (k == BG_ELEM_GY) v = -v; /* e_0 = R f_1, e_1 = -R f_0 */
  if (k == BG_ELEM_SF && m->elem_nbond[e] == 1 && m->bond_head[m->elem_bonds[m->elem_bondadr[e]]] == e)
    v = -v; /* BondGraphTools' f is the flow out of the source */
  bg_sb_putc(out, '=');
  put_num(out, v);
  bg_sb_putc(out, '\n');
}

/* What only bgdraw reads: the simulate block and the plots (flat names). */
static void put_bgdraw(bg_strbuf *out, const bg_model *m) {
  if (!m->sim.present && !m->nplot) return;
  bg_sb_puts(out, "bgdraw:\n");
  if (m->sim.present) {
    bg_sb_puts(out, "  - simulate t_end = ");
    put_num(out, m->sim.t_end);
    if (m->sim.t0 != 0) bg_sb_puts(out, ", t0 = "), put_num(out, m->sim.t0);
    if (m->sim.dt > 0) bg_sb_puts(out, ", dt = "), put_num(out, m->sim.dt);
    if (m->sim.rtol > 0) bg_sb_puts(out, ", rtol = "), put_num(out, m->sim.rtol);
    if (m->sim.atol > 0) bg_sb_puts(out, ", atol = "), put_num(out, m->sim.atol);
    if (m->sim.max_step > 0) bg_sb_puts(out, ", max_step = "), put_num(out, m->sim.max_step);
    if (m->sim.solver && strcmp(m->sim.solver, "auto")) bg_sb_printf(out, ", solver = %s", m->sim.solver);
    bg_sb_putc(out, '\n');
  }
  for (int p = 0; p < m->nplot && !m->ninst; p++) {
    bg_sb_puts(out, "  - plot ");
    for (int i = 0; i < m->plot_nexpr[p]; i++)
      bg_sb_printf(out, "%s%s", i ? ", " : "", m->plotexpr_text[m->plot_expradr[p] + i]);
    bg_sb_putc(out, '\n');
  }
}

char *bg_bgt_write(const bg_model *m, bg_strbuf *out) {
  char *why = cannot_carry(m);
  if (why) return why;
  bg_sb_printf(out, "# %s as BondGraphTools YAML, written by bgdraw (docs/import.md)\n", m->name);
  if (m->ninst) bg_sb_puts(out, "# written flat: the names of submodel instances are joined by '_'\n");
  for (int e = 0; e < m->nelem; e++)
    if ((m->elem_kind[e] == BG_ELEM_C || m->elem_kind[e] == BG_ELEM_I) && m->elem_init[e] >= 0 &&
        value_of(m, m->elem_init[e]) != 0) {
      bg_sb_printf(out, "# not carried: %s %s0 = ", m->elem_name[e], m->elem_kind[e] == BG_ELEM_C ? "q" : "p");
      put_num(out, value_of(m, m->elem_init[e]));
      bg_sb_puts(out, " (BondGraphTools takes initial states when simulating)\n");
    }
  for (int d = 0; d < m->ndet; d++) bg_sb_printf(out, "# not carried: detector %s\n", m->det_name[d]);
  bg_sb_puts(out, "version: 0.1\nroot: ");
  put_name(out, m->name);
  bg_sb_puts(out, "\nmodels:\n  /:\n    components:\n");
  for (int e = 0; e < m->nelem; e++) put_component(out, m, e);
  if (m->nbond) bg_sb_puts(out, "    netlist:\n");
  for (int b = 0; b < m->nbond; b++) {
    bg_sb_puts(out, "      - ");
    put_end(out, m, b, m->bond_tail[b]);
    bg_sb_putc(out, ' ');
    put_end(out, m, b, m->bond_head[b]);
    bg_sb_putc(out, '\n');
  }
  put_bgdraw(out, m);
  return NULL;
}
