/* SPDX-License-Identifier: BSD-3-Clause */
/* Modulating signals: thin lines with a filled arrowhead at the modulated
 * element. A signal starts at the element whose variable it carries, at the
 * middle of a bond for a bond variable (e7, f7), or at the integrator node of
 * a user state (drawn with the signals that feed it); self-modulation is a
 * small loop on the element. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

/* Where the ray from node n's centre towards `toward` leaves its box grown by gap. */
static bg_vec node_exit(const bg_diagram_layout *d, int n, bg_vec toward, double gap) {
  return bg_box_exit(bg_v(d->nx[n], d->ny[n]), d->nw[n] / 2 + gap, d->nh[n] / 2 + gap, toward);
}

/* ---------------------------------------------------------------- drawing */
static int bond_between(const bg_model *m, int x, int y) {
  for (int i = 0; i < m->elem_nbond[x]; i++) {
    int b = m->elem_bonds[m->elem_bondadr[x] + i];
    if (m->bond_tail[b] == y || m->bond_head[b] == y) return b;
  }
  return -1;
}

enum { ALEN = 6, AWID = 4 };

/* Roles: "KIND NAME" for the line ("signal w->T", counted by the tests),
 * "KIND-arrow NAME" and "KIND-dot NAME" for the marks. */
typedef struct sigrole {
  const char *kind, *name;
} sigrole;

static bg_scene_item *signal_item(bg_diagram *d, sigrole role, int hot) {
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "%s %s", role.kind, role.name);
  it->color = bg_diagram_ink(d, d->st.signal, hot), it->width = d->st.signal_width;
  if (d->st.signal_dashed) it->dash[0] = 3, it->dash[1] = 2;
  return it;
}

static void signal_head(bg_diagram *d, sigrole role, bg_vec tip, bg_vec dir, int hot) {
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "%s-arrow %s", role.kind, role.name);
  it->fill = it->color = bg_diagram_ink(d, d->st.signal, hot), it->width = 0;
  bg_geom_arrowhead(&d->scene, tip, dir, ALEN, AWID);
}

/* A signal from p0 to the box of node `to`, bowed by `bow` (a vector, or
 * zero for a straight line). */
static void signal_to_node(bg_diagram *d, sigrole role, bg_vec p0, int to, bg_vec bow, int hot) {
  bg_vec ct = bg_v(d->L->nx[to], d->L->ny[to]);
  bg_vec aim = bg_vlen(bow) > 0 ? bg_vadd(bg_vscale(bg_vadd(p0, ct), 0.5), bow) : p0;
  bg_vec p1 = node_exit(d->L, to, aim, 1.5);
  signal_item(d, role, hot);
  bg_scene_move(&d->scene, p0.x, p0.y);
  bg_vec dir;
  if (bg_vlen(bow) > 0) {
    bg_vec chord = bg_vsub(p1, p0);
    bg_vec c1 = bg_vadd(bg_vadd(p0, bg_vscale(chord, 0.25)), bow);
    bg_vec c2 = bg_vadd(bg_vadd(p0, bg_vscale(chord, 0.75)), bow);
    dir = bg_vunit(bg_vsub(p1, c2));
    bg_vec end = bg_vsub(p1, bg_vscale(dir, ALEN * 0.8));
    bg_scene_curve(&d->scene, c1.x, c1.y, c2.x, c2.y, end.x, end.y);
  } else {
    dir = bg_vunit(bg_vsub(p1, p0));
    bg_vec end = bg_vsub(p1, bg_vscale(dir, ALEN * 0.8));
    bg_scene_line(&d->scene, end.x, end.y);
  }
  signal_head(d, role, p1, dir, hot);
}

/* ---------------------------------------------------------------- near */
/* What a signal's tests look at, by where it is: a uniform grid of cells
 * over the layout, each listing the nodes whose box (grown by 3 pt) and the
 * bond legs whose bounding box meet it. A signal then tests what is near
 * its chords instead of every node and bond, so drawing the signals stays
 * linear in the model (a reaction network with 1 000 signals tested each
 * bow against its 3 500 nodes and 4 000 bonds). The answers are the full
 * scan's: every node or leg a chord can meet is in a cell the walk visits. */
typedef struct near_index {
  double x0, y0, cell;
  int nx, ny;
  int *adr, *item;       /* per cell (CSR): nodes k as k, legs as nnode + leg */
  int nleg;
  bg_vec *la, *lb;       /* legs' ends */
  int *stamp, tick;      /* per item: the query it was last seen in */
} near_index;

