/* The renderers (Graphviz, cairo, pango: two thirds of the shared libraries
 * bgdraw maps) live in a module, bgdraw_render.so, that the command line
 * loads only when a run draws: a diagram, a plot, the report, --version, or a
 * --show or --highlight to check. cli_render.c gives the CLI the functions
 * below under their usual names and loads the module on the first call;
 * cli_render_module.c is the module's one table. The module's calls into
 * the engine bind to the executable's (CMakeLists.txt). Found at
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

/* Raised whenever a signature below changes: a module from another build is
 * refused rather than called wrongly. */
#define BG_RENDER_API_VERSION 3

typedef struct bg_render_api {
  int version;
  bg_diagram *(*diagram_build)(const bg_model *m, const bg_analysis *a, const bg_render_opts *o,
                               bg_diags *dg);
  void (*diagram_free)(bg_diagram *d);
  int (*diagram_write)(bg_diagram *d, const char *path, const char *format, bg_diags *dg);
  int (*diagram_render)(bg_diagram *d, const char *format, bg_strbuf *out, bg_diags *dg);
  int (*show_parse)(const char *list, unsigned *out);
  int (*highlight_parse)(const char *item, int *kind, int *index);
  int (*plot_write)(const bg_model *m, const bg_simresult *r, const char *style,
                    const char *style_dir, const char *path, bg_diags *dg);
  int (*plot_linear_write)(const bg_model *m, const bg_linear *l, int kind, const char *style,
                           const char *style_dir, const char *path, bg_diags *dg);
  int (*report_write)(const bg_report_input *in, const char *path, bg_diags *dg);
  void (*style_path)(const char *name, const char *style_dir, char *buf, size_t n);
  void (*versions)(bg_strbuf *out);
  void (*fonts_own)(void); /* bgdraw is fontconfig's only user (scene/surface.h) */
} bg_render_api;

/* The module's table (the one symbol the executable looks up). */
extern const bg_render_api bg_render_module;
#endif
