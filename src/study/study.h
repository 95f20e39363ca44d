/* SPDX-License-Identifier: BSD-3-Clause */
/* Parameter studies (docs/study.md): one model run many times with params
 * changed, a sweep (listed values, linear or logarithmic ranges, the grid of
 * several params) or a Monte Carlo draw from stated distributions with a
 * seed, and per run the quantities asked for (final value, extrema, mean,
 * the times of the extrema, the first time an output reaches a level),
 * optionally the collected outputs' whole trajectories.
 *
 * Each run is its own bg_run (its own SUNDIALS context) on one of the
 * study's threads; run i's param values depend only on the spec and i, and
 * its results land in slot i, so every output is the same whatever the
 * number of threads or the subset of runs a machine computes. A run that
 * fails is recorded with its reason and the study goes on. */
#ifndef BG_STUDY_H
#define BG_STUDY_H
#include <stddef.h>
#include <stdint.h>

#include "base/log.h"
#include "base/strbuf.h"
#include "run/run.h"

enum { BG_STUDY_MAX_PARAMS = 16, BG_STUDY_MAX_COLLECT = 64, BG_STUDY_MAX_RUNS = 1000000 };

typedef enum bg_study_kind { BG_STUDY_SWEEP = 0, BG_STUDY_MONTE_CARLO } bg_study_kind;
typedef enum bg_dist { BG_DIST_NORMAL = 0, BG_DIST_UNIFORM, BG_DIST_LOGNORMAL } bg_dist;
typedef enum bg_collect_kind {
  BG_COLLECT_FINAL = 0, BG_COLLECT_MIN, BG_COLLECT_MAX, BG_COLLECT_MEAN,
  BG_COLLECT_TMIN, BG_COLLECT_TMAX, BG_COLLECT_CROSS,
  BG_COLLECT_POLES,                   /* the word `poles`: the linearisation's poles ... */
  BG_COLLECT_POLE_RE, BG_COLLECT_POLE_IM /* ... as the study's columns, one pair a pole */
} bg_collect_kind;

typedef struct bg_study_param {
  char *name;
  char *spec;     /* as written after '=' */
  int nvalues;    /* sweep: the values in order */
  double *values;
  bg_dist dist;   /* Monte Carlo: the distribution and its two numbers */
  double a, b;
} bg_study_param;

typedef struct bg_study_collect {
  char *var;      /* an output column, as in the CSV header ("C1.e"); "poles" for poles */
  bg_collect_kind kind;
  double level;   /* cross=LEVEL */
  int pole;       /* POLE_RE, POLE_IM: the pole's index (0-based) */
  char *label;    /* "C1.e:max", the column's name in the summary */
} bg_study_collect;

typedef struct bg_study_spec {
  bg_study_kind kind;
  bg_study_param params[BG_STUDY_MAX_PARAMS];
  int nparams;
  long draws;      /* Monte Carlo: number of runs */
  uint64_t seed;   /* Monte Carlo: the seed (default 1) */
  bg_study_collect collect[BG_STUDY_MAX_COLLECT];
  int ncollect;    /* 0: final, min and max of every output column */
} bg_study_spec;

/* Parsers of the command line's words (docs/study.md); 0, or -1 with the
 * reason in err. --sweep NAME=A:B:N[:log] | NAME=V1,V2,...; --vary
 * NAME=normal(MU,SIGMA) | uniform(LO,HI) | lognormal(MU,SIGMA); --collect
 * VAR:final|min|max|mean|tmin|tmax|cross=LEVEL. */
int bg_study_add_sweep(bg_study_spec *s, const char *arg, char *err, size_t n);
int bg_study_add_vary(bg_study_spec *s, const char *arg, char *err, size_t n);
int bg_study_add_collect(bg_study_spec *s, const char *arg, char *err, size_t n);
/* The number of runs (the grid's size, or the draws); 0 when none. */
long bg_study_nruns(const bg_study_spec *s);
/* Run i's param values (nparams of them), which depend only on s and i. */
void bg_study_values(const bg_study_spec *s, long i, double *out);
void bg_study_spec_free(bg_study_spec *s);

typedef enum bg_study_status {
  BG_STUDY_OK = 0, BG_STUDY_PARTIAL, BG_STUDY_REFUSED, BG_STUDY_FAILED, BG_STUDY_MODEL_ERROR
} bg_study_status;
/* "ok", "partial", "refused", "failed", "model-error" */
const char *bg_study_status_name(bg_study_status s);

