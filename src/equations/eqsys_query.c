/* SPDX-License-Identifier: BSD-3-Clause */
/* What a built bg_eqsys is (eqsys.h): sizes, names, its form, its outputs.
 * A leaf: eqsys.c builds the system, the files under it ask these. */
#include "equations/eqsys_int.h"
#include "base/sort.h"

int bg_eqsys_n(const bg_eqsys *s) { return s->n; }
int bg_eqsys_nx(const bg_eqsys *s) { return s->nx; }
int bg_eqsys_is_ode(const bg_eqsys *s) { return s->nz == 0 && s->ndep == 0; }
int bg_eqsys_is_reduced(const bg_eqsys *s) { return s->reduced; }
const char *bg_eqsys_name(const bg_eqsys *s, int i) { return i >= 0 && i < s->n ? s->uname[i] : NULL; }
/* A bond's variable: "e" or "f" and the bond's number (eqsys.c, bg_eqs_signame). */
static int is_bond_variable(const char *name) {
  if ((name[0] != 'e' && name[0] != 'f') || !name[1]) return 0;
  for (const char *c = name + 1; *c; c++)
    if (*c < '0' || *c > '9') return 0;
  return 1;
}

/* A bond's variable against an element's unknown must not go by their text:
 * "e20" sorts after "C4.q" but before "x0.q" (docs/property.md, finding 17c). */
int bg_eqsys_name_cmp(const char *a, const char *b) {
  int ba = is_bond_variable(a), bb = is_bond_variable(b);
  return ba != bb ? ba - bb : bg_natural_cmp(a, b);
}
int bg_eqsys_is_differential(const bg_eqsys *s, int i) { return i < s->nx; }
const char *bg_eqsys_error(const bg_eqsys *s) { return s->has_err ? s->err : NULL; }
int bg_eqsys_noutput(const bg_eqsys *s) { return s->nout; }
const char *bg_eqsys_output_name(const bg_eqsys *s, int k) { return k >= 0 && k < s->nout ? s->out_name[k] : NULL; }
