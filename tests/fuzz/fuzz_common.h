/* SPDX-License-Identifier: BSD-3-Clause */
/* Shared by the fuzz targets (tests/fuzz/README.md): the input bytes are a
 * model file; each target runs one part of bgdraw's pipeline on it as the
 * CLI does, and must never crash, hang, leak its own memory or trip a
 * sanitizer. A target ignores inputs above FUZZ_MAX_LEN (libFuzzer's
 * -max_len does the same) so that every run stays short. */
#ifndef BG_FUZZ_COMMON_H
#define BG_FUZZ_COMMON_H
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "analysis/analysis.h"
#include "base/diag.h"
#include "base/strbuf.h"
#include "causality/causality.h"
#include "equations/equations.h"
#include "lang/lang.h"
#include "model/model.h"

enum { FUZZ_MAX_LEN = 8192 };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

typedef struct fuzz_run {
  char *src;
  bg_diags dg;
  bg_ast *ast; /* kept for the transformations (fuzz_equations) */
  bg_model *model;
  bg_analysis analysis;
  int analysed;
  bg_index_facts facts; /* the reduced form and numeric index, as the run keeps them */
} fuzz_run;

/* Parses, compiles, assigns causality and analyses; 0 when the model is
 * valid (the analysis is then filled), -1 for a model with errors. The
 * diagnostics are printed to a memory buffer, as the CLI prints them. */
static inline int fuzz_load(fuzz_run *f, const uint8_t *data, size_t size) {
  memset(f, 0, sizeof *f);
  f->src = malloc(size + 1);
  if (!f->src) return -1;
  memcpy(f->src, data, size);
  f->src[size] = '\0';
  /* a path whose folder does not exist: relative table files are not found */
  const char *path = "/nonexistent-bgdraw-fuzz/model.bg";
  bg_diags_init(&f->dg, path, f->src, size);
  bg_ast *ast = bg_parse_string(path, f->src, size, &f->dg);
  /* as bg_run_load: after syntax errors the statements that parsed are compiled too */
  if (ast && (!f->dg.nerrors || (f->dg.nskipped && !bg_diags_full(&f->dg))))
    f->model = bg_model_compile(ast, NULL, 0, &f->dg);
  f->ast = ast;
  char *text = NULL;
  size_t len = 0;
  FILE *mem = open_memstream(&text, &len);
  if (mem) {
    bg_diags_print(&f->dg, mem);
    fclose(mem);
  }
  free(text);
  if (!f->model || f->dg.nerrors) return -1;
  bg_analysis_init(&f->analysis, f->model);
  f->analysed = 1;
  bg_causality_assign(f->model, f->model->method, &f->analysis, &f->dg);
  bg_analysis_limits lim = {50, 50};
  bg_analysis_run(f->model, &f->analysis, &lim);
  bg_strbuf sb = {0};
  bg_model_summary(f->model, &sb);
  bg_analysis_summary(f->model, &f->analysis, &sb);
  bg_sb_free(&sb);
  return 0;
}

/* The equations of a model fuzz_load accepted (NULL when they cannot be
 * built), their reduced form recorded in the analysis as the CLI does. */
static inline bg_eqsys *fuzz_eqsys(fuzz_run *f, size_t size) {
  bg_diags eqd;
  bg_diags_init(&eqd, "fuzz", f->src, size);
  bg_eqsys *s = bg_eqsys_build(f->model, &f->analysis, &eqd);
  bg_diags_free(&eqd);
  if (s) f->facts.reduced_form = bg_eqred_form(s, &f->facts.reduced_note);
  return s;
}

static inline void fuzz_free(fuzz_run *f) {
  if (f->analysed) bg_analysis_free(&f->analysis);
  if (f->model) bg_model_free(f->model);
  bg_ast_free(f->ast);
  bg_diags_free(&f->dg);
  free(f->src);
}
#endif
