/* SPDX-License-Identifier: BSD-3-Clause */
/* String-to-index hash table (strindex.h). */
#include "base/strindex.h"

#include <stdlib.h>
#include <string.h>

#include "base/arena.h"

static const char *key(bg_strkeys keys, int i) {
  return *(const char *const *)((const char *)keys.first + (size_t)i * keys.stride);
}

static unsigned str_hash(const char *s) { /* FNV-1a */
  unsigned h = 2166136261u;
  for (; *s; s++) h = (h ^ (unsigned char)*s) * 16777619u;
  return h;
}

int bg_strindex_size(int n) {
  int cap = 16;
  while (cap < 2 * n + 2) cap *= 2;
  return cap;
}

static void put(int *slot, int cap, const char *name, int i) {
  unsigned mask = (unsigned)(cap - 1), h = str_hash(name) & mask;
  while (slot[h] >= 0) h = (h + 1) & mask;
  slot[h] = i;
}

void bg_strindex_fill(int *slot, int cap, bg_strkeys keys, int n) {
  for (int i = 0; i < cap; i++) slot[i] = -1;
  for (int i = 0; i < n; i++) put(slot, cap, key(keys, i), i);
}

int bg_strindex_find(const int *slot, int cap, bg_strkeys keys, const char *name) {
  if (!slot) return -1;
  unsigned mask = (unsigned)(cap - 1);
  for (unsigned h = str_hash(name) & mask; slot[h] >= 0; h = (h + 1) & mask)
    if (strcmp(key(keys, slot[h]), name) == 0) return slot[h];
  return -1;
}

void bg_strindex_add(bg_strindex *t, bg_strkeys keys, int n) {
  if (2 * n + 2 > t->cap) { /* grow: every key again */
    free(t->slot);
    t->cap = bg_strindex_size(n);
    t->slot = bg_xmalloc((size_t)t->cap * sizeof *t->slot);
    bg_strindex_fill(t->slot, t->cap, keys, n);
  } else {
    put(t->slot, t->cap, key(keys, n - 1), n - 1);
  }
}

int bg_strindex_lookup(const bg_strindex *t, bg_strkeys keys, const char *name) {
  return bg_strindex_find(t->slot, t->cap, keys, name);
}

void bg_strindex_free(bg_strindex *t) {
  free(t->slot);
  t->slot = NULL;
  t->cap = 0;
}
