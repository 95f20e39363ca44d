/* SPDX-License-Identifier: BSD-3-Clause */
/* Internal to the model compiler (model*.c): the state of one compile.
 * Arrays of the model grow with malloc while compiling and are moved into
 * the model's arena at the end. */
#ifndef BG_MODEL_BUILD_H
#define BG_MODEL_BUILD_H
#include "base/strindex.h"
#include "lang/lang.h"
#include "model/model.h"

/* What a name in the shared namespace is. */
typedef enum { NS_ELEM, NS_PARAM, NS_INPUT, NS_STATE, NS_DETECTOR, NS_FIELD } ns_kind;
/* "an element", "a param", ... by ns_kind, for messages. */
extern const char *const bg_ns_what[6];

typedef struct ns_entry {
  const char *name;
  ns_kind kind;
  int id;        /* element id, param file index, input id, state id */
  bg_srcloc loc; /* of the declaration */
} ns_entry;

/* What an expression being compiled may read. */
enum {
  ALLOW_TIME = 1,   /* t */
  ALLOW_INPUT = 2,  /* inputs (with id < input_limit) */
  ALLOW_MODEL = 4   /* states, bond and element variables */
};

typedef struct bg_build {
  bg_model *m;
  const bg_ast *ast;
  bg_diags *dg;
#define BG_X_CAP(type, name, count) int name;
  struct { BG_MODEL_ARRAYS(BG_X_CAP) } cap;
#undef BG_X_CAP
  /* namespace: entries in declaration order, their names hashed */
  ns_entry *ns;
  int nns, nscap;
  bg_strindex names;
  const bg_ast_stmt **elem_stmt; /* per element id */
  int elem_stmt_cap;
  int *param_id;                 /* param file index -> param id (dependency order) */
  /* the expression being compiled */
  int allow;          /* ALLOW_* */
  const char *what;   /* "a param", ... for messages */
  int input_limit;    /* inputs with id < this may be read */
  int elem;           /* element whose value/law is compiled (signals), or -1 */
  int law_elem;       /* element whose law is compiled (own e, f, q, p), or -1 */
  int field;          /* field whose law or energy is compiled (port variables), or -1 */
  char law_lhs;       /* the law's left-hand side letter */
  const char *modvar; /* first model variable met (for "modulated by ...") */
  bg_srcloc modvar_loc;
  const char *base_dir; /* the model file's directory, for table CSV files */
  unsigned char *elem_guessed; /* per element: the "did you mean" of a misspelled bond end;
                                 its bond count is then not reported (a consequence) */
  const char **param_named;   /* elements refused for a param's name (20-sim's habit
                                 `param Ra = 2`, `R Ra = Ra`): their bonds say nothing more */
  int nparam_named, param_named_cap;
} bg_build;

/* ---- model.c */
/* Index of a new object of the family counted by *count (zeroed slots). */
int bg_build_new(bg_build *b, int *count);
const ns_entry *bg_build_lookup(const bg_build *b, const char *name);
/* The closest name (edit distance) among the namespace and `extra`, or NULL. */
const char *bg_build_suggest(const bg_build *b, const char *name, const char *const *extra,
                             int nextra);
const char *bg_build_strdup(bg_build *b, const char *s);
/* "a C", "an R", "an MTF": the kind with its article, for messages. */
const char *bg_elem_kind_article(int kind);

/* The version 1 compiler (model.c): bg_model_compile without flattening. */
/* The named warnings of a compiled model (model_warn.c): unused params, an
 * empty model, values that make an element degenerate. */
void bg_model_warnings(const bg_model *m, const bg_ast *ast, bg_diags *dg);
bg_model *bg_model_compile_flat(const bg_ast *ast, const bg_param_override *ov, int nov,
                                bg_diags *dg);

/* Declares a name in the shared namespace (model.c); 0 on success. */
int bg_build_declare(bg_build *b, const char *name, bg_srcloc loc, ns_kind kind, int id);

/* ---- model_detect.c: effort and flow detectors (De, Df) */
int bg_build_is_detector(const bg_ast_stmt *s);
void bg_build_declare_detector(bg_build *b, const bg_ast_stmt *s);
/* Resolves every detector's node (after the bonds, before any expression). */
void bg_build_detectors(bg_build *b);
/* The detector's output of the linear analysis, in statement order. */
void bg_build_detector_output(bg_build *b, const bg_ast_stmt *s);

