/* SPDX-License-Identifier: BSD-3-Clause */
/* Internals of the diagram builder, shared by diagram*.c and render.c. */
#ifndef BG_DIAGRAM_INT_H
#define BG_DIAGRAM_INT_H
#include "causality/causality.h"
#include "diagram/layout.h"
#include "model/model.h"
#include "diagram/render.h"
#include "scene/scene.h"
#include "scene/style.h"

/* <math.h> constants are not C11 */
#define BG_PI 3.14159265358979323846
#define BG_SQRT1_2 0.70710678118654752440
/* A signal's arrowhead: its length (diagram_signals.c draws it; the
 * router keeps other signals off it, diagram_route_cost.c). */
#define BG_SIGNAL_ARROW 6.0

typedef struct bg_vec {
  double x, y;
} bg_vec;

/* Where a bond runs on the page. */
typedef struct bg_bond_geom {
  bg_vec tail, head;   /* end points on the node boxes */
  bg_vec ltail, lhead; /* the same before a causal stroke drew them back off a label's text
                          (diagram_geom.c): text beside the bond goes along these */
  bg_vec tdir, hdir;   /* unit travel direction (tail → head) at each end */
  bg_vec mid, mdir;    /* middle point and direction there */
  int spladr, spln;    /* Graphviz spline points (page coordinates) or spln 0: straight */
  int bendadr, bendn;  /* else the corners of its route (lay.bendx/y), bendn 0: straight */
} bg_bond_geom;

/* The layout result: fixed once laid out (nodes measured, Graphviz or
 * rows, the grid pass, where each bond runs). Every drawing of it reads it
 * and none writes: bg_diagram_redraw shares its source's (counted by refs,
 * so either may be freed first). The layout stage's functions take it
 * writable; the passes see it through bg_diagram.L, const. */
typedef struct bg_diagram_layout {
  int refs;
  const bg_model *m;
  const bg_analysis *a; /* nullable */
  bg_render_opts o;     /* as built (collapse, engine, verbose); names not kept after the build */
  unsigned show;        /* its labels and signals bits decide the nodes */
  bg_style st;
  /* nodes: the model's elements, then one per Lagrange flow source attached to a junction */
  int nnode;
  double *nw, *nh, *nx, *ny; /* box size and centre on the page */
  char **nlabel;             /* pango markup */
  int *lag_node;             /* per Lagrange source: its node, or -1 (a split bond) */
  int *rep;                  /* per node: the node that draws it (a field's other ports:
                                its first port's, diagram_fields.c); NULL without fields */
  int *state_node;           /* per user state: its integrator node (drawn when a signal
                                comes from the state and signals are shown), or -1 */
  int *signal_state;         /* per signal: the user state it comes from, or -1 (bg_signal_states) */
  int *node_state, *node_det; /* per node: the user state whose integrator, the detector whose
                                node it is, or -1 (the inverses of state_node and det_draw) */
  int *det_draw;             /* per detector: its node (De : vC), or -1 (inside a box) */
  int *inst_box;             /* per instance: its word-bond-graph box node when it is drawn
                                collapsed (--collapse; the outermost collapsed one), or -1 */
  int *node_of;              /* per node: the node it is drawn as (a collapsed instance's
                                elements: its box), itself otherwise */
  unsigned char *bond_hidden; /* per bond: inside a collapsed box (not drawn) */
  int *box_inst;             /* per node: the instance whose box it is, or -1 */
  int ncollapsed;            /* boxes drawn */
  bg_layout lay;
  double *splx, *sply;       /* spline points moved onto the page */
  bg_bond_geom *bg;          /* per bond */
  double *jr;                /* per node: radius of a junction's end circle, else 0 */
  double *bjr;               /* per bond end (2 b + 1: head): radius it leaves its junction at, else 0 */
  const double *jr_least;    /* per node: the least radius of a junction's end circle (the one
                                the bonds were routed for, bg_diagonal_one_ports), or NULL */
  /* One arrangement in every style (issue 31): a style whose sizes are not
   * the reference style's follows the reference style's layout of the same
   * model where the grid pass or rows laid both out in the reference boxes */
  const struct bg_diagram_layout *ref; /* that layout while this one is laid out, or NULL */
  int ref_sized;             /* laid out in the reference style's boxes (the grid pass, rows) */
  int keeps_routes;          /* a reference: keeps what the bond router did (rerouted, mirrored) */
  unsigned char *pulled;     /* per node: moved back towards its hub (the grid pass's pull_in) */
  unsigned char *rerouted;   /* per bond: drawn otherwise by bg_route_blocked_bonds (a reference) */
  unsigned char *mirrored;   /* per node: a one-port mirrored through its hub there (a reference) */
  bg_arena arena;
} bg_diagram_layout;

