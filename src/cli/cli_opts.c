/* Command-line parsing for bgdraw. Usage errors name the fix. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli_opts.h"
#include "base/fileio.h"
#include "base/strbuf.h"

static const char *const formats[] = {"svg", "pdf", "png", "json", "dot", "tex", "c", "csv", NULL};
static const char *const eq_forms[] = {"text", "latex", "c", "json", NULL};
static const char *const lin_forms[] = {"text", "latex", "json", NULL};
static const char *const methods[] = {"scap", "relaxed", "vandijk", "lagrange", NULL};
static const char *const layouts[] = {"dot", "neato", "fdp", "sfdp", "pinned", "rows", NULL};

/* Options taking a value, and where it goes. */
typedef struct {
  const char *name;
  size_t offset; /* of a const char * in bg_cli_opts */
} valued_opt;

#define OPT(n, field) {n, offsetof(bg_cli_opts, field)}
static const valued_opt valued[] = {
    OPT("--causality", causality), OPT("--show", show),     OPT("--highlight", highlight),
    OPT("--style", style),         OPT("--layout", layout), OPT("--report", report),
    OPT("--plot", plot),           OPT("--equations", equations), OPT("-T", force_format),
    OPT("--max-list", max_list),   OPT("--max-errors", max_errors), OPT("--linear", linear),
};
static const char *const flags[] = {"--simulate", "--check", "-q", "-v", "--help", "-h", "--version", "-o", "--set", NULL};

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

static int usage_error(const char *fmt, const char *a, const char *b) {
  fputs("bgdraw: error: ", stderr);
  fprintf(stderr, fmt, a, b);
  fputs("\nTry 'bgdraw --help' for the options.\n", stderr);
  return -1;
}


static const char *closest_option(const char *arg) {
  const char *best = NULL;
  int bestd = 4;
  for (size_t i = 0; i < sizeof valued / sizeof *valued; i++) {
    int d = bg_edit_distance(arg, valued[i].name);
    if (d < bestd) bestd = d, best = valued[i].name;
  }
  for (int i = 0; flags[i]; i++) {
    int d = bg_edit_distance(arg, flags[i]);
    if (d < bestd) bestd = d, best = flags[i];
  }
  return best;
}

static int check_choice(const char *opt, const char *val, const char *const *list) {
  if (in_list(val, list)) return 0;
  char buf[200];
  join_list(list, buf, sizeof buf);
  char msg[300];
  snprintf(msg, sizeof msg, "%s takes one of: %s", opt, buf);
  return usage_error("unknown value '%s' for %s", val, msg);
}

static int add_output(bg_cli_opts *o, const char *path) {
  if (o->nout == BG_MAX_OUTPUTS) return usage_error("too many -o outputs%s%s", "", "");
  o->out[o->nout].path = path;
  o->out[o->nout].format = bg_path_ext(path);
  o->nout++;
  return 0;
}

static int add_set(bg_cli_opts *o, const char *arg) {
  const char *eq = strchr(arg, '=');
  if (!eq || eq == arg) return usage_error("--set takes NAME=VALUE, not '%s'%s", arg, "");
  char *end;
  double v = strtod(eq + 1, &end);
  if (end == eq + 1 || *end) return usage_error("--set %s: '%s' is not a number", arg, eq + 1);
  if (o->nsets == BG_MAX_SETS) return usage_error("too many --set options%s%s", "", "");
  size_t n = (size_t)(eq - arg);
  char *name = malloc(n + 1); /* lives for the whole run */
  memcpy(name, arg, n);
  name[n] = '\0';
  o->sets[o->nsets++] = (bg_param_override){name, v};
  return 0;
}

/* Handles one option that takes a value; returns 1 if arg was one. */
static int take_valued(bg_cli_opts *o, const char *arg, const char *val, int *err) {
  for (size_t i = 0; i < sizeof valued / sizeof *valued; i++) {
    if (strcmp(arg, valued[i].name) != 0) continue;
    if (!val) *err = usage_error("%s needs a value%s", arg, "");
    else *(const char **)((char *)o + valued[i].offset) = val;
    return 1;
  }
  return 0;
}

static int take_flag(bg_cli_opts *o, const char *arg) {
  if (!strcmp(arg, "--simulate")) o->simulate = 1;
  else if (!strcmp(arg, "--check")) o->check = 1;
  else if (!strcmp(arg, "-q")) o->quiet = 1;
  else if (!strcmp(arg, "-v")) o->verbose = 1;
  else if (!strcmp(arg, "--help") || !strcmp(arg, "-h")) o->help = 1;
  else if (!strcmp(arg, "--version")) o->version = 1;
  else return 0;
  return 1;
}

