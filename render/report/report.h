/* SPDX-License-Identifier: BSD-3-Clause */
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
#include "run/run.h"
#include "study/study.h"
#include "transform/transform.h"

/* What the report shows beyond the run. */
typedef struct bg_report_opts {
  const bg_render_opts *ropts;   /* style, layout, log */
  const char *tx_name;           /* nullable: --transform NAME (section 11 left out) */
  const bg_transform_result *tx; /* the transformed model, with tx_name */
  const bg_study *study;         /* nullable: a parameter study of the model (its section) */
  const bg_study_bode *bode;     /* nullable: the study's Bode family */
} bg_report_opts;

/* The report of what the run computed (the stages it has not run are said
 * so: no equations, no simulation, no linear analysis) as PDF into out.
 * Returns BG_RENDER_OK or BG_RENDER_ERROR (render.h), errors reported to dg. */
int bg_report_render(const bg_run *r, const bg_report_opts *o, bg_strbuf *out, bg_diags *dg);
#endif
