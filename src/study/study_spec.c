/* SPDX-License-Identifier: BSD-3-Clause */
/* A study's words (docs/study.md): --sweep, --vary and --collect parsed
 * into a bg_study_spec, and the param values of run i. Sweeps form the grid
 * of their params, the first param varying slowest (nested loops in the
 * order written). Monte Carlo draws come from a generator seeded by the
 * seed and the run's number alone (splitmix64 to seed xoshiro256**, both
 * written here: GSL has them but is GPL, and a study needs twenty lines),
 * so run i draws the same values on any machine, thread or subset. */
#define _DEFAULT_SOURCE /* M_PI */
#include "study/study.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"

static char *dupn(const char *s, size_t n) {
  char *d = bg_xmalloc(n + 1);
  memcpy(d, s, n);
  d[n] = '\0';
  return d;
}

/* A finite number filling exactly [s, e); 0 or -1. */
static int number(const char *s, const char *e, double *v) {
  if (s == e) return -1;
  char buf[64];
  if ((size_t)(e - s) >= sizeof buf) return -1;
  memcpy(buf, s, (size_t)(e - s));
  buf[e - s] = '\0';
  char *end;
  errno = 0;
  *v = strtod(buf, &end);
  return *end || errno == ERANGE || !isfinite(*v) || buf[0] == ' ' ? -1 : 0;
}

/* NAME=REST: the name (a param name: letters, digits, '_', '.') checked. */
static const char *split_name(bg_study_spec *s, const char *arg, const char *opt, char *err,
                              size_t n) {
  const char *eq = strchr(arg, '=');
  if (!eq || eq == arg) {
    snprintf(err, n, "%s wants NAME=%s, not '%s'", opt,
             strcmp(opt, "--vary") ? "VALUES" : "DISTRIBUTION", arg);
    return NULL;
  }
  if (s->nparams == BG_STUDY_MAX_PARAMS) {
    snprintf(err, n, "a study varies at most %d params", BG_STUDY_MAX_PARAMS);
    return NULL;
  }
  for (int i = 0; i < s->nparams; i++)
    if (strlen(s->params[i].name) == (size_t)(eq - arg) &&
        !strncmp(s->params[i].name, arg, (size_t)(eq - arg))) {
      snprintf(err, n, "%s: param '%s' is varied twice", opt, s->params[i].name);
      return NULL;
    }
  return eq;
}

static int too_many(long nruns, char *err, size_t n) {
  snprintf(err, n, "the study would have %ld runs or more (at most %d)", nruns,
           BG_STUDY_MAX_RUNS);
  return -1;
}

