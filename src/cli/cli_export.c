/* Export outputs (-o NAME.c with NAME.h beside it, .py, .m, .fmu (cli_fmu.c); and
 * --equations c): the equation system is built again in export form
 * (params stay variables, bg_eqsys_build_export) and handed to src/export. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/fileio.h"
#include "cli/cli_run.h"
#include "export/export.h"

/* The export build, once per run; NULL (with the reason printed) when the
 * model has no equations. */
static bg_eqsys *export_system(run *r, const char *what) {
  if (!r->eqsys) {
    fprintf(stderr, "bgdraw: error: no equations for '%s': %s\n", what,
            r->eqsys_problem ? r->eqsys_problem : "unknown reason");
    return NULL;
  }
  bg_diags dg;
  bg_diags_init(&dg, r->opts.model_path, r->src, r->srclen);
  bg_eqsys *s = bg_eqsys_build_export(r->model, &r->analysis, &dg);
  bg_diags_free(&dg);
  if (!s) fprintf(stderr, "bgdraw: error: no equations for '%s'\n", what);
  return s;
}

static void prefix_of(run *r, char *buf, size_t n) {
  if (r->opts.prefix) snprintf(buf, n, "%s", r->opts.prefix);
  else bg_export_default_prefix(r->model, buf, n);
}

/* Base name without folder and extension ("out/rlc_model.m" -> "rlc_model"). */
static void base_name(const char *path, char *buf, size_t n) {
  const char *b = strrchr(path, '/');
  b = b ? b + 1 : path;
  snprintf(buf, n, "%s", b);
  char *dot = strrchr(buf, '.');
  if (dot) *dot = 0;
}

static int write_c(run *r, bg_eqsys *s, const char *path) {
  char prefix[80], hpath[4096];
  prefix_of(r, prefix, sizeof prefix);
  size_t len = strlen(path);
  if (len + 1 > sizeof hpath) {
    fprintf(stderr, "bgdraw: error: output path too long: '%s'\n", path);
    return EXIT_USAGE;
  }
  memcpy(hpath, path, len + 1);
  hpath[len - 1] = 'h'; /* NAME.c -> NAME.h */
  const char *slash = strrchr(hpath, '/'), *hname = slash ? slash + 1 : hpath;
  bg_strbuf h = {0}, c = {0};
  bg_export_c(s, prefix, hname, &h, &c);
  int rc = cli_write_text(hpath, &h);
  if (rc == EXIT_OK) rc = cli_write_text(path, &c);
  bg_sb_free(&h), bg_sb_free(&c);
  return rc;
}

/* The text of one single-file export into sb; EXIT_OK or EXIT_MODEL. */
static int export_text(run *r, bg_eqsys *s, const char *path, const char *format, bg_strbuf *sb) {
  char name[300], prefix[80];
  prefix_of(r, prefix, sizeof prefix);
  if (!strcmp(format, "c")) { /* --equations c: header and source as one unit */
    bg_strbuf c = {0};
    bg_export_c(s, prefix, NULL, sb, &c);
    bg_sb_puts(sb, "\n");
    bg_sb_putn(sb, c.s ? c.s : "", c.len);
    bg_sb_free(&c);
  } else if (!strcmp(format, "py")) bg_export_python(s, sb);
  else if (!strcmp(format, "mo")) bg_export_modelica(s, sb);
  else if (!strcmp(format, "m")) {
    if (path) base_name(path, name, sizeof name);
    else snprintf(name, sizeof name, "%s", prefix); /* on stdout: the function is named by the prefix */
    bg_export_octave(s, name, sb);
  }
  return EXIT_OK;
}

int cli_write_export(run *r, const char *path, const char *format) {
  if (r->opts.prefix && !bg_export_prefix_ok(r->opts.prefix)) {
    fprintf(stderr, "bgdraw: error: --prefix '%s' is not a C identifier (letters, digits, '_')\n",
            r->opts.prefix);
    return EXIT_USAGE;
  }
  bg_eqsys *s = export_system(r, path ? path : "stdout");
  if (!s) return EXIT_MODEL;
  int rc;
  char prefix[80];
  prefix_of(r, prefix, sizeof prefix);
  if (path && bg_cli_is_stdout(path)) path = NULL; /* -o - : as --equations c */
  if (!strcmp(format, "fmu")) rc = cli_write_fmu(s, prefix, path ? path : BG_CLI_STDOUT);
  else if (!strcmp(format, "c") && path) rc = write_c(r, s, path);
  else {
    bg_strbuf sb = {0};
    rc = export_text(r, s, path, format, &sb);
    if (rc == EXIT_OK) rc = cli_write_text(path ? path : BG_CLI_STDOUT, &sb);
    bg_sb_free(&sb);
  }
  bg_eqsys_free(s);
  return rc;
}
