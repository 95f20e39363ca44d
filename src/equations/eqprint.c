/* SPDX-License-Identifier: BSD-3-Clause */
/* Printers of the equation system: text, LaTeX and JSON from the equation
 * trees through the symbolic layer (sym.h: simplified, bond-numbered
 * variables), with the reduced form (eqsym.h) after them. (C, like the
 * other exports, is written by src/export.) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqprint.h"
#include "equations/eqsym.h"
#include "equations/eqsys_int.h"
#include "model/model.h"

enum { ST_TEXT = BG_SYM_TEXT, ST_LATEX = BG_SYM_LATEX, ST_MATHML = BG_SYM_MATHML };

/* The printers' symbols: one context per call; trees simplified on the way
 * (junction coefficients of +-1 cancel, 1/(1/A) is A, like terms collect). */
typedef struct prn {
  const bg_eqsys *s;
  bg_sym *S;
  int st;
} prn;

static void pr(prn *P, int nd, bg_strbuf *out) {
  int a = bg_eqsym_tree(P->S, P->s, nd, NULL);
  bg_sym_print(P->S, a, P->st, bg_eqsym_name, (void *)P->s, out);
}

static void pr_sig(const bg_eqsys *s, int v, int st, bg_strbuf *out) {
  bg_eqsym_name((void *)s, SYM_SIG, v, st, out);
}


/* ------------------------------------------------------------ text, LaTeX */
/* Sorted equations, headed by the definitions of the moduli that print by
 * name (T = ... of an MTF modulated by states). */
static void print_eqs(prn *P, bg_strbuf *out) {
  const bg_eqsys *s = P->s;
  for (int k = 0; k < s->norder; k++) bg_eqsym_tree(P->S, s, s->sig_root[s->order[k]], NULL);
  for (int i = 0; i < s->n; i++) bg_eqsym_tree(P->S, s, s->row_root[i], NULL);
  bg_eqsym_aliases(P->S, s, P->st, out);
  const bg_eqpunct *pu = bg_eqpunct_of(P->st);
  for (int k = 0; k < s->norder; k++) {
    int v = s->order[k];
    bg_sb_puts(out, pu->row);
    pr_sig(s, v, P->st, out);
    bg_sb_puts(out, pu->eq);
    pr(P, s->sig_root[v], out);
    bg_sb_puts(out, pu->end);
  }
}

static void print_rows(prn *P, int alg, bg_strbuf *out) {
  const bg_eqsys *s = P->s;
  int st = P->st;
  const bg_eqpunct *pu = bg_eqpunct_of(st);
  for (int i = alg ? s->nx : 0; i < (alg ? s->n : s->nx); i++) {
    bg_sb_puts(out, pu->row);
    if (s->row_kind[i] == 0) bg_eqsym_name((void *)s, SYM_YP, i, st, out);
    else bg_sb_puts(out, st == ST_MATHML ? "<mn>0</mn>" : "0");
    bg_sb_puts(out, pu->eq);
    pr(P, s->row_root[i], out);
    if (st == ST_TEXT && alg) bg_sb_printf(out, "    (solved for %s)", s->uname[i]);
    if (st == ST_TEXT && !alg && s->row_kind[i]) bg_sb_printf(out, "    (dependent store: constraint)");
    bg_sb_puts(out, pu->end);
  }
}

/* Detectors (De, Df): outputs, not equations; each names the bond variable
 * it reads (docs/equations.md), so the equations above stay as they are. */
static void print_detectors(const bg_eqsys *s, int st, bg_strbuf *out) {
  const bg_model *m = s->m;
  if (!m->ndet) return;
  if (st == ST_TEXT) bg_sb_puts(out, "# detectors (outputs: the bond variables they read)\n");
  const bg_eqpunct *pu = bg_eqpunct_of(st);
  for (int k = 0; k < m->ndet; k++) {
    const bg_xnode *x = &m->xnode[m->det_expr[k]];
    bg_sb_puts(out, pu->row);
    if (st == ST_MATHML) bg_eqsym_mathml_name(m->det_name[k], out);
    else if (st == ST_LATEX) bg_eqsym_latex_name(m->det_name[k], out);
    else bg_sb_puts(out, m->det_name[k]);
    bg_sb_puts(out, pu->eq);
    pr_sig(s, 2 * x->ref + (x->op == BG_X_FLOW), st, out);
    bg_sb_puts(out, pu->end);
  }
}

