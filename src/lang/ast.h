/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_ast: the syntax of a .bg file as written (mutable, with source spans).
 * Produced by bg_parse_*, consumed by bg_model_compile, then freed. */
#ifndef BG_AST_H
#define BG_AST_H
#include "base/arena.h"

/* The largest bond number a model may write (docs/format.md). */
#define BG_BOND_NUMBER_MAX 1000000000
#include "base/diag.h"

/* ---------------------------------------------------------------- expressions */
typedef enum {
  BG_EX_NUM,    /* num */
  BG_EX_STR,    /* str: a string literal (only as a table() file argument or option value) */
  BG_EX_NAME,   /* name: t, pi, a param/input/state, e7/f7, or a bare element name */
  BG_EX_FIELD,  /* name.field: X.e, X.f, X.q, X.p, X.e1, J.e, ... */
  BG_EX_UNARY,  /* op: '-', '!' ('+' is dropped by the parser); args[0] */
  BG_EX_BINARY, /* op: one of bg_binop; args[0], args[1] */
  BG_EX_CALL,   /* name(args...) */
  BG_EX_MATRIX, /* [a, b; c, d]: nrows x ncols, args row-major (inline table data) */
  BG_EX_TUPLE   /* (a, b): only as an option value, e.g. at = (10, 20) */
} bg_exkind;

typedef enum {
  BG_OP_ADD = 1, BG_OP_SUB, BG_OP_MUL, BG_OP_DIV, BG_OP_POW,
  BG_OP_LT, BG_OP_LE, BG_OP_GT, BG_OP_GE, BG_OP_EQ, BG_OP_NE,
  BG_OP_AND, BG_OP_OR, BG_OP_NEG, BG_OP_NOT
} bg_binop;

typedef struct bg_expr bg_expr;
struct bg_expr {
  bg_exkind kind;
  int op;          /* bg_binop for UNARY/BINARY */
  bg_srcloc loc;   /* first character of the expression (of the operator for BINARY) */
  double num;      /* NUM */
  const char *str; /* STR: unescaped text; NAME/FIELD/CALL: the name */
  const char *field; /* FIELD: the part after the dot */
  bg_srcloc field_loc;
  bg_expr **args;  /* UNARY, BINARY, CALL, MATRIX, TUPLE */
  int nargs;
  int nrows, ncols; /* MATRIX */
  int start, end;  /* byte offsets of the expression's text in the line buffer */
  const char *text; /* the expression's source text as written (trimmed), e.g. "C1.e";
                       set for leaves, calls and whole expressions, NULL for inner
                       operators (copying every operator's text would be quadratic) */
  int depth;        /* height of the tree below and including this node */
};

/* ---------------------------------------------------------------- statements */
typedef struct bg_ast_option {
  const char *key;
  bg_srcloc loc; /* of the key */
  bg_expr *value;
} bg_ast_option;

/* A named item of a list: a submodel's parameter (with its default), an
 * instance's argument, a port. */
typedef struct bg_ast_item {
  const char *name;
  bg_srcloc loc;      /* of the name */
  bg_expr *value;     /* parameter default, argument; NULL for a port */
  const char *text;   /* description; nullable */
} bg_ast_item;

typedef enum {
  BG_ST_MODEL, BG_ST_PARAM, BG_ST_INPUT, BG_ST_STATE, BG_ST_ELEMENT,
  BG_ST_BOND, BG_ST_CAUSALITY, BG_ST_SIMULATE, BG_ST_PLOT, BG_ST_LAYOUT,
  BG_ST_OUTPUT, BG_ST_LINEARISE, /* linear analysis: docs/linear.md */
  /* language version 2: components (flattened away before the model compiler) */
  BG_ST_SUBMODEL, /* name, text = title, items = parameters; the body follows up to END */
  BG_ST_PORT,     /* items = the ports */
  BG_ST_END,      /* ends the SUBMODEL before it */
  BG_ST_USE,      /* text = the path as written */
  BG_ST_INSTANCE, /* kindword = the submodel, name = the instance, items = arguments */
  /* a parameter study carried by the model (docs/format.md, "study"): name =
   * "sweep", "vary", "draws" or "collect"; items = the command line's words
   * for it ("R0=5:125:7", "seed=7", "C1.e:max"), each at its position */
  BG_ST_STUDY
} bg_stkind;

typedef enum { BG_ARROW_PLAIN, BG_ARROW_STROKE_HEAD /* ->| */, BG_ARROW_STROKE_TAIL /* |-> */ } bg_arrow;

typedef struct bg_ast_stmt {
  bg_stkind kind;
  bg_srcloc loc;      /* of the statement's first token */
  const char *kindword; /* ELEMENT: the kind as written ("Se", "MTF", "0", ...) */
  const char *name;   /* MODEL, PARAM, INPUT, STATE, OUTPUT, ELEMENT name; CAUSALITY method */
  bg_srcloc name_loc;
  const char *text;   /* MODEL title, PARAM and OUTPUT description; nullable */
  /* ELEMENT: either a shorthand value (law_var == 0) or a law "v = EXPR" (law_var 'e','f'). */
  bg_expr *expr;      /* PARAM/INPUT/STATE right-hand side; ELEMENT value or law rhs; nullable */
  char law_var;       /* ELEMENT with ": v = ..." : 'e' or 'f' (or the letter written) */
  const char *law_lhs; /* the law's left-hand side as written */
  bg_srcloc law_loc;
  int has_law;
  /* BOND */
  int number;         /* 0 = unnumbered; else 1..BG_BOND_NUMBER_MAX */
  bg_srcloc number_loc;
  const char *from, *to;
  bg_srcloc from_loc, to_loc;
  bg_arrow arrow;
  /* PLOT: expressions; options for all kinds that take them */
  bg_expr **exprs;
  int nexprs;
  bg_ast_option *opts;
  int nopts;
  bg_ast_item *items; /* SUBMODEL, PORT, INSTANCE; a field ELEMENT's ports */
  int nitems;
  /* ELEMENT: a multiport field `C K(a, b) : e1 = ..., b.e = ...` (docs/format.md,
   * Multiport fields): its ports are `items` (named, or "1".."n" for `K(n)`),
   * its laws `laws` (name = the left-hand side as written: "e1", "b.e",
   * "energy"; value = the right-hand side) */
  int is_field;
  int field_numbered; /* the ports were given as a count: K(2) */
  /* ELEMENT and BOND written by `open X` / `short X` (a zero source and its
   * bond; docs/format.md, "Open and shorted ports"): the bond's direction
   * follows the port's, and the element is named after the node */
  int zero_port;
  bg_ast_item *laws;
  int nlaws;
} bg_ast_stmt;

typedef struct bg_ast {
  bg_arena arena;     /* owns every node and string */
  bg_ast_stmt *stmts; /* in file order */
  int nstmts;
  bg_ast_stmt *heap_stmts; /* stmts when malloc'd (the flat AST takes the flattener's
                              array instead of a copy), freed with the AST; else NULL */
  const char *path;   /* the model file's path as given */
  int file;           /* its diagnostics source index (0: the model file) */
  int has_components; /* a SUBMODEL, USE or INSTANCE statement: needs flattening */
  /* Where `use "NAME"` looks after the using file's folder (docs/format.md,
   * "Files"): the folders of BGDRAW_PATH (NULL-terminated), then the
   * installed component library. Set by the caller before compiling;
   * borrowed; both nullable. */
  const char *const *use_path;
  const char *use_lib;
} bg_ast;
#endif
