/* SPDX-License-Identifier: BSD-3-Clause */
/* Report text: markup pieces, greedy line breaking, wrapping with pango
 * metrics, equations typeset as markup, number and count wording. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"
#include "report/report_int.h"

/* Words longer than this many visible characters may break inside. */
#define RP_LONG_WORD 16

const bg_rgba rp_ink = {0.08, 0.08, 0.08, 1}, rp_grey = {0.42, 0.42, 0.42, 1},
              rp_rule = {0.72, 0.72, 0.72, 1}, rp_shade = {0.93, 0.93, 0.93, 1},
              rp_accent = {0.10, 0.22, 0.45, 1}, rp_red = {0.75, 0.10, 0.10, 1};

/* ---------------------------------------------------------------- pieces */
static void words_push(rp_words *w, const char *s, size_t n, int space_before) {
  if (n == 0) return;
  if (w->n == w->cap) {
    w->cap = w->cap ? 2 * w->cap : 16;
    w->text = bg_xrealloc(w->text, (size_t)w->cap * sizeof *w->text);
    w->space_before = bg_xrealloc(w->space_before, (size_t)w->cap * sizeof(int));
  }
  char *t = bg_xmalloc(n + 1);
  memcpy(t, s, n), t[n] = 0;
  w->text[w->n] = t;
  w->space_before[w->n++] = space_before;
}

/* A break is allowed after these (outside tags) in long words. */
static int break_after(const char *p) {
  if (*p == '*' || *p == '/' || *p == ',' || *p == '(' || *p == '+') return 1;
  return (unsigned char)p[0] == 0xc2 && (unsigned char)p[1] == 0xb7 ? 2 : 0; /* · */
}

/* Splits one space-free word (balanced at depth 0 at both ends) into pieces. */
static void split_long(rp_words *w, const char *s, size_t n, int space_before) {
  size_t visible = 0;
  int intag = 0;
  for (size_t i = 0; i < n; i++) {
    if (s[i] == '<') intag = 1;
    else if (s[i] == '>') intag = 0;
    else if (!intag && ((unsigned char)s[i] & 0xc0) != 0x80) visible++;
  }
  if (visible <= RP_LONG_WORD) {
    words_push(w, s, n, space_before);
    return;
  }
  size_t from = 0;
  int depth = 0;
  intag = 0;
  for (size_t i = 0; i < n; i++) {
    if (s[i] == '<') {
      intag = 1;
      depth += s[i + 1] == '/' ? -1 : 1;
    } else if (s[i] == '>') {
      intag = 0;
      if (i > 0 && s[i - 1] == '/') depth--;
    } else if (!intag && depth == 0) {
      int k = break_after(s + i);
      if (k && i + (size_t)k < n) {
        words_push(w, s + from, i + (size_t)k - from, from == 0 ? space_before : 0);
        from = i + (size_t)k;
        i += (size_t)k - 1;
      }
    }
  }
  words_push(w, s + from, n - from, from == 0 ? space_before : 0);
}

/* Open tags at a split point: closed at the end of one piece and opened
 * again at the start of the next, so every piece is valid markup. */
typedef struct tagstack {
  int n;
  const char *at[32]; /* start of each open tag in the markup */
  size_t len[32];
} tagstack;

static void finish_piece(rp_words *w, bg_strbuf *cur, int visible, const tagstack *st, int space) {
  if (visible) {
    for (int i = st->n - 1; i >= 0; i--) {
      const char *t = st->at[i] + 1;
      size_t k = 0;
      while (k < st->len[i] - 2 && t[k] != ' ' && t[k] != '>') k++;
      bg_sb_puts(cur, "</"), bg_sb_putn(cur, t, k), bg_sb_putc(cur, '>');
    }
    split_long(w, cur->s, cur->len, w->n > 0 && space);
  }
  bg_sb_clear(cur);
  for (int i = 0; i < st->n; i++) bg_sb_putn(cur, st->at[i], st->len[i]);
}

/* One tag at p (ending at its '>'): appended to cur, the stack updated. */
static const char *take_tag(const char *p, bg_strbuf *cur, tagstack *st) {
  const char *e = strchr(p, '>');
  if (!e) e = p + strlen(p) - 1;
  size_t n = (size_t)(e - p) + 1;
  bg_sb_putn(cur, p, n);
  if (p[1] == '/') {
    if (st->n > 0) st->n--;
  } else if (e[-1] != '/' && st->n < 32) {
    st->at[st->n] = p, st->len[st->n++] = n;
  }
  return e + (*e ? 1 : 0);
}

