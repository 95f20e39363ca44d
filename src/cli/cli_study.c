/* SPDX-License-Identifier: BSD-3-Clause */
/* The command line's parameter studies (docs/study.md): the study's words
 * checked and parsed, the study run on -j threads (src/study), its outputs
 * (the summary table as CSV or JSON, the quantities against the param, the
 * family of curves) written, or the study split into jobs for GNU parallel
 * or a Slurm array, and the parts merged into the same outputs. */
#define _DEFAULT_SOURCE /* scandir, alphasort */
#include "cli/cli_study.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/fileio.h"
#include "cli/cli_render.h"
#include "cli/cli_usage.h"

static const char *const table_exts[] = {"csv", "json", NULL};
static const char *const figure_exts[] = {"svg", "pdf", "png", NULL};

static int in(const char *s, const char *const *list) {
  for (int i = 0; list[i]; i++) if (!strcmp(s, list[i])) return 1;
  return 0;
}

int cli_study_asked(const bg_cli_opts *o) {
  return o->nstudy || o->draws || o->seed || o->jobs || o->runs || o->split || o->joblist ||
         o->slurm || o->merge;
}

/* A whole number in [lo, hi]; 0 or -1. */
static int whole(const char *s, long lo, long hi, long *v) {
  char *end;
  errno = 0;
  long x = strtol(s, &end, 10);
  if (end == s || *end || errno || x < lo || x > hi) return -1;
  return *v = x, 0;
}

/* FIRST:COUNT or N:DIR */
static int pair(const char *s, long *a, const char **rest) {
  const char *c = strchr(s, ':');
  if (!c) return -1;
  char buf[32];
  if ((size_t)(c - s) >= sizeof buf) return -1;
  memcpy(buf, s, (size_t)(c - s));
  buf[c - s] = '\0';
  *rest = c + 1;
  return whole(buf, 0, BG_STUDY_MAX_RUNS, a);
}

