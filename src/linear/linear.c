/* SPDX-License-Identifier: BSD-3-Clause */
/* Linear analysis driver: inputs, the equation system with perturbable
 * inputs, the operating point, the descriptor form from the exact Jacobians,
 * then reduction, poles and transfer functions (docs/linear.md). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "linear/linear_int.h"

/* The inputs of the linearisation: the `linearise inputs` list, else every
 * source element in file order (refs as bg_eqsys_build_io takes them).
 * Returns the count; refs has room for m->nelem + m->ninput entries. */
static int linear_inputs(const bg_model *m, int *refs) {
  int nu = 0;
  if (m->linear.inputs_given) {
    for (int k = 0; k < m->nlininput; k++) refs[nu++] = m->lininput_ref[k];
    return nu;
  }
  for (int e = 0; e < m->nelem; e++)
    if (bg_elem_is_source(m->elem_kind[e])) refs[nu++] = e;
  return nu;
}

static void set_message(bg_linear *l, const char *msg) {
  free(l->message);
  l->message = msg && *msg ? strdup(msg) : NULL;
}

/* Input and output names; outputs default to the differential unknowns. */
static void io_names(bg_linear *l, const bg_model *m, const bg_eqsys *s, const int *refs) {
  l->uname = bg_xcalloc((size_t)l->nu + 1, sizeof *l->uname);
  for (int k = 0; k < l->nu; k++)
    l->uname[k] = refs[k] >= 0 ? m->elem_name[refs[k]] : m->input_name[-1 - refs[k]];
  l->outputs_are_states = m->noutput == 0;
  l->ny = m->noutput ? m->noutput : bg_eqsys_nx(s);
  l->yname = bg_xcalloc((size_t)l->ny + 1, sizeof *l->yname);
  for (int k = 0; k < l->ny; k++)
    l->yname[k] = m->noutput ? m->output_name[k] : bg_arena_strdup(&l->arena, bg_eqsys_name(s, k));
}

/* E x' = A x + B u, y = C x + Cp x' + D u from F(t, y, yp, u) = 0 and h. */
static int descriptor(bg_linear *l, bg_eqsys *s, const bg_model *m) {
  int N = l->N, nu = l->nu, nh = m->noutput;
  size_t NN = (size_t)N * N;
  double *Fy = bg_xcalloc(NN + 1, sizeof *Fy), *Fyp = bg_xcalloc(NN + 1, sizeof *Fyp);
  double *Fu = bg_xcalloc((size_t)N * nu + 1, sizeof *Fu);
  double *Hy = bg_xcalloc((size_t)nh * N + 1, sizeof *Hy), *Hyp = bg_xcalloc((size_t)nh * N + 1, sizeof *Hyp);
  double *Hu = bg_xcalloc((size_t)nh * nu + 1, sizeof *Hu), *yp = bg_xcalloc((size_t)N + 1, sizeof *yp);
  l->h0 = bg_xcalloc((size_t)l->ny + 1, sizeof *l->h0);
  int rc = bg_eqsys_jac_io(s, l->t, l->y0, yp, Fy, Fyp, Fu, Hy, Hyp, Hu, nh ? l->h0 : NULL);
  if (rc == 0) {
    double *F = bg_xcalloc((size_t)N + 1, sizeof *F);
    bg_eqsys_residual(s, l->t, l->y0, yp, F);
    for (int i = 0; i < N; i++) l->resid = fmax(l->resid, fabs(F[i]));
    free(F);
    for (size_t k = 0; k < NN; k++) Fy[k] = -Fy[k] + 0.0;
    for (size_t k = 0; k < (size_t)N * nu; k++) Fu[k] = -Fu[k] + 0.0;
    l->E = Fyp, l->Ad = Fy, l->Bd = Fu, Fyp = Fy = Fu = NULL;
    if (nh) l->Cd = Hy, l->Cpd = Hyp, l->Dd = Hu, Hy = Hyp = Hu = NULL;
    else { /* outputs: the states */
      l->Cd = bg_xcalloc((size_t)l->ny * N + 1, sizeof *l->Cd);
      l->Cpd = bg_xcalloc((size_t)l->ny * N + 1, sizeof *l->Cpd);
      l->Dd = bg_xcalloc((size_t)l->ny * nu + 1, sizeof *l->Dd);
      for (int k = 0; k < l->ny; k++) l->Cd[(size_t)k * l->ny + k] = 1, l->h0[k] = l->y0[k];
    }
    for (size_t k = 0; k < (size_t)l->ny * N; k++) l->has_cp |= l->Cpd[k] != 0;
  }
  free(Fy), free(Fyp), free(Fu), free(Hy), free(Hyp), free(Hu), free(yp);
  return rc;
}

