/* SPDX-License-Identifier: BSD-3-Clause */
/* -M/--depfile FILE: a make rule "OUTPUTS: MODEL USED STYLE TABLES" naming
 * every file the run read (the files `use`d, directly or through others), plus an empty rule per input (as gcc -MP writes), so
 * make rebuilds a figure when an input changes and does not fail when one
 * is deleted. */
#include <string.h>
#include <unistd.h>

#include "base/strbuf.h"
#include "cli/cli_run.h"
#include "cli/cli_render.h"

/* A path as make reads it: blanks and '#' escaped with '\', '$' doubled. */
static void put_path(bg_strbuf *b, const char *path) {
  for (const char *c = path; *c; c++) {
    if (*c == ' ' || *c == '\t' || *c == '#' || *c == '\\') bg_sb_putc(b, '\\');
    if (*c == '$') bg_sb_putc(b, '$');
    bg_sb_putc(b, *c);
  }
}

static void add_unique(const char **list, int *n, int cap, const char *path) {
  for (int i = 0; i < *n; i++)
    if (!strcmp(list[i], path)) return;
  if (*n < cap) list[(*n)++] = path;
}

/* The inputs read: the model, the files it uses (every source of the
 * diagnostics that is a file read, not an instance's view of one), the
 * style file (when something was drawn) and every table CSV. style_buf
 * holds the style's path. */
static int collect_inputs(const run *r, const char **in, int cap, char *style_buf, size_t n) {
  int k = 0;
  if (!bg_cli_is_stdout(r->opts.model_path)) add_unique(in, &k, cap, r->opts.model_path);
  const bg_diags *dg = &r->R->dg;
  for (int i = 1; i < dg->nsources; i++)
    if (dg->sources[i].context.line == 0 && dg->sources[i].path)
      add_unique(in, &k, cap, dg->sources[i].path);
  if (r->out.diagram || r->opts.plot || r->opts.report || r->opts.bode || r->opts.nyquist ||
      r->opts.step) {
    bg_style_path(r->ropts.style ? r->ropts.style : "default", r->ropts.style_dir, style_buf, n);
    if (access(style_buf, R_OK) == 0) add_unique(in, &k, cap, style_buf);
  }
  for (int t = 0; t < r->R->model->ntable; t++)
    if (r->R->model->table_path[t]) add_unique(in, &k, cap, r->R->model->table_path[t]);
  return k;
}

int cli_write_depfile(run *r) {
  enum { CAP = 4096 };
  static const char *in[CAP];
  char style[4096];
  int nin = collect_inputs(r, in, CAP, style, sizeof style);
  bg_strbuf b = {0};
  int ntarget = 0;
  for (int i = 0; i < r->opts.nout; i++) {
    if (bg_cli_is_stdout(r->opts.out[i].path)) continue;
    if (ntarget++) bg_sb_putc(&b, ' ');
    put_path(&b, r->opts.out[i].path);
  }
  const char *more[] = {r->opts.plot, r->opts.report, r->opts.bode, r->opts.nyquist, r->opts.step};
  for (int i = 0; i < 5; i++)
    if (more[i]) {
      if (ntarget++) bg_sb_putc(&b, ' ');
      put_path(&b, more[i]);
    }
  bg_sb_putc(&b, ':');
  for (int i = 0; i < nin; i++) bg_sb_putc(&b, ' '), put_path(&b, in[i]);
  bg_sb_putc(&b, '\n');
  for (int i = 0; i < nin; i++) bg_sb_putc(&b, '\n'), put_path(&b, in[i]), bg_sb_puts(&b, ":\n");
  int rc = cli_write_text(r->opts.depfile, &b);
  bg_sb_free(&b);
  return rc;
}
