/* SPDX-License-Identifier: BSD-3-Clause */
/* Crossings of two bonds of one node as the layout draws them (issue 31:
 * never needed; the checker's fc_adjacent counts them in the scene), for
 * the bond router's second pass (diagram_route_bonds.c): which pairs cross,
 * which bond of a pair to route or draw straight, and how many bonds a set
 * of changed bonds crosses (or runs along). */
#include <math.h>
#include <stdlib.h>

#include "diagram/diagram_route_int.h"
#include "base/sort.h"

/* Whether segments a-b and c-d cross at a point inside both (not within
 * 0.5 pt of an end). */
static int segs_cross(bg_vec a, bg_vec b, bg_vec c, bg_vec d) {
  bg_vec u = bg_vsub(b, a), v = bg_vsub(d, c), w = bg_vsub(c, a);
  double lu = bg_vlen(u), lv = bg_vlen(v), den = u.x * v.y - u.y * v.x;
  if (lu <= 0 || lv <= 0 || fabs(den) < 1e-9 * lu * lv) return 0;
  double t = (w.x * v.y - w.y * v.x) / den, s = (w.x * u.y - w.y * u.x) / den;
  return t * lu > 0.5 && (1 - t) * lu > 0.5 && s * lv > 0.5 && (1 - s) * lv > 0.5;
}

/* Whether segments a-b and c-d run on one line: parallel within 1 degree,
 * less than 1 pt apart, sharing more than 2 pt (the checker's bonds on
 * lines, fc_seg_overlap), not from one point (two routes out of one port,
 * which the false T's pass parts). */
static int segs_along(bg_vec a, bg_vec b, bg_vec c, bg_vec d) {
  bg_vec u = bg_vsub(b, a), v = bg_vsub(d, c);
  double lu = bg_vlen(u), lv = bg_vlen(v);
  if (lu < 2 || lv < 2) return 0;
  bg_vec end[2] = {a, b}, oend[2] = {c, d};
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++)
      if (bg_vlen(bg_vsub(end[i], oend[j])) < 0.5) return 0;
  u = bg_vscale(u, 1 / lu), v = bg_vscale(v, 1 / lv);
  if (fabs(u.x * v.y - u.y * v.x) > 0.0175) return 0;
  bg_vec c0 = bg_vsub(c, a), d0 = bg_vsub(d, a);
  if (fmax(fabs(c0.x * u.y - c0.y * u.x), fabs(d0.x * u.y - d0.y * u.x)) >= 1) return 0;
  double t0 = c0.x * u.x + c0.y * u.y, t1 = d0.x * u.x + d0.y * u.y;
  return fmin(lu, fmax(t0, t1)) - fmax(0, fmin(t0, t1)) > 2;
}

/* Whether some leg of bond b and some leg of bond c meet as `legs` tells
 * (their lines from tail to head over the corners, the half arrow not
 * counted; a Graphviz curve not looked at). */
static int legs_meet(const bg_diagram_layout *L, int b, int c, int (*legs)(bg_vec, bg_vec, bg_vec, bg_vec)) {
  const bg_bond_geom *gb = &L->bg[b], *gc = &L->bg[c];
  if (gb->spln || gc->spln || (L->bond_hidden && (L->bond_hidden[b] || L->bond_hidden[c]))) return 0;
  for (int i = 0; i <= gb->bendn; i++)
    for (int j = 0; j <= gc->bendn; j++)
      if (legs(bg_route_leg_end(L, b, i - 1), bg_route_leg_end(L, b, i), bg_route_leg_end(L, c, j - 1),
               bg_route_leg_end(L, c, j)))
        return 1;
  return 0;
}

/* Whether bonds b and c cross as drawn. */
static int bonds_cross(const bg_diagram_layout *L, int b, int c) { return legs_meet(L, b, c, segs_cross); }

/* Whether bond b, drawn straight, runs off the axes (as the router's costs
 * tell a slanted line: the smaller extent more than 9 % of the larger). */
