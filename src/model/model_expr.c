/* SPDX-License-Identifier: BSD-3-Clause */
/* The model compiler, part 2: expressions. Resolves names to ids and emits
 * bg_xnode trees (children before parents), records modulating signals,
 * loads table() data, and checks laws for linearity. Recursion follows the
 * AST, whose depth the parser limits. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr.h"
#include "model/model_int.h"
#include "lang/lang.h"

#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* A placeholder after an error (the compile fails anyway). */
static int bad(bg_build *b, bg_srcloc loc) { return bg_build_num(b, NAN, loc); }

/* ---------------------------------------------------------------- signals */
/* Records a read of a model variable by the element being compiled: a
 * signal from `from` (element id, -1 for states and e7/f7), deduplicated. */
static void use_model_var(bg_build *b, int from, const bg_expr *e) {
  if (!b->modvar) {
    b->modvar = e->text;
    b->modvar_loc = e->loc;
  }
  if (b->elem < 0) return;
  bg_model *m = b->m;
  for (int i = 0; i < m->nsignal; i++)
    if (m->signal_to[i] == b->elem && m->signal_from[i] == from &&
        (from >= 0 || strcmp(m->signal_var[i], e->text) == 0))
      return;
  int k = bg_build_new(b, &m->nsignal);
  m->signal_from[k] = from;
  m->signal_to[k] = b->elem;
  m->signal_var[k] = bg_build_strdup(b, e->text);
}

static int check_allowed(bg_build *b, int need, const bg_expr *e) {
  if (b->allow & need) return 1;
  bg_diag_error(b->dg, e->loc, "'%s' cannot be used in %s", e->text, b->what);
  return 0;
}

/* ---------------------------------------------------------------- law variables */
/* The node for the law element's own e, f, q or p; -1 if `v` is not one. */
static int own_var(bg_build *b, char v, const bg_expr *e) {
  bg_model *m = b->m;
  int el = b->law_elem, kind = m->elem_kind[el];
  if (!(v == 'e' || v == 'f' || (v == 'q' && kind == BG_ELEM_C) || (v == 'p' && kind == BG_ELEM_I)))
    return -1;
  if (v == b->law_lhs) {
    bg_diag_error(b->dg, e->loc, "the right-hand side of %s's law cannot use its left-hand side '%c'",
                  m->elem_name[el], v);
    return bad(b, e->loc);
  }
  static const char *const forms[] = {[BG_ELEM_C] = "e = F(q)", [BG_ELEM_I] = "f = F(p)"};
  if (kind != BG_ELEM_R && v != (kind == BG_ELEM_C ? 'q' : 'p')) {
    bg_diag_error(b->dg, e->loc, "%s law is '%s': '%c' cannot be used in it",
                  bg_elem_kind_article(kind), forms[kind], v);
    return bad(b, e->loc);
  }
  if (v == 'q' || v == 'p') return bg_build_ref(b, BG_X_STORE, el, e->loc);
  int bond = bg_elem_port_bond(m, el);
  if (bond < 0) return bad(b, e->loc); /* its bond count is reported elsewhere */
  int k = bg_build_ref(b, v == 'e' ? BG_X_EFFORT : BG_X_FLOW, bond, e->loc);
  if (v == 'e' || m->bond_head[bond] == el) return k;
  /* The bond points out of the R: the element's own flow (power into it
   * positive) is the bond's flow negated, as in the value form e = -R f. */
  int neg = bg_build_node(b, BG_X_NEG, e->loc);
  m->xnode[neg].nargs = 1;
  m->xnode[neg].arg[0] = k;
  return neg;
}

