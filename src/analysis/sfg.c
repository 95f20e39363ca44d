/* SPDX-License-Identifier: BSD-3-Clause */
/* Signal flow graph: construction from the strokes, gains of edge chains,
 * algebraic cycles (Johnson) and algebraic blocks (Tarjan). All graph
 * searches use explicit stacks: model size never grows the C stack. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "analysis/paths_int.h"
#include "analysis/sfg_int.h"
#include "base/scc.h"
#include "base/strbuf.h"

#define E_(b) BG_SIG_EFFORT(b)
#define F_(b) BG_SIG_FLOW(b)

/* ------------------------------------------------------------ the operating point */
typedef struct opctx {
  bg_xenv env;
  double *effort, *flow, *store, *state;
} opctx;

static void op_init(const bg_model *m, opctx *c) {
  c->effort = bg_xcalloc((size_t)m->nbond + 1, sizeof(double));
  c->flow = bg_xcalloc((size_t)m->nbond + 1, sizeof(double));
  c->store = bg_xcalloc((size_t)m->nelem + 1, sizeof(double));
  c->state = bg_xcalloc((size_t)m->nstate + 1, sizeof(double));
  c->env = (bg_xenv){m->sim.present ? m->sim.t0 : 0.0, NULL, c->state,
                     c->effort, c->flow, c->store};
  /* initial values may use params and t only; evaluate them at zero states */
  for (int e = 0; e < m->nelem; e++)
    if (m->elem_init && m->elem_init[e] >= 0) c->store[e] = bg_xeval(m, m->elem_init[e], &c->env);
  for (int s = 0; s < m->nstate; s++)
    if (m->state_init && m->state_init[s] >= 0) c->state[s] = bg_xeval(m, m->state_init[s], &c->env);
}

static void op_free(opctx *c) { free(c->effort); free(c->flow); free(c->store); free(c->state); }

static double *op_var(opctx *c, int op, int ref) {
  switch (op) {
  case BG_X_EFFORT: return &c->effort[ref];
  case BG_X_FLOW: return &c->flow[ref];
  case BG_X_STORE: return &c->store[ref];
  default: return &c->state[ref];
  }
}

/* d root / d var at the operating point, by a central difference: laws are
 * arbitrary expressions, and a numeric slope is all a linearisation needs. */
static double op_slope(const bg_model *m, int root, opctx *c, int op, int ref) {
  double *x = op_var(c, op, ref), x0 = *x, h = 1e-6 * fmax(1.0, fabs(x0));
  *x = x0 + h;
  double fp = bg_xeval(m, root, &c->env);
  *x = x0 - h;
  double fm = bg_xeval(m, root, &c->env);
  *x = x0;
  return (fp - fm) / (2 * h);
}

/* Is root linear in the variable near the operating point? Its slope must
 * be the same there and a finite step either side (a second difference at
 * one point would call odd functions like tanh linear at 0). */
static int op_linear(const bg_model *m, int root, opctx *c, int op, int ref) {
  double *x = op_var(c, op, ref), x0 = *x, H = 0.1 * fmax(1.0, fabs(x0));
  double s0 = op_slope(m, root, c, op, ref);
  *x = x0 + H;
  double sp = op_slope(m, root, c, op, ref);
  *x = x0 - H;
  double sm = op_slope(m, root, c, op, ref);
  *x = x0;
  double tol = 1e-6 * (fabs(s0) + fabs(sp) + fabs(sm)) + 1e-300;
  return fabs(sp - s0) <= tol && fabs(sm - s0) <= tol;
}

/* ------------------------------------------------------------ building */
typedef struct builder {
  const bg_model *m;
  const bg_analysis *a;
  bg_sfg *g;
  opctx op;
  int cap;
} builder;

static bg_sfg_edge *add_edge(builder *B, int src, int dst, int kind, int elem, double v) {
  bg_sfg *g = B->g;
  if (g->nedge == B->cap) {
    B->cap = B->cap ? 2 * B->cap : 256;
    g->edge = bg_xrealloc(g->edge, (size_t)B->cap * sizeof *g->edge);
  }
  bg_sfg_edge *e = &g->edge[g->nedge++];
  *e = (bg_sfg_edge){src, dst, kind, elem, 0, v, v < 0 ? -1 : 1, {NULL, NULL}, {NULL, NULL}, 1};
  return e;
}

/* Text of an expression, parenthesised when it is not a single operand, so
 * it can stand as a factor of a product. */
static const char *factor_text(builder *B, int root) {
  bg_strbuf sb = {0};
  bg_xprint(B->m, root, &sb);
  const char *t = bg_sb_str(&sb);
  int depth = 0, compound = t[0] == '-';
  for (const char *p = t; *p; p++) {
    if (*p == '(') depth++;
    else if (*p == ')') depth--;
    else if (depth == 0 && strchr(" */^", *p)) compound = 1;
  }
  char *r;
  if (compound) {
    size_t n = strlen(t);
    r = bg_arena_alloc(&B->g->arena, n + 3);
    r[0] = '(';
    memcpy(r + 1, t, n);
    r[n + 1] = ')';
  } else {
    r = bg_arena_strdup(&B->g->arena, t);
  }
  bg_sb_free(&sb);
  return r;
}

