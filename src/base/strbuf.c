/* SPDX-License-Identifier: BSD-3-Clause */
#include "base/strbuf.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"

/* Hands the text to the sink and starts again empty (strbuf.h). */
static void pass_on(bg_strbuf *b) {
  bg_sb_sink *k = b->sink;
  if (!k->err) {
    int rc = k->take(k, b->s, b->len);
    if (rc > 0) { /* declined: the text stays whole here */
      b->sink = NULL;
      return;
    }
    if (rc < 0) k->err = errno ? errno : EIO;
    else k->passed += b->len;
  }
  b->len = 0;
  b->s[0] = '\0';
}

static void reserve(bg_strbuf *b, size_t extra) {
  if (b->sink && b->len && b->len + extra + 1 > b->sink->chunk) pass_on(b);
  if (b->len + extra + 1 <= b->cap) return;
  size_t cap = b->cap ? b->cap * 2 : 64;
  while (cap < b->len + extra + 1) cap *= 2;
  b->s = bg_xrealloc(b->s, cap);
  b->cap = cap;
}

void bg_sb_putn(bg_strbuf *b, const char *s, size_t n) {
  reserve(b, n);
  memcpy(b->s + b->len, s, n);
  b->len += n;
  b->s[b->len] = '\0';
}

void bg_sb_putc(bg_strbuf *b, char c) { bg_sb_putn(b, &c, 1); }
void bg_sb_puts(bg_strbuf *b, const char *s) { bg_sb_putn(b, s, strlen(s)); }

void bg_sb_vprintf(bg_strbuf *b, const char *fmt, va_list ap) {
  va_list ap2;
  va_copy(ap2, ap);
  int n = vsnprintf(NULL, 0, fmt, ap);
  if (n > 0) {
    reserve(b, (size_t)n);
    vsnprintf(b->s + b->len, (size_t)n + 1, fmt, ap2);
    b->len += (size_t)n;
  }
  va_end(ap2);
}

void bg_sb_printf(bg_strbuf *b, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  bg_sb_vprintf(b, fmt, ap);
  va_end(ap);
}

void bg_sb_json_str(bg_strbuf *b, const char *s) {
  bg_sb_putc(b, '"');
  for (; *s; s++) {
    unsigned char c = (unsigned char)*s;
    if (c == '"' || c == '\\') {
      bg_sb_putc(b, '\\');
      bg_sb_putc(b, (char)c);
    } else if (c == '\n') {
      bg_sb_puts(b, "\\n");
    } else if (c == '\t') {
      bg_sb_puts(b, "\\t");
    } else if (c < 0x20) {
      bg_sb_printf(b, "\\u%04x", c);
    } else {
      bg_sb_putc(b, (char)c);
    }
  }
  bg_sb_putc(b, '"');
}

void bg_sb_num(bg_strbuf *b, double v) {
  if (isnan(v)) { bg_sb_puts(b, "nan"); return; }
  if (isinf(v)) { bg_sb_puts(b, v < 0 ? "-inf" : "inf"); return; }
  char buf[40];
  bg_num_format(buf, sizeof buf, v, 15);
  bg_sb_puts(b, buf);
}

void bg_sb_json_num(bg_strbuf *b, double v) {
  if (!isfinite(v)) {
    bg_sb_puts(b, "null");
    return;
  }
  if (v == 0) v = 0; /* no "-0" */
  bg_sb_num(b, v);
}

const char *bg_sb_str(const bg_strbuf *b) { return b->s ? b->s : ""; }

void bg_sb_clear(bg_strbuf *b) {
  b->len = 0;
  if (b->s) b->s[0] = '\0';
}

void bg_sb_free(bg_strbuf *b) {
  free(b->s);
  b->s = NULL;
  b->len = b->cap = 0;
}

/* Levenshtein distance for "did you mean" hints; strings longer than 63
 * characters are simply far (99). */
int bg_edit_distance(const char *a, const char *b) {
  int la = (int)strlen(a), lb = (int)strlen(b);
  if (la > 63 || lb > 63) return 99;
  int row[64];
  for (int j = 0; j <= lb; j++) row[j] = j;
  for (int i = 1; i <= la; i++) {
    int diag = row[0];
    row[0] = i;
    for (int j = 1; j <= lb; j++) {
      int up = row[j];
      int best = diag + (a[i - 1] != b[j - 1]);
      if (up + 1 < best) best = up + 1;
      if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
      row[j] = best;
      diag = up;
    }
  }
  return row[lb];
}

/* The length of the valid UTF-8 sequence starting at p (lead byte c >=
 * 0x80), or 0 (RFC 3629: the second byte's range excludes overlong forms,
 * surrogates and values above U+10FFFF). */
static size_t utf8_sequence(const unsigned char *p, size_t left) {
  unsigned c = p[0];
  size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (n == 0 || left < n) return 0;
  unsigned lo = 0x80, hi = 0xBF;
  if (c == 0xE0) lo = 0xA0;
  else if (c == 0xED) hi = 0x9F;
  else if (c == 0xF0) lo = 0x90;
  else if (c == 0xF4) hi = 0x8F;
  if (p[1] < lo || p[1] > hi) return 0;
  for (size_t i = 2; i < n; i++)
    if ((p[i] & 0xC0) != 0x80) return 0;
  return n;
}

size_t bg_text_bad_byte(const char *s, size_t len, const char **why) {
  const unsigned char *p = (const unsigned char *)s;
  for (size_t i = 0; i < len;) {
    if (p[i] == 0) {
      if (why) *why = "a NUL byte";
      return i;
    }
    if (p[i] < 0x80) {
      i++;
      continue;
    }
    size_t n = utf8_sequence(p + i, len - i);
    if (n == 0) {
      if (why) *why = "a byte that is not valid UTF-8";
      return i;
    }
    i += n;
  }
  return len;
}
