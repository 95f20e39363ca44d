/* Model + analysis → scene: labels measured with pango, positions from
 * Graphviz, then bonds with half arrows, causal strokes, bond numbers,
 * modulating signals, Lagrange sources and the analysis layers. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram_int.h"

/* ---------------------------------------------------------------- labels */
static void put_escaped(bg_strbuf *b, const char *s, size_t n) {
  for (size_t i = 0; i < n && s[i]; i++) {
    switch (s[i]) {
    case '&': bg_sb_puts(b, "&amp;"); break;
    case '<': bg_sb_puts(b, "&lt;"); break;
    case '>': bg_sb_puts(b, "&gt;"); break;
    case '"': bg_sb_puts(b, "&quot;"); break;
    default: bg_sb_putc(b, s[i]);
    }
  }
}

void bg_markup_escape(bg_strbuf *b, const char *s) { put_escaped(b, s, strlen(s)); }

/* A name with its trailing digits (or the part after the last '_') set as a
 * subscript: a pango span, since <sub> mis-scales on scaled surfaces. */
static void put_name(bg_strbuf *b, const char *name, double font_size) {
  size_t n = strlen(name), k = n;
  while (k > 0 && isdigit((unsigned char)name[k - 1])) k--;
  const char *us = strrchr(name, '_');
  size_t base = k, sub = k;
  if (k == n || k == 0) base = sub = n;
  if (us && us > name && us[1]) base = (size_t)(us - name), sub = base + 1;
  put_escaped(b, name, base);
  if (sub < n) {
    bg_sb_printf(b, "<span size=\"70%%\" rise=\"%.1fpt\">", -0.27 * font_size);
    put_escaped(b, name + sub, n - sub);
    bg_sb_puts(b, "</span>");
  }
}

static char *elem_markup(bg_diagram *d, int e) {
  const bg_model *m = d->m;
  bg_strbuf b = {0};
  const char *kind = bg_elem_display_kind(m, e);
  put_escaped(&b, kind, strlen(kind));
  if (!bg_elem_is_junction(m->elem_kind[e]) && (d->show & BG_SHOW_LABELS)) {
    bg_sb_puts(&b, " : ");
    if (m->elem_label && m->elem_label[e]) put_escaped(&b, m->elem_label[e], strlen(m->elem_label[e]));
    else put_name(&b, m->elem_name[e], d->st.font_size);
  }
  char *s = bg_arena_strdup(&d->arena, bg_sb_str(&b));
  bg_sb_free(&b);
  return s;
}

static void measure_nodes(bg_diagram *d) {
  const bg_model *m = d->m;
  for (int i = 0; i < d->nnode; i++) {
    d->nlabel[i] = i < m->nelem ? elem_markup(d, i) : "Sf*";
    double w, h;
    bg_text_measure(d->st.font, d->st.font_size, d->nlabel[i], &w, &h);
    /* pango's logical height includes the line gap: trim it so vertical
     * bonds come as close to the glyphs as horizontal ones */
    d->nw[i] = w + 2 * d->st.node_pad;
    d->nh[i] = 0.8 * h + 2 * d->st.node_pad;
  }
}

/* ---------------------------------------------------------------- layout */
static const char *choose_engine(const bg_diagram *d) {
  const bg_model *m = d->m;
  if (d->o.layout) return d->o.layout;
  const char *e = m->layout.engine ? m->layout.engine : "dot";
  if (!strcmp(e, "dot") && d->nnode > 2000) {
    /* dot needs ~8 s at 10 000 nodes, sfdp ~2.5 s (DRAWING.md) */
    if (d->o.verbose)
      fprintf(stderr, "bgdraw: %d nodes: laying out with sfdp instead of dot\n", d->nnode);
    return "sfdp";
  }
  return e;
}

/* Layout edges: the bonds, then Sf* → junction for Lagrange sources. */
static void layout_edges(const bg_diagram *d, int *tail, int *head) {
  const bg_model *m = d->m;
  for (int b = 0; b < m->nbond; b++) tail[b] = m->bond_tail[b], head[b] = m->bond_head[b];
  int k = m->nbond;
  for (int i = 0; d->a && i < d->a->nlag; i++)
    if (d->lag_node[i] >= 0) tail[k] = d->lag_node[i], head[k++] = d->a->lag_junction[i];
}

