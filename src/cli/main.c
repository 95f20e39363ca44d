/* SPDX-License-Identifier: BSD-3-Clause */
/* bgdraw: the command line. Runs the stages a request needs (load, analyse,
 * equations, numeric index, simulation); cli_outputs.c writes the outputs.
 * Only the cli files touch argv, output paths and exit codes. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "causality/causality.h"
#include "cli/cli_run.h"
#include "cli/cli_study.h"
#include "equations/equations.h"
#include "base/fileio.h"
#include "analysis/analysis.h"
#include "base/strbuf.h"

#ifndef BG_VERSION
#define BG_VERSION "0.0.0"
#endif

/* The engine's messages on stderr: progress with -v, the rest unless -q. */
static void log_stderr(void *ctx, bg_log_level level, const char *msg) {
  const bg_cli_opts *o = ctx;
  if (level >= BG_LOG_INFO && o->quiet) return;
  fprintf(stderr, "bgdraw: %s%s\n",
          level == BG_LOG_WARNING ? "warning: " : level == BG_LOG_NOTE ? "note: " : "", msg);
}

static void run_free(run *r) {
  if (r->tx_done) bg_transform_result_free(&r->tx);
  if (r->R) bg_output_free(&r->out);
  bg_run_free(r->R);
  bg_cli_free(&r->opts);
}

/* Reads, parses and compiles the model into the run; diagnostics stay in
 * its dg. The model from stdin is called <stdin> in messages, or what
 * --stdin-name says (then its used files and tables are found from there). */
static int load_model(run *r) {
  const bg_cli_opts *o = &r->opts;
  bg_run_opts ro;
  bg_run_opts_init(&ro);
  ro.method = o->causality ? bg_method_parse(o->causality) : -1;
  ro.sets = o->sets, ro.nsets = o->nsets;
  ro.max_list = r->max_list;
  ro.max_errors = r->max_errors;
  ro.verify = o->verify;
  ro.warn_off = o->warn_off, ro.werror = o->werror;
  ro.keep_ast = o->transform != NULL; /* the transformations edit the syntax */
  ro.lib_dir = cli_lib_dir();
  ro.log = (bg_log){log_stderr, &r->opts, o->verbose};
  r->R = bg_run_new(&ro);
  int rc;
  if (!bg_cli_is_stdout(o->model_path)) {
    rc = bg_run_load_file(r->R, o->model_path);
  } else {
    size_t len = 0;
    char *text = bg_read_stream(stdin, &len);
    rc = bg_run_load(r->R, o->stdin_name ? o->stdin_name : "<stdin>", text, len);
  }
  bg_output_opts oo = {r->ropts, o->prefix, o->transform, NULL, 1}; /* the FMU cleans up on ^C */
  oo.render.log = &r->R->o.log;
  bg_output_init(&r->out, r->R, &oo);
  return rc;
}

/* Runs the simulation; prints the refusal or failure. EXIT_SIM on failure
 * (partial results are still written), EXIT_OK otherwise. */
static int simulate(run *r) {
  bg_run_need(r->R, BG_STAGE_SIMULATION);
  const bg_run *R = r->R;
  if (R->sim_status == 0) return EXIT_OK;
  const char *why = R->sim.message ? R->sim.message : R->eqsys_problem;
  if (R->sim_status == 1) fprintf(stderr, "bgdraw: simulation refused: %s\n", why ? why : "unknown reason");
  else fprintf(stderr, "bgdraw: %s\n", why ? why : "simulation failed"); /* "simulation failed at t = ..." */
  return EXIT_SIM;
}

static void print_version(void) {
  bg_strbuf sb = {0};
  bg_render_versions(&sb);
  printf("bgdraw %s\nbuilt with SUNDIALS %s, %s\n", BG_VERSION, bg_simulate_sundials_version(),
         bg_sb_str(&sb));
  bg_sb_free(&sb);
}

/* Diagnostics: colour on a terminal unless NO_COLOR is set (or --color
 * says otherwise); JSON lines with --diagnostics-format=json. */
static void diagnostics_output(const bg_cli_opts *o) {
  const char *no_color = getenv("NO_COLOR");
  int color = isatty(fileno(stderr)) && !(no_color && *no_color);
  if (o->color && !strcmp(o->color, "always")) color = 1;
  if (o->color && !strcmp(o->color, "never")) color = 0;
  int json = o->diag_format && !strcmp(o->diag_format, "json");
  bg_diags_set_output(color && !json, json);
}

/* --transform NAME: the new model, checked; EXIT_SIM with the reason when
 * the transformation does not apply (nothing is written then). */
static int transform(run *r) {
  const bg_cli_opts *o = &r->opts;
  const bg_run *R = r->R;
  bg_transform_input in = {o->transform, R->src, R->srclen, R->dg.file, R->ast, R->model,
                           &R->analysis, o->sets, o->nsets};
  char *why = NULL;
  bg_logf(&R->o.log, BG_LOG_PROGRESS, "transformation %s", o->transform);
  if (bg_transform_apply(&in, &r->tx, &why) != 0) {
    fprintf(stderr, "bgdraw: error: --transform %s does not apply to %s: %s\n", o->transform,
            R->model->name, why);
    free(why);
    return EXIT_SIM;
  }
  r->tx_done = 1;
  r->out.o.tx = &r->tx;
  bg_logf(&R->o.log, BG_LOG_PROGRESS, "%s", r->tx.summary);
  return EXIT_OK;
}

