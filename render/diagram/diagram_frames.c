/* SPDX-License-Identifier: BSD-3-Clause */
/* Instance frames: with submodels, each instance is drawn inside a labelled
 * frame ("M1 : DCMotor") around its elements and its own instances' frames,
 * measured on the final node positions (after dot and the grid placement).
 * dot is given one cluster per instance, so an instance's nodes stay
 * together. Bonds through a port cross the frame; causal paths and loops are
 * drawn over it. A version 1 model has no frames. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

enum { FRAME_PAD = 6 };

/* The frames' label height, which the layout keeps free above the nodes. */
double bg_frame_label_height(const bg_style *st) { return 1.3 * 0.85 * st->font_size; }

typedef struct box { double x0, y0, x1, y1; } box;

/* A frame's piece: instance k's nodes in one band of a folded part (a fold
 * through an instance draws it as one frame per band, each round its own
 * nodes: one box round both bands held the nodes between them, another
 * instance's or the model's; issue 31). Unfolded, an instance is one piece. */
typedef struct piece {
  int k, band;
  box b;
} piece;

static int by_instance_band(const void *a, const void *b) {
  const piece *p = a, *q = b;
  return p->k != q->k ? (p->k > q->k) - (p->k < q->k) : (p->band > q->band) - (p->band < q->band);
}

static int band_of(const bg_diagram *d, int n) { return d->L->lay.band ? d->L->lay.band[n] : 0; }

/* The piece of instance k in band, or -1. */
static int find_piece(const piece *p, int np, int k, int band) {
  int lo = 0, hi = np - 1;
  while (lo <= hi) {
    int mid = (lo + hi) / 2;
    if (p[mid].k == k && p[mid].band == band) return mid;
    if (p[mid].k < k || (p[mid].k == k && p[mid].band < band)) lo = mid + 1;
    else hi = mid - 1;
  }
  return -1;
}

/* Node n of instance k (an element, a collapsed child's box, a detector):
 * pass 0 lists a piece for k and each instance round it in n's band, pass
 * 1 grows k's piece by n's box. */
static void take_node(const bg_diagram *d, piece *p, int *np, int pass, int k, int n) {
  const bg_model *m = d->m;
  int band = band_of(d, n);
  if (pass == 0) {
    for (int j = k; j >= 0; j = m->inst_parent[j]) p[(*np)++] = (piece){j, band, {INFINITY, INFINITY, -INFINITY, -INFINITY}};
    return;
  }
  int i = k >= 0 ? find_piece(p, *np, k, band) : -1;
  if (i < 0) return;
  box *b = &p[i].b;
  b->x0 = fmin(b->x0, d->L->nx[n] - d->L->nw[n] / 2), b->x1 = fmax(b->x1, d->L->nx[n] + d->L->nw[n] / 2);
  b->y0 = fmin(b->y0, d->L->ny[n] - d->L->nh[n] / 2), b->y1 = fmax(b->y1, d->L->ny[n] + d->L->nh[n] / 2);
}

/* The pieces of every instance's frame, in instance order: its nodes in
 * the band, then (children after parents in the model, so walking
 * backwards) its instances' pieces in that band, padded. */
static piece *instance_pieces(const bg_diagram *d, int *npiece) {
  const bg_model *m = d->m;
  int depth = 1, np = 0;
  for (int k = 0; k < m->ninst; k++) {
    int dk = 0;
    for (int j = k; j >= 0; j = m->inst_parent[j]) dk++;
    depth = dk > depth ? dk : depth;
  }
  piece *p = bg_xmalloc(((size_t)(m->nelem + m->ninst + m->ndet) * (size_t)depth + 1) * sizeof *p);
  for (int pass = 0; pass < 2; pass++) {
    for (int e = 0; e < m->nelem; e++)
      if (m->elem_inst[e] >= 0 && bg_node_shown(d->L, e)) take_node(d, p, &np, pass, m->elem_inst[e], e);
    for (int i = 0; i < m->ninst; i++)
      if (d->L->inst_box[i] >= 0 && m->inst_parent[i] >= 0) take_node(d, p, &np, pass, m->inst_parent[i], d->L->inst_box[i]);
    for (int i = 0; i < m->ndet; i++)
      if (d->L->det_draw[i] >= 0 && m->elem_inst[m->det_node[i]] >= 0)
        take_node(d, p, &np, pass, m->elem_inst[m->det_node[i]], d->L->det_draw[i]);
    if (pass == 0) { /* sorted and each (instance, band) once */
      qsort(p, (size_t)np, sizeof *p, by_instance_band);
      int u = 0;
      for (int i = 0; i < np; i++)
        if (u == 0 || p[i].k != p[u - 1].k || p[i].band != p[u - 1].band) p[u++] = p[i];
      np = u;
    }
  }
  double lh = bg_frame_label_height(&d->st);
  for (int i = np - 1; i >= 0; i--) {
    box *b = &p[i].b;
    if (!(b->x0 <= b->x1)) continue; /* no element at all */
    b->x0 -= FRAME_PAD, b->x1 += FRAME_PAD, b->y1 += FRAME_PAD;
    b->y0 -= FRAME_PAD + lh;
    int q = m->inst_parent[p[i].k] >= 0 ? find_piece(p, np, m->inst_parent[p[i].k], p[i].band) : -1;
    if (q < 0) continue;
    box *a = &p[q].b;
    a->x0 = fmin(a->x0, b->x0), a->x1 = fmax(a->x1, b->x1);
    a->y0 = fmin(a->y0, b->y0), a->y1 = fmax(a->y1, b->y1);
  }
  *npiece = np;
  return p;
}

