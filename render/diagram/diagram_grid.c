/* SPDX-License-Identifier: BSD-3-Clause */
/* The grid placement pass (docs/drawing.md, "Layout"): Graphviz's dot ranks
 * and orders the nodes; this pass puts the junction structure on a grid and
 * draws the bonds horizontal and vertical, the way textbooks draw bond graphs.
 *
 * Hubs (nodes with two or more bonds: junctions, two-ports) get a column from
 * their dot rank and a row from a tree drawing: each hangs from its parent
 * (the hub before it nearest in dot's order), the child with the longest
 * chain onward continues the parent's row (so the longest source-to-load
 * chain is the main row) and the other children's subtrees are stacked
 * above and below it, as near as their rows allow, in a tree in the
 * parent's own column, their bonds straight (assign_rows); a part whose
 * hubs form a rectangular mesh takes the mesh's lattice instead (mesh_rows). Grid cells: hubs at even (gx, gy); their one-ports
 * (leaves) go to a free side cell next to them (left, above, below, right, in
 * the order that best keeps dot's directions), else a diagonal one. A bond
 * between hubs is a straight run of free cells, else an elbow (one or two
 * corners) through free cells, else a straight slanted line; an elbow to a
 * branch whose side of the graph fits on the corner is made straight by
 * moving that side there (straighten_branches). Cells hold one
 * thing each, so routed bonds neither cross nor overlap. Components are
 * packed on a skyline; a component wider than its wrap width snakes into bands. Then
 * the cells become points: each grid column as wide as its widest node plus a
 * gap, each row likewise. Everything is linear in the graph size but the
 * sorts. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"
#include "base/sort.h"

enum { SIDE_R = 1, SIDE_U = 2, SIDE_L = 4, SIDE_D = 8 };
/* a route's corners at most (a maze route's, maze_hub_bonds; the others have two), and its points */
enum { MAX_CORNER = 10, MAX_PTS = MAX_CORNER + 2 };

typedef struct grid {
  bg_diagram_layout *d;
  int n, ne;          /* nodes; edges (bonds, then Sf* → junction) */
  int *et, *eh;       /* edge ends */
  int *adr, *adj;     /* node → incident edges (CSR) */
  int *deg;
  int *gx, *gy;       /* grid cell per node */
  unsigned char *placed, *hub, *sides;
  unsigned char *signalled; /* nodes where a signal starts or ends (bg_signal_end_nodes) */
  unsigned char *mesh; /* hubs placed on a mesh's lattice (mesh_rows): their part is not folded */
  int *tree_par;      /* hubs: the hub they hang from in the tree drawing (-1: a root; assign_rows) */
  unsigned char *spine; /* hubs: on their root's row chain (the root, the child continuing it, ...) */
  int *col, *row;     /* hubs: dot column, row */
  int *band;          /* hubs: the band of their part's fold they are in (stack_components) */
  /* cells: open addressing, key (gx, gy), value the owner (node n, or -2 - edge) */
  long long *key;
  int *val, cap, used;
  /* routes: per edge the corners (grid cells), bent[e] = count, -1: slanted */
  int *bent, (*corner)[2 * MAX_CORNER];
  int mazed;                /* a hub bond routed by maze_hub_bonds: no compaction */
  double *inst_cx, *inst_cy; /* per instance: the centre of its hubs (NULL: no instances) */
  /* one-ports round a hub whose next cells cannot hold them (ring_leaves;
   * NULL: none): per one-port its hub (-1: none) and offset from it in
   * points, per hub the width and height of its ring */
  int *orbit;
  double *ring_x, *ring_y, *ring_w, *ring_h;
  int own_ranks;            /* ranks from bg_grid_tree_ranks, not dot: a large forest */
  int spare_sides;          /* routing: keep off cells beside other hubs (walk) */
  unsigned char *turned;    /* nodes of parts whose bands turn upside down (NULL: none) */
  int *first_end;           /* per node the other end of its first signal, itself for a self
                               signal, -1: none (signal_hub; NULL until first asked) */
  int *up;                  /* the parts: union-find over the edges (find; find_parts) */
  unsigned char *cyclic;    /* per part's root: whether it has a cycle (cyclic_parts) */
  int *sadr, *slist;        /* per user state its signals, slist[sadr[s] ..] in order (state_signals) */
  const bg_style *ref;      /* the reference style and its boxes (bg_grid_place) */
  const double *rw, *rh;
} grid;

static double layer_band(const grid *g);
static void style_gaps(const bg_style *st, double band, double *xgap, double *ygap);

static unsigned long long cell_key(int x, int y) {
  return ((unsigned long long)(unsigned)x << 32) | (unsigned)y;
}

enum { RELEASED = -1000000 }; /* a cell given back (rip-up): free, but keeps its probe chain */

/* The slot of cell (x, y): its own, or the empty one where it would go. */
static int cell_slot(const grid *g, unsigned long long k) {
  unsigned mask = (unsigned)g->cap - 1, i = (unsigned)((k * 0x9E3779B97F4A7C15ull) >> 32) & mask;
  while (g->val[i] != -1 && (unsigned long long)g->key[i] != k) i = (i + 1) & mask;
  return (int)i;
}

static int cell_free(const grid *g, int x, int y) {
  int v = g->val[cell_slot(g, cell_key(x, y))];
  return v == -1 || v == RELEASED;
}

static void cell_grow(grid *g) {
  long long *key = g->key;
  int *val = g->val, cap = g->cap;
  g->cap = cap ? 2 * cap : 1024;
  g->key = bg_xcalloc((size_t)g->cap, sizeof(long long));
  g->val = bg_xmalloc((size_t)g->cap * sizeof(int));
  for (int i = 0; i < g->cap; i++) g->val[i] = -1;
  for (int i = 0; i < cap; i++)
    if (val[i] != -1) {
      int j = cell_slot(g, (unsigned long long)key[i]);
      g->key[j] = key[i], g->val[j] = val[i];
    }
  free(key), free(val);
}

static void cell_take(grid *g, int x, int y, int owner) {
  if (2 * (g->used + 1) > g->cap) cell_grow(g);
  unsigned long long k = cell_key(x, y);
  int i = cell_slot(g, k);
  g->used += g->val[i] == -1;
  g->key[i] = (long long)k, g->val[i] = owner;
}

/* ---------------------------------------------------------------- graph */
/* The node that draws v: a collapsed instance's element its box, a field's
 * other port the field's node (its first port's), else v itself. */
static int drawn_by(const bg_diagram_layout *d, int v) { return d->node_of[d->rep ? d->rep[v] : v]; }

static int own_node(const bg_diagram_layout *d, int v) { return drawn_by(d, v) == v; }

static void build_edges(grid *g) {
  const bg_model *m = g->d->m;
  const bg_analysis *a = g->d->a;
  int nlag = a ? a->nlag : 0;
  g->et = bg_xcalloc((size_t)(m->nbond + nlag + 1), sizeof(int));
  g->eh = bg_xcalloc((size_t)(m->nbond + nlag + 1), sizeof(int));
  for (int b = 0; b < m->nbond; b++)
    g->et[g->ne] = drawn_by(g->d, m->bond_tail[b]), g->eh[g->ne++] = drawn_by(g->d, m->bond_head[b]);
  for (int i = 0; i < nlag; i++)
    if (g->d->lag_node[i] >= 0) g->et[g->ne] = g->d->lag_node[i], g->eh[g->ne++] = a->lag_junction[i];
  g->adr = bg_xcalloc((size_t)g->n + 2, sizeof(int));
  g->adj = bg_xcalloc(2 * (size_t)g->ne + 1, sizeof(int));
  g->deg = bg_xcalloc((size_t)g->n + 1, sizeof(int));
  for (int e = 0; e < g->ne; e++)
    if (g->et[e] != g->eh[e]) g->deg[g->et[e]]++, g->deg[g->eh[e]]++; /* not inside a box */
  for (int v = 0; v < g->n; v++) g->adr[v + 1] = g->adr[v] + g->deg[v];
  int *fill = bg_xcalloc((size_t)g->n + 1, sizeof(int));
  for (int e = 0; e < g->ne; e++) {
    if (g->et[e] == g->eh[e]) continue;
    g->adj[g->adr[g->et[e]] + fill[g->et[e]]++] = e;
    g->adj[g->adr[g->eh[e]] + fill[g->eh[e]]++] = e;
  }
  free(fill);
}

static int other(const grid *g, int e, int v) { return g->et[e] == v ? g->eh[e] : g->et[e]; }

/* Hubs: two or more edges; of two nodes joined only to each other, the first. */
static void classify(grid *g) {
  for (int v = 0; v < g->n; v++) {
    if (g->deg[v] >= 2) g->hub[v] = 1;
    else if (g->deg[v] == 1) {
      int u = other(g, g->adj[g->adr[v]], v);
      g->hub[v] = g->deg[u] == 1 && v < u;
    }
  }
}

/* ---------------------------------------------------------------- columns and rows */
static int by_x(const void *a, const void *b, void *ctx) {
  const grid *sort_g = ctx;
  int i = *(const int *)a, j = *(const int *)b;
  double dx = sort_g->d->nx[i] - sort_g->d->nx[j], dy = sort_g->d->ny[i] - sort_g->d->ny[j];
  return dx < -0.5 ? -1 : dx > 0.5 ? 1 : dy < 0 ? -1 : dy > 0 ? 1 : i - j;
}

/* Hubs in dot's rank order (x), each rank top to bottom; col = rank index. */
static int *order_hubs(grid *g, int *nh) {
  int *h = bg_xcalloc((size_t)g->n + 1, sizeof(int)), k = 0;
  for (int v = 0; v < g->n; v++)
    if (g->hub[v]) h[k++] = v;
  bg_sort(h, (size_t)k, sizeof(int), by_x, g);
  for (int i = 0, c = -1; i < k; i++) {
    if (i == 0 || g->d->nx[h[i]] - g->d->nx[h[i - 1]] > 0.5) c++;
    g->col[h[i]] = c;
  }
  *nh = k;
  return h;
}

/* The hub before v (smaller column) that v continues: the one of the
 * nearest column, then nearest in dot's y. */
static int parent_of(const grid *g, int v) {
  int best = -1;
  for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
    int u = other(g, g->adj[k], v);
    if (!g->hub[u] || g->col[u] >= g->col[v]) continue;
    if (best < 0 || g->col[u] > g->col[best] ||
        (g->col[u] == g->col[best] &&
         fabs(g->d->ny[u] - g->d->ny[v]) < fabs(g->d->ny[best] - g->d->ny[v])))
      best = u;
  }
  return best;
}

/* Whether s comes before v among p's children in dot's order. */
static int before(const grid *g, int s, int v) {
  double ds = g->d->ny[s], dv = g->d->ny[v];
  return ds < dv || (ds == dv && s < v);
}

static int by_dot_y(const void *a, const void *b, void *ctx) {
  int s = *(const int *)a, v = *(const int *)b;
  return s == v ? 0 : before(ctx, s, v) ? -1 : 1;
}

/* The rows, as a tree drawing (issue 31): every hub hangs from its parent
 * (parent_of); of a hub's children the one with the longest chain onward
 * (the farthest column, then the most hubs, then the nearest in dot's y)
 * continues its row, so the longest source-to-load chain is the main row
 * and a side branch never bends it (a quarter car, a π filter had the
 * chain on an elbow where the branch was nearer in dot's y); the other
 * children's subtrees are stacked above (those before it in dot's order)
 * and below (those after), each as near as its subtree's rows allow,
 * column by column (its contour: per column the least and greatest row).
 * A hub takes over the contour of the child that continues it, which
 * spans the most columns, and merges the others' into it, so the work is
 * the sum of the shorter subtrees' spans: linear. Several roots (parts,
 * hubs with no hub in an earlier column) are stacked the same way. */
typedef struct contour {
  int *top, *bot, len, cap; /* index i: column last - i; rows relative to the root */
} contour;

enum { NO_ROW = 1 << 29, GAP = 2 };

static void contour_push(contour *c, int top, int bot) {
  if (c->len == c->cap) {
    c->cap = c->cap ? 2 * c->cap : 4;
    c->top = bg_xrealloc(c->top, (size_t)c->cap * sizeof(int));
    c->bot = bg_xrealloc(c->bot, (size_t)c->cap * sizeof(int));
  }
  c->top[c->len] = top, c->bot[c->len++] = bot;
}

/* The offset that puts subtree s (its last column slast) just above (dir
 * -1) or below (dir 1) what acc (last column alast) holds, at least `least`
 * beyond it in dir; then s merged into acc at that offset. */
static int contour_stack(contour *acc, int alast, const contour *s, int slast, int dir, int least) {
  int off = least;
  for (int i = 0; i < s->len; i++) {
    int k = alast - slast + i; /* s's column slast - i in acc */
    if (k < 0 || k >= acc->len || acc->top[k] == NO_ROW || s->top[i] == NO_ROW) continue;
    int need = dir < 0 ? acc->top[k] - GAP - s->bot[i] : acc->bot[k] + GAP - s->top[i];
    if (dir < 0 ? need < off : need > off) off = need;
  }
  for (int i = 0; i < s->len; i++) {
    int k = alast - slast + i;
    if (s->top[i] == NO_ROW || k < 0) continue;
    while (acc->len <= k) contour_push(acc, NO_ROW, -NO_ROW);
    if (acc->top[k] == NO_ROW) acc->top[k] = s->top[i] + off, acc->bot[k] = s->bot[i] + off;
    acc->top[k] = s->top[i] + off < acc->top[k] ? s->top[i] + off : acc->top[k];
    acc->bot[k] = s->bot[i] + off > acc->bot[k] ? s->bot[i] + off : acc->bot[k];
  }
  return off;
}

/* Stacks kids[0..n) round kids[cont] (offset 0, its contour taken over
 * into acc): those before it upwards, nearest first, those after it
 * downwards; each one's offset into off[]. */
static void stack_children(contour *cs, const int *last, const int *shift, int *off, const int *kids, int n, int cont,
                           contour *acc, int alast) {
  for (int dir = -1; dir <= 1; dir += 2) {
    int least = 0;
    for (int i = cont + dir; i >= 0 && i < n; i += dir) {
      int s = kids[i];
      off[s] = contour_stack(acc, alast, &cs[s], last[s] - shift[s], dir, least + dir);
      least = off[s];
      free(cs[s].top), free(cs[s].bot), memset(&cs[s], 0, sizeof cs[s]);
    }
  }
}

static int find(int *up, int v);

