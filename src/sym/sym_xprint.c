/* SPDX-License-Identifier: BSD-3-Clause */
/* A model expression printed simplified (the laws of a field's ports in the
 * JSON and the report: an energy's gradient as compiled reads
 * 2*K.el.q*K.mech.q/(2*eps*A), simplified K.el.q*K.mech.q/(eps*A)). */
#include <stdlib.h>

#include "sym/sym.h"

typedef struct xname {
  const bg_model *m;
} xname;

/* store states are unknowns by element id, user states after them */
static void leaf_name(void *ctx, int kind, int ref, int latex, bg_strbuf *out) {
  const bg_model *m = ((const xname *)ctx)->m;
  (void)latex;
  switch (kind) {
  case SYM_PARAM: bg_sb_puts(out, m->param_name[ref]); break;
  case SYM_INPUT: bg_sb_puts(out, m->input_name[ref]); break;
  case SYM_T: bg_sb_puts(out, "t"); break;
  case SYM_Y:
    if (ref < m->nelem)
      bg_sb_printf(out, "%s.%c", m->elem_name[ref], m->elem_kind[ref] == BG_ELEM_C ? 'q' : 'p');
    else bg_sb_puts(out, m->state_name[ref - m->nelem]);
    break;
  case SYM_SIG: bg_sb_printf(out, "%c%d", ref & 1 ? 'f' : 'e', m->bond_num[ref / 2]); break;
  default: bg_sb_puts(out, "?"); break;
  }
}

void bg_sym_print_model_expr(const bg_model *m, int root, bg_strbuf *out) {
  int *store_y = malloc(sizeof(int) * ((size_t)m->nelem + 1));
  int *state_y = malloc(sizeof(int) * ((size_t)m->nstate + 1));
  for (int e = 0; e < m->nelem; e++) store_y[e] = bg_elem_is_store(m->elem_kind[e]) ? e : -1;
  for (int s = 0; s < m->nstate; s++) state_y[s] = m->nelem + s;
  bg_sym *S = bg_sym_new(m);
  xname X = {m};
  bg_sym_print(S, bg_sym_from_x(S, root, state_y, store_y), 0, leaf_name, &X, out);
  bg_sym_free(S);
  free(store_y), free(state_y);
}
