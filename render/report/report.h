/* The multi-page A4 PDF analysis report (--report FILE.pdf): title page
 * with a verdict, the diagram with all layers, highlighted diagrams per
 * path, loop and conflict, the causality trace, tables of paths, loops and
 * conflicts, form and index with the rank history, the equations, the
 * estimates beside the eigenvalues, the simulation plots and statistics.
 * Contents list, page numbers and PDF outlines. Conventions: docs/report.md. */
#ifndef BG_REPORT_H
#define BG_REPORT_H
#include "causality/causality.h"
#include "base/diag.h"
#include "equations/equations.h"
#include "model/model.h"
#include "diagram/render.h"
#include "simulate/simulate.h"
#include "linear/linear.h"
#include "transform/transform.h"

/* What one run knows; everything borrowed; the nullable parts are missing
 * when that stage did not run or failed (the report then says why). */
typedef struct bg_report_input {
  const bg_model *m;
  const bg_analysis *a;
  const bg_eqsys *eqs;          /* nullable */
  const char *eqs_problem;      /* nullable: why there are no equations */
  const bg_index_result *index; /* nullable: numeric index not computed */
  const char *index_skipped;    /* nullable: why not (e.g. too many unknowns) */
  const bg_simresult *sim;      /* nullable: no simulate block / not run */
  int sim_status;               /* bg_simulate's return: 0 ok, 1 refused, 2 failed */
  const bg_render_opts *ropts;  /* style, layout, verbose */
  const bg_linear *lin;         /* nullable: no linear analysis (section 10 left out) */
  const char *tx_name;          /* nullable: --transform NAME (section 11 left out) */
  const bg_transform_result *tx; /* the transformed model, with tx_name */
} bg_report_input;

/* Writes the report to path atomically. Returns BG_RENDER_OK,
 * BG_RENDER_ERROR or BG_RENDER_EWRITE (render.h), errors reported to dg. */
int bg_report_write(const bg_report_input *in, const char *path, bg_diags *dg);
#endif
