/* SPDX-License-Identifier: BSD-3-Clause */
/* A geometry checker for diagrams: reads a scene (every item has a role,
 * render/scene/scene.h) and counts what a textbook figure must not have:
 * slanted bonds, causal strokes touching a neighbouring bond, labels over
 * lines or other labels, bond numbers nearer another bond than their own,
 * path tags and gains away from their line, overlays and lines through
 * element labels, bond crossings and bonds hardly longer than their half
 * arrow; and (issue 31) signals crossing bonds, lines drawn on top of each
 * other, bond ends on another bond (false T-junctions), bonds shorter than
 * their half arrow, crossing frames and elements inside a foreign frame,
 * text below 6 pt, the arrangement a style changed
 * (fc_arrangement), crossings of one element's lines (fc_adjacent),
 * crossings a short detour avoids (fc_avoidable) and the diagonals a
 * junction of more than four bonds forces (fc_forced_diagonals, not faults).
 * Used by test_figures.c; the
 * definitions are in docs/drawing.md ("Measured geometry"). */
#ifndef BG_TEST_FIGURE_CHECK_H
#define BG_TEST_FIGURE_CHECK_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "scene/scene.h"

typedef struct fc_stats {
  int bonds, slanted;        /* bonds; bonds with a segment off the axes */
  int strokes, touching;     /* causal strokes; those touching another bond */
  int labels, over;          /* numbers, tags, gains, conflict texts; those over a line or label */
  int numbers, astray;       /* bond numbers and variables; those nearer another bond */
  int tags, tags_far;        /* path tags and gains; nearer another overlay or > 12 pt off */
  int crowded;               /* tags and bond numbers with another text within 2 pt beside them (read as one) */
  int through;               /* overlay polylines and leaders × element labels they run through */
  int lines_through;         /* bonds and signals × element labels they run through */
  int crossings;             /* pairs of bonds that cross */
  int short_bonds;           /* bonds shorter than 2.5 half arrows (the half arrow not counted) */
  /* issue 31 */
  int sig_cross;             /* signal × bond pairs that cross */
  int sig_oblique;           /* of those, crossing more than 5 degrees off a right angle */
  int overlaps;              /* pairs of lines (bonds, signals) sharing a stretch: collinear, < 1 pt apart, > 2 pt long */
  int false_tees;            /* bond ends on another bond's line away from its ends (read as a T-junction) */
  int tiny_bonds;            /* bonds shorter than their own half arrow */
  int frames, frame_cross;   /* instance frames; pairs of frames whose borders cross */
  int foreign;               /* element labels inside a frame of an instance they do not belong to */
  int texts, small_text;     /* every text item; those with some part below 6 pt */
  int arrangement;           /* element label pairs in another order than in the default style (fc_arrangement) */
  int layer_oblique;         /* path/loop line × bond pairs crossing more than 5 degrees off a right angle */
  int spine_bent;            /* bonds of the longest source-to-load chain drawn with a corner (fc_spine_bent) */
  int sig_through;           /* of lines_through, signals × element labels (a route through a node) */
  int bond_overlaps;         /* of overlaps, the pairs with a bond (a bond drawn on another line) */
  int bare_branches;         /* signals starting on another signal's line without a branch dot (fc_bare_branches) */
  int adjacent;              /* of crossings and signal × bond, those of lines sharing an end (fc_adjacent) */
  int avoidable;             /* of crossings and signal × bond, those a short detour avoids (fc_avoidable) */
  int diagonals;             /* bonds at 45 degrees off a junction whose four sides its other bonds take
                                (fc_forced_diagonals; taken out of slanted by the callers that count them) */
  int nodes_overlap;         /* pairs of element labels whose boxes overlap (two nodes on one place) */
  int tips_beside;           /* signal arrows pointing past their node's label, not at it (fc_tip_beside) */
  int steps;                 /* signal lines with a small step: a leg under 8 pt between two legs going on the same way (fc_steps) */
  int on_frames;             /* bonds and signals running along a frame's border, within 2 pt for more than 8 pt (fc_on_frame) */
  int sig_at_ends;           /* of sig_cross, those at a bond's end, among its half arrow or stroke (fc_sig_cross) */
  int sig_on_layers;         /* signal × path or loop line pairs running side by side within 3 pt for more than 8 pt (fc_beside_layer) */
  int sig_beside;            /* signal pairs of different sources side by side within 5 pt for more than 20 pt (fc_sig_beside) */
  int sig_touch;             /* signal pairs of different sources where a corner or end of one lies on the other (fc_sig_touch) */
  int stroke_text;           /* causal strokes whose bar comes within half a point of an element label's text (fc_stroke_text) */
  int bond_at_ends;          /* bond pairs where one passes between the other's end and its node (fc_end_gap):
                                a crossing hidden in the gap, read as a T or as crossing among the half arrow */
} fc_stats;

enum { FC_BOND, FC_SIGNAL, FC_OVERLAY, FC_STROKE, FC_LEADER, FC_FRAME, FC_OTHER }; /* line kinds */
enum { FC_NODE, FC_NUMBER, FC_TAG, FC_TEXT, FC_IGNORED };         /* text kinds */

/* Set (BG_FIGURES_VERBOSE=2) to print every fault found, with where it is. */
static int fc_explain;

typedef struct fc_seg {
  double x0, y0, x1, y1;
} fc_seg;

typedef struct fc_line {
  const char *name;         /* frames: the instance (the role's second word) */
  int kind, id, nseg, barb; /* id: bond number, path/loop number; barb: last seg is the half arrow */
  int loop;                 /* overlays: "loop K" or "path K loop=K" draws loop K, else 0 */
  double width;
  fc_seg *seg;
  double x0, y0, x1, y1;    /* the segments' bounding box: pairs of lines far apart are skipped (fc_near) */
} fc_line;

typedef struct fc_box {
  const char *name;   /* element labels: the element ("node NAME") */
  int kind, id, loop; /* numbers: bond; tags: path (loop 0) or loop (id 0) */
  double x0, y0, x1, y1;
  int elem;           /* an element's label ("node NAME") */
} fc_box;

typedef struct fc_scene {
  fc_line *line;
  int nline;
  fc_box *box;
  int nbox;
} fc_scene;

static int fc_starts(const char *role, const char *prefix) {
  size_t n = strlen(prefix);
  return !strncmp(role, prefix, n) && (role[n] == ' ' || role[n] == '\0');
}

static int fc_num_after(const char *role, const char *key) {
  const char *p = strstr(role, key);
  return p ? atoi(p + strlen(key)) : 0;
}

static int fc_line_kind(const char *r, int *id, int *loop) {
  *loop = 0;
  if (fc_starts(r, "bond") || fc_starts(r, "lagrange-bond")) {
    *id = fc_starts(r, "bond") ? atoi(r + 5) : -atoi(r + 14); /* Sf* bonds: negative */
    return FC_BOND;
  }
  if (fc_starts(r, "stroke") || fc_starts(r, "lagrange-stroke")) {
    *id = fc_starts(r, "stroke") ? fc_num_after(r, "bond=") : -atoi(r + 16);
    return FC_STROKE;
  }
  if (fc_starts(r, "signal") || fc_starts(r, "state-input")) return *id = 0, FC_SIGNAL;
  if (fc_starts(r, "path")) {
    *id = atoi(r + 5), *loop = fc_num_after(r, "loop=");
    return FC_OVERLAY;
  }
  if (fc_starts(r, "loop")) return *id = 0, *loop = atoi(r + 5), FC_OVERLAY;
  /* a tag's leader line: "path-leader K" (id K), "gain-leader loop=K" (loop K) */
  if (fc_starts(r, "path-leader")) return *id = atoi(r + 12), FC_LEADER;
  if (fc_starts(r, "gain-leader")) return *id = 0, *loop = fc_num_after(r, "loop="), FC_LEADER;
  if (fc_starts(r, "frame")) return *id = 0, FC_FRAME;
  return *id = 0, FC_OTHER;
}

static int fc_text_kind(const char *r, int *id, int *loop) {
  *id = *loop = 0;
  if (fc_starts(r, "node") || fc_starts(r, "state-node") || fc_starts(r, "lagrange-label") ||
      fc_starts(r, "box-label") || fc_starts(r, "detector"))
    return FC_NODE;
  if (fc_starts(r, "number") || fc_starts(r, "variable") || fc_starts(r, "bondlabel")) {
    *id = fc_num_after(r, "bond=");
    return FC_NUMBER;
  }
  if (fc_starts(r, "path-tag")) return *id = atoi(r + 9), FC_TAG;
  if (fc_starts(r, "gain")) return *loop = fc_num_after(r, "loop="), FC_TAG;
  if (fc_starts(r, "conflict-text") || fc_starts(r, "frame-label")) return FC_TEXT;
  return FC_IGNORED; /* legend text, titles */
}

