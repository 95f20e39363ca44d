/* SPDX-License-Identifier: BSD-3-Clause */
/* The model compiler, part 4: multiport C, I and R fields (docs/format.md,
 * Multiport fields). A field of n ports becomes n consecutive one-port
 * elements of its kind, one per port ("K.el", "K.2"), each with its port's
 * law; every later stage (causality per port, equations, simulation) sees
 * one-ports whose laws read their sibling ports' variables, and the field
 * record groups them for the JSON, the report and the diagram.
 *
 * Port variables in a field's laws are the port's own variables, power into
 * the field positive (the one-port convention of docs/format.md): effort e,
 * flow f (the bond's flow negated when the bond points out of the port) and
 * for a C field the displacement q with dq/dt = f, for an I field the
 * momentum p with dp/dt = e. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model_int.h"

/* ---------------------------------------------------------------- declaring */
void bg_build_declare_field(bg_build *b, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  int kind = strcmp(s->kindword, "C") == 0 ? BG_ELEM_C : strcmp(s->kindword, "I") == 0 ? BG_ELEM_I : BG_ELEM_R;
  if (bg_build_declare(b, s->name, s->name_loc, NS_FIELD, m->nfield) != 0) return;
  int f = bg_build_new(b, &m->nfield);
  m->field_name[f] = bg_build_strdup(b, s->name);
  m->field_kind[f] = kind;
  m->field_elemadr[f] = m->nelem;
  m->field_numbered[f] = s->field_numbered;
  m->field_energy[f] = -1;
  m->field_loc[f] = s->name_loc;
  for (int k = 0; k < s->nitems; k++) {
    char *name = malloc(strlen(s->name) + strlen(s->items[k].name) + 2);
    sprintf(name, "%s.%s", s->name, s->items[k].name);
    int e = bg_build_new_elem(b, s, kind, name, s->items[k].loc);
    free(name);
    if (e < 0) continue; /* a port named twice: reported by the namespace */
    m->elem_field[e] = f;
    m->elem_fport[e] = m->field_nport[f] + 1;
    m->field_nport[f]++;
  }
}

/* ---------------------------------------------------------------- laws */
/* The port a law's left-hand side names ("e2", "el.f"), its letter in *v;
 * -1 if none (reported). "energy" is handled by the caller. */
static int law_port(bg_build *b, int f, const bg_ast_item *law, char *v) {
  const bg_model *m = b->m;
  const char *lhs = law->name, *dot = strchr(lhs, '.');
  int pe = -1;
  if (dot) {
    char port[256];
    snprintf(port, sizeof port, "%.*s", (int)(dot - lhs), lhs);
    *v = dot[1] && !dot[2] ? dot[1] : 0;
    pe = bg_build_port_elem(m, f, port, 0);
  } else if (strchr("efq", lhs[0]) && lhs[1] && strspn(lhs + 1, "0123456789") == strlen(lhs + 1)) {
    *v = lhs[0]; /* more digits than any port number has: no port */
    pe = strlen(lhs + 1) > 7 ? -1 : bg_build_port_elem(m, f, NULL, atoi(lhs + 1));
  } else {
    *v = 0;
  }
  int kind = m->field_kind[f];
  const char *form = kind == BG_ELEM_C   ? "e1 = F(q1, q2) or energy = W(q1, q2)"
                     : kind == BG_ELEM_I ? "f1 = F(p1, p2), energy = W(p1, p2) or inertance = [L1, M; M, L2]"
                                         : "e1 = F(f1, f2) or f1 = G(e1, e2)";
  if (pe < 0 || !*v || (kind == BG_ELEM_C && *v != 'e') || (kind == BG_ELEM_I && *v != 'f') ||
      (kind == BG_ELEM_R && *v == 'q')) {
    if (*v && pe < 0)
      bg_diag_error(b->dg, law->loc, "'%s': field %s has no such port (a law is %s)", lhs,
                    m->field_name[f], form);
    else
      bg_diag_error(b->dg, law->loc, "'%s = ...' is not a law of %s field (a law is %s)", lhs,
                    bg_elem_kind_article(kind), form);
    return -1;
  }
  return pe;
}

