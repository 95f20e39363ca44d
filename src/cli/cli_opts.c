/* SPDX-License-Identifier: BSD-3-Clause */
/* Command-line parsing for bgdraw with glibc's getopt_long, so the usual GNU
 * habits work (--opt=value, --, attached short values, bundled flags,
 * unambiguous prefixes of long options). Usage errors name the fix; the
 * checks of how options combine are in cli_usage.c. */
#define _GNU_SOURCE /* getopt_long */
#include <getopt.h>
#include <stddef.h>
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/fileio.h"
#include "base/strbuf.h"
#include "cli/cli_opts.h"
#include "output/output.h"
#include "cli/cli_usage.h"

enum {
  OPT_CAUSALITY = 256, OPT_SHOW, OPT_HIGHLIGHT, OPT_STYLE, OPT_LAYOUT, OPT_REPORT, OPT_PLOT,
  OPT_EQUATIONS, OPT_LINEAR, OPT_BODE, OPT_NYQUIST, OPT_STEP, OPT_MAX_LIST, OPT_MAX_ERRORS, OPT_SET, OPT_SIMULATE, OPT_VERIFY, OPT_CHECK, OPT_DIAG_FORMAT, OPT_COLOR,
  OPT_PREFIX, OPT_TRANSFORM, OPT_COLLAPSE, OPT_STDIN_NAME, OPT_IMPORT,
  /* the study's words (cli_study.h): kept in order for cli_study.c */
  OPT_SWEEP, OPT_VARY, OPT_COLLECT, OPT_STUDY, OPT_FAMILY, OPT_ROOT_LOCUS, OPT_BODE_FAMILY, OPT_MONTE_CARLO, OPT_SEED, OPT_RUNS,
  OPT_JOB_LIST, OPT_SLURM, OPT_MERGE, OPT_SPLIT
};

static const char short_opts[] = ":o:T:M:K:W:j:qvhV";

static const struct option long_opts[] = {
    {"output", required_argument, NULL, 'o'},
    {"format", required_argument, NULL, 'T'},
    {"depfile", required_argument, NULL, 'M'},
    {"causality", required_argument, NULL, OPT_CAUSALITY},
    {"show", required_argument, NULL, OPT_SHOW},
    {"highlight", required_argument, NULL, OPT_HIGHLIGHT},
    {"style", required_argument, NULL, OPT_STYLE},
    {"layout", required_argument, NULL, OPT_LAYOUT},
    {"report", required_argument, NULL, OPT_REPORT},
    {"plot", required_argument, NULL, OPT_PLOT},
    {"equations", required_argument, NULL, OPT_EQUATIONS},
    {"linear", required_argument, NULL, OPT_LINEAR},
    {"bode", required_argument, NULL, OPT_BODE},
    {"nyquist", required_argument, NULL, OPT_NYQUIST},
    {"step", required_argument, NULL, OPT_STEP},
    {"max-list", required_argument, NULL, OPT_MAX_LIST},
    {"max-errors", required_argument, NULL, OPT_MAX_ERRORS},
    {"set", required_argument, NULL, OPT_SET},
    {"diagnostics-format", required_argument, NULL, OPT_DIAG_FORMAT},
    {"color", required_argument, NULL, OPT_COLOR},
    {"prefix", required_argument, NULL, OPT_PREFIX},
    {"transform", required_argument, NULL, OPT_TRANSFORM},
    {"collapse", required_argument, NULL, OPT_COLLAPSE},
    {"stdin-name", required_argument, NULL, OPT_STDIN_NAME},
    {"sweep", required_argument, NULL, OPT_SWEEP},
    {"vary", required_argument, NULL, OPT_VARY},
    {"collect", required_argument, NULL, OPT_COLLECT},
    {"study", required_argument, NULL, OPT_STUDY},
    {"family", required_argument, NULL, OPT_FAMILY},
    {"root-locus", required_argument, NULL, OPT_ROOT_LOCUS},
    {"bode-family", required_argument, NULL, OPT_BODE_FAMILY},
    {"monte-carlo", required_argument, NULL, OPT_MONTE_CARLO},
    {"seed", required_argument, NULL, OPT_SEED},
    {"jobs", required_argument, NULL, 'j'},
    {"runs", required_argument, NULL, OPT_RUNS},
    {"job-list", required_argument, NULL, OPT_JOB_LIST},
    {"slurm", required_argument, NULL, OPT_SLURM},
    {"merge", required_argument, NULL, OPT_MERGE},
    {"split", required_argument, NULL, OPT_SPLIT},
    {"simulate", no_argument, NULL, OPT_SIMULATE},
    {"verify", no_argument, NULL, OPT_VERIFY},
    {"check", no_argument, NULL, OPT_CHECK},
    {"import", no_argument, NULL, OPT_IMPORT},
    {"quiet", no_argument, NULL, 'q'},
    {"verbose", no_argument, NULL, 'v'},
    {"help", no_argument, NULL, 'h'},
    {"version", no_argument, NULL, 'V'},
    {NULL, 0, NULL, 0},
};

