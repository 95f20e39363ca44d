/* bgdraw: the command line. Runs the stages a request needs (load, analyse,
 * equations, numeric index, simulation); cli_outputs.c writes the outputs.
 * Only the cli files touch argv, output paths and exit codes. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "causality/causality.h"
#include "cli/cli_run.h"
#include "equations/equations.h"
#include "base/fileio.h"
#include "analysis/analysis.h"
#include "base/strbuf.h"

#ifndef BG_VERSION
#define BG_VERSION "0.0.0"
#endif

static void run_free(run *r) {
  if (r->tx_done) bg_transform_result_free(&r->tx);
  if (r->lin_done) bg_linear_free(&r->lin);
  if (r->simulated) bg_simresult_free(&r->sim); /* before the systems its names point into */
  if (r->ired_done) bg_indexred_free(&r->ired);
  if (r->index_done) bg_index_free(&r->index);
  if (r->eqsys) bg_eqsys_free(r->eqsys);
  free(r->eqsys_problem);
  if (r->diagram) bg_diagram_free(r->diagram);
  if (r->analysed) bg_analysis_free(&r->analysis);
  if (r->model) bg_model_free(r->model);
  if (r->ast) bg_ast_free(r->ast);
  bg_diags_free(&r->dg);
  free(r->src);
  bg_cli_free(&r->opts);
}

/* Reads, parses and compiles the model; diagnostics stay in r->dg. The
 * model from stdin is called <stdin> in messages (the model name "stdin"). */
static int load_model(run *r) {
  const bg_cli_opts *o = &r->opts;
  int from_stdin = bg_cli_is_stdout(o->model_path); /* "-" */
  const char *name = from_stdin ? "<stdin>" : o->model_path;
  r->src = from_stdin ? bg_read_stream(stdin, &r->srclen) : bg_read_file(o->model_path, &r->srclen);
  bg_diags_init(&r->dg, name, r->src, r->srclen);
  r->dg.max_errors = r->max_errors;
  if (!r->src) {
    bg_srcloc none = {0};
    bg_diag_error(&r->dg, none, "cannot read the model: %s", bg_file_strerror(errno));
    return -1;
  }
  r->ast = bg_parse_string(name, r->src, r->srclen, &r->dg);
  if (!r->ast || r->dg.nerrors) return -1;
  r->model = bg_model_compile(r->ast, o->sets, o->nsets, &r->dg);
  if (!o->transform) { /* the transformations edit the syntax */
    bg_ast_free(r->ast);
    r->ast = NULL;
  }
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
  bg_analysis_limits lim = {r->max_list, r->max_list};
  bg_analysis_run(r->model, &r->analysis, &lim);
}

/* The equations. A model whose equations cannot be formed is not an error
 * here: the reason is kept for the outputs that need equations. */
static void derive_equations(run *r) {
  if (r->opts.verbose) fprintf(stderr, "bgdraw: equations\n");
  bg_diags eqd;
  bg_diags_init(&eqd, r->dg.file, r->src, r->srclen);
  r->eqsys = bg_eqsys_build(r->model, &r->analysis, &eqd);
  if (!r->eqsys) {
    r->eqsys_problem = strdup(eqd.n ? eqd.items[0].msg : "the equations could not be formed");
    bg_diags_free(&eqd);
    return;
  }
  bg_diags_free(&eqd);
  /* what the equations become after symbolic elimination (JSON reduced_form) */
  r->analysis.reduced_form = bg_eqred_form(r->eqsys);
}

/* The numeric index of the linearised model (JSON index.numeric). */
static void numeric_index(run *r) {
  if (!r->eqsys) return;
  if (bg_eqsys_n(r->eqsys) > INDEX_MAX_UNKNOWNS) {
    if (r->opts.verbose)
      fprintf(stderr, "bgdraw: %d unknowns: numeric index skipped (dense algorithm, limit %d)\n",
              bg_eqsys_n(r->eqsys), INDEX_MAX_UNKNOWNS);
    return;
  }
  if (r->opts.verbose) fprintf(stderr, "bgdraw: numeric index (Algorithm 4.1)\n");
  bg_index_compute(r->eqsys, r->model, &r->index);
  r->index_done = 1;
  r->analysis.index_numeric_set = r->index.index != BG_INDEX_FAILED;
  r->analysis.index_numeric = r->index.index;
  char *why = bg_index_disagreement(&r->analysis, &r->index);
  if (why) {
    r->analysis.index_disagreement = bg_arena_strdup(&r->analysis.arena, why);
    if (!r->opts.quiet) fprintf(stderr, "bgdraw: warning: %s\n", why);
    free(why);
  }
}

static const char **arena_list(bg_arena *ar, char **v, int n) {
  const char **out = bg_arena_alloc(ar, (size_t)(n + 1) * sizeof(char *));
  for (int k = 0; k < n; k++) out[k] = bg_arena_strdup(ar, v[k]);
  return out;
}

