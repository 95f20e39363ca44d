/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_eqsys: derivation of one equation per bond variable from the causal
 * strokes (docs/equations.md), the unknowns, and the public accessors.
 * Sorting and tearing are in eqsys_order.c, evaluation in eqsys_tape.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsys_int.h"
#include "model/model.h"
#include "analysis/analysis.h"

/* ------------------------------------------------------------ equation trees */
static int new_node(bg_eqsys *s, int kind, int a, int b, double c) {
  if (s->nnode == s->capnode) {
    s->capnode = s->capnode ? 2 * s->capnode : 256;
    s->node = bg_xrealloc(s->node, (size_t)s->capnode * sizeof *s->node);
  }
  s->node[s->nnode] = (eq_node){kind, a, b, c};
  return s->nnode++;
}

static int lin_push(bg_eqsys *s, double c, int nd) {
  if (s->nlin == s->caplin) {
    s->caplin = s->caplin ? 2 * s->caplin : 256;
    s->lin_coef = bg_xrealloc(s->lin_coef, (size_t)s->caplin * sizeof *s->lin_coef);
    s->lin_node = bg_xrealloc(s->lin_node, (size_t)s->caplin * sizeof *s->lin_node);
  }
  s->lin_coef[s->nlin] = c;
  s->lin_node[s->nlin] = nd;
  return s->nlin++;
}

static int n_sig(bg_eqsys *s, int sig) { return new_node(s, EQ_SIG, sig, 0, 0); }
static int n_x(bg_eqsys *s, int root) { return new_node(s, EQ_X, root, 0, 0); }
static int n_mul(bg_eqsys *s, int x, int y) { return new_node(s, EQ_MUL, x, y, 0); }
static int n_div(bg_eqsys *s, int x, int y) { return new_node(s, EQ_DIV, x, y, 0); }
/* c1*x1 + c2*x2 (x2 < 0: one term). */
static int n_lin2(bg_eqsys *s, double c1, int x1, double c2, int x2) {
  int adr = lin_push(s, c1, x1);
  if (x2 >= 0) lin_push(s, c2, x2);
  return new_node(s, EQ_LIN, adr, x2 >= 0 ? 2 : 1, 0);
}
/* x scaled by sg (+1: x itself). */
static int n_signed(bg_eqsys *s, int sg, int x) { return sg > 0 ? x : n_lin2(s, -1, x, 0, -1); }

/* ------------------------------------------------------------ names */
/* "R1.e" for a 1-port's bond, else "e4"; arena-owned. */
const char *bg_eqs_signame(const bg_eqsys *s, int sig, bg_arena *ar) {
  const bg_model *m = s->m;
  int b = sig / 2, fl = sig & 1, port = -1;
  if (bg_elem_is_oneport(m->elem_kind[m->bond_head[b]])) port = m->bond_head[b];
  else if (bg_elem_is_oneport(m->elem_kind[m->bond_tail[b]])) port = m->bond_tail[b];
  char buf[300];
  if (port >= 0) snprintf(buf, sizeof buf, "%s.%c", m->elem_name[port], fl ? 'f' : 'e');
  else snprintf(buf, sizeof buf, "%c%d", fl ? 'f' : 'e', m->bond_num[b]);
  return bg_arena_strdup(ar, buf);
}

/* ------------------------------------------------------------ derivation */
typedef struct derive {
  bg_eqsys *s;
  bg_diags *dg;
  int bad;
} derive;

/* A bond split by an inserted Lagrange 1-junction has two efforts, one at
 * each original end, and one flow, the inserted junction's (a generalised
 * velocity). Its tail's relation gives e_b; the head's relation says what
 * the effort at the head must be, and the inserted junction's effort balance
 * (no source or store on it: the efforts into the artificial flow source sum
 * to zero, Section 4.10.3) makes the two equal. So the head's relation
 * becomes the implicit equation of the flow: 0 = e_b - (head's effort), or
 * the head's own residual when it is implicit already. */