/* Where each valued long option goes (a const char * in bg_cli_opts). */
static const struct {
  int val;
  size_t offset;
} valued[] = {
    {OPT_CAUSALITY, offsetof(bg_cli_opts, causality)},
    {OPT_SHOW, offsetof(bg_cli_opts, show)},
    {OPT_HIGHLIGHT, offsetof(bg_cli_opts, highlight)},
    {OPT_STYLE, offsetof(bg_cli_opts, style)},
    {OPT_LAYOUT, offsetof(bg_cli_opts, layout)},
    {OPT_REPORT, offsetof(bg_cli_opts, report)},
    {OPT_PLOT, offsetof(bg_cli_opts, plot)},
    {OPT_EQUATIONS, offsetof(bg_cli_opts, equations)},
    {OPT_LINEAR, offsetof(bg_cli_opts, linear)},
    {OPT_BODE, offsetof(bg_cli_opts, bode)},
    {OPT_NYQUIST, offsetof(bg_cli_opts, nyquist)},
    {OPT_STEP, offsetof(bg_cli_opts, step)},
    {OPT_MAX_LIST, offsetof(bg_cli_opts, max_list)},
    {OPT_MAX_ERRORS, offsetof(bg_cli_opts, max_errors)},
    {OPT_DIAG_FORMAT, offsetof(bg_cli_opts, diag_format)},
    {OPT_COLOR, offsetof(bg_cli_opts, color)},
    {OPT_PREFIX, offsetof(bg_cli_opts, prefix)},
    {OPT_TRANSFORM, offsetof(bg_cli_opts, transform)},
    {OPT_STDIN_NAME, offsetof(bg_cli_opts, stdin_name)},
    {'T', offsetof(bg_cli_opts, force_format)},
    {'M', offsetof(bg_cli_opts, depfile)},
    {'K', offsetof(bg_cli_opts, layout)}, /* dot's -K ENGINE */
    {OPT_MONTE_CARLO, offsetof(bg_cli_opts, draws)},
    {OPT_SEED, offsetof(bg_cli_opts, seed)},
    {'j', offsetof(bg_cli_opts, jobs)},
    {OPT_RUNS, offsetof(bg_cli_opts, runs)},
    {OPT_JOB_LIST, offsetof(bg_cli_opts, joblist)},
    {OPT_SLURM, offsetof(bg_cli_opts, slurm)},
    {OPT_MERGE, offsetof(bg_cli_opts, merge)},
    {OPT_SPLIT, offsetof(bg_cli_opts, split)},
};



/* The closest option name to what the user typed (without "=value"). */
static const char *closest_option(const char *arg, char *buf, size_t n) {
  static const char shorts[] = "oTMjqvhV";
  char typed[64];
  snprintf(typed, sizeof typed, "%s", arg);
  int bestd = 4;
  buf[0] = '\0';
  for (int i = 0; long_opts[i].name; i++) {
    char cand[64];
    snprintf(cand, sizeof cand, "--%s", long_opts[i].name);
    int d = bg_edit_distance(typed, cand);
    if (d < bestd) bestd = d, snprintf(buf, n, "%s", cand);
  }
  for (int i = 0; shorts[i] && strlen(typed) <= 3; i++) {
    char cand[3] = {'-', shorts[i], 0};
    int d = bg_edit_distance(typed, cand);
    if (d < bestd) bestd = d, snprintf(buf, n, "%s", cand);
  }
  return buf[0] ? buf : NULL;
}

/* An unknown short option -x: the short option of the other case (-t: -T),
 * else the long options that begin with its letter (-c: --check,
 * --causality, ...); NULL when none. One letter is too little for an edit
 * distance: every short option is one edit away. */
