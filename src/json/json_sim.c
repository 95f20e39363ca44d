/* SPDX-License-Identifier: BSD-3-Clause */
/* The "simulation" key of the analysis JSON (docs/cli.md): how a simulation
 * that ran with the analysis went (status, solver and why, tolerances,
 * statistics, consistent initial values). Kept apart from src/json.c, which
 * writes the analysis itself; this only appends one key to its document. */
#include "json/json_sim.h"

#include <string.h>

static void str_or_null(bg_strbuf *o, const char *s) {
  if (s) bg_sb_json_str(o, s);
  else bg_sb_puts(o, "null");
}

static const char *status_name(int status) {
  return status == 0 ? "ok" : status == 1 ? "refused" : "failed";
}

/* --verify: null unless asked; the deviation of each output (docs/json.md). */
static void put_verify(bg_strbuf *o, const bg_simresult *r) {
  bg_sb_puts(o, ",\n    \"verify\": ");
  if (!r->verified) { bg_sb_puts(o, "null"); return; }
  bg_sb_puts(o, "{\"rtol\": "); /* null when no solver ran (an algebraic model) */
  if (r->n) bg_sb_json_num(o, r->verify_rtol);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ", \"atol\": ");
  if (r->n) bg_sb_json_num(o, r->verify_atol);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ", \"outputs\": [");
  for (int k = 0; r->verified > 0 && k < r->nout; k++) {
    bg_sb_printf(o, "%s{\"name\": ", k ? ", " : "");
    bg_sb_json_str(o, r->names[k]);
    bg_sb_puts(o, ", \"deviation\": ");
    bg_sb_json_num(o, r->verify_dev[k]);
    bg_sb_puts(o, "}");
  }
  bg_sb_puts(o, "], \"worst\": ");
  if (r->verified > 0) bg_sb_json_num(o, r->verify_worst);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ", \"bound\": ");
  if (r->verified > 0) bg_sb_json_num(o, BG_VERIFY_BOUND * r->verify_worst);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ", \"worst_of\": ");
  if (r->verified > 0 && r->verify_worst_name) bg_sb_json_str(o, r->verify_worst_name);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ", \"states\": ");
  if (r->verified > 0 && r->verify_state_worst >= 0) bg_sb_json_num(o, r->verify_state_worst);
  else bg_sb_puts(o, "null");
  if (r->verified > 0 && r->nconditions > 0) {
    bg_sb_printf(o, ", \"events\": {\"count\": %d, \"tighter_count\": %d, \"time_deviation\": ", r->nevents,
                 r->verify_events_other);
    if (r->verify_event_dt >= 0) bg_sb_json_num(o, r->verify_event_dt);
    else bg_sb_puts(o, "null");
    bg_sb_puts(o, ", \"part_at\": ");
    if (r->verify_event_dt < 0) bg_sb_json_num(o, r->verify_event_t);
    else bg_sb_puts(o, "null");
    bg_sb_puts(o, "}");
  }
  bg_sb_printf(o, ", \"too_loose\": %s, \"text\": ", r->verified > 0 && r->verify_worst > BG_VERIFY_LOOSE ? "true" : "false");
  bg_strbuf t = {0};
  bg_sim_verify_text(r, &t);
  bg_sb_json_str(o, bg_sb_str(&t));
  bg_sb_free(&t);
  bg_sb_puts(o, "}");
}

/* State events: only for a model with switching conditions (docs/json.md),
 * so the documents of models without them are as they were. */
static void put_events(bg_strbuf *o, const bg_simresult *r) {
  if (r->nconditions <= 0) return;
  bg_sb_printf(o, ",\n    \"events\": {\"searched\": %s, \"conditions\": [", r->events_searched ? "true" : "false");
  for (int i = 0; i < r->nconditions; i++) {
    if (i) bg_sb_puts(o, ", ");
    bg_sb_json_str(o, r->condition_text[i]);
  }
  bg_sb_printf(o, "], \"count\": %d, \"list\": [", r->nevents);
  for (int k = 0; k < r->nevents; k++) {
    bg_sb_puts(o, k ? ",\n      {\"t\": " : "\n      {\"t\": ");
    bg_sb_json_num(o, r->event_t[k]);
    bg_sb_printf(o, ", \"condition\": %d, \"direction\": \"%s\"}", r->event_cond[k],
                 r->event_dir[k] > 0 ? "rising" : "falling");
  }
  bg_sb_puts(o, r->nevents ? "\n    ]}" : "]}");
}

/* The accuracy control of a switching model at default tolerances: only
 * when it ran (docs/json.md, docs/simulation.md "Accuracy through events"). */
