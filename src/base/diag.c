/* SPDX-License-Identifier: BSD-3-Clause */
#include "base/diag.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/strbuf.h"

static char *dup_str(const char *s, size_t n);
static int unsure_name(const bg_diags *d, const char *name);

void bg_diags_init(bg_diags *d, const char *file, const char *src, size_t srclen) {
  memset(d, 0, sizeof *d);
  d->file = file;
  d->src = src;
  d->srclen = srclen;
  d->max_errors = BG_DIAG_MAX_ERRORS;
}

int bg_diags_full(const bg_diags *d) { return d->max_errors > 0 && d->nerrors >= d->max_errors; }

void bg_diags_free(bg_diags *d) {
  for (int i = 0; i < d->n; i++) free(d->items[i].msg);
  free(d->items);
  d->items = NULL;
  d->n = d->cap = 0;
  for (int i = 1; i < d->nsources; i++) {
    free((char *)d->sources[i].path);
    if (d->sources[i].owns_src) free((char *)d->sources[i].src);
    free(d->sources[i].context_msg);
  }
  free(d->sources);
  d->sources = NULL;
  d->nsources = d->srccap = 0;
  for (int i = 0; i < d->nunsure; i++) free(d->unsure[i]);
  free(d->unsure);
  d->unsure = NULL;
  d->nunsure = d->unsure_cap = 0;
  bg_strindex_free(&d->unsure_index);
}

/* ---------------------------------------------------------------- dropped statements */
void bg_diags_skipped(bg_diags *d, const char *const *names, int n, int bond_unnamed) {
  d->nskipped++;
  d->unsure_bonds |= bond_unnamed;
  for (int i = 0; i < n; i++) {
    if (unsure_name(d, names[i])) continue;
    if (d->nunsure == d->unsure_cap) {
      d->unsure_cap = d->unsure_cap ? 2 * d->unsure_cap : 16;
      d->unsure = bg_xrealloc(d->unsure, (size_t)d->unsure_cap * sizeof *d->unsure);
    }
    d->unsure[d->nunsure++] = dup_str(names[i], strlen(names[i]));
    bg_strindex_add(&d->unsure_index, BG_STRKEYS_ARRAY(d->unsure), d->nunsure);
  }
}

/* The look-up of bg_diags_unsure, without counting. */
static int unsure_name(const bg_diags *d, const char *name) {
  if (!name || !d->nunsure) return 0;
  bg_strkeys keys = BG_STRKEYS_ARRAY(d->unsure);
  if (bg_strindex_lookup(&d->unsure_index, keys, name) >= 0) return 1;
  const char *dot = strchr(name, '.');
  if (!dot) return 0;
  if (bg_strindex_lookup(&d->unsure_index, keys, strrchr(name, '.') + 1) >= 0) return 1;
  char head[256]; /* M1 of M1.a; the last part is R1 of M1.R1, an instance's element */
  size_t n = (size_t)(dot - name);
  if (n >= sizeof head) return 0;
  memcpy(head, name, n);
  head[n] = '\0';
  return bg_strindex_lookup(&d->unsure_index, keys, head) >= 0;
}

int bg_diags_unsure(bg_diags *d, const char *name) {
  int u = unsure_name(d, name);
  d->unsaid += u;
  return u;
}

int bg_diags_unsure_bonds(bg_diags *d, const char *name) {
  int u = d->unsure_bonds || unsure_name(d, name);
  d->unsaid += u;
  return u;
}

int bg_diags_failures(const bg_diags *d) { return d->nerrors + d->unsaid; }

/* ---------------------------------------------------------------- sources */
static char *dup_str(const char *s, size_t n) {
  char *c = bg_xmalloc(n + 1);
  if (n) memcpy(c, s, n);
  c[n] = '\0';
  return c;
}

static bg_diag_source *new_source(bg_diags *d, int *index) {
  if (d->nsources == 0) d->nsources = 1; /* index 0: the model file, kept in d->file */
  if (d->nsources >= d->srccap) {
    d->srccap = d->srccap ? 2 * d->srccap : 16;
    d->sources = bg_xrealloc(d->sources, (size_t)d->srccap * sizeof *d->sources);
  }
  *index = d->nsources++;
  bg_diag_source *s = &d->sources[*index];
  memset(s, 0, sizeof *s);
  return s;
}

int bg_diags_add_source(bg_diags *d, const char *path, const char *src, size_t srclen) {
  int k;
  bg_diag_source *s = new_source(d, &k);
  s->path = dup_str(path, strlen(path));
  if (src) {
    s->src = dup_str(src, srclen);
    s->srclen = srclen;
    s->owns_src = 1;
  }
  return k;
}