static void assign_rows(grid *g, const int *h, int nh) {
  int n = g->n, *par = bg_xcalloc((size_t)n + 1, sizeof(int)), *last = bg_xcalloc((size_t)n + 1, sizeof(int));
  int *reach = bg_xcalloc((size_t)n + 1, sizeof(int)), *cont = bg_xcalloc((size_t)n + 1, sizeof(int));
  int *off = bg_xcalloc((size_t)n + 1, sizeof(int)), *kids = bg_xcalloc((size_t)nh + 1, sizeof(int));
  int *shift = bg_xcalloc((size_t)n + 1, sizeof(int)); /* columns a branch moves left, then summed down */
  /* per hub its instance (-1: the model's own) and its subtree's: the same
   * for every hub in it, else -2 (children merged before their parents) */
  int *inst = bg_xmalloc(((size_t)n + 1) * sizeof(int)), *uni = bg_xmalloc(((size_t)n + 1) * sizeof(int));
  for (int v = 0; v < n; v++) inst[v] = uni[v] = v < g->d->m->nelem ? g->d->m->elem_inst[v] : -1;
  contour *cs = bg_xcalloc((size_t)n + 1, sizeof(contour));
  for (int i = 0; i < nh; i++) par[h[i]] = parent_of(g, h[i]), last[h[i]] = g->col[h[i]], reach[h[i]] = 1, cont[h[i]] = -1;
  for (int i = nh - 1; i >= 0; i--) { /* children lie in later columns: done before their parent */
    int v = h[i], p = par[v];
    if (p < 0) continue;
    int c = cont[p];
    if (c < 0 || last[v] > last[c] || (last[v] == last[c] && reach[v] > reach[c]) ||
        (last[v] == last[c] && reach[v] == reach[c] &&
         (fabs(g->d->ny[v] - g->d->ny[p]) < fabs(g->d->ny[c] - g->d->ny[p]) ||
          (fabs(g->d->ny[v] - g->d->ny[p]) == fabs(g->d->ny[c] - g->d->ny[p]) && v < c))))
      cont[p] = v;
    if (last[v] > last[p]) last[p] = last[v];
    if (reach[v] + 1 > reach[p]) reach[p] = reach[v] + 1;
    if (uni[v] != uni[p]) uni[p] = -2;
  }
  for (int i = nh - 1; i >= 0; i--) { /* each hub's contour from its children's */
    int v = h[i], nk = 0, at = 0;
    contour acc = {0};
    if (cont[v] >= 0) acc = cs[cont[v]], memset(&cs[cont[v]], 0, sizeof acc);
    while (acc.len < last[v] - g->col[v]) contour_push(&acc, NO_ROW, -NO_ROW);
    contour_push(&acc, 0, 0); /* v's own column */
    for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
      int s = other(g, g->adj[k], v);
      if (g->hub[s] && par[s] == v && (nk == 0 || kids[nk - 1] != s)) kids[nk++] = s;
    }
    bg_sort(kids, (size_t)nk, sizeof(int), by_dot_y, g);
    int m = 0;
    for (int k = 0; k < nk; k++) /* a child joined by two bonds counted once */
      if (m == 0 || kids[m - 1] != kids[k]) kids[m++] = kids[k];
    for (int k = 0; k < m; k++) at = kids[k] == cont[v] ? k : at;
    /* as many branches above as below (one each takes the hub's free
     * sides): dot's order kept, the continuing child moved among them */
    int q = m - 1, want = m == 0 ? 0 : at < q / 2 ? q / 2 : at > q - q / 2 ? q - q / 2 : at;
    for (; at < want; at++) kids[at] = kids[at + 1], kids[at + 1] = cont[v];
    for (; at > want; at--) kids[at] = kids[at - 1], kids[at - 1] = cont[v];
    /* in a part without a cycle a branch hangs in v's own column, its
     * bond straight up or down (a book's drawing; the grid pass's
     * straighten_branches did it after the fact, where the cells were
     * free), and the rows that bond crosses in v's column are taken, so
     * no sibling of v is stacked across it (a random tree's junction, its
     * four sides taken, reached its lowest branch by a slanted line
     * across another branch's bond) */
    int tree = !g->cyclic[find(g->up, v)], iv = last[v] - g->col[v];
    for (int k = 0; k < m; k++) {
      /* not where the branch's own column holds some of it on v's side
       * (a branch of the branch hung towards v): the bond would run
       * through it; such a branch hangs a column on, its bond an elbow */
      int s = kids[k], is = last[s] - g->col[s];
      if (!tree || s == cont[v]) { /* the continuing child's contour is acc's now */
        shift[s] = 0;
        continue;
      }
      int toward = k < at ? cs[s].bot[is] > 0 : cs[s].top[is] < 0;
      /* with submodels, only a branch wholly in v's instance, or from the
       * model's own hub (as straighten_branches moves sides: a tee's
       * branch pipe and the tee beyond it went into the first tee's
       * frame) */
      int framed = inst[v] >= 0 && uni[s] != inst[v];
      shift[s] = toward || framed ? 0 : g->col[s] - g->col[v];
    }
    if (cont[v] >= 0) off[cont[v]] = 0, stack_children(cs, last, shift, off, kids, m, at, &acc, last[v]);
    for (int k = 0; k < m && tree; k++) {
      if (kids[k] == cont[v]) continue;
      acc.top[iv] = off[kids[k]] < acc.top[iv] ? off[kids[k]] : acc.top[iv];
      acc.bot[iv] = off[kids[k]] > acc.bot[iv] ? off[kids[k]] : acc.bot[iv];
    }
    cs[v] = acc;
  }
  /* the roots, in dot's order, stacked below one another */
  contour all = {0};
  int alast = 0, least = 0, first = 1;
  for (int i = 0; i < nh; i++)
    if (par[h[i]] < 0) alast = last[h[i]] > alast ? last[h[i]] : alast;
  for (int i = 0; i < nh; i++) {
    int v = h[i];
    if (par[v] >= 0) continue;
    off[v] = contour_stack(&all, alast, &cs[v], last[v], 1, first ? 0 : least + 1);
    least = off[v], first = 0;
  }
  for (int i = 0; i < nh; i++) g->row[h[i]] = (par[h[i]] >= 0 ? g->row[par[h[i]]] : 0) + off[h[i]];
  for (int i = 0; i < nh; i++) /* parents first (earlier columns): each subtree moved with its branch */
    shift[h[i]] += par[h[i]] >= 0 ? shift[par[h[i]]] : 0;
  for (int i = 0; i < nh; i++) g->col[h[i]] -= shift[h[i]];
  for (int i = 0; i < nh; i++) { /* parents come first: earlier columns */
    int v = h[i], p = par[v];
    g->spine[v] = p < 0 || (g->spine[p] && cont[p] == v);
  }
  for (int v = 0; v < n; v++) free(cs[v].top), free(cs[v].bot);
  g->tree_par = par;
  free(shift), free(inst), free(uni);
  free(all.top), free(all.bot), free(cs), free(last), free(reach), free(cont), free(off), free(kids);
}

/* ---------------------------------------------------------------- meshes */
/* Issue 31, grids recognised: a part whose hubs form a rectangular mesh
 * (a 5 x 5 grid of RC cells: 0-junctions joined along rows and columns
 * through 1-junctions) was drawn as a tree from its source, a 45-degree
 * diamond of staircases. Such a part's hubs are put on the mesh's own
 * lattice instead. Its four corners are the hubs with two hub bonds whose
 * neighbours have two each (meshes of at least 3 x 3 junctions); from
 * the corner nearest the source, A, and the one that ends its longer
 * side, B, breadth-first distances give each hub its lattice point:
 * x = (dA - dB + |AB|) / 2, y = (dA + dB - |AB|) / 2. The part counts as
 * a mesh only when every hub gets a point of its own and every bond
 * between hubs joins neighbouring points, so whatever passes is drawn
 * with every hub bond straight; anything else keeps the tree drawing.
 * The mesh is looked for on the part's core: hubs hanging off it in
 * chains (a plate's load junction at a corner, a source's junction
 * before the first cell) are peeled off first and then drawn straight
 * out from their mesh hub's free outer side (mesh_pendants).
 * Linear in the part's size. */
static int hub_degree(const grid *g, int v) {
  int k = 0;
  for (int i = g->adr[v]; i < g->adr[v + 1]; i++) k += g->hub[other(g, g->adj[i], v)];
  return k;
}

/* Hub bonds of v to hubs of the core (pend: the hubs peeled off). */
static int core_degree(const grid *g, const unsigned char *pend, int v) {
  int k = 0;
  for (int i = g->adr[v]; i < g->adr[v + 1]; i++) {
    int u = other(g, g->adj[i], v);
    k += g->hub[u] && !pend[u];
  }
  return k;
}

/* Breadth-first distances over hub bonds from s into dist (-1: not
 * reached; reset by the caller); the hubs reached into q. Returns their count. */
static int hub_bfs(const grid *g, int s, int *dist, int *q) {
  int qh = 0, qt = 0;
  dist[s] = 0, q[qt++] = s;
  while (qh < qt) {
    int v = q[qh++];
    for (int i = g->adr[v]; i < g->adr[v + 1]; i++) {
      int u = other(g, g->adj[i], v);
      if (g->hub[u] && dist[u] < 0) dist[u] = dist[v] + 1, q[qt++] = u;
    }
  }
  return qt;
}

/* Whether core hub v may be a mesh's corner: two hub bonds, to hubs of two
 * hub bonds each (in the core). */
static int corner_like(const grid *g, const unsigned char *pend, int v) {
  if (core_degree(g, pend, v) != 2) return 0;
  for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
    int u = other(g, g->adj[k], v);
    if (g->hub[u] && !pend[u] && core_degree(g, pend, u) != 2) return 0;
  }
  return 1;
}

/* Peels the part's hubs q[0..n) down to its core: a hub with at most one
 * hub bond left is marked in pend, repeatedly (cdeg, queue: scratch).
 * Returns the hubs left. */
static int peel_pendants(const grid *g, const int *q, int n, unsigned char *pend, int *cdeg, int *queue) {
  int qt = 0, left = n;
  for (int i = 0; i < n; i++)
    if ((cdeg[q[i]] = hub_degree(g, q[i])) <= 1) queue[qt++] = q[i];
  for (int qh = 0; qh < qt; qh++) {
    int v = queue[qh];
    if (pend[v]) continue;
    pend[v] = 1, left--;
    for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
      int u = other(g, g->adj[k], v);
      if (g->hub[u] && !pend[u] && --cdeg[u] == 1) queue[qt++] = u;
    }
  }
  return left;
}

/* The peeled hubs' points (pc, pr, set for the core's hubs), each chain
 * drawn straight out of its mesh hub's free outer side (L, H: the lattice's
 * last column and row): right or left before down or up, one chain per
 * side. A peeled tree that branches, or a hub with more chains than free
 * outer sides, leaves the part to the tree drawing: returns 0 (the part's
 * col and row untouched). Chains out of different sides never meet: each keeps to its
 * own row or column outside the lattice. */
static int mesh_pendants(const grid *g, const int *q, int n, const unsigned char *pend, int L, int H, int *pc, int *pr) {
  static const int dir[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int i = 0; i < n; i++) {
    int a = q[i], used = 0;
    if (pend[a]) continue;
    for (int k = g->adr[a]; k < g->adr[a + 1]; k++) {
      int p = other(g, g->adj[k], a);
      if (!g->hub[p] || !pend[p]) continue;
      int c = pc[a], r = pr[a], side = -1;
      for (int s = 0; s < 4 && side < 0; s++) {
        int out = s == 0 ? c == L : s == 1 ? c == 0 : s == 2 ? r == H : r == 0;
        if (out && !(used >> s & 1)) side = s;
      }
      if (side < 0) return 0;
      used |= 1 << side;
      for (int prev = a, cur = p, step = 1; cur >= 0 && step <= n; step++) {
        pc[cur] = c + step * dir[side][0], pr[cur] = r + step * dir[side][1];
        int next = -1, nn = 0;
        for (int j = g->adr[cur]; j < g->adr[cur + 1]; j++) {
          int u = other(g, g->adj[j], cur);
          if (g->hub[u] && u != prev && u != cur) next = u, nn++;
        }
        if (nn > 1) return 0;
        prev = cur, cur = next;
      }
    }
  }
  return 1;
}

/* The part of hubs q[0..n) as a mesh: col and row of each, or nothing.
 * da, db, ds: per node, -1 for the part's hubs on entry (the caller
 * resets them); qq: a queue; pend: 0 for the part's hubs (reset by the
 * caller); cq: room for n hubs. */
static void mesh_part(grid *g, const int *q, int n, int *da, int *db, int *ds, int *qq, unsigned char *pend, int *cq) {
  int corner[4], nc = 0, src = -1;
  int ncore = peel_pendants(g, q, n, pend, ds, qq);
  for (int i = 0; i < n; i++) ds[q[i]] = -1;
  if (ncore < 13) return;
  for (int i = 0, k = 0; i < n; i++)
    if (!pend[q[i]]) cq[k++] = q[i];
  for (int i = 0; i < ncore; i++) {
    int v = cq[i];
    if (core_degree(g, pend, v) > 4) return;
    if (!corner_like(g, pend, v)) continue;
    /* a mesh two junctions deep (a counterflow exchanger's two streams
     * joined by walls) has its end rungs corner-like too, between two
     * corners: a corner has a neighbour that is not */
    int between = 1;
    for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
      int u = other(g, g->adj[k], v);
      if (g->hub[u] && !pend[u] && !corner_like(g, pend, u)) between = 0;
    }
    if (between) continue;
    if (nc == 4) return;
    corner[nc++] = v;
  }
  if (nc != 4) return;
  const bg_model *m = g->d->m;
  for (int i = 0; i < n; i++) ds[q[i]] = 0; /* the part, to find the hub its first source hangs on */
  for (int e = 0; e < m->nelem && src < 0; e++) {
    int v = drawn_by(g->d, e);
    if (!bg_elem_is_source(m->elem_kind[e]) || g->hub[v] || g->deg[v] != 1) continue;
    int u = other(g, g->adj[g->adr[v]], v);
    if (ds[u] == 0) src = u;
  }
  for (int i = 0; i < n; i++) ds[q[i]] = -1;
  hub_bfs(g, src >= 0 ? src : q[0], ds, qq);
  int a = corner[0];
  for (int k = 1; k < 4; k++)
    if (ds[corner[k]] < ds[a]) a = corner[k];
  hub_bfs(g, a, da, qq);
  int o[3], no = 0;
  for (int k = 0; k < 4; k++)
    if (corner[k] != a) o[no++] = corner[k];
  for (int i = 0; i < 3; i++) /* by distance from A: the two ends of its sides, then the far corner */
    for (int j = i + 1; j < 3; j++)
      if (da[o[j]] < da[o[i]]) {
        int t = o[i];
        o[i] = o[j], o[j] = t;
      }
  if (da[o[0]] + da[o[1]] != da[o[2]]) return;
  int b = da[o[1]] > da[o[0]] || (da[o[1]] == da[o[0]] && g->d->nx[o[1]] > g->d->nx[o[0]]) ? o[1] : o[0];
  int L = da[b], H = da[o[2]] - L;
  if ((long long)(L + 1) * (H + 1) > 4LL * ncore + 16) return;
  hub_bfs(g, b, db, qq);
  /* lattice point of v: x = (da - db + L) / 2, y = (da + db - L) / 2 */
  int *at = bg_xcalloc((size_t)(L + 1) * (size_t)(H + 1), sizeof(int)), ok = 1;
  for (int i = 0; i < ncore && ok; i++) {
    int v = cq[i], x2 = da[v] - db[v] + L, y2 = da[v] + db[v] - L;
    ok = db[v] >= 0 && x2 >= 0 && y2 >= 0 && x2 % 2 == 0 && y2 % 2 == 0 && x2 / 2 <= L && y2 / 2 <= H;
    if (ok) ok = !at[(y2 / 2) * (L + 1) + x2 / 2]++;
  }
  for (int i = 0; i < ncore && ok; i++)
    for (int k = g->adr[cq[i]]; k < g->adr[cq[i] + 1] && ok; k++) {
      int v = cq[i], u = other(g, g->adj[k], v);
      if (g->hub[u] && !pend[u])
        ok = abs((da[u] - db[u]) - (da[v] - db[v])) / 2 + abs((da[u] + db[u]) - (da[v] + db[v])) / 2 == 1;
    }
  free(at);
  if (!ok) return;
  /* every hub's point into pc, pr (ds and qq, not read again): the core's,
   * then the chains' out of it; the part's col and row only if all fit */
  int *pc = ds, *pr = qq, minc = 0;
  for (int i = 0; i < ncore; i++) {
    int v = cq[i];
    pc[v] = (da[v] - db[v] + L) / 2, pr[v] = (da[v] + db[v] - L) / 2;
  }
  if (ncore < n && !mesh_pendants(g, q, n, pend, L, H, pc, pr)) return;
  for (int i = 0; i < n; i++) minc = pc[q[i]] < minc ? pc[q[i]] : minc;
  for (int i = 0; i < n; i++) /* a chain out of the left side: columns from 0 */
    g->col[q[i]] = pc[q[i]] - minc, g->row[q[i]] = pr[q[i]], g->mesh[q[i]] = 1;
}

static void mesh_rows(grid *g, const int *h, int nh) {
  size_t n = (size_t)g->n + 1;
  int *seen = bg_xmalloc(n * sizeof(int)), *da = bg_xmalloc(n * sizeof(int)), *db = bg_xmalloc(n * sizeof(int));
  int *ds = bg_xmalloc(n * sizeof(int)), *q = bg_xmalloc(n * sizeof(int)), *qq = bg_xmalloc(n * sizeof(int));
  int *cq = bg_xmalloc(n * sizeof(int));
  unsigned char *pend = bg_xcalloc(n, 1);
  for (size_t v = 0; v < n; v++) seen[v] = da[v] = db[v] = ds[v] = -1;
  for (int i = 0; i < nh; i++) {
    if (seen[h[i]] >= 0) continue;
    int k = hub_bfs(g, h[i], seen, q);
    if (k >= 13) mesh_part(g, q, k, da, db, ds, qq, pend, cq); /* 2 x 3 junctions and their links at least */
    for (int j = 0; j < k; j++) da[q[j]] = db[q[j]] = ds[q[j]] = -1, pend[q[j]] = 0;
  }
  free(seen), free(da), free(db), free(ds), free(q), free(qq), free(cq), free(pend);
}

/* ---------------------------------------------------------------- components, wrapping */
static int find(int *up, int v) {
  while (up[v] != v) v = up[v] = up[up[v]];
  return v;
}

/* Per instance (issue 31): the columns its hubs (its own and its
 * instances') take, lo..hi, and their component (-1: none). */
static void instance_columns(const grid *g, const int *h, int nh, int *up, int *ilo, int *ihi, int *icomp) {
  const bg_model *m = g->d->m;
  for (int k = 0; k < m->ninst; k++) ilo[k] = 1 << 30, ihi[k] = -1, icomp[k] = -1;
  for (int i = 0; i < nh; i++) {
    int v = h[i];
    if (v >= m->nelem) continue;
    for (int k = m->elem_inst[v]; k >= 0; k = m->inst_parent[k]) {
      ilo[k] = g->col[v] < ilo[k] ? g->col[v] : ilo[k];
      ihi[k] = g->col[v] > ihi[k] ? g->col[v] : ihi[k];
      icomp[k] = find(up, v);
    }
  }
}

/* Where the bands of component c (ncol columns, at most wrap a band) start:
 * as even as the columns allow (a 25-section ladder folded 16 + 16 + 16 + 2,
 * leaving one section alone on its last row; issue 31); with instance
 * frames, each fold at the column boundary near the even place (at least
 * half a band on) that cuts the fewest instances, so a frame stays whole in
 * one band where its columns fit one (a fold through an instance put its
 * nodes on two bands, its frame round both, across its siblings); in a
 * tree, away from boundaries where the fold's bond down from the band's
 * last spine hub would meet a branch (blocked, NULL: none). Returns the
 * number of bands; start[0] = 0. */
