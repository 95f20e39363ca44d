/* SPDX-License-Identifier: BSD-3-Clause */
/* Analysis layers: causal paths and topological loops as offset dashed
 * polylines with direction arrows, conflicts as lightning flashes. A layer
 * always runs on the left of its direction of travel, so a flat loop (out
 * along the path and back) surrounds its bonds and the two open loops of a
 * causal loop, which run in opposite directions, fall on opposite sides. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

/* Bond b traversed from point u to point v: nodes, or (ids from nnode on)
 * the corners of bent bonds; fwd: in the bond's tail → head direction. */
typedef struct seg {
  int b, u, v;
  double off;
  bg_vec dir, n;
  int fwd;
} seg;

/* How the polyline passes a node: entry point p0, exit p1 (kind 0: p1 = p0;
 * 1: a straight link; 2: a half-turn curve
 * with controls c1, c2; 5: a half turn as two curves, controls c1, c2 to
 * corner[0], then corner[1], corner[2] to p1). */
typedef struct joint {
  int kind;
  bg_vec p0, p1, c1, c2;
  int ncorner;      /* kind 3: round a collapsed instance's box or a two-port's label, through these corners */
  bg_vec corner[6];
  int rounded;      /* kind 3 round a two-port's label: the corners rounded, so the line reads as
                       passing the label, not as a dashed box drawn round it */
  bg_vec *via;      /* kind 4: a loop closed along its modulating signal's route, through these */
  int nvia;
} joint;

static bg_vec centre(const bg_diagram *d, int n) {
  if (n >= d->L->nnode) return bg_v(d->L->lay.bendx[n - d->L->nnode], d->L->lay.bendy[n - d->L->nnode]);
  return bg_v(d->L->nx[n], d->L->ny[n]);
}

/* The segments split at the corners of bent bonds, each leg a segment of
 * its own (the corners joined like junctions: mitred or rounded). */
static seg *split_bends(const bg_diagram *d, seg *s, int *n) {
  int total = 0;
  for (int k = 0; k < *n; k++) total += 1 + d->L->bg[s[k].b].bendn;
  seg *out = bg_xcalloc((size_t)total + 1, sizeof *out);
  int m = 0;
  for (int k = 0; k < *n; k++) {
    const bg_bond_geom *g = &d->L->bg[s[k].b];
    int nb = g->bendn, fwd = s[k].u == d->L->node_of[d->m->bond_tail[s[k].b]], prev = s[k].u;
    for (int i = 0; i < nb; i++) {
      int c = d->L->nnode + g->bendadr + (fwd ? i : nb - 1 - i);
      out[m] = s[k], out[m].fwd = fwd, out[m].u = prev, out[m].v = c, prev = c, m++;
    }
    out[m] = s[k], out[m].fwd = fwd, out[m].u = prev, m++;
  }
  free(s);
  *n = m;
  return out;
}

/* The segments as drawn: ends at the nodes they are drawn as (a collapsed
 * instance's box), the bonds inside a box left out, so a path or loop that
 * enters a collapsed instance ends at its box (docs/drawing.md). */
static int visible_segs(const bg_diagram *d, seg *s, int n) {
  int m = 0;
  for (int k = 0; k < n; k++) {
    if (d->L->bond_hidden[s[k].b]) continue;
    s[m] = s[k], s[m].u = d->L->node_of[s[k].u], s[m].v = d->L->node_of[s[k].v], m++;
  }
  return m;
}

static int other_end(const bg_model *m, int b, int e) {
  return m->bond_tail[b] == e ? m->bond_head[b] : m->bond_tail[b];
}

/* Layers stack on a bond side in drawing order, each 3 pt (more for thick
 * lines) beyond the one before, except the side's home layer
 * (bg_layers_prepare), which runs outermost; once the home is drawn, the
 * layers after it close up. side_home: the home's key, -2 - key once it is
 * drawn, -1 for none. */
static int side_rank(const bg_diagram *d, int side, int key) {
  int home = d->side_home ? d->side_home[side] : -1;
  if (home == key) return d->side_total[side] - 1;
  return d->side_use[side] - (home <= -2);
}

static void seg_geom(bg_diagram *d, seg *s, int key) {
  s->dir = bg_vunit(bg_vsub(centre(d, s->v), centre(d, s->u)));
  s->n = bg_vleft(s->dir);
  s->off = bg_layer_line(&d->st, side_rank(d, 2 * s->b + (s->fwd ? 0 : 1), key));
}

/* One more layer on each side of a bond this polyline ran along (once for
 * the legs of a bent bond). */
static void claim_sides(bg_diagram *d, const seg *s, int n, int key) {
  for (int i = 0; i < n; i++) {
    if (i > 0 && s[i].b == s[i - 1].b && s[i].fwd == s[i - 1].fwd) continue;
    int side = 2 * s[i].b + (s[i].fwd ? 0 : 1);
    d->side_use[side]++;
    if (d->side_home && d->side_home[side] == key) d->side_home[side] = -2 - key;
  }
}

static double cross(bg_vec a, bg_vec b) { return a.x * b.y - a.y * b.x; }

/* A half turn around the end of bond s->b at node s->v, from s's offset
 * to t's (the way back, on the other side; its own rank there). With the
 * two offsets equal, a half circle; else two quarter ellipses that meet on
 * the bond's line, as far out as the larger offset, so the turn crosses it
 * at a right angle (one curve between unequal offsets crossed it at a
 * slant: tree40's path 7 round its last one-port, issue 31). */
static joint turn(const bg_diagram *d, const seg *s, const seg *t) {
  int v = s->v;
  bg_vec e = bg_box_exit(centre(d, v), d->L->nw[v] / 2, d->L->nh[v] / 2, centre(d, s->u));
  double r = fmax(s->off, t->off);
  bg_vec base = bg_vsub(e, bg_vscale(s->dir, r + 1));
  joint j = {2, bg_vadd(base, bg_vscale(s->n, s->off)), bg_vsub(base, bg_vscale(s->n, t->off)), {0, 0}, {0, 0}, 0, {{0, 0}}, 0, NULL, 0};
  if (fabs(s->off - t->off) > 0.5) {
    const double k = 0.5523; /* a quarter ellipse's controls */
    bg_vec apex = bg_vadd(base, bg_vscale(s->dir, r));
    j.kind = 5;
    j.c1 = bg_vadd(j.p0, bg_vscale(s->dir, k * r)), j.c2 = bg_vadd(apex, bg_vscale(s->n, k * s->off));
    j.corner[0] = apex;
    j.corner[1] = bg_vsub(apex, bg_vscale(s->n, k * t->off)), j.corner[2] = bg_vadd(j.p1, bg_vscale(s->dir, k * r));
    return j;
  }
  j.c1 = bg_vadd(j.p0, bg_vscale(s->dir, 4.0 / 3 * s->off));
  j.c2 = bg_vadd(j.p1, bg_vscale(s->dir, 4.0 / 3 * t->off));
  return j;
}