/* Pantelides and dummy derivatives when the index is above 1 (or a loop of
 * gain +1 makes it so); the analysis keeps what was done, in words, for the
 * JSON, the report and --check. */
static void index_reduction(run *r) {
  bg_analysis *a = &r->analysis;
  if (!r->eqsys || !bg_simulate_index_problem(a)) return;
  if (r->opts.verbose) fprintf(stderr, "bgdraw: index reduction (Pantelides, dummy derivatives)\n");
  bg_indexred_run(r->eqsys, &r->ired);
  r->ired_done = 1;
  a->ired_status = r->ired.status;
  a->ired_index = r->ired.index;
  a->ired_message = bg_arena_strdup(&a->arena, r->ired.message ? r->ired.message : "");
  a->ired_nconstraint = r->ired.nconstraint, a->ired_nlost = r->ired.nlost, a->ired_ndummy = r->ired.ndummy;
  a->ired_constraint = arena_list(&a->arena, r->ired.constraint, r->ired.nconstraint);
  a->ired_lost = arena_list(&a->arena, r->ired.lost, r->ired.nlost);
  a->ired_dummy = arena_list(&a->arena, r->ired.dummy, r->ired.ndummy);
  if (r->opts.verbose) {
    bg_strbuf sb = {0};
    bg_indexred_text(&r->ired, "bgdraw:   ", &sb);
    fputs(bg_sb_str(&sb), stderr);
    bg_sb_free(&sb);
  }
}

/* The system a simulation integrates: the index reduction's when there is one. */
static bg_eqsys *sim_system(run *r) {
  return r->ired_done && r->ired.status == 1 ? r->ired.reduced : r->eqsys;
}

static int wants_format(const bg_cli_opts *o, const char *format) {
  for (int i = 0; i < o->nout; i++)
    if (!strcmp(o->out[i].format, format)) return 1;
  return 0;
}

/* Only what some output shows is computed: a diagram alone needs neither
 * equations nor the index, so large models draw quickly. */
static int wants_index(const bg_cli_opts *o) {
  return o->check || o->report || wants_format(o, "json");
}

static int wants_equations(const bg_cli_opts *o) {
  return wants_index(o) || o->equations || o->simulate || o->plot || wants_format(o, "tex") ||
         wants_format(o, "c") || wants_format(o, "csv") || wants_format(o, "py") ||
         wants_format(o, "m") || wants_format(o, "mo") ||
         wants_format(o, "fmu");
}

static int wants_simulation(const bg_cli_opts *o) {
  return o->simulate || o->plot || wants_format(o, "csv");
}

/* Runs the simulation; prints the refusal or failure. EXIT_SIM on failure
 * (partial results are still written), EXIT_OK otherwise. */
static int simulate(run *r) {
  bg_sim_opts so = {0};
  so.log = &r->log;
  so.eqs_problem = r->eqsys_problem;
  int rc = bg_simulate(r->model, &r->analysis, sim_system(r), &so, &r->sim);
  r->sim_status = rc;
  r->simulated = 1;
  if (r->sim.ic_report && !r->opts.quiet && !r->opts.verbose) /* -v printed it already */
    fprintf(stderr, "bgdraw: note: initial values made consistent: %s\n", r->sim.ic_report);
  bg_strbuf w = {0};
  if (bg_simresult_row_warning(&r->sim, &w)) fprintf(stderr, "bgdraw: warning: %s\n", bg_sb_str(&w));
  bg_sb_clear(&w);
  if (rc == 0 && r->opts.verify) {
    bg_sim_verify(r->model, &r->analysis, sim_system(r), &so, &r->sim);
    if (bg_sim_verify_text(&r->sim, &w) && !r->opts.quiet) fprintf(stderr, "bgdraw: %s\n", bg_sb_str(&w));
  }
  bg_sb_free(&w);
  if (rc == 0) {
    if (r->opts.verbose && r->sim.solver_reason)
      fprintf(stderr, "bgdraw: solver %s: %s\n", r->sim.solver_used, r->sim.solver_reason);
    return EXIT_OK;
  }
  const char *why = r->sim.message ? r->sim.message : r->eqsys_problem;
  if (rc == 1) fprintf(stderr, "bgdraw: simulation refused: %s\n", why ? why : "unknown reason");
  else fprintf(stderr, "bgdraw: %s\n", why ? why : "simulation failed"); /* "simulation failed at t = ..." */
  return EXIT_SIM;
}

