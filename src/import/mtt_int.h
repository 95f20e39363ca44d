/* SPDX-License-Identifier: BSD-3-Clause */
/* The MTT reader's internals: the text files of a system beside its drawing
 * (mtt_files.c), read by the drawing's conversion (mtt_read.c). */
#ifndef BG_MTT_INT_H
#define BG_MTT_INT_H
#include "import/import_int.h"

/* One line of a label file (name, CR, arguments), an alias (short, real) or
 * an assignment (name, value), with its line. */
typedef struct {
  const char *f[3];
  int n; /* fields present */
  int line;
} bg_mtt_row;
typedef struct {
  bg_mtt_row *v; /* owned */
  int n, cap;
  bg_strindex idx; /* f[0] -> the first row of that name */
} bg_mtt_rows;

typedef struct {
  int file; /* its diagnostics source; -1: there is no label file */
  bg_mtt_rows rows, aliases;
  const char *summary; /* #SUMMARY's text, or NULL */
  int summary_line;
} bg_mtt_lbl;

typedef struct {
  int file; /* -1: no such file */
  bg_mtt_rows rows; /* the last assignment of each name */
  int skipped, skipped_line; /* lines that are not "name = value" (other Octave code): not read */
} bg_mtt_assign;

/* Read path when it exists (a missing file is empty, file -1). 0, or -1
 * after errors (at the file's lines). */
int bg_mtt_read_lbl(const char *path, bg_arena *a, bg_diags *dg, bg_mtt_lbl *out);
int bg_mtt_read_assign(const char *path, bg_arena *a, bg_diags *dg, bg_mtt_assign *out);
const bg_mtt_row *bg_mtt_find(const bg_mtt_rows *r, const char *name);
void bg_mtt_rows_free(bg_mtt_rows *r);

/* ------------------------------------------------------------ a drawing */
/* The largest drawing read: what is near what is found by comparing
 * distances, quadratic in the drawing's size, so the size is bounded (MTT's
 * drawings are drawn by hand: its largest example has 80 components). */
enum { BG_MTT_MAX_COMPONENTS = 10000, BG_MTT_MAX_BONDS = 10000, BG_MTT_MAX_MARKS = 20000 };

enum { BG_MTT_HEAD = 0, BG_MTT_TAIL = 1 }; /* the two ends of a bond */

typedef struct {
  const char *type;  /* R, C, SS, 0, a subsystem's name, ... */
  const char *name;  /* the label after ':' (without [] for SS:[NAME]), or NULL */
  const char *cr;    /* a third field TYPE:NAME:CR, or NULL */
  const char *label; /* the text as written, for messages */
  int port_ss;       /* SS:[NAME]: a port of the system */
  bg_fig_pt at;      /* the text's anchor */
  int line;          /* the text object's line */
  int nbonds;
} bg_mtt_comp;

typedef struct {
  bg_fig_pt end[2];      /* [BG_MTT_HEAD]: the half arrow's corner; [BG_MTT_TAIL] */
  bg_fig_pt barb;        /* the half arrow's tip: its side is the flow side */
  int line;              /* the polyline's line */
  int comp[2];           /* the component at each end */
  const char *port[2];   /* the port label at each end, or NULL */
  int stroke[2];         /* a full stroke at that end */
  int half_e[2], half_f[2]; /* half strokes (effort side, flow side) */
} bg_mtt_bond;

/* One system: a drawing and the files beside it. */
typedef struct {
  const char *type;  /* its name (the drawing's NAME_abg.fig) */
  const char *dir;   /* its folder ("" for the current one) */
  int file;          /* the drawing's diagnostics source */
  bg_mtt_comp *c;    /* owned */
  int nc, capc;
  bg_mtt_bond *b;    /* owned */
  int nb, capb;
  bg_mtt_lbl lbl;
  const char **notes; /* owned array: the readings said in warnings, for the .bg text */
  int nnotes, capnotes;
} bg_mtt_sys;

/* The drawing's bonds, strokes, components and port labels, and what is
 * near what (mtt_geom.c). 0, or -1 after errors at the drawing's lines. */
int bg_mtt_geometry(bg_mtt_sys *s, const bg_fig *fig, bg_arena *a, bg_diags *dg);
#endif