/* The symbol of an element's parameter in gains: its expression when that
 * is short and constant (n, R0, 1/A), else the element's name (a modulated
 * MTF T stands for its modulus T(phi)). */
static const char *param_text(builder *B, int e) {
  const bg_model *m = B->m;
  const char *t = factor_text(B, m->elem_expr[e]);
  int k = m->elem_kind[e];
  if (strlen(t) > 16 || k == BG_ELEM_MTF || k == BG_ELEM_MGY || (m->elem_modulated && m->elem_modulated[e]))
    return m->elem_name[e];
  return t;
}

static const char *slope_name(builder *B, int elem) {
  const char *n = B->m->elem_name[elem];
  size_t k = strlen(n);
  char *r = bg_arena_alloc(&B->g->arena, k + 2);
  memcpy(r, n, k);
  r[k] = '\'';
  return r;
}

static int sigma(const bg_model *m, int b, int e) { return m->bond_head[b] == e ? 1 : -1; }

/* 0-junction: the strong bond's effort goes to every other bond; its flow
 * is the signed sum of the others' (sum of sigma*f = 0, sigma = +1 for a
 * bond pointing in). A 1-junction is the dual. */
static void junction_edges(builder *B, int e) {
  const bg_model *m = B->m;
  int j0 = m->elem_kind[e] == BG_ELEM_J0, strong = -1, nstrong = 0;
  const int *bs = m->elem_bonds + m->elem_bondadr[e];
  for (int i = 0; i < m->elem_nbond[e]; i++) {
    if (B->a->bond_stroke[bs[i]] == BG_STROKE_NONE) return;
    if (bg_paths_effort_in(m, B->a, e, bs[i]) == j0) { strong = bs[i]; nstrong++; }
  }
  if (nstrong != 1) return; /* a causal conflict: no consistent reading */
  for (int i = 0; i < m->elem_nbond[e]; i++) {
    int w = bs[i], sg = -sigma(m, strong, e) * sigma(m, w, e);
    if (w == strong) continue;
    if (j0) {
      add_edge(B, E_(strong), E_(w), BG_SFGE_JUNCTION, e, 1);
      add_edge(B, F_(w), F_(strong), BG_SFGE_JUNCTION, e, sg);
    } else {
      add_edge(B, F_(strong), F_(w), BG_SFGE_JUNCTION, e, 1);
      add_edge(B, E_(w), E_(strong), BG_SFGE_JUNCTION, e, sg);
    }
  }
}

static void twoport_bonds(const bg_model *m, int e, int *in, int *out) {
  const int *bs = m->elem_bonds + m->elem_bondadr[e];
  *in = m->bond_head[bs[0]] == e ? bs[0] : bs[1];
  *out = *in == bs[0] ? bs[1] : bs[0];
}

/* An edge with one symbolic factor, over (inv = 0) or under the line. */
static void add_factor_edge(builder *B, int src, int dst, int kind, int e, double v,
                            const char *f, int inv) {
  bg_sfg_edge *x = add_edge(B, src, dst, kind, e, inv ? 1.0 / v : v);
  if (inv) x->den[0] = f;
  else x->num[0] = f;
  x->sign = 1;
}

/* a -> TF -> b: e_b = n e_a, f_a = n f_b. GY: e_a = r f_b, e_b = r f_a. */
static void twoport_edges(builder *B, int e) {
  const bg_model *m = B->m;
  int a, b;
  if (m->elem_nbond[e] != 2 || m->elem_expr[e] < 0) return;
  twoport_bonds(m, e, &a, &b);
  if (B->a->bond_stroke[a] == BG_STROKE_NONE || B->a->bond_stroke[b] == BG_STROKE_NONE) return;
  double n = bg_xeval(m, m->elem_expr[e], &B->op.env);
  B->g->ratio[e] = n;
  const char *t = param_text(B, e);
  int ia = bg_paths_effort_in(m, B->a, e, a), ib = bg_paths_effort_in(m, B->a, e, b);
  int k = m->elem_kind[e];
  if (k == BG_ELEM_TF || k == BG_ELEM_MTF) {
    if (ia == ib) return;
    add_factor_edge(B, ia ? E_(a) : E_(b), ia ? E_(b) : E_(a), BG_SFGE_TF, e, n, t, !ia);
    add_factor_edge(B, ia ? F_(b) : F_(a), ia ? F_(a) : F_(b), BG_SFGE_TF, e, n, t, !ia);
  } else {
    if (ia != ib) return;
    add_factor_edge(B, ia ? E_(a) : F_(b), ia ? F_(b) : E_(a), BG_SFGE_GY, e, n, t, ia);
    add_factor_edge(B, ia ? E_(b) : F_(a), ia ? F_(a) : E_(b), BG_SFGE_GY, e, n, t, ia);
  }
}

