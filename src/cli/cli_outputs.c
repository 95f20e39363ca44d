/* The writers of bgdraw's outputs: diagrams, JSON, equations, CSV, plots
 * and the report, each written atomically; their exit statuses (docs/cli.md). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli/cli_run.h"
#include "equations/equations.h"
#include "base/fileio.h"
#include "json/json.h"
#include "cli/cli_render.h"
#include "base/strbuf.h"

static int is_diagram_format(const char *f) {
  return !strcmp(f, "svg") || !strcmp(f, "pdf") || !strcmp(f, "png") || !strcmp(f, "dot");
}

/* Whether the run draws, and so reads a style file: a diagram output, a
 * plot or the report. A run that does not never loads the render module
 * (cli_render.h). The default diagram is an -o by now. */
static int run_draws(const run *r) {
  const bg_cli_opts *o = &r->opts;
  if (o->plot || o->report || o->bode || o->nyquist || o->step) return 1;
  for (int i = 0; i < o->nout; i++)
    if (is_diagram_format(o->out[i].format)) return 1;
  return 0;
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
  return EXIT_OK;
}

/* The default output when no -o is given: out/<model>.svg. */
void cli_default_output(run *r, char *buf, size_t n) {
  mkdir("out", 0777); /* may exist already */
  snprintf(buf, n, "out/%s.svg", r->model->name);
  r->opts.out[0].path = buf;
  r->opts.out[0].format = "svg";
  r->opts.nout = 1;
}

int cli_write_text(const char *path, const bg_strbuf *sb) {
  if (bg_cli_is_stdout(path)) return cli_write_stdout(sb); /* in place, never renamed */
  if (bg_write_file_atomic(path, bg_sb_str(sb), sb->len) == 0) return EXIT_OK;
  fprintf(stderr, "bgdraw: error: cannot write '%s': %s\n", path, bg_file_strerror(errno));
  return EXIT_WRITE;
}

int cli_write_stdout(const bg_strbuf *sb) {
  if (bg_write_stream(stdout, bg_sb_str(sb), sb->len) == 0) return EXIT_OK;
  fprintf(stderr, "bgdraw: error: cannot write to stdout: %s\n", bg_file_strerror(errno));
  return EXIT_WRITE;
}

static int write_json(run *r, const char *path) {
  bg_strbuf sb = {0};
  bg_json_write_analysis(r->model, &r->analysis, &sb);
  if (r->simulated) bg_json_append_simulation(&sb, r->model, &r->sim, r->sim_status);
  if (r->lin_done) bg_json_append_linear(&sb, &r->lin);
  int rc = cli_write_text(path, &sb);
  bg_sb_free(&sb);
  return rc;
}

static int write_diagram(run *r, const bg_cli_output *out) {
  if (!r->diagram) {
    r->diagram = bg_diagram_build(r->model, &r->analysis, &r->ropts, &r->dg);
    if (!r->diagram) {
      bg_diags_print(&r->dg, stderr);
      return EXIT_USAGE;
    }
  }
  int rc;
  if (bg_cli_is_stdout(out->path)) {
    bg_strbuf sb = {0};
    rc = bg_diagram_render(r->diagram, out->format, &sb, &r->dg);
    if (rc == BG_RENDER_OK) rc = cli_write_text(out->path, &sb) == EXIT_OK ? BG_RENDER_OK
                                                                      : BG_RENDER_EWRITE;
    bg_sb_free(&sb);
    if (rc == BG_RENDER_EWRITE) return EXIT_WRITE;
  } else {
    rc = bg_diagram_write(r->diagram, out->path, out->format, &r->dg);
  }
  if (rc == BG_RENDER_OK) return EXIT_OK;
  bg_diags_print(&r->dg, stderr);
  return rc == BG_RENDER_EWRITE ? EXIT_WRITE : EXIT_USAGE;
}

