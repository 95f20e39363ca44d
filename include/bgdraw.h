/* libbgdraw: the bgdraw engine as a C library (docs/library.md).
 *
 *   char *err = NULL;
 *   bg_api_model *m = bg_api_load_file("rlc.bg", &err);   // parse, check, analyse
 *   if (!m) { fputs(err, stderr); free(err); return 1; }
 *   printf("%d bonds, %d states\n", bg_api_count(m, "bonds"), bg_api_count(m, "states"));
 *   char *svg; size_t n;
 *   if (bg_api_render(m, "svg", "print", NULL, &svg, &n, &err) == 0) fwrite(svg, 1, n, out);
 *   free(svg);
 *   bg_api_free(m);
 *
 * Link with `pkg-config --cflags --libs bgdraw`. Every returned string is
 * malloc'd and freed by the caller with free(). Not thread-safe. */
#ifndef BGDRAW_H
#define BGDRAW_H
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct bg_api_model bg_api_model;

/* Reads, parses, compiles and analyses a model (causality as the model's
 * `causality` statement says, else SCAP). NULL when the model has errors:
 * *errors (if errors is not NULL) then holds the diagnostics as bgdraw
 * prints them ("file:line:col: error: ..." with source lines and carets). */
bg_api_model *bg_api_load_file(const char *path, char **errors);
/* The same for model text in memory; name appears in the diagnostics and
 * gives the model's default name. */
bg_api_model *bg_api_load_string(const char *name, const char *text, char **errors);

/* The model's name (its `model` statement, else the file name's stem). */
const char *bg_api_name(const bg_api_model *m);
/* How many of: "bonds", "elements", "states", "conflicts", "causal_paths",
 * "causal_loops", "topological_loops"; -1 for another word. */
int bg_api_count(const bg_api_model *m, const char *what);
/* The one-line model summary and the analysis summary (bgdraw --check). */
char *bg_api_summary(const bg_api_model *m);
/* The analysis document (docs/json.md), as bgdraw -o x.json writes it. */
char *bg_api_json(const bg_api_model *m);
/* The annotated diagram in format "svg", "pdf", "png" or "dot", with style
 * (NULL: "default"; a name or a style file) and show (NULL: the default
 * layers; a --show list). 0 with *data (len bytes, NUL-terminated) or -1
 * with *errors. */
int bg_api_render(bg_api_model *m, const char *format, const char *style, const char *show,
                  char **data, size_t *len, char **errors);
void bg_api_free(bg_api_model *m);

/* The library's version ("0.1.0"). */
const char *bg_api_version(void);

#ifdef __cplusplus
}
#endif
#endif