/* R: value form e = R f; laws e = F(f) or f = G(e), linearised. */
static void r_edges(builder *B, int e, int b) {
  const bg_model *m = B->m;
  int cond = bg_paths_effort_in(m, B->a, e, b), src = cond ? E_(b) : F_(b);
  int dst = cond ? F_(b) : E_(b), form = m->elem_form[e], root = m->elem_expr[e];
  if (root < 0) return;
  if (form == BG_FORM_VALUE) {
    double r = bg_xeval(m, root, &B->op.env);
    add_factor_edge(B, src, dst, BG_SFGE_R, e, r, param_text(B, e), cond);
    return;
  }
  /* slope of the law in its own argument; inverted when causality is the other one */
  int lawe = form == BG_FORM_LAW_E, op = lawe ? BG_X_FLOW : BG_X_EFFORT;
  double d = op_slope(m, root, &B->op, op, b);
  /* an e-law reads the element's own flow, the bond's negated when the bond
   * points out: its slope in the bond's flow is then -F', and the edge is F' */
  if (lawe && m->bond_head[b] != e) d = -d;
  add_factor_edge(B, src, dst, BG_SFGE_R, e, d, slope_name(B, e), lawe == cond);
  B->g->edge[B->g->nedge - 1].linear = op_linear(m, root, &B->op, op, b);
}

/* C (e = q/C or e = F(q)) and I (f = p/I or f = F(p)): integrators in
 * integral causality, differentiators in derivative causality. */
static void store_edges(builder *B, int e, int b) {
  const bg_model *m = B->m;
  int isc = m->elem_kind[e] == BG_ELEM_C, root = m->elem_expr[e];
  int integ = bg_paths_store_integral(m, B->a, e);
  int in = isc ? F_(b) : E_(b), out = isc ? E_(b) : F_(b);
  if (root < 0) return;
  int value = m->elem_form[e] == BG_FORM_VALUE;
  double k = value ? bg_xeval(m, root, &B->op.env) : op_slope(m, root, &B->op, BG_X_STORE, e);
  const char *t = value ? param_text(B, e) : slope_name(B, e);
  /* value form: the parameter divides (1/(C s), C s); law form: the slope
   * multiplies in integral causality (F'(q)/s) and divides in derivative */
  int k_under = value == integ;
  bg_sfg_edge *x = add_edge(B, integ ? in : out, integ ? out : in, BG_SFGE_STORE, e,
                            k_under ? 1.0 / k : k);
  x->sign = 1;
  x->order = integ ? 1 : -1;
  const char **kside = k_under ? x->den : x->num, **sside = integ ? x->den : x->num;
  kside[0] = t;
  sside[kside == sside ? 1 : 0] = "s";
}

/* ------------------------------------------------------------ modulation */
/* The signal node a variable reference reads, or -1. Store states stand at
 * the store's effort (C) or flow (I): a function of q or p at any instant. */
static int var_node(const bg_model *m, int op, int ref) {
  switch (op) {
  case BG_X_EFFORT: return E_(ref);
  case BG_X_FLOW: return F_(ref);
  case BG_X_STATE: return 2 * m->nbond + ref;
  case BG_X_STORE: {
    int b = m->elem_bonds[m->elem_bondadr[ref]];
    return m->elem_kind[ref] == BG_ELEM_C ? E_(b) : F_(b);
  }
  default: return -1;
  }
}

/* A store in derivative causality: its state is the inverse of its law at
 * its input, q = F^-1(e) (C; I likewise), so a read of the state depends on
 * the input by dq/de = 1/F'(q) (C for a value form e = q/C): *scale, with
 * the symbol over (value form) or under (law: the slope) the line. The
 * state's dependence on the law's other variables (a field's sibling ports)
 * goes through their integrators, not algebraically. */
static void store_state_scale(builder *B, int st, double *scale, const char **factor) {
  const bg_model *m = B->m;
  int root = m->elem_expr[st];
  if (root < 0) return;
  if (m->elem_form[st] == BG_FORM_VALUE) {
    *scale = bg_xeval(m, root, &B->op.env);
    *factor = param_text(B, st);
  } else {
    double d = op_slope(m, root, &B->op, BG_X_STORE, st);
    *scale = d != 0 ? 1.0 / d : 1;
    *factor = slope_name(B, st);
  }
}

/* Where a modulating reference enters the graph, and through how many
 * integrators: a store's state in integral causality is the output of its
 * integrator, not its effort or flow (C1's law reading C2.q does not read
 * C2.e = F(C2.q, ...), which may read C1.q in turn: two such laws closed an
 * "algebraic loop" the equations do not have). It enters from the
 * integrator's input with order 1. Everything else as var_node. */
static int var_source(builder *B, const bg_xnode *x, int *order, double *scale,
                      const char **factor) {
  const bg_model *m = B->m;
  *order = 0;
  *scale = 1;
  *factor = NULL;
  if (x->op == BG_X_STORE && bg_paths_store_integral(m, B->a, x->ref)) {
    int b = m->elem_bonds[m->elem_bondadr[x->ref]];
    *order = 1;
    return m->elem_kind[x->ref] == BG_ELEM_C ? F_(b) : E_(b);
  }
  if (x->op == BG_X_STORE) store_state_scale(B, x->ref, scale, factor);
  return var_node(m, x->op, x->ref);
}

static int is_var(int op) {
  return op == BG_X_EFFORT || op == BG_X_FLOW || op == BG_X_STATE || op == BG_X_STORE;
}

