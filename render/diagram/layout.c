/* SPDX-License-Identifier: BSD-3-Clause */
/* Graphviz layout through libgvc/libcgraph (never the dot program): fixed
 * size, unlabelled box nodes whose sizes come from pango measurements, so the
 * positions fit the labels bgdraw draws. Graphviz's y axis points up: we flip. */
#include "diagram/layout.h"

#include <graphviz/cgraph.h>
#include <graphviz/gvc.h>
#include <graphviz/graphviz_version.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"

static const char *const engines[] = {"dot", "neato", "fdp", "sfdp", "pinned", "rows"};

int bg_layout_engine_ok(const char *name) {
  for (size_t i = 0; i < sizeof engines / sizeof engines[0]; i++)
    if (name && !strcmp(name, engines[i])) return 1;
  return 0;
}

static void set_num(void *obj, const char *attr, double v) {
  char buf[64];
  snprintf(buf, sizeof buf, "%.4f", v);
  agsafeset(obj, (char *)attr, buf, "");
}

static void graph_attrs(Agraph_t *g, const bg_layout_in *in, int is_dot) {
  agsafeset(g, "splines", in->splines && is_dot ? "true" : "false", "");
  set_num(g, "nodesep", in->node_sep / 72);
  if (is_dot) {
    agsafeset(g, "rankdir", (char *)(in->rankdir ? in->rankdir : "LR"), "");
    set_num(g, "ranksep", in->rank_sep / 72);
  } else {
    agsafeset(g, "overlap", "false", "");
    set_num(g, "sep", in->node_sep / 2);
    set_num(g, "K", (in->rank_sep + 30) / 72);
    agsafeset(g, "inputscale", "72", "");
    agsafeset(g, "start", "1", ""); /* a fixed seed: reproducible layouts */
  }
  agattr(g, AGNODE, "shape", "box");
  agattr(g, AGNODE, "fixedsize", "true");
  agattr(g, AGNODE, "label", "");
  agattr(g, AGEDGE, "dir", "none");
  agattr(g, AGEDGE, "constraint", "true"); /* before any edge sets it to false */
}

static Agnode_t **add_nodes(Agraph_t *g, const bg_layout_in *in) {
  Agnode_t **nodes = bg_xcalloc((size_t)in->nnode, sizeof *nodes);
  for (int i = 0; i < in->nnode; i++) {
    char name[32];
    snprintf(name, sizeof name, "n%d", i);
    nodes[i] = agnode(g, name, 1);
    set_num(nodes[i], "width", in->w[i] / 72);
    set_num(nodes[i], "height", in->h[i] / 72);
    if (in->pinned && in->pinned[i]) {
      char pos[96];
      snprintf(pos, sizeof pos, "%.3f,%.3f!", in->px[i], in->py[i]);
      agsafeset(nodes[i], "pos", pos, "");
    }
  }
  return nodes;
}

/* Edges; with in->root (dot), each runs from the node nearer the roots to the
 * farther one (rev[i] set where that is head → tail) and edges between nodes
 * at the same distance do not constrain the ranks. */
static Agedge_t **add_edges(Agraph_t *g, const bg_layout_in *in, Agnode_t **nodes, int is_dot,
                            unsigned char *rev) {
  Agedge_t **edges = bg_xcalloc((size_t)(in->nedge ? in->nedge : 1), sizeof *edges);
  int *depth = is_dot && in->root ? bg_layout_depths(in, NULL) : NULL;
  for (int i = 0; i < in->nedge; i++) {
    char name[32];
    snprintf(name, sizeof name, "e%d", i);
    int t = in->tail[i], h = in->head[i];
    rev[i] = depth && depth[t] > depth[h];
    edges[i] = agedge(g, nodes[rev[i] ? h : t], nodes[rev[i] ? t : h], name, 1);
    /* two ways round a ring meeting (the same distance, or instances
     * reached whole from two sides: bg_layout_depths) */
    if (depth && abs(depth[t] - depth[h]) != 1) agsafeset(edges[i], "constraint", "false", "");
    if (is_dot && in->weight && in->weight[i] != 1) {
      char w[16];
      snprintf(w, sizeof w, "%d", in->weight[i]);
      agsafeset(edges[i], "weight", w, "1");
    }
  }
  free(depth);
  return edges;
}

static void read_nodes(Agraph_t *g, Agnode_t **nodes, const bg_layout_in *in, bg_layout *out) {
  boxf bb = GD_bb(g);
  out->width = bb.UR.x - bb.LL.x;
  out->height = bb.UR.y - bb.LL.y;
  out->x = bg_xcalloc((size_t)in->nnode + 1, sizeof *out->x);
  out->y = bg_xcalloc((size_t)in->nnode + 1, sizeof *out->y);
  for (int i = 0; i < in->nnode; i++) {
    out->x[i] = ND_coord(nodes[i]).x - bb.LL.x;
    out->y[i] = bb.UR.y - ND_coord(nodes[i]).y;
  }
}

