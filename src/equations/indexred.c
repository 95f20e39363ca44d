/* SPDX-License-Identifier: BSD-3-Clause */
/* Index reduction: Pantelides' algorithm on the structure of the equations,
 * then the dummy derivatives of Mattsson and Soederlind (indexred.h,
 * docs/equations.md "Index reduction"). The reduced system is built in
 * indexred_build.c; graph searches use explicit stacks. */
#include <float.h>
#include "base/lapack.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsym.h"
#include "equations/index.h"
#include "equations/indexred_int.h"
#include "base/sort.h"

enum {
  IR_MAX_UNKNOWNS = 500, /* dense selection and index check, like the numeric index */
  IR_MAX_ORDER = 4,      /* an equation differentiated more often: give up */
  IR_MAX_NODES = 400000  /* symbolic nodes: derivatives of large models grow */
};

/* ------------------------------------------------------------ variables and equations */
static void grow(void **p, int cap, size_t sz) { *p = bg_xrealloc(*p, (size_t)cap * sz); }

static int new_var(ir_work *W, int unk, int ord, int anti) {
  if (W->nv == W->capv) {
    W->capv = W->capv ? 2 * W->capv : 64;
    int **a[] = {&W->v_unk, &W->v_ord, &W->v_der, &W->v_anti, &W->assign};
    for (size_t k = 0; k < sizeof a / sizeof *a; k++) grow((void **)a[k], W->capv, sizeof(int));
    grow((void **)&W->v_dummy, W->capv, 1);
  }
  int v = W->nv++;
  W->v_unk[v] = unk, W->v_ord[v] = ord, W->v_der[v] = -1, W->v_anti[v] = anti;
  W->assign[v] = -1, W->v_dummy[v] = 0;
  if (anti >= 0) W->v_der[anti] = v;
  return v;
}

static int new_eq(ir_work *W, int expr, int row, int ord, int anti) {
  if (W->ne == W->cape) {
    W->cape = W->cape ? 2 * W->cape : 64;
    int **a[] = {&W->e_expr, &W->e_der, &W->e_anti, &W->e_row, &W->e_ord, &W->inc_adr, &W->inc_n};
    for (size_t k = 0; k < sizeof a / sizeof *a; k++) grow((void **)a[k], W->cape, sizeof(int));
  }
  int e = W->ne++;
  W->e_expr[e] = expr, W->e_der[e] = -1, W->e_anti[e] = anti, W->e_row[e] = row, W->e_ord[e] = ord;
  if (anti >= 0) W->e_der[anti] = e;
  return e;
}

/* Variables by the name of their unknown (natural order), then by order of
 * derivative; equations by the name of the unknown of their row. Pantelides'
 * searches go in these orders, not in the order of the unknowns and rows,
 * which follows the statements (docs/property.md, finding 2c). */
static int cmp_var_name(const void *a, const void *b, void *ctx) {
  const ir_work *W = ctx;
  int va = *(const int *)a, vb = *(const int *)b, ja = W->v_unk[va], jb = W->v_unk[vb];
  int c = ja == jb ? 0 : bg_eqsys_name_cmp(bg_eqsys_name(W->s, ja), bg_eqsys_name(W->s, jb));
  if (c) return c;
  if (ja != jb) return ja < jb ? -1 : 1;
  return (W->v_ord[va] > W->v_ord[vb]) - (W->v_ord[va] < W->v_ord[vb]);
}

static int cmp_eq_name(const void *a, const void *b, void *ctx) {
  const ir_work *W = ctx;
  int ra = W->e_row[*(const int *)a], rb = W->e_row[*(const int *)b];
  int c = ra == rb ? 0 : bg_eqsys_name_cmp(bg_eqsys_name(W->s, ra), bg_eqsys_name(W->s, rb));
  return c ? c : (ra > rb) - (ra < rb);
}

/* Incidence of a new equation: its variables (original equations, by name),
 * or Pantelides' rule for a derivative: the parent's variables and theirs. */
static void set_incidence(ir_work *W, int e) {
  W->inc_adr[e] = W->inc.n;
  int l = W->e_anti[e];
  if (l < 0) {
    ir_expr_vars(W, W->e_expr[e], &W->inc);
    bg_sort(W->inc.v + W->inc_adr[e], (size_t)(W->inc.n - W->inc_adr[e]), sizeof(int), cmp_var_name, W);
  } else
    for (int k = 0; k < W->inc_n[l]; k++) {
      int v = W->inc.v[W->inc_adr[l] + k];
      bg_ivec_push(&W->inc, v);
      if (W->v_der[v] < 0) new_var(W, W->v_unk[v], W->v_ord[v] + 1, v);
      bg_ivec_push(&W->inc, W->v_der[v]);
    }
  W->inc_n[e] = W->inc.n - W->inc_adr[e];
}

