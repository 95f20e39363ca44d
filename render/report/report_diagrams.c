/* SPDX-License-Identifier: BSD-3-Clause */
/* Report sections 2 and 3: the diagram with every layer, and one
 * highlighted diagram per path, loop and conflict worth showing. A diagram
 * is scaled to fit its space, but never so far that its smallest text falls
 * below RP_MIN_TEXT points: then it goes on a page of its own, or its
 * drawing is cut into even parts on several pages with its legend placed
 * whole (the whole diagram), or it is cropped to the highlighted item
 * (highlights). Measured by tests/unit/test_report_split.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"
#include "report/report_int.h"

#define MAX_SCALE 1.25     /* small diagrams are enlarged at most this much */
#define MAX_TILES 48       /* pages for the whole diagram */
#define MAX_GRID 1024      /* tiles of the grid, empty ones included */
#define MAX_HL_TILES 4     /* pages for one cropped highlight */
#define TILE_OVERLAP 18.0  /* points of the diagram repeated on neighbouring tiles */
#define MAX_HIGHLIGHTS 12  /* redrawn from section 2's layout: no layout of their own */
/* A tile map of a diagram with more items than this is an image of
 * MAP_RASTER pixels a point (216 dpi): as vectors cairo recorded every item
 * of the diagram on the map's page, 2.7 GB at 100 000 masses, where its
 * text was a few hundredths of a point high. */
#define MAP_VECTOR_ITEMS 20000
#define MAP_RASTER 3.0

/* ---------------------------------------------------------------- building */
/* Keeps d until the PDF is written; NULL marks the report failed. */
bg_diagram *rp_keep(rp_ctx *c, bg_diagram *d) {
  if (!d) {
    c->failed = 1;
    return NULL;
  }
  if (c->ndiag == c->capdiag) {
    c->capdiag = c->capdiag ? 2 * c->capdiag : 8;
    c->diag = bg_xrealloc(c->diag, (size_t)c->capdiag * sizeof *c->diag);
  }
  c->diag[c->ndiag++] = d;
  /* transparent: the page's own items (an overview grid) stay visible */
  d->scene.background.a = 0;
  return d;
}

/* Section 2's diagram: the one layout of the report. */
static bg_diagram *build_full(rp_ctx *c) {
  bg_render_opts o = {0};
  if (c->in->ropts) o = *c->in->ropts;
  o.show = BG_SHOW_ALL, o.highlight_kind = 0, o.highlight_index = 0;
  return c->full = rp_keep(c, bg_diagram_build(c->m, c->a, &o, c->dg));
}

/* A highlighted diagram: the full diagram's layout drawn again, so nodes are
 * where they are in section 2. Not kept: its pages place only the part of
 * its scene that keep_cropped keeps. */
static bg_diagram *build_highlight(rp_ctx *c, int kind, int index) {
  bg_diagram *d = !c->full ? NULL
                  : rp_hl_from_full(c) ? rp_hl_view(c, kind, index) /* a large diagram */
                  : bg_diagram_redraw(c->full, BG_SHOW_DEFAULT, kind, index, c->dg);
  if (!d) c->failed = 1;
  return d;
}

/* Keeps the items of dg's scene that pages placing rectangles inside r (x, y, w, h)
 * replay: those meeting r grown by the cull margin (BG_PLACE_CULL_PAD), so
 * the PDF is the same as with all of s. A highlight of a large diagram shows
 * a small part of it, and thirteen whole scenes kept until the PDF is
 * written were most of a large report's memory. */
static const bg_scene *keep_cropped(rp_ctx *c, const bg_diagram *dg, const double r[4]) {
  if (c->nhl == c->caphl) {
    c->caphl = c->caphl ? 2 * c->caphl : 16;
    c->hl = bg_xrealloc(c->hl, (size_t)c->caphl * sizeof *c->hl);
  }
  const double pad = BG_PLACE_CULL_PAD;
  const double clip[4] = {r[0] - pad, r[1] - pad, r[0] + r[2] + pad, r[1] + r[3] + pad};
  bg_scene *k = bg_xmalloc(sizeof *k);
  if (rp_hl_from_full(c)) rp_hl_crop(dg, clip, k);
  else bg_scene_crop(&dg->scene, clip, k);
  k->background.a = 0; /* as rp_keep: the page's own items stay visible */
  return c->hl[c->nhl++] = k;
}

static double min_text(const bg_scene *s) {
  double m = 0;
  for (int i = 0; i < s->nitem; i++)
    if (s->item[i].kind == BG_ITEM_TEXT && (m == 0 || s->item[i].size < m)) m = s->item[i].size;
  return m > 0 ? m : RP_MIN_TEXT;
}

static double smallest_scale(const bg_scene *s) { return RP_MIN_TEXT / min_text(s); }

static double fit_scale(double w, double h, double availw, double availh, double cap) {
  double s = availw / w;
  if (availh / h < s) s = availh / h;
  return s < cap ? s : cap;
}

static void note(rp_doc *d, const char *fmt, double v) {
  char buf[256];
  snprintf(buf, sizeof buf, fmt, v);
  rp_para(d, buf, RP_SIZE_SMALL, 0, 0, rp_grey);
}

/* ---------------------------------------------------------------- tiles */
typedef struct tiling {
  int nx, ny;
  double tw, th;     /* tile size in diagram points */
  double stepx, stepy;
  double scale;
  int num[MAX_GRID]; /* part number of each tile (row-major), 0: nothing drawn there */
  int nused;
} tiling;