/* Where the line of s stops (or t starts) beside node v: off the box of
 * a non-junction, grown by 2, at the segment's offset. */
static bg_vec beside_node(const bg_diagram *d, const seg *s, int v, int other) {
  bg_vec c = centre(d, v);
  double hw = d->L->nw[v] / 2 + 2, hh = d->L->nh[v] / 2 + 2;
  return bg_vadd(bg_box_exit(c, hw, hh, centre(d, other)), bg_vscale(s->n, s->off));
}

/* Where p lies on the boundary of the box [x0, x1] × [y0, y1] (moved onto
 * it first), as the length walked clockwise (on a y-down page) from the
 * top left corner. */
static double label_perimeter_at(const double *b, bg_vec p) {
  double x = fmax(b[0], fmin(b[2], p.x)), y = fmax(b[1], fmin(b[3], p.y)), w = b[2] - b[0], h = b[3] - b[1];
  double dt = y - b[1], dr = b[2] - x, db = b[3] - y, dl = x - b[0], m = fmin(fmin(dt, dr), fmin(db, dl));
  if (m == dt) return x - b[0];
  if (m == dr) return w + y - b[1];
  if (m == db) return w + h + b[2] - x;
  return 2 * w + h + b[3] - y;
}

/* A straight link from p0 to p1 past a non-junction node v would cut its
 * label (a two-port passed straight through, or turned at): the line
 * goes round the label's box (grown by 2, and to hold both ends)
 * clockwise, which keeps the node on its right, as the bond it follows. */
static void round_label(const bg_diagram *d, int v, joint *j) {
  double b[4] = {d->L->nx[v] - d->L->nw[v] / 2 - 2, d->L->ny[v] - d->L->nh[v] / 2 - 2, d->L->nx[v] + d->L->nw[v] / 2 + 2,
                 d->L->ny[v] + d->L->nh[v] / 2 + 2};
  for (int k = 0; k < 2; k++) {
    bg_vec p = k ? j->p1 : j->p0;
    b[0] = fmin(b[0], p.x), b[1] = fmin(b[1], p.y), b[2] = fmax(b[2], p.x), b[3] = fmax(b[3], p.y);
  }
  double w = b[2] - b[0], h = b[3] - b[1], per = 2 * (w + h);
  double from = label_perimeter_at(b, j->p0), to = label_perimeter_at(b, j->p1);
  if (to < from) to += per;
  const double at[4] = {w, w + h, 2 * w + h, per}; /* top right, bottom right, bottom left, top left */
  const bg_vec corner[4] = {bg_v(b[2], b[1]), bg_v(b[2], b[3]), bg_v(b[0], b[3]), bg_v(b[0], b[1])};
  j->ncorner = 0;
  for (int lap = 0; lap < 2; lap++)
    for (int k = 0; k < 4; k++) {
      double q = at[k] + lap * per;
      if (q > from + 1e-9 && q < to - 1e-9 && j->ncorner < 4) j->corner[j->ncorner++] = corner[k];
    }
  if (j->ncorner) j->kind = 3, j->rounded = 1;
}

/* How many of 24 points along the cubic p0 c1 c2 p1 fall in the box of a
 * node other than a and b (only nodes whose box meets the control
 * polygon's box are looked at: the curve stays inside it). */
static int curve_in_labels(const bg_diagram *d, const bg_vec c[4], int a, int b) {
  double x0 = c[0].x, x1 = c[0].x, y0 = c[0].y, y1 = c[0].y;
  for (int k = 1; k < 4; k++)
    x0 = fmin(x0, c[k].x), x1 = fmax(x1, c[k].x), y0 = fmin(y0, c[k].y), y1 = fmax(y1, c[k].y);
  int hits = 0;
  for (int n = 0; n < d->L->nnode; n++) {
    if (n == a || n == b || d->L->node_of[n] != n || d->L->nx[n] + d->L->nw[n] / 2 < x0 || d->L->nx[n] - d->L->nw[n] / 2 > x1 ||
        d->L->ny[n] + d->L->nh[n] / 2 < y0 || d->L->ny[n] - d->L->nh[n] / 2 > y1)
      continue;
    for (int k = 1; k < 24; k++) {
      double t = k / 24.0, u = 1 - t;
      bg_vec p = bg_vadd(bg_vadd(bg_vscale(c[0], u * u * u), bg_vscale(c[1], 3 * u * u * t)),
                         bg_vadd(bg_vscale(c[2], 3 * u * t * t), bg_vscale(c[3], t * t * t)));
      hits += fabs(p.x - d->L->nx[n]) < d->L->nw[n] / 2 && fabs(p.y - d->L->ny[n]) < d->L->nh[n] / 2;
    }
  }
  return hits;
}

/* The corners (at most 4, into c) of the shorter way from p0 to p1 round
 * node v's box, grown by 2 pt and to hold both ends. */
static int round_box_short(const bg_diagram *d, int v, bg_vec p0, bg_vec p1, bg_vec c[4]) {
  double b[4] = {d->L->nx[v] - d->L->nw[v] / 2 - 2, d->L->ny[v] - d->L->nh[v] / 2 - 2, d->L->nx[v] + d->L->nw[v] / 2 + 2,
                 d->L->ny[v] + d->L->nh[v] / 2 + 2};
  for (int k = 0; k < 2; k++) {
    bg_vec p = k ? p1 : p0;
    b[0] = fmin(b[0], p.x), b[1] = fmin(b[1], p.y), b[2] = fmax(b[2], p.x), b[3] = fmax(b[3], p.y);
  }
  double w = b[2] - b[0], h = b[3] - b[1], per = 2 * (w + h);
  double from = label_perimeter_at(b, p0), to = label_perimeter_at(b, p1), cw = fmod(to - from + per, per);
  const double at[4] = {w, w + h, 2 * w + h, 0}; /* top right, bottom right, bottom left, top left */
  const bg_vec corner[4] = {bg_v(b[2], b[1]), bg_v(b[2], b[3]), bg_v(b[0], b[3]), bg_v(b[0], b[1])};
  int n = 0, back = cw > per / 2; /* anticlockwise is shorter */
  double len = back ? per - cw : cw, dist[4];
  for (int k = 0; k < 4; k++) { /* the corners passed, in the order of the way taken */
    double dk = back ? fmod(from - at[k] + per, per) : fmod(at[k] - from + per, per);
    if (dk <= 1e-9 || dk >= len - 1e-9) continue;
    int i = n++;
    for (; i > 0 && dist[i - 1] > dk; i--) dist[i] = dist[i - 1], c[i] = c[i - 1];
    dist[i] = dk, c[i] = corner[k];
  }
  return n;
}

