/* SPDX-License-Identifier: BSD-3-Clause */
/* Conflict flashes and the legend. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

/* A lightning flash about `size` points high, centred at p. */
static void flash_path(bg_scene *s, bg_vec p, double size) {
  static const double pt[][2] = {{0.62, 0},    {0.16, 0.56}, {0.45, 0.56}, {0.28, 1},
                                 {0.84, 0.40}, {0.55, 0.40}, {0.78, 0}};
  for (size_t i = 0; i < sizeof pt / sizeof pt[0]; i++) {
    double x = p.x + (pt[i][0] - 0.5) * size, y = p.y + (pt[i][1] - 0.5) * size;
    if (i == 0) bg_scene_move(s, x, y);
    else bg_scene_line(s, x, y);
  }
  bg_scene_close(s);
}

#define RING_STEPS 6 /* rings 6 pt apart: a conflict text at most 30 pt beyond the nearest, by its flash */
#define RING_DIRS 16

static void draw_conflict(bg_diagram *d, int k) {
  const bg_analysis *a = d->a;
  const bg_style *st = &d->st;
  int j = d->L->node_of[a->conflict_node[k]]; /* at the box of a collapsed instance */
  int hot = !d->o.highlight_kind || (d->o.highlight_kind == 'c' && d->o.highlight_index == k + 1);
  bg_vec dir = bg_free_direction(d->L, j), c = bg_v(d->L->nx[j], d->L->ny[j]);
  double r = fmax(d->L->nw[j], d->L->nh[j]) / 2 + 8;
  bg_vec p = bg_vadd(c, bg_vscale(dir, r));
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "flash conflict=%d", k + 1);
  it->fill = bg_diagram_ink(d, st->conflict, hot);
  it->color = bg_diagram_ink(d, st->flash_outline, hot);
  it->width = 0.5;
  flash_path(&d->scene, p, 12);
  char text[64], role[48];
  if (a->conflict_type[k] == 1) snprintf(text, sizeof text, "type 1");
  else snprintf(text, sizeof text, "type 2, k = %d", a->conflict_degree[k]);
  snprintf(role, sizeof role, "conflict-text conflict=%d", k + 1);
  bg_obstacle_rect(d, p.x - 6, p.y - 6, p.x + 6, p.y + 6);
  /* the text beyond the flash, as close as it is free */
  double size = st->font_size * st->number_scale, w, h;
  bg_text_measure(st->font, size, text, &w, &h);
  w += 1, h *= 0.8;
  double extent = fabs(dir.x) * w / 2 + fabs(dir.y) * h / 2;
  bg_vec cand[16 + RING_STEPS * RING_DIRS];
  for (int i = 0; i < 4; i++) cand[i] = bg_vadd(p, bg_vscale(dir, 7 + extent + 5 * i));
  bg_vec side = bg_vleft(dir);
  for (int i = 0; i < 4; i++)
    cand[4 + i] = bg_vadd(cand[0], bg_vscale(side, (i % 2 ? -1 : 1) * (i / 2 + 1) * (h + 1)));
  /* crowded: further out, and beside the flash across its direction */
  for (int i = 0; i < 4; i++) cand[8 + i] = bg_vadd(p, bg_vscale(dir, 27 + extent + 8 * i));
  for (int i = 0; i < 4; i++)
    cand[12 + i] = bg_vadd(p, bg_vscale(side, (i % 2 ? -1 : 1) * (6 + w / 2 + 8 * (i / 2))));
  /* none of those free: rings round the flash, nearest first, each
   * starting from the free direction (issue 31: two held-out models'
   * conflict texts lay over a bond beside the flash) */
  for (int ring = 0; ring < RING_STEPS; ring++)
    for (int i = 0; i < RING_DIRS; i++) {
      double a = atan2(dir.y, dir.x) + 2 * BG_PI * ((i + 1) / 2) * (i % 2 ? 1 : -1) / RING_DIRS;
      bg_vec u = bg_v(cos(a), sin(a));
      cand[16 + ring * RING_DIRS + i] = bg_vadd(p, bg_vscale(u, 7 + fabs(u.x) * w / 2 + fabs(u.y) * h / 2 + 6 * ring));
    }
  bg_vec q = cand[bg_place_best(d, cand, 16 + RING_STEPS * RING_DIRS, w, h)];
  if (d->show & (BG_SHOW_PATHS | BG_SHOW_LOOPS) || d->o.highlight_kind) bg_text_halo(d, text, q, size);
  bg_scene_text(&d->scene, text, q.x, q.y, size, 0.5, 0.5, bg_diagram_ink(d, st->conflict, hot), role);
}

