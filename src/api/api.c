/* libbgdraw: the public C API (include/bgdraw.h) over the engine and the
 * renderers. A model handle owns the source text, the compiled model and
 * its analysis; diagrams are drawn on request. */
#define _GNU_SOURCE /* dladdr */
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <bgdraw.h> /* the public header, include/ */
#include "analysis/analysis.h"
#include "base/diag.h"
#include "base/fileio.h"
#include "base/strbuf.h"
#include "causality/causality.h"
#include "diagram/render.h"
#include "json/json.h"
#include "lang/lang.h"
#include "model/model.h"

#ifndef BG_VERSION
#define BG_VERSION "0.0.0"
#endif
#ifndef BG_LIB_TO_STYLES
#define BG_LIB_TO_STYLES "../share/bgdraw/styles"
#endif

struct bg_api_model {
  char *src;
  char *name; /* as given, for diagnostics */
  bg_model *model;
  bg_analysis analysis;
};

/* The diagnostics as text, for *errors. */
static void give_errors(const bg_diags *dg, char **errors) {
  if (!errors) return;
  char *buf = NULL;
  size_t n = 0;
  FILE *f = open_memstream(&buf, &n);
  if (f) {
    bg_diags_print(dg, f);
    fclose(f);
  }
  *errors = buf;
}

static bg_api_model *load(const char *name, char *src, size_t len, char **errors) {
  bg_api_model *h = calloc(1, sizeof *h);
  h->src = src;
  h->name = strdup(name);
  bg_diags dg;
  bg_diags_init(&dg, h->name, src, len);
  bg_ast *ast = bg_parse_string(h->name, src, len, &dg);
  if (ast && !dg.nerrors) h->model = bg_model_compile(ast, NULL, 0, &dg);
  bg_ast_free(ast);
  if (!h->model || dg.nerrors) {
    give_errors(&dg, errors);
    bg_diags_free(&dg);
    if (h->model) bg_model_free(h->model);
    free(h->src), free(h->name), free(h);
    return NULL;
  }
  bg_analysis_init(&h->analysis, h->model);
  bg_causality_assign(h->model, h->model->method, &h->analysis, &dg);
  bg_analysis_limits lim = {0, 0};
  bg_analysis_run(h->model, &h->analysis, &lim);
  bg_diags_free(&dg);
  if (errors) *errors = NULL;
  return h;
}

bg_api_model *bg_api_load_file(const char *path, char **errors) {
  size_t len = 0;
  char *src = bg_read_file(path, &len);
  if (!src) {
    if (errors) {
      size_t n = strlen(path) + 200;
      *errors = malloc(n);
      snprintf(*errors, n, "%s: error: cannot read the model: %s\n", path, bg_file_strerror(errno));
    }
    return NULL;
  }
  return load(path, src, len, errors);
}

bg_api_model *bg_api_load_string(const char *name, const char *text, char **errors) {
  return load(name ? name : "<string>", strdup(text), strlen(text), errors);
}

const char *bg_api_name(const bg_api_model *m) { return m->model->name; }

int bg_api_count(const bg_api_model *m, const char *what) {
  const bg_analysis *a = &m->analysis;
  static const char *const words[] = {"bonds", "elements", "states", "conflicts",
                                      "causal_paths", "causal_loops", "topological_loops"};
  const int counts[] = {m->model->nbond, m->model->nelem, a->nstates, a->nconflict,
                        a->npath, a->ncloop, a->ntloop};
  for (int i = 0; i < 7; i++)
    if (!strcmp(what, words[i])) return counts[i];
  return -1;
}

char *bg_api_summary(const bg_api_model *m) {
  bg_strbuf sb = {0};
  bg_model_summary(m->model, &sb);
  bg_sb_putc(&sb, '\n');
  bg_analysis_summary(m->model, &m->analysis, &sb);
  return sb.s;
}

char *bg_api_json(const bg_api_model *m) {
  bg_strbuf sb = {0};
  bg_json_write_analysis(m->model, &m->analysis, NULL, &sb);
  return sb.s;
}

/* Named styles: $BGDRAW_STYLE_DIR (style.c), else share/bgdraw/styles
 * relative to this library's file (installed: LIBDIR/../share/bgdraw/styles). */
static const char *library_style_dir(void) {
  static char dir[4200];
  const char *env = getenv("BGDRAW_STYLE_DIR");
  if (env && *env) return NULL;
  Dl_info info;
  if (!dladdr((void *)bg_api_version, &info) || !info.dli_fname) return NULL;
  char lib[4096];
  snprintf(lib, sizeof lib, "%s", info.dli_fname);
  char *slash = strrchr(lib, '/');
  if (!slash) return NULL;
  *slash = '\0';
  const char *rel[] = {BG_LIB_TO_STYLES, "share/bgdraw/styles"};
  for (int i = 0; i < 2; i++) {
    struct stat st;
    snprintf(dir, sizeof dir, "%s/%s", lib, rel[i]);
    if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode)) return dir;
  }
  return NULL;
}

int bg_api_render(bg_api_model *m, const char *format, const char *style, const char *show,
                  char **data, size_t *len, char **errors) {
  bg_render_opts o = {.style = style, .style_dir = library_style_dir()};
  bg_diags dg;
  bg_diags_init(&dg, "bgdraw", NULL, 0);
  *data = NULL;
  if (show && bg_show_parse(show, &o.show) != 0)
    bg_diag_error(&dg, (bg_srcloc){0}, "unknown layer in show list '%s'", show);
  bg_diagram *d = dg.nerrors ? NULL : bg_diagram_build(m->model, &m->analysis, &o, &dg);
  bg_strbuf sb = {0};
  int rc = d ? bg_diagram_render(d, format, &sb, &dg) : -1;
  if (d) bg_diagram_free(d);
  if (rc == BG_RENDER_OK) {
    *len = sb.len;
    *data = sb.s ? sb.s : strdup("");
    if (errors) *errors = NULL;
  } else {
    bg_sb_free(&sb);
    give_errors(&dg, errors);
  }
  bg_diags_free(&dg);
  return rc == BG_RENDER_OK ? 0 : -1;
}

void bg_api_free(bg_api_model *m) {
  if (!m) return;
  bg_analysis_free(&m->analysis);
  bg_model_free(m->model);
  free(m->src);
  free(m->name);
  free(m);
}

const char *bg_api_version(void) { return BG_VERSION; }
