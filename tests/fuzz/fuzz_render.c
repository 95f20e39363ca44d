/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzz target: layout and drawing (Graphviz, cairo, pango): the diagram as
 * SVG and DOT with every layer, and redrawn with the first path highlighted
 * (fuzz_common.h), in the default, print or slides style by the input's size. */
#include "diagram/render.h"
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > FUZZ_MAX_LEN) return 0;
  fuzz_run f;
  if (fuzz_load(&f, data, size) == 0) {
    bg_render_opts o = {0};
    o.show = size % 2 ? BG_SHOW_ALL : BG_SHOW_DEFAULT | BG_SHOW_VARIABLES;
    o.style_dir = BG_SOURCE_DIR "/styles";
    /* every built-in style: print and slides lay the reference style's
     * layout out first and follow its routes (diagram_restyle.c) */
    static const char *const styles[3] = {NULL, "print", "slides"};
    o.style = styles[size / 2 % 3];
    bg_diags dg;
    bg_diags_init(&dg, "fuzz", NULL, 0);
    bg_diagram *d = bg_diagram_build(f.model, &f.analysis, &o, &dg);
    if (d) {
      bg_strbuf out = {0};
      bg_diagram_render(d, "svg", &out, &dg);
      bg_sb_clear(&out);
      bg_diagram_render(d, "dot", &out, &dg);
      bg_sb_free(&out);
      if (f.analysis.npath > 0) {
        bg_diagram *h = bg_diagram_redraw(d, BG_SHOW_ALL, 'p', 1, &dg);
        if (h) bg_diagram_free(h);
      }
      bg_diagram_free(d);
    }
    bg_diags_free(&dg);
  }
  fuzz_free(&f);
  return 0;
}