static int band_starts(const grid *g, int c, int ncol, int wrap, const int *ilo, const int *ihi, const int *icomp,
                       const unsigned char *blocked, int *start) {
  int nb = 0, *cut = NULL;
  if (g->d->m->ninst) { /* cut[b]: instances with columns on both sides of boundary b (before column b) */
    cut = bg_xcalloc((size_t)ncol + 2, sizeof *cut);
    for (int k = 0; k < g->d->m->ninst; k++)
      if (icomp[k] == c && ilo[k] < ihi[k]) cut[ilo[k] + 1]++, cut[ihi[k] + 1]--;
    for (int b = 1; b <= ncol; b++) cut[b] += cut[b - 1];
  }
  start[nb++] = 0;
  for (int s = 0; ncol - s > wrap;) {
    int left = (ncol - s + wrap - 1) / wrap, ideal = (ncol - s + left - 1) / left, best = s + ideal;
    if (cut || blocked) {
      long best_cost = -1;
      for (int b = s + (ideal + 1) / 2; b <= s + wrap && b < ncol; b++) {
        long cost = (long)(cut ? cut[b] : 0) * 4 * ncol + (long)(blocked ? blocked[b] : 0) * 2 * ncol;
        cost += abs(b - (s + ideal));
        if (best_cost < 0 || cost < best_cost) best_cost = cost, best = b;
      }
    }
    start[nb++] = s = best;
  }
  free(cut);
  return nb;
}

/* Issue 31, disconnected parts packed side by side: the parts (part[],
 * their width in columns and height in rows, the free ones after them
 * included) go into shelves, the tallest first (of equal height, model
 * order), left to right with a free column between them, a new shelf
 * below the tallest part of the one before when the next does not fit;
 * a shelf is the square root of the parts' summed area columns wide (a
 * column is wider than a row, so the page comes out landscape), the
 * widest part at least. Sets each part's row
 * offset (base, as -1 - row) and column offset (xoff). */
static int by_index(const void *a, const void *b, void *ctx) {
  (void)ctx;
  return *(const int *)a - *(const int *)b;
}

/* Packs the parts (component part[i], width[c] + 1 columns with the gap,
 * height[c] rows) on a page sqrt(area) columns wide (at least the widest)
 * by bg_layout_pack (layout_pack.c: on a skyline, each part where it sits
 * highest, the tallest first or the widest first, whichever fills the
 * smaller box; in shelves, a shelf was as tall as its tallest part and the
 * room under the others stayed empty). Sets xoff and base (as -1 - row)
 * per component; part[] comes back sorted. */
static void pack_parts(int *part, int nparts, const int *width, const int *height, int *base, int *xoff) {
  double area = 0;
  int widest = 0;
  for (int i = 0; i < nparts; i++) {
    area += (double)(width[part[i]] + 1) * height[part[i]];
    widest = width[part[i]] + 1 > widest ? width[part[i]] + 1 : widest;
  }
  int page_w = (int)ceil(sqrt(area));
  if (page_w < widest) page_w = widest;
  bg_sort(part, (size_t)nparts, sizeof *part, by_index, NULL); /* equal parts in component order */
  double *w = bg_xcalloc((size_t)nparts + 1, sizeof *w), *h = bg_xcalloc((size_t)nparts + 1, sizeof *h);
  double *x = bg_xcalloc((size_t)nparts + 1, sizeof *x), *y = bg_xcalloc((size_t)nparts + 1, sizeof *y);
  for (int i = 0; i < nparts; i++) w[i] = width[part[i]] + 1, h[i] = height[part[i]];
  bg_layout_pack(nparts, w, h, page_w, 0, 0, x, y);
  for (int i = 0; i < nparts; i++) xoff[part[i]] = (int)x[i], base[part[i]] = -1 - (int)y[i];
  free(w), free(h), free(x), free(y);
}

/* Each component's hubs snake into bands of at most `wrap` columns when it is
 * wider than that (a long chain becomes rows), and the components are stacked
 * on the page by pack_parts. A band runs back from
 * under the end of the band before it. */
/* A large forest's column pitch over its row pitch, as to_points will
 * make them from the reference boxes: a column as wide as its widest hub
 * and the widest one-port beside one (the odd column after it), a row as
 * high as its hub and one-port; each with its gaps. */
static double column_pitch_of(const grid *g, const int *h, int nh, double *width) {
  int ncol = 0;
  for (int i = 0; i < nh; i++) ncol = g->col[h[i]] + 1 > ncol ? g->col[h[i]] + 1 : ncol;
  double *hub = bg_xcalloc((size_t)ncol + 1, sizeof(double)), *leaf = bg_xcalloc((size_t)ncol + 1, sizeof(double));
  double hh = 0, lh = 0, xgap, ygap, sum = 0;
  for (int i = 0; i < nh; i++) {
    int v = h[i], c = g->col[v];
    hub[c] = fmax(hub[c], g->rw[v]), hh = fmax(hh, g->rh[v]);
    for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
      int w = other(g, g->adj[k], v);
      if (!g->hub[w]) leaf[c] = fmax(leaf[c], g->rw[w]), lh = fmax(lh, g->rh[w]);
    }
  }
  style_gaps(g->ref, 0, &xgap, &ygap);
  for (int c = 0; c < ncol; c++) sum += hub[c] + leaf[c] + 2 * xgap;
  free(hub), free(leaf);
  if (width) *width = ncol ? sum / ncol : 0;
  return ncol ? sum / ncol / (hh + lh + 2 * ygap) : 0;
}

static double column_pitch(const grid *g, const int *h, int nh) { return column_pitch_of(g, h, nh, NULL); }

/* The parts, once for every pass that asks (the tree drawing, the folds,
 * movable): g->up, a union-find over the edges, and per part's root
 * whether it has a cycle (no fewer bonds than nodes), g->cyclic. */
static void find_parts(grid *g) {
  int n = g->n, *up = bg_xmalloc(((size_t)n + 1) * sizeof(int)), *nodes_in = bg_xcalloc((size_t)n + 1, sizeof(int));
  for (int v = 0; v < n; v++) up[v] = v;
  for (int e = 0; e < g->ne; e++) up[find(up, g->et[e])] = find(up, g->eh[e]);
  g->cyclic = bg_xcalloc((size_t)n + 1, 1);
  for (int v = 0; v < n; v++) nodes_in[find(up, v)]++;
  for (int e = 0; e < g->ne; e++) nodes_in[find(up, g->et[e])]--;
  for (int v = 0; v < n; v++) g->cyclic[v] = find(up, v) == v && nodes_in[v] <= 0;
  free(nodes_in);
  g->up = up;
}

/* The band every hub is drawn in (g->band): its column's, and in a part
 * without a cycle a branch's the band of the spine hub it hangs from, so a
 * fold never cuts a branch from its hub (issue 31: a chain's branch three
 * junctions long, hung from the band's last columns, had its far end in
 * the next band's rows, its bond round the figure across two others). A
 * ring's other way is a branch of the tree drawing; it folds with its
 * columns, as the ribbon needs (cyclic parts keep the column's band). */
static void hub_bands(grid *g, const int *h, int nh, int *up, const int *nband, const int *boff, const int *start,
                      const unsigned char *cyclic) {
  for (int i = 0; i < nh; i++) { /* parents before children: earlier columns */
    int v = h[i], c = find(up, v), a = 0, z = nband[c] - 1, p = g->tree_par[v];
    if (!g->spine[v] && p >= 0 && !cyclic[c]) {
      g->band[v] = g->band[p];
      continue;
    }
    const int *st = start + boff[c];
    while (a < z) { /* the band holding v's column */
      int mid = (a + z + 1) / 2;
      if (st[mid] <= g->col[v]) a = mid;
      else z = mid - 1;
    }
    g->band[v] = a;
  }
}

/* The hubs of each part (component root c): chub[first[c] .. first[c + 1]),
 * in h's order. */
static void hubs_by_part(const grid *g, const int *h, int nh, int *up, int **first, int **chub) {
  int *f = bg_xcalloc((size_t)g->n + 2, sizeof(int)), *at = bg_xcalloc((size_t)g->n + 2, sizeof(int));
  int *ch = bg_xcalloc((size_t)nh + 1, sizeof(int));
  for (int i = 0; i < nh; i++) f[find(up, h[i]) + 1]++;
  for (int c = 0; c < g->n; c++) f[c + 1] += f[c];
  for (int i = 0; i < nh; i++) {
    int c = find(up, h[i]);
    ch[f[c] + at[c]++] = h[i];
  }
  free(at);
  *first = f, *chub = ch;
}

/* Per boundary b of a tree's columns (before column b), whether a fold
 * there meets a branch: the fold's bond runs down from the band's last
 * spine hub (column b - 1) to the next band's first (column b, under it),
 * through what hangs below the spine in column b - 1 and what the next
 * band's first hub holds above the spine in its own column (issue 31: a
 * chain's last branch before its fold, hung straight below its hub, sent
 * the fold round it on two corners). hubs[0..nh): the part's; anchor: per
 * hub the spine hub it hangs from (spine_anchors). */
static unsigned char *fold_blocked(const grid *g, const int *hubs, int nh, const int *anchor, int ncol) {
  unsigned char *blocked = bg_xcalloc((size_t)ncol + 2, 1);
  for (int i = 0; i < nh; i++) {
    int v = hubs[i], a = anchor[v], k = g->col[v];
    if (a == v || k < 0 || k >= ncol) continue;
    if (g->row[v] > g->row[a]) blocked[k + 1] = 1;                     /* below the spine: a fold after column k */
    else if (g->row[v] < g->row[a] && g->col[a] == k) blocked[k] = 1; /* above, in its hub's column: before k */
  }
  return blocked;
}

/* Whether a fold before any of columns start[1..nb) would cut a branch
 * (issue 31, a wide branched chain folded): a hub off the spine whose
 * columns from its spine hub's reach over the fold, or a fold
 * fold_blocked refuses. hubs[0..nh): the part's. */
static int folds_cut_branches(const grid *g, const int *hubs, int nh, const int *anchor, const unsigned char *blocked,
                              const int *start, int nb) {
  for (int j = 1; j < nb; j++) {
    int b = start[j];
    if (blocked[b]) return 1;
    for (int i = 0; i < nh; i++) {
      int v = hubs[i], a = anchor[v];
      if (a == v) continue;
      int lo = g->col[v] < g->col[a] ? g->col[v] : g->col[a], hi = g->col[v] > g->col[a] ? g->col[v] : g->col[a];
      if (lo < b && b <= hi) return 1;
    }
  }
  return 0;
}

/* Per hub the spine hub it hangs from (itself on a spine). */
static int *spine_anchors(const grid *g, const int *h, int nh) {
  int *anchor = bg_xmalloc(((size_t)g->n + 1) * sizeof(int));
  for (int i = 0; i < nh; i++) { /* parents before children: earlier columns */
    int v = h[i], p = g->tree_par[v];
    anchor[v] = g->spine[v] || p < 0 ? v : anchor[p];
  }
  return anchor;
}

/* Whether component c holds an instance's elements (its frames would be
 * cut by a fold it does not choose). */
static int part_has_instances(int ni, const int *icomp, int c) {
  for (int k = 0; k < ni; k++)
    if (icomp[k] == c) return 1;
  return 0;
}

/* The widest row a chain is drawn in before it folds, points: 1.14 times
 * A4 landscape's width (11 pt text shrunk to fit that page stays above
 * 9.5 pt). */
#define ROW_MAX 960.0

static void stack_components(grid *g, const int *h, int nh) {
  int n = g->n, *up = g->up;
  const unsigned char *cyclic = g->cyclic;
  int *lo = bg_xcalloc((size_t)n + 1, sizeof(int)), *hi = bg_xcalloc((size_t)n + 1, sizeof(int));
  int *ncol = bg_xcalloc((size_t)n + 1, sizeof(int)), *base = bg_xcalloc((size_t)n + 1, sizeof(int));
  int *boff = bg_xcalloc((size_t)n + 1, sizeof(int)), *nband = bg_xcalloc((size_t)n + 1, sizeof(int));
  int *maxdeg = bg_xcalloc((size_t)n + 1, sizeof(int)); /* per component: its hubs' most links */
  unsigned char *branched = bg_xcalloc((size_t)n + 1, 1); /* per component: a hub with three hubs beside it */
  double colw = -1; /* the hubs' mean column width, points (column_pitch_of), when asked */
  /* bands: at most one per 1 + ncol / 8 columns of a component, ncol <= its nodes */
  int *start = bg_xcalloc(2 * (size_t)n + 2, sizeof(int)), *bx = bg_xcalloc(2 * (size_t)n + 2, sizeof(int));
  int ni = g->d->m->ninst, *ilo = bg_xcalloc((size_t)ni + 1, sizeof(int)), *ihi = bg_xcalloc((size_t)ni + 1, sizeof(int));
  int *icomp = bg_xcalloc((size_t)ni + 1, sizeof(int));
  for (int v = 0; v < n; v++) lo[v] = 1 << 30, hi[v] = -(1 << 30);
  for (int i = 0; i < nh; i++) {
    int v = h[i], c = find(up, v);
    lo[c] = g->row[v] < lo[c] ? g->row[v] : lo[c];
    hi[c] = g->row[v] > hi[c] ? g->row[v] : hi[c];
    ncol[c] = g->col[v] + 1 > ncol[c] ? g->col[v] + 1 : ncol[c];
    int links = g->adr[v + 1] - g->adr[v], hubs = 0;
    for (int k = g->adr[v]; k < g->adr[v + 1]; k++) hubs += g->hub[other(g, g->adj[k], v)];
    maxdeg[c] = links > maxdeg[c] ? links : maxdeg[c];
    branched[c] |= hubs > 2; /* a hub off the chain: a branch */
    if (g->mesh[v]) nband[c] = -1; /* a mesh: one band, a grid is not folded */
  }
  if (ni) instance_columns(g, h, nh, up, ilo, ihi, icomp);
  /* between bands a free row, and with frames one more per level of
   * nesting, for the frames' padding and labels (18 pt a level; a free
   * row is a row gap, 21 pt and more) */
  int depth = 0;
  for (int k = 0; k < ni; k++) {
    int dk = 0;
    for (int q = k; q >= 0; q = g->d->m->inst_parent[q]) dk++;
    depth = dk > depth ? dk : depth;
  }
  int sep = 1 + depth;
  int nstart = 0, nparts = 0;
  int *xoff = bg_xcalloc((size_t)n + 1, sizeof(int)), *width = bg_xcalloc((size_t)n + 1, sizeof(int));
  int *height = bg_xcalloc((size_t)n + 1, sizeof(int)), *part = bg_xcalloc((size_t)n + 1, sizeof(int));
  /* a large forest: bands as wide as a drawing of all its parts about 1.4
   * times as wide as high, in points (its columns hold long labels: 5.5 to
   * 1 before; each part folded to that shape on its own packed badly) */
  double pitch = g->own_ranks ? column_pitch(g, h, nh) : 0, cells = 0;
  int ncomp = 0; /* parts with hubs: several are packed side by side (pack_parts), not capped */
  for (int v = 0; v < n; v++) ncomp += find(up, v) == v && lo[v] <= hi[v];
  for (int v = 0; pitch > 0 && v < n; v++)
    if (find(up, v) == v && lo[v] <= hi[v]) cells += (double)ncol[v] * (hi[v] - lo[v] + 1 + sep);
  int *first = NULL, *chub = NULL, *anchor = NULL; /* per component its hubs, chub[first[c] .. first[c + 1]) */
  for (int v = 0; v < n; v++) {
    int c = find(up, v);
    if (lo[c] > hi[c] || base[c] < 0) continue;
    int span = hi[c] - lo[c] + 1, wrap = (int)ceil(sqrt((double)ncol[c] * (2 * span + 2)));
    if (pitch > 0) wrap = (int)ceil(sqrt(1.4 * cells / pitch));
    if (nband[c] < 0) wrap = ncol[c] + 16;
    else if (wrap < 16) wrap = 16;
    /* a chain of under 16 columns wider than a landscape page: folded too,
     * into even bands of at most ROW_MAX (a 6-section transmission line
     * was one row 1 332 pt wide, 8.7 : 1; issue 31). Only a lone part (parts
     * are packed side by side) of junctions of four bonds or fewer (a ring
     * of one-ports makes its column far wider than the mean); with
     * branches, one without instances (a fold their frames do not choose
     * crossed them: tee_network) and only where no fold cuts a branch
     * (folds_cut_branches) */
    int check_branches = 0, wrap0 = wrap; /* capped with branches: its folds checked */
    if (nband[c] >= 0 && !cyclic[c] && ncol[c] <= wrap && maxdeg[c] <= 4 && ncomp == 1 &&
        (!branched[c] || !part_has_instances(ni, icomp, c))) {
      if (colw < 0) column_pitch_of(g, h, nh, &colw);
      if (ncol[c] * colw > ROW_MAX) {
        int nb = (int)ceil(ncol[c] * colw / ROW_MAX);
        wrap = (ncol[c] + nb - 1) / nb, check_branches = branched[c];
      }
    }
    boff[c] = nstart;
    unsigned char *blocked = NULL;
    if (ncol[c] > wrap && !cyclic[c]) {
      if (!first) hubs_by_part(g, h, nh, up, &first, &chub), anchor = spine_anchors(g, h, nh);
      blocked = fold_blocked(g, chub + first[c], first[c + 1] - first[c], anchor, ncol[c]);
    }
    nband[c] = band_starts(g, c, ncol[c], wrap, ilo, ihi, icomp, blocked, start + nstart);
    /* a branched chain folds only where no branch is cut (a fold's bond
     * round a branch bent the power chain: branchy12) */
    if (check_branches &&
        folds_cut_branches(g, chub + first[c], first[c + 1] - first[c], anchor, blocked, start + nstart, nband[c])) {
      free(blocked), blocked = NULL;
      nband[c] = band_starts(g, c, ncol[c], wrap = wrap0, ilo, ihi, icomp, NULL, start + nstart);
    }
    free(blocked);
    height[c] = nband[c] * (span + sep);
    nstart += nband[c];
    base[c] = -1, part[nparts++] = c; /* marks the component done */
  }
  free(first), free(chub), free(anchor);
  hub_bands(g, h, nh, up, nband, boff, start, cyclic);
  /* each band's first column under the last one of the band before, the
   * bands running right and left in turn; then all moved right of 0. A
   * branch kept in its spine's band (hub_bands) reaches past the band's
   * last column, away from the band before. */
  int *reach = bg_xcalloc((size_t)nstart + 1, sizeof(int));
  for (int i = 0; i < nh; i++) {
    int v = h[i], c = find(up, v), a = g->band[v], k = g->col[v] - start[boff[c] + a] + 1;
    reach[boff[c] + a] = k > reach[boff[c] + a] ? k : reach[boff[c] + a];
  }
  for (int p = 0; p < nparts; p++) {
    int c = part[p], x = 0, minx = 0;
    for (int b = 0; b < nband[c]; b++) {
      int w = (b + 1 < nband[c] ? start[boff[c] + b + 1] : ncol[c]) - start[boff[c] + b];
      int r = reach[boff[c] + b] > w ? reach[boff[c] + b] : w;
      bx[boff[c] + b] = x;
      minx = (b % 2 ? x - (r - 1) : x) < minx ? (b % 2 ? x - (r - 1) : x) : minx;
      x += (b % 2 ? -1 : 1) * (w - 1);
    }
    for (int b = 0; b < nband[c]; b++) {
      bx[boff[c] + b] -= minx;
      int w = (b + 1 < nband[c] ? start[boff[c] + b + 1] : ncol[c]) - start[boff[c] + b];
      int r = reach[boff[c] + b] > w ? reach[boff[c] + b] : w, right = bx[boff[c] + b] + (b % 2 ? w : r);
      width[c] = right > width[c] ? right : width[c];
    }
  }
  free(reach);
  pack_parts(part, nparts, width, height, base, xoff);
  free(width), free(height), free(part);
  /* A part with a cycle folds as a ribbon does, each band after the first
   * turned upside down as well as running back: a ring's two ways run out
   * in the first band's two rows and back in the next, so the first way's
   * fold goes round the second's instead of across it (battery packs in
   * rings: 7 bond crossings in 40, now 0). A tree keeps its bands the same
   * way up: a branch hanging below its spine at a fold would come between
   * the spine's two rows and bend the spine round it. */
  for (int v = 0; v < n; v++)
    if (cyclic[find(up, v)] && nband[find(up, v)] > 1) {
      if (!g->turned) g->turned = bg_xcalloc((size_t)n + 1, 1);
      g->turned[v] = 1;
    }
  for (int i = 0; i < nh; i++) {
    int v = h[i], c = find(up, v), a = g->band[v];
    int k = g->col[v] - start[boff[c] + a], span = hi[c] - lo[c] + 1;
    g->gx[v] = 2 * (xoff[c] + bx[boff[c] + a] + (a % 2 ? -k : k));
    int turned = a % 2 && cyclic[c]; /* a U-turn: the band upside down too */
    g->gy[v] = 2 * ((-1 - base[c]) + a * (span + sep) + (turned ? hi[c] - g->row[v] : g->row[v] - lo[c]));
    g->placed[v] = 1;
    cell_take(g, g->gx[v], g->gy[v], v);
  }
  free(lo), free(hi), free(ncol), free(base), free(boff), free(nband), free(maxdeg), free(branched), free(start), free(bx);
  free(ilo), free(ihi), free(icomp), free(xoff);
}