static bg_vec leg_end(const bg_diagram *d, int b, int i) {
  const bg_bond_geom *g = &d->L->bg[b];
  if (i < 0) return g->tail;
  return i == g->bendn ? g->head : bg_v(d->L->lay.bendx[g->bendadr + i], d->L->lay.bendy[g->bendadr + i]);
}

/* The cells of box [x0, x1] × [y0, y1], clamped. */
static void cell_range(const near_index *ix, double x0, double y0, double x1, double y1, int r[4]) {
  r[0] = (int)floor((x0 - ix->x0) / ix->cell), r[1] = (int)floor((y0 - ix->y0) / ix->cell);
  r[2] = (int)floor((x1 - ix->x0) / ix->cell), r[3] = (int)floor((y1 - ix->y0) / ix->cell);
  r[0] = r[0] < 0 ? 0 : r[0] >= ix->nx ? ix->nx - 1 : r[0];
  r[2] = r[2] < 0 ? 0 : r[2] >= ix->nx ? ix->nx - 1 : r[2];
  r[1] = r[1] < 0 ? 0 : r[1] >= ix->ny ? ix->ny - 1 : r[1];
  r[3] = r[3] < 0 ? 0 : r[3] >= ix->ny ? ix->ny - 1 : r[3];
}

/* Item k's box: a node's grown by 3 pt, a leg's bounding box. */
static void item_box(const bg_diagram *d, const near_index *ix, int k, double b[4]) {
  const bg_diagram_layout *L = d->L;
  if (k < L->nnode) {
    b[0] = L->nx[k] - L->nw[k] / 2 - 3, b[1] = L->ny[k] - L->nh[k] / 2 - 3;
    b[2] = L->nx[k] + L->nw[k] / 2 + 3, b[3] = L->ny[k] + L->nh[k] / 2 + 3;
    return;
  }
  bg_vec a = ix->la[k - L->nnode], c = ix->lb[k - L->nnode];
  b[0] = fmin(a.x, c.x), b[1] = fmin(a.y, c.y), b[2] = fmax(a.x, c.x), b[3] = fmax(a.y, c.y);
}

static void near_build(const bg_diagram *d, near_index *ix) {
  const bg_diagram_layout *L = d->L;
  memset(ix, 0, sizeof *ix);
  for (int b = 0; b < d->m->nbond; b++) ix->nleg += L->bg[b].bendn + 1;
  ix->la = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->la), ix->lb = bg_xcalloc((size_t)ix->nleg + 1, sizeof *ix->lb);
  for (int b = 0, k = 0; b < d->m->nbond; b++)
    for (int i = 0; i <= L->bg[b].bendn; i++, k++) ix->la[k] = leg_end(d, b, i - 1), ix->lb[k] = leg_end(d, b, i);
  int nitem = L->nnode + ix->nleg;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300, area = 0;
  for (int k = 0; k < nitem; k++) {
    double bx[4];
    item_box(d, ix, k, bx);
    x0 = fmin(x0, bx[0]), y0 = fmin(y0, bx[1]), x1 = fmax(x1, bx[2]), y1 = fmax(y1, bx[3]);
    if (k < L->nnode) area += (bx[2] - bx[0]) * (bx[3] - bx[1]);
  }
  if (nitem == 0) x0 = y0 = 0, x1 = y1 = 1;
  /* cells about twice a node's size, at most four per item */
  ix->cell = fmax(8, 2 * sqrt(area / (L->nnode + 1)));
  ix->cell = fmax(ix->cell, sqrt((x1 - x0) * (y1 - y0) / (4.0 * nitem + 4)));
  ix->x0 = x0, ix->y0 = y0;
  ix->nx = (int)((x1 - x0) / ix->cell) + 1, ix->ny = (int)((y1 - y0) / ix->cell) + 1;
  size_t ncell = (size_t)ix->nx * (size_t)ix->ny;
  ix->adr = bg_xcalloc(ncell + 1, sizeof *ix->adr);
  for (int pass = 0; pass < 2; pass++) {
    int *fill = pass ? bg_xcalloc(ncell + 1, sizeof *fill) : NULL;
    for (int k = 0; k < nitem; k++) {
      double bx[4];
      int r[4];
      item_box(d, ix, k, bx);
      cell_range(ix, bx[0], bx[1], bx[2], bx[3], r);
      for (int cy = r[1]; cy <= r[3]; cy++)
        for (int cx = r[0]; cx <= r[2]; cx++) {
          size_t c = (size_t)cy * (size_t)ix->nx + (size_t)cx;
          if (pass) ix->item[ix->adr[c] + fill[c]++] = k;
          else ix->adr[c + 1]++;
        }
    }
    if (!pass) {
      for (size_t c = 0; c < ncell; c++) ix->adr[c + 1] += ix->adr[c];
      ix->item = bg_xcalloc((size_t)ix->adr[ncell] + 1, sizeof *ix->item);
    }
    free(fill);
  }
  ix->stamp = bg_xcalloc((size_t)nitem + 1, sizeof *ix->stamp);
}

