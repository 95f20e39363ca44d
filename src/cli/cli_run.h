/* One run of the bgdraw command line: what it holds, and the writers of its
 * outputs (cli_outputs.c). main.c runs the stages; only these CLI files
 * touch argv, output paths and exit codes. */
#ifndef BG_CLI_RUN_H
#define BG_CLI_RUN_H
#include <stddef.h>

#include "causality/causality.h"
#include "cli/cli_opts.h"
#include "base/diag.h"
#include "base/strbuf.h"
#include "equations/equations.h"
#include "model/model.h"
#include "lang/lang.h"
#include "diagram/render.h"
#include "simulate/simulate.h"
#include "linear/linear.h"
#include "transform/transform.h"

enum { EXIT_OK = 0, EXIT_MODEL = 1, EXIT_USAGE = 2, EXIT_SIM = 3, EXIT_WRITE = 4 };

/* Above this many unknowns the dense index computation (SVDs and a
 * generalised eigenvalue problem, cubic in the unknowns: about 1 s at 500 in
 * a Release build, 5 s at 1000) is skipped; docs/cli.md. */
enum { INDEX_MAX_UNKNOWNS = 500 };

/* Everything one run holds; freed by run_free. */
typedef struct run {
  bg_cli_opts opts;
  bg_log log; /* the engine's messages to stderr (main.c) */
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
  bg_indexred ired;     /* index reduction, tried when the index is above 1 */
  int ired_done;
  bg_simresult sim;
  int sim_status; /* bg_simulate: 0 ok, 1 refused, 2 failed */
  int simulated;
  bg_render_opts ropts;
  int max_list; /* --max-list; 0: the default caps */
  int max_errors; /* --max-errors; BG_DIAG_MAX_ERRORS by default, 0: no limit */
  bg_diagram *diagram; /* laid out once, on the first diagram output */
  bg_linear lin;       /* the linear analysis (cli_linear.c) */
  int lin_done;
  bg_transform_result tx; /* --transform: the new model (main.c) */
  int tx_done;
} run;

/* The running executable's folder (from /proc/self/exe) into buf; -1 when
 * unknown. Styles and the render module are found relative to it. */
int cli_exe_dir(char *buf, size_t n);
/* Diagram options from the command line (and --max-list); -1 after a
 * usage message. */
int cli_render_options(run *r);
/* EXIT_USAGE (with a message) when an output is one of the run's inputs. */
int cli_check_outputs(run *r);
/* Text to stdout, flushed; EXIT_WRITE (with a message) on a write error. */
int cli_write_stdout(const bg_strbuf *sb);
/* The default output when no -o is given: out/<model>.svg (buf holds the path). */
void cli_default_output(run *r, char *buf, size_t n);
/* Every -o in order; the first failure's exit status, or EXIT_OK. */
int cli_write_outputs(run *r);
/* --equations FORM to path, or to stdout when path is NULL. */
int cli_write_equations(run *r, const char *path, const char *form);
/* path's text: atomically to a file, or in place to stdout (BG_CLI_STDOUT);
 * EXIT_WRITE after a message when that failed. */
int cli_write_text(const char *path, const bg_strbuf *sb);
/* -M/--depfile: the make rule of the files this run read (cli_depfile.c). */
int cli_write_depfile(run *r);
/* Exports (cli_export.c): -o NAME.c (and NAME.h), .py, .m, or
 * format "c" to stdout when path is NULL (--equations c). */
int cli_write_export(run *r, const char *path, const char *format);
/* -o NAME.fmu (cli_fmu.c): the FMI 2.0 Model Exchange archive of the export
 * build s, model identifier prefix; EXIT_MODEL for a DAE, EXIT_WRITE when the
 * compiler is missing or fails. */
int cli_write_fmu(const bg_eqsys *s, const char *prefix, const char *path);
/* --plot FILE and --report FILE.pdf. */
int cli_write_plot(run *r);
int cli_write_report(run *r);
/* The linear analysis (cli_linear.c): wanted by the options or the model's
 * `linearise` statement; computed; --linear FORM on stdout, --bode,
 * --nyquist, --step; .m and .py outputs. EXIT_SIM when it was asked for and
 * refused. */
int cli_wants_linear(const run *r);
int cli_linear_asked(const bg_cli_opts *o); /* --linear, --bode, ..., .m, .py */
int cli_linear_only(const bg_cli_opts *o);  /* and nothing else: no default diagram */
void cli_linearise(run *r);
int cli_write_linear(run *r);
#endif
