/* SPDX-License-Identifier: BSD-3-Clause */
/* The annotated graph in Graphviz DOT with the computed positions (points,
 * y up, as Graphviz writes them): `neato -n2 -Tsvg x.dot` redraws it. Written
 * by hand from the layout so the text is deterministic. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

static void dot_str(bg_strbuf *b, const char *s) {
  bg_sb_putc(b, '"');
  for (; *s; s++) {
    if (*s == '"' || *s == '\\') bg_sb_putc(b, '\\');
    bg_sb_putc(b, *s);
  }
  bg_sb_putc(b, '"');
}

static double yup(const bg_diagram *d, double y) { return d->L->lay.height - y; }

/* The user state whose integrator node n is, or -1. */
static int node_state(const bg_diagram *d, int n) { return d->L->node_state[n]; }

/* The instance whose box node n is, else -1 (and *det: the detector node n draws, or -1). */
static int node_part(const bg_diagram *d, int n, int *det) {
  *det = -1;
  if (d->L->box_inst[n] >= 0) return d->L->box_inst[n];
  *det = d->L->node_det[n];
  return -1;
}

static void node_id(const bg_diagram *d, int n, bg_strbuf *out) {
  int f = n < d->m->nelem ? bg_elem_field(d->m, n) : -1;
  if (f >= 0) { /* a field is one node, named as the field */
    dot_str(out, d->m->field_name[f]);
    return;
  }
  if (n < d->m->nelem) {
    dot_str(out, d->m->elem_name[n]);
    return;
  }
  int det, box = node_part(d, n, &det);
  if (box >= 0 || det >= 0) { /* a collapsed instance by its name, a detector "De:vC" */
    bg_strbuf id = {0};
    if (box >= 0) bg_sb_puts(&id, d->m->inst_name[box]);
    else bg_sb_printf(&id, "%s:%s", d->m->det_var[det] == 'e' ? "De" : "Df", d->m->det_name[det]);
    dot_str(out, bg_sb_str(&id));
    bg_sb_free(&id);
    return;
  }
  int s = node_state(d, n);
  if (s >= 0) {
    bg_strbuf id = {0};
    bg_sb_printf(&id, "state:%s", d->m->state_name[s]);
    dot_str(out, bg_sb_str(&id));
    bg_sb_free(&id);
    return;
  }
  char id[32];
  snprintf(id, sizeof id, "Sf*%d", n - d->m->nelem + 1);
  dot_str(out, id);
}

static const char *conflict_at(const bg_diagram *d, int e, char *buf, size_t n) {
  for (int k = 0; d->a && k < d->a->nconflict; k++) {
    if (d->a->conflict_node[k] != e) continue;
    if (d->a->conflict_type[k] == 1) snprintf(buf, n, "type 1");
    else snprintf(buf, n, "type 2, k = %d", d->a->conflict_degree[k]);
    return buf;
  }
  return NULL;
}

static void write_node(const bg_diagram *d, int n, bg_strbuf *out) {
  const bg_model *m = d->m;
  bg_sb_puts(out, "  ");
  node_id(d, n, out);
  bg_sb_puts(out, " [label=");
  int det = -1, box = n >= m->nelem ? node_part(d, n, &det) : -1;
  int f = n < m->nelem ? bg_elem_field(m, n) : -1;
  if (n < m->nelem && bg_elem_is_junction(m->elem_kind[n])) dot_str(out, bg_elem_display_kind(m, n));
  else if (f >= 0) {
    bg_strbuf l = {0};
    bg_sb_printf(&l, "%s : %s", bg_elem_kind_name(m->field_kind[f]), m->field_name[f]);
    dot_str(out, bg_sb_str(&l));
    bg_sb_free(&l);
  } else if (n < m->nelem) {
    bg_strbuf l = {0};
    bg_sb_printf(&l, "%s : %s", bg_elem_display_kind(m, n), m->elem_name[n]);
    dot_str(out, bg_sb_str(&l));
    bg_sb_free(&l);
  } else if (box >= 0 || det >= 0) {
    bg_strbuf l = {0};
    if (box >= 0) bg_sb_printf(&l, "%s : %s", m->inst_name[box], m->inst_def[box]);
    else bg_sb_printf(&l, "%s : %s", m->det_var[det] == 'e' ? "De" : "Df", m->det_name[det]);
    dot_str(out, bg_sb_str(&l));
    bg_sb_free(&l);
    if (box >= 0) bg_sb_puts(out, ", shape=box, bg_collapsed=1");
  } else if (node_state(d, n) >= 0) {
    bg_strbuf l = {0};
    bg_sb_printf(&l, "\u222b : %s", m->state_name[node_state(d, n)]);
    dot_str(out, bg_sb_str(&l));
    bg_sb_free(&l);
    bg_sb_puts(out, ", fontcolor=\"#8b3a1a\"");
  } else {
    bg_sb_puts(out, "\"Sf*\", style=dashed, shape=box");
  }
  bg_sb_printf(out, ", pos=\"%.2f,%.2f\", width=%.4f, height=%.4f", d->L->nx[n], yup(d, d->L->ny[n]),
               d->L->nw[n] / 72, d->L->nh[n] / 72);
  char c[64];
  if (n < m->nelem && conflict_at(d, n, c, sizeof c)) {
    bg_sb_puts(out, ", fontcolor=red, bg_conflict=");
    dot_str(out, c);
  }
  bg_sb_puts(out, "];\n");
}