/* Distinct variable references (xnode ids) under root: an explicit stack
 * over the tree (children have smaller ids than their parent). */
static int collect_vars(const bg_model *m, int root, int *out, int cap) {
  int n = 0, sp = 0, scap = 32, *st = bg_xmalloc(sizeof(int) * (size_t)scap);
  st[sp++] = root;
  while (sp > 0) {
    const bg_xnode *x = &m->xnode[st[--sp]];
    if (is_var(x->op)) {
      int dup = 0;
      for (int i = 0; i < n && !dup; i++)
        dup = m->xnode[out[i]].op == x->op && m->xnode[out[i]].ref == x->ref;
      if (!dup && n < cap) out[n++] = (int)(x - m->xnode);
    }
    for (int i = 0; i < x->nargs; i++) {
      if (sp == scap) st = bg_xrealloc(st, sizeof(int) * (size_t)(scap *= 2));
      st[sp++] = x->arg[i];
    }
  }
  free(st);
  return n;
}

static int mentions(const bg_model *m, int root, int var) {
  int vs[64], n = collect_vars(m, root, vs, 64);
  for (int i = 0; i < n; i++)
    if (m->xnode[vs[i]].op == m->xnode[var].op && m->xnode[vs[i]].ref == m->xnode[var].ref)
      return 1;
  return 0;
}

/* Symbolic factor of d root / d var where the expression is plainly linear
 * in it (var, c*var, var*c, var/c); otherwise a named partial derivative. */
static void mod_label(builder *B, bg_sfg_edge *x, int root, int var, const char *who) {
  const bg_model *m = B->m;
  const bg_xnode *r = &m->xnode[root];
  x->sign = 1;
  if (root == var) return;
  if (r->op == BG_X_MUL && r->arg[1] == var && !mentions(m, r->arg[0], var)) {
    x->num[0] = factor_text(B, r->arg[0]);
  } else if (r->op == BG_X_MUL && r->arg[0] == var && !mentions(m, r->arg[1], var)) {
    x->num[0] = factor_text(B, r->arg[1]);
  } else if (r->op == BG_X_DIV && r->arg[0] == var && !mentions(m, r->arg[1], var)) {
    x->den[0] = factor_text(B, r->arg[1]);
  } else {
    char nm[96], buf[224];
    const bg_xnode *v = &m->xnode[var];
    if (v->op == BG_X_STORE)
      snprintf(nm, sizeof nm, "%s.%c", m->elem_name[v->ref], m->elem_kind[v->ref] == BG_ELEM_C ? 'q' : 'p');
    else bg_sfg_node_name(m, var_node(m, v->op, v->ref), nm, sizeof nm);
    snprintf(buf, sizeof buf, "d%s/d%s", who, nm);
    x->num[0] = bg_arena_strdup(&B->g->arena, buf);
  }
}

static int own_var(const bg_model *m, int e, const bg_xnode *x) {
  if (!(m->elem_kind[e] == BG_ELEM_R || m->elem_kind[e] == BG_ELEM_C || m->elem_kind[e] == BG_ELEM_I))
    return 0; /* sources and two-ports have no own argument: all is modulation */
  int b = m->elem_bonds[m->elem_bondadr[e]];
  if (x->op == BG_X_STORE) return x->ref == e;
  return (x->op == BG_X_EFFORT || x->op == BG_X_FLOW) && x->ref == b;
}

/* How a modulating variable's slope d of an R law reaches the R's output:
 * an explicit e-law gives e (d); an explicit f-law gives the own flow, the
 * bond's times sigma (sigma d); an inverted law y = F(x, m) is solved for its
 * own variable x: -d / F_x (a field port in the causality its law does not
 * have, reading its sibling ports: the implicit equation's sensitivity).
 * Sets *inv when the law is inverted (the slope then stands under the line). */
static double r_mod_gain(builder *B, int e, int b, double d, int *inv) {
  const bg_model *m = B->m;
  int form = m->elem_form[e], lawe = form == BG_FORM_LAW_E;
  *inv = 0;
  if (m->elem_kind[e] != BG_ELEM_R || form == BG_FORM_VALUE) return d;
  int cond = bg_paths_effort_in(m, B->a, e, b);
  if (lawe != cond) return lawe || m->bond_head[b] == e ? d : -d;
  double dx = op_slope(m, m->elem_expr[e], &B->op, lawe ? BG_X_FLOW : BG_X_EFFORT, b);
  *inv = 1;
  return dx != 0 ? -d / dx : d;
}

/* A C or I with a law in derivative causality. */
static int deriv_law_store(const bg_model *m, const bg_analysis *a, int e) {
  return bg_elem_is_store(m->elem_kind[e]) && m->elem_form[e] != BG_FORM_VALUE &&
         !bg_paths_store_integral(m, a, e);
}

