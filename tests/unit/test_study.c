/* SPDX-License-Identifier: BSD-3-Clause */
/* Parameter studies (src/study, docs/study.md) against answers derived by
 * hand:
 * - a damping sweep of the examples' series RLC circuit: the capacitor
 *   voltage's peak 1 + exp(-pi z / sqrt(1 - z^2)) with z = R/2 sqrt(C/L)
 *   when underdamped, its time pi / wd, no overshoot when overdamped;
 * - a Monte Carlo study of a quarter car (tests/data/quarter_car.bg), linear
 *   in the road's speed v0: each run's peak body velocity is v0 times the
 *   peak at v0 = 1, so the runs' mean is the response at the draws' mean,
 *   and the draws have the stated mean and spread;
 * - the same bytes from 1, 2 and 5 threads and from the study cut in parts;
 * - a root locus of the same circuit: the poles -R/2L +- sqrt((R/2L)^2 -
 *   1/LC) of each run, as the table's columns; the Bode family's gains
 *   against |C / (1 - LC w^2 + j RC w)| and its phase;
 * - failures recorded per run with their reasons; the parsers' refusals. */
#define _DEFAULT_SOURCE /* M_PI */
#include "harness.h"

#include "base/fileio.h"
#include "study/study.h"

static char *example(const char *path) {
  char full[512];
  snprintf(full, sizeof full, "%s/%s", BG_SOURCE_DIR, path);
  size_t len;
  return bg_read_file(full, &len);
}

static bg_study_opts opts(const char *name, const char *src, int jobs) {
  bg_study_opts o = {0};
  o.name = name, o.src = src, o.srclen = strlen(src);
  o.method = -1, o.jobs = jobs;
  return o;
}

static void spec_words(bg_study_spec *s, const char *const *sweep, const char *const *vary,
                       const char *const *collect) {
  char err[300];
  memset(s, 0, sizeof *s);
  s->seed = 1;
  for (int i = 0; sweep && sweep[i]; i++)
    if (bg_study_add_sweep(s, sweep[i], err, sizeof err)) { fprintf(stderr, "%s\n", err); OK(0); }
  for (int i = 0; vary && vary[i]; i++)
    if (bg_study_add_vary(s, vary[i], err, sizeof err)) { fprintf(stderr, "%s\n", err); OK(0); }
  for (int i = 0; collect && collect[i]; i++)
    if (bg_study_add_collect(s, collect[i], err, sizeof err)) { fprintf(stderr, "%s\n", err); OK(0); }
}

static void rlc_sweep(void) {
  char *src = example("examples/rlc.bg");
  const char *sweep[] = {"R0=2:120:60", NULL};
  const char *collect[] = {"C1.e:max", "C1.e:tmax", "C1.e:final", NULL};
  bg_study_spec s;
  spec_words(&s, sweep, NULL, collect);
  INT_EQ(bg_study_nruns(&s), 60);
  bg_study_opts o = opts("rlc.bg", src, 2);
  bg_study st;
  char err[300];
  INT_EQ(bg_study_run_all(&s, &o, &st, err, sizeof err), 0);
  const double L = 1e-3, C = 1e-6, dt = 1e-6, wn = 1 / sqrt(L * C);
  int under = 0, over = 0;
  for (long i = 0; i < st.count; i++) {
    const bg_study_run *r = &st.runs[i];
    INT_EQ(r->status, BG_STUDY_OK);
    double R = r->param[0], z = R / 2 * sqrt(C / L);
    DBL_NEAR(R, 2 + (120.0 - 2) * i / 59, 1e-12);
    if (z < 0.95) { /* underdamped: the overshoot of the step response */
      double wd = wn * sqrt(1 - z * z);
      DBL_NEAR(r->value[0], 1 + exp(-M_PI * z / sqrt(1 - z * z)), 2e-3);
      DBL_NEAR(r->value[1], M_PI / wd, dt);
      under++;
    } else if (z > 1.05) { /* overdamped: no overshoot, the peak is the final value */
      OK(r->value[0] <= 1 + 1e-4);
      over++;
    }
    /* at t_end = 2 ms within the envelope of the decaying oscillation */
    double env = z < 1 ? exp(-R / (2 * L) * 2e-3) / sqrt(1 - z * z) : 1e-3;
    DBL_NEAR(r->value[2], 1, env + 1e-4);
  }
  OK(under >= 25 && over >= 25);
  /* the overshoot falls with R: the damping sweep's point */
  for (long i = 1; i < st.count; i++) OK(st.runs[i].value[0] <= st.runs[i - 1].value[0] + 1e-6);
  bg_study_free(&st);
  bg_study_spec_free(&s);
  free(src);
}

