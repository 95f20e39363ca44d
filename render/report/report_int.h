/* SPDX-License-Identifier: BSD-3-Clause */
/* Internals of the report (render/report*.c): a document of A4 pages built
 * on bg_scene (report_doc.c), wrapped text (report_text.c), tables split
 * across pages (report_table.c) and the sections (report.c,
 * report_summary.c, report_diagrams.c, report_analysis.c,
 * report_equations.c, report_sim.c). Conventions: docs/report.md. */
#ifndef BG_REPORT_INT_H
#define BG_REPORT_INT_H
#include "diagram/render.h"
#include "report/report.h"
#include "scene/scene.h"
#include "base/strbuf.h"
#include "scene/style.h"
#include "scene/surface.h"

/* ---------------------------------------------------------------- geometry, type */
#define RP_A4_W 595.276
#define RP_A4_H 841.890
#define RP_MARGIN_X 56.0   /* left and right */
#define RP_MARGIN_TOP 64.0 /* the running header sits above */
#define RP_MARGIN_BOTTOM 60.0

#define RP_SIZE_TITLE 22.0
#define RP_SIZE_H1 15.0
#define RP_SIZE_H2 11.5
#define RP_SIZE_BODY 9.5
#define RP_SIZE_TABLE 8.5
#define RP_SIZE_SMALL 7.5

/* Smallest text size, after scaling, a diagram may be shown at. */
#define RP_MIN_TEXT 6.0

extern const bg_rgba rp_ink, rp_grey, rp_rule, rp_shade, rp_accent, rp_red;

/* ---------------------------------------------------------------- text (report_text.c) */
/* Breakable pieces of one paragraph of pango markup: split at spaces
 * outside tags (space_before = 1), and inside words longer than
 * RP_LONG_WORD characters after * / + , ( (space_before = 0). Each piece is
 * markup on its own (tags balanced). */
typedef struct rp_words {
  int n, cap;
  char **text;
  int *space_before;
} rp_words;

void rp_words_split(const char *markup, rp_words *w);
void rp_words_free(rp_words *w);
/* Greedy line breaking: piece i has width w[i], preceded by a space of
 * width space when space_before[i] (not at a line start). The first line is
 * width1 wide, the others width2. Writes the first piece of each line to
 * start (n entries at most) and returns the number of lines (0 for n = 0).
 * A piece wider than its line gets a line of its own. */
int rp_break_lines(const double *w, const int *space_before, int n, double space, double width1,
                   double width2, int *start);

/* Lines of wrapped markup (each a malloc'd string). */
typedef struct rp_lines {
  int n;
  char **line;
} rp_lines;

/* Wraps markup set in font at size: first line width1, others width2. */
void rp_wrap(const char *font, double size, const char *markup, double width1, double width2,
             rp_lines *out);
void rp_lines_free(rp_lines *l);
/* Height of one line of text at size. */
double rp_line_height(const char *font, double size);
/* Width of markup on one line. */
double rp_text_width(const char *font, double size, const char *markup);

/* Appends plain text with markup's special characters escaped. */
void rp_esc(bg_strbuf *b, const char *s);
/* A plain line of the equation printer (eqprint text) as markup: bond
 * variables e3 → e with subscript 3, C1.q → q with subscript C1, a prime
 * becomes a dot above, * a centred dot, - a minus sign, ^2 a superscript. */
void rp_eq_markup(const char *plain, double size, bg_strbuf *out);
/* A number for tables: %.4g, with a minus sign. */
void rp_num(bg_strbuf *b, double v);
/* A loop gain's value: its coefficient (rp_num) over s to its order
 * ("−0.001/s", "2/s<sup>2</sup>"): the analysis' value leaves the
 * integrations out (docs/json.md). */
void rp_gain_value(bg_strbuf *b, double v, int order);
/* "one", "two", ... "twelve", else the digits (n > 12: in a buffer of the
 * calling thread, valid until its next call). */
