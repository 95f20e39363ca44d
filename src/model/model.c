/* SPDX-License-Identifier: BSD-3-Clause */
/* The model compiler, part 1: the driver, declarations, bonds, params,
 * inputs and states. Elements and the other statements are in
 * model_stmt.c, expressions in model_expr.c, queries in model_query.c; the
 * growable arrays and the namespace every part uses in model_build.c. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr.h"
#include "model/model_int.h"

/* ---------------------------------------------------------------- arrays */
/* Moves every array into the model's arena (one owner for everything). */
static void move_to_arena(bg_model *m) {
#define BG_X_MOVE(type, name, cnt)                                          \
  {                                                                         \
    type *a = bg_arena_alloc(&m->arena, sizeof(type) * (size_t)(m->cnt ? m->cnt : 1)); \
    if (m->cnt) memcpy(a, m->name, sizeof(type) * (size_t)m->cnt);         \
    free(m->name);                                                          \
    m->name = a;                                                            \
  }
  BG_MODEL_ARRAYS(BG_X_MOVE)
#undef BG_X_MOVE
}

static void free_arrays(bg_model *m) {
#define BG_X_FREE(type, name, cnt) free(m->name);
  BG_MODEL_ARRAYS(BG_X_FREE)
#undef BG_X_FREE
}

/* ---------------------------------------------------------------- declarations */
static int kind_from_word(const char *w) {
  for (int k = 0; k < BG_ELEM_COUNT; k++)
    if (strcmp(bg_elem_kind_name(k), w) == 0) return k;
  return -1;
}

static void declare_element(bg_build *b, const bg_ast_stmt *s) {
  int kind = kind_from_word(s->kindword);
  if (kind < 0) BG_FATAL("parser let through element kind '%s'", s->kindword);
  if (s->is_field) bg_build_declare_field(b, s);
  else bg_build_new_elem(b, s, kind, s->name, s->name_loc);
}

/* Declares every name in file order (one namespace). */
static void declare_all(bg_build *b, int *nparam_decl) {
  bg_model *m = b->m;
  for (int i = 0; i < b->ast->nstmts; i++) {
    const bg_ast_stmt *s = &b->ast->stmts[i];
    if (s->kind == BG_ST_ELEMENT && bg_build_is_detector(s)) bg_build_declare_detector(b, s);
    else if (s->kind == BG_ST_ELEMENT) declare_element(b, s);
    else if (s->kind == BG_ST_PARAM) {
      if (bg_build_declare(b, s->name, s->name_loc, NS_PARAM, *nparam_decl) == 0) (*nparam_decl)++;
    } else if (s->kind == BG_ST_INPUT) {
      if (bg_build_declare(b, s->name, s->name_loc, NS_INPUT, m->ninput) != 0) continue;
      int k = bg_build_new(b, &m->ninput);
      m->input_name[k] = bg_build_strdup(b, s->name);
      m->input_loc[k] = s->name_loc;
    } else if (s->kind == BG_ST_STATE) {
      if (bg_build_declare(b, s->name, s->name_loc, NS_STATE, m->nstate) != 0) continue;
      int k = bg_build_new(b, &m->nstate);
      m->state_name[k] = bg_build_strdup(b, s->name);
      m->state_loc[k] = s->name_loc;
      m->state_init[k] = -1;
    }
  }
}

/* ---------------------------------------------------------------- bonds */
/* "K.x" where K is a field without port x: 1 (reported) naming its ports. */
static int unknown_port(bg_build *b, const char *name, bg_srcloc loc) {
  const char *dot = strrchr(name, '.');
  if (!dot) return 0;
  char head[512];
  snprintf(head, sizeof head, "%.*s", (int)(dot - name), name);
  const ns_entry *n = bg_build_lookup(b, head);
  if (!n || n->kind != NS_FIELD) return 0;
  const bg_model *m = b->m;
  int f = n->id;
  bg_strbuf ports = {0};
  for (int k = 0; k < m->field_nport[f]; k++)
    bg_sb_printf(&ports, "%s%s", k ? ", " : "", bg_elem_port_name(m, m->field_elemadr[f] + k));
  bg_diag_error(b->dg, loc, "%s field %s has no port '%s' (its ports: %s)",
                bg_elem_kind_name(m->field_kind[f]), head, dot + 1, ports.s ? ports.s : "");
  bg_sb_free(&ports);
  return 1;
}