/* ---------------------------------------------------------------- names */
static int bond_var(bg_build *b, const bg_expr *e) {
  /* digits only (is_bond_var); beyond int range it names no bond, and must
   * not wrap around to a small one (e4294967298 is not e2) */
  errno = 0;
  long num = strtol(e->str + 1, NULL, 10);
  int bond = errno || num > INT_MAX ? -1 : bg_model_find_bond(b->m, (int)num);
  if (bond < 0) {
    bg_diag_error(b->dg, e->loc, "'%s': the model has no bond %s", e->str, e->str + 1);
    return bad(b, e->loc);
  }
  if (!check_allowed(b, ALLOW_MODEL, e)) return bad(b, e->loc);
  use_model_var(b, -1, e);
  return bg_build_ref(b, e->str[0] == 'e' ? BG_X_EFFORT : BG_X_FLOW, bond, e->loc);
}

static int is_bond_var(const char *s) {
  if ((s[0] != 'e' && s[0] != 'f') || !s[1]) return 0;
  for (const char *c = s + 1; *c; c++)
    if (*c < '0' || *c > '9') return 0;
  return 1;
}

static int undefined(bg_build *b, const bg_expr *e) {
  static const char *const extra[] = {"t", "pi"};
  if (bg_diags_unsure(b->dg, e->str)) return bad(b, e->loc); /* on a dropped line? */
  const char *s = bg_build_suggest(b, e->str, extra, COUNT(extra));
  if (s) bg_diag_error(b->dg, e->loc, "undefined name '%s' (did you mean '%s'?)", e->str, s);
  else bg_diag_error(b->dg, e->loc, "undefined name '%s'", e->str);
  return bad(b, e->loc);
}

static int field_node(bg_build *b, int el, const char *f, bg_srcloc loc);

/* name: t | pi | e7 | f7 | own law variable | param | input | state | detector */
/* A port variable in a field's law: e2, f1, q3 by the port's number. */
static int field_name_var(bg_build *b, const bg_expr *e) {
  const char *s = e->str;
  /* p1, p2 are an I field's momenta; elsewhere p1 stays an ordinary name */
  const char *letters = b->m->field_kind[b->field] == BG_ELEM_I ? "efqp" : "efq";
  if (!s[0] || !strchr(letters, s[0])) return -1;
  if (!s[1]) {
    bg_diag_error(b->dg, e->loc, "in a field's laws, name the port's variable (%c1, %c2, "
                  "PORT.%c), not '%s'", s[0], s[0], s[0], s);
    return bad(b, e->loc);
  }
  if (strspn(s + 1, "0123456789") != strlen(s + 1) || strlen(s + 1) > 7) return -1;
  return bg_build_port_var(b, NULL, atoi(s + 1), s[0], e);
}

/* A field's variables are its ports': a message for the field's bare name. */
static int field_not_value(bg_build *b, const bg_expr *e, int f) {
  const bg_model *m = b->m;
  bg_diag_error(b->dg, e->loc, "'%s' is %s field; use a variable of one of its ports (e.g. "
                "%s.%s)", e->str, bg_elem_kind_article(m->field_kind[f]),
                m->elem_name[m->field_elemadr[f]], m->field_kind[f] == BG_ELEM_C ? "q"
                : m->field_kind[f] == BG_ELEM_I ? "p" : "e");
  return bad(b, e->loc);
}