/* The item's path as segments, curves flattened into 16 chords. */
static int fc_flatten(const bg_scene *s, const bg_scene_item *it, fc_seg **out) {
  int cap = 16 * it->nop + 1, n = 0;
  fc_seg *seg = malloc((size_t)cap * sizeof *seg);
  double px = 0, py = 0, sx = 0, sy = 0;
  bg_scene_op o_;
  for (int k = 0; bg_scene_next_op(s, it, &k, &o_);) {
    const bg_scene_op *o = &o_;
    if (o->code == BG_OP_MOVE) {
      px = sx = o->x[0], py = sy = o->y[0];
    } else if (o->code == BG_OP_LINE || o->code == BG_OP_CLOSE) {
      double x = o->code == BG_OP_LINE ? o->x[0] : sx, y = o->code == BG_OP_LINE ? o->y[0] : sy;
      seg[n++] = (fc_seg){px, py, x, y};
      px = x, py = y;
    } else {
      double x0 = px, y0 = py; /* the curve's start: px, py move along the chords */
      for (int j = 1; j <= 16; j++) {
        double t = j / 16.0, u = 1 - t;
        double x = u * u * u * x0 + 3 * u * u * t * o->x[0] + 3 * u * t * t * o->x[1] + t * t * t * o->x[2];
        double y = u * u * u * y0 + 3 * u * u * t * o->y[0] + 3 * u * t * t * o->y[1] + t * t * t * o->y[2];
        seg[n++] = (fc_seg){px, py, x, y};
        px = x, py = y;
      }
    }
  }
  *out = seg;
  return n;
}

/* A line's bounding box, over its segments. */
static void fc_bound(fc_line *l) {
  l->x0 = l->y0 = 1e300, l->x1 = l->y1 = -1e300;
  for (int k = 0; k < l->nseg; k++) {
    const fc_seg *g = &l->seg[k];
    l->x0 = fmin(l->x0, fmin(g->x0, g->x1)), l->x1 = fmax(l->x1, fmax(g->x0, g->x1));
    l->y0 = fmin(l->y0, fmin(g->y0, g->y1)), l->y1 = fmax(l->y1, fmax(g->y0, g->y1));
  }
}

/* Whether lines a and b come within `by` pt of each other's bounding
 * boxes. Every check of two lines below looks no farther than FC_REACH
 * (a signal's arrowhead 4.8 pt past its line, the gap of 6 pt between a
 * bond's end and its node, signals side by side within 5 pt); the checker
 * compares every pair, and on the 2 000-bond models the pairs far apart
 * took most of the suite's figures test. */
#define FC_REACH 12.0
static int fc_near(const fc_line *a, const fc_line *b, double by) {
  return a->x0 - by <= b->x1 && b->x0 - by <= a->x1 && a->y0 - by <= b->y1 && b->y0 - by <= a->y1;
}

/* The distance from a point, and from a box, to a line's bounding box: no
 * segment of the line is nearer. */
static double fc_bbox_pt(const fc_line *l, double x, double y) {
  return hypot(fmax(fmax(l->x0 - x, x - l->x1), 0), fmax(fmax(l->y0 - y, y - l->y1), 0));
}

static double fc_bbox_box(const fc_line *l, double x0, double y0, double x1, double y1) {
  return hypot(fmax(fmax(l->x0 - x1, x0 - l->x1), 0), fmax(fmax(l->y0 - y1, y0 - l->y1), 0));
}

/* Text boxes as placement sees them: the measured width, 80 % of pango's
 * logical height (its line gap trimmed). */
static fc_box fc_text_box(const bg_scene_item *it, int kind, int id, int loop) {
  double h = 0.8 * it->th, cx = it->x + (0.5 - it->halign) * it->tw;
  double cy = it->y + (0.5 - it->valign) * it->th;
  const char *sp = strchr(it->role, ' ');
  return (fc_box){sp ? sp + 1 : "", kind, id, loop, cx - it->tw / 2, cy - h / 2, cx + it->tw / 2, cy + h / 2, 0};
}

static void fc_read(const bg_scene *s, fc_scene *f) {
  memset(f, 0, sizeof *f);
  f->line = calloc((size_t)s->nitem + 1, sizeof *f->line);
  f->box = calloc((size_t)s->nitem + 1, sizeof *f->box);
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    int id, loop;
    if (it->kind == BG_ITEM_TEXT) {
      int k = fc_text_kind(it->role, &id, &loop);
      if (k != FC_IGNORED) f->box[f->nbox++] = fc_text_box(it, k, id, loop);
      if (k == FC_NODE) f->box[f->nbox - 1].elem = fc_starts(it->role, "node");
    } else if (it->kind == BG_ITEM_STROKE) {
      int k = fc_line_kind(it->role, &id, &loop);
      if (k == FC_OTHER) continue;
      fc_line *l = &f->line[f->nline++];
      const char *sp = strchr(it->role, ' ');
      l->name = sp ? sp + 1 : "";
      l->kind = k, l->id = id, l->loop = loop, l->width = it->width;
      l->nseg = fc_flatten(s, it, &l->seg);
      fc_bound(l);
      l->barb = k == FC_BOND && l->nseg > 1;
    }
  }
}

static void fc_free(fc_scene *f) {
  for (int i = 0; i < f->nline; i++) free(f->line[i].seg);
  free(f->line), free(f->box);
}

/* ---------------------------------------------------------------- distances */
static double fc_pt_seg(double px, double py, const fc_seg *s) {
  double dx = s->x1 - s->x0, dy = s->y1 - s->y0, l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((px - s->x0) * dx + (py - s->y0) * dy) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return hypot(px - s->x0 - t * dx, py - s->y0 - t * dy);
}

