/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzz target: the equations (every printed form, the reduced form), the
 * numeric index of small systems, the analysis JSON, the model exports (C,
 * Python, Octave, Modelica, the FMU's description and glue) and the three
 * model transformations with their recompiled results (fuzz_common.h). */
#include "equations/equations.h"
#include "export/export.h"
#include "fuzz_common.h"
#include "fuzz_exports.h"
#include "json/json.h"
#include "transform/transform.h"

static void transforms(fuzz_run *f, size_t size) {
  static const char *const names[] = {"merge-stores", "parasitic", "relax-junction"};
  for (int i = 0; i < 3; i++) {
    bg_transform_input in = {names[i], f->src, size, "model.bg", f->ast, f->model,
                             &f->analysis, NULL, 0};
    bg_transform_result r;
    memset(&r, 0, sizeof r);
    char *why = NULL;
    if (bg_transform_apply(&in, &r, &why) == 0) bg_transform_result_free(&r);
    free(why);
  }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > FUZZ_MAX_LEN) return 0;
  fuzz_run f;
  if (fuzz_load(&f, data, size) == 0) {
    bg_eqsys *s = fuzz_eqsys(&f, size);
    bg_strbuf sb = {0};
    if (s) {
      static const char *const forms[] = {"text", "latex", "c", "json", "mathml"};
      for (int i = 0; i < 5; i++) bg_eqprint(s, forms[i], &sb);
      if (bg_eqsys_n(s) <= 40) { /* the dense index is cubic: keep runs short */
        bg_index_result ix;
        bg_index_compute(s, f.model, &ix);
        f.facts.numeric = &ix;
        bg_json_write_analysis(f.model, &f.analysis, &f.facts, &sb);
        f.facts.numeric = NULL;
        bg_index_free(&ix);
      }
      fuzz_exports(&f, size, 1);
    }
    bg_json_write_analysis(f.model, &f.analysis, &f.facts, &sb);
    bg_sb_free(&sb);
    if (s) bg_eqsys_free(s);
    transforms(&f, size);
  }
  fuzz_free(&f);
  return 0;
}
