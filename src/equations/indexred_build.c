/* SPDX-License-Identifier: BSD-3-Clause */
/* The reduced system of the index reduction as a bg_eqsys: unknowns, rows,
 * the tape. Per original unknown j with variables (j, 0..h): when some
 * derivative (j, d) is a dummy, (j, 0..d-1) are unknowns of their own,
 * (j, d-1) algebraic (its derivative is now the dummy, an algebraic unknown),
 * and (j, d..h) dummies; otherwise (j, 0..h-1) are differential unknowns and
 * (j, h) is the yp of (j, h-1). Between two unknowns of one chain a row
 * y(j, k-1)' = y(j, k) keeps the derivative; between a state and its dummy
 * derivative there is none: that is what makes the state algebraic. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/indexred_int.h"

typedef struct plan {
  int n, nx;        /* unknowns of the reduced system, differential first */
  int *rep_u, *rep_yp; /* per variable: its unknown, and 1 when it is that unknown's yp */
  int *u_var;       /* per unknown: its variable */
  int nrow, *row_e; /* rows: equation of W (>= 0), or -1 - u: the chain row of unknown u */
  int *row_of;      /* per unknown: the row matched to it */
} plan;

/* Kinds of variables: 0 differential unknown, 1 algebraic unknown, 2 dummy, 3 a yp. */
static void classify(ir_work *W, int *kind) {
  for (int j = 0; j < W->n; j++) {
    int h = 0, d = -1, v = j, chain[16];
    for (; v >= 0 && h < 16; v = W->v_der[v], h++) {
      chain[h] = v;
      if (d < 0 && W->v_dummy[v]) d = h;
    }
    h--;
    for (int k = 0; k <= h; k++) {
      int x = chain[k];
      if (d >= 0) kind[x] = k >= d ? 2 : k == d - 1 ? 1 : 0;
      else kind[x] = h == 0 ? 1 : k == h ? 3 : 0;
    }
  }
}

static void assign_unknowns(ir_work *W, plan *P, const int *kind) {
  P->rep_u = bg_xmalloc((size_t)W->nv * sizeof(int)), P->rep_yp = bg_xcalloc((size_t)W->nv, sizeof(int));
  P->u_var = bg_xmalloc((size_t)W->nv * sizeof(int));
  P->n = 0;
  for (int pass = 0; pass < 3; pass++) /* differential, algebraic, dummies; by unknown and order */
    for (int j = 0; j < W->n; j++)
      for (int v = j; v >= 0; v = W->v_der[v])
        if (kind[v] == pass) P->u_var[P->n] = v, P->rep_u[v] = P->n++;
  for (int v = 0; v < W->nv; v++)
    if (kind[v] == 3) P->rep_u[v] = P->rep_u[W->v_anti[v]], P->rep_yp[v] = 1;
  P->nx = 0;
  for (int u = 0; u < P->n; u++) P->nx += kind[P->u_var[u]] == 0;
}

/* Rows: every equation, then a chain row for every unknown (j, k >= 1) that is no dummy. */
static void make_rows(ir_work *W, plan *P, const int *kind) {
  P->row_e = bg_xmalloc((size_t)(W->ne + P->n + 1) * sizeof(int));
  P->nrow = 0;
  for (int e = 0; e < W->ne; e++) P->row_e[P->nrow++] = e;
  for (int u = 0; u < P->n; u++) {
    int v = P->u_var[u];
    if (W->v_ord[v] >= 1 && kind[v] != 2) P->row_e[P->nrow++] = -1 - u;
  }
}

/* The unknowns a row can be solved for: algebraic ones it reads, differential
 * ones whose yp it reads (index 1 by structure: a perfect matching). */
static void row_unknowns(ir_work *W, const plan *P, int r, bg_ivec *out) {
  int e = P->row_e[r];
  out->n = 0;
  if (e < 0) { /* chain row: y(u_prev)' - y(u) */
    int u = -1 - e, prev = P->rep_u[W->v_anti[P->u_var[u]]];
    bg_ivec_push(out, prev);
    if (u >= P->nx) bg_ivec_push(out, u);
    return;
  }
  bg_ivec vars = {0};
  ir_expr_vars(W, W->e_expr[e], &vars);
  for (int k = 0; k < vars.n; k++) {
    int v = vars.v[k], u = P->rep_u[v];
    if (P->rep_yp[v] || u >= P->nx) bg_ivec_push(out, u);
  }
  free(vars.v);
}