int cli_study_parse(const bg_cli_opts *o, cli_study *cs) {
  memset(cs, 0, sizeof *cs);
  bg_study_spec *s = &cs->spec;
  s->seed = 1;
  char err[512];
  int nvary = 0, nsweep = 0;
  for (int i = 0; i < o->nstudy; i++) {
    const char *a = o->study_arg[i];
    int rc = 0;
    switch (o->study_opt[i]) {
    case 's': rc = bg_study_add_sweep(s, a, err, sizeof err), nsweep++; break;
    case 'v': rc = bg_study_add_vary(s, a, err, sizeof err), nvary++; break;
    case 'c': rc = bg_study_add_collect(s, a, err, sizeof err); break;
    case 'o':
    case 'f':
    case 'l':
    case 'b': {
      char c = (char)o->study_opt[i];
      static const char *const optname[] = {"--family", "--root-locus", "--bode-family"};
      const char *ext = bg_path_ext(a);
      if (!in(ext, figure_exts) && (c != 'o' || !in(ext, table_exts)))
        return bg_cli_usage_error(c != 'o' ? "%s %s: the plot is .svg, .pdf or .png"
                                           : "--study %s%s: the table is .csv or .json, the plot "
                                             "of the quantities .svg, .pdf or .png",
                                  c == 'o' ? "" : optname[c == 'f' ? 0 : c == 'l' ? 1 : 2], a);
      if (cs->nout == CLI_STUDY_MAX_OUT) return bg_cli_usage_error("too many study outputs%s%s", "", "");
      cs->out[cs->nout].path = a;
      cs->out[cs->nout].kind = c == 'f' ? BG_STUDY_PLOT_FAMILY : c == 'l' ? BG_STUDY_PLOT_LOCUS
                             : c == 'b' ? BG_STUDY_PLOT_BODE : in(ext, table_exts) ? -1
                                                             : BG_STUDY_PLOT_QUANTITIES;
      cs->nout++;
      cs->curves |= c == 'f', cs->locus |= c == 'l', cs->bode |= c == 'b';
      break;
    }
    }
    if (rc) return bg_cli_usage_error("%s%s", err, "");
  }
  cs->cli_params = nsweep + nvary;
  for (int i = 0; i < o->nstudy; i++) cs->cli_collect += o->study_opt[i] == 'c';
  if (o->draws) {
    long d;
    if (whole(o->draws, 1, BG_STUDY_MAX_RUNS, &d))
      return bg_cli_usage_error("--monte-carlo %s: the number of runs is a whole number from 1 "
                                "to 1000000%s", o->draws, "");
    s->draws = d;
  }
  if (o->seed) {
    char *end;
    errno = 0;
    unsigned long long v = strtoull(o->seed, &end, 10);
    if (end == o->seed || *end || errno || o->seed[0] == '-')
      return bg_cli_usage_error("--seed %s: the seed is a whole number from 0 to 2^64-1%s", o->seed, "");
    s->seed = v;
  }
  cs->jobs = 0;
  if (o->jobs) {
    long j;
    if (whole(o->jobs, 1, 1024, &j))
      return bg_cli_usage_error("-j %s: the number of threads is a whole number from 1 to 1024%s",
                                o->jobs, "");
    cs->jobs = (int)j;
  }
  if (o->runs) {
    const char *rest;
    if (pair(o->runs, &cs->first, &rest) || whole(rest, 1, BG_STUDY_MAX_RUNS, &cs->count))
      return bg_cli_usage_error("--runs %s: FIRST:COUNT, two whole numbers%s", o->runs, "");
  }
  if (o->split) {
    if (pair(o->split, &cs->parts, &cs->partdir) || cs->parts < 1 || !cs->partdir[0])
      return bg_cli_usage_error("--split %s: N:DIR, the number of parts and their folder%s", o->split, "");
    if (!o->joblist && !o->slurm)
      return bg_cli_usage_error("--split %s writes jobs: say where with --job-list FILE or "
                                "--slurm FILE%s", o->split, "");
    if (o->runs || o->merge)
      return bg_cli_usage_error("--split does not combine with %s%s", o->runs ? "--runs" : "--merge", "");
  } else if (o->joblist || o->slurm) {
    return bg_cli_usage_error("%s needs --split N:DIR (how many parts, and where they go)%s",
                              o->joblist ? "--job-list" : "--slurm", "");
  }
  if (o->merge && o->runs) return bg_cli_usage_error("--merge does not combine with --runs%s%s", "", "");
  if (o->merge && cs->curves)
    return bg_cli_usage_error("--family with --merge: the parts keep no trajectories (draw the "
                              "family on one machine, or from a part)%s%s", "", "");
  if (!cs->nout && !o->split && !o->report)
    return bg_cli_usage_error("the study writes nothing: add --study FILE.csv|json|svg, "
                              "--family FILE.svg, --root-locus FILE.svg or --bode-family "
                              "FILE.svg%s%s", "", "");
  if (o->split && (cs->nout || o->report))
    return bg_cli_usage_error("--split writes jobs only; the outputs come from --merge%s%s", "", "");
  /* a study writes only its own outputs: the single run's would be ignored */
  if (o->nout || o->plot || o->simulate || o->equations || o->linear || o->bode ||
      o->nyquist || o->step || o->check || o->transform || o->depfile)
    return bg_cli_usage_error("a study writes --study, --family, --root-locus, --bode-family "
                              "and --report outputs only; write the single run's outputs (-o, "
                              "--plot, ...) in a call "
                              "without %s%s", nsweep ? "--sweep" : nvary ? "--vary"
                                                     : "the study's options", "");
  return 0;
}

/* ------------------------------------------------------------ the jobs */
static void shell_word(bg_strbuf *b, const char *s) {
  bg_sb_putc(b, '\'');
  for (; *s; s++) {
    if (*s == '\'') bg_sb_puts(b, "'\\''");
    else bg_sb_putc(b, *s);
  }
  bg_sb_putc(b, '\'');
}

