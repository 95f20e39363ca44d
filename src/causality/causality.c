/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_causality_assign: the stage's entry point. It runs one procedure
 * (causality_scap.c, causality_vandijk.c, causality_lagrange.c) on the engine
 * (causality_engine.c) and writes the result (causality_result.c). */
#include "causality/causality_int.h"

int bg_causality_assign(const bg_model *m, int method, bg_analysis *a, bg_diags *dg) {
  (void)dg; /* conflicts are results of the analysis, not input errors */
  bg_ceng E;
  if (method < BG_METHOD_SCAP || method > BG_METHOD_LAGRANGE) method = BG_METHOD_SCAP;
  a->method = method;
  bg_ceng_init(&E, m, a);
  switch (method) {
  case BG_METHOD_RELAXED: bg_ceng_scap(&E, 1); break;
  case BG_METHOD_VANDIJK: bg_ceng_vandijk(&E); break;
  case BG_METHOD_LAGRANGE: bg_ceng_lagrange(&E); break;
  default: bg_ceng_scap(&E, 0); break;
  }
  bg_ceng_finish(&E);
  bg_ceng_free(&E);
  return 0;
}