/* Kuhn's augmenting paths with an explicit stack: row_of[u] for every unknown. */
static int match_rows(ir_work *W, plan *P) {
  int n = P->n, *urow = bg_xmalloc((size_t)n * sizeof(int)), ok = 1;
  bg_ivec *adj = bg_xcalloc((size_t)n + 1, sizeof(bg_ivec));
  for (int r = 0; r < n; r++) row_unknowns(W, P, r, &adj[r]);
  int *seen = bg_xcalloc((size_t)n + 1, sizeof(int)), *st_r = bg_xmalloc((size_t)(n + 1) * sizeof(int));
  int *st_p = bg_xmalloc((size_t)(n + 1) * sizeof(int)), *st_u = bg_xmalloc((size_t)(n + 1) * sizeof(int));
  for (int u = 0; u < n; u++) urow[u] = -1;
  for (int r0 = 0; r0 < n && ok; r0++) {
    int d = 0, found = 0;
    st_r[0] = r0, st_p[0] = 0;
    while (d >= 0 && !found) {
      int r = st_r[d];
      if (st_p[d] >= adj[r].n) { d--; continue; }
      int u = adj[r].v[st_p[d]++];
      if (seen[u] == r0 + 1) continue;
      seen[u] = r0 + 1, st_u[d] = u;
      if (urow[u] < 0) found = 1;
      else st_r[d + 1] = urow[u], st_p[d + 1] = 0, d++;
    }
    for (int q = d; found && q >= 0; q--) urow[st_u[q]] = st_r[q];
    ok = found;
  }
  P->row_of = urow;
  for (int r = 0; r < n; r++) free(adj[r].v);
  free(adj), free(seen), free(st_r), free(st_p), free(st_u);
  return ok ? 0 : -1;
}

static char *var_name(ir_work *W, int v, bg_arena *ar) {
  char buf[300];
  int ord = W->v_ord[v];
  snprintf(buf, sizeof buf, "%s%.*s", bg_eqsys_name(W->s, W->v_unk[v]), ord, "''''''''");
  return bg_arena_strdup(ar, buf);
}

/* The bg_eqsys fields of the reduced system (no equation trees: the tape is
 * compiled from the symbolic equations). */
static bg_eqsys *alloc_reduced(ir_work *W, const plan *P) {
  const bg_eqsys *s = W->s;
  const bg_model *m = s->m;
  bg_eqsys *r = bg_xcalloc(1, sizeof *r);
  bg_arena *ar = &r->arena;
  int n = P->n;
  r->m = m, r->a = s->a, r->nsig = s->nsig, r->n = n, r->nx = P->nx, r->nz = n - P->nx, r->reduced = 1;
  size_t ni = (size_t)(n + 1) * sizeof(int);
  r->uname = bg_arena_alloc(ar, (size_t)(n + 1) * sizeof(char *));
  int **per_u[] = {&r->u_elem, &r->u_state, &r->u_sig, &r->row_kind, &r->row_root};
  for (size_t k = 0; k < sizeof per_u / sizeof *per_u; k++) *per_u[k] = bg_arena_alloc(ar, ni);
  r->row_alg = bg_arena_alloc(ar, (size_t)n + 1);
  for (int u = 0; u < n; u++) {
    int v = P->u_var[u], j = W->v_unk[v], base = W->v_ord[v] == 0;
    r->uname[u] = var_name(W, v, ar);
    r->u_elem[u] = base ? s->u_elem[j] : -1, r->u_state[u] = base ? s->u_state[j] : -1;
    r->u_sig[u] = base ? s->u_sig[j] : -1, r->row_kind[u] = 1, r->row_root[u] = -1;
  }
  size_t ns = (size_t)(s->nsig + 1);
  r->sig_elem = bg_arena_alloc(ar, ns * sizeof(int)), r->sig_what = bg_arena_alloc(ar, ns * sizeof(char *));
  memcpy(r->sig_elem, s->sig_elem, (size_t)s->nsig * sizeof(int));
  memcpy(r->sig_what, s->sig_what, (size_t)s->nsig * sizeof(char *));
  r->store_y = bg_arena_alloc(ar, (size_t)(m->nelem + 1) * sizeof(int));
  for (int e = 0; e < m->nelem; e++) r->store_y[e] = s->store_y[e] >= 0 ? P->rep_u[s->store_y[e]] : -1;
  r->state_y = bg_arena_alloc(ar, (size_t)(m->nstate + 1) * sizeof(int));
  for (int k = 0; k < m->nstate; k++) r->state_y[k] = P->rep_u[s->state_y[k]];
  r->input_slot = bg_arena_alloc(ar, (size_t)(m->ninput + 1) * sizeof(int));
  for (int k = 0; k < m->ninput; k++) r->input_slot[k] = -1;
  return r;
}

/* Row r of the plan as an expression (a chain row built here). */
static int row_expr(ir_work *W, const plan *P, int r) {
  int e = P->row_e[r];
  if (e >= 0) return W->e_expr[e];
  int u = -1 - e, prev = P->rep_u[W->v_anti[P->u_var[u]]];
  return bg_sym_sub(W->S, bg_sym_leaf(W->S, SYM_YP, prev), ir_var_leaf(W, P->u_var[u]));
}