static int compile_name(bg_build *b, const bg_expr *e) {
  if (b->field >= 0) {
    int k = field_name_var(b, e);
    if (k >= 0) return k;
  }
  if (b->law_elem >= 0 && !e->str[1]) {
    int k = own_var(b, e->str[0], e);
    if (k >= 0) return k;
  }
  if (strcmp(e->str, "pi") == 0) return bg_build_num(b, 3.14159265358979323846, e->loc);
  if (strcmp(e->str, "t") == 0)
    return check_allowed(b, ALLOW_TIME, e) ? bg_build_node(b, BG_X_TIME, e->loc) : bad(b, e->loc);
  const ns_entry *n = bg_build_lookup(b, e->str); /* a declared f0 is not a bond variable */
  if (!n && is_bond_var(e->str)) return bond_var(b, e);
  if (!n) return undefined(b, e);
  switch (n->kind) {
  case NS_PARAM: return bg_build_ref(b, BG_X_PARAM, b->param_id[n->id], e->loc);
  case NS_INPUT:
    if (!check_allowed(b, ALLOW_INPUT, e)) return bad(b, e->loc);
    if (!(b->allow & ALLOW_MODEL) && n->id >= b->input_limit) {
      bg_diag_error(b->dg, e->loc, "input '%s' is used before its definition at line %d",
                    e->str, n->loc.line);
      return bad(b, e->loc);
    }
    return bg_build_ref(b, BG_X_INPUT, n->id, e->loc);
  case NS_STATE:
    if (!check_allowed(b, ALLOW_MODEL, e)) return bad(b, e->loc);
    use_model_var(b, -1, e);
    return bg_build_ref(b, BG_X_STATE, n->id, e->loc);
  case NS_DETECTOR: { /* its node's effort or flow (docs/format.md, "Detectors") */
    int el = b->m->det_node[n->id];
    if (el < 0) return bad(b, e->loc); /* reported with the detector */
    if (!check_allowed(b, ALLOW_MODEL, e)) return bad(b, e->loc);
    use_model_var(b, el, e);
    return field_node(b, el, b->m->det_var[n->id] == 'e' ? "e" : "f", e->loc);
  }
  case NS_FIELD: return field_not_value(b, e, n->id);
  default:
    bg_diag_error(b->dg, e->loc, "'%s' is %s, not a value; use one of its variables "
                  "(e.g. %s.%s)", e->str, bg_elem_kind_article(b->m->elem_kind[n->id]), e->str,
                  b->m->elem_kind[n->id] == BG_ELEM_J1 ? "f" : "e");
    return bad(b, e->loc);
  }
}

/* The valid fields of an element kind, as text for messages. */
static const char *fields_of(int kind) {
  switch (kind) {
  case BG_ELEM_C: return "e, f, q";
  case BG_ELEM_I: return "e, f, p";
  case BG_ELEM_TF: case BG_ELEM_MTF: case BG_ELEM_GY: case BG_ELEM_MGY: return "e1, f1, e2, f2";
  case BG_ELEM_J0: return "e";
  case BG_ELEM_J1: return "f";
  default: return "e, f";
  }
}

/* The node of field f of element el; -2 if the kind has no such field. */
static int field_node(bg_build *b, int el, const char *f, bg_srcloc loc) {
  const bg_model *m = b->m;
  int kind = m->elem_kind[el], bond = -1, op = f[0] == 'e' ? BG_X_EFFORT : BG_X_FLOW;
  if (bg_elem_is_oneport(kind) && (!strcmp(f, "e") || !strcmp(f, "f"))) bond = bg_elem_port_bond(m, el);
  else if ((kind == BG_ELEM_C && !strcmp(f, "q")) || (kind == BG_ELEM_I && !strcmp(f, "p")))
    return bg_build_ref(b, BG_X_STORE, el, loc);
  else if (bg_elem_is_twoport(kind) && (!strcmp(f, "e1") || !strcmp(f, "f1")))
    bond = bg_elem_in_bond(m, el);
  else if (bg_elem_is_twoport(kind) && (!strcmp(f, "e2") || !strcmp(f, "f2")))
    bond = bg_elem_out_bond(m, el);
  else if ((kind == BG_ELEM_J0 && !strcmp(f, "e")) || (kind == BG_ELEM_J1 && !strcmp(f, "f")))
    bond = m->elem_nbond[el] ? m->elem_bonds[m->elem_bondadr[el]] : -1;
  else return -2;
  if (bond < 0) return bad(b, loc); /* a wrong bond count is reported with the element */
  return bg_build_ref(b, op, bond, loc);
}

