/* SPDX-License-Identifier: BSD-3-Clause */
/* The analysis document of a run (json.h, bg_json_write_run): the one
 * writer the command line, the library and the report's callers share. */
#include "json/json.h"

void bg_json_write_run(const bg_run *r, bg_strbuf *out) {
  bg_json_write_analysis(r->model, &r->analysis, &r->facts, out);
  if (bg_run_has(r, BG_STAGE_SIMULATION))
    bg_json_append_simulation(out, r->model, &r->sim, r->sim_status);
  if (bg_run_has(r, BG_STAGE_LINEAR)) bg_json_append_linear(out, &r->lin);
}