/* The route of the signal from node `from` to node `to`, or NULL. */
static const bg_signal_route *signal_route(const bg_diagram *d, int from, int to) {
  for (int k = 0; k < d->nroutes; k++)
    if (d->routes[k].from == from && d->routes[k].to == to && d->routes[k].n >= 2) return &d->routes[k];
  return NULL;
}

/* A loop closed by a modulation follows its signal's route (issue 31), at
 * the first layer's offset on the route's left (no other layer runs there),
 * as it runs beside a bond: from where the loop reaches the signal's source
 * round that box (the shorter way) to the route's start, along the route,
 * and round the modulated element's box to its bond. 0 when the signal is
 * not routed (signals not shown, or not from a node). */
static int routed_jump(const bg_diagram *d, const seg *s, const seg *t, joint *j) {
  const bg_signal_route *r = signal_route(d, d->L->node_of[s->v], d->L->node_of[t->u]);
  if (!r) return 0;
  int n = r->n;
  double off = d->st.layer_offset; /* no other layer runs beside the signal */
  bg_vec d0 = bg_vunit(bg_vsub(r->pts[1], r->pts[0])), dn = bg_vunit(bg_vsub(r->pts[n - 1], r->pts[n - 2]));
  bg_vec q0 = bg_vadd(bg_vadd(r->pts[0], bg_vscale(d0, 2)), bg_vscale(bg_vleft(d0), off));
  bg_vec qn = bg_vadd(bg_vsub(r->pts[n - 1], bg_vscale(dn, 0.5)), bg_vscale(bg_vleft(dn), off));
  bg_vec ca[4], cb[4];
  int na = round_box_short(d, s->v, j->p0, q0, ca), nb = round_box_short(d, t->u, qn, j->p1, cb);
  j->via = bg_xcalloc((size_t)(n + na + nb), sizeof *j->via);
  j->nvia = 0;
  for (int k = 0; k < na; k++) j->via[j->nvia++] = ca[k];
  j->via[j->nvia++] = q0;
  for (int k = 1; k + 1 < n; k++) { /* a corner of the route, moved off on both legs' left (mitred:
                                        a diagonal stub's corner turns by 45 degrees, not 90) */
    bg_vec in = bg_vunit(bg_vsub(r->pts[k], r->pts[k - 1])), out = bg_vunit(bg_vsub(r->pts[k + 1], r->pts[k]));
    double turn = 1 + in.x * out.x + in.y * out.y;
    j->via[j->nvia++] = bg_vadd(r->pts[k], bg_vscale(bg_vadd(bg_vleft(in), bg_vleft(out)), off / fmax(turn, 0.2)));
  }
  j->via[j->nvia++] = qn;
  for (int k = 0; k < nb; k++) j->via[j->nvia++] = cb[k];
  j->kind = 4;
  return 1;
}

/* A modulation closes the loop between different nodes (the signal of s
 * arrives at s->v, whose variable an element's law uses: t->u): a straight
 * line beside the modulating signal, bowed (12 to 45 pt at its middle,
 * either side) where it would cross another node's label, or, back along
 * the same bond (an element modulated by its own output), a curve bulging
 * further out. */
static joint jump(const bg_diagram *d, const seg *s, const seg *t) {
  joint j = {1, beside_node(d, s, s->v, s->u), beside_node(d, t, t->u, t->v), {0, 0}, {0, 0}, 0, {{0, 0}}, 0, NULL, 0};
  if (s->b != t->b && routed_jump(d, s, t, &j)) return j;
  if (s->b != t->b) {
    static const double bows[] = {0, 12, -12, 20, -20, 30, -30, 45, -45};
    bg_vec ab = bg_vsub(j.p1, j.p0), nrm = bg_vleft(bg_vunit(ab));
    int best = -1, fewest = 0;
    for (size_t k = 0; k < sizeof bows / sizeof bows[0] && (best < 0 || fewest > 0); k++) {
      bg_vec off = bg_vscale(nrm, bows[k] / 0.75); /* both controls out: the middle moves 3/4 of it */
      bg_vec c[4] = {j.p0, bg_vadd(bg_vadd(j.p0, bg_vscale(ab, 1.0 / 3)), off),
                     bg_vadd(bg_vadd(j.p0, bg_vscale(ab, 2.0 / 3)), off), j.p1};
      int hits = curve_in_labels(d, c, s->v, t->u);
      if (best < 0 || hits < fewest) best = (int)k, fewest = hits, j.c1 = c[1], j.c2 = c[2];
    }
    if (best > 0) j.kind = 2;
    return j;
  }
  double k = 0.3 * bg_vlen(bg_vsub(j.p1, j.p0)) + 12, bulge = 14 + s->off;
  j.kind = 2;
  j.c1 = bg_vadd(j.p0, bg_vadd(bg_vscale(s->dir, k), bg_vscale(s->n, bulge)));
  j.c2 = bg_vsub(bg_vadd(j.p1, bg_vscale(t->n, bulge)), bg_vscale(t->dir, k));
  return j;
}

/* Where p lies along the perimeter of the rectangle r = (x0, y0, x1, y1),
 * measured clockwise (on the page) from its top left corner; *on gets the
 * nearest point of the perimeter. */
static double perimeter_at(const double r[4], bg_vec p, bg_vec *on) {
  double w = r[2] - r[0], h = r[3] - r[1];
  double x = fmin(fmax(p.x, r[0]), r[2]), y = fmin(fmax(p.y, r[1]), r[3]);
  double dt = fabs(p.y - r[1]), dr = fabs(p.x - r[2]), db = fabs(p.y - r[3]), dl = fabs(p.x - r[0]);
  double m = fmin(fmin(dt, dr), fmin(db, dl));
  if (m == dt) return *on = bg_v(x, r[1]), x - r[0];
  if (m == dr) return *on = bg_v(r[2], y), w + y - r[1];
  if (m == db) return *on = bg_v(x, r[3]), w + h + r[2] - x;
  return *on = bg_v(r[0], y), 2 * w + h + r[3] - y;
}

/* A path through a collapsed instance (in at one port, out at another)
 * goes round its box clockwise, so it keeps to its left like everywhere
 * else and never crosses the box. */
