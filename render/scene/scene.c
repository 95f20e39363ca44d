/* SPDX-License-Identifier: BSD-3-Clause */
/* The display list: items with path operations, text and role tags. */
#include "scene/scene.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void bg_scene_init(bg_scene *s, const char *font) {
  memset(s, 0, sizeof *s);
  s->background = (bg_rgba){1, 1, 1, 1};
  s->font = bg_arena_strdup(&s->arena, font ? font : "Sans");
}

void bg_scene_free(bg_scene *s) {
  free(s->item);
  free(s->pt);
  free(s->code);
  bg_arena_free(&s->arena);
  memset(s, 0, sizeof *s);
}

bg_scene_item *bg_scene_begin(bg_scene *s, int kind, const char *role_fmt, ...) {
  if (s->nitem == s->capitem) {
    s->capitem = s->capitem ? 2 * s->capitem : 64;
    s->item = bg_xrealloc(s->item, (size_t)s->capitem * sizeof *s->item);
  }
  char role[256];
  va_list ap;
  va_start(ap, role_fmt);
  vsnprintf(role, sizeof role, role_fmt, ap);
  va_end(ap);
  bg_scene_item *it = &s->item[s->nitem++];
  memset(it, 0, sizeof *it);
  it->kind = kind;
  it->opadr = s->nop;
  it->color = (bg_rgba){0, 0, 0, 1};
  if (kind != BG_ITEM_TEXT) it->width = 1; /* text's anchor and size share its bytes */
  it->role = bg_arena_strdup(&s->arena, role);
  return it;
}

/* Appends n slots with code to the last item's path; returns the first. */
static bg_scene_pt *add_slots(bg_scene *s, int code, int n) {
  if (!s->nitem) BG_FATAL("scene path operation without an item");
  while (s->nop + n > s->capop) {
    s->capop = s->capop ? 2 * s->capop : 256;
    s->pt = bg_xrealloc(s->pt, (size_t)s->capop * sizeof *s->pt);
    s->code = bg_xrealloc(s->code, (size_t)s->capop);
  }
  bg_scene_pt *p = &s->pt[s->nop];
  memset(p, 0, (size_t)n * sizeof *p);
  memset(s->code + s->nop, code, (size_t)n);
  s->nop += n;
  s->item[s->nitem - 1].nop += n;
  return p;
}

void bg_scene_move(bg_scene *s, double x, double y) { *add_slots(s, BG_OP_MOVE, 1) = (bg_scene_pt){x, y}; }

void bg_scene_line(bg_scene *s, double x, double y) { *add_slots(s, BG_OP_LINE, 1) = (bg_scene_pt){x, y}; }

void bg_scene_curve(bg_scene *s, double x1, double y1, double x2, double y2, double x3,
                    double y3) {
  bg_scene_pt *p = add_slots(s, BG_OP_CURVE, 3);
  p[0] = (bg_scene_pt){x1, y1}, p[1] = (bg_scene_pt){x2, y2}, p[2] = (bg_scene_pt){x3, y3};
}

void bg_scene_close(bg_scene *s) { add_slots(s, BG_OP_CLOSE, 1); }

void bg_scene_circle(bg_scene *s, double x, double y, double r) {
  double k = 0.5523 * r; /* the control distance of a quarter circle */
  bg_scene_move(s, x + r, y);
  bg_scene_curve(s, x + r, y + k, x + k, y + r, x, y + r);
  bg_scene_curve(s, x - k, y + r, x - r, y + k, x - r, y);
  bg_scene_curve(s, x - r, y - k, x - k, y - r, x, y - r);
  bg_scene_curve(s, x + k, y - r, x + r, y - k, x + r, y);
  bg_scene_close(s);
}

bg_scene_item *bg_scene_text(bg_scene *s, const char *markup, double x, double y, double size,
                             double halign, double valign, bg_rgba color, const char *role) {
  bg_scene_item *it = bg_scene_begin(s, BG_ITEM_TEXT, "%s", role);
  it->text = bg_arena_strdup(&s->arena, markup);
  it->x = x, it->y = y, it->size = size;
  it->halign = halign, it->valign = valign;
  it->color = color;
  bg_text_measure(s->font, size, markup, &it->tw, &it->th);
  return it;
}

