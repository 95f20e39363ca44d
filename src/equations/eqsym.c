/* SPDX-License-Identifier: BSD-3-Clause */
/* Equation trees of bg_eqsys (eqsys_int.h) as bg_sym expressions, and the
 * names of their leaves (eqsym.h). */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsym.h"
#include "equations/eqsys_int.h"

/* What a model expression reads: 1 bond variables, 2 states/time/inputs. */
static int x_reads(const bg_model *m, int root) {
  const bg_xnode *n = &m->xnode[root];
  int r = 0;
  switch (n->op) {
  case BG_X_EFFORT: case BG_X_FLOW: return 1;
  case BG_X_STATE: case BG_X_STORE: case BG_X_TIME: case BG_X_INPUT: return 2;
  case BG_X_NUM: case BG_X_PARAM: return 0;
  default:
    for (int k = 0; k < n->nargs && k < 3; k++) {
      int q = x_reads(m, n->arg[k]);
      r = q == 1 || r == 1 ? 1 : r > q ? r : q;
    }
    return r;
  }
}

/* The two-port whose modulus is expression root when it is modulated by
 * states only (an MTF T(phi)) prints as its name: x_modulus[root] is that
 * element, else -1. The lowest-numbered two-port owning a root decides. */
void bg_eqs_sym_lookups(bg_eqsys *s) {
  const bg_model *m = s->m;
  s->state_y = bg_arena_alloc(&s->arena, (size_t)(m->nstate + 1) * sizeof(int));
  for (int k = 0; k < m->nstate; k++) s->state_y[k] = s->nint - m->nstate + k;
  s->x_modulus = bg_arena_alloc(&s->arena, (size_t)(m->nxnode + 1) * sizeof(int));
  for (int x = 0; x < m->nxnode; x++) s->x_modulus[x] = -1;
  for (int e = m->nelem - 1; e >= 0; e--) {
    int root = m->elem_expr[e];
    if (bg_elem_is_twoport(m->elem_kind[e]) && root >= 0 && root < m->nxnode)
      s->x_modulus[root] = x_reads(m, root) == 2 ? e : -1;
  }
}

/* Signals replaced by the expressions of a map (read only). */
static int sig_cb(void *ctx, int kind, int ref) {
  const int *map = ctx;
  return kind == SYM_SIG && map[ref] >= 0 ? map[ref] : -1;
}

int bg_eqsym_tree(bg_sym *S, const bg_eqsys *s, int nd, const int *sigmap) {
  const eq_node *n = &s->node[nd];
  switch (n->kind) {
  case EQ_NUM: return bg_sym_num(S, n->c);
  case EQ_SIG: return sigmap && sigmap[n->a] >= 0 ? sigmap[n->a] : bg_sym_leaf(S, SYM_SIG, n->a);
  case EQ_Y: return bg_sym_leaf(S, SYM_Y, n->a);
  case EQ_YP: return bg_sym_leaf(S, SYM_YP, n->a);
  case EQ_X: {
    int r = bg_sym_from_x(S, n->a, s->state_y, s->store_y), e = s->x_modulus[n->a];
    if (e >= 0) return bg_sym_alias(S, e, r);
    return sigmap ? bg_sym_subst(S, r, sig_cb, (void *)sigmap) : r;
  }
  case EQ_MUL: case EQ_DIV: {
    int a = bg_eqsym_tree(S, s, n->a, sigmap), b = bg_eqsym_tree(S, s, n->b, sigmap);
    return n->kind == EQ_MUL ? bg_sym_mul(S, a, b) : bg_sym_div(S, a, b);
  }
  default: { /* EQ_LIN */
    int tmp[32], *t = n->b <= 32 ? tmp : bg_xmalloc((size_t)n->b * sizeof(int));
    for (int k = 0; k < n->b; k++) t[k] = bg_eqsym_tree(S, s, s->lin_node[n->a + k], sigmap);
    int r = bg_sym_sum(S, 0, n->b, t, s->lin_coef + n->a);
    if (t != tmp) free(t);
    return r;
  }
  }
}

