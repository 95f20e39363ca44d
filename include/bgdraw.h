/* SPDX-License-Identifier: BSD-3-Clause */
/* libbgdraw: the bgdraw engine as a C library (docs/library.md).
 *
 *   bgd_model *m = bgd_open_file("rlc.bg", NULL);      // read, parse, check
 *   if (bgd_status(m) != BGD_OK) { char *t = bgd_diagnostics_text(m); fputs(t, stderr); free(t); }
 *   else {
 *     printf("%d bonds, %d states\n", bgd_count(m, "bonds"), bgd_count(m, "states"));
 *     char *svg; size_t n;
 *     if (bgd_output(m, "svg", NULL, &svg, &n) == BGD_OK) fwrite(svg, 1, n, stdout);
 *     free(svg);
 *   }
 *   bgd_free(m);
 *
 * A model handle is bgdraw's run: every stage (causality and analysis,
 * equations, numeric index, index reduction, simulation, linear analysis)
 * runs once, when a call needs it, exactly as the command line runs it, so
 * every output is byte for byte what `bgdraw` writes.
 *
 * Link with `pkg-config --cflags --libs bgdraw` or CMake's
 * `find_package(bgdraw)` (target bgdraw::bgdraw). Strings returned as
 * `char *` are malloc'd: free them with free(). Pointers in records are
 * borrowed from the handle and valid until bgd_free.
 *
 * Threads: a handle is used by one thread at a time; handles share no state
 * and may be used on different threads at once, except that the first
 * drawing call of a process loads fonts (pango/fontconfig) under their own
 * locks. */
#ifndef BGDRAW_H
#define BGDRAW_H
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* BGDRAW_VERSION_MAJOR, _MINOR, _PATCH, BGDRAW_VERSION_STRING and
 * BGDRAW_API_VERSION (raised whenever a call or a record of this header
 * changes; a program, the Python package, compares it with
 * bgd_api_version() at load time): made by the build from the one version
 * in CMakeLists.txt. */
#include "bgdraw_version.h"

/* Result codes: the command line's exit statuses (docs/cli.md). */
typedef enum bgd_status_code {
  BGD_OK = 0,
  BGD_MODEL = 1,   /* errors in the model, or the model cannot give this (no equations) */
  BGD_USAGE = 2,   /* a wrong argument (an unknown output, layer, method or index) */
  BGD_REFUSED = 3, /* the analysis refuses it (simulation or linear analysis refused, failed) */
  BGD_WRITE = 4    /* it could not be produced or written */
} bgd_status_code;

typedef struct bgd_model bgd_model;

/* Messages while the stages run: level 0 progress (only with verbose),
 * 1 a result in words, 2 a note, 3 a warning. */
typedef void (*bgd_log_fn)(void *ctx, int level, const char *message);

typedef struct bgd_options {
  const char *causality;           /* "scap", "relaxed", "vandijk", "lagrange"; NULL: the model's */
  int nparams;                     /* params overridden, as --set NAME=VALUE */
  const char *const *param_names;
  const double *param_values;
  int max_list;                    /* listing cap of paths and loops; 0: the default */
  int max_errors;                  /* diagnostics kept; 0: no limit; -1: the default (100) */
  int verify;                      /* verify the simulation at tighter tolerances */
  const char *style;               /* diagrams, plots, report: a style name or file; NULL: default */
  const char *show;                /* diagram layers as --show (overlays add to the default) */
  const char *highlight;           /* "path:K", "loop:K", "conflict:K"; NULL: none */
  const char *layout;              /* "dot", "neato", ..., "rows"; NULL: the model's */
  const char *prefix;              /* exported C symbols' prefix; NULL: from the model */
  bgd_log_fn log;                  /* NULL: silent */
  void *log_ctx;
  int verbose;                     /* 1: progress messages to log */
  const char *warnings;            /* as -W: "no-unused-param,error"; NULL: all on */
} bgd_options;

/* Fills o with the defaults (all NULL/0, max_errors -1). */
void bgd_options_init(bgd_options *o);

/* ---------------------------------------------------------------- loading */
/* Reads, parses and compiles model text (copied); name appears in the
 * diagnostics and gives the model's default name. Never NULL (but for lack
 * of memory): look at bgd_status. o NULL: the defaults. */
bgd_model *bgd_open(const char *name, const char *text, const bgd_options *o);
/* The same for len bytes of text (copied) that may hold anything, as a file
 * may: a NUL byte is a diagnostic ("not a text file"), as it is in a file,
 * where bgd_open's text would end at it. */
