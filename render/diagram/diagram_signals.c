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
#include "base/sort.h"

/* Where the ray from node n's centre towards `toward` leaves its box grown by gap. */
static bg_vec node_exit(const bg_diagram_layout *d, int n, bg_vec toward, double gap) {
  return bg_box_exit(bg_v(d->nx[n], d->ny[n]), d->nw[n] / 2 + gap, d->nh[n] / 2 + gap, toward);
}

/* ---------------------------------------------------------------- drawing */
#define ALEN BG_SIGNAL_ARROW
enum { AWID = 4 };

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

/* A signal's polyline pts (diagram_route.c), the last leg ending in the arrowhead. */
static void signal_polyline(bg_diagram *d, sigrole role, const bg_vec *pts, int n, int hot) {
  signal_item(d, role, hot);
  bg_scene_move(&d->scene, pts[0].x, pts[0].y);
  for (int i = 1; i + 1 < n; i++) bg_scene_line(&d->scene, pts[i].x, pts[i].y);
  bg_vec tip = pts[n - 1], adir = bg_vunit(bg_vsub(tip, pts[n - 2]));
  bg_vec end = bg_vsub(tip, bg_vscale(adir, ALEN * 0.8));
  bg_scene_line(&d->scene, end.x, end.y);
  signal_head(d, role, tip, adir, hot);
}

/* The route of the next signal: with a router, found and kept in
 * d->routes (the routing pass, bg_route_signals); without, the one kept
 * for it (the drawing pass, which walks the signals in the same order). */
static const bg_signal_route *route_of(bg_diagram *d, bg_router *rt, int from, int from_bond, int to, int group) {
  if (!rt) return d->route_next < d->nroutes ? &d->routes[d->route_next++] : NULL;
  bg_vec pts[256];
  int n = bg_route(rt, d->m, from, from_bond, to, group, pts, 256);
  if (d->nroutes % 16 == 0)
    d->routes = bg_xrealloc(d->routes, (size_t)(d->nroutes + 16) * sizeof *d->routes);
  bg_signal_route *r = &d->routes[d->nroutes++];
  *r = (bg_signal_route){from, from_bond, to, n, bg_arena_alloc(&d->arena, (size_t)n * sizeof *pts), -1, {0, 0}};
  memcpy(r->pts, pts, (size_t)n * sizeof *pts);
  r->branch_k = bg_route_branch(rt, &r->branch_at);
  return r;
}

/* A routed signal drawn: where it branches off the line of an earlier
 * signal from the same source, from a dot there (as block diagrams draw a
 * signal taken off another), so no two lines are drawn on top of each
 * other (issue 31: modladder120's 40 signals of f1 shared their stretches
 * out of six ports); else whole. */
static void signal_routed(bg_diagram *d, sigrole role, const bg_signal_route *r, int hot) {
  if (r->branch_k < 0) {
    signal_polyline(d, role, r->pts, r->n, hot);
    return;
  }
  int k = r->branch_k, n = r->n - k;
  bg_vec *pts = bg_xcalloc((size_t)n, sizeof *pts);
  pts[0] = r->branch_at;
  memcpy(pts + 1, r->pts + k + 1, (size_t)(n - 1) * sizeof *pts);
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "%s-branch %s", role.kind, role.name);
  it->fill = it->color = bg_diagram_ink(d, d->st.signal, hot), it->width = 0;
  bg_scene_circle(&d->scene, pts[0].x, pts[0].y, 1.6);
  signal_polyline(d, role, pts, n, hot);
  free(pts);
}

/* Between two nodes, along the route from `from` to `to`. */
static void signal_between(bg_diagram *d, bg_router *rt, sigrole role, int from, int to, int hot) {
  const bg_signal_route *r = route_of(d, rt, from, -1, to, from);
  if (!rt && r) signal_routed(d, role, r, hot);
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

/* A bond variable (e7, f7): from a dot on the bond, at its middle or near it. */
static int signal_from_bond(bg_diagram *d, bg_router *rt, sigrole role, const char *var, int to, int hot) {
  int b = bg_signal_bond(d->m, var);
  if (b < 0) return -1;
  /* the group of a bond variable: after the nodes, two per bond (e, f) */
  const bg_signal_route *r = route_of(d, rt, -1, b, to, d->L->nnode + 2 * b + (var[0] == 'f'));
  if (rt || !r) return 0;
  if (r->branch_k < 0) { /* a branch leaves a line whose signal drew the dot on the bond */
    bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "%s-dot %s", role.kind, role.name);
    it->fill = it->color = bg_diagram_ink(d, d->st.signal, hot), it->width = 0;
    bg_scene_circle(&d->scene, r->pts[0].x, r->pts[0].y, 1.6);
  }
  signal_routed(d, role, r, hot);
  return 0;
}

