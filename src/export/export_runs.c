/* SPDX-License-Identifier: BSD-3-Clause */
/* Repeated patterns of a generated C function (docs/export.md, "Compile
 * time"). A model built of many equal parts (a chain of masses, a ladder)
 * gives a tape whose instructions repeat one pattern with other slots: the
 * C export writes such a run as a loop over a table of the slots, each
 * iteration the pattern's statements with v[x[j]] for v[N] (and an event's
 * number from the table likewise), in the order of
 * the straight-line code, so the loop computes every value as that code did,
 * bit for bit, while the compiler sees the pattern once. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/strindex.h"
#include "export/export_int.h"

/* A run: at least this many repetitions covering at least this many
 * statements (fewer stay straight-line: a small model's export reads as its
 * equations), patterns of at most BG_RUN_PERIOD statements. */
#define BG_RUN_REPS 4
#define BG_RUN_STMTS 64
#define BG_RUN_PERIOD 64

void bg_xstmts_end(bg_xstmts *t) {
  if (t->n + 2 > t->cap) {
    t->cap = t->cap ? 2 * t->cap : 256;
    t->at = bg_xrealloc(t->at, (size_t)t->cap * sizeof *t->at);
  }
  if (!t->n) t->at[0] = 0;
  t->at[++t->n] = t->text.len;
}

void bg_xstmts_free(bg_xstmts *t) {
  bg_sb_free(&t->text);
  free(t->at);
  memset(t, 0, sizeof *t);
}

static int ident_char(char c) {
  return c == '_' || (c >= '0' && c <= '9') || ((c | 32) >= 'a' && (c | 32) <= 'z');
}

/* Does the text [s, p) end with w? */
static int ends_with(const char *s, const char *p, const char *w) {
  size_t n = strlen(w);
  return (size_t)(p - s) >= n && !memcmp(p - n, w, n);
}

/* Is the number starting at p one of the statement's parameters? A slot
 * v[N], d[N], y0[N], or an event's number: bg_at(c, E, ...), bg_held(c, E),
 * md->m[E], zero[E], only[E], and its first root function: g + R, dir + R
 * (the root functions' code, export_events.c) and bg_at's eighth argument
 * (r0: the walker is there). Each name is not the tail of a longer one.
 * Everything else (coefficients, kinds, tables) is text. */
static int parameter(const char *s, const char *p, int r0) {
  static const char *const before[] = {"v[", "d[", "y0[", "zero[", "only[", "g + ", "dir + ",
                                       "bg_at(c, ", "bg_held(c, ", "->m["};
  for (size_t k = 0; k < sizeof before / sizeof *before; k++) {
    size_t n = strlen(before[k]);
    if (ends_with(s, p, before[k]) &&
        (!ident_char(before[k][0]) || (size_t)(p - s) == n || !ident_char(p[-(long)n - 1])))
      return 1;
  }
  return r0 && ends_with(s, p, ", ");
}

/* Statement k's text with each parameter replaced: loop 0, by '#' (its
 * pattern, into out) with the parameters' values appended to nums; loop 1,
 * by x[j] (j counting on from *j), every line indented one level more. */
static void walk(const bg_xstmts *t, int k, int loop, bg_strbuf *out, int **nums, int *nn, int *cap, int *j) {
  const char *s = t->text.s + t->at[k], *e = t->text.s + t->at[k + 1];
  int at = -1, depth = 0, commas = 0, bol = 1; /* at: bg_at's depth while inside it */
  for (const char *p = s; p < e;) {
    if (*p >= '0' && *p <= '9' && (p == s || (!ident_char(p[-1]) && p[-1] != '.')) &&
        parameter(s, p, at >= 0 && depth == at && commas == 7)) {
      int v = 0;
      for (; p < e && *p >= '0' && *p <= '9'; p++) v = v * 10 + (*p - '0');
      if (loop) { bg_sb_printf(out, "x[%d]", (*j)++); continue; }
      bg_sb_putc(out, '#');
      if (*nn == *cap) *cap = *cap ? 2 * *cap : 64, *nums = bg_xrealloc(*nums, (size_t)*cap * sizeof **nums);
      (*nums)[(*nn)++] = v;
      continue;
    }
    char ch = *p++;
    if (loop && bol) bg_sb_puts(out, "  ");
    bol = ch == '\n';
    bg_sb_putc(out, ch);
    if (ch == '(') {
      depth++;
      if (ends_with(s, p, "bg_at(")) at = depth, commas = 0;
    } else if (ch == ')') {
      if (depth-- == at) at = -1;
    } else if (ch == ',' && depth == at) commas++;
  }
}

/* Statement k's pattern (into sh); its parameters appended to nums when
 * nums is given. */
static void pattern(const bg_xstmts *t, int k, bg_strbuf *sh, int **nums, int *nn, int *cap) {
  int *none = NULL, n0 = 0, c0 = 0;
  bg_sb_clear(sh);
  walk(t, k, 0, sh, nums ? nums : &none, nums ? nn : &n0, nums ? cap : &c0, NULL);
  free(none);
}

/* Each line of text a statement. */
static void xstmts_lines(bg_xstmts *t, const char *text) {
  for (const char *p = text; p && *p;) {
    const char *e = strchr(p, '\n');
    e = e ? e + 1 : p + strlen(p);
    bg_sb_putn(&t->text, p, (size_t)(e - p));
    bg_xstmts_end(t);
    p = e;
  }
}

