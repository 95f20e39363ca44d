/* SPDX-License-Identifier: BSD-3-Clause */
/* The diagram's shared helpers, called by every pass and calling none:
 * vector maths, ink (the highlight's muting), layer colours and dashes,
 * and questions about the model and the layout result (which nodes are
 * drawn, what a user state reads). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"
#include "base/strindex.h"

bg_vec bg_v(double x, double y) { return (bg_vec){x, y}; }

bg_vec bg_vadd(bg_vec a, bg_vec b) { return bg_v(a.x + b.x, a.y + b.y); }

bg_vec bg_vsub(bg_vec a, bg_vec b) { return bg_v(a.x - b.x, a.y - b.y); }

bg_vec bg_vscale(bg_vec a, double k) { return bg_v(a.x * k, a.y * k); }

double bg_vlen(bg_vec a) { return hypot(a.x, a.y); }

/* The point of segment p-q nearest point c. */
bg_vec bg_seg_nearest(bg_vec c, bg_vec p, bg_vec q) {
  bg_vec u = bg_vsub(q, p);
  double l2 = u.x * u.x + u.y * u.y, t = l2 > 0 ? ((c.x - p.x) * u.x + (c.y - p.y) * u.y) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return bg_vadd(p, bg_vscale(u, t));
}

/* Distance from point c to the segment p-q. */
double bg_point_seg(bg_vec c, bg_vec p, bg_vec q) { return bg_vlen(bg_vsub(c, bg_seg_nearest(c, p, q))); }

double bg_seg_seg(bg_vec a0, bg_vec a1, bg_vec b0, bg_vec b1) {
  bg_vec da = bg_vsub(a1, a0), db = bg_vsub(b1, b0);
  double s0 = da.x * (b0.y - a0.y) - da.y * (b0.x - a0.x), s1 = da.x * (b1.y - a0.y) - da.y * (b1.x - a0.x);
  double t0 = db.x * (a0.y - b0.y) - db.y * (a0.x - b0.x), t1 = db.x * (a1.y - b0.y) - db.y * (a1.x - b0.x);
  if (s0 * s1 < 0 && t0 * t1 < 0) return 0;
  return fmin(fmin(bg_point_seg(a0, b0, b1), bg_point_seg(a1, b0, b1)),
              fmin(bg_point_seg(b0, a0, a1), bg_point_seg(b1, a0, a1)));
}

bg_vec bg_vleft(bg_vec d) { return bg_v(d.y, -d.x); }

bg_vec bg_vunit(bg_vec a) {
  double n = bg_vlen(a);
  return n > 1e-12 ? bg_vscale(a, 1 / n) : bg_v(1, 0);
}

bg_vec bg_box_exit(bg_vec c, double hw, double hh, bg_vec p) {
  bg_vec dv = bg_vsub(p, c);
  double tx = fabs(dv.x) > 1e-12 ? hw / fabs(dv.x) : 1e300;
  double ty = fabs(dv.y) > 1e-12 ? hh / fabs(dv.y) : 1e300;
  double t = tx < ty ? tx : ty;
  if (t > 1) t = 1; /* overlapping boxes: stop at the other centre */
  return bg_vadd(c, bg_vscale(dv, t));
}

/* ---------------------------------------------------------------- colours */
int bg_diagram_muted(const bg_diagram *d) { return d->o.highlight_kind != 0; }

bg_rgba bg_diagram_ink(const bg_diagram *d, bg_rgba c, int hot) {
  return hot || !bg_diagram_muted(d) ? c : d->st.muted;
}

int bg_node_shown(const bg_diagram_layout *d, int n) { return !d->node_of || d->node_of[n] == n; }

int bg_detector_anchor(const bg_diagram_layout *d, int k) { return d->node_of[d->m->det_node[k]]; }

int bg_fields_hidden(const bg_diagram_layout *d, int n) {
  return d->rep && n < d->m->nelem && d->rep[n] != n;
}

int bg_bond_derivative(const bg_model *m, const bg_analysis *a, int b) {
  int ends[2] = {m->bond_tail[b], m->bond_head[b]};
  for (int k = 0; k < 2; k++)
    if (bg_elem_is_store(m->elem_kind[ends[k]]) && a->elem_caus[ends[k]] == BG_CAUS_DERIVATIVE) return 1;
  return 0;
}

