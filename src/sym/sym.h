/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_sym: a small symbolic expression layer for printing, symbolic
 * elimination and differentiation (not for simulation: that evaluates the
 * tape of eqsys_tape.c).
 *
 * Nodes are hash-consed: building the same expression twice gives the same
 * id, so equality of ids is structural equality and shared subexpressions
 * are stored once. Every constructor returns a canonical, simplified form:
 *  - constants folded (functions of numbers included); params stay symbols;
 *  - sums are  c0 + sum w_i t_i  with numeric weights, like terms collected,
 *    nested sums flattened, numeric multiples of sums distributed, 0 dropped;
 *  - products are  c * prod b_i^e_i  with numeric exponents, equal bases
 *    merged (x * x^-1 = 1), nested products flattened, 1 and x^0 dropped;
 *  - a sum used as a factor has its first term positive (signs normalised:
 *    1/(1 - n) is -1/(n - 1)), so equal factors meet and cancel;
 *  - terms and factors in a fixed structural order (numbers, params, inputs,
 *    aliases, t, unknowns, bond variables, powers, functions, products, sums), which
 *    does not depend on the order of construction.
 * Numeric coefficients are combined exactly where IEEE arithmetic is exact
 * (products of +-1 and moduli); a sum of numbers whose magnitude is below
 * 16 eps times the sum of magnitudes is 0, so unity-gain cancellations are
 * exact zeros (docs/equations.md).
 *
 * Ownership: a context owns its nodes; ids are valid until bg_sym_free.
 * The model is borrowed. Not thread-safe. Recursion follows expression
 * depth (bounded by the parser's nesting limit and by the caller's sizes). */
#ifndef BG_SYM_H
#define BG_SYM_H
#include "model/model.h"
#include "base/strbuf.h"

/* Node kinds, in the structural order used for sorting. */
enum {
  SYM_NUM,    /* c */
  SYM_PARAM,  /* ref = param id */
  SYM_INPUT,  /* ref = input id */
  SYM_ALIAS,  /* ref = alias: an opaque name for an expression (T(phi) of an MTF) */
  SYM_DALIAS, /* ref = partial derivative of an alias with respect to a leaf */
  SYM_T,      /* time */
  SYM_Y,      /* ref = unknown index (eqsys) */
  SYM_YP,     /* ref = unknown index: its time derivative */
  SYM_SIG,    /* ref = signal 2*bond (effort) or 2*bond + 1 (flow) */
  SYM_POW,    /* arg0 ^ arg1 (exponent not a number) */
  SYM_CALL,   /* ref = bg_func, args */
  SYM_TABLE,  /* ref = table id, arg0 = abscissa */
  SYM_DTABLE, /* slope of table ref at arg0 */
  SYM_OP,     /* ref = bg_xop (comparison, logic, NOT), 1 or 2 args */
  SYM_MUL,    /* c * prod arg_i ^ w_i */
  SYM_ADD     /* c + sum w_i * arg_i */
};

typedef struct bg_symnode {
  int kind, ref, n, adr; /* args arg[adr .. adr+n), weights w[adr .. adr+n) */
  double c;
  unsigned h;
} bg_symnode;

typedef struct bg_sym {
  const bg_model *m;
  bg_symnode *node;
  int nnode, capnode;
  int *arg;
  double *w;
  int narg, caparg;
  int *tab; /* open-addressing hash table of node ids, -1 empty */
  int captab;
  /* per-call scratch, stamped by generation */
  int *memo;
  unsigned *stamp;
  double *val;
  int capmemo;
  unsigned gen;
  int max_nodes; /* soft limit: constructors keep working, bg_sym_full() says so */
  /* Work budget (deterministic, no clock): every node interned, every step
   * of a structural comparison and every node an operation visits costs one
   * unit. 0: unlimited. Past it `over` is set: the operations return at once
   * with meaningless results and bg_sym_full() is 1, so the caller drops all
   * it built (docs/equations.md "Work budget"). */
  long work, budget;
  int over;
  /* aliases: expression by ref (-1 none); partial derivatives (alias ref, leaf, expression) */
  int nalias, *alias_expr;
  int ndalias, *dalias_of, *dalias_var, *dalias_expr;
} bg_sym;

bg_sym *bg_sym_new(const bg_model *m);
void bg_sym_free(bg_sym *S);
/* 1 when the context holds more than S->max_nodes nodes or its work budget
 * ran out (callers give up and drop every result of the context). */
int bg_sym_full(const bg_sym *S);
/* 1 when the work budget ran out (S->over). */
int bg_sym_over(const bg_sym *S);
/* The budget of a context whose results may be dropped: symbolic
 * elimination, index reduction. About a twentieth of a second of work; the
 * examples need at most 1 500 units, generated 2000-bond chains, ladders
 * and grids 100 000 (docs/equations.md "Work budget"). */
#define BG_SYM_BUDGET 2000000L
#define BG_SYM_BUDGET_WORDS "2 million" /* the same, for messages */
/* Counts n units of work against the budget. */
void bg_sym_spend(bg_sym *S, long n);

/* ---------------------------------------------------------------- building */
int bg_sym_num(bg_sym *S, double c);
int bg_sym_leaf(bg_sym *S, int kind, int ref);
int bg_sym_add(bg_sym *S, int a, int b);
int bg_sym_sub(bg_sym *S, int a, int b);
int bg_sym_mul(bg_sym *S, int a, int b);
int bg_sym_div(bg_sym *S, int a, int b);
int bg_sym_neg(bg_sym *S, int a);
int bg_sym_scale(bg_sym *S, double c, int a);
int bg_sym_powc(bg_sym *S, int a, double e); /* a^e, e a number */
int bg_sym_pow(bg_sym *S, int a, int b);
/* c0 + sum w[k] * t[k]; c * prod b[k]^e[k] (the general constructors). */
int bg_sym_sum(bg_sym *S, double c0, int n, const int *t, const double *w);
int bg_sym_prod(bg_sym *S, double c, int n, const int *b, const double *e);
int bg_sym_call(bg_sym *S, int fn, int nargs, const int *args);
int bg_sym_op(bg_sym *S, int op, int a, int b); /* b ignored for NOT */
int bg_sym_table(bg_sym *S, int table, int x);
int bg_sym_dtable(bg_sym *S, int table, int x);

