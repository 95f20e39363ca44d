/* SPDX-License-Identifier: BSD-3-Clause */
/* Detectors and collapsed instances (docs/drawing.md, "Detectors" and
 * "Collapsed instances").
 * - A detector (De, Df) is drawn as its own node `De : vC` beside the node it
 *   reads, joined by an activated bond: a bond line with a full arrowhead at
 *   the detector and no half arrow, no number, no stroke (it carries no power:
 *   one of its variables is zero, the other is the signal it passes on).
 * - `--collapse M1` draws instance M1 as one word-bond-graph box `M1 : DCMotor`:
 *   its elements are hidden (they take the box's place, so every bond through
 *   a port ends on the box, with its half arrow and its stroke there), bonds
 *   inside it are not drawn, and the layout sees the box as one node. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

/* ---------------------------------------------------------------- names */
static int inst_named(const bg_model *m, const char *name) {
  for (int k = 0; k < m->ninst; k++)
    if (!strcmp(m->inst_name[k], name)) return k;
  return -1;
}

static void unknown_instance(const bg_model *m, const char *name, bg_diags *dg) {
  const char *best = NULL;
  int bd = strlen(name) < 3 ? 2 : 3;
  for (int k = 0; k < m->ninst; k++) {
    int dd = bg_edit_distance(name, m->inst_name[k]);
    if (dd < bd) bd = dd, best = m->inst_name[k];
  }
  if (best)
    bg_diag_error(dg, (bg_srcloc){0}, "--collapse %s: no instance '%s' (did you mean '%s'?)", name,
                  name, best);
  else if (m->ninst)
    bg_diag_error(dg, (bg_srcloc){0}, "--collapse %s: no instance '%s' (the model has %d: %s%s)",
                  name, name, m->ninst, m->inst_name[0], m->ninst > 1 ? ", ..." : "");
  else
    bg_diag_error(dg, (bg_srcloc){0}, "--collapse %s: the model has no submodel instances", name);
}

/* Marks the instances named by --collapse; -1 after an unknown name. */
static int mark_collapsed(const bg_diagram_layout *d, unsigned char *on, bg_diags *dg) {
  const bg_model *m = d->m;
  int bad = 0;
  for (int i = 0; i < d->o.ncollapse; i++) {
    const char *name = d->o.collapse[i];
    if (!strcmp(name, "all")) {
      memset(on, 1, (size_t)m->ninst);
      continue;
    }
    int k = inst_named(m, name);
    if (k < 0) unknown_instance(m, name, dg), bad = 1;
    else on[k] = 1;
  }
  return bad ? -1 : 0;
}