static void near_free(near_index *ix) {
  free(ix->adr), free(ix->item), free(ix->la), free(ix->lb), free(ix->stamp);
}

/* The items near segment p-q (each once, in out; returns how many): those
 * listed in the cells around the points every quarter cell along it. */
static int near_segment(near_index *ix, bg_vec p, bg_vec q, int **out, int *cap) {
  int n = 0, steps = (int)ceil(bg_vlen(bg_vsub(q, p)) / (ix->cell / 4)) + 1;
  ix->tick++;
  int last[4] = {-1, -1, -1, -1};
  for (int s = 0; s <= steps; s++) {
    bg_vec f = bg_vadd(p, bg_vscale(bg_vsub(q, p), (double)s / steps));
    int r[4];
    cell_range(ix, f.x - ix->cell, f.y - ix->cell, f.x + ix->cell, f.y + ix->cell, r);
    if (!memcmp(r, last, sizeof r)) continue;
    memcpy(last, r, sizeof r);
    for (int cy = r[1]; cy <= r[3]; cy++)
      for (int cx = r[0]; cx <= r[2]; cx++) {
        size_t c = (size_t)cy * (size_t)ix->nx + (size_t)cx;
        for (int j = ix->adr[c]; j < ix->adr[c + 1]; j++) {
          int k = ix->item[j];
          if (ix->stamp[k] == ix->tick) continue;
          ix->stamp[k] = ix->tick;
          if (n == *cap) *cap = 2 * *cap + 16, *out = bg_xrealloc(*out, (size_t)*cap * sizeof **out);
          (*out)[n++] = k;
        }
      }
  }
  return n;
}

/* A query's scratch list. */
typedef struct near_list {
  int *k, n, cap;
} near_list;

/* Whether the line between the centres of a and b passes another node's box. */
static int node_between(const bg_diagram *d, near_index *ix, near_list *nl, int a, int b) {
  bg_vec p = bg_v(d->L->nx[a], d->L->ny[a]), q = bg_v(d->L->nx[b], d->L->ny[b]), pq = bg_vsub(q, p);
  double l2 = pq.x * pq.x + pq.y * pq.y;
  if (!(l2 > 0)) return 0;
  nl->n = near_segment(ix, p, q, &nl->k, &nl->cap);
  for (int j = 0; j < nl->n; j++) {
    int n = nl->k[j];
    if (n >= d->L->nnode || n == a || n == b) continue;
    bg_vec c = bg_v(d->L->nx[n], d->L->ny[n]);
    double t = ((c.x - p.x) * pq.x + (c.y - p.y) * pq.y) / l2;
    bg_vec f = bg_vadd(p, bg_vscale(pq, t));
    if (t > 0 && t < 1 && fabs(f.x - c.x) < d->L->nw[n] / 2 + 2 && fabs(f.y - c.y) < d->L->nh[n] / 2 + 2) return 1;
  }
  return 0;
}

