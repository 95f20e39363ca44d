/* SPDX-License-Identifier: BSD-3-Clause */
/* The writers' messages (output_int.h), shared by the table's writers in
 * output.c, output_export.c, output_fmu.c and output_linear.c: an error as
 * a diagnostic, a refusal in words. */
#include <stdlib.h>

#include "output/output_int.h"

bg_output_status bg_out_refuse(bg_output *w, const char *what, const char *why) {
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "%s%s", what, why);
  free(w->refusal);
  w->refusal = sb.s;
  return BG_OUT_REFUSED;
}

bg_output_status bg_out_error(bg_output *w, bg_output_status st, const char *fmt, const char *a,
                              const char *b) {
  bg_diag_error(&w->dg, (bg_srcloc){0}, fmt, a, b);
  return st;
}

bg_output_status bg_out_no_equations(bg_output *w, const char *path) {
  return bg_out_error(w, BG_OUT_MODEL, "no equations for '%s': %s", path ? path : "stdout",
                      w->run->eqsys_problem ? w->run->eqsys_problem : "unknown reason");
}