static int split_head(bg_eqsys *s, int *sig, int *form, int *root, int elem) {
  int b = *sig / 2;
  if ((*sig & 1) || !bg_analysis_bond_split(s->a, b) || s->m->bond_head[b] != elem) return 0;
  if (*form == EQF_EXPLICIT) *root = n_lin2(s, 1, new_node(s, EQ_SIG, *sig, 0, 0), -1, *root);
  *form = EQF_IMPLICIT;
  *sig += 1;
  return 1;
}

static void set_eq(derive *d, int sig, int form, int root, int elem, const char *what) {
  bg_eqsys *s = d->s;
  if (split_head(s, &sig, &form, &root, elem)) what = "inserted junction";
  if (s->sig_root[sig] >= 0) { /* two producers: causality inconsistent */
    d->bad = 1;
    return;
  }
  s->sig_form[sig] = form;
  s->sig_root[sig] = root;
  s->sig_elem[sig] = elem;
  s->sig_what[sig] = what;
}

static int sigma(const bg_model *m, int b, int e) { return m->bond_head[b] == e ? 1 : -1; }
static int recv_e(const bg_eqsys *s, int e, int b) { return bg_paths_effort_in(s->m, s->a, e, b); }

/* Sum of sigma_x * signal over the junction's bonds except `skip`, scaled by k. */
static int junction_sum(bg_eqsys *s, int e, int fl, int skip, double k) {
  const bg_model *m = s->m;
  int adr = s->nlin, cnt = 0;
  for (int i = 0; i < m->elem_nbond[e]; i++) {
    int x = m->elem_bonds[m->elem_bondadr[e] + i];
    if (x == skip) continue;
    lin_push(s, k * sigma(m, x, e), n_sig(s, 2 * x + fl));
    cnt++;
  }
  return new_node(s, EQ_LIN, adr, cnt, 0); /* n_sig adds no terms: contiguous */
}

/* 0-junction (fl = 1: its flows balance, efforts equal) or 1-junction (fl = 0).
 * Strong bonds: those whose `fl` signal the junction computes. */
static void eq_junction(derive *d, int e) {
  bg_eqsys *s = d->s;
  const bg_model *m = s->m;
  int zero = m->elem_kind[e] == BG_ELEM_J0, fl = zero ? 1 : 0, common = 1 - fl;
  /* The strong bond that computes the balance (the others' balances are
   * residuals: a type 2 conflict) and, without one, the bond whose variable
   * is solved implicitly: the lowest bond number, not the first bond
   * statement, so reordering the statements keeps the equations (the
   * analysis names the same ones; docs/property.md, finding 20). */
  int s0 = -1, w0 = -1;
  for (int i = 0; i < m->elem_nbond[e]; i++) {
    int b = m->elem_bonds[m->elem_bondadr[e] + i];
    if (recv_e(s, e, b) == zero && (s0 < 0 || m->bond_num[b] < m->bond_num[s0])) s0 = b;
    if (w0 < 0 || m->bond_num[b] < m->bond_num[w0]) w0 = b;
  }
  if (s0 < 0) { /* type 1 conflict: no strong bond; balance solved implicitly */
    set_eq(d, 2 * w0 + common, EQF_IMPLICIT, junction_sum(s, e, fl, -1, 1), e, "balance");
    for (int i = 0; i < m->elem_nbond[e]; i++) {
      int w = m->elem_bonds[m->elem_bondadr[e] + i];
      if (w != w0) set_eq(d, 2 * w + common, EQF_EXPLICIT, n_sig(s, 2 * w0 + common), e, "junction");
    }
    return;
  }
  for (int i = 0; i < m->elem_nbond[e]; i++) {
    int b = m->elem_bonds[m->elem_bondadr[e] + i];
    if (b == s0)
      set_eq(d, 2 * b + fl, EQF_EXPLICIT, junction_sum(s, e, fl, s0, -sigma(m, s0, e)), e,
             "balance");
    else if (recv_e(s, e, b) != zero) /* weak: shares the common variable */
      set_eq(d, 2 * b + common, EQF_EXPLICIT, n_sig(s, 2 * s0 + common), e, "junction");
    else /* a second strong bond (type 2 conflict): its common variable must agree */
      set_eq(d, 2 * b + fl, EQF_IMPLICIT,
             n_lin2(s, 1, n_sig(s, 2 * b + common), -1, n_sig(s, 2 * s0 + common)), e,
             "junction");
  }
}

