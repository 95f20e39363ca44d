/* SPDX-License-Identifier: BSD-3-Clause */
/* The run: one model's way through the pipeline, the front door every front
 * end uses (the command line, libbgdraw, the transformations' second model,
 * the tests). It holds the source and its diagnostics, the model, the
 * causality and causal analysis, the equations, the numeric index, the index
 * reduction, the simulation and the linear analysis. Each stage runs at most
 * once, when something asks for it (bg_run_need), after the stages it needs,
 * and its result stays in the run; so every front end computes the same
 * things the same way (docs/architecture.md, "The run").
 *
 * A run is used by one thread at a time; two runs share nothing and may run
 * on two threads at once. */
#ifndef BG_RUN_H
#define BG_RUN_H
#include <stddef.h>

#include "base/diag.h"
#include "base/log.h"
#include "causality/causality.h"
#include "equations/equations.h"
#include "import/import.h"
#include "lang/lang.h"
#include "linear/linear.h"
#include "model/model.h"
#include "simulate/simulate.h"

/* The stages in pipeline order; each needs the ones before it, except
 * LINEAR, which needs only ANALYSIS (it builds its own equations). */
typedef enum bg_stage {
  BG_STAGE_MODEL = 0,  /* read, parsed, compiled: model (diagnostics in dg) */
  BG_STAGE_ANALYSIS,   /* causality and the causal analysis: analysis */
  BG_STAGE_EQUATIONS,  /* the equation system and its reduced form, or why not */
  BG_STAGE_INDEX,      /* the numeric index (not above BG_RUN_INDEX_MAX unknowns) */
  BG_STAGE_REDUCTION,  /* index reduction, where the index asks for it */
  BG_STAGE_SIMULATION, /* the model's simulate block (and its verification) */
  BG_STAGE_LINEAR,     /* the linear analysis */
  BG_STAGE_COUNT
} bg_stage;

/* Above this many unknowns the dense numeric index (SVDs and a generalised
 * eigenvalue problem, cubic: about 1 s at 500 in a Release build, 5 s at
 * 1000) is skipped, and the run says so (docs/cli.md). */
enum { BG_RUN_INDEX_MAX = 500 };

typedef struct bg_run_opts {
  int method;                    /* bg_method; -1: the model's own (else SCAP) */
  const bg_param_override *sets; /* --set: params overridden (copied) */
  int nsets;
  int max_list;   /* listing cap of paths and loops; 0: the analysis' default */
  int max_errors; /* diagnostics kept at most; 0: no limit (default BG_DIAG_MAX_ERRORS) */
  int verify;     /* the simulation is verified at tighter tolerances (--verify) */
  int keep_ast;   /* the syntax stays in the run (the transformations edit it) */
  unsigned warn_off; /* named warnings not reported: bit per bg_warning (-Wno-NAME) */
  int werror;        /* named warnings are errors (-Werror) */
  bg_log log;     /* progress, notes and warnings; {0}: silent */
  /* The installed component library's folder, where `use "NAME.bg"` looks
   * after the model's folder and $BGDRAW_PATH's (docs/format.md, "Files");
   * borrowed, nullable. */
  const char *lib_dir;
} bg_run_opts;

typedef struct bg_run {
  bg_run_opts o;
  bg_param_override *sets; /* o.sets copied (names owned) */
  char *name;              /* the source's name in diagnostics */
  char *src;
  size_t srclen;
  bg_diags dg;
  bg_import_format imported; /* src is another tool's model (src/import) ... */
  bg_import_result import;   /* ... read as this .bg text (what -o m.bg writes with --import) */
  bg_ast *ast;             /* with o.keep_ast */
  bg_model *model;         /* NULL until loaded, or when it has errors */
  bg_analysis analysis;
  bg_eqsys *eqsys;         /* NULL when the equations could not be formed */
  char *eqsys_problem;     /* why not, in words */
  bg_index_result index;   /* with done[BG_STAGE_INDEX] and index_computed */
  int index_computed;
  char *index_skipped;     /* why the numeric index was not computed; nullable */
  char *index_disagreement;/* the prediction and the numeric index disagree: why */
  bg_indexred ired;        /* with ired_tried */
  int ired_tried;
  bg_index_facts facts;    /* what the stages above found about the index */
  bg_simresult sim;        /* with done[BG_STAGE_SIMULATION] */
  int sim_status;          /* bg_simulate: 0 ok, 1 refused, 2 failed */
  bg_linear lin;           /* with done[BG_STAGE_LINEAR] */
  unsigned char done[BG_STAGE_COUNT];
} bg_run;

/* Defaults: the model's causality method, the default caps and error limit. */
void bg_run_opts_init(bg_run_opts *o);
/* A new run (o NULL: defaults); nothing is loaded yet. */
bg_run *bg_run_new(const bg_run_opts *o);
/* Loads model text (the run takes text, malloc'd, NUL at len); name is the
 * source's name in diagnostics and gives the model's default name. 0, or
 * -1 with the errors in r->dg. A run is loaded once. */
int bg_run_load(bg_run *r, const char *name, char *text, size_t len);
/* The same from a file (its path is its name) or a copy of a string. */
int bg_run_load_file(bg_run *r, const char *path);
int bg_run_load_string(bg_run *r, const char *name, const char *text);
/* Runs stage s and every stage it needs, each at most once. 0 when s has
 * run (its result may be a refusal: look at the stage's record); -1 when
 * the model did not load. */
int bg_run_need(bg_run *r, bg_stage s);
int bg_run_has(const bg_run *r, bg_stage s);
void bg_run_free(bg_run *r);
#endif
