/* SPDX-License-Identifier: BSD-3-Clause */
/* The reduced form of the equations (eqsym.h): explicit ODE wherever the
 * algebraic part is linear and regular.
 *
 * 1. Every explicit bond variable is substituted, in computational order,
 *    into the rows: the rows then read only the unknowns y, yp and t.
 * 2. Unknowns to eliminate W: the algebraic unknowns z and the derivatives
 *    of the dependent stores' states. Equations: the rows of z, and for each
 *    dependent store its constraint g = 0 if g reads some W (class12_paths:
 *    e4 holds R1.e), else dg/dt = 0 with the independent states' x'
 *    substituted (slider_crank: m.p' follows from J.p' and phi').
 * 3. Linear in W when every coefficient dE/dw (symbolic differentiation) is
 *    free of W and no piecewise function reads W. The system splits into
 *    independent blocks (union-find on its structure); each block of at most
 *    BLOCK_MAX unknowns is solved by Cramer's rule on symbolic coefficients.
 *    A block whose determinant is 0 at the initial point (exact cancellation:
 *    bond_loop with n = 1) stays a DAE.
 * 4. A dependent store whose constraint was differentiated is no longer a
 *    state when the constraint is linear in it (x_d = its solution); else it
 *    stays a state with x_d' from the solution.
 * The form and the index in the analysis stay those of the causal graph
 * (docs/json.md); this is what the equations became. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsym.h"
#include "equations/eqsys_int.h"

enum { BLOCK_MAX = 5, SIG_MAX = 4000 };
/* Work the printed forms may take in all (bg_sym units, apart from the
 * context's budget): past it the remaining rows print as they are. */
#define PRINT_BUDGET BG_SYM_BUDGET

struct bg_eqred {
  const bg_eqsys *s;
  bg_sym *S;
  int ode, changed;
  int skipped;                         /* the symbolic work budget ran out: no form */
  int printing;                        /* build the printed forms (not for the form alone) */
  long print_left;                     /* PRINT_BUDGET not yet spent */
  int print_cut;                       /* rows printed unsimplified: the budget ran out */
  char note[300];
  int nst, *st_u, *st_rhs, *st_print;  /* reduced states: unknown, x', x' for printing */
  int nsol, *sol_u, *sol_expr;         /* eliminated unknowns (z, and yp of dependent stores) */
  int ndef, *def_u, *def_expr;         /* dependent stores no longer states */
  int nw, *w_u, *w_isyp, *w_sol;       /* every eliminated unknown, unsimplified solution */
  int nmass, *mass_lhs, *mass_rhs;     /* Lagrange: M(x) v' = f(x), one row per coordinate */
  int lagrange;
  unsigned char *inv;                  /* per row of s: replaced by its time derivative */
  double *y, *yp;
  int *full;                           /* per signal: its expression (bg_eqred_build_keep) */
};

typedef struct red {
  bg_eqred *r;
  const bg_eqsys *s;
  bg_sym *S;
  int *full;       /* per signal: its expression in y, yp, t */
  int *row;        /* per row */
  int nw, *w_leaf, *w_u, *w_isyp; /* unknowns to eliminate: leaf, unknown index */
  int ne, *eq;     /* their equations */
  int *diffed;     /* per unknown: the dependent store's constraint was differentiated */
  int *lagv;       /* per unknown: the flow of an artificial flow source (Lagrange) */
  int *sol;        /* per w: solution */
  unsigned char *mark;
  int nmark;
  double *y0;      /* the initial point */
  double t0;
  const unsigned char *keep; /* per signal: left as its leaf (linear analysis inputs), nullable */
} red;

static void note(bg_eqred *r, const char *msg) { snprintf(r->note, sizeof r->note, "%s", msg); }

/* ------------------------------------------------------------ substitution */
static void substitute_all(red *R) {
  const bg_eqsys *s = R->s;
  R->full = bg_xmalloc((size_t)(s->nsig + 1) * sizeof(int));
  for (int v = 0; v < s->nsig; v++) R->full[v] = s->sig_torn[v] ? bg_sym_leaf(R->S, SYM_Y, s->sig_z[v]) : -1;
  for (int k = 0; k < s->norder; k++) {
    int v = s->order[k];
    if (R->keep && R->keep[v]) continue; /* stays a leaf: an input's value */
    R->full[v] = bg_eqsym_tree(R->S, s, s->sig_root[v], R->full);
  }
  R->row = bg_xmalloc((size_t)(s->n + 1) * sizeof(int));
  for (int i = 0; i < s->n; i++) R->row[i] = bg_eqsym_tree(R->S, s, s->row_root[i], R->full);
}

/* Marks the leaves of W (by node id) for dependency tests. */
static void mark_w(red *R) {
  free(R->mark);
  R->nmark = R->S->nnode;
  R->mark = bg_xcalloc((size_t)R->nmark + 1, 1);
  for (int k = 0; k < R->nw; k++) R->mark[R->w_leaf[k]] = 1;
}

static int depends_w(red *R, int a) {
  if (R->S->nnode > R->nmark) mark_w(R);
  return bg_sym_depends(R->S, a, R->mark, R->nmark);
}

/* ------------------------------------------------------------ the equations of W */
static int yp_cb(void *ctx, int kind, int ref) {
  red *R = ctx;
  if (kind != SYM_YP || ref >= R->s->nx || R->s->row_kind[ref] != 0) return -1;
  return R->row[ref]; /* x' of an independent state: its right-hand side */
}

