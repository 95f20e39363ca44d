/* SPDX-License-Identifier: BSD-3-Clause */
/* Model transformations of the reference chapter (docs/transform.md): a
 * model whose causal analysis shows a problem is rewritten as a new .bg
 * model in which the problem is gone, with a comment saying what changed
 * and why. The rewrite edits the model's own text (comments, layout and
 * every statement not concerned stay as written) and is checked by parsing,
 * compiling and analysing the result before anything is written.
 *   merge-stores    dependent linear stores merged into the independent
 *                   store they are tied to by constant transformers (4.4)
 *   parasitic       small C or I stores where the analysis names an
 *                   algebraic loop between resistors or a conflict (Fig. 4.5)
 *   relax-junction  an extra junction between a source and a resistor it
 *                   forces against its law, taking the violation (Fig. 4.26) */
#ifndef BG_TRANSFORM_H
#define BG_TRANSFORM_H
#include <stddef.h>

#include "base/strbuf.h"
#include "causality/causality.h"
#include "lang/lang.h"
#include "model/model.h"
#include "run/run.h"

/* The factor by which the parasitic stores' estimated time scales are
 * faster than the model's fastest estimate (docs/transform.md). */
#define BG_TX_PARASITIC_FACTOR 100.0

/* 1 when name is a transformation; list: the names, comma separated. */
int bg_transform_known(const char *name);
const char *bg_transform_names(void);

typedef struct bg_transform_input {
  const char *name;          /* the transformation */
  const char *src;           /* the model's text and length */
  size_t srclen;
  const char *path;          /* as given (diagnostics, the header comment) */
  const bg_ast *ast;         /* its syntax */
  const bg_model *model;     /* compiled */
  const bg_analysis *analysis; /* causality and causal analysis of model */
  const bg_param_override *sets; /* --set, for checking the result */
  int nsets;
} bg_transform_input;

typedef struct bg_transform_result {
  char *text;          /* the new model (malloc) */
  char *summary;       /* what changed and why, one paragraph (malloc) */
  bg_run *run;         /* the new model, loaded (with the run's --set) and analysed
                          with its own causality method: a second run */
} bg_transform_result;

/* 0 with out filled; -1 when the transformation does not apply to this
 * model: *why (malloc) says why. Never writes a file. */
int bg_transform_apply(const bg_transform_input *in, bg_transform_result *out, char **why);
void bg_transform_result_free(bg_transform_result *r);
#endif