/* ---------------------------------------------------------------- extents */
static void grow(double b[4], double x, double y, double pad) {
  if (x - pad < b[0]) b[0] = x - pad;
  if (y - pad < b[1]) b[1] = y - pad;
  if (x + pad > b[2]) b[2] = x + pad;
  if (y + pad > b[3]) b[3] = y + pad;
}

/* Miter joins reach past the points by up to miter limit (10) x width / 2. */
void bg_scene_item_box(const bg_scene *s, const bg_scene_item *it, double b[4]) {
  b[0] = b[1] = 1e300, b[2] = b[3] = -1e300;
  if (it->kind == BG_ITEM_TEXT) {
    double x = it->x - it->halign * it->tw, y = it->y - it->valign * it->th, ink = it->size;
    b[0] = x - ink, b[1] = y - ink, b[2] = x + it->tw + ink, b[3] = y + it->th + ink;
    return;
  }
  double pad = (it->round ? 0.5 : 5) * it->width;
  for (int i = it->opadr; i < it->opadr + it->nop; i++)
    if (s->code[i] != BG_OP_CLOSE) grow(b, s->pt[i].x, s->pt[i].y, pad);
}

void bg_scene_crop(const bg_scene *src, const double clip[4], bg_scene *dst) {
  bg_scene_crop_keep(src, clip, NULL, NULL, dst);
}

void bg_scene_crop_keep(const bg_scene *src, const double clip[4], bg_scene_keep_fn keep, void *ctx,
                        bg_scene *dst) {
  bg_scene_init(dst, src->font);
  dst->width = src->width, dst->height = src->height, dst->background = src->background;
  dst->title = src->title ? bg_arena_strdup(&dst->arena, src->title) : NULL;
  for (int i = 0; i < src->nitem; i++) {
    const bg_scene_item *it = &src->item[i];
    double b[4];
    bg_scene_item_box(src, it, b);
    if (b[2] < clip[0] || b[0] > clip[2] || b[3] < clip[1] || b[1] > clip[3]) continue;
    if (dst->nitem == dst->capitem) {
      dst->capitem = dst->capitem ? 2 * dst->capitem : 64;
      dst->item = bg_xrealloc(dst->item, (size_t)dst->capitem * sizeof *dst->item);
    }
    while (dst->nop + it->nop > dst->capop) {
      dst->capop = dst->capop ? 2 * dst->capop : 256;
      dst->pt = bg_xrealloc(dst->pt, (size_t)dst->capop * sizeof *dst->pt);
      dst->code = bg_xrealloc(dst->code, (size_t)dst->capop);
    }
    bg_scene_item *d = &dst->item[dst->nitem];
    *d = *it;
    if (keep && !keep(ctx, src, i, d)) continue;
    dst->nitem++;
    d->opadr = dst->nop;
    if (it->nop) {
      memcpy(dst->pt + dst->nop, src->pt + it->opadr, (size_t)it->nop * sizeof *dst->pt);
      memcpy(dst->code + dst->nop, src->code + it->opadr, (size_t)it->nop);
    }
    dst->nop += it->nop;
    d->role = bg_arena_strdup(&dst->arena, it->role);
    if (it->text) d->text = bg_arena_strdup(&dst->arena, it->text);
  }
}

static void grow_item(const bg_scene *s, const bg_scene_item *it, double b[4]) {
  if (it->kind == BG_ITEM_TEXT) {
    double x = it->x - it->halign * it->tw, y = it->y - it->valign * it->th;
    grow(b, x, y, 0);
    grow(b, x + it->tw, y + it->th, 0);
    return;
  }
  for (int i = it->opadr; i < it->opadr + it->nop; i++)
    if (s->code[i] != BG_OP_CLOSE) grow(b, s->pt[i].x, s->pt[i].y, it->width / 2);
}

