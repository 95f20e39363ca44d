/* SPDX-License-Identifier: BSD-3-Clause */
/* The model's named warnings (base/diag.h, docs/cli.md "Warnings"): what
 * compiles but is likely not what the author meant. Read-only over the
 * compiled model: a param no expression reads, a model without elements,
 * a store or transducer whose value is 0 at these parameter values. */
#include <stdlib.h>

#include "model/model.h"
#include "model/model_int.h"

/* Whether the expression at root reads only numbers and params (so its
 * value is fixed before a run): an explicit stack, the depth being the
 * user's. */
static int is_constant(const bg_model *m, int root) {
  int stack[256], n = 0, constant = 1;
  if (root < 0) return 0;
  stack[n++] = root;
  while (n > 0 && constant) {
    const bg_xnode *x = &m->xnode[stack[--n]];
    if (x->op != BG_X_NUM && x->op != BG_X_PARAM && x->op < BG_X_NEG) constant = 0;
    if (x->op == BG_X_TABLE) constant = 0;
    for (int k = 0; k < x->nargs && constant; k++) {
      if (n == (int)(sizeof stack / sizeof *stack)) return 0; /* deep: not judged */
      stack[n++] = x->arg[k];
    }
  }
  return constant;
}

static void unused_params(const bg_model *m, bg_diags *dg) {
  if (!m->nparam) return;
  unsigned char *used = calloc((size_t)m->nparam, 1);
  for (int i = 0; i < m->nxnode; i++)
    if (m->xnode[i].op == BG_X_PARAM && m->xnode[i].ref >= 0 && m->xnode[i].ref < m->nparam)
      used[m->xnode[i].ref] = 1;
  for (int p = 0; p < m->nparam; p++)
    if (!used[p] && !m->param_overridden[p])
      bg_diag_warn(dg, BG_W_UNUSED_PARAM, m->param_loc[p], "param '%s' is never used",
                   m->param_name[p]);
  free(used);
}

static void degenerate_values(const bg_model *m, bg_diags *dg) {
  for (int e = 0; e < m->nelem; e++) {
    int k = m->elem_kind[e];
    const char *what = k == BG_ELEM_C ? "capacitance" : k == BG_ELEM_I ? "inertance"
                       : k == BG_ELEM_TF || k == BG_ELEM_GY ? "modulus" : NULL;
    if (!what || m->elem_form[e] != BG_FORM_VALUE || !is_constant(m, m->elem_expr[e])) continue;
    bg_xenv env = {0};
    double v = bg_xeval(m, m->elem_expr[e], &env);
    if (v != 0) continue;
    bg_diag_warn(dg, BG_W_DEGENERATE, m->elem_loc[e], "the %s of %s '%s' is 0 at these parameter "
                 "values: %s", what, bg_elem_kind_name(k), m->elem_name[e],
                 k == BG_ELEM_C ? "its law e = q/C divides by zero"
                 : k == BG_ELEM_I ? "its law f = p/I divides by zero"
                 : "it passes no power, and its inverse law divides by zero");
  }
}

void bg_model_warnings(const bg_model *m, const bg_ast *ast, bg_diags *dg) {
  if (m->nelem == 0) {
    int defs = 0;
    for (int i = 0; i < ast->nstmts; i++) defs += ast->stmts[i].kind == BG_ST_SUBMODEL;
    bg_srcloc at = ast->nstmts ? ast->stmts[0].loc : (bg_srcloc){1, 1, 0};
    if (defs)
      bg_diag_warn(dg, BG_W_EMPTY_MODEL, at, "the file defines %d submodel%s but no model uses "
                   "them: the figure is empty (add an instance, `NAME INSTANCE`, or `use` this "
                   "file from a model)", defs, defs == 1 ? "" : "s");
    else
      bg_diag_warn(dg, BG_W_EMPTY_MODEL, at, "the model has no elements: the figure is empty");
    return;
  }
  unused_params(m, dg);
  degenerate_values(m, dg);
}