static void finish(bg_linear *l, const bg_model *m, bg_eqsys *s) {
  /* elimination preference: algebraic unknowns, dependent stores (a
   * differential unknown with a constraint row), the others from the last */
  int *order = bg_xcalloc((size_t)l->N + 1, sizeof *order), k = 0;
  for (int i = 0; i < l->N; i++) if (!bg_eqsys_is_differential(s, i)) order[k++] = i;
  for (int i = 0; i < l->N; i++)
    if (bg_eqsys_is_differential(s, i) && bg_eqsys_is_algebraic_row(s, i)) order[k++] = i;
  for (int i = l->N - 1; i >= 0; i--)
    if (bg_eqsys_is_differential(s, i) && !bg_eqsys_is_algebraic_row(s, i)) order[k++] = i;
  bg_lin_reduce(l, order);
  free(order);
  bg_lin_poles(l);
  bg_lin_tfs(l);
  bg_lin_sym_derive(l, m, s);
}

int bg_linear_compute(const bg_model *m, const bg_analysis *a, int steady, bg_linear *l) {
  memset(l, 0, sizeof *l);
  l->steady = steady < 0 ? m->linear.steady : steady;
  l->t = m->linear.t_given ? m->linear.t : m->sim.present ? m->sim.t0 : 0;
  int *refs = bg_xcalloc((size_t)(m->nelem + m->ninput) + 1, sizeof *refs);
  l->nu = linear_inputs(m, refs);
  bg_diags dg;
  bg_diags_init(&dg, m->path, NULL, 0);
  bg_eqsys *s = bg_eqsys_build_io(m, a, refs, l->nu, &dg);
  if (!s) {
    set_message(l, dg.n ? dg.items[0].msg : "the equations could not be formed");
  } else if ((l->N = bg_eqsys_n(s)) > BG_LIN_MAX_UNKNOWNS) {
    char buf[160];
    snprintf(buf, sizeof buf, "%d unknowns: not linearised (dense matrices, limit %d)", l->N,
             BG_LIN_MAX_UNKNOWNS);
    set_message(l, buf);
  } else {
    io_names(l, m, s, refs);
    l->uname_all = bg_xcalloc((size_t)l->N + 1, sizeof *l->uname_all);
    for (int i = 0; i < l->N; i++) l->uname_all[i] = bg_arena_strdup(&l->arena, bg_eqsys_name(s, i));
    l->y0 = bg_xcalloc((size_t)l->N + 1, sizeof *l->y0);
    bg_strbuf note = {0};
    if (bg_lin_point(s, l->t, l->steady, l->y0, &note) == 0) {
      if (descriptor(l, s, m) == 0) l->ok = 1, finish(l, m, s);
      else bg_sb_printf(&note, "%scannot linearise: %s", note.len ? "; " : "", bg_eqsys_error(s));
    }
    set_message(l, bg_sb_str(&note));
    bg_sb_free(&note);
  }
  if (s) bg_eqsys_free(s);
  bg_diags_free(&dg);
  free(refs);
  return l->ok ? 0 : -1;
}

void bg_linear_free(bg_linear *l) {
  free(l->message), free(l->uname_all), free(l->y0), free(l->h0);
  free(l->uname), free(l->yname);
  free(l->E), free(l->Ad), free(l->Bd), free(l->Cd), free(l->Cpd), free(l->Dd);
  free(l->reduce_note), free(l->elim), free(l->state), free(l->A), free(l->B), free(l->C), free(l->D);
  free(l->pole_re), free(l->pole_im), free(l->tf_note);
  for (int k = 0; k < l->ntf; k++) {
    bg_lin_tf *t = &l->tf[k];
    free(t->num), free(t->den), free(t->pole_re), free(t->pole_im), free(t->zero_re), free(t->zero_im);
  }
  free(l->tf);
  bg_arena_free(&l->arena);
  memset(l, 0, sizeof *l);
}