static int run_layout(bg_diagram *d, bg_diags *dg) {
  const bg_model *m = d->m;
  int ne = m->nbond + d->nnode - m->nelem;
  int *tail = bg_xcalloc((size_t)ne + 1, sizeof *tail), *head = bg_xcalloc((size_t)ne + 1, sizeof *head);
  layout_edges(d, tail, head);
  int *pinned = bg_xcalloc((size_t)d->nnode, sizeof *pinned);
  double *px = bg_xcalloc((size_t)d->nnode, sizeof *px), *py = bg_xcalloc((size_t)d->nnode, sizeof *py);
  for (int e = 0; e < m->nelem; e++)
    if (m->elem_has_at && m->elem_has_at[e]) pinned[e] = 1, px[e] = m->elem_at_x[e], py[e] = m->elem_at_y[e];
  bg_layout_in in = {d->nnode, d->nw, d->nh, pinned, px, py, ne, tail, head,
                     choose_engine(d), m->layout.rankdir, d->st.node_sep, d->st.rank_sep,
                     d->st.splines};
  char err[256];
  int rc = bg_layout_run(&in, &d->lay, err, sizeof err);
  if (rc) bg_diag_error(dg, (bg_srcloc){0, 0}, "%s", err);
  free(tail), free(head), free(pinned), free(px), free(py);
  if (rc) return -1;
  d->nx = d->lay.x, d->ny = d->lay.y;
  d->splx = d->lay.splx, d->sply = d->lay.sply;
  return 0;
}

/* ---------------------------------------------------------------- colours */
int bg_diagram_muted(const bg_diagram *d) { return d->o.highlight_kind != 0; }

bg_rgba bg_diagram_ink(const bg_diagram *d, bg_rgba c, int hot) {
  return hot || !bg_diagram_muted(d) ? c : d->st.muted;
}

static bg_rgba parse_hex(const char *s, bg_rgba dflt) {
  unsigned v;
  if (!s || s[0] != '#' || strlen(s) != 7 || sscanf(s + 1, "%6x", &v) != 1) return dflt;
  return (bg_rgba){((v >> 16) & 255) / 255.0, ((v >> 8) & 255) / 255.0, (v & 255) / 255.0, 1};
}

/* ---------------------------------------------------------------- bonds */
static void draw_bond(bg_diagram *d, int b) {
  const bg_model *m = d->m;
  const bg_style *st = &d->st;
  bg_rgba c = parse_hex(m->bond_color ? m->bond_color[b] : NULL, st->fg);
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "bond %d", m->bond_num[b]);
  it->color = bg_diagram_ink(d, c, d->hot_bond[b]);
  it->width = st->line_width;
  it->round = 1;
  bg_geom_bond_path(d, b);
  /* the half arrow: one barb, 45 degrees back from the tip */
  const bg_bond_geom *g = &d->bg[b];
  double len = 7 * st->line_width;
  bg_vec barb = bg_vadd(g->head, bg_vscale(bg_vsub(bg_barb_side(d, b), g->hdir), len * BG_SQRT1_2));
  bg_scene_line(&d->scene, barb.x, barb.y);
}

static int derivative_bond(const bg_diagram *d, int b) {
  const bg_model *m = d->m;
  int ends[2] = {m->bond_tail[b], m->bond_head[b]};
  for (int k = 0; k < 2; k++)
    if (bg_elem_is_store(m->elem_kind[ends[k]]) && d->a->elem_caus[ends[k]] == BG_CAUS_DERIVATIVE)
      return 1;
  return 0;
}

static void stroke_bar(bg_diagram *d, bg_vec e, bg_vec n, double half) {
  bg_scene_move(&d->scene, e.x + n.x * half, e.y + n.y * half);
  bg_scene_line(&d->scene, e.x - n.x * half, e.y - n.y * half);
}