/* c*x - y, a residual. */
static int n_res(bg_eqsys *s, int c, int x, int y) {
  return n_lin2(s, 1, c >= 0 ? n_mul(s, c, x) : x, -1, y);
}

/* TF a -> TF -> b: e_b = n e_a, f_a = n f_b. GY: e_a = r f_b, e_b = r f_a. */
static void eq_twoport(derive *d, int e) {
  bg_eqsys *s = d->s;
  const bg_model *m = s->m;
  int a = bg_elem_in_bond(m, e), b = bg_elem_out_bond(m, e);
  int ra = recv_e(s, e, a), rb = recv_e(s, e, b), k = m->elem_kind[e];
  int ea = 2 * a, fa = 2 * a + 1, eb = 2 * b, fb = 2 * b + 1;
  const char *w = "modulus";
  if (k == BG_ELEM_TF || k == BG_ELEM_MTF) {
    if (ra && !rb) {
      set_eq(d, eb, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, ea)), e, w);
      set_eq(d, fa, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fb)), e, w);
    } else if (!ra && rb) {
      set_eq(d, ea, EQF_EXPLICIT, n_div(s, n_sig(s, eb), n_x(s, m->elem_expr[e])), e, w);
      set_eq(d, fb, EQF_EXPLICIT, n_div(s, n_sig(s, fa), n_x(s, m->elem_expr[e])), e, w);
    } else if (ra) { /* both at: type 2 conflict */
      set_eq(d, fa, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fb)), e, w);
      set_eq(d, fb, EQF_IMPLICIT, n_res(s, n_x(s, m->elem_expr[e]), n_sig(s, ea), n_sig(s, eb)),
             e, w);
    } else { /* both away: type 1 conflict */
      set_eq(d, eb, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, ea)), e, w);
      set_eq(d, ea, EQF_IMPLICIT, n_res(s, n_x(s, m->elem_expr[e]), n_sig(s, fb), n_sig(s, fa)),
             e, w);
    }
    return;
  }
  w = "ratio";
  if (!ra && !rb) {
    set_eq(d, ea, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fb)), e, w);
    set_eq(d, eb, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fa)), e, w);
  } else if (ra && rb) {
    set_eq(d, fb, EQF_EXPLICIT, n_div(s, n_sig(s, ea), n_x(s, m->elem_expr[e])), e, w);
    set_eq(d, fa, EQF_EXPLICIT, n_div(s, n_sig(s, eb), n_x(s, m->elem_expr[e])), e, w);
  } else if (!ra) { /* mixed: type 2 conflict */
    set_eq(d, ea, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fb)), e, w);
    set_eq(d, fb, EQF_IMPLICIT, n_res(s, n_x(s, m->elem_expr[e]), n_sig(s, fa), n_sig(s, eb)),
           e, w);
  } else {
    set_eq(d, eb, EQF_EXPLICIT, n_mul(s, n_x(s, m->elem_expr[e]), n_sig(s, fa)), e, w);
    set_eq(d, fa, EQF_IMPLICIT, n_res(s, n_x(s, m->elem_expr[e]), n_sig(s, fb), n_sig(s, ea)),
           e, w);
  }
}