static joint around_box(const bg_diagram *d, const seg *s, const seg *t, joint j) {
  int v = s->v;
  double g = 2 + fmax(s->off, t->off);
  double r[4] = {d->L->nx[v] - d->L->nw[v] / 2 - g, d->L->ny[v] - d->L->nh[v] / 2 - g,
                 d->L->nx[v] + d->L->nw[v] / 2 + g, d->L->ny[v] + d->L->nh[v] / 2 + g};
  double w = r[2] - r[0], h = r[3] - r[1], per = 2 * (w + h);
  const double at[4] = {0, w, w + h, 2 * w + h};
  const bg_vec c[4] = {{r[0], r[1]}, {r[2], r[1]}, {r[2], r[3]}, {r[0], r[3]}};
  bg_vec e0, e1;
  double t0 = perimeter_at(r, j.p0, &e0), t1 = perimeter_at(r, j.p1, &e1);
  double len = fmod(t1 - t0 + per, per);
  j.kind = 3, j.ncorner = 0;
  j.corner[j.ncorner++] = e0;
  int first = 0; /* the first corner after t0 clockwise, then the others in turn */
  for (int k = 1; k < 4; k++)
    if (fmod(at[k] - t0 + per, per) < fmod(at[first] - t0 + per, per)) first = k;
  for (int k = 0; k < 4; k++) {
    double dk = fmod(at[(first + k) % 4] - t0 + per, per);
    if (dk > 1e-9 && dk < len) j.corner[j.ncorner++] = c[(first + k) % 4];
  }
  j.corner[j.ncorner++] = e1;
  return j;
}

/* Where the polyline of s meets the one of t at their common node. */
static joint join(const bg_diagram *d, const seg *s, const seg *t) {
  int v = s->v;
  bg_vec c = centre(d, v);
  if (t->u != s->v) return jump(d, s, t);
  if (t->b == s->b && t->u == s->v && t->v == s->u) return turn(d, s, t);
  bg_vec a = bg_vadd(c, bg_vscale(s->n, s->off)), b = bg_vadd(c, bg_vscale(t->n, t->off));
  joint j = {1, a, b, {0, 0}, {0, 0}, 0, {{0, 0}}, 0, NULL, 0};
  if (!bg_elem_is_junction(v < d->m->nelem ? d->m->elem_kind[v] : BG_ELEM_J1)) {
    /* keep off the label: leave and re-enter at the box, around it */
    j.p0 = beside_node(d, s, v, s->u), j.p1 = beside_node(d, t, v, t->v);
    if (d->L->box_inst && d->L->box_inst[v] >= 0) return around_box(d, s, t, j);
    round_label(d, v, &j);
    return j;
  }
  double den = cross(s->dir, t->dir);
  if (fabs(den) < 0.05) return j;
  double u = cross(bg_vsub(b, a), t->dir) / den;
  bg_vec x = bg_vadd(a, bg_vscale(s->dir, u));
  double off = s->off > t->off ? s->off : t->off, dist = bg_vlen(bg_vsub(x, c));
  /* y grows downwards: den < 0 turns towards the left, where the layer runs */
  int inside = den < 0;
  if (dist <= 1.3 * off || (inside && dist <= 4 * off)) {
    j.kind = 0, j.p0 = j.p1 = x;
  } else if (!inside) {
    /* round the outside of a sharp turn with an arc about the junction */
    double ang = acos(fmax(-1, fmin(1, s->n.x * t->n.x + s->n.y * t->n.y)));
    double k = 4.0 / 3 * tan(ang / 4) * off;
    j.kind = 2, j.c1 = bg_vadd(a, bg_vscale(s->dir, k)), j.c2 = bg_vsub(b, bg_vscale(t->dir, k));
  }
  return j;
}

/* A corner c between a and b as a quarter circle of radius up to 3 pt
 * (half the shorter leg at most). */
static void round_corner(bg_scene *sc, bg_vec a, bg_vec c, bg_vec b) {
  double r = fmin(3, 0.5 * fmin(bg_vlen(bg_vsub(a, c)), bg_vlen(bg_vsub(b, c))));
  bg_vec in = bg_vadd(c, bg_vscale(bg_vunit(bg_vsub(a, c)), r)), out = bg_vadd(c, bg_vscale(bg_vunit(bg_vsub(b, c)), r));
  bg_vec c1 = bg_vadd(in, bg_vscale(bg_vsub(c, in), 0.5523)), c2 = bg_vadd(out, bg_vscale(bg_vsub(c, out), 0.5523));
  bg_scene_line(sc, in.x, in.y);
  bg_scene_curve(sc, c1.x, c1.y, c2.x, c2.y, out.x, out.y);
}

static void emit_joint(bg_scene *sc, const joint *j) {
  bg_scene_line(sc, j->p0.x, j->p0.y);
  for (int k = 0; j->kind == 3 && k < j->ncorner; k++)
    if (j->rounded)
      round_corner(sc, k ? j->corner[k - 1] : j->p0, j->corner[k], k + 1 < j->ncorner ? j->corner[k + 1] : j->p1);
    else
      bg_scene_line(sc, j->corner[k].x, j->corner[k].y);
  for (int k = 0; j->kind == 4 && k < j->nvia; k++) bg_scene_line(sc, j->via[k].x, j->via[k].y);
  if (j->kind == 1 || j->kind == 3 || j->kind == 4) bg_scene_line(sc, j->p1.x, j->p1.y);
  if (j->kind == 2) bg_scene_curve(sc, j->c1.x, j->c1.y, j->c2.x, j->c2.y, j->p1.x, j->p1.y);
  if (j->kind == 5) { /* two curves through corner[0] */
    bg_scene_curve(sc, j->c1.x, j->c1.y, j->c2.x, j->c2.y, j->corner[0].x, j->corner[0].y);
    bg_scene_curve(sc, j->corner[1].x, j->corner[1].y, j->corner[2].x, j->corner[2].y, j->p1.x, j->p1.y);
  }
}

static int layer_hot(const bg_diagram *d, int kind, int i) {
  return !d->o.highlight_kind || (d->o.highlight_kind == kind && d->o.highlight_index == i + 1);
}

/* A straight run of a drawn polyline (segment k between its joints), with
 * the normal n on the outside (the left of travel, away from the bond). */
typedef struct run {
  bg_vec a, b, n;
} run;

static bg_vec bezier(bg_vec p0, bg_vec c1, bg_vec c2, bg_vec p1, double t) {
  double u = 1 - t;
  return bg_vadd(bg_vadd(bg_vscale(p0, u * u * u), bg_vscale(c1, 3 * u * u * t)),
                 bg_vadd(bg_vscale(c2, 3 * u * t * t), bg_vscale(p1, t * t * t)));
}

/* The top of the curve that closes a loop back along its own bond (jump):
 * the chord of its middle fifth, outside towards the bulge, where a gain
 * reads as the curve's. */
static run bulge_run(const joint *j) {
  bg_vec a = bezier(j->p0, j->c1, j->c2, j->p1, 0.4), b = bezier(j->p0, j->c1, j->c2, j->p1, 0.6);
  bg_vec n = bg_vleft(bg_vunit(bg_vsub(b, a)));
  bg_vec out = bg_vsub(bg_vscale(bg_vadd(a, b), 0.5), bg_vscale(bg_vadd(j->p0, j->p1), 0.5));
  if (n.x * out.x + n.y * out.y < 0) n = bg_vscale(n, -1);
  return (run){a, b, n};
}