/* Memory (hyst, stick): the discrete states, which no equation above
 * integrates: each changes only at state events (docs/format.md). */
static void print_discrete(const bg_eqsys *s, int json, bg_strbuf *out) {
  int nm = bg_eqsys_nmodes(s), k = 0;
  if (!bg_eqsys_has_memory(s)) return;
  bg_sb_puts(out, json ? ", \"discrete\": [" : "# discrete states (memory: changed only at state events)\n");
  for (int e = 0; e < nm; e++) {
    if (!bg_eqsys_mode_memory(s, e)) continue;
    bg_strbuf where = {0}, what = {0};
    bg_eqsys_mode_describe(s, e, &where, &what);
    if (json) {
      bg_sb_printf(out, "%s{\"where\": ", k ? ", " : "");
      bg_sb_json_str(out, bg_sb_str(&where));
      bg_sb_puts(out, ", \"expr\": ");
      bg_sb_json_str(out, bg_sb_str(&what));
      bg_sb_puts(out, "}");
    } else {
      bg_sb_printf(out, "# %s: %s\n", bg_sb_str(&where), bg_sb_str(&what));
    }
    k++;
    bg_sb_free(&where), bg_sb_free(&what);
  }
  if (json) bg_sb_puts(out, "]");
}

static void unknown_list(const bg_eqsys *s, int i0, int i1, bg_strbuf *out) {
  for (int i = i0; i < i1; i++) bg_sb_printf(out, "%s%s", i > i0 ? ", " : "", s->uname[i]);
}

void bg_eqprint_text(const bg_eqsys *s, bg_strbuf *out) {
  int ode = bg_eqsys_is_ode(s);
  prn P = {s, bg_sym_new(s->m), ST_TEXT};
  bg_sb_printf(out, "# equations of %s, in computational order\n", s->m->name);
  bg_sb_puts(out, "# form: ");
  bg_sb_puts(out, ode ? "ODE x' = f(t, x)" : "DAE F(t, x, x', z) = 0");
  bg_sb_puts(out, "; x = (");
  unknown_list(s, 0, s->nx, out);
  bg_sb_puts(out, ")");
  if (s->nz) bg_sb_puts(out, "; z = ("), unknown_list(s, s->nx, s->n, out), bg_sb_puts(out, ")");
  bg_sb_puts(out, "\n");
  print_eqs(&P, out);
  if (s->nz) bg_sb_puts(out, "# algebraic residuals\n"), print_rows(&P, 1, out);
  bg_sb_puts(out, "# state equations\n");
  print_rows(&P, 0, out);
  print_detectors(s, ST_TEXT, out);
  print_discrete(s, 0, out);
  bg_sym_free(P.S);
  bg_eqred *r = bg_eqred_build(s);
  bg_eqred_print(r, 0, out);
  bg_eqred_free(r);
}

void bg_eqprint_latex(const bg_eqsys *s, bg_strbuf *out) {
  prn P = {s, bg_sym_new(s->m), ST_LATEX};
  bg_sb_puts(out, "\\begin{align*}\n");
  print_eqs(&P, out);
  print_rows(&P, 1, out);
  print_rows(&P, 0, out);
  print_detectors(s, ST_LATEX, out);
  bg_sb_puts(out, "\\end{align*}\n");
  bg_sym_free(P.S);
  bg_eqred *r = bg_eqred_build(s);
  if (bg_eqred_is_ode(r) && bg_eqred_changed(r)) {
    bg_sb_puts(out, "% reduced form: ");
    bg_sb_puts(out, bg_eqred_note(r));
    bg_sb_puts(out, "\n\\begin{align*}\n");
    bg_eqred_print(r, 1, out);
    bg_sb_puts(out, "\\end{align*}\n");
  }
  bg_eqred_free(r);
}

/* The same rows as MathML, an HTML fragment: one <math display="block"> per
 * equation, each group headed by an <h3> (the HTML report's section 7 and
 * --equations mathml; docs/equations.md). */