void bg_draw_conflicts(bg_diagram *d) {
  for (int k = 0; k < d->a->nconflict; k++) draw_conflict(d, k);
}

/* ---------------------------------------------------------------- legend */
typedef struct legend {
  bg_diagram *d;
  double x, y, size, row, sample;
} legend;

/* A legend line; its subscripts (written at 70 %) are set larger where 70 %
 * of the legend's size would be below 6 pt (bg_sub_percent). */
static void legend_text(legend *L, const char *markup) {
  bg_strbuf t = {0};
  char want[32];
  snprintf(want, sizeof want, "size=\"%d%%\"", bg_sub_percent(L->size));
  for (const char *p = markup; *p;) {
    const char *q = strstr(p, "size=\"70%\"");
    if (!q) {
      bg_sb_puts(&t, p);
      break;
    }
    bg_sb_putn(&t, p, (size_t)(q - p)), bg_sb_puts(&t, want);
    p = q + strlen("size=\"70%\"");
  }
  bg_scene_text(&L->d->scene, bg_sb_str(&t), L->x + L->sample + 8, L->y, L->size, 0, 0.5,
                L->d->st.fg, "legend-text");
  bg_sb_free(&t);
  L->y += L->row;
}

static bg_scene_item *sample_line(legend *L, const char *role, bg_rgba c, double w) {
  bg_scene_item *it = bg_scene_begin(&L->d->scene, BG_ITEM_STROKE, "%s", role);
  it->color = c, it->width = w, it->round = 1;
  bg_scene_move(&L->d->scene, L->x, L->y);
  bg_scene_line(&L->d->scene, L->x + L->sample, L->y);
  return it;
}

/* A bond ending in a causal stroke; doubled = the print style's derivative mark. */
static void sample_stroke(legend *L, bg_rgba c, int doubled) {
  const bg_style *st = &L->d->st;
  sample_line(L, "legend-sample", st->fg, st->line_width);
  bg_scene_item *it = bg_scene_begin(&L->d->scene, BG_ITEM_STROKE, "legend-sample");
  it->color = c, it->width = 1.5 * st->line_width;
  double x = L->x + L->sample, h = 4.5 * st->line_width;
  for (int k = 0; k <= doubled; k++) {
    bg_scene_move(&L->d->scene, x - k * 2.5 * st->line_width, L->y - h);
    bg_scene_line(&L->d->scene, x - k * 2.5 * st->line_width, L->y + h);
  }
}

/* The cross the print style sets beside a conflicting stroke (diagram.c). */
static void sample_cross(legend *L) {
  const bg_style *st = &L->d->st;
  bg_scene_item *it = bg_scene_begin(&L->d->scene, BG_ITEM_STROKE, "legend-sample");
  it->color = st->conflict, it->width = 1.5 * st->line_width;
  double x = L->x + L->sample - 5 * st->line_width, h = 0.7 * 4.5 * st->line_width * BG_SQRT1_2;
  bg_scene_move(&L->d->scene, x - h, L->y - h);
  bg_scene_line(&L->d->scene, x + h, L->y + h);
  bg_scene_move(&L->d->scene, x - h, L->y + h);
  bg_scene_line(&L->d->scene, x + h, L->y - h);
}

