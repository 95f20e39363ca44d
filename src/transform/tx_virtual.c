/* SPDX-License-Identifier: BSD-3-Clause */
/* merge-stores through a modulated transformer (chapter Section 4.10,
 * "Virtual Inertia and its Companion Gyristor", Figure 4.30): an inertia D
 * tied to an independent inertia A by a class 1 causal path through an MTF
 * whose modulus T depends on generalised coordinates (user states) moves
 * with k(phi) times A's flow (k = T or 1/T). Merged, A is the virtual
 * inertia J~ = A + k^2 D, not constant, and a companion gyristor on A's
 * junction keeps the kinetic co-energy right. With the momentum
 * p = J~ w as the state (bgdraw's I), dp/dt = J~ w' + dJ~/dt w while
 * Lagrange's equation (4.53) has J~ w' + (1/2) dJ~/dt w = Q: the companion
 * takes the effort e = -(1/2) dJ~/dt f = -D k dk/dt f, written as a
 * modulated resistor R GR_A = -D*k*dk/dt (e = value * f). */
#include <stdlib.h>
#include <string.h>

#include "sym/sym.h"
#include "transform/tx_int.h"

/* The modulus reads params, numbers and user states only (generalised
 * coordinates), at least one state. */
int tx_modulus_of_coordinates(const bg_model *m, int x) {
  int states = 0;
  /* the tree walked with an explicit stack (children are earlier nodes) */
  int *stack = malloc(sizeof *stack * (size_t)(m->nxnode + 1)), n = 0, ok = 1;
  stack[n++] = x;
  while (n && ok) {
    const bg_xnode *d = &m->xnode[stack[--n]];
    switch (d->op) {
    case BG_X_STATE: states++; break;
    case BG_X_TIME: case BG_X_INPUT: case BG_X_EFFORT: case BG_X_FLOW: case BG_X_STORE:
    case BG_X_TABLE:
      ok = 0;
      break;
    default: break;
    }
    for (int k = 0; k < d->nargs && n <= m->nxnode; k++) stack[n++] = d->arg[k];
  }
  free(stack);
  return ok && states > 0;
}

static void leaf_name(void *ctx, int kind, int ref, int latex, bg_strbuf *out) {
  const bg_model *m = ctx;
  (void)latex;
  switch (kind) {
  case SYM_PARAM: bg_sb_puts(out, m->param_name[ref]); break;
  case SYM_INPUT: bg_sb_puts(out, m->input_name[ref]); break;
  case SYM_T: bg_sb_puts(out, "t"); break;
  case SYM_Y: bg_sb_puts(out, m->state_name[ref]); break;
  default: bg_sb_printf(out, "%c%d", ref & 1 ? 'f' : 'e', m->bond_num[ref / 2]); break;
  }
}

/* -D k dk/dt as .bg text, with dk/dt = sum over the states of dk/dphi_i
 * times phi_i' (the states' own equations). */
static void companion_value(const bg_model *m, int mtf, int drop, int inverse, bg_strbuf *out) {
  bg_sym *S = bg_sym_new(m);
  int *state_y = malloc(sizeof *state_y * (size_t)(m->nstate + 1));
  int *store_y = malloc(sizeof *store_y * (size_t)(m->nelem + 1));
  for (int i = 0; i < m->nstate; i++) state_y[i] = i;
  for (int i = 0; i < m->nelem; i++) store_y[i] = -1;
  int T = bg_sym_from_x(S, m->elem_expr[mtf], state_y, store_y);
  int k = inverse ? bg_sym_powc(S, T, -1) : T;
  int dk = bg_sym_num(S, 0);
  for (int i = 0; i < m->nstate; i++) {
    int rate = bg_sym_from_x(S, m->state_expr[i], state_y, store_y);
    dk = bg_sym_add(S, dk, bg_sym_mul(S, bg_sym_diff(S, k, bg_sym_leaf(S, SYM_Y, i)), rate));
  }
  int D = bg_sym_from_x(S, m->elem_expr[drop], state_y, store_y);
  int v = bg_sym_neg(S, bg_sym_mul(S, bg_sym_mul(S, D, k), dk));
  bg_sym_print(S, v, 0, leaf_name, (void *)m, out);
  free(state_y);
  free(store_y);
  bg_sym_free(S);
}

