/* SPDX-License-Identifier: BSD-3-Clause */
/* Free-floating text placement: bond numbers, path tags, loop gains. Every
 * drawn node box, label box and line (bonds, signals, path and loop
 * polylines) is an obstacle kept in a hashed grid; a label goes to the first
 * of its candidate positions that touches the fewest obstacles. The grid's
 * bucket count grows with its entries (at most two a bucket on average), so
 * a query costs the same in a diagram of 50 000 nodes as in one of 50. A
 * segment is entered in the cells along it, not in every cell of its
 * bounding box: the long slanted lines dot draws across a grid filled whole
 * regions, and every query there tested them all (a query box meets a
 * segment only in a cell the segment passes through, so scores are the
 * same). */
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

enum { CELL = 24, HASH0 = 1 << 14 };

struct bg_obstacles {
  int n, cap;
  double *box;          /* x0 y0 x1 y1; a segment keeps its end points */
  unsigned char *seg;   /* 1: the segment (x0,y0)-(x1,y1), 0: a rectangle */
  int *owner;           /* per obstacle: the path/loop polyline it belongs to (1, 2, ...), a bond's
                           line -1 - b, or 0 */
  unsigned *stamp;      /* per obstacle: last query that looked at it */
  unsigned query;
  int *head;            /* per hash bucket: first entry, -1 */
  unsigned nhash;       /* buckets, a power of two */
  int *enext, *eob;     /* entries: next in bucket, obstacle */
  unsigned *ekey;       /* entries: the cell's hash before the mask (not the cell: 4 bytes less an
                           entry; a query that meets another cell's entry of the same key tests it,
                           and it scores only where it also has an entry in a queried cell) */
  int nent, capent;
};

static int cell_of(double v) { return (int)floor(v / CELL); }

static unsigned cell_key(int cx, int cy) { return (unsigned)cx * 73856093u ^ (unsigned)cy * 19349663u; }

static unsigned bucket(const bg_obstacles *o, int cx, int cy) { return cell_key(cx, cy) & (o->nhash - 1); }

/* Four times the buckets, every entry rechained; the score of a query does
 * not depend on the order of a chain. */
static void rehash(bg_obstacles *o) {
  free(o->head);
  o->nhash *= 4;
  o->head = bg_xmalloc(o->nhash * sizeof(int));
  for (unsigned i = 0; i < o->nhash; i++) o->head[i] = -1;
  for (int e = 0; e < o->nent; e++) {
    unsigned h = o->ekey[e] & (o->nhash - 1);
    o->enext[e] = o->head[h], o->head[h] = e;
  }
}

static bg_obstacles *obstacles(bg_diagram *d) {
  if (!d->obs) {
    d->obs = bg_xcalloc(1, sizeof *d->obs);
    d->obs->nhash = HASH0;
    d->obs->head = bg_xmalloc(HASH0 * sizeof(int));
    for (int i = 0; i < HASH0; i++) d->obs->head[i] = -1;
  }
  return d->obs;
}

void bg_obstacles_free(bg_obstacles *o) {
  if (!o) return;
  free(o->box), free(o->seg), free(o->owner), free(o->stamp), free(o->head);
  free(o->enext), free(o->eob), free(o->ekey);
  free(o);
}

static void add_entry(bg_obstacles *o, int ob, int cx, int cy) {
  if (o->nent == o->capent) {
    o->capent = o->capent ? 2 * o->capent : 1024;
    o->enext = bg_xrealloc(o->enext, (size_t)o->capent * sizeof(int));
    o->eob = bg_xrealloc(o->eob, (size_t)o->capent * sizeof(int));
    o->ekey = bg_xrealloc(o->ekey, (size_t)o->capent * sizeof(unsigned));
  }
  if ((unsigned)o->nent >= 2 * o->nhash) rehash(o);
  unsigned h = bucket(o, cx, cy);
  int e = o->nent++;
  o->eob[e] = ob, o->ekey[e] = cell_key(cx, cy), o->enext[e] = o->head[h];
  o->head[h] = e;
}

static void add_obstacle(bg_diagram *d, int seg, int owner, double x0, double y0, double x1, double y1) {
  bg_obstacles *o = obstacles(d);
  if (o->n == o->cap) {
    o->cap = o->cap ? 2 * o->cap : 256;
    o->box = bg_xrealloc(o->box, (size_t)o->cap * 4 * sizeof(double));
    o->seg = bg_xrealloc(o->seg, (size_t)o->cap);
    o->owner = bg_xrealloc(o->owner, (size_t)o->cap * sizeof(int));
    o->stamp = bg_xrealloc(o->stamp, (size_t)o->cap * sizeof(unsigned));
  }
  int k = o->n++;
  double *b = o->box + 4 * k;
  b[0] = x0, b[1] = y0, b[2] = x1, b[3] = y1;
  o->seg[k] = (unsigned char)seg, o->owner[k] = owner, o->stamp[k] = 0;
  int cx0 = cell_of(fmin(x0, x1)), cx1 = cell_of(fmax(x0, x1));
  int cy0 = cell_of(fmin(y0, y1)), cy1 = cell_of(fmax(y0, y1));
  for (int cy = cy0; cy <= cy1; cy++) {
    int lo = cx0, hi = cx1;
    if (seg && y0 != y1) { /* only the cells along the line, one more each side for rounding */
      double ya = fmax(fmin(y0, y1), (double)cy * CELL), yb = fmin(fmax(y0, y1), (double)(cy + 1) * CELL);
      double xa = x0 + (ya - y0) * (x1 - x0) / (y1 - y0), xb = x0 + (yb - y0) * (x1 - x0) / (y1 - y0);
      lo = cell_of(fmin(xa, xb)) - 1, hi = cell_of(fmax(xa, xb)) + 1;
      if (lo < cx0) lo = cx0;
      if (hi > cx1) hi = cx1;
    }
    for (int cx = lo; cx <= hi; cx++) add_entry(o, k, cx, cy);
  }
}

