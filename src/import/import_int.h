/* SPDX-License-Identifier: BSD-3-Clause */
/* The import stage's internals: a YAML document as a tree with positions
 * (yaml_tree.c, over libyaml), and the imported graph that the readers fill
 * and the .bg writer (import_emit.c) prints. */
#ifndef BG_IMPORT_INT_H
#define BG_IMPORT_INT_H
#include "base/arena.h"
#include "base/diag.h"
#include "import/import.h"

/* ------------------------------------------------------------ YAML tree */
typedef enum { BG_Y_SCALAR, BG_Y_SEQ, BG_Y_MAP } bg_ynode_kind;
typedef struct bg_ynode bg_ynode;
struct bg_ynode {
  bg_ynode_kind kind;
  int line, col;   /* 1-based, of the node's first character */
  int plain;       /* a scalar written without quotes or block style (so its
                      characters sit on its line at col + offset) */
  const char *str; /* scalar text */
  bg_ynode **kids; /* SEQ: items; MAP: key, value, key, value, ... */
  int nkids;
};

/* Limits that keep the work bounded on any input. */
enum { BG_Y_MAX_DEPTH = 64, BG_Y_MAX_NODES = 1000000 };

/* Parses src into a tree in arena a; errors (libyaml's, aliases, several
 * documents, the limits) go to dg. NULL after an error. */
bg_ynode *bg_yaml_parse(const char *src, size_t len, bg_arena *a, bg_diags *dg);
/* The value of key in map m, or NULL. */
const bg_ynode *bg_yaml_get(const bg_ynode *m, const char *key);

/* ---------------------------------------------------------- the graph */
/* Where a bond must point at one of its ends: into the node there (HEAD),
 * out of it (TAIL), or either way (FREE). */
enum { BG_IG_FREE, BG_IG_HEAD, BG_IG_TAIL };

typedef struct bg_ig_node {
  const char *name;   /* a valid .bg name */
  const char *orig;   /* the name in the source */
  const char *label;  /* a port's label in the source (is_port) */
  const char *sig;    /* printed right after the name: a field's "(2)", or NULL */
  const char *kind;   /* R C I Se Sf 0 1 TF GY, or the submodel's name */
  const char *value;  /* "= EXPR" text, or NULL */
  const char *law;    /* ": LAWS" text, or NULL */
  const char *opts;   /* "[...]" text, or NULL */
  const char *comment; /* printed after the statement, or NULL */
  int sf_value_neg_if_head; /* Sf: value is the flow out of the source (negate
                               when its bond points into it) */
  int is_port;        /* a submodel port (BondGraphTools' exposed SS): no statement */
  int line;           /* source line */
  int file;           /* source (bg_diags index; 0: the model file) */
} bg_ig_node;

typedef struct bg_ig_bond {
  int a, b;               /* nodes */
  const char *pa, *pb;    /* port suffixes (".1", ".A") or "" */
  int ca, cb;             /* BG_IG_FREE / HEAD / TAIL */
  int line;
  int file;
  int stroke;             /* a fixed causal stroke: 0 none, BG_IG_HEAD at b, BG_IG_TAIL at a */
} bg_ig_bond;

typedef struct bg_ig_param {
  const char *name, *value, *desc;
  int line;
  int file;
  int is_input;           /* an `input` (a function of time), not a `param` */
} bg_ig_param;

typedef struct bg_ig_model {
  const char *name;       /* submodel (or model) name */
  const char *title;      /* nullable */
  bg_ig_node *nodes;
  int nnodes, capnodes;
  bg_ig_bond *bonds;
  int nbonds, capbonds;
  bg_ig_param *params;
  int nparams, capparams;
  const char **notes;     /* comment lines before the model's statements */
  int *note_lines;
  int nnotes, capnotes;
  const char **extra;     /* .bg statements after the bonds (the YAML's bgdraw: list) */
  int *extra_lines;
  int *extra_files;       /* nullable: then all in `file` */
  int nextra, capextra;
  int line;
  int file;               /* the source of its notes, extra statements and header */
  const char *params_sig; /* "(a = 1, b)" after a submodel's name, or NULL */
} bg_ig_model;