/* d e / dt = de/dt + sum_v de/dv v'. */
static int time_derivative(ir_work *W, int e) {
  bg_sym *S = W->S;
  bg_ivec vars = {0};
  ir_expr_vars(W, e, &vars);
  int *t = bg_xmalloc((size_t)(vars.n + 1) * sizeof(int)), k = 0;
  for (int q = 0; q < vars.n; q++) {
    int v = vars.v[q], d = bg_sym_diff(S, e, ir_var_leaf(W, v));
    if (S->node[d].kind == SYM_NUM && S->node[d].c == 0) continue;
    if (W->v_der[v] < 0) new_var(W, W->v_unk[v], W->v_ord[v] + 1, v);
    t[k++] = bg_sym_mul(S, d, ir_var_leaf(W, W->v_der[v]));
  }
  t[k++] = bg_sym_diff(S, e, bg_sym_leaf(S, SYM_T, 0));
  int r = bg_sym_sum(S, 0, k, t, NULL);
  free(t), free(vars.v);
  return r;
}

/* ------------------------------------------------------------ the rows as variables */
typedef struct subst_ctx { ir_work *W; const int *yp_var; } subst_ctx;

/* Params at their values (a loop gain n = 1 cancels exactly), yp_j as the
 * variable (j, 1). */
static int rows_cb(void *ctx, int kind, int ref) {
  subst_ctx *c = ctx;
  if (kind == SYM_PARAM) return bg_sym_num(c->W->S, c->W->s->m->param_value[ref]);
  if (kind == SYM_YP) return ir_var_leaf(c->W, c->yp_var[ref]);
  return -1;
}

static int setup(ir_work *W) {
  const bg_eqsys *s = W->s;
  int n = s->n, *rows = bg_xmalloc((size_t)(n + 1) * sizeof(int));
  int *yp_var = bg_xmalloc((size_t)(n + 1) * sizeof(int));
  W->sig = bg_xmalloc((size_t)(s->nsig + 1) * sizeof(int));
  if (bg_eqsym_rows_signals(W->S, s, rows, W->sig)) {
    free(rows), free(yp_var);
    snprintf(W->why, sizeof W->why, "the model is too large for the symbolic equations");
    return -1;
  }
  for (int j = 0; j < n; j++) new_var(W, j, 0, -1);
  for (int j = 0; j < n; j++) yp_var[j] = j < s->nx ? new_var(W, j, 1, j) : -1;
  subst_ctx c = {W, yp_var};
  W->row_sym = rows;
  for (int i = 0; i < n; i++) {
    int r = rows[i];
    if (s->row_kind[i] == 0) r = bg_sym_sub(W->S, bg_sym_leaf(W->S, SYM_YP, i), r);
    rows[i] = r;
    int e = new_eq(W, bg_sym_subst(W->S, r, rows_cb, &c), i, 0, -1);
    set_incidence(W, e);
  }
  for (int v = 0; v < s->nsig; v++) W->sig[v] = bg_sym_subst(W->S, W->sig[v], rows_cb, &c);
  free(yp_var);
  return 0;
}

/* ------------------------------------------------------------ Pantelides */
typedef struct colours { int *ce, *cv, stamp; } colours;

/* Augmenting path from equation e0 over the highest derivatives (variables
 * without a derivative), colouring what it visits; explicit stack. */
