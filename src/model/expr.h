/* SPDX-License-Identifier: BSD-3-Clause */
/* Evaluation of model expressions (bg_xnode trees).
 * Two evaluators share one definition of every operator and function:
 *  - bg_xeval: a direct tree walk, for one-off values (params, initial values,
 *    linearisation points); small and obviously right.
 *  - bg_prog: expressions compiled to register bytecode that evaluates with no
 *    name look-ups and no allocation; for simulation and large models. */
#ifndef BG_EXPR_H
#define BG_EXPR_H
#include "model/model.h"
#include "base/strbuf.h"

/* Values of the variables an expression may read. Any pointer may be NULL
 * when the expression cannot use that kind (reading it then yields NAN). */
typedef struct bg_xenv {
  double t;
  const double *param;  /* by param id; NULL: use m->param_value */
  const double *state;  /* user states by state id */
  const double *effort; /* by bond id */
  const double *flow;   /* by bond id */
  const double *store;  /* by element id (q of C, p of I) */
} bg_xenv;

/* Value of expression `root` of model m. Inputs are expanded in place. */
double bg_xeval(const bg_model *m, int root, const bg_xenv *env);

/* A binary or unary operator (bg_xop) applied; y is ignored for NEG/NOT. */
double bg_xop_apply(int op, double x, double y);
/* One function applied to its arguments (shared by both evaluators). */
double bg_func_apply(int fn, const double *args, int nargs);
/* Table look-up: linear interpolation, clamped at the ends. */
double bg_table_lookup(const bg_model *m, int table, double x);
/* d table(x)/dx: the slope of the segment holding x (right-continuous at
 * breakpoints), 0 where the table is clamped. */
double bg_table_slope(const bg_model *m, int table, double x);
/* Name and arity of a function; arity -1 if not a function name. */
const char *bg_func_name(int fn);
int bg_func_lookup(const char *name, int *min_args, int *max_args);

/* Appends expression `root` as readable text with minimal parentheses:
 * params, inputs and states by name, bond variables as e7/f7, store states
 * as C1.q / L1.p, functions by name, tables as table(x, #k). */
void bg_xprint(const bg_model *m, int root, bg_strbuf *out);

/* Where each kind of variable sits in the flat input vector of a program.
 * An entry -1 means "not available" (reading it is a compile-time error of
 * the caller: bg_prog_compile fails with BG_FATAL). Arrays are borrowed. */
typedef struct bg_slotmap {
  int time_slot;
  const int *param_slot;  /* by param id; NULL: params are folded to constants */
  const int *state_slot;  /* by user state id */
  const int *effort_slot; /* by bond id */
  const int *flow_slot;   /* by bond id */
  const int *store_slot;  /* by element id */
} bg_slotmap;

typedef struct bg_prog bg_prog;

/* Compiles the expressions roots[0..nroots) into one program whose result k
 * is written to out[k]. Common subexpressions are not merged (yet); constant
 * subtrees are folded. The caller owns the program (bg_prog_free); m is
 * borrowed (tables are read from it at run time) and must outlive it.
 * map is nullable (no variables: every expression must fold). */
bg_prog *bg_prog_compile(const bg_model *m, const int *roots, int nroots,
                         const bg_slotmap *map);
/* Runs the program: reads vars (laid out per the slot map), writes out.
 * No allocation, no name look-up; thread-compatible (scratch lives in p:
 * use one program per thread). */
void bg_prog_eval(bg_prog *p, const double *vars, double *out);
/* Length of the code (the data entries of a fused sum count as instructions). */
int bg_prog_ninstr(const bg_prog *p);
void bg_prog_free(bg_prog *p);
#endif