const char *rp_count_word(int n);
/* "1 causal path" / "2 causal paths" (plural by appending s). */
void rp_count(bg_strbuf *b, int n, const char *noun);
/* "1, 2, 3" bond numbers of bond ids. */
void rp_bond_list(bg_strbuf *b, const bg_model *m, const int *bonds, int n);

/* ---------------------------------------------------------------- document (report_doc.c) */
typedef struct rp_page {
  bg_scene sc;
  bg_surface_place *place;
  int nplace, capplace;
} rp_page;

/* A heading: an outline entry and a line of the contents. */
typedef struct rp_head {
  char *title; /* plain text (owned) */
  int level;   /* 0 section, 1 subsection */
  int page;    /* index in its document */
  double y;
} rp_head;

typedef struct rp_doc {
  const char *font;
  rp_page **page;
  int npage, cappage;
  double y;            /* cursor on the last page */
  rp_head *head;
  int nhead, caphead;
  int section;         /* number of the last numbered section */
} rp_doc;

void rp_doc_init(rp_doc *d, const char *font);
void rp_doc_free(rp_doc *d);
/* Starts a page (A4, landscape when asked); the cursor goes to the top margin. */
void rp_new_page(rp_doc *d, int landscape);
bg_scene *rp_scene(rp_doc *d);
double rp_left(void);
double rp_content_w(const rp_doc *d);
/* Room left below the cursor on the last page. */
double rp_room(const rp_doc *d);
/* Height of the content area of the last page. */
double rp_page_room(const rp_doc *d);
/* A new page (same orientation: portrait) unless h fits below the cursor or the page is still empty. */
void rp_need(rp_doc *d, double h);
void rp_gap(rp_doc *d, double h);
/* A section heading ("3 Causality trace" when numbered), kept on a page with
 * at least keep points of what follows. newpage: start on a fresh page. */
void rp_section(rp_doc *d, const char *title, int numbered, int newpage, double keep);
void rp_subsection(rp_doc *d, const char *title, double keep);
/* The room a subsection's heading takes, its gaps above and below included. */
double rp_subsection_height(const rp_doc *d);
/* Records an outline entry without drawing anything. */
void rp_outline(rp_doc *d, const char *title, int level, double y);
/* A wrapped paragraph at the cursor; lines that do not fit go on the next
 * page. indent: from the left margin; hang: further indent of lines 2... */
void rp_para(rp_doc *d, const char *markup, double size, double indent, double hang, bg_rgba color);
/* The height rp_para gives the paragraph (its lines at their line height). */
double rp_para_height(const rp_doc *d, const char *markup, double size, double indent, double hang);
/* One text item at (x, y) (top-left unless halign given), no wrapping. */
bg_scene_item *rp_text(rp_doc *d, const char *markup, double x, double y, double size,
                       double halign, bg_rgba color);
void rp_fill_rect(bg_scene *s, double x, double y, double w, double h, bg_rgba fill, const char *role);
void rp_hline(bg_scene *s, double x0, double x1, double y, double width, bg_rgba c);
/* Places the rectangle (sx, sy, sw, sh) of scene s on the last page at (x, y), scaled. */
void rp_place(rp_doc *d, const bg_scene *s, double sx, double sy, double sw, double sh, double x,
              double y, double scale);
/* A figure under a subsection title: scene s (kept alive by the caller
 * until the PDF is written) at the content width, or smaller to fit a page. */
void rp_figure(rp_doc *d, const bg_scene *s, const char *title);
/* Running header and footer on every page of d: header text on pages from
 * first_header on, "page N of TOTAL" with N = index + offset + 1. */
void rp_decorate(rp_doc *d, const char *header, int first_header, int offset, int total);
/* Writes the pages of the documents in order with their headings as PDF
 * outlines. 0, or -1 when cairo failed. */
int rp_write_pdf(rp_doc *const *docs, int ndoc, const char *title, bg_strbuf *out);