static int augment(ir_work *W, int e0, colours *C, int *st_e, int *st_p, int *st_v) {
  int d = 0;
  st_e[0] = e0, st_p[0] = -1, C->ce[e0] = C->stamp;
  while (d >= 0) {
    int e = st_e[d], a = W->inc_adr[e], cnt = W->inc_n[e];
    if (st_p[d] < 0) { /* first visit: an unmatched variable ends the path */
      st_p[d] = 0;
      for (int k = 0; k < cnt; k++) {
        int v = W->inc.v[a + k];
        if (W->v_der[v] >= 0 || W->assign[v] >= 0) continue;
        W->assign[v] = e;
        for (int q = d - 1; q >= 0; q--) W->assign[st_v[q]] = st_e[q];
        return 1;
      }
    }
    int next = -1;
    while (st_p[d] < cnt && next < 0) {
      int v = W->inc.v[a + st_p[d]++];
      if (W->v_der[v] < 0 && C->cv[v] != C->stamp) next = v;
    }
    if (next < 0) { d--; continue; }
    C->cv[next] = C->stamp;
    st_v[d] = next;
    int e2 = W->assign[next];
    if (e2 < 0 || C->ce[e2] == C->stamp) continue;
    C->ce[e2] = C->stamp;
    d++;
    st_e[d] = e2, st_p[d] = -1;
  }
  return 0;
}

/* The coloured variables get derivatives, the coloured equations are
 * differentiated, and the matching moves up to the derivatives. */
static int differentiate_coloured(ir_work *W, colours *C, int nv0, int ne0) {
  for (int v = 0; v < nv0; v++)
    if (C->cv[v] == C->stamp && W->v_der[v] < 0) new_var(W, W->v_unk[v], W->v_ord[v] + 1, v);
  for (int e = 0; e < ne0; e++) {
    if (C->ce[e] != C->stamp) continue;
    if (W->e_ord[e] + 1 > IR_MAX_ORDER) {
      snprintf(W->why, sizeof W->why, "an equation would be differentiated more than %d times "
               "(Pantelides' algorithm does not terminate: the equations are structurally singular)",
               IR_MAX_ORDER);
      return -1;
    }
    int d = new_eq(W, time_derivative(W, W->e_expr[e]), W->e_row[e], W->e_ord[e] + 1, e);
    set_incidence(W, d);
  }
  for (int v = 0; v < nv0; v++)
    if (C->cv[v] == C->stamp) W->assign[W->v_der[v]] = W->e_der[W->assign[v]];
  return 0;
}

/* Why the symbolic work stopped: the node limit or the work budget. */
static void too_large(ir_work *W) {
  if (bg_sym_over(W->S))
    snprintf(W->why, sizeof W->why, "the differentiated equations exceed the symbolic work budget "
             "of " BG_SYM_BUDGET_WORDS " operations");
  else snprintf(W->why, sizeof W->why, "the differentiated equations grow too large");
}

static int pantelides(ir_work *W) {
  int n0 = W->ne, *order = bg_xmalloc((size_t)(n0 + 1) * sizeof(int));
  for (int k = 0; k < n0; k++) order[k] = k;
  bg_sort(order, (size_t)n0, sizeof(int), cmp_eq_name, W);
  for (int k = 0; k < n0; k++) {
    for (int i = order[k];;) {
      int cap = W->ne + W->nv + 1;
      colours C = {bg_xcalloc((size_t)cap, sizeof(int)), bg_xcalloc((size_t)cap, sizeof(int)), 1};
      int *st = bg_xmalloc((size_t)3 * cap * sizeof(int));
      int ok = augment(W, i, &C, st, st + cap, st + 2 * cap);
      int rc = ok ? 0 : differentiate_coloured(W, &C, W->nv, W->ne);
      free(st), free(C.ce), free(C.cv);
      if (ok) break;
      if (rc || bg_sym_full(W->S)) {
        if (!W->why[0]) too_large(W);
        free(order);
        return -1;
      }
      i = W->e_der[i];
    }
  }
  free(order);
  return 0;
}

/* Pantelides' algorithm needs a structurally regular system: a matching of
 * the equations to the variables of any order. */
static int structurally_regular(ir_work *W) {
  int *save = bg_xmalloc((size_t)W->nv * sizeof(int)), *der = bg_xmalloc((size_t)W->nv * sizeof(int));
  memcpy(save, W->assign, (size_t)W->nv * sizeof(int));
  memcpy(der, W->v_der, (size_t)W->nv * sizeof(int));
  for (int v = 0; v < W->nv; v++) W->v_der[v] = -1; /* every variable eligible */
  int cap = W->ne + W->nv + 1, ok = 1;
  colours C = {bg_xcalloc((size_t)cap, sizeof(int)), bg_xcalloc((size_t)cap, sizeof(int)), 0};
  int *st = bg_xmalloc((size_t)3 * cap * sizeof(int));
  for (int e = 0; e < W->ne && ok; e++) {
    C.stamp++;
    ok = augment(W, e, &C, st, st + cap, st + 2 * cap);
    if (!ok) {
      bg_strbuf sb = {0};
      bg_sym_print(W->S, W->row_sym[W->e_row[e]], 0, bg_eqsym_name, (void *)W->s, &sb);
      snprintf(W->why, sizeof W->why, "the equations are structurally singular: the equation of %s "
               "(0 = %s) has no unknown of its own (it constrains inputs or parameters alone, or "
               "the equations do not determine every unknown)", bg_eqsys_name(W->s, W->e_row[e]),
               bg_sb_str(&sb));
      bg_sb_free(&sb);
    }
  }
  memcpy(W->assign, save, (size_t)W->nv * sizeof(int));
  memcpy(W->v_der, der, (size_t)W->nv * sizeof(int));
  free(save), free(der), free(C.ce), free(C.cv), free(st);
  return ok ? 0 : -1;
}