/* Whether bond b's line meets the box. */
static int bond_meets_box(const bg_diagram_layout *L, int b, double x0, double y0, double x1, double y1) {
  const bg_bond_geom *g = &L->bg[b];
  bg_vec p = g->tail;
  for (int i = 0; i <= g->bendn; i++) {
    bg_vec q = i == g->bendn ? g->head : bg_v(L->lay.bendx[g->bendadr + i], L->lay.bendy[g->bendadr + i]);
    const double seg[4] = {p.x, p.y, q.x, q.y};
    if (bg_seg_hits_box(seg, x0, y0, x1, y1)) return 1;
    p = q;
  }
  return 0;
}

/* Per instance, the bonds with an end in it or in one of its instances
 * (CSR: adr, list); the bonds that can run through its frame's label. */
static void instance_bonds(const bg_diagram *d, int **adr, int **list) {
  const bg_model *m = d->m;
  *adr = bg_xcalloc((size_t)m->ninst + 2, sizeof **adr);
  for (int pass = 0; pass < 2; pass++) {
    int *fill = pass ? bg_xcalloc((size_t)m->ninst + 1, sizeof *fill) : NULL;
    for (int b = 0; b < m->nbond; b++)
      for (int end = 0; end < 2; end++) {
        int e = end ? m->bond_head[b] : m->bond_tail[b];
        int other = end ? m->bond_tail[b] : m->bond_head[b];
        for (int k = e < m->nelem ? m->elem_inst[e] : -1; k >= 0; k = m->inst_parent[k]) {
          int shared = 0; /* both ends in k: listed once, from the tail */
          for (int j = other < m->nelem ? m->elem_inst[other] : -1; end && j >= 0 && !shared; j = m->inst_parent[j])
            shared = j == k;
          if (shared) continue;
          if (pass) (*list)[(*adr)[k] + fill[k]++] = b;
          else (*adr)[k + 1]++;
        }
      }
    if (!pass) {
      for (int k = 0; k < m->ninst; k++) (*adr)[k + 1] += (*adr)[k];
      *list = bg_xcalloc((size_t)(*adr)[m->ninst] + 1, sizeof **list);
    }
    free(fill);
  }
}

/* Whether a bond of frame k's list runs through the label's box at x. */
static int label_crossed(const bg_diagram *d, const int *adr, const int *list, int k, double x, double y, double tw,
                         double th) {
  for (int j = adr[k]; j < adr[k + 1]; j++)
    if (bond_meets_box(d->L, list[j], x, y, x + tw, y + th)) return 1;
  return 0;
}

void bg_draw_frames(bg_diagram *d) {
  const bg_model *m = d->m;
  if (!m->ninst) return;
  int np;
  piece *pc = instance_pieces(d, &np);
  int *adr, *list;
  instance_bonds(d, &adr, &list);
  double size = 0.85 * d->st.font_size;
  for (int i = 0; i < np; i++) {
    int k = pc[i].k;
    const box *b = &pc[i].b;
    if (!(b->x0 <= b->x1)) continue; /* empty, or collapsed (drawn as a box) */
    /* inside its parent's frame, which names the parent: its own name;
     * then its submodel's, where the frame is wide enough for both (a wall
     * of one-element layers: each frame grew to `plaster :
     * ThermalCapacitance` and lay over the next one's) */
    bg_strbuf t = {0}, full = {0};
    const char *name = m->inst_name[k], *dot = strrchr(name, '.');
    bg_markup_escape(&t, m->inst_parent[k] >= 0 && dot && dot[1] ? dot + 1 : name);
    bg_sb_printf(&full, "%s : ", bg_sb_str(&t));
    bg_markup_escape(&full, m->inst_def[k]);
    double tw, th;
    bg_text_measure(d->st.font, size, bg_sb_str(&full), &tw, &th);
    if (b->x0 + tw + 8 <= b->x1) bg_sb_clear(&t), bg_sb_puts(&t, bg_sb_str(&full));
    else bg_text_measure(d->st.font, size, bg_sb_str(&t), &tw, &th);
    bg_sb_free(&full);
    double x1 = fmax(b->x1, b->x0 + tw + 8);
    bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "frame %s", m->inst_name[k]);
    it->color = d->st.muted;
    it->width = 0.6 * d->st.line_width;
    bg_scene_move(&d->scene, b->x0, b->y0);
    bg_scene_line(&d->scene, x1, b->y0);
    bg_scene_line(&d->scene, x1, b->y1);
    bg_scene_line(&d->scene, b->x0, b->y1);
    bg_scene_close(&d->scene);
    char role[256];
    snprintf(role, sizeof role, "frame-label %s", m->inst_name[k]);
    /* at the top left, or the top right where a bond (a fold's, coming
     * down into the frame's first element) runs through it there only */
    double lx = b->x0 + 4, ly = b->y0 + 2, rx = x1 - 4 - tw;
    if (rx > lx && label_crossed(d, adr, list, k, lx, ly, tw, th) && !label_crossed(d, adr, list, k, rx, ly, tw, th))
      lx = rx;
    bg_scene_text(&d->scene, bg_sb_str(&t), lx, ly, size, 0, 0, d->st.muted, role);
    bg_sb_free(&t);
  }
  free(pc), free(adr), free(list);
}
