/* SPDX-License-Identifier: BSD-3-Clause */
/* Linear studies (docs/study.md, "Linear studies"): the poles of each run
 * as columns of the table (`--collect poles`), and the Bode family, the
 * frequency responses of a few runs on one frequency grid. The poles come
 * from the run's own linearisation (src/linear, the same as --linear
 * prints); the Bode family relinearises the runs it draws, since a study
 * keeps no matrices. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "study/study.h"

static char *dup_str(const char *s) {
  size_t n = strlen(s) + 1;
  return memcpy(bg_xmalloc(n), s, n);
}

void bg_study_poles_from_values(const bg_study *st, bg_study_run *rec) {
  free(rec->pole_re), free(rec->pole_im);
  rec->pole_re = bg_xcalloc((size_t)st->npole + 1, sizeof(double));
  rec->pole_im = bg_xcalloc((size_t)st->npole + 1, sizeof(double));
  rec->npole = 0;
  for (int k = 0; k < st->ncollect; k++) {
    const bg_study_collect *q = &st->collect[k];
    if ((q->kind != BG_COLLECT_POLE_RE && q->kind != BG_COLLECT_POLE_IM) || !isfinite(rec->value[k]))
      continue;
    (q->kind == BG_COLLECT_POLE_RE ? rec->pole_re : rec->pole_im)[q->pole] = rec->value[k];
    if (q->pole + 1 > rec->npole) rec->npole = q->pole + 1;
  }
}

int bg_study_pick(const bg_study *st, int max, long *idx) {
  long n = 0;
  for (long i = 0; i < st->count; i++) n += st->runs[i].status == BG_STUDY_OK;
  if (n == 0) return 0;
  int m = n < max ? (int)n : max;
  long *ok = bg_xcalloc((size_t)n, sizeof *ok), k = 0;
  for (long i = 0; i < st->count; i++) if (st->runs[i].status == BG_STUDY_OK) ok[k++] = i;
  for (int j = 0; j < m; j++) idx[j] = ok[m == 1 ? 0 : (long)((double)j * (n - 1) / (m - 1) + 0.5)];
  free(ok);
  return m;
}

void bg_study_bode_free(bg_study_bode *b) {
  for (int p = 0; p < b->npair && b->pair_name; p++) free(b->pair_name[p]);
  free(b->pair_name), free(b->run), free(b->w), free(b->mag), free(b->phase);
  memset(b, 0, sizeof *b);
}

int bg_study_bode_compute(const bg_study *st, const bg_study_opts *o, bg_study_bode *out,
                          char *err, size_t n) {
  memset(out, 0, sizeof *out);
  out->run = bg_xcalloc(BG_STUDY_BODE_RUNS, sizeof *out->run);
  out->nrun = bg_study_pick(st, BG_STUDY_BODE_RUNS, out->run);
  if (out->nrun == 0) {
    snprintf(err, n, "no run of the study succeeded");
    bg_study_bode_free(out);
    return -1;
  }
  bg_run *R[BG_STUDY_BODE_RUNS] = {0};
  double lo = HUGE_VAL, hi = 0;
  int rc = 0;
  for (int j = 0; j < out->nrun && !rc; j++) {
    R[j] = bg_study_new_run(st->spec, o, st->runs[out->run[j]].param);
    const bg_linear *l = &R[j]->lin;
    if (bg_run_load_string(R[j], o->name, o->src) != 0 || bg_run_need(R[j], BG_STAGE_LINEAR) || !l->ok) {
      snprintf(err, n, "run %ld is not linearised: %s", st->first + out->run[j],
               l->message ? l->message : "the model has errors");
      rc = -1;
    } else if (l->nu * l->ny == 0) {
      snprintf(err, n, "the model has no inputs or no outputs");
      rc = -1;
    } else if (j && l->nu * l->ny != out->npair) {
      snprintf(err, n, "run %ld has another number of input/output pairs", st->first + out->run[j]);
      rc = -1;
    } else {
      double w[2];
      bg_linear_freqs(l, R[j]->model, 2, w); /* the run's own range: its two ends */
      lo = fmin(lo, w[0]), hi = fmax(hi, w[1]);
      out->npair = l->nu * l->ny;
    }
  }
  if (!rc) {
    if (hi / lo > 1e12) lo = hi * 1e-12; /* at most 12 decades, as one run's grid */
    int nw = out->nw = BG_STUDY_BODE_POINTS, np = out->npair;
    out->w = bg_xcalloc((size_t)nw, sizeof *out->w);
    for (int k = 0; k < nw; k++) out->w[k] = lo * pow(hi / lo, (double)k / (nw - 1));
    out->w[0] = lo, out->w[nw - 1] = hi;
    out->mag = bg_xcalloc((size_t)out->nrun * np * nw, sizeof *out->mag);
    out->phase = bg_xcalloc((size_t)out->nrun * np * nw, sizeof *out->phase);
    out->pair_name = bg_xcalloc((size_t)np, sizeof *out->pair_name);
    const bg_linear *l0 = &R[0]->lin;
    for (int p = 0; p < np; p++) {
      char buf[256];
      snprintf(buf, sizeof buf, "%s \xe2\x86\x90 %s", l0->yname[p / l0->nu], l0->uname[p % l0->nu]);
      out->pair_name[p] = dup_str(buf);
    }
    double *re = bg_xcalloc((size_t)nw * np, sizeof *re), *im = bg_xcalloc((size_t)nw * np, sizeof *im);
    for (int j = 0; j < out->nrun && !rc; j++) {
      const bg_linear *l = &R[j]->lin;
      if (bg_linear_freqresp(l, nw, out->w, re, im)) {
        snprintf(err, n, "run %ld: the frequency response could not be computed", st->first + out->run[j]);
        rc = -1;
        break;
      }
      for (int p = 0; p < np; p++) {
        size_t at = ((size_t)j * np + p) * nw;
        for (int k = 0; k < nw; k++) {
          double mag = hypot(re[(size_t)p * nw + k], im[(size_t)p * nw + k]);
          out->mag[at + k] = mag > 0 ? 20 * log10(mag) : -INFINITY;
        }
        bg_linear_phase(l, p, nw, out->w, re + (size_t)p * nw, im + (size_t)p * nw, out->phase + at);
      }
    }
    free(re), free(im);
  }
  for (int j = 0; j < out->nrun; j++) if (R[j]) bg_run_free(R[j]);
  if (rc) bg_study_bode_free(out);
  return rc;
}
