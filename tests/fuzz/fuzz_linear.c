/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzz target: the linear analysis of a model (at its operating point, or
 * the steady state when the input's size is odd) in every printed form, its
 * JSON object and Octave/Python exports, the frequency and time responses,
 * and the Bode, Nyquist and step plots rendered as SVG; then the model
 * exports (C, Python, Octave, Modelica, the FMU's description and glue)
 * (fuzz_common.h). */
#include "export/export.h"
#include "fuzz_common.h"
#include "fuzz_exports.h"
#include "json/json_linear.h"
#include "linear/linear.h"
#include "plot/plot_linear.h"

static void linear(fuzz_run *f, size_t size) {
  bg_linear l;
  memset(&l, 0, sizeof l);
  if (bg_linear_compute(f->model, &f->analysis, size % 2 ? 1 : -1, &l) == 0) {
    bg_strbuf sb = {0};
    bg_linear_print(&l, f->model, "text", &sb);
    bg_linear_print(&l, f->model, "latex", &sb);
    bg_json_write_linear(&l, &sb);
    bg_linear_export_m(&l, f->model, &sb);
    bg_linear_export_py(&l, f->model, &sb);
    bg_diags dg;
    bg_diags_init(&dg, "fuzz", NULL, 0);
    for (int kind = BG_PLOT_BODE; kind <= BG_PLOT_STEP; kind++) {
      bg_sb_clear(&sb);
      bg_plot_linear_render(f->model, &l, kind, NULL, BG_SOURCE_DIR "/styles", "svg", NULL, &sb, &dg);
    }
    bg_diags_free(&dg);
    bg_sb_free(&sb);
  }
  bg_linear_free(&l);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > FUZZ_MAX_LEN) return 0;
  fuzz_run f;
  if (fuzz_load(&f, data, size) == 0) {
    linear(&f, size);
    fuzz_exports(&f, size, 0);
  }
  fuzz_free(&f);
  return 0;
}
