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
#include "eqprint.h"
#include "eqsym.h"
#include "eqsys.h"
#include "index.h"
#include "fileio.h"
#include "json.h"
#include "json_sim.h"
#include "model.h"
#include "parse.h"
#include "paths.h"
#include "plot.h"
#include "render.h"
#include "report.h"
#include "simulate.h"
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
  bg_eqsys *eqsys;      /* NULL when the equations could not be formed */
  char *eqsys_problem;  /* why not, in words (owned); nullable */
  bg_index_result index;
  int index_done;
  bg_simresult sim;
  int sim_status; /* bg_simulate: 0 ok, 1 refused, 2 failed */
  int simulated;
  bg_render_opts ropts;
  int max_list; /* --max-list; 0: the default caps */
  bg_diagram *diagram; /* laid out once, on the first diagram output */
} run;

static void run_free(run *r) {
  if (r->simulated) bg_simresult_free(&r->sim);
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
  bg_analysis_limits lim = {r->max_list, r->max_list};
  bg_analysis_run(r->model, &r->analysis, &lim);
}

/* Above this many unknowns the dense index computation (SVDs and a
 * generalised eigenvalue problem, cubic in the unknowns: about 1 s at 500 in
 * a Release build, 5 s at 1000) is skipped; docs/cli.md. */
enum { INDEX_MAX_UNKNOWNS = 500 };

/* The equations. A model whose equations cannot be formed is not an error
 * here: the reason is kept for the outputs that need equations. */
static void derive_equations(run *r) {
  if (r->opts.verbose) fprintf(stderr, "bgdraw: equations\n");
  bg_diags eqd;
  bg_diags_init(&eqd, r->opts.model_path, r->src, r->srclen);
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
         wants_format(o, "c") || wants_format(o, "csv");
}

static int wants_simulation(const bg_cli_opts *o) {
  return o->simulate || o->plot || wants_format(o, "csv");
}

/* Runs the simulation; prints the refusal or failure. EXIT_SIM on failure
 * (partial results are still written), EXIT_OK otherwise. */
static int simulate(run *r) {
  bg_sim_opts so = {0};
  so.verbose = r->opts.verbose;
  so.eqs_problem = r->eqsys_problem;
  int rc = bg_simulate(r->model, &r->analysis, r->eqsys, &so, &r->sim);
  r->sim_status = rc;
  r->simulated = 1;
  if (r->sim.ic_report && !r->opts.quiet && !r->opts.verbose) /* -v printed it already */
    fprintf(stderr, "bgdraw: note: initial values made consistent: %s\n", r->sim.ic_report);
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
  if (r->simulated) bg_json_append_simulation(&sb, r->model, &r->sim, r->sim_status);
  int rc = write_text(path, &sb);
  bg_sb_free(&sb);
  return rc;
}

/* Diagram options from the command line; -1 on a usage error. */
static int render_options(run *r) {
  const bg_cli_opts *o = &r->opts;
  bg_render_opts *ro = &r->ropts;
  ro->show = BG_SHOW_DEFAULT;
  if (o->show && bg_show_parse(o->show, &ro->show) != 0) {
    fprintf(stderr, "bgdraw: error: unknown layer in --show '%s' (layers: strokes, numbers, "
                    "paths, loops, conflicts, signals, labels, legend; or all, none)\n", o->show);
    return -1;
  }
  if (o->highlight && bg_highlight_parse(o->highlight, &ro->highlight_kind,
                                         &ro->highlight_index) != 0) {
    fprintf(stderr, "bgdraw: error: --highlight takes path:K, loop:K or conflict:K, not '%s'\n",
            o->highlight);
    return -1;
  }
  if (o->max_list) {
    char *end;
    long n = strtol(o->max_list, &end, 10);
    if (end == o->max_list || *end || n < 1 || n > 100000000) {
      fprintf(stderr, "bgdraw: error: --max-list takes a positive whole number, not '%s'\n",
              o->max_list);
      return -1;
    }
    r->max_list = (int)n;
  }
  ro->style = o->style;
  ro->style_dir = getenv("BGDRAW_STYLE_DIR") ? NULL : BG_STYLE_DIR;
  ro->layout = o->layout;
  ro->verbose = o->verbose;
  return 0;
}

static int write_diagram(run *r, const bg_cli_output *out) {
  if (!r->diagram) {
    r->diagram = bg_diagram_build(r->model, &r->analysis, &r->ropts, &r->dg);
    if (!r->diagram) {
      bg_diags_print(&r->dg, stderr);
      return EXIT_USAGE;
    }
  }
  int rc = bg_diagram_write(r->diagram, out->path, out->format, &r->dg);
  if (rc == BG_RENDER_OK) return EXIT_OK;
  bg_diags_print(&r->dg, stderr);
  return rc == BG_RENDER_EWRITE ? EXIT_WRITE : EXIT_USAGE;
}

