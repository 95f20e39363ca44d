/* SPDX-License-Identifier: BSD-3-Clause */
/* Multiport fields in the diagram (docs/drawing.md): a field is one node
 * ("C : K") with one bond per port, each labelled with its port's name at
 * the field's end. The model keeps one element per port; here the first
 * port's node draws the field and the other ports' nodes are hidden: they
 * are left out of the layout and take the field node's box, so every bond,
 * stroke, path and signal that ends at a port ends at the field's box. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

/* "C : K" (MC when a port is modulated), or the field's label. */
static char *field_markup(bg_diagram_layout *d, int f) {
  const bg_model *m = d->m;
  int p1 = m->field_elemadr[f], mod = 0;
  for (int k = 0; k < m->field_nport[f]; k++) mod |= m->elem_modulated[p1 + k];
  bg_strbuf b = {0};
  bg_sb_printf(&b, "%s%s", mod ? "M" : "", bg_elem_kind_name(m->field_kind[f]));
  if (d->show & BG_SHOW_LABELS) {
    bg_sb_puts(&b, " : ");
    if (m->elem_label && m->elem_label[p1]) bg_markup_escapen(&b, m->elem_label[p1], strlen(m->elem_label[p1]));
    else bg_name_markup(&b, m->field_name[f], d->st.font_size);
  }
  char *s = bg_arena_strdup(&d->arena, bg_sb_str(&b));
  bg_sb_free(&b);
  return s;
}

/* The field's label on its first port's node, in d's style (the layout's
 * reference style too: diagram.c measures it like every label). */
void bg_fields_labels(bg_diagram_layout *d) {
  for (int f = 0; f < d->m->nfield; f++) d->nlabel[d->m->field_elemadr[f]] = field_markup(d, f);
}

void bg_fields_prepare(bg_diagram_layout *d) {
  const bg_model *m = d->m;
  if (!m->nfield) return;
  d->rep = bg_arena_alloc(&d->arena, ((size_t)d->nnode + 1) * sizeof *d->rep);
  for (int n = 0; n < d->nnode; n++) d->rep[n] = n;
  for (int f = 0; f < m->nfield; f++) {
    int p1 = m->field_elemadr[f];
    for (int k = 1; k < m->field_nport[f]; k++) {
      d->rep[p1 + k] = p1;
      d->nw[p1 + k] = d->nw[p1], d->nh[p1 + k] = d->nh[p1];
    }
  }
}

/* ---------------------------------------------------------------- layout */
struct bg_fields_lay {
  int *vis;     /* node -> layout node, or -1 (hidden) */
  int *back;    /* layout node -> node */
  int n;
  double *w, *h, *px, *py;
  int *pinned, *tail, *head, *cluster;
  unsigned char *root, *dead_end;
  int *link_a, *link_b; /* the links (rows), in the compacted numbering */
};

static int lay_node(const bg_diagram_layout *d, const bg_fields_lay *L, int n) { return L->vis[d->rep[n]]; }

bg_fields_lay *bg_fields_compact(const bg_diagram_layout *d, bg_layout_in *in) {
  if (!d->rep) return NULL;
  bg_fields_lay *L = calloc(1, sizeof *L);
  int nn = in->nnode;
  L->vis = malloc(sizeof(int) * (size_t)(nn + 1));
  L->back = malloc(sizeof(int) * (size_t)(nn + 1));
  for (int v = 0; v < nn; v++) {
    L->vis[v] = bg_fields_hidden(d, v) ? -1 : L->n;
    if (L->vis[v] >= 0) L->back[L->n++] = v;
  }
  size_t k = (size_t)L->n + 1, ne = (size_t)in->nedge + 1;
  L->w = malloc(k * sizeof(double)), L->h = malloc(k * sizeof(double));
  L->px = calloc(k, sizeof(double)), L->py = calloc(k, sizeof(double));
  L->pinned = calloc(k, sizeof(int)), L->cluster = malloc(k * sizeof(int));
  L->root = calloc(k, 1), L->dead_end = calloc(k, 1);
  for (int i = 0; i < L->n; i++) {
    int v = L->back[i];
    L->w[i] = in->w[v], L->h[i] = in->h[v];
    if (in->pinned) L->pinned[i] = in->pinned[v], L->px[i] = in->px[v], L->py[i] = in->py[v];
    if (in->root) L->root[i] = in->root[v];
    if (in->dead_end) L->dead_end[i] = in->dead_end[v];
    L->cluster[i] = in->cluster ? in->cluster[v] : -1;
  }
  L->tail = malloc(ne * sizeof(int)), L->head = malloc(ne * sizeof(int));
  for (int i = 0; i < in->nedge; i++)
    L->tail[i] = lay_node(d, L, in->tail[i]), L->head[i] = lay_node(d, L, in->head[i]);
  L->link_a = malloc(((size_t)in->nlink + 1) * sizeof(int)), L->link_b = malloc(((size_t)in->nlink + 1) * sizeof(int));
  for (int i = 0; i < in->nlink; i++)
    L->link_a[i] = lay_node(d, L, in->link_a[i]), L->link_b[i] = lay_node(d, L, in->link_b[i]);
  if (in->nlink) in->link_a = L->link_a, in->link_b = L->link_b;
  in->nnode = L->n, in->w = L->w, in->h = L->h, in->tail = L->tail, in->head = L->head;
  if (in->pinned) in->pinned = L->pinned, in->px = L->px, in->py = L->py;
  if (in->root) in->root = L->root;
  if (in->dead_end) in->dead_end = L->dead_end;
  if (in->cluster) in->cluster = L->cluster;
  return L;
}