/* Part k's command: the study's own words, its runs and its table. */
static void part_command(const bg_cli_opts *o, const cli_study *cs, long k, long nruns,
                         const char *jobs, bg_strbuf *b) {
  long base = nruns / cs->parts, extra = nruns % cs->parts;
  long first = k * base + (k < extra ? k : extra), count = base + (k < extra);
  bg_sb_puts(b, "bgdraw ");
  shell_word(b, o->model_path);
  for (int i = 0; i < o->nsets; i++) {
    char v[40];
    bg_num_format(v, sizeof v, o->sets[i].value, 15);
    bg_sb_printf(b, " --set '%s=%s'", o->sets[i].name, v);
  }
  if (o->causality) bg_sb_puts(b, " --causality "), shell_word(b, o->causality);
  for (int i = 0; i < o->nstudy; i++) {
    char c = (char)o->study_opt[i];
    if (c == 'o' || c == 'f' || c == 'l' || c == 'b') continue;
    bg_sb_puts(b, c == 's' ? " --sweep " : c == 'v' ? " --vary " : " --collect ");
    shell_word(b, o->study_arg[i]);
  }
  if (o->draws) bg_sb_printf(b, " --monte-carlo %s", o->draws);
  if (o->seed) bg_sb_printf(b, " --seed %s", o->seed);
  bg_sb_printf(b, " -q -j %s --runs %ld:%ld --study ", jobs, first, count);
  char part[64];
  snprintf(part, sizeof part, "/part-%06ld.csv", k);
  bg_strbuf path = {0};
  bg_sb_printf(&path, "%s%s", cs->partdir, part);
  shell_word(b, bg_sb_str(&path));
  bg_sb_free(&path);
}

static int write_jobs(const bg_cli_opts *o, const cli_study *cs) {
  long nruns = bg_study_nruns(&cs->spec);
  int rc = 0;
  if (o->joblist) {
    bg_strbuf b = {0};
    for (long k = 0; k < cs->parts; k++) part_command(o, cs, k, nruns, "1", &b), bg_sb_putc(&b, '\n');
    rc = cli_write_text(o->joblist, &b);
    bg_sb_free(&b);
  }
  if (!rc && o->slurm) {
    bg_strbuf b = {0};
    bg_sb_printf(&b, "#!/bin/bash\n# A bgdraw parameter study as a Slurm job array: %ld parts of "
                 "%ld runs in all;\n# submit with sbatch, then merge the parts with --merge ",
                 cs->parts, nruns);
    shell_word(&b, cs->partdir);
    bg_sb_printf(&b, " (docs/study.md).\n#SBATCH --job-name=bgdraw-study\n#SBATCH --array=0-%ld\n"
                 "#SBATCH --cpus-per-task=1\nset -euo pipefail\nmkdir -p ", cs->parts - 1);
    shell_word(&b, cs->partdir);
    bg_sb_puts(&b, "\ncase \"$SLURM_ARRAY_TASK_ID\" in\n");
    for (long k = 0; k < cs->parts; k++) {
      bg_sb_printf(&b, "%ld) exec ", k);
      part_command(o, cs, k, nruns, "\"${SLURM_CPUS_PER_TASK:-1}\"", &b);
      bg_sb_puts(&b, " ;;\n");
    }
    bg_sb_puts(&b, "*) echo \"no part $SLURM_ARRAY_TASK_ID\" >&2; exit 2 ;;\nesac\n");
    rc = cli_write_text(o->slurm, &b);
    bg_sb_free(&b);
  }
  return rc ? EXIT_WRITE : EXIT_OK;
}

/* ------------------------------------------------------------ merging */
/* The next CSV field of *p (quotes undone) into f; 1 when a field was read,
 * *end set when it closed the line. */
static int csv_next(const char **p, bg_strbuf *f, int *end) {
  const char *s = *p;
  bg_sb_clear(f);
  bg_sb_puts(f, "");
  if (*s == '"') {
    for (s++; *s; s++) {
      if (*s == '"' && s[1] == '"') bg_sb_putc(f, '"'), s++;
      else if (*s == '"') { s++; break; }
      else bg_sb_putc(f, *s);
    }
  } else {
    while (*s && *s != ',' && *s != '\n') bg_sb_putc(f, *s++);
  }
  *end = *s != ',';
  *p = *s ? s + 1 : s;
  return 1;
}