/* ------------------------------------------------------------ dummy derivatives */
/* Which derivatives become dummies first (Mattsson-Soederlind leave the
 * choice open among regular ones): an algebraic unknown's (it stays
 * algebraic), a dependent store's (it is in derivative causality already),
 * a state whose initial value the model does not state, then the others;
 * within a group by name (cmp_pref). */
static int pref_group(const ir_work *W, int v) {
  const bg_eqsys *s = W->s;
  const bg_model *m = s->m;
  int j = W->v_unk[v];
  if (j >= s->nx) return 0;
  if (s->row_kind[j] == 1) return 1;
  int root = s->u_elem[j] >= 0 ? m->elem_init[s->u_elem[j]] : s->u_state[j] >= 0 ? m->state_init[s->u_state[j]] : -1;
  return root < 0 ? 2 : 3;
}

/* The store's or state's name, or the algebraic unknown's ("e4", "R1.e"). */
static const char *pref_name(const ir_work *W, int v) {
  const bg_eqsys *s = W->s;
  int j = W->v_unk[v];
  if (j >= s->nx) return bg_eqsys_name(s, j);
  return s->u_elem[j] >= 0 ? s->m->elem_name[s->u_elem[j]]
         : s->u_state[j] >= 0 ? s->m->state_name[s->u_state[j]] : NULL;
}

/* Within a group stores, states and algebraic unknowns go by name (natural order), not by the
 * order of the unknowns, which follows the order of the statements: moving
 * a line must not move a dummy derivative (docs/causality.md, "Ties"). */
static int cmp_pref(const void *a, const void *b, void *ctx) {
  const ir_work *W = ctx;
  int va = *(const int *)a, vb = *(const int *)b;
  int ga = pref_group(W, va), gb = pref_group(W, vb);
  if (ga != gb) return ga < gb ? -1 : 1;
  const char *na = pref_name(W, va), *nb = pref_name(W, vb);
  int c = na && nb && W->v_unk[va] != W->v_unk[vb] ? bg_eqsys_name_cmp(na, nb) : 0;
  if (c) return c;
  int ja = W->v_unk[va], jb = W->v_unk[vb];
  if (ja != jb) return ja < jb ? -1 : 1;
  return (W->v_ord[va] > W->v_ord[vb]) - (W->v_ord[va] < W->v_ord[vb]);
}

/* 1 when the columns of M (rows x cols, column-major) are independent:
 * every column scaled to max 1, smallest singular value above 1e-9 of the largest. */
static int independent(double *M, int rows, int cols) {
  for (int c = 0; c < cols; c++) {
    double mx = 0;
    for (int r = 0; r < rows; r++) mx = fmax(mx, fabs(M[(size_t)c * rows + r]));
    if (!(mx > 0)) return 0;
    for (int r = 0; r < rows; r++) M[(size_t)c * rows + r] /= mx;
  }
  int k = rows < cols ? rows : cols;
  double *sv = bg_xmalloc((size_t)k * sizeof(double)), *sup = bg_xmalloc((size_t)k * sizeof(double)), u, vt;
  int info = LAPACKE_dgesvd(LAPACK_COL_MAJOR, 'N', 'N', rows, cols, M, rows, sv, &u, 1, &vt, 1, sup);
  int ok = info == 0 && cols <= rows && sv[k - 1] > 1e-9 * sv[0];
  free(sv), free(sup);
  return ok;
}

static double jac_entry(ir_work *W, int e, int v) {
  bg_symenv env = {W->s->m->sim.present ? W->s->m->sim.t0 : 0, W->val, NULL, NULL, NULL};
  return bg_sym_eval(W->S, bg_sym_diff(W->S, W->e_expr[e], ir_var_leaf(W, v)), &env);
}