/* The element id of a bond end, or -1 (reported). */
static int bond_end(bg_build *b, const char *name, bg_srcloc loc) {
  const ns_entry *n = bg_build_lookup(b, name);
  if (n && n->kind == NS_ELEM) return n->id;
  if (n && n->kind == NS_FIELD) {
    const bg_model *m = b->m;
    int f = n->id, p1 = m->field_elemadr[f];
    bg_diag_error(b->dg, loc, "'%s' is %s field with %d ports; a bond joins one of its ports "
                  "(e.g. %s)", name, bg_elem_kind_article(m->field_kind[f]), m->field_nport[f],
                  m->elem_name[p1]);
    return -1;
  }
  if (n && n->kind == NS_DETECTOR) {
    bg_diag_error(b->dg, loc, "'%s' is a detector (line %d); a detector has no bond: it reads "
                  "the node named in its statement", name, n->loc.line);
    return -1;
  }
  for (int i = 0; n && n->kind == NS_PARAM && i < b->nparam_named; i++)
    if (!strcmp(b->param_named[i], name)) return -1; /* said at the element */
  if (n) {
    bg_diag_error(b->dg, loc, "'%s' is %s (line %d); a bond joins elements and junctions",
                  name, bg_ns_what[n->kind], n->loc.line);
    return -1;
  }
  const char *s = bg_build_suggest(b, name, NULL, 0);
  const ns_entry *guess = s ? bg_build_lookup(b, s) : NULL;
  if (guess && guess->kind == NS_ELEM) b->elem_guessed[guess->id] = 1; /* see check_bond_count */
  if (unknown_port(b, name, loc)) return -1;
  if (bg_diags_unsure(b->dg, name)) return -1; /* declared on a line with a syntax error? */
  if (s) bg_diag_error(b->dg, loc, "undefined name '%s' (did you mean '%s'?)", name, s);
  else bg_diag_error(b->dg, loc, "undefined name '%s' (no element or junction has this name)", name);
  return -1;
}

static void add_bond(bg_build *b, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  int tail = bond_end(b, s->from, s->from_loc), head = bond_end(b, s->to, s->to_loc);
  if (tail >= 0 && tail == head) /* still recorded: bond ids stay in statement order */
    bg_diag_error(b->dg, s->to_loc, "a bond cannot join '%s' to itself", s->to);
  int k = bg_build_new(b, &m->nbond);
  m->bond_num[k] = s->number;
  m->bond_tail[k] = tail;
  m->bond_head[k] = head;
  m->bond_fix[k] = s->arrow == BG_ARROW_STROKE_HEAD   ? BG_FIX_HEAD
                   : s->arrow == BG_ARROW_STROKE_TAIL ? BG_FIX_TAIL : BG_FIX_NONE;
  m->bond_loc[k] = s->loc;
}

typedef struct numbered_bond {
  int num, bond;
} numbered_bond;

static int by_number_then_bond(const void *a, const void *b) {
  const numbered_bond *x = a, *y = b;
  if (x->num != y->num) return (x->num > y->num) - (x->num < y->num);
  return (x->bond > y->bond) - (x->bond < y->bond);
}

/* Explicit numbers must be unique: sorted, so a model of many bonds with
 * large numbers stays n log n and no array is sized by a number. */
static void check_unique_numbers(bg_build *b, const bg_ast_stmt **stmt) {
  bg_model *m = b->m;
  numbered_bond *nb = bg_xmalloc((size_t)(m->nbond + 1) * sizeof *nb);
  int n = 0;
  for (int k = 0; k < m->nbond; k++)
    if (m->bond_num[k]) nb[n++] = (numbered_bond){m->bond_num[k], k};
  qsort(nb, (size_t)n, sizeof *nb, by_number_then_bond);
  for (int i = 1; i < n; i++) {
    if (nb[i].num != nb[i - 1].num) continue;
    int first = i - 1;
    while (first > 0 && nb[first - 1].num == nb[i].num) first--;
    bg_diag_error(b->dg, stmt[nb[i].bond]->number_loc, "bond %d already defined at line %d",
                  nb[i].num, m->bond_loc[nb[first].bond].line);
    bg_diag_note(b->dg, m->bond_loc[nb[first].bond], "bond %d first defined here", nb[i].num);
  }
  free(nb);
}

/* Unnumbered bonds take the smallest free numbers in file order. */
static void number_bonds(bg_build *b, const bg_ast_stmt **stmt) {
  bg_model *m = b->m;
  int n = m->nbond;
  check_unique_numbers(b, stmt);
  char *taken = bg_xcalloc((size_t)n + 2, 1); /* numbers <= n+1 are all a bond can need */
  for (int k = 0; k < n; k++)
    if (m->bond_num[k] >= 1 && m->bond_num[k] <= n + 1) taken[m->bond_num[k]] = 1;
  int next = 1;
  for (int k = 0; k < n; k++) {
    if (m->bond_num[k] != 0) continue;
    while (taken[next]) next++;
    taken[next] = 1;
    m->bond_num[k] = next;
  }
  free(taken);
}