/* The path and text of source i (0 or unknown: the model file). */
static bg_diag_source source_of(const bg_diags *d, int i) {
  if (i > 0 && i < d->nsources) return d->sources[i];
  bg_diag_source s = {d->file, d->src, d->srclen, 0, {0, 0, 0}, NULL};
  return s;
}

int bg_diags_add_context(bg_diags *d, int of, bg_srcloc context, const char *msg) {
  bg_diag_source base = source_of(d, of);
  int k;
  bg_diag_source *s = new_source(d, &k);
  s->path = dup_str(base.path, strlen(base.path));
  s->src = base.src;
  s->srclen = base.srclen;
  s->context = context;
  s->context_msg = msg ? dup_str(msg, strlen(msg)) : NULL;
  return k;
}

const char *bg_diags_path(const bg_diags *d, bg_srcloc loc) { return source_of(d, loc.file).path; }

/* The same message at the same place of the same file: one mistake in a
 * submodel used by several instances is reported once (with the first chain). */
static int repeated(const bg_diags *d, bg_severity sev, bg_srcloc loc, const char *msg) {
  if (loc.file == 0) return 0; /* only sources of used files and instances repeat */
  const char *path = bg_diags_path(d, loc);
  for (int i = 0; i < d->n; i++) {
    const bg_diag *g = &d->items[i];
    if (g->sev == sev && g->loc.line == loc.line && g->loc.col == loc.col &&
        strcmp(g->msg, msg) == 0 && strcmp(bg_diags_path(d, g->loc), path) == 0)
      return 1;
  }
  return 0;
}

/* The chain of instances source `file` is used from: calls fn with each
 * context as a note, innermost first. Bounded by the number of sources. */
static void each_context(const bg_diags *d, int file, void (*fn)(const bg_diag *, void *),
                         void *ctx) {
  for (int hops = 0; file > 0 && file < d->nsources && hops < d->nsources; hops++) {
    const bg_diag_source *s = &d->sources[file];
    if (s->context.line <= 0 || !s->context_msg) break;
    bg_diag note = {BG_SEV_NOTE, s->context, s->context_msg};
    fn(&note, ctx);
    file = s->context.file;
  }
}

/* ---------------------------------------------------------------- adding */

static void add(bg_diags *d, bg_severity sev, bg_srcloc loc, const char *fmt, va_list ap) {
  /* beyond the limit an error is only counted, and so are its notes */
  if (sev == BG_SEV_ERROR && bg_diags_full(d)) {
    d->dropped++;
    d->dropping = 1;
    return;
  }
  if (sev == BG_SEV_NOTE && d->dropping) return;
  d->dropping = 0;
  va_list ap2;
  va_copy(ap2, ap);
  int n = vsnprintf(NULL, 0, fmt, ap);
  char *msg = bg_xmalloc((size_t)(n > 0 ? n : 0) + 1);
  vsnprintf(msg, (size_t)(n > 0 ? n : 0) + 1, fmt, ap2);
  va_end(ap2);
  if (sev != BG_SEV_NOTE && (d->dropping = repeated(d, sev, loc, msg)) != 0) {
    free(msg);
    return;
  }
  if (d->n == d->cap) {
    d->cap = d->cap ? d->cap * 2 : 16;
    d->items = bg_xrealloc(d->items, (size_t)d->cap * sizeof *d->items);
  }
  d->items[d->n++] = (bg_diag){sev, loc, msg};
  if (sev == BG_SEV_ERROR) d->nerrors++;
  if (sev == BG_SEV_WARNING) d->nwarnings++;
}

#define DEFINE_ADDER(name, sev)                                        \
  void name(bg_diags *d, bg_srcloc loc, const char *fmt, ...) {        \
    va_list ap;                                                        \
    va_start(ap, fmt);                                                 \
    add(d, sev, loc, fmt, ap);                                         \
    va_end(ap);                                                        \
  }
static const char *const warning_names[BG_W_COUNT] = {"unused-param", "empty-model",
                                                      "degenerate-value", "unbonded-port"};

int bg_warning_parse(const char *name) {
  for (int i = 0; i < BG_W_COUNT; i++)
    if (!strcmp(name, warning_names[i])) return i;
  return -1;
}

const char *bg_warning_name(bg_warning w) { return w < BG_W_COUNT ? warning_names[w] : "?"; }