static const char *closest_short(char c, char *buf, size_t n) {
  static const char shorts[] = "oTMKjqvhV";
  buf[0] = '\0';
  for (int i = 0; shorts[i]; i++)
    if (shorts[i] != c && tolower((unsigned char)shorts[i]) == tolower((unsigned char)c)) {
      snprintf(buf, n, "-%c", shorts[i]);
      return buf;
    }
  int k = 0;
  for (int i = 0; long_opts[i].name; i++) {
    if (long_opts[i].name[0] != tolower((unsigned char)c)) continue;
    size_t used = strlen(buf);
    snprintf(buf + used, n - used, "%s--%s", k++ ? ", " : "", long_opts[i].name);
  }
  return k ? buf : NULL;
}

static int unknown_option(char **argv, int optopt_char) {
  char typed[64], hint[200];
  if (optopt_char) snprintf(typed, sizeof typed, "-%c", optopt_char);
  else snprintf(typed, sizeof typed, "%s", argv[optind - 1]);
  typed[strcspn(typed, "=")] = '\0'; /* --stlye=print: the option is --stlye */
  const char *h = optopt_char ? closest_short((char)optopt_char, hint, sizeof hint)
                              : closest_option(typed, hint, sizeof hint);
  if (h && optopt_char && strchr(h, ','))
    return bg_cli_usage_error("unknown option '%s' (did you mean one of %s?)", typed, h);
  if (h) return bg_cli_usage_error("unknown option '%s' (did you mean '%s'?)", typed, h);
  return bg_cli_usage_error("unknown option '%s'%s", typed, "");
}

static int missing_value(char **argv, int optopt_char) {
  char typed[64];
  const char *arg = argv[optind - 1];
  if (!strncmp(arg, "--", 2)) { /* the full name, also when a prefix was typed */
    snprintf(typed, sizeof typed, "%s", arg);
    for (int i = 0; long_opts[i].name; i++)
      if (long_opts[i].val == optopt_char) snprintf(typed, sizeof typed, "--%s", long_opts[i].name);
  } else {
    snprintf(typed, sizeof typed, "-%c", optopt_char);
  }
  return bg_cli_usage_error("%s needs a value%s", typed, "");
}

static int add_output(bg_cli_opts *o, const char *path) {
  if (o->nout == BG_MAX_OUTPUTS) return bg_cli_usage_error("too many -o outputs%s%s", "", "");
  if (!path[0]) return bg_cli_usage_error("-o needs a file name (or - for stdout)%s%s", "", "");
  o->out[o->nout].path = path;
  o->out[o->nout].format = bg_cli_is_stdout(path) ? "" : bg_path_ext(path);
  o->nout++;
  return 0;
}

static int add_set(bg_cli_opts *o, const char *arg) {
  const char *eq = strchr(arg, '=');
  if (!eq || eq == arg) return bg_cli_usage_error("--set takes NAME=VALUE, not '%s'%s", arg, "");
  char *end;
  double v = strtod(eq + 1, &end);
  if (end == eq + 1 || *end)
    return bg_cli_usage_error("--set %s: '%s' is not a number", arg, eq + 1);
  if (o->nsets == BG_MAX_SETS) return bg_cli_usage_error("too many --set options%s%s", "", "");
  size_t n = (size_t)(eq - arg);
  char *name = malloc(n + 1); /* lives for the whole run */
  memcpy(name, arg, n);
  name[n] = '\0';
  o->sets[o->nsets++] = (bg_param_override){name, v};
  return 0;
}

/* Applies one option getopt_long returned; -1 on a usage error. */
/* -W NAME, -Wno-NAME, -Werror (as compilers have them; docs/cli.md, "Warnings"). */
static int take_warning(bg_cli_opts *o, const char *arg) {
  if (!strcmp(arg, "error")) return o->werror = 1, 0;
  if (!strcmp(arg, "all")) return o->warn_off = 0, 0;
  int off = !strncmp(arg, "no-", 3);
  int w = bg_warning_parse(off ? arg + 3 : arg);
  if (w < 0) {
    char names[200] = "";
    for (int i = 0; i < BG_W_COUNT; i++) {
      if (i) strncat(names, ", ", sizeof names - strlen(names) - 1);
      strncat(names, bg_warning_name(i), sizeof names - strlen(names) - 1);
    }
    return bg_cli_usage_error("unknown warning '-W%s' (the warnings: %s; -Werror, -Wall)", arg, names);
  }
  if (off) o->warn_off |= 1u << w;
  else o->warn_off &= ~(1u << w);
  return 0;
}

