#include "base/diag.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/strbuf.h"

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
}

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
DEFINE_ADDER(bg_diag_error, BG_SEV_ERROR)
DEFINE_ADDER(bg_diag_warning, BG_SEV_WARNING)
DEFINE_ADDER(bg_diag_note, BG_SEV_NOTE)

/* Finds source lines for diagnostics printed in line order: a cursor that
 * moves forward, so printing k diagnostics reads the source once (it restarts
 * only for a note about an earlier line). */
typedef struct line_cursor {
  const char *p; /* start of line `line` */
  int line;
} line_cursor;

/* The text of source line `line` (1-based) without its line end. */
static const char *find_line(const bg_diags *d, line_cursor *c, int line, size_t *len) {
  if (!d->src || line < 1) return NULL;
  const char *end = d->src + d->srclen;
  if (!c->p || line < c->line) c->p = d->src, c->line = 1;
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
  if (g->loc.line > 0)
    fprintf(out, "%s%s:%d:%d:%s %s%s:%s %s\n", bold, d->file, g->loc.line, g->loc.col, off, sev,
            sevname[g->sev], off, g->msg);
  else
    fprintf(out, "%s%s:%s %s%s:%s %s\n", bold, d->file, off, sev, sevname[g->sev], off, g->msg);
  size_t len = 0;
  const char *line = find_line(d, c, g->loc.line, &len);
  if (line) print_caret_line(g, line, len, out);
}

static void json_fields(bg_strbuf *b, const bg_diags *d, const bg_diag *g) {
  bg_sb_puts(b, "{\"file\":");
  bg_sb_json_str(b, d->file);
  bg_sb_printf(b, ",\"line\":%d,\"column\":%d,\"severity\":\"%s\",\"message\":", g->loc.line,
               g->loc.col, sevname[g->sev]);
  bg_sb_json_str(b, g->msg);
}

/* One line: the diagnostic and the notes that follow it in d. */
static void print_json(const bg_diags *d, const bg_diag *g, FILE *out) {
  bg_strbuf b = {0};
  json_fields(&b, d, g);
  bg_sb_puts(&b, ",\"notes\":[");
  for (const bg_diag *n = g + 1; n < d->items + d->n && n->sev == BG_SEV_NOTE; n++) {
    if (n > g + 1) bg_sb_putc(&b, ',');
    json_fields(&b, d, n);
    bg_sb_putc(&b, '}');
  }
  bg_sb_puts(&b, "]}\n");
  fputs(bg_sb_str(&b), out);
  bg_sb_free(&b);
}

static int cmp_pos(const void *a, const void *b) {
  const bg_diag *x = *(bg_diag *const *)a, *y = *(bg_diag *const *)b;
  if (x->loc.line != y->loc.line) return x->loc.line < y->loc.line ? -1 : 1;
  if (x->loc.col != y->loc.col) return x->loc.col < y->loc.col ? -1 : 1;
  return x < y ? -1 : (x > y);
}

void bg_diags_print(const bg_diags *d, FILE *out) {
  /* Notes stay right after the diagnostic they follow; only the others sort. */
  const bg_diag **order = bg_xmalloc((size_t)(d->n ? d->n : 1) * sizeof *order);
  int k = 0;
  for (int i = 0; i < d->n; i++)
    if (d->items[i].sev != BG_SEV_NOTE || i == 0) order[k++] = &d->items[i];
  qsort(order, (size_t)k, sizeof *order, cmp_pos);
  line_cursor c = {NULL, 0};
  for (int i = 0; i < k; i++) {
    if (use_json) {
      print_json(d, order[i], out);
      continue;
    }
    print_one(d, &c, order[i], out);
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