void rp_words_split(const char *markup, rp_words *w) {
  memset(w, 0, sizeof *w);
  bg_strbuf cur = {0};
  tagstack st = {0};
  int visible = 0, space = 0;
  const char *p = markup;
  while (*p) {
    if (*p == '<') {
      p = take_tag(p, &cur, &st);
    } else if (*p == ' ') {
      if (visible) finish_piece(w, &cur, 1, &st, space), visible = 0, space = 0;
      space = 1;
      p++;
    } else {
      bg_sb_putc(&cur, *p++);
      visible = 1;
    }
  }
  if (visible) split_long(w, cur.s, cur.len, w->n > 0 && space);
  bg_sb_free(&cur);
}

void rp_words_free(rp_words *w) {
  for (int i = 0; i < w->n; i++) free(w->text[i]);
  free(w->text);
  free(w->space_before);
  memset(w, 0, sizeof *w);
}

/* ---------------------------------------------------------------- breaking */
int rp_break_lines(const double *w, const int *space_before, int n, double space, double width1,
                   double width2, int *start) {
  int nl = 0;
  double x = 0;
  for (int i = 0; i < n; i++) {
    if (nl == 0) {
      start[nl++] = i, x = w[i];
      continue;
    }
    double lim = nl == 1 ? width1 : width2;
    double add = (space_before[i] ? space : 0) + w[i];
    if (x + add <= lim + 1e-9) {
      x += add;
    } else {
      start[nl++] = i, x = w[i];
    }
  }
  return nl;
}

double rp_text_width(const char *font, double size, const char *markup) {
  double w, h;
  bg_text_measure(font, size, markup, &w, &h);
  return w;
}

double rp_line_height(const char *font, double size) {
  double w, h;
  bg_text_measure(font, size, "Hg", &w, &h);
  return h;
}

void rp_wrap(const char *font, double size, const char *markup, double width1, double width2,
             rp_lines *out) {
  rp_words w;
  rp_words_split(markup, &w);
  memset(out, 0, sizeof *out);
  if (w.n == 0) {
    out->n = 1;
    out->line = bg_xmalloc(sizeof(char *));
    out->line[0] = bg_xmalloc(1);
    out->line[0][0] = 0;
    rp_words_free(&w);
    return;
  }
  double *wd = bg_xmalloc((size_t)w.n * sizeof(double));
  int *start = bg_xmalloc((size_t)w.n * sizeof(int));
  for (int i = 0; i < w.n; i++) wd[i] = rp_text_width(font, size, w.text[i]);
  double space = rp_text_width(font, size, "x x") - rp_text_width(font, size, "xx");
  out->n = rp_break_lines(wd, w.space_before, w.n, space, width1, width2, start);
  out->line = bg_xmalloc((size_t)out->n * sizeof(char *));
  for (int l = 0; l < out->n; l++) {
    int end = l + 1 < out->n ? start[l + 1] : w.n;
    bg_strbuf b = {0};
    for (int i = start[l]; i < end; i++) {
      if (i > start[l] && w.space_before[i]) bg_sb_putc(&b, ' ');
      bg_sb_puts(&b, w.text[i]);
    }
    out->line[l] = strdup(bg_sb_str(&b));
    bg_sb_free(&b);
  }
  free(wd);
  free(start);
  rp_words_free(&w);
}

void rp_lines_free(rp_lines *l) {
  for (int i = 0; i < l->n; i++) free(l->line[i]);
  free(l->line);
  memset(l, 0, sizeof *l);
}

/* ---------------------------------------------------------------- words, numbers */
void rp_esc(bg_strbuf *b, const char *s) { bg_markup_escape(b, s ? s : ""); }

void rp_num(bg_strbuf *b, double v) {
  char buf[64];
  if (v == 0) v = 0; /* no "-0" */
  snprintf(buf, sizeof buf, "%.4g", v);
  if (buf[0] == '-') bg_sb_printf(b, "\u2212%s", buf + 1);
  else bg_sb_puts(b, buf);
}

void rp_gain_value(bg_strbuf *b, double v, int order) {
  rp_num(b, v);
  if (order == 1) bg_sb_puts(b, "/s");
  else if (order > 1) bg_sb_printf(b, "/s<sup>%d</sup>", order);
}

const char *rp_count_word(int n) {
  static const char *words[] = {"no", "one", "two", "three", "four", "five", "six",
                                "seven", "eight", "nine", "ten", "eleven", "twelve"};
  static _Thread_local char buf[32]; /* reports on two threads: one each */
  if (n >= 0 && n <= 12) return words[n];
  snprintf(buf, sizeof buf, "%d", n);
  return buf;
}

void rp_count(bg_strbuf *b, int n, const char *noun) {
  bg_sb_printf(b, "%d %s%s", n, noun, n == 1 ? "" : "s");
}

void rp_bond_list(bg_strbuf *b, const bg_model *m, const int *bonds, int n) {
  for (int i = 0; i < n; i++) bg_sb_printf(b, "%s%d", i ? ", " : "", m->bond_num[bonds[i]]);
}