/* field: X.e | X.f | X.q | X.p | X.e1 ... | J.e | J.f */
static int compile_field(bg_build *b, const bg_expr *e) {
  if (b->field >= 0 && strchr("efqp", e->field[0]) && !e->field[1]) {
    /* el.e, or K.el.e with the field's own name: a port's own variable */
    const char *port = e->str, *fname = b->m->field_name[b->field];
    size_t nf = strlen(fname);
    if (strncmp(port, fname, nf) == 0 && port[nf] == '.') port += nf + 1;
    int k = bg_build_port_var(b, port, 0, e->field[0], e);
    if (k >= 0) return k;
  }
  const ns_entry *n = bg_build_lookup(b, e->str);
  if (n && n->kind == NS_FIELD) return field_not_value(b, e, n->id);
  if (!n) return undefined(b, e);
  if (n->kind != NS_ELEM) {
    bg_diag_error(b->dg, e->loc, "'%s' is %s and has no fields", e->str, bg_ns_what[n->kind]);
    return bad(b, e->loc);
  }
  int el = n->id, kind = b->m->elem_kind[el];
  if (el == b->law_elem && !e->field[1]) {
    int k = own_var(b, e->field[0], e);
    if (k >= 0) return k;
  }
  int k = field_node(b, el, e->field, e->loc);
  if (k == -2) {
    bg_diag_error(b->dg, e->field_loc, "%s '%s' has no variable '%s' (valid: %s)",
                  bg_elem_kind_name(kind), e->str, e->field, fields_of(kind));
    return bad(b, e->loc);
  }
  if (!check_allowed(b, ALLOW_MODEL, e)) return bad(b, e->loc);
  use_model_var(b, el, e);
  return k;
}

/* ---------------------------------------------------------------- tables */
static int new_table(bg_build *b, const double *x, const double *y, int n) {
  bg_model *m = b->m;
  int t = bg_build_new(b, &m->ntable);
  m->table_adr[t] = m->ntabledata;
  m->table_n[t] = n;
  for (int i = 0; i < n; i++) {
    int k = bg_build_new(b, &m->ntabledata);
    m->table_x[k] = x[i];
    m->table_y[k] = y[i];
  }
  return t;
}

/* A table from an inline matrix [x0, y0; x1, y1; ...]; -1 after an error. */
static int inline_table(bg_build *b, const bg_expr *mat) {
  if (mat->ncols != 2 || mat->nrows < 1) {
    bg_diag_error(b->dg, mat->loc, "a table needs two columns (x, y), one row per point: "
                  "[x0, y0; x1, y1; ...]");
    return -1;
  }
  int n = mat->nrows;
  double *xy = bg_xmalloc(2 * (size_t)n * sizeof *xy);
  for (int i = 0; i < 2 * n; i++) xy[i] = bg_build_const(b, mat->args[i], "table data");
  double *x = bg_xmalloc((size_t)n * sizeof *x), *y = bg_xmalloc((size_t)n * sizeof *y);
  int ok = 1;
  for (int i = 0; i < n; i++) {
    x[i] = xy[2 * i];
    y[i] = xy[2 * i + 1];
    if (ok && i > 0 && !(x[i] > x[i - 1])) {
      bg_diag_error(b->dg, mat->args[2 * i]->loc,
                    "table x values must increase strictly (row %d: %g after %g)", i + 1, x[i],
                    x[i - 1]);
      ok = 0;
    }
  }
  int t = ok ? new_table(b, x, y, n) : -1;
  free(xy);
  free(x);
  free(y);
  return t;
}

/* Parses one CSV data line "x, y" (or "x y"); 1 on success. */
static int csv_pair(const char *line, double *x, double *y) {
  char *end;
  errno = 0;
  *x = strtod(line, &end);
  if (end == line) return 0;
  const char *p = end;
  while (*p == ' ' || *p == '\t') p++;
  if (*p == ',' || *p == ';') p++;
  *y = strtod(p, &end);
  if (end == p) return 0;
  while (*end == ' ' || *end == '\t' || *end == '\r' || *end == ',') end++;
  return *end == '\0' || *end == '#';
}

typedef struct csv_data {
  double *x, *y;
  int n, cap;
} csv_data;