/* One modulation edge from a read variable into e's output on bond b. */
static void mod_edge(builder *B, int e, int b, int var) {
  const bg_model *m = B->m;
  const bg_xnode *x = &m->xnode[var];
  int root = m->elem_expr[e], order, inv;
  double scale;
  const char *factor;
  int u = var_source(B, x, &order, &scale, &factor);
  double d = op_slope(m, root, &B->op, x->op, x->ref);
  int out = bg_paths_effort_in(m, B->a, e, b) ? F_(b) : E_(b);
  if (deriv_law_store(m, B->a, e)) { /* q = F^-1(e, m): the rate reads m' */
    double fq = op_slope(m, root, &B->op, BG_X_STORE, e);
    bg_sfg_edge *y = add_edge(B, u, out, BG_SFGE_MOD, e, (fq != 0 ? -d / fq : d) * scale);
    mod_label(B, y, root, var, m->elem_name[e]);
    y->linear = op_linear(m, root, &B->op, x->op, x->ref);
    y->sign = -1;
    y->den[y->den[0] ? 1 : 0] = slope_name(B, e);
    y->order = order - 1;
    if (!order) y->num[y->num[0] ? 1 : 0] = "s";
    return;
  }
  double g = r_mod_gain(B, e, b, d, &inv);
  bg_sfg_edge *y = add_edge(B, u, out, BG_SFGE_MOD, e, g * scale);
  mod_label(B, y, root, var, m->elem_name[e]);
  y->linear = op_linear(m, root, &B->op, x->op, x->ref);
  if (!inv && d != 0 && g == -d) y->sign = -1;
  if (inv) y->den[y->den[0] ? 1 : 0] = slope_name(B, e), y->sign = -1;
  if (factor && !y->num[1]) (m->elem_form[x->ref] == BG_FORM_VALUE ? y->num : y->den)[1] = factor;
  if (order) y->order = order, y->den[y->den[0] ? 1 : 0] = "s";
}

/* Edges from each modulating variable of element e into its outputs. */
static void mod_edges(builder *B, int e) {
  const bg_model *m = B->m;
  int root = m->elem_expr[e], vs[64];
  if (root < 0) return;
  int nv = collect_vars(m, root, vs, 64);
  for (int i = 0; i < nv; i++) {
    if (own_var(m, e, &m->xnode[vs[i]])) continue;
    for (int k = 0; k < m->elem_nbond[e]; k++) {
      int b = m->elem_bonds[m->elem_bondadr[e] + k];
      if (B->a->bond_stroke[b] != BG_STROKE_NONE) mod_edge(B, e, b, vs[i]);
    }
  }
}

/* d s/dt = expr: integrator edges from what the right-hand side reads. */
static void state_edges(builder *B, int s) {
  const bg_model *m = B->m;
  int root = m->state_expr[s], vs[64];
  if (root < 0) return;
  int nv = collect_vars(m, root, vs, 64);
  for (int i = 0; i < nv; i++) {
    const bg_xnode *x = &m->xnode[vs[i]];
    double d = op_slope(m, root, &B->op, x->op, x->ref), scale;
    const char *factor;
    int order, u = var_source(B, x, &order, &scale, &factor);
    bg_sfg_edge *y = add_edge(B, u, 2 * m->nbond + s, BG_SFGE_STATE, -1, d * scale);
    mod_label(B, y, root, vs[i], m->state_name[s]);
    y->den[1] = "s";
    y->order = 1 + order;
  }
}

static void element_edges(builder *B, int e) {
  const bg_model *m = B->m;
  int k = m->elem_kind[e], b = m->elem_nbond[e] > 0 ? m->elem_bonds[m->elem_bondadr[e]] : -1;
  if (k == BG_ELEM_J0 || k == BG_ELEM_J1) junction_edges(B, e);
  else if (bg_paths_is_js(k)) twoport_edges(B, e);
  else if (b >= 0 && B->a->bond_stroke[b] != BG_STROKE_NONE) {
    if (k == BG_ELEM_R) r_edges(B, e, b);
    else if (k == BG_ELEM_C || k == BG_ELEM_I) store_edges(B, e, b);
  }
  if (m->elem_expr && m->elem_expr[e] >= 0) mod_edges(B, e);
}

/* Out-edge lists in insertion order (a counting sort by source). */
static void build_csr(bg_sfg *g) {
  g->adr = bg_arena_alloc(&g->arena, sizeof(int) * (size_t)(g->nnode + 1));
  g->n = bg_arena_alloc(&g->arena, sizeof(int) * (size_t)(g->nnode + 1));
  g->out = bg_arena_alloc(&g->arena, sizeof(int) * (size_t)(g->nedge + 1));
  for (int i = 0; i < g->nedge; i++) g->n[g->edge[i].src]++;
  for (int v = 1; v <= g->nnode; v++) g->adr[v] = g->adr[v - 1] + g->n[v - 1];
  int *fill = bg_xcalloc((size_t)g->nnode + 1, sizeof(int));
  for (int i = 0; i < g->nedge; i++) {
    int s = g->edge[i].src;
    g->out[g->adr[s] + fill[s]++] = i;
  }
  free(fill);
}

