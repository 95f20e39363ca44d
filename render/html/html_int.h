/* SPDX-License-Identifier: BSD-3-Clause */
/* Internals of the HTML report (render/html): the writer's context, escaping,
 * tables with headers and row ids, and the sections (html_analysis.c,
 * html_figures.c). */
#ifndef BG_HTML_INT_H
#define BG_HTML_INT_H
#include "html/html.h"
#include "report/report_int.h"

#define HT_MAX_ROWS 400   /* per table, as the PDF; the JSON has every row */
#define HT_MAX_EQ_ROWS 4000 /* MathML equations shown; the rest: --equations */

typedef struct ht_ctx {
  rp_ctx rp;              /* what the PDF report reads (in, m, a): its verdict */
  const bg_report_input *in;
  const bg_model *m;
  const bg_analysis *a;
  bg_strbuf *out;
  bg_diags *dg;
  int section;            /* number of the last section */
  bg_strbuf toc;          /* the contents' <li>s */
  int failed;
} ht_ctx;

/* ------------------------------------------------------------ writing (html_write.c) */
/* Text with & < > " escaped. */
void ht_esc(bg_strbuf *b, const char *s);
/* A row <tr><th scope=row>key</th><td>plain</td></tr> into the strbuf ctx
 * (the PDF report's rp_row_fn: summary and solver statistics). */
void ht_row(void *ctx, const char *key, const char *plain);
/* <section id> with a numbered <h2> and its line in the contents. */
void ht_section(ht_ctx *c, const char *id, const char *title);
void ht_section_end(ht_ctx *c);
/* <h3 id> */
void ht_sub(ht_ctx *c, const char *id, const char *title);
/* <p> with escaped text (printf style, the arguments plain text). */
void ht_para(ht_ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* A table's start: caption, header cells (th scope=col), an optional class. */
void ht_table(ht_ctx *c, const char *cls, const char *caption, int ncol, const char *const *head);
void ht_table_end(ht_ctx *c);
/* A note under a table that lists only the first of its rows. */
void ht_more_rows(ht_ctx *c, int shown, int total, int omitted, const char *what);
/* "1, 2, 3": bond numbers of bond ids (plain). */
void ht_bonds(bg_strbuf *b, const bg_model *m, const int *bonds, int n);
/* A number as the PDF prints it (%.4g, a minus sign). */
void ht_num(bg_strbuf *b, double v);
/* The style sheet, the part of it the interaction needs (also in a page
 * that embeds the diagram and tables) and the script (html_assets.c). */
extern const char ht_css[], ht_css_parts[], ht_js[];

/* ------------------------------------------------------------ sections */
void ht_summary(ht_ctx *c);    /* html_analysis.c */
void ht_trace(ht_ctx *c);
void ht_tables(ht_ctx *c);
void ht_index(ht_ctx *c);
void ht_estimates(ht_ctx *c);
void ht_components(ht_ctx *c); /* html_model.c: models with submodels */
void ht_fields(ht_ctx *c);     /* html_model.c: models with multiport fields */
void ht_diagram(ht_ctx *c);    /* html_figures.c */
void ht_equations(ht_ctx *c);
void ht_simulation(ht_ctx *c);
void ht_linear(ht_ctx *c);
void ht_transform(ht_ctx *c);
#endif