/* dg/dt with the independent states' derivatives substituted. */
static int time_derivative(red *R, int g) {
  const bg_eqsys *s = R->s;
  bg_sym *S = R->S;
  int n = s->n + 1, *t = bg_xmalloc((size_t)n * sizeof *t), k = 0;
  for (int j = 0; j < s->n; j++) {
    if (j >= s->nx && !R->lagv[j]) continue;
    int d = bg_sym_diff(S, g, bg_sym_leaf(S, SYM_Y, j));
    if (S->node[d].kind == SYM_NUM && S->node[d].c == 0) continue;
    t[k++] = bg_sym_mul(S, d, bg_sym_leaf(S, SYM_YP, j));
  }
  t[k++] = bg_sym_diff(S, g, bg_sym_leaf(S, SYM_T, 0));
  int dg = bg_sym_sum(S, 0, k, t, NULL);
  free(t);
  return bg_sym_subst(S, dg, yp_cb, R);
}

static void collect_w(red *R) {
  const bg_eqsys *s = R->s;
  int cap = s->n + 1;
  R->w_leaf = bg_xmalloc((size_t)cap * sizeof(int)), R->w_u = bg_xmalloc((size_t)cap * sizeof(int));
  R->w_isyp = bg_xmalloc((size_t)cap * sizeof(int)), R->eq = bg_xmalloc((size_t)cap * sizeof(int));
  R->diffed = bg_xcalloc((size_t)cap, sizeof(int));
  for (int i = s->nx; i < s->n; i++) /* a Lagrange velocity is a state: its derivative is in W */
    R->w_leaf[R->nw] = bg_sym_leaf(R->S, R->lagv[i] ? SYM_YP : SYM_Y, i), R->w_u[R->nw] = i,
    R->w_isyp[R->nw++] = R->lagv[i];
  for (int i = 0; i < s->nx; i++)
    if (s->row_kind[i] == 1)
      R->w_leaf[R->nw] = bg_sym_leaf(R->S, SYM_YP, i), R->w_u[R->nw] = i, R->w_isyp[R->nw++] = 1;
  mark_w(R);
  for (int i = s->nx; i < s->n; i++) { /* a balance without accelerations: differentiated (4.58a) */
    int g = R->row[i];
    if (R->lagv[i] && !depends_w(R, g)) g = time_derivative(R, g), R->diffed[i] = 1;
    R->eq[R->ne++] = g;
  }
  for (int i = 0; i < s->nx; i++) {
    if (s->row_kind[i] != 1) continue;
    int g = R->row[i];
    if (!depends_w(R, g)) g = time_derivative(R, g), R->diffed[i] = 1;
    R->eq[R->ne++] = g;
  }
}

/* ------------------------------------------------------------ linear blocks */
static int is_zero(const bg_sym *S, int a) { return S->node[a].kind == SYM_NUM && S->node[a].c == 0; }

/* Symbolic determinant by expansion along the first row (n <= BLOCK_MAX). */
static int sym_det(bg_sym *S, const int *A, int n, int ld) {
  if (n == 1) return A[0];
  int *minor = bg_xmalloc((size_t)(n - 1) * (n - 1) * sizeof *minor), *t = bg_xmalloc((size_t)n * sizeof *t);
  double *w = bg_xmalloc((size_t)n * sizeof *w);
  int k = 0;
  for (int j = 0; j < n; j++) {
    if (is_zero(S, A[j])) continue;
    for (int r = 1; r < n; r++)
      for (int c = 0, cc = 0; c < n; c++)
        if (c != j) minor[(r - 1) * (n - 1) + cc++] = A[r * ld + c];
    t[k] = bg_sym_mul(S, A[j], sym_det(S, minor, n - 1, n - 1)), w[k++] = j % 2 ? -1 : 1;
  }
  int d = bg_sym_sum(S, 0, k, t, w);
  free(minor), free(t), free(w);
  return d;
}

/* Numeric determinant and the permanent of |A| (its scale). */
static double num_det(const double *A, int n, int ld, double *scale) {
  if (n == 1) return *scale = fabs(A[0]), A[0];
  double *minor = bg_xmalloc((size_t)(n - 1) * (n - 1) * sizeof *minor), d = 0;
  *scale = 0;
  for (int j = 0; j < n; j++) {
    if (A[j] == 0) continue;
    for (int r = 1; r < n; r++)
      for (int c = 0, cc = 0; c < n; c++)
        if (c != j) minor[(r - 1) * (n - 1) + cc++] = A[r * ld + c];
    double sc, m = num_det(minor, n - 1, n - 1, &sc);
    d += (j % 2 ? -1 : 1) * A[j] * m, *scale += fabs(A[j]) * sc;
  }
  free(minor);
  return d;
}

static int uf_find(int *p, int x) {
  while (p[x] != x) p[x] = p[p[x]], x = p[x];
  return x;
}