int bg_study_add_sweep(bg_study_spec *s, const char *arg, char *err, size_t n) {
  if (s->kind == BG_STUDY_MONTE_CARLO && s->nparams) {
    snprintf(err, n, "--sweep and --vary do not combine: a study is a sweep or a Monte Carlo draw");
    return -1;
  }
  const char *eq = split_name(s, arg, "--sweep", err, n);
  if (!eq) return -1;
  const char *v = eq + 1;
  double *vals = NULL;
  int nv = 0;
  if (strchr(v, ':')) { /* A:B:N or A:B:N:log */
    const char *c1 = strchr(v, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
    const char *c3 = c2 ? strchr(c2 + 1, ':') : NULL;
    double a, b, cnt;
    int lg = c3 && !strcmp(c3 + 1, "log");
    if (!c2 || (c3 && !lg) || number(v, c1, &a) || number(c1 + 1, c2, &b) ||
        number(c2 + 1, c3 ? c3 : c2 + strlen(c2), &cnt) || cnt != floor(cnt) || cnt < 1) {
      snprintf(err, n, "--sweep %s: a range is FROM:TO:COUNT or FROM:TO:COUNT:log (COUNT a "
               "whole number >= 1)", arg);
      return -1;
    }
    if (lg && (a <= 0 || b <= 0)) {
      snprintf(err, n, "--sweep %s: a logarithmic range needs FROM and TO above 0", arg);
      return -1;
    }
    if (cnt > BG_STUDY_MAX_RUNS) return too_many((long)cnt, err, n);
    nv = (int)cnt;
    vals = bg_xcalloc((size_t)nv, sizeof *vals);
    for (int k = 0; k < nv; k++) {
      double f = nv == 1 ? 0 : (double)k / (nv - 1);
      /* the ends exactly as written; between them by the same formula on any machine */
      vals[k] = k == 0 ? a : k == nv - 1 ? b
              : lg ? exp(log(a) + f * (log(b) - log(a))) : a + f * (b - a);
    }
  } else { /* V1,V2,... */
    for (const char *p = v;; ) {
      const char *c = strchr(p, ',');
      const char *e = c ? c : p + strlen(p);
      double x;
      if (number(p, e, &x)) {
        free(vals);
        snprintf(err, n, "--sweep %s: '%.*s' is not a number (values are V1,V2,... or a range "
                 "FROM:TO:COUNT[:log])", arg, (int)(e - p), p);
        return -1;
      }
      if (nv == BG_STUDY_MAX_RUNS) { free(vals); return too_many(nv, err, n); }
      vals = bg_xrealloc(vals, (size_t)(nv + 1) * sizeof *vals);
      vals[nv++] = x;
      if (!c) break;
      p = c + 1;
    }
  }
  long total = (long)nv * (s->nparams ? bg_study_nruns(s) : 1);
  if (total > BG_STUDY_MAX_RUNS) { free(vals); return too_many(total, err, n); }
  bg_study_param *p = &s->params[s->nparams++];
  memset(p, 0, sizeof *p);
  p->name = dupn(arg, (size_t)(eq - arg));
  p->spec = dupn(v, strlen(v));
  p->values = vals, p->nvalues = nv;
  s->kind = BG_STUDY_SWEEP;
  return 0;
}

int bg_study_add_vary(bg_study_spec *s, const char *arg, char *err, size_t n) {
  if (s->kind == BG_STUDY_SWEEP && s->nparams) {
    snprintf(err, n, "--sweep and --vary do not combine: a study is a sweep or a Monte Carlo draw");
    return -1;
  }
  const char *eq = split_name(s, arg, "--vary", err, n);
  if (!eq) return -1;
  static const struct { const char *name; bg_dist d; } dists[] = {
      {"normal", BG_DIST_NORMAL}, {"uniform", BG_DIST_UNIFORM}, {"lognormal", BG_DIST_LOGNORMAL}};
  const char *v = eq + 1, *open = strchr(v, '('), *comma = open ? strchr(open, ',') : NULL;
  const char *close = comma ? strchr(comma, ')') : NULL;
  int d = -1;
  for (int k = 0; open && k < 3; k++)
    if (strlen(dists[k].name) == (size_t)(open - v) && !strncmp(v, dists[k].name, (size_t)(open - v)))
      d = k;
  double a, b;
  if (d < 0 || !close || close[1] || number(open + 1, comma, &a) || number(comma + 1, close, &b)) {
    snprintf(err, n, "--vary %s: a distribution is normal(MEAN,SD), uniform(LOW,HIGH) or "
             "lognormal(MU,SIGMA) (of the log)", arg);
    return -1;
  }
  if ((dists[d].d != BG_DIST_UNIFORM && b < 0) || (dists[d].d == BG_DIST_UNIFORM && b < a)) {
    snprintf(err, n, "--vary %s: %s", arg,
             dists[d].d == BG_DIST_UNIFORM ? "HIGH is below LOW" : "the spread is negative");
    return -1;
  }
  bg_study_param *p = &s->params[s->nparams++];
  memset(p, 0, sizeof *p);
  p->name = dupn(arg, (size_t)(eq - arg));
  p->spec = dupn(v, strlen(v));
  p->dist = dists[d].d, p->a = a, p->b = b;
  s->kind = BG_STUDY_MONTE_CARLO;
  return 0;
}

int bg_study_add_collect(bg_study_spec *s, const char *arg, char *err, size_t n) {
  static const struct { const char *name; bg_collect_kind k; } kinds[] = {
      {"final", BG_COLLECT_FINAL}, {"min", BG_COLLECT_MIN}, {"max", BG_COLLECT_MAX},
      {"mean", BG_COLLECT_MEAN}, {"tmin", BG_COLLECT_TMIN}, {"tmax", BG_COLLECT_TMAX}};
  const char *c = strrchr(arg, ':');
  int poles = !strcmp(arg, "poles");
  if (!poles && (!c || c == arg)) {
    snprintf(err, n, "--collect wants OUTPUT:WHAT (WHAT: final, min, max, mean, tmin, tmax, "
             "cross=LEVEL) or poles, not '%s'", arg);
    return -1;
  }
  if (s->ncollect == BG_STUDY_MAX_COLLECT) {
    snprintf(err, n, "a study collects at most %d quantities", BG_STUDY_MAX_COLLECT);
    return -1;
  }
  bg_study_collect q = {0};
  int found = 0;
  if (poles) { /* the linearisation's poles: columns pole1:re, pole1:im, ... */
    for (int i = 0; i < s->ncollect; i++)
      if (s->collect[i].kind == BG_COLLECT_POLES) {
        snprintf(err, n, "--collect poles is given twice");
        return -1;
      }
    q.kind = BG_COLLECT_POLES;
    q.var = dupn(arg, strlen(arg)), q.label = dupn(arg, strlen(arg));
    s->collect[s->ncollect++] = q;
    return 0;
  }
  for (int k = 0; k < 6; k++)
    if (!strcmp(c + 1, kinds[k].name)) q.kind = kinds[k].k, found = 1;
  if (!found && !strncmp(c + 1, "cross=", 6)) {
    if (number(c + 7, c + strlen(c), &q.level)) {
      snprintf(err, n, "--collect %s: cross=LEVEL wants a number", arg);
      return -1;
    }
    q.kind = BG_COLLECT_CROSS, found = 1;
  }
  if (!found) {
    snprintf(err, n, "--collect %s: '%s' is not final, min, max, mean, tmin, tmax or "
             "cross=LEVEL", arg, c + 1);
    return -1;
  }
  for (int i = 0; i < s->ncollect; i++)
    if (!strcmp(s->collect[i].label, arg)) {
      snprintf(err, n, "--collect %s is given twice", arg);
      return -1;
    }
  q.var = dupn(arg, (size_t)(c - arg));
  q.label = dupn(arg, strlen(arg));
  s->collect[s->ncollect++] = q;
  return 0;
}

static char *dupn_all(const char *s) { return dupn(s, strlen(s)); }

void bg_study_expand_poles(bg_study *st, const bg_study_collect *q, int nq, int npole) {
  int n = 0;
  for (int k = 0; k < nq; k++) n += q[k].kind == BG_COLLECT_POLES ? 2 * npole : 1;
  st->collect = bg_xcalloc((size_t)n + 1, sizeof *st->collect);
  st->own_collect = 1;
  st->ncollect = 0;
  for (int k = 0; k < nq; k++) {
    if (q[k].kind != BG_COLLECT_POLES) {
      bg_study_collect *c = &st->collect[st->ncollect++];
      *c = q[k];
      c->var = dupn_all(q[k].var), c->label = dupn_all(q[k].label);
      continue;
    }
    for (int p = 0; p < npole; p++)
      for (int part = 0; part < 2; part++) {
        bg_study_collect *c = &st->collect[st->ncollect++];
        c->kind = part ? BG_COLLECT_POLE_IM : BG_COLLECT_POLE_RE;
        c->pole = p;
        c->var = dupn_all("poles");
        c->label = bg_xmalloc(32);
        snprintf(c->label, 32, "pole%d:%s", p + 1, part ? "im" : "re");
      }
  }
}

long bg_study_nruns(const bg_study_spec *s) {
  if (!s->nparams) return 0;
  if (s->kind == BG_STUDY_MONTE_CARLO) return s->draws;
  long r = 1;
  for (int i = 0; i < s->nparams; i++) r *= s->params[i].nvalues;
  return r;
}

/* ---------------------------------------------------------- the draws */
static uint64_t splitmix64(uint64_t *x) {
  uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

typedef struct rng { uint64_t s[4]; } rng;

static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static uint64_t next(rng *g) { /* xoshiro256** */
  uint64_t *s = g->s, r = rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
  s[2] ^= s[0], s[3] ^= s[1], s[1] ^= s[2], s[0] ^= s[3], s[2] ^= t, s[3] = rotl(s[3], 45);
  return r;
}

/* Uniform in (0, 1): never 0, so the logarithm below is finite. */
static double unit(rng *g) { return ((double)(next(g) >> 11) + 0.5) * 0x1.0p-53; }

static double std_normal(rng *g) { /* Box-Muller, one of the pair */
  double u = unit(g), v = unit(g);
  return sqrt(-2 * log(u)) * cos(2 * M_PI * v);
}

void bg_study_values(const bg_study_spec *s, long i, double *out) {
  if (s->kind == BG_STUDY_SWEEP) {
    long rest = i;
    for (int k = s->nparams - 1; k >= 0; k--) {
      const bg_study_param *p = &s->params[k];
      out[k] = p->values[rest % p->nvalues];
      rest /= p->nvalues;
    }
    return;
  }
  uint64_t x = s->seed ^ ((uint64_t)i * 0xd1342543de82ef95ULL);
  rng g;
  for (int k = 0; k < 4; k++) g.s[k] = splitmix64(&x);
  for (int k = 0; k < s->nparams; k++) {
    const bg_study_param *p = &s->params[k];
    switch (p->dist) {
    case BG_DIST_NORMAL: out[k] = p->a + p->b * std_normal(&g); break;
    case BG_DIST_LOGNORMAL: out[k] = exp(p->a + p->b * std_normal(&g)); break;
    case BG_DIST_UNIFORM: out[k] = p->a + (p->b - p->a) * unit(&g); break;
    }
  }
}

void bg_study_spec_free(bg_study_spec *s) {
  for (int i = 0; i < s->nparams; i++)
    free(s->params[i].name), free(s->params[i].spec), free(s->params[i].values);
  for (int i = 0; i < s->ncollect; i++) free(s->collect[i].var), free(s->collect[i].label);
  s->nparams = s->ncollect = 0;
}

const char *bg_study_status_name(bg_study_status s) {
  static const char *names[] = {"ok", "partial", "refused", "failed", "model-error"};
  return names[s];
}
