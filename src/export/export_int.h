/* SPDX-License-Identifier: BSD-3-Clause */
/* Shared by the exporters: the evaluation tape of an export build written in
 * a target language from per-language templates, and identifiers. */
#ifndef BG_EXPORT_INT_H
#define BG_EXPORT_INT_H
#include "base/strbuf.h"
#include "equations/equations.h"
#include "export/export.h"
#include "model/model.h"

/* How a language writes the tape's operations. Templates use %0 %1 %2 for
 * the argument values and %t for a table number (0-based). */
typedef struct bg_xlang {
  int base;                   /* index of the first array element: 0 or 1 */
  const char *open, *close;   /* array subscript brackets */
  const char *stmt_end;       /* ";" or "" */
  const char *indent;
  const char *fn[BG_FN_COUNT];
  const char *neg, *not_, *and_, *or_, *pow_;
  const char *div_;            /* %0 / %1, or a helper where the language raises at 0 */
  const char *cmp;            /* comparison: %0 OP %1 as a number 0/1; %o is OP */
  const char *table;
  const char *eq, *ne;        /* spelling of == and != */
  const char *const *reserved; /* names a parameter may not take (export_names.c) */
} bg_xlang;

/* ---- export_names.c: identifiers clear of each language's reserved names */
extern const char *const bg_reserved_c[], *const bg_reserved_python[], *const bg_reserved_octave[],
    *const bg_reserved_modelica[];
/* 1 when id is in the NULL-terminated list. */
int bg_export_reserved(const char *const *reserved, const char *id);
/* bg_export_ident, then a trailing '_' when the result is reserved. */
void bg_export_ident_in(const char *const *reserved, const char *name, char *buf, size_t n);
/* 1 when some independent param's identifier in L differs from its name
 * (the export then writes a table of the original names). */
int bg_export_params_renamed(const bg_xlang *L, const bg_eqsys *s);

extern const bg_xlang bg_xlang_c, bg_xlang_python, bg_xlang_octave;

/* arr[k] in the language ("v[3]", "v(4)"). */
void bg_xl_slot(const bg_xlang *L, bg_strbuf *o, const char *arr, int k);
/* A number literal that reads back exactly (inf and nan spelled per language). */
void bg_xl_num(const bg_xlang *L, bg_strbuf *o, double c);
/* Statements that set every constant slot and every param slot (from the
 * parameter record: pfmt is a printf format with %s for the field name,
 * e.g. "p->%s", "p['%s']", "p.%s"). */
void bg_xl_constants(const bg_xlang *L, const bg_eqsys *s, const char *arr, const char *pfmt,
                     bg_strbuf *o);
/* Statements for code [c0, c1). */
void bg_xl_code(const bg_xlang *L, const bg_eqsys *s, int c0, int c1, const char *arr, bg_strbuf *o);


/* ---- export_runs.c: the repeated patterns of a generated C function,
 * written as loops over tables of slots (docs/export.md, "Compile time"). */
typedef struct bg_xstmts {
  bg_strbuf text; /* the statements' text, one after another */
  size_t *at;     /* statement k is text [at[k], at[k + 1]) */
  int n, cap;
} bg_xstmts;
/* Ends statement n: the text appended since the previous end. */
void bg_xstmts_end(bg_xstmts *t);
void bg_xstmts_free(bg_xstmts *t);
/* A piece of the function: statements [start, start + period * reps), a
 * pattern of `period` statements repeated `reps` times (reps 1: straight). */
typedef struct bg_xrun {
  int start, period, reps;
} bg_xrun;
/* The pieces in order (malloc'd): runs of one pattern with at least 4
 * repetitions covering at least 64 statements, and the straight code
 * between them. Two statements share a pattern when their texts are equal
 * but for the numbers N of their slot references v[N], d[N] and y0[N] and
 * of their events and root functions (export_runs.c, parameter). */
void bg_xruns_plan(const bg_xstmts *t, bg_xrun **runs, int *nruns);
/* Statements [k0, k1) as they are. */
void bg_xruns_straight(const bg_xstmts *t, int k0, int k1, bg_strbuf *c);
/* A run's table `static const int tab[reps][K]`: row m the slot numbers of
 * repetition m in text order; and its loop, row by row, each statement with
 * x[j] for each of those numbers. */
void bg_xruns_table(const bg_xstmts *t, const bg_xrun *r, const char *tab, bg_strbuf *c);
void bg_xruns_loop(const bg_xstmts *t, const bg_xrun *r, const char *tab, bg_strbuf *c);
/* Text of one statement a line as a function's body: its runs as loops
 * (their tables, name_<piece>, into tables, which go before the function),
 * the rest as it is (into body). */
void bg_xruns_lines(const char *text, const char *name, bg_strbuf *tables, bg_strbuf *body);

/* ---- export_events.c (and the tape's part in export_tape.c): state events in the C and Python exports (docs/export.md,
 * "State events"): the switching instructions through their modes, the root
 * functions, and the function that applies an event, as eqsys_events.c and
 * the tape evaluate them inside bgdraw. */
/* The kinds of switching instruction (export_tape.c); the numbers are the
 * runtime's (BG_K_* in C, the Python helpers' k). */
enum { K_LT, K_LE, K_GT, K_GE, K_TABLE, K_ABS, K_SIGN, K_STEP, K_RAMP, K_MIN, K_MAX, K_PULSE, K_SAT,
       K_HYST, K_STICK, K_FLOOR, K_CEIL };
int bg_xev_kind(const bg_eqsys *s, int e);
/* "K, T, [MODE, ]x, y, z" of event e (mode: a format with %d for e, or NULL). */
void bg_xev_args(const bg_xlang *L, const bg_eqsys *s, int e, const char *arr, const char *mode, bg_strbuf *o);
/* C: the runtime (kinds, root functions, modes, held values and slopes)
 * before the tape's functions; the modes struct and API in the header; the
 * derivative of event e when its mode is held ("if (...) d[o] = ...; else");
 * the API functions (roots, modes_start, event). */
void bg_xev_c_runtime(const bg_eqsys *s, const char *P, bg_strbuf *c);
void bg_xev_c_header(const bg_eqsys *s, const char *P, const char *U, bg_strbuf *h);
void bg_xev_c_der(const bg_eqsys *s, int e, bg_strbuf *c);
void bg_xev_c_api(const bg_eqsys *s, const char *P, const char *U, bg_strbuf *c);
/* Python: the runtime and the API (Modes, modes_start, roots, event) and
 * simulate() as a solve_ivp driver that restarts at each event. */
void bg_xev_python(const bg_eqsys *s, bg_strbuf *o);

/* Param k as an identifier of the exported record in language L (its name
 * with every character outside [A-Za-z0-9_] made '_', a trailing '_' when
 * L reserves it; names are unique in a model, so are these unless two meet
 * after that: then "_<k>" is added). */
const char *bg_export_param_ident(const bg_xlang *L, const bg_eqsys *s, int k, char *buf, size_t n);
/* Any name as an identifier, same rule. */
void bg_export_ident(const char *name, char *buf, size_t n);
/* Number of independent params (those the parameter record holds). */
int bg_export_nparams(const bg_eqsys *s);
#endif