static int slanted(const bg_diagram_layout *L, int b) {
  bg_vec d = bg_vsub(L->bg[b].head, L->bg[b].tail);
  return fmin(fabs(d.x), fabs(d.y)) > 0.09 * fmax(fabs(d.x), fabs(d.y));
}

/* The crossings of two bonds of one node as the layout draws them (issue
 * 31: never needed). todo (nullable): of each such pair, a bond not routed
 * (route[] 0) drawn straight and slanted marked ROUTE, to be routed in the
 * second pass, and the other, when the layout drew it with corners and did
 * not route it, STRAIGHTEN: it takes the diagonal, the routed one its way
 * out (the number of slanted bonds stays). A straight bond along an axis
 * is a row of the layout, kept. */
int bg_route_adjacent_crossings(const bg_diagram_layout *L, const unsigned char *route, unsigned char *todo) {
  int nb = L->m->nbond, nn = L->nnode, n = 0;
  int *adr = bg_xcalloc((size_t)nn + 2, sizeof *adr), *at = bg_xcalloc((size_t)2 * nb + 1, sizeof *at);
  int *fill = bg_xcalloc((size_t)nn + 1, sizeof *fill);
  for (int b = 0; b < nb; b++) /* the bonds of each node */
    for (int e = 0; e < 2; e++) adr[bg_route_end_node(L, b, e) + 1]++;
  for (int k = 0; k < nn; k++) adr[k + 1] += adr[k];
  for (int b = 0; b < nb; b++)
    for (int e = 0; e < 2; e++) {
      int k = bg_route_end_node(L, b, e);
      at[adr[k] + fill[k]++] = b;
    }
  for (int k = 0; k < nn; k++)
    for (int i = adr[k]; i < adr[k + 1]; i++)
      for (int j = i + 1; j < adr[k + 1]; j++) {
        int b = at[i], c = at[j];
        if (b == c || !bonds_cross(L, b, c)) continue;
        n++;
        if (!todo) continue;
        for (int swap = 0; swap < 2; swap++) {
          int s = swap ? c : b, o = swap ? b : c;
          if (route[s] || L->bg[s].bendn || !slanted(L, s)) continue;
          todo[s] = BG_ROUTE;
          if (!route[o] && L->bg[o].bendn && todo[o] == BG_KEEP) todo[o] = BG_STRAIGHTEN;
          break;
        }
      }
  free(adr), free(at), free(fill);
  return n;
}

/* Whether bonds b and c run on one line somewhere: drawn as one bond. */
static int bonds_along(const bg_diagram_layout *L, int b, int c) { return legs_meet(L, b, c, segs_along); }

/* A pair of bonds on one line, as crossings: a route kept for fewer
 * crossings must not put a bond on another (issue 31: the second pass took
 * a twin's route that ran 6.7 pt along its partner into their junction's
 * corner to uncross two bonds elsewhere, and the pair read as one bond). */
#define ALONG_CROSSINGS 1000

/* The pairs of crossing bonds as the layout draws them of which one is
 * marked in changed, a pair on one line counted ALONG_CROSSINGS times.
 * Each changed bond is tried against the bonds whose boxes meet its own,
 * found through a grid of square cells over the drawing (each bond listed
 * in the cells its box covers, a bond covering more than 64 cells tried
 * against every changed bond): trying every pair
 * made the bond router's second pass quadratic (a random tree of 12 000
 * junctions spent a fifth of its layout here). */
typedef struct cell_entry {
  long long cell;
  int bond;
} cell_entry;

static int by_cell(const void *a, const void *b, void *ctx) {
  (void)ctx;
  const cell_entry *p = a, *q = b;
  return p->cell < q->cell ? -1 : p->cell > q->cell ? 1 : p->bond - q->bond;
}

enum { CELL_SPAN = 1 << 20, BIG_BOND = 64 };