/* ---------------------------------------------------------------- routing bonds between hubs */
static int sgn(int v) { return (v > 0) - (v < 0); }

static int side_of(int dx, int dy) {
  return dx > 0 ? SIDE_R : dx < 0 ? SIDE_L : dy < 0 ? SIDE_U : SIDE_D;
}

/* Whether cell (x, y) is beside a hub other than u and v: where one of
 * that hub's one-ports would go. */
static int beside_hub(const grid *g, int x, int y, int u, int v) {
  for (int k = 0; k < 4; k++) {
    int w = g->val[cell_slot(g, cell_key(x + (k == 0) - (k == 1), y + (k == 2) - (k == 3)))];
    if (w >= 0 && w != u && w != v && g->hub[w]) return 1;
  }
  return 0;
}

/* Walks the route through pts[0..n) (axis-parallel legs): with take == 0
 * whether every cell but the two ends is free (and, while spare_sides is
 * set, beside no hub but e's ends), with take 1 claims the free ones for
 * edge e, with take -1 gives back those it holds. */
static int walk(grid *g, const int (*pts)[2], int n, int take, int e) {
  for (int k = 0; k + 1 < n; k++) {
    int x = pts[k][0], y = pts[k][1], sx = sgn(pts[k + 1][0] - x), sy = sgn(pts[k + 1][1] - y);
    if (sx && sy) return 0;
    while (x != pts[k + 1][0] || y != pts[k + 1][1]) {
      x += sx, y += sy;
      if (k == n - 2 && x == pts[n - 1][0] && y == pts[n - 1][1]) break;
      if (take > 0) {
        if (cell_free(g, x, y)) cell_take(g, x, y, -2 - e); /* a cell a maze route crosses stays the other bond's */
      }
      else if (take < 0) {
        int i = cell_slot(g, cell_key(x, y));
        if (g->val[i] == -2 - e) g->val[i] = RELEASED; /* not a cell a maze route crosses: the other bond's */
      }
      else if (!cell_free(g, x, y) || (g->spare_sides && beside_hub(g, x, y, g->et[e], g->eh[e]))) return 0;
    }
  }
  return 1;
}

/* Edge e takes the route through pts[0..n): its cells, the sides it
 * leaves and enters by, its corners. */
static void take_route(grid *g, int e, const int (*pts)[2], int n) {
  walk(g, pts, n, 1, e);
  g->sides[g->et[e]] |= (unsigned char)side_of(pts[1][0] - pts[0][0], pts[1][1] - pts[0][1]);
  g->sides[g->eh[e]] |= (unsigned char)side_of(pts[n - 2][0] - pts[n - 1][0], pts[n - 2][1] - pts[n - 1][1]);
  g->bent[e] = n - 2;
  for (int k = 1; k + 1 < n; k++) g->corner[e][2 * (k - 1)] = pts[k][0], g->corner[e][2 * k - 1] = pts[k][1];
}

static int try_route(grid *g, int e, const int (*pts)[2], int n) {
  int u = g->et[e], v = g->eh[e];
  int su = side_of(pts[1][0] - pts[0][0], pts[1][1] - pts[0][1]);
  int sv = side_of(pts[n - 2][0] - pts[n - 1][0], pts[n - 2][1] - pts[n - 1][1]);
  if ((g->sides[u] & su) || (g->sides[v] & sv) || !walk(g, pts, n, 0, e)) return 0;
  take_route(g, e, pts, n);
  return 1;
}

/* Straight when allowed (pass 0); an elbow or two (pass 1): one corner
 * either way, then two through a column or row between the ends or beside
 * them. */
static int route_bent(grid *g, int e);

static int route(grid *g, int e, int pass) {
  int x0 = g->gx[g->et[e]], y0 = g->gy[g->et[e]], x1 = g->gx[g->eh[e]], y1 = g->gy[g->eh[e]];
  if (pass == 0) {
    int p[2][2] = {{x0, y0}, {x1, y1}};
    return (x0 == x1 || y0 == y1) && try_route(g, e, (const int(*)[2])p, 2);
  }
  if (g->turned && g->turned[g->et[e]] && g->band[g->et[e]] != g->band[g->eh[e]]) {
    /* a ring's fold round the other way's (stack_components): round the
     * cells beside that way's hubs if it can, where their one-ports go
     * (else they went to diagonals: 6 in 40 battery packs). Only there: in
     * trees' folds it crossed more bonds than it spared. */
    g->spare_sides = 1;
    int ok = route_bent(g, e);
    g->spare_sides = 0;
    if (ok) return 1;
  }
  return route_bent(g, e);
}

static int route_bent(grid *g, int e) {
  int x0 = g->gx[g->et[e]], y0 = g->gy[g->et[e]], x1 = g->gx[g->eh[e]], y1 = g->gy[g->eh[e]];
  int l1[3][2] = {{x0, y0}, {x1, y0}, {x1, y1}}, l2[3][2] = {{x0, y0}, {x0, y1}, {x1, y1}};
  if (x0 != x1 && y0 != y1 && (try_route(g, e, (const int(*)[2])l1, 3) || try_route(g, e, (const int(*)[2])l2, 3)))
    return 1;
  for (int k = 1; k <= 4; k++)
    for (int s = -1; s <= 1; s += 2) {
      int xm = x0 == x1 ? x0 + s * k : (x0 + x1) / 2 + s * (k - 1);
      int ym = y0 == y1 ? y0 + s * k : (y0 + y1) / 2 + s * (k - 1);
      int z1[4][2] = {{x0, y0}, {xm, y0}, {xm, y1}, {x1, y1}}, z2[4][2] = {{x0, y0}, {x0, ym}, {x1, ym}, {x1, y1}};
      if ((y0 != y1 || x0 == x1) && xm != x0 && xm != x1 && try_route(g, e, (const int(*)[2])z1, 4)) return 1;
      if ((x0 != x1 || y0 == y1) && ym != y0 && ym != y1 && try_route(g, e, (const int(*)[2])z2, 4)) return 1;
    }
  return 0;
}

/* Edge e's route as points (its ends and corners); returns how many. */
static int route_points(const grid *g, int e, int (*pts)[2]) {
  int n = 0;
  pts[n][0] = g->gx[g->et[e]], pts[n++][1] = g->gy[g->et[e]];
  for (int k = 0; k < g->bent[e]; k++) pts[n][0] = g->corner[e][2 * k], pts[n++][1] = g->corner[e][2 * k + 1];
  pts[n][0] = g->gx[g->eh[e]], pts[n++][1] = g->gy[g->eh[e]];
  return n;
}

/* Takes edge e's route away: its cells and the sides at its ends. */
static void unroute(grid *g, int e) {
  int pts[MAX_PTS][2], n = route_points(g, e, pts);
  walk(g, (const int(*)[2])pts, n, -1, e);
  g->sides[g->et[e]] &= (unsigned char)~side_of(pts[1][0] - pts[0][0], pts[1][1] - pts[0][1]);
  g->sides[g->eh[e]] &= (unsigned char)~side_of(pts[n - 2][0] - pts[n - 1][0], pts[n - 2][1] - pts[n - 1][1]);
  g->bent[e] = -1;
}

static int is_hub_bond(const grid *g, int e) {
  return g->hub[g->et[e]] && g->hub[g->eh[e]] && g->et[e] != g->eh[e];
}

/* Edge e found no route: a bond at one of its ends, routed before it, may
 * block the only side it can reach (loop_class1: bond 3 straight down from
 * the upper 0-junction, where bond 2 from inside the loop must arrive).
 * Each such bond f is taken away, e routed, then f again (an elbow may do);
 * if either fails, f goes back where it was. */
static void rip_up(grid *g, int e) {
  for (int end = 0; end < 2 && g->bent[e] < 0; end++) {
    int v = end ? g->eh[e] : g->et[e];
    for (int k = g->adr[v]; k < g->adr[v + 1] && g->bent[e] < 0; k++) {
      int f = g->adj[k], pts[MAX_PTS][2], n;
      if (f == e || g->bent[f] < 0 || !is_hub_bond(g, f)) continue;
      n = route_points(g, f, pts);
      unroute(g, f);
      if ((route(g, e, 0) || route(g, e, 1)) && (route(g, f, 0) || route(g, f, 1))) return;
      if (g->bent[e] >= 0) unroute(g, e);
      try_route(g, f, (const int(*)[2])pts, n); /* back as it was: its cells are free again */
    }
  }
}

static void route_hub_bonds(grid *g) {
  for (int e = 0; e < g->ne; e++) g->bent[e] = -1;
  for (int pass = 0; pass < 2; pass++)
    for (int e = 0; e < g->ne; e++)
      if (g->bent[e] < 0 && is_hub_bond(g, e)) route(g, e, pass);
  for (int e = 0; e < g->ne; e++)
    if (g->bent[e] < 0 && is_hub_bond(g, e)) rip_up(g, e);
}

/* ---------------------------------------------------------------- maze routes */
/* A hub bond still without a route (no straight run, no route of one or
 * two corners, none after rip-up) was drawn as one slanted line across
 * whatever lay between: a bridge's fourth arm (a Wheatstone bridge, a
 * diode bridge, an H-bridge) ran diagonally through the middle and across
 * another arm. The grid's ranks put a bridge's two sides in the same
 * columns, so one arm has to pass the others; now it is routed over the
 * cells (layout_maze.c): round them where a detour of up to MAZE_CROSS
 * cells will do, else across one other bond at a right angle, as books
 * draw a crossing. It turns on free cells only, keeps off cells beside
 * other hubs where it can (their one-ports go there), and has at most
 * MAX_CORNER corners; a crossed cell stays its bond's. Taken only where
 * it crosses no more routed bonds than the straight line would. Run
 * after the branches are straightened, so everything before is as it
 * was; the cells searched in all are bounded by the graph's size. */
/* the window's margin round the ends (and a third of their span more), its
 * cells at most, the cells searched per node of the graph in all, costs */
enum { MAZE_MARGIN = 8, MAZE_CELLS = 40000, MAZE_PER_NODE = 400, MAZE_BEND = 3, MAZE_CROSS = 30, MAZE_BESIDE = 2 };

typedef struct maze_ctx {
  grid *g;
  int u, v;
} maze_ctx;

static int owner_at(const grid *g, int x, int y) { return g->val[cell_slot(g, cell_key(x, y))]; }

static int maze_cell(void *ctx, int x, int y, int *extra) {
  const maze_ctx *c = ctx;
  const grid *g = c->g;
  int w = owner_at(g, x, y);
  *extra = 0;
  if (w == -1 || w == RELEASED) {
    *extra = beside_hub(g, x, y, c->u, c->v) ? MAZE_BESIDE : 0;
    return BG_MAZE_FREE;
  }
  if (w >= 0) return BG_MAZE_BLOCKED; /* a node */
  if (owner_at(g, x - 1, y) == w && owner_at(g, x + 1, y) == w) return BG_MAZE_CROSS_V; /* a run along x */
  if (owner_at(g, x, y - 1) == w && owner_at(g, x, y + 1) == w) return BG_MAZE_CROSS_H;
  return BG_MAZE_BLOCKED; /* a corner, or next to the bond's end */
}

