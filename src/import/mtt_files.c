/* SPDX-License-Identifier: BSD-3-Clause */
/* The text files of an MTT system beside its drawing (mtt_int.h): the
 * label file NAME_lbl.txt (one component a line: name, constitutive
 * relationship, arguments; #ALIAS and #SUMMARY directives) and the
 * assignment files NAME_numpar.txt, NAME_input.txt, NAME_simpar.txt
 * ("name = value;" lines, # or % comments). Each file read becomes a source
 * of the diagnostics, so errors and the .bg lines made from it point at it. */
#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/fileio.h"
#include "import/mtt_int.h"

/* The file at path when it exists (else NULL, *file -1); errors other than
 * its absence are reported. The text is the caller's to free. */
static char *read_optional(const char *path, bg_diags *dg, int *file, size_t *len) {
  struct stat st;
  *file = -1;
  if (stat(path, &st) != 0) return NULL;
  char *t = bg_read_file(path, len);
  if (!t) {
    bg_diag_error(dg, (bg_srcloc){0}, "cannot read %s: %s", path, bg_file_strerror(errno));
    return NULL;
  }
  *file = bg_diags_add_source(dg, path, t, *len);
  return t;
}

/* Splits one line (not modified) into at most max blank-separated words
 * copied into the arena. */
static int words(bg_arena *a, const char *s, size_t n, const char **w, int max) {
  int k = 0;
  for (size_t i = 0; i < n && k < max;) {
    while (i < n && isspace((unsigned char)s[i])) i++;
    if (i >= n) break;
    size_t j = i;
    while (j < n && !isspace((unsigned char)s[j])) j++;
    w[k++] = bg_arena_strndup(a, s + i, j - i);
    i = j;
  }
  return k;
}

static void push_row(bg_mtt_rows *r, bg_mtt_row row) {
  if (r->n == r->cap) {
    r->cap = r->cap ? 2 * r->cap : 16;
    r->v = bg_xrealloc(r->v, (size_t)r->cap * sizeof *r->v);
  }
  r->v[r->n++] = row;
  bg_strindex_add(&r->idx, BG_STRKEYS(r->v, f[0]), r->n);
}

/* Calls line() on each line of the file at path (a missing file has none).
 * 0, or -1 when the file cannot be read or a line() failed. */
typedef int (*line_fn)(void *ctx, const char *s, size_t n, int line);
static int each_line(const char *path, bg_diags *dg, int *file, line_fn line, void *ctx) {
  size_t len;
  int before = dg->nerrors;
  char *t = read_optional(path, dg, file, &len);
  if (!t) return dg->nerrors > before ? -1 : 0;
  int k = 0, rc = 0;
  for (size_t i = 0; i < len;) {
    size_t e = i;
    while (e < len && t[e] != '\n') e++;
    if (line(ctx, t + i, e - i, ++k)) rc = -1;
    i = e + 1;
  }
  free(t);
  return rc;
}

typedef struct {
  bg_arena *a;
  bg_diags *dg;
  void *out;
} reading;

/* A label file's line: a directive (#ALIAS, #SUMMARY; others are comments)
 * or a component's name, CR and arguments. */
