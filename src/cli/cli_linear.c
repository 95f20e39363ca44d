/* The linear analysis on the command line (docs/linear.md, docs/cli.md):
 * when it runs, --linear FORM on stdout (text, latex, json, and the state
 * space as an Octave script or a Python module), the plots. (-o FILE.m and
 * FILE.py are the model exports of docs/export.md.) */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "base/fileio.h"
#include "cli/cli_run.h"
#include "json/json.h"
#include "cli/cli_render.h"

static int has_format(const bg_cli_opts *o, const char *f) {
  for (int i = 0; i < o->nout; i++)
    if (!strcmp(o->out[i].format, f)) return 1;
  return 0;
}

int cli_linear_asked(const bg_cli_opts *o) {
  return o->linear || o->bode || o->nyquist || o->step;
}

int cli_linear_only(const bg_cli_opts *o) {
  return cli_linear_asked(o) && o->nout == 0 && !o->simulate && !o->plot && !o->report &&
         !o->equations;
}

int cli_wants_linear(const run *r) {
  const bg_cli_opts *o = &r->opts;
  if (o->check) return 0;
  return cli_linear_asked(o) || (r->model->linear.present && (o->report || has_format(o, "json")));
}

void cli_linearise(run *r) {
  if (r->opts.verbose) fprintf(stderr, "bgdraw: linear analysis\n");
  bg_linear_compute(r->model, &r->analysis, -1, &r->lin);
  r->lin_done = 1;
  if (r->lin.ok && r->lin.message && !r->opts.quiet)
    fprintf(stderr, "bgdraw: note: linear analysis: %s\n", r->lin.message);
}

static int refused(run *r) {
  if (r->lin.ok) return 0;
  fprintf(stderr, "bgdraw: linear analysis refused: %s\n",
          r->lin.message ? r->lin.message : "unknown reason");
  return 1;
}

/* --linear octave|python: the state space as an Octave script or a Python module. */
static int write_state_space(run *r, const char *form) {
  if (refused(r)) return EXIT_SIM;
  if (!r->lin.reduced) {
    fprintf(stderr, "bgdraw: error: no state space to export: %s\n",
            r->lin.reduce_note ? r->lin.reduce_note : "not reduced");
    return EXIT_SIM;
  }
  bg_strbuf sb = {0};
  if (!strcmp(form, "octave")) bg_linear_export_m(&r->lin, r->model, &sb);
  else bg_linear_export_py(&r->lin, r->model, &sb);
  int rc = cli_write_stdout(&sb);
  bg_sb_free(&sb);
  return rc;
}

static int write_plot(run *r, const char *path, int kind) {
  bg_diags dg;
  bg_diags_init(&dg, "bgdraw", NULL, 0);
  int rc = bg_plot_linear_write(r->model, &r->lin, kind, r->ropts.style, r->ropts.style_dir, path, &dg);
  if (rc) bg_diags_print(&dg, stderr);
  bg_diags_free(&dg);
  return rc == 0 ? EXIT_OK : rc == BG_RENDER_EWRITE ? EXIT_WRITE : EXIT_SIM;
}

int cli_write_linear(run *r) {
  const bg_cli_opts *o = &r->opts;
  if (!o->linear && !o->bode && !o->nyquist && !o->step) return EXIT_OK;
  if (!r->lin_done) return EXIT_OK;
  if (o->linear && (!strcmp(o->linear, "octave") || !strcmp(o->linear, "python"))) {
    int rc = write_state_space(r, o->linear);
    if (rc) return rc;
  } else if (o->linear) {
    bg_strbuf sb = {0};
    if (!strcmp(o->linear, "json")) bg_json_write_linear(&r->lin, &sb), bg_sb_putc(&sb, '\n');
    else bg_linear_print(&r->lin, r->model, o->linear, &sb);
    int rc = cli_write_stdout(&sb);
    bg_sb_free(&sb);
    if (rc) return rc;
  }
  if (refused(r)) return EXIT_SIM;
  int rc = EXIT_OK;
  if (o->bode) rc = write_plot(r, o->bode, BG_PLOT_BODE);
  if (!rc && o->nyquist) rc = write_plot(r, o->nyquist, BG_PLOT_NYQUIST);
  if (!rc && o->step) rc = write_plot(r, o->step, BG_PLOT_STEP);
  return rc;
}
