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

static void grow(box *b, int k, const bg_diagram *d, int n) {
  if (k < 0) return;
  b[k].x0 = fmin(b[k].x0, d->L->nx[n] - d->L->nw[n] / 2), b[k].x1 = fmax(b[k].x1, d->L->nx[n] + d->L->nw[n] / 2);
  b[k].y0 = fmin(b[k].y0, d->L->ny[n] - d->L->nh[n] / 2), b[k].y1 = fmax(b[k].y1, d->L->ny[n] + d->L->nh[n] / 2);
}

/* Boxes of every instance: its nodes, then (children after parents in the
 * model, so walking backwards) its instances' boxes, padded. */
static box *instance_boxes(const bg_diagram *d) {
  const bg_model *m = d->m;
  box *b = bg_xmalloc((size_t)(m->ninst + 1) * sizeof *b);
  for (int k = 0; k < m->ninst; k++) b[k] = (box){INFINITY, INFINITY, -INFINITY, -INFINITY};
  /* an element, a collapsed child's box, a detector: in its instance's frame */
  for (int e = 0; e < m->nelem; e++)
    if (bg_node_shown(d->L, e)) grow(&b[0], m->elem_inst[e], d, e);
  for (int i = 0; i < m->ninst; i++)
    if (d->L->inst_box[i] >= 0) grow(&b[0], m->inst_parent[i], d, d->L->inst_box[i]);
  for (int i = 0; i < m->ndet; i++)
    if (d->L->det_draw[i] >= 0) grow(&b[0], m->elem_inst[m->det_node[i]], d, d->L->det_draw[i]);
  double lh = bg_frame_label_height(&d->st);
  for (int k = m->ninst - 1; k >= 0; k--) {
    if (!(b[k].x0 <= b[k].x1)) continue; /* no element at all */
    b[k].x0 -= FRAME_PAD, b[k].x1 += FRAME_PAD, b[k].y1 += FRAME_PAD;
    b[k].y0 -= FRAME_PAD + lh;
    int p = m->inst_parent[k];
    if (p < 0) continue;
    b[p].x0 = fmin(b[p].x0, b[k].x0), b[p].x1 = fmax(b[p].x1, b[k].x1);
    b[p].y0 = fmin(b[p].y0, b[k].y0), b[p].y1 = fmax(b[p].y1, b[k].y1);
  }
  return b;
}

void bg_draw_frames(bg_diagram *d) {
  const bg_model *m = d->m;
  if (!m->ninst) return;
  box *b = instance_boxes(d);
  double size = 0.85 * d->st.font_size;
  for (int k = 0; k < m->ninst; k++) {
    if (!(b[k].x0 <= b[k].x1)) continue; /* empty, or collapsed (drawn as a box) */
    bg_strbuf t = {0};
    /* inside its parent's frame, which names the parent: its own name */
    const char *name = m->inst_name[k], *dot = strrchr(name, '.');
    bg_markup_escape(&t, m->inst_parent[k] >= 0 && dot && dot[1] ? dot + 1 : name);
    bg_sb_puts(&t, " : ");
    bg_markup_escape(&t, m->inst_def[k]);
    double tw, th;
    bg_text_measure(d->st.font, size, bg_sb_str(&t), &tw, &th);
    double x1 = fmax(b[k].x1, b[k].x0 + tw + 8);
    bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "frame %s", m->inst_name[k]);
    it->color = d->st.muted;
    it->width = 0.6 * d->st.line_width;
    bg_scene_move(&d->scene, b[k].x0, b[k].y0);
    bg_scene_line(&d->scene, x1, b[k].y0);
    bg_scene_line(&d->scene, x1, b[k].y1);
    bg_scene_line(&d->scene, b[k].x0, b[k].y1);
    bg_scene_close(&d->scene);
    char role[256];
    snprintf(role, sizeof role, "frame-label %s", m->inst_name[k]);
    bg_scene_text(&d->scene, bg_sb_str(&t), b[k].x0 + 4, b[k].y0 + 2, size, 0, 0, d->st.muted, role);
    bg_sb_free(&t);
  }
  free(b);
}