/* An opaque leaf SYM_ALIAS with the caller's ref (>= 0, e.g. an element
 * id) standing for expression e (its value, and derivatives through it):
 * printed by name, so T*T merges into T^2 and 4.53 reads as in the
 * reference. e must not read bond variables (substitution does not see
 * inside an alias). Returns the leaf. */
int bg_sym_alias(bg_sym *S, int ref, int e);
/* For a SYM_DALIAS leaf's ref: the alias' ref and the leaf id. */
void bg_sym_dalias_info(const bg_sym *S, int ref, int *alias, int *var);

/* A model expression; user states and store states become SYM_Y leaves
 * through state_y[state id] and store_y[element id] (-1: not an unknown),
 * bond variables SYM_SIG leaves, inputs SYM_INPUT leaves. */
int bg_sym_from_x(bg_sym *S, int root, const int *state_y, const int *store_y);


/* ---------------------------------------------------------------- operations */
/* Replaces leaves: f(ctx, kind, ref) returns the replacement id, or -1 to
 * keep the leaf. The result is simplified. */
typedef int (*bg_sym_substfn)(void *ctx, int kind, int ref);
int bg_sym_subst(bg_sym *S, int a, bg_sym_substfn f, void *ctx);
/* d a / d x for a leaf x (SYM_Y, SYM_YP, SYM_T, SYM_SIG, SYM_PARAM); inputs
 * are differentiated through their expressions with respect to t.
 * Piecewise-constant functions and comparisons have derivative 0; if, min,
 * max and sat take the derivative of the active branch (as an `if`). */
int bg_sym_diff(bg_sym *S, int a, int x);
/* Products of sums with small positive integer powers multiplied out and
 * like terms collected (at most max_terms terms; beyond that a is returned). */
int bg_sym_expand(bg_sym *S, int a, int max_terms);
/* A sum over one common denominator made of the sum denominators all its
 * terms have (every: all its sum denominators), the numerator expanded and
 * cancelled by what divides it; sum denominators are made rational first
 * (1/(1 + m T^2/J) is J/(J + m T^2)): n F/(n - 1) - p/(n - 1) becomes
 * (n F - p)/(n - 1). A product gets its sum denominators made rational. */
int bg_sym_together(bg_sym *S, int a, int every);
/* 1 when a contains a leaf whose id is marked (mark has `nmark` entries,
 * indexed by node id). */
int bg_sym_depends(bg_sym *S, int a, const unsigned char *mark, int nmark);
/* 1 when a piecewise function, comparison or table of a reads a marked leaf. */
int bg_sym_piecewise(bg_sym *S, int a, const unsigned char *mark, int nmark);
/* A sum grouped by the part of each term that reads more than params and
 * numbers: sum_g c_g(params) * v_g, each coefficient c_g over one common
 * denominator with common factors cancelled (1/I0 - n/(I0 (n - 1)) is
 * -1/(I0 (n - 1))). Other expressions are returned as they are. */
int bg_sym_collect(bg_sym *S, int a);
/* Every sum inside a, bottom-up, over one common denominator (all of them,
 * monomials included), numerators expanded, common monomial factors and
 * integer content cancelled. For expressions in params only. */
int bg_sym_rational(bg_sym *S, int a);
/* The marked leaves a contains (distinct, at most max written to out;
 * returns how many there are, possibly more than max). */
int bg_sym_leaves(bg_sym *S, int a, const unsigned char *mark, int nmark, int *out, int max);
/* Number of nodes reachable from a (the size of the DAG). */
int bg_sym_size(bg_sym *S, int a);

/* ---------------------------------------------------------------- evaluation */
typedef struct bg_symenv {
  double t;
  const double *y, *yp; /* by unknown index; NULL reads 0 */
  const double *sig;    /* by signal; NULL reads NAN */
  const double *param;  /* by param id; NULL: the model's values */
} bg_symenv;
/* Value of a. Sums follow the exact-cancellation rule; products evaluate
 * numerator and denominator separately (k / R is k/R, not k * (1/R)). */
double bg_sym_eval(bg_sym *S, int a, const bg_symenv *env);

/* ---------------------------------------------------------------- printing */
/* The printers' forms: text, LaTeX, presentation MathML (the content of a
 * <math> element: <mrow>s, <mfrac>, <msup>, <msqrt>; names from the caller). */
enum { BG_SYM_TEXT, BG_SYM_LATEX, BG_SYM_MATHML };
/* Names of leaves: unknowns, their derivatives and bond variables are named
 * by the caller (params, inputs and t by the model). latex: a BG_SYM_* form. */
typedef void (*bg_sym_namefn)(void *ctx, int kind, int ref, int latex, bg_strbuf *out);
void bg_sym_print(bg_sym *S, int a, int mode, bg_sym_namefn name, void *ctx, bg_strbuf *out);
/* Model expression `root` simplified and printed as text (sym_xprint.c):
 * store states C1.q / L1.p, user states and params by name, bond
 * variables e7 / f7. */
void bg_sym_print_model_expr(const bg_model *m, int root, bg_strbuf *out);
#endif
