/* Printers of the equation system: text, LaTeX and JSON from the equation
 * trees through the symbolic layer (sym.h: simplified, bond-numbered
 * variables), with the reduced form (eqsym.h) after them; C from the
 * evaluation tape. */
#include <stdio.h>
#include <string.h>

#include "equations/eqprint.h"
#include "equations/eqsym.h"
#include "equations/eqsys_int.h"
#include "model/expr.h"

enum { ST_TEXT, ST_LATEX };

/* The printers' symbols: one context per call; trees simplified on the way
 * (junction coefficients of +-1 cancel, 1/(1/A) is A, like terms collect). */
typedef struct prn {
  const bg_eqsys *s;
  bg_sym *S;
  int st;
} prn;

static void pr(prn *P, int nd, bg_strbuf *out) {
  int a = bg_eqsym_tree(P->S, P->s, nd, NULL);
  bg_sym_print(P->S, a, P->st == ST_LATEX, bg_eqsym_name, (void *)P->s, out);
}

static void pr_sig(const bg_eqsys *s, int v, int st, bg_strbuf *out) {
  bg_sb_printf(out, st == ST_LATEX ? "%c_{%d}" : "%c%d", v & 1 ? 'f' : 'e', s->m->bond_num[v / 2]);
}

static void pr_unknown(const bg_eqsys *s, int i, int st, bg_strbuf *out) {
  if (st == ST_LATEX) bg_eqsym_latex_name(s->uname[i], out);
  else bg_sb_puts(out, s->uname[i]);
}

/* ------------------------------------------------------------ text, LaTeX */
/* Sorted equations, headed by the definitions of the moduli that print by
 * name (T = ... of an MTF modulated by states). */
static void print_eqs(prn *P, bg_strbuf *out) {
  const bg_eqsys *s = P->s;
  for (int k = 0; k < s->norder; k++) bg_eqsym_tree(P->S, s, s->sig_root[s->order[k]], NULL);
  for (int i = 0; i < s->n; i++) bg_eqsym_tree(P->S, s, s->row_root[i], NULL);
  bg_eqsym_aliases(P->S, s, P->st == ST_LATEX, out);
  const char *eq = P->st == ST_LATEX ? " &= " : " = ", *nl = P->st == ST_LATEX ? " \\\\\n" : "\n";
  for (int k = 0; k < s->norder; k++) {
    int v = s->order[k];
    pr_sig(s, v, P->st, out);
    bg_sb_puts(out, eq);
    pr(P, s->sig_root[v], out);
    bg_sb_puts(out, nl);
  }
}

static void print_rows(prn *P, int alg, bg_strbuf *out) {
  const bg_eqsys *s = P->s;
  int st = P->st;
  const char *eq = st == ST_LATEX ? " &= " : " = ", *nl = st == ST_LATEX ? " \\\\\n" : "\n";
  for (int i = alg ? s->nx : 0; i < (alg ? s->n : s->nx); i++) {
    if (s->row_kind[i] == 0) {
      if (st == ST_LATEX) bg_sb_puts(out, "\\dot{"), pr_unknown(s, i, st, out), bg_sb_puts(out, "}");
      else bg_sb_printf(out, "%s'", s->uname[i]);
      bg_sb_puts(out, eq);
    } else {
      bg_sb_printf(out, "0%s", eq);
    }
    pr(P, s->row_root[i], out);
    if (st == ST_TEXT && alg) bg_sb_printf(out, "    (solved for %s)", s->uname[i]);
    if (st == ST_TEXT && !alg && s->row_kind[i]) bg_sb_printf(out, "    (dependent store: constraint)");
    bg_sb_puts(out, nl);
  }
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

/* ------------------------------------------------------------ JSON */
static void json_tree(prn *P, int nd, bg_strbuf *out) {
  bg_strbuf t = {0};
  pr(P, nd, &t);
  bg_sb_json_str(out, bg_sb_str(&t));
  bg_sb_free(&t);
}

void bg_eqprint_json(const bg_eqsys *s, bg_strbuf *out) {
  prn P = {s, bg_sym_new(s->m), ST_TEXT};
  bg_sb_puts(out, "{\"model\": ");
  bg_sb_json_str(out, s->m->name);
  bg_sb_printf(out, ", \"form\": \"%s\", \"unknowns\": [", bg_eqsys_is_ode(s) ? "ode" : "dae");
  for (int i = 0; i < s->n; i++) {
    bg_sb_printf(out, "%s{\"name\": ", i ? ", " : "");
    bg_sb_json_str(out, s->uname[i]);
    bg_sb_printf(out, ", \"kind\": \"%s\"}", i >= s->nx ? "algebraic" : s->row_kind[i] ? "dependent" : "state");
  }
  bg_sb_puts(out, "], \"equations\": [");
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
  bg_sym_free(P.S);
  bg_eqred *r = bg_eqred_build(s);
  bg_eqred_json(r, out);
  bg_eqred_free(r);
  bg_sb_puts(out, "}\n");
}

/* ------------------------------------------------------------ C */
void bg_eqprint_c(const bg_eqsys *s, bg_strbuf *out) { bg_eqprint_c_tape(s, out); }

int bg_eqprint(const bg_eqsys *s, const char *format, bg_strbuf *out) {
  if (!strcmp(format, "text")) bg_eqprint_text(s, out);
  else if (!strcmp(format, "latex")) bg_eqprint_latex(s, out);
  else if (!strcmp(format, "json")) bg_eqprint_json(s, out);
  else if (!strcmp(format, "c")) bg_eqprint_c(s, out);
  else return -1;
  return 0;
}