/* Compiles one expression of field f: a law of port pe (lhs v), or the
 * energy (pe -1). */
static int field_expr(bg_build *b, int f, int pe, char v, const bg_expr *x) {
  b->allow = ALLOW_TIME | ALLOW_INPUT | ALLOW_MODEL;
  b->input_limit = b->m->ninput;
  b->what = "a field's law";
  b->elem = pe >= 0 ? pe : b->m->field_elemadr[f];
  b->law_elem = pe;
  b->law_lhs = v;
  b->field = f;
  b->modvar = NULL;
  int root = bg_build_expr(b, x);
  /* reading a variable of no port (another element's, a state) modulates */
  for (int k = 0; b->modvar && k < b->m->field_nport[f]; k++)
    if (pe < 0 || b->m->field_elemadr[f] + k == pe) b->m->elem_modulated[b->m->field_elemadr[f] + k] = 1;
  b->field = b->law_elem = b->elem = -1;
  return root;
}

/* The energy form: each port's effort is dW/dq of its port (C), each
 * port's flow dW/dp (I). */
static void energy_laws(bg_build *b, int f, const bg_ast_item *law) {
  bg_model *m = b->m;
  if (m->field_kind[f] == BG_ELEM_R) {
    bg_diag_error(b->dg, law->loc, "only a C or I field has an energy function; write an R field's "
                  "laws per port (f1 = G(e1, e2), ...)");
    return;
  }
  int w = field_expr(b, f, -1, 0, law->value);
  m->field_energy[f] = w;
  for (int k = 0; k < m->field_nport[f]; k++) {
    int pe = m->field_elemadr[f] + k, d = bg_build_diff(b, w, pe);
    if (d == -2) {
      bg_diag_error(b->dg, law->loc, "the energy of %s uses table(), which has no smooth "
                    "gradient; give the %s as laws (%s)", m->field_name[f],
                    m->field_kind[f] == BG_ELEM_C ? "efforts" : "flows",
                    m->field_kind[f] == BG_ELEM_C ? "e1 = ..., e2 = ..." : "f1 = ..., f2 = ...");
      return;
    }
    m->elem_expr[pe] = d >= 0 ? d : bg_build_num(b, 0, law->loc);
    m->elem_form[pe] = m->field_kind[f] == BG_ELEM_C ? BG_FORM_LAW_E : BG_FORM_LAW_F;
  }
}

/* ---------------------------------------------------------------- inertance matrix */
/* The short form of a linear I field, `inertance = [L11, L12; L21, L22]`:
 * the momenta are p = L f, so each port's flow is row k of L^-1 times p.
 * L^-1 is built as model expressions by Gauss-Jordan elimination without
 * pivoting (L is symmetric positive definite: its pivots are positive), so
 * params stay params (exports, --set); the constants fold. */
enum { MAX_INERTANCE_PORTS = 16 }; /* n^3 nodes: a field beyond this writes its laws */

static int is_num(const bg_model *m, int k, double v) {
  return m->xnode[k].op == BG_X_NUM && m->xnode[k].num == v;
}

/* a op c with the obvious constants folded (0 + x, 1 * x, x / 1, 0 * x). */
static int fold(bg_build *b, int op, int a, int c, bg_srcloc loc) {
  const bg_model *m = b->m;
  if (m->xnode[a].op == BG_X_NUM && m->xnode[c].op == BG_X_NUM) {
    double x = m->xnode[a].num, y = m->xnode[c].num;
    return bg_build_num(b, op == BG_X_ADD ? x + y : op == BG_X_SUB ? x - y : op == BG_X_MUL ? x * y : x / y, loc);
  }
  if (op == BG_X_MUL && (is_num(m, a, 0) || is_num(m, c, 0))) return bg_build_num(b, 0, loc);
  if (op == BG_X_MUL && is_num(m, a, 1)) return c;
  if ((op == BG_X_MUL || op == BG_X_DIV) && is_num(m, c, 1)) return a;
  if ((op == BG_X_ADD || op == BG_X_SUB) && is_num(m, c, 0)) return a;
  if (op == BG_X_ADD && is_num(m, a, 0)) return c;
  if (op == BG_X_SUB && is_num(m, a, 0)) return bg_build_op(b, BG_X_NEG, c, -1, loc);
  return bg_build_op(b, op, a, c, loc);
}