/* Graphviz arrow lengths (arrowsize 1): lvee 10 pt, tee 5 pt, teelvee both. */
enum { ARROW_LVEE = 10, ARROW_TEE = 5 };

static void put_pt(const bg_diagram *d, bg_strbuf *out, bg_vec p, int first) {
  bg_sb_printf(out, "%s%.2f,%.2f", first ? "" : " ", p.x, yup(d, p.y));
}

/* The bond as Graphviz writes an edge: "e,x,y" the head's arrow tip, "s,x,y"
 * the tail's (with a stroke there), then cubic Bezier points from where the
 * tail arrow ends to where the head arrow starts (a straight or bent bond:
 * straight pieces, one per leg), so `neato -n2` draws the half arrow and the
 * strokes where bgdraw does. */
static void write_pos(const bg_diagram *d, int b, int stroke, bg_strbuf *out) {
  const bg_bond_geom *g = &d->L->bg[b];
  double elen = ARROW_LVEE + (stroke == BG_STROKE_HEAD ? ARROW_TEE : 0);
  double slen = stroke == BG_STROKE_TAIL ? ARROW_TEE : 0;
  int n = g->spln ? 0 : g->bendn + 2;
  bg_vec *p = bg_xcalloc((size_t)(g->spln ? g->spln : n) + 1, sizeof *p);
  if (g->spln)
    for (int i = 0; i < g->spln; i++) p[i] = bg_v(d->L->splx[g->spladr + i], d->L->sply[g->spladr + i]);
  else
    for (int i = 0; i < n; i++)
      p[i] = i == 0 ? g->tail : i == n - 1 ? g->head
                             : bg_v(d->L->lay.bendx[g->bendadr + i - 1], d->L->lay.bendy[g->bendadr + i - 1]);
  int last = g->spln ? g->spln - 1 : n - 1;
  /* short legs keep a third of their length */
  double lh = bg_vlen(bg_vsub(p[last], p[last - 1])), lt = bg_vlen(bg_vsub(p[1], p[0]));
  elen = fmin(elen, 2 * lh / 3), slen = fmin(slen, 2 * lt / 3);
  bg_sb_puts(out, ", pos=\"");
  bg_sb_printf(out, "e,%.2f,%.2f ", p[last].x, yup(d, p[last].y));
  if (slen > 0) bg_sb_printf(out, "s,%.2f,%.2f ", p[0].x, yup(d, p[0].y));
  p[last] = bg_vsub(p[last], bg_vscale(g->hdir, elen));
  p[0] = bg_vadd(p[0], bg_vscale(g->tdir, slen));
  if (g->spln) {
    for (int i = 0; i <= last; i++) put_pt(d, out, p[i], i == 0);
  } else {
    put_pt(d, out, p[0], 1);
    for (int i = 0; i + 1 < n; i++)
      for (int k = 1; k <= 3; k++) put_pt(d, out, bg_vadd(p[i], bg_vscale(bg_vsub(p[i + 1], p[i]), k / 3.0)), 0);
  }
  bg_sb_putc(out, '"');
  free(p);
}

static void write_bond(const bg_diagram *d, int b, bg_strbuf *out) {
  const bg_model *m = d->m;
  int stroke = d->a ? d->a->bond_stroke[b] : BG_STROKE_NONE;
  bg_sb_puts(out, "  ");
  node_id(d, d->L->node_of[m->bond_tail[b]], out);
  bg_sb_puts(out, " -> ");
  node_id(d, d->L->node_of[m->bond_head[b]], out);
  bg_sb_printf(out, " [label=\"%d\", bg_bond=%d, arrowhead=%s", m->bond_num[b], m->bond_num[b],
               stroke == BG_STROKE_HEAD ? "teelvee" : "lvee");
  if (stroke == BG_STROKE_TAIL) bg_sb_puts(out, ", dir=both, arrowtail=tee");
  bg_sb_printf(out, ", bg_stroke=%s",
               stroke == BG_STROKE_HEAD ? "head" : stroke == BG_STROKE_TAIL ? "tail" : "none");
  if (d->a && d->a->bond_conflict && d->a->bond_conflict[b]) bg_sb_puts(out, ", color=red, bg_conflict=1");
  for (int k = 0; k < 2; k++) { /* a field's port: its name at that end */
    int e = k ? m->bond_head[b] : m->bond_tail[b];
    if (bg_elem_field(m, e) < 0) continue;
    bg_sb_puts(out, k ? ", headlabel=" : ", taillabel=");
    dot_str(out, bg_elem_port_name(m, e));
  }
  write_pos(d, b, stroke, out);
  bg_sb_puts(out, "];\n");
}