/* ------------------------------------------------------------ names */
const bg_eqpunct *bg_eqpunct_of(int form) {
  static const bg_eqpunct p[3] = {
      {"", " = ", "\n", "(", ")", "*", " + ", " - "},
      {"", " &= ", " \\\\\n", "\\left(", "\\right)", " ", " + ", " - "},
      {"<math display=\"block\"><mrow>", "<mo>=</mo>", "</mrow></math>\n", "<mrow><mo>(</mo>",
       "<mo>)</mo></mrow>", "<mo>&#x2062;</mo>", "<mo>+</mo>", "<mo>&#x2212;</mo>"}};
  return &p[form == BG_SYM_MATHML ? 2 : form ? 1 : 0];
}

void bg_eqsym_latex_name(const char *nm, bg_strbuf *out) {
  const char *dot = strrchr(nm, '.');
  if (dot && dot[1]) {
    bg_sb_printf(out, "%s_{\\mathrm{", dot + 1);
    bg_sb_putn(out, nm, (size_t)(dot - nm));
    bg_sb_puts(out, "}}");
  } else if ((nm[0] == 'e' || nm[0] == 'f') && isdigit((unsigned char)nm[1])) {
    bg_sb_printf(out, "%c_{%s}", nm[0], nm + 1);
  } else if (nm[0] && !nm[1]) {
    bg_sb_puts(out, nm);
  } else {
    bg_sb_printf(out, "\\mathrm{%s}", nm);
  }
}

/* Names are identifiers, dotted paths and bond variables: only an unlikely
 * '&' or '<' needs escaping. */
static void ml_text(bg_strbuf *out, const char *s, size_t n) {
  for (size_t i = 0; i < n && s[i]; i++) {
    if (s[i] == '&') bg_sb_puts(out, "&amp;");
    else if (s[i] == '<') bg_sb_puts(out, "&lt;");
    else if (s[i] == '>') bg_sb_puts(out, "&gt;");
    else bg_sb_putc(out, s[i]);
  }
}

void bg_eqsym_mathml_name(const char *nm, bg_strbuf *out) {
  const char *dot = strrchr(nm, '.');
  if (dot && dot[1]) { /* C1.q: q with subscript C1, upright (a name, not a product) */
    bg_sb_puts(out, "<msub><mi>"), ml_text(out, dot + 1, strlen(dot + 1));
    bg_sb_puts(out, "</mi><mi mathvariant=\"normal\">"), ml_text(out, nm, (size_t)(dot - nm));
    bg_sb_puts(out, "</mi></msub>");
  } else if ((nm[0] == 'e' || nm[0] == 'f') && isdigit((unsigned char)nm[1])) {
    bg_sb_printf(out, "<msub><mi>%c</mi><mn>", nm[0]), ml_text(out, nm + 1, strlen(nm + 1));
    bg_sb_puts(out, "</mn></msub>");
  } else {
    bg_sb_puts(out, "<mi>"), ml_text(out, nm, strlen(nm)), bg_sb_puts(out, "</mi>");
  }
}

/* A name in one of the printers' forms (BG_SYM_*). */
static void form_name(const char *nm, int form, bg_strbuf *out) {
  if (form == BG_SYM_MATHML) bg_eqsym_mathml_name(nm, out);
  else if (form == BG_SYM_LATEX) bg_eqsym_latex_name(nm, out);
  else bg_sb_puts(out, nm);
}