/* Draws a closed layer polyline through the segments, with an arrow at the
 * middle of each; writes each segment's straight run to runs (n of them),
 * then the top of each bulge that closes the loop (room for 2 n); returns
 * how many runs it wrote. */
static int draw_polyline(bg_diagram *d, seg *s, int n, int kind, int i, int merged, run *runs) {
  const char *name = kind == 'p' ? "path" : "loop";
  joint *j = bg_xcalloc((size_t)n, sizeof *j);
  for (int k = 0; k < n; k++) j[k] = join(d, &s[k], &s[(k + 1) % n]);
  bg_rgba c = bg_diagram_ink(d, bg_layer_color(d, kind, i), layer_hot(d, kind, i));
  bg_scene_item *it = merged >= 0
      ? bg_scene_begin(&d->scene, BG_ITEM_STROKE, "%s %d loop=%d", name, i + 1, merged + 1)
      : bg_scene_begin(&d->scene, BG_ITEM_STROKE, "%s %d", name, i + 1);
  if (d->npoly == d->cappoly) {
    d->cappoly = d->cappoly ? 2 * d->cappoly : 16;
    d->poly = bg_xrealloc(d->poly, (size_t)d->cappoly * sizeof *d->poly);
  }
  d->poly[d->npoly++] = d->scene.nitem - 1;
  it->color = c, it->width = d->st.layer_width, it->round = 1;
  bg_layer_dash(d, kind, i, it->dash);
  bg_scene_move(&d->scene, j[n - 1].p1.x, j[n - 1].p1.y);
  for (int k = 0; k < n; k++) emit_joint(&d->scene, &j[k]);
  bg_scene_close(&d->scene);
  for (int k = 0; k < n; k++) {
    bg_vec a = j[(k + n - 1) % n].p1, b = j[k].p0;
    runs[k] = (run){a, b, s[k].n};
    if (bg_vlen(bg_vsub(b, a)) < 14) continue; /* no room for an arrow */
    bg_vec mid = bg_vadd(bg_vscale(bg_vadd(a, b), 0.5), bg_vscale(s[k].dir, 2.5));
    it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "%s-arrow %d", name, i + 1);
    it->fill = it->color = c, it->width = 0;
    bg_geom_arrowhead(&d->scene, mid, s[k].dir, 5, 4);
  }
  int nrun = n;
  for (int k = 0; k < n; k++)
    if (j[k].kind == 2 && s[(k + 1) % n].u != s[k].v) runs[nrun++] = bulge_run(&j[k]);
  for (int k = 0; k < n; k++) free(j[k].via);
  free(j);
  return nrun;
}

/* ---------------------------------------------------------------- labels */
/* A path tag or loop gain, placed after every line is drawn beside one of
 * the straight runs of its own polyline (in order of preference). */
struct bg_layer_label {
  const char *markup;
  bg_rgba color;
  char role[40];
  int owner;     /* its polyline: index in d->poly + 1 */
  run *runs;
  int nrun;
};

/* A label for the polyline drawn next, its markup set later. */
static bg_layer_label *new_label(bg_diagram *d, bg_rgba c, int nrun) {
  if (d->nlabels == d->caplabels) {
    d->caplabels = d->caplabels ? 2 * d->caplabels : 16;
    d->labels = bg_xrealloc(d->labels, (size_t)d->caplabels * sizeof *d->labels);
  }
  bg_layer_label *L = &d->labels[d->nlabels++];
  L->color = c;
  L->owner = d->npoly + 1; /* its polyline is drawn next */
  L->runs = bg_arena_alloc(&d->arena, sizeof(run) * (size_t)(nrun + 1));
  L->nrun = 0;
  return L;
}

static double label_size(const bg_diagram *d) { return d->st.font_size * d->st.number_scale; }

/* How far a w × h box reaches from its centre in direction n (a unit axis
 * or diagonal). */
static double reach(bg_vec n, double w, double h) { return fabs(n.x) * w / 2 + fabs(n.y) * h / 2; }

/* The runs in `order` copied to the label, those where it can come closest
 * to its line first: beside a horizontal run before a slanted one, before a
 * vertical one. */
static void label_runs(bg_layer_label *L, const run *r, const int *order, int n, double w, double h) {
  for (int pass = 0; pass < 3; pass++)
    for (int k = 0; k < n; k++) {
      const run *t = &r[order[k]];
      double extent = reach(t->n, w, h);
      int band = extent <= h ? 0 : extent <= 0.5 * (w / 2 + h) ? 1 : 2;
      if (band == pass) L->runs[L->nrun++] = *t;
    }
}

/* Segment indices 0..n-1 from the middle outwards. */
static void middle_first(int *order, int n) {
  int mid = (n - 1) / 2, k = 0;
  order[k++] = mid;
  for (int r = 1; k < n; r++) {
    if (mid + r < n) order[k++] = mid + r;
    if (k < n && mid - r >= 0) order[k++] = mid - r;
  }
}

static void measure_label(const bg_diagram *d, const char *markup, double *w, double *h) {
  bg_text_measure(d->st.font, label_size(d), markup, w, h);
  *w += 2, *h = 0.8 * *h + 1;
}

enum { TAG_GAP = 2 }; /* between a tag's box and its line */

enum { TEXT_CLEAR = 6 }; /* between a tag and other text beside it, so "L2: G = n" and "1" stay two */

/* What a label at p costs: the obstacles it touches (bg_place_score, 8
 * each), 4 when another polyline comes nearer to it than its own line (the
 * box grown by its distance from its own line, out beyond the gap), 2 when
 * one comes within 6 pt more, so a tag does not nestle between other
 * layers when there is open room (a tag a little astray is better than one
 * over a line), and 1 when a node label or another text is within
 * TEXT_CLEAR pt beside it (where they would read as one: "L2: G = n 1").
 * 0 is a perfect place; below 4 its nearest line is its own. */
/* Once the cost reaches bound (a place as good is already known; -1:
 * none) the rest is not looked at: the place cannot win. */
static int label_cost(bg_diagram *d, const bg_layer_label *L, bg_vec p, double w, double h, double out,
                      int bound) {
  int c = 8 * bg_place_score(d, p, w, h);
  if (bound >= 0 && c >= bound) return c;
  double g = 2 * (TAG_GAP + out + 1), far = g + 12;
  if (bg_place_others(d, p, w + far, h + far, L->owner) > 0)
    c += 2 + 2 * (bg_place_others(d, p, w + g, h + g, L->owner) > 0);
  if (bound >= 0 && c >= bound) return c;
  return c + (bg_place_boxes(d, p, w + 2 * TEXT_CLEAR, h + 2) > 0);
}

/* Tries the places beside run r at distance `out` beyond the gap, on its
 * outside (side 1) or inside (-1), from its middle outwards; keeps the
 * cheapest in *best. Returns 1 when a perfect place was found. */