static double fc_orient(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/* Whether the segments cross at a point inside both (not at an end). */
static int fc_cross(const fc_seg *a, const fc_seg *b) {
  double d1 = fc_orient(a->x0, a->y0, a->x1, a->y1, b->x0, b->y0);
  double d2 = fc_orient(a->x0, a->y0, a->x1, a->y1, b->x1, b->y1);
  double d3 = fc_orient(b->x0, b->y0, b->x1, b->y1, a->x0, a->y0);
  double d4 = fc_orient(b->x0, b->y0, b->x1, b->y1, a->x1, a->y1);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

static double fc_seg_seg(const fc_seg *a, const fc_seg *b) {
  if (fc_cross(a, b)) return 0;
  double d = fc_pt_seg(a->x0, a->y0, b);
  d = fmin(d, fc_pt_seg(a->x1, a->y1, b));
  d = fmin(d, fc_pt_seg(b->x0, b->y0, a));
  return fmin(d, fc_pt_seg(b->x1, b->y1, a));
}

static int fc_in_box(double x, double y, const fc_box *b) {
  return x > b->x0 && x < b->x1 && y > b->y0 && y < b->y1;
}

static double fc_seg_box(const fc_seg *s, const fc_box *b) {
  if (fc_in_box(s->x0, s->y0, b) || fc_in_box(s->x1, s->y1, b)) return 0;
  fc_seg e[4] = {{b->x0, b->y0, b->x1, b->y0}, {b->x1, b->y0, b->x1, b->y1},
                 {b->x1, b->y1, b->x0, b->y1}, {b->x0, b->y1, b->x0, b->y0}};
  double d = 1e300;
  for (int k = 0; k < 4; k++) d = fmin(d, fc_seg_seg(s, &e[k]));
  return d;
}

/* Nearest approach of a line (its half arrow excluded when nobarb) to a point or a box. */
static double fc_line_pt(const fc_line *l, double x, double y, int nobarb) {
  double d = 1e300;
  for (int k = 0; k < l->nseg - (nobarb && l->barb); k++) d = fmin(d, fc_pt_seg(x, y, &l->seg[k]));
  return d;
}

static double fc_line_box(const fc_line *l, const fc_box *b) {
  double d = 1e300;
  for (int k = 0; k < l->nseg; k++) d = fmin(d, fc_seg_box(&l->seg[k], b));
  return d;
}

static fc_box fc_shrink(const fc_box *b, double by) {
  return (fc_box){b->name, b->kind, b->id, b->loop, b->x0 + by, b->y0 + by, b->x1 - by, b->y1 - by, b->elem};
}

static int fc_boxes_meet(const fc_box *a, const fc_box *b) {
  return a->x0 < b->x1 && b->x0 < a->x1 && a->y0 < b->y1 && b->y0 < a->y1;
}

/* ---------------------------------------------------------------- counts */
static int fc_slanted(const fc_line *l) {
  for (int k = 0; k < l->nseg - l->barb; k++) {
    const fc_seg *s = &l->seg[k];
    if (fmin(fabs(s->x1 - s->x0), fabs(s->y1 - s->y0)) > 0.05) {
      if (fc_explain) printf("  slanted: bond %d\n", l->id);
      return 1;
    }
  }
  return 0;
}

/* A bond whose line (its half arrow not counted) is shorter than 2.5 times
 * its half arrow: the barb is then most of what one sees of the bond. */
static int fc_short(const fc_line *l) {
  if (!l->barb) return 0;
  double body = 0;
  for (int k = 0; k < l->nseg - 1; k++) body += hypot(l->seg[k].x1 - l->seg[k].x0, l->seg[k].y1 - l->seg[k].y0);
  const fc_seg *b = &l->seg[l->nseg - 1];
  int is_short = body < 2.5 * hypot(b->x1 - b->x0, b->y1 - b->y0);
  if (fc_explain && is_short) printf("  short: bond %d, %.1f pt\n", l->id, body);
  return is_short;
}

/* A stroke touches another bond when their inked widths meet. */
static int fc_touching(const fc_scene *f, const fc_line *st) {
  for (int j = 0; j < f->nline; j++) {
    const fc_line *b = &f->line[j];
    if ((b->kind != FC_BOND && b->kind != FC_STROKE) || b->id == st->id || !fc_near(st, b, (st->width + b->width) / 2))
      continue;
    for (int p = 0; p < st->nseg; p++)
      for (int q = 0; q < b->nseg; q++)
        if (fc_seg_seg(&st->seg[p], &b->seg[q]) < (st->width + b->width) / 2) {
          if (fc_explain)
            printf("  touching: the stroke of bond %d meets %s %d\n", st->id, b->kind == FC_BOND ? "bond" : "the stroke of bond", b->id);
          return 1;
        }
  }
  return 0;
}

static int fc_crosses(const fc_line *a, const fc_line *b) {
  if (!fc_near(a, b, 0)) return 0;
  for (int p = 0; p < a->nseg - a->barb; p++)
    for (int q = 0; q < b->nseg - b->barb; q++)
      if (fc_cross(&a->seg[p], &b->seg[q])) return 1;
  return 0;
}

/* A label over a line or another label (0.5 pt of slack for touching boxes). */
static int fc_label_over(const fc_scene *f, int i) {
  fc_box b = fc_shrink(&f->box[i], 0.5);
  for (int j = 0; j < f->nline; j++)
    if (f->line[j].kind != FC_STROKE && fc_bbox_box(&f->line[j], b.x0, b.y0, b.x1, b.y1) == 0 &&
        fc_line_box(&f->line[j], &b) == 0) {
      if (fc_explain)
        printf("  label over: kind %d id %d loop %d at (%.0f,%.0f) over line kind %d id %d loop %d\n", b.kind,
               b.id, b.loop, b.x0, b.y0, f->line[j].kind, f->line[j].id, f->line[j].loop);
      return 1;
    }
  for (int j = 0; j < f->nbox; j++)
    if (j != i && fc_boxes_meet(&b, &f->box[j])) {
      if (fc_explain)
        printf("  label over: kind %d id %d loop %d at (%.0f,%.0f) over box kind %d id %d\n", b.kind, b.id,
               b.loop, b.x0, b.y0, f->box[j].kind, f->box[j].id);
      return 1;
    }
  return 0;
}

/* A bond number (or variable, bond label) nearer to another bond than to its own. */
static int fc_number_astray(const fc_scene *f, const fc_box *n) {
  double cx = (n->x0 + n->x1) / 2, cy = (n->y0 + n->y1) / 2, own = 1e300, other = 1e300;
  for (int j = 0; j < f->nline; j++) {
    const fc_line *l = &f->line[j];
    if (l->kind != FC_BOND || fc_bbox_pt(l, cx, cy) >= (l->id == n->id ? own : other)) continue;
    double d = fc_line_pt(l, cx, cy, 1);
    if (l->id == n->id) own = fmin(own, d);
    else other = fmin(other, d);
  }
  if (other < own && fc_explain) printf("  astray: number of bond %d at (%.0f,%.0f): own %.1f, other %.1f\n", n->id, cx, cy, own, other);
  return other < own;
}

static int fc_own_overlay(const fc_line *l, const fc_box *t) {
  return t->loop ? l->loop == t->loop : l->id == t->id;
}

/* Whether leader line l starts on (within 0.5 pt of) an overlay line of its tag. */
static int fc_leader_on_own(const fc_scene *f, const fc_line *l) {
  for (int j = 0; j < f->nline; j++)
    if (f->line[j].kind == FC_OVERLAY && fc_own_overlay(&f->line[j], &(fc_box){"", FC_TAG, l->id, l->loop, 0, 0, 0, 0, 0}) &&
        fc_line_pt(&f->line[j], l->seg[0].x0, l->seg[0].y0, 0) <= 0.5)
      return 1;
  return 0;
}

/* A tag or gain whose nearest overlay is not its own, or more than 12 pt
 * from its own; its own line is its polyline, or a leader line of its own
 * that starts on it (a leader elsewhere counts for nothing). */
static int fc_tag_far(const fc_scene *f, const fc_box *t) {
  double own = 1e300, other = 1e300;
  int near = -1;
  for (int j = 0; j < f->nline; j++) {
    const fc_line *l = &f->line[j];
    if (fc_bbox_box(l, t->x0, t->y0, t->x1, t->y1) >= (fc_own_overlay(l, t) ? own : other)) continue;
    if (l->kind == FC_LEADER && fc_own_overlay(l, t) && l->nseg && fc_leader_on_own(f, l))
      own = fmin(own, fc_line_box(l, t));
    if (l->kind != FC_OVERLAY) continue;
    double d = fc_line_box(l, t);
    if (fc_own_overlay(l, t)) own = fmin(own, d);
    else if (d < other) other = d, near = j;
  }
  if (fc_explain && (other < own || own > 12))
    printf("  tag far: %s %d at (%.0f,%.0f): own %.1f, other %.1f (path %d loop %d)\n", t->loop ? "loop" : "path",
           t->loop ? t->loop : t->id, t->x0, t->y0, own, other, near >= 0 ? f->line[near].id : 0,
           near >= 0 ? f->line[near].loop : 0);
  return other < own || own > 12;
}

/* A tag or gain with another text (a number, a label, a tag) beside it,
 * its box within 2 pt to the left or right and overlapping in height, where
 * the two would read as one ("L2: G = n 1"); texts over it count as over. */
static int fc_crowded(const fc_scene *f, int i) {
  const fc_box *t = &f->box[i];
  fc_box g = {t->name, t->kind, t->id, t->loop, t->x0 - 2, t->y0, t->x1 + 2, t->y1, 0};
  for (int j = 0; j < f->nbox; j++)
    if (j != i && fc_boxes_meet(&g, &f->box[j]) && !fc_boxes_meet(t, &f->box[j])) {
      if (fc_explain)
        printf("  crowded: %s %d at (%.0f,%.0f) beside box kind %d id %d\n",
               t->kind == FC_NUMBER ? "number" : t->loop ? "loop" : "path", t->loop ? t->loop : t->id, t->x0, t->y0,
               f->box[j].kind, f->box[j].id);
      return 1;
    }
  return 0;
}

/* Lines of `kind` × element labels they run through (the label's ink box,
 * 1 pt inside, so a line ending on its own element's box does not count). */
static int fc_through(const fc_scene *f, int kind) {
  int n = 0;
  for (int j = 0; j < f->nline; j++) {
    if (f->line[j].kind != kind) continue;
    for (int i = 0; i < f->nbox; i++) {
      if (f->box[i].kind != FC_NODE) continue;
      fc_box b = fc_shrink(&f->box[i], 1);
      if (b.x0 < b.x1 && b.y0 < b.y1 && fc_bbox_box(&f->line[j], b.x0, b.y0, b.x1, b.y1) == 0 &&
          fc_line_box(&f->line[j], &b) == 0) {
        n++;
        if (fc_explain)
          printf("  through: line kind %d id %d loop %d through the label at (%.0f,%.0f)\n", f->line[j].kind,
                 f->line[j].id, f->line[j].loop, b.x0, b.y0);
      }
    }
  }
  return n;
}

/* ---------------------------------------------------------------- issue 31 */
static double fc_seg_len(const fc_seg *a) { return hypot(a->x1 - a->x0, a->y1 - a->y0); }

/* The segments of a line that are drawn as its body (a bond's half arrow left out). */
static int fc_body(const fc_line *l) { return l->nseg - l->barb; }

/* Signal l × bond b: whether they cross, (*oblique) whether some crossing
 * is more than 5 degrees off a right angle, and (*at_end) whether some is
 * at one of b's ends, among its half arrow (7 line widths back) or causal
 * stroke: nearer the end than 7 line widths and 3 pt, or, on a short bond,
 * than 0.35 of its length (its middle is the best a crossing can do), or
 * past it, within FC_END_GAP, between the bond and its node (*at_end only). */
#define FC_END_GAP 6.0 /* pt past a bond's end: the gap to its node */
/* Whether one of the first nseg segments of line l crosses the stretch
 * past an end of bond b, from 0.5 to FC_END_GAP pt on towards its node. */
static int fc_end_gap(const fc_line *l, int nseg, const fc_line *b) {
  for (int e = 0; e < 2 && fc_body(b) > 0; e++) {
    const fc_seg *v = &b->seg[e ? fc_body(b) - 1 : 0];
    double len = fc_seg_len(v), ex = e ? v->x1 : v->x0, ey = e ? v->y1 : v->y0;
    if (len <= 0) continue;
    double dx = (e ? v->x1 - v->x0 : v->x0 - v->x1) / len, dy = (e ? v->y1 - v->y0 : v->y0 - v->y1) / len;
    fc_seg gap = {ex + 0.5 * dx, ey + 0.5 * dy, ex + FC_END_GAP * dx, ey + FC_END_GAP * dy};
    for (int p = 0; p < nseg; p++)
      if (fc_cross(&l->seg[p], &gap)) return 1;
  }
  return 0;
}
static int fc_sig_cross(const fc_line *l, const fc_line *b, int *oblique, int *at_end) {
  int n = 0;
  double total = 0;
  for (int q = 0; q < fc_body(b); q++) total += fc_seg_len(&b->seg[q]);
  double zone = fmin(7 * b->width + 3, 0.35 * total);
  for (int p = 0; p < l->nseg; p++) {
    double before = 0; /* b's length before segment q */
    for (int q = 0; q < fc_body(b); before += fc_seg_len(&b->seg[q]), q++)
      if (fc_cross(&l->seg[p], &b->seg[q])) {
        const fc_seg *u = &l->seg[p], *v = &b->seg[q];
        double ux = u->x1 - u->x0, uy = u->y1 - u->y0, vx = v->x1 - v->x0, vy = v->y1 - v->y0;
        double c = (ux * vx + uy * vy) / (fc_seg_len(u) * fc_seg_len(v) + 1e-300);
        if (fabs(c) > sin(5 * 3.14159265358979 / 180)) *oblique = 1;
        double den = vx * uy - vy * ux, t = ((u->x0 - v->x0) * uy - (u->y0 - v->y0) * ux) / den;
        double along = before + t * fc_seg_len(v);
        if (fmin(along, total - along) < zone) {
          *at_end = 1;
          if (fc_explain)
            printf("  signal %s crosses bond %d %.1f pt from its end\n", l->name, b->id, fmin(along, total - along));
        }
        n = 1;
      }
  }
  /* past an end, between the bond and its node: read as crossing there */
  if (fc_end_gap(l, l->nseg, b)) {
    *at_end = 1;
    if (fc_explain) printf("  signal %s passes between bond %d's end and its node\n", l->name, b->id);
  }
  return n;
}

/* Path/loop line l × bond b: whether l crosses b more than 5 degrees off a
 * right angle away from b's ends (more than 8 pt from them: a path turns
 * round a bond's end, and a layer changes sides at a junction, there): a
 * loop closed by a modulation jumping across the figure. */
static int fc_layer_oblique(const fc_line *l, const fc_line *b) {
  int nb = fc_body(b);
  if (nb < 1) return 0;
  double ex[2] = {b->seg[0].x0, b->seg[nb - 1].x1}, ey[2] = {b->seg[0].y0, b->seg[nb - 1].y1};
  for (int p = 0; p < l->nseg; p++)
    for (int q = 0; q < nb; q++) {
      const fc_seg *u = &l->seg[p], *v = &b->seg[q];
      if (!fc_cross(u, v)) continue;
      double ux = u->x1 - u->x0, uy = u->y1 - u->y0, vx = v->x1 - v->x0, vy = v->y1 - v->y0;
      double den = ux * vy - uy * vx, t = ((v->x0 - u->x0) * vy - (v->y0 - u->y0) * vx) / den;
      double x = u->x0 + t * ux, y = u->y0 + t * uy;
      if (hypot(x - ex[0], y - ey[0]) < 8 || hypot(x - ex[1], y - ey[1]) < 8) continue;
      if (fabs(ux * vx + uy * vy) / (fc_seg_len(u) * fc_seg_len(v) + 1e-300) > sin(5 * 3.14159265358979 / 180)) return 1;
    }
  return 0;
}

/* Whether segments a and b run along each other: parallel within 1
 * degree, less than `near` pt apart, sharing more than `share` pt. */
static int fc_seg_beside(const fc_seg *a, const fc_seg *b, double near, double share) {
  double la = fc_seg_len(a), lb = fc_seg_len(b);
  if (la < share || lb < share) return 0;
  double ux = (a->x1 - a->x0) / la, uy = (a->y1 - a->y0) / la;
  double vx = (b->x1 - b->x0) / lb, vy = (b->y1 - b->y0) / lb;
  if (fabs(ux * vy - uy * vx) > 0.0175) return 0;
  double d0 = fabs((b->x0 - a->x0) * uy - (b->y0 - a->y0) * ux);
  double d1 = fabs((b->x1 - a->x0) * uy - (b->y1 - a->y0) * ux);
  if (fmax(d0, d1) >= near) return 0;
  double t0 = (b->x0 - a->x0) * ux + (b->y0 - a->y0) * uy, t1 = (b->x1 - a->x0) * ux + (b->y1 - a->y0) * uy;
  double lo = fmax(0, fmin(t0, t1)), hi = fmin(la, fmax(t0, t1));
  return hi - lo > share;
}

/* Whether line l (a bond or a signal) runs along frame f's border: within
 * 2 pt for more than 8 pt, where it reads as part of the frame. */
static int fc_on_frame(const fc_line *l, const fc_line *f) {
  for (int p = 0; p < fc_body(l); p++)
    for (int q = 0; q < f->nseg; q++)
      if (fc_seg_beside(&l->seg[p], &f->seg[q], 2, 8)) return 1;
  return 0;
}

/* Two segments on one line (parallel within 1 degree, < 1 pt apart) that
 * share more than 2 pt: drawn on top of each other. */
static int fc_seg_overlap(const fc_seg *a, const fc_seg *b) { return fc_seg_beside(a, b, 1, 2); }

static int fc_lines_overlap(const fc_line *a, const fc_line *b) {
  for (int p = 0; p < fc_body(a); p++)
    for (int q = 0; q < fc_body(b); q++)
      if (fc_seg_overlap(&a->seg[p], &b->seg[q])) return 1;
  return 0;
}

/* Bond a's ends (the tail, the tip of its half arrow) that lie on bond b's
 * line (within 1 pt) more than 3 pt from b's ends: a T-junction that is
 * not there. */
static int fc_false_tee(const fc_line *a, const fc_line *b) {
  if (fc_body(a) < 1 || fc_body(b) < 1) return 0;
  double end[2][2] = {{a->seg[0].x0, a->seg[0].y0}, {a->seg[fc_body(a) - 1].x1, a->seg[fc_body(a) - 1].y1}};
  const fc_seg *b0 = &b->seg[0], *b1 = &b->seg[fc_body(b) - 1];
  for (int k = 0; k < 2; k++) {
    double x = end[k][0], y = end[k][1];
    if (hypot(x - b0->x0, y - b0->y0) <= 3 || hypot(x - b1->x1, y - b1->y1) <= 3) continue;
    for (int q = 0; q < fc_body(b); q++)
      if (fc_pt_seg(x, y, &b->seg[q]) < 1) return 1;
  }
  return 0;
}

static int fc_tiny(const fc_line *l) {
  if (!l->barb) return 0;
  double body = 0;
  for (int k = 0; k < fc_body(l); k++) body += fc_seg_len(&l->seg[k]);
  return body < fc_seg_len(&l->seg[l->nseg - 1]);
}

/* A frame's rectangle from its segments. */
static fc_box fc_frame_box(const fc_line *l) {
  fc_box r = {l->name, FC_TEXT, 0, 0, 1e300, 1e300, -1e300, -1e300, 0};
  for (int k = 0; k < l->nseg; k++) {
    r.x0 = fmin(r.x0, fmin(l->seg[k].x0, l->seg[k].x1)), r.x1 = fmax(r.x1, fmax(l->seg[k].x0, l->seg[k].x1));
    r.y0 = fmin(r.y0, fmin(l->seg[k].y0, l->seg[k].y1)), r.y1 = fmax(r.y1, fmax(l->seg[k].y0, l->seg[k].y1));
  }
  return r;
}

/* Two frames cross when neither holds the other and their areas meet. */
static int fc_frames_cross(const fc_box *a, const fc_box *b) {
  int a_in_b = a->x0 >= b->x0 && a->x1 <= b->x1 && a->y0 >= b->y0 && a->y1 <= b->y1;
  int b_in_a = b->x0 >= a->x0 && b->x1 <= a->x1 && b->y0 >= a->y0 && b->y1 <= a->y1;
  return !a_in_b && !b_in_a && fc_boxes_meet(a, b);
}

/* Whether element `name` belongs to instance `inst` (its name starts "inst."). */
static int fc_member(const char *name, const char *inst) {
  size_t n = strlen(inst);
  return !strncmp(name, inst, n) && name[n] == '.';
}

/* The smallest size of any part of a text item: its size times the nested
 * span sizes in per cent ("<span size=\"70%\">"). */
static double fc_smallest_size(const bg_scene_item *it) {
  double stack[16], cur = it->size, least = it->size;
  int sp = 0;
  for (const char *p = it->text; p && *p; p++) {
    if (!strncmp(p, "<span", 5)) {
      const char *e = strchr(p, '>'), *z = strstr(p, "size=\"");
      double f = 1;
      if (z && e && z < e && strchr(z + 6, '%') && strchr(z + 6, '%') < e) f = atof(z + 6) / 100;
      if (sp < 16) stack[sp++] = cur;
      cur *= f;
      if (cur < least) least = cur;
    } else if (!strncmp(p, "</span>", 7) && sp > 0) {
      cur = stack[--sp];
    }
  }
  return least;
}

/* Pairs of element labels placed in a different order (left/right or
 * above/below) in two drawings of the same model: the arrangement a style
 * changed. Labels are matched by their role. A pair counts when it is
 * reversed (more than 1 pt apart each way), or level (within 1 pt) in one
 * drawing and more than 4 pt apart in the other (moved into or out of the
 * other's row or column): a stretch of the whole drawing, which keeps every
 * order, can take two labels 0.9 pt apart to 1.4 pt, and that is no change
 * of arrangement. */
static inline int fc_order_changed(double d, double D) {
  int s = d > 1 ? 1 : d < -1 ? -1 : 0, S = D > 1 ? 1 : D < -1 ? -1 : 0;
  if (s * S < 0) return 1;
  return (s == 0 && fabs(D) > 4) || (S == 0 && fabs(d) > 4);
}
static inline int fc_arrangement(const bg_scene *a, const bg_scene *b) {
  int n = 0, *match = calloc((size_t)a->nitem + 1, sizeof *match);
  for (int i = 0; i < a->nitem; i++) {
    match[i] = -1;
    if (a->item[i].kind != BG_ITEM_TEXT || !fc_starts(a->item[i].role, "node")) continue;
    for (int j = 0; j < b->nitem && match[i] < 0; j++)
      if (b->item[j].kind == BG_ITEM_TEXT && !strcmp(a->item[i].role, b->item[j].role)) match[i] = j;
  }
  for (int i = 0; i < a->nitem; i++)
    for (int k = i + 1; match[i] >= 0 && k < a->nitem; k++) {
      if (match[k] < 0) continue;
      const bg_scene_item *p = &a->item[i], *q = &a->item[k], *P = &b->item[match[i]], *Q = &b->item[match[k]];
      double dx = q->x - p->x, dy = q->y - p->y, DX = Q->x - P->x, DY = Q->y - P->y;
      if (fc_order_changed(dx, DX) || fc_order_changed(dy, DY)) {
        n++;
        if (fc_explain) printf("  arrangement: %s and %s\n", p->role, q->role);
      }
    }
  free(match);
  return n;
}

/* Issue 31, signals branching: a signal line that starts on another
 * signal's line, more than 0.5 pt from that line's start, is a signal
 * taken off the other (as block diagrams draw one signal splitting); it
 * needs a dot there (a "signal-branch" or "state-input-branch" fill
 * centred within 1 pt), else it reads as a line ending on a line. */
static int fc_bare_branches(const bg_scene *s, const fc_scene *f) {
  int ndot = 0, bare = 0;
  double(*dot)[2] = malloc(((size_t)s->nitem + 1) * sizeof *dot);
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    if (it->kind != BG_ITEM_FILL || !(fc_starts(it->role, "signal-branch") || fc_starts(it->role, "state-input-branch")))
      continue;
    fc_seg *seg;
    int n = fc_flatten(s, it, &seg);
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (int k = 0; k < n; k++)
      x0 = fmin(x0, fmin(seg[k].x0, seg[k].x1)), x1 = fmax(x1, fmax(seg[k].x0, seg[k].x1)),
      y0 = fmin(y0, fmin(seg[k].y0, seg[k].y1)), y1 = fmax(y1, fmax(seg[k].y0, seg[k].y1));
    free(seg);
    if (n) dot[ndot][0] = (x0 + x1) / 2, dot[ndot++][1] = (y0 + y1) / 2;
  }
  for (int j = 0; j < f->nline; j++) {
    const fc_line *l = &f->line[j];
    if (l->kind != FC_SIGNAL || l->nseg < 1) continue;
    double x = l->seg[0].x0, y = l->seg[0].y0;
    int on = 0;
    for (int k = 0; k < f->nline && !on; k++) {
      const fc_line *m = &f->line[k];
      if (k == j || m->kind != FC_SIGNAL || m->nseg < 1 || hypot(x - m->seg[0].x0, y - m->seg[0].y0) <= 0.5) continue;
      for (int q = 0; q < m->nseg && !on; q++) on = fc_pt_seg(x, y, &m->seg[q]) < 0.5;
    }
    int marked = 0;
    for (int d = 0; on && d < ndot && !marked; d++) marked = hypot(x - dot[d][0], y - dot[d][1]) <= 1;
    if (on && !marked) {
      bare++;
      if (fc_explain) printf("  signal %s starts on another signal's line without a branch dot\n", l->name);
    }
  }
  free(dot);
  return bare;
}

/* Whether signal line l's arrow points past the label it ends at. The line
 * stops 4.8 pt short of the arrow's tip, and the tip 4.5 pt short of the
 * text (the router's box: the label and its 3 pt pad, less 1.5); the ray on
 * from the line's end must meet the text's box (0.5 pt more each way) within
 * 6 pt of the tip, else the arrow reads as pointing beside the label (a
 * route ending at a corner of the padded box, the text 3 pt inside it). The
 * label is the node label nearest the tip. */
static int fc_tip_beside(const fc_scene *f, const fc_line *l) {
  if (l->kind != FC_SIGNAL || l->nseg < 1) return 0;
  const fc_seg *e = &l->seg[l->nseg - 1];
  double len = fc_seg_len(e);
  if (len < 1e-9) return 0;
  double ux = (e->x1 - e->x0) / len, uy = (e->y1 - e->y0) / len;
  double tx = e->x1 + 4.8 * ux, ty = e->y1 + 4.8 * uy;
  const fc_box *near = NULL;
  double best = 1e300;
  for (int i = 0; i < f->nbox; i++) {
    const fc_box *b = &f->box[i];
    if (b->kind != FC_NODE) continue;
    double dx = fmax(fmax(b->x0 - tx, tx - b->x1), 0), dy = fmax(fmax(b->y0 - ty, ty - b->y1), 0);
    if (hypot(dx, dy) < best) best = hypot(dx, dy), near = b;
  }
  if (!near || best > 12) return 0; /* not at a label: a bond-variable's or a detector's end */
  fc_box g = {near->name, near->kind, 0, 0, near->x0 - 0.5, near->y0 - 0.5, near->x1 + 0.5, near->y1 + 0.5, 0};
  fc_seg ray = {e->x1, e->y1, tx + 6 * ux, ty + 6 * uy};
  if (fc_seg_box(&ray, &g) < 1e-9) return 0;
  if (fc_explain) printf("  signal %s: arrow at (%.1f, %.1f) points beside %s\n", l->name, tx, ty, near->name);
  return 1;
}

/* The small steps of signal line l: three legs in a row, the middle one
 * shorter than 8 pt across the other two, which go on the same way (an S
 * or Z the line makes to shift sideways by a few pt, as two boxes almost
 * in line draw when the ports are not); the line's last leg ends 4.8 pt
 * short of the arrow's tip, so it counts whole. */
static int fc_steps(const fc_line *l) {
  if (l->kind != FC_SIGNAL) return 0;
  int n = 0;
  for (int k = 0; k + 2 < l->nseg; k++) {
    const fc_seg *a = &l->seg[k], *b = &l->seg[k + 1], *c = &l->seg[k + 2];
    double ax = a->x1 - a->x0, ay = a->y1 - a->y0, cx = c->x1 - c->x0, cy = c->y1 - c->y0;
    double la = hypot(ax, ay), lb = fc_seg_len(b), lc = hypot(cx, cy);
    if (la < 1e-9 || lc < 1e-9 || lb >= 8 || lb < 1e-9) continue;
    if ((ax * cx + ay * cy) / (la * lc) < 0.999) continue; /* not going on the same way */
    if (fabs(ax * (b->y1 - b->y0) - ay * (b->x1 - b->x0)) / (la * lb) < 0.9) continue; /* not across */
    n++;
    if (fc_explain) printf("  signal %s: a %.1f pt step at (%.1f, %.1f)\n", l->name, lb, b->x0, b->y0);
  }
  return n;
}

/* Whether signals l and m, from different sources (the names' parts
 * before "->"; one source's lines branch off each other), run side by side
 * within 5 pt for more than 20 pt: two lines a few points apart read as
 * one double line. */
static int fc_other_sources(const fc_line *l, const fc_line *m) {
  const char *a = l->name ? strstr(l->name, "->") : NULL, *b = m->name ? strstr(m->name, "->") : NULL;
  return a && b && !(a - l->name == b - m->name && !strncmp(l->name, m->name, (size_t)(a - l->name)));
}

static int fc_sig_beside(const fc_line *l, const fc_line *m) {
  if (!fc_other_sources(l, m)) return 0;
  for (int p = 0; p < fc_body(l); p++)
    for (int q = 0; q < fc_body(m); q++)
      if (fc_seg_beside(&l->seg[p], &m->seg[q], 5, 20)) {
        if (fc_explain)
          printf("  signals %s and %s side by side at (%.0f, %.0f)-(%.0f, %.0f)\n", l->name, m->name, l->seg[p].x0,
                 l->seg[p].y0, l->seg[p].x1, l->seg[p].y1);
        return 1;
      }
  return 0;
}

/* Whether a corner or an end of signal l lies on signal m (within 1 pt),
 * or m crosses l's arrowhead (the line stops 4.8 pt short of the tip, the
 * head is 6 pt long), m from another source: two signals meeting end to
 * end, or at a corner, read as one line that turns or branches (which
 * source feeds which arrow cannot be told), an end on the other's line as
 * a T, a line through an arrowhead as ending there. */
/* Signal l's arrowhead as a segment along its axis: 1 and *head, else 0. */
static int fc_head(const fc_line *l, fc_seg *head) {
  const fc_seg *e = l->nseg > 0 ? &l->seg[l->nseg - 1] : NULL;
  double len = e ? fc_seg_len(e) : 0;
  if (len <= 0) return 0;
  double ux = (e->x1 - e->x0) / len, uy = (e->y1 - e->y0) / len;
  *head = (fc_seg){e->x1 - 1.2 * ux, e->y1 - 1.2 * uy, e->x1 + 4.8 * ux, e->y1 + 4.8 * uy};
  return 1;
}

/* Whether segment s passes within 1 pt of a corner or an end of signal m,
 * or crosses its arrowhead. */
static int fc_seg_touches(const fc_seg *s, const fc_line *m) {
  for (int p = 0; p <= m->nseg && m->nseg > 0; p++) {
    double x = p < m->nseg ? m->seg[p].x0 : m->seg[p - 1].x1, y = p < m->nseg ? m->seg[p].y0 : m->seg[p - 1].y1;
    if (fc_pt_seg(x, y, s) < 1) return 1;
  }
  fc_seg head;
  return fc_head(m, &head) && fc_cross(s, &head);
}

static int fc_sig_touch_one(const fc_line *l, const fc_line *m) {
  for (int q = 0; q < m->nseg; q++)
    if (fc_seg_touches(&m->seg[q], l)) {
      if (fc_explain)
        printf("  signal %s touches signal %s (a corner, an end or the arrowhead) at (%.1f, %.1f)-(%.1f, %.1f)\n",
               m->name, l->name, m->seg[q].x0, m->seg[q].y0, m->seg[q].x1, m->seg[q].y1);
      return 1;
    }
  return 0;
}

static int fc_sig_touch(const fc_line *l, const fc_line *m) {
  return fc_other_sources(l, m) && (fc_sig_touch_one(l, m) || fc_sig_touch_one(m, l));
}

/* Whether signal l runs along path or loop line o: within 3 pt for more
 * than 8 pt, where it reads as part of the path. */
static int fc_beside_layer(const fc_line *l, const fc_line *o) {
  for (int p = 0; p < l->nseg; p++)
    for (int q = 0; q < o->nseg; q++)
      if (fc_seg_beside(&l->seg[p], &o->seg[q], 3, 8)) {
        if (fc_explain) printf("  (signal segment %.1f,%.1f - %.1f,%.1f)\n", l->seg[p].x0, l->seg[p].y0, l->seg[p].x1, l->seg[p].y1);
        return 1;
      }
  return 0;
}

static void fc_count_31(const bg_scene *s, const fc_scene *f, fc_stats *st) {
  st->bare_branches += fc_bare_branches(s, f);
  for (int j = 0; j < f->nline; j++) {
    const fc_line *l = &f->line[j];
    if (l->kind == FC_BOND) st->tiny_bonds += fc_tiny(l);
    st->tips_beside += fc_tip_beside(f, l);
    st->steps += fc_steps(l);
    for (int k = 0; k < f->nline; k++) {
      const fc_line *m = &f->line[k];
      if (!fc_near(l, m, FC_REACH)) continue; /* every check below looks nearer */
      if (l->kind == FC_SIGNAL && m->kind == FC_BOND) {
        int ob = 0, at_end = 0;
        if (fc_sig_cross(l, m, &ob, &at_end)) {
          st->sig_cross++, st->sig_oblique += ob;
          if (fc_explain) printf("  signal %s crosses bond %d%s\n", l->name, m->id, ob ? " obliquely" : "");
        }
        st->sig_at_ends += at_end;
        if (fc_explain && at_end) printf("  signal %s crosses bond %d at its end\n", l->name, m->id);
      }
      if (l->kind == FC_OVERLAY && m->kind == FC_BOND) { /* a modulation's jump straight across */
        if (fc_layer_oblique(l, m)) {
          st->layer_oblique++;
          if (fc_explain) printf("  %s %d crosses bond %d obliquely\n", l->id ? "path" : "loop", l->id ? l->id : l->loop, m->id);
        }
      }
      if (l->kind == FC_BOND && m->kind == FC_BOND && k != j && fc_false_tee(l, m)) {
        st->false_tees++;
        if (fc_explain) printf("  false T: bond %d ends on bond %d\n", l->id, m->id);
      }
      if (l->kind == FC_BOND && m->kind == FC_BOND && k != j && fc_end_gap(l, fc_body(l), m)) {
        st->bond_at_ends++;
        if (fc_explain) printf("  bond %d passes between bond %d's end and its node\n", l->id, m->id);
      }
      if (k > j && l->kind == FC_SIGNAL && m->kind == FC_SIGNAL && fc_sig_beside(l, m)) st->sig_beside++;
      if (k > j && l->kind == FC_SIGNAL && m->kind == FC_SIGNAL && fc_sig_touch(l, m)) st->sig_touch++;
      if (k > j && (l->kind == FC_BOND || l->kind == FC_SIGNAL) && (m->kind == FC_BOND || m->kind == FC_SIGNAL) &&
          fc_lines_overlap(l, m)) {
        st->overlaps++, st->bond_overlaps += l->kind == FC_BOND || m->kind == FC_BOND;
        if (fc_explain)
          printf("  overlap: line kind %d id %d (%s) and kind %d id %d (%s)\n", l->kind, l->id, l->name, m->kind, m->id,
                 m->name);
      }
    }
    for (int k = 0; l->kind == FC_SIGNAL && k < f->nline; k++)
      if (f->line[k].kind == FC_OVERLAY && fc_near(l, &f->line[k], FC_REACH) && fc_beside_layer(l, &f->line[k])) {
        st->sig_on_layers++;
        if (fc_explain) printf("  signal %s beside %s\n", l->name, f->line[k].name ? f->line[k].name : "a layer line");
      }
    if (l->kind != FC_FRAME) continue;
    st->frames++;
    for (int k = 0; k < f->nline; k++)
      if ((f->line[k].kind == FC_BOND || f->line[k].kind == FC_SIGNAL) && fc_near(&f->line[k], l, FC_REACH) &&
          fc_on_frame(&f->line[k], l)) {
        st->on_frames++;
        if (fc_explain) printf("  %s %d (%s) along the frame of %s\n", f->line[k].kind == FC_BOND ? "bond" : "signal",
                               f->line[k].id, f->line[k].name, l->name);
      }
    fc_box r = fc_frame_box(l);
    for (int k = j + 1; k < f->nline; k++)
      if (f->line[k].kind == FC_FRAME) {
        fc_box q = fc_frame_box(&f->line[k]);
        if (fc_frames_cross(&r, &q)) {
          st->frame_cross++;
          if (fc_explain) printf("  frames cross: %s and %s\n", l->name, f->line[k].name);
        }
      }
    for (int i = 0; i < f->nbox; i++) {
      const fc_box *b = &f->box[i];
      double cx = (b->x0 + b->x1) / 2, cy = (b->y0 + b->y1) / 2;
      if (!b->elem || !fc_in_box(cx, cy, &r) ||
          fc_member(b->name, l->name))
        continue;
      st->foreign++;
      if (fc_explain) printf("  foreign: %s inside the frame of %s\n", b->name, l->name);
    }
  }
  for (int i = 0; i < f->nbox; i++) /* element labels on one another: 0.5 pt each way */
    for (int k = i + 1; f->box[i].elem && k < f->nbox; k++) {
      const fc_box *a = &f->box[i], *b = &f->box[k];
      if (!b->elem || fmin(a->x1, b->x1) - fmax(a->x0, b->x0) <= 0.5 || fmin(a->y1, b->y1) - fmax(a->y0, b->y0) <= 0.5)
        continue;
      st->nodes_overlap++;
      if (fc_explain) printf("  nodes overlap: %s and %s\n", a->name, b->name);
    }
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    if (it->kind != BG_ITEM_TEXT) continue;
    st->texts++;
    if (fc_smallest_size(it) < 6 - 1e-9) {
      st->small_text++;
      if (fc_explain) printf("  small text: %s '%s' %.2f pt\n", it->role, it->text, fc_smallest_size(it));
    }
  }
}