static int print_check(run *r) {
  bg_strbuf sb = {0};
  bg_model_summary(r->model, &sb);
  bg_sb_putc(&sb, '\n');
  bg_analysis_summary(r->model, &r->analysis, &sb);
  if (r->index_done) {
    bg_sb_puts(&sb, "numeric index: ");
    if (r->index.index >= 0) bg_sb_printf(&sb, "%d", r->index.index);
    else bg_sb_puts(&sb, r->index.index == BG_INDEX_SINGULAR ? "singular" : "not computed");
    if (r->index.message) bg_sb_printf(&sb, " (%s)", r->index.message);
    bg_sb_putc(&sb, '\n');
  } else if (r->eqsys_problem) {
    bg_sb_printf(&sb, "equations: %s\n", r->eqsys_problem);
  }
  if (r->ired_done) {
    bg_sb_puts(&sb, "index reduction:\n");
    bg_indexred_text(&r->ired, "  ", &sb);
  }
  int rc = cli_write_stdout(&sb);
  bg_sb_free(&sb);
  return rc;
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
  bg_transform_input in = {o->transform, r->src, r->srclen, r->dg.file, r->ast, r->model,
                           &r->analysis, o->sets, o->nsets};
  char *why = NULL;
  if (o->verbose) fprintf(stderr, "bgdraw: transformation %s\n", o->transform);
  if (bg_transform_apply(&in, &r->tx, &why) != 0) {
    fprintf(stderr, "bgdraw: error: --transform %s does not apply to %s: %s\n", o->transform,
            r->model->name, why);
    free(why);
    return EXIT_SIM;
  }
  r->tx_done = 1;
  if (o->verbose) fprintf(stderr, "bgdraw: %s\n", r->tx.summary);
  return EXIT_OK;
}

/* Everything after the analysis: simulation, outputs, plot, report. */
static int write_all(run *r) {
  const bg_cli_opts *o = &r->opts;
  if (o->check) return print_check(r);
  if (o->equations && o->nout == 0 && !o->plot && !o->report && !o->simulate)
    return cli_write_equations(r, NULL, o->equations);
  if (cli_linear_only(o)) return cli_write_linear(r);
  int wantsim = wants_simulation(o);
  int simrc = wantsim || (o->report && r->model->sim.present) ? simulate(r) : EXIT_OK;
  int refused = simrc && !r->sim.nrows;
  if (!wantsim && r->sim_status == 1) simrc = refused = 0; /* the report says why */
  int rc = EXIT_OK;
  if (o->equations) rc = cli_write_equations(r, NULL, o->equations);
  if (!rc) rc = cli_write_outputs(r);
  if (!rc && o->plot) rc = cli_write_plot(r);
  if (!rc && o->report) rc = cli_write_report(r);
  if (!rc) rc = cli_write_linear(r);
  if (!rc) rc = refused ? EXIT_SIM : simrc;
  return rc;
}

/* The engine's messages on stderr: progress with -v, the rest unless -q. */
static void log_stderr(void *ctx, bg_log_level level, const char *msg) {
  const bg_cli_opts *o = ctx;
  if (level >= BG_LOG_INFO && o->quiet) return;
  fprintf(stderr, "bgdraw: %s%s\n",
          level == BG_LOG_WARNING ? "warning: " : level == BG_LOG_NOTE ? "note: " : "", msg);
}

int main(int argc, char **argv) {
  run r;
  memset(&r, 0, sizeof r);
  r.log = (bg_log){log_stderr, &r.opts, 0};
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
  r.log.verbose = r.opts.verbose;
  if (cli_render_options(&r) != 0) {
    bg_cli_free(&r.opts);
    return EXIT_USAGE;
  }
  int rc = load_model(&r);
  if (!r.opts.quiet || rc) bg_diags_print(&r.dg, stderr);
  if (rc) {
    run_free(&r);
    return EXIT_MODEL;
  }
  char defpath[1024];
  if (!r.opts.check && r.opts.nout == 0 && !r.opts.simulate && !r.opts.equations &&
      !r.opts.plot && !r.opts.report && !cli_linear_asked(&r.opts))
    cli_default_output(&r, defpath, sizeof defpath);
  if ((rc = cli_check_outputs(&r)) != 0) {
    run_free(&r);
    return rc;
  }
  analyse(&r);
  if (r.opts.transform && (rc = transform(&r)) != 0) {
    run_free(&r);
    return rc;
  }
  if (wants_equations(&r.opts)) derive_equations(&r);
  /* a simulation needs it too: a numeric index above 1 refuses the run */
  if (wants_index(&r.opts) || wants_simulation(&r.opts)) numeric_index(&r);
  if (wants_index(&r.opts) || wants_simulation(&r.opts) || (r.opts.report && r.model->sim.present))
    index_reduction(&r);
  if (cli_wants_linear(&r)) cli_linearise(&r);
  rc = write_all(&r);
  if ((rc == EXIT_OK || rc == EXIT_SIM) && r.opts.depfile) {
    int drc = cli_write_depfile(&r);
    if (drc) rc = drc;
  }
  run_free(&r);
  return rc;
}
