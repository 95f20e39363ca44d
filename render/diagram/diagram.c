/* SPDX-License-Identifier: BSD-3-Clause */
/* The driver. Model + analysis → a layout result (labels measured with
 * pango, positions from Graphviz and the grid pass, where the bonds run),
 * then a scene drawn from it by the passes, in drawing order. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

/* ---------------------------------------------------------------- labels */

/* The name an element's label shows: inside an instance's frame, which
 * names the instance, its own name (R : r, not R : O1.M1.S1.r; issue 31). */
static const char *frame_name(const bg_model *m, int e) {
  const char *name = m->elem_name[e], *dot = strrchr(name, '.');
  return m->ninst > 0 && m->elem_inst[e] >= 0 && dot && dot[1] ? dot + 1 : name;
}

static char *elem_markup(bg_diagram_layout *d, int e) {
  const bg_model *m = d->m;
  bg_strbuf b = {0};
  const char *kind = bg_elem_display_kind(m, e);
  bg_markup_escapen(&b, kind, strlen(kind));
  if (!bg_elem_is_junction(m->elem_kind[e]) && (d->show & BG_SHOW_LABELS)) {
    bg_sb_puts(&b, " : ");
    if (m->elem_label && m->elem_label[e]) bg_markup_escapen(&b, m->elem_label[e], strlen(m->elem_label[e]));
    else bg_name_markup(&b, frame_name(m, e), d->st.font_size);
  }
  char *s = bg_arena_strdup(&d->arena, bg_sb_str(&b));
  bg_sb_free(&b);
  return s;
}

/* "∫ : phi": the integrator of a user state. */
static char *state_markup(bg_diagram_layout *d, int s) {
  bg_strbuf b = {0};
  bg_sb_puts(&b, "\u222b : ");
  bg_name_markup(&b, d->m->state_name[s], d->st.font_size);
  char *r = bg_arena_strdup(&d->arena, bg_sb_str(&b));
  bg_sb_free(&b);
  return r;
}

/* Every node's box (label and padding) in style st. */
static void node_boxes(const bg_diagram_layout *d, const bg_style *st, double *nw, double *nh) {
  const bg_model *m = d->m;
  for (int i = 0; i < d->nnode; i++) {
    double w, h;
    bg_text_measure(st->font, st->font_size, d->nlabel[i], &w, &h);
    /* pango's logical height includes the line gap: trim it so vertical
     * bonds come as close to the glyphs as horizontal ones */
    nw[i] = w + 2 * st->node_pad;
    nh[i] = 0.8 * h + 2 * st->node_pad;
  }
  /* a collapsed instance's box: room around its label for the bonds and
   * their strokes on every side */
  for (int k = 0; k < m->ninst; k++)
    if (d->inst_box[k] >= 0) nw[d->inst_box[k]] += 16, nh[d->inst_box[k]] += 12;
}

static void label_nodes(bg_diagram_layout *d) {
  const bg_model *m = d->m;
  for (int i = 0; i < d->nnode; i++) d->nlabel[i] = i < m->nelem ? elem_markup(d, i) : "Sf*";
  for (int s = 0; s < m->nstate; s++)
    if (d->state_node[s] >= 0) d->nlabel[d->state_node[s]] = state_markup(d, s);
  bg_parts_labels(d);
  bg_fields_labels(d);
}

static void measure_nodes(bg_diagram_layout *d) {
  label_nodes(d);
  node_boxes(d, &d->st, d->nw, d->nh);
}

/* The boxes the labels would have in style ref (their markup made again
 * for it: a subscript's rise follows the font size and changes the height). */
static void reference_boxes(bg_diagram_layout *d, const bg_style *ref, double *w, double *h) {
  bg_style own = d->st;
  char **labels = d->nlabel;
  d->st = *ref;
  d->nlabel = bg_arena_alloc(&d->arena, ((size_t)d->nnode + 1) * sizeof(char *));
  label_nodes(d);
  node_boxes(d, ref, w, h);
  d->nlabel = labels, d->st = own;
}

/* ---------------------------------------------------------------- layout */
static const char *choose_engine(const bg_diagram_layout *d, int *instead_of_dot) {
  const bg_model *m = d->m;
  *instead_of_dot = 0;
  if (d->o.layout) return d->o.layout;
  const char *e = m->layout.engine ? m->layout.engine : "dot";
  if (!strcmp(e, "dot") && d->nnode > 2000) {
    *instead_of_dot = 1;
    /* dot and sfdp need 10-30 s at 10 000 nodes, rows (linear) a few ms
     * (docs/drawing.md) */
    bg_logf(d->o.log, BG_LOG_PROGRESS, "%d nodes: too many for dot", d->nnode);
    return "rows";
  }
  return e;
}

/* Layout edges: the bonds, Sf* → junction for Lagrange sources, and for a
 * drawn user state its inputs → integrator → modulated elements. Returns
 * the count; *tail and *head are allocated. */