static void draw_stroke(bg_diagram *d, int b) {
  const bg_style *st = &d->st;
  const bg_bond_geom *g = &d->bg[b];
  int at_head = d->a->bond_stroke[b] == BG_STROKE_HEAD;
  int conflict = d->a->bond_conflict && d->a->bond_conflict[b];
  int deriv = derivative_bond(d, b);
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "stroke bond=%d%s%s",
                                     d->m->bond_num[b], deriv ? " derivative" : "",
                                     conflict ? " conflict" : "");
  bg_rgba c = conflict ? st->conflict : deriv ? st->derivative : st->fg;
  it->color = bg_diagram_ink(d, c, d->hot_bond[b]);
  it->width = 1.5 * st->line_width;
  bg_vec e = at_head ? g->head : g->tail, dir = at_head ? g->hdir : g->tdir;
  bg_vec n = bg_vleft(dir), back = at_head ? bg_vscale(dir, -1) : dir;
  double half = 4.5 * st->line_width;
  stroke_bar(d, e, n, half);
  if (deriv && st->derivative_double) stroke_bar(d, bg_vadd(e, bg_vscale(back, 2.5 * st->line_width)), n, half);
  if (conflict && st->conflict_cross) {
    bg_vec c1 = bg_vadd(e, bg_vscale(back, 5 * st->line_width));
    stroke_bar(d, c1, bg_vunit(bg_vadd(n, dir)), half * 0.7);
    stroke_bar(d, c1, bg_vunit(bg_vsub(n, dir)), half * 0.7);
  }
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

static int overlaps(const double r[4], double x0, double y0, double x1, double y1) {
  return x0 < r[2] && r[0] < x1 && y0 < r[3] && r[1] < y1;
}

static int label_free(const bg_diagram *d, double x0, double y0, double x1, double y1) {
  for (int i = 0; i < d->nnode; i++) {
    double r[4] = {d->nx[i] - d->nw[i] / 2, d->ny[i] - d->nh[i] / 2, d->nx[i] + d->nw[i] / 2,
                   d->ny[i] + d->nh[i] / 2};
    if (overlaps(r, x0, y0, x1, y1)) return 0;
  }
  for (int i = 0; i < d->nplaced; i++)
    if (overlaps(d->placed + 4 * i, x0, y0, x1, y1)) return 0;
  return 1;
}

void bg_place_label(bg_diagram *d, double w, double h, bg_vec *p) {
  static const double steps[] = {0, 1, -1, 2, -2, 3, -3, 4, -4};
  bg_vec best = *p;
  for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
    bg_vec c = bg_v(p->x, p->y + steps[k] * (h + 1));
    if (label_free(d, c.x - w / 2, c.y - h / 2, c.x + w / 2, c.y + h / 2)) {
      best = c;
      break;
    }
  }
  if (d->nplaced == d->capplaced) {
    d->capplaced = d->capplaced ? 2 * d->capplaced : 16;
    d->placed = bg_xrealloc(d->placed, (size_t)d->capplaced * 4 * sizeof(double));
  }
  double *r = d->placed + 4 * d->nplaced++;
  r[0] = best.x - w / 2, r[1] = best.y - h / 2, r[2] = best.x + w / 2, r[3] = best.y + h / 2;
  *p = best;
}

/* Places text beside mid-bond on the side n, clear of the line by gap. */
static void text_beside(bg_diagram *d, const char *markup, bg_vec mid, bg_vec n, double size,
                        bg_rgba c, const char *role) {
  double w, h;
  bg_text_measure(d->st.font, size, markup, &w, &h);
  double extent = fabs(n.x) * w / 2 + fabs(n.y) * 0.8 * h / 2;
  bg_vec p = bg_vadd(mid, bg_vscale(n, 3.5 + extent));
  if (d->show & (BG_SHOW_PATHS | BG_SHOW_LOOPS) || d->o.highlight_kind)
    bg_text_halo(d, markup, p, size);
  bg_scene_text(&d->scene, markup, p.x, p.y, size, 0.5, 0.5, c, role);
}

static void draw_number(bg_diagram *d, int b) {
  const bg_model *m = d->m;
  char num[32], role[48];
  snprintf(num, sizeof num, "%d", m->bond_num[b]);
  snprintf(role, sizeof role, "number bond=%d", m->bond_num[b]);
  bg_vec n = bg_vscale(bg_barb_side(d, b), -1);
  text_beside(d, num, d->bg[b].mid, n, d->st.font_size * d->st.number_scale,
              bg_diagram_ink(d, d->st.fg, d->hot_bond[b]), role);
}

