/* SPDX-License-Identifier: BSD-3-Clause */
/* The public rendering API: option parsing, one layout per diagram, output
 * in any number of formats, written atomically. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"
#include "base/fileio.h"
#include "scene/surface.h"

static const char *const layer_names[] = {"strokes", "numbers", "paths",  "loops",    "conflicts",
                                          "signals", "labels",  "legend", "variables"};

static int show_word(const char *w, size_t n, unsigned *bits) {
  if (n == 3 && !strncmp(w, "all", 3)) return *bits |= BG_SHOW_ALL, 0;
  if (n == 4 && !strncmp(w, "none", 4)) return 0;
  for (unsigned i = 0; i < sizeof layer_names / sizeof layer_names[0]; i++)
    if (strlen(layer_names[i]) == n && !strncmp(w, layer_names[i], n)) return *bits |= 1u << i, 0;
  return -1;
}

int bg_show_parse(const char *list, unsigned *out) {
  unsigned bits = 0;
  const char *p = list;
  while (p && *p) {
    const char *e = strchr(p, ',');
    size_t n = e ? (size_t)(e - p) : strlen(p);
    while (n && *p == ' ') p++, n--;
    while (n && p[n - 1] == ' ') n--;
    if (show_word(p, n, &bits) != 0) return -1;
    p = e ? e + 1 : NULL;
  }
  /* "none" must stay distinguishable from "use the default" (0) */
  *out = bits ? bits : (1u << 31);
  return 0;
}

int bg_highlight_parse(const char *item, int *kind, int *index) {
  static const struct { const char *name; int kind; } kinds[] = {
      {"path:", 'p'}, {"loop:", 'l'}, {"conflict:", 'c'}};
  for (size_t i = 0; item && i < sizeof kinds / sizeof kinds[0]; i++) {
    size_t n = strlen(kinds[i].name);
    if (strncmp(item, kinds[i].name, n)) continue;
    char *end;
    errno = 0;
    long k = strtol(item + n, &end, 10);
    if (end == item + n || *end || errno || k < 1 || k > 1000000000) return -1;
    *kind = kinds[i].kind, *index = (int)k;
    return 0;
  }
  return -1;
}

int bg_diagram_render(bg_diagram *d, const char *format, bg_strbuf *out, bg_diags *dg) {
  int rc = 0;
  if (d->scene.nitem > 20000) /* progress under -v for a large diagram */
    bg_logf(d->o.log, BG_LOG_PROGRESS, "diagram: writing %s (%d items)", format, d->scene.nitem);
  if (!strcmp(format, "svg")) rc = bg_surface_svg_write_tips(&d->scene, bg_diagram_tip, d, out);
  else if (!strcmp(format, "svg-cairo")) rc = bg_surface_svg_cairo_write(&d->scene, out);
  else if (!strcmp(format, "pdf")) rc = bg_surface_pdf_write(&d->scene, out);
  else if (!strcmp(format, "png")) rc = bg_surface_png_write(&d->scene, d->st.png_scale, out);
  else if (!strcmp(format, "dot")) bg_diagram_write_dot(d, out);
  else {
    bg_diag_error(dg, (bg_srcloc){0}, "unknown diagram format '%s' (svg, pdf, png, dot)", format);
    return BG_RENDER_ERROR;
  }
  if (rc) {
    bg_diag_error(dg, (bg_srcloc){0}, "cairo could not draw the %s diagram", format);
    return BG_RENDER_ERROR;
  }
  return BG_RENDER_OK;
}

int bg_diagram_write(bg_diagram *d, const char *path, const char *format, bg_diags *dg) {
  if (!format) format = bg_path_ext(path);
  bg_strbuf out = {0};
  int rc = bg_diagram_render(d, format, &out, dg);
  if (rc == BG_RENDER_OK && bg_write_file_atomic(path, out.s ? out.s : "", out.len) != 0) {
    bg_diag_error(dg, (bg_srcloc){0}, "cannot write '%s': %s", path, bg_file_strerror(errno));
    rc = BG_RENDER_EWRITE;
  }
  if (rc == BG_RENDER_OK) bg_logf(d->o.log, BG_LOG_PROGRESS, "wrote %s (%zu bytes)", path, out.len);
  bg_sb_free(&out);
  return rc;
}

void bg_diagram_dump(const bg_diagram *d, bg_strbuf *out) { bg_scene_dump(&d->scene, out); }

const bg_scene *bg_diagram_scene(const bg_diagram *d) { return &d->scene; }

int bg_diagram_count(const bg_diagram *d, const char *prefix) {
  return bg_scene_count(&d->scene, prefix);
}

const char *bg_diagram_engine(const bg_diagram *d) { return d->L->lay.engine; }

void bg_diagram_size(const bg_diagram *d, double *w, double *h) {
  *w = d->scene.width, *h = d->scene.height;
}