/* One drawing: the scene of a layout with some layers and a highlight. */
struct bg_diagram {
  const bg_model *m;
  const bg_analysis *a; /* nullable */
  bg_render_opts o;
  unsigned show;
  bg_style st;
  const bg_diagram_layout *L; /* read only */
  bg_diagram_layout *held;    /* the same, for the reference count (diagram.c alone) */
  unsigned char *hot_bond, *hot_elem; /* highlight: what stays in colour */
  int *side_use;             /* per bond side: layers already drawn there */
  int *side_total, *side_home; /* per bond side: layers drawn there in all, the one that runs
                                  outermost (diagram_layers.c, plan_homes) */
  struct bg_obstacles *obs;  /* what labels must avoid (diagram_place.c) */
  int *loop_path;            /* per topological loop: the causal path whose polyline also
                                draws it (a flat loop caused by a shown path), or -1 */
  struct bg_layer_label *labels; /* path tags and loop gains, placed after every line */
  int nlabels, caplabels;
  int *poly, npoly, cappoly; /* scene items of path and loop polylines */
  struct bg_signal_route *routes; /* every routed signal's polyline, in drawing order
                                     (diagram_signals.c, bg_route_signals) */
  int nroutes, route_next;
  bg_vec shift;              /* what the scene was moved by: page = layout + shift */
  int keep_page;             /* drawn again (bg_diagram_redraw): placed on the page below */
  bg_vec keep_shift;         /* that diagram's shift and page size */
  double keep_w, keep_h;
  bg_scene scene;
  bg_arena arena;
};


/* The files call down this list, never a sibling or up (docs/developer.md):
 *   diagram_base.c, diagram_words.c  leaves: vectors, ink, colours, queries; markup
 *   diagram_route_near.c, then _cost.c and _grid.c, then _search.c and _branch.c  the router's insides
 *   diagram_geom.c, diagram_place.c, diagram_route.c, diagram_route_detour.c  where bonds run; text
 *           placement; signal routes (diagram_route_int.h); detours round one-ports
 *   passes: diagram_grid.c (layout stage), diagram_bonds.c, diagram_layers.c, diagram_marks.c,
 *           diagram_signals.c, diagram_parts.c, diagram_fields.c,
 *           diagram_frames.c, diagram_dot.c, diagram_tips.c, diagram_route_bonds.c,
 *           diagram_diagonals.c, diagram_restyle.c
 *   diagram.c  the driver: layout stage, then the scene stage calling each pass
 *   render.c   the front door (render.h) */

/* What highlight kind/index (checked; kind 0: none, everything) keeps in
 * colour: hot_bond (nbond + 1 bytes) and hot_elem (nnode + 1), zeroed by the
 * caller (diagram.c; the report's large highlights use it too). */
void bg_diagram_hot(const bg_diagram_layout *L, int kind, int index, unsigned char *hot_bond,
                    unsigned char *hot_elem);

/* ---- shared helpers (diagram_base.c): calls nothing of the diagram */
bg_vec bg_v(double x, double y);
bg_vec bg_vadd(bg_vec a, bg_vec b);
bg_vec bg_vsub(bg_vec a, bg_vec b);
bg_vec bg_vscale(bg_vec a, double k);
bg_vec bg_vunit(bg_vec a);
bg_vec bg_vleft(bg_vec d); /* left of travel on a y-down page */
double bg_vlen(bg_vec a);
double bg_point_seg(bg_vec c, bg_vec p, bg_vec q); /* distance from c to segment p-q */
double bg_seg_seg(bg_vec a0, bg_vec a1, bg_vec b0, bg_vec b1); /* distance between two segments, 0 where they cross */
bg_vec bg_seg_nearest(bg_vec c, bg_vec p, bg_vec q); /* the point of segment p-q nearest c */
/* Where the ray from a box's centre towards p leaves the box (half sizes hw, hh). */
bg_vec bg_box_exit(bg_vec c, double hw, double hh, bg_vec p);
/* colours with the highlight applied */
bg_rgba bg_diagram_ink(const bg_diagram *d, bg_rgba c, int hot);
int bg_diagram_muted(const bg_diagram *d);
/* The layer colour and dash of path (kind 'p') or loop ('l') i. */
bg_rgba bg_layer_color(const bg_diagram *d, int kind, int i);
void bg_layer_dash(const bg_diagram *d, int kind, int i, double dash[2]);
/* How far from its bond the k-th path or loop line stacked on a side runs
 * (k from 0): the first st->layer_offset off, each next 3 pt further (more
 * for thick lines). */
