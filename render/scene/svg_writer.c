/* SPDX-License-Identifier: BSD-3-Clause */
/* SVG for the web, written from the scene: paths as <path>, text as <text>
 * (so it can be searched, selected and restyled), the font with a fallback
 * list, a CSS class per role, <title> tooltips, a viewBox and no fixed size.
 * Positions come from pango's measurements (the same as the cairo surfaces),
 * so a rasterisation looks like the PNG and PDF. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene/surface.h"

/* A number with at most 2 decimals and no trailing zeros: small, stable.
 * The digits are those of printf's "%.2f" (the decimal nearest the double,
 * ties to even), found without printf: with a long double of 64 mantissa
 * bits |v| * 100 is exact (53 + 7 bits), so its integer part and the
 * remainder decide the rounding. Printing every coordinate through
 * snprintf was a tenth of a large SVG's time. */
static void num(bg_strbuf *b, double v) {
  if (fabs(v) < 0.005) v = 0.0;
#if LDBL_MANT_DIG >= 64
  if (fabs(v) < 1e15) {
    long double p = fabsl((long double)v * 100);
    unsigned long long k = (unsigned long long)p;
    long double frac = p - (long double)k;
    if (frac > 0.5L || (frac == 0.5L && (k & 1))) k++;
    char buf[32], *e = buf + sizeof buf;
    *--e = '\0';
    unsigned cents = (unsigned)(k % 100);
    k /= 100;
    if (cents) {
      if (cents % 10) *--e = (char)('0' + cents % 10);
      *--e = (char)('0' + cents / 10);
      *--e = '.';
    }
    do *--e = (char)('0' + k % 10); while (k /= 10);
    if (v < 0) *--e = '-';
    bg_sb_puts(b, e);
    return;
  }
#endif
  char buf[64];
  snprintf(buf, sizeof buf, "%.2f", v);
  char *e = buf + strlen(buf) - 1;
  while (*e == '0') *e-- = '\0';
  if (*e == '.') *e = '\0';
  bg_sb_puts(b, buf);
}

static void hex2(bg_strbuf *b, double c) {
  static const char digit[] = "0123456789abcdef";
  int v = (int)(c * 255 + 0.5);
  if (v < 0 || v > 255) { /* as printf's %02x would show it */
    bg_sb_printf(b, "%02x", (unsigned)v);
    return;
  }
  bg_sb_putc(b, digit[v >> 4]), bg_sb_putc(b, digit[v & 15]);
}

static void color_attr(bg_strbuf *b, const char *name, bg_rgba c) {
  bg_sb_putc(b, ' '), bg_sb_puts(b, name), bg_sb_puts(b, "=\"#");
  hex2(b, c.r), hex2(b, c.g), hex2(b, c.b), bg_sb_putc(b, '"');
  if (c.a < 1) bg_sb_printf(b, " %s-opacity=\"%.3g\"", name, c.a);
}

static void path_data(bg_strbuf *b, const bg_scene *s, const bg_scene_item *it) {
  static const char code[] = "MLCZ";
  bg_sb_puts(b, " d=\"");
  bg_scene_op o_;
  for (int i = 0; bg_scene_next_op(s, it, &i, &o_);) {
    const bg_scene_op *o = &o_;
    int npt = o->code == BG_OP_CURVE ? 3 : o->code == BG_OP_CLOSE ? 0 : 1;
    bg_sb_putc(b, code[o->code]);
    for (int k = 0; k < npt; k++) {
      if (k) bg_sb_putc(b, ' ');
      num(b, o->x[k]), bg_sb_putc(b, ','), num(b, o->y[k]);
    }
  }
  bg_sb_putc(b, '"');
}

/* CSS classes from a role: the first word, then each number as the first
 * letter of its word and the number ("path 2 loop=1" -> "path p2 l1"), and
 * each key of key=value ("flash conflict=1" -> "flash conflict c1"). */
static void class_attr(bg_strbuf *b, const char *role) {
  char w0 = '\0'; /* the first word's letter */
  bg_sb_puts(b, " class=\"");
  int first = 1;
  for (const char *p = role; *p;) {
    while (*p == ' ') p++;
    size_t n = strcspn(p, " ");
    if (!n) break;
    char tok[128];
    size_t k = n < 127 ? n : 127;
    memcpy(tok, p, k), tok[k] = '\0';
    p += n;
    char *eq = strchr(tok, '=');
    if (first) {
      w0 = tok[0];
      bg_sb_puts(b, tok);
      first = 0;
    } else if (eq && eq[1] >= '0' && eq[1] <= '9' && strspn(eq + 1, "0123456789") == strlen(eq + 1)) {
      *eq = '\0';
      if (strcmp(tok, "bond")) bg_sb_putc(b, ' '), bg_sb_puts(b, tok);
      bg_sb_putc(b, ' '), bg_sb_putc(b, tok[0]), bg_sb_puts(b, eq + 1);
    } else if (tok[0] >= '0' && tok[0] <= '9' && strspn(tok, "0123456789") == strlen(tok)) {
      bg_sb_putc(b, ' '), bg_sb_putc(b, w0), bg_sb_puts(b, tok);
    }
  }
  bg_sb_putc(b, '"');
}

