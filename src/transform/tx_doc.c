/* SPDX-License-Identifier: BSD-3-Clause */
/* The text editor of the transformations: the model's source as physical
 * lines, edited statement by statement, so that everything a transformation
 * does not touch (comments, blank lines, layout, continuation lines) is
 * written back byte for byte. */
#include <stdlib.h>
#include <string.h>

#include "transform/tx_int.h"

void tx_doc_init(tx_doc *d, const char *src, size_t len) {
  memset(d, 0, sizeof *d);
  d->src = src;
  int n = 1;
  for (size_t i = 0; i < len; i++) n += src[i] == '\n';
  d->line = calloc((size_t)n + 2, sizeof *d->line);
  d->len = calloc((size_t)n + 2, sizeof *d->len);
  d->repl = calloc((size_t)n + 2, sizeof *d->repl);
  d->drop = calloc((size_t)n + 2, 1);
  d->cr = calloc((size_t)n + 2, 1);
  d->after = calloc((size_t)n + 2, sizeof *d->after);
  size_t start = 0;
  if (len >= 3 && !memcmp(src, "\xEF\xBB\xBF", 3)) start = 3; /* the header comes first */
  for (size_t i = start; i <= len; i++) {
    if (i < len && src[i] != '\n') continue;
    d->nline++;
    d->line[d->nline] = src + start;
    size_t l = i - start;
    if (l && src[start + l - 1] == '\r') l--, d->cr[d->nline] = 1;
    d->len[d->nline] = (int)l;
    start = i + 1;
  }
  if (d->nline && d->len[d->nline] == 0 && len && src[len - 1] == '\n') d->nline--; /* final newline */
}

void tx_doc_free(tx_doc *d) {
  for (int i = 0; i <= d->nline; i++) {
    free(d->repl[i]);
    bg_sb_free(&d->after[i]);
  }
  free(d->line);
  free(d->len);
  free(d->repl);
  free(d->drop);
  free(d->cr);
  free(d->after);
  bg_sb_free(&d->head);
  memset(d, 0, sizeof *d);
}

/* Where the comment of a physical line starts (its length when it has none):
 * the first '#' outside a string. */
static int comment_start(const char *s, int n) {
  int in_str = 0;
  for (int i = 0; i < n; i++) {
    if (in_str) {
      if (s[i] == '\\' && i + 1 < n) i++;
      else if (s[i] == '"') in_str = 0;
    } else if (s[i] == '"') {
      in_str = 1;
    } else if (s[i] == '#') {
      return i;
    }
  }
  return n;
}

/* A line continues on the next when its last non-blank character before
 * any comment is a backslash and nothing but blanks follows it (docs/format.md). */
static int continues(const char *s, int n) {
  int c = comment_start(s, n);
  if (c < n) return 0; /* a '\' followed by a comment is no continuation */
  while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t')) n--;
  return n > 0 && s[n - 1] == '\\';
}

int tx_stmt_end(const tx_doc *d, int line) {
  while (line < d->nline && continues(d->line[line], d->len[line])) line++;
  return line;
}

void tx_delete_stmt(tx_doc *d, int line) {
  int end = tx_stmt_end(d, line);
  free(d->repl[line]); /* a statement first rewritten, then removed */
  d->repl[line] = NULL;
  for (int i = line; i <= end; i++) d->drop[i] = 1;
}

void tx_replace_stmt(tx_doc *d, int line, const char *text) {
  int end = tx_stmt_end(d, line);
  bg_strbuf b = {0};
  bg_sb_puts(&b, text);
  int c = comment_start(d->line[end], d->len[end]);
  if (c < d->len[end]) {
    bg_sb_puts(&b, "  ");
    bg_sb_putn(&b, d->line[end] + c, (size_t)(d->len[end] - c));
  }
  free(d->repl[line]);
  d->repl[line] = strdup(bg_sb_str(&b));
  bg_sb_free(&b);
  for (int i = line + 1; i <= end; i++) d->drop[i] = 1;
}

void tx_insert_after(tx_doc *d, int line, const char *text) {
  int end = line > 0 ? tx_stmt_end(d, line) : 0;
  bg_sb_puts(&d->after[end], text);
  bg_sb_putc(&d->after[end], '\n');
}

/* New text with the file's line ending: "\n" becomes "\r\n" in a CRLF file. */
static void put_text(bg_strbuf *b, const char *s, int crlf) {
  for (; *s; s++) {
    if (*s == '\n' && crlf) bg_sb_putc(b, '\r');
    bg_sb_putc(b, *s);
  }
}

char *tx_doc_text(const tx_doc *d) {
  bg_strbuf b = {0};
  int ncr = 0;
  for (int i = 1; i <= d->nline; i++) ncr += d->cr[i];
  int crlf = 2 * ncr > d->nline; /* most lines end in CR LF: so do the new ones */
  put_text(&b, bg_sb_str(&d->head), crlf);
  put_text(&b, bg_sb_str(&d->after[0]), crlf);
  for (int i = 1; i <= d->nline; i++) {
    if (d->repl[i]) {
      put_text(&b, d->repl[i], crlf);
      bg_sb_puts(&b, crlf ? "\r\n" : "\n");
    } else if (!d->drop[i]) {
      bg_sb_putn(&b, d->line[i], (size_t)d->len[i]);
      bg_sb_puts(&b, d->cr[i] ? "\r\n" : "\n");
    }
    put_text(&b, bg_sb_str(&d->after[i]), crlf);
  }
  char *s = strdup(bg_sb_str(&b));
  bg_sb_free(&b);
  return s;
}