/* elem_bonds: per element its bonds in file order. */
static void index_bonds(bg_build *b) {
  bg_model *m = b->m;
  for (int k = 0; k < m->nbond; k++) {
    if (m->bond_tail[k] >= 0) m->elem_nbond[m->bond_tail[k]]++;
    if (m->bond_head[k] >= 0) m->elem_nbond[m->bond_head[k]]++;
  }
  int adr = 0;
  for (int e = 0; e < m->nelem; e++) {
    m->elem_bondadr[e] = adr;
    adr += m->elem_nbond[e];
    m->elem_nbond[e] = 0;
  }
  for (int i = 0; i < adr; i++) bg_build_new(b, &m->nbondref);
  for (int k = 0; k < m->nbond; k++) {
    int ends[2] = {m->bond_tail[k], m->bond_head[k]};
    for (int j = 0; j < 2; j++)
      if (ends[j] >= 0) m->elem_bonds[m->elem_bondadr[ends[j]] + m->elem_nbond[ends[j]]++] = k;
  }
}

/* The bond numbered num, or -1. */
static int bond_numbered(const bg_model *m, long num) {
  for (int k = 0; k < m->nbond; k++)
    if (m->bond_num[k] == num) return k;
  return -1;
}

/* A declared name e<N> or f<N> would hide the effort or flow of bond N, so
 * it is refused when bond N exists; otherwise it is an ordinary name (a
 * frequency f0, a junction f1 in a model with no bond 1). */
static void check_bond_names(bg_build *b) {
  for (int i = 0; i < b->nns; i++) {
    const char *name = b->ns[i].name;
    if ((name[0] != 'e' && name[0] != 'f') || !name[1] || strlen(name) > 11) continue;
    if (strspn(name + 1, "0123456789") != strlen(name + 1)) continue;
    int k = bond_numbered(b->m, strtol(name + 1, NULL, 10));
    if (k < 0) continue;
    bg_diag_error(b->dg, b->ns[i].loc, "'%s' is the %s of bond %d and cannot be declared",
                  name, name[0] == 'e' ? "effort" : "flow", b->m->bond_num[k]);
    bg_diag_note(b->dg, b->m->bond_loc[k], "bond %d is defined here", b->m->bond_num[k]);
  }
}

static void build_bonds(bg_build *b) {
  const bg_ast_stmt **stmt = NULL;
  int cap = 0;
  b->elem_guessed = bg_xcalloc((size_t)b->m->nelem + 1, 1);
  for (int i = 0; i < b->ast->nstmts; i++) {
    const bg_ast_stmt *s = &b->ast->stmts[i];
    if (s->kind != BG_ST_BOND) continue;
    int before = b->m->nbond;
    add_bond(b, s);
    if (b->m->nbond > cap) {
      cap = cap ? 2 * cap : 64;
      stmt = bg_xrealloc(stmt, (size_t)cap * sizeof *stmt);
    }
    stmt[before] = s;
  }
  number_bonds(b, stmt); /* bond options are read in model_stmt.c */
  free(stmt);
  index_bonds(b);
  check_bond_names(b);
}

/* ---------------------------------------------------------------- params */
typedef struct param_graph {
  const bg_ast_stmt **stmt; /* by param file index */
  int **dep;                /* param file indices each one uses */
  int *ndep;
  int n;
  bg_build *b;
  int cur;
} param_graph;

static void note_param_use(void *ctx, const bg_expr *name) {
  param_graph *g = ctx;
  const ns_entry *n = bg_build_lookup(g->b, name->str);
  if (!n || n->kind != NS_PARAM) return;
  int *nd = &g->ndep[g->cur];
  if ((*nd & (*nd - 1)) == 0) /* 0, 1, 2, 4, ...: grow to the next power of two */
    g->dep[g->cur] = bg_xrealloc(g->dep[g->cur], (size_t)(*nd ? 2 * *nd : 1) * sizeof(int));
  g->dep[g->cur][(*nd)++] = n->id;
}

/* Reports the cycle that closes at param `at`: the stack from `at` to its top. */
static void report_cycle(param_graph *g, const int *stack, int top, int at) {
  bg_strbuf sb = {0};
  int from = top;
  while (stack[from] != at) from--;
  for (int i = from; i <= top; i++) bg_sb_printf(&sb, "%s -> ", g->stmt[stack[i]]->name);
  bg_sb_puts(&sb, g->stmt[at]->name);
  bg_diag_error(g->b->dg, g->stmt[at]->name_loc, "cyclic param definition: %s", bg_sb_str(&sb));
  bg_sb_free(&sb);
}