/* Whether causal stroke l's bar (its inked width) comes within half a
 * point of an element label's text: a bond at 45 degrees reaching a label
 * wider than tall a little way in from its corner put the bar's half
 * towards the corner over the first glyph (issue 31). */
static int fc_stroke_text(const fc_scene *f, const fc_line *l) {
  double reach = l->width / 2 + 0.5;
  for (int i = 0; i < f->nbox; i++) {
    const fc_box *b = &f->box[i];
    if (b->kind != FC_NODE || fc_bbox_box(l, b->x0, b->y0, b->x1, b->y1) >= reach || fc_line_box(l, b) >= reach)
      continue;
    if (fc_explain) printf("  stroke on text: bond %d's stroke %.2f pt from %s\n", l->id, fc_line_box(l, b), b->name);
    return 1;
  }
  return 0;
}

static inline void fc_count(const bg_scene *s, fc_stats *st) {
  fc_scene f;
  fc_read(s, &f);
  for (int j = 0; j < f.nline; j++) {
    const fc_line *l = &f.line[j];
    if (l->kind == FC_BOND) {
      st->bonds++, st->slanted += fc_slanted(l), st->short_bonds += fc_short(l);
      for (int k = j + 1; k < f.nline; k++)
        if (f.line[k].kind == FC_BOND && fc_crosses(l, &f.line[k])) {
          st->crossings++;
          if (fc_explain) printf("  crossing: bonds %d and %d\n", l->id, f.line[k].id);
        }
    }
    if (l->kind == FC_STROKE) st->strokes++, st->touching += fc_touching(&f, l), st->stroke_text += fc_stroke_text(&f, l);
  }
  for (int i = 0; i < f.nbox; i++) {
    const fc_box *b = &f.box[i];
    if (b->kind == FC_NODE) continue;
    st->labels++, st->over += fc_label_over(&f, i);
    if (b->kind == FC_NUMBER) st->numbers++, st->astray += fc_number_astray(&f, b), st->crowded += fc_crowded(&f, i);
    if (b->kind == FC_TAG) st->tags++, st->tags_far += fc_tag_far(&f, b), st->crowded += fc_crowded(&f, i);
  }
  st->through += fc_through(&f, FC_OVERLAY) + fc_through(&f, FC_LEADER);
  int sig_through = fc_through(&f, FC_SIGNAL);
  st->sig_through += sig_through;
  st->lines_through += fc_through(&f, FC_BOND) + sig_through;
  fc_count_31(s, &f, st);
  fc_free(&f);
}

