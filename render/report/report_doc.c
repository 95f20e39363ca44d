/* SPDX-License-Identifier: BSD-3-Clause */
/* The report's document: A4 pages, each a bg_scene with other scenes
 * placed on it, a flowing cursor, headings recorded for the outline and the
 * contents, running header and footer, the multi-page PDF. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report/report_int.h"

void rp_doc_init(rp_doc *d, const char *font) {
  memset(d, 0, sizeof *d);
  d->font = font;
}

void rp_doc_free(rp_doc *d) {
  for (int i = 0; i < d->npage; i++) {
    bg_scene_free(&d->page[i]->sc);
    free(d->page[i]->place);
    free(d->page[i]);
  }
  free(d->page);
  for (int i = 0; i < d->nhead; i++) free(d->head[i].title);
  free(d->head);
  memset(d, 0, sizeof *d);
}

/* ---------------------------------------------------------------- pages */
void rp_new_page(rp_doc *d, int landscape) {
  if (d->npage == d->cappage) {
    d->cappage = d->cappage ? 2 * d->cappage : 16;
    d->page = bg_xrealloc(d->page, (size_t)d->cappage * sizeof *d->page);
  }
  rp_page *p = bg_xcalloc(1, sizeof *p);
  bg_scene_init(&p->sc, d->font);
  p->sc.width = landscape ? RP_A4_H : RP_A4_W;
  p->sc.height = landscape ? RP_A4_W : RP_A4_H;
  d->page[d->npage++] = p;
  d->y = RP_MARGIN_TOP;
}

bg_scene *rp_scene(rp_doc *d) {
  if (!d->npage) rp_new_page(d, 0);
  return &d->page[d->npage - 1]->sc;
}

static double page_w(const rp_doc *d) { return d->npage ? d->page[d->npage - 1]->sc.width : RP_A4_W; }
static double page_h(const rp_doc *d) { return d->npage ? d->page[d->npage - 1]->sc.height : RP_A4_H; }
double rp_left(void) { return RP_MARGIN_X; }
double rp_content_w(const rp_doc *d) { return page_w(d) - 2 * RP_MARGIN_X; }
double rp_page_room(const rp_doc *d) { return page_h(d) - RP_MARGIN_TOP - RP_MARGIN_BOTTOM; }

double rp_room(const rp_doc *d) {
  if (!d->npage) return RP_A4_H - RP_MARGIN_TOP - RP_MARGIN_BOTTOM;
  return page_h(d) - RP_MARGIN_BOTTOM - d->y;
}

static int page_empty(const rp_doc *d) { return d->npage && d->y <= RP_MARGIN_TOP + 0.01; }

void rp_need(rp_doc *d, double h) {
  if (!d->npage) rp_new_page(d, 0);
  else if (h > rp_room(d) && !page_empty(d)) rp_new_page(d, 0);
}

void rp_gap(rp_doc *d, double h) {
  if (!page_empty(d)) d->y += h;
}

/* ---------------------------------------------------------------- drawing */
bg_scene_item *rp_text(rp_doc *d, const char *markup, double x, double y, double size,
                       double halign, bg_rgba color) {
  return bg_scene_text(rp_scene(d), markup, x, y, size, halign, 0, color, "text");
}

void rp_fill_rect(bg_scene *s, double x, double y, double w, double h, bg_rgba fill,
                  const char *role) {
  bg_scene_item *it = bg_scene_begin(s, BG_ITEM_FILL, "%s", role);
  it->fill = fill;
  it->width = 0;
  bg_scene_move(s, x, y);
  bg_scene_line(s, x + w, y);
  bg_scene_line(s, x + w, y + h);
  bg_scene_line(s, x, y + h);
  bg_scene_close(s);
}

void rp_hline(bg_scene *s, double x0, double x1, double y, double width, bg_rgba c) {
  bg_scene_item *it = bg_scene_begin(s, BG_ITEM_STROKE, "rule");
  it->color = c;
  it->width = width;
  bg_scene_move(s, x0, y);
  bg_scene_line(s, x1, y);
}

void rp_place(rp_doc *d, const bg_scene *s, double sx, double sy, double sw, double sh, double x,
              double y, double scale) {
  rp_scene(d);
  rp_page *p = d->page[d->npage - 1];
  if (p->nplace == p->capplace) {
    p->capplace = p->capplace ? 2 * p->capplace : 4;
    p->place = bg_xrealloc(p->place, (size_t)p->capplace * sizeof *p->place);
  }
  p->place[p->nplace++] = (bg_surface_place){s, sx, sy, sw, sh, x, y, scale, 0};
}

void rp_outline(rp_doc *d, const char *title, int level, double y) {
  if (d->nhead == d->caphead) {
    d->caphead = d->caphead ? 2 * d->caphead : 16;
    d->head = bg_xrealloc(d->head, (size_t)d->caphead * sizeof *d->head);
  }
  rp_scene(d);
  d->head[d->nhead++] = (rp_head){strdup(title), level, d->npage - 1, y};
}

void rp_para(rp_doc *d, const char *markup, double size, double indent, double hang,
             bg_rgba color) {
  rp_scene(d);
  double w = rp_content_w(d) - indent;
  rp_lines l;
  rp_wrap(d->font, size, markup, w, w - hang, &l);
  double lh = rp_line_height(d->font, size);
  for (int i = 0; i < l.n; i++) {
    rp_need(d, lh);
    bg_scene_item *it = rp_text(d, l.line[i], rp_left() + indent + (i ? hang : 0), d->y, size, 0, color);
    d->y += it->th > lh ? it->th : lh;
  }
  rp_lines_free(&l);
}