/* Solves one block: equations eqs[0..n), unknowns ws[0..n) (indices into W). */
static int solve_block(red *R, const int *eqs, const int *ws, int n, int *coef, const int *b) {
  bg_sym *S = R->S;
  int A[BLOCK_MAX * BLOCK_MAX], M[BLOCK_MAX * BLOCK_MAX];
  double An[BLOCK_MAX * BLOCK_MAX], scale;
  bg_symenv env = {R->t0, R->y0, NULL, NULL, NULL};
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      A[i * n + j] = coef[eqs[i] * R->nw + ws[j]];
      An[i * n + j] = bg_sym_eval(S, A[i * n + j], &env);
    }
  double dn = num_det(An, n, n, &scale);
  if (!isfinite(dn) || fabs(dn) <= 1e-12 * scale) return -1;
  int det = sym_det(S, A, n, n);
  for (int j = 0; j < n; j++) {
    memcpy(M, A, (size_t)n * n * sizeof *M);
    for (int i = 0; i < n; i++) M[i * n + j] = b[eqs[i]];
    R->sol[ws[j]] = bg_sym_div(S, sym_det(S, M, n, n), det);
  }
  return 0;
}

/* Coefficients, right-hand sides and the block structure; 0 when solved. */
static int w_cb(void *ctx, int kind, int ref) {
  red *R = ctx;
  for (int k = 0; k < R->nw; k++)
    if (R->S->node[R->w_leaf[k]].kind == kind && R->S->node[R->w_leaf[k]].ref == ref) return bg_sym_num(R->S, 0);
  return -1;
}

/* Index in W of a leaf id, or -1. */
static int w_index(const red *R, int leaf) {
  for (int k = 0; k < R->nw; k++)
    if (R->w_leaf[k] == leaf) return k;
  return -1;
}

/* Structure first (which unknowns each equation holds, the blocks, their
 * sizes), then coefficients only where the structure has them: a large
 * algebraic block is refused before any differentiation. */
static int eliminate(red *R) {
  bg_sym *S = R->S;
  int nw = R->nw, ne = R->ne, rc = 0;
  if (ne != nw) {
    note(R->r, "as many equations as unknowns are needed");
    return -1;
  }
  int *coef = bg_xcalloc((size_t)ne * nw + 1, sizeof *coef), *b = bg_xmalloc((size_t)(ne + 1) * sizeof *b);
  int *par = bg_xmalloc((size_t)(nw + 1) * sizeof *par), *lv = bg_xmalloc((size_t)(nw + 1) * sizeof *lv);
  unsigned char *has = bg_xcalloc((size_t)ne * nw + 1, 1);
  for (int j = 0; j < nw; j++) par[j] = j;
  if (S->nnode > R->nmark) mark_w(R);
  for (int i = 0; i < ne && !rc; i++) {
    int cnt = bg_sym_leaves(S, R->eq[i], R->mark, R->nmark, lv, nw), first = -1;
    for (int q = 0; q < cnt && q < nw; q++) {
      int j = w_index(R, lv[q]);
      has[i * nw + j] = 1;
      if (first < 0) first = j;
      else par[uf_find(par, j)] = uf_find(par, first);
    }
    if (first < 0) rc = -3;
  }
  if (rc == -3) note(R->r, "an algebraic equation holds none of the unknowns to eliminate (a constraint among the states: index above 1)");
  int *eqs = bg_xmalloc((size_t)(ne + 1) * sizeof *eqs), *ws = bg_xmalloc((size_t)(nw + 1) * sizeof *ws);
  int *bn = bg_xcalloc((size_t)nw + 1, sizeof *bn), *be = bg_xcalloc((size_t)nw + 1, sizeof *be);
  for (int i = 0; i < ne && !rc; i++) {
    int j = 0;
    while (!has[i * nw + j]) j++;
    be[uf_find(par, j)]++;
  }
  for (int j = 0; j < nw && !rc; j++) bn[uf_find(par, j)]++;
  for (int j = 0; j < nw && !rc; j++) {
    if (uf_find(par, j) != j) continue;
    if (bn[j] != be[j]) rc = -4, note(R->r, "an algebraic block has more equations than unknowns: singular, index above 1");
    else if (bn[j] > BLOCK_MAX) rc = -5, note(R->r, "an algebraic block is too large for symbolic elimination");
  }
  for (int i = 0; i < ne && !rc; i++) { /* coefficients and right-hand sides */
    if (bg_sym_piecewise(S, R->eq[i], R->mark, R->nmark)) rc = -2;
    for (int j = 0; j < nw && !rc; j++) {
      coef[i * nw + j] = has[i * nw + j] ? bg_sym_diff(S, R->eq[i], R->w_leaf[j]) : bg_sym_num(S, 0);
      if (has[i * nw + j] && depends_w(R, coef[i * nw + j])) rc = -2;
    }
    if (!rc) b[i] = bg_sym_neg(S, bg_sym_subst(S, R->eq[i], w_cb, R));
  }
  if (rc == -2) note(R->r, "the algebraic equations are not linear in their unknowns: they stay implicit");
  for (int root = 0; root < nw && !rc; root++) {
    if (uf_find(par, root) != root) continue;
    int n = 0, m = 0;
    for (int j = 0; j < nw; j++)
      if (uf_find(par, j) == root) ws[n++] = j;
    for (int i = 0; i < ne; i++) {
      int j = 0;
      while (!has[i * nw + j]) j++;
      if (uf_find(par, j) == root) eqs[m++] = i;
    }
    if (solve_block(R, eqs, ws, n, coef, b)) rc = -6, note(R->r, "an algebraic block is singular at the parameters' values");
  }
  free(coef), free(b), free(par), free(eqs), free(ws), free(lv), free(has), free(bn), free(be);
  return rc;
}

