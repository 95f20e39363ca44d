/* SPDX-License-Identifier: BSD-3-Clause */
/* The versions of the rendering libraries, for bgdraw --version. */
#include "diagram/layout.h"
#include "diagram/render.h"
#include "scene/surface.h"

void bg_render_versions(bg_strbuf *out) {
  bg_sb_printf(out, "Graphviz %s, cairo %s, pango %s", bg_layout_graphviz_version(),
               bg_surface_cairo_version(), bg_surface_pango_version());
}