int tx_virtual_inertia(tx_ctx *c, int p, int keep, int drop, int mtf, int inverse) {
  const bg_model *m = c->m;
  const bg_ast_stmt *s = tx_elem_stmt(c, keep);
  for (int i = 0; i < s->nopts; i++)
    if (!strcmp(s->opts[i].key, "p0")) {
      bg_sb_printf(&c->problem, "%s has an initial momentum p0, which the virtual inertia "
                   "would scale by its value at t0 (not done)", m->elem_name[keep]);
      return -1;
    }
  const char *T = tx_elem_stmt(c, mtf)->expr->text;
  const char *A = s->expr->text, *D = tx_elem_stmt(c, drop)->expr->text;
  bg_strbuf jt = {0}, line = {0}, gv = {0};
  bg_sb_printf(&jt, "(%s) + (%s)%s(%s)^2", A, D, inverse ? "/" : "*", T);
  bg_sb_printf(&line, "%-3s %s : f = p/(%s)", s->kindword, s->name, bg_sb_str(&jt));
  tx_print_options(&line, s, NULL, NULL);
  tx_replace_stmt(&c->doc, s->loc.line, bg_sb_str(&line));
  companion_value(m, mtf, drop, inverse, &gv);
  char base[64], gr[64];
  snprintf(base, sizeof base, "GR_%s", m->elem_name[keep]);
  tx_fresh_name(c, base, gr, sizeof gr);
  int j = bg_bond_other(m, bg_elem_port_bond(m, keep), keep);
  bg_sb_clear(&line);
  bg_sb_printf(&line, "R   %s = %s   # companion gyristor of the virtual inertia %s", gr,
               bg_sb_str(&gv), m->elem_name[keep]);
  tx_insert_after(&c->doc, s->loc.line, bg_sb_str(&line));
  bg_sb_clear(&line);
  tx_print_bond(&line, c->next_bond++, m->elem_name[j], BG_ARROW_PLAIN, gr, NULL);
  tx_insert_after(&c->doc, tx_last_bond_line(c), bg_sb_str(&line));
  tx_delete_stmt(&c->doc, tx_elem_line(c, drop));
  tx_remove_bond(c, bg_elem_port_bond(m, drop));
  if (c->why.len) bg_sb_putc(&c->why, ' ');
  const char *K = m->elem_name[keep], *Dn = m->elem_name[drop], *Tn = m->elem_name[mtf];
  bg_sb_printf(&c->why, "I %s, in derivative causality, is tied to %s by class 1 causal path %d "
               "through the transformer %s, whose modulus T depends on a generalised "
               "coordinate: %s's flow is %s times %s's, so both are one virtual inertia "
               "%s~ = %s + %s%sT^2 (chapter Section 4.10, Figure 4.30), not constant: %s's law "
               "is now f = p/%s~ with the momentum p = %s~ f as the state. Its companion "
               "gyristor %s on %s takes the effort -(1/2) d%s~/dt f = -%s%sdT/dt f (dT/dt "
               "from the states' equations), so that the kinetic co-energy is conserved and "
               "Lagrange's equation 4.53 holds. %s and its bond %d are removed.", Dn, K, p + 1,
               Tn, Dn, inverse ? "1/T" : "T", K, K, A, D, inverse ? "/" : "*", K, K, K, gr,
               m->elem_name[j], K, D, inverse ? "/T^3*" : "*T*", Dn,
               m->bond_num[bg_elem_port_bond(m, drop)]);
  bg_sb_free(&jt);
  bg_sb_free(&line);
  bg_sb_free(&gv);
  return 0;
}