static void write_extras(const bg_diagram *d, bg_strbuf *out) {
  const bg_model *m = d->m;
  for (int s = 0; s < m->nstate; s++) {
    if (d->L->state_node[s] < 0) continue;
    int in[64], nin = bg_state_inputs(m, s, in, 64);
    for (int k = 0; k < nin; k++) {
      bg_sb_puts(out, "  ");
      node_id(d, in[k], out);
      bg_sb_puts(out, " -> ");
      node_id(d, d->L->state_node[s], out);
      bg_sb_puts(out, " [style=dashed, color=\"#8b3a1a\", arrowhead=normal, bg_state_input=1];\n");
    }
  }
  for (int k = 0; k < m->ndet; k++) {
    if (d->L->det_draw[k] < 0) continue;
    bg_sb_puts(out, "  ");
    node_id(d, bg_detector_anchor(d->L, k), out);
    bg_sb_puts(out, " -> ");
    node_id(d, d->L->det_draw[k], out);
    bg_sb_puts(out, " [arrowhead=normal, bg_detector=1];\n"); /* an activated bond */
  }
  for (int i = 0; i < m->nsignal; i++) {
    int from = m->signal_from[i], s = bg_signal_state(d->L, i), to = d->L->node_of[m->signal_to[i]];
    if (from < 0 && s >= 0) from = d->L->state_node[s];
    if (from < 0) continue; /* a bond variable: no node to start from */
    from = d->L->node_of[from];
    if (from == to && to != m->signal_to[i]) continue; /* inside a collapsed instance */
    bg_sb_puts(out, "  ");
    node_id(d, from, out);
    bg_sb_puts(out, " -> ");
    node_id(d, to, out);
    bg_sb_puts(out, " [style=dashed, color=\"#8b3a1a\", arrowhead=normal, bg_signal=");
    dot_str(out, m->signal_var[i] ? m->signal_var[i] : "");
    bg_sb_puts(out, "];\n");
  }
  for (int i = 0; d->a && i < d->a->nlag; i++) {
    if (d->L->lag_node[i] < 0) continue;
    bg_sb_puts(out, "  ");
    node_id(d, d->L->lag_node[i], out);
    bg_sb_puts(out, " -> ");
    node_id(d, d->a->lag_junction[i], out);
    bg_sb_puts(out, " [style=dashed, arrowhead=lvee, dir=both, arrowtail=tee];\n");
  }
}

static void write_layers(const bg_diagram *d, bg_strbuf *out) {
  const bg_analysis *a = d->a;
  if (!a) return;
  for (int kind = 0; kind < 2; kind++) {
    int n = kind ? a->ntloop : a->npath;
    for (int i = 0; i < n; i++) {
      bg_strbuf t = {0};
      bg_layer_describe(d, kind ? 'l' : 'p', i, 0, &t);
      bg_sb_printf(out, "  bg_%s%d=", kind ? "loop" : "path", i + 1);
      dot_str(out, bg_sb_str(&t));
      bg_sb_puts(out, ";\n");
      bg_sb_free(&t);
    }
  }
}

void bg_diagram_write_dot(const bg_diagram *d, bg_strbuf *out) {
  const bg_model *m = d->m;
  bg_sb_puts(out, "/* bgdraw: annotated bond graph; positions in points. Redraw: neato -n2 -Tsvg */\n");
  bg_sb_puts(out, "digraph ");
  dot_str(out, m->name ? m->name : "bg");
  bg_sb_printf(out, " {\n  graph [bb=\"0,0,%.2f,%.2f\", bg_engine=\"%s\"];\n", d->L->lay.width,
               d->L->lay.height, d->L->lay.engine);
  bg_sb_printf(out, "  node [shape=plaintext, fixedsize=true, fontname=\"%s\", fontsize=%.1f];\n",
               d->st.font, d->st.font_size);
  bg_sb_printf(out, "  edge [fontsize=%.1f];\n", d->st.font_size * d->st.number_scale);
  write_layers(d, out);
  for (int n = 0; n < d->L->nnode; n++)
    if (bg_node_shown(d->L, n) && !bg_fields_hidden(d->L, n)) write_node(d, n, out);
  for (int b = 0; b < m->nbond; b++)
    if (!d->L->bond_hidden[b]) write_bond(d, b, out);
  write_extras(d, out);
  bg_sb_puts(out, "}\n");
}