int bg_scene_bbox(const bg_scene *s, double *x0, double *y0, double *x1, double *y1) {
  double b[4] = {1e300, 1e300, -1e300, -1e300};
  for (int i = 0; i < s->nitem; i++) grow_item(s, &s->item[i], b);
  if (b[0] > b[2]) b[0] = b[1] = b[2] = b[3] = 0;
  *x0 = b[0], *y0 = b[1], *x1 = b[2], *y1 = b[3];
  return s->nitem > 0;
}

void bg_scene_fit(bg_scene *s, double margin) {
  double x0, y0, x1, y1;
  bg_scene_bbox(s, &x0, &y0, &x1, &y1);
  double dx = margin - x0, dy = margin - y0;
  for (int i = 0; i < s->nop; i++) s->pt[i].x += dx, s->pt[i].y += dy;
  for (int i = 0; i < s->nitem; i++)
    if (s->item[i].kind == BG_ITEM_TEXT) s->item[i].x += dx, s->item[i].y += dy;
  /* whole points: page sizes and PNG pixel sizes stay stable */
  s->width = ceil(x1 - x0 + 2 * margin);
  s->height = ceil(y1 - y0 + 2 * margin);
}

/* ---------------------------------------------------------------- dump */
static void dump_color(bg_strbuf *b, bg_rgba c) {
  bg_sb_printf(b, " #%02x%02x%02x", (int)(c.r * 255 + 0.5), (int)(c.g * 255 + 0.5),
               (int)(c.b * 255 + 0.5));
  if (c.a < 1) bg_sb_printf(b, "/%.2f", c.a);
}

static void dump_ops(const bg_scene *s, const bg_scene_item *it, bg_strbuf *b) {
  static const char code[] = "MLCZ";
  bg_scene_op op;
  for (int i = 0; bg_scene_next_op(s, it, &i, &op);) {
    const bg_scene_op *o = &op;
    int npt = o->code == BG_OP_CURVE ? 3 : o->code == BG_OP_CLOSE ? 0 : 1;
    bg_sb_printf(b, " %c", code[o->code]);
    for (int k = 0; k < npt; k++) bg_sb_printf(b, " %.1f,%.1f", o->x[k], o->y[k]);
  }
}

void bg_scene_dump(const bg_scene *s, bg_strbuf *out) {
  static const char *kind[] = {"stroke", "fill", "text"};
  bg_sb_printf(out, "scene %.1f x %.1f\n", s->width, s->height);
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    bg_sb_printf(out, "%s\t%s", it->role, kind[it->kind]);
    dump_color(out, it->kind == BG_ITEM_FILL ? it->fill : it->color);
    if (it->kind == BG_ITEM_TEXT) {
      bg_sb_printf(out, " %.1f,%.1f size %.1f \"%s\"", it->x, it->y, it->size, it->text);
    } else {
      bg_sb_printf(out, " w %.2f%s", it->width, it->dash[0] > 0 ? " dashed" : "");
      dump_ops(s, it, out);
    }
    bg_sb_putc(out, '\n');
  }
}

int bg_scene_count(const bg_scene *s, const char *prefix) {
  size_t n = strlen(prefix);
  int count = 0;
  for (int i = 0; i < s->nitem; i++) {
    const char *r = s->item[i].role;
    if (strncmp(r, prefix, n) == 0 && (r[n] == ' ' || r[n] == '\0')) count++;
  }
  return count;
}

/* ---------------------------------------------------------------- markup */
void bg_markup_escapen(bg_strbuf *b, const char *s, size_t n) {
  for (size_t i = 0; i < n && s[i]; i++) {
    switch (s[i]) {
    case '&': bg_sb_puts(b, "&amp;"); break;
    case '<': bg_sb_puts(b, "&lt;"); break;
    case '>': bg_sb_puts(b, "&gt;"); break;
    case '"': bg_sb_puts(b, "&quot;"); break;
    default: bg_sb_putc(b, s[i]);
    }
  }
}

void bg_markup_escape(bg_strbuf *b, const char *s) { bg_markup_escapen(b, s, strlen(s)); }