static void eq_source(derive *d, int e, int b) {
  bg_eqsys *s = d->s;
  int k = s->m->elem_kind[e], is_e = k == BG_ELEM_SE || k == BG_ELEM_MSE;
  int own = is_e ? 2 * b : 2 * b + 1, other = is_e ? 2 * b + 1 : 2 * b;
  int value = n_x(s, s->m->elem_expr[e]);
  if (recv_e(s, e, b) != is_e) set_eq(d, own, EQF_EXPLICIT, value, e, "value");
  else /* a source against its type (conflict): its own variable still holds */
    set_eq(d, other, EQF_IMPLICIT, n_lin2(s, 1, n_sig(s, own), -1, value), e, "value");
}

/* R: value form e = s R f / f = s e / R. A law is written for the element's
 * own variables, e and s f (its compiled f already reads s f): e = F(s f)
 * explicit, s f = G(e) gives f = s G(e); inverted laws are implicit residuals. */
static void eq_resistor(derive *d, int e, int b) {
  bg_eqsys *s = d->s;
  const bg_model *m = s->m;
  int sg = sigma(m, b, e), res = !recv_e(s, e, b), form = m->elem_form[e];
  int eb = 2 * b, fb = 2 * b + 1, x = m->elem_expr[e];
  if (form == BG_FORM_VALUE) {
    if (res) set_eq(d, eb, EQF_EXPLICIT, n_mul(s, n_x(s, x), n_signed(s, sg, n_sig(s, fb))), e, "value");
    else set_eq(d, fb, EQF_EXPLICIT, n_div(s, n_signed(s, sg, n_sig(s, eb)), n_x(s, x)), e, "value");
    return;
  }
  int law_e = form == BG_FORM_LAW_E, own = res ? eb : fb;
  int lhs_sign = law_e ? 1 : sg; /* the law's left side is e, or the own flow s f */
  if (law_e == res) set_eq(d, own, EQF_EXPLICIT, n_signed(s, lhs_sign, n_x(s, x)), e, "law");
  else
    set_eq(d, own, EQF_IMPLICIT, n_lin2(s, 1, n_x(s, x), -lhs_sign, n_sig(s, law_e ? eb : fb)), e,
           "law");
}

/* C (q, e = q/C or the law) and I (p, f = p/I or the law). Integral: the
 * state's row is its balance; derivative: the row is the constraint
 * (Equation 4.19) and the output is the state's derivative. */
static void eq_store(derive *d, int e, int b) {
  bg_eqsys *s = d->s;
  const bg_model *m = s->m;
  int isc = m->elem_kind[e] == BG_ELEM_C, sg = sigma(m, b, e), y = s->store_y[e];
  int st = isc ? 2 * b : 2 * b + 1, in = isc ? 2 * b + 1 : 2 * b; /* state-side, rate-side */
  int integral = bg_paths_store_integral(m, s->a, e), x = m->elem_expr[e];
  int val = m->elem_form[e] == BG_FORM_VALUE;
  if (integral) {
    int out = val ? n_div(s, new_node(s, EQ_Y, y, 0, 0), n_x(s, x)) : n_x(s, x);
    set_eq(d, st, EQF_EXPLICIT, out, e, val ? "value" : "law");
    s->row_kind[y] = 0;
    s->row_root[y] = n_signed(s, sg, n_sig(s, in));
    return;
  }
  set_eq(d, in, EQF_EXPLICIT, n_signed(s, sg, new_node(s, EQ_YP, y, 0, 0)), e, "rate");
  s->row_kind[y] = 1;
  s->row_root[y] = val ? n_lin2(s, 1, new_node(s, EQ_Y, y, 0, 0), -1,
                                n_mul(s, n_x(s, x), n_sig(s, st)))
                       : n_lin2(s, 1, n_x(s, x), -1, n_sig(s, st));
}