/* Whether bond line l turns a corner (its half arrow not counted). */
static int fc_has_corner(const fc_line *l) {
  for (int k = 1; k < l->nseg - l->barb; k++) {
    const fc_seg *a = &l->seg[k - 1], *b = &l->seg[k];
    double cr = (a->x1 - a->x0) * (b->y1 - b->y0) - (a->y1 - a->y0) * (b->x1 - b->x0);
    double la = hypot(a->x1 - a->x0, a->y1 - a->y0), lb = hypot(b->x1 - b->x0, b->y1 - b->y0);
    if (la > 0.5 && lb > 0.5 && fabs(cr) > 0.02 * la * lb) return 1;
  }
  return 0;
}

/* Issue 31, the spine: the longest source-to-load power chain is the main
 * row, and a side branch must not bend it onto an elbow. In each connected
 * part with a source (the first in model order, the one the layout ranks
 * from) the chain is walked from the source: breadth-first distances from
 * it, and from each element the next one a step further whose reach (the
 * farthest distance onward, a step further each time) is the largest; of
 * several such, one whose bond is drawn without a corner. Counts the
 * chain's bonds drawn with a corner (a fold between bands is a straight
 * run down, not counted). */
static inline int fc_spine_bent(const bg_model *m, const bg_scene *s) {
  fc_scene f;
  fc_read(s, &f);
  int n = m->nelem, nb = m->nbond, bent = 0;
  int *dist = malloc(((size_t)n + 1) * sizeof(int)), *reach = malloc(((size_t)n + 1) * sizeof(int));
  int *queue = malloc(((size_t)n + 1) * sizeof(int)), *corner = calloc((size_t)nb + 1, sizeof(int));
  for (int j = 0; j < f.nline; j++)
    if (f.line[j].kind == FC_BOND && f.line[j].id > 0)
      for (int b = 0; b < nb; b++)
        if (m->bond_num[b] == f.line[j].id) corner[b] = fc_has_corner(&f.line[j]);
  for (int v = 0; v < n; v++) dist[v] = -1;
  for (int src = 0; src < n; src++) {
    if (!bg_elem_is_source(m->elem_kind[src]) || dist[src] >= 0) continue;
    int qh = 0, qt = 0;
    dist[src] = 0, queue[qt++] = src;
    while (qh < qt) {
      int v = queue[qh++];
      for (int k = 0; k < m->elem_nbond[v]; k++) {
        int b = m->elem_bonds[m->elem_bondadr[v] + k], u = m->bond_tail[b] == v ? m->bond_head[b] : m->bond_tail[b];
        if (dist[u] < 0) dist[u] = dist[v] + 1, queue[qt++] = u;
      }
    }
    for (int i = qt - 1; i >= 0; i--) { /* farthest first: reach of every element of the part */
      int v = queue[i];
      reach[v] = dist[v];
      for (int k = 0; k < m->elem_nbond[v]; k++) {
        int b = m->elem_bonds[m->elem_bondadr[v] + k], u = m->bond_tail[b] == v ? m->bond_head[b] : m->bond_tail[b];
        if (dist[u] == dist[v] + 1 && reach[u] > reach[v]) reach[v] = reach[u];
      }
    }
    for (int v = src;;) {
      int next = -1, next_bent = 1;
      for (int k = 0; k < m->elem_nbond[v]; k++) {
        int b = m->elem_bonds[m->elem_bondadr[v] + k], u = m->bond_tail[b] == v ? m->bond_head[b] : m->bond_tail[b];
        if (dist[u] != dist[v] + 1 || reach[u] != reach[src]) continue;
        if (next < 0 || (next_bent && !corner[b])) next = u, next_bent = corner[b];
      }
      if (next < 0) break;
      if (next_bent && fc_explain) printf("  spine: the bond %s -> %s turns a corner\n", m->elem_name[v], m->elem_name[next]);
      bent += next_bent, v = next;
    }
  }
  free(dist), free(reach), free(queue), free(corner);
  fc_free(&f);
  return bent;
}

