/* SPDX-License-Identifier: BSD-3-Clause */
/* An MTT drawing's geometry (mtt_int.h): which xfig objects are bonds,
 * strokes, components and port labels (MTT's rules: solid open polylines and
 * texts at a depth that is a multiple of 10; a bond has two or more
 * segments, the shorter end segment its half arrow; a stroke one segment),
 * and what is near what: the component at each bond end, the bond end each
 * port label and each stroke belongs to. Every choice is the nearest one, as
 * MTT makes it; where the second nearest is almost as near, the reading
 * taken is said in a warning with the drawing's coordinates. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "import/mtt_int.h"

typedef long long i64;

static i64 dist2(bg_fig_pt a, bg_fig_pt b) {
  i64 dx = (i64)a.x - b.x, dy = (i64)a.y - b.y;
  return dx * dx + dy * dy;
}

/* Second nearest within 25% of the nearest distance: the reading is said. */
static int close_call(i64 d1, i64 d2) { return d2 >= 0 && d2 * 16 <= d1 * 25; }

static bg_srcloc at_obj(const bg_mtt_sys *s, const bg_fig_obj *o) { return (bg_srcloc){o->line, 1, s->file}; }

static int name_char(char c) { return isalnum((unsigned char)c) || c == '_' || c == '-'; }

/* A component's text: TYPE, TYPE:NAME, TYPE:NAME:CR, or SS:[NAME]; NULL
 * type when the text is artwork. */
static void parse_component(bg_arena *a, const char *s, bg_mtt_comp *c) {
  const char *c1 = strchr(s, ':');
  const char *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
  size_t tn = c1 ? (size_t)(c1 - s) : strlen(s);
  size_t nn = c1 ? (c2 ? (size_t)(c2 - c1 - 1) : strlen(c1 + 1)) : 0;
  if (!tn) return;
  for (size_t i = 0; i < tn; i++)
    if (!name_char(s[i]) && s[i] != '*') return;
  const char *name = c1 ? c1 + 1 : NULL;
  int port = 0;
  if (name && nn >= 2 && name[0] == '[' && name[nn - 1] == ']') {
    port = 1, name++, nn -= 2;
    if (!nn) return;
  }
  for (size_t i = 0; name && i < nn; i++)
    if (!name_char(name[i]) && name[i] != '*') return;
  if (c1 && !nn) return;
  c->type = bg_arena_strndup(a, s, tn);
  c->name = name ? bg_arena_strndup(a, name, nn) : NULL;
  c->cr = c2 ? bg_arena_strdup(a, c2 + 1) : NULL;
  c->port_ss = port;
}

/* A port label's text: [NAME] (a vector [a,b] is taken whole and refused
 * later); NULL when the text is not one. */
static const char *parse_port_label(bg_arena *a, const char *s) {
  size_t n = strlen(s);
  if (n < 3 || s[0] != '[' || s[n - 1] != ']') return NULL;
  for (size_t i = 1; i + 1 < n; i++)
    if (!name_char(s[i]) && s[i] != ',' && s[i] != ':') return NULL;
  return bg_arena_strndup(a, s + 1, n - 2);
}

static void add_comp(bg_mtt_sys *s, bg_mtt_comp c) {
  if (s->nc == s->capc) {
    s->capc = s->capc ? 2 * s->capc : 16;
    s->c = bg_xrealloc(s->c, (size_t)s->capc * sizeof *s->c);
  }
  s->c[s->nc++] = c;
}

static void add_bond(bg_mtt_sys *s, bg_mtt_bond b) {
  if (s->nb == s->capb) {
    s->capb = s->capb ? 2 * s->capb : 16;
    s->b = bg_xrealloc(s->b, (size_t)s->capb * sizeof *s->b);
  }
  s->b[s->nb++] = b;
}

/* A bond's ends from its points: the half arrow is the shorter end segment,
 * its corner the head; the tail is the other end of the polyline. */