int cli_write_equations(run *r, const char *path, const char *form) {
  if (!r->eqsys) {
    fprintf(stderr, "bgdraw: error: no equations for '%s': %s\n", path ? path : "stdout",
            r->eqsys_problem ? r->eqsys_problem : "unknown reason");
    return EXIT_MODEL;
  }
  if (!strcmp(form, "c")) return cli_write_export(r, path, "c");
  bg_strbuf sb = {0};
  bg_eqprint(r->eqsys, form, &sb);
  int rc = cli_write_text(path ? path : BG_CLI_STDOUT, &sb);
  bg_sb_free(&sb);
  return rc;
}

static int write_csv(run *r, const char *path) {
  if (!r->simulated || !r->sim.nrows) return EXIT_OK; /* refused: nothing to write */
  bg_strbuf sb = {0};
  bg_csv_write(&r->sim, &sb);
  int rc = cli_write_text(path, &sb);
  bg_sb_free(&sb);
  return rc;
}

static int write_one(run *r, const bg_cli_output *out) {
  if (r->opts.verbose)
    fprintf(stderr, "bgdraw: writing %s\n", bg_cli_is_stdout(out->path) ? "stdout" : out->path);
  if (!strcmp(out->format, "json")) return write_json(r, out->path);
  if (is_diagram_format(out->format)) return write_diagram(r, out);
  if (!strcmp(out->format, "tex")) return cli_write_equations(r, out->path, "latex");
  if (!strcmp(out->format, "c") || !strcmp(out->format, "py") || !strcmp(out->format, "m") ||
      !strcmp(out->format, "mo") || !strcmp(out->format, "fmu"))
    return cli_write_export(r, out->path, out->format);
  if (!strcmp(out->format, "csv")) return write_csv(r, out->path);
  if (!strcmp(out->format, "bg")) {
    bg_strbuf sb = {0};
    bg_sb_puts(&sb, r->tx.text);
    int rc = cli_write_text(out->path, &sb);
    bg_sb_free(&sb);
    return rc;
  }
  BG_FATAL("option parsing let through output format '%s'", out->format);
}

int cli_write_outputs(run *r) {
  for (int i = 0; i < r->opts.nout; i++) {
    int rc = write_one(r, &r->opts.out[i]);
    if (rc) return rc;
  }
  return EXIT_OK;
}

/* --plot FILE: the simulation plots, also of a partial run; none when the
 * run was refused (no rows). The extension was checked with the options. */
int cli_write_plot(run *r) {
  const char *path = r->opts.plot;
  if (!r->simulated || !r->sim.nrows) return EXIT_OK;
  bg_diags dg;
  bg_diags_init(&dg, "bgdraw", NULL, 0);
  int rc = bg_plot_write(r->model, &r->sim, r->ropts.style, r->ropts.style_dir, path, &dg);
  if (rc != BG_RENDER_OK) bg_diags_print(&dg, stderr);
  else if (r->opts.verbose) fprintf(stderr, "bgdraw: wrote %s\n", path);
  bg_diags_free(&dg);
  return rc == BG_RENDER_OK ? EXIT_OK : rc == BG_RENDER_EWRITE ? EXIT_WRITE : EXIT_USAGE;
}

/* --report FILE.pdf; the simulation ran when the model has a simulate block. */
int cli_write_report(run *r) {
  char skipped[160] = "";
  if (r->eqsys && !r->index_done)
    snprintf(skipped, sizeof skipped, "%d unknowns, more than the dense algorithm's limit of %d",
             bg_eqsys_n(r->eqsys), INDEX_MAX_UNKNOWNS);
  bg_report_input in = {r->model, &r->analysis, r->eqsys, r->eqsys_problem,
                        r->index_done ? &r->index : NULL, skipped[0] ? skipped : NULL,
                        r->simulated ? &r->sim : NULL, r->sim_status, &r->ropts,
                        r->lin_done ? &r->lin : NULL, r->tx_done ? r->opts.transform : NULL,
                        r->tx_done ? &r->tx : NULL};
  bg_diags dg;
  bg_diags_init(&dg, "bgdraw", NULL, 0);
  int rc = bg_report_write(&in, r->opts.report, &dg);
  if (rc != BG_RENDER_OK) bg_diags_print(&dg, stderr);
  bg_diags_free(&dg);
  return rc == BG_RENDER_OK ? EXIT_OK : rc == BG_RENDER_EWRITE ? EXIT_WRITE : EXIT_USAGE;
}