static int is_legend(const bg_scene_item *it) { return !strncmp(it->role, "legend", 6); }

static void item_box(const bg_scene *s, const bg_scene_item *it, double b[4]) {
  if (it->kind == BG_ITEM_TEXT) {
    double x = it->x - it->halign * it->tw, y = it->y - it->valign * it->th;
    b[0] = fmin(b[0], x), b[1] = fmin(b[1], y);
    b[2] = fmax(b[2], x + it->tw), b[3] = fmax(b[3], y + it->th);
    return;
  }
  bg_scene_op o_;
  for (int i = 0; bg_scene_next_op(s, it, &i, &o_);) {
    const bg_scene_op *o = &o_;
    int npt = o->code == BG_OP_CURVE ? 3 : o->code == BG_OP_CLOSE ? 0 : 1;
    for (int k = 0; k < npt; k++) {
      b[0] = fmin(b[0], o->x[k]), b[1] = fmin(b[1], o->y[k]);
      b[2] = fmax(b[2], o->x[k]), b[3] = fmax(b[3], o->y[k]);
    }
  }
}

/* A diagram's drawing and its legend (bg_draw_legend puts it below the
 * drawing) as regions x, y, w, h of the scene, each with its smallest
 * text: a split diagram's parts cover the drawing only, and its legend is
 * placed whole on a page of its own (legend[2] 0: no legend). The drawing
 * keeps the style's margin but stops half way down the gap above the
 * legend, so no part shows a sliver of the legend's first row. */
typedef struct regions {
  double draw[4], legend[4];
  double draw_text, legend_text;
} regions;

static void split_regions(const bg_scene *s, double margin, regions *g) {
  double d[4] = {1e300, 1e300, -1e300, -1e300}, l[4] = {1e300, 1e300, -1e300, -1e300};
  g->draw_text = g->legend_text = 0;
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    int leg = is_legend(it);
    item_box(s, it, leg ? l : d);
    double *m = leg ? &g->legend_text : &g->draw_text;
    if (it->kind == BG_ITEM_TEXT && (*m == 0 || it->size < *m)) *m = it->size;
  }
  if (d[0] > d[2]) d[0] = d[1] = 0, d[2] = s->width, d[3] = s->height;
  double x0 = fmax(0, d[0] - margin), y0 = fmax(0, d[1] - margin);
  double x1 = fmin(s->width, d[2] + margin), y1 = fmin(s->height, d[3] + margin);
  g->legend[2] = 0;
  if (l[0] <= l[2]) {
    double gap = (d[3] + l[1]) / 2, pad = 4;
    if (y1 > gap) y1 = gap;
    double ly0 = fmax(gap, l[1] - pad), lx0 = fmax(0, l[0] - pad);
    g->legend[0] = lx0, g->legend[1] = ly0;
    g->legend[2] = fmin(s->width, l[2] + pad) - lx0, g->legend[3] = fmin(s->height, l[3] + pad) - ly0;
  }
  g->draw[0] = x0, g->draw[1] = y0, g->draw[2] = x1 - x0, g->draw[3] = y1 - y0;
  if (g->draw_text <= 0) g->draw_text = RP_MIN_TEXT;
  if (g->legend_text <= 0) g->legend_text = RP_MIN_TEXT;
}

/* Even parts of a w x h region on pages cw x ch at scale s or above: the
 * fewest columns and rows at s, then the largest scale (at most cap) at
 * which they still cover the region. Every part is the same size and
 * neighbours share exactly TILE_OVERLAP: spreading fixed-size tiles over
 * the region instead repeated up to 90 % of a part on its neighbour. */
static int tiles_for(double w, double h, double cw, double ch, double s, double cap, tiling *t) {
  const double ov = TILE_OVERLAP;
  double tw = cw / s, th = ch / s;
  t->nx = w <= tw ? 1 : (int)ceil((w - ov) / (tw - ov));
  t->ny = h <= th ? 1 : (int)ceil((h - ov) / (th - ov));
  t->tw = (w + (t->nx - 1) * ov) / t->nx, t->th = (h + (t->ny - 1) * ov) / t->ny;
  t->scale = fmin(fmin(cw / t->tw, ch / t->th), fmax(cap, s));
  t->stepx = t->nx > 1 ? t->tw - ov : 0;
  t->stepy = t->ny > 1 ? t->th - ov : 0;
  return t->nx * t->ny;
}

/* Tiles [lo, hi] along one axis that [a, b] (relative to the region)
 * reaches into by more than half the overlap. */
static void tile_range(double a, double b, double step, double size, int n, int *lo, int *hi) {
  double in = TILE_OVERLAP / 2;
  if (step <= 0) {
    *lo = 0, *hi = n - 1;
    return;
  }
  *lo = (int)ceil((a - size + in) / step), *hi = (int)floor((b - in) / step);
  if (*lo < 0) *lo = 0;
  if (*hi > n - 1) *hi = n - 1;
}

/* Marks a box (region coordinates) in every tile it reaches, counting the
 * tiles newly marked in t->nused. */
static void mark_box(tiling *t, const double b[4]) {
  int i0, i1, j0, j1;
  tile_range(b[0], b[2], t->stepx, t->tw, t->nx, &i0, &i1);
  tile_range(b[1], b[3], t->stepy, t->th, t->ny, &j0, &j1);
  for (int j = j0; j <= j1; j++)
    for (int i = i0; i <= i1; i++)
      if (!t->num[j * t->nx + i]) t->num[j * t->nx + i] = 1, t->nused++;
}