/* Where every entry is a constant: symmetric and positive definite
 * (Cholesky at the model's values), else a diagnostic. */
static int inertance_ok(bg_build *b, int f, const bg_ast_item *law, const int *L, int n) {
  bg_model *m = b->m;
  double *a = malloc((size_t)(n * n) * sizeof *a);
  int ok = 1;
  for (int i = 0; i < n * n && ok; i++) {
    a[i] = bg_xeval(m, L[i], NULL);
    if (isnan(a[i])) ok = -1; /* not constant (reads a variable), or reported already */
  }
  for (int i = 0; i < n && ok == 1; i++)
    for (int j = 0; j < i && ok == 1; j++)
      if (a[i * n + j] != a[j * n + i]) {
        bg_diag_error(b->dg, law->value->loc, "the inertance matrix of %s is not symmetric: row %d, "
                      "column %d is %g, row %d, column %d is %g", m->field_name[f], i + 1, j + 1,
                      a[i * n + j], j + 1, i + 1, a[j * n + i]);
        ok = 0;
      }
  for (int k = 0; k < n && ok == 1; k++) { /* Cholesky, in place, lower triangle */
    double d = a[k * n + k];
    for (int j = 0; j < k; j++) d -= a[k * n + j] * a[k * n + j];
    if (!(d > 0)) {
      bg_diag_error(b->dg, law->value->loc, "the inertance matrix of %s is not positive definite "
                    "(its kinetic energy would not be positive; pivot %d is %g): a coupling above "
                    "the geometric mean of the two inertances?", m->field_name[f], k + 1, d);
      ok = 0;
      break;
    }
    a[k * n + k] = sqrt(d);
    for (int i = k + 1; i < n; i++) {
      double s = a[i * n + k];
      for (int j = 0; j < k; j++) s -= a[i * n + j] * a[k * n + j];
      a[i * n + k] = s / a[k * n + k];
    }
  }
  free(a);
  return ok != 0;
}

static void inertance_laws(bg_build *b, int f, const bg_ast_item *law) {
  bg_model *m = b->m;
  int n = m->field_nport[f];
  const bg_expr *x = law->value;
  bg_srcloc loc = x->loc;
  if (m->field_kind[f] != BG_ELEM_I) {
    bg_diag_error(b->dg, law->loc, "only an I field has an inertance matrix; write %s field's laws "
                  "per port", bg_elem_kind_article(m->field_kind[f]));
    return;
  }
  if (x->kind != BG_EX_MATRIX || x->nrows != n || x->ncols != n) {
    bg_diag_error(b->dg, loc, "the inertance of %s, a field of %d ports, is a %d x %d matrix [L11, "
                  "L12; L21, L22] with one row per port", m->field_name[f], n, n, n);
    return;
  }
  if (n > MAX_INERTANCE_PORTS) {
    bg_diag_error(b->dg, loc, "an inertance matrix has at most %d ports (here %d): write the "
                  "field's laws per port (f1 = ..., ...)", MAX_INERTANCE_PORTS, n);
    return;
  }
  int *A = malloc((size_t)(2 * n * n) * sizeof *A), *G = A + n * n;
  for (int i = 0; i < n * n; i++) {
    A[i] = field_expr(b, f, -1, 0, x->args[i]);
    G[i] = bg_build_num(b, i / n == i % n ? 1 : 0, loc);
  }
  if (inertance_ok(b, f, law, A, n)) {
    for (int k = 0; k < n; k++) { /* Gauss-Jordan: [A | G] -> [1 | A^-1] */
      int piv = A[k * n + k];
      for (int j = 0; j < n; j++) {
        A[k * n + j] = fold(b, BG_X_DIV, A[k * n + j], piv, loc);
        G[k * n + j] = fold(b, BG_X_DIV, G[k * n + j], piv, loc);
      }
      for (int i = 0; i < n; i++) {
        if (i == k || is_num(m, A[i * n + k], 0)) continue;
        int c = A[i * n + k];
        for (int j = 0; j < n; j++) {
          A[i * n + j] = fold(b, BG_X_SUB, A[i * n + j], fold(b, BG_X_MUL, c, A[k * n + j], loc), loc);
          G[i * n + j] = fold(b, BG_X_SUB, G[i * n + j], fold(b, BG_X_MUL, c, G[k * n + j], loc), loc);
        }
      }
    }
    for (int k = 0; k < n; k++) { /* f_k = sum_j (L^-1)_kj p_j */
      int pe = m->field_elemadr[f] + k, sum = bg_build_num(b, 0, loc);
      for (int j = 0; j < n; j++)
        sum = fold(b, BG_X_ADD, sum, fold(b, BG_X_MUL, G[k * n + j],
                                          bg_build_ref(b, BG_X_STORE, m->field_elemadr[f] + j, loc), loc), loc);
      m->elem_expr[pe] = sum;
      m->elem_form[pe] = BG_FORM_LAW_F;
    }
  }
  free(A);
}