static int layout_edges(const bg_diagram_layout *d, int **tail, int **head) {
  const bg_model *m = d->m;
  int cap = m->nbond + d->nnode + m->nsignal + m->ndet + 1, n = 0;
  for (int s = 0; s < m->nstate; s++) cap += d->state_node[s] >= 0 ? 64 : 0;
  int *t = bg_xcalloc((size_t)cap, sizeof *t), *h = bg_xcalloc((size_t)cap, sizeof *h);
  /* bonds first (edge b is bond b; a bond inside a collapsed box joins the
   * box to itself and is left out by run_layout) */
  for (int b = 0; b < m->nbond; b++) t[n] = m->bond_tail[b], h[n++] = m->bond_head[b];
  for (int k = 0; k < m->ndet; k++)
    if (d->det_draw[k] >= 0) t[n] = bg_detector_anchor(d, k), h[n++] = d->det_draw[k];
  for (int i = 0; d->a && i < d->a->nlag; i++)
    if (d->lag_node[i] >= 0) t[n] = d->lag_node[i], h[n++] = d->a->lag_junction[i];
  for (int s = 0; s < m->nstate; s++) {
    if (d->state_node[s] < 0) continue;
    int in[64], nin = bg_state_inputs(m, s, in, 64);
    for (int k = 0; k < nin; k++) t[n] = in[k], h[n++] = d->state_node[s];
  }
  for (int i = 0; i < m->nsignal; i++) {
    int s = bg_signal_state(d, i);
    if (s >= 0 && d->state_node[s] >= 0) t[n] = d->state_node[s], h[n++] = m->signal_to[i];
  }
  for (int i = 0; i < n; i++) t[i] = d->node_of[t[i]], h[i] = d->node_of[h[i]];
  *tail = t, *head = h;
  return n;
}

static int part_of(int *up, int v) {
  while (up[v] != v) v = up[v] = up[up[v]]; /* halving: unions in file order leave paths as long as the chain */
  return v;
}

/* The roots dot ranks from: the first source (in model order) of each
 * connected part, so a chain with sources at both ends (slider crank) runs
 * from one to the other instead of folding back from both. A part without a
 * source starts from its first node (layout.c). A ring's drawing splits
 * where it starts and where its two ways meet, so a ring of instances whose
 * first source is inside an instance starts at the first element of the
 * model's own instead, when the part has one (a battery pack's cells in a
 * ring with its load: started in the first cell, the first and the opposite
 * cell's frames each spanned both rows, round the load; issue 31). */
static void first_sources(const bg_diagram_layout *d, const int *tail, const int *head, int ne,
                          unsigned char *root) {
  const bg_model *m = d->m;
  int *up = bg_xcalloc((size_t)d->nnode + 1, sizeof *up);
  unsigned char *has = bg_xcalloc((size_t)d->nnode + 1, 1), *ring = bg_xcalloc((size_t)d->nnode + 1, 1);
  int *own = bg_xcalloc((size_t)d->nnode + 1, sizeof *own), *first = bg_xcalloc((size_t)d->nnode + 1, sizeof *first);
  for (int v = 0; v < d->nnode; v++) up[v] = v, own[v] = first[v] = -1;
  for (int i = 0; i < ne; i++) {
    int a = part_of(up, tail[i]), b = part_of(up, head[i]);
    if (a == b && tail[i] != head[i] && i < m->nbond) ring[a] = 1; /* a bond closing a cycle */
    if (a != b) up[a] = b, ring[b] |= ring[a];
  }
  for (int e = 0; e < m->nelem; e++) {
    int c = part_of(up, e);
    if (bg_elem_is_source(m->elem_kind[e]) && first[c] < 0) first[c] = e;
    if (m->ninst > 0 && m->elem_inst[e] < 0 && own[c] < 0) own[c] = e;
  }
  for (int e = 0; e < m->nelem; e++) {
    int c = part_of(up, e);
    if (has[c] || first[c] < 0) continue;
    has[c] = 1;
    root[ring[c] && own[c] >= 0 && m->elem_inst[first[c]] >= 0 ? own[c] : first[c]] = 1;
  }
  free(up), free(has), free(ring), free(own), free(first);
}

/* The rows layout of the default style's boxes (rw, rh) stretched, across
 * and down apart, by the most any of the style's own boxes is larger: a
 * stretch keeps every left/right and above/below order, so every style
 * draws the same arrangement (issue 31), and no two boxes that were apart
 * can meet (each grows by at most the stretch, the space between them by
 * as much). A smaller style keeps the default's places. */
static void scale_rows(bg_diagram_layout *d, const double *rw, const double *rh) {
  double kx = 1, ky = 1;
  for (int v = 0; v < d->nnode; v++) {
    if (rw[v] > 0) kx = fmax(kx, d->nw[v] / rw[v]);
    if (rh[v] > 0) ky = fmax(ky, d->nh[v] / rh[v]);
  }
  if (kx == 1 && ky == 1) return;
  for (int v = 0; v < d->lay.nnode; v++) d->lay.x[v] *= kx, d->lay.y[v] *= ky;
  d->lay.width *= kx, d->lay.height *= ky;
}

