/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_model: a compiled bond graph model — flat, immutable after
 * bg_model_compile, structure of arrays indexed by integer ids, every object
 * with its source position. Every later stage takes `const bg_model *`. */
#ifndef BG_MODEL_H
#define BG_MODEL_H
#include "base/arena.h"
#include "lang/lang.h"
#include "base/diag.h"
#include "base/strbuf.h"

/* ---------------------------------------------------------------- element kinds */
typedef enum {
  BG_ELEM_SE, BG_ELEM_SF, BG_ELEM_MSE, BG_ELEM_MSF,
  BG_ELEM_C, BG_ELEM_I, BG_ELEM_R,
  BG_ELEM_TF, BG_ELEM_MTF, BG_ELEM_GY, BG_ELEM_MGY,
  BG_ELEM_J0, BG_ELEM_J1,
  BG_ELEM_COUNT
} bg_elem_kind;

/* How the element's expression is to be read. */
typedef enum {
  BG_FORM_NONE,   /* junction */
  BG_FORM_VALUE,  /* "= EXPR": source value, C capacitance, I inertance, R resistance,
                     TF modulus n, GY ratio r */
  BG_FORM_LAW_E,  /* ": e = F(...)" (R: resistance form; C: e = F(q)) */
  BG_FORM_LAW_F   /* ": f = G(...)" (R: conductance form; I: f = F(p)) */
} bg_elem_form;

/* A causality fixed by the `causality =` element option. */
typedef enum {
  BG_CAUS_OPT_NONE, BG_CAUS_OPT_INTEGRAL, BG_CAUS_OPT_DERIVATIVE,
  BG_CAUS_OPT_RESISTANCE, BG_CAUS_OPT_CONDUCTANCE
} bg_caus_opt;

typedef enum { BG_METHOD_SCAP, BG_METHOD_RELAXED, BG_METHOD_VANDIJK, BG_METHOD_LAGRANGE } bg_method;

/* A fixed causal stroke written in the model ("->|" stroke at head, "|->" at tail). */
typedef enum { BG_FIX_NONE, BG_FIX_HEAD, BG_FIX_TAIL } bg_fix;

/* ---------------------------------------------------------------- expressions
 * Every expression of the model (element values and laws, params, inputs,
 * states, plots, initial values) lives in one flat node array with names
 * resolved to ids. A node's children are earlier indices in the array. */
typedef enum {
  BG_X_NUM,     /* num */
  BG_X_TIME,    /* t */
  BG_X_PARAM,   /* ref = param id (value in param_value; may be overridden by --set) */
  BG_X_INPUT,   /* ref = input id (a function of t and params: input_expr) */
  BG_X_STATE,   /* ref = user state id (state declared with `state`) */
  BG_X_EFFORT,  /* ref = bond id: effort of that bond */
  BG_X_FLOW,    /* ref = bond id: flow of that bond */
  BG_X_STORE,   /* ref = element id of a C or I: its state q or p */
  BG_X_NEG, BG_X_NOT,
  BG_X_ADD, BG_X_SUB, BG_X_MUL, BG_X_DIV, BG_X_POW,
  BG_X_LT, BG_X_LE, BG_X_GT, BG_X_GE, BG_X_EQ, BG_X_NE, BG_X_AND, BG_X_OR,
  BG_X_CALL,    /* ref = bg_func id; arg[0..nargs) */
  BG_X_TABLE    /* ref = table id; arg[0] = the abscissa */
} bg_xop;

typedef enum {
  BG_FN_ABS, BG_FN_SIGN, BG_FN_SQRT, BG_FN_EXP, BG_FN_LOG, BG_FN_LOG10,
  BG_FN_SIN, BG_FN_COS, BG_FN_TAN, BG_FN_ASIN, BG_FN_ACOS, BG_FN_ATAN, BG_FN_ATAN2,
  BG_FN_SINH, BG_FN_COSH, BG_FN_TANH, BG_FN_MIN, BG_FN_MAX, BG_FN_POW,
  BG_FN_FLOOR, BG_FN_CEIL, BG_FN_IF, BG_FN_STEP, BG_FN_RAMP, BG_FN_PULSE, BG_FN_SAT,
  BG_FN_HYST, BG_FN_STICK, /* memory: a discrete state changed only at events (docs/format.md) */
  BG_FN_COUNT
} bg_func;

typedef struct bg_xnode {
  unsigned char op;    /* bg_xop */
  unsigned char nargs; /* 0..3 */
  int ref;             /* see bg_xop */
  int arg[3];          /* children (indices into xnode) */
  double num;          /* BG_X_NUM */
  bg_srcloc loc;
} bg_xnode;

