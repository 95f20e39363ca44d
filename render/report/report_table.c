/* SPDX-License-Identifier: BSD-3-Clause */
/* Report tables: cells of markup, column widths from pango metrics, wrapped
 * cells, split across pages with the header row repeated. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report/report_int.h"

#define PAD_X 4.0
#define PAD_Y 2.5

void rp_table_init(rp_table *t, int ncol, const char *const *head, const char *align) {
  memset(t, 0, sizeof *t);
  t->ncol = ncol, t->head = head, t->align = align;
  t->size = RP_SIZE_TABLE;
}

static void push_cell(rp_table *t, char *s) {
  if (t->ncell == t->capcell) {
    t->capcell = t->capcell ? 2 * t->capcell : 32;
    t->cell = bg_xrealloc(t->cell, (size_t)t->capcell * sizeof *t->cell);
  }
  t->cell[t->ncell++] = s;
}

void rp_table_cell(rp_table *t, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(NULL, 0, fmt, ap);
  va_end(ap);
  char *s = bg_xmalloc((size_t)n + 1);
  va_start(ap, fmt);
  vsnprintf(s, (size_t)n + 1, fmt, ap);
  va_end(ap);
  push_cell(t, s);
}

void rp_table_text(rp_table *t, const char *plain) {
  bg_strbuf b = {0};
  rp_esc(&b, plain);
  push_cell(t, strdup(bg_sb_str(&b)));
  bg_sb_free(&b);
}

static void table_free(rp_table *t) {
  for (int i = 0; i < t->ncell; i++) free(t->cell[i]);
  free(t->cell);
  t->cell = NULL;
  t->ncell = t->capcell = 0;
}

/* ---------------------------------------------------------------- pure layout */
void rp_table_widths(const double *natural, const double *minw, int ncol, double avail,
                     double *out) {
  /* columns narrower than a fair share of what is left keep their natural
   * width; the others get their minimum plus a share of the rest in
   * proportion to what they lack */
  unsigned char fixed[64] = {0};
  int nc = ncol < 64 ? ncol : 64, nrem = nc;
  double rem = avail;
  for (int changed = 1; changed && nrem > 0;) {
    changed = 0;
    double fair = rem / nrem;
    for (int c = 0; c < nc; c++)
      if (!fixed[c] && natural[c] <= fair) {
        out[c] = natural[c], fixed[c] = 1, rem -= natural[c], nrem--, changed = 1;
      }
  }
  double sum_m = 0, lack = 0;
  for (int c = 0; c < nc; c++) {
    if (fixed[c]) continue;
    double mn = minw[c] < natural[c] ? minw[c] : natural[c];
    sum_m += mn, lack += natural[c] - mn;
  }
  for (int c = 0; c < nc; c++) {
    if (fixed[c]) continue;
    double mn = minw[c] < natural[c] ? minw[c] : natural[c];
    out[c] = sum_m >= rem || lack <= 0 ? mn : mn + (rem - sum_m) * (natural[c] - mn) / lack;
  }
}

int rp_paginate(const double *rowh, int n, double headh, double room, double cap, int *page) {
  if (n <= 0) return 0;
  int p = 0;
  double left = room, start = headh; /* the header and the first rows (up to 3) stay together */
  for (int i = 0; i < n && i < 3; i++) start += rowh[i];
  if (start > room && room < cap) p = 1, left = cap;
  left -= headh;
  int first = 1;
  for (int i = 0; i < n; i++) {
    if (rowh[i] > left && !first) p++, left = cap - headh;
    page[i] = p;
    left -= rowh[i];
    first = 0;
  }
  return p + 1;
}

int rp_two_columns(int n, int rows_first, int rows_full, int *page, int *col, int *row) {
  int i = 0, p = 0;
  if (rows_full < 1) rows_full = 1;
  if (rows_first < 1) rows_first = 0, p = n > 0;
  while (i < n) {
    int rows = p == 0 ? rows_first : rows_full;
    int m = n - i < 2 * rows ? n - i : 2 * rows, left = (m + 1) / 2;
    for (int k = 0; k < m; k++, i++) page[i] = p, col[i] = k >= left, row[i] = k < left ? k : k - left;
    p++;
  }
  return p;
}

/* ---------------------------------------------------------------- emit */
typedef struct tlay {
  int nrow;
  double *w;       /* column widths (with padding) */
  rp_lines *lines; /* (nrow + 1) * ncol: the header first */
  double *rowh;    /* nrow + 1 */
  double lh;
} tlay;

static const char *cell_of(const rp_table *t, int r, int c) {
  if (r < 0) return t->head[c];
  int i = r * t->ncol + c;
  return i < t->ncell ? t->cell[i] : "";
}