void bg_eqprint_mathml(const bg_eqsys *s, bg_strbuf *out) {
  prn P = {s, bg_sym_new(s->m), ST_MATHML};
  bg_sb_puts(out, "<h3>Sorted equations</h3>\n");
  print_eqs(&P, out);
  if (s->nz) bg_sb_puts(out, "<h3>Algebraic residuals</h3>\n"), print_rows(&P, 1, out);
  bg_sb_puts(out, "<h3>State equations</h3>\n");
  print_rows(&P, 0, out);
  if (s->m->ndet) bg_sb_puts(out, "<h3>Detectors</h3>\n");
  print_detectors(s, ST_MATHML, out);
  bg_sym_free(P.S);
  bg_eqred *r = bg_eqred_build(s);
  if (bg_eqred_is_ode(r) && bg_eqred_changed(r)) {
    bg_sb_puts(out, "<h3>Reduced form</h3>\n<p>");
    for (const char *c = bg_eqred_note(r); *c; c++) {
      if (*c == '<') bg_sb_puts(out, "&lt;");
      else if (*c == '&') bg_sb_puts(out, "&amp;");
      else bg_sb_putc(out, *c);
    }
    bg_sb_puts(out, "</p>\n");
    bg_eqred_print(r, ST_MATHML, out);
  }
  bg_eqred_free(r);
}

/* ------------------------------------------------------------ JSON */
static void json_tree(prn *P, int nd, bg_strbuf *out) {
  bg_strbuf t = {0};
  pr(P, nd, &t);
  bg_sb_json_str(out, bg_sb_str(&t));
  bg_sb_free(&t);
}

/* What the equations read besides the unknowns: params with their values
 * (after --set), named inputs as written, tables as breakpoints. */
static void json_givens(const bg_eqsys *s, bg_sym *S, bg_strbuf *out) {
  const bg_model *m = s->m;
  bg_sb_puts(out, "\"parameters\": [");
  for (int k = 0; k < m->nparam; k++) {
    bg_sb_printf(out, "%s{\"name\": ", k ? ", " : "");
    bg_sb_json_str(out, m->param_name[k]);
    bg_sb_puts(out, ", \"value\": ");
    bg_sb_json_num(out, m->param_value[k]);
    bg_sb_puts(out, "}");
  }
  bg_sb_puts(out, "], \"inputs\": [");
  bg_strbuf t = {0};
  for (int k = 0; k < m->ninput; k++) {
    bg_sb_printf(out, "%s{\"name\": ", k ? ", " : "");
    bg_sb_json_str(out, m->input_name[k]);
    bg_sb_clear(&t);
    /* through the symbols, so a table prints as the equations print it (#1) */
    bg_sym_print(S, bg_sym_from_x(S, m->input_expr[k], NULL, s->store_y), 0, bg_eqsym_name, (void *)s, &t);
    bg_sb_puts(out, ", \"expr\": ");
    bg_sb_json_str(out, bg_sb_str(&t));
    bg_sb_puts(out, "}");
  }
  bg_sb_free(&t);
  bg_sb_puts(out, "], \"tables\": [");
  for (int k = 0; k < m->ntable; k++) {
    const double *x = m->table_x + m->table_adr[k], *y = m->table_y + m->table_adr[k];
    bg_sb_printf(out, "%s{\"name\": \"#%d\", \"x\": [", k ? ", " : "", k + 1);
    for (int i = 0; i < m->table_n[k]; i++) bg_sb_puts(out, i ? ", " : ""), bg_sb_json_num(out, x[i]);
    bg_sb_puts(out, "], \"y\": [");
    for (int i = 0; i < m->table_n[k]; i++) bg_sb_puts(out, i ? ", " : ""), bg_sb_json_num(out, y[i]);
    bg_sb_puts(out, "]}");
  }
  bg_sb_puts(out, "], ");
}

/* Unknowns with their kind and the value the model starts them from (q0,
 * p0, init; an algebraic unknown's is bg_eqsys_initial's guess). */
static void json_unknowns(const bg_eqsys *s, bg_strbuf *out) {
  double *y0 = bg_xmalloc((size_t)(s->n + 1) * sizeof(double));
  bg_eqsys_initial(s, y0);
  bg_sb_puts(out, "\"unknowns\": [");
  for (int i = 0; i < s->n; i++) {
    bg_sb_printf(out, "%s{\"name\": ", i ? ", " : "");
    bg_sb_json_str(out, s->uname[i]);
    bg_sb_printf(out, ", \"kind\": \"%s\", \"initial\": ",
                 i >= s->nx ? "algebraic" : s->row_kind[i] ? "dependent" : "state");
    bg_sb_json_num(out, y0[i]);
    if (s->u_sig[i] >= 0) { /* the equations read it by its bond variable */
      bg_sb_puts(out, ", \"signal\": \"");
      pr_sig(s, s->u_sig[i], ST_TEXT, out);
      bg_sb_puts(out, "\"");
    }
    bg_sb_puts(out, "}");
  }
  bg_sb_puts(out, "], ");
  free(y0);
}