static double field_num(const char *s, int *bad) {
  if (!*s) return NAN;
  char *end;
  double v = strtod(s, &end);
  if (*end) *bad = 1;
  return v;
}

static int part_name(const struct dirent *d) {
  return !strncmp(d->d_name, "part-", 5) && !strcmp(bg_path_ext(d->d_name), "csv");
}

/* Every part's rows in the study's slots; each run exactly once, and each
 * part's header the study's own. */
static int merge_parts(const bg_cli_opts *o, const cli_study *cs, bg_study *st) {
  const char *dir = o->merge;
  struct dirent **names = NULL;
  int nf = scandir(dir, &names, part_name, alphasort);
  if (nf < 0) {
    fprintf(stderr, "bgdraw: error: --merge %s: %s\n", dir, strerror(errno));
    return EXIT_MODEL;
  }
  bg_strbuf header = {0}, f = {0};
  bg_study_csv_header(st, &header);
  int rc = EXIT_OK;
  for (long k = 0; k < st->count; k++) st->runs[k].status = -1; /* not seen */
  for (int i = 0; i < nf && rc == EXIT_OK; i++) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, names[i]->d_name);
    size_t len = 0;
    char *text = bg_read_file(path, &len);
    const char *nl = text ? strchr(text, '\n') : NULL;
    if (!nl || strncmp(text, bg_sb_str(&header), (size_t)(nl - text + 1))) {
      fprintf(stderr, "bgdraw: error: --merge: %s is not a part of this study (its header "
              "differs, or it cannot be read)\n", path);
      free(text);
      rc = EXIT_MODEL;
      break;
    }
    for (const char *p = nl + 1; *p && rc == EXIT_OK;) {
      int end = 0, bad = 0;
      csv_next(&p, &f, &end);
      long run;
      if (whole(bg_sb_str(&f), 0, st->nruns - 1, &run)) bad = 1;
      bg_study_run *r = bad ? NULL : &st->runs[run];
      if (r && r->status != (bg_study_status)-1) {
        fprintf(stderr, "bgdraw: error: --merge: run %ld is in two parts (%s)\n", run, path);
        rc = EXIT_MODEL;
        break;
      }
      if (r) {
        r->param = calloc((size_t)cs->spec.nparams + 1, sizeof(double));
        r->value = calloc((size_t)st->ncollect + 1, sizeof(double));
        for (int k = 0; k < cs->spec.nparams && !end; k++)
          csv_next(&p, &f, &end), r->param[k] = field_num(bg_sb_str(&f), &bad);
        if (!end) csv_next(&p, &f, &end);
        int status = -1;
        for (int k = 0; k <= BG_STUDY_MODEL_ERROR; k++)
          if (!strcmp(bg_sb_str(&f), bg_study_status_name(k))) status = k;
        bad |= status < 0;
        for (int k = 0; k < st->ncollect && !end; k++)
          csv_next(&p, &f, &end), r->value[k] = field_num(bg_sb_str(&f), &bad);
        if (!end) csv_next(&p, &f, &end);
        if (f.len) r->reason = strdup(bg_sb_str(&f));
        bad |= !end;
        r->status = bad ? (bg_study_status)-1 : (bg_study_status)status;
        /* the values of a run depend only on the study: a part of another study is refused */
        double *want = calloc((size_t)cs->spec.nparams + 1, sizeof(double));
        bg_study_values(&cs->spec, run, want);
        for (int k = 0; k < cs->spec.nparams && !bad; k++) bad |= want[k] != r->param[k];
        free(want);
      }
      if (bad) {
        fprintf(stderr, "bgdraw: error: --merge: %s: a row that is not one of this study's runs\n", path);
        rc = EXIT_MODEL;
      }
    }
    free(text);
  }
  for (int i = 0; i < nf; i++) free(names[i]);
  free(names);
  bg_sb_free(&header), bg_sb_free(&f);
  long missing = 0, first_missing = -1;
  for (long k = 0; k < st->count && rc == EXIT_OK; k++)
    if (st->runs[k].status == (bg_study_status)-1) missing++, first_missing = first_missing < 0 ? k : first_missing;
  if (rc == EXIT_OK && missing) {
    fprintf(stderr, "bgdraw: error: --merge %s: %ld of %ld runs are in no part (the first: run "
            "%ld)\n", dir, missing, st->nruns, first_missing);
    rc = EXIT_MODEL;
  }
  for (long k = 0; k < st->count; k++) {
    if (st->runs[k].status == (bg_study_status)-1) st->runs[k].status = BG_STUDY_FAILED;
    st->nfailed += st->runs[k].status != BG_STUDY_OK;
  }
  return rc;
}