/* ------------------------------------------------------------ the reduced ODE */
static int sol_cb(void *ctx, int kind, int ref) {
  red *R = ctx;
  for (int k = 0; k < R->nw; k++)
    if (R->S->node[R->w_leaf[k]].kind == kind && R->S->node[R->w_leaf[k]].ref == ref) return R->sol[k];
  if (kind == SYM_Y)
    for (int k = 0; k < R->r->ndef; k++)
      if (R->r->def_u[k] == ref) return R->r->def_expr[k];
  return -1;
}

/* Dependent stores whose constraint was differentiated and is linear in
 * their state: no longer states. */
static void drop_dependent(red *R) {
  const bg_eqsys *s = R->s;
  bg_eqred *r = R->r;
  bg_sym *S = R->S;
  r->def_u = bg_xmalloc((size_t)(s->nx + 1) * sizeof(int));
  r->def_expr = bg_xmalloc((size_t)(s->nx + 1) * sizeof(int));
  for (int i = 0; i < s->nx; i++) {
    if (!R->diffed[i]) continue;
    int g = R->row[i], x = bg_sym_leaf(S, SYM_Y, i), a = bg_sym_diff(S, g, x);
    unsigned char *mk = bg_xcalloc((size_t)S->nnode + 1, 1);
    mk[x] = 1;
    int lin = !bg_sym_depends(S, a, mk, S->nnode) && !bg_sym_piecewise(S, g, mk, S->nnode) && !is_zero(S, a);
    free(mk);
    if (!lin) continue;
    r->def_u[r->ndef] = i; /* g = a x + rest, so x = -rest / a */
    r->def_expr[r->ndef++] = bg_sym_neg(S, bg_sym_div(S, bg_sym_sub(S, g, bg_sym_mul(S, a, x)), a));
  }
}

/* The form to print: expanded, grouped by the variables with rational
 * coefficients in the params, over one denominator (bond_loop: Equation
 * 4.27). Falls back to a when that grows much larger, or when the printed
 * forms' own budget runs out (their work is not counted against the
 * context's, so the form, ode or dae, never depends on printing). */
static int print_form(bg_eqred *r, int a) {
  bg_sym *S = r->S;
  if (!r->printing || S->over) return a;
  if (r->print_left <= 0) return r->print_cut++, a;
  long work0 = S->work, budget0 = S->budget;
  S->budget = work0 + r->print_left;
  int n0 = bg_sym_size(S, a), e = a;
  if (n0 <= 3000) {
    int c = bg_sym_collect(S, bg_sym_expand(S, a, 2000));
    int e0 = bg_sym_together(S, c, 0), e1 = bg_sym_together(S, c, 1);
    int n1 = bg_sym_size(S, e0), n2 = bg_sym_size(S, e1);
    e = n2 < n1 ? e1 : e0;
    if ((n2 < n1 ? n2 : n1) > 3 * n0 + 40) e = a;
  }
  if (S->over) e = a, S->over = 0, r->print_cut++;
  r->print_left -= S->work - work0;
  S->work = work0, S->budget = budget0;
  return e;
}

static void assemble(red *R) {
  const bg_eqsys *s = R->s;
  bg_eqred *r = R->r;
  bg_sym *S = R->S;
  r->st_u = bg_xmalloc((size_t)(s->n + 1) * sizeof(int));
  r->st_rhs = bg_xmalloc((size_t)(s->n + 1) * sizeof(int));
  r->st_print = bg_xmalloc((size_t)(s->n + 1) * sizeof(int));
  for (int i = 0; i < s->n; i++) {
    if (i >= s->nx && !R->lagv[i]) continue;
    int dropped = 0;
    for (int k = 0; k < r->ndef; k++) dropped |= r->def_u[k] == i;
    if (dropped) continue;
    int e = s->row_kind[i] == 0 ? R->row[i] : bg_sym_leaf(S, SYM_YP, i);
    e = bg_sym_subst(S, e, sol_cb, R);
    r->st_u[r->nst] = i, r->st_rhs[r->nst] = e, r->st_print[r->nst++] = print_form(r, e);
  }
  r->sol_u = bg_xmalloc((size_t)(R->nw + 1) * sizeof(int));
  r->sol_expr = bg_xmalloc((size_t)(R->nw + 1) * sizeof(int));
  r->nw = R->nw;
  r->w_u = bg_xmalloc((size_t)(R->nw + 1) * sizeof(int));
  r->w_isyp = bg_xmalloc((size_t)(R->nw + 1) * sizeof(int));
  r->w_sol = bg_xmalloc((size_t)(R->nw + 1) * sizeof(int));
  for (int k = 0; k < R->nw; k++)
    r->w_u[k] = R->w_u[k], r->w_isyp[k] = R->w_isyp[k], r->w_sol[k] = bg_sym_subst(S, R->sol[k], sol_cb, R);
  for (int k = 0; k < R->nw; k++) {
    if (R->w_isyp[k]) continue;
    r->sol_u[r->nsol] = R->w_u[k];
    r->sol_expr[r->nsol++] = print_form(r, bg_sym_subst(S, R->sol[k], sol_cb, R));
  }
}

/* ------------------------------------------------------------ Lagrange */
static int lagzero_cb(void *ctx, int kind, int ref) {
  red *R = ctx;
  return kind == SYM_YP && ref < R->s->n && R->lagv[ref] ? bg_sym_num(R->S, 0) : -1;
}

/* The mass-matrix form of Lagrange's equations (Equation 4.53): every
 * other unknown eliminated with the accelerations v' kept as symbols
 * (stage 1), then each balance is linear in v': sum_j M_kj v_j' = f_k. */