/* "detectors": [{name, kind, signal}] (only for a model that has them). */
static void json_detectors(const bg_eqsys *s, bg_strbuf *out) {
  const bg_model *m = s->m;
  if (!m->ndet) return;
  bg_sb_puts(out, "\"detectors\": [");
  for (int k = 0; k < m->ndet; k++) {
    const bg_xnode *x = &m->xnode[m->det_expr[k]];
    bg_sb_printf(out, "%s{\"name\": ", k ? ", " : "");
    bg_sb_json_str(out, m->det_name[k]);
    bg_sb_printf(out, ", \"kind\": \"%s\", \"signal\": \"", m->det_var[k] == 'e' ? "De" : "Df");
    pr_sig(s, 2 * x->ref + (x->op == BG_X_FLOW), ST_TEXT, out);
    bg_sb_puts(out, "\"}");
  }
  bg_sb_puts(out, "], ");
}

/* Self-contained: every name an equation uses is defined in the document
 * (docs/json.md, "The equations document"). */
void bg_eqprint_json(const bg_eqsys *s, bg_strbuf *out) {
  prn P = {s, bg_sym_new(s->m), ST_TEXT};
  bg_sb_puts(out, "{\"format\": \"bgdraw-equations\", \"version\": 1, \"model\": ");
  bg_sb_json_str(out, s->m->name);
  bg_sb_printf(out, ", \"form\": \"%s\", \"t0\": ", bg_eqsys_is_ode(s) ? "ode" : "dae");
  bg_sb_json_num(out, s->m->sim.present ? s->m->sim.t0 : 0.0);
  bg_sb_puts(out, ", ");
  json_givens(s, P.S, out);
  json_unknowns(s, out);
  bg_sb_puts(out, "\"equations\": [");
  for (int k = 0; k < s->norder; k++) {
    int v = s->order[k];
    bg_sb_printf(out, "%s{\"lhs\": \"%c%d\", \"rhs\": ", k ? ", " : "", v & 1 ? 'f' : 'e', s->m->bond_num[v / 2]);
    json_tree(&P, s->sig_root[v], out);
    bg_sb_puts(out, ", \"element\": ");
    bg_sb_json_str(out, s->m->elem_name[s->sig_elem[v]]);
    bg_sb_puts(out, "}");
  }
  bg_sb_puts(out, "], \"rows\": [");
  for (int i = 0; i < s->n; i++) {
    bg_sb_printf(out, "%s{\"unknown\": ", i ? ", " : "");
    bg_sb_json_str(out, s->uname[i]);
    bg_sb_printf(out, ", \"type\": \"%s\", \"expr\": ", s->row_kind[i] ? "residual" : "derivative");
    json_tree(&P, s->row_root[i], out);
    bg_sb_puts(out, "}");
  }
  bg_sb_puts(out, "], ");
  json_detectors(s, out);
  bg_eqred *r = bg_eqred_build(s);
  bg_eqred_json(r, out);
  bg_strbuf seen = {0};
  int first = 1;
  bg_sb_puts(out, ", \"definitions\": [");
  bg_eqsym_json_defs(P.S, s, &seen, &first, out);
  bg_eqsym_json_defs(bg_eqred_sym(r), s, &seen, &first, out);
  bg_sb_puts(out, "]");
  print_discrete(s, 1, out);
  bg_sb_puts(out, "}\n");
  bg_sb_free(&seen);
  bg_eqred_free(r);
  bg_sym_free(P.S);
}

int bg_eqprint(const bg_eqsys *s, const char *format, bg_strbuf *out) {
  if (!strcmp(format, "text")) bg_eqprint_text(s, out);
  else if (!strcmp(format, "latex")) bg_eqprint_latex(s, out);
  else if (!strcmp(format, "mathml")) bg_eqprint_mathml(s, out);
  else if (!strcmp(format, "json")) bg_eqprint_json(s, out);
  else return -1;
  return 0;
}
