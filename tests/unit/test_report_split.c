/* SPDX-License-Identifier: BSD-3-Clause */
/* How the report splits a diagram too large for its page (issue 31,
 * "reports that split well"), measured on the models figure_models.h
 * generates, in every shipped style: sections 2 (the diagram) and 3 (the
 * highlights) are built and their pages read back. Counted as faults:
 * - parts beyond the fewest: the whole diagram placed in more parts than
 *   the fewest pages of either orientation that hold it, 18 pt overlap
 *   included, at its readable scale (smallest text 6 pt);
 * - overlap beyond the margin: two parts repeating more than 19 pt of the
 *   diagram along a side (the tiles' 18 pt, rounding allowed);
 * - legend cut: a row of a diagram's legend (a text or a sample) that a
 *   placed rectangle shows in part, or places beyond its page;
 * - orientation switches: a section whose pages are not all portrait or
 *   all landscape.
 * BG_SPLIT_VERBOSE=1 prints each model's numbers. */
#include <math.h>

#include "harness.h"
#include "analysis_fixture.h"
#include "figure_models.h"
#include "report/report_int.h"

#define OVERLAP_MARGIN 19.0 /* the tiles' 18 pt, rounded */
#define CAPTION_ROOM 20.0   /* a part's caption line and gap, at most */

typedef struct split_stats {
  int parts, fewest, over_parts, over_overlap, legend_cut, orient_switch, legend_places;
  double max_overlap, scale;
} split_stats;

static int is_legend(const bg_scene_item *it) { return !strncmp(it->role, "legend", 6); }

static void grow(double b[4], double x0, double y0, double x1, double y1) {
  b[0] = fmin(b[0], x0), b[1] = fmin(b[1], y0), b[2] = fmax(b[2], x1), b[3] = fmax(b[3], y1);
}

/* Box of the legend's items (legend = 1) or of everything else (0);
 * smallest text among them in *minsz. Returns 0 when there is none. */
static int part_box(const bg_scene *s, int legend, double b[4], double *minsz) {
  b[0] = b[1] = 1e300, b[2] = b[3] = -1e300;
  *minsz = 0;
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    if (is_legend(it) != legend) continue;
    if (it->kind == BG_ITEM_TEXT) {
      double x = it->x - it->halign * it->tw, y = it->y - it->valign * it->th;
      grow(b, x, y, x + it->tw, y + it->th);
      if (*minsz == 0 || it->size < *minsz) *minsz = it->size;
      continue;
    }
    bg_scene_op o_;
    for (int k = 0; bg_scene_next_op(s, it, &k, &o_);) {
      const bg_scene_op *o = &o_;
      int npt = o->code == BG_OP_CURVE ? 3 : o->code == BG_OP_CLOSE ? 0 : 1;
      for (int q = 0; q < npt; q++) grow(b, o->x[q], o->y[q], o->x[q], o->y[q]);
    }
  }
  return b[0] <= b[2];
}

static int page_has(const rp_page *p, const char *role) {
  for (int i = 0; i < p->sc.nitem; i++)
    if (!strcmp(p->sc.item[i].role, role)) return 1;
  return 0;
}

static int landscape(const rp_page *p) { return p->sc.width > p->sc.height; }

/* The fewest parts of a w x h drawing at scale s on pages of either
 * orientation, tiles overlapping by 18 pt. */
static int fewest_parts(double w, double h, double s) {
  int best = 0;
  for (int land = 0; land < 2; land++) {
    rp_doc d;
    rp_doc_init(&d, "Sans");
    rp_new_page(&d, land);
    double tw = rp_content_w(&d) / s, th = (rp_page_room(&d) - CAPTION_ROOM) / s, ov = 18;
    int nx = w <= tw ? 1 : (int)ceil((w - ov) / (tw - ov)), ny = h <= th ? 1 : (int)ceil((h - ov) / (th - ov));
    if (!best || nx * ny < best) best = nx * ny;
    rp_doc_free(&d);
  }
  return best;
}

/* Rows of a legend (items of its scene) that the placement p cuts: shows
 * in part, or places beyond its page. A legend may continue on the next
 * page between its rows; a row is never cut. */
