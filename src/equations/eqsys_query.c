/* SPDX-License-Identifier: BSD-3-Clause */
/* What a built bg_eqsys is (eqsys.h): sizes, names, its form, its outputs.
 * A leaf: eqsys.c builds the system, the files under it ask these. */
#include "equations/eqsys_int.h"

int bg_eqsys_n(const bg_eqsys *s) { return s->n; }
int bg_eqsys_nx(const bg_eqsys *s) { return s->nx; }
int bg_eqsys_is_ode(const bg_eqsys *s) { return s->nz == 0 && s->ndep == 0; }
int bg_eqsys_is_reduced(const bg_eqsys *s) { return s->reduced; }
const char *bg_eqsys_name(const bg_eqsys *s, int i) { return i >= 0 && i < s->n ? s->uname[i] : NULL; }
int bg_eqsys_is_differential(const bg_eqsys *s, int i) { return i < s->nx; }
const char *bg_eqsys_error(const bg_eqsys *s) { return s->has_err ? s->err : NULL; }
int bg_eqsys_noutput(const bg_eqsys *s) { return s->nout; }
const char *bg_eqsys_output_name(const bg_eqsys *s, int k) { return k >= 0 && k < s->nout ? s->out_name[k] : NULL; }
