/* SPDX-License-Identifier: BSD-3-Clause */
/* PDF output through cairo's PDF surface. cairo 1.16 stamps the creation
 * date from the clock and ignores SOURCE_DATE_EPOCH, so we set it ourselves
 * (from SOURCE_DATE_EPOCH when set, else a fixed date) for reproducible files. */
#include <cairo-pdf.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "scene/surface.h"
#include "scene/surface_cairo.h"
#include "scene/text_int.h"

/* ISO 8601 date for the PDF metadata. */
static void creation_date(char *buf, size_t n) {
  const char *sde = getenv("SOURCE_DATE_EPOCH");
  char *end = NULL;
  long long secs = sde ? strtoll(sde, &end, 10) : 0;
  if (!sde || end == sde || *end || secs < 0) secs = 946684800; /* 2000-01-01 */
  time_t t = (time_t)secs;
  struct tm tm;
  gmtime_r(&t, &tm);
  strftime(buf, n, "%Y-%m-%dT%H:%M:%SZ", &tm);
}

/* A PDF surface writing to out, with the reproducible dates and the title. */
static cairo_surface_t *pdf_open(bg_strbuf *out, double w, double h, const char *title) {
  cairo_surface_t *sf = cairo_pdf_surface_create_for_stream(bg_surface_sink, out, w, h);
  char date[64];
  creation_date(date, sizeof date);
  cairo_pdf_surface_set_metadata(sf, CAIRO_PDF_METADATA_CREATE_DATE, date);
  cairo_pdf_surface_set_metadata(sf, CAIRO_PDF_METADATA_MOD_DATE, date);
  if (title) cairo_pdf_surface_set_metadata(sf, CAIRO_PDF_METADATA_TITLE, title);
  return sf;
}

int bg_surface_pdf_write(const bg_scene *s, bg_strbuf *out) {
  bg_text_lock();
  cairo_surface_t *sf = pdf_open(out, s->width, s->height, s->title);
  cairo_t *cr = cairo_create(sf);
  bg_surface_replay(cr, s);
  int rc = bg_surface_close(cr, sf);
  bg_text_unlock();
  return rc;
}

/* ---------------------------------------------------------------- multi-page */
/* A placement drawn as an image (surface.h): its items are rasterised at
 * p->raster pixels per page point, text too small to read left out, and the
 * page gets one image instead of every path and glyph of the region. */
static void draw_place_raster(cairo_t *cr, const bg_surface_place *p, const double *box) {
  double k = p->raster, px = p->scale * k; /* pixels per point of the placed scene */
  int w = (int)ceil(p->sw * px), h = (int)ceil(p->sh * px);
  if (w < 1 || h < 1 || w > 32000 || h > 32000) return;
  cairo_surface_t *img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
  cairo_t *ic = cairo_create(img);
  cairo_scale(ic, px, px);
  cairo_translate(ic, -p->sx, -p->sy);
  const double pad = BG_PLACE_CULL_PAD, clip[4] = {p->sx - pad, p->sy - pad, p->sx + p->sw + pad, p->sy + p->sh + pad};
  bg_surface_replay_clipped_text(ic, p->scene, clip, BG_RASTER_MIN_TEXT / px, box);
  cairo_destroy(ic);
  cairo_surface_flush(img);
  cairo_save(cr);
  cairo_rectangle(cr, p->x, p->y, p->sw * p->scale, p->sh * p->scale);
  cairo_clip(cr);
  cairo_translate(cr, p->x, p->y);
  cairo_scale(cr, 1 / k, 1 / k);
  cairo_set_source_surface(cr, img, 0, 0);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(img);
}

static void draw_place(cairo_t *cr, const bg_surface_place *p, const double *box) {
  if (p->raster > 0) {
    draw_place_raster(cr, p, box);
    return;
  }
  cairo_save(cr);
  cairo_rectangle(cr, p->x, p->y, p->sw * p->scale, p->sh * p->scale);
  cairo_clip(cr);
  cairo_translate(cr, p->x, p->y);
  cairo_scale(cr, p->scale, p->scale);
  cairo_translate(cr, -p->sx, -p->sy);
  /* a tile of a large diagram draws only what reaches into it (surface.h) */
  const double pad = BG_PLACE_CULL_PAD, clip[4] = {p->sx - pad, p->sy - pad, p->sx + p->sw + pad, p->sy + p->sh + pad};
  bg_surface_replay_clipped_text(cr, p->scene, clip, BG_PLACE_MIN_TEXT / p->scale, box);
  cairo_restore(cr);
}