/* The modulating signals as pairs of layout nodes (rows hangs a one-port on
 * the side facing them): from the element, the user state's node, or a
 * bond variable's bond (its head's node), to the modulated element.
 * Returns the count; *a and *b are allocated. */
static int signal_links(const bg_diagram_layout *d, int **a, int **b) {
  const bg_model *m = d->m;
  int n = 0;
  *a = bg_xcalloc((size_t)m->nsignal + 1, sizeof **a), *b = bg_xcalloc((size_t)m->nsignal + 1, sizeof **b);
  for (int i = 0; i < m->nsignal; i++) {
    int from = bg_signal_from_node(d, i), to = d->node_of[m->signal_to[i]];
    if (from >= 0 && from != to) (*a)[n] = from, (*b)[n++] = to;
  }
  return n;
}

/* The layout a forest too large for dot starts from: no engine run (the
 * grid pass places every node from bg_grid_tree_ranks), arrays for every
 * node and edge, no curves; its engine "tree". */
static void forest_layout(bg_layout *lay, const bg_layout_in *in) {
  memset(lay, 0, sizeof *lay);
  lay->nnode = in->nnode, lay->nedge = in->nedge;
  lay->x = bg_xcalloc((size_t)in->nnode + 1, sizeof *lay->x);
  lay->y = bg_xcalloc((size_t)in->nnode + 1, sizeof *lay->y);
  lay->spladr = bg_xcalloc((size_t)in->nedge + 1, sizeof *lay->spladr);
  lay->spln = bg_xcalloc((size_t)in->nedge + 1, sizeof *lay->spln);
  snprintf(lay->engine, sizeof lay->engine, "tree");
}