static void put_control(bg_strbuf *o, const bg_simresult *r) {
  if (r->control_runs <= 0) return;
  bg_sb_printf(o, ",\n    \"accuracy_control\": {\"runs\": %d, \"deviation\": ", r->control_runs);
  bg_sb_json_num(o, r->control_dev);
  bg_sb_printf(o, ", \"target\": ");
  bg_sb_json_num(o, BG_SIM_SWITCH_TARGET);
  bg_sb_printf(o, ", \"reached\": %s}", r->control_short ? "false" : "true");
}

/* Appends `  "simulation": {...}` (no trailing comma or newline) to o.
 * status is bg_simulate's return: 0 ok, 1 refused, 2 failed. */
static void write_simulation(const bg_model *m, const bg_simresult *r, int status, bg_strbuf *o) {
  bg_sb_puts(o, "  \"simulation\": {\n    \"status\": ");
  bg_sb_json_str(o, status_name(status));
  bg_sb_puts(o, ",\n    \"message\": ");
  str_or_null(o, r->message);
  bg_sb_puts(o, ",\n    \"solver\": ");
  str_or_null(o, r->solver_used);
  bg_sb_puts(o, ",\n    \"solver_reason\": ");
  str_or_null(o, r->solver_reason);
  bg_sb_puts(o, ",\n    \"linear_solver\": ");
  str_or_null(o, r->linear_solver);
  bg_sb_puts(o, ",\n    \"unknowns\": ");
  if (r->solver_used) bg_sb_printf(o, "%d", r->n);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ",\n    \"rtol\": ");
  if (r->solver_used) bg_sb_json_num(o, r->rtol);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ",\n    \"atol\": ");
  if (r->solver_used) bg_sb_json_num(o, r->atol);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ",\n    \"t0\": ");
  bg_sb_json_num(o, m->sim.t0);
  bg_sb_puts(o, ",\n    \"t_end\": ");
  bg_sb_json_num(o, m->sim.t_end);
  bg_sb_puts(o, ",\n    \"t_reached\": ");
  if (r->solver_used) bg_sb_json_num(o, r->t_reached);
  else bg_sb_puts(o, "null");
  bg_sb_printf(o, ",\n    \"rows\": %d,\n    \"partial\": %s", r->nrows, r->partial ? "true" : "false");
  bg_sb_printf(o, ",\n    \"statistics\": {\"steps\": %ld, \"function_evaluations\": %ld, "
                  "\"jacobian_evaluations\": %ld, \"error_test_failures\": %ld, "
                  "\"nonlinear_iterations\": %ld}",
               r->steps, r->rhs_evals, r->jac_evals, r->err_test_fails, r->nonlin_iters);
  bg_sb_printf(o, ",\n    \"initial_values\": {\"changed\": %s, \"guess_retries\": %d, \"report\": ",
               r->consistent_ic_changed ? "true" : "false", r->ic_retries);
  str_or_null(o, r->ic_report);
  bg_sb_printf(o, "},\n    \"row_check\": {\"rows_redone\": %d, \"rows_violating\": %d, \"worst\": ",
               r->rows_redone, r->rows_violating);
  if (r->rows_violating) bg_sb_json_num(o, r->row_worst);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ", \"worst_t\": ");
  if (r->rows_violating) bg_sb_json_num(o, r->row_worst_t);
  else bg_sb_puts(o, "null");
  bg_sb_puts(o, ", \"worst_unknown\": ");
  str_or_null(o, r->rows_violating ? r->row_worst_unknown : NULL);
  bg_sb_puts(o, ", \"warning\": ");
  bg_strbuf w = {0};
  str_or_null(o, bg_simresult_row_warning(r, &w) ? bg_sb_str(&w) : NULL);
  bg_sb_free(&w);
  bg_sb_puts(o, "}");
  put_verify(o, r);
  put_events(o, r);
  put_control(o, r);
  bg_sb_puts(o, "\n  }");
}

int bg_json_reopen(bg_strbuf *doc) {
  static const char end[] = "\n}\n";
  size_t ne = sizeof end - 1;
  if (doc->len < ne || memcmp(doc->s + doc->len - ne, end, ne) != 0) return -1;
  doc->len -= ne; /* reopen the document's top-level object */
  doc->s[doc->len] = 0;
  bg_sb_puts(doc, ",\n");
  return 0;
}

void bg_json_append_simulation(bg_strbuf *doc, const bg_model *m, const bg_simresult *r,
                               int status) {
  if (bg_json_reopen(doc)) return;
  write_simulation(m, r, status, doc);
  bg_sb_puts(doc, "\n}\n");
}