static int try_run(bg_diagram *d, const bg_layer_label *L, const run *r, int side, double out, double w,
                   double h, bg_vec *best, int *best_cost) {
  bg_vec ab = bg_vsub(r->b, r->a), dir = bg_vunit(ab), n = bg_vscale(r->n, side);
  double len = bg_vlen(ab), room = len / 2; /* the box may reach past a short run's ends */
  double dist = TAG_GAP + out + reach(n, w, h), step = fmax(3, len / 12);
  bg_vec mid = bg_vadd(bg_vadd(r->a, bg_vscale(ab, 0.5)), bg_vscale(n, dist));
  for (int k = 0; k == 0 || k * step <= room; k++)
    for (int sgn = -1; sgn <= (k ? 1 : -1); sgn += 2) {
      bg_vec p = bg_vadd(mid, bg_vscale(dir, sgn * k * step));
      int c = label_cost(d, L, p, w, h, out, *best_cost);
      if (*best_cost < 0 || c < *best_cost) *best = p, *best_cost = c;
      if (c == 0) return 1;
    }
  return 0;
}

/* The label's place beside its own runs: outside at the gap, then inside
 * (an open loop's gain inside its bond loop), then 4 and 8 pt further out;
 * the cheapest, the first of equals. Returns its cost. */
static int label_place(bg_diagram *d, const bg_layer_label *L, double w, double h, bg_vec *at) {
  static const struct { int side; double out; } pass[] = {{1, 0}, {-1, 0}, {1, 4}, {-1, 4}, {1, 8}, {-1, 8}};
  bg_vec best = L->nrun ? bg_vscale(bg_vadd(L->runs[0].a, L->runs[0].b), 0.5) : bg_v(0, 0);
  int best_cost = -1;
  for (size_t p = 0; p < sizeof pass / sizeof pass[0]; p++)
    for (int k = 0; k < L->nrun; k++)
      if (try_run(d, L, &L->runs[k], pass[p].side, pass[p].out, w, h, &best, &best_cost)) {
        *at = best;
        return 0;
      }
  *at = best;
  return best_cost < 0 ? 0 : best_cost;
}

/* A tag on a leader line: the tag at p, the line from a (on its own
 * polyline, with a dot) to e (the tag's box). */
typedef struct leader {
  bg_vec p, a, e;
} leader;

enum { LEADER_RUNS = 6, LEADER_TRIES = 600 };

/* Where no place beside its own line is free and nearer its own line than
 * any other (a crowded figure), the tag goes into open room nearby on a
 * leader line, as a textbook labels a line in a bundle: straight out from
 * a point of one of its first runs (either side, the run's middle
 * outwards), at right angles or 45° to it, 8 to 44 pt long. The tag must
 * touch nothing and have no other layer within 3 pt; the line must cross no
 * label or node; of those, the fewest lines crossed (a bond counts 5), then
 * the shortest, at right angles before slanted, the first of equals. Returns
 * 0 when there is none. */
static int leader_place(bg_diagram *d, const bg_layer_label *L, double w, double h, leader *best) {
  static const double lens[] = {8, 14, 22, 32, 44};
  static const double ts[] = {0.5, 0.375, 0.625, 0.25, 0.75, 0.125, 0.875};
  int best_cost = -1, tries = 0;
  for (size_t li = 0; li < sizeof lens / sizeof lens[0]; li++)
    for (int k = 0; k < L->nrun && k < LEADER_RUNS; k++) {
      const run *r = &L->runs[k];
      bg_vec ab = bg_vsub(r->b, r->a), dir = bg_vunit(ab);
      if (bg_vlen(ab) < 6) continue;
      for (int side = 1; side >= -1; side -= 2)
        for (size_t ti = 0; ti < sizeof ts / sizeof ts[0]; ti++)
          for (int slant = 0; slant < 3; slant++) {
            if (++tries > LEADER_TRIES && best_cost >= 0) return 1;
            bg_vec n = bg_vscale(r->n, side), a = bg_vadd(r->a, bg_vscale(ab, ts[ti]));
            if (slant) n = bg_vscale(bg_vadd(n, bg_vscale(dir, slant == 1 ? 1 : -1)), BG_SQRT1_2);
            bg_vec p = bg_vadd(a, bg_vscale(n, lens[li] + reach(n, w, h)));
            if (bg_place_score(d, p, w, h) || bg_place_others(d, p, w + 6, h + 6, L->owner)) continue;
            bg_vec e = bg_box_exit(p, w / 2, h / 2, a);
            int bonds, lines;
            if (bg_place_crossings(d, a, e, L->owner, &bonds, &lines)) continue;
            int cost = 2 * (5 * bonds + lines) + (bg_place_boxes(d, p, w + 2 * TEXT_CLEAR, h + 2) > 0);
            if (best_cost < 0 || cost < best_cost) best_cost = cost, *best = (leader){p, a, e};
            if (cost == 0) return 1;
          }
    }
  return best_cost >= 0;
}

/* The leader line, thin and solid in the tag's colour, with a dot where it
 * meets the tag's own line (roles "path-leader K", "gain-leader loop=K"). */
static void draw_leader(bg_diagram *d, const bg_layer_label *L, const leader *q) {
  char kind[8], which[24];
  int path = !strncmp(L->role, "path-tag ", 9);
  snprintf(kind, sizeof kind, "%s", path ? "path" : "gain");
  snprintf(which, sizeof which, path ? "%d" : "loop=%d", atoi(L->role + (path ? 9 : 10)));
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "%s-leader %s", kind, which);
  it->color = L->color, it->width = fmax(0.4, 0.5 * d->st.layer_width), it->round = 1;
  bg_scene_move(&d->scene, q->a.x, q->a.y);
  bg_scene_line(&d->scene, q->e.x, q->e.y);
  bg_obstacle_item(d, d->scene.nitem - 1);
  it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "%s-leader-dot %s", kind, which);
  it->fill = it->color = L->color, it->width = 0;
  bg_scene_circle(&d->scene, q->a.x, q->a.y, fmax(1.2, d->st.layer_width));
}

void bg_place_layer_labels(bg_diagram *d) {
  for (int i = 0; i < d->nlabels; i++) {
    bg_layer_label *L = &d->labels[i];
    double w, h;
    measure_label(d, L->markup, &w, &h);
    bg_vec p;
    leader q = {{0, 0}, {0, 0}, {0, 0}};
    /* below 4: no other line nearer than its own, nothing touched */
    if (label_place(d, L, w, h, &p) >= 4 && leader_place(d, L, w, h, &q)) {
      p = q.p;
      draw_leader(d, L, &q);
    }
    bg_obstacle_rect(d, p.x - w / 2, p.y - h / 2, p.x + w / 2, p.y + h / 2);
    bg_text_halo(d, L->markup, p, label_size(d));
    bg_scene_text(&d->scene, L->markup, p.x, p.y, label_size(d), 0.5, 0.5, L->color, L->role);
  }
}

