/* SPDX-License-Identifier: BSD-3-Clause */
/* Checks of option values and combinations. A run never silently ignores
 * an option: -T that contradicts an -o extension, --simulate with nowhere to
 * show the simulation and --check with outputs are refused with the fix. */
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "base/fileio.h"
#include "cli/cli_usage.h"
#include "output/output.h"
#include "transform/transform.h"

static const char *const eq_forms[] = {"text", "latex", "mathml", "c", "json", NULL};
static const char *const lin_forms[] = {"text", "latex", "json", "octave", "python", NULL};
static const char *const methods[] = {"scap", "relaxed", "vandijk", "lagrange", NULL};
static const char *const layouts[] = {"dot", "neato", "fdp", "sfdp", "pinned", "rows", NULL};
static const char *const diag_formats[] = {"text", "json", NULL};
static const char *const colors[] = {"auto", "always", "never", NULL};

int bg_cli_usage_error(const char *fmt, const char *a, const char *b) {
  fputs("bgdraw: error: ", stderr);
  fprintf(stderr, fmt, a, b);
  fputs("\nTry 'bgdraw --help' for the options.\n", stderr);
  return -1;
}

static int in_list(const char *s, const char *const *list) {
  for (int i = 0; list[i]; i++)
    if (strcmp(s, list[i]) == 0) return 1;
  return 0;
}

static void join_list(const char *const *list, char *buf, size_t n) {
  buf[0] = '\0';
  for (int i = 0; list[i]; i++) {
    if (i) strncat(buf, ", ", n - strlen(buf) - 1);
    strncat(buf, list[i], n - strlen(buf) - 1);
  }
}

/* The formats -o FILE.EXT and -T choose: the rows of the output table
 * (src/output) marked BG_OUTK_EXT, in the table's order. */
static void join_formats(char *buf, size_t n) {
  buf[0] = '\0';
  for (const bg_output_kind *k = bg_output_kinds; k->name; k++) {
    if (!(k->flags & BG_OUTK_EXT)) continue;
    if (buf[0]) strncat(buf, ", ", n - strlen(buf) - 1);
    strncat(buf, k->name, n - strlen(buf) - 1);
  }
}

static int check_format(const char *val) {
  if (!val || bg_output_for_ext(val)) return 0;
  const char *colon = strchr(val, ':');
  if (colon) { /* dot's -Tsvg:cairo */
    char fmt[64];
    snprintf(fmt, sizeof fmt, "%.*s", (int)(colon - val), val);
    if (bg_output_for_ext(fmt))
      return bg_cli_usage_error("-T %s: bgdraw has one renderer for each format (its own SVG "
                                "writer; cairo and pango for PDF and PNG), so there is nothing to "
                                "choose after ':'; write -T %s", val, fmt);
  }
  char buf[200], msg[300];
  join_formats(buf, sizeof buf);
  snprintf(msg, sizeof msg, "-T takes one of: %s", buf);
  return bg_cli_usage_error("unknown value '%s' for %s", val, msg);
}

static int check_choice(const char *opt, const char *val, const char *const *list) {
  if (!val || in_list(val, list)) return 0;
  char buf[200], msg[300];
  join_list(list, buf, sizeof buf);
  snprintf(msg, sizeof msg, "%s takes one of: %s", opt, buf);
  return bg_cli_usage_error("unknown value '%s' for %s", val, msg);
}

static int check_transform(const char *name) {
  if (!name || bg_transform_known(name)) return 0;
  return bg_cli_usage_error("unknown transformation '%s': --transform takes one of: %s", name,
                            bg_transform_names());
}

static int check_choices(const bg_cli_opts *o) {
  return check_choice("--causality", o->causality, methods) ||
         check_choice("--equations", o->equations, eq_forms) ||
         check_choice("--linear", o->linear, lin_forms) ||
         check_choice("--layout", o->layout, layouts) ||
         check_format(o->force_format) ||
         check_choice("--diagnostics-format", o->diag_format, diag_formats) ||
         check_choice("--color", o->color, colors) || check_transform(o->transform) ? -1 : 0;
}

/* -T gives the format of -o - and of files without a known extension; a
 * known extension that says otherwise would be ignored, so it is an error. */
static int resolve_format(const bg_cli_opts *o, bg_cli_output *out) {
  const char *T = o->force_format;
  char buf[200], msg[400];
  if (bg_cli_is_stdout(out->path)) {
    if (!T) return bg_cli_usage_error("-o - writes to stdout: name its format with -T "
                                      "(e.g. -T svg)%s%s", "", "");
    out->format = bg_output_for_ext(T)->name;
    return 0;
  }
  /* .bg is a format only for --transform: before it, -T svg -o m.bg wrote svg */
  int bg_without_transform = !strcmp(out->format, "bg") && !o->transform && !o->import && T;
  const bg_output_kind *k = bg_output_for_ext(out->format);
  if (k && !bg_without_transform) {
    out->format = k->name; /* ".SVG" is an SVG */
    if (!T || !strcmp(bg_output_for_ext(T)->name, out->format)) return 0;
    snprintf(msg, sizeof msg, "-T %s with -o '%s'", T, out->path);
    return bg_cli_usage_error("%s: the extension says %s; drop -T or rename the file",
                              msg, out->format);
  }
  if (T) {
    out->format = bg_output_for_ext(T)->name;
    return 0;
  }
  join_formats(buf, sizeof buf);
  return bg_cli_usage_error("cannot tell the format of '%s': use an extension (%s) or -T FMT",
                            out->path, buf);
}

