/* SPDX-License-Identifier: BSD-3-Clause */
/* Annotated bond graph diagrams: the public API for the CLI.
 *
 *   bg_diagram *d = bg_diagram_build(m, a, &opts, dg);   // layout once
 *   bg_diagram_write(d, "x.svg", NULL, dg);               // any number of outputs
 *   bg_diagram_write(d, "x.pdf", NULL, dg);
 *   bg_diagram *h = bg_diagram_redraw(d, 0, 'p', 2, dg);  // path 2 highlighted, same layout
 *   bg_diagram_free(h);
 *   bg_diagram_free(d);
 *
 * Formats: svg, pdf, png (cairo) and dot (the annotated graph in Graphviz DOT
 * with the computed positions). Conventions: docs/drawing.md. */
#ifndef BG_RENDER_H
#define BG_RENDER_H
#include "causality/causality.h"
#include "base/diag.h"
#include "base/log.h"
#include "model/model.h"
#include "base/strbuf.h"

/* Layers of --show. */
enum {
  BG_SHOW_STROKES = 1u << 0,
  BG_SHOW_NUMBERS = 1u << 1,
  BG_SHOW_PATHS = 1u << 2,
  BG_SHOW_LOOPS = 1u << 3,
  BG_SHOW_CONFLICTS = 1u << 4,
  BG_SHOW_SIGNALS = 1u << 5,
  BG_SHOW_LABELS = 1u << 6,
  BG_SHOW_LEGEND = 1u << 7,
  BG_SHOW_ALL = (1u << 8) - 1, /* the eight layers above */
  BG_SHOW_VARIABLES = 1u << 8, /* e_k, f_k beside each bond instead of its number; not in "all" */
  BG_SHOW_DEFAULT = BG_SHOW_STROKES | BG_SHOW_NUMBERS | BG_SHOW_CONFLICTS | BG_SHOW_SIGNALS |
                    BG_SHOW_LABELS
};

/* Return values of bg_diagram_write and bg_diagram_render. */
enum { BG_RENDER_OK = 0, BG_RENDER_ERROR = -1, BG_RENDER_EWRITE = -2 };

typedef struct bg_render_opts {
  unsigned show;         /* BG_SHOW_* bits; 0 means BG_SHOW_DEFAULT */
  int highlight_kind;    /* 0 none, 'p' causal path, 'l' topological loop, 'c' conflict */
  int highlight_index;   /* 1-based, as numbered in the JSON and the report */
  const char *style;     /* nullable: style name or file; NULL = "default" */
  const char *style_dir; /* nullable: where named styles live (the CLI passes BG_STYLE_DIR);
                            NULL: $BGDRAW_STYLE_DIR, else "styles" */
  const char *layout;    /* nullable: engine; NULL = the model's layout statement, else dot */
  const bg_log *log;     /* progress and engine choices (-v); nullable: silent */
  int layer_room;        /* the grid layout leaves room beside the bonds for path and loop
                            lines: 0 when show has paths or loops, 1 always, -1 never
                            (a redraw keeps its source's layout, room and all) */
  const char *const *collapse; /* nullable: instances drawn as one word-bond-graph box
                                  (qualified names, or "all"); --collapse */
  int ncollapse;
} bg_render_opts;

/* Parses a --show list ("strokes,numbers", "all", "none"). Returns 0, or -1
 * for an unknown word (*out is then unchanged). */
int bg_show_parse(const char *list, unsigned *out);
/* Parses a --highlight item ("path:2", "loop:1", "conflict:1"). Returns 0, or -1. */
int bg_highlight_parse(const char *item, int *kind, int *index);

typedef struct bg_diagram bg_diagram;

/* Lays out and draws the diagram once. m and a are borrowed and must outlive
 * the diagram; a may be NULL (no causality: bonds without strokes). Returns
 * NULL after reporting errors to dg (unknown style or engine, highlight index
 * out of range, layout failure). The caller frees the result. */
bg_diagram *bg_diagram_build(const bg_model *m, const bg_analysis *a, const bg_render_opts *o,
                             bg_diags *dg);
/* Draws d's layout again with other layers (show; 0: the default layers) and
 * another highlight (kind 0: none; else as in bg_render_opts), without a new
 * layout: every node and bond is where it is in d, on d's page, in d's style.
 * The page grows only where the new drawing reaches beyond it (it then moves
 * right or down by that much). The labels and signals bits of show are d's:
 * they decide the nodes and their sizes. Returns NULL after reporting a
 * highlight index out of range to dg. The result is independent of d (either
 * may be freed first); m and a must outlive it. */
bg_diagram *bg_diagram_redraw(const bg_diagram *d, unsigned show, int highlight_kind,
                              int highlight_index, bg_diags *dg);
/* Writes the diagram to path atomically. format: "svg", "pdf", "png", "dot"
 * or NULL for path's extension. Returns BG_RENDER_OK, BG_RENDER_ERROR (unknown
 * format; reported to dg) or BG_RENDER_EWRITE (the file could not be written;
 * reported to dg; the CLI exits 4). */
int bg_diagram_write(bg_diagram *d, const char *path, const char *format, bg_diags *dg);
/* The bytes of one format, appended to out (tests, the report). Same returns. */
int bg_diagram_render(bg_diagram *d, const char *format, bg_strbuf *out, bg_diags *dg);
/* A text listing of the scene, one drawn item a line with its role tag
 * ("stroke bond=3", "flash conflict=1", "path 1", "signal w->T"). */
void bg_diagram_dump(const bg_diagram *d, bg_strbuf *out);
/* The diagram's scene (render/scene/scene.h), for checks that read its
 * geometry (tests/unit/figure_check.h). Valid while d lives. */
struct bg_scene;
const struct bg_scene *bg_diagram_scene(const bg_diagram *d);
/* Items whose role is prefix or starts with prefix + ' ' ("path" counts "path 1"). */
int bg_diagram_count(const bg_diagram *d, const char *prefix);
/* The layout engine used (after automatic choices, e.g. "sfdp"). */
const char *bg_diagram_engine(const bg_diagram *d);
/* Page size in points. */
void bg_diagram_size(const bg_diagram *d, double *w, double *h);
void bg_diagram_free(bg_diagram *d);

/* "Graphviz X, cairo Y, pango Z": the rendering libraries bgdraw was built with. */
void bg_render_versions(bg_strbuf *out);
#endif
