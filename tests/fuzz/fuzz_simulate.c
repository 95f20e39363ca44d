/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzz target: a short simulation (at most 50 output rows, 500 steps per
 * interval), its CSV and its JSON (fuzz_common.h). */
#include "equations/equations.h"
#include "fuzz_common.h"
#include "json/json.h"
#include "simulate/simulate.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > FUZZ_MAX_LEN) return 0;
  fuzz_run f;
  if (fuzz_load(&f, data, size) == 0) {
    bg_eqsys *s = fuzz_eqsys(&f, size);
    /* the grid the model asks for, coarsened to at most 50 rows */
    bg_simspec *sp = &f.model->sim;
    if (sp->dt > 0 && (sp->t_end - sp->t0) / sp->dt > 50) sp->dt = 0;
    bg_sim_opts so = {0};
    so.max_steps = 500;
    bg_simresult r;
    int rc = bg_simulate(f.model, &f.analysis, s, &so, &r);
    bg_strbuf sb = {0};
    bg_csv_write(&r, &sb);
    bg_sb_clear(&sb);
    bg_json_write_analysis(f.model, &f.analysis, &f.facts, &sb);
    bg_json_append_simulation(&sb, f.model, &r, rc);
    bg_sb_free(&sb);
    bg_simresult_free(&r);
    if (s) bg_eqsys_free(s);
  }
  fuzz_free(&f);
  return 0;
}