double bg_layer_line(const bg_style *st, int k);
/* Whether bond b ends at a store in derivative causality (its stroke drawn
 * in the derivative colour, doubled in print). */
int bg_bond_derivative(const bg_model *m, const bg_analysis *a, int b);
/* The bond whose variable a signal reads ("e7", "f7"), or -1. */
int bg_signal_bond(const bg_model *m, const char *var);
/* Fills d->signal_state (in d's arena): per signal the user state it comes
 * from, found by name in a hash of the states' names. */
void bg_signal_states(bg_diagram_layout *d);
/* The user state signal i comes from, or -1. */
int bg_signal_state(const bg_diagram_layout *d, int i);
/* The node signal i is drawn from (element, integrator or bond head), or -1. */
int bg_signal_from_node(const bg_diagram_layout *d, int i);
/* Per node: whether a signal starts or ends there (bg_signal_from_node, its
 * target's node), shown or not; free it. */
unsigned char *bg_signal_end_nodes(const bg_diagram_layout *d);
/* Per bond: how many path and loop lines are drawn beside it (the paths
 * and loops shown, or all of them when the layout keeps their room), or
 * NULL when none is; free it. */
int *bg_layer_use(const bg_diagram_layout *d);
/* Whether boxes a and b ({x0, y0, x1, y1}) overlap. */
int bg_boxes_meet(const double a[4], const double b[4]);
/* Whether segment s[0],s[1] - s[2],s[3] meets box [x0,x1]×[y0,y1] (Liang-Barsky clipping). */
int bg_seg_hits_box(const double *s, double x0, double y0, double x1, double y1);
/* Elements whose variables user state s integrates (at most cap, no repeats). */
int bg_state_inputs(const bg_model *m, int s, int *out, int cap);
/* Whether node n is drawn (not an element hidden in a collapsed box). */
int bg_node_shown(const bg_diagram_layout *d, int n);
/* The node a detector's node is anchored to in the layout (its det_node as drawn). */
int bg_detector_anchor(const bg_diagram_layout *d, int k);
/* A field's port drawn by its field's node. */
int bg_fields_hidden(const bg_diagram_layout *d, int n);

/* ---- words (diagram_words.c): calls nothing of the diagram */
/* A subscript's size in per cent of size: 70, or more to keep it at 6 pt. */
int bg_sub_percent(double size);
/* A name as markup: its trailing digits (or what follows the
 * last '_') a subscript, as in element labels. */
void bg_name_markup(bg_strbuf *b, const char *name, double font_size);
/* A loop gain as markup, typeset like the labels:
 * names with subscripts, powers raised, products by juxtaposition (a thin
 * space), minus signs, primes. */
void bg_gain_markup(const char *gain, double size, bg_strbuf *out);
/* Text for a path's or loop's legend line.
 * markup: the gain typeset (legend), else plain text (DOT). */
void bg_layer_describe(const bg_diagram *d, int kind, int i, int markup, bg_strbuf *out);

/* geometry (diagram_geom.c) */
void bg_geom_bonds(bg_diagram_layout *d);
/* Where a bond leaving node n's centre in direction dir stops: on a
 * junction's end circle, else on the node's box. */
bg_vec bg_node_end(const bg_diagram_layout *d, int n, bg_vec dir);
/* The point a fraction t of the way along bond b (its route's length), and
 * the direction of travel there (dir nullable). */