/* The tables of a study on n threads (and, with parts > 1, the rows of the
 * parts, each run once, concatenated). */
static char *table(const bg_study_spec *s, const char *src, int jobs, int parts, int json) {
  bg_strbuf b = {0};
  long n = bg_study_nruns(s);
  for (int k = 0; k < parts; k++) {
    bg_study_opts o = opts("model.bg", src, jobs);
    o.first = n * k / parts, o.count = n * (k + 1) / parts - o.first;
    bg_study st;
    char err[300];
    if (bg_study_run_all(s, &o, &st, err, sizeof err)) {
      fprintf(stderr, "%s\n", err);
      OK(0);
      continue;
    }
    bg_strbuf t = {0};
    if (json) bg_study_write_json(&st, &t);
    else bg_study_write_csv(&st, &t);
    const char *text = bg_sb_str(&t);
    bg_sb_puts(&b, k ? strchr(text, '\n') + 1 : text); /* one header */
    bg_sb_free(&t);
    bg_study_free(&st);
  }
  return b.s;
}

static void quarter_car(void) {
  char *src = example("tests/data/quarter_car.bg");
  const double mu = 0.5, sd = 0.05;
  const int N = 400;
  /* the response to v0 = 1 (a sweep of one value) */
  const char *one[] = {"v0=1", NULL};
  const char *collect[] = {"mb.f:max", "Ks.q:max", "mb.f:tmax", NULL};
  bg_study_spec s1;
  spec_words(&s1, one, NULL, collect);
  bg_study_opts o = opts("quarter_car.bg", src, 1);
  bg_study unit;
  char err[300];
  INT_EQ(bg_study_run_all(&s1, &o, &unit, err, sizeof err), 0);
  double peak1 = unit.runs[0].value[0], defl1 = unit.runs[0].value[1], tpeak = unit.runs[0].value[2];
  OK(peak1 > 0.1 && defl1 > 0);

  const char *vary[] = {"v0=normal(0.5,0.05)", "ks=uniform(15000,17000)", NULL};
  const char *collect2[] = {"mb.f:max", NULL};
  bg_study_spec s;
  spec_words(&s, NULL, vary, collect2);
  /* ks varies too, but only in a second study below: here it is fixed */
  bg_study_spec_free(&s);
  const char *vary1[] = {"v0=normal(0.5,0.05)", NULL};
  spec_words(&s, NULL, vary1, collect);
  s.draws = N, s.seed = 2024;
  o.jobs = 2;
  bg_study st;
  INT_EQ(bg_study_run_all(&s, &o, &st, err, sizeof err), 0);
  double sv = 0, sv2 = 0, sp = 0, sp2 = 0;
  for (long i = 0; i < st.count; i++) {
    const bg_study_run *r = &st.runs[i];
    INT_EQ(r->status, BG_STUDY_OK);
    double v = r->param[0];
    /* linear in v0: each run's peak is v0 times the unit peak, at the same time */
    DBL_NEAR(r->value[0], v * peak1, 1e-4 * v * peak1);
    DBL_NEAR(r->value[1], v * defl1, 1e-4 * v * defl1);
    DBL_NEAR(r->value[2], tpeak, 1e-3 + 1e-12);
    sv += v, sv2 += v * v, sp += r->value[0], sp2 += r->value[0] * r->value[0];
  }
  double mv = sv / N, vv = (sv2 - N * mv * mv) / (N - 1);
  double mp = sp / N, vp = (sp2 - N * mp * mp) / (N - 1);
  /* the draws: the mean within 4 standard errors, the variance within 4 of
   * its standard errors (sqrt(2/(N-1)) sd^2 for a normal sample) */
  DBL_NEAR(mv, mu, 4 * sd / sqrt(N));
  DBL_NEAR(vv, sd * sd, 4 * sqrt(2.0 / (N - 1)) * sd * sd);
  /* the mean of a linear response is the response at the mean: the peak at
   * v0 = mu, within the sampling error of its mean (sd(peak) = sd peak1) */
  DBL_NEAR(mp, mu * peak1, 4 * sd * peak1 / sqrt(N));
  DBL_NEAR(mp, mv * peak1, 1e-4 * mp);
  DBL_NEAR(sqrt(vp), sd * peak1, 4 * sqrt(1.0 / (2 * (N - 1))) * sd * peak1);
  bg_study_free(&st);

  /* uniform draws: inside the range, mean (lo+hi)/2, variance (hi-lo)^2/12 */
  bg_study_spec su;
  const char *varyu[] = {"ks=uniform(15000,17000)", "v0=lognormal(-0.7,0.1)", NULL};
  spec_words(&su, NULL, varyu, collect2);
  su.draws = 2000, su.seed = 5;
  double m = 0, m2 = 0, lm = 0, lo = 1e300, hi = -1e300;
  double *v = calloc(2, sizeof *v);
  for (long i = 0; i < su.draws; i++) {
    bg_study_values(&su, i, v);
    m += v[0], m2 += v[0] * v[0], lm += log(v[1]);
    lo = fmin(lo, v[0]), hi = fmax(hi, v[0]);
  }
  m /= su.draws, lm /= su.draws;
  double var = m2 / su.draws - m * m, w = 2000;
  OK(lo >= 15000 && hi <= 17000 && lo < 15010 && hi > 16990);
  DBL_NEAR(m, 16000, 4 * w / sqrt(12.0 * su.draws));
  DBL_NEAR(var, w * w / 12, 4 * w * w / sqrt(180.0 * su.draws)); /* var of U^2: w^4/180 */
  DBL_NEAR(lm, -0.7, 4 * 0.1 / sqrt(su.draws));
  /* run i's draws depend only on the seed and i */
  double a[2], b[2];
  bg_study_values(&su, 1234, a);
  bg_study_values(&su, 1234, b);
  OK(a[0] == b[0] && a[1] == b[1]);
  su.seed = 6;
  bg_study_values(&su, 1234, b);
  OK(a[0] != b[0]);
  free(v);
  bg_study_spec_free(&su);

  /* byte-identical on 1, 2 and 5 threads, and cut into 3 parts */
  s.draws = 24;
  char *t1 = table(&s, src, 1, 1, 0), *t2 = table(&s, src, 2, 1, 0), *t5 = table(&s, src, 5, 1, 0);
  char *tp = table(&s, src, 2, 3, 0), *j1 = table(&s, src, 1, 1, 1), *j2 = table(&s, src, 3, 1, 1);
  OK(t1 && t2 && t5 && tp && j1 && j2);
  if (t1 && t2 && t5 && tp && j1 && j2) {
    OK(!strcmp(t1, t2));
    OK(!strcmp(t1, t5));
    OK(!strcmp(t1, tp));
    OK(!strcmp(j1, j2));
  }
  free(t1), free(t2), free(t5), free(tp), free(j1), free(j2);
  bg_study_free(&unit);
  bg_study_spec_free(&s1);
  bg_study_spec_free(&s);
  free(src);
}

