/* SPDX-License-Identifier: BSD-3-Clause */
/* The study's driver (docs/study.md): checks the spec against the model
 * once (a probe run up to the equations), then runs the study's runs on
 * jobs threads. Each thread takes the next run number from a counter under
 * a lock, builds its own bg_run with the run's params as --set overrides,
 * simulates it and writes the record of that run only, so the records are
 * the same whatever thread computed them. The calling thread reports
 * progress at most once a second. */
#define _GNU_SOURCE /* clock_gettime, sysconf */
#include "study/study.h"

#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "base/arena.h"

/* The number of cores online (at least 1): -j's default. */
static int cores(void) {
  long n = sysconf(_SC_NPROCESSORS_ONLN);
  return n < 1 ? 1 : n > 256 ? 256 : (int)n;
}

typedef struct shared {
  const bg_study_spec *s;
  const bg_study_opts *o;
  bg_study *st;
  pthread_mutex_t lock;
  pthread_cond_t done_cv;
  long next, done, failed; /* under lock */
  int threads_left;        /* under lock */
} shared;

static char *xstrdup(const char *s) {
  size_t n = strlen(s) + 1;
  return memcpy(bg_xmalloc(n), s, n);
}

/* The collected quantity q of column c over rows [0, nrows). */
static double quantity(const bg_simresult *r, int c, const bg_study_collect *q) {
  int n = r->nrows, w = r->nout;
  const double *t = r->t, *v = r->values;
  if (n == 0) return NAN;
  double best = v[c];
  int at = 0;
  switch (q->kind) {
  case BG_COLLECT_FINAL: return v[(size_t)(n - 1) * w + c];
  case BG_COLLECT_MIN: case BG_COLLECT_TMIN:
    for (int i = 1; i < n; i++) if (v[(size_t)i * w + c] < best) best = v[(size_t)i * w + c], at = i;
    return q->kind == BG_COLLECT_MIN ? best : t[at];
  case BG_COLLECT_MAX: case BG_COLLECT_TMAX:
    for (int i = 1; i < n; i++) if (v[(size_t)i * w + c] > best) best = v[(size_t)i * w + c], at = i;
    return q->kind == BG_COLLECT_MAX ? best : t[at];
  case BG_COLLECT_MEAN: {
    if (n == 1 || t[n - 1] == t[0]) return v[c];
    double sum = 0; /* the trapezoid rule over the output rows */
    for (int i = 1; i < n; i++)
      sum += 0.5 * (v[(size_t)i * w + c] + v[(size_t)(i - 1) * w + c]) * (t[i] - t[i - 1]);
    return sum / (t[n - 1] - t[0]);
  }
  case BG_COLLECT_CROSS: { /* the first time the output reaches the level, interpolated */
    double L = q->level;
    if (v[c] == L) return t[0];
    for (int i = 1; i < n; i++) {
      double a = v[(size_t)(i - 1) * w + c] - L, b = v[(size_t)i * w + c] - L;
      if ((a < 0) != (b < 0) || b == 0) return t[i - 1] + (t[i] - t[i - 1]) * a / (a - b);
    }
    return NAN;
  }
  case BG_COLLECT_POLES: case BG_COLLECT_POLE_RE: case BG_COLLECT_POLE_IM: break; /* not a column's */
  }
  return NAN;
}

static int column(const bg_simresult *r, const char *name) {
  for (int k = 0; k < r->nout; k++) if (!strcmp(r->names[k], name)) return k;
  return -1;
}

bg_run *bg_study_new_run(const bg_study_spec *s, const bg_study_opts *o, const double *param) {
  bg_param_override *ov = bg_xcalloc((size_t)(o->nsets + s->nparams) + 1, sizeof *ov);
  int nov = 0;
  for (int k = 0; k < o->nsets; k++) { /* a --set of a studied param gives way */
    int studied = 0;
    for (int j = 0; j < s->nparams; j++) studied |= !strcmp(o->sets[k].name, s->params[j].name);
    if (!studied) ov[nov++] = o->sets[k];
  }
  for (int k = 0; k < s->nparams; k++) ov[nov++] = (bg_param_override){s->params[k].name, param[k]};
  bg_run_opts ro;
  bg_run_opts_init(&ro);
  ro.method = o->method, ro.sets = ov, ro.nsets = nov;
  bg_run *R = bg_run_new(&ro); /* copies the overrides */
  free(ov);
  return R;
}