typedef struct bg_ig {
  bg_arena arena;
  const char *source_path, *format; /* for the header comment */
  bg_ig_model *models;              /* [0] is the root; then submodels */
  int nmodels, capmodels;
} bg_ig;

int bg_ig_add_model(bg_ig *g, const char *name, int line);
int bg_ig_add_node(bg_ig_model *m, bg_ig_node n);
int bg_ig_add_bond(bg_ig_model *m, bg_ig_bond b);
void bg_ig_add_param(bg_ig_model *m, bg_ig_param p);
/* A .bg statement after the bonds, from line `line` of source `file`. */
void bg_ig_add_extra(bg_ig_model *m, int file, int line, const char *text);
void bg_ig_add_note(bg_ig *g, bg_ig_model *m, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* A string in the graph's arena. */
char *bg_ig_printf(bg_ig *g, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* name made a valid .bg name (other characters become '_', a leading digit
 * or a keyword gets '_'), unique among the names already in m. */
const char *bg_ig_name(bg_ig *g, const bg_ig_model *m, const char *name);
/* Fixes the direction of model mi's bonds (a -> b) from what their ends
 * demand; two ends that both demand power in (or out) get a 0-junction
 * between them, with a note. The number of junctions added. */
int bg_ig_orient(bg_ig *g, int mi);
/* After bg_ig_orient: BG_IG_HEAD when power comes into submodel m at port
 * (so a bond outside must point into the instance's port), BG_IG_TAIL when
 * it goes out, BG_IG_FREE when the port has no bond, -1 for no such port. */
int bg_ig_port_direction(const bg_ig_model *m, const char *port);
/* Prints the graph as .bg text with the line map. */
void bg_ig_emit(const bg_ig *g, bg_import_result *out);
void bg_ig_free(bg_ig *g);

/* The BondGraphTools reader: the YAML tree into g. 0 on success. */
int bg_bgt_read(const bg_ynode *doc, bg_ig *g, bg_diags *dg);

/* ---------------------------------------------------------------- xfig */
/* What an MTT drawing is made of: open polylines (bonds, strokes) and texts
 * (components, port labels) with their coordinates (xfig units, 1200 a
 * inch, y downwards) and the file line each object starts on. */
enum { BG_FIG_LINE = 1, BG_FIG_TEXT = 2 };
enum { BG_FIG_MAX_OBJECTS = 1000000, BG_FIG_MAX_COORD = 100000000 };
typedef struct {
  int x, y;
} bg_fig_pt;
typedef struct {
  int kind;      /* BG_FIG_LINE or BG_FIG_TEXT */
  int line;      /* the object's first line in the file */
  int sub_type;  /* polyline: 1 open polyline; text: justification */
  int style;     /* polyline: 0 solid */
  int depth;
  int arrows;    /* polyline: it has an arrow head at either end */
  bg_fig_pt *pts; /* polyline: its points; text: its anchor */
  int npts;
  const char *text; /* text: the string, escapes undone */
} bg_fig_obj;
typedef struct {
  bg_fig_obj *objs; /* owned (free); their points and strings in the arena */
  int n, cap;
} bg_fig;
/* Parses an xfig 3.x file (errors at its lines in source `file`). 0 on success. */
int bg_fig_parse(const char *src, size_t len, bg_arena *a, bg_diags *dg, int file, bg_fig *out);

/* The MTT reader (mtt_read.c): the drawing src (at path; its label file,
 * numeric parameters, inputs, simulation parameters and subsystems beside
 * it) into g. 0 on success. */
int bg_mtt_read(const char *path, const char *src, size_t len, bg_ig *g, bg_diags *dg);
#endif