static void draw_bond_label(bg_diagram *d, int b) {
  const bg_model *m = d->m;
  if (!m->bond_label || !m->bond_label[b]) return;
  bg_strbuf t = {0};
  put_escaped(&t, m->bond_label[b], strlen(m->bond_label[b]));
  char role[48];
  snprintf(role, sizeof role, "bondlabel bond=%d", m->bond_num[b]);
  text_beside(d, bg_sb_str(&t), d->bg[b].mid, bg_barb_side(d, b),
              d->st.font_size * d->st.number_scale, bg_diagram_ink(d, d->st.fg, d->hot_bond[b]), role);
  bg_sb_free(&t);
}

static void draw_bonds(bg_diagram *d) {
  const bg_model *m = d->m;
  for (int b = 0; b < m->nbond; b++) draw_bond(d, b);
  if (d->a && (d->show & BG_SHOW_STROKES))
    for (int b = 0; b < m->nbond; b++)
      if (d->a->bond_stroke[b] != BG_STROKE_NONE) draw_stroke(d, b);
  for (int b = 0; b < m->nbond; b++) {
    if (d->show & BG_SHOW_NUMBERS) draw_number(d, b);
    if (d->show & BG_SHOW_LABELS) draw_bond_label(d, b);
  }
}

/* ---------------------------------------------------------------- signals */
static bg_vec node_exit(const bg_diagram *d, int n, bg_vec toward, double gap) {
  return bg_box_exit(bg_v(d->nx[n], d->ny[n]), d->nw[n] / 2 + gap, d->nh[n] / 2 + gap, toward);
}

static int bond_between(const bg_model *m, int x, int y) {
  for (int i = 0; i < m->elem_nbond[x]; i++) {
    int b = m->elem_bonds[m->elem_bondadr[x] + i];
    if (m->bond_tail[b] == y || m->bond_head[b] == y) return b;
  }
  return -1;
}

static void draw_signal(bg_diagram *d, int i) {
  const bg_model *m = d->m;
  int from = m->signal_from[i], to = m->signal_to[i];
  if (from < 0 || from == to) return; /* a user state has no node to start from */
  const bg_style *st = &d->st;
  bg_vec cf = bg_v(d->nx[from], d->ny[from]), ct = bg_v(d->nx[to], d->ny[to]);
  bg_vec p0 = node_exit(d, from, ct, 0), p1 = node_exit(d, to, cf, 1.5);
  bg_vec dir = bg_vunit(bg_vsub(p1, p0));
  double alen = 6, awid = 4.5;
  int hot = d->hot_elem[from] && d->hot_elem[to];
  bg_rgba c = bg_diagram_ink(d, st->signal, hot);
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "signal %s->%s",
                                     m->elem_name[from], m->elem_name[to]);
  it->color = c, it->width = 0.7;
  if (st->signal_dashed) it->dash[0] = 3, it->dash[1] = 2;
  int b = bond_between(m, from, to);
  if (b >= 0) {
    /* a bond joins the same nodes: bow the signal out to the barb side (the
     * number is on the other) so the two stay apart */
    bg_vec bow = bg_vscale(bg_barb_side(d, b), 16), chord = bg_vsub(p1, p0);
    bg_vec c1 = bg_vadd(bg_vadd(p0, bg_vscale(chord, 1.0 / 3)), bow);
    bg_vec c2 = bg_vadd(bg_vadd(p0, bg_vscale(chord, 2.0 / 3)), bow);
    dir = bg_vunit(bg_vsub(p1, c2));
    bg_vec end = bg_vsub(p1, bg_vscale(dir, alen * 0.8));
    bg_scene_move(&d->scene, p0.x, p0.y);
    bg_scene_curve(&d->scene, c1.x, c1.y, c2.x, c2.y, end.x, end.y);
  } else {
    bg_vec end = bg_vsub(p1, bg_vscale(dir, alen * 0.8));
    bg_scene_move(&d->scene, p0.x, p0.y);
    bg_scene_line(&d->scene, end.x, end.y);
  }
  it = bg_scene_begin(&d->scene, BG_ITEM_FILL, "signal-arrow %s->%s", m->elem_name[from],
                      m->elem_name[to]);
  it->fill = it->color = c, it->width = 0;
  bg_geom_arrowhead(&d->scene, p1, dir, alen, awid);
}