void bg_obstacle_rect(bg_diagram *d, double x0, double y0, double x1, double y1) {
  add_obstacle(d, 0, 0, x0, y0, x1, y1);
}

void bg_obstacle_item(bg_diagram *d, int i) { bg_obstacle_owned(d, i, 0); }

/* The lines of scene item i (curves flattened into chords) become obstacles. */
void bg_obstacle_owned(bg_diagram *d, int i, int owner) {
  const bg_scene *s = &d->scene;
  const bg_scene_item *it = &s->item[i];
  double px = 0, py = 0, sx = 0, sy = 0;
  bg_scene_op op_;
  for (int k = 0; bg_scene_next_op(s, it, &k, &op_);) {
    const bg_scene_op *op = &op_;
    if (op->code == BG_OP_MOVE) {
      px = sx = op->x[0], py = sy = op->y[0];
    } else if (op->code == BG_OP_LINE || op->code == BG_OP_CLOSE) {
      double x = op->code == BG_OP_LINE ? op->x[0] : sx, y = op->code == BG_OP_LINE ? op->y[0] : sy;
      add_obstacle(d, 1, owner, px, py, x, y);
      px = x, py = y;
    } else { /* a chord per 5 pt of the control polygon, at least 4: a long bulge keeps its shape */
      double len = hypot(op->x[0] - px, op->y[0] - py) + hypot(op->x[1] - op->x[0], op->y[1] - op->y[0]) +
                   hypot(op->x[2] - op->x[1], op->y[2] - op->y[1]);
      int nc = (int)fmin(32, fmax(4, ceil(len / 5)));
      double x0 = px, y0 = py; /* the curve's start: px, py move along the chords */
      for (int j = 1; j <= nc; j++) {
        double t = (double)j / nc, u = 1 - t;
        double x = u * u * u * x0 + 3 * u * u * t * op->x[0] + 3 * u * t * t * op->x[1] + t * t * t * op->x[2];
        double y = u * u * u * y0 + 3 * u * u * t * op->y[0] + 3 * u * t * t * op->y[1] + t * t * t * op->y[2];
        add_obstacle(d, 1, owner, px, py, x, y);
        px = x, py = y;
      }
    }
  }
}

/* What a w × h box centred at p touches: the score of bg_place_score, or
 * (owner > 0) how many segments of polylines other than owner's, or (owner
 * -1) how many boxes. */
static int query(bg_diagram *d, bg_vec p, double w, double h, int owner, int limit) {
  bg_obstacles *o = obstacles(d);
  double x0 = p.x - w / 2, y0 = p.y - h / 2, x1 = p.x + w / 2, y1 = p.y + h / 2;
  int score = 0;
  o->query++;
  for (int cy = cell_of(y0); cy <= cell_of(y1); cy++)
    for (int cx = cell_of(x0); cx <= cell_of(x1); cx++) {
      unsigned key = cell_key(cx, cy);
      for (int e = o->head[key & (o->nhash - 1)]; e >= 0; e = o->enext[e]) {
        int k = o->eob[e];
        if (o->ekey[e] != key || o->stamp[k] == o->query) continue;
        o->stamp[k] = o->query;
        if (owner < 0 && o->seg[k]) continue;
        if (owner > 0 && (o->owner[k] <= 0 || o->owner[k] == owner)) continue;
        const double *b = o->box + 4 * k;
        if (o->seg[k] ? bg_seg_hits_box(b, x0, y0, x1, y1)
                      : (x0 < b[2] && b[0] < x1 && y0 < b[3] && b[1] < y1))
          score += o->seg[k] ? 1 : 10; /* covering text is worse than crossing lines */
        if (score >= limit) return score; /* it cannot win (bg_place_score_below) */
      }
    }
  return score;
}

int bg_place_score(bg_diagram *d, bg_vec p, double w, double h) { return query(d, p, w, h, 0, INT_MAX); }

int bg_place_score_below(bg_diagram *d, bg_vec p, double w, double h, int limit) {
  return query(d, p, w, h, 0, limit);
}

int bg_place_others(bg_diagram *d, bg_vec p, double w, double h, int owner) {
  return query(d, p, w, h, owner, INT_MAX);
}

