/* SPDX-License-Identifier: BSD-3-Clause */
/* Where the outputs go: every output's bytes come from src/output's table;
 * here they are written atomically to their files, or in place to standard
 * output, and their statuses become exit codes (docs/cli.md). */
#define _DEFAULT_SOURCE /* realpath */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/fileio.h"
#include "base/strbuf.h"
#include "cli/cli_render.h"
#include "cli/cli_run.h"
#include "export/export.h"

/* Whether the run draws, and so reads a style file: a diagram output, a
 * plot or the report. A run that does not never loads the render module
 * (cli_render.h). The default diagram is an -o by now. */
static int run_draws(const run *r) {
  const bg_cli_opts *o = &r->opts;
  if (o->plot || o->report || o->bode || o->nyquist || o->step) return 1;
  for (int i = 0; i < o->nout; i++) {
    const bg_output_kind *k = bg_output_find(o->out[i].format);
    if (k && (k->flags & BG_OUTK_DRAWS)) return 1;
  }
  return 0;
}

/* The real path of path's folder, and its name (path need not exist). */
static char *folder_identity(const char *path) {
  const char *slash = strrchr(path, '/');
  char dir[4096];
  snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) : 1, slash ? path : ".");
  if (slash == path) snprintf(dir, sizeof dir, "/");
  char *rdir = realpath(dir, NULL);
  if (!rdir) return strdup(path);
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "%s/%s", rdir, slash ? slash + 1 : path);
  free(rdir);
  return sb.s;
}

/* The file a path names, for comparing outputs: the name the bytes go to
 * (links followed as the writer follows them, so a dangling link names its
 * target), then the real path of what exists, else folder_identity. */
static char *file_identity(const char *given) {
  char *target = bg_resolve_links(given);
  const char *path = target ? target : given;
  char *id = realpath(path, NULL);
  if (!id) id = folder_identity(path);
  free(target);
  return id;
}

/* Two outputs into one file would overwrite each other: refused before
 * anything is computed (a usage error). An -o NAME.c also writes NAME.h. */
static int same_file_twice(const run *r, const char **paths, int n) {
  char hpaths[BG_MAX_OUTPUTS][4096];
  const char *all[2 * BG_MAX_OUTPUTS + 8];
  int k = 0, nh = 0;
  for (int i = 0; i < n; i++) all[k++] = paths[i];
  for (int i = 0; i < r->opts.nout && nh < BG_MAX_OUTPUTS; i++) {
    const char *p = r->opts.out[i].path;
    size_t len = strlen(p);
    if (bg_cli_is_stdout(p) || strcmp(r->opts.out[i].format, "c") || len >= sizeof hpaths[0]) continue;
    memcpy(hpaths[nh], p, len + 1);
    hpaths[nh][len - 1] = 'h';
    all[k++] = hpaths[nh++];
  }
  char *id[2 * BG_MAX_OUTPUTS + 8];
  for (int i = 0; i < k; i++) id[i] = file_identity(all[i]);
  int rc = EXIT_OK;
  for (int i = 0; i < k && !rc; i++)
    for (int j = i + 1; j < k && !rc; j++) {
      if (strcmp(id[i], id[j])) continue;
      fprintf(stderr, "bgdraw: error: two outputs go to one file, '%s' and '%s' (%s); give each "
                      "output its own file\n", all[i], all[j], id[i]);
      rc = EXIT_USAGE;
    }
  for (int i = 0; i < k; i++) free(id[i]);
  return rc;
}

/* No output may be a file the run reads (model, tables, style): compared by
 * device and inode, so another name or a symlink for an input is refused
 * too. A usage error, found before anything is written. */
int cli_check_outputs(run *r) {
  if (run_draws(r)) {
    char style[4096];
    bg_style_path(r->ropts.style ? r->ropts.style : "default", r->ropts.style_dir, style,
                  sizeof style);
    bg_input_note(style);
  }
  const char *paths[BG_MAX_OUTPUTS + 6];
  int n = 0;
  for (int i = 0; i < r->opts.nout; i++)
    if (!bg_cli_is_stdout(r->opts.out[i].path)) paths[n++] = r->opts.out[i].path;
  if (r->opts.plot) paths[n++] = r->opts.plot;
  if (r->opts.report) paths[n++] = r->opts.report;
  const char *lin_plots[] = {r->opts.bode, r->opts.nyquist, r->opts.step};
  for (int i = 0; i < 3; i++)
    if (lin_plots[i]) paths[n++] = lin_plots[i];
  if (r->opts.depfile && !bg_cli_is_stdout(r->opts.depfile)) paths[n++] = r->opts.depfile;
  for (int i = 0; i < n; i++) {
    if (!bg_path_is_input(paths[i])) continue;
    fprintf(stderr, "bgdraw: error: output '%s' is one of the run's input files (the model, a "
                    "table or a style file); refusing to overwrite it\n", paths[i]);
    return EXIT_USAGE;
  }
  return same_file_twice(r, paths, n);
}

/* The default output when no -o is given: the SVG diagram on standard
 * output when that is not a terminal (`bgdraw m.bg > m.svg`, as dot does),
 * unless a depfile needs a file to name; else out/<model>.svg. */