/* The element a signal's end names ("signal FROM->TO", side 0 FROM, 1 TO),
 * -1 when it is none (a bond variable, an integrator). */
static int fc_signal_end(const bg_model *m, const char *name, int side) {
  const char *arrow = name ? strstr(name, "->") : NULL;
  if (!arrow) return -1;
  const char *a = side ? arrow + 2 : name;
  size_t n = side ? strcspn(a, " ") : (size_t)(arrow - name);
  for (int v = 0; v < m->nelem; v++)
    if (strlen(m->elem_name[v]) == n && !strncmp(m->elem_name[v], a, n)) return v;
  return -1;
}

/* Per line of f: the model's bond it draws (by its number), -1 for any
 * other line; the caller frees it. */
static int *fc_model_bonds(const bg_model *m, const fc_scene *f) {
  int *bond = malloc(((size_t)f->nline + 1) * sizeof(int));
  for (int j = 0; j < f->nline; j++) {
    bond[j] = -1;
    if (f->line[j].kind == FC_BOND && f->line[j].id > 0)
      for (int b = 0; b < m->nbond; b++)
        if (m->bond_num[b] == f->line[j].id) bond[j] = b;
  }
  return bond;
}

/* Per element of m its label's box in f (the first with its name), or -1. */
static int *fc_elem_boxes(const bg_model *m, const fc_scene *f) {
  int *elem_box = malloc(((size_t)m->nelem + 1) * sizeof(int));
  for (int e = 0; e < m->nelem; e++) elem_box[e] = -1;
  for (int i = 0; i < f->nbox; i++)
    if (f->box[i].elem)
      for (int e = 0; e < m->nelem; e++)
        if (elem_box[e] < 0 && !strcmp(m->elem_name[e], f->box[i].name)) elem_box[e] = i;
  return elem_box;
}