/* Whether segments pq and rs cross, other than where they share an end. */
static int legs_cross(const int *p, const int *q, const int *r, const int *s) {
  if ((p[0] == r[0] && p[1] == r[1]) || (p[0] == s[0] && p[1] == s[1]) || (q[0] == r[0] && q[1] == r[1]) ||
      (q[0] == s[0] && q[1] == s[1]))
    return 0;
  long long d1 = (long long)(q[0] - p[0]) * (r[1] - p[1]) - (long long)(q[1] - p[1]) * (r[0] - p[0]);
  long long d2 = (long long)(q[0] - p[0]) * (s[1] - p[1]) - (long long)(q[1] - p[1]) * (s[0] - p[0]);
  long long d3 = (long long)(s[0] - r[0]) * (p[1] - r[1]) - (long long)(s[1] - r[1]) * (p[0] - r[0]);
  long long d4 = (long long)(s[0] - r[0]) * (q[1] - r[1]) - (long long)(s[1] - r[1]) * (q[0] - r[0]);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/* The routed hub bonds the straight line of edge e would cross: a maze
 * route is taken only where it crosses no more. */
static int straight_crossings(const grid *g, int e) {
  int a[2] = {g->gx[g->et[e]], g->gy[g->et[e]]}, b[2] = {g->gx[g->eh[e]], g->gy[g->eh[e]]}, n = 0;
  for (int f = 0; f < g->ne; f++) {
    if (f == e || g->bent[f] < 0 || !is_hub_bond(g, f)) continue;
    int pts[MAX_PTS][2], np = route_points(g, f, pts);
    for (int k = 0; k + 1 < np; k++) n += legs_cross(a, b, pts[k], pts[k + 1]);
  }
  return n;
}

static void maze_hub_bonds(grid *g) {
  static const int side[4] = {SIDE_R, SIDE_D, SIDE_L, SIDE_U}; /* layout_maze's headings */
  long long budget = MAZE_PER_NODE * (long long)g->n + MAZE_CELLS; /* cells searched in all: linear in the graph */
  for (int e = 0; e < g->ne && budget > 0; e++) {
    if (g->bent[e] >= 0 || !is_hub_bond(g, e) || !g->placed[g->et[e]] || !g->placed[g->eh[e]]) continue;
    int u = g->et[e], v = g->eh[e], sdirs = 0, tdirs = 0;
    for (int d = 0; d < 4; d++) {
      sdirs |= !(g->sides[u] & side[d]) << d;
      tdirs |= !(g->sides[v] & side[(d + 2) % 4]) << d; /* heading d comes in by the opposite side */
    }
    int x0 = g->gx[u] < g->gx[v] ? g->gx[u] : g->gx[v], x1 = g->gx[u] < g->gx[v] ? g->gx[v] : g->gx[u];
    int y0 = g->gy[u] < g->gy[v] ? g->gy[u] : g->gy[v], y1 = g->gy[u] < g->gy[v] ? g->gy[v] : g->gy[u];
    maze_ctx c = {g, u, v};
    int span = x1 - x0 > y1 - y0 ? x1 - x0 : y1 - y0, margin = MAZE_MARGIN + span / 3; /* room to go round */
    bg_maze mz = {.x0 = x0 - margin, .y0 = y0 - margin, .w = x1 - x0 + 2 * margin + 1, .h = y1 - y0 + 2 * margin + 1,
                  .cell = maze_cell, .ctx = &c, .bend = MAZE_BEND, .cross = MAZE_CROSS};
    if (!sdirs || !tdirs || (long long)mz.w * mz.h > MAZE_CELLS) continue;
    budget -= (long long)mz.w * mz.h;
    int corner[MAX_CORNER][2], pts[MAX_PTS][2];
    int ncr = 0, nc = bg_maze_route(&mz, g->gx[u], g->gy[u], sdirs, g->gx[v], g->gy[v], tdirs, corner, MAX_CORNER,
                                    &ncr);
    if (nc < 0 || ncr > straight_crossings(g, e)) continue;
    pts[0][0] = g->gx[u], pts[0][1] = g->gy[u];
    for (int k = 0; k < nc; k++) pts[k + 1][0] = corner[k][0], pts[k + 1][1] = corner[k][1];
    pts[nc + 1][0] = g->gx[v], pts[nc + 1][1] = g->gy[v];
    take_route(g, e, (const int(*)[2])pts, nc + 2);
    g->mazed = 1;
  }
}

/* ---------------------------------------------------------------- straight branches */
/* A branch in another row than its hub hangs one column to the right of it
 * (the tree drawing's column is dot's rank), so its bond is an elbow: up or
 * down off the hub, then across (the quarter car's suspension junction above
 * the body's; a fifth of a random tree's bonds). Books draw a branch
 * straight off its hub. Where an elbow's bond is a bridge, the smaller of
 * the two sides it joins moves as one onto the corner, when every cell that
 * side and its routes take there is free: the bond is then straight and the
 * side keeps its shape. The sides are searched breadth-first in turn until
 * one is complete, so the work is the smaller side's: n log n on a tree. */

/* Whether f is a hub bond other than e with both ends placed (routed or
 * slanted). */
static int branch_edge(const grid *g, int f, int e) {
  return f != e && is_hub_bond(g, f) && g->placed[g->et[f]] && g->placed[g->eh[f]];
}

/* Which end of e holds the smaller part of the graph once e is cut: 1 the
 * tail, 2 the head, 0 when e is no bridge (a cycle runs through it) or
 * that part holds a mesh hub; its nodes in qa (tail) or qb (head), the
 * end first, *nq of them. mark[] is left clear. */
static int smaller_side(const grid *g, int e, unsigned char *mark, int *qa, int *qb, int *nq) {
  int ends[2] = {g->et[e], g->eh[e]}, head[2] = {0, 0}, tail[2] = {1, 1}, *q[2] = {qa, qb}, done = -1, bridge = 1;
  qa[0] = ends[0], qb[0] = ends[1], mark[ends[0]] = 1, mark[ends[1]] = 2;
  while (done < 0 && bridge)
    for (int s = 0; s < 2 && done < 0 && bridge; s++) {
      if (head[s] == tail[s]) {
        done = s;
        break;
      }
      int x = q[s][head[s]++];
      bridge = !g->mesh[x];
      for (int k = g->adr[x]; k < g->adr[x + 1] && bridge; k++) {
        int f = g->adj[k], y = other(g, f, x);
        if (!branch_edge(g, f, e) || mark[y] == s + 1) continue;
        if (mark[y]) bridge = 0; /* the other side: a cycle through e */
        else mark[y] = (unsigned char)(s + 1), q[s][tail[s]++] = y;
      }
    }
  for (int s = 0; s < 2; s++)
    for (int i = 0; i < tail[s]; i++) mark[q[s][i]] = 0;
  *nq = done >= 0 ? tail[done] : 0;
  return bridge && done >= 0 ? done + 1 : 0;
}

/* A move of the side q[0..nq) (its nodes marked in mark[]) by (dx, dy),
 * after which bond e runs straight from p to the side's end c. */
typedef struct side_move {
  const int *q;
  int nq, e, p, c, dx, dy;
  const unsigned char *mark;
} side_move;

/* Whether (x, y) lies on e's new straight run, its ends included. */
static int on_run(const grid *g, const side_move *mv, int x, int y) {
  int x0 = g->gx[mv->p], y0 = g->gy[mv->p], x1 = g->gx[mv->c] + mv->dx, y1 = g->gy[mv->c] + mv->dy;
  return x0 == x1 ? x == x0 && (y - y0) * (y - y1) <= 0 : y == y0 && (x - x0) * (x - x1) <= 0;
}

/* Whether a cell holding v (a node, -2 - an edge, or nothing) may take
 * the moved side: free, the side's own or e's (given back as it moves). */
static int side_may_take(const grid *g, const side_move *mv, int v) {
  if (v == -1 || v == RELEASED || v == -2 - mv->e) return 1;
  if (v >= 0) return mv->mark[v];
  return mv->mark[g->et[-2 - v]] && mv->mark[g->eh[-2 - v]];
}

/* Whether cell (x, y) may take the side's node `node` (-1: a route's
 * cell): side_may_take, and off e's new run but for c at its end. */
static int cell_for_side(const grid *g, const side_move *mv, int x, int y, int node) {
  return (node == mv->c || !on_run(g, mv, x, y)) && side_may_take(g, mv, g->val[cell_slot(g, cell_key(x, y))]);
}

/* Whether e's new run is open: every cell between its ends side_may_take. */
static int run_open(const grid *g, const side_move *mv) {
  int x0 = g->gx[mv->p], y0 = g->gy[mv->p], x1 = g->gx[mv->c] + mv->dx, y1 = g->gy[mv->c] + mv->dy;
  int sx = sgn(x1 - x0), sy = sgn(y1 - y0);
  for (int x = x0 + sx, y = y0 + sy; x != x1 || y != y1; x += sx, y += sy)
    if (!side_may_take(g, mv, g->val[cell_slot(g, cell_key(x, y))])) return 0;
  return 1;
}

/* The routes inside the moving side: each once (from its tail). */
static int inner_edge(const grid *g, const side_move *mv, int f, int x) {
  return branch_edge(g, f, mv->e) && g->et[f] == x && mv->mark[g->eh[f]] && g->bent[f] >= 0;
}

/* Whether every node and route cell of the side may go where the move
 * puts it (cell_for_side). */
static int side_fits(const grid *g, const side_move *mv) {
  for (int i = 0; i < mv->nq; i++) {
    int x = mv->q[i];
    if (!cell_for_side(g, mv, g->gx[x] + mv->dx, g->gy[x] + mv->dy, x)) return 0;
    for (int k = g->adr[x]; k < g->adr[x + 1]; k++) {
      int f = g->adj[k], pts[MAX_PTS][2], n;
      if (!inner_edge(g, mv, f, x)) continue;
      n = route_points(g, f, pts);
      for (int j = 0; j + 1 < n; j++) { /* every cell of the route, corners too, but the end nodes' */
        int sx = sgn(pts[j + 1][0] - pts[j][0]), sy = sgn(pts[j + 1][1] - pts[j][1]), cx = pts[j][0], cy = pts[j][1];
        do {
          cx += sx, cy += sy;
          if ((j + 2 < n || cx != pts[j + 1][0] || cy != pts[j + 1][1]) && !cell_for_side(g, mv, cx + mv->dx, cy + mv->dy, -1))
            return 0;
        } while (cx != pts[j + 1][0] || cy != pts[j + 1][1]);
      }
    }
  }
  return 1;
}

/* Moves the side: its routes and nodes given back, moved (corners too),
 * taken again. */
static void move_side(grid *g, const side_move *mv) {
  for (int pass = 0; pass < 2; pass++)
    for (int i = 0; i < mv->nq; i++)
      for (int k = g->adr[mv->q[i]]; k < g->adr[mv->q[i] + 1]; k++) {
        int f = g->adj[k], pts[MAX_PTS][2], n;
        if (!inner_edge(g, mv, f, mv->q[i])) continue;
        if (pass == 1)
          for (int c = 0; c < g->bent[f]; c++) g->corner[f][2 * c] += mv->dx, g->corner[f][2 * c + 1] += mv->dy;
        else {
          n = route_points(g, f, pts);
          walk(g, (const int(*)[2])pts, n, -1, f);
        }
      }
  for (int i = 0; i < mv->nq; i++) g->val[cell_slot(g, cell_key(g->gx[mv->q[i]], g->gy[mv->q[i]]))] = RELEASED;
  for (int i = 0; i < mv->nq; i++) {
    int x = mv->q[i];
    g->gx[x] += mv->dx, g->gy[x] += mv->dy;
    cell_take(g, g->gx[x], g->gy[x], x);
  }
  for (int i = 0; i < mv->nq; i++) /* the routes again, once every node is in place */
    for (int k = g->adr[mv->q[i]]; k < g->adr[mv->q[i] + 1]; k++) {
      int f = g->adj[k], pts[MAX_PTS][2], n;
      if (!inner_edge(g, mv, f, mv->q[i])) continue;
      n = route_points(g, f, pts);
      walk(g, (const int(*)[2])pts, n, 1, f);
    }
}

/* Whether moving the side puts c in line with p with e's sides free. */
static int move_fits(const grid *g, const side_move *mv) {
  int pts[MAX_PTS][2], n = route_points(g, mv->e, pts), at_c = pts[0][0] == g->gx[mv->c] && pts[0][1] == g->gy[mv->c];
  int px = g->gx[mv->p], py = g->gy[mv->p], cx = g->gx[mv->c] + mv->dx, cy = g->gy[mv->c] + mv->dy;
  int was_c = at_c ? side_of(pts[1][0] - pts[0][0], pts[1][1] - pts[0][1])
                   : side_of(pts[n - 2][0] - pts[n - 1][0], pts[n - 2][1] - pts[n - 1][1]);
  int was_p = at_c ? side_of(pts[n - 2][0] - pts[n - 1][0], pts[n - 2][1] - pts[n - 1][1])
                   : side_of(pts[1][0] - pts[0][0], pts[1][1] - pts[0][1]);
  if ((cx != px && cy != py) || (cx == px && cy == py)) return 0;
  if (g->sides[mv->c] & side_of(px - cx, py - cy) & ~was_c) return 0;
  if (g->sides[mv->p] & side_of(cx - px, cy - py) & ~was_p) return 0;
  return run_open(g, mv) && side_fits(g, mv);
}

/* Which nodes may move, per node: 1 where its part is a forest of hubs or
 * every hub bond of its part found a route on the grid (a reaction
 * network's chords did not: they are routed later round the moved nodes,
 * and came out worse); 2 at the ends of a hub bond without a route and at
 * their hub neighbours, which stay where they are with what hangs from
 * them (the later route of such a bond touched a ring's one-port bond, or
 * crossed its junction's other bonds, once a branch beside it moved). */
static unsigned char *movable(const grid *g) {
  size_t n = (size_t)g->n + 1;
  int *up = g->up, *cyc = bg_xcalloc(n, sizeof(int)); /* hub bonds - hubs (>= 0: a cycle) */
  unsigned char *ok = bg_xcalloc(n, 1), *rough = bg_xcalloc(n, 1);
  for (int v = 0; v < g->n; v++) cyc[find(up, v)] -= g->hub[v] && g->placed[v];
  for (int e = 0; e < g->ne; e++) cyc[find(up, g->et[e])] += is_hub_bond(g, e);
  for (int e = 0; e < g->ne; e++)
    if (g->bent[e] < 0 && is_hub_bond(g, e)) rough[find(up, g->et[e])] |= cyc[find(up, g->et[e])] >= 0;
  for (int v = 0; v < g->n; v++) ok[v] = !rough[find(up, v)];
  unsigned char *end = bg_xcalloc(n, 1); /* ends of hub bonds without a route */
  for (int e = 0; e < g->ne; e++)
    if (g->bent[e] < 0 && is_hub_bond(g, e)) end[g->et[e]] = end[g->eh[e]] = 1;
  for (int e = 0; e < g->ne; e++) /* those and their hub neighbours stay */
    if (is_hub_bond(g, e) && (end[g->et[e]] || end[g->eh[e]]))
      ok[g->et[e]] = ok[g->et[e]] ? 2 : 0, ok[g->eh[e]] = ok[g->eh[e]] ? 2 : 0;
  free(end);
  free(cyc), free(rough);
  return ok;
}

/* With submodels, whether the side lies wholly inside the instance its hub
 * p is drawn in or wholly outside it (or p is the model's own): a side
 * holding both, the instance's branch and another instance beyond it, took
 * that other instance into the columns of p's frame, round its nodes (a
 * tee's branch pipe inside the tee's frame, issue 31). */
static int side_in_hub_instance(const grid *g, const side_move *mv) {
  const bg_model *m = g->d->m;
  if (!m->ninst || mv->p >= m->nelem || m->elem_inst[mv->p] < 0) return 1;
  int inside = 0;
  for (int i = 0; i < mv->nq; i++) {
    int v = mv->q[i], in = 0;
    for (int k = v < m->nelem ? m->elem_inst[v] : -1; k >= 0 && !in; k = m->inst_parent[k]) in = k == m->elem_inst[mv->p];
    inside += in;
  }
  return inside == 0 || inside == mv->nq;
}

static void straighten_branches(grid *g) {
  size_t n = (size_t)g->n + 1;
  unsigned char *mark = bg_xcalloc(n, 1), *ok = movable(g);
  int *qa = bg_xcalloc(n, sizeof(int)), *qb = bg_xcalloc(n, sizeof(int));
  for (int e = 0; e < g->ne; e++) {
    if (g->bent[e] < 1 || !is_hub_bond(g, e) || ok[g->et[e]] != 1 || ok[g->eh[e]] != 1) continue;
    int nq, s = smaller_side(g, e, mark, qa, qb, &nq), fits = 0;
    side_move mv = {.q = s == 1 ? qa : qb, .nq = nq, .e = e, .mark = mark};
    for (int i = 0; i < nq; i++) s = ok[mv.q[i]] == 1 ? s : 0;
    if (!s) continue;
    mv.c = mv.q[0], mv.p = other(g, e, mv.c);
    if (!side_in_hub_instance(g, &mv)) continue;
    /* into p's column or p's row, the shorter move first */
    int ax = g->gx[mv.p] - g->gx[mv.c], ay = g->gy[mv.p] - g->gy[mv.c];
    for (int i = 0; i < nq; i++) mark[mv.q[i]] = 1;
    for (int k = 0; k < 2 && !fits; k++) {
      int across = (abs(ax) <= abs(ay)) == (k == 0);
      mv.dx = across ? ax : 0, mv.dy = across ? 0 : ay;
      fits = move_fits(g, &mv);
    }
    if (fits) {
      unroute(g, e);
      move_side(g, &mv);
      int t = g->et[e], h = g->eh[e]; /* tail first: try_route gives pts[0]'s side to the tail */
      int pts[2][2] = {{g->gx[t], g->gy[t]}, {g->gx[h], g->gy[h]}};
      try_route(g, e, (const int(*)[2])pts, 2);
    }
    for (int i = 0; i < nq; i++) mark[mv.q[i]] = 0;
  }
  free(mark), free(ok), free(qa), free(qb);
}

/* ---------------------------------------------------------------- one-ports */
static const int side_dx[4] = {1, 0, -1, 0}, side_dy[4] = {0, -1, 0, 1}; /* R U L D */

/* How far (radians) side k is from where dot put leaf w around hub v; a
 * source prefers the left, where textbooks start the chain. */
static double side_cost(const grid *g, int v, int w, int k) {
  const bg_diagram_layout *d = g->d;
  double ang = atan2(d->ny[w] - d->ny[v], d->nx[w] - d->nx[v]);
  double dif = fabs(remainder(ang - atan2(side_dy[k], side_dx[k]), 2 * BG_PI));
  int source = w < d->m->nelem && bg_elem_is_source(d->m->elem_kind[w]);
  const bg_model *m = d->m;
  if (g->inst_cx && v < m->nelem && w < m->nelem && m->elem_inst[v] >= 0 && m->elem_inst[w] != m->elem_inst[v]) {
    /* an element outside the hub's instance (on a port's junction) goes
     * out of its frame: away from the instance's hubs (issue 31: R : load
     * sat inside the frames of the last Inner it hangs from) */
    int i = m->elem_inst[v];
    double ax = g->gx[v] - g->inst_cx[i], ay = g->gy[v] - g->inst_cy[i], al = hypot(ax, ay);
    double c = al > 1e-9 ? (ax * side_dx[k] + ay * side_dy[k]) / al : 0;
    dif += 4 * (1 - c);
  }
  return dif - (source && k == 2 ? 1.0 : 0);
}

static void put_leaf(grid *g, int v, int w, int x, int y, int side) {
  g->gx[w] = x, g->gy[w] = y, g->placed[w] = 1;
  cell_take(g, x, y, w);
  g->sides[v] |= (unsigned char)side;
}

/* Best assignment of up to four leaves to hub v's free sides (every
 * injective choice tried; a leaf may also stay without a side). */
static void assign_sides(grid *g, int v, const int *leaf, int nl) {
  int freeside[4], nf = 0, best[4] = {-1, -1, -1, -1}, cur[4];
  for (int k = 0; k < 4; k++)
    if (!(g->sides[v] & (1 << k)) && cell_free(g, g->gx[v] + side_dx[k], g->gy[v] + side_dy[k])) freeside[nf++] = k;
  double best_cost = 1e300;
  int total = 1;
  for (int i = 0; i < nl; i++) total *= nf + 1;
  for (int code = 0; code < total; code++) {
    int c = code, used = 0, placed = 0, ok = 1;
    double cost = 0;
    for (int i = 0; i < nl; i++, c /= nf + 1) {
      cur[i] = c % (nf + 1) - 1;
      if (cur[i] < 0) continue;
      if (used & (1 << cur[i])) ok = 0;
      used |= 1 << cur[i], placed++;
      cost += side_cost(g, v, leaf[i], freeside[cur[i]]);
    }
    cost += 10.0 * (nl - placed); /* a side for as many leaves as possible */
    if (ok && cost < best_cost) best_cost = cost, memcpy(best, cur, sizeof cur);
  }
  for (int i = 0; i < nl; i++)
    if (best[i] >= 0) {
      int k = freeside[best[i]];
      put_leaf(g, v, leaf[i], g->gx[v] + side_dx[k], g->gy[v] + side_dy[k], 1 << k);
    }
}

/* A free cell near (x, y): rings of growing radius, the diagonal neighbours
 * first. */
static void near_cell(grid *g, int x, int y, int sides, int *ox, int *oy) {
  for (int r = 1;; r++)
    for (int k = 0; k < 8 * r; k++) {
      int side = k / (2 * r), t = k % (2 * r) - r + 1;
      int cx = side == 0 ? x + r : side == 1 ? x - t : side == 2 ? x - r : x + t;
      int cy = side == 0 ? y - t : side == 1 ? y - r : side == 2 ? y + t : y + r;
      if (r == 1 && k % 2 == 0 && !sides) continue; /* the four sides were offered already */
      if (cell_free(g, cx, cy)) {
        *ox = cx, *oy = cy;
        return;
      }
    }
}

/* The diagonal quadrants of hub v (bit 2 * (dy > 0) + (dx > 0)) that may
 * hold the half arrow of a bond ending at v: the barb leans back from the
 * head to one side, the left of the bond in one style and below or right in
 * another (bg_barb_side_at), so both count and the choice is the same in
 * every style (issue 31: one arrangement for every style). A one-port's
 * bond drawn at 45 degrees into such a quadrant had its causal stroke on
 * the barb (the 5 x 5 grid in slides: nine strokes touching). */
static int barb_quadrants(const grid *g, int v) {
  int mask = 0;
  for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
    int e = g->adj[k], w = other(g, e, v), pts[MAX_PTS][2], sx, sy;
    if (e >= g->d->m->nbond || g->eh[e] != v || !g->placed[w]) continue;
    if (g->bent[e] >= 0) {
      int n = route_points(g, e, pts);
      sx = sgn(pts[n - 2][0] - pts[n - 1][0]), sy = sgn(pts[n - 2][1] - pts[n - 1][1]);
    } else {
      sx = sgn(g->gx[w] - g->gx[v]), sy = sgn(g->gy[w] - g->gy[v]);
    }
    if (!sx == !sy) continue; /* a diagonal, or a bond inside a box */
    /* heading (-sx, -sy): its left (y down) is (-sy, sx); "down" is below a
     * horizontal bond and right of a vertical one */
    int lx = -sy, ly = sx, dx = sx ? 0 : 1, dy = sx ? 1 : 0;
    mask |= 1 << (2 * (sy + ly > 0) + (sx + lx > 0));
    mask |= 1 << (2 * (sy + dy > 0) + (sx + dx > 0));
  }
  return mask;
}