/* Reads the lines of a table file into d; returns 0 or reports at `at`. */
static int csv_read(bg_build *b, const char *shown, char *text, csv_data *d, bg_srcloc at) {
  int lineno = 0, seen_data = 0;
  for (char *line = text; line; ) {
    char *nl = strchr(line, '\n');
    if (nl) *nl = '\0';
    lineno++;
    char *p = line;
    while (*p == ' ' || *p == '\t' || *p == '\r') p++;
    if (*p && *p != '#') {
      double x, y;
      if (!csv_pair(p, &x, &y)) {
        if (seen_data) { /* only the first line may be a header */
          bg_diag_error(b->dg, at, "table file '%s' line %d: expected two numbers 'x, y'", shown,
                        lineno);
          return -1;
        }
      } else {
        if (d->n && !(x > d->x[d->n - 1])) {
          bg_diag_error(b->dg, at, "table file '%s' line %d: x values must increase strictly "
                        "(%g after %g)", shown, lineno, x, d->x[d->n - 1]);
          return -1;
        }
        if (d->n == d->cap) {
          d->cap = d->cap ? 2 * d->cap : 64;
          d->x = bg_xrealloc(d->x, (size_t)d->cap * sizeof *d->x);
          d->y = bg_xrealloc(d->y, (size_t)d->cap * sizeof *d->y);
        }
        d->x[d->n] = x;
        d->y[d->n++] = y;
      }
      seen_data = 1;
    }
    line = nl ? nl + 1 : NULL;
  }
  return 0;
}

/* A table from a CSV file, relative to the model's directory. */
static int file_table(bg_build *b, const bg_expr *file, bg_srcloc at) {
  char path[4096];
  if (file->str[0] == '/') snprintf(path, sizeof path, "%s", file->str);
  else snprintf(path, sizeof path, "%s/%s", b->base_dir, file->str);
  size_t len;
  char *text = bg_read_file(path, &len);
  if (!text) {
    bg_diag_error(b->dg, at, "cannot read table file '%s' (%s): %s", file->str, path,
                  bg_file_strerror(errno));
    return -1;
  }
  csv_data d = {0};
  int t = -1;
  if (csv_read(b, file->str, text, &d, at) == 0) {
    if (d.n == 0) bg_diag_error(b->dg, at, "table file '%s' has no data lines", file->str);
    else {
      t = new_table(b, d.x, d.y, d.n);
      b->m->table_path[t] = bg_build_strdup(b, path); /* for make dependency files */
    }
  }
  free(d.x);
  free(d.y);
  free(text);
  return t;
}

/* table(x, "file.csv") | table(x, [x0, y0; ...]) */
static int compile_table(bg_build *b, const bg_expr *e) {
  if (e->nargs != 2) {
    bg_diag_error(b->dg, e->loc, "table() takes 2 arguments (x, \"file.csv\" or [x0, y0; ...]), not %d",
                  e->nargs);
    return bad(b, e->loc);
  }
  int x = bg_build_expr(b, e->args[0]), t = -1;
  const bg_expr *data = e->args[1];
  if (data->kind == BG_EX_STR) t = file_table(b, data, e->loc);
  else if (data->kind == BG_EX_MATRIX) t = inline_table(b, data);
  else bg_diag_error(b->dg, data->loc, "table() data must be a file name \"file.csv\" or a matrix [x0, y0; x1, y1; ...]");
  if (t < 0) return bad(b, e->loc);
  int k = bg_build_ref(b, BG_X_TABLE, t, e->loc);
  b->m->xnode[k].nargs = 1;
  b->m->xnode[k].arg[0] = x;
  return k;
}

/* ---------------------------------------------------------------- calls, operators */
static const char *const func_names[] = {
    "abs", "sign", "sqrt", "exp", "log", "log10", "sin", "cos", "tan", "asin", "acos",
    "atan", "atan2", "sinh", "cosh", "tanh", "min", "max", "pow", "floor", "ceil", "if",
    "step", "ramp", "pulse", "sat", "hyst", "stick", "table"};