static void failures(void) {
  /* a negative capacitance makes some runs fail or be refused: each is in
   * the table with its reason, the others are computed */
  char *src = example("examples/rlc.bg");
  const char *sweep[] = {"C0=1e-6,0,2e-6", NULL};
  const char *collect[] = {"C1.e:final", NULL};
  bg_study_spec s;
  spec_words(&s, sweep, NULL, collect);
  bg_study_opts o = opts("rlc.bg", src, 2);
  bg_study st;
  char err[300];
  INT_EQ(bg_study_run_all(&s, &o, &st, err, sizeof err), 0);
  INT_EQ(st.runs[0].status, BG_STUDY_OK);
  OK(st.runs[1].status != BG_STUDY_OK && st.runs[1].reason && *st.runs[1].reason);
  OK(isnan(st.runs[1].value[0]));
  INT_EQ(st.runs[2].status, BG_STUDY_OK);
  INT_EQ(st.nfailed, 1);
  bg_strbuf b = {0};
  bg_study_write_csv(&st, &b);
  OK(strstr(bg_sb_str(&b), "\n1,0,") != NULL);
  bg_sb_free(&b);
  bg_study_free(&st);
  bg_study_spec_free(&s);
  /* refusals before anything runs: a param the model does not have, an output it has not */
  const char *bad[] = {"R00=1,2", NULL};
  spec_words(&s, bad, NULL, NULL);
  OK(bg_study_run_all(&s, &o, &st, err, sizeof err) == -1 && strstr(err, "did you mean 'R0'"));
  bg_study_spec_free(&s);
  const char *good[] = {"R0=1,2", NULL}, *badc[] = {"C9.e:max", NULL};
  spec_words(&s, good, NULL, badc);
  OK(bg_study_run_all(&s, &o, &st, err, sizeof err) == -1 && strstr(err, "outputs: C1.e"));
  bg_study_spec_free(&s);
  /* no --collect: final, min and max of every output */
  spec_words(&s, good, NULL, NULL);
  INT_EQ(bg_study_run_all(&s, &o, &st, err, sizeof err), 0);
  INT_EQ(st.ncollect, 6);
  STR_EQ(st.collect[2].label, "C1.e:max");
  bg_study_free(&st);
  bg_study_spec_free(&s);
  free(src);
}

