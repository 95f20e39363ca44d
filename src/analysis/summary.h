/* Short human summaries of an analysis, for --check and -v. */
#ifndef BG_SUMMARY_H
#define BG_SUMMARY_H
#include "causality/analysis.h"
#include "base/strbuf.h"

/* A few lines: method, states, dependent stores, conflicts, paths by class,
 * loops, form and predicted index with its reason. */
void bg_analysis_summary(const bg_model *m, const bg_analysis *a, bg_strbuf *out);
const char *bg_form_name(int form);
#endif