static int legend_cut(const bg_surface_place *p, const rp_page *pg) {
  const bg_scene *s = p->scene;
  double r[4] = {p->sx, p->sy, p->sx + p->sw, p->sy + p->sh}, e = 0.5;
  int n = 0;
  for (int i = 0; i < s->nitem; i++) {
    if (!is_legend(&s->item[i])) continue;
    double L[4] = {1e300, 1e300, -1e300, -1e300};
    const bg_scene_item *it = &s->item[i];
    if (it->kind == BG_ITEM_TEXT) {
      double x = it->x - it->halign * it->tw, y = it->y - it->valign * it->th;
      grow(L, x, y, x + it->tw, y + it->th);
    } else {
      bg_scene_op o_;
      for (int k = 0; bg_scene_next_op(s, it, &k, &o_);) {
        const bg_scene_op *o = &o_;
        for (int q = 0; q < (o->code == BG_OP_CURVE ? 3 : o->code == BG_OP_CLOSE ? 0 : 1); q++)
          grow(L, o->x[q], o->y[q], o->x[q], o->y[q]);
      }
    }
    if (!(L[0] < r[2] - e && L[2] > r[0] + e && L[1] < r[3] - e && L[3] > r[1] + e)) continue;
    int inside = L[0] >= r[0] - e && L[2] <= r[2] + e && L[1] >= r[1] - e && L[3] <= r[3] + e;
    double px1 = p->x + (L[2] - p->sx) * p->scale, py1 = p->y + (L[3] - p->sy) * p->scale;
    n += !inside || px1 > pg->sc.width + e || py1 > pg->sc.height + e;
  }
  return n;
}

static int section_switches(const rp_doc *d, int from, int to) {
  for (int i = from + 1; i < to; i++)
    if (landscape(d->page[i]) != landscape(d->page[from])) return 1;
  return 0;
}

/* Largest extent two parts of one scene share along a side (they meet in
 * the other direction). */
static double overlap_of(const bg_surface_place *a, const bg_surface_place *b) {
  double ox = fmin(a->sx + a->sw, b->sx + b->sw) - fmax(a->sx, b->sx);
  double oy = fmin(a->sy + a->sh, b->sy + b->sh) - fmax(a->sy, b->sy);
  if (ox <= 0 || oy <= 0) return 0;
  return fmin(ox, oy); /* side by side: the shared width; one above the other: the height */
}

static void measure(const fx *f, const char *style, split_stats *st) {
  memset(st, 0, sizeof *st);
  bg_render_opts o = {0};
  o.style = style, o.style_dir = BG_SOURCE_DIR "/styles";
  static const bg_index_facts none;
  bg_report_input in = {f->m, &f->a, NULL, NULL, &none, NULL, NULL, NULL, 0, &o, NULL, NULL, NULL, NULL, NULL};
  bg_diags dg;
  bg_diags_init(&dg, "test", NULL, 0);
  rp_ctx c;
  memset(&c, 0, sizeof c);
  c.in = &in, c.m = f->m, c.a = &f->a, c.dg = &dg;
  OK(bg_style_load(&c.st, style, o.style_dir, &dg) == 0);
  rp_doc_init(&c.body, c.st.font);
  c.body.section = 1;
  rp_sec_diagram(&c);
  int sec3 = c.body.npage;
  rp_sec_highlights(&c);
  OK(!c.failed && c.full);
  if (c.failed || !c.full) goto done;
  const bg_scene *full = bg_diagram_scene(c.full);
  double D[4], L[4], dsz, lsz;
  part_box(full, 0, D, &dsz);
  double smin = dsz > 0 ? RP_MIN_TEXT / dsz : 1, dbottom = D[3];
  if (part_box(full, 1, L, &lsz)) grow(D, L[0], L[1], L[2], L[3]);
  /* section 2: the parts (placements of the full diagram, not the map
   * and not the legend placed on its own, below the drawing) */
  const bg_surface_place *part[64];
  int np = 0;
  for (int i = 0; i < sec3; i++) {
    const rp_page *p = c.body.page[i];
    int map = page_has(p, "tile");
    for (int k = 0; k < p->nplace; k++) {
      const bg_surface_place *pl = &p->place[k];
      if (pl->scene != full || (map && k == 0)) continue;
      if (getenv("DBGSPLIT")) fprintf(stderr, "page %d place %d: %g %g %g %g at %g (dbottom %g, L %g %g %g %g)\n", i, k, pl->sx, pl->sy, pl->sw, pl->sh, pl->scale, dbottom, L[0], L[1], L[2], L[3]);
      if (pl->sy >= dbottom) st->legend_places++;
      else if (np < 64) part[np++] = pl, st->scale = pl->scale;
    }
  }
  st->parts = np;
  /* the drawing and its legend, with the style's margin round them */
  double mg = c.st.margin, w = D[2] - D[0] + 2 * mg, h = D[3] - D[1] + 2 * mg;
  st->fewest = fewest_parts(w, h, smin);
  /* at the readable scale (a smaller one only beyond the report's 48 pages) */
  if (np > 1 && st->scale >= smin - 1e-9 && np > st->fewest) st->over_parts = np - st->fewest;
  for (int i = 0; i < np; i++)
    for (int j = i + 1; j < np; j++) {
      double ov = overlap_of(part[i], part[j]);
      if (ov > st->max_overlap) st->max_overlap = ov;
      st->over_overlap += ov > OVERLAP_MARGIN;
    }
  /* every placement of a diagram, map included, in both sections */
  for (int i = 0; i < c.body.npage; i++) {
    const rp_page *p = c.body.page[i];
    for (int k = 0; k < p->nplace; k++) {
      const bg_scene *s = p->place[k].scene;
      int diagram = s == full;
      for (int h2 = 0; h2 < c.nhl && !diagram; h2++) diagram = s == c.hl[h2];
      if (diagram) st->legend_cut += legend_cut(&p->place[k], p);
    }
  }
  st->orient_switch = section_switches(&c.body, 0, sec3) + section_switches(&c.body, sec3, c.body.npage);
done:
  INT_EQ(dg.nerrors, 0);
  for (int i = 0; i < c.ndiag; i++) bg_diagram_free(c.diag[i]);
  free(c.diag);
  for (int i = 0; i < c.nhl; i++) bg_scene_free(c.hl[i]), free(c.hl[i]);
  free(c.hl);
  rp_doc_free(&c.body);
  bg_diags_free(&dg);
}