static void parsers(void) {
  bg_study_spec s;
  memset(&s, 0, sizeof s);
  char err[300];
  INT_EQ(bg_study_add_sweep(&s, "k=1:100:3:log", err, sizeof err), 0);
  DBL_NEAR(s.params[0].values[1], 10, 1e-12);
  INT_EQ(bg_study_add_sweep(&s, "c=1,2", err, sizeof err), 0);
  INT_EQ(bg_study_nruns(&s), 6);
  double v[2];
  bg_study_values(&s, 3, v); /* the first param varies slowest */
  DBL_NEAR(v[0], 10, 1e-12);
  OK(v[1] == 2);
  OK(bg_study_add_sweep(&s, "k=1,2", err, sizeof err) == -1 && strstr(err, "twice"));
  OK(bg_study_add_vary(&s, "m=normal(1,2)", err, sizeof err) == -1 && strstr(err, "do not combine"));
  bg_study_spec_free(&s);
  memset(&s, 0, sizeof s);
  static const char *const bad_sweeps[] = {"k", "=1", "k=1:2", "k=1:2:0", "k=1:2:2.5", "k=0:1:3:log",
                                           "k=1:2:3:lin", "k=1,,2", "k=a", "k=1e999", "k=1:2:2000000", NULL};
  for (int i = 0; bad_sweeps[i]; i++) OK(bg_study_add_sweep(&s, bad_sweeps[i], err, sizeof err) == -1);
  static const char *const bad_vary[] = {"m=normal(1)", "m=gauss(1,2)", "m=normal(1,-1)",
                                         "m=uniform(2,1)", "m=normal(1,2)x", NULL};
  for (int i = 0; bad_vary[i]; i++) OK(bg_study_add_vary(&s, bad_vary[i], err, sizeof err) == -1);
  static const char *const bad_collect[] = {"x", ":max", "x:maximum", "x:cross=", "x:cross=a", NULL};
  for (int i = 0; bad_collect[i]; i++) OK(bg_study_add_collect(&s, bad_collect[i], err, sizeof err) == -1);
  INT_EQ(bg_study_add_collect(&s, "M.x:cross=0.5", err, sizeof err), 0);
  STR_EQ(s.collect[0].var, "M.x");
  DBL_NEAR(s.collect[0].level, 0.5, 0);
  OK(bg_study_add_collect(&s, "M.x:cross=0.5", err, sizeof err) == -1);
  INT_EQ(s.nparams, 0);
  bg_study_spec_free(&s);
}