static void derive_all(derive *d) {
  const bg_model *m = d->s->m;
  for (int e = 0; e < m->nelem; e++) {
    int k = m->elem_kind[e];
    if (bg_elem_is_junction(k)) eq_junction(d, e);
    else if (bg_elem_is_twoport(k)) eq_twoport(d, e);
    else {
      int b = bg_elem_port_bond(m, e);
      if (bg_elem_is_source(k)) eq_source(d, e, b);
      else if (k == BG_ELEM_R) eq_resistor(d, e, b);
      else eq_store(d, e, b);
    }
  }
}

/* ------------------------------------------------------------ unknowns */
static void add_unknowns(bg_eqsys *s) {
  const bg_model *m = s->m;
  int n = 0, cap = m->nelem + m->nstate + s->nsig;
  s->uname = bg_arena_alloc(&s->arena, (size_t)cap * sizeof *s->uname);
  s->u_elem = bg_arena_alloc(&s->arena, (size_t)cap * sizeof(int));
  s->u_state = bg_arena_alloc(&s->arena, (size_t)cap * sizeof(int));
  s->u_sig = bg_arena_alloc(&s->arena, (size_t)cap * sizeof(int));
  s->row_kind = bg_arena_alloc(&s->arena, (size_t)cap * sizeof(int));
  s->row_root = bg_arena_alloc(&s->arena, (size_t)cap * sizeof(int));
  char buf[300];
  for (int pass = 0; pass < 3; pass++) {
    if (pass == 1) {
      for (int k = 0; k < m->nstate; k++, n++) {
        s->uname[n] = m->state_name[k];
        s->u_elem[n] = -1, s->u_state[n] = k, s->u_sig[n] = -1;
      }
      s->nint = n;
      continue;
    }
    for (int e = 0; e < m->nelem; e++) {
      if (!bg_elem_is_store(m->elem_kind[e])) continue;
      if (bg_paths_store_integral(m, s->a, e) != (pass == 0)) continue;
      snprintf(buf, sizeof buf, "%s.%c", m->elem_name[e], m->elem_kind[e] == BG_ELEM_C ? 'q' : 'p');
      s->uname[n] = bg_arena_strdup(&s->arena, buf);
      s->u_elem[n] = e, s->u_state[n] = -1, s->u_sig[n] = -1;
      s->store_y[e] = n++;
      if (pass == 2) s->ndep++;
    }
  }
  s->nx = n;
}

/* Algebraic unknowns: the torn signals, in the order tearing chose them. */
static void add_z(bg_eqsys *s, int sig) {
  int i = s->nx + s->nz++;
  s->sig_torn[sig] = 1;
  s->sig_z[sig] = i;
  s->uname[i] = bg_eqs_signame(s, sig, &s->arena);
  for (int k = 0; k < s->a->nlag; k++) /* an artificial flow source's flow: "ma.f" */
    if (s->a->lag_junction[k] == s->sig_elem[sig] && (sig & 1)) {
      char buf[300];
      snprintf(buf, sizeof buf, "%s.f", s->m->elem_name[s->sig_elem[sig]]);
      s->uname[i] = bg_arena_strdup(&s->arena, buf);
    }
  s->u_elem[i] = -1, s->u_state[i] = -1, s->u_sig[i] = sig;
  s->row_kind[i] = 1;
  s->row_root[i] = s->sig_form[sig] == EQF_IMPLICIT
                       ? s->sig_root[sig]
                       : n_lin2(s, 1, n_sig(s, sig), -1, s->sig_root[sig]);
}