void bg_sfg_build(const bg_model *m, const bg_analysis *a, bg_sfg *g) {
  memset(g, 0, sizeof *g);
  g->nbondsig = 2 * m->nbond;
  g->nnode = g->nbondsig + m->nstate;
  builder B;
  memset(&B, 0, sizeof B);
  B.m = m;
  B.a = a;
  B.g = g;
  op_init(m, &B.op);
  g->ratio = bg_arena_alloc(&g->arena, sizeof *g->ratio * (size_t)(m->nelem + 1));
  memset(g->ratio, 0, sizeof *g->ratio * (size_t)(m->nelem + 1));
  for (int e = 0; e < m->nelem; e++) element_edges(&B, e);
  for (int s = 0; s < m->nstate; s++) state_edges(&B, s);
  op_free(&B.op);
  /* move the edges into the arena so that one free releases everything */
  bg_sfg_edge *tmp = g->edge;
  g->edge = bg_arena_alloc(&g->arena, sizeof *g->edge * (size_t)(g->nedge + 1));
  if (g->nedge) memcpy(g->edge, tmp, sizeof *g->edge * (size_t)g->nedge);
  free(tmp);
  build_csr(g);
}

void bg_sfg_free(bg_sfg *g) {
  bg_arena_free(&g->arena);
  memset(g, 0, sizeof *g);
}

int bg_sfg_find_edge(const bg_sfg *g, int src, int dst) {
  for (int i = 0; i < g->n[src]; i++)
    if (g->edge[g->out[g->adr[src] + i]].dst == dst) return g->out[g->adr[src] + i];
  return -1;
}

/* ------------------------------------------------------------ gains */
static void gain_push(const char ***arr, int *n, int *cap, const char *f) {
  if (!f) return;
  if (*n == *cap) {
    *cap = *cap ? 2 * *cap : 8;
    *arr = bg_xrealloc((void *)*arr, (size_t)*cap * sizeof **arr);
  }
  (*arr)[(*n)++] = f;
}

void bg_sfg_cycle_gain(const bg_sfg *g, const int *sig, int n, bg_gain *out) {
  memset(out, 0, sizeof *out);
  out->ok = n > 0;
  out->sign = 1;
  out->value = 1;
  out->mod_edge = -1;
  for (int i = 0; i < n && out->ok; i++) {
    int e = bg_sfg_find_edge(g, sig[i], sig[(i + 1) % n]);
    if (e < 0) { out->ok = 0; break; }
    const bg_sfg_edge *x = &g->edge[e];
    out->value *= x->value;
    out->sign *= x->sign;
    out->order += x->order;
    if (x->kind == BG_SFGE_MOD && out->mod_edge < 0) out->mod_edge = e;
    for (int k = 0; k < 2; k++) {
      gain_push(&out->num, &out->nnum, &out->cap_num, x->num[k]);
      gain_push(&out->den, &out->nden, &out->cap_den, x->den[k]);
    }
  }
}

/* "(1/A)" under the line is A over it (and the other way round). */
static const char *flip_inverse(const char *f, bg_arena *ar) {
  size_t n = strlen(f);
  if (n < 5 || strncmp(f, "(1/", 3) != 0 || f[n - 1] != ')') return NULL;
  for (size_t i = 3; i < n - 1; i++)
    if (strchr(" +-*/^()", f[i])) return NULL;
  return bg_arena_strndup(ar, f + 3, n - 4);
}

static void gain_flip(bg_gain *gn, bg_arena *ar) {
  int nn = gn->nnum, nd = gn->nden;
  for (int i = 0; i < nn; i++) {
    const char *x = gn->num[i] ? flip_inverse(gn->num[i], ar) : NULL;
    if (x) { gn->num[i] = NULL; gain_push(&gn->den, &gn->nden, &gn->cap_den, x); }
  }
  for (int i = 0; i < nd; i++) {
    const char *x = gn->den[i] ? flip_inverse(gn->den[i], ar) : NULL;
    if (x) { gn->den[i] = NULL; gain_push(&gn->num, &gn->nnum, &gn->cap_num, x); }
  }
}

/* Factors as a product, equal factors as powers, "s" last. */
static int put_factors(bg_strbuf *sb, const char **f, int n) {
  int k = 0;
  for (int pass = 0; pass < 2; pass++)
    for (int i = 0; i < n; i++) {
      if (!f[i] || (strcmp(f[i], "s") == 0) != pass) continue;
      int cnt = 1;
      for (int j = i + 1; j < n; j++)
        if (f[j] && strcmp(f[i], f[j]) == 0) { cnt++; f[j] = NULL; }
      if (k++) bg_sb_putc(sb, '*');
      bg_sb_puts(sb, f[i]);
      if (cnt > 1) bg_sb_printf(sb, "^%d", cnt);
      k += cnt > 1; /* a power counts as a product for parentheses */
    }
  return k;
}