/* ---------------------------------------------------------------- the model
 * Arrays are named <object>_<field> next to their count n<object> (MuJoCo).
 * BG_MODEL_ARRAYS lists each once: X(type, name, count). */
/* The largest coordinate an `at` position may have, in points. */
#define BG_POSITION_MAX 1e6

#define BG_MODEL_ARRAYS(X)                                                     \
  /* elements and junctions (one namespace with params, inputs, states) */     \
  X(int, elem_kind, nelem)          /* bg_elem_kind */                         \
  X(const char *, elem_name, nelem)                                            \
  X(bg_srcloc, elem_loc, nelem)     /* of the name */                          \
  X(int, elem_form, nelem)          /* bg_elem_form */                         \
  X(int, elem_expr, nelem)          /* root xnode of value or law rhs; -1 */   \
  X(int, elem_linear, nelem)        /* law linear (invertible) in its own variable */ \
  X(int, elem_modulated, nelem)     /* expression uses other model variables (MC, MI, MR...) */ \
  X(int, elem_causopt, nelem)       /* bg_caus_opt */                          \
  X(int, elem_init, nelem)          /* C: q0, I: p0 root xnode; -1 = 0 */      \
  X(const char *, elem_label, nelem) /* nullable */                            \
  X(const char *, elem_color, nelem) /* "#rrggbb" or NULL */                   \
  X(int, elem_has_at, nelem)                                                   \
  X(double, elem_at_x, nelem)       /* points, |x| <= BG_POSITION_MAX */        \
  X(double, elem_at_y, nelem)                                                  \
  X(int, elem_bondadr, nelem)       /* first index into elem_bonds */          \
  X(int, elem_nbond, nelem)                                                    \
  X(int, elem_bonds, nbondref)      /* bond ids per element, in file order */  \
  /* bonds */                                                                  \
  X(int, bond_num, nbond)           /* the user-visible bond number */         \
  X(int, bond_tail, nbond)          /* element id the half arrow leaves */     \
  X(int, bond_head, nbond)          /* element id the half arrow points at */  \
  X(int, bond_fix, nbond)           /* bg_fix */                               \
  X(const char *, bond_label, nbond)                                           \
  X(const char *, bond_color, nbond)                                           \
  X(bg_srcloc, bond_loc, nbond)                                                \
  /* params, in dependency order (= file order; a param uses only earlier ones) */ \
  X(const char *, param_name, nparam)                                          \
  X(int, param_expr, nparam)                                                   \
  X(double, param_value, nparam)    /* evaluated, after --set overrides */      \
  X(int, param_overridden, nparam)                                             \
  X(const char *, param_desc, nparam) /* nullable */                           \
  X(bg_srcloc, param_loc, nparam)                                              \
  /* inputs: named functions of t and params */                                \
  X(const char *, input_name, ninput)                                          \
  X(int, input_expr, ninput)                                                   \
  X(bg_srcloc, input_loc, ninput)                                              \
  /* user states: d name/dt = expr */                                          \
  X(const char *, state_name, nstate)                                          \
  X(int, state_expr, nstate)                                                   \
  X(int, state_init, nstate)        /* root xnode, -1 = 0 */                   \
  X(bg_srcloc, state_loc, nstate)                                              \
  /* modulating signals: `signal_to` uses a variable of node `signal_from` */  \
  X(int, signal_from, nsignal)      /* element id, or -1 (a user state) */     \
  X(int, signal_to, nsignal)        /* element id */                           \
  X(const char *, signal_var, nsignal) /* the variable as written, e.g. "ji.f" */ \
  /* plot panels and their expressions */                                      \
  X(int, plot_expradr, nplot)                                                  \
  X(int, plot_nexpr, nplot)                                                    \
  X(const char *, plot_title, nplot)  /* nullable */                           \
  X(const char *, plot_ylabel, nplot)                                          \
  X(const char *, plot_xlabel, nplot)                                          \
  X(int, plotexpr_root, nplotexpr)                                             \
  X(const char *, plotexpr_text, nplotexpr) /* as written, for CSV headers */  \
  /* outputs of the linear analysis (docs/linear.md): `output` statements and \
     detectors in file order (a detector's output_det >= 0) */               \
  X(const char *, output_name, noutput)                                        \
  X(int, output_expr, noutput)      /* root xnode */                           \
  X(const char *, output_desc, noutput) /* nullable */                         \
  X(int, output_det, noutput)       /* detector id, or -1 */                   \
  X(bg_srcloc, output_loc, noutput)                                            \
  /* inputs named by `linearise inputs = (...)`: a source element id, or       \
     -1 - id of an `input` */                                                  \
  X(int, lininput_ref, nlininput)                                              \
  /* lookup tables (from CSV files or inline), breakpoints sorted by x */      \
  X(int, table_adr, ntable)                                                    \
  X(int, table_n, ntable)                                                      \
  X(const char *, table_path, ntable) /* CSV file read (as opened); NULL inline */ \
  X(double, table_x, ntabledata)                                               \
  X(double, table_y, ntabledata)                                               \
  /* all expression nodes */                                                   \
  X(bg_xnode, xnode, nxnode)                                                   \
  /* submodel instances (language version 2), a parent before its children;  \
     flat names are qualified by inst_name ("M1.Ra" belongs to "M1") */        \
  X(int, elem_inst, nelem)          /* instance the element belongs to; -1 */  \
  X(const char *, inst_name, ninst) /* qualified: "M1", "M1.S" */              \
  X(const char *, inst_def, ninst)  /* the submodel's name */                  \
  X(int, inst_parent, ninst)        /* instance id, -1 = the model */          \
  X(bg_srcloc, inst_loc, ninst)     /* of the instance's name where it is used */ \
  X(int, inst_bondoff, ninst)       /* flat bond number = this + number inside */ \
  X(int, inst_bondspan, ninst)      /* numbers bondoff+1 .. bondoff+span are its */ \
  /* the bonds as written that each flat bond joins through ports (none for a \
     version 1 model): the outermost first, then from tail to head */          \
  X(int, bond_segadr, nbond)                                                   \
  X(int, bond_nseg, nbond)                                                     \
  X(int, seg_inst, nseg)            /* instance id, -1 = the model */          \
  X(int, seg_num, nseg)             /* the bond's number in that scope */         \
  /* effort and flow detectors (De, Df): no bond, no power; a name for the \
     effort or flow of a node, usable in expressions, and an output */        \
  X(const char *, det_name, ndet)                                              \
  X(int, det_var, ndet)             /* 'e' (De) or 'f' (Df) */                 \
  X(int, det_node, ndet)            /* element id of the node it reads */      \
  X(int, det_expr, ndet)            /* root xnode of its value (-1 after an error) */ \
  X(bg_srcloc, det_loc, ndet)                                                 \
  /* multiport fields (docs/format.md, Multiport fields): a C or R field of n \
     ports is n consecutive one-port elements of its kind, one per port,     \
     named "K.el" / "K.1", each with the port's law (the efforts of an       \
     energy form are its gradient); the field record groups them */          \
  X(int, elem_field, nelem)         /* field the element is a port of; -1 */  \
  X(int, elem_fport, nelem)         /* its port's number in the field, 1..n; 0 */ \
  X(const char *, field_name, nfield)                                          \
  X(int, field_kind, nfield)        /* BG_ELEM_C or BG_ELEM_R */              \
  X(int, field_elemadr, nfield)     /* the element of port 1 */               \
  X(int, field_nport, nfield)                                                  \
  X(int, field_numbered, nfield)    /* ports given as a count: K(2) */         \
  X(int, field_energy, nfield)      /* energy root xnode (C), or -1 */         \
  X(bg_srcloc, field_loc, nfield)   /* of the field's name */                 \
  /* the model's own parameter study (`study` statements, docs/study.md): \
     the command line's words for it, in file order; kind 's' sweep, 'v'    \
     vary, 'd' draws, 'e' seed, 'c' collect */                                \
  X(int, study_kind, nstudy)                                                   \
  X(const char *, study_word, nstudy) /* "R0=5:125:7", "draws=500", "C1.e:max" */ \
  X(bg_srcloc, study_loc, nstudy)