bg_vec bg_geom_along(const bg_diagram_layout *d, int b, double t, bg_vec *dir);
/* The ends of bond b's longest leg (the whole bond when it is straight). */
void bg_geom_longest_leg(const bg_diagram_layout *d, int b, bg_vec *p, bg_vec *q);
/* The grid placement pass (diagram_grid.c): node centres and bond routes.
 * ref, rw, rh: the reference style and the boxes the labels have in it
 * (what Graphviz saw), for what must not change with the style; own_ranks:
 * the ranks are bg_grid_tree_ranks', not dot's (a large forest). */
void bg_grid_place(bg_diagram_layout *d, const bg_style *ref, const double *rw, const double *rh, int own_ranks);
/* Ranks and orders for the grid pass without dot (a forest too large for
 * dot, bg_grid_is_forest): d->nx the breadth-first depth from the roots
 * (root[v]: a part's first source), d->ny a depth-first order. */
void bg_grid_tree_ranks(bg_diagram_layout *d, const unsigned char *root);
/* Whether the grid pass's graph of d (its bonds between drawn nodes) is a
 * forest: no cycle, no two bonds between the same nodes. */
int bg_grid_is_forest(bg_diagram_layout *d);
/* The side of the barb at the head of bond b: a unit normal. */
bg_vec bg_barb_side(const bg_diagram_layout *d, int b);
/* The barb's side for travel in direction dir (a bent bond's numbers use
 * the direction of the leg they are beside). */
bg_vec bg_barb_side_at(const bg_diagram_layout *d, bg_vec dir);
/* The far end of the half arrow at a bond's end `end`, the bond arriving in
 * direction dir: 7 line widths, 45 degrees back, on the barb's side. */
bg_vec bg_barb_tip(const bg_diagram_layout *d, bg_vec end, bg_vec dir);
/* Draws the bond's centre line as the current item's path of scene s. */
void bg_geom_bond_path(const bg_diagram_layout *d, bg_scene *s, int b);
/* The direction (of 8) around node n farthest in angle from its bonds. */
bg_vec bg_free_direction(const bg_diagram_layout *d, int n);
/* Filled arrowhead with its tip at p, pointing along dir. */
void bg_geom_arrowhead(bg_scene *s, bg_vec p, bg_vec dir, double len, double wid);


/* Orthogonal signal routes (diagram_route.c, its insides in diagram_route_*.c): a router holds the layout's
 * nodes and bond legs in a grid of cells and the routes given so far; the
 * legs of bonds marked in skip (nullable) are left out, as if not drawn.
 * ends_clear (the signals, and the bonds the bond router routes again):
 * each bond reaches its nodes' boxes (a line passing between a bond's end
 * and its node crosses the bond there, hidden in the gap) and a crossing
 * among its half arrow or stroke costs more (COST_AT_END); 0: the bonds as
 * drawn (the checks round the bond router). */
typedef struct bg_router bg_router;
bg_router *bg_router_new(const bg_diagram_layout *L, int nbond, const unsigned char *skip, int ends_clear);
/* The route from node from_node (or, when it is < 0, from the middle of
 * bond from_bond or near it) to node `to`: a polyline of horizontal and
 * vertical legs into pts (at most cap points), the first on the source,
 * the last the arrow's tip. Later routes keep off it, but for those of the
 * same group (>= 0: the same source), which may run on it and branch off. */
int bg_route(bg_router *r, const bg_model *m, int from_node, int from_bond, int to, int group, bg_vec *pts,
             int cap);
/* Where the last route leaves the earlier routes of its group that it
 * starts on: the index k of the segment pts[k]-pts[k+1] it leaves them on,
 * and the point (*at); -1 when it does not share its start. */
int bg_route_branch(const bg_router *r, bg_vec *at);
/* Route k (the k-th bg_route), pts[0..n-1] as kept, after all are routed:
 * each crossing of a one-port's bond on its segments from `first` on that
 * a short U round the one-port avoids, taken (at most cap points; the
 * index follows). Called again (after bg_route_nudge has made room), the
 * U's taken before are the route's own. Returns the new number of points. */
int bg_route_detour(bg_router *r, int k, int first, bg_vec *pts, int n, int cap);
/* Route k, pts[0..*n-1] as kept, after all are routed and taken round the
 * one-ports: each segment from `first` on that runs a few points beside
 * another source's signal moved across, whole (at an end its port sliding
 * along the box's side; the first stays when `first` > 0), where that
 * costs no more, then a small step by either end (the start's only when
 * `first` <= 0) straightened, its two points dropped (*n gets the new
 * length; diagram_route_nudge.c); the index follows. Returns how many
 * moves were made. */
