/* SPDX-License-Identifier: BSD-3-Clause */
/* The run (run.h): each stage once, on demand, after what it needs. The
 * order and the conditions are the command line's of old, so every output
 * is what it was; the command line and the library now share them. */
#include "run/run.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "analysis/analysis.h"
#include "base/fileio.h"
#include "base/strbuf.h"

void bg_run_opts_init(bg_run_opts *o) {
  memset(o, 0, sizeof *o);
  o->method = -1;
  o->max_errors = BG_DIAG_MAX_ERRORS;
}

bg_run *bg_run_new(const bg_run_opts *o) {
  bg_run *r = calloc(1, sizeof *r);
  if (!r) BG_FATAL("out of memory");
  if (o) r->o = *o;
  else bg_run_opts_init(&r->o);
  if (r->o.nsets > 0) { /* the caller's overrides may not outlive the call */
    r->sets = calloc((size_t)r->o.nsets, sizeof *r->sets);
    for (int i = 0; i < r->o.nsets; i++) {
      r->sets[i] = r->o.sets[i];
      r->sets[i].name = strdup(r->o.sets[i].name);
    }
  }
  r->o.sets = r->sets;
  return r;
}

int bg_run_has(const bg_run *r, bg_stage s) { return r && s >= 0 && s < BG_STAGE_COUNT && r->done[s]; }

/* The folders of $BGDRAW_PATH (':' between them, empty ones skipped) into
 * dirs (NULL-terminated; the strings point into buf). */
static void split_use_path(char *buf, const char **dirs, int cap) {
  int n = 0;
  for (char *save = NULL, *d = strtok_r(buf, ":", &save); d && n < cap - 1;
       d = strtok_r(NULL, ":", &save))
    dirs[n++] = d;
  dirs[n] = NULL;
}

/* Compiles the syntax with the folders `use` searches. */
static bg_model *compile(bg_run *r, bg_ast *ast) {
  enum { MAX_DIRS = 64 };
  const char *env = getenv("BGDRAW_PATH");
  char *buf = strdup(env ? env : "");
  if (!buf) BG_FATAL("out of memory");
  const char *dirs[MAX_DIRS];
  split_use_path(buf, dirs, MAX_DIRS);
  ast->use_path = dirs;
  ast->use_lib = r->o.lib_dir;
  bg_model *m = bg_model_compile(ast, r->o.sets, r->o.nsets, &r->dg);
  ast->use_path = NULL;
  free(buf);
  return m;
}

/* Diagnostics in the imported .bg text (source k and the instances' sources
 * sharing its text) point at the foreign file's line they came from: the
 * model file's, or another file the import read (an MTT label file). */
static void point_at_source(bg_run *r, int k, int from) {
  const char *text = r->dg.sources[k].src;
  const bg_import_result *ir = &r->import;
  for (int i = from; i < r->dg.n; i++) {
    bg_srcloc *at = &r->dg.items[i].loc;
    if (at->file <= 0 || at->file >= r->dg.nsources || r->dg.sources[at->file].src != text) continue;
    if (at->line < 1 || at->line > ir->nlines || !ir->line_of[at->line]) continue;
    int line = ir->line_of[at->line], col = 1, file = ir->file_of ? ir->file_of[at->line] : 0;
    const char *src = file ? r->dg.sources[file].src : r->src;
    size_t len = file ? r->dg.sources[file].srclen : r->srclen;
    const char *s = src;
    for (int l = 1; l < line && s; l++) s = memchr(s, '\n', len - (size_t)(s - src)), s = s ? s + 1 : s;
    while (s && s < src + len && (*s == ' ' || *s == '-' || *s == '\t')) s++, col++;
    *at = (bg_srcloc){line, col, file};
  }
}

/* Another tool's model: converted (errors at its own lines), then parsed as
 * the .bg text it became, a source of its own. */
