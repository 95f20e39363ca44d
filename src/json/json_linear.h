/* SPDX-License-Identifier: BSD-3-Clause */
/* The "linear" key of the analysis JSON (docs/json.md#linear), written when
 * the run made a linear analysis (docs/linear.md). Deterministic. */
#ifndef BG_JSON_LINEAR_H
#define BG_JSON_LINEAR_H
#include "base/strbuf.h"
#include "linear/linear.h"

/* Matrices are written up to this many unknowns (else "matrices_omitted"). */
enum { BG_JSON_LINEAR_MAX_MATRIX = 200 };

/* The object `{...}` (two-space indented as a top-level key's value). */
void bg_json_write_linear(const bg_linear *l, bg_strbuf *out);
/* Adds `"linear": {...}` as the last key of a finished analysis document. */
void bg_json_append_linear(bg_strbuf *doc, const bg_linear *l);
#endif