static bg_eqsys *alloc_sys(const bg_model *m, const bg_analysis *a) {
  bg_eqsys *s = bg_xcalloc(1, sizeof *s);
  s->m = m, s->a = a, s->nsig = 2 * m->nbond;
  int ns = s->nsig > 0 ? s->nsig : 1;
  s->sig_form = bg_arena_alloc(&s->arena, (size_t)ns * sizeof(int));
  s->sig_root = bg_arena_alloc(&s->arena, (size_t)ns * sizeof(int));
  s->sig_elem = bg_arena_alloc(&s->arena, (size_t)ns * sizeof(int));
  s->sig_what = bg_arena_alloc(&s->arena, (size_t)ns * sizeof(char *));
  s->sig_torn = bg_arena_alloc(&s->arena, (size_t)ns * sizeof(int));
  s->sig_z = bg_arena_alloc(&s->arena, (size_t)ns * sizeof(int));
  for (int i = 0; i < s->nsig; i++) s->sig_root[i] = -1, s->sig_z[i] = -1;
  s->store_y = bg_arena_alloc(&s->arena, (size_t)(m->nelem + 1) * sizeof(int));
  for (int e = 0; e < m->nelem; e++) s->store_y[e] = -1;
  return s;
}

static int user_state_rows(bg_eqsys *s) {
  for (int i = 0; i < s->nx; i++)
    if (s->u_state[i] >= 0) {
      s->row_kind[i] = 0;
      s->row_root[i] = n_x(s, s->m->state_expr[s->u_state[i]]);
    }
  return 0;
}

static bg_eqsys *build(const bg_model *m, const bg_analysis *a, const int *inputs, int nu,
                       bg_diags *dg, int live) {
  bg_srcloc none = {0};
  if (!a->complete) {
    bg_diag_error(dg, none, "the causality is incomplete: no equations can be derived");
    return NULL;
  }
  bg_eqsys *s = alloc_sys(m, a);
  add_unknowns(s);
  bg_eqs_sym_lookups(s);
  user_state_rows(s);
  derive d = {s, dg, 0};
  derive_all(&d);
  for (int i = 0; i < s->nsig && !d.bad; i++) d.bad = s->sig_root[i] < 0;
  if (d.bad) {
    bg_diag_error(dg, none, "the strokes do not give every bond variable exactly one "
                            "equation; no equations can be derived");
    bg_eqsys_free(s);
    return NULL;
  }
  bg_eqs_deps(s);
  int *torn = bg_xmalloc(((size_t)s->nsig + 1) * sizeof *torn);
  int nt = bg_eqs_sort(s, torn); /* tears: the algebraic unknowns */
  for (int i = 0; i < nt; i++) add_z(s, torn[i]);
  free(torn);
  s->n = s->nx + s->nz;
  if (inputs) {
    s->lin_nu = nu, s->lin_nh = m->noutput;
    s->lin_ref = bg_arena_alloc(&s->arena, (size_t)(nu + 1) * sizeof(int));
    s->lin_uslot = bg_arena_alloc(&s->arena, (size_t)(nu + 1) * sizeof(int));
    s->lin_hslot = bg_arena_alloc(&s->arena, (size_t)(m->noutput + 1) * sizeof(int));
    memcpy(s->lin_ref, inputs, (size_t)nu * sizeof(int));
  }
  s->live_params = live;
  bg_eqs_compile(s);
  bg_eqs_pattern(s);
  bg_eqs_events_find(s);
  s->work = bg_arena_alloc(&s->arena, (size_t)(s->n + 1) * sizeof(double));
  return s;
}

bg_eqsys *bg_eqsys_build(const bg_model *m, const bg_analysis *a, bg_diags *dg) {
  return build(m, a, NULL, 0, dg, 0);
}

bg_eqsys *bg_eqsys_build_io(const bg_model *m, const bg_analysis *a, const int *inputs, int nu,
                            bg_diags *dg) {
  static const int none = 0;
  return build(m, a, inputs ? inputs : &none, inputs ? nu : 0, dg, 0);
}

bg_eqsys *bg_eqsys_build_export(const bg_model *m, const bg_analysis *a, bg_diags *dg) {
  return build(m, a, NULL, 0, dg, 1);
}

void bg_eqsys_free(bg_eqsys *s) {
  if (!s) return;
  bg_eqs_tape_free(s);
  free(s->node);
  free(s->lin_coef);
  free(s->lin_node);
  bg_arena_free(&s->arena);
  free(s);
}