/* "L1: G = -n" (symbolic when short, else the value). */
static void gain_text(const bg_diagram *d, int l, bg_strbuf *t) {
  const bg_analysis *a = d->a;
  bg_sb_printf(t, "L%d", l + 1);
  const char *g = a->tloop_gain ? a->tloop_gain[l] : NULL;
  if (g && strlen(g) <= 24) {
    bg_sb_puts(t, ": G = "), bg_gain_markup(g, label_size(d), t);
  } else if (a->tloop_gain_value && isfinite(a->tloop_gain_value[l])) {
    /* the value is the coefficient without the integrations (docs/json.md):
     * G = -0.001/s, not -0.001 (the tutorial's tank read G = -0.001) */
    char v[80];
    double x = a->tloop_gain_value[l] + 0.0; /* no -0 */
    snprintf(v, sizeof v, x == 0 || (fabs(x) >= 1e-3 && fabs(x) < 1e5) ? "%.4g" : "%.3e", x);
    char *e = strchr(v, 'e');
    if (e) snprintf(e, sizeof v - (size_t)(e - v), "\u00b710^%d", atoi(e + 1)); /* 1.235e-05 → 1.235·10^-5 */
    int order = a->tloop_order ? a->tloop_order[l] : 0;
    size_t n = strlen(v);
    if (order == 1) snprintf(v + n, sizeof v - n, "/s");
    else if (order > 1) snprintf(v + n, sizeof v - n, "/s^%d", order);
    bg_sb_puts(t, ": G = "), bg_gain_markup(v, label_size(d), t);
  }
}

/* ---------------------------------------------------------------- paths */
/* The flat loop a causal path's polyline also draws, or -1. */
static int path_loop(const bg_diagram *d, int p) {
  for (int l = 0; d->loop_path && l < d->a->ntloop; l++)
    if (d->loop_path[l] == p) return l;
  return -1;
}

static int path_segs(const bg_diagram *d, int p, seg *s) {
  const bg_analysis *a = d->a;
  int n = a->path_n[p], cur = a->path_end0[p];
  for (int k = 0; k < n; k++) {
    int b = a->path_bonds[a->path_adr[p] + k], nxt = other_end(d->m, b, cur);
    s[k] = (seg){b, cur, nxt, 0, {0, 0}, {0, 0}, 0};
    s[2 * n - 1 - k] = (seg){b, nxt, cur, 0, {0, 0}, {0, 0}, 0};
    cur = nxt;
  }
  return 2 * n;
}

/* Effort travels towards the stroke end, flow away from it. */
static seg signal_seg(const bg_diagram *d, int sig) {
  const bg_model *m = d->m;
  int b = sig / 2, flow = sig & 1;
  int head_stroke = d->a->bond_stroke[b] != BG_STROKE_TAIL;
  int forward = flow ? !head_stroke : head_stroke;
  int u = forward ? m->bond_tail[b] : m->bond_head[b];
  return (seg){b, u, other_end(m, b, u), 0, {0, 0}, {0, 0}, 0};
}

/* A layer's identity among all of them: paths, then loops. */
static int layer_key(const bg_diagram *d, int kind, int i) { return kind == 'p' ? i : d->a->npath + i; }

/* Whether layer (kind, i) is drawn: its layer is shown or it is the
 * highlight (a flat loop drawn with its path is not drawn itself). */
static int layer_drawn(const bg_diagram *d, int kind, int i) {
  const bg_analysis *a = d->a;
  unsigned flag = kind == 'p' ? BG_SHOW_PATHS : BG_SHOW_LOOPS;
  if (!(d->show & flag) && !(d->o.highlight_kind == kind && d->o.highlight_index == i + 1)) return 0;
  if (kind == 'p') return a->path_n[i] >= 1;
  return d->loop_path[i] < 0 && a->tloop_n[i] >= 1;
}

/* The segments of a drawn layer (corners of bent bonds split; *n of
 * them), the caller frees them; NULL when it is not drawn. */
/* Whether a loop closed by a modulation (segment `last` ends where the
 * next one, `first`, does not start: the jump) reads the variable of the
 * node `last` left, not of the one it reaches: internal_mod_r's `js.f` is
 * the flow of bond 1 to E, but the signal comes from the junction js. That
 * segment is then left out, so the loop closes from js along its signal
 * instead of running out to E and across the figure. */
static int modulation_detour(const bg_diagram *d, const seg *last, const seg *first) {
  const bg_model *m = d->m;
  if (first->u == last->v || last->u >= m->nelem || first->u >= m->nelem) return 0;
  int from_u = 0, from_v = 0;
  for (int k = 0; k < m->nsignal; k++) {
    if (m->signal_to[k] != first->u) continue;
    from_u |= m->signal_from[k] == last->u, from_v |= m->signal_from[k] == last->v;
  }
  return from_u && !from_v;
}

static seg *layer_segs(const bg_diagram *d, int kind, int i, int *n) {
  const bg_analysis *a = d->a;
  if (!layer_drawn(d, kind, i)) return NULL;
  seg *s;
  if (kind == 'p') {
    s = bg_xcalloc(2 * (size_t)a->path_n[i], sizeof *s);
    *n = path_segs(d, i, s);
  } else {
    *n = a->tloop_n[i];
    s = bg_xcalloc((size_t)*n, sizeof *s);
    for (int k = 0; k < *n; k++) s[k] = signal_seg(d, a->tloop_signals[a->tloop_adr[i] + k]);
    for (int k = 0; *n > 2 && k < *n; k++)
      if (modulation_detour(d, &s[k], &s[(k + 1) % *n])) {
        memmove(&s[k], &s[k + 1], (size_t)(*n - k - 1) * sizeof *s), --*n;
        break;
      }
  }
  *n = visible_segs(d, s, *n);
  if (*n == 0) { /* wholly inside a collapsed instance */
    free(s);
    return NULL;
  }
  return split_bends(d, s, n);
}

/* Order of drawing: a highlighted layer goes last, on top of the greyed ones. */
static int layer_at(const bg_diagram *d, int kind, int k, int n) {
  if (d->o.highlight_kind != kind) return k;
  int hot = d->o.highlight_index - 1;
  if (k == n - 1) return hot;
  return k < hot ? k : k + 1;
}

