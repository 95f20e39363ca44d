/* SPDX-License-Identifier: BSD-3-Clause */
/* A YAML document as a tree with positions, built from libyaml's events
 * (Debian's libyaml: a YAML 1.1 parser with exact error positions; why not
 * a parser of our own is in docs/import.md). Depth and size are bounded;
 * anchors and aliases are refused (no model file needs them, and they are
 * the way a small YAML file expands into a huge one). */
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#include "import/import_int.h"

typedef struct {
  bg_ynode *node;
  bg_ynode **kids; /* growing, malloc'd; copied into the arena when closed */
  int n, cap;
} frame;

static bg_ynode *new_node(bg_arena *a, bg_ynode_kind kind, const yaml_mark_t *m) {
  bg_ynode *n = bg_arena_alloc(a, sizeof *n);
  memset(n, 0, sizeof *n);
  n->kind = kind;
  n->line = (int)m->line + 1;
  n->col = (int)m->column + 1;
  return n;
}

static void push_kid(frame *f, bg_ynode *kid) {
  if (f->n == f->cap) {
    f->cap = f->cap ? 2 * f->cap : 8;
    f->kids = bg_xrealloc(f->kids, (size_t)f->cap * sizeof *f->kids);
  }
  f->kids[f->n++] = kid;
}

static void close_frame(bg_arena *a, frame *f) {
  f->node->nkids = f->n;
  f->node->kids = bg_arena_alloc(a, (size_t)(f->n ? f->n : 1) * sizeof *f->kids);
  if (f->n) memcpy(f->node->kids, f->kids, (size_t)f->n * sizeof *f->kids);
  free(f->kids);
  f->kids = NULL;
}

static void yaml_error(bg_diags *dg, const yaml_parser_t *p) {
  const yaml_mark_t *m = p->problem ? &p->problem_mark : &p->mark;
  bg_srcloc at = {(int)m->line + 1, (int)m->column + 1, 0};
  bg_diag_error(dg, at, "YAML: %s%s%s", p->problem ? p->problem : "malformed YAML",
                p->context ? " " : "", p->context ? p->context : "");
}

bg_ynode *bg_yaml_parse(const char *src, size_t len, bg_arena *a, bg_diags *dg) {
  yaml_parser_t p;
  if (!yaml_parser_initialize(&p)) BG_FATAL("out of memory");
  yaml_parser_set_input_string(&p, (const unsigned char *)src, len);
  frame stack[BG_Y_MAX_DEPTH + 1];
  int depth = 0, nodes = 0, docs = 0, ok = 1, done = 0;
  bg_ynode *root = NULL;
  while (ok && !done) {
    yaml_event_t ev;
    if (!yaml_parser_parse(&p, &ev)) {
      yaml_error(dg, &p);
      ok = 0;
      break;
    }
    bg_srcloc at = {(int)ev.start_mark.line + 1, (int)ev.start_mark.column + 1, 0};
    bg_ynode *made = NULL;
    switch (ev.type) {
    case YAML_STREAM_END_EVENT: done = 1; break;
    case YAML_DOCUMENT_START_EVENT:
      if (++docs > 1) {
        bg_diag_error(dg, at, "a second YAML document; a model file holds one");
        ok = 0;
      }
      break;
    case YAML_ALIAS_EVENT:
      bg_diag_error(dg, at, "YAML aliases (*%s) are not read in model files",
                    (const char *)ev.data.alias.anchor);
      ok = 0;
      break;
    case YAML_SCALAR_EVENT:
      made = new_node(a, BG_Y_SCALAR, &ev.start_mark);
      made->str = bg_arena_strndup(a, (const char *)ev.data.scalar.value, ev.data.scalar.length);
      if (ev.data.scalar.style == YAML_SINGLE_QUOTED_SCALAR_STYLE ||
          ev.data.scalar.style == YAML_DOUBLE_QUOTED_SCALAR_STYLE)
        made->col++, made->plain = 1;
      else made->plain = ev.data.scalar.style == YAML_PLAIN_SCALAR_STYLE;
      if (ev.data.scalar.anchor) {
        bg_diag_error(dg, at, "YAML anchors (&%s) are not read in model files",
                      (const char *)ev.data.scalar.anchor);
        ok = 0;
      }
      break;
    case YAML_SEQUENCE_START_EVENT:
    case YAML_MAPPING_START_EVENT:
      made = new_node(a, ev.type == YAML_SEQUENCE_START_EVENT ? BG_Y_SEQ : BG_Y_MAP, &ev.start_mark);
      break;
    case YAML_SEQUENCE_END_EVENT:
    case YAML_MAPPING_END_EVENT:
      close_frame(a, &stack[--depth]);
      break;
    default: break;
    }
    if (made && ok) {
      if (++nodes > BG_Y_MAX_NODES) {
        bg_diag_error(dg, at, "more than %d YAML nodes; a model file is smaller", BG_Y_MAX_NODES);
        ok = 0;
      } else {
        if (depth > 0) push_kid(&stack[depth - 1], made);
        else root = made;
        if (made->kind != BG_Y_SCALAR) {
          if (depth == BG_Y_MAX_DEPTH) {
            bg_diag_error(dg, at, "YAML nested more than %d levels deep", BG_Y_MAX_DEPTH);
            ok = 0;
          } else stack[depth++] = (frame){made, NULL, 0, 0};
        }
      }
    }
    yaml_event_delete(&ev);
  }
  while (depth > 0) free(stack[--depth].kids);
  yaml_parser_delete(&p);
  if (ok && !root) bg_diag_error(dg, (bg_srcloc){1, 1, 0}, "an empty YAML document");
  return ok ? root : NULL;
}

const bg_ynode *bg_yaml_get(const bg_ynode *m, const char *key) {
  if (!m || m->kind != BG_Y_MAP) return NULL;
  for (int i = 0; i + 1 < m->nkids; i += 2)
    if (m->kids[i]->kind == BG_Y_SCALAR && !strcmp(m->kids[i]->str, key)) return m->kids[i + 1];
  return NULL;
}
