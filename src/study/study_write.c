/* SPDX-License-Identifier: BSD-3-Clause */
/* The study's summary table (docs/study.md): CSV with one row per run and
 * the bgdraw-study JSON document. Nothing of the machine goes in (no
 * times, no thread count), so the bytes depend only on the study. */
#include <math.h>
#include <string.h>

#include "study/study.h"

static const char *kind_word(const bg_study_collect *q) {
  static const char *w[] = {"final", "min", "max", "mean", "tmin", "tmax", "cross", "poles",
                            "pole-re", "pole-im"};
  return w[q->kind];
}

/* A CSV field: quoted when it holds a comma, a quote or a line break. */
static void csv_field(bg_strbuf *b, const char *s) {
  if (!strpbrk(s, ",\"\n\r")) {
    bg_sb_puts(b, s);
    return;
  }
  bg_sb_putc(b, '"');
  for (; *s; s++) {
    if (*s == '"') bg_sb_putc(b, '"');
    bg_sb_putc(b, *s);
  }
  bg_sb_putc(b, '"');
}

static void csv_num(bg_strbuf *b, double v) {
  if (isfinite(v)) bg_sb_num(b, v); /* none (never crossed, a failed run): empty */
}

void bg_study_csv_header(const bg_study *st, bg_strbuf *out) {
  const bg_study_spec *s = st->spec;
  bg_sb_puts(out, "run");
  for (int k = 0; k < s->nparams; k++) bg_sb_putc(out, ','), csv_field(out, s->params[k].name);
  bg_sb_puts(out, ",status");
  for (int k = 0; k < st->ncollect; k++) bg_sb_putc(out, ','), csv_field(out, st->collect[k].label);
  bg_sb_puts(out, ",reason\n");
}

void bg_study_write_csv(const bg_study *st, bg_strbuf *out) {
  const bg_study_spec *s = st->spec;
  bg_study_csv_header(st, out);
  for (long i = 0; i < st->count; i++) {
    const bg_study_run *r = &st->runs[i];
    bg_sb_printf(out, "%ld", st->first + i);
    for (int k = 0; k < s->nparams; k++) bg_sb_putc(out, ','), csv_num(out, r->param[k]);
    bg_sb_printf(out, ",%s", bg_study_status_name(r->status));
    for (int k = 0; k < st->ncollect; k++) bg_sb_putc(out, ','), csv_num(out, r->value[k]);
    bg_sb_putc(out, ',');
    if (r->reason) csv_field(out, r->reason);
    bg_sb_putc(out, '\n');
  }
}

void bg_study_write_json(const bg_study *st, bg_strbuf *out) {
  const bg_study_spec *s = st->spec;
  bg_sb_printf(out, "{\n  \"format\": \"bgdraw-study\",\n  \"version\": 1,\n  \"kind\": \"%s\",\n",
               s->kind == BG_STUDY_SWEEP ? "sweep" : "monte-carlo");
  if (s->kind == BG_STUDY_MONTE_CARLO) bg_sb_printf(out, "  \"seed\": %llu,\n", (unsigned long long)s->seed);
  bg_sb_printf(out, "  \"runs_total\": %ld,\n  \"first\": %ld,\n  \"count\": %ld,\n", st->nruns,
               st->first, st->count);
  long failed = 0;
  for (long i = 0; i < st->count; i++) failed += st->runs[i].status != BG_STUDY_OK;
  bg_sb_printf(out, "  \"failed\": %ld,\n  \"params\": [", failed);
  for (int k = 0; k < s->nparams; k++) {
    bg_sb_puts(out, k ? ", {\"name\": " : "{\"name\": ");
    bg_sb_json_str(out, s->params[k].name);
    bg_sb_puts(out, ", \"spec\": ");
    bg_sb_json_str(out, s->params[k].spec);
    bg_sb_putc(out, '}');
  }
  bg_sb_puts(out, "],\n  \"collect\": [");
  for (int k = 0; k < st->ncollect; k++) {
    const bg_study_collect *q = &st->collect[k];
    bg_sb_puts(out, k ? ",\n    {\"label\": " : "\n    {\"label\": ");
    bg_sb_json_str(out, q->label);
    int pole = q->kind == BG_COLLECT_POLE_RE || q->kind == BG_COLLECT_POLE_IM;
    bg_sb_puts(out, ", \"output\": ");
    if (pole) bg_sb_puts(out, "null");
    else bg_sb_json_str(out, q->var);
    bg_sb_printf(out, ", \"what\": \"%s\"", kind_word(q));
    if (pole) bg_sb_printf(out, ", \"pole\": %d", q->pole + 1);
    if (q->kind == BG_COLLECT_CROSS) bg_sb_puts(out, ", \"level\": "), bg_sb_json_num(out, q->level);
    bg_sb_putc(out, '}');
  }
  bg_sb_puts(out, st->ncollect ? "\n  ],\n  \"runs\": [" : "],\n  \"runs\": [");
  for (long i = 0; i < st->count; i++) {
    const bg_study_run *r = &st->runs[i];
    bg_sb_printf(out, "%s\n    {\"run\": %ld, \"params\": [", i ? "," : "", st->first + i);
    for (int k = 0; k < s->nparams; k++) bg_sb_puts(out, k ? ", " : ""), bg_sb_json_num(out, r->param[k]);
    bg_sb_printf(out, "], \"status\": \"%s\", \"values\": [", bg_study_status_name(r->status));
    for (int k = 0; k < st->ncollect; k++) bg_sb_puts(out, k ? ", " : ""), bg_sb_json_num(out, r->value[k]);
    bg_sb_puts(out, "], \"reason\": ");
    if (r->reason) bg_sb_json_str(out, r->reason);
    else bg_sb_puts(out, "null");
    bg_sb_putc(out, '}');
  }
  bg_sb_puts(out, st->count ? "\n  ]\n}\n" : "]\n}\n");
}
