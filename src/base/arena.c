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

/* size bytes at the first multiple of align in the newest block, or in a
 * new block when they do not fit there. Strings are packed at byte
 * alignment: rounded up to max_align_t, a diagram's two million short roles
 * and labels took 30 MB more at 100 000 masses. */
static void *take(bg_arena *a, size_t size, size_t align) {
  bg_arena_block *b = a->head;
  size_t at = b ? (b->used + align - 1) / align * align : 0;
  if (!b || at > b->size || b->size - at < size) {
    size_t cap = size > BLOCK_MIN ? size : BLOCK_MIN;
    b = bg_xmalloc(sizeof *b + cap);
    b->prev = a->head;
    b->size = cap;
    a->head = b;
    at = 0;
  }
  b->used = at + size;
  return (char *)b->data + at;
}

void *bg_arena_alloc(bg_arena *a, size_t size) {
  if (!size) size = 1;
  void *p = take(a, size, sizeof(max_align_t));
  memset(p, 0, size);
  return p;
}

char *bg_arena_strndup(bg_arena *a, const char *s, size_t len) {
  char *d = take(a, len + 1, 1);
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
