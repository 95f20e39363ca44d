/* Diagnostics: user-facing errors and warnings with source positions,
 * printed like a C compiler's ("file:line:col: error: msg", the line, a caret). */
#ifndef BG_DIAG_H
#define BG_DIAG_H
#include <stdio.h>

/* A position in the model file; line and col count from 1 (col in bytes). */
typedef struct bg_srcloc {
  int line, col;
} bg_srcloc;

typedef enum { BG_SEV_ERROR, BG_SEV_WARNING, BG_SEV_NOTE } bg_severity;

typedef struct bg_diag {
  bg_severity sev;
  bg_srcloc loc; /* line 0: no position (a whole-file or command-line problem) */
  char *msg;     /* owned */
} bg_diag;

typedef struct bg_diags {
  const char *file; /* as given on the command line; borrowed */
  const char *src;  /* the whole source text, for echoing lines; borrowed, nullable */
  size_t srclen;
  bg_diag *items; /* owned */
  int n, cap;
  int nerrors, nwarnings;
  int max_errors;  /* errors kept and printed at most (0: no limit); bg_diags_init sets
                      BG_DIAG_MAX_ERRORS */
  int dropped;     /* errors beyond max_errors: counted, not kept */
  int dropping;    /* the last error was dropped, and so are its notes */
} bg_diags;

/* The default error limit (--max-errors changes it; docs/cli.md). */
enum { BG_DIAG_MAX_ERRORS = 100 };

void bg_diags_init(bg_diags *d, const char *file, const char *src, size_t srclen);
void bg_diags_free(bg_diags *d);
void bg_diag_error(bg_diags *d, bg_srcloc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void bg_diag_warning(bg_diags *d, bg_srcloc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void bg_diag_note(bg_diags *d, bg_srcloc loc, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* 1 when the error limit is reached: the stages may stop looking for more. */
int bg_diags_full(const bg_diags *d);
/* Prints every diagnostic in source order (stable for equal positions):
 * "FILE:LINE:COL: error: MSG", then the source line and a caret under COL;
 * after the limit, a note that more errors were not shown. */
void bg_diags_print(const bg_diags *d, FILE *out);

/* How bg_diags_print writes, for the whole process (the CLI sets it once):
 * color adds gcc's ANSI colours (the CLI: on a terminal, unless NO_COLOR);
 * json writes one JSON object a line instead of text, each error or warning
 * with its notes: {"file","line","column","severity","message","notes":[...]}. */
void bg_diags_set_output(int color, int json);
#endif