/* Issue 31: a slanted bond that nothing could have drawn straight. A
 * junction leaves one bond a side; one with more than four bonds has at
 * least (bonds - 4) off the axes, and books draw those at 45 degrees. Counts
 * the bonds drawn as one straight line within half a degree of 45 from a
 * junction of five or more bonds whose four sides (right, up, left, down)
 * its other bonds all leave by, each along the axis (within 3 degrees, by
 * the leg at the junction). A junction of more than eight bonds cannot
 * keep to the eight directions at all: the ring of one-ports round it
 * (layout_ring.c) spreads them round a rectangle, so off such a junction
 * with its four sides taken every straight slanted bond counts, whatever
 * its angle. Such a bond is counted slanted by fc_slanted; the callers
 * that count both take these out of slanted. */
static inline int fc_forced_diagonals(const bg_model *m, const bg_scene *s) {
  fc_scene f;
  fc_read(s, &f);
  int n = 0, *bond = fc_model_bonds(m, &f), *elem_box = fc_elem_boxes(m, &f);
  for (int j = 0; j < f.nline; j++) {
    const fc_line *l = &f.line[j];
    if (bond[j] < 0 || l->nseg - l->barb != 1) continue;
    double dx = fabs(l->seg[0].x1 - l->seg[0].x0), dy = fabs(l->seg[0].y1 - l->seg[0].y0);
    int diagonal = fabs(atan2(dy, dx) - atan(1.0)) <= 0.5 * atan(1.0) / 45, forced = 0;
    if (!diagonal && fmin(dx, dy) <= 0.05) continue; /* along an axis: not slanted (fc_slanted) */
    for (int end = 0; end < 2 && !forced; end++) {
      int e = end ? m->bond_head[bond[j]] : m->bond_tail[bond[j]];
      if (!bg_elem_is_junction(m->elem_kind[e]) || m->elem_nbond[e] < (diagonal ? 5 : 9) || elem_box[e] < 0)
        continue;
      const fc_box *jb = &f.box[elem_box[e]];
      double cx = (jb->x0 + jb->x1) / 2, cy = (jb->y0 + jb->y1) / 2;
      int sides = 0;
      for (int k = 0; k < f.nline; k++) {
        if (k == j || bond[k] < 0 || (m->bond_tail[bond[k]] != e && m->bond_head[bond[k]] != e)) continue;
        const fc_line *o = &f.line[k];
        const fc_seg *a = &o->seg[0], *z = &o->seg[o->nseg - o->barb - 1];
        int first = hypot(a->x0 - cx, a->y0 - cy) <= hypot(z->x1 - cx, z->y1 - cy);
        double ux = first ? a->x1 - a->x0 : z->x0 - z->x1, uy = first ? a->y1 - a->y0 : z->y0 - z->y1;
        if (fabs(uy) < 0.05 * fabs(ux)) sides |= ux > 0 ? 1 : 4;
        else if (fabs(ux) < 0.05 * fabs(uy)) sides |= uy < 0 ? 2 : 8;
      }
      forced = sides == 15;
    }
    n += forced;
    if (forced && fc_explain) printf("  diagonal: bond %d slanted off a junction with four sides taken\n", l->id);
  }
  free(bond), free(elem_box);
  fc_free(&f);
  return n;
}

/* Issue 31, crossings the graph does not force: pairs of bonds that cross
 * and share an end element, and signals crossing a bond of their own
 * source or target element. Two lines out of one node can always be
 * drawn without crossing each other (the node's sides taken in the other
 * order, or the one-port moved to the other side), so such a crossing is
 * avoidable at a bounded cost, a few points of length round the node. */
static inline int fc_adjacent(const bg_model *m, const bg_scene *s) {
  fc_scene f;
  fc_read(s, &f);
  int n = 0, *bond = fc_model_bonds(m, &f);
  for (int j = 0; j < f.nline; j++)
    for (int k = 0; k < f.nline; k++) {
      int b = bond[k];
      if (b < 0 || k == j) continue;
      int ends[2] = {-1, -1};
      if (f.line[j].kind == FC_BOND && bond[j] >= 0 && k > j)
        ends[0] = m->bond_tail[bond[j]], ends[1] = m->bond_head[bond[j]];
      else if (f.line[j].kind == FC_SIGNAL)
        ends[0] = fc_signal_end(m, f.line[j].name, 0), ends[1] = fc_signal_end(m, f.line[j].name, 1);
      else
        continue;
      int shared = 0;
      for (int e = 0; e < 2; e++) shared |= ends[e] >= 0 && (ends[e] == m->bond_tail[b] || ends[e] == m->bond_head[b]);
      if (!shared || !fc_crosses(&f.line[j], &f.line[k])) continue;
      n++;
      if (fc_explain)
        printf("  adjacent: %s %d (%s) crosses bond %d, a bond of its own end\n",
               f.line[j].kind == FC_BOND ? "bond" : "signal", f.line[j].id, f.line[j].name ? f.line[j].name : "",
               f.line[k].id);
    }
  free(bond);
  fc_free(&f);
  return n;
}