static void xml_text(bg_strbuf *b, const char *s) {
  while (*s) {
    size_t n = strcspn(s, "&<>\""); /* a run written at once */
    bg_sb_putn(b, s, n);
    s += n;
    if (*s == '&') bg_sb_puts(b, "&amp;");
    else if (*s == '<') bg_sb_puts(b, "&lt;");
    else if (*s == '>') bg_sb_puts(b, "&gt;");
    else if (*s == '"') bg_sb_puts(b, "&quot;");
    else break;
    s++;
  }
}

static void title(bg_strbuf *b, bg_svg_tip_fn tip, void *ctx, const char *role) {
  if (!tip) return;
  bg_strbuf t = {0};
  tip(ctx, role, &t);
  if (t.len) bg_sb_puts(b, "<title>"), xml_text(b, bg_sb_str(&t)), bg_sb_puts(b, "</title>");
  bg_sb_free(&t);
}

static void shape(bg_strbuf *b, const bg_scene *s, const bg_scene_item *it, bg_svg_tip_fn tip,
                  void *ctx) {
  bg_sb_puts(b, "<path");
  class_attr(b, it->role);
  path_data(b, s, it);
  int outline = it->kind == BG_ITEM_STROKE || it->width > 0;
  if (it->kind == BG_ITEM_FILL) color_attr(b, "fill", it->fill);
  else bg_sb_puts(b, " fill=\"none\"");
  if (outline) {
    color_attr(b, "stroke", it->color);
    bg_sb_puts(b, " stroke-width=\""), num(b, it->width), bg_sb_putc(b, '"');
    if (it->round) bg_sb_puts(b, " stroke-linecap=\"round\" stroke-linejoin=\"round\"");
    if (it->dash[0] > 0) {
      bg_sb_puts(b, " stroke-dasharray=\""), num(b, it->dash[0]), bg_sb_putc(b, ' ');
      num(b, it->dash[1]), bg_sb_putc(b, '"');
    }
  }
  bg_strbuf t = {0};
  title(&t, tip, ctx, it->role);
  if (t.len) bg_sb_printf(b, ">%s</path>\n", bg_sb_str(&t));
  else bg_sb_puts(b, "/>\n");
  bg_sb_free(&t);
}

/* ---------------------------------------------------------------- text */
/* Pango markup as bgdraw writes it: spans with size="P%" and rise="Rpt",
 * <b>, <i>, <sub>, <sup>, entities; the plots write spans in pango units (size and
 * rise in 1/1024 pt). Each run becomes a <tspan>. */
typedef struct run_style {
  double scale, rise; /* font size factor; baseline shift up, points */
  int bold, italic;
} run_style;

/* An attribute's unit as pango reads it: "70%", "3.5pt", or a bare number in pango
 * units (1/1024 pt). Returns the unit's first character, 'u' for pango units, 0 when
 * the attribute is absent. */
static char attr_unit(const char *tag, const char *name, double *v) {
  char key[32];
  snprintf(key, sizeof key, " %s=\"", name);
  const char *p = strstr(tag, key);
  if (!p) return 0;
  char *end;
  *v = strtod(p + strlen(key), &end);
  return *end == '%' ? '%' : *end == 'p' ? 'p' : 'u';
}

static run_style open_tag(const char *tag, run_style cur, double size) {
  if (!strncmp(tag, "<span", 5)) {
    double v;
    char u = attr_unit(tag, "size", &v); /* the plots write absolute sizes, the diagrams % */
    if (u == '%' && v > 0) cur.scale *= v / 100;
    else if (u == 'p' && v > 0) cur.scale = v / size;
    else if (u == 'u' && v > 0) cur.scale = v / 1024 / size;
    u = attr_unit(tag, "rise", &v);
    if (u) cur.rise += u == 'u' ? v / 1024 : v;
    if (strstr(tag, "weight=\"bold\"")) cur.bold = 1;
    if (strstr(tag, "style=\"italic\"")) cur.italic = 1;
  } else if (!strcmp(tag, "<b>")) cur.bold = 1;
  else if (!strcmp(tag, "<i>")) cur.italic = 1;
  else if (!strcmp(tag, "<sub>")) cur.scale *= 0.7, cur.rise -= 0.3 * size;
  else if (!strcmp(tag, "<sup>")) cur.scale *= 0.7, cur.rise += 0.4 * size;
  return cur;
}