static void mass_rows(red *R) {
  const bg_eqsys *s = R->s;
  bg_eqred *r = R->r;
  bg_sym *S = R->S;
  red Q = *R;
  int cap = R->nw + 1, nz = s->n - s->nx;
  Q.w_leaf = bg_xmalloc((size_t)cap * sizeof(int)), Q.w_u = bg_xmalloc((size_t)cap * sizeof(int));
  Q.w_isyp = bg_xmalloc((size_t)cap * sizeof(int)), Q.eq = bg_xmalloc((size_t)cap * sizeof(int));
  Q.sol = bg_xcalloc((size_t)cap, sizeof(int)), Q.mark = NULL, Q.nmark = 0, Q.nw = Q.ne = 0;
  for (int k = 0; k < R->nw; k++)
    if (!(R->w_isyp[k] && R->w_u[k] >= s->nx))
      Q.w_leaf[Q.nw] = R->w_leaf[k], Q.w_u[Q.nw] = R->w_u[k], Q.w_isyp[Q.nw++] = R->w_isyp[k];
  for (int q = 0; q < R->ne; q++) /* rows of z first (collect_w), then constraints */
    if (!(q < nz && R->lagv[s->nx + q])) Q.eq[Q.ne++] = R->eq[q];
  char keep[sizeof r->note];
  memcpy(keep, r->note, sizeof keep);
  int rc = Q.nw ? (mark_w(&Q), eliminate(&Q)) : 0;
  memcpy(r->note, keep, sizeof keep);
  if (!rc) {
    r->mass_lhs = bg_xmalloc((size_t)(nz + 1) * sizeof(int));
    r->mass_rhs = bg_xmalloc((size_t)(nz + 1) * sizeof(int));
    bg_symenv env = {R->t0, R->y0, NULL, NULL, NULL};
    for (int i = s->nx; i < s->n; i++) {
      if (!R->lagv[i]) continue;
      int E = Q.nw ? bg_sym_subst(S, R->eq[i - s->nx], sol_cb, &Q) : R->eq[i - s->nx];
      int f = bg_sym_neg(S, bg_sym_subst(S, E, lagzero_cb, R));
      double sg = bg_sym_eval(S, bg_sym_diff(S, E, bg_sym_leaf(S, SYM_YP, i)), &env) < 0 ? -1 : 1;
      int *t = bg_xmalloc((size_t)(nz + 1) * sizeof *t), nt = 0;
      for (int j = s->nx; j < s->n; j++) { /* sum_j M_kj v_j', each M_kj printed whole */
        if (!R->lagv[j]) continue;
        int yp = bg_sym_leaf(S, SYM_YP, j), M = bg_sym_scale(S, sg, bg_sym_diff(S, E, yp));
        if (S->node[M].kind != SYM_NUM || S->node[M].c != 0) t[nt++] = bg_sym_mul(S, print_form(r, M), yp);
      }
      r->mass_lhs[r->nmass] = bg_sym_sum(S, 0, nt, t, NULL);
      r->mass_rhs[r->nmass++] = print_form(r, bg_sym_scale(S, sg, f));
      free(t);
    }
  }
  free(Q.w_leaf), free(Q.w_u), free(Q.w_isyp), free(Q.eq), free(Q.sol), free(Q.mark);
}

static void describe(red *R) {
  bg_eqred *r = R->r;
  const bg_eqsys *s = R->s;
  int nd = 0;
  for (int i = 0; i < s->nx; i++) nd += s->row_kind[i] == 1;
  char buf[300];
  int len = snprintf(buf, sizeof buf, "explicit ODE after symbolic elimination");
  if (s->nz) len += snprintf(buf + len, sizeof buf - (size_t)len, " of %d algebraic unknown%s", s->nz, s->nz == 1 ? "" : "s");
  if (nd) snprintf(buf + len, sizeof buf - (size_t)len, "%s %d dependent store%s combined%s", s->nz ? "," : ";",
                   nd, nd == 1 ? "" : "s", r->ndef ? " (constraints differentiated once)" : "");
  note(r, buf);
}

/* W and its equations, then the linear blocks solved; 0 or eliminate's code. */
static int collect_and_eliminate(red *R) {
  collect_w(R);
  R->sol = bg_xcalloc((size_t)R->nw + 1, sizeof(int));
  if (bg_sym_over(R->S)) return -8;
  if (bg_sym_full(R->S)) {
    note(R->r, "the equations are too large for symbolic elimination");
    return -7;
  }
  return eliminate(R);
}

/* The budget ran out: whatever was built is dropped, the form is unknown. */
static void skip(bg_eqred *r) {
  r->ode = r->changed = 0, r->skipped = 1;
  r->nst = r->nsol = r->ndef = r->nw = r->nmass = 0;
  note(r, BG_EQRED_SKIPPED);
}

static void reduce_budgeted(red *R);

static void reduce(red *R) {
  reduce_budgeted(R);
  if (bg_sym_over(R->S)) skip(R->r);
}