/* ---------------------------------------------------------------- tables (report_table.c) */
typedef struct rp_table {
  int ncol;
  const char *const *head; /* ncol header markups */
  const char *align;       /* ncol chars: 'l' or 'r' */
  char **cell;             /* markup, row-major */
  int ncell, capcell;
  double size;             /* font size; RP_SIZE_TABLE by default */
} rp_table;

void rp_table_init(rp_table *t, int ncol, const char *const *head, const char *align);
/* Appends the next cell (markup, printf-style). */
void rp_table_cell(rp_table *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Appends the next cell from plain text (escaped). */
void rp_table_text(rp_table *t, const char *plain);
/* Lays the table out at the cursor, splitting it across pages with the
 * header row repeated, then frees its cells. */
void rp_table_emit(rp_doc *d, rp_table *t);
/* Column widths: natural (unwrapped) and minimum (widest piece) widths of
 * each column; every column gets its natural width when they all fit in
 * avail, else its minimum plus a share of the rest proportional to what it
 * lacks. Writes out[ncol]. */
void rp_table_widths(const double *natural, const double *minw, int ncol, double avail,
                     double *out);
/* Page breaks of a table: rows of heights rowh, a header of height headh
 * repeated on each page, room left on the first page, capacity of a full
 * page. Writes page[i] (0 = the first page) for every row and returns the
 * number of pages; page[0] is 1 when the header and the first rows (up to
 * three) do not fit the first page's room (unless that room is a full page). */
int rp_paginate(const double *rowh, int n, double headh, double room, double cap, int *page);

/* Two balanced columns of n one-line rows, page by page: rows_first rows
 * fit on the first page, rows_full on the others. A page takes up to twice
 * its rows; its left column gets the first half (rounded up). Writes the
 * page (0-based), column (0, 1) and row of each item; returns the pages. */
int rp_two_columns(int n, int rows_first, int rows_full, int *page, int *col, int *row);

/* ---------------------------------------------------------------- sections */
/* What one run knows, as the sections read it (report.c fills it from the
 * run); the nullable parts are missing when that stage did not run or
 * failed (the report then says why). */
typedef struct bg_report_input {
  const bg_model *m;
  const bg_analysis *a;
  const bg_eqsys *eqs;          /* nullable */
  const char *eqs_problem;      /* nullable: why there are no equations */
  const bg_index_facts *facts;  /* numeric index, reduced form, index reduction */
  const bg_index_result *index; /* facts->numeric: nullable, numeric index not computed */
  const char *index_skipped;    /* nullable: why not (e.g. too many unknowns) */
  const bg_simresult *sim;      /* nullable: no simulate block / not run */
  int sim_status;               /* bg_simulate's return: 0 ok, 1 refused, 2 failed */
  const bg_render_opts *ropts;  /* style, layout, log */
  const bg_linear *lin;         /* nullable: no linear analysis (section 10 left out) */
  const char *tx_name;          /* nullable: --transform NAME (section 11 left out) */
  const bg_transform_result *tx; /* the transformed model, with tx_name */
  const bg_study *study;        /* nullable: a parameter study (its section left out) */
  const bg_study_bode *bode;    /* nullable: the study's Bode family */
} bg_report_input;

typedef struct rp_ctx {
  const bg_report_input *in;
  const bg_model *m;
  const bg_analysis *a;
  bg_style st;
  rp_doc body;
  bg_diagram **diag; /* kept until the PDF is written (placed scenes are borrowed) */
  bg_diagram *full;  /* section 2's diagram, whose layout the highlights reuse (in diag) */
  int ndiag, capdiag;
  bg_scene **hl;     /* section 3's highlighted diagrams, cropped to what their pages show */
  int nhl, caphl;
  bg_scene *plot;     /* the simulation plots (owned), nullable */
  bg_scene *lin_plot[2]; /* the linear analysis' Bode and step plots (owned) */
  int nlin_plot;
  bg_scene *study_plot[4]; /* the parameter study's plots (owned) */
  int nstudy_plot;
  bg_diags *dg;
  int failed;        /* a diagram could not be built (errors in dg) */
  int hl_full_items; /* highlights seen in section 2's scene above this many of its
                        items; 0: RP_HL_FULL_ITEMS (tests set less) */
} rp_ctx;

/* Shared with the HTML report (render/html): the one-sentence verdict (plain
 * text), the summary table's rows (key, plain text) and the eigenvalue
 * nearest an estimate (kind 0 a time constant, 1 a frequency; -1 none). */
typedef void (*rp_row_fn)(void *ctx, const char *key, const char *plain);
/* What the report reads of a run (report.c). */
bg_report_input rp_input(const bg_run *r, const bg_report_opts *ro);
void rp_verdict(const rp_ctx *c, bg_strbuf *out);
void rp_summary_rows(const rp_ctx *c, rp_row_fn row, void *ctx);
int rp_nearest_eig(const bg_index_result *r, int kind, double value);
/* 1 for the member with im > 0 of a pair listed as its conjugate (one row "re ± im"). */
int rp_conjugate_listed(const bg_index_result *r, int k);
/* The analysis before and after --transform, one row each (what, before,
 * after: report_transform.c). */
typedef void (*rp_cmp_fn)(void *ctx, const char *what, const char *before, const char *after);
void rp_transform_rows(const bg_analysis *a, const bg_analysis *b, rp_cmp_fn fn, void *ctx);
/* The solver statistics' rows (report_sim.c). */
void rp_sim_stat_rows(const rp_ctx *c, const bg_simresult *r, rp_row_fn fn, void *ctx);

/* A progress line under -v ("report: ..."), report_doc.c. */
void rp_progress(const rp_ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Keeps diagram d until the PDF is written (NULL: marks the report failed). */
bg_diagram *rp_keep(rp_ctx *c, bg_diagram *d);
/* The diagram with every layer (report_diagrams.c). */
void rp_sec_diagram(rp_ctx *c);
/* Highlighted diagrams of paths, loops and conflicts worth showing. */
void rp_sec_highlights(rp_ctx *c);
/* report_highlight.c: above RP_HL_FULL_ITEMS items of section 2's scene (a
 * diagram whose map is an image, report_diagrams.c) a highlight is a view of
 * section 2's diagram, not a redraw: rp_hl_view (only its hot bonds and
 * elements its own), its page's items by rp_hl_crop (the highlighted item in
 * colour, the rest muted, other paths, loops and the legend left out),
 * rp_hl_done frees a view or a redrawn diagram. */
#define RP_HL_FULL_ITEMS 20000
int rp_hl_from_full(const rp_ctx *c);
bg_diagram *rp_hl_view(const rp_ctx *c, int kind, int index);
void rp_hl_crop(const bg_diagram *view, const double clip[4], bg_scene *dst);
void rp_hl_done(const rp_ctx *c, bg_diagram *d);
/* report_analysis.c */
void rp_sec_trace(rp_ctx *c);
/* report_components.c: instances and bond origins (models with submodels only) */
void rp_sec_components(rp_ctx *c);
void rp_sec_fields(rp_ctx *c); /* report_fields.c: multiport fields */
void rp_sec_tables(rp_ctx *c);
void rp_sec_index(rp_ctx *c);
void rp_sec_estimates(rp_ctx *c);
/* report_equations.c */
void rp_sec_equations(rp_ctx *c);
/* report_sim.c */
void rp_sec_simulation(rp_ctx *c);
/* report_linear.c: only when the run made a linear analysis */
void rp_sec_linear(rp_ctx *c);
/* report_study.c: only with a parameter study: what was varied, the table,
 * the family of runs, the quantities against the param, the root locus and
 * the Bode family */
void rp_sec_study(rp_ctx *c);
/* report_transform.c: only with --transform: what changed, before and after */
void rp_sec_transform(rp_ctx *c);
/* report_summary.c: the title page with the summary and the contents of
 * body (page numbers counted after the front pages). */
void rp_front(rp_ctx *c, rp_doc *front);
#endif
