/* Printers of the equation system: text, LaTeX and JSON from the equation
 * trees (bond-numbered variables), C from the evaluation tape. */
#include <ctype.h>
#include <stdio.h>
#include <string.h>

#include "eqprint.h"
#include "eqsys_int.h"
#include "expr.h"

enum { ST_TEXT, ST_LATEX };

/* "C1.q" -> "q_{C1}", "e4" -> "e_{4}", other names upright. */
static void latex_name(const char *nm, bg_strbuf *out) {
  const char *dot = strrchr(nm, '.');
  if (dot && dot[1]) {
    bg_sb_printf(out, "%s_{\\mathrm{", dot + 1);
    bg_sb_putn(out, nm, (size_t)(dot - nm));
    bg_sb_puts(out, "}}");
  } else if ((nm[0] == 'e' || nm[0] == 'f') && isdigit((unsigned char)nm[1])) {
    bg_sb_printf(out, "%c_{%s}", nm[0], nm + 1);
  } else {
    bg_sb_printf(out, "\\mathrm{%s}", nm);
  }
}

/* Text of a model expression turned into LaTeX token by token. */
static void latex_text(const char *t, bg_strbuf *out) {
  while (*t) {
    if (isalpha((unsigned char)*t) || *t == '_') {
      const char *b = t;
      while (isalnum((unsigned char)*t) || *t == '_' || *t == '.') t++;
      char nm[256];
      size_t len = (size_t)(t - b) < sizeof nm - 1 ? (size_t)(t - b) : sizeof nm - 1;
      memcpy(nm, b, len), nm[len] = 0;
      if (*t == '(') bg_sb_printf(out, "\\operatorname{%s}", nm);
      else latex_name(nm, out);
    } else if (*t == '*') {
      bg_sb_puts(out, " \\cdot "), t++;
    } else {
      bg_sb_putc(out, *t++);
    }
  }
}

static int compound(const bg_eqsys *s, int nd) {
  const eq_node *n = &s->node[nd];
  if (n->kind == EQ_LIN) return n->b > 1 || s->lin_coef[n->a] != 1;
  if (n->kind == EQ_X) {
    int op = s->m->xnode[n->a].op;
    return op == BG_X_ADD || op == BG_X_SUB || op == BG_X_NEG;
  }
  return 0;
}

static void pr(const bg_eqsys *s, int nd, int st, bg_strbuf *out);

static void pr_wrapped(const bg_eqsys *s, int nd, int st, int wrap, bg_strbuf *out) {
  if (wrap) bg_sb_puts(out, st == ST_LATEX ? "\\left(" : "(");
  pr(s, nd, st, out);
  if (wrap) bg_sb_puts(out, st == ST_LATEX ? "\\right)" : ")");
}

static void pr_lin(const bg_eqsys *s, const eq_node *n, int st, bg_strbuf *out) {
  for (int k = 0; k < n->b; k++) {
    double c = s->lin_coef[n->a + k];
    int child = s->lin_node[n->a + k];
    if (k > 0) bg_sb_puts(out, c < 0 ? " - " : " + ");
    else if (c < 0) bg_sb_puts(out, "-");
    double a = c < 0 ? -c : c;
    if (a != 1) bg_sb_printf(out, st == ST_LATEX ? "%g \\cdot " : "%g*", a);
    pr_wrapped(s, child, st, (a != 1 || c < 0) && compound(s, child), out);
  }
}

static void pr(const bg_eqsys *s, int nd, int st, bg_strbuf *out) {
  const eq_node *n = &s->node[nd];
  bg_strbuf tmp = {0};
  switch (n->kind) {
  case EQ_NUM: bg_sb_printf(out, "%g", n->c); break;
  case EQ_X:
    bg_xprint(s->m, n->a, &tmp);
    if (st == ST_LATEX) latex_text(bg_sb_str(&tmp), out);
    else bg_sb_puts(out, bg_sb_str(&tmp));
    break;
  case EQ_SIG:
    bg_sb_printf(out, st == ST_LATEX ? "%c_{%d}" : "%c%d", n->a & 1 ? 'f' : 'e', s->m->bond_num[n->a / 2]);
    break;
  case EQ_Y:
    if (st == ST_LATEX) latex_name(s->uname[n->a], out);
    else bg_sb_puts(out, s->uname[n->a]);
    break;
  case EQ_YP:
    if (st == ST_LATEX) bg_sb_puts(out, "\\dot{"), latex_name(s->uname[n->a], out), bg_sb_puts(out, "}");
    else bg_sb_printf(out, "%s'", s->uname[n->a]);
    break;
  case EQ_LIN: pr_lin(s, n, st, out); break;
  default: /* MUL, DIV */
    pr_wrapped(s, n->a, st, compound(s, n->a), out);
    bg_sb_puts(out, n->kind == EQ_MUL ? (st == ST_LATEX ? " \\cdot " : "*") : "/");
    pr_wrapped(s, n->b, st, compound(s, n->b) || (n->kind == EQ_DIV && s->node[n->b].kind != EQ_SIG &&
                                                   s->node[n->b].kind != EQ_NUM && s->node[n->b].kind != EQ_Y &&
                                                   !(s->node[n->b].kind == EQ_X && s->m->xnode[s->node[n->b].a].nargs == 0)),
               out);
    break;
  }
  bg_sb_free(&tmp);
}