/* The study of src over the words given, run on jobs threads; 0 or -1. */
static int run_words(const char *name, const char *src, const char *const *sweep,
                     const char *const *collect, int jobs, bg_study_spec *s, bg_study_opts *o,
                     bg_study *st) {
  char err[300];
  spec_words(s, sweep, NULL, collect);
  *o = opts(name, src, jobs);
  int rc = bg_study_run_all(s, o, st, err, sizeof err);
  if (rc) fprintf(stderr, "%s\n", err);
  return rc;
}

/* The RLC's poles as R varies, closed form: s = -R/2L +- sqrt((R/2L)^2 - 1/LC),
 * in the linear stage's order (by real part, then imaginary part). */
static void root_locus(void) {
  char *src = example("examples/rlc.bg");
  const char *sweep[] = {"R0=5:125:25", NULL}, *collect[] = {"poles", "C1.e:max", NULL};
  bg_study_spec s;
  bg_study_opts o;
  bg_study st;
  char err[300];
  INT_EQ(run_words("rlc.bg", src, sweep, collect, 2, &s, &o, &st), 0);
  INT_EQ(st.npole, 2);
  INT_EQ(st.ncollect, 5); /* pole1:re, pole1:im, pole2:re, pole2:im, C1.e:max */
  STR_EQ(st.collect[0].label, "pole1:re");
  STR_EQ(st.collect[3].label, "pole2:im");
  OK(st.need_sim); /* C1.e:max needs the simulation */
  const double L = 1e-3, C = 1e-6;
  int complex_pairs = 0, real_pairs = 0;
  for (long i = 0; i < st.count; i++) {
    const bg_study_run *r = &st.runs[i];
    INT_EQ(r->status, BG_STUDY_OK);
    double R = r->param[0], a = R / (2 * L), d = a * a - 1 / (L * C), scale = 1 / sqrt(L * C);
    if (d < 0) { /* underdamped: -a -+ j sqrt(1/LC - a^2) */
      DBL_NEAR(r->value[0], -a, 1e-9 * scale);
      DBL_NEAR(r->value[1], -sqrt(-d), 1e-9 * scale);
      DBL_NEAR(r->value[2], -a, 1e-9 * scale);
      DBL_NEAR(r->value[3], sqrt(-d), 1e-9 * scale);
      complex_pairs++;
    } else { /* overdamped: two real poles -a -+ sqrt(d) */
      DBL_NEAR(r->value[0], -a - sqrt(d), 1e-9 * scale);
      DBL_NEAR(r->value[2], -a + sqrt(d), 1e-9 * scale);
      OK(r->value[1] == 0 && r->value[3] == 0);
      real_pairs++;
    }
    INT_EQ(r->npole, 2);
    OK(r->pole_re[0] == r->value[0] && r->pole_im[1] == r->value[3]);
  }
  OK(complex_pairs >= 10 && real_pairs >= 10);
  /* the Bode family of C1.q <- U (the states are the outputs): |C / (1 - LC w^2 + j RC w)| */
  bg_study_bode b;
  INT_EQ(bg_study_bode_compute(&st, &o, &b, err, sizeof err), 0);
  INT_EQ(b.nrun, BG_STUDY_BODE_RUNS);
  INT_EQ(b.run[0], 0);
  INT_EQ(b.run[b.nrun - 1], st.count - 1);
  int pq = -1;
  for (int p = 0; p < b.npair; p++) if (strstr(b.pair_name[p], "C1.q")) pq = p;
  OK(pq >= 0);
  OK(b.w[0] <= 1e3 && b.w[b.nw - 1] >= 1e6); /* the union covers every run's poles */
  for (int j = 0; j < b.nrun && pq >= 0; j++) {
    double R = st.runs[b.run[j]].param[0];
    for (int k = 0; k < b.nw; k += 7) {
      double w = b.w[k], re = 1 - L * C * w * w, im = R * C * w;
      double mag = 20 * log10(C / hypot(re, im)), ph = -atan2(im, re) * 180 / M_PI;
      DBL_NEAR(b.mag[((size_t)j * b.npair + pq) * b.nw + k], mag, 1e-6);
      DBL_NEAR(b.phase[((size_t)j * b.npair + pq) * b.nw + k], ph, 1e-6);
    }
  }
  bg_study_bode_free(&b);
  bg_study_free(&st);
  /* poles alone: no simulation; the root locus's runs keep their poles without columns */
  bg_study_spec_free(&s);
  const char *only[] = {"poles", NULL};
  spec_words(&s, sweep, NULL, only);
  INT_EQ(bg_study_run_all(&s, &o, &st, err, sizeof err), 0);
  OK(!st.need_sim && st.ncollect == 4);
  bg_study_free(&st);
  bg_study_spec_free(&s);
  const char *peak[] = {"C1.e:max", NULL};
  spec_words(&s, sweep, NULL, peak);
  o.want_poles = 1;
  INT_EQ(bg_study_run_all(&s, &o, &st, err, sizeof err), 0);
  INT_EQ(st.ncollect, 1);
  INT_EQ(st.runs[3].npole, 2);
  DBL_NEAR(st.runs[3].pole_re[0], -st.runs[3].param[0] / (2 * L), 1e-6);
  bg_study_free(&st);
  bg_study_spec_free(&s);
  /* a model without states has no poles: refused before any run */
  const char *nostate = "model r\nparam R0 = 1\nSe U = 1\nR R1 = R0\nbond U -> R1\n";
  bg_study_opts o2 = opts("r.bg", nostate, 1);
  const char *sw2[] = {"R0=1,2", NULL};
  spec_words(&s, sw2, NULL, only);
  OK(bg_study_run_all(&s, &o2, &st, err, sizeof err) == -1 && strstr(err, "poles"));
  bg_study_spec_free(&s);
  free(src);
}

