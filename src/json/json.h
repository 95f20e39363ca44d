/* SPDX-License-Identifier: BSD-3-Clause */
/* The analysis JSON of docs/json.md (format "bgdraw-analysis", version 1):
 * every required key in the schema's order, 2-space indentation, one list
 * item per line, deterministic (same model and analysis, same bytes). The
 * json stage's front door: other stages include this header only. */
#ifndef BG_JSON_H
#define BG_JSON_H
#include "causality/causality.h"
#include "equations/equations.h"
#include "run/run.h"
#include "model/model.h"
#include "base/strbuf.h"

/* Appends the analysis document (ending with a newline) to out. Lists the
 * analysis has not filled (count 0) are written empty; f (nullable) gives
 * the numeric index, the reduced form and the index reduction, null while
 * not computed. */
void bg_json_write_analysis(const bg_model *m, const bg_analysis *a, const bg_index_facts *f,
                            bg_strbuf *out);
/* The whole document of a run, as `bgdraw -o x.json` writes it: the
 * analysis with the run's index facts, then the simulation and the linear
 * analysis when the run has them. */
void bg_json_write_run(const bg_run *r, bg_strbuf *out);
/* The `fields` key and list (json_fields.c; nothing without fields), and
 * whether field f's ports have more than one causality. */
void bg_json_put_fields(bg_strbuf *o, const bg_model *m, const bg_analysis *a);
int bg_json_field_mixed(const bg_model *m, const bg_analysis *a, int f);
/* The simulation's and the linear analysis' JSON objects. */
#include "json/json_linear.h"
#include "json/json_sim.h"
#endif