static int load_imported(bg_run *r, bg_ast **ast) {
  *ast = NULL;
  if (bg_import_convert(r->imported, r->name, r->src, r->srclen, &r->dg, &r->import)) return -1;
  if (r->o.keep_ast) {
    bg_diag_error(&r->dg, (bg_srcloc){0}, "--transform edits .bg text: convert the %s model first "
                  "(bgdraw --import %s -o MODEL.bg)", bg_import_format_name(r->imported), r->name);
    return -1;
  }
  bg_strbuf path = {0};
  bg_sb_printf(&path, "%s (imported)", r->name);
  int k = bg_diags_add_source(&r->dg, path.s, r->import.text, r->import.len);
  bg_sb_free(&path);
  int from = r->dg.n;
  *ast = bg_parse_source(r->name, r->import.text, r->import.len, k, &r->dg);
  if (*ast && !r->dg.nerrors) r->model = compile(r, *ast);
  point_at_source(r, k, from);
  return 0;
}

int bg_run_load(bg_run *r, const char *name, char *text, size_t len) {
  if (r->done[BG_STAGE_MODEL]) BG_FATAL("a run is loaded once");
  r->done[BG_STAGE_MODEL] = 1;
  r->name = strdup(name);
  r->src = text, r->srclen = len;
  bg_diags_init(&r->dg, r->name, r->src, r->srclen);
  r->dg.log = &r->o.log; /* -v: the flattener's progress */
  r->dg.max_errors = r->o.max_errors;
  r->dg.warn_off = r->o.warn_off;
  r->dg.werror = r->o.werror;
  if (!r->src) {
    bg_diag_error(&r->dg, (bg_srcloc){0}, "cannot read the model: %s", bg_file_strerror(errno));
    return -1;
  }
  bg_ast *ast;
  r->imported = bg_import_detect(r->src, r->srclen);
  if (r->imported) {
    if (load_imported(r, &ast)) return -1;
  } else ast = bg_parse_string(r->name, r->src, r->srclen, &r->dg);
  /* After syntax errors the statements that parsed are still compiled, so
   * their name and structure errors come in the same run (what may follow
   * from a dropped statement is not said: bg_diags_unsure); the model is
   * then dropped. A file refused whole (not text, another tool's format)
   * and a run at the error limit stop here. */
  if (ast && !r->model && (!r->dg.nerrors || (r->dg.nskipped && !bg_diags_full(&r->dg))))
    r->model = compile(r, ast);
  if (r->o.keep_ast) r->ast = ast; /* the transformations edit the syntax */
  else bg_ast_free(ast);
  if (r->model && r->dg.nerrors) bg_model_free(r->model), r->model = NULL;
  return r->model ? 0 : -1;
}

int bg_run_load_file(bg_run *r, const char *path) {
  size_t len = 0;
  struct stat st;
  if (!stat(path, &st) && S_ISDIR(st.st_mode)) { /* an MTT model's folder: its drawing */
    char *why = NULL, *fig = bg_import_find_drawing(path, &why);
    if (!fig) {
      bg_diags_init(&r->dg, path, NULL, 0);
      r->done[BG_STAGE_MODEL] = 1;
      r->name = strdup(path);
      bg_diag_error(&r->dg, (bg_srcloc){0}, "%s", why);
      free(why);
      return -1;
    }
    char *text = bg_read_file(fig, &len);
    int rc = bg_run_load(r, fig, text, len);
    free(fig);
    return rc;
  }
  char *text = bg_read_file(path, &len);
  return bg_run_load(r, path, text, len);
}

int bg_run_load_string(bg_run *r, const char *name, const char *text) {
  size_t len = strlen(text);
  char *copy = malloc(len + 1);
  if (!copy) BG_FATAL("out of memory");
  memcpy(copy, text, len + 1);
  return bg_run_load(r, name ? name : "<string>", copy, len);
}

/* Causality with the method asked for, else the model's own; then paths,
 * loops, form and the predicted index. */