bgd_model *bgd_open_buffer(const char *name, const char *text, size_t len, const bgd_options *o);
bgd_model *bgd_open_file(const char *path, const bgd_options *o);
/* BGD_OK when the model loaded, BGD_MODEL when it has errors, BGD_USAGE for
 * a wrong option (unknown causality method, layer, highlight). */
int bgd_status(const bgd_model *m);
void bgd_free(bgd_model *m);

/* ------------------------------------------------------------ diagnostics */
typedef struct bgd_diagnostic {
  const char *file;     /* the source it points into ("rlc.bg", a used file) */
  int line, column;     /* from 1; 0: no position (a whole-file problem) */
  const char *severity; /* "error", "warning", "note" */
  const char *message;
  int nnotes;           /* the notes that belong to it (where it is used from) */
  const struct bgd_diagnostic *notes;
} bgd_diagnostic;

/* The diagnostics in the order bgdraw prints them (notes inside their
 * diagnostic); *out is borrowed. Returns the count. */
int bgd_diagnostics(bgd_model *m, const bgd_diagnostic **out);
/* As bgdraw prints them: "file:line:col: error: ...", the line, a caret. */
char *bgd_diagnostics_text(const bgd_model *m);

/* ---------------------------------------------------------------- results */
/* The model's name (its `model` statement, else the file name's stem). */
const char *bgd_name(const bgd_model *m);
/* How many of: "elements", "bonds", "params", "states", "dependent_stores",
 * "conflicts", "causal_paths", "causal_loops", "topological_loops",
 * "unknowns" (of the equations), "rows" and "columns" (of the simulation),
 * "poles", "transfer_functions", "eigenvalues"; -1 for another word or a
 * model that did not load. Asking runs the stages the count needs. */
int bgd_count(bgd_model *m, const char *what);

typedef struct bgd_element {
  const char *name;
  const char *kind;      /* "R", "C", "I", "Se", "Sf", "0", "1", "TF", "GY", ... */
  const char *causality; /* "integral", "derivative", "resistance", ...; NULL for none */
} bgd_element;
int bgd_element_at(bgd_model *m, int i, bgd_element *out);

typedef struct bgd_bond {
  int number;        /* as written in the model */
  const char *from;  /* the element the half arrow leaves */
  const char *to;    /* the element it points at */
  const char *stroke;/* "from", "to" (the end with the causal stroke), NULL: none */
} bgd_bond;
int bgd_bond_at(bgd_model *m, int i, bgd_bond *out);

typedef struct bgd_path {
  const char *from, *to; /* the one-port elements at its ends */
  const char *kind;      /* "R-R", "C-I", ... */
  int cls;               /* van Dijk's class 1 or 2; 0: none */
  int order;             /* integrations in the loop it closes; BGD_NO_ORDER: none (a
                            path from a source closes no loop) */
  int nbonds;
  const int *bonds;      /* bond numbers, from end to end */
} bgd_path;
#define BGD_NO_ORDER (-1000000)
int bgd_causal_path_at(bgd_model *m, int i, bgd_path *out);

typedef struct bgd_loop {
  int nbonds;
  const int *bonds;      /* bond numbers */
  const char *gain;      /* symbolic */
  double gain_value;
  int cls;               /* causal loops: class 4 or 5; topological loops: 0 */
  const char *kind;      /* topological loops: "flat" or "open"; causal loops: "causal" */
  int order;             /* topological loops: integrations around it */
  int algebraic;         /* topological loops: an algebraic loop */
} bgd_loop;
int bgd_causal_loop_at(bgd_model *m, int i, bgd_loop *out);
int bgd_topological_loop_at(bgd_model *m, int i, bgd_loop *out);

typedef struct bgd_conflict {
  const char *element;
  int type;              /* 1 or 2 */
  int degree;            /* type 2: k; type 1: 0 */
  int nbonds;
  const int *bonds;
} bgd_conflict;
int bgd_conflict_at(bgd_model *m, int i, bgd_conflict *out);

typedef struct bgd_index {
  const char *form;          /* "ode", "dae", "incomplete" */
  int predicted;             /* from the causal pattern; -1 unknown */
  const char *reason;
  int numeric;               /* Algorithm 4.1; -1 when not computed or singular */
  const char *numeric_status;/* "computed", "singular", "not computed" */
  const char *reduced_form;  /* "ode"/"dae" after symbolic elimination; NULL */
  const char *reduction;     /* what index reduction did, in words; NULL: not tried */
} bgd_index;
/* Runs the equations, the numeric index and (where needed) the reduction. */
int bgd_index_info(bgd_model *m, bgd_index *out);
/* Eigenvalues of the linearised model (with the numeric index): count. */
int bgd_eigenvalues(bgd_model *m, const double **re, const double **im);