static int any_derivative(const bg_diagram *d) {
  for (int e = 0; d->a && e < d->m->nelem; e++)
    if (d->a->elem_caus[e] == BG_CAUS_DERIVATIVE) return 1;
  return 0;
}

static void legend_conventions(legend *L) {
  bg_diagram *d = L->d;
  const bg_style *st = &d->st;
  bg_scene_item *it = sample_line(L, "legend-sample", st->fg, st->line_width);
  double len = 7 * st->line_width * BG_SQRT1_2, x = L->x + L->sample;
  double side = st->harpoon == BG_HARPOON_DOWN ? 1 : -1;
  bg_scene_line(&d->scene, x - len, L->y + side * len); /* the barb continues the path */
  legend_text(L, "half arrow: positive direction of power");
  if (d->a && (d->show & BG_SHOW_STROKES)) {
    sample_stroke(L, st->fg, 0);
    legend_text(L, "causal stroke: the end where the effort is an input");
    if (any_derivative(d)) {
      sample_stroke(L, st->derivative, st->derivative_double);
      legend_text(L, "derivative causality");
    }
  }
  if (d->a && d->a->nconflict && ((d->show & BG_SHOW_CONFLICTS) || d->o.highlight_kind == 'c')) {
    sample_stroke(L, st->conflict, 0);
    if (st->conflict_cross) sample_cross(L);
    it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "legend-sample");
    it->fill = st->conflict, it->color = st->flash_outline, it->width = 0.5;
    flash_path(&d->scene, bg_v(L->x + L->sample / 2 - 2, L->y - 1), 11);
    /* as drawn: the print style's conflicts are black strokes with a cross */
    legend_text(L, st->conflict_cross ? "causal conflict: stroke with a cross, flash with type (and degree k)"
                                      : "causal conflict: stroke in red, flash with type (and degree k)");
  }
  if (d->a && d->a->nlag) {
    it = sample_line(L, "legend-sample", st->fg, st->line_width);
    it->dash[0] = 4, it->dash[1] = 2;
    legend_text(L, "Sf*: artificial flow source (Lagrange causality)");
  }
  if (bg_scene_count(&d->scene, "signal") && (d->show & BG_SHOW_SIGNALS)) {
    it = sample_line(L, "legend-sample", st->signal, st->signal_width);
    if (st->signal_dashed) it->dash[0] = 3, it->dash[1] = 2;
    it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "legend-sample");
    it->fill = it->color = st->signal, it->width = 0;
    bg_geom_arrowhead(&d->scene, bg_v(L->x + L->sample, L->y), bg_v(1, 0), 6, 4);
    legend_text(L, bg_scene_count(&d->scene, "state-node")
                       ? "modulating signal; \u222b : x integrates a user state x"
                       : "modulating signal");
  }
  if (d->show & BG_SHOW_VARIABLES) {
    L->x -= L->sample + 8;
    legend_text(L, "e<span size=\"70%\" rise=\"-2pt\">k</span>, f<span size=\"70%\" rise=\"-2pt\">k</span>: "
                   "effort (barb side) and flow of bond k");
    L->x += L->sample + 8;
  }
}

/* A sample of path or loop i, as drawn: colour, dash and an arrowhead. */
static void sample_layer(legend *L, int kind, int i) {
  bg_diagram *d = L->d;
  bg_rgba c = bg_layer_color(d, kind, i);
  bg_scene_item *it = sample_line(L, "legend-sample", c, d->st.layer_width);
  bg_layer_dash(d, kind, i, it->dash);
  it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "legend-sample");
  it->fill = it->color = c, it->width = 0;
  bg_geom_arrowhead(&d->scene, bg_v(L->x + L->sample / 2 + 2.5, L->y), bg_v(1, 0), 5, 4);
}

static int has_kind(const bg_model *m, int k1, int k2) {
  for (int e = 0; e < m->nelem; e++)
    if (m->elem_kind[e] == k1 || m->elem_kind[e] == k2) return 1;
  return 0;
}

