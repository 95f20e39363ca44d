/* SPDX-License-Identifier: BSD-3-Clause */
/* The HTML analysis report (--report FILE.html): one self-contained,
 * deterministic page with every section of the PDF report; the diagram as
 * inline SVG with layer toggles, tables of paths, loops and conflicts whose
 * rows highlight their bonds (hover, focus, #path-3), equations as MathML,
 * plots as inline SVG with a readout under the pointer. No network access at
 * view time: the style sheet and the script are inline. Conventions:
 * docs/report.md. */
#ifndef BG_HTML_H
#define BG_HTML_H
#include "base/diag.h"
#include "base/strbuf.h"
#include "report/report.h"
#include "run/run.h"

/* The report of what the run computed, as HTML into out. o as for the PDF
 * (style, layout, --transform). Returns BG_RENDER_OK or BG_RENDER_ERROR
 * (render.h), errors reported to dg. */
int bg_html_report_render(const bg_run *r, const bg_report_opts *o, bg_strbuf *out, bg_diags *dg);
#endif
