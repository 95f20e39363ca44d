/* SPDX-License-Identifier: BSD-3-Clause */
#include "base/arena.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct bg_arena_block {
  bg_arena_block *prev;
  size_t size, used;
  max_align_t data[];
};

enum { BLOCK_MIN = 64 * 1024 };

_Noreturn void bg_fatal(const char *file, int line, const char *fmt, ...) {
  va_list ap;
  fprintf(stderr, "bgdraw: internal error at %s:%d: ", file, line);
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
  abort();
}

void *bg_xmalloc(size_t n) {
  void *p = malloc(n ? n : 1);
  if (!p) BG_FATAL("out of memory (%zu bytes)", n);
  return p;
}

void *bg_xrealloc(void *p, size_t n) {
  void *q = realloc(p, n ? n : 1);
  if (!q) BG_FATAL("out of memory (%zu bytes)", n);
  return q;
}

void *bg_xcalloc(size_t n, size_t size) {
  void *p = calloc(n ? n : 1, size ? size : 1);
  if (!p) BG_FATAL("out of memory (%zu x %zu bytes)", n, size);
  return p;
}

void bg_ivec_push(bg_ivec *x, int value) {
  if (x->n == x->cap) {
    x->cap = x->cap ? 2 * x->cap : 64;
    x->v = bg_xrealloc(x->v, (size_t)x->cap * sizeof *x->v);
  }
  x->v[x->n++] = value;
}

static size_t round_up(size_t n) {
  size_t a = sizeof(max_align_t);
  return (n + a - 1) / a * a;
}

void *bg_arena_alloc(bg_arena *a, size_t size) {
  size = round_up(size ? size : 1);
  bg_arena_block *b = a->head;
  if (!b || b->size - b->used < size) {
    size_t cap = size > BLOCK_MIN ? size : BLOCK_MIN;
    b = bg_xmalloc(sizeof *b + cap);
    b->prev = a->head;
    b->size = cap;
    b->used = 0;
    a->head = b;
  }
  void *p = (char *)b->data + b->used;
  b->used += size;
  memset(p, 0, size);
  return p;
}

char *bg_arena_strndup(bg_arena *a, const char *s, size_t len) {
  char *d = bg_arena_alloc(a, len + 1);
  memcpy(d, s, len);
  d[len] = '\0';
  return d;
}

char *bg_arena_strdup(bg_arena *a, const char *s) {
  return bg_arena_strndup(a, s, strlen(s));
}

void bg_arena_free(bg_arena *a) {
  while (a->head) {
    bg_arena_block *prev = a->head->prev;
    free(a->head);
    a->head = prev;
  }
}