static int bond_of(const bg_mtt_sys *s, const bg_fig_obj *o, bg_diags *dg, bg_mtt_bond *b) {
  int n = o->npts;
  i64 l1 = dist2(o->pts[0], o->pts[1]), l2 = dist2(o->pts[n - 2], o->pts[n - 1]);
  memset(b, 0, sizeof *b);
  b->line = o->line;
  b->comp[0] = b->comp[1] = -1;
  if (!l1 || !l2 || l1 == l2) {
    bg_diag_error(dg, at_obj(s, o),
                  "MTT drawing: the bond from (%d, %d) to (%d, %d) has %s: draw its half arrow "
                  "as the shorter end segment",
                  o->pts[0].x, o->pts[0].y, o->pts[n - 1].x, o->pts[n - 1].y,
                  !l1 || !l2 ? "a segment of no length" : "two end segments of the same length");
    return -1;
  }
  if (l1 < l2) b->barb = o->pts[0], b->end[BG_MTT_HEAD] = o->pts[1], b->end[BG_MTT_TAIL] = o->pts[n - 1];
  else b->barb = o->pts[n - 1], b->end[BG_MTT_HEAD] = o->pts[n - 2], b->end[BG_MTT_TAIL] = o->pts[0];
  return 0;
}

/* The nearest bond end to p (bond index, end in *end), the squared
 * distances of the nearest and second nearest (-1: none). */
static int nearest_end(const bg_mtt_sys *s, bg_fig_pt p, int *end, i64 *d1, i64 *d2) {
  int best = -1;
  *d1 = *d2 = -1;
  for (int i = 0; i < s->nb; i++)
    for (int k = 0; k < 2; k++) {
      i64 d = dist2(p, s->b[i].end[k]);
      if (best < 0 || d < *d1) *d2 = *d1, *d1 = d, best = i, *end = k;
      else if (*d2 < 0 || d < *d2) *d2 = d;
    }
  return best;
}

/* A reading worth saying: a warning at the object's line, and a note the
 * .bg text keeps as a comment. */
static void say(bg_mtt_sys *s, bg_arena *a, bg_diags *dg, int line, const char *msg) {
  bg_diag_warning(dg, (bg_srcloc){line, 1, s->file}, "MTT drawing: %s", msg);
  if (s->nnotes == s->capnotes) {
    s->capnotes = s->capnotes ? 2 * s->capnotes : 8;
    s->notes = bg_xrealloc(s->notes, (size_t)s->capnotes * sizeof *s->notes);
  }
  size_t n = strlen(msg) + 48;
  char *note = bg_arena_alloc(a, n);
  snprintf(note, n, "%s_abg.fig:%d: %s", s->type, line, msg);
  s->notes[s->nnotes++] = note;
}

static void ambiguous(bg_mtt_sys *s, bg_arena *a, bg_diags *dg, int line, const char *what,
                      bg_fig_pt p, const char *taken, const char *other) {
  size_t n = strlen(what) + strlen(taken) * 2 + strlen(other) + 96;
  char *msg = bg_arena_alloc(a, n);
  snprintf(msg, n, "%s at (%d, %d) is almost as near %s as %s: read as %s", what, p.x, p.y, other,
           taken, taken);
  say(s, a, dg, line, msg);
}

static const char *comp_label(bg_arena *a, const bg_mtt_comp *c) {
  size_t n = strlen(c->type) + (c->name ? strlen(c->name) : 0) + 8;
  char *s = bg_arena_alloc(a, n);
  if (!c->name) snprintf(s, n, "%s", c->type);
  else snprintf(s, n, c->port_ss ? "%s:[%s]" : "%s:%s", c->type, c->name);
  return s;
}

static const char *end_label(bg_arena *a, const bg_mtt_sys *s, int bond, int end) {
  const bg_mtt_bond *b = &s->b[bond];
  size_t n = 96;
  char *t = bg_arena_alloc(a, n);
  snprintf(t, n, "the %s of the bond at (%d, %d)", end == BG_MTT_HEAD ? "head" : "tail",
           b->end[end].x, b->end[end].y);
  return t;
}