static void analyse(bg_run *r) {
  int method = r->o.method >= 0 ? r->o.method : r->model->method;
  bg_logf(&r->o.log, BG_LOG_PROGRESS, "causality (%s)", bg_method_name(method));
  bg_analysis_init(&r->analysis, r->model);
  bg_causality_assign(r->model, method, &r->analysis, &r->dg);
  bg_logf(&r->o.log, BG_LOG_PROGRESS, "causal paths, loops, form and index");
  bg_analysis_limits lim = {r->o.max_list, r->o.max_list};
  bg_analysis_run(r->model, &r->analysis, &lim);
}

/* The equations. A model whose equations cannot be formed is not an error
 * here: the reason is kept for what needs them. */
static void derive_equations(bg_run *r) {
  bg_logf(&r->o.log, BG_LOG_PROGRESS, "equations");
  bg_diags eqd;
  bg_diags_init(&eqd, r->dg.file, r->src, r->srclen);
  r->eqsys = bg_eqsys_build(r->model, &r->analysis, &eqd);
  if (!r->eqsys)
    r->eqsys_problem = strdup(eqd.n ? eqd.items[0].msg : "the equations could not be formed");
  else { /* what the equations become after symbolic elimination */
    r->facts.reduced_form = bg_eqred_form(r->eqsys, &r->facts.reduced_note);
    if (r->facts.reduced_note) bg_logf(&r->o.log, BG_LOG_PROGRESS, "reduced form %s", r->facts.reduced_note);
  }
  bg_diags_free(&eqd);
}

/* The numeric index of the linearised model; dense, so skipped above
 * BG_RUN_INDEX_MAX unknowns (and said). */
static void numeric_index(bg_run *r) {
  if (!r->eqsys) return;
  int n = bg_eqsys_n(r->eqsys);
  if (n > BG_RUN_INDEX_MAX) {
    bg_logf(&r->o.log, BG_LOG_PROGRESS, "%d unknowns: numeric index skipped (dense algorithm, limit %d)",
            n, BG_RUN_INDEX_MAX);
    bg_strbuf sb = {0};
    bg_sb_printf(&sb, "%d unknowns, more than the dense algorithm's limit of %d", n, BG_RUN_INDEX_MAX);
    r->index_skipped = sb.s;
    r->facts.numeric_skipped = r->index_skipped;
    return;
  }
  bg_logf(&r->o.log, BG_LOG_PROGRESS, "numeric index (Algorithm 4.1)");
  bg_index_compute(r->eqsys, r->model, &r->index);
  r->index_computed = 1;
  r->facts.numeric = &r->index;
  r->index_disagreement = bg_index_disagreement(&r->analysis, &r->index);
  r->facts.disagreement = r->index_disagreement;
  if (r->index_disagreement) bg_logf(&r->o.log, BG_LOG_WARNING, "%s", r->index_disagreement);
}

/* Pantelides and dummy derivatives when the index is above 1 (or a loop of
 * gain +1 makes it so). */
static void index_reduction(bg_run *r) {
  if (!r->eqsys || !bg_simulate_index_problem(&r->analysis, &r->facts)) return;
  bg_logf(&r->o.log, BG_LOG_PROGRESS, "index reduction (Pantelides, dummy derivatives)");
  bg_indexred_run(r->eqsys, &r->ired);
  r->ired_tried = 1;
  r->facts.reduction = &r->ired;
  if (bg_log_on(&r->o.log, BG_LOG_PROGRESS)) {
    bg_strbuf sb = {0};
    bg_indexred_text(&r->ired, "  ", &sb);
    for (char *line = sb.s, *nl; line && *line; line = nl + 1) {
      nl = strchr(line, '\n');
      if (nl) *nl = 0;
      bg_logf(&r->o.log, BG_LOG_PROGRESS, "%s", line);
      if (!nl) break;
    }
    bg_sb_free(&sb);
  }
}

/* The system a simulation integrates: the index reduction's when there is one. */
static bg_eqsys *sim_system(const bg_run *r) {
  return r->ired_tried && r->ired.status == 1 ? r->ired.reduced : r->eqsys;
}