/* The diagonal quadrants of hub v (as barb_quadrants) towards the far end
 * of a hub bond of v the grid found no route for: the bond router draws it
 * later and, v's four sides taken, it comes in there (issue 31: a random
 * tree's junction of five hub bonds had a one-port on that diagonal, the
 * bond's causal stroke on the one-port's bond). */
static int unrouted_quadrants(const grid *g, int v, int *only) {
  int mask = 0;
  *only = 0;
  for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
    int e = g->adj[k], w = other(g, e, v), dx, dy;
    if (g->bent[e] >= 0 || !is_hub_bond(g, e) || !g->placed[w]) continue;
    dx = g->gx[w] - g->gx[v], dy = g->gy[w] - g->gy[v];
    for (int q = 0; q < 4; q++) /* straight above, below or beside: both quadrants that way */
      if ((dx || dy) && (q & 1 ? dx >= 0 : dx <= 0) && (q & 2 ? dy >= 0 : dy <= 0)) mask |= 1 << q;
    if (dx && dy) *only |= 1 << (2 * (dy > 0) + (dx > 0)); /* the one way in there is */
  }
  return mask;
}

/* A diagonal neighbour cell of hub v for its one-port w when its four sides
 * are taken: a free one away from the half arrows there (barb_quadrants)
 * and from the ways in of the hub bonds still unrouted, nearest where dot
 * put w; a quadrant that is an unrouted bond's only way in (its far end
 * diagonal from v) is kept freer still: a one-port there sent the bond
 * into another corner, across v's other bonds (100 held-out property
 * models: 6 of their 28 crossings of two bonds of one node). 0 when none
 * is free. */
static int diagonal_cell(grid *g, int v, int w, int *ox, int *oy) {
  const bg_diagram_layout *d = g->d;
  int only, barbs = barb_quadrants(g, v) | unrouted_quadrants(g, v, &only), found = 0;
  double best = 1e300, ang = atan2(d->ny[w] - d->ny[v], d->nx[w] - d->nx[v]);
  for (int q = 0; q < 4; q++) {
    int dx = q & 1 ? 1 : -1, dy = q & 2 ? 1 : -1;
    if (!cell_free(g, g->gx[v] + dx, g->gy[v] + dy)) continue;
    double cost = fabs(remainder(ang - atan2(dy, dx), 2 * BG_PI)) + (barbs & (1 << q) ? 10 : 0) +
                  (only & (1 << q) ? 10 : 0);
    if (cost < best) best = cost, *ox = g->gx[v] + dx, *oy = g->gy[v] + dy, found = 1;
  }
  return found;
}

/* Per instance: the centre of its own hubs on the grid (side_cost). */
static void instance_centres(grid *g) {
  const bg_model *m = g->d->m;
  if (!m->ninst) return;
  g->inst_cx = bg_xcalloc((size_t)m->ninst, sizeof(double)), g->inst_cy = bg_xcalloc((size_t)m->ninst, sizeof(double));
  int *cnt = bg_xcalloc((size_t)m->ninst, sizeof(int));
  for (int v = 0; v < g->n && v < m->nelem; v++)
    if (g->hub[v] && g->placed[v] && m->elem_inst[v] >= 0)
      g->inst_cx[m->elem_inst[v]] += g->gx[v], g->inst_cy[m->elem_inst[v]] += g->gy[v], cnt[m->elem_inst[v]]++;
  for (int i = 0; i < m->ninst; i++)
    if (cnt[i]) g->inst_cx[i] /= cnt[i], g->inst_cy[i] /= cnt[i];
  free(cnt);
}

/* The gaps between neighbouring grid columns and between rows (to_points):
 * at least 2.5 half arrows (7 line widths each) and the junction's end
 * circle, so that thick lines (slides) do not leave one-port bonds hardly
 * longer than their barb, and room for path and loop lines. */
static void style_gaps(const bg_style *st, double band, double *xgap, double *ygap) {
  double least = 2.5 * 7 * st->line_width + 3;
  *xgap = fmax(st->rank_sep / 2, least) + band;
  *ygap = fmax(st->node_sep * 0.75, least) + band;
}

static void cell_gaps(const grid *g, double *xgap, double *ygap) { style_gaps(&g->d->st, layer_band(g), xgap, ygap); }

/* How many of the eight cells round hub v are free. */
static int free_neighbours(const grid *g, int v) {
  int n = 0;
  for (int dx = -1; dx <= 1; dx++)
    for (int dy = -1; dy <= 1; dy++) n += (dx || dy) && cell_free(g, g->gx[v] + dx, g->gy[v] + dy);
  return n;
}

/* Per node the other end of its first signal (both ends in the layout),
 * -1 for none: one pass over the signals. A signal from a node to itself
 * counts as its first with keep_self (that end is the node), else it is
 * passed over. */
static int *first_signal_ends(const grid *g, int keep_self) {
  const bg_diagram_layout *d = g->d;
  const bg_model *m = d->m;
  int *end = bg_xmalloc(((size_t)g->n + 1) * sizeof *end);
  for (int v = 0; v < g->n; v++) end[v] = -1;
  for (int i = 0; i < m->nsignal; i++) {
    int from = bg_signal_from_node(d, i), to = d->node_of[m->signal_to[i]];
    if (from < 0 || from >= g->n || to < 0 || to >= g->n || (from == to && !keep_self)) continue;
    if (end[from] < 0) end[from] = to;
    if (end[to] < 0) end[to] = from;
  }
  return end;
}

/* The placed hub at the other end of one-port u's first signal (that end
 * itself, or the hub a one-port there hangs from), or -1. */
static int signal_hub(grid *g, int u) {
  /* once: a loop over the signals per one-port was signals x one-ports */
  if (!g->first_end) g->first_end = first_signal_ends(g, 1);
  int p = g->first_end[u];
  if (p < 0) return -1;
  if (!g->hub[p] && g->deg[p] == 1) p = other(g, g->adj[g->adr[p]], p);
  return g->hub[p] && g->placed[p] ? p : -1;
}

/* Hub v's nl one-ports on a ring round it (bg_layout_ring), in the order of
 * their angles in dot's drawing, when the cells next to it cannot hold them
 * (a one-port with a signal at the angle towards its other end on the grid)
 * (issue 31: the rest went to cells further out, on bonds through the labels
 * nearer in, which the bond router then took round the whole figure: a star
 * of 20 one-ports had 6 crossings and 2 bonds on others, of 100, 709 and 597).
 * The one-ports take no cell: the hub's cell is made as wide and tall as the
 * ring (to_points), so the rest of the figure keeps out of it, and a side
 * whose cell a bond or a node holds keeps its middle free. */
static void ring_leaves(grid *g, int v, const int *leaf, int nl) {
  const bg_diagram_layout *d = g->d;
  if (!g->orbit) {
    size_t n = (size_t)g->n + 1;
    g->orbit = bg_xmalloc(n * sizeof(int));
    for (int u = 0; u < g->n; u++) g->orbit[u] = -1;
    g->ring_x = bg_xcalloc(n, sizeof(double)), g->ring_y = bg_xcalloc(n, sizeof(double));
    g->ring_w = bg_xcalloc(n, sizeof(double)), g->ring_h = bg_xcalloc(n, sizeof(double));
  }
  double *ang = bg_xmalloc(3 * (size_t)nl * sizeof(double)), *ox = ang + nl, *oy = ox + nl;
  double w = 0, h = 0, rw = 0, rh = 0, sx = 0, sy = 0;
  for (int i = 0; i < nl; i++) {
    int u = leaf[i], p = g->signalled[u] ? signal_hub(g, u) : -1;
    w = fmax(w, d->nw[u]), h = fmax(h, d->nh[u]), rw = fmax(rw, g->rw[u]), rh = fmax(rh, g->rh[u]);
    if (g->rw[u] > 0 && g->rh[u] > 0) sx = fmax(sx, d->nw[u] / g->rw[u]), sy = fmax(sy, d->nh[u] / g->rh[u]);
    if (p >= 0 && p != v && (g->gx[p] != g->gx[v] || g->gy[p] != g->gy[v]))
      ang[i] = atan2(g->gy[p] - g->gy[v], g->gx[p] - g->gx[v]); /* towards its signal's other end */
    else ang[i] = atan2(d->ny[u] - d->ny[v], d->nx[u] - d->nx[v]);
  }
  int closed = 0;
  for (int k = 0; k < 4; k++)
    if ((g->sides[v] & (1 << k)) || !cell_free(g, g->gx[v] + side_dx[k], g->gy[v] + side_dy[k])) closed |= 1 << k;
  /* laid out in the reference style without the layers' room, then
   * stretched along each axis until every box of this style fits in its
   * stretched reference box and the pitches are this style's: the same
   * ring, corner for corner, in every style and layer set (a stretch keeps
   * every clearance of the reference ring) */
  double xgap, ygap, rxgap, rygap, hx, hy;
  cell_gaps(g, &xgap, &ygap);
  style_gaps(g->ref, 0, &rxgap, &rygap);
  bg_layout_ring(nl, ang, rw, rh, rxgap, rygap, closed, ox, oy, &hx, &hy);
  sx = fmax(sx, (w + xgap) / (rw + rxgap)), sy = fmax(sy, (h + ygap) / (rh + rygap));
  for (int i = 0; i < nl; i++) {
    int u = leaf[i];
    g->gx[u] = g->gx[v], g->gy[u] = g->gy[v], g->placed[u] = 1;
    g->orbit[u] = v, g->ring_x[u] = ox[i] * sx, g->ring_y[u] = oy[i] * sy;
  }
  g->ring_w[v] = 2 * hx * sx, g->ring_h[v] = 2 * hy * sy;
  free(ang);
}

/* One-ports to free sides of their hubs (assign_sides), the rest to a
 * diagonal cell: one away from the hub's barbs (diagonal_cell) when the
 * one-port has no signal, else the first free one round the hub
 * (near_cell): the barb rule turned the reaction rings' species
 * capacitors away from their reactions, 17 -> 18 signal crossings in
 * reactions12 and 163 -> 174 in reactions60. */
static int compactable(const grid *g);

/* Per node, the node at the other end of its first signal that is not
 * itself (as drawn), or -1: one pass over the signals. */
static int *signal_partners(const grid *g) {
  const bg_diagram_layout *d = g->d;
  const bg_model *m = d->m;
  int *partner = first_signal_ends(g, 0);
  for (int v = 0; v < g->n; v++)
    if (partner[v] >= 0) partner[v] = drawn_by(d, partner[v]);
  /* an element a user state integrates (its signal goes to the state's
   * integrator, placed later beside what the state modulates): that */
  int in[64];
  for (int k = 0; k < m->nstate; k++) {
    int target = -1;
    for (int j = g->sadr[k]; j < g->sadr[k + 1] && target < 0; j++)
      if (d->node_of[m->signal_to[g->slist[j]]] < g->n) target = drawn_by(d, m->signal_to[g->slist[j]]);
    if (target < 0 || d->state_node[k] < 0) continue;
    for (int j = 0, nin = bg_state_inputs(m, k, in, 64); j < nin; j++) {
      int u = d->node_of[in[j]] < g->n ? drawn_by(d, in[j]) : -1;
      if (u >= 0 && u != target && partner[u] < 0) partner[u] = target;
    }
  }
  return partner;
}

/* A one-port with a signal (or one a user state integrates: its partner
 * is what the state modulates, beside which the integrator goes) hung
 * above or below its hub while the signal's other end is on the far side
 * of the hub's row goes to the other side when that cell is free, or
 * changes places with a one-port of the hub there that has no signal: its
 * signal then need not cross the row (issue
 * 31: a robot joint's spring under its junction, its signal to an
 * amplifier above the row, crossed the bond between; a modulated ladder of
 * 9 sections 5 -> 1 signal crossings, of 120 drawn on the grid 87 -> 17).
 * Only where every hub bond has its grid route (compactable): a bond drawn
 * round the nodes later is routed only where its straight line meets a
 * box, and a one-port moved off its line left reactions20's chord 87
 * slanted, seven signals across it at a slant. */
static void face_signals(grid *g) {
  int *partner = signal_partners(g);
  /* moves to free cells first, then changes of place: a one-port whose
   * partner would move to face it stays (a robot joint's spring, its
   * partner the motor's voltage above, went up; the voltage swapped down
   * first and took the joint's inertia with it) */
  for (int pass = 0; pass < 2; pass++) {
    for (int w = 0; w < g->n; w++) {
      if (g->hub[w] || g->deg[w] != 1 || partner[w] < 0 || !g->placed[w] || !own_node(g->d, w)) continue;
      int v = other(g, g->adj[g->adr[w]], w), p = partner[w];
      if (!g->hub[v] || !g->placed[p] || g->gx[w] != g->gx[v] || abs(g->gy[w] - g->gy[v]) != 1) continue;
      int dy = g->gy[w] - g->gy[v], dp = g->gy[p] - g->gy[v], side = dy < 0 ? SIDE_U : SIDE_D, flip = dy < 0 ? SIDE_D : SIDE_U;
      int x = g->gx[v], y = g->gy[v] - dy, u = g->val[cell_slot(g, cell_key(x, y))];
      if (dp * dy >= 0) continue;
      int swap = pass == 1 && u >= 0 && partner[u] < 0 && !g->hub[u] && g->deg[u] == 1;
      if (swap && other(g, g->adj[g->adr[u]], u) == v) {
        /* the other side holds a one-port of v without a signal: the two
         * change places (a boom's mass under its junction, its friction
         * above, the mass's signal to the valve below crossed the row) */
        g->gx[u] = g->gx[w], g->gy[u] = g->gy[w], cell_take(g, g->gx[u], g->gy[u], u);
        g->gx[w] = x, g->gy[w] = y, cell_take(g, x, y, w);
        continue;
      }
      if ((g->sides[v] & flip) || !cell_free(g, x, y)) continue;
      g->val[cell_slot(g, cell_key(g->gx[w], g->gy[w]))] = RELEASED;
      g->sides[v] &= (unsigned char)~side;
      put_leaf(g, v, w, x, y, flip);
    }
  }
  free(partner);
}

