/* SPDX-License-Identifier: BSD-3-Clause */
/* Layout: node positions (and optionally edge splines) from Graphviz. The
 * only interface to Graphviz; everything is drawn by bgdraw itself. */
#ifndef BG_LAYOUT_H
#define BG_LAYOUT_H
#include <stddef.h>

typedef struct bg_layout_in {
  int nnode;
  const double *w, *h;       /* node box sizes in points */
  const int *pinned;         /* nullable: node has a fixed position */
  const double *px, *py;     /* nullable: the fixed position (points, y up) */
  int nedge;
  const int *tail, *head;    /* node indices */
  const char *engine;        /* "dot", "neato", "fdp", "sfdp", "pinned", "rows" */
  const char *rankdir;       /* dot only: "LR", "TB", "RL", "BT" */
  double node_sep, rank_sep; /* points */
  int splines;               /* route edges as splines (else straight lines) */
  const unsigned char *root; /* nullable; dot: rank nodes by their breadth-first distance
                                from the root nodes (sources), not by edge direction */
  const int *weight;         /* nullable; dot: per edge, how much straighter and shorter
                                it should be than the others (1 = normal) */
  const unsigned char *dead_end; /* nullable; per node: the ranks reach it but do not go on
                                    through it (a user state's integrator) */
  /* dot only: frames (Graphviz clusters) around groups of nodes, e.g. the
   * instances of submodels; parents before children */
  int ncluster;
  const int *cluster;        /* nullable; per node: its innermost cluster, -1 none */
  const int *cluster_parent; /* per cluster: the enclosing one, -1 none */
  const double *cluster_label_h; /* per cluster: height kept for its label, points */
  /* rows only: pairs of nodes joined by lines the layout does not place by
   * (modulating signals); a hung one-port goes to the side facing them */
  int nlink;
  const int *link_a, *link_b;
} bg_layout_in;

typedef struct bg_layout {
  int nnode, nedge;      /* as laid out */
  double width, height;  /* bounding box of the nodes, points */
  double *x, *y;         /* node centres, y down, origin top-left of the box */
  int *spladr, *spln;    /* per edge: cubic Bezier points tail → head (3k+1), n 0 = none */
  double *splx, *sply;
  int nspl;
  /* per bond (edges 0..nbond-1) the corners of an orthogonal route set by
   * the grid pass (diagram_grid.c), bendn 0: straight; NULL when unused */
  int *bendadr, *bendn;
  double *bendx, *bendy;
  int nbend;
  int *band;             /* per node the band of a folded part it is drawn in, set by the
                            grid pass (frames are drawn per band); NULL when unused */
  char engine[16];       /* the engine actually used */
} bg_layout;

/* Lays out the graph. Returns 0, or -1 with a message in err. The caller
 * frees out with bg_layout_free. */
int bg_layout_run(const bg_layout_in *in, bg_layout *out, char *err, size_t errn);
void bg_layout_free(bg_layout *l);
/* Breadth-first distance of each node from in->root (nullable; a component
 * without a root starts from its first node);
 * order (nullable, nnode) gets the nodes in the order reached. Caller frees. */
int *bg_layout_depths(const bg_layout_in *in, int *order);
/* layout_align.c: n boxes in a fixed order along a line, box i at least
 * gap[i] after box i - 1 (gap[0] unused), the first at lo or after, the
 * last at hi or before (the gaps must fit), placed (x) as near their
 * wishes as that allows: the summed distance least, at least one box of
 * every pushed run exactly at its wish. O(n) but for runs merged again
 * and again. */
void bg_layout_align(int n, const double *wish, const double *gap, double lo, double hi, double *x);
/* layout_pack.c: n parts, part i w[i] by h[i], packed on a page `page`
 * wide, each where it sits highest on the outline of those placed, then
 * leftmost, hgap to its right and vgap below it kept free, the tallest
 * first or the widest first (ties: the lower index), whichever fills the
 * smaller box; part i's corner into x[i], y[i] (y down). Returns the area
 * of the box the parts fill. */
double bg_layout_pack(int n, const double *w, const double *h, double page, double hgap, double vgap, double *x,
                      double *y);
/* layout_maze.c: the cheapest orthogonal route over a window of cells
 * (x0, y0; w by h): cell(ctx, x, y, &extra) tells each cell's kind
 * (BG_MAZE_*) and the extra cost of passing it; a step costs 1, a corner
 * `bend`, a crossing `cross`. The route leaves (sx, sy) heading one of
 * sdirs and enters (tx, ty) heading one of tdirs (bit d: 0 +x, 1 +y,
 * 2 -x, 3 -y); it turns on free cells only, crosses other runs at right
 * angles only. Its corners into corner (start to end); returns their
 * count, -1 when there is no route or it needs more than max_corner;
 * the crossings into ncross (nullable). */
enum { BG_MAZE_FREE, BG_MAZE_BLOCKED, BG_MAZE_CROSS_H, BG_MAZE_CROSS_V }; /* CROSS_H: crossed heading along x */
typedef struct bg_maze {
  int x0, y0, w, h;
  int (*cell)(void *ctx, int x, int y, int *extra);
  void *ctx;
  int bend, cross;
} bg_maze;
int bg_maze_route(const bg_maze *mz, int sx, int sy, int sdirs, int tx, int ty, int tdirs, int (*corner)[2],
                  int max_corner, int *ncross);
/* layout_ring.c: n one-ports round their junction, each on a straight bond
 * from its centre, none through another's box (boxes at most w by h, gaps
 * xgap and ygap between them): on the sides of the smallest rectangle that
 * holds them, in the order of angle[i] (where each would be, radians, y
 * down), the middle of side k (bit k of closed: right, up, left, down) left
 * free when a bond leaves there. Offsets from the junction into ox[i],
 * oy[i]; half the width and height the boxes cover into *hx, *hy. */
void bg_layout_ring(int n, const double *angle, double w, double h, double xgap, double ygap, int closed,
                    double *ox, double *oy, double *hx, double *hy);
/* layout_rows.c: the "rows" engine (bg_layout_run calls it for "rows"). */
int bg_layout_rows(const bg_layout_in *in, bg_layout *out);
/* Whether name is an engine bg_layout_run accepts. */
int bg_layout_engine_ok(const char *name);
/* The Graphviz version bgdraw was built with ("2.43.0"). */
const char *bg_layout_graphviz_version(void);
#endif