/* Spline control points of each edge, flipped like the nodes. */
static void read_edges(Agraph_t *g, Agedge_t **edges, const bg_layout_in *in,
                       const unsigned char *rev, bg_layout *out) {
  boxf bb = GD_bb(g);
  size_t n = (size_t)in->nedge + 1;
  out->spladr = bg_xcalloc(n, sizeof *out->spladr);
  out->spln = bg_xcalloc(n, sizeof *out->spln);
  int cap = 0;
  for (int i = 0; i < in->nedge; i++) {
    splines *spl = ED_spl(edges[i]);
    out->spladr[i] = out->nspl;
    if (!spl || spl->size < 1 || !in->splines) continue;
    bezier *bz = &spl->list[0]; /* one piece: no compound or multi-part edges */
    if (out->nspl + bz->size > cap) {
      cap = 2 * (out->nspl + bz->size) + 64;
      out->splx = bg_xrealloc(out->splx, (size_t)cap * sizeof *out->splx);
      out->sply = bg_xrealloc(out->sply, (size_t)cap * sizeof *out->sply);
    }
    for (int k = 0; k < bz->size; k++) {
      pointf p = bz->list[rev[i] ? bz->size - 1 - k : k]; /* back to tail → head */
      out->splx[out->nspl + k] = p.x - bb.LL.x;
      out->sply[out->nspl + k] = bb.UR.y - p.y;
    }
    out->spln[i] = bz->size;
    out->nspl += bz->size;
  }
}

/* Clusters (dot): a subgraph "cluster_K" per cluster, nested as given, its
 * label sized to the room the caller draws its own label in. */
static Agraph_t **add_clusters(Agraph_t *g, const bg_layout_in *in, Agnode_t **nodes) {
  Agraph_t **sub = bg_xcalloc((size_t)in->ncluster + 1, sizeof *sub);
  for (int k = 0; k < in->ncluster; k++) {
    char name[32];
    snprintf(name, sizeof name, "cluster_%d", k);
    int p = in->cluster_parent[k];
    sub[k] = agsubg(p >= 0 && p < k ? sub[p] : g, name, 1);
    /* a blank label as tall as ours: dot keeps room for it at the top */
    agsafeset(sub[k], "label", " ", "");
    set_num(sub[k], "fontsize", in->cluster_label_h[k]);
    agsafeset(sub[k], "labeljust", "l", "");
    agsafeset(sub[k], "margin", "10", "");
  }
  for (int i = 0; i < in->nnode; i++)
    if (in->cluster[i] >= 0 && in->cluster[i] < in->ncluster)
      agsubnode(sub[in->cluster[i]], nodes[i], 1);
  return sub;
}

int bg_layout_run(const bg_layout_in *in, bg_layout *out, char *err, size_t errn) {
  memset(out, 0, sizeof *out);
  const char *engine = in->engine ? in->engine : "dot";
  if (!bg_layout_engine_ok(engine)) {
    snprintf(err, errn, "unknown layout engine '%s' (dot, neato, fdp, sfdp, pinned, rows)", engine);
    return -1;
  }
  if (!strcmp(engine, "rows")) {
    snprintf(out->engine, sizeof out->engine, "rows");
    out->nnode = in->nnode, out->nedge = in->nedge;
    return bg_layout_rows(in, out);
  }
  int is_dot = !strcmp(engine, "dot");
  const char *gv_engine = !strcmp(engine, "pinned") ? "neato" : engine;
  snprintf(out->engine, sizeof out->engine, "%s", engine);
  out->nnode = in->nnode, out->nedge = in->nedge;
  /* Graphviz keeps process-wide state (its error level, cgraph's and the
   * layout engines' statics, this context): one layout at a time */
  static pthread_mutex_t gv_lock = PTHREAD_MUTEX_INITIALIZER;
  pthread_mutex_lock(&gv_lock);
  agseterr(AGMAX); /* Graphviz warnings are ours to report, not its to print */
  /* one context per process: creating it reads Graphviz's plugin
   * configuration (slow, and it leaks inside libgvc 2.43 every time) */
  static GVC_t *gvc;
  if (!gvc) gvc = gvContext();
  Agraph_t *g = agopen("bg", Agdirected, NULL);
  graph_attrs(g, in, is_dot);
  Agnode_t **nodes = add_nodes(g, in);
  int clusters = is_dot && in->ncluster > 0 && in->cluster;
  Agraph_t **sub = clusters ? add_clusters(g, in, nodes) : NULL;
  unsigned char *rev = bg_xcalloc((size_t)in->nedge + 1, 1);
  Agedge_t **edges = add_edges(g, in, nodes, is_dot, rev);
  int rc = gvLayout(gvc, g, gv_engine);
  if (rc == 0) {
    read_nodes(g, nodes, in, out);
    read_edges(g, edges, in, rev, out);
    gvFreeLayout(gvc, g);
  } else {
    snprintf(err, errn, "Graphviz layout with '%s' failed", gv_engine);
  }
  free(nodes);
  free(edges);
  free(rev);
  free(sub);
  agclose(g);
  pthread_mutex_unlock(&gv_lock);
  return rc == 0 ? 0 : -1;
}

void bg_layout_free(bg_layout *l) {
  free(l->x);
  free(l->y);
  free(l->spladr);
  free(l->spln);
  free(l->splx);
  free(l->sply);
  free(l->bendadr);
  free(l->bendn);
  free(l->bendx);
  free(l->bendy);
  free(l->band);
  memset(l, 0, sizeof *l);
}

const char *bg_layout_graphviz_version(void) { return PACKAGE_VERSION; }