/* Numbers, pi and params only: the tree's value is known now. */
static int const_tree(const bg_model *m, int k) {
  const bg_xnode *x = &m->xnode[k];
  if (x->op == BG_X_NUM || x->op == BG_X_PARAM) return 1;
  if (x->op == BG_X_CALL && x->ref == BG_FN_IF) return 0; /* keep it simple: if() may hide anything */
  if (x->op == BG_X_TIME || x->op == BG_X_INPUT || x->op == BG_X_STATE || x->op == BG_X_EFFORT ||
      x->op == BG_X_FLOW || x->op == BG_X_STORE || x->op == BG_X_TABLE)
    return 0;
  for (int i = 0; i < x->nargs; i++)
    if (!const_tree(m, x->arg[i])) return 0;
  return x->nargs > 0;
}

/* hyst(x, lo, hi) needs lo < hi, stick(v, F, Fs) a limit Fs >= 0, where
 * they are constants (docs/format.md, "Memory"); otherwise the run would
 * switch at every event and stop as chattering, far from the mistake. */
static void check_memory(bg_build *b, const bg_expr *e, int fn, const int *args) {
  const bg_model *m = b->m;
  if (fn == BG_FN_HYST && const_tree(m, args[1]) && const_tree(m, args[2])) {
    double lo = bg_xeval(m, args[1], NULL), hi = bg_xeval(m, args[2], NULL);
    if (!isnan(lo) && !isnan(hi) && !(lo < hi))
      bg_diag_error(b->dg, e->args[1]->loc, "hyst(x, lo, hi) needs lo below hi: here lo = %g, hi = %g", lo, hi);
  }
  if (fn == BG_FN_STICK && const_tree(m, args[2])) {
    double lim = bg_xeval(m, args[2], NULL);
    if (!isnan(lim) && !(lim >= 0))
      bg_diag_error(b->dg, e->args[2]->loc, "stick(v, F, Fs) needs a static friction limit Fs >= 0: here %g", lim);
  }
}

static int compile_call(bg_build *b, const bg_expr *e) {
  if (strcmp(e->str, "table") == 0) return compile_table(b, e);
  int lo, hi, fn = bg_func_lookup(e->str, &lo, &hi);
  if (fn < 0) {
    const char *s = bg_build_suggest(NULL, e->str, func_names, COUNT(func_names));
    if (s) bg_diag_error(b->dg, e->loc, "unknown function '%s' (did you mean '%s'?)", e->str, s);
    else bg_diag_error(b->dg, e->loc, "unknown function '%s'", e->str);
    return bad(b, e->loc);
  }
  if (e->nargs < lo || e->nargs > hi) {
    bg_diag_error(b->dg, e->loc, "%s() takes %d argument%s, not %d", e->str, lo, lo == 1 ? "" : "s",
                  e->nargs);
    return bad(b, e->loc);
  }
  int args[3];
  for (int i = 0; i < e->nargs; i++) args[i] = bg_build_expr(b, e->args[i]);
  int k = bg_build_ref(b, BG_X_CALL, fn, e->loc);
  b->m->xnode[k].nargs = (unsigned char)e->nargs;
  for (int i = 0; i < e->nargs; i++) b->m->xnode[k].arg[i] = args[i];
  if (fn == BG_FN_HYST || fn == BG_FN_STICK) check_memory(b, e, fn, args);
  return k;
}

static int xop_of(int op) {
  static const int map[] = {
      [BG_OP_ADD] = BG_X_ADD, [BG_OP_SUB] = BG_X_SUB, [BG_OP_MUL] = BG_X_MUL,
      [BG_OP_DIV] = BG_X_DIV, [BG_OP_POW] = BG_X_POW, [BG_OP_LT] = BG_X_LT,
      [BG_OP_LE] = BG_X_LE,   [BG_OP_GT] = BG_X_GT,   [BG_OP_GE] = BG_X_GE,
      [BG_OP_EQ] = BG_X_EQ,   [BG_OP_NE] = BG_X_NE,   [BG_OP_AND] = BG_X_AND,
      [BG_OP_OR] = BG_X_OR,   [BG_OP_NEG] = BG_X_NEG, [BG_OP_NOT] = BG_X_NOT};
  return map[op];
}