/* Numbers the tiles of region r that show something: a text or a path
 * point of the scene (its legend aside: placed on its own) beyond the
 * overlap. Returns the count; stops counting once it is above max (a scale
 * plan_tiles refuses: most of its steps on a large diagram, each of which
 * went through every item). */
static int number_tiles(const bg_scene *s, const double r[4], int max, tiling *t) {
  memset(t->num, 0, sizeof t->num);
  t->nused = 0;
  for (int k = 0; k < s->nitem && t->nused <= max; k++) {
    const bg_scene_item *it = &s->item[k];
    if (is_legend(it)) continue;
    if (it->kind == BG_ITEM_TEXT) {
      double b[4] = {1e300, 1e300, -1e300, -1e300};
      item_box(s, it, b);
      double rb[4] = {b[0] - r[0], b[1] - r[1], b[2] - r[0], b[3] - r[1]};
      mark_box(t, rb);
      continue;
    }
    bg_scene_op o_;
    for (int i = 0; bg_scene_next_op(s, it, &i, &o_);) {
      const bg_scene_op *o = &o_;
      int npt = o->code == BG_OP_CURVE ? 3 : o->code == BG_OP_CLOSE ? 0 : 1;
      for (int q = 0; q < npt; q++) {
        double rb[4] = {o->x[q] - r[0], o->y[q] - r[1], o->x[q] - r[0], o->y[q] - r[1]};
        mark_box(t, rb);
      }
    }
  }
  if (t->nused > max) return t->nused;
  t->nused = 0;
  for (int i = 0; i < t->nx * t->ny; i++)
    if (t->num[i]) t->num[i] = ++t->nused;
  return t->nused;
}

/* The largest scale not above `scale` (then grown up to cap to even the
 * parts) with at most max pages showing something (smaller than asked
 * only when even that many are not enough). */
static void plan_tiles(const bg_scene *s, const double r[4], double cw, double ch, double scale,
                       double cap, int max, tiling *t) {
  for (;; scale *= 0.92)
    if (tiles_for(r[2], r[3], cw, ch, scale, cap, t) <= MAX_GRID && number_tiles(s, r, max, t) <= max) return;
}

/* A map of the tiles: the whole region shrunk onto the page with the parts
 * numbered, leaving `reserve` points below it (the legend's). */
static void overview(rp_doc *d, const bg_scene *s, const double r[4], const tiling *t, double reserve) {
  double cw = rp_content_w(d), ch = rp_room(d) - 10 - reserve;
  double sc = fit_scale(r[2], r[3], cw, ch, 1);
  double x0 = rp_left() + (cw - r[2] * sc) / 2, y0 = d->y;
  bg_scene *pg = rp_scene(d);
  for (int j = 0; j < t->ny; j++)
    for (int i = 0; i < t->nx; i++) {
      if (!t->num[j * t->nx + i]) continue;
      double x = x0 + i * t->stepx * sc, y = y0 + j * t->stepy * sc;
      bg_scene_item *it = bg_scene_begin(pg, BG_ITEM_FILL, "tile");
      it->fill = (bg_rgba){0.2, 0.35, 0.7, 0.06}, it->color = (bg_rgba){0.2, 0.35, 0.7, 0.8};
      it->width = 0.6;
      bg_scene_move(pg, x, y), bg_scene_line(pg, x + t->tw * sc, y);
      bg_scene_line(pg, x + t->tw * sc, y + t->th * sc), bg_scene_line(pg, x, y + t->th * sc);
      bg_scene_close(pg);
      char num[32];
      snprintf(num, sizeof num, "<b>%d</b>", t->num[j * t->nx + i]);
      rp_text(d, num, x + 3, y + 2, 9, 0, (bg_rgba){0.2, 0.35, 0.7, 1});
    }
  rp_place(d, s, r[0], r[1], r[2], r[3], x0, y0, sc);
  if (s->nitem > MAP_VECTOR_ITEMS) {
    rp_page *p = d->page[d->npage - 1];
    p->place[p->nplace - 1].raster = MAP_RASTER;
  }
  d->y += r[3] * sc + 6;
}

/* The region r (x, y, w, h of scene s) over t->nx x t->ny pages: a page
 * each, or with `pack` each below the one before while the page (in the
 * same orientation) holds it with its caption: a highlight too wide for a
 * page is a strip whose parts each took a page of their own, three
 * quarters of it empty (hydraulic_bridge's path 3, issue 31). */
#define TILE_CAPTION 14.0 /* a part's caption line and the gap below it */
static void emit_tiles(rp_doc *d, const bg_scene *s, const double r[4], const tiling *t,
                       int landscape, const char *what, int pack) {
  for (int j = 0; j < t->ny; j++)
    for (int i = 0; i < t->nx; i++) {
      if (!t->num[j * t->nx + i]) continue;
      const rp_page *p = d->npage ? d->page[d->npage - 1] : NULL;
      int same_way = p && (p->sc.width > p->sc.height) == (landscape != 0);
      if (pack && same_way && rp_room(d) >= 8 + TILE_CAPTION + t->th * t->scale) d->y += 8;
      else rp_new_page(d, landscape);
      char cap[256];
      if (t->nused == 1) snprintf(cap, sizeof cap, "%s, at %.0f %%", what, 100 * t->scale);
      else
        snprintf(cap, sizeof cap, "%s, part %d of %d (row %d, column %d), at %.0f %%", what,
                 t->num[j * t->nx + i], t->nused, j + 1, i + 1, 100 * t->scale);
      rp_para(d, cap, RP_SIZE_SMALL, 0, 0, rp_grey);
      d->y += 2;
      double sx = r[0] + i * t->stepx, sy = r[1] + j * t->stepy;
      rp_place(d, s, sx, sy, t->tw, t->th, rp_left(), d->y, t->scale);
      d->y += t->th * t->scale;
    }
}