static void draw_signal(bg_diagram *d, bg_router *rt, int i) {
  const bg_model *m = d->m;
  int from = m->signal_from[i], to = m->signal_to[i], s = bg_signal_state(d->L, i);
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
  if (from == to) {
    if (!rt) signal_self(d, role, to, hot);
  }
  else if (from >= 0) signal_between(d, rt, role, from, to, hot);
  else if (s >= 0 && d->L->state_node[s] >= 0) signal_between(d, rt, role, d->L->state_node[s], to, hot);
  else signal_from_bond(d, rt, role, m->signal_var[i], to, hot);
}

/* The integrator of a user state and the signals that feed it. */
static void draw_state(bg_diagram *d, bg_router *rt, int s) {
  const bg_model *m = d->m;
  int n = d->L->state_node[s];
  if (n < 0) return;
  char role[160];
  snprintf(role, sizeof role, "state-node %s", m->state_name[s]);
  if (!rt)
    bg_scene_text(&d->scene, d->L->nlabel[n], d->L->nx[n], d->L->ny[n], d->st.font_size, 0.5, 0.5,
                  bg_diagram_ink(d, d->st.signal, !bg_diagram_muted(d)), role);
  int in[64], nin = bg_state_inputs(m, s, in, 64);
  for (int k = 0; k < nin; k++) {
    char name[160];
    snprintf(name, sizeof name, "%s->%s", m->elem_name[in[k]], m->state_name[s]);
    signal_between(d, rt, (sigrole){"state-input", name}, d->L->node_of[in[k]], n, !bg_diagram_muted(d));
  }
}

/* What signal i is drawn from: its element's node (a collapsed box's
 * when it is outside the box), -2 - its user state, or -3 - 2 bonds - the
 * bond variable's (as draw_signal draws it). */
static long signal_source(const bg_diagram *d, int i) {
  const bg_model *m = d->m;
  int from = m->signal_from[i], s = bg_signal_state(d->L, i);
  if (from >= 0) return d->L->node_of[from] != from ? d->L->node_of[from] : from;
  if (s >= 0) return -2 - s;
  int b = bg_signal_bond(m, m->signal_var[i]);
  return b >= 0 ? -3L - 2L * b - (m->signal_var[i][0] == 'f') : -1;
}

typedef struct field_signal {
  int field, i;
  long source;
} field_signal;

static int by_field_source(const void *a, const void *b, void *ctx) {
  (void)ctx;
  const field_signal *p = a, *q = b;
  if (p->field != q->field) return p->field < q->field ? -1 : 1;
  if (p->source != q->source) return p->source < q->source ? -1 : 1;
  return p->i - q->i;
}

/* Per signal, whether an earlier one comes from the same source into the
 * same multiport field (to another of its ports): a field is one node, so
 * a source read in two ports' laws was drawn as two arrows side by side
 * into it (a held-out pathway's product inhibiting both ports of a
 * reaction). Only the first is drawn; the model, JSON and DOT keep both. */
static unsigned char *field_duplicates(const bg_diagram *d) {
  const bg_model *m = d->m;
  unsigned char *dup = bg_xcalloc((size_t)m->nsignal + 1, 1);
  field_signal *fs = bg_xmalloc(((size_t)m->nsignal + 1) * sizeof *fs);
  int n = 0;
  for (int i = 0; i < m->nsignal; i++) {
    int f = bg_elem_field(m, m->signal_to[i]);
    if (f >= 0 && d->L->node_of[m->signal_to[i]] == m->signal_to[i]) fs[n++] = (field_signal){f, i, signal_source(d, i)};
  }
  bg_sort(fs, (size_t)n, sizeof *fs, by_field_source, NULL);
  for (int k = 1; k < n; k++) dup[fs[k].i] = fs[k].field == fs[k - 1].field && fs[k].source == fs[k - 1].source;
  free(fs);
  return dup;
}

/* Every signal and state input, in drawing order: routed (rt) or drawn. */
static void walk_signals(bg_diagram *d, bg_router *rt) {
  for (int s = 0; s < d->m->nstate; s++) draw_state(d, rt, s);
  unsigned char *dup = field_duplicates(d);
  for (int i = 0; i < d->m->nsignal; i++)
    if (!dup[i]) draw_signal(d, rt, i);
  free(dup);
}

/* Once every signal is routed, each route round the one-ports whose bonds
 * a short U avoids (bg_route_detour; issue 31, crossings a detour of
 * bounded length avoids): against the finished routes, so the U keeps off
 * every other signal and later routes are not pushed aside. A branch's
 * shared stretch (drawn by an earlier signal) is left as it is. */