void cli_default_output(run *r, char *buf, size_t n) {
  if (!isatty(STDOUT_FILENO) && !r->opts.depfile) {
    snprintf(buf, n, "%s", BG_CLI_STDOUT);
  } else {
    mkdir("out", 0777); /* may exist already */
    snprintf(buf, n, "out/%s.svg", r->R->model->name);
  }
  r->opts.out[0].path = buf;
  r->opts.out[0].format = "svg";
  r->opts.nout = 1;
}


/* The writers' messages: errors as diagnostics, a refusal in words. */
static void say(run *r) {
  bg_output *w = &r->out;
  bg_diags_print(&w->dg_model, stderr);
  bg_diags_print(&w->dg, stderr);
  if (w->refusal) fprintf(stderr, "bgdraw: %s\n", w->refusal);
  bg_output_clear_messages(w);
}

/* An output whose writer only appends, going to a file: written to the
 * file while it is made (fileio.h, bg_stream), so a 100 000-mass SVG is
 * never whole in memory. */
static int write_streamed(run *r, const char *kind, const char *form, const char *path) {
  bg_strbuf sb = {0};
  bg_stream st;
  bg_stream_begin(&st, &sb, path);
  int rc = (int)bg_output_write(&r->out, kind, form, path, &sb);
  say(r);
  size_t bytes;
  int ok = rc == EXIT_OK && !r->out.nothing;
  if (bg_stream_finish(&st, &sb, ok, &bytes) != 0) {
    fprintf(stderr, "bgdraw: error: cannot write '%s': %s\n", path, bg_file_strerror(errno));
    rc = EXIT_WRITE;
  } else if (ok) {
    bg_logf(&r->R->o.log, BG_LOG_PROGRESS, "wrote %s (%zu bytes)", path, bytes);
  }
  bg_sb_free(&sb);
  return rc;
}

int cli_write_output(run *r, const char *kind, const char *form, const char *path) {
  if (!path) path = BG_CLI_STDOUT;
  int to_stdout = bg_cli_is_stdout(path);
  const bg_output_kind *k = bg_output_find(kind);
  if (!to_stdout && k && (k->flags & BG_OUTK_APPENDS)) return write_streamed(r, kind, form, path);
  bg_strbuf sb = {0};
  int rc = (int)bg_output_write(&r->out, kind, form, to_stdout ? NULL : path, &sb);
  say(r);
  if (r->out.nothing) {
    bg_sb_free(&sb);
    return rc;
  }
  if (rc == EXIT_OK) rc = cli_write_text(path, &sb);
  if (rc == EXIT_OK && !to_stdout)
    bg_logf(&r->R->o.log, BG_LOG_PROGRESS, "wrote %s (%zu bytes)", path, sb.len);
  bg_sb_free(&sb);
  return rc;
}

/* -o NAME.c: NAME.h beside it, then the source that includes it. */
static int write_c(run *r, const char *path) {
  if (bg_cli_is_stdout(path)) return cli_write_output(r, "c", NULL, NULL); /* as --equations c */
  size_t len = strlen(path);
  char hpath[4096];
  if (len + 1 > sizeof hpath) {
    fprintf(stderr, "bgdraw: error: output path too long: '%s'\n", path);
    return EXIT_USAGE;
  }
  memcpy(hpath, path, len + 1);
  hpath[len - 1] = 'h'; /* NAME.c -> NAME.h */
  bg_strbuf h = {0};
  int rc = (int)bg_output_write(&r->out, "h", NULL, path, &h);
  say(r);
  if (rc == EXIT_OK) rc = cli_write_text(hpath, &h);
  bg_sb_free(&h);
  return rc ? rc : cli_write_output(r, "c", NULL, path);
}

int cli_write_outputs(run *r) {
  for (int i = 0; i < r->opts.nout; i++) {
    const bg_cli_output *out = &r->opts.out[i];
    bg_logf(&r->R->o.log, BG_LOG_PROGRESS, "writing %s",
            bg_cli_is_stdout(out->path) ? "stdout" : out->path);
    int rc;
    if (!strcmp(out->format, "c")) rc = write_c(r, out->path);
    else rc = cli_write_output(r, out->format, NULL, out->path);
    if (rc) return rc;
  }
  return EXIT_OK;
}

int cli_linear_asked(const bg_cli_opts *o) { return o->linear || o->bode || o->nyquist || o->step; }

int cli_linear_only(const bg_cli_opts *o) {
  return cli_linear_asked(o) && o->nout == 0 && !o->simulate && !o->plot && !o->report &&
         !o->equations;
}

int cli_write_linear(run *r) {
  const bg_cli_opts *o = &r->opts;
  if (!cli_linear_asked(o)) return EXIT_OK;
  bg_run_need(r->R, BG_STAGE_LINEAR);
  int rc = o->linear ? cli_write_output(r, "linear", o->linear, NULL) : EXIT_OK;
  if (rc) return rc;
  if (!r->R->lin.ok) { /* the text said why; the plots would say it again */
    fprintf(stderr, "bgdraw: linear analysis refused: %s\n",
            r->R->lin.message ? r->R->lin.message : "unknown reason");
    return EXIT_SIM;
  }
  if (o->bode) rc = cli_write_output(r, "bode", NULL, o->bode);
  if (!rc && o->nyquist) rc = cli_write_output(r, "nyquist", NULL, o->nyquist);
  if (!rc && o->step) rc = cli_write_output(r, "step", NULL, o->step);
  return rc;
}