/* ---------------------------------------------------------------- nodes */
int bg_parts_nodes(bg_diagram_layout *d, bg_diags *dg) {
  const bg_model *m = d->m;
  unsigned char *on = bg_xcalloc((size_t)m->ninst + 1, 1);
  if (mark_collapsed(d, on, dg) != 0) {
    free(on);
    return -1;
  }
  d->inst_box = bg_arena_alloc(&d->arena, sizeof(int) * ((size_t)m->ninst + 1));
  int *outer = bg_xcalloc((size_t)m->ninst + 1, sizeof(int)); /* outermost collapsed, or -1 */
  for (int k = 0; k < m->ninst; k++) { /* parents come before their children */
    int p = m->inst_parent[k];
    outer[k] = p >= 0 && outer[p] >= 0 ? outer[p] : on[k] ? k : -1;
    d->inst_box[k] = outer[k] == k ? d->nnode++ : -1;
    d->ncollapsed += outer[k] == k;
  }
  d->det_draw = bg_arena_alloc(&d->arena, sizeof(int) * ((size_t)m->ndet + 1));
  int has_inst = m->ninst > 0 && m->elem_inst; /* hand-built models have neither */
  for (int k = 0; k < m->ndet; k++) {
    int e = m->det_node[k], in = e >= 0 && has_inst ? m->elem_inst[e] : -1;
    d->det_draw[k] = e >= 0 && (in < 0 || outer[in] < 0) ? d->nnode++ : -1;
  }
  d->node_of = bg_arena_alloc(&d->arena, sizeof(int) * ((size_t)d->nnode + 1));
  d->box_inst = bg_arena_alloc(&d->arena, sizeof(int) * ((size_t)d->nnode + 1));
  for (int n = 0; n < d->nnode; n++) d->node_of[n] = n, d->box_inst[n] = -1;
  for (int k = 0; k < m->ninst; k++)
    if (d->inst_box[k] >= 0) d->box_inst[d->inst_box[k]] = k;
  for (int e = 0; has_inst && e < m->nelem; e++) {
    int in = m->elem_inst[e];
    if (in >= 0 && outer[in] >= 0) d->node_of[e] = d->inst_box[outer[in]];
  }
  d->bond_hidden = bg_arena_alloc(&d->arena, (size_t)m->nbond + 1);
  for (int b = 0; b < m->nbond; b++)
    d->bond_hidden[b] = d->node_of[m->bond_tail[b]] == d->node_of[m->bond_head[b]] &&
                        d->node_of[m->bond_tail[b]] != m->bond_tail[b];
  free(on), free(outer);
  return 0;
}

void bg_parts_labels(bg_diagram_layout *d) {
  const bg_model *m = d->m;
  bg_strbuf b = {0};
  for (int k = 0; k < m->ninst; k++) {
    if (d->inst_box[k] < 0) continue;
    bg_sb_clear(&b);
    bg_name_markup(&b, m->inst_name[k], d->st.font_size);
    bg_sb_puts(&b, " : ");
    bg_markup_escape(&b, m->inst_def[k]);
    d->nlabel[d->inst_box[k]] = bg_arena_strdup(&d->arena, bg_sb_str(&b));
  }
  for (int k = 0; k < m->ndet; k++) {
    if (d->det_draw[k] < 0) continue;
    bg_sb_clear(&b);
    bg_sb_puts(&b, m->det_var[k] == 'e' ? "De" : "Df");
    if (d->show & BG_SHOW_LABELS) {
      bg_sb_puts(&b, " : ");
      bg_name_markup(&b, m->det_name[k], d->st.font_size);
    }
    d->nlabel[d->det_draw[k]] = bg_arena_strdup(&d->arena, bg_sb_str(&b));
  }
  bg_sb_free(&b);
}

/* A box is wider than its label alone, so several bonds fit along its sides. */
void bg_parts_spread(bg_diagram_layout *d) {
  for (int n = 0; n < d->nnode; n++) {
    int to = d->node_of[n];
    if (to == n) continue;
    d->nx[n] = d->nx[to], d->ny[n] = d->ny[to];
    d->nw[n] = d->nw[to], d->nh[n] = d->nh[to];
  }
}

/* ---------------------------------------------------------------- drawing */
static void draw_box(bg_diagram *d, int k) {
  int n = d->L->inst_box[k];
  double x0 = d->L->nx[n] - d->L->nw[n] / 2, x1 = d->L->nx[n] + d->L->nw[n] / 2;
  double y0 = d->L->ny[n] - d->L->nh[n] / 2, y1 = d->L->ny[n] + d->L->nh[n] / 2;
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "box %s", d->m->inst_name[k]);
  it->color = bg_diagram_ink(d, d->st.fg, d->hot_elem[n]);
  it->width = d->st.line_width;
  bg_scene_move(&d->scene, x0, y0);
  bg_scene_line(&d->scene, x1, y0);
  bg_scene_line(&d->scene, x1, y1);
  bg_scene_line(&d->scene, x0, y1);
  bg_scene_close(&d->scene);
  char role[256];
  snprintf(role, sizeof role, "box-label %s", d->m->inst_name[k]);
  bg_scene_text(&d->scene, d->L->nlabel[n], d->L->nx[n], d->L->ny[n], d->st.font_size, 0.5, 0.5,
                bg_diagram_ink(d, d->st.fg, d->hot_elem[n]), role);
}