static void place_leaves(grid *g) {
  instance_centres(g);
  int *leaf = bg_xcalloc((size_t)g->n + 1, sizeof(int));
  for (int v = 0; v < g->n; v++) {
    if (!g->hub[v] || !g->placed[v]) continue;
    int nl = 0;
    for (int k = g->adr[v]; k < g->adr[v + 1]; k++) {
      int w = other(g, g->adj[k], v);
      if (!g->hub[w] && !g->placed[w]) leaf[nl++] = w;
    }
    if (nl > free_neighbours(g, v)) {
      ring_leaves(g, v, leaf, nl);
      continue;
    }
    assign_sides(g, v, leaf, nl < 4 ? nl : 4);
    for (int i = 0; i < nl; i++) {
      if (g->placed[leaf[i]]) continue;
      int x, y;
      if (g->signalled[leaf[i]] || !diagonal_cell(g, v, leaf[i], &x, &y)) near_cell(g, g->gx[v], g->gy[v], 0, &x, &y);
      put_leaf(g, v, leaf[i], x, y, 0);
    }
  }
  free(leaf);
  if (compactable(g)) face_signals(g);
}

/* Per user state its signals, in order: g->slist[g->sadr[s] .. sadr[s + 1])
 * (a loop over every signal per integrator made the layout quadratic in
 * the states: float_anchor, signal_partners). */
static void state_signals(grid *g) {
  const bg_model *m = g->d->m;
  int *adr = bg_xcalloc((size_t)m->nstate + 2, sizeof(int)), *list = bg_xcalloc((size_t)m->nsignal + 1, sizeof(int));
  int *fill = bg_xcalloc((size_t)m->nstate + 1, sizeof(int));
  for (int i = 0; i < m->nsignal; i++)
    if (bg_signal_state(g->d, i) >= 0) adr[bg_signal_state(g->d, i) + 1]++;
  for (int s = 0; s < m->nstate; s++) adr[s + 1] += adr[s];
  for (int i = 0; i < m->nsignal; i++) {
    int s = bg_signal_state(g->d, i);
    if (s >= 0) list[adr[s] + fill[s]++] = i;
  }
  free(fill);
  g->sadr = adr, g->slist = list;
}

/* The node a float sits beside: for a user-state integrator the element
 * its first signal modulates, else the placed node dot put nearest. */
static int float_anchor(const grid *g, int v) {
  const int *sadr = g->sadr, *slist = g->slist;
  const bg_diagram_layout *d = g->d;
  const bg_model *m = d->m;
  int k = d->node_det[v], s = d->node_state[v];
  if (k >= 0 && g->placed[bg_detector_anchor(d, k)]) return bg_detector_anchor(d, k); /* beside the node it reads */
  for (int j = s >= 0 ? sadr[s] : 0; s >= 0 && j < sadr[s + 1]; j++)
    if (g->placed[drawn_by(d, m->signal_to[slist[j]])]) return drawn_by(d, m->signal_to[slist[j]]);
  int best = -1;
  double bd = 1e300;
  for (int u = 0; u < g->n; u++) {
    double dd = hypot(d->nx[u] - d->nx[v], d->ny[u] - d->ny[v]);
    if (g->placed[u] && own_node(d, u) && dd < bd) bd = dd, best = u;
  }
  return best;
}

/* Nodes with no place yet (user-state integrators, elements without bonds):
 * above or below their anchor, else in a free cell next to it. */
static void place_floats(grid *g) {
  for (int v = 0; v < g->n; v++) {
    if (g->placed[v]) continue;
    int a = float_anchor(g, v), x = 0, y = 0;
    if (a >= 0 && cell_free(g, g->gx[a], g->gy[a] - 1)) x = g->gx[a], y = g->gy[a] - 1; /* above */
    else if (a >= 0 && cell_free(g, g->gx[a], g->gy[a] + 1)) x = g->gx[a], y = g->gy[a] + 1;
    else if (a >= 0) near_cell(g, g->gx[a], g->gy[a], 1, &x, &y);
    else while (!cell_free(g, x, y)) x += 2;
    g->gx[v] = x, g->gy[v] = y, g->placed[v] = 1;
    cell_take(g, x, y, v);
  }
}

/* The band every node is drawn in (bg_layout.band), for frames drawn per
 * band when a fold cuts an instance (diagram_frames.c): a hub's from the
 * fold, a one-port's its hub's, a node without bonds its anchor's, a node
 * inside a box or a field its drawer's. */
static void record_bands(grid *g) {
  bg_diagram_layout *d = g->d;
  int *band = bg_xcalloc((size_t)g->n + 1, sizeof *band);
  unsigned char *done = bg_xcalloc((size_t)g->n + 1, 1);
  for (int v = 0; v < g->n; v++)
    if (g->hub[v] && own_node(d, v)) band[v] = g->band[v], done[v] = 1;
  for (int v = 0; v < g->n; v++)
    for (int k = g->adr[v]; !done[v] && own_node(d, v) && k < g->adr[v + 1]; k++) {
      int w = drawn_by(d, other(g, g->adj[k], v));
      if (g->hub[w]) band[v] = band[w], done[v] = 1;
    }
  for (int v = 0; v < g->n; v++)
    if (!done[v] && own_node(d, v)) {
      int a = float_anchor(g, v);
      band[v] = a >= 0 && done[a] ? band[a] : 0;
    }
  for (int v = 0; v < g->n; v++)
    if (!own_node(d, v)) band[v] = band[drawn_by(d, v)];
  free(done);
  free(d->lay.band);
  d->lay.band = band;
}

/* ---------------------------------------------------------------- cells to points */
/* Centre of every grid line (column or row) k in [lo, hi]: each as wide as
 * its widest node, `gap` between neighbours. */
static double *line_centres(const grid *g, const int *cell, const double *size, int lo, int hi,
                            double gap) {
  int n = hi - lo + 1;
  double *w = bg_xcalloc((size_t)n + 1, sizeof(double)), *c = bg_xcalloc((size_t)n + 1, sizeof(double));
  for (int v = 0; v < g->n; v++)
    if (own_node(g->d, v) && size[v] > w[cell[v] - lo]) w[cell[v] - lo] = size[v];
  c[0] = w[0] / 2;
  for (int k = 1; k < n; k++) c[k] = c[k - 1] + w[k - 1] / 2 + gap + w[k] / 2;
  free(w);
  return c;
}

static double *line_centres(const grid *g, const int *cell, const double *size, int lo, int hi, double gap);

typedef struct room_item {
  int row, col; /* its cell */
  double half;  /* half its width */
} room_item;

static int by_row_then_column(const void *a, const void *b, void *ctx) {
  (void)ctx;
  const room_item *p = a, *q = b;
  if (p->row != q->row) return (p->row > q->row) - (p->row < q->row);
  return (p->col > q->col) - (p->col < q->col);
}

/* What takes room in the rows: every node (half its width; one per cell,
 * the largest: a ring's one-ports share their hub's cell) and every cell a
 * bond's route runs through (no width, so nothing comes to sit on a
 * vertical bond), sorted by row, then column. Returns the count. */
static int room_items(const grid *g, const double *width, room_item **out) {
  int ni = 0, cap = g->n + 16;
  room_item *it = bg_xmalloc((size_t)cap * sizeof *it);
  for (int v = 0; v < g->n; v++)
    if (own_node(g->d, v)) it[ni++] = (room_item){g->gy[v], g->gx[v], width[v] / 2};
  for (int e = 0; e < g->ne; e++) {
    if (g->bent[e] < 0 || !is_hub_bond(g, e)) continue;
    int pts[MAX_PTS][2], np = route_points(g, e, pts);
    for (int k = 0; k + 1 < np; k++) {
      int x = pts[k][0], y = pts[k][1], sx = sgn(pts[k + 1][0] - x), sy = sgn(pts[k + 1][1] - y);
      while (x != pts[k + 1][0] || y != pts[k + 1][1]) {
        x += sx, y += sy;
        if (k == np - 2 && x == pts[np - 1][0] && y == pts[np - 1][1]) break;
        if (sx && !(x == pts[k + 1][0] && y == pts[k + 1][1])) continue; /* along its row: it stretches */
        if (ni == cap) cap *= 2, it = bg_xrealloc(it, (size_t)cap * sizeof *it);
        it[ni++] = (room_item){y, x, 0};
      }
    }
  }
  bg_sort(it, (size_t)ni, sizeof *it, by_row_then_column, NULL);
  int nu = 0;
  for (int i = 0; i < ni; i++)
    if (nu && it[nu - 1].row == it[i].row && it[nu - 1].col == it[i].col) it[nu - 1].half = fmax(it[nu - 1].half, it[i].half);
    else it[nu++] = it[i];
  *out = it;
  return nu;
}

/* Centre of every column k in [lo, hi] from what meets in each row: two
 * neighbours in a row at least their half widths and `gap` per column
 * between them apart, each column at least `gap` after the one before (issue
 * 31, columns compacted: line_centres made a column as wide as its widest
 * node in any row, so a one-port hung beside a junction above the main row
 * widened the main row's bond under it: the quarter car's bond 7 was 1.58
 * times bond 3). A slanted one-port bond (on a diagonal cell) keeps the run across
 * the columns line_centres gives it: packed closer, it ran steeper past the
 * strokes and numbers round it. For a grid whose hub bonds all have routes
 * (compactable). Linear but for the sort. */
static double *compact_columns(const grid *g, const double *width, int lo, int hi, double gap) {
  int n = hi - lo + 1;
  room_item *it;
  int ni = room_items(g, width, &it);
  double *wide = line_centres(g, g->gx, width, lo, hi, gap), *c = bg_xcalloc((size_t)n + 1, sizeof *c);
  /* constraints into each column: from its row neighbours (pass 0) and the
   * slanted bonds ending there (pass 1), as (from, distance) lists */
  int *adr = bg_xcalloc((size_t)n + 2, sizeof *adr), *fill = bg_xcalloc((size_t)n + 1, sizeof *fill);
  int *from = bg_xmalloc(((size_t)ni + (size_t)g->ne + 1) * sizeof *from);
  double *dist = bg_xmalloc(((size_t)ni + (size_t)g->ne + 1) * sizeof *dist);
  for (int pass = 0; pass < 2; pass++) {
    for (int i = 0; i + 1 < ni; i++) {
      if (it[i].row != it[i + 1].row) continue;
      int a = it[i].col - lo, b = it[i + 1].col - lo;
      if (!pass) adr[b + 1]++;
      else from[adr[b] + fill[b]] = a, dist[adr[b] + fill[b]++] = it[i].half + it[i + 1].half + gap * (b - a);
    }
    for (int e = 0; e < g->ne; e++) {
      int u = g->et[e], v = g->eh[e];
      if (is_hub_bond(g, e) || u == v || !own_node(g->d, u) || !own_node(g->d, v) || g->gx[u] == g->gx[v] ||
          g->gy[u] == g->gy[v] || (g->orbit && (g->orbit[u] >= 0 || g->orbit[v] >= 0)))
        continue;
      int a = (g->gx[u] < g->gx[v] ? g->gx[u] : g->gx[v]) - lo, b = (g->gx[u] < g->gx[v] ? g->gx[v] : g->gx[u]) - lo;
      if (!pass) adr[b + 1]++;
      else from[adr[b] + fill[b]] = a, dist[adr[b] + fill[b]++] = wide[b] - wide[a];
    }
    if (!pass)
      for (int k = 0; k < n; k++) adr[k + 1] += adr[k];
  }
  for (int i = 0; i < ni; i++) c[it[i].col - lo] = fmax(c[it[i].col - lo], it[i].half); /* nothing left of 0 */
  for (int k = 0; k < n; k++) {
    if (k) c[k] = fmax(c[k], c[k - 1] + gap);
    for (int j = adr[k]; j < adr[k + 1]; j++) c[k] = fmax(c[k], c[from[j]] + dist[j]);
  }
  free(it), free(wide), free(adr), free(fill), free(from), free(dist);
  return c;
}

/* Whether the columns may be compacted: every bond between hubs has a
 * route on the grid (none is drawn round the nodes later, in the room the
 * columns leave: a held-out tree of 1 400 junctions had one such bond run
 * over a causal stroke) and no junction's one-ports stand on a ring (the
 * one-ports of hubs beside a ring are pulled into its tall row, into the
 * room the columns leave: ringtree22 had two on long steep bonds). */
static int compactable(const grid *g) {
  if (g->orbit || g->mazed) return 0;
  for (int e = 0; e < g->ne; e++)
    if (g->bent[e] < 0 && is_hub_bond(g, e)) return 0;
  return 1;
}

static void range(const grid *g, const int *cell, int *lo, int *hi) {
  *lo = 1 << 30, *hi = -(1 << 30);
  for (int v = 0; v < g->n; v++)
    if (own_node(g->d, v)) *lo = cell[v] < *lo ? cell[v] : *lo, *hi = cell[v] > *hi ? cell[v] : *hi;
  for (int e = 0; e < g->ne; e++)
    for (int k = 0; k < g->bent[e]; k++) {
      int c = cell == g->gx ? g->corner[e][2 * k] : g->corner[e][2 * k + 1];
      *lo = c < *lo ? c : *lo, *hi = c > *hi ? c : *hi;
    }
}

/* Room for the path and loop lines a bond carries on one side when those
 * layers are shown (at most six counted), so numbers fit beyond them. */
static double layer_band(const grid *g) {
  const bg_diagram_layout *d = g->d;
  int *use = bg_layer_use(d), most = 0;
  if (!use) return 0;
  for (int b = 0; b < d->m->nbond; b++) most = use[b] > most ? use[b] : most;
  free(use);
  if (most > 6) most = 6;
  return most ? bg_layer_line(&d->st, most - 1) : 0;
}

/* The grid lines (columns or rows, centres c[0..n) in points) whose boxes
 * can meet [a, b]: a box in line k lies between the midpoints to its
 * neighbours; one more each side for a one-port pulled towards its hub. */
static void lines_meeting(const double *c, int n, double a, double b, int *lo, int *hi) {
  int l = 0, h = n; /* the first line whose upper midpoint reaches a */
  while (l < h) {
    int mid = (l + h) / 2;
    if (mid + 1 < n && (c[mid] + c[mid + 1]) / 2 < a) l = mid + 1;
    else h = mid;
  }
  *lo = l > 0 ? l - 1 : 0;
  for (h = l; h + 1 < n && (c[h] + c[h + 1]) / 2 <= b; h++) {}
  *hi = h + 1 < n ? h + 1 : n - 1;
}

/* One-ports that a ring's row or column pushed away from their hub (a bus's
 * inertia level with its ring's top: the ring's cell sets its whole row's
 * height and column's width): each in a cell next to a hub in a row or
 * column that holds a ring (a side or a diagonal one) moves back to a gap
 * from its hub along the ring's way when its box there meets no other box
 * or ring. Only there: elsewhere a row's one-ports stay in line. */
static void pull_in(grid *g, double xgap, double ygap, const double *cx, const double *cy, int x0, int x1, int y0, int y1) {
  bg_diagram_layout *d = g->d;
  /* in a style that follows the reference style's layout, those it pulled
   * in and no other, each where its box keeps a quarter of a gap off the
   * others: with half a gap, slides' wider labels kept a capacitor 124 pt
   * below its hub that the default style drew 38 pt below it, beside its
   * neighbour (issue 31: one arrangement in every style) */
  const unsigned char *follow = d->ref && d->ref->pulled && d->ref->nnode == d->nnode ? d->ref->pulled : NULL;
  int nr = 0, *rings = bg_xmalloc(((size_t)g->n + 1) * sizeof(int));
  for (int v = 0; v < g->n; v++)
    if (g->ring_w[v] > 0) rings[nr++] = v;
  for (int w = 0; w < g->n; w++) {
    if (!own_node(d, w) || g->hub[w] || g->deg[w] != 1 || g->orbit[w] >= 0) continue;
    int v = other(g, g->adj[g->adr[w]], w), dx = g->gx[w] - g->gx[v], dy = g->gy[w] - g->gy[v], pushed = 0;
    if (!g->hub[v] || g->ring_w[v] > 0 || abs(dx) > 1 || abs(dy) > 1 || (!dx && !dy) || (follow && !follow[w])) continue;
    for (int k = 0; k < nr; k++) pushed |= (dx && g->gx[rings[k]] == g->gx[v]) || (dy && g->gy[rings[k]] == g->gy[v]);
    if (!pushed) continue;
    double x = dx ? d->nx[v] + dx * (d->nw[v] / 2 + xgap + d->nw[w] / 2) : d->nx[w];
    double y = dy ? d->ny[v] + dy * (d->nh[v] / 2 + ygap + d->nh[w] / 2) : d->ny[w];
    /* back towards its hub only: where the columns are narrow (a large
     * forest's, no ring's width in them) a gap from the hub lies beyond
     * the cell, and whether the box fits there depends on the style */
    int clear = fabs(x - d->nx[w]) + fabs(y - d->ny[w]) > 0.5 && fabs(x - d->nx[v]) <= fabs(d->nx[w] - d->nx[v]) + 0.01 &&
                fabs(y - d->ny[v]) <= fabs(d->ny[w] - d->ny[v]) + 0.01;
    double room = fmin(xgap, ygap) / (follow ? 4 : 2); /* to any other box: half a gap (a quarter) */
    /* the boxes it could meet: the rings (a ring's one-ports inside its
     * box), and the nodes of the cells near the place (every node was
     * tried: quadratic in a large forest with rings) */
    for (int k = 0; clear && k < nr; k++) {
      int u = rings[k];
      double hw = fmax(d->nw[u], g->ring_w[u]) / 2, hh = fmax(d->nh[u], g->ring_h[u]) / 2;
      clear = fabs(x - d->nx[u]) >= d->nw[w] / 2 + hw + room || fabs(y - d->ny[u]) >= d->nh[w] / 2 + hh + room;
    }
    int ca, cb, ra, rb;
    lines_meeting(cx, x1 - x0 + 1, x - d->nw[w] / 2 - room, x + d->nw[w] / 2 + room, &ca, &cb);
    lines_meeting(cy, y1 - y0 + 1, y - d->nh[w] / 2 - room, y + d->nh[w] / 2 + room, &ra, &rb);
    for (int i = ca; clear && i <= cb; i++)
      for (int j = ra; clear && j <= rb; j++) {
        int u = g->val[cell_slot(g, cell_key(i + x0, j + y0))];
        if (u < 0 || u == w || !own_node(d, u) || g->ring_w[u] > 0) continue;
        clear = fabs(x - d->nx[u]) >= d->nw[w] / 2 + d->nw[u] / 2 + room ||
                fabs(y - d->ny[u]) >= d->nh[w] / 2 + d->nh[u] / 2 + room;
      }
    if (clear) d->nx[w] = x, d->ny[w] = y, d->pulled[w] = 1;
  }
  free(rings);
}