/* ---------------------------------------------------------------- nodes */
static void draw_nodes(bg_diagram *d) {
  const bg_model *m = d->m;
  for (int e = 0; e < m->nelem; e++) {
    bg_rgba c = parse_hex(m->elem_color ? m->elem_color[e] : NULL, d->st.fg);
    char role[160];
    snprintf(role, sizeof role, "node %s", m->elem_name[e]);
    bg_scene_text(&d->scene, d->nlabel[e], d->nx[e], d->ny[e], d->st.font_size, 0.5, 0.5,
                  bg_diagram_ink(d, c, d->hot_elem[e]), role);
  }
}

/* A dashed artificial flow source Sf* at c, its dashed bond to p (half arrow
 * at p), the stroke at the source (a flow source takes the effort). */
static void draw_lagrange_source(bg_diagram *d, int i, bg_vec c, double hw, double hh, bg_vec p) {
  const bg_style *st = &d->st;
  bg_scene_item *it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "lagrange %d", i + 1);
  it->width = 0.6, it->dash[0] = 2, it->dash[1] = 1.5, it->color = st->fg;
  bg_scene_move(&d->scene, c.x - hw, c.y - hh);
  bg_scene_line(&d->scene, c.x + hw, c.y - hh);
  bg_scene_line(&d->scene, c.x + hw, c.y + hh);
  bg_scene_line(&d->scene, c.x - hw, c.y + hh);
  bg_scene_close(&d->scene);
  bg_scene_text(&d->scene, "Sf*", c.x, c.y, st->font_size, 0.5, 0.5, st->fg, "lagrange-label");
  bg_vec t = bg_box_exit(c, hw, hh, p), dir = bg_vunit(bg_vsub(p, t));
  it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "lagrange-bond %d", i + 1);
  it->width = st->line_width, it->dash[0] = 4, it->dash[1] = 2, it->round = 1, it->color = st->fg;
  bg_vec barb = bg_vadd(p, bg_vscale(bg_vsub(bg_vleft(dir), dir), 7 * st->line_width * BG_SQRT1_2));
  bg_scene_move(&d->scene, t.x, t.y);
  bg_scene_line(&d->scene, p.x, p.y);
  bg_scene_line(&d->scene, barb.x, barb.y);
  it = bg_scene_begin(&d->scene, BG_ITEM_STROKE, "lagrange-stroke %d", i + 1);
  it->width = 1.5 * st->line_width, it->color = st->fg;
  stroke_bar(d, t, bg_vleft(dir), 4.5 * st->line_width);
}

static void draw_lagrange(bg_diagram *d) {
  const bg_analysis *a = d->a;
  for (int i = 0; a && i < a->nlag; i++) {
    int n = d->lag_node[i];
    if (n >= 0) {
      int j = a->lag_junction[i];
      bg_vec cn = bg_v(d->nx[n], d->ny[n]);
      draw_lagrange_source(d, i, cn, d->nw[n] / 2, d->nh[n] / 2, node_exit(d, j, cn, 0));
    } else if (a->lag_bond[i] >= 0) {
      /* the inserted 1-junction sits on the split bond: attach beside it */
      int b = a->lag_bond[i];
      bg_vec side = bg_vscale(bg_barb_side(d, b), -1), mid = d->bg[b].mid;
      double w, h;
      bg_text_measure(d->st.font, d->st.font_size, "Sf*", &w, &h);
      bg_vec c = bg_vadd(mid, bg_vscale(side, 30 + h / 2));
      draw_lagrange_source(d, i, c, w / 2 + d->st.node_pad, 0.4 * h + d->st.node_pad,
                           bg_vadd(mid, bg_vscale(side, 2)));
    }
  }
}

/* ---------------------------------------------------------------- highlight */
static void hot_bond(bg_diagram *d, int b) {
  d->hot_bond[b] = 1;
  d->hot_elem[d->m->bond_tail[b]] = d->hot_elem[d->m->bond_head[b]] = 1;
}

static int count_of(const bg_analysis *a, int kind) {
  if (!a) return 0;
  return kind == 'p' ? a->npath : kind == 'l' ? a->ntloop : a->nconflict;
}