/* The simulate block: the result (a refusal, a failure with the rows up to
 * it, or the whole run) stays in r->sim; the caller says what it means. */
static void simulate(bg_run *r) {
  bg_sim_opts so = {0};
  so.log = &r->o.log;
  so.eqs_problem = r->eqsys_problem;
  so.facts = &r->facts;
  r->sim_status = bg_simulate(r->model, &r->analysis, sim_system(r), &so, &r->sim);
  const bg_log *log = &r->o.log;
  if (r->sim.ic_report && !bg_log_on(log, BG_LOG_PROGRESS)) /* -v said it already */
    bg_logf(log, BG_LOG_NOTE, "initial values made consistent: %s", r->sim.ic_report);
  bg_strbuf w = {0};
  if (bg_simresult_row_warning(&r->sim, &w)) bg_logf(log, BG_LOG_WARNING, "%s", bg_sb_str(&w));
  bg_sb_clear(&w);
  if (r->sim_status == 0 && r->o.verify) {
    bg_sim_verify(r->model, &r->analysis, sim_system(r), &so, &r->sim);
    if (bg_sim_verify_text(&r->sim, &w)) bg_logf(log, BG_LOG_INFO, "%s", bg_sb_str(&w));
  }
  bg_sb_free(&w);
  if (r->sim_status == 0 && r->sim.solver_reason)
    bg_logf(log, BG_LOG_PROGRESS, "solver %s: %s", r->sim.solver_used, r->sim.solver_reason);
}

static void linearise(bg_run *r) {
  bg_logf(&r->o.log, BG_LOG_PROGRESS, "linear analysis");
  bg_linear_compute(r->model, &r->analysis, -1, &r->lin);
  if (r->lin.ok && r->lin.message) bg_logf(&r->o.log, BG_LOG_NOTE, "linear analysis: %s", r->lin.message);
}

/* What each stage needs first. */
static bg_stage needs(bg_stage s) { return s == BG_STAGE_LINEAR ? BG_STAGE_ANALYSIS : s - 1; }

int bg_run_need(bg_run *r, bg_stage s) {
  if (!r->model) return -1;
  if (s < 0 || s >= BG_STAGE_COUNT) BG_FATAL("no stage %d", (int)s);
  if (r->done[s]) return 0;
  if (s > BG_STAGE_MODEL) bg_run_need(r, needs(s));
  r->done[s] = 1;
  switch (s) {
  case BG_STAGE_MODEL: break;
  case BG_STAGE_ANALYSIS: analyse(r); break;
  case BG_STAGE_EQUATIONS: derive_equations(r); break;
  case BG_STAGE_INDEX: numeric_index(r); break;
  case BG_STAGE_REDUCTION: index_reduction(r); break;
  case BG_STAGE_SIMULATION: simulate(r); break;
  case BG_STAGE_LINEAR: linearise(r); break;
  case BG_STAGE_COUNT: break;
  }
  return 0;
}

void bg_run_free(bg_run *r) {
  if (!r) return;
  if (r->done[BG_STAGE_LINEAR] && r->model) bg_linear_free(&r->lin);
  if (r->done[BG_STAGE_SIMULATION] && r->model) bg_simresult_free(&r->sim); /* before the systems its names point into */
  if (r->ired_tried) bg_indexred_free(&r->ired);
  if (r->index_computed) bg_index_free(&r->index);
  free(r->index_skipped);
  free(r->index_disagreement);
  if (r->eqsys) bg_eqsys_free(r->eqsys);
  free(r->eqsys_problem);
  if (r->done[BG_STAGE_ANALYSIS] && r->model) bg_analysis_free(&r->analysis);
  if (r->model) bg_model_free(r->model);
  if (r->ast) bg_ast_free(r->ast);
  if (r->done[BG_STAGE_MODEL]) bg_diags_free(&r->dg);
  free(r->src);
  bg_import_result_free(&r->import);
  free(r->name);
  for (int i = 0; i < r->o.nsets; i++) free((char *)r->sets[i].name);
  free(r->sets);
  free(r);
}
