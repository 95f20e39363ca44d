/* SPDX-License-Identifier: BSD-3-Clause */
/* The flattener's shared helpers (flatten_int.h), under the driver
 * (flatten.c) and the parts (flatten_expand.c, flatten_bonds.c): growable
 * arrays, strings in the flat AST's arena, and scopes, the name tables of
 * submodel definitions. */
#include <stdlib.h>
#include <string.h>

#include "lang/flatten_int.h"
#include "base/strbuf.h"
#include "lang/parse.h"

void *bg_fl_push(void *arr, int *n, size_t size) {
  int k = (*n)++;
  if ((k & (k - 1)) == 0) /* 0, 1, 2, 4, ...: grow to the next power of two */
    arr = bg_xrealloc(arr, (size_t)(k ? 2 * k : 1) * size);
  memset((char *)arr + (size_t)k * size, 0, size);
  return arr;
}

const char *bg_fl_strdup(fl_flattener *f, const char *s) {
  return s ? bg_arena_strdup(&f->out->arena, s) : NULL;
}

const char *bg_fl_join(fl_flattener *f, const char *prefix, const char *name) {
  return bg_ast_join(&f->out->arena, prefix, name);
}

/* ---------------------------------------------------------------- name tables */
const sc_entry *bg_fl_lookup(const fl_scope *s, const char *name) {
  int i = bg_strindex_lookup(&s->names, BG_STRKEYS(s->e, name), name);
  return i >= 0 ? &s->e[i] : NULL;
}

const sc_entry *bg_fl_declare(fl_scope *s, const char *name, int kind, int index, bg_srcloc loc) {
  const sc_entry *old = bg_fl_lookup(s, name);
  if (old) return old;
  *FL_PUSH(s->e, s->n) = (sc_entry){name, kind, index, loc};
  bg_strindex_add(&s->names, BG_STRKEYS(s->e, name), s->n);
  return NULL;
}

void bg_fl_scope_free(fl_scope *s) {
  free(s->e);
  bg_strindex_free(&s->names);
  memset(s, 0, sizeof *s);
}

const char *bg_fl_suggest(const fl_scope *s, const char *name, unsigned mask) {
  const char *best = NULL;
  int bestd = strlen(name) < 3 ? 2 : 3;
  for (int i = 0; i < s->n; i++) {
    if (!(mask & (1u << s->e[i].kind))) continue;
    int d = bg_edit_distance(name, s->e[i].name);
    if (d > 0 && d < bestd) { bestd = d; best = s->e[i].name; }
  }
  return best;
}
