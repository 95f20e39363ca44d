/* SPDX-License-Identifier: BSD-3-Clause */
/* Section 3's highlights of a large diagram, seen in section 2's scene
 * instead of drawn again (docs/report.md, "Large diagrams"). A redraw lays
 * out every label of the whole diagram once more, seconds at 10^5 bonds and
 * twelve times over, for a page that shows the highlighted item's
 * neighbourhood. Above RP_HL_FULL_ITEMS scene items a highlight is a view
 * of section 2's diagram instead: its own hot bonds and elements
 * (bg_diagram_hot, as a redraw marks them), everything else shared read
 * only; its page keeps the items of section 2's scene in its region with
 * the highlighted item in colour, everything else in the style's muted
 * colour, and the other paths, loops and the legend left out, so it shows
 * the layers a highlighted diagram shows (BG_SHOW_DEFAULT and its item).
 * What differs from a redraw: the bond numbers and the item's line stand
 * where section 2 placed them among every layer. */
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"
#include "report/report_int.h"

int rp_hl_from_full(const rp_ctx *c) {
  int limit = c->hl_full_items > 0 ? c->hl_full_items : RP_HL_FULL_ITEMS;
  return c->full && c->full->scene.nitem > limit;
}

bg_diagram *rp_hl_view(const rp_ctx *c, int kind, int index) {
  const bg_diagram *f = c->full;
  bg_diagram *v = bg_xmalloc(sizeof *v);
  *v = *f; /* everything shared, read only; rp_hl_done frees only what is its own */
  v->o.highlight_kind = kind, v->o.highlight_index = index;
  v->hot_bond = bg_xcalloc((size_t)f->m->nbond + 1, 1);
  v->hot_elem = bg_xcalloc((size_t)f->L->nnode + 1, 1);
  bg_diagram_hot(f->L, kind, index, v->hot_bond, v->hot_elem);
  return v;
}

void rp_hl_done(const rp_ctx *c, bg_diagram *d) {
  if (!d) return;
  if (!rp_hl_from_full(c)) {
    bg_diagram_free(d);
    return;
  }
  free(d->hot_bond);
  free(d->hot_elem);
  free(d);
}

/* ---------------------------------------------------------------- the page */
enum { DROP, MUTE, KEEP };

/* The number after "key" in role ("bond=12" -> 12), or -1. */
static int role_value(const char *role, const char *key) {
  const char *p = strstr(role, key);
  return p ? atoi(p + strlen(key)) : -1;
}

/* Whether role's first word (n bytes) is one of the names (NULL-ended). */
static int word_is(const char *role, size_t n, const char *const *names) {
  for (; *names; names++)
    if (strlen(*names) == n && !strncmp(role, *names, n)) return 1;
  return 0;
}

/* What the page does with item i of section 2's scene s. */
static int fate(const bg_diagram *v, const bg_scene *s, int i) {
  static const char *const path[] = {"path", "path-arrow", "path-tag", "path-leader", "path-leader-dot", NULL};
  static const char *const loop[] = {"loop", "loop-arrow", NULL};
  static const char *const gain[] = {"gain", "gain-leader", "gain-leader-dot", NULL};
  static const char *const conflict[] = {"flash", "conflict-text", NULL};
  const char *r = s->item[i].role;
  int kind = v->o.highlight_kind, k = v->o.highlight_index;
  size_t w = strcspn(r, " ");
  /* a halo (the background patch under a label) goes with its label */
  if (!strcmp(r, "halo")) return i + 1 < s->nitem && fate(v, s, i + 1) != DROP ? KEEP : DROP;
  if (!strncmp(r, "legend", 6)) return DROP;
  if (word_is(r, w, path)) return kind == 'p' && atoi(r + w) == k ? KEEP : DROP;
  if (word_is(r, w, loop)) return kind == 'l' && atoi(r + w) == k ? KEEP : DROP;
  if (word_is(r, w, gain)) return kind == 'l' && role_value(r, "loop=") == k ? KEEP : DROP;
  if (word_is(r, w, conflict)) return kind == 'c' && role_value(r, "conflict=") == k ? KEEP : MUTE;
  if (!strncmp(r, "node ", 5)) {
    int e = bg_model_find_elem(v->m, r + 5);
    return e >= 0 && v->hot_elem[e] ? KEEP : MUTE;
  }
  int num = !strncmp(r, "bond ", 5) ? atoi(r + 5) : role_value(r, "bond=");
  int b = num >= 0 ? bg_model_find_bond(v->m, num) : -1;
  return b >= 0 && v->hot_bond[b] ? KEEP : MUTE;
}

static int same_rgb(bg_rgba a, bg_rgba b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

static int keep_item(void *ctx, const bg_scene *s, int i, bg_scene_item *it) {
  const bg_diagram *v = ctx;
  int f = fate(v, s, i);
  if (f == DROP) return 0;
  if (f == MUTE && strcmp(it->role, "halo")) { /* as bg_diagram_ink mutes a redraw */
    it->color = v->st.muted;
    if (it->kind == BG_ITEM_FILL && !same_rgb(it->fill, s->background)) it->fill = v->st.muted;
  }
  return 1;
}

void rp_hl_crop(const bg_diagram *view, const double clip[4], bg_scene *dst) {
  bg_scene_crop_keep(&view->scene, clip, keep_item, (void *)view, dst);
}