/* Issue 31, crossings a route of bounded extra length avoids. Bond B is
 * crossed by line L (a signal or a bond) at a right angle at X, and B runs
 * straight from X to its end at a one-port E (an element with this one
 * bond: the bond leads nowhere else). Then L can go round E instead: a
 * U-turn off L's crossing segment, along B past E's label (6 pt clear: a
 * node's 3 pt pad round its label and the 2 pt the router keeps off a box),
 * across and back onto L, which crosses nothing. It counts when that U
 * lies within L's segment, crosses no bond (nor, for a bond L, a signal),
 * runs on no line (within 3 pt), runs through no element label, and adds at most FC_DETOUR pt (the two
 * legs along B): the router's price for a crossed bond (160 pt) less its
 * two bends (14 pt each) and a margin, so a detour its own costs prefer.
 * For two bonds either may go round the other's one-port. Counts pairs of
 * lines (as the crossings and signal × bond do). */
#define FC_DETOUR 160.0

typedef struct fc_pt {
  double x, y;
} fc_pt;

/* Whether segments a and b run side by side within 3 pt for more than 2
 * pt (read as one line; the router's own measure of running on a line). */
static int fc_seg_along(const fc_seg *a, const fc_seg *b) {
  double la = fc_seg_len(a), lb = fc_seg_len(b);
  if (la < 2 || lb < 2) return 0;
  double ux = (a->x1 - a->x0) / la, uy = (a->y1 - a->y0) / la, vx = (b->x1 - b->x0) / lb, vy = (b->y1 - b->y0) / lb;
  if (fabs(ux * vy - uy * vx) > 0.0175) return 0;
  if (fabs((b->x0 - a->x0) * uy - (b->y0 - a->y0) * ux) >= 3) return 0;
  double t0 = (b->x0 - a->x0) * ux + (b->y0 - a->y0) * uy, t1 = (b->x1 - a->x0) * ux + (b->y1 - a->y0) * uy;
  return fmin(la, fmax(t0, t1)) - fmax(0, fmin(t0, t1)) > 2;
}

/* Whether seg crosses (or runs through) anything the U must keep off:
 * for a signal's U also another source's signal touched (fc_seg_touches
 * both ways: through its corner, end or arrowhead, or the U's corner on it). */
static int fc_detour_blocked(const fc_scene *f, const fc_seg *seg, int nseg, int lj, int bk, int bond_l) {
  for (int j = 0; j < f->nline; j++) {
    const fc_line *o = &f->line[j];
    if (j == lj || j == bk || !(o->kind == FC_BOND || o->kind == FC_SIGNAL)) continue;
    for (int p = 0; p < nseg; p++)
      for (int q = 0; q < o->nseg - o->barb; q++)
        if (((o->kind == FC_BOND || bond_l) && fc_cross(&seg[p], &o->seg[q])) || fc_seg_along(&seg[p], &o->seg[q]))
          return 1;
    if (bond_l || o->kind != FC_SIGNAL || !fc_other_sources(&f->line[lj], o)) continue;
    for (int p = 0; p < nseg; p++)
      if (fc_seg_touches(&seg[p], o) || fc_line_pt(o, seg[p].x0, seg[p].y0, 0) < 1) return 1;
  }
  for (int i = 0; i < f->nbox; i++) {
    if (f->box[i].kind != FC_NODE) continue;
    fc_box b = fc_shrink(&f->box[i], 1);
    for (int p = 0; b.x0 < b.x1 && b.y0 < b.y1 && p < nseg; p++)
      if (fc_seg_box(&seg[p], &b) == 0) return 1;
  }
  return 0;
}

/* Whether line L (index lj) avoids bond B (index bk, model bond b) by a U
 * round B's one-port end; ends: L's end elements (-1 none). */
static int fc_detour(const bg_model *m, const fc_scene *f, const int *elem_box, int lj, int bk, int b, const int ends[2]) {
  const fc_line *L = &f->line[lj], *B = &f->line[bk];
  int nb = B->nseg - B->barb;
  for (int side = 0; side < 2; side++) {
    int e = side ? m->bond_head[b] : m->bond_tail[b];
    if (m->elem_nbond[e] != 1 || elem_box[e] < 0 || e == ends[0] || e == ends[1]) continue;
    const fc_box *E = &f->box[elem_box[e]];
    const fc_seg *q = &B->seg[side ? nb - 1 : 0]; /* B's leg at E */
    fc_pt tip = side ? (fc_pt){B->seg[B->nseg - 1].x1, B->seg[B->nseg - 1].y1} : (fc_pt){q->x0, q->y0};
    for (int p = 0; p < L->nseg - L->barb; p++) {
      const fc_seg *s = &L->seg[p];
      if (!fc_cross(s, q)) continue;
      double lu = fc_seg_len(s), lv = fc_seg_len(q);
      fc_pt u = {(s->x1 - s->x0) / lu, (s->y1 - s->y0) / lu}, w = {(q->x1 - q->x0) / lv, (q->y1 - q->y0) / lv};
      if (fabs(u.x * w.x + u.y * w.y) > 0.01) continue; /* not at a right angle */
      if (!side) w.x = -w.x, w.y = -w.y;                /* from the crossing towards E */
      double den = u.x * w.y - u.y * w.x;
      double t = ((q->x0 - s->x0) * w.y - (q->y0 - s->y0) * w.x) / den; /* X along s */
      fc_pt X = {s->x0 + t * u.x, s->y0 + t * u.y};
      double nw = -u.y * w.x + u.x * w.y; /* the U's legs square to L (B may be off by 0.6 degrees) */
      w = nw > 0 ? (fc_pt){-u.y, u.x} : (fc_pt){u.y, -u.x};
      /* what the U must hold: E's label, B from X to its end, the half arrow */
      double a0 = 1e300, a1 = -1e300, depth = 0;
      double cx[6] = {E->x0, E->x1, E->x0, E->x1, tip.x, side ? B->seg[nb - 1].x1 : q->x0};
      double cy[6] = {E->y0, E->y0, E->y1, E->y1, tip.y, side ? B->seg[nb - 1].y1 : q->y0};
      for (int k = 0; k < 6; k++) {
        double du = (cx[k] - X.x) * u.x + (cy[k] - X.y) * u.y, dw = (cx[k] - X.x) * w.x + (cy[k] - X.y) * w.y;
        a0 = fmin(a0, du), a1 = fmax(a1, du), depth = fmax(depth, dw);
      }
      a0 -= 6, a1 += 6, depth += 6;
      if (t + a0 < 0 || t + a1 > lu || 2 * depth > FC_DETOUR) continue;
      fc_pt A = {X.x + a0 * u.x, X.y + a0 * u.y}, C = {X.x + a1 * u.x, X.y + a1 * u.y};
      fc_seg U[3] = {{A.x, A.y, A.x + depth * w.x, A.y + depth * w.y},
                     {A.x + depth * w.x, A.y + depth * w.y, C.x + depth * w.x, C.y + depth * w.y},
                     {C.x + depth * w.x, C.y + depth * w.y, C.x, C.y}};
      if (fc_detour_blocked(f, U, 3, lj, bk, L->kind == FC_BOND)) continue;
      if (fc_explain)
        printf("  avoidable: %s %d (%s) crosses bond %d at (%.0f,%.0f): round %s, %.0f pt more\n",
               L->kind == FC_BOND ? "bond" : "signal", L->id, L->name ? L->name : "", B->id, X.x, X.y,
               m->elem_name[e], 2 * depth);
      return 1;
    }
  }
  return 0;
}

static inline int fc_avoidable(const bg_model *m, const bg_scene *s) {
  fc_scene f;
  fc_read(s, &f);
  int n = 0, *bond = fc_model_bonds(m, &f), *elem_box = fc_elem_boxes(m, &f);
  for (int j = 0; j < f.nline; j++)
    for (int k = 0; k < f.nline; k++) {
      const fc_line *L = &f.line[j];
      if (bond[k] < 0 || k == j || !(L->kind == FC_SIGNAL || (L->kind == FC_BOND && bond[j] >= 0 && k > j)) ||
          !fc_near(L, &f.line[k], 0))
        continue;
      int crossed = L->kind == FC_SIGNAL ? fc_sig_cross(L, &f.line[k], &(int){0}, &(int){0}) : fc_crosses(L, &f.line[k]);
      if (!crossed) continue;
      int ends[2] = {-1, -1}, kends[2] = {m->bond_tail[bond[k]], m->bond_head[bond[k]]};
      if (L->kind == FC_BOND) ends[0] = m->bond_tail[bond[j]], ends[1] = m->bond_head[bond[j]];
      else ends[0] = fc_signal_end(m, L->name, 0), ends[1] = fc_signal_end(m, L->name, 1);
      n += fc_detour(m, &f, elem_box, j, k, bond[k], ends) ||
           (L->kind == FC_BOND && fc_detour(m, &f, elem_box, k, j, bond[j], kends));
    }
  free(bond), free(elem_box);
  fc_free(&f);
  return n;
}

static inline void fc_add(fc_stats *sum, const fc_stats *s) {
  const int *a = (const int *)s;
  int *b = (int *)sum;
  for (size_t k = 0; k < sizeof *s / sizeof(int); k++) b[k] += a[k];
}
#endif