/* Depth-first post-order with an explicit stack: dependencies first, otherwise
 * file order. state: 0 new, 1 on the stack, 2 done. Fills order[]. */
static int order_params(param_graph *g, int *order) {
  int *state = bg_xcalloc((size_t)g->n + 1, sizeof *state);
  int *stack = bg_xmalloc(((size_t)g->n + 1) * sizeof *stack);
  int *nexti = bg_xcalloc((size_t)g->n + 1, sizeof *nexti);
  int norder = 0;
  for (int root = 0; root < g->n; root++) {
    if (state[root]) continue;
    int top = 0;
    stack[0] = root;
    state[root] = 1;
    while (top >= 0) {
      int v = stack[top];
      if (nexti[v] < g->ndep[v]) {
        int w = g->dep[v][nexti[v]++];
        if (state[w] == 1) report_cycle(g, stack, top, w);
        if (state[w]) continue;
        state[w] = 1;
        stack[++top] = w;
      } else {
        state[v] = 2;
        order[norder++] = v;
        top--;
      }
    }
  }
  free(state);
  free(stack);
  free(nexti);
  return norder;
}

static void apply_overrides(bg_build *b, const bg_param_override *ov, int nov) {
  bg_model *m = b->m;
  bg_srcloc none = {0};
  for (int i = 0; i < nov; i++) {
    const ns_entry *n = bg_build_lookup(b, ov[i].name);
    if (n && n->kind == NS_PARAM && !isfinite(ov[i].value)) { /* nan, inf: every result would be */
      bg_diag_error(b->dg, none, "--set %s=%g: a param takes a finite number", ov[i].name,
                    isnan(ov[i].value) ? NAN : ov[i].value);
      continue;
    }
    if (n && n->kind == NS_PARAM) {
      m->param_value[b->param_id[n->id]] = ov[i].value;
      m->param_overridden[b->param_id[n->id]] = 1;
      continue;
    }
    if (bg_diags_unsure(b->dg, ov[i].name)) continue;
    const char *s = bg_build_suggest(b, ov[i].name, NULL, 0);
    const ns_entry *sn = s ? bg_build_lookup(b, s) : NULL;
    if (sn && sn->kind == NS_PARAM)
      bg_diag_error(b->dg, none, "--set %s: no param '%s' in the model (did you mean '%s'?)",
                    ov[i].name, ov[i].name, s);
    else
      bg_diag_error(b->dg, none, "--set %s: no param '%s' in the model", ov[i].name, ov[i].name);
  }
}

/* Params in dependency order, compiled, overridden, then evaluated. */
static void build_params(bg_build *b, int ndecl, const bg_param_override *ov, int nov) {
  bg_model *m = b->m;
  param_graph g = {bg_xcalloc((size_t)ndecl + 1, sizeof(void *)),
                   bg_xcalloc((size_t)ndecl + 1, sizeof(int *)),
                   bg_xcalloc((size_t)ndecl + 1, sizeof(int)), ndecl, b, 0};
  for (int i = 0, k = 0; i < b->ast->nstmts; i++) {
    const bg_ast_stmt *s = &b->ast->stmts[i];
    const ns_entry *n = s->kind == BG_ST_PARAM ? bg_build_lookup(b, s->name) : NULL;
    if (!n || n->kind != NS_PARAM || n->id != k || n->loc.line != s->name_loc.line ||
        n->loc.col != s->name_loc.col)
      continue; /* not a param, or a duplicate (reported) */
    g.stmt[k] = s;
    g.cur = k++;
    bg_build_names(s->expr, note_param_use, &g);
  }
  int *order = bg_xmalloc(((size_t)ndecl + 1) * sizeof *order);
  order_params(&g, order);
  b->param_id = bg_xmalloc(((size_t)ndecl + 1) * sizeof *b->param_id);
  for (int i = 0; i < ndecl; i++) {
    int id = bg_build_new(b, &m->nparam);
    b->param_id[order[i]] = id;
    m->param_name[id] = bg_build_strdup(b, g.stmt[order[i]]->name);
    m->param_desc[id] = bg_build_strdup(b, g.stmt[order[i]]->text);
    m->param_loc[id] = g.stmt[order[i]]->name_loc;
  }
  b->allow = 0;
  b->what = "a param (params may use numbers, pi and other params)";
  for (int i = 0; i < ndecl; i++) m->param_expr[b->param_id[i]] = bg_build_expr(b, g.stmt[i]->expr);
  apply_overrides(b, ov, nov);
  for (int id = 0; id < m->nparam; id++) {
    if (!m->param_overridden[id]) m->param_value[id] = bg_xeval(m, m->param_expr[id], NULL);
    double v = m->param_value[id];
    if (isnan(v)) /* 0/0, sqrt(-1), log(-1), inf - inf: it would surface later as another element's error */
      bg_diag_error(b->dg, m->param_loc[id], "param '%s' is not a number (NaN): its value is "
                    "undefined (0/0, the square root or logarithm of a negative, inf - inf)", m->param_name[id]);
    else if (isinf(v))
      bg_diag_warning(b->dg, m->param_loc[id], "param '%s' is %s", m->param_name[id],
                      v > 0 ? "infinite (inf)" : "minus infinity (-inf)");
  }
  for (int i = 0; i < ndecl; i++) free(g.dep[i]);
  free(g.dep);
  free(g.ndep);
  free(g.stmt);
  free(order);
}

