/* Surfaces: replay a bg_scene with cairo into SVG, PDF or PNG bytes.
 * surface_cairo.c holds the replay and the pango text code shared by the
 * three format files; only these four files include cairo or pango. */
#ifndef BG_SURFACE_H
#define BG_SURFACE_H
#include "scene.h"
#include "strbuf.h"

/* Each appends the whole file to out and returns 0, or -1 when cairo failed
 * (nothing useful in out). */
int bg_surface_svg_write(const bg_scene *s, bg_strbuf *out);
int bg_surface_pdf_write(const bg_scene *s, bg_strbuf *out);
/* scale: pixels per point (2 gives 144 dpi). */
int bg_surface_png_write(const bg_scene *s, double scale, bg_strbuf *out);
#endif