static int run_layout(bg_diagram_layout *d, bg_diags *dg) {
  const bg_model *m = d->m;
  int *tail, *head, ne = layout_edges(d, &tail, &head);
  int *pinned = bg_xcalloc((size_t)d->nnode, sizeof *pinned);
  unsigned char *root = bg_xcalloc((size_t)d->nnode, 1);
  double *px = bg_xcalloc((size_t)d->nnode, sizeof *px), *py = bg_xcalloc((size_t)d->nnode, sizeof *py);
  int any_pinned = 0;
  for (int e = 0; e < m->nelem; e++)
    if (m->elem_has_at && m->elem_has_at[e])
      pinned[e] = any_pinned = 1, px[e] = m->elem_at_x[e], py[e] = m->elem_at_y[e];
  first_sources(d, tail, head, ne, root);
  /* the junction structure (bonds between junctions and two-ports) straight,
   * the one-ports hanging off it */
  int *weight = bg_xcalloc((size_t)ne + 1, sizeof *weight);
  for (int i = 0; i < ne; i++) {
    int t = tail[i], h = head[i];
    weight[i] = i < m->nbond && !bg_elem_is_oneport(m->elem_kind[t]) &&
                        !bg_elem_is_oneport(m->elem_kind[h]) ? 4 : 1;
  }
  /* Where the grid pass places the nodes, Graphviz only ranks and orders
   * them, and it sees the labels measured in the built-in default style
   * (font, size, padding, spacing): the order then depends on the graph and
   * its words, not on the style, so a figure keeps its arrangement in every
   * style (issue 31: print's serif font swapped nodes in 9 of 69 models);
   * the grid pass spaces them with the style's own sizes. */
  int instead_of_dot;
  const char *engine = choose_engine(d, &instead_of_dot), *rd = m->layout.rankdir;
  int grid = !strcmp(engine, "dot") && !d->st.splines && !any_pinned && (!rd || !strcmp(rd, "LR"));
  /* a forest too large for dot: the grid pass's tree drawing, from
   * breadth-first ranks and a depth-first order (bg_grid_tree_ranks), in
   * place of the rows layout's places (issue 31: the rows layout drew a
   * random tree with 4 to 5 times the crossings and 8 times the slanted
   * bonds; the grid pass is linear, and faster) */
  int tree = instead_of_dot && !d->st.splines && !any_pinned && (!rd || !strcmp(rd, "LR"));
  /* rows likewise lays out the default style's boxes, and the result is
   * stretched to fit the style's own (scale_rows) */
  int is_rows = !strcmp(engine, "rows"), rows = is_rows && !any_pinned, refsized = grid || rows;
  bg_style ref;
  bg_style_default(&ref);
  const bg_style *lst = refsized ? &ref : &d->st;
  double *gw = d->nw, *gh = d->nh;
  if (refsized) {
    gw = bg_xcalloc((size_t)d->nnode + 1, sizeof *gw), gh = bg_xcalloc((size_t)d->nnode + 1, sizeof *gh);
    reference_boxes(d, &ref, gw, gh);
  }
  unsigned char *dead_end = bg_xcalloc((size_t)d->nnode + 1, 1); /* the integrators: no short cuts */
  for (int s = 0; s < m->nstate; s++)
    if (d->state_node[s] >= 0) dead_end[d->state_node[s]] = 1;
  bg_layout_in in = {d->nnode, gw, gh, pinned, px, py, ne, tail, head,
                     engine, rd, lst->node_sep, lst->rank_sep,
                     d->st.splines, root, weight, dead_end, 0, NULL, NULL, NULL, 0, NULL, NULL};
  int *link_a = NULL, *link_b = NULL;
  if (is_rows) in.nlink = signal_links(d, &link_a, &link_b), in.link_a = link_a, in.link_b = link_b;
  /* submodel instances: one frame (cluster) each, around its elements */
  int *cluster = NULL;
  double *label_h = NULL;
  if (m->ninst > 0) {
    cluster = bg_xcalloc((size_t)d->nnode + 1, sizeof *cluster);
    label_h = bg_xcalloc((size_t)m->ninst + 1, sizeof *label_h);
    for (int i = 0; i < d->nnode; i++) cluster[i] = i < m->nelem ? m->elem_inst[i] : -1;
    for (int k = 0; k < m->ninst; k++) /* a box sits in its parent's frame */
      if (d->inst_box[k] >= 0) cluster[d->inst_box[k]] = m->inst_parent[k];
    for (int k = 0; k < m->ndet; k++) /* a detector in the frame of the node it reads */
      if (d->det_draw[k] >= 0)
        cluster[d->det_draw[k]] = bg_detector_anchor(d, k) < m->nelem ? m->elem_inst[m->det_node[k]] : -1;
    for (int k = 0; k < m->ninst; k++) label_h[k] = bg_frame_label_height(lst);
    in.ncluster = m->ninst, in.cluster = cluster, in.cluster_parent = m->inst_parent;
    in.cluster_label_h = label_h;
  }
  char err[256];
  if (d->rep && d->ncollapsed) { /* both leave nodes out of the layout: not combined yet */
    bg_diag_error(dg, (bg_srcloc){0}, "--collapse cannot draw a model with multiport fields yet; "
                  "draw it without --collapse");
    free(tail), free(head), free(pinned), free(root), free(weight), free(dead_end), free(px), free(py);
    free(cluster), free(label_h), free(link_a), free(link_b);
    if (refsized) free(gw), free(gh);
    return -1;
  }
  int rc = 0;
  if (tree && bg_grid_is_forest(d)) {
    forest_layout(&d->lay, &in);
    bg_logf(d->o.log, BG_LOG_PROGRESS, "a forest: drawn as a tree on the grid");
  } else {
    if (instead_of_dot) bg_logf(d->o.log, BG_LOG_PROGRESS, "laying out with rows instead");
    tree = 0;
    bg_fields_lay *fields = bg_fields_compact(d, &in);
    rc = bg_parts_layout(d, &in, &d->lay, err, sizeof err);
    bg_fields_expand(d, fields);
  }
  if (rc) bg_diag_error(dg, (bg_srcloc){0}, "%s", err);
  free(tail), free(head), free(pinned), free(weight), free(dead_end), free(px), free(py);
  free(cluster), free(label_h), free(link_a), free(link_b);
  if (rc == 0) {
    d->nx = d->lay.x, d->ny = d->lay.y;
    d->splx = d->lay.splx, d->sply = d->lay.sply;
    if (tree) bg_grid_tree_ranks(d, root), grid = 1, rows = 0;
    if (rows) scale_rows(d, gw, gh);
    if (grid) bg_grid_place(d, &ref, gw, gh, tree);
    bg_parts_spread(d);
    d->ref_sized = grid || rows;
  }
  if (refsized) free(gw), free(gh);
  free(root);
  return rc ? -1 : 0;
}

/* ---------------------------------------------------------------- highlight */
static void hot_bond(const bg_diagram_layout *L, int b, unsigned char *hb, unsigned char *he) {
  const bg_model *m = L->m;
  hb[b] = 1;
  he[m->bond_tail[b]] = he[m->bond_head[b]] = 1;
  he[L->node_of[m->bond_tail[b]]] = he[L->node_of[m->bond_head[b]]] = 1;
}

static int count_of(const bg_analysis *a, int kind) {
  if (!a) return 0;
  return kind == 'p' ? a->npath : kind == 'l' ? a->ntloop : a->nconflict;
}

/* Whether the highlighted item exists; reports it to dg when not. */
static int check_highlight(const bg_diagram *d, bg_diags *dg) {
  int kind = d->o.highlight_kind, k = d->o.highlight_index - 1;
  static const char *names[] = {"causal path", "topological loop", "conflict"};
  const char *what = names[kind == 'p' ? 0 : kind == 'l' ? 1 : 2];
  int n = count_of(d->a, kind);
  if (k < 0 || k >= n) {
    bg_diag_error(dg, (bg_srcloc){0}, "--highlight: no %s %d (the model has %d)", what, k + 1, n);
    return -1;
  }
  return 0;
}