/* ------------------------------------------------------------ outputs */
static int write_outputs(run *r, const cli_study *cs, const bg_study *st, const bg_study_bode *bode) {
  int rc = EXIT_OK;
  for (int i = 0; i < cs->nout && rc == EXIT_OK; i++) {
    const char *path = cs->out[i].path, *ext = bg_path_ext(path);
    bg_strbuf b = {0};
    if (!strcmp(ext, "csv")) bg_study_write_csv(st, &b);
    else if (!strcmp(ext, "json")) bg_study_write_json(st, &b);
    else if (bg_study_plot_render(st, cs->out[i].kind, bode, r->ropts.style, r->ropts.style_dir, ext,
                                  path, &b, &r->R->dg) != BG_RENDER_OK) {
      bg_diags_print(&r->R->dg, stderr);
      rc = EXIT_WRITE;
    }
    if (rc == EXIT_OK) rc = cli_write_text(path, &b);
    bg_sb_free(&b);
  }
  return rc;
}

/* --report in a study's call: the model's report at its own values with the
 * study's section (docs/study.md, "In the report"). */
static int write_report(run *r, const bg_study *st, const bg_study_bode *bode) {
  bg_run *R = r->R;
  bg_run_need(R, BG_STAGE_REDUCTION);
  if (R->model->linear.present) bg_run_need(R, BG_STAGE_LINEAR);
  if (R->model->sim.present) bg_run_need(R, BG_STAGE_SIMULATION);
  bg_report_opts ro = {&r->out.o.render, NULL, NULL, st, bode};
  bg_strbuf b = {0};
  int rc = EXIT_OK;
  if (bg_report_render(R, &ro, &b, &R->dg) != BG_RENDER_OK) {
    bg_diags_print(&R->dg, stderr);
    rc = EXIT_WRITE;
  } else rc = cli_write_text(r->opts.report, &b);
  bg_sb_free(&b);
  return rc;
}

/* A usage message after the model was read: the exit status. */
static int usage_status(const char *fmt, const char *a, const char *b) {
  bg_cli_usage_error(fmt, a, b);
  return EXIT_USAGE;
}

/* The study of the command line completed by the model's own (`study`
 * statements, docs/format.md): the command line's params (--sweep,
 * --vary), --monte-carlo, --seed and --collect each replace the model's;
 * then what depends on the whole study is checked. 0, or an exit status. */