/* Node centres and bond corners in points; the layout's box. */
static void to_points(grid *g) {
  bg_diagram_layout *d = g->d;
  int x0, x1, y0, y1;
  range(g, g->gx, &x0, &x1);
  range(g, g->gy, &y0, &y1);
  double xgap, ygap, *sw = NULL, *sh = NULL;
  cell_gaps(g, &xgap, &ygap);
  if (g->orbit) { /* a hub's cell as large as its ring */
    sw = bg_xmalloc((size_t)g->n * sizeof(double)), sh = bg_xmalloc((size_t)g->n * sizeof(double));
    for (int v = 0; v < g->n; v++) sw[v] = fmax(d->nw[v], g->ring_w[v]), sh[v] = fmax(d->nh[v], g->ring_h[v]);
  }
  /* columns as wide as their rows ask, where every bond between hubs has
   * its grid route and no path or loop lines need the room (compact_columns) */
  double *cx = layer_band(g) == 0 && compactable(g) ? compact_columns(g, sw ? sw : d->nw, x0, x1, xgap)
                                                   : line_centres(g, g->gx, sw ? sw : d->nw, x0, x1, xgap);
  double *cy = line_centres(g, g->gy, sh ? sh : d->nh, y0, y1, ygap);
  free(sw), free(sh);
  for (int v = 0; v < g->n; v++)
    if (own_node(d, v)) d->nx[v] = cx[g->gx[v] - x0], d->ny[v] = cy[g->gy[v] - y0];
  for (int v = 0; g->orbit && v < g->n; v++)
    if (g->orbit[v] >= 0) d->nx[v] += g->ring_x[v], d->ny[v] += g->ring_y[v];
  d->pulled = bg_arena_alloc(&d->arena, (size_t)d->nnode + 1);
  memset(d->pulled, 0, (size_t)d->nnode + 1);
  if (g->orbit) pull_in(g, xgap, ygap, cx, cy, x0, x1, y0, y1);
  for (int v = 0; v < g->n; v++) /* a field's other ports where their field is (boxes: bg_parts_spread) */
    if (!own_node(d, v)) d->nx[v] = d->nx[drawn_by(d, v)], d->ny[v] = d->ny[drawn_by(d, v)];
  bg_layout *l = &d->lay;
  l->width = l->height = 0;
  for (int v = 0; v < g->n; v++) {
    if (!own_node(d, v)) continue; /* drawn by its box or field */
    l->width = fmax(l->width, d->nx[v] + d->nw[v] / 2);
    l->height = fmax(l->height, d->ny[v] + d->nh[v] / 2);
  }
  int nb = d->m->nbond, total = 0;
  for (int b = 0; b < nb; b++) total += g->bent[b] > 0 ? g->bent[b] : 0;
  l->bendadr = bg_xcalloc((size_t)l->nedge + 1, sizeof(int));
  l->bendn = bg_xcalloc((size_t)l->nedge + 1, sizeof(int));
  l->bendx = bg_xcalloc((size_t)total + 1, sizeof(double));
  l->bendy = bg_xcalloc((size_t)total + 1, sizeof(double));
  for (int b = 0; b < nb; b++) {
    l->bendadr[b] = l->nbend;
    for (int k = 0; k < g->bent[b]; k++, l->nbend++) {
      l->bendx[l->nbend] = cx[g->corner[b][2 * k] - x0];
      l->bendy[l->nbend] = cy[g->corner[b][2 * k + 1] - y0];
    }
    l->bendn[b] = g->bent[b] > 0 ? g->bent[b] : 0;
  }
  free(cx), free(cy);
}

/* The offset (along both axes: a diagonal bond) of one-port w from its hub
 * on a diagonal cell whose centres lie `along` apart on the longer axis
 * (x when along_x) and `across` on the other (boxes w, h): `across`, or,
 * with a label k in the cell beside the hub that w moves towards (-1:
 * none), far enough out for w's box to stay an em off k's. */
static double diagonal_offset(const double *w, const double *h, int k, int one_port, int along_x, double across,
                              double em) {
  if (k < 0) return across;
  double need = (along_x ? w[one_port] + w[k] : h[one_port] + h[k]) / 2 + em;
  return fmax(across, need);
}

/* Whether one-port w on a diagonal cell of hub v may move out by `out`
 * along the shorter axis (y when along_x): the two cells beyond it that way
 * are free, or its box (reference sizes) stays on its own side of the
 * middle between its row (column) and theirs. */
static int room_outward(const grid *g, int v, int w, int along_x, double out, const double *rx, int x0, int x1,
                        const double *ry, int y0, int y1) {
  int o = along_x ? sgn(g->gy[w] - g->gy[v]) : sgn(g->gx[w] - g->gx[v]);
  int cx = along_x ? g->gx[w] : g->gx[w] + o, cy = along_x ? g->gy[w] + o : g->gy[w];
  int bx = along_x ? g->gx[v] : cx, by = along_x ? cy : g->gy[v];
  if (cell_free(g, cx, cy) && cell_free(g, bx, by)) return 1;
  if (along_x ? cy < y0 || cy > y1 : cx < x0 || cx > x1) return 0; /* a route's cell outside the nodes' range */
  double here = along_x ? ry[g->gy[w] - y0] : rx[g->gx[w] - x0];
  double there = along_x ? ry[cy - y0] : rx[cx - x0]; /* the range covers every node's cell */
  double half = along_x ? g->rh[w] / 2 : g->rw[w] / 2;
  return out + half <= fabs(there - here) / 2;
}

/* A one-port on a diagonal cell of its hub (the hub's four sides taken, as
 * at a grid's inner junction or a species of many reactions) drew its bond
 * from centre to centre at whatever angle the column and row sizes gave
 * (27 degrees in the RC grid). Books draw that bond at 45 degrees: the
 * one-port moves along the longer axis towards its hub until the line
 * between their centres is diagonal, if its label then stays clear of the
 * hub's bonds along that axis (a causal stroke's half length and a gap)
 * and the bond stays at least 2.5 half arrows long (its own cell held
 * nothing else; the cell it moves towards may hold a bond's run). Where
 * that cell holds a label (the I above a mass's junction, its R on the
 * diagonal: 25 degrees), the one-port stops an em short of it and moves
 * out along the shorter axis by as much (diagonal_offset). */
static void diagonal_leaves(grid *g) {
  bg_diagram_layout *d = g->d;
  if (layer_band(g) > 0) return; /* path and loop lines beside every bond: the longer slant keeps their room */
  /* whether a one-port moves is decided in the reference style (its boxes,
   * gaps and line width), as the cells were: decided in each style's own
   * sizes, one moved in print and its neighbour in the next band did not,
   * and their order changed with the style (a large forest's columns) */
  int x0, x1, y0, y1;
  range(g, g->gx, &x0, &x1);
  range(g, g->gy, &y0, &y1);
  double xgap, ygap, lw = g->ref->line_width, clear = 4.5 * lw + 3, least = 2.5 * 7 * lw + 3;
  style_gaps(g->ref, 0, &xgap, &ygap);
  double *rx = compactable(g) ? compact_columns(g, g->rw, x0, x1, xgap) : line_centres(g, g->gx, g->rw, x0, x1, xgap);
  double *ry = line_centres(g, g->gy, g->rh, y0, y1, ygap);
  for (int e = 0; e < g->ne && e < d->m->nbond; e++) {
    int v = g->et[e], w = g->eh[e];
    if (!g->hub[v]) v = g->eh[e], w = g->et[e];
    if (!g->hub[v] || g->hub[w] || g->deg[w] != 1 || g->bent[e] > 0 || !own_node(d, w) || g->signalled[w]) continue;
    if (abs(g->gx[w] - g->gx[v]) != 1 || abs(g->gy[w] - g->gy[v]) != 1) continue;
    int q = 2 * (g->gy[w] > g->gy[v]) + (g->gx[w] > g->gx[v]);
    if (barb_quadrants(g, v) & (1 << q)) continue; /* nearer the barb, its stroke would touch it */
    double ax = fabs(rx[g->gx[w] - x0] - rx[g->gx[v] - x0]), ay = fabs(ry[g->gy[w] - y0] - ry[g->gy[v] - y0]);
    int along_x = ax > ay, tx = along_x ? g->gx[v] : g->gx[w], ty = along_x ? g->gy[w] : g->gy[v];
    /* the cell it moves towards (beside the hub) holds a bond's run in a
     * grid; a label there (series_conductances' R : Ra above its junction)
     * is kept an em off (k: its node, -1 none) */
    int k = g->val[cell_slot(g, cell_key(tx, ty))];
    if (k < 0) k = -1;
    else if (!own_node(d, k)) continue;
    double along = fmax(ax, ay), across = fmin(ax, ay);
    double t = diagonal_offset(g->rw, g->rh, k, w, along_x, across, g->ref->font_size); /* both offsets */
    if (t > along || (t > across && !room_outward(g, v, w, along_x, t - across, rx, x0, x1, ry, y0, y1))) continue;
    double half_along = along_x ? g->rw[w] / 2 : g->rh[w] / 2;
    /* the bond enters the label's box at its nearer edge; the junction's end
     * circle at 45 degrees is about 7.3 line widths (diagram_geom.c) */
    double body = (t - fmin(g->rw[w], g->rh[w]) / 2) / BG_SQRT1_2 - 7.5 * lw;
    if (t - half_along < clear || body < least) continue;
    /* the diagonal bond passes the label's corner */
    if (k >= 0 && (across - (g->rw[k] + g->rh[k]) / 2) * BG_SQRT1_2 < clear) continue;
    double dx = d->nx[w] - d->nx[v], dy = d->ny[w] - d->ny[v], on = along_x ? fabs(dx) : fabs(dy);
    double own = diagonal_offset(d->nw, d->nh, k, w, along_x, along_x ? fabs(dy) : fabs(dx), d->st.font_size);
    if (on <= own) continue; /* this style's cell is no longer along that axis */
    d->nx[w] = d->nx[v] + (dx > 0 ? own : -own);
    d->ny[w] = d->ny[v] + (dy > 0 ? own : -own);
  }
  free(rx), free(ry);
}

/* ---------------------------------------------------------------- ranks without dot */
/* Whether the layout graph (the grid pass's edges) is a forest: no cycle,
 * no two edges between the same nodes. */
static int is_forest(const grid *g) {
  int *up = bg_xcalloc((size_t)g->n + 1, sizeof(int)), forest = 1;
  for (int v = 0; v < g->n; v++) up[v] = v;
  for (int e = 0; e < g->ne && forest; e++) {
    if (g->et[e] == g->eh[e]) continue; /* inside a box */
    int a = find(up, g->et[e]), b = find(up, g->eh[e]);
    if (a == b) forest = 0;
    else up[a] = b;
  }
  free(up);
  return forest;
}

/* The grid pass's graph of d alone (bg_grid_is_forest, bg_grid_tree_ranks). */
static void graph_only(grid *g, bg_diagram_layout *d) {
  memset(g, 0, sizeof *g);
  g->d = d, g->n = d->nnode;
  build_edges(g);
}

static void graph_free(grid *g) { free(g->et), free(g->eh), free(g->adr), free(g->adj), free(g->deg); }

int bg_grid_is_forest(bg_diagram_layout *d) {
  grid g;
  graph_only(&g, d);
  int forest = is_forest(&g);
  graph_free(&g);
  return forest;
}

void bg_grid_tree_ranks(bg_diagram_layout *d, const unsigned char *root) {
  grid g;
  graph_only(&g, d);
  /* the breadth-first depth over this graph (a field one node, as the grid
   * pass sees it: over the layout's edges a field's ports are apart, and a
   * chain through fields broke into parts whose ranks each started again),
   * from the roots, then from the first node of a part without one */
  int *depth = bg_xcalloc((size_t)g.n + 1, sizeof(int)), *queue = bg_xcalloc((size_t)g.n + 1, sizeof(int));
  int qh = 0, qt = 0;
  for (int v = 0; v < g.n; v++) depth[v] = -1;
  for (int v = 0; v < g.n; v++)
    if (root[v] && depth[drawn_by(d, v)] < 0) depth[drawn_by(d, v)] = 0, queue[qt++] = drawn_by(d, v);
  for (int s = 0; s <= g.n; s++) {
    for (; qh < qt; qh++)
      for (int k = g.adr[queue[qh]]; k < g.adr[queue[qh] + 1]; k++) {
        int w = other(&g, g.adj[k], queue[qh]);
        if (depth[w] < 0) depth[w] = depth[queue[qh]] + 1, queue[qt++] = w;
      }
    if (s < g.n && depth[s] < 0 && own_node(d, s)) depth[s] = 0, queue[qt++] = s;
  }
  /* hubs in depth-first order from each root (depth 0), so a subtree's
   * hubs are consecutive and siblings keep the order of their bonds;
   * one-ports level with their hub, one rank on */
  int *stack = queue, *seen = bg_xcalloc((size_t)g.n + 1, sizeof(int)), next = 0;
  for (int s = 0; s < g.n; s++) {
    if (seen[s] || depth[s] != 0) continue;
    int top = 0;
    stack[top++] = s, seen[s] = 1; /* each node pushed once: n at most */
    while (top > 0) {
      int v = stack[--top];
      d->nx[v] = depth[v], d->ny[v] = next++;
      for (int k = g.adr[v + 1] - 1; k >= g.adr[v]; k--) { /* pushed last first: popped in bond order */
        int w = other(&g, g.adj[k], v);
        if (!seen[w]) seen[w] = 1, stack[top++] = w;
      }
    }
  }
  for (int v = 0; v < g.n; v++) /* nodes inside a box or a field: drawn by it */
    if (!seen[v]) d->nx[v] = d->nx[drawn_by(d, v)], d->ny[v] = d->ny[drawn_by(d, v)];
  for (int v = 0; v < g.n; v++) /* a one-port beside its hub */
    if (g.deg[v] == 1) {
      int u = other(&g, g.adj[g.adr[v]], v);
      if (g.deg[u] > 1) d->ny[v] = d->ny[u];
    }
  free(depth), free(queue), free(seen);
  graph_free(&g);
}

/* ---------------------------------------------------------------- the pass */
static void grid_alloc(grid *g, bg_diagram_layout *d) {
  memset(g, 0, sizeof *g);
  g->d = d, g->n = d->nnode;
  build_edges(g);
  size_t n = (size_t)g->n + 1;
  g->gx = bg_xcalloc(n, sizeof(int)), g->gy = bg_xcalloc(n, sizeof(int));
  g->col = bg_xcalloc(n, sizeof(int)), g->row = bg_xcalloc(n, sizeof(int)), g->band = bg_xcalloc(n, sizeof(int));
  g->placed = bg_xcalloc(n, 1), g->hub = bg_xcalloc(n, 1), g->sides = bg_xcalloc(n, 1), g->mesh = bg_xcalloc(n, 1);
  g->spine = bg_xcalloc(n, 1);
  g->bent = bg_xcalloc((size_t)g->ne + 1, sizeof(int));
  g->corner = bg_xcalloc((size_t)g->ne + 1, sizeof *g->corner);
  cell_grow(g);
}

static void grid_free(grid *g) {
  free(g->et), free(g->eh), free(g->adr), free(g->adj), free(g->deg);
  free(g->gx), free(g->gy), free(g->col), free(g->row), free(g->band);
  free(g->placed), free(g->hub), free(g->sides), free(g->mesh), free(g->bent), free(g->corner);
  free(g->tree_par), free(g->spine);
  free(g->key), free(g->val), free(g->inst_cx), free(g->inst_cy), free(g->signalled);
  free(g->orbit), free(g->ring_x), free(g->ring_y), free(g->ring_w), free(g->ring_h), free(g->turned);
  free(g->first_end), free(g->up), free(g->cyclic), free(g->sadr), free(g->slist);
}

void bg_grid_place(bg_diagram_layout *d, const bg_style *ref, const double *rw, const double *rh, int own_ranks) {
  if (d->nnode == 0) return; /* an empty model: nothing to place, and no line range */
  grid g;
  grid_alloc(&g, d);
  g.ref = ref, g.rw = rw, g.rh = rh, g.own_ranks = own_ranks;
  classify(&g);
  find_parts(&g);
  state_signals(&g);
  g.signalled = bg_signal_end_nodes(d);
  for (int v = 0; v < g.n; v++) g.placed[v] = !own_node(d, v); /* inside a box, a field's other port */
  int nh, *h = order_hubs(&g, &nh);
  assign_rows(&g, h, nh);
  mesh_rows(&g, h, nh);
  stack_components(&g, h, nh);
  route_hub_bonds(&g);
  straighten_branches(&g);
  maze_hub_bonds(&g);
  place_leaves(&g);
  place_floats(&g);
  record_bands(&g);
  to_points(&g);
  diagonal_leaves(&g);
  free(h);
  grid_free(&g);
}
