/* SPDX-License-Identifier: BSD-3-Clause */
/* Internal to the flattener (flatten*.c): the state of one flattening. */
#ifndef BG_FLATTEN_INT_H
#define BG_FLATTEN_INT_H
#include "base/strindex.h"
#include "lang/flatten.h"

/* What a name of a scope (the model or one submodel definition) is. */
typedef enum { SC_ELEM, SC_PARAM, SC_INPUT, SC_STATE, SC_INST, SC_PORT, SC_ARG } sc_kind;

typedef struct sc_entry {
  const char *name;
  int kind;  /* sc_kind */
  int index; /* SC_PORT: port index; SC_INST: the statement; SC_ARG: parameter index */
  bg_srcloc loc;
} sc_entry;

/* A name table: entries in declaration order, their names hashed. */
typedef struct fl_scope {
  sc_entry *e;
  int n, cap;
  bg_strindex names;
} fl_scope;

typedef struct fl_file {
  const char *path;    /* as opened (relative to the working directory) */
  const char *key;     /* canonical path, for cycles and repeated uses */
  const char *dir_rel; /* its directory relative to the model file's ("." for that one) */
  bg_ast *ast;         /* owned; NULL for the model file (borrowed as root) */
  int loading;         /* on the stack of files being loaded */
} fl_file;

typedef struct fl_def {
  const char *name;
  const bg_ast_stmt *head; /* SUBMODEL; NULL for the model itself */
  const bg_ast_stmt **stmt; /* the body: between head and END (the model: all outside defs) */
  int nstmt;
  int file;                /* fl_file index */
  fl_scope names;
  int names_built;
  const bg_ast_stmt **port_stmt; /* per port: its PORT statement */
  int *port_item;                /* per port: its item in that statement */
  int nports;
  int *bondnum; /* per BOND statement of the body, in order: its number in the scope */
  int nbonds, maxnum;
  long span;    /* bond numbers an instance takes: maxnum + its instances' spans */
  long size;    /* flat statements an instance emits: its parameters, its body's
                   statements and its instances' sizes (capped at BG_FLAT_MAX + 1) */
  int span_state; /* 0 not yet, 1 being computed (recursion), 2 done */
} fl_def;

typedef struct fl_inst {
  bg_flat_instance pub;
  int def;      /* fl_def index */
  int src;      /* diagnostics source of its body (the def's file, used from here) */
  int port_adr; /* its ports in fl_flattener.ports */
} fl_inst;

/* Both sides of one port of one instance: the segment inside the submodel
 * and the segment outside; counts catch ports used twice. */
typedef struct fl_port {
  int inner, outer;   /* segment indices, -1 none */
  int ninner, nouter;
  int inner_is_tail;  /* the inside bond leaves the port: power flows in */
  int outer_is_head;  /* the outside bond points at the port: power flows in */
  bg_srcloc inner_loc, outer_loc;
} fl_port;

/* A bond end: a node (flat name) or the inside/outside of an instance's port. */
typedef struct fl_end {
  const char *node; /* flat name, NULL for a port */
  int port;         /* fl_flattener.ports index, -1 for a node */
  bg_srcloc loc;
} fl_end;

typedef struct fl_seg {
  int inst, num;      /* scope and the bond's number there */
  long flatnum;
  fl_end end[2];      /* tail, head */
  int fix;            /* bg_arrow */
  int depth;          /* nesting depth of its scope */
  int slot;           /* index of its placeholder in the output statements */
  int chain;          /* the chain (flat bond) it belongs to, -1 before chaining */
  const bg_ast_stmt *stmt; /* the rewritten statement (options, positions) */
} fl_seg;

typedef struct fl_bondvar { bg_expr *node; int inst, num; } fl_bondvar;

typedef struct fl_flattener {
  bg_diags *dg;
  int capped;  /* an instance would have crossed BG_FLAT_MAX: expansion stopped */
  int dry;     /* checking a submodel no instance uses: nested instances are not
                  expanded (each submodel is checked once, on its own) */
  long next_progress; /* statements at which -v says how far the expansion is */
  bg_ast *out; /* the flat AST being built */
  bg_ast_stmt *stmts;
  int *stmt_inst; /* per output statement: instance, -1 */
  int nstmts, cap;
  fl_file *files;
  int nfiles;
  fl_def *defs;
  int ndefs;
  fl_scope defnames; /* submodel name -> def index */
  fl_inst *inst;
  int ninst;
  fl_port *ports;
  int nports;
  fl_seg *segs;
  int nsegs;
  bg_expr **fields;   /* FIELD nodes that may name a qualified param (M1.K) */
  int nfields;
  fl_bondvar *bondvars; /* e7/f7 inside submodels, renumbered after chaining */
  int nbondvars;
  int depth;          /* instances being expanded */
  /* flat bonds (chains of segments), filled by bg_fl_chain_bonds */
  int *slot_chain;    /* per output statement: its chain, -1 */
  int *chain_adr, *chain_n; /* per chain: its segments in chain_segs (outermost first) */
  int nchains;
  int *chain_segs;
  int nchain_segs;
} fl_flattener;

/* Appends one zeroed element to a malloc'd array with count *n. */
void *bg_fl_push(void *arr, int *n, size_t size);
#define FL_PUSH(arr, n) ((arr) = bg_fl_push((arr), &(n), sizeof *(arr)), &(arr)[(n)-1])

/* ---- flatten.c: scopes, files, definitions */
const sc_entry *bg_fl_lookup(const fl_scope *s, const char *name);
/* Adds a name; returns the existing entry (not added) on a clash, else NULL. */
const sc_entry *bg_fl_declare(fl_scope *s, const char *name, int kind, int index, bg_srcloc loc);
void bg_fl_scope_free(fl_scope *s);
/* Closest name of the scope (of kinds in mask, 1 << kind), or NULL. */
const char *bg_fl_suggest(const fl_scope *s, const char *name, unsigned mask);
const char *bg_fl_strdup(fl_flattener *f, const char *s);
const char *bg_fl_join(fl_flattener *f, const char *prefix, const char *name);

/* ---- flatten_expand.c: instances, statements, expressions */
void bg_fl_expand_model(fl_flattener *f, int root);
/* Checks every submodel that no instance of the flat model uses, as a
 * compiler checks a function nobody calls; what it emits is dropped. */
void bg_fl_check_unused(fl_flattener *f);

/* ---- flatten_bonds.c: ports, chains of segments, numbers */
void bg_fl_chain_bonds(fl_flattener *f);
/* Bond span of a def (numbers its instances take), with recursion reported. */
long bg_fl_span(fl_flattener *f, int def, bg_srcloc use);
#endif
