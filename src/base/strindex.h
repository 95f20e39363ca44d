/* SPDX-License-Identifier: BSD-3-Clause */
/* A hash table from strings to indices into the caller's own array of
 * entries (open addressing, linear probing, a power-of-two size at most half
 * full). The table holds only indices; the keys stay where the caller keeps
 * them and are read through a bg_strkeys view: key i is the string pointer
 * at first + i * stride. So one table serves the model compiler's namespace
 * (ns_entry.name), the compiled model's element names (elem_name[]) and
 * flattening's scopes (sc_entry.name), whatever their entries hold besides. */
#ifndef BG_STRINDEX_H
#define BG_STRINDEX_H
#include <stddef.h>

typedef struct bg_strkeys {
  const void *first; /* the first key's `const char *` (may be NULL when n is 0) */
  size_t stride;     /* bytes from one key pointer to the next */
} bg_strkeys;
/* Keys in the member `field` of the entries of array arr; keys of an array
 * of strings. */
#define BG_STRKEYS(arr, field) ((bg_strkeys){(arr) ? (const void *)&(arr)[0].field : NULL, sizeof *(arr)})
#define BG_STRKEYS_ARRAY(names) ((bg_strkeys){(const void *)(names), sizeof *(names)})

/* The table size for n keys: the least power of two >= 16 and >= 2n + 2. */
int bg_strindex_size(int n);
/* Fills slot[0, cap) (cap from bg_strindex_size(n) or larger, a power of two)
 * with keys 0 .. n-1; the caller owns slot (an arena's, say). */
void bg_strindex_fill(int *slot, int cap, bg_strkeys keys, int n);
/* The index of the first key equal to name, or -1 (also when slot is NULL). */
int bg_strindex_find(const int *slot, int cap, bg_strkeys keys, const char *name);

/* A table that grows with its keys (slots malloc'd). Zero-initialised is empty. */
typedef struct bg_strindex {
  int *slot; /* cap entries, -1 = empty */
  int cap;
} bg_strindex;
/* Adds key n-1, just appended to the caller's array of n keys. */
void bg_strindex_add(bg_strindex *t, bg_strkeys keys, int n);
/* bg_strindex_find on t. */
int bg_strindex_lookup(const bg_strindex *t, bg_strkeys keys, const char *name);
void bg_strindex_free(bg_strindex *t);
#endif