/* Each bond end's component: the nearest one. */
static int attach_components(bg_mtt_sys *s, bg_arena *a, bg_diags *dg) {
  int rc = 0;
  for (int i = 0; i < s->nb; i++) {
    bg_mtt_bond *b = &s->b[i];
    for (int k = 0; k < 2; k++) {
      int best = -1, second = -1;
      i64 d1 = -1, d2 = -1;
      for (int c = 0; c < s->nc; c++) {
        i64 d = dist2(b->end[k], s->c[c].at);
        if (best < 0 || d < d1) second = best, d2 = d1, d1 = d, best = c;
        else if (d2 < 0 || d < d2) d2 = d, second = c;
      }
      if (best < 0) {
        bg_diag_error(dg, (bg_srcloc){b->line, 1, s->file},
                      "MTT drawing: the bond at (%d, %d) has no component near it (none is drawn)",
                      b->end[k].x, b->end[k].y);
        return -1;
      }
      b->comp[k] = best;
      if (second >= 0 && close_call(d1, d2))
        ambiguous(s, a, dg, b->line, k == BG_MTT_HEAD ? "the bond's head" : "the bond's tail",
                  b->end[k], comp_label(a, &s->c[best]), comp_label(a, &s->c[second]));
    }
    if (b->comp[0] == b->comp[1]) {
      const bg_mtt_comp *c = &s->c[b->comp[0]];
      bg_diag_error(dg, (bg_srcloc){b->line, 1, s->file},
                    "MTT drawing: both ends of the bond from (%d, %d) to (%d, %d) are nearest %s "
                    "(at %d, %d)",
                    b->end[1].x, b->end[1].y, b->end[0].x, b->end[0].y, comp_label(a, c), c->at.x,
                    c->at.y);
      rc = -1;
    }
  }
  for (int c = 0; c < s->nc && !rc; c++) {
    int n = 0;
    for (int i = 0; i < s->nb; i++) n += (s->b[i].comp[0] == c) + (s->b[i].comp[1] == c);
    s->c[c].nbonds = n;
    if (!n) {
      bg_diag_error(dg, (bg_srcloc){s->c[c].line, 1, s->file},
                    "MTT drawing: %s at (%d, %d) has no bond (no bond end is nearer to it than to "
                    "another component)",
                    comp_label(a, &s->c[c]), s->c[c].at.x, s->c[c].at.y);
      rc = -1;
    }
  }
  return rc;
}

/* A port label belongs to the nearest bond end. */
static int attach_port_label(bg_mtt_sys *s, bg_arena *a, bg_diags *dg, const bg_fig_obj *o,
                             const char *label) {
  int end = 0;
  i64 d1, d2;
  int i = nearest_end(s, o->pts[0], &end, &d1, &d2);
  char *what = bg_arena_alloc(a, strlen(label) + 24);
  snprintf(what, strlen(label) + 24, "the port label [%s]", label);
  if (i < 0) {
    bg_diag_error(dg, at_obj(s, o), "MTT drawing: %s at (%d, %d) has no bond near it", what,
                  o->pts[0].x, o->pts[0].y);
    return -1;
  }
  if (s->b[i].port[end]) {
    bg_diag_error(dg, at_obj(s, o),
                  "MTT drawing: %s at (%d, %d) and [%s] both label %s", what, o->pts[0].x,
                  o->pts[0].y, s->b[i].port[end], end_label(a, s, i, end));
    return -1;
  }
  s->b[i].port[end] = label;
  if (close_call(d1, d2)) {
    int other = 0;
    i64 dd = -1;
    for (int j = 0; j < s->nb; j++)
      for (int k = 0; k < 2; k++)
        if ((j != i || k != end) && (dd < 0 || dist2(o->pts[0], s->b[j].end[k]) < dd))
          dd = dist2(o->pts[0], s->b[j].end[k]), other = j * 2 + k;
    ambiguous(s, a, dg, o->line, what, o->pts[0], end_label(a, s, i, end),
              end_label(a, s, other / 2, other % 2));
  }
  return 0;
}

/* A stroke: its centre at a bond end is a full stroke there; an end of it
 * there, a half stroke, on the flow side when it lies on the half arrow's
 * side of the bond. */
