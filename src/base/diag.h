/* SPDX-License-Identifier: BSD-3-Clause */
/* Diagnostics: user-facing errors and warnings with source positions,
 * printed like a C compiler's ("file:line:col: error: msg", the line, a caret). */
#ifndef BG_DIAG_H
#define BG_DIAG_H
#include <stdio.h>

#include "base/strindex.h"

/* A position in a source; line and col count from 1 (col in bytes). `file`
 * indexes the sources of the bg_diags (0: the model file given on the command
 * line), so every position written {line, col} is in the model file. */
typedef struct bg_srcloc {
  int line, col;
  int file;
} bg_srcloc;

typedef enum { BG_SEV_ERROR, BG_SEV_WARNING, BG_SEV_NOTE } bg_severity;

typedef struct bg_diag {
  bg_severity sev;
  bg_srcloc loc; /* line 0: no position (a whole-file or command-line problem) */
  char *msg;     /* owned */
} bg_diag;

/* One source a position can point into. A file used by a submodel instance
 * gets one source per instance (sharing the text) whose `context` says where
 * the instance is: diagnostics print that chain as notes, innermost first. */
typedef struct bg_diag_source {
  const char *path; /* owned copy */
  const char *src;  /* the text, for echoing lines; nullable */
  size_t srclen;
  int owns_src;     /* src is an owned copy */
  bg_srcloc context; /* where this source is used from; context.line 0: nowhere */
  char *context_msg; /* owned, e.g. "in instance M1 of DCMotor"; nullable */
} bg_diag_source;

typedef struct bg_diags {
  const char *file; /* as given on the command line; borrowed */
  const char *src;  /* the whole source text, for echoing lines; borrowed, nullable */
  size_t srclen;
  bg_diag_source *sources; /* index 0 is the model file (file, src above) and unused here; owned */
  int nsources, srccap;
  bg_diag *items; /* owned */
  int n, cap;
  int nerrors, nwarnings;
  int max_errors;  /* errors kept and printed at most (0: no limit); bg_diags_init sets
                      BG_DIAG_MAX_ERRORS */
  int dropped;     /* errors beyond max_errors: counted, not kept */
  unsigned warn_off; /* bit per bg_warning: not reported (-Wno-NAME) */
  int werror;        /* named warnings are errors (-Werror) */
  int dropping;    /* the last error was dropped (beyond the limit, or a repeat of an
                      earlier one), and so are its notes */
  const struct bg_log *log; /* progress of long work on the input (flattening); nullable */
  /* Statements the parser dropped after a syntax error (docs/format.md,
   * "Errors"): the stages after it still check every statement that parsed,
   * but say nothing that may only follow from a dropped one. */
  int nskipped;        /* statements dropped */
  char **unsure;       /* the names written on their lines; owned */
  int nunsure, unsure_cap;
  bg_strindex unsure_index;
  int unsure_bonds;    /* a dropped bond line did not name both its ends */
  int unsaid;          /* errors not reported for that reason: a stage stops as on an error */
} bg_diags;

/* Named warnings, as compilers have them (docs/cli.md, "Warnings"): each
 * can be turned off (-Wno-NAME) and all turned into errors (-Werror). */
typedef enum bg_warning {
  BG_W_UNUSED_PARAM,  /* unused-param: a param no expression reads */
  BG_W_EMPTY_MODEL,   /* empty-model: no element (or only submodel definitions) */
  BG_W_DEGENERATE,    /* degenerate-value: a C, I, TF or GY whose value is 0 */
  BG_W_UNBONDED_PORT, /* unbonded-port: an instance's port left unbonded, taken as open or short */
  BG_W_COUNT
} bg_warning;
/* The warning named name ("unused-param"), or -1. */
int bg_warning_parse(const char *name);
const char *bg_warning_name(bg_warning w);

/* The default error limit (--max-errors changes it; docs/cli.md). */
enum { BG_DIAG_MAX_ERRORS = 100 };

void bg_diags_init(bg_diags *d, const char *file, const char *src, size_t srclen);
void bg_diags_free(bg_diags *d);
/* Adds a source (path and text are copied) and returns its index. */
int bg_diags_add_source(bg_diags *d, const char *path, const char *src, size_t srclen);
/* Adds a source sharing the text of source `of`, used from `context` (which
 * points into another source) with the note text `msg`; returns its index. */
int bg_diags_add_context(bg_diags *d, int of, bg_srcloc context, const char *msg);
/* The path of the source a position points into. */
const char *bg_diags_path(const bg_diags *d, bg_srcloc loc);
void bg_diag_error(bg_diags *d, bg_srcloc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void bg_diag_warning(bg_diags *d, bg_srcloc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void bg_diag_note(bg_diags *d, bg_srcloc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* A named warning: nothing when it is off, an error with -Werror; the
 * message ends with its name, " [-Wunused-param]". */
void bg_diag_warn(bg_diags *d, bg_warning w, bg_srcloc loc, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* The parser dropped a statement: the names written on its line (names[n])
 * and whether it was a bond that did not name both its ends. */
void bg_diags_skipped(bg_diags *d, const char *const *names, int n, int bond_unnamed);
/* 1 when an error about `name` may only follow from a dropped statement: the
 * name, its first part (M1 of M1.a) or its last (R1 of M1.R1) was written
 * on a dropped line. Name and structure errors call it before they report. */
int bg_diags_unsure(bg_diags *d, const char *name);
/* 1 when a wrong bond count of element `name` may follow from a dropped
 * statement (the name was on a dropped line, or a dropped bond named fewer
 * than two ends). */
int bg_diags_unsure_bonds(bg_diags *d, const char *name);
/* Errors so far, said or not (bg_diags_unsure): a stage that stops on an
 * error compares this count before and after. */
int bg_diags_failures(const bg_diags *d);
/* 1 when the error limit is reached: the stages may stop looking for more. */
int bg_diags_full(const bg_diags *d);
/* Prints every diagnostic in source order (stable for equal positions):
 * "FILE:LINE:COL: error: MSG", then the source line and a caret under COL;
 * after the limit, a note that more errors were not shown. */
void bg_diags_print(const bg_diags *d, FILE *out);

/* Every diagnostic in the order bg_diags_print prints them, each followed
 * by its notes (is_note 1: the notes written after it, then the chain of
 * instances its source is used from); a note's g lives only during the call. */
void bg_diags_each(const bg_diags *d, void (*fn)(void *ctx, const bg_diag *g, int is_note),
                   void *ctx);
/* How bg_diags_print writes, for the whole process: the program sets it once,
 * before any run starts, from its own stderr (a terminal or not, NO_COLOR,
 * --diagnostics-format), and never again, so runs on several threads only
 * read it. A library host that wants other settings per run prints
 * bg_diags' records itself.
 * color adds gcc's ANSI colours (the CLI: on a terminal, unless NO_COLOR);
 * json writes one JSON object a line instead of text, each error or warning
 * with its notes: {"file","line","column","severity","message","notes":[...]}. */
void bg_diags_set_output(int color, int json);
#endif