static void reduce_budgeted(red *R) {
  bg_eqred *r = R->r;
  const bg_eqsys *s = R->s;
  substitute_all(R);
  R->lagv = bg_xcalloc((size_t)s->n + 1, sizeof(int));
  for (int i = s->nx; i < s->n; i++)
    for (int k = 0; k < s->a->nlag; k++)
      if (s->a->lag_junction[k] == s->sig_elem[s->u_sig[i]] || /* or an inserted one's flow */
          (s->a->lag_junction[k] < 0 && s->u_sig[i] == 2 * s->a->lag_bond[k] + 1))
        R->lagv[i] = 1, r->lagrange = 1;
  int rc = collect_and_eliminate(R);
  if (rc <= -3 && rc >= -4 && r->lagrange && !bg_sym_full(R->S)) {
    /* No Lagrange equations of second order: a coordinate whose balance
     * holds no acceleration but other unknowns (resistive or dependent
     * storage ports only) is not a state. Eliminate the velocities like
     * any other algebraic unknown. */
    free(R->w_leaf), free(R->w_u), free(R->w_isyp), free(R->eq), free(R->diffed), free(R->sol);
    R->nw = R->ne = 0;
    memset(R->lagv, 0, (size_t)(s->n + 1) * sizeof(int));
    r->lagrange = 0;
    rc = collect_and_eliminate(R);
  }
  if (rc) return;
  if (r->lagrange) mass_rows(R);
  for (int i = s->nx; i < s->n; i++) r->inv[i] = (unsigned char)R->diffed[i]; /* Lagrange balances */
  drop_dependent(R);
  assemble(R);
  r->ode = 1, r->changed = s->nz > 0 || s->ndep > 0;
  if (r->changed) describe(R);
  else note(r, "explicit ODE");
  if (r->lagrange)
    note(r, "explicit ODE from Lagrange's equations (the flows of the artificial sources are states; "
            "balances without accelerations differentiated once)");
}

static bg_eqred *build(const bg_eqsys *s, const unsigned char *keep, int printing) {
  bg_eqred *r = bg_xcalloc(1, sizeof *r);
  r->s = s;
  r->S = bg_sym_new(s->m);
  r->S->budget = BG_SYM_BUDGET;
  r->printing = printing, r->print_left = PRINT_BUDGET;
  r->y = bg_xcalloc((size_t)s->n + 1, sizeof *r->y);
  r->yp = bg_xcalloc((size_t)s->n + 1, sizeof *r->yp);
  r->inv = bg_xcalloc((size_t)s->n + 1, 1);
  if (s->nsig > SIG_MAX) {
    note(r, "the model is too large for symbolic elimination");
    return r;
  }
  red R = {0};
  R.r = r, R.s = s, R.S = r->S;
  R.y0 = bg_xcalloc((size_t)s->n + 1, sizeof *R.y0);
  R.t0 = s->m->sim.present ? s->m->sim.t0 : 0;
  R.keep = keep;
  bg_eqsys_initial(s, R.y0);
  reduce(&R);
  if (keep) r->full = R.full, R.full = NULL;
  free(R.full), free(R.row), free(R.w_leaf), free(R.w_u), free(R.w_isyp), free(R.eq);
  free(R.diffed), free(R.sol), free(R.mark), free(R.y0), free(R.lagv);
  return r;
}

bg_eqred *bg_eqred_build(const bg_eqsys *s) { return build(s, NULL, 1); }

bg_eqred *bg_eqred_build_keep(const bg_eqsys *s, const unsigned char *keep) {
  return build(s, keep, 1);
}

int bg_eqred_state_rhs(const bg_eqred *r, int k) { return r->ode ? r->st_rhs[k] : -1; }

/* A leaf of an expression of bond variables and unknowns, in the reduced
 * variables: signals by their expressions, eliminated unknowns by their
 * solutions, states' derivatives by their right-hand sides. */
static int reduced_cb(void *ctx, int kind, int ref) {
  const bg_eqred *r = ctx;
  if (kind == SYM_SIG) return r->full[ref]; /* -1 (kept): the leaf itself */
  if (kind != SYM_Y && kind != SYM_YP) return -1;
  for (int k = 0; k < r->nw; k++)
    if (r->w_u[k] == ref && r->w_isyp[k] == (kind == SYM_YP)) return r->w_sol[k];
  for (int k = 0; kind == SYM_YP && k < r->nst; k++)
    if (r->st_u[k] == ref) return r->st_rhs[k];
  return -1;
}

int bg_eqred_unknown_expr(bg_eqred *r, int u) {
  if (!r->ode) return -1;
  for (int k = 0; k < r->nst; k++)
    if (r->st_u[k] == u) return bg_sym_leaf(r->S, SYM_Y, u);
  for (int k = 0; k < r->ndef; k++)
    if (r->def_u[k] == u) return r->def_expr[k];
  for (int k = 0; k < r->nw; k++)
    if (r->w_u[k] == u && !r->w_isyp[k]) return r->w_sol[k];
  return -1;
}

int bg_eqred_reduce_expr(bg_eqred *r, int xroot) {
  if (!r->ode || !r->full) return -1;
  int e = bg_sym_from_x(r->S, xroot, r->s->state_y, r->s->store_y);
  for (int pass = 0; pass < 3; pass++) e = bg_sym_subst(r->S, e, reduced_cb, r); /* signals, then W */
  return e;
}

void bg_eqred_free(bg_eqred *r) {
  if (!r) return;
  bg_sym_free(r->S);
  free(r->st_u), free(r->st_rhs), free(r->st_print), free(r->sol_u), free(r->sol_expr);
  free(r->def_u), free(r->def_expr), free(r->y), free(r->yp), free(r->inv);
  free(r->w_u), free(r->w_isyp), free(r->w_sol), free(r->mass_lhs), free(r->mass_rhs);
  free(r->full);
  free(r);
}