static int complete(run *r, cli_study *cs) {
  const bg_cli_opts *o = &r->opts;
  const bg_model *m = r->R->model;
  bg_study_spec *s = &cs->spec;
  char err[512];
  for (int j = 0; m && j < m->nstudy; j++) {
    int k = m->study_kind[j], rc = 0;
    const char *w = m->study_word[j];
    if (k == 's' && !cs->cli_params) rc = bg_study_add_sweep(s, w, err, sizeof err);
    else if (k == 'v' && !cs->cli_params) rc = bg_study_add_vary(s, w, err, sizeof err);
    else if (k == 'c' && !cs->cli_collect) rc = bg_study_add_collect(s, w, err, sizeof err);
    else if (k == 'd' && !o->draws) s->draws = strtol(w + 6, NULL, 10);
    else if (k == 'e' && !o->seed) s->seed = strtoull(w + 5, NULL, 10);
    if (rc) { /* the model checked the words: only the grid's size can still be too large */
      fprintf(stderr, "%s:%d:%d: error: %s\n", r->R->name, m->study_loc[j].line,
              m->study_loc[j].col, err);
      return EXIT_MODEL;
    }
  }
  int sweep = s->nparams && s->kind == BG_STUDY_SWEEP, vary = s->nparams && !sweep;
  if (!sweep && !vary)
    return usage_status("a study needs --sweep NAME=VALUES or --monte-carlo N with --vary "
                              "NAME=DISTRIBUTION (or a study statement in the model)%s%s", "", "");
  if (vary && !s->draws)
    return usage_status("--vary draws from a distribution: say how many runs with "
                              "--monte-carlo N%s%s", "", "");
  if (sweep && (o->draws || o->seed))
    return usage_status("%s belongs to a Monte Carlo study (--vary), not to a sweep%s",
                              o->draws ? "--monte-carlo" : "--seed", "");
  if (!vary) s->draws = 0;
  long nruns = bg_study_nruns(s);
  if (o->runs && cs->first + cs->count > nruns) {
    char buf[64];
    snprintf(buf, sizeof buf, "%ld", nruns);
    return usage_status("--runs %s: the study has %s runs", o->runs, buf);
  }
  if (cs->parts > nruns) cs->parts = nruns;
  int poles = 0;
  for (int k = 0; k < s->ncollect; k++) poles |= s->collect[k].kind == BG_COLLECT_POLES;
  if (o->merge && cs->locus && !poles)
    return usage_status("--root-locus with --merge draws the poles of the parts' tables: "
                              "give the study --collect poles%s%s", "", "");
  return 0;
}

int cli_study_run(run *r, cli_study *cs) {
  const bg_cli_opts *o = &r->opts;
  int crc = complete(r, cs);
  if (crc) return crc;
  if (o->split) return write_jobs(o, cs);
  bg_study_opts so = {0};
  so.name = r->R->name, so.src = r->R->src, so.srclen = r->R->srclen;
  so.sets = o->sets, so.nsets = o->nsets;
  so.method = o->causality ? bg_method_parse(o->causality) : -1;
  so.jobs = cs->jobs, so.keep_curves = cs->curves || (o->report && !o->merge), so.want_poles = cs->locus;
  so.first = cs->first, so.count = cs->count;
  so.log = r->R->o.log;
  bg_study st;
  char err[1024];
  if (o->merge ? bg_study_prepare(&cs->spec, &so, &st, err, sizeof err)
               : bg_study_run_all(&cs->spec, &so, &st, err, sizeof err)) {
    fprintf(stderr, "bgdraw: error: %s\n", err);
    return EXIT_MODEL;
  }
  int rc = o->merge ? merge_parts(o, cs, &st) : EXIT_OK;
  for (long k = 0; o->merge && st.npole && k < st.count; k++) bg_study_poles_from_values(&st, &st.runs[k]);
  bg_study_bode bode = {0};
  if (rc == EXIT_OK && cs->bode && bg_study_bode_compute(&st, &so, &bode, err, sizeof err)) {
    fprintf(stderr, "bgdraw: error: --bode-family: %s\n", err);
    rc = EXIT_MODEL;
  }
  if (rc == EXIT_OK) rc = write_outputs(r, cs, &st, &bode);
  if (rc == EXIT_OK && o->report) rc = write_report(r, &st, &bode);
  bg_study_bode_free(&bode);
  if (rc == EXIT_OK && st.nfailed) {
    fprintf(stderr, "bgdraw: %s: %ld of %ld runs failed (the table's status and reason say why)\n",
            st.nfailed == st.count ? "error" : "warning", st.nfailed, st.count);
    if (st.nfailed == st.count) rc = EXIT_SIM;
  }
  bg_study_free(&st);
  return rc;
}

void cli_study_free(cli_study *cs) { bg_study_spec_free(&cs->spec); }