/* Whether segments p-q and r-s cross. */
static int segs_cross(bg_vec p, bg_vec q, bg_vec r, bg_vec s) {
  double d1 = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  double d2 = (q.x - p.x) * (s.y - p.y) - (q.y - p.y) * (s.x - p.x);
  double d3 = (s.x - r.x) * (p.y - r.y) - (s.y - r.y) * (p.x - r.x);
  double d4 = (s.x - r.x) * (q.y - r.y) - (s.y - r.y) * (q.x - r.x);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/* What the signal curve from a to b bowed by bow runs through, sampled at
 * 24 points: 10 for each sample in a node box (ends excepted, 3 pt of
 * room), 1 for each bond leg a chord between samples crosses. */
static int bow_hits(const bg_diagram *d, near_index *ix, near_list *nl, int a, int b, bg_vec bow) {
  bg_vec p = bg_v(d->L->nx[a], d->L->ny[a]), q = bg_v(d->L->nx[b], d->L->ny[b]), ch = bg_vsub(q, p);
  bg_vec c1 = bg_vadd(bg_vadd(p, bg_vscale(ch, 0.25)), bow), c2 = bg_vadd(bg_vadd(p, bg_vscale(ch, 0.75)), bow);
  int hits = 0;
  bg_vec prev = p;
  for (int k = 1; k <= 24; k++) {
    double t = k / 24.0, u = 1 - t;
    bg_vec f = bg_vadd(bg_vadd(bg_vscale(p, u * u * u), bg_vscale(c1, 3 * u * u * t)),
                       bg_vadd(bg_vscale(c2, 3 * u * t * t), bg_vscale(q, t * t * t)));
    nl->n = near_segment(ix, prev, f, &nl->k, &nl->cap);
    for (int j = 0; j < nl->n; j++) {
      int n = nl->k[j];
      if (n < d->L->nnode)
        hits += 10 * (k < 24 && n != a && n != b && fabs(f.x - d->L->nx[n]) < d->L->nw[n] / 2 + 3 &&
                      fabs(f.y - d->L->ny[n]) < d->L->nh[n] / 2 + 3);
      else hits += segs_cross(prev, f, ix->la[n - d->L->nnode], ix->lb[n - d->L->nnode]);
    }
    prev = f;
  }
  return hits;
}

/* A signal along a grid line, where bonds run, bows off them: up or down
 * (left or right), as far as it takes to clear the labels there, to the
 * side where it crosses fewest bonds (the ones it starts and ends on count
 * on both sides alike). */
static bg_vec clear_bow(const bg_diagram *d, near_index *ix, near_list *nl, int a, int b, double len) {
  bg_vec chord = bg_v(d->L->nx[b] - d->L->nx[a], d->L->ny[b] - d->L->ny[a]);
  bg_vec side = fabs(chord.x) >= fabs(chord.y) ? bg_v(0, -1) : bg_v(-1, 0), best = bg_v(0, 0);
  int best_hits = -1;
  for (int k = 0; k < 8 && best_hits != 0; k++) {
    bg_vec bow = bg_vscale(side, (k % 2 ? -1 : 1) * (18 + 0.12 * len) * (1 + 0.6 * (k / 2)));
    int h = bow_hits(d, ix, nl, a, b, bow);
    if (best_hits < 0 || h < best_hits) best_hits = h, best = bow;
  }
  return best;
}

/* Between two nodes: straight, or bowed out to the barb side of a bond that
 * joins the same two nodes (the bond number is on the other side), or, along
 * a row or column of the grid past other nodes, bowed up or down (left or
 * right) off the bonds there (clear_bow). */
static void signal_between(bg_diagram *d, near_index *ix, near_list *nl, sigrole role, int from, int to, int hot) {
  bg_vec cf = bg_v(d->L->nx[from], d->L->ny[from]), ct = bg_v(d->L->nx[to], d->L->ny[to]);
  bg_vec bow = bg_v(0, 0), aim = ct;
  int b = from < d->m->nelem && to < d->m->nelem ? bond_between(d->m, from, to) : -1;
  bg_vec chord = bg_vsub(ct, cf);
  double len = bg_vlen(chord);
  if (b >= 0) {
    bow = bg_vscale(bg_barb_side(d->L, b), 20);
  } else if (fmin(fabs(chord.x), fabs(chord.y)) < 0.18 * fmax(fabs(chord.x), fabs(chord.y)) &&
             node_between(d, ix, nl, from, to)) {
    bow = clear_bow(d, ix, nl, from, to, len);
  }
  if (b >= 0 || bg_vlen(bow) > 0) aim = bg_vadd(bg_vscale(bg_vadd(cf, ct), 0.5), bow);
  signal_to_node(d, role, node_exit(d->L, from, aim, 0), to, bow, hot);
}

/* Self-modulation: a loop leaving the box and coming back, on its free side. */
static void signal_self(bg_diagram *d, sigrole role, int e, int hot) {
  bg_vec c = bg_v(d->L->nx[e], d->L->ny[e]), dir = bg_free_direction(d->L, e), n = bg_vleft(dir);
  /* leave and re-enter the box 8 pt either side of where `dir` leaves it */
  bg_vec q = node_exit(d->L, e, bg_vadd(c, bg_vscale(dir, 100)), 0);
  bg_vec p0 = node_exit(d->L, e, bg_vadd(q, bg_vscale(n, 8)), 0);
  bg_vec p1 = node_exit(d->L, e, bg_vsub(q, bg_vscale(n, 8)), 1.5);
  bg_vec c1 = bg_vadd(p0, bg_vadd(bg_vscale(dir, 24), bg_vscale(n, 10)));
  bg_vec c2 = bg_vadd(p1, bg_vsub(bg_vscale(dir, 24), bg_vscale(n, 10)));
  bg_vec adir = bg_vunit(bg_vsub(p1, c2)), end = bg_vsub(p1, bg_vscale(adir, ALEN * 0.8));
  signal_item(d, role, hot);
  bg_scene_move(&d->scene, p0.x, p0.y);
  bg_scene_curve(&d->scene, c1.x, c1.y, c2.x, c2.y, end.x, end.y);
  signal_head(d, role, p1, adir, hot);
}

/* A bond variable (e7, f7): from a dot on the bond's middle. */
static int signal_from_bond(bg_diagram *d, sigrole role, const char *var, int to, int hot) {
  const bg_model *m = d->m;
  if ((var[0] != 'e' && var[0] != 'f') || !var[1]) return -1;
  char *end;
  long num = strtol(var + 1, &end, 10);
  int b = *end ? -1 : bg_model_find_bond(m, (int)num);
  if (b < 0) return -1;
  bg_vec p0 = d->L->bg[b].mid;
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "%s-dot %s", role.kind, role.name);
  it->fill = it->color = bg_diagram_ink(d, d->st.signal, hot), it->width = 0;
  bg_scene_circle(&d->scene, p0.x, p0.y, 1.6);
  signal_to_node(d, role, p0, to, bg_v(0, 0), hot);
  return 0;
}