static int count_stdout(const bg_cli_opts *o) {
  int n = (o->equations ? 1 : 0) + (o->linear ? 1 : 0);
  for (int i = 0; i < o->nout; i++) n += bg_cli_is_stdout(o->out[i].path);
  return n;
}

static int has_format(const bg_cli_opts *o, const char *f) {
  for (int i = 0; i < o->nout; i++)
    if (!strcmp(o->out[i].format, f)) return 1;
  return 0;
}

static int check_outputs(bg_cli_opts *o) {
  if (o->force_format && o->nout == 0 && !o->check) {
    o->out[0] = (bg_cli_output){BG_CLI_STDOUT, o->force_format}; /* as dot -Tsvg does */
    o->nout = 1;
  }
  for (int i = 0; i < o->nout; i++)
    if (resolve_format(o, &o->out[i]) != 0) return -1;
  if (count_stdout(o) > 1)
    return bg_cli_usage_error("only one output can go to stdout (-o -, -T without -o, "
                              "--equations, --linear); write the others to files%s%s", "", "");
  static const char *const plot_formats[] = {"svg", "pdf", "png", NULL};
  if (o->plot && !in_list(bg_path_ext(o->plot), plot_formats))
    return bg_cli_usage_error("--plot writes svg, pdf or png, not '%s'%s", o->plot, "");
  const char *rext = o->report ? bg_path_ext(o->report) : "";
  if (o->report && strcasecmp(rext, "pdf") && strcasecmp(rext, "html") && strcasecmp(rext, "htm"))
    return bg_cli_usage_error("--report writes a PDF or an HTML page: give a .pdf or .html file, "
                              "not '%s'%s", o->report, "");
  const char *const lin_plots[] = {o->bode, o->nyquist, o->step};
  const char *const lin_names[] = {"--bode", "--nyquist", "--step"};
  for (int i = 0; i < 3; i++)
    if (lin_plots[i] && !in_list(bg_path_ext(lin_plots[i]), plot_formats))
      return bg_cli_usage_error("%s writes svg, pdf or png, not '%s'", lin_names[i], lin_plots[i]);
  return 0;
}

/* Options that the rest of the request would ignore. */
static int check_ignored(const bg_cli_opts *o) {
  if (o->check && (o->nout || o->force_format || o->report || o->plot || o->equations ||
                   o->simulate || o->depfile || o->linear || o->transform))
    return bg_cli_usage_error("--check writes nothing: drop it to write the outputs, or drop "
                              "%s%s", o->nout || o->force_format ? "-o/-T"
                              : o->report ? "--report" : o->plot ? "--plot"
                              : o->equations ? "--equations"
                              : o->simulate ? "--simulate"
                              : o->linear ? "--linear"
                              : o->transform ? "--transform" : "--depfile", "");
  if (has_format(o, "bg") && !o->transform && !o->import)
    return bg_cli_usage_error("a .bg output is the model rewritten by --transform, or read by "
                              "--import: add --transform NAME (%s) or --import%s", bg_transform_names(), "");
  if (o->import && o->transform)
    return bg_cli_usage_error("--import writes the model as it is, --transform rewrites it: convert "
                              "first (--import -o MODEL.bg), then transform MODEL.bg%s%s", "", "");
  if (o->transform && !has_format(o, "bg") && !o->report)
    return bg_cli_usage_error("--transform %s writes a new model: add -o NEW.bg (or -T bg for "
                              "stdout, or --report FILE.pdf to see it)%s", o->transform, "");
  if (o->simulate && !o->plot && !o->report && !has_format(o, "csv") && !has_format(o, "json"))
    return bg_cli_usage_error("--simulate alone shows no result: add --plot FILE, -o FILE.csv, "
                              "-o FILE.json or --report FILE.pdf%s%s", "", "");
  if (o->depfile) {
    int files = o->report || o->plot;
    for (int i = 0; i < o->nout; i++) files += !bg_cli_is_stdout(o->out[i].path);
    if (!files && (o->nout || o->equations || o->linear))
      return bg_cli_usage_error("--depfile names the files written as its targets, and this "
                                "run writes only to stdout: add -o FILE%s%s", "", "");
  }
  return 0;
}

int bg_cli_check_usage(bg_cli_opts *o) {
  if (check_choices(o) != 0) return -1;
  if (check_outputs(o) != 0 || check_ignored(o) != 0) return -1;
  /* as dot does: no model file and input from a pipe or file reads it */
  if (!o->model_path && !isatty(fileno(stdin))) o->model_path = BG_CLI_STDOUT;
  if (!o->model_path) return bg_cli_usage_error("no model file given (- reads stdin)%s%s", "", "");
  if (o->stdin_name && !bg_cli_is_stdout(o->model_path))
    return bg_cli_usage_error("--stdin-name names standard input, and the model is read from "
                              "'%s'%s", o->model_path, ": give '-' as the model");
  if (o->stdin_name && !*o->stdin_name)
    return bg_cli_usage_error("--stdin-name takes a file name%s%s", "", "");
  return 0;
}