static void bond_box(const bg_diagram_layout *L, int b, double box[4]) {
  box[0] = box[1] = 1e300, box[2] = box[3] = -1e300;
  for (int i = -1; i <= L->bg[b].bendn; i++) {
    bg_vec p = bg_route_leg_end(L, b, i);
    box[0] = fmin(box[0], p.x), box[1] = fmin(box[1], p.y), box[2] = fmax(box[2], p.x), box[3] = fmax(box[3], p.y);
  }
}

int bg_route_crossings_of(const bg_diagram_layout *L, const unsigned char *changed) {
  int nb = L->m->nbond, n = 0, nch = 0;
  for (int b = 0; b < nb; b++) nch += changed[b] != 0;
  if (nch == 0) return 0;
  double (*box)[4] = bg_xcalloc((size_t)nb + 1, sizeof *box), size = 0, lo[2] = {1e300, 1e300};
  for (int b = 0; b < nb; b++) {
    bond_box(L, b, box[b]);
    size += fmax(box[b][2] - box[b][0], box[b][3] - box[b][1]);
    lo[0] = fmin(lo[0], box[b][0]), lo[1] = fmin(lo[1], box[b][1]);
  }
  double cell = fmax(16, 2 * size / nb); /* about twice a bond's length */
  size_t ne = 0, cap = (size_t)nb * 4 + 16;
  cell_entry *ent = bg_xmalloc(cap * sizeof *ent);
  int *big = bg_xcalloc((size_t)nb + 1, sizeof *big), nbig = 0, *seen = bg_xcalloc((size_t)nb + 1, sizeof *seen);
  int range[4];
  for (int b = 0; b < nb; b++) {
    for (int k = 0; k < 4; k++) range[k] = (int)fmin(CELL_SPAN - 1, floor((box[b][k] - lo[k % 2]) / cell));
    long cells = (long)(range[2] - range[0] + 1) * (range[3] - range[1] + 1);
    if (cells > BIG_BOND) {
      big[nbig++] = b;
      continue;
    }
    for (int x = range[0]; x <= range[2]; x++)
      for (int y = range[1]; y <= range[3]; y++) {
        if (ne == cap) cap *= 2, ent = bg_xrealloc(ent, cap * sizeof *ent);
        ent[ne].cell = (long long)x * CELL_SPAN + y, ent[ne++].bond = b;
      }
  }
  bg_sort(ent, ne, sizeof *ent, by_cell, NULL);
  for (int b = 0; b < nb; b++) {
    if (!changed[b]) continue;
    /* a pair is counted once: from its changed bond, from the smaller of two */
#define TRY(c)                                                                                                         \
  if ((c) != b && seen[c] != b + 1 && (!changed[c] || (c) > b))                                                       \
  seen[c] = b + 1, n += bonds_cross(L, b, c) ? 1 : bonds_along(L, b, c) ? ALONG_CROSSINGS : 0
    for (int i = 0; i < nbig; i++) TRY(big[i]);
    for (int k = 0; k < 4; k++) range[k] = (int)fmin(CELL_SPAN - 1, floor((box[b][k] - lo[k % 2]) / cell));
    if ((long)(range[2] - range[0] + 1) * (range[3] - range[1] + 1) > BIG_BOND) { /* a big one: every bond */
      for (int c = 0; c < nb; c++) TRY(c);
      continue;
    }
    for (int x = range[0]; x <= range[2]; x++)
      for (int y = range[1]; y <= range[3]; y++) {
        long long key = (long long)x * CELL_SPAN + y;
        size_t a = 0, z = ne; /* the first entry of the cell */
        while (a < z) {
          size_t mid = (a + z) / 2;
          if (ent[mid].cell < key) a = mid + 1;
          else z = mid;
        }
        for (; a < ne && ent[a].cell == key; a++) TRY(ent[a].bond);
      }
#undef TRY
  }
  free(box), free(ent), free(big), free(seen);
  return n;
}