int bg_route_nudge(bg_router *r, int k, int first, bg_vec *pts, int *n);
/* A line drawn before the routes that they must not run along (a frame's
 * border: a signal beside it reads as part of the frame), cheap to cross. */
void bg_route_fence(bg_router *r, bg_vec a, bg_vec b);
/* How far the path and loop lines drawn beside bond b reach from it:
 * ring[b] (the caller keeps it while routing; 0 or NULL: none). A route
 * pays for running among them as for running beside the bond, and a
 * source's corner port whose straight stub would run among them leaves on
 * a short diagonal out past them instead (a signal out of a junction,
 * issue 31). */
void bg_router_rings(bg_router *r, const double *ring);
void bg_router_free(bg_router *r);
/* Bonds whose line runs through another node's box routed again
 * (diagram_route_bonds.c), orthogonally round the boxes (their corners into L->lay); returns how
 * many. Call bg_geom_bonds again when it did any. */
int bg_route_blocked_bonds(bg_diagram_layout *L);
/* The bonds L's reference layout R routed again (R->rerouted) drawn as R
 * routed them, their corners carried over into L's sizes, and the one-ports
 * R mirrored through their hubs mirrored here too (diagram_restyle.c): the
 * same routes, corner for corner, in every style, where routing them again
 * in the style's own sizes took other corners and sides (issue 31). Call
 * bg_geom_bonds again after. */
void bg_restyle_routes(bg_diagram_layout *L, const bg_diagram_layout *R);
/* One-ports hanging off a junction at another slant moved to 45 degrees
 * (diagram_diagonals.c, after the bond router). bg_diagonal_choose: those
 * whose box and bond would stay clear of every other box and line, per
 * bond: its one-port's new distance from the junction along the longer
 * axis, as a share of its old one (negative: it stays level with its row
 * or column; 0: it does not move; free the array). bg_diagonal_one_ports
 * moves those chosen (NULL: those L's own layout chooses) by those shares,
 * each where its place at 45 degrees exists and is clear in L's own sizes;
 * returns how many. Call bg_geom_bonds again when it moved any.
 * bg_diagonal_any: whether L has a one-port that may move (its angle off
 * an axis; its room not asked): without one the pass is not run, nor
 * another style's layout built to choose. */
double *bg_diagonal_choose(const bg_diagram_layout *L);
int bg_diagonal_one_ports(bg_diagram_layout *L, const double *chosen);
int bg_diagonal_any(const bg_diagram_layout *L);

/* A patch of background behind centred text at p, so it stays readable over
 * path and loop lines. */
void bg_text_halo(bg_diagram *d, const char *markup, bg_vec p, double size);

/* placement (diagram_place.c) */
typedef struct bg_obstacles bg_obstacles;
void bg_obstacles_free(bg_obstacles *o);
void bg_obstacle_rect(bg_diagram *d, double x0, double y0, double x1, double y1);
/* Every node box. */
void bg_obstacle_nodes(bg_diagram *d);
/* The lines of scene item i (curves flattened). */
void bg_obstacle_item(bg_diagram *d, int i);
/* The same for a path or loop polyline: its segments remember their owner
 * (1, 2, ...); bond b's line is owned by -1 - b. */
void bg_obstacle_owned(bg_diagram *d, int i, int owner);
/* How many obstacles a w × h box centred at p touches (a box counts 10, a line 1). */
int bg_place_score(bg_diagram *d, bg_vec p, double w, double h);
/* The same, but it stops counting at limit and returns a value at or above
 * it: a candidate that cannot beat the best so far is not counted out (a
 * label near a fan of thousands of bonds out of one junction scanned them
 * all for every candidate). */
int bg_place_score_below(bg_diagram *d, bg_vec p, double w, double h, int limit);
/* How many segments of polylines other than owner's a w × h box centred at p touches. */
int bg_place_others(bg_diagram *d, bg_vec p, double w, double h, int owner);
/* How many boxes (nodes, texts) a w × h box centred at p touches. */
int bg_place_boxes(bg_diagram *d, bg_vec p, double w, double h);
/* The bond whose line comes nearest to p within r (the lowest index of
 * equals), or -1: a bond number is astray where it is not its own; into
 * *margin how much nearer it is than the next bond, at most slack (a
 * number midway between two bonds reads as either's). */
