/* SPDX-License-Identifier: BSD-3-Clause */
/* Every model export of a fuzz input (C, Python, Octave, Modelica, the FMU's
 * description and glue), shared by fuzz_equations and fuzz_linear. The two
 * call it with other arguments, so between them both spellings of each are
 * fuzzed: `named` gives the C header's and the Octave function's names and
 * the FMU's GUID from the model's text; otherwise no header name, the
 * model's prefix as the Octave name and the GUID from the generated C. */
#ifndef BG_FUZZ_EXPORTS_H
#define BG_FUZZ_EXPORTS_H
#include "export/export.h"
#include "fuzz_common.h"

static void fuzz_exports(fuzz_run *f, size_t size, int named) {
  bg_diags dg;
  bg_diags_init(&dg, "fuzz", f->src, size);
  bg_eqsys *s = bg_eqsys_build_export(f->model, &f->analysis, &dg);
  bg_diags_free(&dg);
  if (!s) return;
  char prefix[80], guid[64];
  bg_export_default_prefix(f->model, prefix, sizeof prefix);
  bg_strbuf h = {0}, c = {0};
  bg_export_c(s, prefix, named ? "model.h" : NULL, &h, &c);
  bg_export_python(s, &c);
  bg_export_octave(s, named ? "model" : prefix, &c);
  bg_export_modelica(s, &c);
  if (named) bg_export_fmu_guid(f->src, size, guid, sizeof guid);
  else bg_export_fmu_guid(c.s ? c.s : "", c.len, guid, sizeof guid);
  bg_export_fmu_description(s, prefix, guid, &c);
  bg_export_fmu_glue(s, prefix, "model.h", guid, &c);
  bg_sb_free(&h);
  bg_sb_free(&c);
  bg_eqsys_free(s);
}
#endif