/* Natural and minimum widths of every column. */
static void measure(const rp_doc *d, const rp_table *t, int nrow, double *nat, double *mn) {
  for (int c = 0; c < t->ncol; c++) {
    nat[c] = mn[c] = 0;
    for (int r = -1; r < nrow; r++) {
      bg_strbuf b = {0};
      if (r < 0) bg_sb_printf(&b, "<b>%s</b>", t->head[c]);
      else bg_sb_puts(&b, cell_of(t, r, c));
      double w = rp_text_width(d->font, t->size, bg_sb_str(&b));
      if (w > nat[c]) nat[c] = w;
      rp_words wd;
      rp_words_split(bg_sb_str(&b), &wd);
      for (int k = 0; k < wd.n; k++) {
        double pw = rp_text_width(d->font, t->size, wd.text[k]);
        if (pw > mn[c]) mn[c] = pw;
      }
      rp_words_free(&wd);
      bg_sb_free(&b);
    }
    nat[c] += 2 * PAD_X, mn[c] += 2 * PAD_X;
  }
}

static void lay_out(const rp_doc *d, const rp_table *t, tlay *L) {
  int nc = t->ncol;
  L->nrow = (t->ncell + nc - 1) / nc;
  double *nat = bg_xmalloc((size_t)nc * sizeof(double)), *mn = bg_xmalloc((size_t)nc * sizeof(double));
  L->w = bg_xmalloc((size_t)nc * sizeof(double));
  measure(d, t, L->nrow, nat, mn);
  rp_table_widths(nat, mn, nc, rp_content_w(d), L->w);
  L->lh = rp_line_height(d->font, t->size);
  L->lines = bg_xcalloc((size_t)(L->nrow + 1) * (size_t)nc, sizeof *L->lines);
  L->rowh = bg_xmalloc((size_t)(L->nrow + 1) * sizeof(double));
  for (int r = -1; r < L->nrow; r++) {
    int most = 1;
    for (int c = 0; c < nc; c++) {
      bg_strbuf b = {0};
      if (r < 0) bg_sb_printf(&b, "<b>%s</b>", t->head[c]);
      else bg_sb_puts(&b, cell_of(t, r, c));
      double inner = L->w[c] - 2 * PAD_X;
      rp_lines *l = &L->lines[(size_t)(r + 1) * (size_t)nc + (size_t)c];
      rp_wrap(d->font, t->size, bg_sb_str(&b), inner, inner, l);
      bg_sb_free(&b);
      if (l->n > most) most = l->n;
    }
    L->rowh[r + 1] = most * L->lh + 2 * PAD_Y;
  }
  free(nat);
  free(mn);
}

static void draw_row(rp_doc *d, const rp_table *t, const tlay *L, int r) {
  bg_scene *s = rp_scene(d);
  double x = rp_left(), h = L->rowh[r + 1], total = 0;
  for (int c = 0; c < t->ncol; c++) total += L->w[c];
  if (r < 0) rp_fill_rect(s, x, d->y, total, h, rp_shade, "table-head");
  for (int c = 0; c < t->ncol; c++) {
    const rp_lines *l = &L->lines[(size_t)(r + 1) * (size_t)t->ncol + (size_t)c];
    int right = t->align && t->align[c] == 'r';
    for (int k = 0; k < l->n; k++) {
      double tx = right ? x + L->w[c] - PAD_X : x + PAD_X;
      rp_text(d, l->line[k], tx, d->y + PAD_Y + k * L->lh, t->size, right ? 1 : 0, rp_ink);
    }
    x += L->w[c];
  }
  rp_hline(s, rp_left(), rp_left() + total, d->y + h, r < 0 ? 0.7 : 0.3, r < 0 ? rp_ink : rp_rule);
  d->y += h;
}

static void free_layout(const rp_table *t, tlay *L) {
  for (size_t i = 0; i < (size_t)(L->nrow + 1) * (size_t)t->ncol; i++) rp_lines_free(&L->lines[i]);
  free(L->lines);
  free(L->rowh);
  free(L->w);
}

void rp_table_emit(rp_doc *d, rp_table *t) {
  rp_scene(d);
  tlay L;
  lay_out(d, t, &L);
  int *page = bg_xmalloc(((size_t)L.nrow + 1) * sizeof(int));
  rp_paginate(L.rowh + 1, L.nrow, L.rowh[0], rp_room(d), rp_page_room(d), page);
  int cur = 0;
  if (L.nrow == 0) {
    rp_need(d, L.rowh[0]);
    draw_row(d, t, &L, -1);
  }
  for (int r = 0; r < L.nrow; r++) {
    int head = r == 0;
    if (page[r] > cur) rp_new_page(d, 0), cur = page[r], head = 1;
    if (head) draw_row(d, t, &L, -1);
    draw_row(d, t, &L, r);
  }
  d->y += 6;
  free(page);
  free_layout(t, &L);
  table_free(t);
}