static int take(bg_cli_opts *o, int c, const char *arg) {
  for (size_t i = 0; i < sizeof valued / sizeof *valued; i++)
    if (valued[i].val == c) {
      *(const char **)((char *)o + valued[i].offset) = arg;
      return 0;
    }
  switch (c) {
  case 'o': return add_output(o, arg);
  case OPT_SET: return add_set(o, arg);
  case OPT_COLLAPSE:
    if (o->ncollapse == BG_MAX_COLLAPSE) return bg_cli_usage_error("too many --collapse options%s%s", "", "");
    o->collapse[o->ncollapse++] = arg;
    return 0;
  case OPT_SWEEP: case OPT_VARY: case OPT_COLLECT: case OPT_STUDY: case OPT_FAMILY:
  case OPT_ROOT_LOCUS: case OPT_BODE_FAMILY:
    if (o->nstudy == BG_MAX_STUDY_WORDS) return bg_cli_usage_error("too many study options%s%s", "", "");
    o->study_opt[o->nstudy] = c == OPT_SWEEP ? 's' : c == OPT_VARY ? 'v' : c == OPT_COLLECT ? 'c'
                            : c == OPT_STUDY ? 'o' : c == OPT_FAMILY ? 'f'
                            : c == OPT_ROOT_LOCUS ? 'l' : 'b';
    o->study_arg[o->nstudy++] = arg;
    return 0;
  case OPT_SIMULATE: o->simulate = 1; return 0;
  case OPT_IMPORT: o->import = 1; return 0;
  case OPT_VERIFY: o->verify = 1; o->simulate = 1; return 0;
  case OPT_CHECK: o->check = 1; return 0;
  case 'W': return take_warning(o, arg);
  case 'q': o->quiet = 1; return 0;
  case 'v': o->verbose = 1; return 0;
  case 'h': o->help = 1; return 0;
  case 'V': o->version = 1; return 0;
  default: BG_FATAL("getopt_long returned option %d with no handler", c);
  }
}

static int take_operands(bg_cli_opts *o, int argc, char **argv) {
  for (int i = optind; i < argc; i++) {
    if (o->model_path)
      return bg_cli_usage_error("more than one model file ('%s' and '%s')", o->model_path,
                                argv[i]);
    o->model_path = argv[i];
  }
  return 0;
}

int bg_cli_parse(int argc, char **argv, bg_cli_opts *o) {
  memset(o, 0, sizeof *o);
  opterr = 0;  /* our own messages, with hints */
  optind = 0;  /* glibc: full reinitialisation (tests parse several argv) */
  int c, longindex;
  while ((c = getopt_long(argc, argv, short_opts, long_opts, &longindex)) != -1) {
    if (c == '?') return unknown_option(argv, optopt);
    if (c == ':') return missing_value(argv, optopt);
    if (take(o, c, optarg) != 0) return -1;
  }
  if (take_operands(o, argc, argv) != 0) return -1;
  if (o->help || o->version) return 0;
  return bg_cli_check_usage(o);
}