static int lbl_line(void *ctx, const char *t, size_t len, int line) {
  reading *r = ctx;
  bg_mtt_lbl *out = r->out;
  const char *w[5];
  int n = words(r->a, t, len, w, 5);
  bg_mtt_row row = {{NULL, NULL, NULL}, 0, line};
  if (n && (w[0][0] == '%' || w[0][0] == '#')) {
    const char *d = w[0] + 1;
    if (!*d && n > 1) d = w[1], n--, memmove(w + 1, w + 2, sizeof *w * 3);
    if (!strcmp(d, "ALIAS") && n >= 3) {
      row.f[0] = w[1], row.f[1] = w[2], row.n = 2;
      push_row(&out->aliases, row);
    } else if (!strcmp(d, "SUMMARY") && !out->summary) {
      const char *s = memchr(t, 'S', len); /* the summary's text after the word */
      const char *rest = s ? s + 7 : t + len;
      while (rest < t + len && isspace((unsigned char)*rest)) rest++;
      size_t m = (size_t)(t + len - rest);
      while (m && isspace((unsigned char)rest[m - 1])) m--;
      char *sum = bg_arena_strndup(r->a, rest, m);
      for (char *p = sum; *p; p++)
        if (*p == '"' || *p == '\\') *p = '\'';
      out->summary = sum, out->summary_line = line;
    }
    return 0;
  }
  if (!n) return 0;
  for (int k = 0; k < 3 && k < n; k++) row.f[k] = w[k];
  row.n = n < 3 ? n : 3;
  const bg_mtt_row *first = bg_mtt_find(&out->rows, w[0]);
  if (first) {
    bg_diag_error(r->dg, (bg_srcloc){line, 1, out->file},
                  "MTT label file: '%s' is labelled twice (first at line %d)", w[0], first->line);
    return -1;
  }
  push_row(&out->rows, row);
  return 0;
}

int bg_mtt_read_lbl(const char *path, bg_arena *a, bg_diags *dg, bg_mtt_lbl *out) {
  memset(out, 0, sizeof *out);
  reading r = {a, dg, out};
  return each_line(path, dg, &out->file, lbl_line, &r);
}

/* An assignment file's line: name = value; (after # or % a comment). */
static int assign_line(void *ctx, const char *t, size_t len, int line) {
  reading *r = ctx;
  bg_mtt_assign *out = r->out;
  size_t end = 0;
  while (end < len && t[end] != '#' && t[end] != '%') end++;
  while (end > 0 && (isspace((unsigned char)t[end - 1]) || t[end - 1] == ';')) end--;
  size_t s = 0;
  while (s < end && isspace((unsigned char)t[s])) s++;
  if (s >= end) return 0;
  size_t n = s;
  while (n < end && (isalnum((unsigned char)t[n]) || t[n] == '_')) n++;
  size_t q = n;
  while (q < end && isspace((unsigned char)t[q])) q++;
  if (n == s || q >= end || t[q] != '=' || (q + 1 < end && t[q + 1] == '=')) {
    out->skipped++; /* Octave code of other forms (global, u(1) = ..., [a, b] = f(x)) */
    if (!out->skipped_line) out->skipped_line = line;
    return 0;
  }
  size_t v = q + 1;
  while (v < end && isspace((unsigned char)t[v])) v++;
  bg_mtt_row row = {{bg_arena_strndup(r->a, t + s, n - s), bg_arena_strndup(r->a, t + v, end - v), NULL},
                    2, line};
  if (v == end) {
    bg_diag_error(r->dg, (bg_srcloc){line, (int)q + 2, out->file}, "MTT parameter file: '%s' has no value",
                  row.f[0]);
    return -1;
  }
  /* a later assignment of the same name wins, as in Octave */
  int k = bg_strindex_lookup(&out->rows.idx, BG_STRKEYS(out->rows.v, f[0]), row.f[0]);
  if (k >= 0) out->rows.v[k] = row;
  else push_row(&out->rows, row);
  return 0;
}

int bg_mtt_read_assign(const char *path, bg_arena *a, bg_diags *dg, bg_mtt_assign *out) {
  memset(out, 0, sizeof *out);
  reading r = {a, dg, out};
  return each_line(path, dg, &out->file, assign_line, &r);
}

const bg_mtt_row *bg_mtt_find(const bg_mtt_rows *r, const char *name) {
  int k = bg_strindex_lookup(&r->idx, BG_STRKEYS(r->v, f[0]), name);
  return k >= 0 ? &r->v[k] : NULL;
}

void bg_mtt_rows_free(bg_mtt_rows *r) {
  free(r->v);
  bg_strindex_free(&r->idx);
  memset(r, 0, sizeof *r);
}