static void draw_path(bg_diagram *d, int p) {
  int n, key = layer_key(d, 'p', p);
  seg *s = layer_segs(d, 'p', p, &n);
  if (s) {
    for (int k = 0; k < n; k++) seg_geom(d, &s[k], key);
    int l = path_loop(d, p);
    run *runs = bg_xcalloc((size_t)(2 * n), sizeof *runs);
    bg_layer_label *L = new_label(d, bg_diagram_ink(d, bg_layer_color(d, 'p', p), layer_hot(d, 'p', p)), 2 * n);
    int nrun = draw_polyline(d, s, n, 'p', p, l, runs);
    /* the tag (with the gain of the flat loop drawn along) outside the
     * polyline, beside a bond from the middle of the path outwards */
    bg_strbuf t = {0};
    bg_sb_printf(&t, "P%d", p + 1);
    if (l >= 0) bg_sb_puts(&t, ", "), gain_text(d, l, &t);
    double w, h;
    measure_label(d, bg_sb_str(&t), &w, &h);
    int *order = bg_xcalloc((size_t)nrun, sizeof *order);
    middle_first(order, n / 2);
    for (int k = 0; k < n / 2; k++) order[n / 2 + k] = n - 1 - order[k]; /* the way back */
    for (int k = n; k < nrun; k++) order[k] = k;                         /* bulges last */
    L->markup = bg_arena_strdup(&d->arena, bg_sb_str(&t));
    snprintf(L->role, sizeof L->role, l >= 0 ? "path-tag %d gain" : "path-tag %d", p + 1);
    label_runs(L, runs, order, nrun, w, h);
    free(order), free(runs);
    bg_sb_free(&t);
    claim_sides(d, s, n, key);
    free(s);
  }
}

void bg_draw_paths(bg_diagram *d) {
  int n = d->a ? d->a->npath : 0;
  for (int k = 0; k < n; k++) draw_path(d, layer_at(d, 'p', k, n));
}

/* ---------------------------------------------------------------- loops */
static void draw_loop(bg_diagram *d, int l) {
  int n, key = layer_key(d, 'l', l);
  seg *s = layer_segs(d, 'l', l, &n);
  if (s) {
    for (int k = 0; k < n; k++) seg_geom(d, &s[k], key);
    run *runs = bg_xcalloc((size_t)(2 * n), sizeof *runs);
    bg_layer_label *L = new_label(d, bg_diagram_ink(d, bg_layer_color(d, 'l', l), layer_hot(d, 'l', l)), 2 * n);
    int nrun = draw_polyline(d, s, n, 'l', l, -1, runs);
    /* the gain beside the loop's line, like a path tag */
    bg_strbuf t = {0};
    gain_text(d, l, &t);
    double w, h;
    measure_label(d, bg_sb_str(&t), &w, &h);
    L->markup = bg_arena_strdup(&d->arena, bg_sb_str(&t));
    snprintf(L->role, sizeof L->role, "gain loop=%d", l + 1);
    int *order = bg_xcalloc((size_t)nrun, sizeof *order);
    middle_first(order, n);
    for (int k = n; k < nrun; k++) order[k] = k; /* bulges last */
    label_runs(L, runs, order, nrun, w, h);
    free(order), free(runs);
    bg_sb_free(&t);
    claim_sides(d, s, n, key);
    free(s);
  }
}

void bg_draw_loops(bg_diagram *d) {
  int n = d->a ? d->a->ntloop : 0;
  for (int k = 0; k < n; k++) draw_loop(d, layer_at(d, 'l', k, n));
}

/* ---------------------------------------------------------------- homes */
/* The side a layer takes as its home: of those no other layer has, the one
 * with the fewest layers (beside a horizontal bond on ties, where a tag sits
 * closest), from the middle of the layer outwards; -1 when none is left. */
static int choose_home(const bg_diagram *d, const seg *s, int n) {
  int *order = bg_xcalloc((size_t)n, sizeof *order), best = -1, best_cost = 0;
  middle_first(order, n);
  for (int k = 0; k < n; k++) {
    const seg *t = &s[order[k]];
    int side = 2 * t->b + (t->fwd ? 0 : 1);
    bg_vec dir = bg_vsub(centre(d, t->v), centre(d, t->u));
    int cost = 2 * d->side_total[side] + (fabs(dir.y) > fabs(dir.x));
    if (d->side_home[side] == -1 && (best < 0 || cost < best_cost)) best = side, best_cost = cost;
  }
  free(order);
  return best;
}

/* Layers stack on a bond side in drawing order, so a layer drawn early can
 * run between others on every bond it follows, and no place beside its
 * line has that line as the nearest: its tag would read as another's.
 * Before drawing, each layer (in drawing order) gets a home side
 * (choose_home) where it runs outermost (seg_geom); pass 0 counts the
 * layers on each side. */
static void plan_homes(bg_diagram *d) {
  size_t nside = 2 * (size_t)d->m->nbond + 1;
  d->side_total = bg_arena_alloc(&d->arena, nside * sizeof(int));
  d->side_home = bg_arena_alloc(&d->arena, nside * sizeof(int));
  memset(d->side_total, 0, nside * sizeof(int));
  for (size_t k = 0; k < nside; k++) d->side_home[k] = -1;
  static const int kinds[2] = {'p', 'l'};
  for (int pass = 0; d->a && pass < 2; pass++)
    for (int ki = 0; ki < 2; ki++) {
      int kd = kinds[ki], count = kd == 'p' ? d->a->npath : d->a->ntloop;
      for (int k = 0; k < count; k++) {
        int n, i = layer_at(d, kd, k, count);
        seg *s = layer_segs(d, kd, i, &n);
        if (!s) continue;
        for (int j = 0; pass == 0 && j < n; j++)
          if (j == 0 || s[j].b != s[j - 1].b || s[j].fwd != s[j - 1].fwd) d->side_total[2 * s[j].b + (s[j].fwd ? 0 : 1)]++;
        int home = pass == 1 ? choose_home(d, s, n) : -1;
        if (home >= 0) d->side_home[home] = layer_key(d, kd, i);
        free(s);
      }
    }
}

/* A flat loop caused by a causal path runs exactly where the path's polyline
 * runs (out along the path and back): when both layers are shown, and the
 * highlight does not single out either, the path's polyline draws both.
 * Then every drawn layer gets its home (plan_homes). */
void bg_layers_prepare(bg_diagram *d) {
  const bg_analysis *a = d->a;
  int n = a ? a->ntloop : 0;
  d->loop_path = bg_arena_alloc(&d->arena, sizeof(int) * ((size_t)n + 1));
  int both = (d->show & BG_SHOW_PATHS) && (d->show & BG_SHOW_LOOPS);
  for (int l = 0; l < n; l++) d->loop_path[l] = -1;
  for (int l = 0; l < n; l++) {
    int p = -1;
    const char *c = a->tloop_cause ? a->tloop_cause[l] : NULL;
    if (both && a->tloop_kind[l] == BG_TLOOP_FLAT && c && sscanf(c, "causal path %d", &p) == 1 &&
        p >= 1 && p <= a->npath && path_loop(d, p - 1) < 0 &&
        !(d->o.highlight_kind == 'l' && d->o.highlight_index == l + 1) &&
        !(d->o.highlight_kind == 'p' && d->o.highlight_index == p))
      p -= 1;
    else
      p = -1;
    d->loop_path[l] = p;
  }
  plan_homes(d);
}