const char *bg_eqred_form(const bg_eqsys *s, const char **why) {
  bg_eqred *r = build(s, NULL, 0); /* the form only: no printed forms */
  const char *f = r->skipped ? NULL : r->ode ? "ode" : "dae";
  if (why) *why = r->skipped ? BG_EQRED_SKIPPED : NULL;
  bg_eqred_free(r);
  return f;
}


int bg_eqred_is_ode(const bg_eqred *r) { return r->ode; }
int bg_eqred_invariant(const bg_eqred *r, int i) { return i >= 0 && i < r->s->n && r->inv[i]; }
int bg_eqred_changed(const bg_eqred *r) { return r->changed; }
const char *bg_eqred_note(const bg_eqred *r) { return r->note; }
int bg_eqred_nstate(const bg_eqred *r) { return r->nst; }
int bg_eqred_state(const bg_eqred *r, int k) { return k >= 0 && k < r->nst ? r->st_u[k] : -1; }

int bg_eqred_rhs(bg_eqred *r, double t, const double *x, double *xdot) {
  if (!r->ode) return -1;
  memset(r->y, 0, (size_t)r->s->n * sizeof *r->y);
  for (int k = 0; k < r->nst; k++) r->y[r->st_u[k]] = x[k];
  bg_symenv env = {t, r->y, NULL, NULL, NULL};
  int bad = 0;
  for (int k = 0; k < r->nst; k++) xdot[k] = bg_sym_eval(r->S, r->st_rhs[k], &env), bad |= !isfinite(xdot[k]);
  return bad ? -1 : 0;
}

int bg_eqred_point(bg_eqred *r, double t, const double *x, double *y, double *yp) {
  if (!r->ode) return -1;
  int n = r->s->n, bad = 0;
  double *xd = bg_xmalloc((size_t)(r->nst + 1) * sizeof *xd);
  if (bg_eqred_rhs(r, t, x, xd)) bad = 1;
  memset(y, 0, (size_t)n * sizeof *y), memset(yp, 0, (size_t)n * sizeof *yp);
  for (int k = 0; k < r->nst; k++) y[r->st_u[k]] = x[k], yp[r->st_u[k]] = xd[k];
  bg_symenv env = {t, r->y, NULL, NULL, NULL}; /* r->y: the states (set by bg_eqred_rhs) */
  for (int k = 0; k < r->ndef; k++) y[r->def_u[k]] = bg_sym_eval(r->S, r->def_expr[k], &env);
  for (int k = 0; k < r->nw; k++) (r->w_isyp[k] ? yp : y)[r->w_u[k]] = bg_sym_eval(r->S, r->w_sol[k], &env);
  for (int i = 0; i < n; i++) bad |= !isfinite(y[i]) || !isfinite(yp[i]);
  free(xd);
  return bad ? -1 : 0;
}

int bg_eqsym_rows(bg_sym *S, const bg_eqsys *s, int *rows) {
  if (s->nsig > SIG_MAX) return -1;
  red R = {0};
  R.s = s, R.S = S;
  substitute_all(&R);
  memcpy(rows, R.row, (size_t)s->n * sizeof *rows);
  free(R.full), free(R.row);
  return 0;
}

int bg_eqsym_rows_signals(bg_sym *S, const bg_eqsys *s, int *rows, int *sigs) {
  if (s->nsig > SIG_MAX) return -1;
  red R = {0};
  R.s = s, R.S = S;
  substitute_all(&R);
  memcpy(rows, R.row, (size_t)s->n * sizeof *rows);
  memcpy(sigs, R.full, (size_t)s->nsig * sizeof *sigs);
  free(R.full), free(R.row);
  return 0;
}

/* ------------------------------------------------------------ printing */
static void put_lhs(bg_eqred *r, int u, int deriv, int latex, bg_strbuf *out) {
  bg_eqsym_name((void *)r->s, deriv ? SYM_YP : SYM_Y, u, latex, out);
}

static void put_row(bg_eqred *r, int u, int deriv, int e, int latex, bg_strbuf *out) {
  const bg_eqpunct *pu = bg_eqpunct_of(latex);
  bg_sb_puts(out, pu->row);
  put_lhs(r, u, deriv, latex, out);
  bg_sb_puts(out, pu->eq);
  bg_sym_print(r->S, e, latex, bg_eqsym_name, (void *)r->s, out);
  bg_sb_puts(out, pu->end);
}

/* The coefficient prints with a leading minus sign. */
static int coef_negative(bg_sym *S, int M, int latex, const bg_eqsys *s) {
  bg_strbuf sb = {0};
  bg_sym_print(S, M, latex, bg_eqsym_name, (void *)s, &sb);
  int neg = bg_sb_str(&sb)[0] == '-';
  bg_sb_free(&sb);
  return neg;
}