static void attach_stroke(bg_mtt_sys *s, bg_arena *a, bg_diags *dg, const bg_fig_obj *o) {
  bg_fig_pt p0 = o->pts[0], p1 = o->pts[1];
  bg_fig_pt mid = {(p0.x + p1.x) / 2, (p0.y + p1.y) / 2};
  int end = 0;
  i64 d1, d2;
  int i = nearest_end(s, mid, &end, &d1, &d2);
  if (i < 0) return;
  bg_mtt_bond *b = &s->b[i];
  bg_fig_pt e = b->end[end];
  i64 len2 = dist2(p0, p1);
  if (d1 > 4 * len2) {
    char msg[256];
    snprintf(msg, sizeof msg, "the stroke at (%d, %d) is far from every bond end; taken as a stroke at %s",
             mid.x, mid.y, end_label(a, s, i, end));
    say(s, a, dg, o->line, msg);
  }
  i64 dm = dist2(e, mid), da = dist2(e, p0), db = dist2(e, p1);
  if (dm <= da && dm <= db) {
    b->stroke[end] = 1;
    return;
  }
  bg_fig_pt near = da < db ? p0 : p1;
  bg_fig_pt arrow = {b->barb.x - b->end[BG_MTT_HEAD].x, b->barb.y - b->end[BG_MTT_HEAD].y};
  i64 dot = (i64)(mid.x - near.x) * arrow.x + (i64)(mid.y - near.y) * arrow.y;
  if (dot > 0) b->half_f[end] = 1;
  else b->half_e[end] = 1;
  if (b->half_e[end] && b->half_f[end]) b->stroke[end] = 1;
}

static int too_big(const bg_mtt_sys *s, bg_diags *dg, const bg_fig_obj *o, const char *what, int max) {
  bg_diag_error(dg, at_obj(s, o),
                "MTT drawing: more than %d %s; bgdraw reads drawings up to that size", max, what);
  return -1;
}

int bg_mtt_geometry(bg_mtt_sys *s, const bg_fig *fig, bg_arena *a, bg_diags *dg) {
  int rc = 0, marks = 0;
  for (int i = 0; i < fig->n && !rc; i++) {
    const bg_fig_obj *o = &fig->objs[i];
    if (o->depth % 10 == 0 && ++marks > BG_MTT_MAX_MARKS)
      return too_big(s, dg, o, "objects of the bond graph (bonds, strokes, texts)", BG_MTT_MAX_MARKS);
  }
  for (int i = 0; i < fig->n && !rc; i++) {
    const bg_fig_obj *o = &fig->objs[i];
    if (o->depth % 10 != 0) continue; /* artwork, MTT's rule */
    if (o->kind == BG_FIG_LINE && o->sub_type == 1 && o->style == 0 && !o->arrows && o->npts >= 3) {
      bg_mtt_bond b;
      if (s->nb >= BG_MTT_MAX_BONDS) return too_big(s, dg, o, "bonds", BG_MTT_MAX_BONDS);
      if (bond_of(s, o, dg, &b)) rc = -1;
      else add_bond(s, b);
    } else if (o->kind == BG_FIG_TEXT) {
      bg_mtt_comp c = {0};
      parse_component(a, o->text, &c);
      if (!c.type) continue;
      c.at = o->pts[0], c.line = o->line;
      c.label = comp_label(a, &c);
      if (s->nc >= BG_MTT_MAX_COMPONENTS) return too_big(s, dg, o, "components", BG_MTT_MAX_COMPONENTS);
      add_comp(s, c);
    }
  }
  if (rc || attach_components(s, a, dg)) return -1;
  for (int i = 0; i < fig->n && !rc; i++) {
    const bg_fig_obj *o = &fig->objs[i];
    if (o->depth % 10 != 0) continue;
    if (o->kind == BG_FIG_TEXT) {
      const char *label = parse_port_label(a, o->text);
      if (label) rc = attach_port_label(s, a, dg, o, label);
    } else if (o->sub_type == 1 && o->style == 0 && !o->arrows && o->npts == 2 &&
               (o->pts[0].x != o->pts[1].x || o->pts[0].y != o->pts[1].y))
      attach_stroke(s, a, dg, o);
  }
  return rc;
}