int bg_place_boxes(bg_diagram *d, bg_vec p, double w, double h) { return query(d, p, w, h, -1, INT_MAX) / 10; }

int bg_place_nearest_bond(bg_diagram *d, bg_vec p, double r, double slack, double *margin) {
  bg_obstacles *o = obstacles(d);
  int best = -1;
  double best_d = r, second = INFINITY;
  r += slack;
  o->query++;
  for (int cy = cell_of(p.y - r); cy <= cell_of(p.y + r); cy++)
    for (int cx = cell_of(p.x - r); cx <= cell_of(p.x + r); cx++) {
      unsigned key = cell_key(cx, cy);
      for (int e = o->head[key & (o->nhash - 1)]; e >= 0; e = o->enext[e]) {
        int k = o->eob[e];
        if (o->ekey[e] != key || o->stamp[k] == o->query) continue;
        o->stamp[k] = o->query;
        if (o->owner[k] >= 0) continue;
        const double *sg = o->box + 4 * k;
        double dk = bg_point_seg(p, bg_v(sg[0], sg[1]), bg_v(sg[2], sg[3]));
        int bk = -1 - o->owner[k];
        if (bk == best) {
          best_d = fmin(best_d, dk);
        } else if (dk < best_d || (dk == best_d && best >= 0 && bk < best)) {
          if (best >= 0) second = fmin(second, best_d);
          best_d = dk, best = bk;
        } else {
          second = fmin(second, dk);
        }
      }
    }
  *margin = best >= 0 ? fmin(second - best_d, slack) : 0;
  return best;
}

static double orient(const double *s, double x, double y) {
  return (s[2] - s[0]) * (y - s[1]) - (s[3] - s[1]) * (x - s[0]);
}

/* Whether the segments s and t (x0 y0 x1 y1) cross or touch. */
static int segs_meet(const double *s, const double *t) {
  double d1 = orient(s, t[0], t[1]), d2 = orient(s, t[2], t[3]);
  double d3 = orient(t, s[0], s[1]), d4 = orient(t, s[2], s[3]);
  return d1 * d2 <= 0 && d3 * d4 <= 0 && (d1 != 0 || d2 != 0 || d3 != 0 || d4 != 0);
}

int bg_place_crossings(bg_diagram *d, bg_vec a, bg_vec b, int owner, int *bonds, int *lines) {
  bg_obstacles *o = obstacles(d);
  double s[4] = {a.x, a.y, b.x, b.y};
  int boxes = 0;
  *bonds = *lines = 0;
  o->query++;
  for (int cy = cell_of(fmin(a.y, b.y)); cy <= cell_of(fmax(a.y, b.y)); cy++)
    for (int cx = cell_of(fmin(a.x, b.x)); cx <= cell_of(fmax(a.x, b.x)); cx++) {
      unsigned key = cell_key(cx, cy);
      for (int e = o->head[key & (o->nhash - 1)]; e >= 0; e = o->enext[e]) {
        int k = o->eob[e];
        if (o->ekey[e] != key || o->stamp[k] == o->query) continue;
        o->stamp[k] = o->query;
        const double *r = o->box + 4 * k;
        if (!o->seg[k]) boxes += bg_seg_hits_box(s, r[0], r[1], r[2], r[3]);
        else if (o->owner[k] != owner && segs_meet(s, r)) ++*(o->owner[k] < 0 ? bonds : lines);
      }
    }
  return boxes;
}

int bg_place_best(bg_diagram *d, const bg_vec *cand, int n, double w, double h) {
  int best = 0, best_score = -1;
  for (int k = 0; k < n && best_score != 0; k++) {
    int s = bg_place_score_below(d, cand[k], w, h, best_score < 0 ? INT_MAX : best_score);
    if (best_score < 0 || s < best_score) best = k, best_score = s;
  }
  bg_obstacle_rect(d, cand[best].x - w / 2, cand[best].y - h / 2, cand[best].x + w / 2,
                   cand[best].y + h / 2);
  return best;
}

void bg_obstacle_nodes(bg_diagram *d) {
  for (int i = 0; i < d->L->nnode; i++)
    bg_obstacle_rect(d, d->L->nx[i] - d->L->nw[i] / 2, d->L->ny[i] - d->L->nh[i] / 2, d->L->nx[i] + d->L->nw[i] / 2,
                     d->L->ny[i] + d->L->nh[i] / 2);
}

void bg_text_halo(bg_diagram *d, const char *markup, bg_vec p, double size) {
  double w, h;
  bg_text_measure(d->st.font, size, markup, &w, &h);
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "halo");
  it->fill = d->st.background, it->width = 0;
  double hw = w / 2 + 1, hh = 0.8 * h / 2 + 0.5;
  bg_scene_move(&d->scene, p.x - hw, p.y - hh);
  bg_scene_line(&d->scene, p.x + hw, p.y - hh);
  bg_scene_line(&d->scene, p.x + hw, p.y + hh);
  bg_scene_line(&d->scene, p.x - hw, p.y + hh);
  bg_scene_close(&d->scene);
}