/* sum_j M_kj v_j' with each coefficient first: (J0 + m0*T^2)*w.f'. */
static void print_mass_lhs(bg_eqred *r, int lhs, int latex, bg_strbuf *out) {
  bg_sym *S = r->S;
  const bg_symnode *x = &S->node[lhs];
  int n = x->kind == SYM_ADD ? x->n : 1;
  for (int k = 0; k < n; k++) {
    x = &S->node[lhs];
    int t = x->kind == SYM_ADD ? S->arg[x->adr + k] : lhs, yp = -1;
    double w = x->kind == SYM_ADD ? S->w[x->adr + k] : 1;
    const bg_symnode *m = &S->node[t];
    for (int q = 0; m->kind == SYM_MUL && q < m->n; q++)
      if (S->node[S->arg[m->adr + q]].kind == SYM_YP && S->w[m->adr + q] == 1) yp = S->arg[m->adr + q];
    if (m->kind == SYM_YP) yp = t;
    int M = yp >= 0 ? bg_sym_scale(S, w, bg_sym_div(S, t, yp)) : bg_sym_scale(S, w, t);
    int paren = S->node[M].kind == SYM_ADD;
    const bg_eqpunct *pu = bg_eqpunct_of(latex);
    if (k && !paren && coef_negative(S, M, BG_SYM_TEXT, r->s)) { /* "a - b*v'", not "a + -b*v'" */
      M = bg_sym_scale(S, -1, M);
      bg_sb_puts(out, pu->minus);
    } else if (k)
      bg_sb_puts(out, pu->plus);
    if (!(S->node[M].kind == SYM_NUM && S->node[M].c == 1)) {
      if (paren) bg_sb_puts(out, pu->lp);
      bg_sym_print(S, M, latex, bg_eqsym_name, (void *)r->s, out);
      if (paren) bg_sb_puts(out, pu->rp);
      if (yp >= 0) bg_sb_puts(out, pu->times);
    }
    if (yp >= 0) bg_sym_print(S, yp, latex, bg_eqsym_name, (void *)r->s, out);
  }
}

void bg_eqred_print(bg_eqred *r, int latex, bg_strbuf *out) {
  if (r->ode && !r->changed) return;
  if (!latex && r->skipped) bg_sb_printf(out, "# reduced form: %s\n", r->note);
  else if (!latex) bg_sb_printf(out, "# reduced form: %s%s%s\n", r->ode ? "" : "DAE (", r->note, r->ode ? "" : ")");
  if (!latex && r->print_cut)
    bg_sb_printf(out, "# %d row%s printed unsimplified: printing exceeded its budget of " BG_SYM_BUDGET_WORDS " operations\n",
                 r->print_cut, r->print_cut == 1 ? "" : "s");
  if (!r->ode) return;
  if (r->nmass && !latex) bg_sb_puts(out, "# Lagrange equations, mass-matrix form M(x) v' = f(x)\n");
  const bg_eqpunct *pu = bg_eqpunct_of(latex);
  for (int k = 0; k < r->nmass; k++) {
    bg_sb_puts(out, pu->row);
    print_mass_lhs(r, r->mass_lhs[k], latex, out);
    bg_sb_puts(out, pu->eq);
    bg_sym_print(r->S, r->mass_rhs[k], latex, bg_eqsym_name, (void *)r->s, out);
    bg_sb_puts(out, pu->end);
  }
  if (r->nmass && !latex) bg_sb_puts(out, "# explicit form\n");
  for (int k = 0; k < r->nsol; k++) put_row(r, r->sol_u[k], 0, r->sol_expr[k], latex, out);
  for (int k = 0; k < r->ndef; k++) put_row(r, r->def_u[k], 0, r->def_expr[k], latex, out);
  for (int k = 0; k < r->nst; k++) put_row(r, r->st_u[k], 1, r->st_print[k], latex, out);
}

/* One row of the reduced form: lhs, rhs and what the row is. */
static void json_row(bg_eqred *r, int u, int deriv, int e, const char *kind, int *first,
                     bg_strbuf *out) {
  bg_strbuf t = {0};
  put_lhs(r, u, deriv, 0, &t);
  bg_sb_puts(out, *first ? "{\"lhs\": " : ", {\"lhs\": ");
  *first = 0;
  bg_sb_json_str(out, bg_sb_str(&t));
  bg_sb_clear(&t);
  bg_sym_print(r->S, e, 0, bg_eqsym_name, (void *)r->s, &t);
  bg_sb_puts(out, ", \"rhs\": ");
  bg_sb_json_str(out, bg_sb_str(&t));
  bg_sb_printf(out, ", \"kind\": \"%s\"}", kind);
  bg_sb_free(&t);
}

/* The rows the text prints, in its order: the eliminated unknowns, the
 * dependent stores that are no longer states (C1.q = 1), the state rows. */
void bg_eqred_json(bg_eqred *r, bg_strbuf *out) {
  if (r->skipped) bg_sb_puts(out, "\"reduced_form\": null, \"reduced_note\": ");
  else bg_sb_printf(out, "\"reduced_form\": \"%s\", \"reduced_note\": ", r->ode ? "ode" : "dae");
  bg_sb_json_str(out, r->note);
  bg_sb_puts(out, ", \"reduced\": [");
  int first = 1;
  for (int k = 0; r->ode && r->changed && k < r->nsol; k++)
    json_row(r, r->sol_u[k], 0, r->sol_expr[k], "solved", &first, out);
  for (int k = 0; r->ode && r->changed && k < r->ndef; k++)
    json_row(r, r->def_u[k], 0, r->def_expr[k], "dependent", &first, out);
  for (int k = 0; r->ode && k < r->nst; k++) json_row(r, r->st_u[k], 1, r->st_print[k], "state", &first, out);
  bg_sb_puts(out, "]");
}

bg_sym *bg_eqred_sym(bg_eqred *r) { return r->S; }
