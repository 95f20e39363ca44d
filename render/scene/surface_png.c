/* SPDX-License-Identifier: BSD-3-Clause */
/* PNG output: an ARGB image surface scaled by `scale` pixels per point. */
#include <cairo.h>
#include <math.h>

#include "scene/surface.h"
#include "scene/surface_cairo.h"
#include "scene/text_int.h"

int bg_surface_png_write(const bg_scene *s, double scale, bg_strbuf *out) {
  if (!(scale > 0)) scale = 1;
  /* cairo images are limited to 32767 pixels a side: shrink huge diagrams */
  double limit = 32000;
  if (s->width * scale > limit) scale = limit / s->width;
  if (s->height * scale > limit) scale = limit / s->height;
  double pixels = 40e6; /* and to about 160 MB of image memory */
  if (s->width * s->height * scale * scale > pixels) scale = sqrt(pixels / (s->width * s->height));
  int w = (int)ceil(s->width * scale), h = (int)ceil(s->height * scale);
  bg_text_lock();
  cairo_surface_t *sf = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
  cairo_t *cr = cairo_create(sf);
  cairo_scale(cr, scale, scale);
  bg_surface_replay(cr, s);
  cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_write_to_png_stream(sf, bg_surface_sink, out);
  cairo_surface_destroy(sf);
  bg_text_unlock();
  return st == CAIRO_STATUS_SUCCESS ? 0 : -1;
}