static int detour_routes(bg_diagram *d, bg_router *rt) {
  int taken = 0;
  for (int k = 0; k < d->nroutes; k++) {
    bg_signal_route *r = &d->routes[k];
    int cap = r->n + 64;
    bg_vec *pts = bg_xcalloc((size_t)cap, sizeof *pts);
    memcpy(pts, r->pts, (size_t)r->n * sizeof *pts);
    int n = bg_route_detour(rt, k, r->branch_k + 1, pts, r->n, cap);
    if (n != r->n) {
      r->pts = bg_arena_alloc(&d->arena, (size_t)n * sizeof *pts);
      memcpy(r->pts, pts, (size_t)n * sizeof *pts), r->n = n, taken++;
    }
    free(pts);
  }
  return taken;
}

/* Then each route's segments moved off other sources' signals they run a
 * few points beside (bg_route_nudge), past a branch's shared stretch and
 * the segment it leaves it by. Returns how many moved. */
static int nudge_routes(bg_diagram *d, bg_router *rt) {
  int moved = 0;
  for (int k = 0; k < d->nroutes; k++) {
    int b = d->routes[k].branch_k;
    moved += bg_route_nudge(rt, k, b < 0 ? 0 : b + 2, d->routes[k].pts, &d->routes[k].n);
  }
  return moved;
}

/* U's and nudges in turn: a nudge frees the room a U needed, a U may come
 * to run beside another line. At most ROUNDS rounds (one pass over the
 * routes each: bounded work), none once a round changes nothing. Three:
 * a fourth to a sixth changed no total over the 85 held-out models. */
#define ROUNDS 3
static void tidy_routes(bg_diagram *d, bg_router *rt) {
  for (int k = 0; k < ROUNDS; k++) {
    int changed = detour_routes(d, rt);
    changed += nudge_routes(d, rt);
    if (!changed) break;
  }
}

/* The frames drawn so far (bg_draw_frames, before the routes) fence the
 * routes: a signal run along a frame's border read as part of it (issue
 * 31: two motors' speed signals along their frames' bottoms, 1 pt off). */
static void fence_frames(bg_diagram *d, bg_router *rt) {
  const bg_scene *s = &d->scene;
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    if (it->kind != BG_ITEM_STROKE || strncmp(it->role, "frame", 5) || (it->role[5] && it->role[5] != ' ')) continue;
    bg_vec p = bg_v(0, 0), start = p;
    bg_scene_op op;
    for (int k = 0; bg_scene_next_op(s, it, &k, &op);) {
      bg_vec q = op.code == BG_OP_CLOSE ? start : bg_v(op.x[op.code == BG_OP_CURVE ? 2 : 0], op.y[op.code == BG_OP_CURVE ? 2 : 0]);
      if (op.code == BG_OP_MOVE) start = q;
      else bg_route_fence(rt, p, q); /* a curve by its chord: frames are rectangles */
      p = q;
    }
  }
}

/* How far the path and loop lines beside each bond reach from it
 * (bg_router_rings): the outermost of those drawn on its fuller side
 * (bg_layers_prepare counted them), with half its width. NULL when no
 * layer is drawn. */
static double *layer_rings(const bg_diagram *d) {
  double *ring = NULL;
  for (int b = 0; d->side_total && b < d->m->nbond; b++) {
    int most = d->side_total[2 * b] > d->side_total[2 * b + 1] ? d->side_total[2 * b] : d->side_total[2 * b + 1];
    if (!most) continue;
    if (!ring) ring = bg_xcalloc((size_t)d->m->nbond, sizeof *ring);
    ring[b] = bg_layer_line(&d->st, most - 1) + d->st.layer_width / 2;
  }
  return ring;
}

/* Needs bg_layers_prepare first: the routes keep clear of the layer lines
 * round the nodes they leave. */
void bg_route_signals(bg_diagram *d) {
  bg_router *rt = bg_router_new(d->L, d->m->nbond, NULL, 1);
  double *ring = layer_rings(d);
  bg_router_rings(rt, ring);
  fence_frames(d, rt);
  walk_signals(d, rt);
  tidy_routes(d, rt);
  bg_router_free(rt);
  free(ring);
}

void bg_draw_signals(bg_diagram *d) {
  int first = d->scene.nitem;
  d->route_next = 0;
  walk_signals(d, NULL);
  for (int i = first; i < d->scene.nitem; i++) /* numbers and tags keep off the lines */
    if (d->scene.item[i].kind == BG_ITEM_STROKE) bg_obstacle_item(d, i);
}