/* A run's reason in words (malloc'd). */
static char *reason_printf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static char *reason_printf(const char *fmt, ...) {
  bg_strbuf b = {0};
  va_list ap;
  va_start(ap, fmt);
  bg_sb_vprintf(&b, fmt, ap);
  va_end(ap);
  return b.s ? b.s : xstrdup("");
}

/* The run's poles (its linearisation at the model's operating point). */
static void run_poles(const bg_study *st, bg_run *R, bg_study_run *rec) {
  bg_run_need(R, BG_STAGE_LINEAR);
  const bg_linear *l = &R->lin;
  if (!l->ok) {
    rec->status = BG_STUDY_REFUSED;
    rec->reason = reason_printf("not linearised: %s", l->message ? l->message : "no reason given");
    return;
  }
  if (st->npole && l->npole > st->npole) { /* the table has no room: refused, not cut */
    rec->status = BG_STUDY_FAILED;
    rec->reason = reason_printf("%d poles, more than the table's %d (the poles at the model's own values)",
                                l->npole, st->npole);
    return;
  }
  rec->npole = l->npole;
  rec->pole_re = bg_xcalloc((size_t)l->npole + 1, sizeof(double));
  rec->pole_im = bg_xcalloc((size_t)l->npole + 1, sizeof(double));
  memcpy(rec->pole_re, l->pole_re, (size_t)l->npole * sizeof(double));
  memcpy(rec->pole_im, l->pole_im, (size_t)l->npole * sizeof(double));
  for (int k = 0; k < st->ncollect; k++) {
    const bg_study_collect *q = &st->collect[k];
    if (q->kind == BG_COLLECT_POLE_RE || q->kind == BG_COLLECT_POLE_IM)
      rec->value[k] = q->pole >= rec->npole ? NAN : q->kind == BG_COLLECT_POLE_RE ? rec->pole_re[q->pole]
                                                                                 : rec->pole_im[q->pole];
  }
}

/* One run of the study: its params as overrides, the simulation, the
 * quantities. Writes only rec. */
static void one_run(const shared *sh, long i, bg_study_run *rec) {
  const bg_study_spec *s = sh->s;
  const bg_study_opts *o = sh->o;
  const bg_study *st = sh->st;
  rec->param = bg_xcalloc((size_t)s->nparams + 1, sizeof(double));
  rec->value = bg_xcalloc((size_t)st->ncollect + 1, sizeof(double));
  for (int k = 0; k < st->ncollect; k++) rec->value[k] = NAN;
  bg_study_values(s, i, rec->param);
  bg_run *R = bg_study_new_run(s, o, rec->param);
  if (bg_run_load_string(R, o->name, o->src) != 0 || !R->model) {
    rec->status = BG_STUDY_MODEL_ERROR;
    const char *why = "the model has errors";
    for (int k = R->dg.n - 1; k >= 0; k--)
      if (R->dg.items[k].sev == BG_SEV_ERROR) why = R->dg.items[k].msg;
    rec->reason = xstrdup(why);
    bg_run_free(R);
    return;
  }
  if (st->want_poles) run_poles(st, R, rec);
  if (!st->need_sim || rec->status != BG_STUDY_OK) {
    bg_run_free(R);
    return;
  }
  bg_run_need(R, BG_STAGE_SIMULATION);
  const bg_simresult *r = &R->sim;
  if (R->sim_status != 0 || r->partial) {
    const char *why = r->message ? r->message : R->eqsys_problem;
    rec->status = R->sim_status == 1 ? BG_STUDY_REFUSED : r->partial && r->nrows ? BG_STUDY_PARTIAL
                                                                                 : BG_STUDY_FAILED;
    rec->reason = xstrdup(why ? why : "the simulation failed");
    for (int k = 0; k < st->ncollect; k++) rec->value[k] = NAN; /* a failed run has no quantities */
  } else {
    for (int k = 0; k < st->ncollect; k++) {
      if (st->collect_curve[k] < 0) continue; /* a pole: above */
      int c = column(r, st->collect[k].var);
      if (c < 0) {
        rec->status = BG_STUDY_FAILED;
        rec->reason = reason_printf("'%s' is not an output of this run", st->collect[k].var);
        break;
      }
      rec->value[k] = quantity(r, c, &st->collect[k]);
    }
  }
  if (o->keep_curves && r->nrows && rec->status == BG_STUDY_OK) {
    rec->nrows = r->nrows;
    rec->t = bg_xcalloc((size_t)r->nrows, sizeof(double));
    memcpy(rec->t, r->t, (size_t)r->nrows * sizeof(double));
    rec->curve = bg_xcalloc((size_t)r->nrows * st->ncurve + 1, sizeof(double));
    for (int c = 0; c < st->ncurve; c++) {
      int col = column(r, st->curve_name[c]);
      for (int row = 0; row < r->nrows; row++)
        rec->curve[(size_t)row * st->ncurve + c] = r->values[(size_t)row * r->nout + col];
    }
  }
  bg_run_free(R);
}

