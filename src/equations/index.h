/* SPDX-License-Identifier: BSD-3-Clause */
/* Numeric index of the equations linearised at the initial point (Algorithm 4.1
 * of the reference, docs/equations.md): regularity of the pencil first, then
 * the shuffle algorithm with rank decisions by SVD on equilibrated matrices;
 * eigenvalues of the linearised model for index 0 and 1. Dense: fine up to a
 * few thousand unknowns. */
#ifndef BG_INDEX_H
#define BG_INDEX_H
#include "equations/eqsys.h"
#include "model/model.h"
#include "causality/causality.h"
#include "base/strbuf.h"

#define BG_INDEX_SINGULAR (-1)  /* singular pencil: no (unique) solution */
#define BG_INDEX_FAILED (-2)    /* the equations could not be evaluated */

typedef struct bg_index_result {
  int index;        /* 0, 1, 2, ... or BG_INDEX_SINGULAR / BG_INDEX_FAILED */
  int n;            /* unknowns */
  int nhist;        /* rank history, one text line per decision */
  char **hist;
  int neig;         /* finite generalized eigenvalues, sorted by (re, im) */
  double *eig_re, *eig_im;
  char *message;    /* one line: what was found and why */
} bg_index_result;

/* Linearises at t0 and consistent initial values (bg_eqsys_initial), then
 * runs the algorithm. Returns out->index. The caller frees with bg_index_free. */
int bg_index_compute(bg_eqsys *s, const bg_model *m, bg_index_result *out);
/* The same on a given pencil A x' + B x (column-major n x n; copied). */
int bg_index_pencil(const double *A, const double *B, int n, bg_index_result *out);
void bg_index_free(bg_index_result *r);

struct bg_indexred;
/* What the equations stage found about the index beyond the causal
 * prediction (bg_analysis): the numeric index, the reduced form and the
 * index reduction. The run (src/run) fills it as those stages finish; the
 * simulation's refusals, the JSON and the report read it. Everything is
 * borrowed; {0}: nothing computed. */
typedef struct bg_index_facts {
  const bg_index_result *numeric;  /* NULL: not computed */
  const char *numeric_skipped;     /* why not computed (too many unknowns); nullable */
  const char *disagreement;        /* the prediction and the numeric index disagree: why */
  const char *reduced_form;        /* "ode" / "dae" after symbolic elimination; NULL: not done */
  const char *reduced_note;        /* why reduced_form is NULL although the equations were
                                      formed (the symbolic work budget ran out); else NULL */
  const struct bg_indexred *reduction; /* index reduction; NULL: not tried */
} bg_index_facts;
/* Algorithm 4.1 ran to a verdict (an index, or a singular pencil). */
int bg_index_facts_numeric_set(const bg_index_facts *f);
/* What eigenvalue k means for stability. "Zero" and "undamped" are decided
 * relative to the largest magnitude (BG_EIG_ZERO_REL of it): a conserved
 * quantity's eigenvalue comes out as ~1e-16 of the largest, of either sign,
 * and is neither a time constant nor unstable. */
#define BG_EIG_ZERO_REL 1e-10
typedef enum { BG_EIG_DECAYING, BG_EIG_ZERO, BG_EIG_UNDAMPED, BG_EIG_UNSTABLE } bg_eig_kind;
bg_eig_kind bg_index_eig_kind(const bg_index_result *r, int k);
const char *bg_index_eig_word(bg_eig_kind kind); /* "zero (a conserved quantity)", ... */
/* When the index predicted from the causal pattern (a->index_predicted) and
 * the numeric index r disagree: a malloc'd warning saying which one to use
 * and why (issue 12, defect 8); NULL when they agree or one is unknown. */
char *bg_index_disagreement(const bg_analysis *a, const bg_index_result *r);
/* The rank history and the eigenvalues as report text. */
void bg_index_report(const bg_index_result *r, bg_strbuf *out);
#endif