double rp_para_height(const rp_doc *d, const char *markup, double size, double indent, double hang) {
  double w = rp_content_w(d) - indent;
  rp_lines l;
  rp_wrap(d->font, size, markup, w, w - hang, &l);
  double h = l.n * rp_line_height(d->font, size);
  rp_lines_free(&l);
  return h;
}

/* ---------------------------------------------------------------- headings */
void rp_section(rp_doc *d, const char *title, int numbered, int newpage, double keep) {
  double lh = rp_line_height(d->font, RP_SIZE_H1);
  if (newpage && !page_empty(d)) rp_new_page(d, 0);
  else rp_need(d, lh + 14 + keep);
  rp_gap(d, 12);
  char full[256];
  if (numbered) snprintf(full, sizeof full, "%d  %s", ++d->section, title);
  else snprintf(full, sizeof full, "%s", title);
  rp_outline(d, full, 0, d->y);
  bg_strbuf b = {0};
  bg_sb_puts(&b, "<b>");
  rp_esc(&b, full);
  bg_sb_puts(&b, "</b>");
  rp_text(d, bg_sb_str(&b), rp_left(), d->y, RP_SIZE_H1, 0, rp_accent);
  bg_sb_free(&b);
  d->y += lh + 2;
  rp_hline(rp_scene(d), rp_left(), rp_left() + rp_content_w(d), d->y, 0.6, rp_accent);
  d->y += 10;
}

double rp_subsection_height(const rp_doc *d) { return rp_line_height(d->font, RP_SIZE_H2) + 12; }

void rp_subsection(rp_doc *d, const char *title, double keep) {
  double lh = rp_line_height(d->font, RP_SIZE_H2);
  rp_need(d, rp_subsection_height(d) + keep); /* the gaps above (8) and below (4): keep whole below it */
  rp_gap(d, 8);
  rp_outline(d, title, 1, d->y);
  bg_strbuf b = {0};
  bg_sb_puts(&b, "<b>");
  rp_esc(&b, title);
  bg_sb_puts(&b, "</b>");
  rp_text(d, bg_sb_str(&b), rp_left(), d->y, RP_SIZE_H2, 0, rp_ink);
  bg_sb_free(&b);
  d->y += lh + 4;
}

/* ---------------------------------------------------------------- decoration, output */
void rp_decorate(rp_doc *d, const char *header, int first_header, int offset, int total) {
  for (int i = 0; i < d->npage; i++) {
    bg_scene *s = &d->page[i]->sc;
    double right = s->width - RP_MARGIN_X;
    char num[64];
    snprintf(num, sizeof num, "page %d of %d", i + offset + 1, total);
    bg_scene_text(s, num, s->width / 2, s->height - 34, RP_SIZE_SMALL, 0.5, 1, rp_grey, "footer");
    if (i < first_header) continue;
    bg_scene_text(s, header, RP_MARGIN_X, 34, RP_SIZE_SMALL, 0, 1, rp_grey, "header");
    bg_scene_text(s, "bgdraw analysis report", right, 34, RP_SIZE_SMALL, 1, 1, rp_grey, "header");
    rp_hline(s, RP_MARGIN_X, right, 38, 0.4, rp_rule);
  }
}

int rp_write_pdf(rp_doc *const *docs, int ndoc, const char *title, bg_strbuf *out) {
  int npage = 0, nol = 0;
  for (int k = 0; k < ndoc; k++) npage += docs[k]->npage, nol += docs[k]->nhead;
  bg_surface_page *pages = bg_xcalloc((size_t)npage + 1, sizeof *pages);
  bg_surface_outline *ol = bg_xcalloc((size_t)nol + 1, sizeof *ol);
  int ip = 0, io = 0;
  for (int k = 0; k < ndoc; k++) {
    const rp_doc *d = docs[k];
    for (int i = 0; i < d->nhead; i++)
      ol[io++] = (bg_surface_outline){d->head[i].title, d->head[i].level, ip + d->head[i].page,
                                      d->head[i].y};
    for (int i = 0; i < d->npage; i++)
      pages[ip++] = (bg_surface_page){&d->page[i]->sc, d->page[i]->place, d->page[i]->nplace};
  }
  int rc = bg_surface_pdf_pages(pages, npage, ol, nol, title, out);
  free(pages);
  free(ol);
  return rc;
}

void rp_figure(rp_doc *d, const bg_scene *s, const char *title) {
  double sc = rp_content_w(d) / s->width, room = rp_page_room(d) - 30;
  if (s->height * sc > room) sc = room / s->height;
  rp_subsection(d, title, s->height * sc);
  rp_place(d, s, 0, 0, s->width, s->height, rp_left() + (rp_content_w(d) - s->width * sc) / 2, d->y, sc);
  d->y += s->height * sc + 8;
}

/* ---------------------------------------------------------------- progress */
void rp_progress(const rp_ctx *c, const char *fmt, ...) {
  if (!c->in->ropts) return;
  char what[256];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(what, sizeof what, fmt, ap);
  va_end(ap);
  bg_logf(c->in->ropts->log, BG_LOG_PROGRESS, "report: %s", what);
}