static void put_run(bg_strbuf *b, const char *txt, size_t n, run_style st, double size,
                    double *shift) {
  if (!n) return;
  bg_sb_puts(b, "<tspan");
  double dy = -st.rise - *shift; /* SVG's y grows downwards; dy is relative */
  if (fabs(dy) > 1e-9) bg_sb_puts(b, " dy=\""), num(b, dy), bg_sb_putc(b, '"');
  *shift = -st.rise;
  if (st.scale != 1) bg_sb_puts(b, " font-size=\""), num(b, size * st.scale), bg_sb_putc(b, '"');
  if (st.bold) bg_sb_puts(b, " font-weight=\"bold\"");
  if (st.italic) bg_sb_puts(b, " font-style=\"italic\"");
  bg_sb_putc(b, '>');
  bg_sb_putn(b, txt, n); /* markup text is already escaped for XML */
  bg_sb_puts(b, "</tspan>");
}

static void text_runs(bg_strbuf *b, const char *m, double size) {
  run_style stack[8] = {{1, 0, 0, 0}};
  int depth = 0;
  double shift = 0;
  while (*m) {
    size_t n = strcspn(m, "<");
    put_run(b, m, n, stack[depth], size, &shift);
    m += n;
    if (!*m) break;
    size_t t = strcspn(m, ">");
    char tag[256];
    snprintf(tag, sizeof tag, "%.*s", (int)(t + 1 < 255 ? t + 1 : 255), m);
    m += m[t] ? t + 1 : t;
    if (tag[1] == '/') depth = depth > 0 ? depth - 1 : 0;
    else if (depth < 7) stack[depth + 1] = open_tag(tag, stack[depth], size), depth++;
  }
}

static void text(bg_strbuf *b, const bg_scene *s, const bg_scene_item *it, bg_svg_tip_fn tip,
                 void *ctx) {
  double x = it->x - it->halign * it->tw, y = it->y - it->valign * it->th;
  double base = bg_text_baseline(s->font, it->size, it->text);
  bg_sb_puts(b, "<text");
  class_attr(b, it->role);
  bg_sb_puts(b, " x=\""), num(b, x), bg_sb_puts(b, "\" y=\""), num(b, y + base);
  bg_sb_puts(b, "\" font-size=\""), num(b, it->size), bg_sb_putc(b, '"');
  color_attr(b, "fill", it->color);
  bg_sb_putc(b, '>');
  title(b, tip, ctx, it->role);
  text_runs(b, it->text, it->size);
  bg_sb_puts(b, "</text>\n");
}

/* The scene's font, then fonts with the same metrics class, then generic. */
static void font_family(bg_strbuf *b, const char *font) {
  bg_sb_puts(b, " font-family=\"'");
  xml_text(b, font);
  bg_sb_puts(b, "', 'DejaVu Sans', Verdana, 'Bitstream Vera Sans', Arial, sans-serif\"");
}

int bg_surface_svg_write_tips(const bg_scene *s, bg_svg_tip_fn tip, void *ctx, bg_strbuf *out) {
  bg_sb_puts(out, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 ");
  num(out, s->width), bg_sb_putc(out, ' '), num(out, s->height);
  bg_sb_puts(out, "\" class=\"bgdraw\"");
  font_family(out, s->font);
  bg_sb_puts(out, " stroke-miterlimit=\"10\" xml:space=\"preserve\">\n");
  if (s->title) bg_sb_puts(out, "<title>"), xml_text(out, s->title), bg_sb_puts(out, "</title>\n");
  bg_sb_puts(out, "<rect class=\"background\" width=\""), num(out, s->width);
  bg_sb_puts(out, "\" height=\""), num(out, s->height), bg_sb_putc(out, '"');
  color_attr(out, "fill", s->background);
  bg_sb_puts(out, "/>\n");
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    if (it->kind == BG_ITEM_TEXT) text(out, s, it, tip, ctx);
    else shape(out, s, it, tip, ctx);
  }
  bg_sb_puts(out, "</svg>\n");
  return 0;
}

int bg_surface_svg_write(const bg_scene *s, bg_strbuf *out) {
  return bg_surface_svg_write_tips(s, NULL, NULL, out);
}