/* A cropped highlight of one column of parts (tiling t: nx 1, ny > 1)
 * flowed like text from the room left below its heading: the first part as
 * tall as that room, the others a page each (the last as tall as what is
 * left), neighbours sharing TILE_OVERLAP. Its heading and text had stood at
 * the foot of a page whose rest stayed empty, the parts on the pages after
 * (a 60-bond model's report: five highlights so, up to 60 % of a page
 * empty). heights[0..n): each part's height in diagram points; n, or 0
 * when the room left is under FLOW_MIN of a page's (so also when the
 * heading itself goes to the next page) or the parts would be more than
 * MAX_HL_TILES (the even parts are kept then). */
#define FLOW_MIN 0.3
static int flow_parts(const rp_doc *d, const double r[4], const tiling *t, double room0, double *heights) {
  /* a part after the first has a page of its own: its caption's line, 2 pt
   * and itself (a heading's line and gap more were counted: 22 pt of every
   * such page left empty) */
  double page = rp_page_room(d), full = page - rp_line_height(d->font, RP_SIZE_SMALL) - 2 - 1;
  if (t->nx != 1 || t->ny < 2 || room0 < FLOW_MIN * page) return 0;
  double h0 = room0 / t->scale, hf = full / t->scale, y = 0;
  if (h0 <= TILE_OVERLAP || hf <= TILE_OVERLAP) return 0;
  int n = 0;
  for (double h = h0;; h = hf) {
    if (n == MAX_HL_TILES) return 0;
    heights[n++] = fmin(h, r[3] - y);
    if (y + h >= r[3]) return n;
    y += h - TILE_OVERLAP;
  }
}

/* The parts flow_parts planned, the first at the cursor, each next one
 * below the one before while the page holds it, else on a new page. */
static void emit_flow(rp_doc *d, const bg_scene *s, const double r[4], double scale, const double *heights, int n,
                      const char *what) {
  double y = r[1];
  for (int i = 0; i < n; i++) {
    if (i == 0 || rp_room(d) >= 8 + TILE_CAPTION + heights[i] * scale) d->y += 8;
    else rp_new_page(d, 0);
    char cap[256];
    snprintf(cap, sizeof cap, "%s, part %d of %d, at %.0f %%", what, i + 1, n, 100 * scale);
    rp_para(d, cap, RP_SIZE_SMALL, 0, 0, rp_grey);
    d->y += 2;
    rp_place(d, s, r[0], y, r[2], heights[i], rp_left(), d->y, scale);
    d->y += heights[i] * scale;
    y += heights[i] - TILE_OVERLAP;
  }
}

/* ---------------------------------------------------------------- section 2 */
static void diagram_caption(rp_ctx *c, bg_diagram *dg) {
  bg_strbuf b = {0};
  bg_sb_puts(&b, "Every layer: causal strokes (derivative causality in orange, conflicts in red), "
                 "bond numbers, causal paths P<i>k</i>, topological loops L<i>k</i> with their gains, "
                 "conflicts, modulating signals and the legend. Layout: ");
  rp_esc(&b, bg_diagram_engine(dg));
  bg_sb_puts(&b, ".");
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_BODY, 0, 0, rp_ink);
  bg_sb_free(&b);
  rp_gap(&c->body, 4);
}

/* Content width and the room of a full page of either orientation. */
static void page_box(int land, double *cw, double *ch) {
  *cw = (land ? RP_A4_H : RP_A4_W) - 2 * RP_MARGIN_X;
  *ch = (land ? RP_A4_W : RP_A4_H) - RP_MARGIN_TOP - RP_MARGIN_BOTTOM;
}

/* Where a slice of the legend from y0 may end to fit up to y1: moved up
 * above any legend item it would cut (its rows stand apart). */
static double legend_cut_at(const bg_scene *s, double y0, double y1) {
  for (int moved = 1; moved;) {
    moved = 0;
    for (int i = 0; i < s->nitem; i++) {
      if (!is_legend(&s->item[i])) continue;
      double b[4] = {1e300, 1e300, -1e300, -1e300};
      item_box(s, &s->item[i], b);
      if (b[1] < y1 && b[3] > y1 && b[1] - 0.5 > y0) y1 = b[1] - 0.5, moved = 1;
    }
  }
  return y1;
}

/* The legend's scale: the parts', smaller to fit a page, never
 * below its own readable scale (a legend row wider than the page at 6 pt
 * is cut at the page's edge rather than made unreadable). */
static double legend_scale(const rp_doc *d, const regions *g, double scale) {
  double sc = fmin(scale, rp_content_w(d) / g->legend[2]), lmin = RP_MIN_TEXT / g->legend_text;
  sc = fmin(sc, (rp_page_room(d) - 8) / g->legend[3]); /* a page of its own holds it whole */
  return sc < lmin ? lmin : sc;
}

/* A split diagram's legend at the cursor, whole: on the next page when it
 * does not fit below the cursor, and only when it is taller than a page
 * in slices cut between its rows, side by side in balanced columns while
 * the page's width allows, then on further pages. */