/* The activated bond from the node read to the detector: a bond line, a
 * full arrowhead at the detector (the signal it passes on), no half arrow. */
static void draw_detector(bg_diagram *d, int k) {
  const bg_model *m = d->m;
  int n = d->L->det_draw[k], a = bg_detector_anchor(d->L, k);
  bg_vec cn = bg_v(d->L->nx[n], d->L->ny[n]), ca = bg_v(d->L->nx[a], d->L->ny[a]);
  bg_vec p = bg_node_end(d->L, a, bg_vunit(bg_vsub(cn, ca)));
  bg_vec q = bg_box_exit(cn, d->L->nw[n] / 2, d->L->nh[n] / 2, ca);
  bg_vec dir = bg_vunit(bg_vsub(q, p));
  bg_rgba ink = bg_diagram_ink(d, d->st.fg, d->hot_elem[a]);
  double len = 7 * d->st.line_width;
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "detector-bond %s", m->det_name[k]);
  it->color = ink, it->width = d->st.line_width, it->round = 1;
  bg_scene_move(&d->scene, p.x, p.y);
  bg_vec stop = bg_vsub(q, bg_vscale(dir, len * 0.8));
  bg_scene_line(&d->scene, stop.x, stop.y);
  bg_obstacle_item(d, d->scene.nitem - 1);
  it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "detector-arrow %s", m->det_name[k]);
  it->fill = it->color = ink, it->width = 0;
  bg_geom_arrowhead(&d->scene, q, dir, len, 0.75 * len);
  char role[256];
  snprintf(role, sizeof role, "detector %s", m->det_name[k]);
  bg_scene_text(&d->scene, d->L->nlabel[n], cn.x, cn.y, d->st.font_size, 0.5, 0.5, ink, role);
}

void bg_draw_parts(bg_diagram *d) {
  for (int k = 0; k < d->m->ninst; k++)
    if (d->L->inst_box[k] >= 0) draw_box(d, k);
  for (int k = 0; k < d->m->ndet; k++)
    if (d->L->det_draw[k] >= 0) draw_detector(d, k);
}

/* ---------------------------------------------------------------- layout */
typedef struct compact {
  int *lay_of, *edge_of; /* node → layout node (-1 hidden); layout edge → edge */
  int n, ne;
} compact;

static double *pick_d(const double *a, const compact *c, int nnode) {
  if (!a) return NULL;
  double *r = bg_xcalloc((size_t)c->n + 1, sizeof *r);
  for (int v = 0; v < nnode; v++)
    if (c->lay_of[v] >= 0) r[c->lay_of[v]] = a[v];
  return r;
}

static int *pick_i(const int *a, const compact *c, int nnode) {
  if (!a) return NULL;
  int *r = bg_xcalloc((size_t)c->n + 1, sizeof *r);
  for (int v = 0; v < nnode; v++)
    if (c->lay_of[v] >= 0) r[c->lay_of[v]] = a[v];
  return r;
}

/* The layout's arrays back in the diagram's numbering: hidden nodes at 0
 * (bg_parts_spread moves them), left-out edges without a spline. */
static void expand(const bg_layout_in *in, const compact *c, bg_layout *out) {
  double *x = bg_xcalloc((size_t)in->nnode + 1, sizeof *x), *y = bg_xcalloc((size_t)in->nnode + 1, sizeof *y);
  for (int v = 0; v < in->nnode; v++)
    if (c->lay_of[v] >= 0) x[v] = out->x[c->lay_of[v]], y[v] = out->y[c->lay_of[v]];
  free(out->x), free(out->y);
  out->x = x, out->y = y;
  if (out->spladr) {
    int *adr = bg_xcalloc((size_t)in->nedge + 1, sizeof *adr), *n = bg_xcalloc((size_t)in->nedge + 1, sizeof *n);
    for (int i = 0; i < c->ne; i++) adr[c->edge_of[i]] = out->spladr[i], n[c->edge_of[i]] = out->spln[i];
    free(out->spladr), free(out->spln);
    out->spladr = adr, out->spln = n;
  }
  out->nnode = in->nnode, out->nedge = in->nedge;
}

