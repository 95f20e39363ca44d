/* Internals of the diagram builder, shared by diagram*.c and render.c. */
#ifndef BG_DIAGRAM_INT_H
#define BG_DIAGRAM_INT_H
#include "analysis.h"
#include "layout.h"
#include "model.h"
#include "render.h"
#include "scene.h"
#include "style.h"

/* <math.h> constants are not C11 */
#define BG_PI 3.14159265358979323846
#define BG_SQRT1_2 0.70710678118654752440

typedef struct bg_vec {
  double x, y;
} bg_vec;

/* Where a bond runs on the page. */
typedef struct bg_bond_geom {
  bg_vec tail, head;   /* end points on the node boxes */
  bg_vec tdir, hdir;   /* unit travel direction (tail → head) at each end */
  bg_vec mid, mdir;    /* middle point and direction there */
  int spladr, spln;    /* Graphviz spline points (page coordinates) or spln 0: straight */
} bg_bond_geom;

struct bg_diagram {
  const bg_model *m;
  const bg_analysis *a; /* nullable */
  bg_render_opts o;
  unsigned show;
  bg_style st;
  /* nodes: the model's elements, then one per Lagrange flow source attached to a junction */
  int nnode;
  double *nw, *nh, *nx, *ny; /* box size and centre on the page */
  char **nlabel;             /* pango markup */
  int *lag_node;             /* per Lagrange source: its node, or -1 (a split bond) */
  bg_layout lay;
  double *splx, *sply;       /* spline points moved onto the page */
  bg_bond_geom *bg;          /* per bond */
  unsigned char *hot_bond, *hot_elem; /* highlight: what stays in colour */
  int *side_use;             /* per bond side: layers already drawn there */
  double *placed;            /* x0 y0 x1 y1 of free-floating labels placed so far */
  int nplaced, capplaced;
  bg_scene scene;
  bg_arena arena;
};

/* geometry (diagram_geom.c) */
bg_vec bg_v(double x, double y);
bg_vec bg_vadd(bg_vec a, bg_vec b);
bg_vec bg_vsub(bg_vec a, bg_vec b);
bg_vec bg_vscale(bg_vec a, double k);
bg_vec bg_vunit(bg_vec a);
bg_vec bg_vleft(bg_vec d); /* left of travel on a y-down page */
double bg_vlen(bg_vec a);
/* Where the ray from a box's centre towards p leaves the box (half sizes hw, hh). */
bg_vec bg_box_exit(bg_vec c, double hw, double hh, bg_vec p);
void bg_geom_bonds(bg_diagram *d);
/* The side of the barb at the head of bond b: a unit normal. */
bg_vec bg_barb_side(const bg_diagram *d, int b);
/* Draws the bond's centre line as the current item's path. */
void bg_geom_bond_path(const bg_diagram *d, int b);
/* Filled arrowhead with its tip at p, pointing along dir. */
void bg_geom_arrowhead(bg_scene *s, bg_vec p, bg_vec dir, double len, double wid);

/* colours with the highlight applied */
bg_rgba bg_diagram_ink(const bg_diagram *d, bg_rgba c, int hot);
int bg_diagram_muted(const bg_diagram *d);

/* Appends s with pango markup's special characters escaped (diagram.c). */
void bg_markup_escape(bg_strbuf *b, const char *s);
/* A patch of background behind centred text at p, so it stays readable over
 * path and loop lines. */
void bg_text_halo(bg_diagram *d, const char *markup, bg_vec p, double size);

/* Moves a w × h label centred at *p to the nearest of a few positions
 * (above and below) that overlaps no node and no label placed before. */
void bg_place_label(bg_diagram *d, double w, double h, bg_vec *p);

/* layers (diagram_layers.c) */
void bg_draw_paths(bg_diagram *d);
void bg_draw_loops(bg_diagram *d);
void bg_draw_conflicts(bg_diagram *d);
void bg_draw_legend(bg_diagram *d);
/* Text for a path's or loop's legend line. */
void bg_layer_describe(const bg_diagram *d, int kind, int i, bg_strbuf *out);
bg_rgba bg_layer_color(const bg_diagram *d, int kind, int i);

/* DOT output (diagram_dot.c) */
void bg_diagram_write_dot(const bg_diagram *d, bg_strbuf *out);
#endif
