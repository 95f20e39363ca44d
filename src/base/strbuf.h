/* SPDX-License-Identifier: BSD-3-Clause */
/* strbuf: a growable NUL-terminated string, or (with a sink) the tail of
 * a text that is passed on in pieces as it grows. */
#ifndef BG_STRBUF_H
#define BG_STRBUF_H
#include <stdarg.h>
#include <stddef.h>

/* Where a strbuf's text goes in pieces (fileio.h's bg_stream is one): when
 * an append would take the text past `chunk` bytes, the text so far is
 * handed to take() and the strbuf starts again empty, so a writer that only
 * appends holds about `chunk` bytes instead of its whole output (a 100 000-mass
 * SVG is 500 MB). take() returns 0 when it took the bytes, 1 when it
 * declines (the strbuf then keeps its whole text, as without a sink), -1
 * on failure with errno set (the failure is kept in err and the text is
 * dropped from then on). Only for writers that never read back or shorten
 * what they appended: bg_sb_str sees the tail. */
typedef struct bg_sb_sink {
  int (*take)(struct bg_sb_sink *k, const char *p, size_t n);
  size_t chunk;
  size_t passed; /* bytes taken so far */
  int err;       /* errno of the first failure, else 0 */
} bg_sb_sink;

typedef struct bg_strbuf {
  char *s; /* owned; NULL until the first append */
  size_t len, cap;
  bg_sb_sink *sink; /* NULL: the whole text stays here */
} bg_strbuf;

void bg_sb_putc(bg_strbuf *b, char c);
void bg_sb_puts(bg_strbuf *b, const char *s);
void bg_sb_putn(bg_strbuf *b, const char *s, size_t n);
void bg_sb_printf(bg_strbuf *b, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
/* The same with a va_list (ap is used up, as vsnprintf uses it). */
void bg_sb_vprintf(bg_strbuf *b, const char *fmt, va_list ap);
/* Appends s as a JSON string literal, quotes included. */
void bg_sb_json_str(bg_strbuf *b, const char *s);
/* The one number printer: the shortest "%.Ng" with N from min_digits to 17
 * that reads back as the same double (buf of at least 32 bytes; a v that is
 * not finite prints as printf's "%.17g" does: nan, inf, -inf).
 * Every number bgdraw writes for a program to read (JSON, CSV, equations,
 * generated C, re-parsable expressions) goes through it; min_digits 15 is the
 * usual choice (the digits of the shortest decimal that round-trips), 6 gives
 * %g's exponent style for round numbers (1e+06 instead of 1000000). */
void bg_num_format(char *buf, size_t size, double v, int min_digits);
/* Appends bg_num_format(v, 15); "nan", "inf" or "-inf" when not finite. */
void bg_sb_num(bg_strbuf *b, double v);
/* Appends a double the way JSON wants it: bg_num_format(v, 15), no "-0",
 * null when not finite. */
void bg_sb_json_num(bg_strbuf *b, double v);
/* The text so far (never NULL: "" when empty). */
const char *bg_sb_str(const bg_strbuf *b);
void bg_sb_clear(bg_strbuf *b);
void bg_sb_free(bg_strbuf *b);
/* Edit distance of two short strings (99 when one is over 63 characters). */
int bg_edit_distance(const char *a, const char *b);
/* The offset of the first byte of s[0..len) that makes it no text: a NUL,
 * or a byte of no valid UTF-8 sequence (overlong forms, surrogates and code
 * points above U+10FFFF are invalid); len when the text is valid. *why
 * (nullable) says which. */
size_t bg_text_bad_byte(const char *s, size_t len, const char **why);
#endif