static void make_wide_grid(bg_strbuf *b, int n) { fm_grid(b, 3, n); }

static const fm_model generated[] = {
    {"chain30", fm_chain, 30},       {"chain300", fm_chain, 300},    {"ladder25", fm_ladder, 25},
    {"grid5x5", fm_make_grid, 5},       {"grid8x8", fm_make_grid, 8},      {"grid3x12", make_wide_grid, 12},
    {"tree40", fm_make_tree, 40},       {"reactions20", fm_reactions, 20}, {"modladder9", fm_modladder, 9},
    {"nested3", fm_make_nested, 0},     {"stages4", fm_make_stages, 4},    {"pifilter3", fm_pifilter, 3},
    {"branchy20", fm_make_branchy, 20},
};

static const char *const styles[] = {"default", "print", "slides"};

int main(void) {
  (void)fx_load; /* the fixture's loader of examples: these models are generated */
  int verbose = getenv("BG_SPLIT_VERBOSE") != NULL;
  split_stats tot = {0};
  const char *only = getenv("BG_SPLIT_ONLY"); /* one model's name */
  for (size_t g = 0; g < sizeof generated / sizeof generated[0]; g++) {
    if (only && strcmp(only, generated[g].name)) continue;
    bg_strbuf src = {0};
    generated[g].make(&src, generated[g].n);
    fx f;
    int rc = fm_load(&f, generated[g].name, bg_sb_str(&src));
    BG_T_REPORT(rc == 0, "generated model %s compiles", generated[g].name);
    for (int si = 0; rc == 0 && si < 3; si++) {
      split_stats st;
      measure(&f, styles[si], &st);
      if (verbose)
        printf("%-12s %-8s parts %2d (fewest %2d) + legend %d at %3.0f %%  overlap max %6.1f pt  over: parts %d overlap %d "
               " legend cut %d  orientation switches %d\n",
               generated[g].name, styles[si], st.parts, st.fewest, st.legend_places, 100 * st.scale, st.max_overlap, st.over_parts,
               st.over_overlap, st.legend_cut, st.orient_switch);
      tot.parts += st.parts, tot.over_parts += st.over_parts, tot.over_overlap += st.over_overlap;
      tot.legend_cut += st.legend_cut, tot.orient_switch += st.orient_switch;
    }
    fx_free(&f);
    bg_sb_free(&src);
  }
  printf("generated models, three styles: %d parts, %d beyond the fewest, %d overlaps beyond %.0f pt, "
         "%d legends cut, %d sections switching orientation\n",
         tot.parts, tot.over_parts, tot.over_overlap, OVERLAP_MARGIN, tot.legend_cut, tot.orient_switch);
  INT_EQ(tot.over_parts, 0);
  INT_EQ(tot.over_overlap, 0);
  INT_EQ(tot.legend_cut, 0);
  INT_EQ(tot.orient_switch, 0);
  return bg_t_done();
}