/* ------------------------------------------------------------- simulation */
typedef struct bgd_simulation {
  int status;            /* BGD_OK, or BGD_REFUSED (refused or failed: message) */
  const char *message;   /* why it was refused or failed; NULL */
  int nrows, ncolumns;   /* output times; output columns besides time */
  const double *time;    /* nrows */
  const char *const *names; /* ncolumns */
  const char *solver;    /* "cvode_bdf", "cvode_adams", "ida"; NULL when refused */
  int partial;           /* stopped before t_end (rows up to there) */
} bgd_simulation;
/* Runs the model's simulate block (once). */
int bgd_simulate(bgd_model *m, bgd_simulation *out);
/* Column j's nrows values (j: 0..ncolumns-1), or NULL. */
const double *bgd_column(bgd_model *m, int j);

/* ---------------------------------------------------------------- linear */
typedef struct bgd_linear {
  int status;             /* BGD_OK, or BGD_REFUSED with message */
  const char *message;
  int n, nu, ny;          /* states, inputs, outputs of the state space */
  int reduced;            /* 1: A, B, C, D valid (else only poles) */
  const double *A, *B, *C, *D; /* column-major: A n x n, B n x nu, C ny x n, D ny x nu */
  const char *const *inputs, *const *outputs;
  int npoles;
  const double *pole_re, *pole_im;
} bgd_linear;
int bgd_linearise(bgd_model *m, bgd_linear *out);

typedef struct bgd_transfer {
  int input, output;      /* indices into inputs and outputs */
  int nnum, nden;         /* coefficients, highest power first; den monic */
  const double *num, *den;
  double dc_gain;
  int npoles, nzeros;
  const double *pole_re, *pole_im, *zero_re, *zero_im;
} bgd_transfer;
/* Transfer function k (output-major: k = output * nu + input). */
int bgd_transfer_function_at(bgd_model *m, int k, bgd_transfer *out);

/* ---------------------------------------------------------------- outputs */
/* Output kind `kind` as bgdraw writes it (a CSV or a plot of a simulation
 * without rows: BGD_REFUSED, where bgdraw writes no file): "svg", "pdf", "png", "dot",
 * "json", "check", "equations" (form "text", "latex", "json", "c"), "tex",
 * "c", "h", "py", "m", "mo", "fmu" (an FMI 2.0 Model Exchange archive,
 * compiled by $CC or cc, whose messages go to the process's stderr; the
 * program's signal handlers are left alone), "csv", "plot" (form "svg", "pdf", "png"),
 * "report" (form "html": the HTML page; else the PDF, or for bgd_write
 * the HTML page when the path ends in .html or .htm), "linear" (form
 * "text", "latex", "json", "octave", "python"), "equations" also form
 * "mathml", "bode", "nyquist", "step" (form a format). 0 with *data (len bytes,
 * NUL-terminated, malloc'd) or a status with the reason in the diagnostics
 * (bgd_last_error). */
int bgd_output(bgd_model *m, const char *kind, const char *form, char **data, size_t *len);
/* The same into a file, written atomically; the path also names what the
 * format names after its file (the C header a source includes, an Octave
 * function). */
int bgd_write(bgd_model *m, const char *kind, const char *form, const char *path);
/* The message of the last failed bgd_output/bgd_write/bgd_set_drawing
 * (borrowed), or NULL. */
const char *bgd_last_error(const bgd_model *m);
/* Changes how the outputs after it draw: o's style, show, highlight and
 * layout (NULL fields: the defaults; o NULL: every one the default), as if
 * the handle had been opened with them; the other fields of o are not read.
 * The model's results stay; the diagram is laid out again. BGD_USAGE (and
 * the handle's drawing options unchanged) for a wrong layer or highlight,
 * with the reason in bgd_last_error. */
int bgd_set_drawing(bgd_model *m, const bgd_options *o);

/* The library's version ("0.2.0") and API version (BGDRAW_API_VERSION of
 * the build). */
const char *bgd_version(void);
int bgd_api_version(void);

/* ------------------------------------------------ the first API (kept) */
/* Loads and analyses (NULL on model errors, *errors then holds them). */
typedef bgd_model bg_api_model;
bg_api_model *bg_api_load_file(const char *path, char **errors);
bg_api_model *bg_api_load_string(const char *name, const char *text, char **errors);
const char *bg_api_name(const bg_api_model *m);
int bg_api_count(const bg_api_model *m, const char *what);
char *bg_api_summary(const bg_api_model *m);
char *bg_api_json(const bg_api_model *m);
int bg_api_render(bg_api_model *m, const char *format, const char *style, const char *show,
                  char **data, size_t *len, char **errors);
void bg_api_free(bg_api_model *m);
const char *bg_api_version(void);

#ifdef __cplusplus
}
#endif
#endif
