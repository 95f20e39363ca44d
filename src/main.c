/* bgdraw: the command line. The only file that touches argv, the file
 * system's output paths and exit codes; everything else is in the engine. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "analysis.h"
#include "causality.h"
#include "cli_opts.h"
#include "diag.h"
#include "fileio.h"
#include "json.h"
#include "model.h"
#include "parse.h"
#include "paths.h"
#include "strbuf.h"
#include "summary.h"

enum { EXIT_OK = 0, EXIT_MODEL = 1, EXIT_USAGE = 2, EXIT_SIM = 3, EXIT_WRITE = 4 };

#ifndef BG_VERSION
#define BG_VERSION "0.0.0"
#endif

/* Everything one run holds; freed by run_free. */
typedef struct run {
  bg_cli_opts opts;
  char *src;
  size_t srclen;
  bg_diags dg;
  bg_ast *ast;
  bg_model *model;
  bg_analysis analysis;
  int analysed;
} run;

static void run_free(run *r) {
  if (r->analysed) bg_analysis_free(&r->analysis);
  if (r->model) bg_model_free(r->model);
  if (r->ast) bg_ast_free(r->ast);
  bg_diags_free(&r->dg);
  free(r->src);
  bg_cli_free(&r->opts);
}

/* Reads, parses and compiles the model; diagnostics stay in r->dg. */
static int load_model(run *r) {
  const bg_cli_opts *o = &r->opts;
  r->src = bg_read_file(o->model_path, &r->srclen);
  bg_diags_init(&r->dg, o->model_path, r->src, r->srclen);
  if (!r->src) {
    bg_srcloc none = {0, 0};
    bg_diag_error(&r->dg, none, "cannot read the model: %s", strerror(errno));
    return -1;
  }
  r->ast = bg_parse_string(o->model_path, r->src, r->srclen, &r->dg);
  if (!r->ast || r->dg.nerrors) return -1;
  r->model = bg_model_compile(r->ast, o->sets, o->nsets, &r->dg);
  bg_ast_free(r->ast);
  r->ast = NULL;
  return r->model && !r->dg.nerrors ? 0 : -1;
}

/* Causality and causal analysis with the method the user asked for, else
 * the model's own, else SCAP. */
static void analyse(run *r) {
  int method = r->model->method;
  if (r->opts.causality) method = bg_method_parse(r->opts.causality);
  if (r->opts.verbose) fprintf(stderr, "bgdraw: causality (%s)\n", bg_method_name(method));
  bg_analysis_init(&r->analysis, r->model);
  r->analysed = 1;
  bg_causality_assign(r->model, method, &r->analysis, &r->dg);
  if (r->opts.verbose) fprintf(stderr, "bgdraw: causal paths, loops, form and index\n");
  bg_analysis_run(r->model, &r->analysis, NULL);
}

static int print_check(run *r) {
  bg_strbuf sb = {0};
  bg_model_summary(r->model, &sb);
  bg_sb_putc(&sb, '\n');
  bg_analysis_summary(r->model, &r->analysis, &sb);
  fputs(bg_sb_str(&sb), stdout);
  bg_sb_free(&sb);
  return EXIT_OK;
}

/* The default output when no -o is given: out/<model>.svg. */
static void default_output(run *r, char *buf, size_t n) {
  mkdir("out", 0777); /* may exist already */
  snprintf(buf, n, "out/%s.svg", r->model->name);
  r->opts.out[0].path = buf;
  r->opts.out[0].format = "svg";
  r->opts.nout = 1;
}

static int write_text(const char *path, const bg_strbuf *sb) {
  if (bg_write_file_atomic(path, bg_sb_str(sb), sb->len) == 0) return EXIT_OK;
  fprintf(stderr, "bgdraw: error: cannot write '%s': %s\n", path, strerror(errno));
  return EXIT_WRITE;
}

static int write_json(run *r, const char *path) {
  bg_strbuf sb = {0};
  bg_json_write_analysis(r->model, &r->analysis, &sb);
  int rc = write_text(path, &sb);
  bg_sb_free(&sb);
  return rc;
}

static int write_one(run *r, const bg_cli_output *out) {
  if (r->opts.verbose) fprintf(stderr, "bgdraw: writing %s\n", out->path);
  if (!strcmp(out->format, "json")) return write_json(r, out->path);
  fprintf(stderr, "bgdraw: error: %s output is not implemented yet ('%s')\n", out->format,
          out->path);
  return EXIT_WRITE;
}

static int write_outputs(run *r) {
  for (int i = 0; i < r->opts.nout; i++) {
    int rc = write_one(r, &r->opts.out[i]);
    if (rc) return rc;
  }
  return EXIT_OK;
}

int main(int argc, char **argv) {
  run r;
  memset(&r, 0, sizeof r);
  if (bg_cli_parse(argc, argv, &r.opts) != 0) {
    bg_cli_free(&r.opts);
    return EXIT_USAGE;
  }
  if (r.opts.help || r.opts.version) {
    if (r.opts.help) bg_cli_print_help(stdout);
    else printf("bgdraw %s\n", BG_VERSION);
    bg_cli_free(&r.opts);
    return EXIT_OK;
  }
  int rc = load_model(&r);
  if (!r.opts.quiet || rc) bg_diags_print(&r.dg, stderr);
  if (rc) {
    run_free(&r);
    return EXIT_MODEL;
  }
  analyse(&r);
  char defpath[1024];
  if (r.opts.check) rc = print_check(&r);
  else {
    if (r.opts.nout == 0) default_output(&r, defpath, sizeof defpath);
    rc = write_outputs(&r);
  }
  run_free(&r);
  return rc;
}