/* ---- model_expr.c */
/* Compiles e into xnodes under the current context; returns the root (a
 * NaN placeholder after an error, already reported). */
int bg_build_expr(bg_build *b, const bg_expr *e);
/* Compiles and evaluates a constant expression (numbers, pi, params). */
double bg_build_const(bg_build *b, const bg_expr *e, const char *what);
/* Is the tree at root affine in the variable (op, ref)? */
int bg_build_is_affine(const bg_model *m, int root, int op, int ref);
/* Param names used by e (for the dependency order); calls fn for each. */
void bg_build_names(const bg_expr *e, void (*fn)(void *ctx, const bg_expr *name), void *ctx);

/* ---- model_field.c (multiport fields) */
/* Declares field s (a C or R with ports): its name and one element per port. */
void bg_build_declare_field(bg_build *b, const bg_ast_stmt *s);
/* Declares a name in the shared namespace; 0, or -1 after an error (reported). */
int bg_build_declare(bg_build *b, const char *name, bg_srcloc loc, ns_kind kind, int id);
/* A new element of `kind` named `name` written by statement s; -1 if the name is taken. */
int bg_build_new_elem(bg_build *b, const bg_ast_stmt *s, int kind, const char *name, bg_srcloc loc);
/* Compiles the laws (or energy) of field f into its port elements. */
void bg_build_field_laws(bg_build *b, int f);
/* The options of a field (label, color, at, q0, causality, per port). */
void bg_build_field_options(bg_build *b, int f);
/* d root / d (state of C element `store`), as new xnodes; -1 is the number 0;
 * -2 when root holds a table (no smooth derivative). */
int bg_build_diff(bg_build *b, int root, int store);
/* ---- model_build.c: node constructors shared by the compiler's files. */
int bg_build_node(bg_build *b, int op, bg_srcloc loc);
int bg_build_num(bg_build *b, double v, bg_srcloc loc);
int bg_build_ref(bg_build *b, int op, int ref, bg_srcloc loc);
int bg_build_op(bg_build *b, int op, int a, int c, bg_srcloc loc);

/* ---- model_ports.c */
/* The element of port `port` (a name) or number `num` of field f; -1. */
int bg_build_port_elem(const bg_model *m, int f, const char *port, int num);
/* A port variable named inside field f's laws: `v` of port `port` (its name,
 * or NULL with its number in `num`); -1 when it names no port of f. */
int bg_build_port_var(bg_build *b, const char *port, int num, char v, const bg_expr *e);

/* ---- model_opts.c: statement options */
/* Reports unknown and repeated option keys; `valid` is "a, b, c". */
void bg_build_check_options(bg_build *b, const bg_ast_stmt *s, const char *valid, const char *whose);
const bg_ast_option *bg_build_find_opt(const bg_ast_stmt *s, const char *key);
/* A string option ("..."); NULL if absent or wrong (reported). */
const char *bg_build_string_opt(bg_build *b, const bg_ast_stmt *s, const char *key);
/* color = "#rrggbb"; NULL if absent or wrong (reported). */
const char *bg_build_color_opt(bg_build *b, const bg_ast_stmt *s);
/* A word option (a name or a string) that must be one of `valid` ("a, b"). */
const char *bg_build_word_opt(bg_build *b, const bg_ast_stmt *s, const char *key, const char *valid);
/* A numeric option: a constant expression of params; `def` when absent. */
double bg_build_num_opt(bg_build *b, const bg_ast_stmt *s, const char *key, double def);
/* An initial value option (q0, p0, init): its root xnode, -1 if absent. */
int bg_build_init_opt(bg_build *b, const bg_ast_stmt *s, const char *key);
/* A constant expression of params (an initial value) as xnodes. */
int bg_build_init_expr(bg_build *b, const bg_expr *x);
/* at = (X, Y) of element e: finite positions within BG_POSITION_MAX. */
void bg_build_at_opt(bg_build *b, int e, const bg_ast_stmt *s);

/* ---- model_stmt.c */
void bg_build_elements(bg_build *b);
void bg_build_statements(bg_build *b);
#endif
