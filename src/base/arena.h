/* SPDX-License-Identifier: BSD-3-Clause */
/* Arena: a bump allocator, for data that lives as long as
 * one stage (the AST, a compiled model, an analysis). */
#ifndef BG_ARENA_H
#define BG_ARENA_H
#include <stddef.h>

typedef struct bg_arena_block bg_arena_block;
typedef struct bg_arena {
  bg_arena_block *head;
} bg_arena;

/* Zero-filled memory from the arena, aligned for any type; never NULL
 * (aborts on out-of-memory through bg_fatal). */
void *bg_arena_alloc(bg_arena *a, size_t size);
/* A copy of s (len bytes, NUL added) owned by the arena, packed at byte
 * alignment (strings need no more). */
char *bg_arena_strndup(bg_arena *a, const char *s, size_t len);
char *bg_arena_strdup(bg_arena *a, const char *s);
void bg_arena_free(bg_arena *a);

/* Internal invariant failure: prints file:line and aborts. */
_Noreturn void bg_fatal(const char *file, int line, const char *fmt, ...);
#define BG_FATAL(...) bg_fatal(__FILE__, __LINE__, __VA_ARGS__)
/* malloc/realloc that never return NULL. */
void *bg_xmalloc(size_t n);
void *bg_xrealloc(void *p, size_t n);
void *bg_xcalloc(size_t n, size_t size);

/* A growable list of ints (v[0..n)); zero-initialise, push, free(v). */
typedef struct bg_ivec {
  int *v;
  int n, cap;
} bg_ivec;
void bg_ivec_push(bg_ivec *x, int value);
#endif
