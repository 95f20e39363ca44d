/* SPDX-License-Identifier: BSD-3-Clause */
/* The command line's parameter studies (docs/study.md, src/cli/cli_study.c):
 * --sweep, --vary, --monte-carlo, --seed, --collect, -j, --study, --family,
 * --root-locus, --bode-family,
 * --runs, --split with --job-list or --slurm, --merge. */
#ifndef BG_CLI_STUDY_H
#define BG_CLI_STUDY_H
#include "cli/cli_run.h"
#include "study/study.h"

enum { CLI_STUDY_MAX_OUT = 16 };

typedef struct cli_study {
  bg_study_spec spec;
  /* kind: BG_STUDY_PLOT_* for a plot (render/plot/plot.h), -1 for a table */
  struct { const char *path; int kind; } out[CLI_STUDY_MAX_OUT];
  int nout, curves, jobs;
  int locus, bode;       /* --root-locus, --bode-family given */
  int cli_params, cli_collect; /* --sweep/--vary and --collect given (else the model's) */
  long first, count;     /* --runs */
  long parts;            /* --split N:DIR */
  const char *partdir;
} cli_study;

/* Whether any study option was given. */
int cli_study_asked(const bg_cli_opts *o);
/* The study's options checked and parsed; 0, or -1 after a usage message. */
int cli_study_parse(const bg_cli_opts *o, cli_study *cs);
/* Runs the study of the loaded model (or writes its jobs, or merges its
 * parts) and writes its outputs; the exit status. */
int cli_study_run(run *r, cli_study *cs);
void cli_study_free(cli_study *cs);
#endif