typedef struct bg_study_run {
  double *param;       /* nparams values */
  bg_study_status status;
  char *reason;        /* why not ok, in words; NULL when ok */
  double *value;       /* the collected quantities (NaN: none, e.g. never crossed) */
  int nrows;           /* with keep_curves: the rows of the trajectories */
  double *t, *curve;   /* nrows times; nrows x ncurve values, row-major */
  int npole;           /* with poles wanted: the linearisation's poles, as --linear */
  double *pole_re, *pole_im; /* sorts them (by real part, then imaginary part) */
} bg_study_run;

typedef struct bg_study_opts {
  const char *name;    /* the model's name in diagnostics */
  const char *src;     /* the model text */
  size_t srclen;
  const bg_param_override *sets; /* --set overrides kept for every run */
  int nsets;
  int method;          /* bg_method; -1: the model's own */
  int jobs;            /* threads; <= 0: the number of cores */
  int keep_curves;     /* keep the collected outputs' trajectories (plots) */
  int want_poles;      /* keep each run's poles (the root locus) even when not collected */
  long first, count;   /* the runs computed: first .. first+count-1; count 0: all */
  bg_log log;          /* progress at most once a second under -v */
} bg_study_opts;

typedef struct bg_study {
  const bg_study_spec *spec;
  bg_study_collect *collect; /* the spec's, or the defaults (owned) */
  int ncollect, own_collect;
  long nruns;          /* the whole study's */
  long first, count;   /* the runs held: runs[k] is run first + k */
  bg_study_run *runs;
  int ncurve;          /* distinct outputs of the collected quantities */
  char **curve_name;
  int *collect_curve;  /* ncollect: the curve of each quantity (-1: a pole) */
  int npole;           /* the pole columns: the poles of the model at its own values */
  int want_poles;      /* the runs linearise the model and keep their poles */
  int need_sim;        /* the runs simulate (a quantity of an output, or curves) */
  long nfailed;
  int jobs;            /* the threads used */
  char *title;         /* the model's title, or its name (plots) */
} bg_study;

/* Runs the study; 0, or -1 with a reason in err (nothing to run, a param
 * that is not the model's, a model that does not load). Failures of single
 * runs are in their records, not here. */
int bg_study_run_all(const bg_study_spec *s, const bg_study_opts *o, bg_study *out, char *err,
                     size_t n);
/* The same without running: the spec checked against the model and the
 * records allocated (zero), for runs computed elsewhere (the merge). */
int bg_study_prepare(const bg_study_spec *s, const bg_study_opts *o, bg_study *out, char *err,
                     size_t n);
void bg_study_free(bg_study *st);
/* A run (not loaded) with run values param as --set overrides on top of o's
 * (a --set of a studied param gives way); the caller frees it. */
bg_run *bg_study_new_run(const bg_study_spec *s, const bg_study_opts *o, const double *param);
/* The summary table, one row per run: CSV (run, params, status, quantities,
 * reason) and the bgdraw-study JSON document (docs/study.md). */
void bg_study_write_csv(const bg_study *st, bg_strbuf *out);
void bg_study_csv_header(const bg_study *st, bg_strbuf *out); /* its first line */
void bg_study_write_json(const bg_study *st, bg_strbuf *out);

/* ---- linear studies (study_linear.c) */
/* The collected quantities with `poles` expanded into npole pairs of
 * columns pole1:re, pole1:im, ... (owned by st). */
void bg_study_expand_poles(bg_study *st, const bg_study_collect *q, int nq, int npole);
/* Run rec's poles from its pole columns (a merged part's rows). */
void bg_study_poles_from_values(const bg_study *st, bg_study_run *rec);
/* Up to max runs that succeeded, evenly chosen with the first and the last
 * among them (the family's choice); their indices into st->runs; the count. */
int bg_study_pick(const bg_study *st, int max, long *idx);

enum { BG_STUDY_BODE_RUNS = 12, BG_STUDY_BODE_POINTS = 300 };
/* The Bode family: the frequency responses of up to BG_STUDY_BODE_RUNS runs
 * (bg_study_pick) on one frequency grid, the union of each run's own
 * (bg_linear_freqs). mag in dB and phase in degrees, indexed
 * [(run * npair + pair) * nw + k]. */
typedef struct bg_study_bode {
  int nrun, npair, nw;
  long *run;            /* indices into st->runs */
  double *w, *mag, *phase;
  char **pair_name;     /* "vC ← U" */
} bg_study_bode;
/* Relinearises the chosen runs (their params as in the study, o's --set);
 * 0, or -1 with the reason in err (no run succeeded, not linearisable). */
int bg_study_bode_compute(const bg_study *st, const bg_study_opts *o, bg_study_bode *out,
                          char *err, size_t n);
void bg_study_bode_free(bg_study_bode *b);
#endif