static int validate(bg_cli_opts *o) {
  if (o->causality && check_choice("--causality", o->causality, methods)) return -1;
  if (o->equations && check_choice("--equations", o->equations, eq_forms)) return -1;
  if (o->layout && check_choice("--layout", o->layout, layouts)) return -1;
  if (o->force_format && check_choice("-T", o->force_format, formats)) return -1;
  for (int i = 0; i < o->nout; i++) {
    if (o->force_format) o->out[i].format = o->force_format;
    if (!in_list(o->out[i].format, formats)) {
      char buf[200];
      join_list(formats, buf, sizeof buf);
      return usage_error("cannot tell the format of '%s': use an extension (%s) or -T FMT",
                         o->out[i].path, buf);
    }
  }
  static const char *const plot_formats[] = {"svg", "pdf", "png", NULL};
  if (o->plot && !in_list(bg_path_ext(o->plot), plot_formats))
    return usage_error("--plot writes svg, pdf or png, not '%s'%s", o->plot, "");
  if (o->linear && check_choice("--linear", o->linear, lin_forms)) return -1;

  if (o->report && strcmp(bg_path_ext(o->report), "pdf") != 0)
    return usage_error("--report writes a PDF: give a .pdf file, not '%s'%s", o->report, "");
  if (!o->model_path && !o->help && !o->version)
    return usage_error("no model file given%s%s", "", "");
  return 0;
}

int bg_cli_parse(int argc, char **argv, bg_cli_opts *o) {
  memset(o, 0, sizeof *o);
  for (int i = 1; i < argc; i++) {
    const char *arg = argv[i], *next = i + 1 < argc ? argv[i + 1] : NULL;
    int err = 0;
    if (!strcmp(arg, "-o") || !strcmp(arg, "--set")) {
      if (!next) return usage_error("%s needs a value%s", arg, "");
      if ((arg[1] == 'o' ? add_output(o, next) : add_set(o, next)) != 0) return -1;
      i++;
    } else if (take_valued(o, arg, next, &err)) {
      if (err) return -1;
      i++;
    } else if (take_flag(o, arg)) {
    } else if (arg[0] == '-' && arg[1]) {
      const char *hint = closest_option(arg);
      if (hint) return usage_error("unknown option '%s' (did you mean '%s'?)", arg, hint);
      return usage_error("unknown option '%s'%s", arg, "");
    } else if (o->model_path) {
      return usage_error("more than one model file ('%s' and '%s')", o->model_path, arg);
    } else {
      o->model_path = arg;
    }
  }
  return validate(o);
}

void bg_cli_print_help(FILE *out) {
  fputs(
      "usage: bgdraw MODEL.bg [-o OUT]... [options]\n"
      "\n"
      "Assigns causality to a bond graph model, analyses the causal pattern, and\n"
      "draws it. With no -o the diagram goes to out/<model>.svg.\n"
      "\n"
      "outputs (-o FILE, repeatable; the format follows the extension):\n"
      "  .svg .pdf .png   annotated diagram        .json  analysis\n"
      "  .dot             graph with positions     .tex   equations in LaTeX\n"
      "  .c               equations as C           .csv   simulation results\n"
      "  -T FMT           force the format of every -o\n"
      "\n"
      "options:\n"
      "  --causality METHOD  scap (default) | relaxed | vandijk | lagrange\n"
      "  --show LAYERS       strokes,numbers,paths,loops,conflicts,signals,labels,legend,\n"
      "                      variables | all | none\n"
      "  --highlight ITEM    path:K | loop:K | conflict:K\n"
      "  --style NAME|FILE   default | print | slides, or a style file\n"
      "  --layout ENGINE     dot (default) | neato | fdp | sfdp | pinned | rows\n"
      "  --report FILE.pdf   the full analysis report\n"
      "  --simulate          run the model's simulate block (with --plot FILE, -o FILE.csv)\n"
      "  --plot FILE         simulation plot (svg, pdf, png)\n"
      "  --set NAME=VALUE    override a param (repeatable)\n"
      "  --equations FORM    print equations: text | latex | c | json\n"
      "  --linear FORM       linear analysis: text | latex | json (docs/linear.md)\n"
      "  --check             parse and analyse only; diagnostics and a summary\n"
      "  --max-list N        list at most N causal paths and N loops (default 1000)\n"
      "  --max-errors N      stop after N errors (default 100; 0: no limit)\n"
      "  -q, -v              quieter, more verbose (progress on stderr)\n"
      "  --version, --help\n"
      "\n"
      "exit status: 0 ok, 1 model errors, 2 bad usage, 3 simulation failed,\n"
      "4 an output could not be written.\n",
      out);
}

void bg_cli_free(bg_cli_opts *o) {
  for (int i = 0; i < o->nsets; i++) free((char *)o->sets[i].name);
  o->nsets = 0;
}