static int wants_simulation(const bg_cli_opts *o) {
  if (o->simulate || o->plot) return 1;
  for (int i = 0; i < o->nout; i++)
    if (!strcmp(o->out[i].format, "csv")) return 1;
  return 0;
}

/* Everything after the analysis: simulation, outputs, plot, report. */
static int write_all(run *r) {
  const bg_cli_opts *o = &r->opts;
  if (o->check) return cli_write_output(r, "check", NULL, NULL);
  if (o->equations && o->nout == 0 && !o->plot && !o->report && !o->simulate)
    return cli_write_output(r, "equations", o->equations, NULL);
  if (cli_linear_only(o)) return cli_write_linear(r);
  /* every stage some output needs, in the order the command line always
   * ran them: the index and its reduction, the linear analysis, then the
   * simulation */
  for (int i = 0; i < o->nout; i++) {
    const bg_output_kind *k = bg_output_find(o->out[i].format);
    if (k && k->need != BG_STAGE_SIMULATION) bg_output_need(&r->out, k);
  }
  if (o->equations) bg_run_need(r->R, BG_STAGE_EQUATIONS);
  int wantsim = wants_simulation(o), report_sim = o->report && r->R->model->sim.present;
  if (wantsim || o->report) bg_run_need(r->R, BG_STAGE_REDUCTION);
  if (cli_linear_asked(o) || (o->report && r->R->model->linear.present)) bg_run_need(r->R, BG_STAGE_LINEAR);
  int simrc = wantsim || report_sim ? simulate(r) : EXIT_OK;
  int refused = simrc && !r->R->sim.nrows;
  if (!wantsim && r->R->sim_status == 1) simrc = refused = 0; /* the report says why */
  int rc = EXIT_OK;
  if (o->equations) rc = cli_write_output(r, "equations", o->equations, NULL);
  if (!rc) rc = cli_write_outputs(r);
  if (!rc && o->plot) rc = cli_write_output(r, "plot", NULL, o->plot);
  if (!rc && o->report) rc = cli_write_output(r, "report", NULL, o->report);
  if (!rc) rc = cli_write_linear(r);
  if (!rc) rc = refused ? EXIT_SIM : simrc;
  return rc;
}

int main(int argc, char **argv) {
  run r;
  memset(&r, 0, sizeof r);
  /* a reader that closed the pipe is a write error (status 4), not a death */
  signal(SIGPIPE, SIG_IGN);
  if (bg_cli_parse(argc, argv, &r.opts) != 0) {
    bg_cli_free(&r.opts);
    return EXIT_USAGE;
  }
  if (r.opts.help || r.opts.version) {
    if (r.opts.help) bg_cli_print_help(stdout);
    else print_version();
    bg_cli_free(&r.opts);
    return EXIT_OK;
  }
  diagnostics_output(&r.opts);
  cli_study study; /* a parameter study (docs/study.md) */
  int studying = cli_study_asked(&r.opts);
  if ((studying && cli_study_parse(&r.opts, &study) != 0) || cli_render_options(&r) != 0) {
    if (studying) cli_study_free(&study);
    bg_cli_free(&r.opts);
    return EXIT_USAGE;
  }
  int rc = load_model(&r);
  if (!r.opts.quiet || rc) bg_diags_print(&r.R->dg, stderr);
  if (rc || studying) {
    if (!rc) rc = cli_study_run(&r, &study);
    else rc = EXIT_MODEL;
    if (studying) cli_study_free(&study);
    run_free(&r);
    return rc;
  }
  if (r.opts.import && !r.R->imported) {
    fprintf(stderr, "bgdraw: --import: %s is a bgdraw model already, not another tool's (BondGraphTools YAML, an MTT drawing)\n",
            r.R->name);
    run_free(&r);
    return EXIT_USAGE;
  }
  char defpath[1024];
  if (!r.opts.check && r.opts.nout == 0 && !r.opts.simulate && !r.opts.equations &&
      !r.opts.plot && !r.opts.report && !cli_linear_asked(&r.opts))
    cli_default_output(&r, defpath, sizeof defpath);
  if ((rc = cli_check_outputs(&r)) != 0) {
    run_free(&r);
    return rc;
  }
  bg_run_need(r.R, BG_STAGE_ANALYSIS);
  if (r.opts.transform && (rc = transform(&r)) != 0) {
    run_free(&r);
    return rc;
  }
  rc = write_all(&r);
  if ((rc == EXIT_OK || rc == EXIT_SIM) && r.opts.depfile) {
    int drc = cli_write_depfile(&r);
    if (drc) rc = drc;
  }
  run_free(&r);
  return rc;
}