static void draw_signal(bg_diagram *d, near_index *ix, near_list *nl, int i) {
  const bg_model *m = d->m;
  int from = m->signal_from[i], to = m->signal_to[i], s = bg_signal_state(m, i);
  int hot = d->hot_elem[to] && (from < 0 || d->hot_elem[from]);
  char name[160];
  const char *fname = from >= 0 ? m->elem_name[from] : m->signal_var[i];
  snprintf(name, sizeof name, "%s->%s", fname, m->elem_name[to]);
  sigrole role = {"signal", name};
  /* a collapsed instance: its signals start or end at its box; the ones
   * inside it are not drawn */
  int to_box = d->L->node_of[to], from_box = from >= 0 ? d->L->node_of[from] : -1;
  if (to_box != to && (from_box == to_box || from < 0)) return;
  if (from >= 0 && from_box != from && from_box != to_box) from = from_box;
  to = to_box;
  if (from == to) signal_self(d, role, to, hot);
  else if (from >= 0) signal_between(d, ix, nl, role, from, to, hot);
  else if (s >= 0 && d->L->state_node[s] >= 0) signal_between(d, ix, nl, role, d->L->state_node[s], to, hot);
  else signal_from_bond(d, role, m->signal_var[i], to, hot);
}

/* The integrator of a user state and the signals that feed it. */
static void draw_state(bg_diagram *d, near_index *ix, near_list *nl, int s) {
  const bg_model *m = d->m;
  int n = d->L->state_node[s];
  if (n < 0) return;
  char role[160];
  snprintf(role, sizeof role, "state-node %s", m->state_name[s]);
  bg_scene_text(&d->scene, d->L->nlabel[n], d->L->nx[n], d->L->ny[n], d->st.font_size, 0.5, 0.5,
                bg_diagram_ink(d, d->st.signal, !bg_diagram_muted(d)), role);
  int in[64], nin = bg_state_inputs(m, s, in, 64);
  for (int k = 0; k < nin; k++) {
    char name[160];
    snprintf(name, sizeof name, "%s->%s", m->elem_name[in[k]], m->state_name[s]);
    signal_between(d, ix, nl, (sigrole){"state-input", name}, d->L->node_of[in[k]], n, !bg_diagram_muted(d));
  }
}

void bg_draw_signals(bg_diagram *d) {
  int first = d->scene.nitem;
  near_index ix;
  near_list nl = {NULL, 0, 0};
  near_build(d, &ix);
  for (int s = 0; s < d->m->nstate; s++) draw_state(d, &ix, &nl, s);
  for (int i = 0; i < d->m->nsignal; i++) draw_signal(d, &ix, &nl, i);
  near_free(&ix), free(nl.k);
  for (int i = first; i < d->scene.nitem; i++) /* numbers and tags keep off the lines */
    if (d->scene.item[i].kind == BG_ITEM_STROKE) bg_obstacle_item(d, i);
}
