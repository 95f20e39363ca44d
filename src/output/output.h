/* SPDX-License-Identifier: BSD-3-Clause */
/* Every output of a run, from one table (output.c): its name, the stages it
 * needs, whether it draws, and its writer, which produces the output's
 * bytes into a buffer. The command line writes the buffers to files (or
 * standard output) and turns statuses into exit codes; libbgdraw hands them
 * to its caller; so both give the same bytes (docs/architecture.md, "Adding
 * an output"). */
#ifndef BG_OUTPUT_H
#define BG_OUTPUT_H
#include "base/diag.h"
#include "base/strbuf.h"
#include "diagram/render.h"
#include "run/run.h"
#include "transform/transform.h"

/* A writer's result; the numbers are the command line's exit statuses. */
typedef enum bg_output_status {
  BG_OUT_OK = 0,
  BG_OUT_MODEL = 1,   /* the model cannot give it (no equations) */
  BG_OUT_USAGE = 2,   /* an option is wrong for it (an unknown layer or highlight) */
  BG_OUT_REFUSED = 3, /* the analysis refuses it (linear analysis refused, no rows) */
  BG_OUT_WRITE = 4    /* it could not be produced or written */
} bg_output_status;

enum {
  BG_OUTK_DRAWS = 1,      /* needs the renderers (Graphviz, cairo, pango) */
  BG_OUTK_MODEL_SIM = 2,  /* and the simulation when the model has a simulate block */
  BG_OUTK_MODEL_LIN = 4,  /* and the linear analysis when the model has a linearise statement */
  BG_OUTK_EXT = 16,       /* chosen by a file's extension (-o FILE.EXT) or -T */
  BG_OUTK_APPENDS = 32    /* its writer only appends to out, so out may pass its text on
                             to the file in pieces (a strbuf sink, fileio.h's bg_stream) */
};

typedef struct bg_output bg_output;
typedef struct bg_output_kind bg_output_kind;

struct bg_output_kind {
  const char *name; /* "svg", "json", "equations", "report", ... */
  bg_stage need;    /* the last stage it needs (with those before it) */
  unsigned flags;   /* BG_OUTK_* */
  /* form: the printer or plot kind where the output has several ("text",
   * "latex"...), NULL otherwise; path: the file it goes to, nullable (a C
   * export names its header after it, an Octave function after its file) */
  bg_output_status (*write)(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out);
  const char *what; /* one line for --help and the library's docs */
};

/* What the outputs share beyond the run. */
typedef struct bg_output_opts {
  bg_render_opts render;       /* layers, highlight, style, layout, collapse, log */
  const char *prefix;          /* exported C symbols' prefix; NULL: from the model */
  const char *transform;       /* --transform NAME: tx is its result ("bg", the report) */
  const bg_transform_result *tx;
  int catch_signals;           /* the FMU build may take stop signals to clean up (the
                                  command line; a library leaves a program's signals alone) */
} bg_output_opts;

struct bg_output {
  bg_run *run;
  bg_output_opts o;
  bg_diagram *diagram; /* laid out once, on the first diagram output */
  bg_diags dg;         /* writers' errors, printed as "bgdraw: error: ..." */
  bg_diags dg_model;   /* the diagram's errors, named after the model's source */
  char *refusal;       /* with BG_OUT_REFUSED: why, in words ("linear analysis refused: ...") */
  int nothing;         /* the last write had nothing to give (a CSV or plot of a refused
                          simulation): no file is written */
};

/* The table, in --help's order, ending with a row whose name is NULL. */
extern const bg_output_kind bg_output_kinds[];
/* The row named name, or NULL. */
const bg_output_kind *bg_output_find(const char *name);
/* The output kind of a file extension (a row with BG_OUTK_EXT; "SVG" and
 * "svg" alike); NULL when no output has it. */
const bg_output_kind *bg_output_for_ext(const char *ext);

void bg_output_init(bg_output *w, bg_run *run, const bg_output_opts *o);
void bg_output_free(bg_output *w);
/* A --show list into layer bits: overlays (paths, loops, conflicts,
 * signals, legend, variables) and +LAYER add to the default layers; a base
 * layer makes the list the whole set. -1 with the reason (and the layers'
 * names) in err. */
int bg_output_parse_show(const char *list, unsigned *bits, bg_strbuf *err);
/* Forgets the messages of the writes so far (after they were shown). */
void bg_output_clear_messages(bg_output *w);
/* Runs the stages the output needs (bg_output_need) and writes it into out.
 * Errors are in w->dg. */
bg_output_status bg_output_write(bg_output *w, const char *kind, const char *form, const char *path,
                                 bg_strbuf *out);
/* The stages an output needs, run now; the linear analysis before the
 * simulation, as the command line always did. */
void bg_output_need(bg_output *w, const bg_output_kind *k);
#endif