/* Outline ids by level; an entry whose parent level is missing hangs at the root. */
static void add_outlines(cairo_surface_t *sf, const bg_surface_outline *ol, int nol) {
  enum { MAXLEVEL = 8 };
  int parent[MAXLEVEL + 1] = {CAIRO_PDF_OUTLINE_ROOT};
  for (int i = 0; i < nol; i++) {
    int lv = ol[i].level < 0 ? 0 : ol[i].level > MAXLEVEL - 1 ? MAXLEVEL - 1 : ol[i].level;
    char link[96];
    snprintf(link, sizeof link, "page=%d pos=[0 %.0f]", ol[i].page + 1, ol[i].y);
    int id = cairo_pdf_surface_add_outline(sf, parent[lv], ol[i].title, link,
                                           lv == 0 ? CAIRO_PDF_OUTLINE_FLAG_OPEN : 0);
    parent[lv + 1] = id;
    for (int k = lv + 2; k <= MAXLEVEL; k++) parent[k] = CAIRO_PDF_OUTLINE_ROOT;
  }
}

/* Item boxes of the scenes placed on many pages, each computed once: the
 * 48 tiles and the map of a 100 000-mass diagram each tested all of its two
 * million items' boxes. */
#define BOXED_PLACES 8
typedef struct boxed {
  const bg_scene *scene;
  double *box;
} boxed;

static int boxed_scenes(const bg_surface_page *pages, int npage, boxed *bx) {
  int n = 0;
  for (int i = 0; i < npage; i++)
    for (int k = 0; k < pages[i].nplace; k++) {
      const bg_scene *s = pages[i].place[k].scene;
      int uses = 0, known = 0;
      for (int j = 0; j < n; j++) known |= bx[j].scene == s;
      if (known || n == BOXED_PLACES || s->nitem < 1000) continue;
      for (int a = i; a < npage; a++)
        for (int b = 0; b < pages[a].nplace; b++) uses += pages[a].place[b].scene == s;
      if (uses < 4) continue;
      bx[n].scene = s;
      bx[n].box = bg_xmalloc(4 * (size_t)s->nitem * sizeof *bx[n].box);
      for (int j = 0; j < s->nitem; j++) bg_scene_item_box(s, &s->item[j], bx[n].box + 4 * (size_t)j);
      n++;
    }
  return n;
}

static const double *boxes_of(const boxed *bx, int n, const bg_scene *s) {
  for (int i = 0; i < n; i++)
    if (bx[i].scene == s) return bx[i].box;
  return NULL;
}

int bg_surface_pdf_pages(const bg_surface_page *pages, int npage, const bg_surface_outline *ol,
                         int nol, const char *title, bg_strbuf *out) {
  if (npage < 1) return -1;
  boxed bx[BOXED_PLACES];
  int nbx = boxed_scenes(pages, npage, bx);
  bg_text_lock();
  const bg_scene *first = pages[0].scene;
  cairo_surface_t *sf = pdf_open(out, first->width, first->height, title);
  cairo_t *cr = cairo_create(sf);
  for (int i = 0; i < npage && cairo_status(cr) == CAIRO_STATUS_SUCCESS; i++) {
    cairo_pdf_surface_set_size(sf, pages[i].scene->width, pages[i].scene->height);
    bg_surface_replay(cr, pages[i].scene);
    for (int k = 0; k < pages[i].nplace; k++)
      draw_place(cr, &pages[i].place[k], boxes_of(bx, nbx, pages[i].place[k].scene));
    cairo_show_page(cr);
  }
  add_outlines(sf, ol, nol);
  int rc = bg_surface_close(cr, sf);
  bg_text_unlock();
  for (int i = 0; i < nbx; i++) free(bx[i].box);
  return rc;
}