/* ---------------------------------------------------------------- inputs, states */
static void build_inputs_states(bg_build *b) {
  bg_model *m = b->m;
  int input = 0, state = 0;
  for (int i = 0; i < b->ast->nstmts; i++) {
    const bg_ast_stmt *s = &b->ast->stmts[i];
    const ns_entry *n = s->name ? bg_build_lookup(b, s->name) : NULL;
    if (s->kind == BG_ST_INPUT && n && n->kind == NS_INPUT && n->loc.line == s->name_loc.line) {
      b->allow = ALLOW_TIME | ALLOW_INPUT;
      b->input_limit = input++;
      b->what = "an input (inputs may use t, params and inputs defined before them)";
      m->input_expr[n->id] = bg_build_expr(b, s->expr);
    } else if (s->kind == BG_ST_STATE && n && n->kind == NS_STATE &&
               n->loc.line == s->name_loc.line) {
      b->allow = ALLOW_TIME | ALLOW_INPUT | ALLOW_MODEL;
      b->input_limit = m->ninput;
      b->what = "a state equation";
      m->state_expr[n->id] = bg_build_expr(b, s->expr);
      state++;
    }
  }
  (void)state;
}

/* ---------------------------------------------------------------- driver */
static const char *file_stem(bg_build *b, const char *path) {
  if (!strcmp(path, "<stdin>")) return "stdin"; /* bgdraw - */
  const char *base = strrchr(path, '/');
  base = base ? base + 1 : path;
  const char *dot = strrchr(base, '.');
  size_t n = dot && dot != base ? (size_t)(dot - base) : strlen(base);
  if (n == 0) return "model";
  return bg_arena_strndup(&b->m->arena, base, n);
}

static const char *dir_of(bg_build *b, const char *path) {
  const char *slash = strrchr(path, '/');
  if (!slash) return ".";
  return bg_arena_strndup(&b->m->arena, path, (size_t)(slash - path + (slash == path)));
}

static void build_free(bg_build *b) {
  free(b->ns);
  bg_strindex_free(&b->names);
  free(b->elem_stmt);
  free(b->param_id);
  free(b->elem_guessed);
  free(b->param_named);
}

bg_model *bg_model_compile_flat(const bg_ast *ast, const bg_param_override *ov, int nov,
                                bg_diags *dg) {
  bg_model *m = bg_xcalloc(1, sizeof *m);
  bg_build b;
  memset(&b, 0, sizeof b);
  b.m = m;
  b.ast = ast;
  b.dg = dg;
  b.elem = b.law_elem = b.field = -1;
  int errors0 = bg_diags_failures(dg), ndecl = 0;
  const char *path = ast->path ? ast->path : "";
  m->path = bg_arena_strdup(&m->arena, path);
  m->name = file_stem(&b, path);
  b.base_dir = dir_of(&b, path);
  m->sim.solver = "auto";
  m->layout.engine = "dot";
  m->layout.rankdir = "LR";
  declare_all(&b, &ndecl);
  build_bonds(&b);
  bg_build_detectors(&b);
  build_params(&b, ndecl, ov, nov);
  build_inputs_states(&b);
  bg_build_elements(&b);
  bg_build_statements(&b);
  build_free(&b);
  if (bg_diags_failures(dg) > errors0) {
    free_arrays(m);
    bg_arena_free(&m->arena);
    free(m);
    return NULL;
  }
  move_to_arena(m);
  bg_model_hash_names(m);
  return m;
}

void bg_model_free(bg_model *m) {
  if (!m) return;
  bg_arena_free(&m->arena);
  free(m);
}
