/* SPDX-License-Identifier: BSD-3-Clause */
/* Internals of the transformations: the text editor over the model's
 * source lines, the statement printer, and what the transformations share. */
#ifndef BG_TX_INT_H
#define BG_TX_INT_H
#include "base/strbuf.h"
#include "transform/transform.h"

/* The model's text as physical lines (1-based) with edits on whole
 * statements; assembled by tx_doc_text. */
typedef struct tx_doc {
  const char *src;
  int nline;
  const char **line; /* line[i]: start of physical line i (1..nline) */
  int *len;          /* its length without the line end */
  unsigned char *cr; /* it ends in CR LF (kept as written) */
  char **repl;       /* replacement text of the statement starting at line i */
  unsigned char *drop; /* line i is left out */
  bg_strbuf *after;  /* text inserted after physical line i (0: at the top) */
  bg_strbuf head;    /* the comment that starts the file */
} tx_doc;

void tx_doc_init(tx_doc *d, const char *src, size_t len);
void tx_doc_free(tx_doc *d);
/* The last physical line of the statement that starts at line (continuations). */
int tx_stmt_end(const tx_doc *d, int line);
void tx_delete_stmt(tx_doc *d, int line);
/* text (one line, no newline) replaces the statement; the trailing comment
 * of its last line is kept. */
void tx_replace_stmt(tx_doc *d, int line, const char *text);
/* A line after the statement that starts at line (0: before the first). */
void tx_insert_after(tx_doc *d, int line, const char *text);
/* The whole new text (malloc): head, then the edited lines. */
char *tx_doc_text(const tx_doc *d);

/* Statement printer: an element as written, with its value or law replaced
 * by value (NULL: as written) and option key set to optval (NULL key: none
 * changed; a key it does not have is added). */
void tx_print_element(bg_strbuf *b, const bg_ast_stmt *s, const char *value, const char *key,
                      const char *optval);
/* A bond statement: number (0: none written), ends, arrow, the options of
 * like (nullable) copied. */
void tx_print_bond(bg_strbuf *b, int number, const char *from, bg_arrow arrow, const char *to,
                   const bg_ast_stmt *like);
/* "  [k = v, ...]" of statement s, option key's value replaced by optval
 * (added when s has no such option); nothing when there are none. */
void tx_print_options(bg_strbuf *b, const bg_ast_stmt *s, const char *key, const char *optval);

/* One transformation at work. */
typedef struct tx_ctx {
  const bg_transform_input *in;
  const bg_model *m;
  const bg_analysis *a;
  tx_doc doc;
  bg_strbuf why;     /* the header comment's text, sentence by sentence */
  bg_strbuf problem; /* why the transformation does not apply */
  int next_bond;     /* the next free bond number */
  int bonds_numbered; /* every unnumbered bond statement got its number */
  int method;        /* the causality method the new model asks for (-1: as is) */
  char made[64][64]; /* names given to new elements */
  int nmade;
} tx_ctx;

/* The top-level ELEMENT statement of element e. */
const bg_ast_stmt *tx_elem_stmt(const tx_ctx *c, int e);
/* 1 when expression root x of the model uses only numbers, params, pi and
 * functions of them (a constant for the whole run). */
int tx_expr_constant(const bg_model *m, int x);
/* A name not used by the model or by earlier calls: base, base_2, ...
 * (written into buf of n bytes). */
const char *tx_fresh_name(tx_ctx *c, const char *base, char *buf, size_t n);
/* The line of elem e's statement. */
int tx_elem_line(const tx_ctx *c, int e);
/* Bond b split in d at a new junction j: the tail's segment keeps the
 * number, the options and a stroke fixed at the tail; the head's segment
 * gets number and a stroke fixed at the head. */
void tx_split_bond(const tx_ctx *c, tx_doc *d, int b, const char *j, int number);
/* Removes the statement of bond b (numbering the others first). */
void tx_remove_bond(tx_ctx *c, int b);

/* Parses, compiles (with the run's --set) and analyses text: 0 with *m and
 * *a set (free both), -1 with *why (malloc) the first diagnostic. */
int tx_compile(const tx_ctx *c, const char *text, bg_run **out, char **why);
/* The line after which new params go: the last param statement, else the
 * model statement, else 0 (the top). */
int tx_param_line(const tx_ctx *c);
/* The line of the last bond statement. */
int tx_last_bond_line(const tx_ctx *c);
/* The time scale of estimate k of a: its time constant, 1/omega for a frequency. */
double tx_estimate_scale(const bg_analysis *a, int k);

int tx_merge_stores(tx_ctx *c);
/* The virtual inertia and its companion gyristor (tx_virtual.c): store drop
 * merged into keep through the MTF mtf (inverse: k = 1/T); -1 with
 * c->problem when it cannot be done. */
int tx_virtual_inertia(tx_ctx *c, int p, int keep, int drop, int mtf, int inverse);
/* 1 when expression x reads only numbers, params and at least one user state. */
int tx_modulus_of_coordinates(const bg_model *m, int x);
int tx_parasitic(tx_ctx *c);
int tx_relax_junction(tx_ctx *c);
#endif