/* The bond whose variable a signal reads ("e7", "f7": bond number 7), or -1. */
int bg_signal_bond(const bg_model *m, const char *var) {
  if (!var || (var[0] != 'e' && var[0] != 'f') || !var[1]) return -1;
  char *end;
  long num = strtol(var + 1, &end, 10);
  return *end ? -1 : bg_model_find_bond(m, (int)num);
}

/* ---------------------------------------------------------------- user states */
/* Once per layout: each lookup by a loop over the states made every pass
 * over the signals states x signals (a chain of 2 000 sections, each with a
 * state and a detector, took 6.5 s to lay out, 4 000 took 46 s). */
void bg_signal_states(bg_diagram_layout *d) {
  const bg_model *m = d->m;
  int cap = bg_strindex_size(m->nstate);
  int *slot = bg_xmalloc((size_t)cap * sizeof *slot);
  bg_strkeys keys = BG_STRKEYS_ARRAY(m->state_name);
  bg_strindex_fill(slot, cap, keys, m->nstate);
  d->signal_state = bg_arena_alloc(&d->arena, sizeof(int) * ((size_t)m->nsignal + 1));
  for (int i = 0; i < m->nsignal; i++)
    d->signal_state[i] =
        m->signal_from[i] >= 0 || !m->signal_var[i] ? -1 : bg_strindex_find(slot, cap, keys, m->signal_var[i]);
  free(slot);
}

int bg_signal_state(const bg_diagram_layout *d, int i) { return d->signal_state[i]; }

/* The node signal i is drawn from: its element's, its user state's
 * integrator, or the head of the bond whose variable it reads; -1 if none
 * (the layout's signal links and the grid pass's one-ports read this). */
int bg_signal_from_node(const bg_diagram_layout *d, int i) {
  const bg_model *m = d->m;
  int from = m->signal_from[i], s = bg_signal_state(d, i);
  if (from >= 0) return d->node_of[from];
  if (s >= 0) return d->state_node[s];
  int bond = bg_signal_bond(m, m->signal_var[i]);
  return bond >= 0 ? d->node_of[m->bond_head[bond]] : -1;
}

unsigned char *bg_signal_end_nodes(const bg_diagram_layout *d) {
  const bg_model *m = d->m;
  unsigned char *on = bg_xcalloc((size_t)d->nnode + 1, 1);
  for (int i = 0; i < m->nsignal; i++) {
    int from = bg_signal_from_node(d, i), to = d->node_of[m->signal_to[i]];
    if (from >= 0 && from < d->nnode) on[from] = 1;
    if (to >= 0 && to < d->nnode) on[to] = 1;
  }
  return on;
}

int *bg_layer_use(const bg_diagram_layout *d) {
  const bg_analysis *a = d->a;
  unsigned show = d->show;
  if (d->o.layer_room > 0) show |= BG_SHOW_PATHS | BG_SHOW_LOOPS;
  if (!a || d->o.layer_room < 0 || !(show & (BG_SHOW_PATHS | BG_SHOW_LOOPS))) return NULL;
  int *use = bg_xcalloc((size_t)d->m->nbond + 1, sizeof(int));
  for (int p = 0; (show & BG_SHOW_PATHS) && p < a->npath; p++)
    for (int k = 0; k < a->path_n[p]; k++) use[a->path_bonds[a->path_adr[p] + k]]++;
  for (int l = 0; (show & BG_SHOW_LOOPS) && l < a->ntloop; l++)
    for (int k = 0; k < a->tloop_n[l]; k++) use[a->tloop_signals[a->tloop_adr[l] + k] / 2]++;
  return use;
}

int bg_boxes_meet(const double a[4], const double b[4]) {
  return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
}

int bg_seg_hits_box(const double *s, double x0, double y0, double x1, double y1) {
  double t0 = 0, t1 = 1, dx = s[2] - s[0], dy = s[3] - s[1];
  double p[4] = {-dx, dx, -dy, dy}, q[4] = {s[0] - x0, x1 - s[0], s[1] - y0, y1 - s[1]};
  for (int k = 0; k < 4; k++) {
    if (fabs(p[k]) < 1e-12) {
      if (q[k] < 0) return 0;
      continue;
    }
    double r = q[k] / p[k];
    if (p[k] < 0 && r > t0) t0 = r;
    if (p[k] > 0 && r < t1) t1 = r;
    if (t0 > t1) return 0;
  }
  return 1;
}

