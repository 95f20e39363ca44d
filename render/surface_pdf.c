/* PDF output through cairo's PDF surface. cairo 1.16 stamps the creation
 * date from the clock and ignores SOURCE_DATE_EPOCH, so we set it ourselves
 * (from SOURCE_DATE_EPOCH when set, else a fixed date) for reproducible files. */
#include <cairo-pdf.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "surface.h"
#include "surface_cairo.h"

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

int bg_surface_pdf_write(const bg_scene *s, bg_strbuf *out) {
  cairo_surface_t *sf =
      cairo_pdf_surface_create_for_stream(bg_surface_sink, out, s->width, s->height);
  char date[64];
  creation_date(date, sizeof date);
  cairo_pdf_surface_set_metadata(sf, CAIRO_PDF_METADATA_CREATE_DATE, date);
  cairo_pdf_surface_set_metadata(sf, CAIRO_PDF_METADATA_MOD_DATE, date);
  if (s->title) cairo_pdf_surface_set_metadata(sf, CAIRO_PDF_METADATA_TITLE, s->title);
  cairo_t *cr = cairo_create(sf);
  bg_surface_replay(cr, s);
  cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(sf);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(sf);
  cairo_surface_destroy(sf);
  return st == CAIRO_STATUS_SUCCESS ? 0 : -1;
}