void bg_diagram_hot(const bg_diagram_layout *L, int kind, int index, unsigned char *hb,
                    unsigned char *he) {
  const bg_model *m = L->m;
  const bg_analysis *a = L->a;
  int k = index - 1;
  if (!kind) {
    memset(hb, 1, (size_t)m->nbond + 1);
    memset(he, 1, (size_t)L->nnode + 1);
    return;
  }
  if (kind == 'p')
    for (int i = 0; i < a->path_n[k]; i++) hot_bond(L, a->path_bonds[a->path_adr[k] + i], hb, he);
  if (kind == 'l')
    for (int i = 0; i < a->tloop_n[k]; i++) hot_bond(L, a->tloop_signals[a->tloop_adr[k] + i] / 2, hb, he);
  if (kind == 'c') {
    he[a->conflict_node[k]] = 1;
    for (int i = 0; i < a->conflict_n[k]; i++) hot_bond(L, a->conflict_bonds[a->conflict_adr[k] + i], hb, he);
  }
}

/* ---------------------------------------------------------------- build */
static int alloc_nodes(bg_diagram_layout *d, bg_diags *dg) {
  const bg_model *m = d->m;
  int nlag = d->a ? d->a->nlag : 0;
  d->lag_node = bg_arena_alloc(&d->arena, sizeof(int) * (size_t)(nlag + 1));
  d->nnode = m->nelem;
  for (int i = 0; i < nlag; i++)
    d->lag_node[i] = d->a->lag_junction[i] >= 0 ? d->nnode++ : -1;
  d->state_node = bg_arena_alloc(&d->arena, sizeof(int) * ((size_t)m->nstate + 1));
  for (int s = 0; s < m->nstate; s++) d->state_node[s] = -1;
  bg_signal_states(d);
  for (int i = 0; (d->show & BG_SHOW_SIGNALS) && i < m->nsignal; i++) {
    int s = bg_signal_state(d, i);
    if (s >= 0 && d->state_node[s] < 0) d->state_node[s] = d->nnode++;
  }
  if (bg_parts_nodes(d, dg) != 0) return -1;
  size_t n = (size_t)d->nnode + 1;
  d->node_state = bg_arena_alloc(&d->arena, n * sizeof(int));
  d->node_det = bg_arena_alloc(&d->arena, n * sizeof(int));
  for (int v = 0; v < d->nnode; v++) d->node_state[v] = d->node_det[v] = -1;
  for (int s = 0; s < m->nstate; s++)
    if (d->state_node[s] >= 0) d->node_state[d->state_node[s]] = s;
  for (int k = 0; k < m->ndet; k++)
    if (d->det_draw[k] >= 0) d->node_det[d->det_draw[k]] = k;
  d->nw = bg_arena_alloc(&d->arena, n * sizeof(double));
  d->nh = bg_arena_alloc(&d->arena, n * sizeof(double));
  d->nlabel = bg_arena_alloc(&d->arena, n * sizeof(char *));
  d->bg = bg_arena_alloc(&d->arena, ((size_t)m->nbond + 1) * sizeof *d->bg);
  return 0;
}

/* Moves everything drawn by v. */
static void move_scene(bg_scene *s, bg_vec v) {
  for (int i = 0; i < s->nop; i++)
    s->pt[i].x += v.x, s->pt[i].y += v.y;
  for (int i = 0; i < s->nitem; i++)
    if (s->item[i].kind == BG_ITEM_TEXT) s->item[i].x += v.x, s->item[i].y += v.y;
}

/* The page around the drawing (bg_scene_fit), remembering the move. A
 * redrawn diagram is not fitted: keep_page puts it on its source's page. */
static void fit_page(bg_diagram *d) {
  if (d->keep_page) return;
  double x0, y0, x1, y1;
  bg_scene_bbox(&d->scene, &x0, &y0, &x1, &y1);
  d->shift = bg_vadd(d->shift, bg_v(d->st.margin - x0, d->st.margin - y0));
  bg_scene_fit(&d->scene, d->st.margin);
}

/* A redrawn diagram gets its source's shift, so every node lands where it
 * is there, and its page; the page grows (with the margin) where the drawing
 * reaches beyond it, moving everything right or down when that is on the
 * left or at the top. */
static void keep_page(bg_diagram *d) {
  bg_scene *s = &d->scene;
  double x0, y0, x1, y1, mg = d->st.margin;
  bg_scene_bbox(s, &x0, &y0, &x1, &y1);
  bg_vec sh = d->keep_shift;
  double gx = fmax(0, mg - (x0 + sh.x)), gy = fmax(0, mg - (y0 + sh.y));
  d->shift = bg_vadd(sh, bg_v(gx, gy));
  move_scene(s, d->shift);
  s->width = ceil(fmax(d->keep_w, x1 + sh.x + mg) + gx);
  s->height = ceil(fmax(d->keep_h, y1 + sh.y + mg) + gy);
}

/* Drawing order: layer polylines at the bottom, then bonds, strokes,
 * signals, numbers, labels, conflicts, and the path tags and loop gains on
 * top. Text is placed clear of what was drawn before it (diagram_place.c):
 * numbers, tags and gains see the bonds, nodes, signals and polylines. */