static void compile_outputs(ir_work *W, bg_eqsys *r, const int *map, int *memo) {
  const bg_model *m = r->m;
  int np = m->nplotexpr;
  (void)memo;
  int nx = W->s->nx;
  r->nout = np ? np : nx + m->ndet; /* without a plot: the original states by their names, the detectors */
  r->out_name = bg_arena_alloc(&r->arena, (size_t)(r->nout + 1) * sizeof(char *));
  r->out_slot = bg_arena_alloc(&r->arena, (size_t)(r->nout + 1) * sizeof(int));
  for (int k = 0; k < r->nout; k++) {
    if (np) {
      r->out_name[k] = m->plotexpr_text[k];
      r->out_slot[k] = bg_eqs_cx(r, m->plotexpr_root[k], -1000000 - k);
    } else if (k < nx) {
      r->out_name[k] = bg_arena_strdup(&r->arena, bg_eqsys_name(W->s, k));
      r->out_slot[k] = map[k];
    } else {
      int d = k - nx, o = 0;
      while (o < m->noutput && m->output_det[o] != d) o++;
      r->out_name[k] = m->det_name[d];
      r->out_slot[k] = bg_eqs_cx(r, m->det_expr[d], -2000000 - o);
    }
  }
}

static void compile(ir_work *W, bg_eqsys *r, const plan *P) {
  int n = r->n;
  bg_eqs_var_slot(r); /* t */
  r->slot_y = 1, r->slot_yp = 1 + n;
  for (int i = 0; i < 2 * n; i++) bg_eqs_var_slot(r);
  int *rexpr = bg_xmalloc((size_t)(n + 1) * sizeof(int));
  for (int i = 0; i < n; i++) rexpr[i] = row_expr(W, P, P->row_of[i]);
  int *map = bg_xmalloc((size_t)(W->nv + 1) * sizeof(int));
  for (int v = 0; v < W->nv; v++) map[v] = (P->rep_yp[v] ? r->slot_yp : r->slot_y) + P->rep_u[v];
  int nn = W->S->nnode, *memo = bg_xmalloc((size_t)(nn + 1) * sizeof(int));
  for (int k = 0; k < nn; k++) memo[k] = -1;
  r->sig_slot = bg_arena_alloc(&r->arena, (size_t)(r->nsig + 1) * sizeof(int));
  for (int v = 0; v < r->nsig; v++) r->sig_slot[v] = ir_compile(r, W->S, W->sig[v], map, memo, v);
  r->row_slot = bg_arena_alloc(&r->arena, (size_t)(n + 1) * sizeof(int));
  for (int i = 0; i < n; i++) r->row_slot[i] = ir_compile(r, W->S, rexpr[i], map, memo, -1 - i);
  r->nmain = r->ncode;
  compile_outputs(W, r, map, memo);
  r->nout_code = r->ncode;
  r->dv = bg_xcalloc((size_t)r->nslot + 1, sizeof(double));
  bg_eqs_pattern(r);
  bg_eqs_events_find(r); /* switching conditions of the reduced rows: state events as anywhere */
  r->work = bg_arena_alloc(&r->arena, (size_t)(n + 1) * sizeof(double));
  /* algebraic rows: those that read no derivative (the output rows' check) */
  for (int i = 0; i < n; i++) {
    int e = P->row_e[P->row_of[i]], alg = e >= 0;
    bg_ivec vars = {0};
    if (e >= 0) ir_expr_vars(W, W->e_expr[e], &vars);
    for (int k = 0; k < vars.n; k++) alg &= !P->rep_yp[vars.v[k]];
    r->row_alg[i] = (unsigned char)alg;
    free(vars.v);
  }
  free(rexpr), free(map), free(memo);
}

static void plan_free(plan *P) { free(P->rep_u), free(P->rep_yp), free(P->u_var), free(P->row_e), free(P->row_of); }

bg_eqsys *ir_build(ir_work *W) {
  int *kind = bg_xmalloc((size_t)(W->nv + 1) * sizeof(int));
  plan P;
  memset(&P, 0, sizeof P);
  classify(W, kind);
  assign_unknowns(W, &P, kind);
  make_rows(W, &P, kind);
  bg_eqsys *r = NULL;
  if (P.nrow != P.n)
    snprintf(W->why, sizeof W->why, "the reduced system has %d equations for %d unknowns", P.nrow, P.n);
  else if (match_rows(W, &P))
    snprintf(W->why, sizeof W->why, "the reduced system is not of index 1 by its structure (no "
             "row for every unknown)");
  else {
    r = alloc_reduced(W, &P);
    compile(W, r, &P);
  }
  plan_free(&P);
  free(kind);
  return r;
}
