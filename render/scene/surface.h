/* SPDX-License-Identifier: BSD-3-Clause */
/* Surfaces: replay a bg_scene with cairo into SVG, PDF or PNG bytes.
 * surface_cairo.c holds the replay shared by the three format files, text.c
 * the pango text set-up and measurement; only these five files include cairo
 * or pango. */
#ifndef BG_SURFACE_H
#define BG_SURFACE_H
#include "scene/scene.h"
#include "base/strbuf.h"

/* Each appends the whole file to out and returns 0, or -1 when cairo failed
 * (nothing useful in out). */
/* SVG is written from the scene by surface_svg.c: <text> in the scene's font
 * with a fallback list (searchable, selectable), a CSS class per role ("bond
 * b3", "stroke b3", "path p2", "loop l1", "flash conflict c1"), a viewBox and
 * no fixed size. tip, when not NULL, gives the <title> tooltip of an item from
 * its role (appending to buf; nothing appended: no tooltip). */
typedef void (*bg_svg_tip_fn)(void *ctx, const char *role, bg_strbuf *buf);
int bg_surface_svg_write(const bg_scene *s, bg_strbuf *out);
int bg_surface_svg_write_tips(const bg_scene *s, bg_svg_tip_fn tip, void *ctx, bg_strbuf *out);
/* cairo's SVG of the same scene (text as glyph outlines): the reference the
 * tests compare the SVG writer's rasterisation with. */
int bg_surface_svg_cairo_write(const bg_scene *s, bg_strbuf *out);
/* For a program that is fontconfig's only user (the bgdraw executable),
 * called before any text is measured: the renderers then load fontconfig's
 * configuration themselves, as FcInit would but without parsing every
 * template of conf.avail (text.c). Others leave it to FcInit. A setting of
 * the process (fontconfig's current configuration is), made once before any
 * run starts. */
void bg_fonts_own(void);
/* The baseline of markup below the top of its box (pango), points; safe to
 * call from several threads, as bg_text_measure. */
double bg_text_baseline(const char *font, double size, const char *markup);
int bg_surface_pdf_write(const bg_scene *s, bg_strbuf *out);
/* scale: pixels per point (2 gives 144 dpi). */
int bg_surface_png_write(const bg_scene *s, double scale, bg_strbuf *out);

/* ---------------------------------------------------------------- multi-page PDF
 * (the report). A page is its own scene (page size = scene size) with other
 * scenes placed on it: the rectangle (sx, sy, sw, sh) of `scene`, in that
 * scene's points, drawn scaled by `scale` with its corner at page point
 * (x, y) and clipped to the rectangle. Placed scenes are drawn after the
 * page's own items; everything is borrowed. */
/* A placed scene replays only the items whose box meets its rectangle
 * grown by this much on each side (points of the placed scene): a viewer's
 * anti-aliased clip edge still shows some of an item that lies just outside
 * it, within the edge pixel. */
#define BG_PLACE_CULL_PAD 24.0
/* Text a placed scene would show smaller than this many points on the page
 * is left out: only the tiles of a diagram too large for the report's 48
 * pages get there (0.5 pt at 100 000 masses), where a million glyph runs
 * were a third of the report's time and nobody could read them. */
#define BG_PLACE_MIN_TEXT 1.0
/* raster > 0 draws the rectangle as an image of that many pixels per page
 * point instead of as vectors, leaving out text smaller than
 * BG_RASTER_MIN_TEXT pixels: the map of a huge diagram (report), whose
 * every item would otherwise be recorded on one PDF page. */
#define BG_RASTER_MIN_TEXT 2.0
typedef struct bg_surface_place {
  const bg_scene *scene;
  double sx, sy, sw, sh;
  double x, y, scale;
  double raster;
} bg_surface_place;

typedef struct bg_surface_page {
  const bg_scene *scene;
  const bg_surface_place *place;
  int nplace;
} bg_surface_page;

/* A PDF outline entry (bookmark): level 0 at the top, level k under the
 * last entry of level k - 1; page 0-based, y from the page's top. */
typedef struct bg_surface_outline {
  const char *title;
  int level;
  int page;
  double y;
} bg_surface_outline;

/* Writes every page, the outlines and the metadata (title nullable; fixed
 * creation date as in bg_surface_pdf_write) to out. 0, or -1 when cairo failed. */
int bg_surface_pdf_pages(const bg_surface_page *pages, int npage, const bg_surface_outline *ol,
                         int nol, const char *title, bg_strbuf *out);
/* The cairo and pango versions bgdraw was built with ("1.16.0"). */
const char *bg_surface_cairo_version(void);
const char *bg_surface_pango_version(void);
#endif