static void *worker(void *arg) {
  shared *sh = arg;
  bg_study *st = sh->st;
  for (;;) {
    pthread_mutex_lock(&sh->lock);
    long k = sh->next < st->count ? sh->next++ : -1;
    pthread_mutex_unlock(&sh->lock);
    if (k < 0) break;
    one_run(sh, st->first + k, &st->runs[k]);
    pthread_mutex_lock(&sh->lock);
    sh->done++;
    sh->failed += st->runs[k].status != BG_STUDY_OK;
    pthread_cond_signal(&sh->done_cv);
    pthread_mutex_unlock(&sh->lock);
  }
  pthread_mutex_lock(&sh->lock);
  sh->threads_left--;
  pthread_cond_signal(&sh->done_cv);
  pthread_mutex_unlock(&sh->lock);
  return NULL;
}

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* The probe: the model loads with the overrides, the params are its own,
 * and the collected outputs are columns of its simulation (the defaults
 * when none is asked for: final, min and max of every column). */
static int probe(const bg_study_spec *s, const bg_study_opts *o, bg_study *st, char *err,
                 size_t n) {
  bg_run_opts ro;
  bg_run_opts_init(&ro);
  ro.method = o->method, ro.sets = o->sets, ro.nsets = o->nsets;
  bg_run *R = bg_run_new(&ro);
  int rc = 0;
  if (bg_run_load_string(R, o->name, o->src) != 0 || !R->model) {
    snprintf(err, n, "the model %s does not load", o->name);
    bg_run_free(R);
    return -1;
  }
  const bg_model *m = R->model;
  st->title = xstrdup(m->title ? m->title : m->name ? m->name : "model");
  for (int k = 0; k < s->nparams && !rc; k++) {
    int found = 0;
    for (int p = 0; p < m->nparam; p++) found |= !strcmp(m->param_name[p], s->params[k].name);
    if (!found) {
      const char *best = NULL;
      int bestd = 3;
      for (int p = 0; p < m->nparam; p++) {
        int d = bg_edit_distance(m->param_name[p], s->params[k].name);
        if (d < bestd) bestd = d, best = m->param_name[p];
      }
      snprintf(err, n, "'%s' is not a param of %s%s%s%s", s->params[k].name, m->name,
               best ? " (did you mean '" : "", best ? best : "", best ? "'?)" : "");
      rc = -1;
    }
  }
  int poles = o->want_poles;
  for (int k = 0; k < s->ncollect; k++) poles |= s->collect[k].kind == BG_COLLECT_POLES;
  if (poles && !rc) { /* the poles at the model's own values give the table its columns */
    bg_run_need(R, BG_STAGE_LINEAR);
    if (!R->lin.ok || R->lin.npole == 0) {
      snprintf(err, n, "the study asks for poles, but %s", !R->lin.ok
               ? (R->lin.message ? R->lin.message : "the model is not linearised")
               : "the linearisation has none (no states, or more than 500)");
      rc = -1;
    }
    st->want_poles = 1, st->npole = R->lin.npole;
  }
  bg_run_need(R, BG_STAGE_EQUATIONS);
  const bg_eqsys *E = R->eqsys;
  int nout = E ? bg_eqsys_noutput(E) : 0;
  for (int k = 0; k < s->ncollect && !rc && E; k++) {
    int found = s->collect[k].kind == BG_COLLECT_POLES;
    for (int c = 0; c < nout; c++) found |= !strcmp(bg_eqsys_output_name(E, c), s->collect[k].var);
    if (!found) {
      bg_strbuf sb = {0};
      for (int c = 0; c < nout; c++) bg_sb_printf(&sb, "%s%s", c ? ", " : "", bg_eqsys_output_name(E, c));
      snprintf(err, n, "--collect %s: '%s' is not an output of the simulation (outputs: %s)",
               s->collect[k].label, s->collect[k].var, bg_sb_str(&sb));
      bg_sb_free(&sb);
      rc = -1;
    }
  }
  if (!rc && s->ncollect) {
    if (poles) bg_study_expand_poles(st, s->collect, s->ncollect, st->npole);
    else st->collect = (bg_study_collect *)s->collect, st->ncollect = s->ncollect;
  } else if (!rc) {
    if (!E) {
      snprintf(err, n, "the equations cannot be formed (%s), so there are no outputs to collect",
               R->eqsys_problem ? R->eqsys_problem : "unknown reason");
      rc = -1;
    } else {
      static const bg_collect_kind def[] = {BG_COLLECT_FINAL, BG_COLLECT_MIN, BG_COLLECT_MAX};
      static const char *defname[] = {"final", "min", "max"};
      st->own_collect = 1;
      st->ncollect = 3 * nout;
      st->collect = bg_xcalloc((size_t)st->ncollect + 1, sizeof *st->collect);
      for (int c = 0; c < nout; c++)
        for (int d = 0; d < 3; d++) {
          bg_study_collect *q = &st->collect[3 * c + d];
          q->var = xstrdup(bg_eqsys_output_name(E, c));
          q->kind = def[d];
          q->label = bg_xmalloc(strlen(q->var) + 8);
          sprintf(q->label, "%s:%s", q->var, defname[d]);
        }
    }
  }
  /* the distinct outputs of the quantities, in order of first mention; a
   * family of a study that collects only poles draws every output */
  int only_poles = 1;
  for (int k = 0; k < st->ncollect; k++)
    only_poles &= st->collect[k].kind == BG_COLLECT_POLE_RE || st->collect[k].kind == BG_COLLECT_POLE_IM;
  int every = !rc && o->keep_curves && only_poles && E;
  st->curve_name = bg_xcalloc((size_t)st->ncollect + (every ? nout : 0) + 1, sizeof(char *));
  for (int c = 0; every && c < nout; c++) st->curve_name[st->ncurve++] = xstrdup(bg_eqsys_output_name(E, c));
  bg_run_free(R);
  if (rc) return rc;
  st->collect_curve = bg_xcalloc((size_t)st->ncollect + 1, sizeof(int));
  for (int k = 0; k < st->ncollect; k++) {
    int c = 0;
    if (st->collect[k].kind == BG_COLLECT_POLE_RE || st->collect[k].kind == BG_COLLECT_POLE_IM) {
      st->collect_curve[k] = -1;
      continue;
    }
    st->need_sim = 1;
    while (c < st->ncurve && strcmp(st->curve_name[c], st->collect[k].var)) c++;
    if (c == st->ncurve) st->curve_name[st->ncurve++] = xstrdup(st->collect[k].var);
    st->collect_curve[k] = c;
  }
  st->need_sim |= o->keep_curves;
  return 0;
}

