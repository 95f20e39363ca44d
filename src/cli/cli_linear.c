/* The linear analysis on the command line (docs/linear.md, docs/cli.md):
 * when it runs, --linear FORM on stdout, the plots, the .m and .py exports. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "base/fileio.h"
#include "cli/cli_run.h"
#include "json/json_linear.h"

static int has_format(const bg_cli_opts *o, const char *f) {
  for (int i = 0; i < o->nout; i++)
    if (!strcmp(o->out[i].format, f)) return 1;
  return 0;
}

int cli_linear_asked(const bg_cli_opts *o) {
  return o->linear != NULL;
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

int cli_write_linear(run *r) {
  const bg_cli_opts *o = &r->opts;
  if (!o->linear) return EXIT_OK;
  if (!r->lin_done) return EXIT_OK;
  if (o->linear) {
    bg_strbuf sb = {0};
    if (!strcmp(o->linear, "json")) bg_json_write_linear(&r->lin, &sb), bg_sb_putc(&sb, '\n');
    else bg_linear_print(&r->lin, r->model, o->linear, &sb);
    int rc = cli_write_stdout(&sb);
    bg_sb_free(&sb);
    if (rc) return rc;
  }
  return refused(r) ? EXIT_SIM : EXIT_OK;
}