static int compile_op(bg_build *b, const bg_expr *e) {
  int args[2] = {0, 0};
  for (int i = 0; i < e->nargs && i < 2; i++) args[i] = bg_build_expr(b, e->args[i]);
  int k = bg_build_node(b, xop_of(e->op), e->loc);
  b->m->xnode[k].nargs = (unsigned char)e->nargs;
  b->m->xnode[k].arg[0] = args[0];
  b->m->xnode[k].arg[1] = args[1];
  return k;
}

int bg_build_expr(bg_build *b, const bg_expr *e) {
  switch (e->kind) {
  case BG_EX_NUM: return bg_build_num(b, e->num, e->loc);
  case BG_EX_NAME: return compile_name(b, e);
  case BG_EX_FIELD: return compile_field(b, e);
  case BG_EX_CALL: return compile_call(b, e);
  case BG_EX_UNARY:
  case BG_EX_BINARY: return compile_op(b, e);
  case BG_EX_STR:
    bg_diag_error(b->dg, e->loc, "a string is not a number (strings are only table() file "
                  "names and option values)");
    return bad(b, e->loc);
  case BG_EX_MATRIX:
    bg_diag_error(b->dg, e->loc, "a matrix is only allowed as table() data");
    return bad(b, e->loc);
  default:
    bg_diag_error(b->dg, e->loc, "a tuple (a, b) is only allowed as an option value such as at = (X, Y)");
    return bad(b, e->loc);
  }
}

double bg_build_const(bg_build *b, const bg_expr *e, const char *what) {
  int allow = b->allow, elem = b->elem, law = b->law_elem;
  const char *w = b->what;
  b->allow = 0;
  b->elem = b->law_elem = -1;
  b->what = what;
  int root = bg_build_expr(b, e);
  b->allow = allow;
  b->elem = elem;
  b->law_elem = law;
  b->what = w;
  return bg_xeval(b->m, root, NULL);
}

void bg_build_names(const bg_expr *e, void (*fn)(void *ctx, const bg_expr *name), void *ctx) {
  if (!e) return;
  if (e->kind == BG_EX_NAME) fn(ctx, e);
  for (int i = 0; i < e->nargs; i++) bg_build_names(e->args[i], fn, ctx);
}

/* ---------------------------------------------------------------- linearity */
/* Degree of the tree in the variable (op, ref): 0 free of it, 1 affine, 2 other. */
static int degree(const bg_model *m, int k, int op, int ref) {
  const bg_xnode *x = &m->xnode[k];
  if (x->op == op && x->ref == ref) return 1;
  int d[3] = {0, 0, 0}, any = 0;
  for (int i = 0; i < x->nargs; i++) {
    d[i] = degree(m, x->arg[i], op, ref);
    if (d[i] > any) any = d[i];
  }
  switch (x->op) {
  case BG_X_ADD: case BG_X_SUB: case BG_X_NEG: return any;
  case BG_X_MUL: return d[0] && d[1] ? 2 : d[0] + d[1];
  case BG_X_DIV: return d[1] ? 2 : d[0];
  case BG_X_POW:
    if (!any) return 0;
    return !d[1] && m->xnode[x->arg[1]].op == BG_X_NUM && m->xnode[x->arg[1]].num == 1 ? d[0] : 2;
  case BG_X_CALL:
    if (x->ref == BG_FN_IF) return d[0] ? 2 : (d[1] > d[2] ? d[1] : d[2]);
    return any ? 2 : 0;
  default: return any ? 2 : 0;
  }
}

int bg_build_is_affine(const bg_model *m, int root, int op, int ref) {
  return degree(m, root, op, ref) <= 1;
}