static void place_legend(rp_doc *d, const bg_scene *s, const regions *g, double scale, int land) {
  const double *L = g->legend;
  if (L[2] <= 0) return;
  double sc = legend_scale(d, g, scale), end = L[1] + L[3], colw = L[2] * sc + 12;
  int ncol = (int)floor((rp_content_w(d) + 12) / colw);
  if (ncol < 1) ncol = 1;
  if (L[3] * sc > rp_room(d) - 4 && (L[3] * sc > (rp_room(d) - 4) * ncol || rp_room(d) < 0.5 * rp_page_room(d)))
    rp_new_page(d, land);
  double top = d->y, bottom = top, x = rp_left(), row = 2 * g->legend_text;
  int col = 0;
  for (double y = L[1]; y < end - 0.5;) {
    double room = (rp_room(d) - 4) / sc, left = end - y;
    if (room < row && d->y > RP_MARGIN_TOP) { /* not a row's room left: the next page */
      rp_new_page(d, land), top = bottom = d->y, x = rp_left(), col = 0;
      continue;
    }
    double cut = y + fmin(room, left > room ? left / (ncol - col) + row : left);
    cut = cut >= end ? end : legend_cut_at(s, y, cut);
    if (cut < y + 0.5) cut = fmin(end, y + room); /* a row taller than a page: cut */
    rp_place(d, s, L[0], y, L[2], cut - y, x, top, sc);
    bottom = fmax(bottom, top + (cut - y) * sc + 4);
    if ((y = cut) >= end - 0.5) break;
    if (++col < ncol) x += colw;
    else rp_new_page(d, land), top = bottom = d->y, x = rp_left(), col = 0;
  }
  d->y = bottom;
}

/* The section's one orientation and its parts. A diagram a page holds
 * whole at a readable size takes its own orientation (landscape when
 * wider than tall), or the other one when only that holds it; otherwise
 * its drawing is cut into parts in the orientation that needs fewer (of
 * as many, the one with the larger scale, then its own). own: 1 when the
 * whole diagram fits one page. */
static int choose_plan(const bg_scene *s, const regions *g, double smin, tiling *t, int *own) {
  int land = s->width > 1.15 * s->height;
  double cw, ch;
  for (int k = 0; k < 2; k++) {
    int o = k ? !land : land;
    page_box(o, &cw, &ch);
    if (fit_scale(s->width, s->height, cw, ch - 14, MAX_SCALE) >= smin) {
      const double whole[4] = {0, 0, s->width, s->height};
      *own = 1;
      plan_tiles(s, whole, cw, ch - 14, smin, MAX_SCALE, 1, t);
      return o;
    }
  }
  *own = 0;
  double dmin = RP_MIN_TEXT / g->draw_text;
  int grid[2];
  for (int o = 0; o < 2; o++) {
    page_box(o, &cw, &ch);
    grid[o] = tiles_for(g->draw[2], g->draw[3], cw, ch - 14, dmin, MAX_SCALE, t);
  }
  int best = land;
  if (grid[0] <= MAX_TILES || grid[1] <= MAX_TILES) { /* else the scale shrinks in either: keep its own */
    page_box(!land, &cw, &ch);
    plan_tiles(s, g->draw, cw, ch - 14, dmin, MAX_SCALE, MAX_TILES, t);
    int other = t->nused;
    double other_scale = t->scale;
    page_box(land, &cw, &ch);
    plan_tiles(s, g->draw, cw, ch - 14, dmin, MAX_SCALE, MAX_TILES, t);
    if (other < t->nused || (other == t->nused && other_scale > t->scale + 1e-9)) best = !land;
    else return land;
  }
  page_box(best, &cw, &ch);
  plan_tiles(s, g->draw, cw, ch - 14, dmin, MAX_SCALE, MAX_TILES, t);
  return best;
}

void rp_sec_diagram(rp_ctx *c) {
  bg_diagram *dg = build_full(c);
  if (!dg) return;
  rp_doc *d = &c->body;
  const bg_scene *s = &dg->scene;
  double w = s->width, h = s->height, smin = smallest_scale(s);
  regions g;
  split_regions(s, dg->st.margin, &g);
  tiling t;
  int own;
  int land = choose_plan(s, &g, smin, &t, &own);
  rp_new_page(d, land);
  rp_section(d, "Diagram", 1, 0, 0);
  diagram_caption(c, dg);
  double cw = rp_content_w(d), ch = rp_room(d) - 14;
  double sc = fit_scale(w, h, cw, ch, MAX_SCALE);
  if (sc >= smin) {
    rp_place(d, s, 0, 0, w, h, rp_left() + (cw - w * sc) / 2, d->y, sc);
    d->y += h * sc + 4;
    note(d, "Shown at %.0f %% of its natural size.", 100 * sc);
    return;
  }
  const double whole[4] = {0, 0, w, h};
  const double *r = own ? whole : g.draw;
  bg_strbuf b = {0};
  if (own) /* a page of its own is enough: no parts, no map */
    bg_sb_printf(&b, "The diagram does not fit below this text at a readable size (its smallest "
                     "text would be below %.0f pt), so it follows on a page of its own at %.0f %%.",
                 RP_MIN_TEXT, 100 * t.scale);
  else if (t.nused == 1)
    bg_sb_printf(&b, "The diagram is too large for one page at a readable size (its smallest text "
                     "would be below %.0f pt), so its legend is below and its drawing follows on a "
                     "page of its own at %.0f %%.", RP_MIN_TEXT, 100 * t.scale);
  else
    bg_sb_printf(&b, "The diagram is too large for one page at a readable size (its smallest text "
                     "would be below %.0f pt), so its drawing follows in %d parts at %.0f %%, each "
                     "repeating %.0f pt of its neighbours; the map below shows where each part lies, "
                     "and the legend follows it.", RP_MIN_TEXT, t.nused, 100 * t.scale, TILE_OVERLAP);
  if (t.scale < (own ? smin : RP_MIN_TEXT / g.draw_text) - 1e-9)
    bg_sb_puts(&b, " Even so the diagram needs more pages than the report allows, "
                   "so its text is below that size.");
  rp_para(d, bg_sb_str(&b), RP_SIZE_BODY, 0, 0, rp_ink);
  bg_sb_free(&b);
  rp_gap(d, 4);
  if (t.nused > 1) {
    /* the legend under the map when both fit the page with a map of some size */
    double lh = g.legend[2] > 0 ? g.legend[3] * legend_scale(d, &g, t.scale) + 8 : 0;
    overview(d, s, r, &t, lh < 0.6 * rp_room(d) ? lh : 0);
  }
  if (!own) place_legend(d, s, &g, t.scale, land);
  emit_tiles(d, s, r, &t, land, "Diagram", 0);
}

