/* SPDX-License-Identifier: BSD-3-Clause */
/* Styles: the surface-independent look of a diagram (fonts, line widths,
 * colours, spacing), read from `key = value` files in styles/. The keys are
 * documented in docs/drawing.md; unknown keys and bad values are errors. */
#ifndef BG_STYLE_H
#define BG_STYLE_H
#include "base/diag.h"
#include "scene/scene.h"

enum { BG_STYLE_MAX_COLORS = 12 };
enum { BG_HARPOON_LEFT, BG_HARPOON_DOWN };

typedef struct bg_style {
  char name[64];
  char font[64];
  double font_size;    /* element labels, points */
  double number_scale; /* bond numbers and small text, relative to font_size */
  double line_width;   /* bonds */
  int harpoon;         /* BG_HARPOON_* */
  bg_rgba fg, background, derivative, conflict, signal, muted, flash_outline;
  int signal_dashed;       /* modulating signals dashed */
  double signal_width;     /* modulating signal lines, points */
  int derivative_double;   /* derivative strokes drawn as a double bar (print) */
  int conflict_cross;      /* conflicting strokes get a cross mark (print) */
  bg_rgba layer_color[BG_STYLE_MAX_COLORS]; /* paths and loops, cycled */
  int nlayer_color;
  int layer_patterns;      /* vary the dash pattern per path/loop (print) */
  double layer_width, layer_offset; /* polyline width; distance from the bond axis */
  double node_pad;         /* space between a label and the bonds, points */
  double node_sep, rank_sep, margin; /* layout spacing, points */
  int splines;             /* 0: straight bonds; 1: Graphviz splines */
  double png_scale;        /* PNG pixels per point */
} bg_style;

/* The built-in default (the same values as styles/default.style). */
void bg_style_default(bg_style *st);
/* Applies the `key = value` lines of text on top of st. Errors name `origin`.
 * Returns 0, or -1 after reporting errors to dg. */
int bg_style_parse(bg_style *st, const char *text, const char *origin, bg_diags *dg);
/* Loads a style by name (looked up as DIR/NAME.style; DIR is style_dir, else
 * $BGDRAW_STYLE_DIR, else "styles") or by file path (contains '/' or ends in
 * ".style"). NULL or "default" without a file gives the built-in default.
 * Returns 0, or -1 with an error in dg. */
int bg_style_load(bg_style *st, const char *name, const char *style_dir, bg_diags *dg);
/* The file bg_style_load reads for name (into buf), by the same rules. */
void bg_style_path(const char *name, const char *style_dir, char *buf, size_t n);
#endif