char *bg_gain_text(bg_gain *gn, bg_arena *arena) {
  gain_flip(gn, arena);
  /* a factor over and under the line cancels (a TF passed both ways) */
  for (int i = 0; i < gn->nnum; i++)
    for (int j = 0; j < gn->nden && gn->num[i]; j++)
      if (gn->den[j] && strcmp(gn->num[i], gn->den[j]) == 0) gn->num[i] = gn->den[j] = NULL;
  bg_strbuf num = {0}, den = {0}, sb = {0};
  int kn = put_factors(&num, gn->num, gn->nnum), kd = put_factors(&den, gn->den, gn->nden);
  if (gn->sign < 0) bg_sb_putc(&sb, '-');
  bg_sb_puts(&sb, kn ? bg_sb_str(&num) : "1");
  if (kd) bg_sb_printf(&sb, kd > 1 ? "/(%s)" : "/%s", bg_sb_str(&den));
  char *r = bg_arena_strdup(arena, bg_sb_str(&sb));
  bg_sb_free(&num);
  bg_sb_free(&den);
  bg_sb_free(&sb);
  return r;
}

void bg_gain_free(bg_gain *gn) {
  free((void *)gn->num);
  free((void *)gn->den);
  gn->num = gn->den = NULL;
  gn->nnum = gn->nden = gn->cap_num = gn->cap_den = 0;
}

/* ------------------------------------------------------------ sub-graphs */
/* A node-to-node view of some of the edges, parallel edges merged. */
typedef struct dgraph { int nn, *adr, *n, *out; } dgraph;

static void dgraph_build(const bg_sfg *g, int skip_order, dgraph *d) {
  d->nn = g->nnode;
  d->adr = bg_xcalloc((size_t)g->nnode + 1, sizeof(int));
  d->n = bg_xcalloc((size_t)g->nnode + 1, sizeof(int));
  d->out = bg_xcalloc((size_t)g->nedge + 1, sizeof(int));
  /* per destination, the first edge from v to it (bg_sfg_find_edge's answer),
   * stamped by v: a node with 10^5 out-edges once searched its list per edge */
  int *stamp = bg_xmalloc((size_t)(g->nnode + 1) * sizeof(int)), *first = bg_xmalloc((size_t)(g->nnode + 1) * sizeof(int));
  for (int v = 0; v <= g->nnode; v++) stamp[v] = -1;
  int pos = 0;
  for (int v = 0; v < g->nnode; v++) {
    d->adr[v] = pos;
    for (int i = 0; i < g->n[v]; i++) {
      int e = g->out[g->adr[v] + i], dst = g->edge[e].dst;
      if (stamp[dst] != v) stamp[dst] = v, first[dst] = e;
    }
    for (int i = 0; i < g->n[v]; i++) {
      int e = g->out[g->adr[v] + i];
      const bg_sfg_edge *x = &g->edge[e];
      if (x->order == skip_order || (skip_order == 2 && x->order != 0)) continue;
      if (first[x->dst] != e) continue; /* parallel */
      d->out[pos++] = x->dst;
    }
    d->n[v] = pos - d->adr[v];
  }
  free(stamp), free(first);
}

static void dgraph_free(dgraph *d) { free(d->adr); free(d->n); free(d->out); }

/* Strongly connected components (base/scc.h); nontrivial[c] = 1 for a
 * component of more than one node or with a self-loop. Returns their count. */
static int tarjan(const dgraph *d, int *comp, char *nontrivial) {
  int *size = bg_xcalloc((size_t)d->nn + 1, sizeof(int)), nbig = 0;
  int nc = bg_scc(d->nn, d->adr, d->n, d->out, comp, NULL, NULL);
  for (int v = 0; v < d->nn; v++) size[comp[v]]++;
  for (int c = 0; c < nc; c++) nontrivial[c] = size[c] > 1;
  for (int v = 0; v < d->nn; v++)
    for (int i = 0; i < d->n[v]; i++) nontrivial[comp[v]] |= d->out[d->adr[v] + i] == v;
  for (int c = 0; c < nc; c++) nbig += nontrivial[c];
  free(size);
  return nbig;
}

int bg_sfg_algebraic_blocks(const bg_sfg *g, int *comp) {
  dgraph d;
  dgraph_build(g, 1, &d); /* integrator edges removed */
  int *c = comp ? comp : bg_xmalloc(sizeof(int) * (size_t)(g->nnode + 1));
  char *nt = bg_xcalloc((size_t)g->nnode + 1, 1);
  int n = tarjan(&d, c, nt);
  if (!comp) free(c);
  free(nt);
  dgraph_free(&d);
  return n;
}

/* ------------------------------------------------------------ Johnson */
typedef struct johnson {
  const dgraph *d;
  const int *comp;
  int s;          /* current start: only nodes >= s of comp[s] take part */
  char *blocked;
  int **bl, *bn, *bcap; /* B lists */
  int *fv, *fpos, *ufound, *ust;
  long work, budget;
} johnson;

static int j_allowed(const johnson *J, int w) { return w >= J->s && J->comp[w] == J->comp[J->s]; }

static void j_unblock(johnson *J, int u) {
  int sp = 0;
  J->blocked[u] = 0;
  J->ust[sp++] = u;
  while (sp > 0) {
    int x = J->ust[--sp];
    for (int i = 0; i < J->bn[x]; i++) {
      int y = J->bl[x][i];
      if (J->blocked[y]) { J->blocked[y] = 0; J->ust[sp++] = y; }
    }
    J->bn[x] = 0;
  }
}