/* Marks what the highlighted item touches; everything when there is none. */
static int mark_hot(bg_diagram *d, bg_diags *dg) {
  const bg_model *m = d->m;
  const bg_analysis *a = d->a;
  int kind = d->o.highlight_kind, k = d->o.highlight_index - 1;
  if (!kind) {
    memset(d->hot_bond, 1, (size_t)m->nbond + 1);
    memset(d->hot_elem, 1, (size_t)d->nnode + 1);
    return 0;
  }
  static const char *names[] = {"causal path", "topological loop", "conflict"};
  const char *what = names[kind == 'p' ? 0 : kind == 'l' ? 1 : 2];
  int n = count_of(a, kind);
  if (k < 0 || k >= n) {
    bg_diag_error(dg, (bg_srcloc){0, 0}, "--highlight: no %s %d (the model has %d)", what, k + 1, n);
    return -1;
  }
  if (kind == 'p')
    for (int i = 0; i < a->path_n[k]; i++) hot_bond(d, a->path_bonds[a->path_adr[k] + i]);
  if (kind == 'l')
    for (int i = 0; i < a->tloop_n[k]; i++) hot_bond(d, a->tloop_signals[a->tloop_adr[k] + i] / 2);
  if (kind == 'c') {
    d->hot_elem[a->conflict_node[k]] = 1;
    for (int i = 0; i < a->conflict_n[k]; i++) hot_bond(d, a->conflict_bonds[a->conflict_adr[k] + i]);
  }
  return 0;
}

/* ---------------------------------------------------------------- build */
static void alloc_nodes(bg_diagram *d) {
  const bg_model *m = d->m;
  int nlag = d->a ? d->a->nlag : 0;
  d->lag_node = bg_arena_alloc(&d->arena, sizeof(int) * (size_t)(nlag + 1));
  d->nnode = m->nelem;
  for (int i = 0; i < nlag; i++)
    d->lag_node[i] = d->a->lag_junction[i] >= 0 ? d->nnode++ : -1;
  size_t n = (size_t)d->nnode + 1;
  d->nw = bg_arena_alloc(&d->arena, n * sizeof(double));
  d->nh = bg_arena_alloc(&d->arena, n * sizeof(double));
  d->nlabel = bg_arena_alloc(&d->arena, n * sizeof(char *));
  d->hot_elem = bg_arena_alloc(&d->arena, n);
  d->hot_bond = bg_arena_alloc(&d->arena, (size_t)m->nbond + 1);
  d->bg = bg_arena_alloc(&d->arena, ((size_t)m->nbond + 1) * sizeof *d->bg);
  d->side_use = bg_arena_alloc(&d->arena, (2 * (size_t)m->nbond + 1) * sizeof(int));
}

static void draw_all(bg_diagram *d) {
  unsigned show = d->show;
  int hk = d->o.highlight_kind;
  if ((show & BG_SHOW_PATHS) || hk == 'p') bg_draw_paths(d);
  if ((show & BG_SHOW_LOOPS) || hk == 'l') bg_draw_loops(d);
  draw_bonds(d);
  if (show & BG_SHOW_SIGNALS)
    for (int i = 0; i < d->m->nsignal; i++) draw_signal(d, i);
  draw_lagrange(d);
  draw_nodes(d);
  if (d->a && ((show & BG_SHOW_CONFLICTS) || hk == 'c')) bg_draw_conflicts(d);
  bg_scene_fit(&d->scene, d->st.margin);
  if (show & BG_SHOW_LEGEND) {
    bg_draw_legend(d);
    bg_scene_fit(&d->scene, d->st.margin);
  }
}

bg_diagram *bg_diagram_build(const bg_model *m, const bg_analysis *a, const bg_render_opts *o,
                             bg_diags *dg) {
  bg_diagram *d = bg_xcalloc(1, sizeof *d);
  d->m = m, d->a = a, d->o = *o;
  d->show = o->show ? o->show : BG_SHOW_DEFAULT;
  if (bg_style_load(&d->st, o->style, o->style_dir, dg) != 0) goto fail;
  alloc_nodes(d);
  if (mark_hot(d, dg) != 0) goto fail;
  measure_nodes(d);
  if (run_layout(d, dg) != 0) goto fail;
  bg_geom_bonds(d);
  bg_scene_init(&d->scene, d->st.font);
  d->scene.background = d->st.background;
  d->scene.title = bg_arena_strdup(&d->scene.arena, m->title ? m->title : m->name ? m->name : "");
  draw_all(d);
  return d;
fail:
  bg_diagram_free(d);
  return NULL;
}

void bg_diagram_free(bg_diagram *d) {
  if (!d) return;
  bg_layout_free(&d->lay);
  free(d->placed);
  bg_scene_free(&d->scene);
  bg_arena_free(&d->arena);
  free(d);
}
