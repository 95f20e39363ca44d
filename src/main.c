/* bgdraw: the command line. The only file that touches argv, the file
 * system's output paths and exit codes; everything else is in the engine. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli_opts.h"
#include "diag.h"
#include "fileio.h"
#include "model.h"
#include "parse.h"
#include "strbuf.h"

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
} run;

static void run_free(run *r) {
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

static int print_check(run *r) {
  bg_strbuf sb = {0};
  bg_model_summary(r->model, &sb);
  printf("%s\n", bg_sb_str(&sb));
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

static int write_outputs(run *r) {
  for (int i = 0; i < r->opts.nout; i++) {
    const bg_cli_output *out = &r->opts.out[i];
    fprintf(stderr, "bgdraw: error: %s output is not implemented yet ('%s')\n", out->format,
            out->path);
    return EXIT_WRITE;
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
  char defpath[1024];
  if (r.opts.check) rc = print_check(&r);
  else {
    if (r.opts.nout == 0) default_output(&r, defpath, sizeof defpath);
    rc = write_outputs(&r);
  }
  run_free(&r);
  return rc;
}
