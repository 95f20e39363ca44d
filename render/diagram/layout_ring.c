/* SPDX-License-Identifier: BSD-3-Clause */
/* One-ports round their junction when the eight cells next to it cannot hold
 * them all (a junction of a dozen capacitors, a star of 200 resistors): a
 * leaf under diagram_grid.c. The grid pass had put the rest in rings of
 * cells further out, each on a straight bond through the labels nearer in,
 * and the bond router then took those bonds round the figure (docs/drawing.md,
 * "Junctions of many one-ports").
 *
 * Here the one-ports sit on the sides of a rectangle round the junction, each
 * on a straight bond from its centre through the empty inside, so no bond
 * crosses another or passes through a label. Along a side the slots are at
 * least a box and a gap apart, and further apart towards the corners: a bond
 * to a slot far along a side reaches its box through the box's inner edge, and
 * must pass outside the box before it (rule_next); neighbouring bonds keep
 * an angle between them. The corners hold one each when both neighbours
 * leave room. Of the rectangles that hold them all, the one whose larger side
 * is least, a width counted at 2/3 (pick_rect); a side whose middle a bond of
 * the junction leaves through keeps that slot free. The ring is the grid's
 * eight cells when it is as small as it can be (one slot on each side's
 * middle and at each corner). */
#include <math.h>
#include <stdlib.h>

#include "base/arena.h"
#include "base/sort.h"
#include "diagram/layout.h"

#define RING_PI 3.14159265358979323846
#define RING_MARGIN 3.0 /* pt between a bond and a box it passes */

typedef struct ring_box {
  double w, h, px, py; /* the largest box; pitches: a box and a gap */
  double turn;         /* the least angle between neighbouring bonds */
} ring_box;

/* One side of the rectangle seen from the junction: `half` away, `reach`
 * long each way from its middle; its boxes `along` long and `across` deep
 * towards the junction, `pitch` apart at least. */
typedef struct side {
  double half, reach, along, across, pitch;
} side;

static side side_lr(const ring_box *b, double A, double B) { return (side){A, B, b->h, b->w, b->py}; }
static side side_ud(const ring_box *b, double A, double B) { return (side){B, A, b->w, b->h, b->px}; }

/* The least place after `prev` along side s: a pitch on; far enough that the
 * bond to it passes the box at prev by RING_MARGIN (the bond enters its box
 * through the inner edge, and at that depth must be clear of the box before;
 * the margin across the bond, which leans at most to the side's end); and
 * the bond `turn` round from the one to prev (strokes at the junction, bond
 * numbers: a side's middle, seen from afar, had bonds 4 degrees apart).
 * INFINITY when the turn passes the side's end. */
static double rule_next(const side *s, double prev, double turn) {
  double out = (prev + s->along / 2 + RING_MARGIN * hypot(1, s->reach / s->half)) / (1 - s->across / (2 * s->half));
  double ang = atan2(prev, s->half) + turn;
  double turned = ang < RING_PI / 2 - 1e-9 ? s->half * tan(ang) : INFINITY;
  return fmax(prev + s->pitch, fmax(out, turned));
}

/* The places (> 0) along side s from its middle, up to `last`; into pos
 * (when not NULL). Returns how many. */
static int side_places(const side *s, double turn, double last, double *pos) {
  int n = 0;
  for (double at = rule_next(s, 0, turn); at <= last + 1e-9; at = rule_next(s, at, turn)) {
    if (pos) pos[n] = at;
    n++;
  }
  return n;
}

/* The k-th place along side s (0: its middle). */
static double nth_place(const side *s, double turn, int k) {
  double at = 0;
  for (int i = 0; i < k; i++) at = rule_next(s, at, turn);
  return at;
}

/* The slots beside each side's middle (*nv each way on the left and right,
 * *nh above and below), whether the corners hold one (*corner), and how many
 * slots in all, for half sizes A (to the left and right sides' centres) and
 * B. The corners' neighbours stay a pitch off the corner boxes; without a
 * corner slot, the last slots of two sides keep the turn between them (the
 * one with more gives one up). */
static int ring_slots(const ring_box *b, double A, double B, int closed, int *nv, int *nh, int *corner) {
  side v = side_lr(b, A, B), u = side_ud(b, A, B);
  *nv = side_places(&v, b->turn, B - b->py, NULL);
  *nh = side_places(&u, b->turn, A - b->px, NULL);
  for (;;) {
    double yl = nth_place(&v, b->turn, *nv), xl = nth_place(&u, b->turn, *nh);
    *corner = B >= rule_next(&v, yl, b->turn) - 1e-9 && A >= rule_next(&u, xl, b->turn) - 1e-9;
    if (*corner || atan2(B, xl) - atan2(yl, A) >= b->turn - 1e-9 || (!*nv && !*nh)) break;
    if (*nv >= *nh) --*nv;
    else --*nh;
  }
  int open = 0;
  for (int k = 0; k < 4; k++) open += !(closed & (1 << k));
  return open + 4 * *nv + 4 * *nh + 4 * *corner;
}

typedef struct slot {
  double x, y, ang;
} slot;

static int by_ang(const void *a, const void *b, void *ctx) {
  (void)ctx;
  const slot *p = a, *q = b;
  return (p->ang > q->ang) - (p->ang < q->ang);
}