static void j_block_on(johnson *J, int v) {
  for (int i = 0; i < J->d->n[v]; i++) {
    int w = J->d->out[J->d->adr[v] + i], dup = 0;
    if (!j_allowed(J, w)) continue;
    for (int k = 0; k < J->bn[w] && !dup; k++) dup = J->bl[w][k] == v;
    if (dup) continue;
    if (J->bn[w] == J->bcap[w]) {
      J->bcap[w] = J->bcap[w] ? 2 * J->bcap[w] : 4;
      J->bl[w] = bg_xrealloc(J->bl[w], sizeof(int) * (size_t)J->bcap[w]);
    }
    J->bl[w][J->bn[w]++] = v;
  }
}

/* The circuits through start s (Johnson's CIRCUIT, with explicit stacks).
 * Returns 1 to stop (callback or budget). */
static int j_circuits(johnson *J, bg_sfg_cycle_fn fn, void *ctx) {
  int fp = 0, s = J->s;
  J->blocked[s] = 1;
  J->fv[fp] = s; J->fpos[fp] = 0; J->ufound[fp++] = 0;
  while (fp > 0) {
    int v = J->fv[fp - 1];
    if (J->budget && ++J->work > J->budget) return 1;
    if (J->fpos[fp - 1] < J->d->n[v]) {
      int w = J->d->out[J->d->adr[v] + J->fpos[fp - 1]++];
      if (!j_allowed(J, w)) continue;
      if (w == s) {
        J->ufound[fp - 1] = 1;
        if (fn(ctx, J->fv, fp)) return 1;
      } else if (!J->blocked[w]) {
        J->blocked[w] = 1;
        J->fv[fp] = w; J->fpos[fp] = 0; J->ufound[fp++] = 0;
      }
      continue;
    }
    if (J->ufound[fp - 1]) j_unblock(J, v);
    else j_block_on(J, v);
    int f = J->ufound[--fp];
    if (fp > 0) J->ufound[fp - 1] |= f;
  }
  return 0;
}

int bg_sfg_algebraic_cycles(const bg_sfg *g, bg_sfg_cycle_fn fn, void *ctx, long budget) {
  dgraph d;
  dgraph_build(g, 2, &d); /* order-0 edges only */
  int nn = g->nnode, stop = 0;
  int *comp = bg_xmalloc(sizeof(int) * (size_t)(nn + 1));
  char *nt = bg_xcalloc((size_t)nn + 1, 1);
  johnson J = {&d, comp, 0, bg_xcalloc((size_t)nn + 1, 1), bg_xcalloc((size_t)nn + 1, sizeof(int *)),
               bg_xcalloc((size_t)nn + 1, sizeof(int)), bg_xcalloc((size_t)nn + 1, sizeof(int)),
               bg_xmalloc(sizeof(int) * (size_t)(nn + 1)), bg_xmalloc(sizeof(int) * (size_t)(nn + 1)),
               bg_xmalloc(sizeof(int) * (size_t)(nn + 1)), bg_xmalloc(sizeof(int) * (size_t)(nn + 1)),
               0, budget};
  if (tarjan(&d, comp, nt) > 0) {
    /* nodes of each component, increasing: a counting sort by component */
    int *cadr = bg_xcalloc((size_t)nn + 2, sizeof(int)), *list = bg_xmalloc(sizeof(int) * (size_t)(nn + 1));
    for (int v = 0; v < nn; v++) cadr[comp[v] + 1]++;
    for (int c = 0; c < nn; c++) cadr[c + 1] += cadr[c];
    int *fill = bg_xcalloc((size_t)nn + 1, sizeof(int));
    for (int v = 0; v < nn; v++) list[cadr[comp[v]] + fill[comp[v]]++] = v;
    for (int c = 0; c < nn && !stop; c++) {
      if (!nt[c]) continue;
      for (int i = cadr[c]; i < cadr[c + 1] && !stop; i++) {
        J.s = list[i];
        stop = j_circuits(&J, fn, ctx);
        for (int k = i; k < cadr[c + 1]; k++) { J.blocked[list[k]] = 0; J.bn[list[k]] = 0; }
      }
    }
    free(cadr); free(list); free(fill);
  }
  int over = J.budget && J.work > J.budget;
  for (int v = 0; v < nn; v++) free(J.bl[v]);
  free(J.bl); free(J.bn); free(J.bcap); free(J.blocked);
  free(J.fv); free(J.fpos); free(J.ufound); free(J.ust);
  free(comp); free(nt);
  dgraph_free(&d);
  return over;
}

/* ------------------------------------------------------------ names */
void bg_sfg_node_name(const bg_model *m, int node, char *buf, int size) {
  if (node >= 2 * m->nbond) {
    snprintf(buf, (size_t)size, "%s", m->state_name[node - 2 * m->nbond]);
    return;
  }
  int b = node / 2, h = m->bond_head[b], t = m->bond_tail[b];
  char v = node % 2 ? 'f' : 'e';
  int one = m->elem_kind[h] <= BG_ELEM_R ? h : m->elem_kind[t] <= BG_ELEM_R ? t : -1;
  if (one >= 0) snprintf(buf, (size_t)size, "%s.%c", m->elem_name[one], v);
  else snprintf(buf, (size_t)size, "%c%d", v, m->bond_num[b]);
}