void bg_eqsym_name(void *ctx, int kind, int ref, int latex, bg_strbuf *out) {
  const bg_eqsys *s = ctx;
  const bg_model *m = s->m;
  const char *nm = NULL;
  switch (kind) {
  case SYM_PARAM: nm = m->param_name[ref]; break;
  case SYM_INPUT: nm = m->input_name[ref]; break;
  case SYM_T: nm = "t"; break;
  case SYM_Y: nm = s->uname[ref]; break;
  case SYM_ALIAS: nm = m->elem_name[ref]; break;
  case SYM_YP:
    if (latex == BG_SYM_MATHML)
      bg_sb_puts(out, "<mover accent=\"true\"><mrow>"), bg_eqsym_mathml_name(s->uname[ref], out),
          bg_sb_puts(out, "</mrow><mo>&#x02d9;</mo></mover>");
    else if (latex) bg_sb_puts(out, "\\dot{"), bg_eqsym_latex_name(s->uname[ref], out), bg_sb_puts(out, "}");
    else bg_sb_printf(out, "%s'", s->uname[ref]);
    return;
  default:
    bg_sb_printf(out, latex == BG_SYM_MATHML ? "<msub><mi>%c</mi><mn>%d</mn></msub>" : latex ? "%c_{%d}" : "%c%d",
                 ref & 1 ? 'f' : 'e', m->bond_num[ref / 2]);
    return;
  }
  form_name(nm, latex, out);
}

void bg_eqsym_aliases(bg_sym *S, const bg_eqsys *s, int latex, bg_strbuf *out) {
  for (int k = 0; k < S->nalias; k++) {
    if (S->alias_expr[k] < 0) continue;
    const bg_eqpunct *pu = bg_eqpunct_of(latex);
    bg_sb_puts(out, pu->row);
    bg_eqsym_name((void *)s, SYM_ALIAS, k, latex, out);
    bg_sb_puts(out, pu->eq);
    bg_sym_print(S, S->alias_expr[k], latex, bg_eqsym_name, (void *)s, out);
    bg_sb_puts(out, pu->end);
  }
}

/* One definition, unless its name was emitted already. */
static void json_def(bg_sym *S, const bg_eqsys *s, const char *name, const char *kind, int e,
                     bg_strbuf *seen, int *first, bg_strbuf *out) {
  const char *p = bg_sb_str(seen);
  size_t len = strlen(name);
  for (const char *q = p; (q = strstr(q, name)) != NULL; q += len)
    if ((q == p || q[-1] == '\n') && q[len] == '\n') return;
  bg_sb_printf(seen, "%s\n", name);
  bg_sb_puts(out, *first ? "{\"name\": " : ", {\"name\": ");
  *first = 0;
  bg_sb_json_str(out, name);
  bg_sb_printf(out, ", \"kind\": \"%s\", \"expr\": ", kind);
  bg_strbuf t = {0};
  bg_sym_print(S, e, 0, bg_eqsym_name, (void *)s, &t);
  bg_sb_json_str(out, bg_sb_str(&t));
  bg_sb_free(&t);
  bg_sb_puts(out, "}");
}

void bg_eqsym_json_defs(bg_sym *S, const bg_eqsys *s, bg_strbuf *seen, int *first, bg_strbuf *out) {
  bg_strbuf nm = {0};
  for (int k = 0; k < S->nalias; k++)
    if (S->alias_expr[k] >= 0) json_def(S, s, s->m->elem_name[k], "alias", S->alias_expr[k], seen, first, out);
  for (int k = 0; k < S->ndalias; k++) {
    bg_sb_clear(&nm);
    bg_sym_print(S, bg_sym_leaf(S, SYM_DALIAS, k), 0, bg_eqsym_name, (void *)s, &nm);
    const char *txt = bg_sb_str(&nm); /* "(dT/dphi)": the name without its parentheses */
    size_t len = strlen(txt);
    char *bare = bg_xmalloc(len + 1);
    memcpy(bare, txt[0] == '(' ? txt + 1 : txt, len);
    bare[len - (txt[0] == '(' ? 2 : 0)] = 0;
    json_def(S, s, bare, "derivative", S->dalias_expr[k], seen, first, out);
    free(bare);
  }
  bg_sb_free(&nm);
}