typedef struct bg_simspec {
  int present;
  double t0, t_end, dt; /* dt 0: solver's own output points */
  double rtol, atol, max_step; /* 0: default */
  const char *solver;   /* "auto", "cvode_bdf", "cvode_adams", "ida"; default "auto" */
  bg_srcloc loc;
} bg_simspec;

/* The `linearise` statement (docs/linear.md); absent: present = 0, defaults. */
typedef struct bg_linspec {
  int present;
  int steady;          /* at = steady: Newton steady state; else the initial point */
  int inputs_given;    /* inputs = (...) given: lininput_ref, else every source */
  double t;            /* time of the operating point (inputs held at their value) */
  int t_given;         /* else the simulate block's t0, or 0 */
  double w_min, w_max; /* frequency range [rad/s]; 0: automatic */
  double t_end;        /* step and impulse responses; 0: automatic */
  bg_srcloc loc;
} bg_linspec;
/* The widest frequency range: w_max / w_min at most 10^30 (docs/linear.md). */
#define BG_LIN_MAX_DECADES 30
#define BG_LIN_MAX_RANGE 1e30

typedef struct bg_layoutspec {
  const char *engine;  /* "dot" (default), "neato", "fdp", "sfdp", "pinned" */
  const char *rankdir; /* "LR" (default), "TB", "RL", "BT" */
} bg_layoutspec;