void bg_xruns_plan(const bg_xstmts *t, bg_xrun **runs, int *nruns) {
  int n = t->n, *id = bg_xcalloc((size_t)n + 1, sizeof(int)), nshape = 0, capshape = 0;
  char **shape = NULL;
  bg_strindex index = {0};
  bg_strbuf sh = {0};
  for (int k = 0; k < n; k++) {
    pattern(t, k, &sh, NULL, NULL, NULL);
    const char *key = bg_sb_str(&sh);
    int f = bg_strindex_lookup(&index, BG_STRKEYS_ARRAY(shape), key);
    if (f < 0) {
      if (nshape == capshape) capshape = capshape ? 2 * capshape : 64, shape = bg_xrealloc(shape, (size_t)capshape * sizeof *shape);
      size_t len = strlen(key) + 1;
      shape[nshape] = memcpy(bg_xmalloc(len), key, len);
      bg_strindex_add(&index, BG_STRKEYS_ARRAY(shape), ++nshape);
      f = nshape - 1;
    }
    id[k] = f;
  }
  /* Greedy from the front: at each statement the period whose repetitions
   * cover the most statements. The shapes compared are bounded by a budget
   * linear in the function's length (a search that exhausts it leaves the
   * rest straight: slower to compile, the same results). BGDRAW_EXPORT_LOOPS=0
   * in the environment writes every function straight (the reference the
   * tests compare the loops with, docs/export.md). */
  int nr = 0, cap = 0, straight = 0;
  long budget = 256L * n + 1000000L;
  const char *env = getenv("BGDRAW_EXPORT_LOOPS");
  if (env && !strcmp(env, "0")) budget = 0;
  bg_xrun *r = NULL;
#define BG_PUSH(s0, p, m)                                                                      \
  do {                                                                                         \
    if (nr == cap) cap = cap ? 2 * cap : 16, r = bg_xrealloc(r, (size_t)cap * sizeof *r);      \
    r[nr++] = (bg_xrun){s0, p, m};                                                             \
  } while (0)
  for (int i = 0; i < n && budget > 0;) {
    int bestp = 0, bestm = 0;
    for (int p = 1; p <= BG_RUN_PERIOD && i + BG_RUN_REPS * p <= n; p++) {
      budget--;
      if (id[i + p] != id[i]) continue;
      int m = 1;
      while (i + (m + 1) * p <= n && budget > 0 && !memcmp(id + i, id + i + m * p, (size_t)p * sizeof *id))
        m++, budget -= p;
      if (m >= BG_RUN_REPS && m * p >= BG_RUN_STMTS && m * p > bestm * bestp) bestp = p, bestm = m;
      if (m * p >= n - i) break; /* covers the rest: no longer period does better */
    }
    if (!bestp) { i++; continue; }
    if (straight < i) BG_PUSH(straight, i - straight, 1);
    BG_PUSH(i, bestp, bestm);
    i += bestp * bestm;
    straight = i;
  }
  if (straight < n) BG_PUSH(straight, n - straight, 1);
#undef BG_PUSH
  *runs = r, *nruns = nr;
  for (int k = 0; k < nshape; k++) free(shape[k]);
  free(shape), free(id), bg_sb_free(&sh), bg_strindex_free(&index);
}

void bg_xruns_straight(const bg_xstmts *t, int k0, int k1, bg_strbuf *c) {
  bg_sb_putn(c, t->text.s + t->at[k0], t->at[k1] - t->at[k0]);
}

void bg_xruns_table(const bg_xstmts *t, const bg_xrun *r, const char *tab, bg_strbuf *c) {
  int *nums = NULL, nn = 0, cap = 0, per = 0;
  bg_strbuf sh = {0};
  for (int m = 0; m < r->reps; m++) {
    nn = 0;
    for (int k = 0; k < r->period; k++) pattern(t, r->start + m * r->period + k, &sh, &nums, &nn, &cap);
    if (!m) per = nn, bg_sb_printf(c, "static const int %s[%d][%d] = {\n", tab, r->reps, per ? per : 1);
    bg_sb_puts(c, "  {");
    for (int j = 0; j < nn; j++) bg_sb_printf(c, "%s%d", j ? ", " : "", nums[j]);
    bg_sb_puts(c, nn ? "},\n" : "0},\n");
  }
  bg_sb_puts(c, "};\n");
  free(nums), bg_sb_free(&sh);
}

void bg_xruns_loop(const bg_xstmts *t, const bg_xrun *r, const char *tab, bg_strbuf *c) {
  bg_sb_printf(c, "  for (int i = 0; i < %d; i++) {\n    const int *x = %s[i];\n", r->reps, tab);
  int j = 0;
  for (int k = r->start; k < r->start + r->period; k++) walk(t, k, 1, c, NULL, NULL, NULL, &j);
  bg_sb_puts(c, "  }\n");
}

/* The statements with their runs as loops in one function's body: the
 * tables (name_<piece>) into tables, the code into body. */
static void runs_inline(const bg_xstmts *t, const char *name, bg_strbuf *tables, bg_strbuf *body) {
  bg_xrun *run = NULL;
  int nrun = 0;
  char tab[120];
  if (t->n) bg_xruns_plan(t, &run, &nrun);
  for (int q = 0; q < nrun; q++) {
    const bg_xrun *r = &run[q];
    if (r->reps == 1) { bg_xruns_straight(t, r->start, r->start + r->period, body); continue; }
    snprintf(tab, sizeof tab, "%s_%d", name, q);
    bg_xruns_table(t, r, tab, tables);
    bg_xruns_loop(t, r, tab, body);
  }
  free(run);
}

void bg_xruns_lines(const char *text, const char *name, bg_strbuf *tables, bg_strbuf *body) {
  bg_xstmts t = {0};
  xstmts_lines(&t, text);
  runs_inline(&t, name, tables, body);
  bg_xstmts_free(&t);
}