/* In a highlighted diagram the path tag or gain keeps to the box of what
 * is drawn before it (nodes, bonds, numbers, signals, its line), grown by
 * the margin; bands around it count as obstacles. Redrawn from a full
 * diagram (as the report does), whose drawing holds this one's and whose
 * page is the margin larger, it then stays on that page, and a fresh build
 * draws the same. A full diagram's tags need no fence: they keep beside
 * their lines, and the page grows around them. */
static void drawing_fence(bg_diagram *d) {
  double x0, y0, x1, y1, t = 120, g = d->st.margin;
  if (!d->o.highlight_kind || !bg_scene_bbox(&d->scene, &x0, &y0, &x1, &y1)) return;
  x0 -= g, y0 -= g, x1 += g, y1 += g;
  for (int twice = 0; twice < 2; twice++) { /* outside costs as much as two labels covered */
    bg_obstacle_rect(d, x0 - t, y0 - t, x1 + t, y0);
    bg_obstacle_rect(d, x0 - t, y1, x1 + t, y1 + t);
    bg_obstacle_rect(d, x0 - t, y0, x0, y1);
    bg_obstacle_rect(d, x1, y0, x1 + t, y1);
  }
}

static void draw_all(bg_diagram *d) {
  unsigned show = d->show;
  int hk = d->o.highlight_kind;
  int frames = d->scene.nitem;
  bg_draw_frames(d);
  /* numbers and tags keep off the frames' lines and labels (issue 31) */
  for (int i = frames; i < d->scene.nitem; i++) {
    const bg_scene_item *it = &d->scene.item[i];
    double b[4];
    if (it->kind != BG_ITEM_TEXT) bg_obstacle_item(d, i);
    else bg_scene_item_box(&d->scene, it, b), bg_obstacle_rect(d, b[0], b[1], b[2], b[3]);
  }
  bg_obstacle_nodes(d);
  bg_layers_prepare(d); /* the layers' sides counted: the routes keep off their lines */
  if (show & BG_SHOW_SIGNALS) bg_route_signals(d); /* loops closed by a modulation follow them */
  if ((show & BG_SHOW_PATHS) || hk == 'p') bg_draw_paths(d);
  if ((show & BG_SHOW_LOOPS) || hk == 'l') bg_draw_loops(d);
  bg_draw_bonds(d);
  if (show & BG_SHOW_SIGNALS) bg_draw_signals(d);
  bg_draw_lagrange(d);
  for (int i = 0; i < d->npoly; i++) bg_obstacle_owned(d, d->poly[i], i + 1);
  if (d->m->nfield) bg_draw_field_ports(d);
  bg_draw_numbers(d);
  bg_draw_nodes(d);
  bg_draw_parts(d);
  if (d->a && ((show & BG_SHOW_CONFLICTS) || hk == 'c')) bg_draw_conflicts(d);
  drawing_fence(d);
  bg_place_layer_labels(d);
  fit_page(d);
  if (show & BG_SHOW_LEGEND) {
    bg_draw_legend(d);
    fit_page(d);
  }
  if (d->keep_page) keep_page(d);
}

/* What bg_route_blocked_bonds did to a reference layout d, kept for the
 * styles that follow it (bg_restyle_routes): the bonds it drew otherwise
 * than before (bends: d's corners before it; they are freed here) and the
 * nodes it moved (x, y: their centres before: the one-ports it mirrored). */
static void keep_routes(bg_diagram_layout *d, const bg_layout *bends, const double *x, const double *y) {
  const bg_layout *now = &d->lay;
  int nb = d->m->nbond;
  d->rerouted = bg_arena_alloc(&d->arena, (size_t)nb + 1);
  d->mirrored = bg_arena_alloc(&d->arena, (size_t)d->nnode + 1);
  memset(d->rerouted, 0, (size_t)nb + 1), memset(d->mirrored, 0, (size_t)d->nnode + 1);
  for (int b = 0; b < nb; b++) {
    int before = bends->bendn ? bends->bendn[b] : 0, after = now->bendn ? now->bendn[b] : 0, apart = before != after;
    for (int k = 0; !apart && k < after; k++)
      apart = bends->bendx[bends->bendadr[b] + k] != now->bendx[now->bendadr[b] + k] ||
              bends->bendy[bends->bendadr[b] + k] != now->bendy[now->bendadr[b] + k];
    d->rerouted[b] = (unsigned char)apart;
  }
  for (int v = 0; v < d->nnode; v++) d->mirrored[v] = (unsigned char)(x[v] != d->nx[v] || y[v] != d->ny[v]);
}