/* ---------------------------------------------------------------- section 3: choice */
typedef struct hl {
  int kind;  /* 'p', 'l', 'c' */
  int index; /* 0-based */
  int prio;  /* lower is shown first */
  int cloop; /* 'l': the causal loop it stands for, or -1 */
} hl;

static int cause_is(const bg_analysis *a, int l, const char *what, int *k) {
  const char *cs = a->tloop_cause ? a->tloop_cause[l] : NULL;
  size_t n = strlen(what);
  if (!cs || strncmp(cs, what, n) || cs[n] != ' ') return 0;
  *k = atoi(cs + n + 1) - 1;
  return 1;
}

static int path_prio(const bg_analysis *a, int p) {
  if (a->path_class[p] == 1 || a->path_class[p] == 2) return 1;
  if (a->path_order[p] == 0) return 2;
  return a->path_order[p] == BG_PATH_ORDER_NONE ? 4 : 3;
}

static int loop_candidate(const bg_analysis *a, int l, hl *h) {
  int k;
  if (cause_is(a, l, "causal path", &k)) return 0; /* drawn as that path */
  if (cause_is(a, l, "causal loop", &k)) {
    for (int j = 0; j < l; j++) {
      int k2;
      if (cause_is(a, j, "causal loop", &k2) && k2 == k) return 0; /* its other open loop */
    }
    *h = (hl){'l', l, 0, k};
    return 1;
  }
  *h = (hl){'l', l, a->tloop_algebraic[l] ? 1 : 5, -1};
  return 1;
}

static int kind_rank(int kind) { return kind == 'p' ? 0 : kind == 'l' ? 1 : 2; }

static int by_prio(const void *x, const void *y) {
  const hl *a = x, *b = y;
  if (a->prio != b->prio) return a->prio - b->prio;
  if (kind_rank(a->kind) != kind_rank(b->kind)) return kind_rank(a->kind) - kind_rank(b->kind);
  return a->index - b->index;
}

static int by_kind(const void *x, const void *y) {
  const hl *a = x, *b = y;
  if (kind_rank(a->kind) != kind_rank(b->kind)) return kind_rank(a->kind) - kind_rank(b->kind);
  return a->index - b->index;
}

/* Candidates, most telling first; returns how many. */
static int candidates(const bg_analysis *a, hl **out) {
  hl *h = bg_xmalloc(((size_t)a->npath + (size_t)a->ntloop + (size_t)a->nconflict + 1) * sizeof *h);
  int n = 0;
  for (int k = 0; k < a->nconflict; k++) h[n++] = (hl){'c', k, 0, -1};
  for (int p = 0; p < a->npath; p++) h[n++] = (hl){'p', p, path_prio(a, p), -1};
  for (int l = 0; l < a->ntloop; l++) n += loop_candidate(a, l, &h[n]);
  qsort(h, (size_t)n, sizeof *h, by_prio);
  *out = h;
  return n;
}

/* ---------------------------------------------------------------- section 3: drawing */
static int role_is(const char *role, const char *prefix, int k) {
  char want[64];
  snprintf(want, sizeof want, "%s%d", prefix, k);
  return !strcmp(role, want);
}

/* Is item it part of the highlighted item (its layer, hot nodes and bonds)? */
static int hot_item(const bg_diagram *dg, const hl *h, const bg_scene_item *it) {
  const char *r = it->role;
  int k = h->index + 1;
  if (!strncmp(r, "node ", 5)) {
    int e = bg_model_find_elem(dg->m, r + 5);
    return e >= 0 && dg->hot_elem[e];
  }
  if (!strncmp(r, "bond ", 5)) {
    int b = bg_model_find_bond(dg->m, atoi(r + 5));
    return b >= 0 && dg->hot_bond[b];
  }
  if (h->kind == 'p') return role_is(r, "path ", k) || role_is(r, "path-tag ", k);
  if (h->kind == 'l') return role_is(r, "loop ", k) || role_is(r, "gain loop=", k);
  return role_is(r, "flash conflict=", k) || role_is(r, "conflict-text conflict=", k);
}

/* The region around the highlighted item, clamped to the drawn region d
 * (x, y, w, h): x, y, w, h. */