static int write_equations(run *r, const char *path, const char *form) {
  if (!r->eqsys) {
    fprintf(stderr, "bgdraw: error: no equations for '%s': %s\n", path ? path : "stdout",
            r->eqsys_problem ? r->eqsys_problem : "unknown reason");
    return EXIT_MODEL;
  }
  bg_strbuf sb = {0};
  bg_eqprint(r->eqsys, form, &sb);
  int rc = path ? write_text(path, &sb) : (fputs(bg_sb_str(&sb), stdout), EXIT_OK);
  bg_sb_free(&sb);
  return rc;
}

static int write_csv(run *r, const char *path) {
  if (!r->simulated || !r->sim.nrows) return EXIT_OK; /* refused: nothing to write */
  bg_strbuf sb = {0};
  bg_csv_write(&r->sim, &sb);
  int rc = write_text(path, &sb);
  bg_sb_free(&sb);
  return rc;
}

static int is_diagram_format(const char *f) {
  return !strcmp(f, "svg") || !strcmp(f, "pdf") || !strcmp(f, "png") || !strcmp(f, "dot");
}

static int write_one(run *r, const bg_cli_output *out) {
  if (r->opts.verbose) fprintf(stderr, "bgdraw: writing %s\n", out->path);
  if (!strcmp(out->format, "json")) return write_json(r, out->path);
  if (is_diagram_format(out->format)) return write_diagram(r, out);
  if (!strcmp(out->format, "tex")) return write_equations(r, out->path, "latex");
  if (!strcmp(out->format, "c")) return write_equations(r, out->path, "c");
  if (!strcmp(out->format, "csv")) return write_csv(r, out->path);
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

/* --plot FILE: the simulation plots, also of a partial run; none when the
 * run was refused (no rows). An unknown extension is a usage error. */
static int write_plot(run *r) {
  const char *path = r->opts.plot, *ext = bg_path_ext(path);
  if (strcmp(ext, "svg") && strcmp(ext, "pdf") && strcmp(ext, "png")) {
    fprintf(stderr, "bgdraw: error: --plot writes svg, pdf or png, not '%s'\n", path);
    return EXIT_USAGE;
  }
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
static int write_report(run *r) {
  char skipped[160] = "";
  if (r->eqsys && !r->index_done)
    snprintf(skipped, sizeof skipped, "%d unknowns, more than the dense algorithm's limit of %d",
             bg_eqsys_n(r->eqsys), INDEX_MAX_UNKNOWNS);
  bg_report_input in = {r->model, &r->analysis, r->eqsys, r->eqsys_problem,
                        r->index_done ? &r->index : NULL, skipped[0] ? skipped : NULL,
                        r->simulated ? &r->sim : NULL, r->sim_status, &r->ropts};
  bg_diags dg;
  bg_diags_init(&dg, "bgdraw", NULL, 0);
  int rc = bg_report_write(&in, r->opts.report, &dg);
  if (rc != BG_RENDER_OK) bg_diags_print(&dg, stderr);
  bg_diags_free(&dg);
  return rc == BG_RENDER_OK ? EXIT_OK : rc == BG_RENDER_EWRITE ? EXIT_WRITE : EXIT_USAGE;
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
  if (render_options(&r) != 0) {
    bg_cli_free(&r.opts);
    return EXIT_USAGE;
  }
  if (r.opts.report && strcmp(bg_path_ext(r.opts.report), "pdf")) {
    fprintf(stderr, "bgdraw: error: --report writes a PDF: give a .pdf file, not '%s'\n", r.opts.report);
    bg_cli_free(&r.opts);
    return EXIT_USAGE;
  }
  int rc = load_model(&r);
  if (!r.opts.quiet || rc) bg_diags_print(&r.dg, stderr);
  if (rc) {
    run_free(&r);
    return EXIT_MODEL;
  }
  analyse(&r);
  if (wants_equations(&r.opts)) derive_equations(&r);
  if (wants_index(&r.opts)) numeric_index(&r);
  char defpath[1024];
  if (r.opts.check) rc = print_check(&r);
  else if (r.opts.equations && r.opts.nout == 0) rc = write_equations(&r, NULL, r.opts.equations);
  else {
    int wantsim = wants_simulation(&r.opts);
    int simrc = wantsim || (r.opts.report && r.model->sim.present) ? simulate(&r) : EXIT_OK;
    int refused = simrc && !r.sim.nrows;
    if (!wantsim && r.sim_status == 1) simrc = refused = 0; /* the report says why */
    if (r.opts.equations) rc = write_equations(&r, NULL, r.opts.equations);
    if (r.opts.nout == 0 && !r.opts.simulate && !r.opts.equations && !r.opts.plot && !r.opts.report)
      default_output(&r, defpath, sizeof defpath);
    if (!rc) rc = write_outputs(&r);
    if (!rc && r.opts.plot) rc = write_plot(&r);
    if (!rc && r.opts.report) rc = write_report(&r);
    if (!rc) rc = refused ? EXIT_SIM : simrc;
  }
  run_free(&r);
  return rc;
}
