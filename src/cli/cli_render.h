/* SPDX-License-Identifier: BSD-3-Clause */
/* The renderers (Graphviz, cairo, pango: two thirds of the shared libraries
 * bgdraw maps) live in a module, bgdraw_render.so, that the command line
 * loads only when a run draws: a diagram, a plot, the report, --version, or a
 * --show or --highlight to check. BG_RENDER_CALLS below is the module's
 * interface, written once: it makes the table's type here, the table in
 * cli_render_module.c and, in cli_render.c, the functions the CLI calls under
 * their usual names, which load the module on the first call. The module's
 * calls into the engine bind to the executable's (CMakeLists.txt). Found at
 * $BGDRAW_RENDER_MODULE, else at BG_EXE_TO_MODULE from the executable's
 * folder (installed: PREFIX/lib/bgdraw), else beside the executable (the
 * build tree). */
#ifndef BG_CLI_RENDER_H
#define BG_CLI_RENDER_H
#include <stddef.h>

#include "diagram/render.h"
#include "plot/plot.h"
#include "plot/plot_linear.h"
#include "report/report.h"
#include "html/html.h"

/* Raised whenever the calls below change: a module from another build is
 * refused rather than called wrongly. */
#define BG_RENDER_API_VERSION 6

/* R(return type, name, (parameters), (arguments)) for a call that returns a
 * value, V(name, (parameters), (arguments)) for one that does not; the
 * function is bg_<name>. */
#define BG_RENDER_CALLS(R, V)                                                                     \
  R(bg_diagram *, diagram_build,                                                                  \
    (const bg_model *m, const bg_analysis *a, const bg_render_opts *o, bg_diags *dg),             \
    (m, a, o, dg))                                                                                \
  V(diagram_free, (bg_diagram *d), (d))                                                           \
  R(int, diagram_render, (bg_diagram *d, const char *format, bg_strbuf *out, bg_diags *dg),       \
    (d, format, out, dg))                                                                         \
  R(int, show_parse, (const char *list, unsigned *out), (list, out))                              \
  R(int, highlight_parse, (const char *item, int *kind, int *index), (item, kind, index))         \
  R(int, plot_render,                                                                             \
    (const bg_model *m, const bg_simresult *r, const char *style, const char *style_dir,          \
     const char *fmt, const char *path, bg_strbuf *out, bg_diags *dg),                            \
    (m, r, style, style_dir, fmt, path, out, dg))                                                 \
  R(int, plot_linear_render,                                                                      \
    (const bg_model *m, const bg_linear *l, int kind, const char *style, const char *style_dir,   \
     const char *fmt, const char *path, bg_strbuf *out, bg_diags *dg),                            \
    (m, l, kind, style, style_dir, fmt, path, out, dg))                                           \
  R(int, study_plot_render,                                                                       \
    (const bg_study *st, int kind, const bg_study_bode *bode, const char *style,                 \
     const char *style_dir, const char *fmt, const char *path, bg_strbuf *out, bg_diags *dg),     \
    (st, kind, bode, style, style_dir, fmt, path, out, dg))                                       \
  R(int, report_render, (const bg_run *r, const bg_report_opts *o, bg_strbuf *out, bg_diags *dg), \
    (r, o, out, dg))                                                                              \
  R(int, html_report_render,                                                                      \
    (const bg_run *r, const bg_report_opts *o, bg_strbuf *out, bg_diags *dg), (r, o, out, dg))    \
  V(style_path, (const char *name, const char *style_dir, char *buf, size_t n),                   \
    (name, style_dir, buf, n))                                                                    \
  V(render_versions, (bg_strbuf *out), (out))                                                     \
  V(fonts_own, (void), ()) /* bgdraw is fontconfig's only user (scene/surface.h) */

#define BG_RENDER_FIELD_R(ret, name, params, args) ret(*name) params;
#define BG_RENDER_FIELD_V(name, params, args) void(*name) params;
typedef struct bg_render_api {
  int version;
  BG_RENDER_CALLS(BG_RENDER_FIELD_R, BG_RENDER_FIELD_V)
} bg_render_api;

/* The module's table (the one symbol the executable looks up). */
extern const bg_render_api bg_render_module;
#endif