/* ---------------------------------------------------------------- equations */
static void sub_open(bg_strbuf *o, double size) {
  bg_sb_printf(o, "<span size=\"70%%\" rise=\"%.1fpt\">", -0.27 * size);
}

static void sup_open(bg_strbuf *o, double size) {
  bg_sb_printf(o, "<span size=\"70%%\" rise=\"%.1fpt\">", 0.42 * size);
}

/* A variable letter (italic), with a dot above for a derivative. */
static void put_var(bg_strbuf *o, const char *s, size_t n, int deriv) {
  bg_sb_puts(o, "<i>");
  bg_strbuf t = {0};
  bg_sb_putn(&t, s, n);
  rp_esc(o, bg_sb_str(&t));
  bg_sb_free(&t);
  if (deriv) bg_sb_puts(o, n == 1 ? "\u0307" : "\u2032");
  bg_sb_puts(o, "</i>");
}

static void put_name(bg_strbuf *o, const char *nm, size_t n, int deriv, int func, double size) {
  const char *dot = memchr(nm, '.', n);
  const char *last = dot;
  while (last && memchr(last + 1, '.', n - (size_t)(last + 1 - nm)))
    last = memchr(last + 1, '.', n - (size_t)(last + 1 - nm));
  size_t k = 1;
  while (k < n && isdigit((unsigned char)nm[k])) k++;
  bg_strbuf t = {0};
  if (func) {
    bg_sb_putn(&t, nm, n);
    rp_esc(o, bg_sb_str(&t));
  } else if ((nm[0] == 'e' || nm[0] == 'f') && n > 1 && k == n) {
    put_var(o, nm, 1, deriv);
    sub_open(o, size), bg_sb_putn(o, nm + 1, n - 1), bg_sb_puts(o, "</span>");
  } else if (last && last + 1 < nm + n) {
    put_var(o, last + 1, n - (size_t)(last + 1 - nm), deriv);
    bg_sb_putn(&t, nm, (size_t)(last - nm));
    sub_open(o, size), rp_esc(o, bg_sb_str(&t)), bg_sb_puts(o, "</span>");
  } else if (n == 1 || deriv) {
    put_var(o, nm, n, deriv);
  } else {
    bg_sb_putn(&t, nm, n);
    rp_esc(o, bg_sb_str(&t));
  }
  bg_sb_free(&t);
}

static const char *scan_number(const char *p) {
  while (isdigit((unsigned char)*p) || *p == '.') p++;
  if ((*p == 'e' || *p == 'E') &&
      (isdigit((unsigned char)p[1]) || ((p[1] == '-' || p[1] == '+') && isdigit((unsigned char)p[2])))) {
    p += 2;
    while (isdigit((unsigned char)*p)) p++;
  }
  return p;
}

static const char *scan_name(const char *p) {
  while (isalnum((unsigned char)*p) || *p == '_' || *p == '.') p++;
  return p;
}

/* ^ followed by a number or a name: a superscript; else the caret stays. */
static const char *put_power(bg_strbuf *o, const char *p, double size) {
  const char *q = p + 1, *e = q;
  if (*q == '-' && (isdigit((unsigned char)q[1]) || isalpha((unsigned char)q[1]))) e = q + 1;
  if (isdigit((unsigned char)*e) || *e == '.') e = scan_number(e);
  else if (isalpha((unsigned char)*e)) e = scan_name(e);
  if (e == q || (*q == '-' && e == q + 1)) {
    bg_sb_putc(o, '^');
    return q;
  }
  sup_open(o, size);
  if (*q == '-') bg_sb_puts(o, "\u2212"), q++;
  bg_strbuf t = {0};
  bg_sb_putn(&t, q, (size_t)(e - q));
  rp_esc(o, bg_sb_str(&t));
  bg_sb_free(&t);
  bg_sb_puts(o, "</span>");
  return e;
}

void rp_eq_markup(const char *plain, double size, bg_strbuf *out) {
  const char *p = plain;
  while (*p) {
    if (isalpha((unsigned char)*p) || *p == '_') {
      const char *e = scan_name(p);
      int deriv = *e == '\'';
      put_name(out, p, (size_t)(e - p), deriv, *e == '(', size);
      p = e + deriv;
    } else if (isdigit((unsigned char)*p) || (*p == '.' && isdigit((unsigned char)p[1]))) {
      const char *e = scan_number(p);
      bg_sb_putn(out, p, (size_t)(e - p));
      p = e;
    } else if (*p == '^') {
      p = put_power(out, p, size);
    } else {
      switch (*p) {
      case '*': bg_sb_puts(out, "\u00b7"); break;
      case '-': bg_sb_puts(out, "\u2212"); break;
      case '<': bg_sb_puts(out, "&lt;"); break;
      case '>': bg_sb_puts(out, "&gt;"); break;
      case '&': bg_sb_puts(out, "&amp;"); break;
      default: bg_sb_putc(out, *p);
      }
      p++;
    }
  }
}
