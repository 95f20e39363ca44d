/* SPDX-License-Identifier: BSD-3-Clause */
/* Command-line options of bgdraw (docs/cli.md). Parsing only; main.c acts on them. */
#ifndef BG_CLI_OPTS_H
#define BG_CLI_OPTS_H
#include <stdio.h>

#include "model/model.h"

enum { BG_MAX_OUTPUTS = 32, BG_MAX_SETS = 64, BG_MAX_COLLAPSE = 256, BG_MAX_STUDY_WORDS = 96 };

/* The path of an output that goes to standard output ("-o -", or -T with no -o). */
#define BG_CLI_STDOUT "-"

typedef struct bg_cli_output {
  const char *path;   /* BG_CLI_STDOUT for standard output */
  const char *format; /* svg pdf png json dot tex c csv m py bg */
} bg_cli_output;

typedef struct bg_cli_opts {
  const char *model_path;   /* "-": standard input */
  bg_cli_output out[BG_MAX_OUTPUTS];
  int nout;
  const char *force_format; /* -T */
  const char *causality;    /* --causality, NULL = model's or scap */
  const char *show;         /* --show */
  const char *highlight;    /* --highlight */
  const char *style;        /* --style */
  const char *layout;       /* --layout */
  const char *report;       /* --report FILE.pdf */
  const char *plot;         /* --plot FILE */
  const char *equations;    /* --equations FORM */
  const char *max_list;     /* --max-list N: listing cap of paths and loops */
  const char *max_errors;   /* --max-errors N: diagnostics' error limit (0: none) */
  const char *linear;       /* --linear FORM: text | latex | json (docs/linear.md) */
  const char *bode, *nyquist, *step; /* --bode/--nyquist/--step FILE (svg pdf png) */
  const char *depfile;      /* -M/--depfile FILE: make rule of the files read */
  const char *diag_format;  /* --diagnostics-format: "text" (default) or "json" */
  const char *color;        /* --color: "auto" (default), "always", "never" */
  const char *prefix;       /* --prefix NAME: symbol prefix of exported C */
  const char *transform;    /* --transform NAME: the model rewritten (docs/transform.md) */
  const char *stdin_name;   /* --stdin-name FILE: standard input's name (docs/cli.md) */
  int simulate, verify, check, quiet, verbose, help, version;
  int import;               /* --import: the model is another tool's; .bg output is it as .bg text */
  unsigned warn_off;        /* -Wno-NAME: bit per bg_warning */
  int werror;               /* -Werror */
  bg_param_override sets[BG_MAX_SETS];
  int nsets;
  const char *collapse[BG_MAX_COLLAPSE]; /* --collapse NAME (repeatable) or all */
  int ncollapse;
  /* a parameter study (docs/study.md; src/cli/cli_study.c reads them): --sweep,
   * --vary, --collect, --study and --family in the order given */
  int study_opt[BG_MAX_STUDY_WORDS];
  const char *study_arg[BG_MAX_STUDY_WORDS];
  int nstudy;
  const char *draws, *seed, *jobs, *runs; /* --monte-carlo N, --seed S, -j N, --runs A:B */
  const char *split, *joblist, *slurm, *merge; /* --split N:DIR, --job-list FILE, --slurm FILE,
                                                     --merge DIR */
} bg_cli_opts;

/* Parses argv into o (GNU conventions: --opt=value, --, -Tsvg, -qv; options
 * and the model in any order). On a usage error prints "bgdraw: error: ..."
 * with a hint to stderr and returns -1 (the caller exits 2). */
int bg_cli_parse(int argc, char **argv, bg_cli_opts *o);
void bg_cli_print_help(FILE *out);
/* Frees what parsing allocated (the --set names). */
void bg_cli_free(bg_cli_opts *o);
/* 1 when path names standard output. */
int bg_cli_is_stdout(const char *path);
#endif
