/* SPDX-License-Identifier: BSD-3-Clause */
/* The "simulation" key of the analysis JSON (docs/cli.md), written when the
 * run simulated: status, solver and why, linear solver, tolerances, times,
 * rows, solver statistics, consistent initial values. Deterministic (no
 * wall-clock times), like the rest of the document. */
#ifndef BG_JSON_SIM_H
#define BG_JSON_SIM_H
#include "model/model.h"
#include "simulate/simulate.h"
#include "base/strbuf.h"


/* Adds the key to a finished analysis document (bg_json_write_analysis,
 * ending "\n}\n") as its last key. Leaves doc unchanged if it does not end so. */
void bg_json_append_simulation(bg_strbuf *doc, const bg_model *m, const bg_simresult *r,
                               int status);
/* Removes the closing "\n}\n" of a finished document and writes ",\n" so
 * one more top-level key can follow (then close with "\n}\n"); -1 when the
 * document does not end so (left unchanged). */
int bg_json_reopen(bg_strbuf *doc);
#endif