static void hot_region(const bg_diagram *dg, const hl *h, const double d[4], double r[4]) {
  const bg_scene *s = &dg->scene;
  double b[4] = {1e300, 1e300, -1e300, -1e300};
  for (int i = 0; i < s->nitem; i++)
    if (hot_item(dg, h, &s->item[i])) item_box(s, &s->item[i], b);
  if (b[0] > b[2]) b[0] = d[0], b[1] = d[1], b[2] = d[0] + d[2], b[3] = d[1] + d[3];
  double pad = 36;
  b[0] = fmax(d[0], b[0] - pad), b[1] = fmax(d[1], b[1] - pad);
  b[2] = fmin(d[0] + d[2], b[2] + pad), b[3] = fmin(d[1] + d[3], b[3] + pad);
  r[0] = b[0], r[1] = b[1], r[2] = b[2] - b[0], r[3] = b[3] - b[1];
}

/* What is drawn with the style's margin around it, as bg_scene_fit would
 * make the page, clamped to the page: x, y, w, h (a redrawn diagram's page
 * is the full diagram's, legend included). */
static void drawn_region(const bg_diagram *dg, double r[4]) {
  const bg_scene *s = &dg->scene;
  double x0, y0, x1, y1, mg = dg->st.margin;
  bg_scene_bbox(s, &x0, &y0, &x1, &y1);
  double rx = fmax(0, x0 - mg), ry = fmax(0, y0 - mg);
  r[0] = rx, r[1] = ry;
  r[2] = fmin(s->width, x0 - mg + ceil(x1 - x0 + 2 * mg)) - rx;
  r[3] = fmin(s->height, y0 - mg + ceil(y1 - y0 + 2 * mg)) - ry;
}

static void hl_title(const rp_ctx *c, const hl *h, bg_strbuf *t) {
  const bg_analysis *a = c->a;
  const bg_model *m = c->m;
  if (h->kind == 'p')
    bg_sb_printf(t, "Causal path %d (%s, %s to %s)", h->index + 1, a->path_kind[h->index],
                 m->elem_name[a->path_end0[h->index]], m->elem_name[a->path_end1[h->index]]);
  else if (h->kind == 'c')
    bg_sb_printf(t, "Conflict %d at %s", h->index + 1, m->elem_name[a->conflict_node[h->index]]);
  else if (h->cloop >= 0)
    bg_sb_printf(t, "Causal loop %d (topological loop %d)", h->cloop + 1, h->index + 1);
  else
    bg_sb_printf(t, "Topological loop %d (%s)", h->index + 1,
                 a->tloop_cause && a->tloop_cause[h->index] ? a->tloop_cause[h->index] : "loop");
}

static void hl_text(const rp_ctx *c, const hl *h, bg_strbuf *t) {
  const bg_analysis *a = c->a;
  const bg_model *m = c->m;
  int k = h->index;
  if (h->kind == 'p') {
    bg_sb_puts(t, "Bonds ");
    rp_bond_list(t, m, a->path_bonds + a->path_adr[k], a->path_n[k]);
    if (a->path_class[k]) bg_sb_printf(t, "; class %d", a->path_class[k]);
    if (a->path_order[k] != BG_PATH_ORDER_NONE) bg_sb_printf(t, "; order %d%s", a->path_order[k],
                                                             a->path_order[k] == 0 ? " (algebraic)" : "");
    bg_sb_puts(t, ".");
  } else if (h->kind == 'c') {
    bg_sb_printf(t, "Type %d", a->conflict_type[k]);
    if (a->conflict_type[k] == 2) bg_sb_printf(t, ", degree %d", a->conflict_degree[k]);
    bg_sb_puts(t, "; bonds ");
    rp_bond_list(t, m, a->conflict_bonds + a->conflict_adr[k], a->conflict_n[k]);
    bg_sb_puts(t, ".");
  } else {
    bg_sb_printf(t, "%s loop of order %d, gain ", a->tloop_kind[k] == BG_TLOOP_FLAT ? "Flat" : "Open",
                 a->tloop_order[k]);
    rp_esc(t, a->tloop_gain[k]);
    bg_sb_puts(t, " = ");
    rp_gain_value(t, a->tloop_gain_value[k], a->tloop_order[k]);
    if (a->tloop_algebraic[k]) bg_sb_puts(t, " (algebraic)");
    if (h->cloop >= 0) bg_sb_puts(t, "; the loop's other open loop runs the other way on the far side of its bonds");
    bg_sb_puts(t, ".");
  }
}

/* Draws one highlighted diagram at the cursor (two fit on a page when small). */
#define HL_SHRINK 0.75 /* a highlight drawn at least this share of its scale to fit the room
                          left on a page: reactions20's path 2 left the section's first page
                          82 % empty, wanting 100 % where 89 % fitted */