static void pr_sig(const bg_eqsys *s, int v, int st, bg_strbuf *out) {
  bg_sb_printf(out, st == ST_LATEX ? "%c_{%d}" : "%c%d", v & 1 ? 'f' : 'e', s->m->bond_num[v / 2]);
}

/* ------------------------------------------------------------ text, LaTeX */
static void print_eqs(const bg_eqsys *s, int st, bg_strbuf *out) {
  const char *eq = st == ST_LATEX ? " &= " : " = ", *nl = st == ST_LATEX ? " \\\\\n" : "\n";
  for (int k = 0; k < s->norder; k++) {
    int v = s->order[k];
    pr_sig(s, v, st, out);
    bg_sb_puts(out, eq);
    pr(s, s->sig_root[v], st, out);
    bg_sb_puts(out, nl);
  }
}

static void print_rows(const bg_eqsys *s, int st, int alg, bg_strbuf *out) {
  const char *eq = st == ST_LATEX ? " &= " : " = ", *nl = st == ST_LATEX ? " \\\\\n" : "\n";
  for (int i = alg ? s->nx : 0; i < (alg ? s->n : s->nx); i++) {
    if (s->row_kind[i] == 0) {
      if (st == ST_LATEX) bg_sb_puts(out, "\\dot{"), latex_name(s->uname[i], out), bg_sb_puts(out, "}");
      else bg_sb_printf(out, "%s'", s->uname[i]);
      bg_sb_puts(out, eq);
    } else {
      bg_sb_printf(out, "0%s", eq);
    }
    pr(s, s->row_root[i], st, out);
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
  bg_sb_printf(out, "# equations of %s, in computational order\n", s->m->name);
  bg_sb_puts(out, "# form: ");
  bg_sb_puts(out, ode ? "ODE x' = f(t, x)" : "DAE F(t, x, x', z) = 0");
  bg_sb_puts(out, "; x = (");
  unknown_list(s, 0, s->nx, out);
  bg_sb_puts(out, ")");
  if (s->nz) bg_sb_puts(out, "; z = ("), unknown_list(s, s->nx, s->n, out), bg_sb_puts(out, ")");
  bg_sb_puts(out, "\n");
  print_eqs(s, ST_TEXT, out);
  if (s->nz) bg_sb_puts(out, "# algebraic residuals\n"), print_rows(s, ST_TEXT, 1, out);
  bg_sb_puts(out, "# state equations\n");
  print_rows(s, ST_TEXT, 0, out);
}

void bg_eqprint_latex(const bg_eqsys *s, bg_strbuf *out) {
  bg_sb_puts(out, "\\begin{align*}\n");
  print_eqs(s, ST_LATEX, out);
  print_rows(s, ST_LATEX, 1, out);
  print_rows(s, ST_LATEX, 0, out);
  bg_sb_puts(out, "\\end{align*}\n");
}

/* ------------------------------------------------------------ JSON */
static void json_tree(const bg_eqsys *s, int nd, bg_strbuf *out) {
  bg_strbuf t = {0};
  pr(s, nd, ST_TEXT, &t);
  bg_sb_json_str(out, bg_sb_str(&t));
  bg_sb_free(&t);
}

void bg_eqprint_json(const bg_eqsys *s, bg_strbuf *out) {
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
    json_tree(s, s->sig_root[v], out);
    bg_sb_puts(out, ", \"element\": ");
    bg_sb_json_str(out, s->m->elem_name[s->sig_elem[v]]);
    bg_sb_puts(out, "}");
  }
  bg_sb_puts(out, "], \"rows\": [");
  for (int i = 0; i < s->n; i++) {
    bg_sb_printf(out, "%s{\"unknown\": ", i ? ", " : "");
    bg_sb_json_str(out, s->uname[i]);
    bg_sb_printf(out, ", \"type\": \"%s\", \"expr\": ", s->row_kind[i] ? "residual" : "derivative");
    json_tree(s, s->row_root[i], out);
    bg_sb_puts(out, "}");
  }
  bg_sb_puts(out, "]}\n");
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