/* Every slot of the rectangle (A, B), y down, sorted by angle. */
static slot *list_slots(const ring_box *b, double A, double B, int closed, int *ns) {
  int nv, nh, corner, cap = ring_slots(b, A, B, closed, &nv, &nh, &corner);
  slot *s = bg_xmalloc((size_t)cap * sizeof *s);
  side v = side_lr(b, A, B), u = side_ud(b, A, B);
  int fv = side_places(&v, b->turn, B - b->py, NULL), fh = side_places(&u, b->turn, A - b->px, NULL);
  double *pv = bg_xmalloc((size_t)(fv + fh + 1) * sizeof *pv), *ph = pv + fv;
  side_places(&v, b->turn, B - b->py, pv); /* the first nv and nh of them */
  side_places(&u, b->turn, A - b->px, ph);
  int n = 0;
  static const int sx[4] = {1, 0, -1, 0}, sy[4] = {0, -1, 0, 1}; /* R U L D, as the grid's sides */
  for (int k = 0; k < 4; k++) {
    double cx = sx[k] * A, cy = sy[k] * B;
    if (!(closed & (1 << k))) s[n++] = (slot){cx, cy, 0};
    int cnt = sx[k] ? nv : nh;
    const double *p = sx[k] ? pv : ph;
    for (int j = 0; j < cnt; j++)
      for (int sign = -1; sign <= 1; sign += 2)
        s[n++] = sx[k] ? (slot){cx, sign * p[j], 0} : (slot){sign * p[j], cy, 0};
  }
  for (int k = 0; corner && k < 4; k++) s[n++] = (slot){k & 1 ? A : -A, k & 2 ? B : -B, 0};
  free(pv);
  for (int i = 0; i < n; i++) s[i].ang = atan2(s[i].y, s[i].x);
  bg_sort(s, (size_t)n, sizeof *s, by_ang, NULL);
  *ns = n;
  return s;
}

/* The rectangle: for each number of pitches across, the fewest up and down
 * that hold n (a binary search over heights, each height it keeps holding
 * them all); of those the
 * one whose larger side is least, a width counted at 1 / RING_ASPECT (a
 * page's landscape shape; the smallest area alone was a flat band, every
 * bond a sliver out of the junction), then the smaller area. A narrow
 * rectangle's sides hold few (their slots spread out geometrically), so
 * each width's search stops at a height that cannot win, or that a square
 * of (n + 8) pitches' sides would not need. */
#define RING_ASPECT 1.5
static int pick_rect(const ring_box *b, int n, int closed, double *A, double *B) {
  double best = INFINITY, best_area = INFINITY, limit = (n + 8) * (b->px + b->py);
  int nv, nh, corner;
  for (int q = 0;; q++) {
    double a = (q + 1) * b->px, wide = 2 * a + b->w;
    if (wide / RING_ASPECT > best || wide > 2 * limit) break; /* wider only grows the larger side */
    /* the most pitches up and down that could still win */
    int most = (int)floor((fmin(best, limit) - b->h) / (2 * b->py)) - 1, lo = 0, hi = 1;
    if (most < 0) continue;
    hi = hi < most ? hi : most;
    while (ring_slots(b, a, (hi + 1) * b->py, closed, &nv, &nh, &corner) < n && hi < most)
      lo = hi + 1, hi = 2 * hi < most ? 2 * hi : most;
    if (ring_slots(b, a, (hi + 1) * b->py, closed, &nv, &nh, &corner) < n) continue;
    while (lo < hi) {
      int mid = (lo + hi) / 2;
      if (ring_slots(b, a, (mid + 1) * b->py, closed, &nv, &nh, &corner) >= n) hi = mid;
      else lo = mid + 1;
    }
    double bb = (hi + 1) * b->py, tall = 2 * bb + b->h, side = fmax(wide / RING_ASPECT, tall);
    if (side < best || (side == best && wide * tall < best_area)) best = side, best_area = wide * tall, *A = a, *B = bb;
  }
  return best < INFINITY;
}

void bg_layout_ring(int n, const double *angle, double w, double h, double xgap, double ygap, int closed,
                    double *ox, double *oy, double *hx, double *hy) {
  int bonds = n;
  for (int k = 0; k < 4; k++) bonds += (closed >> k) & 1;
  /* three quarters of the even share of the full turn (room for the sides'
   * ends, where the slots lie closer in angle), but no more than the
   * smallest ring's corner makes with a side's middle */
  ring_box b = {w, h, w + xgap, h + ygap, 0};
  b.turn = fmin(0.75 * 2 * RING_PI / bonds, 0.99 * fmin(atan2(b.py, b.px), atan2(b.px, b.py)));
  double A = b.px, B = b.py;
  if (!pick_rect(&b, n, closed, &A, &B)) { /* no rectangle keeps the turn: without it */
    b.turn = 0;
    if (!pick_rect(&b, n, closed, &A, &B)) { /* not met in any test: a square grown until it holds them */
      int nv, nh, corner;
      while (ring_slots(&b, A, B, closed, &nv, &nh, &corner) < n) A *= 2, B *= 2;
    }
  }
  int ns;
  slot *s = list_slots(&b, A, B, closed, &ns);
  bg_keyed *l = bg_xmalloc((size_t)n * sizeof *l + 1);
  for (int i = 0; i < n; i++) l[i] = (bg_keyed){remainder(angle[i], 2 * RING_PI), i};
  bg_sort_keyed(l, (size_t)n);
  /* leaf i of the sorted ones on slot r + i * ns / n: the empty slots spread
   * evenly, the turn r the one nearest the wanted angles */
  double best = INFINITY;
  int turn = 0;
  for (int r = 0; r < ns; r++) {
    double cost = 0;
    for (int i = 0; i < n && cost < best; i++)
      cost += fabs(remainder(l[i].key - s[(r + (long long)i * ns / n) % ns].ang, 2 * RING_PI));
    if (cost < best) best = cost, turn = r;
  }
  for (int i = 0; i < n; i++) {
    const slot *t = &s[(turn + (long long)i * ns / n) % ns];
    ox[l[i].i] = t->x, oy[l[i].i] = t->y;
  }
  *hx = A + w / 2, *hy = B + h / 2;
  free(s), free(l);
}