/* The laid-out positions back on every node: a hidden port where its field is. */
void bg_fields_expand(bg_diagram_layout *d, bg_fields_lay *L) {
  if (!L) return;
  bg_layout *lay = &d->lay;
  if (!lay->x) lay->nnode = L->n; /* the layout failed: nothing to move */
  double *x = malloc(sizeof(double) * ((size_t)d->nnode + 1));
  double *y = malloc(sizeof(double) * ((size_t)d->nnode + 1));
  for (int v = 0; lay->x && v < d->nnode; v++) {
    int i = L->vis[d->rep[v]];
    x[v] = lay->x[i], y[v] = lay->y[i];
  }
  if (lay->x) {
    free(lay->x), free(lay->y);
    lay->x = x, lay->y = y, lay->nnode = d->nnode;
  } else free(x), free(y);
  free(L->vis), free(L->back), free(L->w), free(L->h), free(L->px), free(L->py);
  free(L->pinned), free(L->tail), free(L->head), free(L->cluster), free(L->root), free(L->dead_end);
  free(L->link_a), free(L->link_b);
  free(L);
}

/* ---------------------------------------------------------------- port names */
/* Each port's name beside its bond, just outside the field's box ("el",
 * "[2]" for a numbered port); drawn before the bond numbers, which keep off
 * it (on the grid's short bonds a number sat on "[1]"). */
void bg_draw_field_ports(bg_diagram *d) {
  const bg_model *m = d->m;
  double size = d->st.font_size * d->st.number_scale;
  for (int f = 0; f < m->nfield; f++)
    for (int k = 0; k < m->field_nport[f]; k++) {
      int pe = m->field_elemadr[f] + k, b = bg_elem_port_bond(m, pe);
      if (b < 0) continue;
      const bg_bond_geom *g = &d->L->bg[b];
      int at_tail = m->bond_tail[b] == pe;
      bg_vec end = at_tail ? g->tail : g->head, out = at_tail ? g->tdir : bg_vscale(g->hdir, -1);
      bg_vec side = bg_vleft(out);
      bg_vec p = bg_vadd(end, bg_vadd(bg_vscale(out, 0.9 * size), bg_vscale(side, 0.8 * size)));
      /* italic, and a number in brackets, so a port never reads as a bond number */
      bg_strbuf t = {0};
      const char *name = bg_elem_port_name(m, pe);
      bg_sb_puts(&t, m->field_numbered[f] ? "<i>[" : "<i>");
      bg_markup_escapen(&t, name, strlen(name));
      bg_sb_puts(&t, m->field_numbered[f] ? "]</i>" : "</i>");
      char role[160];
      snprintf(role, sizeof role, "port %s", m->elem_name[pe]);
      bg_scene_text(&d->scene, bg_sb_str(&t), p.x, p.y, size, 0.5, 0.5,
                    bg_diagram_ink(d, d->st.fg, d->hot_elem[pe]), role);
      bg_sb_free(&t);
      double box[4]; /* the bond numbers, placed after, keep off it */
      bg_scene_item_box(&d->scene, &d->scene.item[d->scene.nitem - 1], box);
      bg_obstacle_rect(d, box[0], box[1], box[2], box[3]);
    }
}