enum { LEGEND_MAX_LAYERS = 24 }; /* per kind; the JSON and the report list them all */

static void legend_layers(legend *L, int kind, int count) {
  bg_diagram *d = L->d;
  int hot = d->o.highlight_kind == kind ? d->o.highlight_index - 1 : -1;
  int shown = d->show & (kind == 'p' ? BG_SHOW_PATHS : BG_SHOW_LOOPS);
  if (!shown) count = hot + 1; /* drawn only because highlighted: list that one */
  for (int i = 0; i < count; i++) {
    if ((!shown || i >= LEGEND_MAX_LAYERS) && i != hot) continue;
    sample_layer(L, kind, i);
    bg_strbuf t = {0};
    bg_layer_describe(d, kind, i, 1, &t);
    if (kind == 'l' && d->loop_path[i] >= 0) bg_sb_printf(&t, ", drawn with P%d", d->loop_path[i] + 1);
    legend_text(L, bg_sb_str(&t));
    bg_sb_free(&t);
  }
  if (shown && count > LEGEND_MAX_LAYERS) {
    double x = L->x;
    char more[96];
    snprintf(more, sizeof more, "\u2026 %d more %s", count - LEGEND_MAX_LAYERS,
             kind == 'p' ? "causal paths" : "topological loops");
    L->x -= L->sample + 8;
    legend_text(L, more);
    L->x = x;
  }
}

void bg_draw_legend(bg_diagram *d) {
  double x0, y0, x1, y1;
  bg_scene_bbox(&d->scene, &x0, &y0, &x1, &y1);
  double size = d->st.font_size * 0.8;
  legend L = {d, x0, y1 + 16 + size / 2, size, size * 1.45, 26};
  legend_conventions(&L);
  int paths = d->a && ((d->show & BG_SHOW_PATHS) || d->o.highlight_kind == 'p') && d->a->npath;
  int loops = d->a && ((d->show & BG_SHOW_LOOPS) || d->o.highlight_kind == 'l') && d->a->ntloop;
  if (paths || loops) {
    double x = L.x;
    L.x -= L.sample + 8;
    legend_text(&L, paths && loops ? "dashed: causal paths Pk and topological loops Lk (G: loop gain), "
                                     "on the left of their signals (arrows)"
                    : paths ? "dashed: causal paths Pk, on the left of their signals (arrows)"
                            : "dashed: topological loops Lk (G: loop gain), on the left of their "
                              "signals (arrows)");
    legend_text(&L, paths ? "effort travels towards the causal stroke, flow away from it; a causal "
                            "path is drawn as the flat loop it closes"
                          : "effort travels towards the causal stroke, flow away from it");
    L.x = x;
  }
  if (paths) legend_layers(&L, 'p', d->a->npath);
  if (loops) legend_layers(&L, 'l', d->a->ntloop);
  L.sample = -8; /* text rows without a sample */
  const bg_model *m = d->m;
  if (has_kind(m, BG_ELEM_TF, BG_ELEM_MTF))
    legend_text(&L, "a \u2192 TF \u2192 b:  e<span size=\"70%\" rise=\"-2pt\">b</span> = n e"
                    "<span size=\"70%\" rise=\"-2pt\">a</span>,  f<span size=\"70%\" rise=\"-2pt\">a</span>"
                    " = n f<span size=\"70%\" rise=\"-2pt\">b</span>  (n: the modulus)");
  if (has_kind(m, BG_ELEM_GY, BG_ELEM_MGY))
    legend_text(&L, "a \u2192 GY \u2192 b:  e<span size=\"70%\" rise=\"-2pt\">a</span> = r f"
                    "<span size=\"70%\" rise=\"-2pt\">b</span>,  e<span size=\"70%\" rise=\"-2pt\">b</span>"
                    " = r f<span size=\"70%\" rise=\"-2pt\">a</span>  (r: the modulus)");
}