/* Is the law of port pe affine in the port's own input variable? */
static int port_linear(const bg_model *m, int pe) {
  int root = m->elem_expr[pe];
  if (m->elem_kind[pe] == BG_ELEM_C || m->elem_kind[pe] == BG_ELEM_I) return bg_build_is_affine(m, root, BG_X_STORE, pe);
  int bond = bg_elem_port_bond(m, pe);
  if (bond < 0) return 0;
  return bg_build_is_affine(m, root, m->elem_form[pe] == BG_FORM_LAW_E ? BG_X_FLOW : BG_X_EFFORT,
                            bond);
}

/* Laws per port: one for each port, none twice. */
static void port_laws(bg_build *b, int f, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  int *seen = calloc((size_t)m->field_nport[f] + 1, sizeof *seen);
  for (int i = 0; i < s->nlaws; i++) {
    const bg_ast_item *law = &s->laws[i];
    char v;
    if (strcmp(law->name, "energy") == 0 || strcmp(law->name, "inertance") == 0) {
      bg_diag_error(b->dg, law->loc, "a field has either %s or laws per port, not both",
                    law->name[0] == 'e' ? "an energy" : "an inertance matrix");
      continue;
    }
    int pe = law_port(b, f, law, &v);
    if (pe < 0) continue;
    int k = m->elem_fport[pe];
    if (seen[k]) {
      bg_diag_error(b->dg, law->loc, "port %s of %s has two laws (the first at column %d)",
                    bg_elem_port_name(m, pe), m->field_name[f], s->laws[seen[k] - 1].loc.col);
      continue;
    }
    seen[k] = i + 1;
    m->elem_expr[pe] = field_expr(b, f, pe, v, law->value);
    m->elem_form[pe] = v == 'e' ? BG_FORM_LAW_E : BG_FORM_LAW_F;
  }
  for (int k = 0; k < m->field_nport[f]; k++) {
    int pe = m->field_elemadr[f] + k;
    if (!seen[k + 1])
      bg_diag_error(b->dg, m->elem_loc[pe], "port %s of %s field %s has no law (write %s%s = ... "
                    "in the field's laws)", bg_elem_port_name(m, pe),
                    bg_elem_kind_name(m->field_kind[f]), m->field_name[f],
                    m->field_numbered[f] ? (m->field_kind[f] == BG_ELEM_I ? "f" : "e") : bg_elem_port_name(m, pe),
                    m->field_numbered[f] ? bg_elem_port_name(m, pe) : m->field_kind[f] == BG_ELEM_I ? ".f" : ".e");
  }
  free(seen);
}

