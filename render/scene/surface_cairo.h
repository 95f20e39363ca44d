/* SPDX-License-Identifier: BSD-3-Clause */
/* Shared by the cairo surface files: scene replay and a byte sink. */
#ifndef BG_SURFACE_CAIRO_H
#define BG_SURFACE_CAIRO_H
#include <cairo.h>

#include "scene/scene.h"
#include "base/strbuf.h"

/* Draws every item of s on cr (background first), the caller holding the
 * text lock (scene/text_int.h). Sets font options that
 * make text metrics identical on every surface. */
void bg_surface_replay(cairo_t *cr, const bg_scene *s);
/* The same, but only the items whose box (bg_scene_item_box) meets the
 * rectangle clip (x0, y0, x1, y1, in s's points): what a clipped placement
 * shows, at the cost of what it shows rather than of the whole scene; text
 * items smaller than min_text (points of s) left out. box: each item's box
 * (box[4 i] to box[4 i + 3]) computed once for a scene placed on many
 * pages (the tiles of a large diagram), or NULL. */
void bg_surface_replay_clipped_text(cairo_t *cr, const bg_scene *s, const double clip[4],
                                    double min_text, const double *box);
/* A cairo_write_func_t appending to the bg_strbuf passed as closure. */
cairo_status_t bg_surface_sink(void *closure, const unsigned char *data, unsigned int len);
/* Ends a drawing: destroys cr, finishes and destroys sf; 0 if neither the
 * drawing nor the surface reported an error, else -1. */
int bg_surface_close(cairo_t *cr, cairo_surface_t *sf);
#endif