/* nh columns of dH/dZ, in the order of preference, that are independent at
 * the initial point; they become dummy derivatives. Rows scaled by their max. */
static int select_dummies(ir_work *W, const int *H, int nh, int *Z, int nz, int *sel) {
  bg_sort(Z, (size_t)nz, sizeof *Z, cmp_pref, W);
  double *G = bg_xcalloc((size_t)nh * nz + 1, sizeof(double)), *M = bg_xmalloc(((size_t)nh * nz + 1) * sizeof(double));
  for (int c = 0; c < nz && !bg_sym_full(W->S); c++)
    for (int r = 0; r < nh; r++) G[(size_t)c * nh + r] = jac_entry(W, H[r], Z[c]);
  if (bg_sym_full(W->S)) {
    free(G), free(M);
    return -1;
  }
  for (int r = 0; r < nh; r++) {
    double mx = 0;
    for (int c = 0; c < nz; c++) mx = fmax(mx, fabs(G[(size_t)c * nh + r]));
    for (int c = 0; c < nz && mx > 0; c++) G[(size_t)c * nh + r] /= mx;
  }
  int chosen = 0, *idx = bg_xmalloc((size_t)(nh + 1) * sizeof(int));
  for (int c = 0; c < nz && chosen < nh; c++) {
    idx[chosen] = c;
    for (int q = 0; q <= chosen; q++) memcpy(M + (size_t)q * nh, G + (size_t)idx[q] * nh, (size_t)nh * sizeof(double));
    if (independent(M, nh, chosen + 1)) sel[chosen++] = Z[c];
  }
  free(G), free(M), free(idx);
  return chosen == nh ? 0 : -1;
}

/* Level by level from the highest derivatives: the differentiated equations
 * of the level choose as many dummies among the derivatives; one level down,
 * their parents choose among the antiderivatives of the chosen. */
static int dummy_derivatives(ir_work *W) {
  int *H = bg_xmalloc((size_t)(W->ne + 1) * sizeof(int)), *Z = bg_xmalloc((size_t)(W->nv + 1) * sizeof(int));
  int *sel = bg_xmalloc((size_t)(W->ne + 1) * sizeof(int)), nh = 0, nz = 0, rc = 0;
  for (int e = 0; e < W->ne; e++)
    if (W->e_der[e] < 0 && W->e_anti[e] >= 0) H[nh++] = e;
  for (int v = 0; v < W->nv; v++)
    if (W->v_der[v] < 0 && W->v_anti[v] >= 0) Z[nz++] = v;
  while (nh > 0 && rc == 0) {
    if (nz < nh || select_dummies(W, H, nh, Z, nz, sel)) {
      if (bg_sym_full(W->S)) too_large(W);
      else snprintf(W->why, sizeof W->why, "no regular choice of dummy derivatives at the initial "
               "point: the differentiated constraints are singular there");
      rc = -1;
      break;
    }
    for (int k = 0; k < nh; k++) W->v_dummy[sel[k]] = 1;
    int nh2 = 0, nz2 = 0;
    for (int k = 0; k < nh; k++)
      if (W->e_ord[W->e_anti[H[k]]] >= 1) H[nh2++] = W->e_anti[H[k]];
    for (int k = 0; k < nh; k++)
      if (W->v_ord[W->v_anti[sel[k]]] >= 1) Z[nz2++] = W->v_anti[sel[k]];
    nh = nh2, nz = nz2;
  }
  free(H), free(Z), free(sel);
  return rc;
}

/* ------------------------------------------------------------ entry */
static void initial_values(ir_work *W) {
  W->val = bg_xcalloc((size_t)W->nv + 1, sizeof(double));
  bg_eqsys_initial(W->s, W->val); /* the first n variables are the unknowns */
}

/* The numeric index of the reduced system at its consistent initial point. */
static int reduced_index(bg_eqsys *r) {
  int n = bg_eqsys_n(r);
  size_t nn = (size_t)n * n + 1;
  double *y = bg_xcalloc((size_t)n + 1, sizeof(double)), *yp = bg_xcalloc((size_t)n + 1, sizeof(double));
  double *A = bg_xmalloc(nn * sizeof(double)), *B = bg_xmalloc(nn * sizeof(double));
  bg_eqsys_initial_yp(r, y, yp);
  int idx = BG_INDEX_FAILED;
  if (bg_eqsys_linearise(r, r->m->sim.present ? r->m->sim.t0 : 0, y, yp, A, B) == 0) {
    bg_index_result ix;
    idx = bg_index_pencil(A, B, n, &ix);
    bg_index_free(&ix);
  }
  free(y), free(yp), free(A), free(B);
  return idx;
}