void bg_cli_print_help(FILE *out) {
  fputs(
      "usage: bgdraw [options] MODEL.bg [-o OUT]...\n"
      "       bgdraw -T FMT [options] - < MODEL.bg > OUT\n"
      "\n"
      "Assigns causality to a bond graph model, analyses the causal pattern, and\n"
      "draws it. With no -o the diagram goes to out/<model>.svg; MODEL '-' reads\n"
      "standard input.\n"
      "\n"
      "outputs (-o FILE, repeatable; the format follows the extension):\n", out);
  for (const bg_output_kind *k = bg_output_kinds; k->name; k++) /* src/output's table */
    if (k->flags & BG_OUTK_EXT) fprintf(out, "  .%-5s %s\n", k->name, k->what);
  fputs(
      "  -T, --format FMT    the format of -o FILE without an extension, or of\n"
      "                      -o - (stdout); -T alone writes to stdout\n"
      "  -M, --depfile FILE  make rule: the outputs depend on every file read (the\n"
      "                      model, the files it uses, style, table files)\n"
      "\n"
      "options:\n"
      "  --causality METHOD  scap (default) | relaxed | vandijk | lagrange\n"
      "  --show LAYERS       strokes,numbers,paths,loops,conflicts,signals,labels,legend,\n"
      "                      variables | all | none; a list of overlays only (paths,\n"
      "                      loops, legend, variables) or +LAYER adds to the default\n"
      "  --highlight ITEM    path:K | loop:K | conflict:K\n"
      "  --collapse NAME     draw submodel instance NAME as one box (repeatable; all)\n"
      "  --style NAME|FILE   default | print | slides, or a style file\n"
      "  --layout ENGINE, -K ENGINE\n"
      "                      dot (default) | neato | fdp | sfdp | pinned | rows\n"
      "  --report FILE.pdf   the full analysis report (FILE.html: one interactive page)\n"
      "  --simulate          run the model's simulate block (with --plot FILE, -o FILE.csv\n"
      "                      or -o FILE.json)\n"
      "  --verify            simulate again at tolerances 100 times tighter and report\n"
      "                      the largest deviation of each output (digits to trust)\n"
      "  --plot FILE         simulation plot (svg, pdf, png)\n"
      "  --set NAME=VALUE    override a param (repeatable)\n"
      "  --equations FORM    print equations: text | latex | mathml | c | json\n"
      "  --linear FORM       linear analysis: text | latex | json | octave | python (docs/linear.md)\n"
      "  --bode FILE, --nyquist FILE, --step FILE\n"
      "                      frequency, step and impulse responses (svg, pdf, png)\n"
      "  --sweep NAME=A:B:N[:log] | NAME=V1,V2,...\n"
      "                      a parameter study over a range or values (repeatable:\n"
      "                      the grid; docs/study.md)\n"
      "  --monte-carlo N --vary NAME=DIST [--seed S]\n"
      "                      N runs with NAME drawn from normal(M,SD), uniform(LO,HI),\n"
      "                      lognormal(MU,SIGMA)\n"
      "  --collect OUT:WHAT  per run: final | min | max | mean | tmin | tmax | cross=LEVEL;\n"
      "                      --collect poles: the linearisation's poles\n"
      "  --study FILE        the study's table (csv, json) or the quantities against\n"
      "                      the param (svg, pdf, png); repeatable\n"
      "  --family FILE       the study's runs in one plot (svg, pdf, png)\n"
      "  --root-locus FILE   the runs' poles in the complex plane (svg, pdf, png)\n"
      "  --bode-family FILE  the Bode diagrams of up to 12 runs in one plot\n"
      "  -j, --jobs N        threads of a study (default: the number of cores)\n"
      "  --runs FIRST:COUNT  compute only these runs of the study (a part to --merge)\n"
      "  --split N:DIR --job-list FILE | --slurm FILE\n"
      "                      the study as N jobs for GNU parallel or a Slurm array, each\n"
      "                      writing DIR/part-K.csv\n"
      "  --merge DIR         the study's outputs from the parts in DIR\n"
      "  --transform NAME    rewrite the model (-o NEW.bg, -T bg; docs/transform.md):\n"
      "                      merge-stores | parasitic | relax-junction\n"
      "  --import            write another tool's model as .bg (-o M.bg, -T bg;\n"
      "                      docs/import.md): BondGraphTools YAML, an MTT folder or\n"
      "                      NAME_abg.fig; any option reads it directly too\n"
      "  --check             parse and analyse only; diagnostics and a summary\n"
      "  --max-list N        list at most N causal paths and N loops (default 1000)\n"
      "  --max-errors N      stop after N errors (default 100; 0: no limit)\n"
      "  --prefix NAME       symbol prefix of exported C (-o NAME.c; default: the model name)\n"
      "  --stdin-name FILE   standard input's name in messages; its folder is where\n"
      "                      its used files and tables are found (as if read from FILE)\n"
      "  --diagnostics-format FMT  text (default) | json (one object a line)\n"
      "  --color WHEN        auto (default: on a terminal, unless NO_COLOR) | always | never\n"
      "  -W NAME, -Wno-NAME  turn a named warning on or off: unused-param, empty-model,\n"
      "                      degenerate-value; -Werror makes them errors\n"
      "  -q, --quiet         no warnings and notes\n"
      "  -v, --verbose       progress on stderr\n"
      "  -V, --version       version and the library versions built with\n"
      "  -h, --help\n"
      "\n"
      "exit status: 0 ok, 1 model errors, 2 bad usage, 3 simulation failed,\n"
      "4 an output could not be written.\n",
      out);
}

void bg_cli_free(bg_cli_opts *o) {
  for (int i = 0; i < o->nsets; i++) free((char *)o->sets[i].name);
  o->nsets = 0;
}