typedef struct bg_model {
  const char *name;  /* model name (default: the file's stem) */
  const char *title; /* nullable */
  const char *path;  /* model file as given */
  int method;        /* bg_method from the `causality` statement; default SCAP */
  int method_given;  /* the model has a `causality` statement */
  bg_simspec sim;
  bg_layoutspec layout;
  bg_linspec linear;
  int noutput, nlininput;
  int nelem, nbondref, nbond, nparam, ninput, nstate, nsignal, nplot, nplotexpr;
  int ntable, ntabledata, nxnode, ninst, nseg, ndet, nfield, nstudy;
#define BG_X_DECLARE(type, name, count) type *name;
  BG_MODEL_ARRAYS(BG_X_DECLARE)
#undef BG_X_DECLARE
  /* element names hashed (open addressing, elem_hashcap a power of two, -1
   * empty) so bg_model_find_elem is O(1); NULL in hand-built models, which
   * are then searched linearly. Bond numbers likewise (bond_hash, same
   * capacity rule) for bg_model_find_bond when they are not 1..n in order. */
  int *elem_hash, elem_hashcap;
  int *bond_hash, bond_hashcap;
  bg_arena arena; /* owns every array and string above */
} bg_model;

/* A command-line override of a param: --set NAME=VALUE. */
typedef struct bg_param_override {
  const char *name;
  double value;
} bg_param_override;

/* Compiles the AST into a model, validating every rule of the format.
 * Errors go to dg; returns NULL when there is any error. The caller owns the
 * result (bg_model_free). Overrides that name no param are reported as errors
 * at line 0. */
bg_model *bg_model_compile(const bg_ast *ast, const bg_param_override *ov, int nov,
                           bg_diags *dg);
void bg_model_free(bg_model *m);

/* ---------------------------------------------------------------- queries */
/* Name of an element kind as written in models: "Se", "MTF", "0", ... */
const char *bg_elem_kind_name(int kind);
/* Kind as drawn: modulated C/I/R get their M prefix ("MR"). */
const char *bg_elem_display_kind(const bg_model *m, int elem);
int bg_elem_is_junction(int kind);      /* 0, 1 */
int bg_elem_is_twoport(int kind);       /* TF, MTF, GY, MGY */
int bg_elem_is_source(int kind);        /* Se, Sf, MSe, MSf */
int bg_elem_is_store(int kind);         /* C, I */
int bg_elem_is_oneport(int kind);       /* sources, stores, R */
/* The bond of a one-port element. */
int bg_elem_port_bond(const bg_model *m, int elem);
/* For a two-port: the bond pointing in (side 1) and the bond pointing out (side 2). */
int bg_elem_in_bond(const bg_model *m, int elem);
int bg_elem_out_bond(const bg_model *m, int elem);
/* The element at the other end of bond b from element e. */
int bg_bond_other(const bg_model *m, int b, int e);
/* The field element `elem` is a port of, or -1 (also for hand-built models
 * without field arrays); the port's name ("el", "2") after the field's. */
int bg_elem_field(const bg_model *m, int elem);
const char *bg_elem_port_name(const bg_model *m, int elem);
/* Element id by name, or -1. */
int bg_model_find_elem(const bg_model *m, const char *name);
/* Builds m->elem_hash and m->bond_hash (bg_model_compile does; hand-built
 * models may). */
void bg_model_hash_names(bg_model *m);
/* Bond id by user number, or -1. */
int bg_model_find_bond(const bg_model *m, int number);
const char *bg_method_name(int method);
int bg_method_parse(const char *s); /* -1 if unknown */
/* One-line human summary for --check, e.g. "rlc: 4 elements (Se 1, R 1, I 1, C 1),
 * 1 junction, 4 bonds; 2 stores, 1 source" (no newline). */
void bg_model_summary(const bg_model *m, bg_strbuf *out);
/* The model's expressions (evaluator, printer, bytecode) are part of the
 * stage's front door. */
#include "model/expr.h"
#endif