/* A copy of d's corners and centres before the bond router (keep_routes). */
static void routes_before(const bg_diagram_layout *d, bg_layout *bends, double **x, double **y) {
  const bg_layout *l = &d->lay;
  int nb = d->m->nbond, total = l->bendn ? l->nbend : 0;
  memset(bends, 0, sizeof *bends);
  if (l->bendn) {
    bends->bendadr = bg_xmalloc(((size_t)nb + 1) * sizeof(int)), bends->bendn = bg_xmalloc(((size_t)nb + 1) * sizeof(int));
    bends->bendx = bg_xmalloc(((size_t)total + 1) * sizeof(double)), bends->bendy = bg_xmalloc(((size_t)total + 1) * sizeof(double));
    memcpy(bends->bendadr, l->bendadr, (size_t)nb * sizeof(int)), memcpy(bends->bendn, l->bendn, (size_t)nb * sizeof(int));
    memcpy(bends->bendx, l->bendx, (size_t)total * sizeof(double)), memcpy(bends->bendy, l->bendy, (size_t)total * sizeof(double));
  }
  *x = bg_xmalloc(((size_t)d->nnode + 1) * sizeof(double)), *y = bg_xmalloc(((size_t)d->nnode + 1) * sizeof(double));
  memcpy(*x, d->nx, (size_t)d->nnode * sizeof(double)), memcpy(*y, d->ny, (size_t)d->nnode * sizeof(double));
}

/* Whether layout d follows its reference's routes: both laid out in the
 * reference boxes, the same nodes and bonds. */
static int follows_reference(const bg_diagram_layout *d) {
  const bg_diagram_layout *R = d->ref;
  return R && R->rerouted && R->ref_sized && d->ref_sized && R->nnode == d->nnode;
}

/* Nodes measured and laid out, where the bonds run. */
static int lay_out_bonds(bg_diagram_layout *d, bg_diags *dg) {
  if (alloc_nodes(d, dg) != 0) return -1;
  measure_nodes(d);
  bg_fields_prepare(d);
  if (run_layout(d, dg) != 0) return -1;
  bg_geom_bonds(d);
  /* a straight bond never through another node's label (issue 31); in a
   * style that follows the reference style's layout, where it ran there:
   * routed again in this style's sizes, a route took another corner of its
   * junction and pushed a one-port to the other side (issue 31: 48 label
   * pairs of 100 held-out models in another order in print or slides) */
  if (follows_reference(d)) {
    bg_restyle_routes(d, d->ref);
    bg_geom_bonds(d);
    return 0;
  }
  bg_layout bends;
  double *x = NULL, *y = NULL;
  int keep = d->keeps_routes && d->ref_sized;
  if (keep) routes_before(d, &bends, &x, &y);
  if (bg_route_blocked_bonds(d)) bg_geom_bonds(d);
  if (keep) {
    keep_routes(d, &bends, x, y);
    free(bends.bendadr), free(bends.bendn), free(bends.bendx), free(bends.bendy), free(x), free(y);
  }
  return 0;
}

/* Whether style s lays out as the reference style (the built-in default)
 * does: the same fonts, sizes, line widths, gaps and layer band (its
 * colours and marks do not move anything). */
static int reference_sizes(const bg_style *s) {
  bg_style r;
  bg_style_default(&r);
  return !strcmp(s->font, r.font) && s->font_size == r.font_size && s->number_scale == r.number_scale &&
         s->line_width == r.line_width && s->harpoon == r.harpoon && s->signal_width == r.signal_width &&
         s->layer_width == r.layer_width && s->layer_offset == r.layer_offset && s->node_pad == r.node_pad &&
         s->node_sep == r.node_sep && s->rank_sep == r.rank_sep && s->splines == r.splines;
}

static void layout_release(bg_diagram_layout *L);

/* The reference style's layout of d's model (d's own sizes are not the
 * reference's), laid out as far as the bond router, keeping what the router
 * did; NULL where d's sizes are the reference's, or it failed. A style
 * then follows it: which one-ports the grid pass pulls in towards their
 * hubs, where the routed bonds run (lay_out_bonds), which one-ports move
 * to 45 degrees (lay_out): each decided in the reference's sizes, so a
 * figure keeps its arrangement in every style (issue 31). */
static bg_diagram_layout *reference_layout(const bg_diagram_layout *d) {
  if (reference_sizes(&d->st)) return NULL;
  bg_diagram_layout *R = bg_xcalloc(1, sizeof *R);
  R->refs = 1;
  R->m = d->m, R->a = d->a, R->o = d->o, R->show = d->show;
  R->o.log = NULL; /* its progress is d's */
  R->keeps_routes = 1;
  bg_style_default(&R->st);
  bg_diags quiet;
  bg_diags_init(&quiet, NULL, NULL, 0);
  int rc = lay_out_bonds(R, &quiet);
  bg_diags_free(&quiet);
  if (rc == 0) return R;
  layout_release(R);
  return NULL;
}

/* The layout stage: nodes measured and laid out, where the bonds run, and
 * the one-ports at 45 degrees where nothing is in the way now that it is
 * known (diagram_diagonals.c); in the reference style's layout's steps
 * where d's sizes are not the reference's. */
static int lay_out(bg_diagram_layout *d, bg_diags *dg) {
  bg_diagram_layout *R = reference_layout(d);
  d->ref = R;
  int rc = lay_out_bonds(d, dg);
  if (rc == 0 && bg_diagonal_any(d)) { /* no one-port that may move: no index */
    /* chosen in the reference's layout: chosen in each style's own, where
     * its larger labels left no room in one style and did in another, a
     * one-port moved in the default style and stayed in its column in
     * slides. NULL: d's own sizes are the reference's */
    double *chosen = R ? bg_diagonal_choose(R)
                       : reference_sizes(&d->st) ? NULL : bg_xcalloc((size_t)d->m->nbond + 1, sizeof *chosen);
    if (bg_diagonal_one_ports(d, chosen)) bg_geom_bonds(d);
    free(chosen);
  }
  d->ref = NULL;
  layout_release(R);
  return rc;
}

