/* SPDX-License-Identifier: BSD-3-Clause */
/* One invocation of the bgdraw command line: its options, the engine's run
 * (src/run) and the output writers over it (src/output). main.c decides the
 * outputs and asks for them; cli_outputs.c puts their bytes into files or
 * standard output. Only these CLI files touch argv, output paths and exit
 * codes. */
#ifndef BG_CLI_RUN_H
#define BG_CLI_RUN_H
#include <stddef.h>

#include "base/strbuf.h"
#include "cli/cli_opts.h"
#include "equations/equations.h"
#include "output/output.h"
#include "run/run.h"
#include "transform/transform.h"

enum { EXIT_OK = 0, EXIT_MODEL = 1, EXIT_USAGE = 2, EXIT_SIM = 3, EXIT_WRITE = 4 };

/* Everything one invocation holds; freed by main.c. */
typedef struct run {
  bg_cli_opts opts;
  bg_run *R;              /* the engine's run */
  bg_output out;          /* the writers over it */
  bg_render_opts ropts;   /* diagram options from the command line */
  int max_list;           /* --max-list; 0: the default caps */
  int max_errors;         /* --max-errors; BG_DIAG_MAX_ERRORS by default, 0: no limit */
  bg_transform_result tx; /* --transform: the new model (main.c) */
  int tx_done;
} run;

/* The running executable's folder (from /proc/self/exe) into buf; -1 when
 * unknown. Styles and the render module are found relative to it. */
int cli_exe_dir(char *buf, size_t n);
/* The installed component library's folder (share/bgdraw/lib beside the
 * executable, or in the build tree); NULL when there is none. */
const char *cli_lib_dir(void);
/* Diagram options from the command line (and --max-list); -1 after a
 * usage message. */
int cli_render_options(run *r);
/* EXIT_USAGE (with a message) when an output is one of the run's inputs. */
int cli_check_outputs(run *r);
/* The default output when no -o is given: the SVG on standard output when it
 * is not a terminal, else out/<model>.svg (buf holds the path). */
void cli_default_output(run *r, char *buf, size_t n);
/* path's text: atomically to a file, or in place to stdout (BG_CLI_STDOUT);
 * EXIT_WRITE after a message when that failed. */
int cli_write_text(const char *path, const bg_strbuf *sb);
/* Output kind (a row of src/output's table) with form into path (NULL or
 * BG_CLI_STDOUT: standard output): its exit status, messages printed. */
int cli_write_output(run *r, const char *kind, const char *form, const char *path);
/* Every -o in order; the first failure's exit status, or EXIT_OK. */
int cli_write_outputs(run *r);
/* -M/--depfile: the make rule of the files this run read (cli_depfile.c). */
int cli_write_depfile(run *r);
/* --linear/--bode/--nyquist/--step asked for; and nothing else (no default diagram). */
int cli_linear_asked(const bg_cli_opts *o);
int cli_linear_only(const bg_cli_opts *o);
/* The linear analysis' outputs: --linear FORM on stdout, then the plots. */
int cli_write_linear(run *r);
#endif
