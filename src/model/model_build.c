/* SPDX-License-Identifier: BSD-3-Clause */
/* The model compiler's shared state (model_int.h), under the driver
 * (model.c) and its parts (model_stmt.c, model_expr.c, model_field.c,
 * model_detect.c): the model's growable arrays, strings in its arena, the
 * namespace (declarations, look-ups, "did you mean" suggestions), new
 * elements and the constructors of expression nodes. */
#include <stdlib.h>
#include <string.h>

#include "model/expr.h"
#include "model/model_int.h"

/* ---------------------------------------------------------------- arrays */
static void *reserve(void *p, int n, int *cap, size_t size) {
  if (n < *cap) return p;
  int ncap = *cap ? 2 * *cap : 16;
  while (ncap <= n) ncap *= 2;
  p = bg_xrealloc(p, (size_t)ncap * size);
  memset((char *)p + (size_t)*cap * size, 0, (size_t)(ncap - *cap) * size);
  *cap = ncap;
  return p;
}

int bg_build_new(bg_build *b, int *count) {
  bg_model *m = b->m;
#define BG_X_GROW(type, name, cnt) \
  if (&m->cnt == count) m->name = reserve(m->name, *count, &b->cap.name, sizeof(type));
  BG_MODEL_ARRAYS(BG_X_GROW)
#undef BG_X_GROW
  return (*count)++;
}

const char *bg_build_strdup(bg_build *b, const char *s) {
  return s ? bg_arena_strdup(&b->m->arena, s) : NULL;
}

/* ---------------------------------------------------------------- namespace */
const ns_entry *bg_build_lookup(const bg_build *b, const char *name) {
  int i = bg_strindex_lookup(&b->names, BG_STRKEYS(b->ns, name), name);
  return i >= 0 ? &b->ns[i] : NULL;
}


/* Declares a name; reports duplicates and reserved names. 0 on success. */
int bg_build_declare(bg_build *b, const char *name, bg_srcloc loc, ns_kind kind, int id) {
  const ns_entry *old = bg_build_lookup(b, name);
  if (old && old->kind == NS_PARAM && kind == NS_ELEM) {
    bg_diag_error(b->dg, loc, "the element '%s' has the name of the param '%s' (line %d): params "
                  "and elements share one namespace; name the param after what it is "
                  "(param %s_value = ...) or the element after its role", name, name,
                  old->loc.line, name);
    if (b->nparam_named == b->param_named_cap) {
      b->param_named_cap = b->param_named_cap ? 2 * b->param_named_cap : 8;
      b->param_named = bg_xrealloc(b->param_named, (size_t)b->param_named_cap * sizeof *b->param_named);
    }
    b->param_named[b->nparam_named++] = name;
    return -1;
  }
  if (old) {
    bg_diag_error(b->dg, loc, "'%s' already defined at line %d", name, old->loc.line);
    bg_diag_note(b->dg, old->loc, "'%s' first defined here", name);
    return -1;
  }
  if (strcmp(name, "t") == 0 || strcmp(name, "pi") == 0) { /* e<N>, f<N>: check_bond_names */
    bg_diag_error(b->dg, loc, "'%s' is reserved (%s) and cannot be declared", name,
                  name[0] == 't' ? "time" : "the constant pi");
    return -1;
  }
  if (b->nns == b->nscap) {
    b->nscap = b->nscap ? 2 * b->nscap : 64;
    b->ns = bg_xrealloc(b->ns, (size_t)b->nscap * sizeof *b->ns);
  }
  b->ns[b->nns++] = (ns_entry){name, kind, id, loc};
  bg_strindex_add(&b->names, BG_STRKEYS(b->ns, name), b->nns);
  return 0;
}

static int common_prefix(const char *a, const char *b) {
  int n = 0;
  while (a[n] && a[n] == b[n]) n++;
  return n;
}

/* Closest by edit distance; ties go to the longer common prefix ("sinn": sin, not sign). */
static void consider(const char *name, const char *cand, const char **best, int *bestd) {
  int d = bg_edit_distance(name, cand);
  if (d == 0) return;
  if (d < *bestd || (d == *bestd && *best && common_prefix(name, cand) > common_prefix(name, *best))) {
    *bestd = d;
    *best = cand;
  }
}

const char *bg_build_suggest(const bg_build *b, const char *name, const char *const *extra,
                             int nextra) {
  const char *best = NULL;
  int bestd = strlen(name) < 3 ? 2 : 3; /* at most 1 edit for short names, else 2 */
  for (int i = 0; b && i < b->nns; i++) consider(name, b->ns[i].name, &best, &bestd);
  for (int i = 0; i < nextra; i++) consider(name, extra[i], &best, &bestd);
  return best;
}

const char *const bg_ns_what[6] = {"an element", "a param", "an input", "a state", "a detector",
                                    "a field"};

int bg_build_new_elem(bg_build *b, const bg_ast_stmt *s, int kind, const char *name, bg_srcloc loc) {
  bg_model *m = b->m;
  name = bg_build_strdup(b, name);
  if (bg_build_declare(b, name, loc, NS_ELEM, m->nelem) != 0) return -1;
  int e = bg_build_new(b, &m->nelem);
  m->elem_kind[e] = kind;
  m->elem_name[e] = name;
  m->elem_loc[e] = loc;
  m->elem_expr[e] = m->elem_init[e] = m->elem_inst[e] = m->elem_field[e] = -1;
  if (m->nelem > b->elem_stmt_cap) {
    b->elem_stmt_cap = b->elem_stmt_cap ? 2 * b->elem_stmt_cap : 64;
    b->elem_stmt = bg_xrealloc(b->elem_stmt, (size_t)b->elem_stmt_cap * sizeof *b->elem_stmt);
  }
  b->elem_stmt[e] = s;
  return e;
}

/* ---------------------------------------------------------------- expression nodes */
int bg_build_node(bg_build *b, int op, bg_srcloc loc) {
  int k = bg_build_new(b, &b->m->nxnode);
  bg_xnode *x = &b->m->xnode[k];
  x->op = (unsigned char)op;
  x->loc = loc;
  return k;
}

int bg_build_num(bg_build *b, double v, bg_srcloc loc) {
  int k = bg_build_node(b, BG_X_NUM, loc);
  b->m->xnode[k].num = v;
  return k;
}

int bg_build_ref(bg_build *b, int op, int ref, bg_srcloc loc) {
  int k = bg_build_node(b, op, loc);
  b->m->xnode[k].ref = ref;
  return k;
}

/* A unary (c < 0) or binary operator node over existing nodes. */
int bg_build_op(bg_build *b, int op, int a, int c, bg_srcloc loc) {
  int k = bg_build_node(b, op, loc);
  bg_xnode *x = &b->m->xnode[k];
  x->nargs = c < 0 ? 1 : 2;
  x->arg[0] = a;
  x->arg[1] = c < 0 ? 0 : c;
  return k;
}