int bg_study_prepare(const bg_study_spec *s, const bg_study_opts *o, bg_study *st, char *err,
                     size_t n) {
  memset(st, 0, sizeof *st);
  st->spec = s;
  st->nruns = bg_study_nruns(s);
  if (st->nruns <= 0) {
    snprintf(err, n, "the study has no runs");
    return -1;
  }
  st->first = o->first, st->count = o->count ? o->count : st->nruns - o->first;
  if (st->first < 0 || st->first >= st->nruns || st->count < 0 || st->first + st->count > st->nruns) {
    snprintf(err, n, "runs %ld..%ld are not in the study's 0..%ld", o->first,
             o->first + st->count - 1, st->nruns - 1);
    return -1;
  }
  if (probe(s, o, st, err, n)) {
    bg_study_free(st); /* what the probe kept (the title, the default quantities) */
    return -1;
  }
  st->runs = bg_xcalloc((size_t)st->count, sizeof *st->runs);
  return 0;
}

int bg_study_run_all(const bg_study_spec *s, const bg_study_opts *o, bg_study *st, char *err,
                     size_t n) {
  if (bg_study_prepare(s, o, st, err, n)) return -1;
  int jobs = o->jobs > 0 ? o->jobs : cores();
  if (jobs > st->count) jobs = (int)st->count;
  st->jobs = jobs;
  shared sh = {s, o, st, PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, 0, 0, 0, jobs};
  pthread_t *th = bg_xcalloc((size_t)jobs, sizeof *th);
  double t0 = now(), last = t0;
  int started = 0;
  for (; started < jobs; started++)
    if (pthread_create(&th[started], NULL, worker, &sh)) break;
  if (started == 0) { /* no thread: the calling thread does the work */
    sh.threads_left = 1;
    worker(&sh);
  } else {
    pthread_mutex_lock(&sh.lock);
    sh.threads_left -= jobs - started; /* threads that did not start never finish */
    while (sh.threads_left > 0) {
      struct timespec ts;
      clock_gettime(CLOCK_REALTIME, &ts);
      ts.tv_sec += 1;
      pthread_cond_timedwait(&sh.done_cv, &sh.lock, &ts);
      double t = now();
      if (t - last >= 1.0 && sh.done < st->count) {
        last = t;
        double left = sh.done ? (t - t0) * (st->count - sh.done) / sh.done : NAN;
        int w = 30, bar = (int)(w * sh.done / st->count);
        char b[40];
        for (int k = 0; k < w; k++) b[k] = k < bar ? '#' : '.';
        b[w] = '\0';
        if (isnan(left))
          bg_logf(&o->log, BG_LOG_PROGRESS, "study [%s] %ld/%ld runs, %ld failed", b, sh.done,
                  st->count, sh.failed);
        else
          bg_logf(&o->log, BG_LOG_PROGRESS, "study [%s] %ld/%ld runs, %ld failed, %.0f s left", b,
                  sh.done, st->count, sh.failed, ceil(left));
      }
    }
    pthread_mutex_unlock(&sh.lock);
    for (int k = 0; k < started; k++) pthread_join(th[k], NULL);
  }
  free(th);
  st->nfailed = sh.failed;
  bg_logf(&o->log, BG_LOG_PROGRESS, "study: %ld runs on %d thread%s in %.3g s, %ld failed",
          st->count, jobs, jobs == 1 ? "" : "s", now() - t0, st->nfailed);
  return 0;
}

void bg_study_free(bg_study *st) {
  for (long k = 0; st->runs && k < st->count; k++) {
    bg_study_run *r = &st->runs[k];
    free(r->param), free(r->reason), free(r->value), free(r->t), free(r->curve);
    free(r->pole_re), free(r->pole_im);
  }
  free(st->runs);
  if (st->own_collect)
    for (int k = 0; k < st->ncollect; k++) free(st->collect[k].var), free(st->collect[k].label);
  if (st->own_collect) free(st->collect);
  for (int c = 0; c < st->ncurve; c++) free(st->curve_name[c]);
  free(st->curve_name), free(st->collect_curve), free(st->title);
  memset(st, 0, sizeof *st);
}
