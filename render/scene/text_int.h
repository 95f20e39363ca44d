/* SPDX-License-Identifier: BSD-3-Clause */
/* The pango set-up that text.c measures with and the cairo surfaces draw
 * with (surface_cairo.c), and the lock they share. Internal to render/scene;
 * only text.c and the surface files include pango. */
#ifndef BG_TEXT_INT_H
#define BG_TEXT_INT_H
#include <pango/pangocairo.h>

/* text_lock: held by every use of pango and of cairo's fonts: measuring
 * (text.c), and a cairo surface from its creation to its end (surface_pdf.c,
 * surface_png.c, surface_svg.c: a PDF embeds its fonts when it finishes,
 * reading the font caches cairo shares between surfaces). */
void bg_text_lock(void);
void bg_text_unlock(void);
/* The font map (fontconfig's configuration loaded first when the program owns
 * fontconfig, bg_fonts_own); call with the lock held. */
PangoFontMap *bg_text_font_map(void);
/* Font options free of the surface's defaults (hinting differs per backend). */
cairo_font_options_t *bg_text_font_options(void);
/* No hint metrics, no glyph position rounding, 72 units per inch. */
void bg_text_setup_context(PangoContext *ctx);
/* A layout of markup in font at size points, and its logical size in points. */
PangoLayout *bg_text_layout(PangoContext *ctx, const char *font, double size, const char *markup);
void bg_text_layout_size(PangoLayout *lay, double *w, double *h);
#endif
