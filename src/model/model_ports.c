/* SPDX-License-Identifier: BSD-3-Clause */
/* The variables of a field's ports inside its laws (model_int.h): which
 * element a port is, and e, f or q of a port as expression nodes. Called
 * by the expression compiler (model_expr.c) and the fields (model_field.c). */
#include <string.h>

#include "model/expr.h"
#include "model/model_int.h"

/* The element of port `port` (a name) or number `num` of field f; -1. */
int bg_build_port_elem(const bg_model *m, int f, const char *port, int num) {
  for (int k = 0; k < m->field_nport[f]; k++) {
    int e = m->field_elemadr[f] + k;
    if (port ? strcmp(bg_elem_port_name(m, e), port) == 0 : m->elem_fport[e] == num) return e;
  }
  return -1;
}

/* Port `pe`'s own flow: the bond's, negated when the bond points out. */
static int own_flow(bg_build *b, int pe, int bond, bg_srcloc loc) {
  int k = bg_build_ref(b, BG_X_FLOW, bond, loc);
  if (b->m->bond_head[bond] == pe) return k;
  return bg_build_op(b, BG_X_NEG, k, -1, loc);
}

int bg_build_port_var(bg_build *b, const char *port, int num, char v, const bg_expr *e) {
  bg_model *m = b->m;
  int f = b->field, pe = bg_build_port_elem(m, f, port, num);
  if (pe < 0) {
    if (port) return -1; /* not a port's name: an ordinary name */
    bg_diag_error(b->dg, e->loc, "'%s' names no port of field %s: it has ports 1 to %d", e->text,
                  m->field_name[f], m->field_nport[f]);
    return bg_build_num(b, 0, e->loc);
  }
  int kind = m->field_kind[f];
  if (kind == BG_ELEM_C && v != 'q') {
    bg_diag_error(b->dg, e->loc, "a C field's %s reads the ports' displacements q only, not '%s'",
                  b->law_elem < 0 ? "energy" : "laws", e->text);
    return bg_build_num(b, 0, e->loc);
  }
  if (kind == BG_ELEM_I && v != 'p') {
    bg_diag_error(b->dg, e->loc, "an I field's %s the ports' momenta p only, not '%s'",
                  b->law_elem < 0 ? "energy reads" : "laws read", e->text);
    return bg_build_num(b, 0, e->loc);
  }
  if (kind != BG_ELEM_I && v == 'p') {
    bg_diag_error(b->dg, e->loc, "%s field's ports have no momentum: '%s'", bg_elem_kind_article(kind), e->text);
    return bg_build_num(b, 0, e->loc);
  }
  if (kind == BG_ELEM_R && v == 'q') {
    bg_diag_error(b->dg, e->loc, "an R field's ports have no displacement: '%s'", e->text);
    return bg_build_num(b, 0, e->loc);
  }
  if (pe == b->law_elem && v == b->law_lhs) {
    bg_diag_error(b->dg, e->loc, "the right-hand side of %s's law cannot use its left-hand side "
                  "'%s'", m->elem_name[pe], e->text);
    return bg_build_num(b, 0, e->loc);
  }
  if (v == 'q' || v == 'p') return bg_build_ref(b, BG_X_STORE, pe, e->loc);
  int bond = bg_elem_port_bond(m, pe);
  if (bond < 0) return bg_build_num(b, 0, e->loc); /* its bond count is reported */
  if (v == 'e') return bg_build_ref(b, BG_X_EFFORT, bond, e->loc);
  return own_flow(b, pe, bond, e->loc);
}
