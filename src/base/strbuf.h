/* strbuf: a growable NUL-terminated string. */
#ifndef BG_STRBUF_H
#define BG_STRBUF_H
#include <stddef.h>

typedef struct bg_strbuf {
  char *s; /* owned; NULL until the first append */
  size_t len, cap;
} bg_strbuf;

void bg_sb_putc(bg_strbuf *b, char c);
void bg_sb_puts(bg_strbuf *b, const char *s);
void bg_sb_putn(bg_strbuf *b, const char *s, size_t n);
void bg_sb_printf(bg_strbuf *b, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
/* Appends s as a JSON string literal, quotes included. */
void bg_sb_json_str(bg_strbuf *b, const char *s);
/* Appends a double the way JSON and CSV want it (%.17g, finite only; null otherwise). */
void bg_sb_json_num(bg_strbuf *b, double v);
/* The text so far (never NULL: "" when empty). */
const char *bg_sb_str(const bg_strbuf *b);
void bg_sb_clear(bg_strbuf *b);
void bg_sb_free(bg_strbuf *b);
/* Edit distance of two short strings (99 when one is over 63 characters). */
int bg_edit_distance(const char *a, const char *b);
#endif