/* The element a bond variable of a state expression refers to: the junction
 * whose common variable it is (X.f of a 1-junction is its first bond's flow),
 * else the one-port on the bond, else a two-port. The expression keeps only
 * the bond, and these agree in value. */
static int var_elem(const bg_model *m, int op, int b) {
  int ends[2] = {m->bond_tail[b], m->bond_head[b]};
  for (int k = 0; k < 2; k++) {
    int e = ends[k], kind = m->elem_kind[e];
    if (((kind == BG_ELEM_J1 && op == BG_X_FLOW) || (kind == BG_ELEM_J0 && op == BG_X_EFFORT)) &&
        m->elem_bonds[m->elem_bondadr[e]] == b)
      return e;
  }
  for (int k = 0; k < 2; k++)
    if (bg_elem_is_oneport(m->elem_kind[ends[k]])) return ends[k];
  for (int k = 0; k < 2; k++)
    if (bg_elem_is_twoport(m->elem_kind[ends[k]])) return ends[k];
  return ends[0];
}

int bg_state_inputs(const bg_model *m, int s, int *out, int cap) {
  int n = 0, sp = 0, root = m->state_expr[s];
  if (root < 0) return 0;
  int *stack = bg_xcalloc((size_t)m->nxnode + 1, sizeof *stack);
  stack[sp++] = root;
  while (sp > 0) {
    const bg_xnode *x = &m->xnode[stack[--sp]];
    for (int k = 0; k < x->nargs; k++) stack[sp++] = x->arg[k];
    int e = x->op == BG_X_STORE ? x->ref
            : x->op == BG_X_EFFORT || x->op == BG_X_FLOW ? var_elem(m, x->op, x->ref) : -1;
    int seen = e < 0;
    for (int k = 0; k < n && !seen; k++) seen = out[k] == e;
    if (!seen && n < cap) out[n++] = e;
  }
  free(stack);
  return n;
}

/* The k-th layer's style (paths, then loops): colour c and dash pattern p
 * of 4. Without per-layer patterns, colours cycle and each further round of
 * them takes the next pattern; with them (print), pattern k mod 4 and colour
 * k mod n, shifted by one after every lcm(n, 4) layers. Either way the
 * first 4 n lines drawn all differ (n colours: 32 by default, 12 in print);
 * k counts drawn lines (a flat loop drawn with its path is that line). */
static void layer_style(const bg_diagram *d, int kind, int i, int *c, int *p) {
  if (kind == 'l' && d->loop_path && d->loop_path[i] >= 0) kind = 'p', i = d->loop_path[i];
  int k = kind == 'p' ? i : (d->a ? d->a->npath : 0) + i, n = d->st.nlayer_color;
  /* loops drawn with their path take no style of their own */
  for (int l = 0; kind == 'l' && d->loop_path && l < i; l++) k -= d->loop_path[l] >= 0;
  if (!d->st.layer_patterns) {
    *c = k % n, *p = (k / n) % 4;
    return;
  }
  int l = n % 2 ? 4 * n : n % 4 ? 2 * n : n; /* lcm(n, 4) */
  *p = k % 4, *c = (k + k / l) % n;
}

bg_rgba bg_layer_color(const bg_diagram *d, int kind, int i) {
  int c, p;
  layer_style(d, kind, i, &c, &p);
  return d->st.layer_color[c];
}

double bg_layer_line(const bg_style *st, int k) { return st->layer_offset + fmax(3, 2.5 * st->layer_width) * k; }

void bg_layer_dash(const bg_diagram *d, int kind, int i, double dash[2]) {
  static const double pat[4][2] = {{5, 2.5}, {1.5, 2}, {8, 3}, {3, 3}};
  int c, pi;
  layer_style(d, kind, i, &c, &pi);
  const double *p = pat[pi];
  double z = fmax(1, d->st.layer_width / 1.2); /* thick lines: longer dashes */
  dash[0] = z * p[0], dash[1] = z * p[1];
}
