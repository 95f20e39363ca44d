/* SPDX-License-Identifier: BSD-3-Clause */
/* Index reduction (docs/equations.md, "Index reduction"): Pantelides'
 * algorithm on the structure of the equations (every explicit bond
 * variable substituted, params at their values, so a loop of gain +1
 * cancels exactly), then dummy derivatives (Mattsson-Soederlind) to choose
 * which states become algebraic. The result is a new bg_eqsys of index 0 or
 * 1 that evaluates through the same tape as every other system, so IDA can
 * integrate it. What was done is said in bond-graph terms: which constraint
 * (a dependent store's, the residual of a causal loop or a conflict, a
 * store's balance) was differentiated, and which stores lost their state. */
#ifndef BG_INDEXRED_H
#define BG_INDEXRED_H
#include "equations/eqsys.h"
#include "base/strbuf.h"

typedef struct bg_indexred {
  int status;         /* 1 reduced; -1 failed (message says why) */
  char *message;      /* one line: what was done, or why it failed */
  bg_eqsys *reduced;  /* owned; NULL unless status 1; borrows s's model and analysis */
  int index;          /* numeric index of the reduced system (Algorithm 4.1), or < 0 */
  int ndiff;          /* differentiations (an equation differentiated twice counts 2) */
  int structural_le1; /* failed because Pantelides differentiated nothing: the
                       * structure of the equations has index 0 or 1 */
  int nconstraint;    /* the original equations that were differentiated, in words */
  char **constraint;
  int nlost;          /* stores and states that lost their state, in words */
  char **lost;
  int ndummy;         /* the dummy derivatives ("L1.p'"): algebraic unknowns now */
  char **dummy;
} bg_indexred;

/* Reduces s (whose index is above 1). Returns out->status. out is always
 * filled and must be freed with bg_indexred_free (free the reduced system's
 * simulation results first: their names are borrowed from it). */
int bg_indexred_run(const bg_eqsys *s, bg_indexred *out);
void bg_indexred_free(bg_indexred *r);
/* The reduction in words, one item a line, each line prefixed by `indent`. */
void bg_indexred_text(const bg_indexred *r, const char *indent, bg_strbuf *out);
#endif