/* The scene stage: what the highlight touches, then everything drawn. */
static void draw_scene(bg_diagram *d) {
  const bg_model *m = d->m;
  d->hot_elem = bg_arena_alloc(&d->arena, (size_t)d->L->nnode + 1);
  d->hot_bond = bg_arena_alloc(&d->arena, (size_t)m->nbond + 1);
  d->side_use = bg_arena_alloc(&d->arena, (2 * (size_t)m->nbond + 1) * sizeof(int));
  bg_diagram_hot(d->L, d->o.highlight_kind, d->o.highlight_index, d->hot_bond, d->hot_elem);
  bg_scene_init(&d->scene, d->st.font);
  d->scene.background = d->st.background;
  d->scene.title = bg_arena_strdup(&d->scene.arena, m->title ? m->title : m->name ? m->name : "");
  draw_all(d);
  /* what labels avoided is not needed once everything is placed: at
   * 100 000 masses it was 400 MB held while the SVG was written */
  bg_obstacles_free(d->obs);
  d->obs = NULL;
}

static void layout_release(bg_diagram_layout *L) {
  if (!L || --L->refs > 0) return;
  bg_layout_free(&L->lay);
  bg_arena_free(&L->arena);
  free(L);
}

/* The layout of a build: o's names are used here and not kept (they may be
 * gone when a redraw draws it again). */
static bg_diagram_layout *layout_build(const bg_diagram *d, bg_diags *dg) {
  bg_diagram_layout *L = bg_xcalloc(1, sizeof *L);
  L->refs = 1;
  L->m = d->m, L->a = d->a, L->o = d->o, L->show = d->show, L->st = d->st;
  int rc = lay_out(L, dg);
  L->o.style = L->o.style_dir = L->o.layout = NULL;
  L->o.collapse = NULL, L->o.ncollapse = 0;
  if (rc == 0) return L;
  layout_release(L);
  return NULL;
}

bg_diagram *bg_diagram_build(const bg_model *m, const bg_analysis *a, const bg_render_opts *o,
                             bg_diags *dg) {
  bg_diagram *d = bg_xcalloc(1, sizeof *d);
  d->m = m, d->a = a, d->o = *o;
  d->show = o->show ? o->show : BG_SHOW_DEFAULT;
  if (bg_style_load(&d->st, o->style, o->style_dir, dg) != 0) goto fail;
  /* a bad highlight is reported before the layout is paid for */
  if (o->highlight_kind && check_highlight(d, dg) != 0) goto fail;
  if (!(d->held = layout_build(d, dg))) goto fail;
  d->L = d->held;
  if (m->nbond > 5000) /* progress under -v: the drawing takes seconds at 10^5 bonds */
    bg_logf(d->o.log, BG_LOG_PROGRESS, "diagram: %d nodes laid out (%s); drawing", d->L->nnode,
            d->L->lay.engine);
  draw_scene(d);
  return d;
fail:
  bg_diagram_free(d);
  return NULL;
}

bg_diagram *bg_diagram_redraw(const bg_diagram *src, unsigned show, int highlight_kind,
                              int highlight_index, bg_diags *dg) {
  const unsigned fixed = BG_SHOW_LABELS | BG_SHOW_SIGNALS; /* they decide the nodes */
  bg_diagram *d = bg_xcalloc(1, sizeof *d);
  d->m = src->m, d->a = src->a, d->o = src->o, d->st = src->st;
  d->show = ((show ? show : BG_SHOW_DEFAULT) & ~fixed) | (src->show & fixed);
  /* the names given to bg_diagram_build are not needed any more (and may be gone) */
  d->o.style = d->o.style_dir = d->o.layout = NULL;
  d->o.collapse = NULL, d->o.ncollapse = 0;
  d->o.show = d->show;
  d->o.highlight_kind = highlight_kind, d->o.highlight_index = highlight_index;
  d->keep_page = 1;
  d->keep_shift = src->shift;
  d->keep_w = src->scene.width, d->keep_h = src->scene.height;
  if (highlight_kind && check_highlight(d, dg) != 0) {
    bg_diagram_free(d);
    return NULL;
  }
  /* the layout is shared, read only: either diagram may be freed first */
  d->held = src->held;
  d->held->refs++;
  d->L = d->held;
  draw_scene(d);
  return d;
}

void bg_diagram_free(bg_diagram *d) {
  if (!d) return;
  layout_release(d->held);
  bg_obstacles_free(d->obs);
  free(d->labels);
  free(d->poly);
  free(d->routes);
  bg_scene_free(&d->scene);
  bg_arena_free(&d->arena);
  free(d);
}