static void show_one(rp_ctx *c, const hl *h) {
  bg_diagram *dg = build_highlight(c, h->kind, h->index + 1);
  if (!dg) return;
  rp_doc *d = &c->body;
  const bg_scene *s = &dg->scene;
  double smin = smallest_scale(s), cw = rp_content_w(d);
  double head = 40, half = (rp_page_room(d) - 30) / 2 - head, full = rp_page_room(d) - 30 - head;
  double r[4];
  drawn_region(dg, r);
  double sc = fit_scale(r[2], r[3], cw, half, 1);
  if (sc < smin) sc = fit_scale(r[2], r[3], cw, full, 1);
  int cropped = sc < smin;
  if (cropped) { /* to the drawing: a crop never shows part of the legend */
    regions g;
    split_regions(s, dg->st.margin, &g);
    hot_region(dg, h, g.draw, r);
    sc = fit_scale(r[2], r[3], cw, full, 1);
  }
  bg_strbuf t = {0}, x = {0};
  hl_title(c, h, &t);
  hl_text(c, h, &x);
  if (cropped) bg_sb_puts(&x, " The diagram is cropped to the highlighted item.");
  if (sc >= smin) {
    const bg_scene *k = keep_cropped(c, dg, r);
    /* the heading kept with its text and the whole diagram (16 pt for the
     * text overran the page by up to its second line); where the page's
     * room left holds it a little smaller, still readable, it goes there */
    double text = rp_para_height(d, bg_sb_str(&x), RP_SIZE_BODY, 0, 0) + 4;
    double room = rp_room(d) - rp_subsection_height(d) - text;
    double fits = fit_scale(r[2], r[3], cw, room, 1);
    if (r[3] * sc > room && fits >= smin && fits >= HL_SHRINK * sc) sc = fits;
    rp_subsection(d, bg_sb_str(&t), text + r[3] * sc);
    rp_para(d, bg_sb_str(&x), RP_SIZE_BODY, 0, 0, rp_ink);
    d->y += 4;
    rp_place(d, k, r[0], r[1], r[2], r[3], rp_left() + (cw - r[2] * sc) / 2, d->y, sc);
    d->y += r[3] * sc + 10;
  } else {
    tiling tl; /* planned on the whole scene, as before the crop */
    plan_tiles(s, r, cw, rp_page_room(d) - 14, smin, 1, MAX_HL_TILES, &tl);
    const bg_scene *k = keep_cropped(c, dg, r); /* every tile lies inside r */
    /* the room below the heading and its text (the text measured with the
     * most parts it can announce) for a first part flowed there */
    bg_strbuf most = {0};
    bg_sb_printf(&most, "%s It follows in %d parts, one below the other.", bg_sb_str(&x), MAX_HL_TILES);
    double text = rp_para_height(d, bg_sb_str(&most), RP_SIZE_BODY, 0, 0);
    bg_sb_free(&most);
    double heights[MAX_HL_TILES], above = rp_subsection_height(d) + text + 8 + TILE_CAPTION + 2;
    int nflow = flow_parts(d, r, &tl, rp_room(d) - above, heights);
    /* The heading is kept with its first part (issue 31: a 60-bond model's
     * report had five headings with their text alone at a page's foot, the
     * parts on the pages after): where the room left is too small to flow
     * into, the heading goes to the next page and the parts flow from
     * there; parts of two columns are planned a heading shorter, so the
     * first fits under it, and the heading goes where the first part does. */
    double keep = 30;
    if (!nflow && (nflow = flow_parts(d, r, &tl, rp_page_room(d) - above, heights)))
      keep = rp_room(d); /* too little room here to flow into: a new page */
    else if (!nflow) {
      plan_tiles(s, r, cw, rp_page_room(d) - above, smin, 1, MAX_HL_TILES, &tl);
      keep = text + 8 + TILE_CAPTION + 2 + tl.th * tl.scale;
    }
    rp_subsection(d, bg_sb_str(&t), keep);
    int parts = nflow ? nflow : tl.nused;
    if (parts == 1) bg_sb_puts(&x, " It follows at a readable scale.");
    else bg_sb_printf(&x, " It follows in %d parts, one below the other.", parts);
    rp_para(d, bg_sb_str(&x), RP_SIZE_BODY, 0, 0, rp_ink);
    if (nflow) emit_flow(d, k, r, tl.scale, heights, nflow, bg_sb_str(&t));
    else emit_tiles(d, k, r, &tl, 0, bg_sb_str(&t), 1);
  }
  bg_sb_free(&t);
  bg_sb_free(&x);
  rp_hl_done(c, dg);
}

static void rest_note(rp_ctx *c, const hl *h, int from, int n) {
  int np = 0, nl = 0, nc = 0;
  for (int i = from; i < n; i++) np += h[i].kind == 'p', nl += h[i].kind == 'l', nc += h[i].kind == 'c';
  bg_strbuf b = {0};
  bg_sb_printf(&b, "%d more not drawn here (", n - from);
  int first = 1;
  if (np) rp_count(&b, np, "causal path"), first = 0;
  if (nl) bg_sb_puts(&b, first ? "" : ", "), rp_count(&b, nl, "loop"), first = 0;
  if (nc) bg_sb_puts(&b, first ? "" : ", "), rp_count(&b, nc, "conflict");
  bg_sb_puts(&b, "); the tables list them all, and --highlight path:K, loop:K or conflict:K "
                 "draws any one of them.");
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_BODY, 0, 0, rp_ink);
  bg_sb_free(&b);
}

void rp_sec_highlights(rp_ctx *c) {
  rp_doc *d = &c->body;
  hl *h;
  int n = candidates(c->a, &h);
  rp_section(d, "Highlighted paths, loops and conflicts", 1, 1, 0);
  if (n == 0) {
    rp_para(d, "The model has no causal paths, loops or conflicts to highlight.", RP_SIZE_BODY, 0, 0, rp_ink);
    free(h);
    return;
  }
  int shown = n < MAX_HIGHLIGHTS ? n : MAX_HIGHLIGHTS;
  rp_para(d, "Each item in colour, everything else grey. Causal loops are drawn as one of their "
             "two open topological loops; a flat loop caused by a causal path is drawn as that path.",
          RP_SIZE_BODY, 0, 0, rp_ink);
  if (shown < n) rest_note(c, h, shown, n);
  qsort(h, (size_t)shown, sizeof *h, by_kind);
  for (int i = 0; i < shown && !c->failed; i++) {
    if (c->m->nbond > 5000) rp_progress(c, "highlight %d of %d", i + 1, shown); /* seconds each at 10^5 bonds */
    show_one(c, &h[i]);
  }
  free(h);
}