/* Lays out the graph with every collapsed instance as its box alone: the
 * hidden elements and the bonds inside boxes are left out (their edges join
 * a box to itself). Without boxes, the layout of `in` as it is. */
int bg_parts_layout(const bg_diagram_layout *d, const bg_layout_in *in, bg_layout *out, char *err,
                    size_t errn) {
  if (!d->ncollapsed) return bg_layout_run(in, out, err, errn);
  compact c = {bg_xcalloc((size_t)in->nnode + 1, sizeof(int)),
               bg_xcalloc((size_t)in->nedge + 1, sizeof(int)), 0, 0};
  for (int v = 0; v < in->nnode; v++) c.lay_of[v] = bg_node_shown(d, v) ? c.n++ : -1;
  bg_layout_in k = *in;
  int *t = bg_xcalloc((size_t)in->nedge + 1, sizeof *t), *h = bg_xcalloc((size_t)in->nedge + 1, sizeof *h);
  int *w = bg_xcalloc((size_t)in->nedge + 1, sizeof *w);
  for (int i = 0; i < in->nedge; i++) {
    if (in->tail[i] == in->head[i]) continue;
    c.edge_of[c.ne] = i, t[c.ne] = c.lay_of[in->tail[i]], h[c.ne] = c.lay_of[in->head[i]];
    w[c.ne++] = in->weight ? in->weight[i] : 1;
  }
  unsigned char *root = NULL, *dead = NULL;
  if (in->root) {
    root = bg_xcalloc((size_t)c.n + 1, 1);
    for (int v = 0; v < in->nnode; v++)
      if (c.lay_of[v] >= 0) root[c.lay_of[v]] = in->root[v];
  }
  if (in->dead_end) {
    dead = bg_xcalloc((size_t)c.n + 1, 1);
    for (int v = 0; v < in->nnode; v++)
      if (c.lay_of[v] >= 0) dead[c.lay_of[v]] = in->dead_end[v];
  }
  int *la = bg_xcalloc((size_t)in->nlink + 1, sizeof *la), *lb = bg_xcalloc((size_t)in->nlink + 1, sizeof *lb);
  k.nlink = 0; /* the links between shown nodes */
  for (int i = 0; i < in->nlink; i++)
    if (c.lay_of[in->link_a[i]] >= 0 && c.lay_of[in->link_b[i]] >= 0)
      la[k.nlink] = c.lay_of[in->link_a[i]], lb[k.nlink++] = c.lay_of[in->link_b[i]];
  k.link_a = la, k.link_b = lb;
  k.nnode = c.n, k.nedge = c.ne, k.tail = t, k.head = h, k.weight = w, k.root = root, k.dead_end = dead;
  k.w = pick_d(in->w, &c, in->nnode), k.h = pick_d(in->h, &c, in->nnode);
  k.px = pick_d(in->px, &c, in->nnode), k.py = pick_d(in->py, &c, in->nnode);
  k.pinned = pick_i(in->pinned, &c, in->nnode), k.cluster = pick_i(in->cluster, &c, in->nnode);
  int rc = bg_layout_run(&k, out, err, errn);
  if (rc == 0) expand(in, &c, out);
  free(la), free(lb), free(t), free(h), free(w), free(root), free(dead), free((void *)k.w), free((void *)k.h), free((void *)k.px);
  free((void *)k.py), free((void *)k.pinned), free((void *)k.cluster), free(c.lay_of), free(c.edge_of);
  return rc;
}