static void work_free(ir_work *W) {
  free(W->v_unk), free(W->v_ord), free(W->v_der), free(W->v_anti), free(W->assign), free(W->v_dummy);
  free(W->e_expr), free(W->e_der), free(W->e_anti), free(W->e_row), free(W->e_ord);
  free(W->inc_adr), free(W->inc_n), free(W->inc.v), free(W->row_sym), free(W->sig), free(W->val);
  bg_sym_free(W->S);
}

static int fail(bg_indexred *out, const char *why) {
  out->status = -1;
  free(out->message);
  out->message = strdup(why);
  return -1;
}

static int reduce(ir_work *W, bg_indexred *out) {
  if (W->n > IR_MAX_UNKNOWNS) {
    snprintf(W->why, sizeof W->why, "%d unknowns: more than %d (the choice of dummy derivatives "
             "and the index check are dense)", W->n, IR_MAX_UNKNOWNS);
    return -1;
  }
  if (setup(W) || structurally_regular(W) || pantelides(W)) return -1;
  for (int e = 0; e < W->ne; e++) out->ndiff += W->e_anti[e] >= 0;
  if (out->ndiff == 0) {
    out->structural_le1 = 1;
    snprintf(W->why, sizeof W->why, "the structure of the equations has index 1 or 0 (Pantelides "
             "differentiates nothing), so no structural reduction applies; an index above 1 "
             "could only come from values the structure does not show, and the numeric "
             "index at the initial point decides");
    return -1;
  }
  initial_values(W);
  if (dummy_derivatives(W)) return -1;
  out->reduced = bg_sym_full(W->S) ? NULL : ir_build(W);
  if (out->reduced && bg_sym_full(W->S)) bg_eqsys_free(out->reduced), out->reduced = NULL;
  if (!out->reduced && bg_sym_full(W->S)) too_large(W);
  if (!out->reduced) return -1;
  out->index = reduced_index(out->reduced);
  if (out->index < 0 || out->index > 1) {
    snprintf(W->why, sizeof W->why, "the reduced equations have numeric index %s at the initial point",
             out->index == BG_INDEX_SINGULAR ? "undefined (a singular pencil)" : out->index < 0 ? "unknown (they cannot be evaluated)" : "above 1");
    bg_eqsys_free(out->reduced);
    out->reduced = NULL;
    return -1;
  }
  return 0;
}

int bg_indexred_run(const bg_eqsys *s, bg_indexred *out) {
  memset(out, 0, sizeof *out);
  out->index = -1;
  ir_work W;
  memset(&W, 0, sizeof W);
  W.s = s, W.n = s->n;
  W.S = bg_sym_new(s->m);
  W.S->max_nodes = IR_MAX_NODES;
  W.S->budget = BG_SYM_BUDGET;
  if (reduce(&W, out)) {
    char buf[600];
    snprintf(buf, sizeof buf, "index reduction failed: %s", W.why[0] ? W.why : "unknown reason");
    fail(out, buf);
  } else {
    out->status = 1;
    ir_describe(&W, out);
  }
  work_free(&W);
  return out->status;
}

static void free_list(char **v, int n) {
  for (int k = 0; k < n; k++) free(v[k]);
  free(v);
}

void bg_indexred_free(bg_indexred *r) {
  if (r->reduced) bg_eqsys_free(r->reduced);
  free(r->message);
  free_list(r->constraint, r->nconstraint);
  free_list(r->lost, r->nlost);
  free_list(r->dummy, r->ndummy);
  memset(r, 0, sizeof *r);
}

void bg_indexred_text(const bg_indexred *r, const char *indent, bg_strbuf *out) {
  bg_sb_printf(out, "%s%s\n", indent, r->message ? r->message : "");
  for (int k = 0; k < r->nconstraint; k++) bg_sb_printf(out, "%sdifferentiated: %s\n", indent, r->constraint[k]);
  for (int k = 0; k < r->nlost; k++) bg_sb_printf(out, "%slost its state: %s\n", indent, r->lost[k]);
}
