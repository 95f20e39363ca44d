/* SPDX-License-Identifier: BSD-3-Clause */
/* cairo's SVG of a scene (version 1.1, points; text as glyph outlines): kept
 * as the reference for the SVG writer (svg_writer.c). */
#include <cairo-svg.h>

#include "scene/surface.h"
#include "scene/surface_cairo.h"
#include "scene/text_int.h"

int bg_surface_svg_cairo_write(const bg_scene *s, bg_strbuf *out) {
  bg_text_lock();
  cairo_surface_t *sf =
      cairo_svg_surface_create_for_stream(bg_surface_sink, out, s->width, s->height);
  cairo_svg_surface_restrict_to_version(sf, CAIRO_SVG_VERSION_1_1);
  cairo_svg_surface_set_document_unit(sf, CAIRO_SVG_UNIT_PT);
  cairo_t *cr = cairo_create(sf);
  bg_surface_replay(cr, s);
  int rc = bg_surface_close(cr, sf);
  bg_text_unlock();
  return rc;
}