/* The model's own study (`study` statements, docs/format.md): the words
 * the command line would take, the numbers exactly as written. */
static void model_words(void) {
  const char *src = "model m\nparam a = 1, b = 2\nSe U = a\nC C1 = b\nbond U -> C1\n"
                    "study sweep a = range(-5, + 5, 3)\n"
                    "study sweep b = [1e-3, - 2.5e-3, 7]\n"
                    "study collect C1.e:max, C1.e : cross = -0.5, poles\n";
  bg_run *R = bg_run_new(NULL);
  OK(bg_run_load_string(R, "m.bg", src) == 0 && R->model);
  if (R->model) {
    const bg_model *m = R->model;
    INT_EQ(m->nstudy, 5);
    static const char *const want[] = {"a=-5:5:3", "b=1e-3,-2.5e-3,7", "C1.e:max", "C1.e:cross=-0.5", "poles"};
    static const char kind[] = "sscc" "c";
    for (int k = 0; k < m->nstudy && k < 5; k++) {
      STR_EQ(m->study_word[k], want[k]);
      INT_EQ(m->study_kind[k], kind[k]);
    }
    /* the words parse as the command line's: the same values */
    bg_study_spec s;
    memset(&s, 0, sizeof s);
    char err[200];
    INT_EQ(bg_study_add_sweep(&s, m->study_word[0], err, sizeof err), 0);
    INT_EQ(bg_study_add_sweep(&s, m->study_word[1], err, sizeof err), 0);
    OK(s.params[0].values[0] == -5 && s.params[0].values[1] == 0 && s.params[0].values[2] == 5);
    OK(s.params[1].values[1] == -2.5e-3);
    bg_study_spec_free(&s);
  }
  bg_run_free(R);
  const char *mc = "model m\nparam a = 1\nSe U = a\nC C1 = 1\nbond U -> C1\n"
                   "study vary a = lognormal(0, 0.25)\nstudy seed = 18446744073709551615, draws = 20\n";
  R = bg_run_new(NULL);
  OK(bg_run_load_string(R, "m.bg", mc) == 0 && R->model);
  if (R->model) {
    INT_EQ(R->model->nstudy, 3);
    STR_EQ(R->model->study_word[0], "a=lognormal(0,0.25)");
    STR_EQ(R->model->study_word[1], "seed=18446744073709551615");
    STR_EQ(R->model->study_word[2], "draws=20");
    INT_EQ(R->model->study_kind[1], 'e');
  }
  bg_run_free(R);
}

int main(void) {
  parsers();
  model_words();
  root_locus();
  rlc_sweep();
  quarter_car();
  failures();
  return bg_t_done();
}
