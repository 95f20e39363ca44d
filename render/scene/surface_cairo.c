/* SPDX-License-Identifier: BSD-3-Clause */
/* Scene replay with cairo, text drawn with pango (through pangocairo) with
 * the settings text.c measures with, so SVG, PDF and PNG agree with the
 * layout's idea of every label's size. */
#include "scene/surface_cairo.h"

#include "scene/text_int.h"

cairo_status_t bg_surface_sink(void *closure, const unsigned char *data, unsigned int len) {
  bg_sb_putn((bg_strbuf *)closure, (const char *)data, len);
  return CAIRO_STATUS_SUCCESS;
}

int bg_surface_close(cairo_t *cr, cairo_surface_t *sf) {
  cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(sf);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(sf);
  cairo_surface_destroy(sf);
  return st == CAIRO_STATUS_SUCCESS ? 0 : -1;
}

static void set_color(cairo_t *cr, bg_rgba c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }

static void replay_path(cairo_t *cr, const bg_scene *s, const bg_scene_item *it) {
  cairo_new_path(cr);
  bg_scene_op o_;
  for (int i = 0; bg_scene_next_op(s, it, &i, &o_);) {
    const bg_scene_op *o = &o_;
    switch (o->code) {
    case BG_OP_MOVE: cairo_move_to(cr, o->x[0], o->y[0]); break;
    case BG_OP_LINE: cairo_line_to(cr, o->x[0], o->y[0]); break;
    case BG_OP_CURVE:
      cairo_curve_to(cr, o->x[0], o->y[0], o->x[1], o->y[1], o->x[2], o->y[2]);
      break;
    default: cairo_close_path(cr); break;
    }
  }
}

static void set_line(cairo_t *cr, const bg_scene_item *it) {
  cairo_set_line_width(cr, it->width);
  cairo_set_line_cap(cr, it->round ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
  cairo_set_line_join(cr, it->round ? CAIRO_LINE_JOIN_ROUND : CAIRO_LINE_JOIN_MITER);
  if (it->dash[0] > 0) cairo_set_dash(cr, it->dash, 2, 0);
  else cairo_set_dash(cr, NULL, 0, 0);
}

static void replay_shape(cairo_t *cr, const bg_scene *s, const bg_scene_item *it) {
  replay_path(cr, s, it);
  set_line(cr, it);
  if (it->kind == BG_ITEM_FILL) {
    set_color(cr, it->fill);
    if (it->width > 0) {
      cairo_fill_preserve(cr);
      set_color(cr, it->color);
      cairo_stroke(cr);
    } else {
      cairo_fill(cr);
    }
  } else {
    set_color(cr, it->color);
    cairo_stroke(cr);
  }
}

static void replay_text(cairo_t *cr, PangoContext *ctx, const bg_scene *s,
                        const bg_scene_item *it) {
  PangoLayout *lay = bg_text_layout(ctx, s->font, it->size, it->text);
  double w, h;
  bg_text_layout_size(lay, &w, &h);
  set_color(cr, it->color);
  cairo_move_to(cr, it->x - it->halign * w, it->y - it->valign * h);
  pango_cairo_show_layout(cr, lay);
  g_object_unref(lay);
}

/* The caller holds the text lock (text_int.h). */
static void replay_items(cairo_t *cr, const bg_scene *s, const double *clip, double min_text,
                         const double *boxes) {
  cairo_font_options_t *fo = bg_text_font_options();
  cairo_set_font_options(cr, fo);
  cairo_font_options_destroy(fo);
  bg_text_font_map(); /* pango_cairo_create_context takes the default map */
  PangoContext *ctx = pango_cairo_create_context(cr);
  bg_text_setup_context(ctx);
  set_color(cr, s->background);
  cairo_paint(cr);
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    if (clip) {
      double own[4];
      const double *b = boxes ? boxes + 4 * (size_t)i : own;
      if (!boxes) bg_scene_item_box(s, it, own);
      if (b[2] < clip[0] || b[0] > clip[2] || b[3] < clip[1] || b[1] > clip[3]) continue;
    }
    if (it->kind == BG_ITEM_TEXT) {
      if (it->size >= min_text) replay_text(cr, ctx, s, it);
    } else {
      replay_shape(cr, s, it);
    }
  }
  g_object_unref(ctx);
}

const char *bg_surface_cairo_version(void) { return CAIRO_VERSION_STRING; }
const char *bg_surface_pango_version(void) { return PANGO_VERSION_STRING; }

void bg_surface_replay(cairo_t *cr, const bg_scene *s) { replay_items(cr, s, NULL, 0, NULL); }

void bg_surface_replay_clipped_text(cairo_t *cr, const bg_scene *s, const double clip[4],
                                    double min_text, const double *box) {
  replay_items(cr, s, clip, min_text, box);
}