int bg_place_nearest_bond(bg_diagram *d, bg_vec p, double r, double slack, double *margin);
/* What the segment a-b runs through: the boxes (returned), bond lines
 * (*bonds) and other lines (*lines), the lines of polyline `owner` left out:
 * the cost of a tag's leader line. */
int bg_place_crossings(bg_diagram *d, bg_vec a, bg_vec b, int owner, int *bonds, int *lines);
/* The index of the candidate centre with the lowest score (the first on
 * ties); its box becomes an obstacle. */
int bg_place_best(bg_diagram *d, const bg_vec *cand, int n, double w, double h);

/* bonds (diagram_bonds.c): lines, strokes; numbers and labels beside them;
 * element labels; Lagrange sources */
void bg_draw_bonds(bg_diagram *d);
void bg_draw_numbers(bg_diagram *d);
void bg_draw_nodes(bg_diagram *d);
void bg_draw_lagrange(bg_diagram *d);

/* signals (diagram_signals.c) */
/* A signal's route from node `from` (-1: from bond from_bond's middle) to
 * node `to`: pts[0] on the source, pts[n - 1] the arrow's tip. */
typedef struct bg_signal_route {
  int from, from_bond, to, n;
  bg_vec *pts;
  int branch_k;    /* >= 0: drawn from branch_at on segment branch_k, where it leaves the line
                      of an earlier signal from the same source (a branch point, with a dot) */
  bg_vec branch_at;
} bg_signal_route;
/* Routes every signal drawn (into d->routes), before the path and loop
 * layers, whose loops closed by a modulation follow them. */
void bg_route_signals(bg_diagram *d);
/* Draws the routed signals. */
void bg_draw_signals(bg_diagram *d);

/* layers (diagram_layers.c) */
typedef struct bg_layer_label bg_layer_label;
/* Decides which flat loops are drawn with their causal path (loop_path). */
void bg_layers_prepare(bg_diagram *d);
/* Places and draws the path tags and loop gains collected while drawing. */
void bg_place_layer_labels(bg_diagram *d);
void bg_draw_paths(bg_diagram *d);
void bg_draw_loops(bg_diagram *d);
void bg_draw_conflicts(bg_diagram *d);
void bg_draw_legend(bg_diagram *d);
/* detectors and collapsed instances (diagram_parts.c) */
/* Validates --collapse (unknown names: an error with a suggestion) and
 * appends the detector and box nodes from d->nnode on. */
int bg_parts_nodes(bg_diagram_layout *d, bg_diags *dg);
/* Labels of detector and box nodes (markup, in the arena). */
void bg_parts_labels(bg_diagram_layout *d);
/* After the layout: hidden nodes take their box's centre and size. */
void bg_parts_spread(bg_diagram_layout *d);
/* bg_layout_run with each collapsed instance laid out as its box alone. */
int bg_parts_layout(const bg_diagram_layout *d, const bg_layout_in *in, bg_layout *out, char *err,
                    size_t errn);
/* Boxes and detectors with their activated bonds. */
void bg_draw_parts(bg_diagram *d);
/* instance frames (diagram_frames.c): one labelled box per submodel instance */
double bg_frame_label_height(const bg_style *st);
void bg_draw_frames(bg_diagram *d);

/* multiport fields (diagram_fields.c): one node per field, ports labelled */
typedef struct bg_fields_lay bg_fields_lay;
void bg_fields_labels(bg_diagram_layout *d);             /* each field's label on its first port */
void bg_fields_prepare(bg_diagram_layout *d);            /* after the nodes are measured */
/* Leaves the hidden ports out of the layout input (NULL: nothing to do), and
 * gives them their field's position after it (frees what compact made). */
bg_fields_lay *bg_fields_compact(const bg_diagram_layout *d, bg_layout_in *in);
void bg_fields_expand(bg_diagram_layout *d, bg_fields_lay *L);
void bg_draw_field_ports(bg_diagram *d);

/* DOT output (diagram_dot.c) */
void bg_diagram_write_dot(const bg_diagram *d, bg_strbuf *out);
/* diagram_tips.c: the SVG <title> of an item from its role (ctx: the diagram). */
void bg_diagram_tip(void *ctx, const char *role, bg_strbuf *out);
#endif