void bg_diag_warn(bg_diags *d, bg_warning w, bg_srcloc loc, const char *fmt, ...) {
  if (w >= BG_W_COUNT || (d->warn_off >> w & 1u)) return;
  if (d->nskipped) return; /* a dropped statement may be what the warning misses */
  char msg[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if (d->werror) bg_diag_error(d, loc, "%s [-Werror=%s]", msg, warning_names[w]);
  else bg_diag_warning(d, loc, "%s [-W%s]", msg, warning_names[w]);
}

DEFINE_ADDER(bg_diag_error, BG_SEV_ERROR)
DEFINE_ADDER(bg_diag_warning, BG_SEV_WARNING)
DEFINE_ADDER(bg_diag_note, BG_SEV_NOTE)

/* Finds source lines for diagnostics printed in line order: a cursor that
 * moves forward, so printing k diagnostics reads the source once (it restarts
 * only for a note about an earlier line). */
typedef struct line_cursor {
  const char *p; /* start of line `line` */
  int line;
  const char *src; /* the text it moves in (sources change: used files, instances) */
} line_cursor;

/* The text of source line loc.line (1-based) without its line end. */
static const char *find_line(const bg_diags *d, line_cursor *c, bg_srcloc loc, size_t *len) {
  bg_diag_source s = source_of(d, loc.file);
  int line = loc.line;
  if (!s.src || line < 1) return NULL;
  const char *end = s.src + s.srclen;
  if (!c->p || line < c->line || c->src != s.src) c->p = s.src, c->line = 1, c->src = s.src;
  while (c->line < line) {
    const char *nl = memchr(c->p, '\n', (size_t)(end - c->p));
    if (!nl) return NULL;
    c->p = nl + 1;
    c->line++;
  }
  const char *p = c->p;
  const char *e = memchr(p, '\n', (size_t)(end - p));
  if (!e) e = end;
  if (e > p && e[-1] == '\r') e--;
  *len = (size_t)(e - p);
  return p;
}

static int use_color, use_json;

void bg_diags_set_output(int color, int json) {
  use_color = color;
  use_json = json;
}

static const char *const sevname[] = {"error", "warning", "note"};
/* gcc's colours: bold positions, red errors, magenta warnings, cyan notes, green carets */
static const char *const sevcolor[] = {"\033[1;31m", "\033[1;35m", "\033[1;36m"};
#define COLOR(c) (use_color ? (c) : "")

static void print_caret_line(const bg_diag *g, const char *line, size_t len, FILE *out) {
  /* A very long line (generated input) is shown as a window around the
   * caret, marked with "..." on the cut sides, so the caret stays visible. */
  enum { WIDTH = 100 };
  size_t from = 0, col = g->loc.col > 0 ? (size_t)g->loc.col - 1 : 0;
  if (len > WIDTH && col > WIDTH / 2) from = col - WIDTH / 2;
  if (from > len) from = len;
  size_t shown = len - from > WIDTH ? WIDTH : len - from;
  const char *lead = from ? "..." : "";
  fprintf(out, "%5d | %s%.*s%s\n      | %s", g->loc.line, lead, (int)shown, line + from,
          from + shown < len ? "..." : "", from ? "   " : "");
  /* Keep tabs so the caret lines up under the same column. */
  for (size_t i = from; i < col && i < len; i++) fputc(line[i] == '\t' ? '\t' : ' ', out);
  fprintf(out, "%s^%s\n", COLOR("\033[1;32m"), COLOR("\033[0m"));
}

static void print_one(const bg_diags *d, line_cursor *c, const bg_diag *g, FILE *out) {
  const char *bold = COLOR("\033[1m"), *sev = COLOR(sevcolor[g->sev]), *off = COLOR("\033[0m");
  const char *path = bg_diags_path(d, g->loc);
  if (g->loc.line > 0)
    fprintf(out, "%s%s:%d:%d:%s %s%s:%s %s\n", bold, path, g->loc.line, g->loc.col, off, sev,
            sevname[g->sev], off, g->msg);
  else
    fprintf(out, "%s%s:%s %s%s:%s %s\n", bold, path, off, sev, sevname[g->sev], off, g->msg);
  size_t len = 0;
  const char *line = find_line(d, c, g->loc, &len);
  if (line) print_caret_line(g, line, len, out);
}

typedef struct print_ctx { const bg_diags *d; line_cursor *c; FILE *out; } print_ctx;

static void print_note(const bg_diag *g, void *ctx) {
  print_ctx *p = ctx;
  print_one(p->d, p->c, g, p->out);
}

/* A diagnostic, then the chain of instances its source is used from. */
static void print_with_chain(const bg_diags *d, line_cursor *c, const bg_diag *g, FILE *out) {
  print_one(d, c, g, out);
  print_ctx p = {d, c, out};
  each_context(d, g->loc.file, print_note, &p);
}

static void json_fields(bg_strbuf *b, const bg_diags *d, const bg_diag *g) {
  bg_sb_puts(b, "{\"file\":");
  bg_sb_json_str(b, bg_diags_path(d, g->loc));
  bg_sb_printf(b, ",\"line\":%d,\"column\":%d,\"severity\":\"%s\",\"message\":", g->loc.line,
               g->loc.col, sevname[g->sev]);
  bg_sb_json_str(b, g->msg);
}

/* One line: the diagnostic and the notes that follow it in d. */
typedef struct json_ctx { bg_strbuf *b; const bg_diags *d; int n; } json_ctx;

static void json_note(const bg_diag *g, void *ctx) {
  json_ctx *j = ctx;
  if (j->n++) bg_sb_putc(j->b, ',');
  json_fields(j->b, j->d, g);
  bg_sb_putc(j->b, '}');
}

static void print_json(const bg_diags *d, const bg_diag *g, FILE *out) {
  bg_strbuf b = {0};
  json_fields(&b, d, g);
  bg_sb_puts(&b, ",\"notes\":[");
  json_ctx j = {&b, d, 0};
  for (const bg_diag *n = g + 1; n < d->items + d->n && n->sev == BG_SEV_NOTE; n++) json_note(n, &j);
  each_context(d, g->loc.file, json_note, &j); /* the instance chain */
  bg_sb_puts(&b, "]}\n");
  fputs(bg_sb_str(&b), out);
  bg_sb_free(&b);
}

/* bg_diags_each's instance chain: each link a note. */
static void visit_chain(const bg_diag *g, void *ctx) {
  struct { void (*fn)(void *, const bg_diag *, int); void *ctx; } *c = ctx;
  c->fn(c->ctx, g, 1);
}

static int cmp_pos(const void *a, const void *b) {
  const bg_diag *x = *(bg_diag *const *)a, *y = *(bg_diag *const *)b;
  if (x->loc.file != y->loc.file) return x->loc.file < y->loc.file ? -1 : 1;
  if (x->loc.line != y->loc.line) return x->loc.line < y->loc.line ? -1 : 1;
  if (x->loc.col != y->loc.col) return x->loc.col < y->loc.col ? -1 : 1;
  return x < y ? -1 : (x > y);
}

void bg_diags_each(const bg_diags *d, void (*fn)(void *ctx, const bg_diag *g, int is_note),
                   void *ctx) {
  const bg_diag **order = bg_xmalloc((size_t)(d->n ? d->n : 1) * sizeof *order);
  int k = 0;
  for (int i = 0; i < d->n; i++)
    if (d->items[i].sev != BG_SEV_NOTE || i == 0) order[k++] = &d->items[i];
  qsort(order, (size_t)k, sizeof *order, cmp_pos);
  for (int i = 0; i < k; i++) {
    fn(ctx, order[i], 0);
    for (const bg_diag *n = order[i] + 1; n < d->items + d->n && n->sev == BG_SEV_NOTE; n++)
      fn(ctx, n, 1);
    struct { void (*fn)(void *, const bg_diag *, int); void *ctx; } chain = {fn, ctx};
    each_context(d, order[i]->loc.file, visit_chain, &chain);
  }
  free(order);
}

void bg_diags_print(const bg_diags *d, FILE *out) {
  /* Notes stay right after the diagnostic they follow; only the others sort. */
  const bg_diag **order = bg_xmalloc((size_t)(d->n ? d->n : 1) * sizeof *order);
  int k = 0;
  for (int i = 0; i < d->n; i++)
    if (d->items[i].sev != BG_SEV_NOTE || i == 0) order[k++] = &d->items[i];
  qsort(order, (size_t)k, sizeof *order, cmp_pos);
  line_cursor c = {NULL, 0, NULL};
  for (int i = 0; i < k; i++) {
    if (use_json) {
      print_json(d, order[i], out);
      continue;
    }
    print_with_chain(d, &c, order[i], out);
    for (const bg_diag *g = order[i] + 1; g < d->items + d->n && g->sev == BG_SEV_NOTE; g++)
      print_one(d, &c, g, out);
  }
  free(order);
  if (d->dropped && use_json) {
    bg_strbuf b = {0};
    bg_sb_puts(&b, "{\"file\":");
    bg_sb_json_str(&b, d->file);
    bg_sb_printf(&b, ",\"line\":0,\"column\":0,\"severity\":\"note\",\"message\":\"%d more "
                 "error%s not shown: stopped at %d errors\",\"notes\":[]}\n", d->dropped,
                 d->dropped == 1 ? "" : "s", d->max_errors);
    fputs(bg_sb_str(&b), out);
    bg_sb_free(&b);
  } else if (d->dropped)
    fprintf(out, "%s: note: %d more error%s not shown: stopped at %d errors "
                 "(--max-errors N changes the limit, 0 shows all)\n",
            d->file, d->dropped, d->dropped == 1 ? "" : "s", d->max_errors);
}