void bg_build_field_laws(bg_build *b, int f) {
  bg_model *m = b->m;
  if (m->field_nport[f] == 0) return;
  const bg_ast_stmt *s = b->elem_stmt[m->field_elemadr[f]];
  int energy = -1;
  for (int i = 0; i < s->nlaws; i++)
    if (strcmp(s->laws[i].name, "energy") == 0 && energy < 0) energy = i;
  if (energy >= 0 && s->nlaws == 1) energy_laws(b, f, &s->laws[energy]);
  else if (s->nlaws == 1 && strcmp(s->laws[0].name, "inertance") == 0) inertance_laws(b, f, &s->laws[0]);
  else port_laws(b, f, s);
  for (int k = 0; k < m->field_nport[f]; k++) {
    int pe = m->field_elemadr[f] + k;
    if (m->elem_expr[pe] >= 0) m->elem_linear[pe] = port_linear(m, pe);
  }
}

/* ---------------------------------------------------------------- options */
/* The value of option `o` for port k: the k-th of a tuple of n, or the one
 * value when n is 1 (or, for a word, when it stands alone for every port). */
static const bg_expr *per_port(bg_build *b, int f, const bg_ast_option *o, int k, int word) {
  const bg_model *m = b->m;
  int n = m->field_nport[f];
  const bg_expr *v = o->value;
  if (v->kind == BG_EX_TUPLE && v->nargs == n) return v->args[k];
  if (v->kind != BG_EX_TUPLE && (n == 1 || word)) return v;
  if (k == 0)
    bg_diag_error(b->dg, v->loc, "option '%s' of field %s needs one value per port: (%s) with %d "
                  "entries", o->key, m->field_name[f], word ? "a, b, ..." : "v1, v2, ...", n);
  return NULL;
}

static int caus_word(bg_build *b, int kind, const bg_expr *v) {
  static const char *const words[] = {"integral", "derivative", "resistance", "conductance"};
  static const int opts[] = {BG_CAUS_OPT_INTEGRAL, BG_CAUS_OPT_DERIVATIVE, BG_CAUS_OPT_RESISTANCE,
                             BG_CAUS_OPT_CONDUCTANCE};
  int lo = kind == BG_ELEM_R ? 2 : 0;
  if (v->kind == BG_EX_NAME || v->kind == BG_EX_STR)
    for (int i = lo; i < lo + 2; i++)
      if (strcmp(v->str, words[i]) == 0) return opts[i];
  bg_diag_error(b->dg, v->loc, "invalid causality '%s' (valid: %s, %s)", v->text, words[lo],
                words[lo + 1]);
  return BG_CAUS_OPT_NONE;
}

void bg_build_field_options(bg_build *b, int f) {
  bg_model *m = b->m;
  int p1 = m->field_elemadr[f], kind = m->field_kind[f];
  if (m->field_nport[f] == 0) return;
  const bg_ast_stmt *s = b->elem_stmt[p1];
  char whose[160];
  snprintf(whose, sizeof whose, "%s field '%s'", bg_elem_kind_name(kind), s->name);
  bg_build_check_options(b, s, kind == BG_ELEM_C   ? "label, color, at, causality, q0"
                               : kind == BG_ELEM_I ? "label, color, at, causality, p0"
                                                   : "label, color, at, causality", whose);
  const char *label = bg_build_string_opt(b, s, "label"), *color = bg_build_color_opt(b, s);
  const bg_ast_option *caus = bg_build_find_opt(s, "causality");
  const bg_ast_option *q0 = bg_build_find_opt(s, kind == BG_ELEM_I ? "p0" : "q0");
  bg_build_at_opt(b, p1, s);
  for (int k = 0; k < m->field_nport[f]; k++) {
    int pe = p1 + k;
    const bg_expr *v;
    m->elem_label[pe] = label;
    m->elem_color[pe] = color;
    m->elem_has_at[pe] = m->elem_has_at[p1];
    m->elem_at_x[pe] = m->elem_at_x[p1];
    m->elem_at_y[pe] = m->elem_at_y[p1];
    if (caus && (v = per_port(b, f, caus, k, 1)) != NULL) m->elem_causopt[pe] = caus_word(b, kind, v);
    if (q0 && kind != BG_ELEM_R && (v = per_port(b, f, q0, k, 0)) != NULL)
      m->elem_init[pe] = bg_build_init_expr(b, v);
  }
}
