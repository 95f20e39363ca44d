/* SPDX-License-Identifier: BSD-3-Clause */
/* libbgdraw: the public C API (include/bgdraw.h). A handle is a run
 * (src/run) with the output writers over it (src/output): the same stages,
 * in the same order, and the same writers as the command line, so every
 * output is byte for byte what `bgdraw` writes. The records below are views
 * of the run's results, their strings and arrays kept in the handle. */
#define _GNU_SOURCE /* dladdr */
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <bgdraw.h> /* the public header, include/ */
#include "analysis/analysis.h"
#include "base/arena.h"
#include "base/fileio.h"
#include "base/strbuf.h"
#include "output/output.h"
#include "run/run.h"

#ifndef BG_LIB_TO_STYLES
#define BG_LIB_TO_STYLES "../share/bgdraw/styles"
#endif

struct bgd_model {
  bg_run *run;
  bg_output out;
  int status;            /* bgd_status */
  char *option_error;    /* a wrong option, in words */
  bgd_options opts;      /* the caller's log function and context */
  bg_arena arena;        /* the records' strings and arrays */
  bgd_diagnostic *diags; /* made on the first bgd_diagnostics */
  int ndiag;
  double **columns;      /* the simulation's columns, made on request */
  char *last_error;
  char style_dir[4200];  /* where named styles are, for this handle's drawings */
  char lib_dir[4200];    /* the component library `use "NAME.bg"` finds */
};

void bgd_options_init(bgd_options *o) {
  memset(o, 0, sizeof *o);
  o->max_errors = -1;
}

const char *bgd_version(void) { return BGDRAW_VERSION_STRING; }
int bgd_api_version(void) { return BGDRAW_API_VERSION; }

/* A folder relative to this library's file: `installed` (LIBDIR/../share/
 * bgdraw/...) or `build` (the build tree's share/bgdraw/...); NULL when
 * neither is a folder. */
static const char *library_share_dir(const char *installed, const char *build, char *dir,
                                     size_t n) {
  Dl_info info;
  if (!dladdr((void *)bgd_version, &info) || !info.dli_fname) return NULL;
  char lib[4096];
  snprintf(lib, sizeof lib, "%s", info.dli_fname);
  char *slash = strrchr(lib, '/');
  if (!slash) return NULL;
  *slash = '\0';
  const char *rel[] = {installed, build};
  for (int i = 0; i < 2; i++) {
    struct stat st;
    snprintf(dir, n, "%s/%s", lib, rel[i]);
    if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode)) return dir;
  }
  return NULL;
}

/* Named styles: $BGDRAW_STYLE_DIR (style.c), else share/bgdraw/styles
 * relative to this library's file (installed: LIBDIR/../share/bgdraw/styles). */
static const char *library_style_dir(char *dir, size_t n) {
  const char *env = getenv("BGDRAW_STYLE_DIR");
  if (env && *env) return NULL;
  return library_share_dir(BG_LIB_TO_STYLES, "share/bgdraw/styles", dir, n);
}

/* The run's messages to the caller's function. */
static void to_caller(void *ctx, bg_log_level level, const char *msg) {
  const bgd_model *m = ctx;
  int lv = level == BG_LOG_PROGRESS || level == BG_LOG_DETAIL ? 0 : level == BG_LOG_INFO ? 1
           : level == BG_LOG_NOTE ? 2 : 3;
  m->opts.log(m->opts.log_ctx, lv, msg);
}

static void option_error(bgd_model *m, const char *what) {
  if (!m->option_error) m->option_error = strdup(what);
  m->status = BGD_USAGE;
}

/* The diagrams' options (layers, highlight, style, layout) from the
 * caller's: -1 with the reason in err for a wrong layer or highlight. */
static int drawing(const bgd_options *o, bg_render_opts *rd, bg_strbuf *err) {
  memset(rd, 0, sizeof *rd);
  rd->show = BG_SHOW_DEFAULT;
  if (o->show && bg_output_parse_show(o->show, &rd->show, err) != 0) return -1;
  if (o->highlight && bg_highlight_parse(o->highlight, &rd->highlight_kind, &rd->highlight_index)) {
    bg_sb_puts(err, "a highlight is path:K, loop:K or conflict:K");
    return -1;
  }
  rd->style = o->style;
  rd->layout = o->layout;
  return 0;
}

/* The run's and the diagrams' options from the caller's. */
static void configure(bgd_model *m, const bgd_options *o, bg_run_opts *ro, bg_render_opts *rd,
                      bg_param_override *sets, char *style_dir, size_t n) {
  bg_run_opts_init(ro);
  if (o->causality) {
    ro->method = bg_method_parse(o->causality);
    if (ro->method < 0) option_error(m, "unknown causality method (scap, relaxed, vandijk, lagrange)");
  }
  for (int i = 0; i < o->nparams; i++) sets[i] = (bg_param_override){o->param_names[i], o->param_values[i]};
  ro->sets = sets, ro->nsets = o->nparams;
  ro->max_list = o->max_list > 0 ? o->max_list : 0;
  ro->max_errors = o->max_errors < 0 ? BG_DIAG_MAX_ERRORS : o->max_errors;
  ro->verify = o->verify;
  for (const char *w = o->warnings; w && *w;) { /* "no-unused-param,error" as -W */
    char one[64];
    size_t len = strcspn(w, ",");
    snprintf(one, sizeof one, "%.*s", (int)len, w);
    int off = !strncmp(one, "no-", 3), id = bg_warning_parse(off ? one + 3 : one);
    if (!strcmp(one, "error")) ro->werror = 1;
    else if (id < 0) option_error(m, "unknown warning in the warnings list");
    else if (off) ro->warn_off |= 1u << id;
    else ro->warn_off &= ~(1u << id);
    w += len + (w[len] == ',');
  }
  if (o->log) ro->log = (bg_log){to_caller, m, o->verbose};
  bg_strbuf err = {0};
  if (drawing(o, rd, &err) != 0) option_error(m, bg_sb_str(&err));
  bg_sb_free(&err);
  rd->style_dir = library_style_dir(style_dir, n);
}

static bgd_model *open_run(const char *name, const char *text, size_t len, const char *path,
                           const bgd_options *o) {
  bgd_model *m = calloc(1, sizeof *m);
  if (!m) return NULL;
  if (o) m->opts = *o;
  else bgd_options_init(&m->opts);
  bg_run_opts ro;
  bg_render_opts rd;
  bg_param_override *sets = calloc((size_t)(m->opts.nparams > 0 ? m->opts.nparams : 1), sizeof *sets);
  configure(m, &m->opts, &ro, &rd, sets, m->style_dir, sizeof m->style_dir);
  ro.lib_dir = library_share_dir(BG_LIB_TO_COMPONENTS, "share/bgdraw/lib", m->lib_dir,
                                 sizeof m->lib_dir); /* docs/format.md, "Files" */
  m->run = bg_run_new(&ro); /* copies the overrides */
  free(sets);
  int rc;
  if (path) rc = bg_run_load_file(m->run, path);
  else { /* the run owns its copy; a NUL byte in it is a diagnostic, as in a file */
    char *copy = malloc(len + 1);
    if (!copy) return bg_run_free(m->run), free(m), NULL;
    memcpy(copy, text, len);
    copy[len] = '\0';
    rc = bg_run_load(m->run, name, copy, len);
  }
  if (rc && !m->status) m->status = BGD_MODEL;
  bg_output_opts oo = {rd, m->opts.prefix, NULL, NULL, 0}; /* the program's signals are its own */
  oo.render.log = &m->run->o.log;
  bg_output_init(&m->out, m->run, &oo);
  return m;
}

bgd_model *bgd_open(const char *name, const char *text, const bgd_options *o) {
  return bgd_open_buffer(name, text, text ? strlen(text) : 0, o);
}

bgd_model *bgd_open_buffer(const char *name, const char *text, size_t len, const bgd_options *o) {
  return open_run(name ? name : "<string>", text ? text : "", text ? len : 0, NULL, o);
}

bgd_model *bgd_open_file(const char *path, const bgd_options *o) { return open_run(NULL, NULL, 0, path, o); }

int bgd_status(const bgd_model *m) { return m ? m->status : BGD_MODEL; }

void bgd_free(bgd_model *m) {
  if (!m) return;
  bg_output_free(&m->out);
  if (m->columns) {
    for (int j = 0; j < m->run->sim.nout; j++) free(m->columns[j]);
    free(m->columns);
  }
  bg_run_free(m->run);
  bg_arena_free(&m->arena);
  free(m->diags);
  free(m->option_error);
  free(m->last_error);
  free(m);
}

/* ---------------------------------------------------------------- diagnostics */
typedef struct diag_list {
  bgd_model *m;
  bgd_diagnostic *items;
  int n, cap;
  int *nnotes; /* per top-level item, filled after */
} diag_list;

static void collect(void *ctx, const bg_diag *g, int is_note) {
  diag_list *l = ctx;
  static const char *const sev[] = {"error", "warning", "note"};
  if (l->n == l->cap) {
    l->cap = l->cap ? 2 * l->cap : 16;
    l->items = realloc(l->items, (size_t)l->cap * sizeof *l->items);
  }
  bgd_diagnostic *d = &l->items[l->n++];
  d->file = bg_arena_strdup(&l->m->arena, bg_diags_path(&l->m->run->dg, g->loc));
  d->line = g->loc.line, d->column = g->loc.col;
  d->severity = sev[g->sev];
  d->message = bg_arena_strdup(&l->m->arena, g->msg);
  d->nnotes = is_note ? -1 : 0; /* -1 marks a note until they are grouped */
  d->notes = NULL;
}

int bgd_diagnostics(bgd_model *m, const bgd_diagnostic **out) {
  if (!m->diags && m->run->done[BG_STAGE_MODEL]) {
    diag_list l = {m, NULL, 0, 0, NULL};
    bg_diags_each(&m->run->dg, collect, &l);
    /* top-level items first, each pointing at its notes kept after them all */
    bgd_diagnostic *all = calloc((size_t)(l.n ? l.n : 1), sizeof *all);
    int ntop = 0;
    for (int i = 0; i < l.n; i++) ntop += l.items[i].nnotes == 0;
    int top = 0, note = ntop;
    for (int i = 0; i < l.n; i++) {
      if (l.items[i].nnotes == 0) {
        all[top] = l.items[i];
        all[top].notes = all + note;
        top++;
      } else if (top > 0) {
        all[note] = l.items[i];
        all[note].nnotes = 0;
        all[top - 1].nnotes++;
        note++;
      }
    }
    free(l.items);
    m->diags = all, m->ndiag = ntop;
  }
  *out = m->diags;
  return m->ndiag;
}

char *bgd_diagnostics_text(const bgd_model *m) {
  char *buf = NULL;
  size_t n = 0;
  FILE *f = open_memstream(&buf, &n);
  if (!f) return NULL;
  if (m->option_error) fprintf(f, "bgdraw: error: %s\n", m->option_error);
  if (m->run->done[BG_STAGE_MODEL]) bg_diags_print(&m->run->dg, f);
  fclose(f);
  return buf;
}

/* ---------------------------------------------------------------- results */
static int loaded(const bgd_model *m) { return m && m->run->model && m->status == BGD_OK; }

const char *bgd_name(const bgd_model *m) { return m && m->run->model ? m->run->model->name : NULL; }

static bg_run *analysed(bgd_model *m) {
  if (!loaded(m)) return NULL;
  bg_run_need(m->run, BG_STAGE_ANALYSIS);
  return m->run;
}

int bgd_count(bgd_model *m, const char *what) {
  bg_run *r = analysed(m);
  if (!r || !what) return -1;
  const bg_model *md = r->model;
  const bg_analysis *a = &r->analysis;
  static const char *const words[] = {"elements", "bonds", "params", "states", "dependent_stores",
                                      "conflicts", "causal_paths", "causal_loops",
                                      "topological_loops", NULL};
  const int counts[] = {md->nelem, md->nbond, md->nparam, a->nstates, a->ndependent,
                        a->nconflict, a->npath, a->ncloop, a->ntloop};
  for (int i = 0; words[i]; i++)
    if (!strcmp(what, words[i])) return counts[i];
  if (!strcmp(what, "unknowns")) {
    bg_run_need(r, BG_STAGE_EQUATIONS);
    return r->eqsys ? bg_eqsys_n(r->eqsys) : 0;
  }
  if (!strcmp(what, "eigenvalues")) {
    bg_run_need(r, BG_STAGE_INDEX);
    return r->index_computed ? r->index.neig : 0;
  }
  if (!strcmp(what, "rows") || !strcmp(what, "columns")) {
    bg_run_need(r, BG_STAGE_SIMULATION);
    return what[0] == 'r' ? r->sim.nrows : r->sim.nout;
  }
  if (!strcmp(what, "poles") || !strcmp(what, "transfer_functions")) {
    bg_run_need(r, BG_STAGE_LINEAR);
    return what[0] == 'p' ? r->lin.npole : r->lin.ntf;
  }
  return -1;
}

int bgd_element_at(bgd_model *m, int i, bgd_element *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  if (i < 0 || i >= r->model->nelem) return BGD_USAGE;
  out->name = r->model->elem_name[i];
  out->kind = bg_elem_kind_name(r->model->elem_kind[i]);
  int c = r->analysis.elem_caus[i];
  out->causality = c == BG_CAUS_NONE ? NULL : bg_caus_name(c);
  return BGD_OK;
}

int bgd_bond_at(bgd_model *m, int i, bgd_bond *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  const bg_model *md = r->model;
  if (i < 0 || i >= md->nbond) return BGD_USAGE;
  out->number = md->bond_num[i];
  out->from = md->elem_name[md->bond_tail[i]];
  out->to = md->elem_name[md->bond_head[i]];
  int s = r->analysis.bond_stroke[i];
  out->stroke = s == BG_STROKE_HEAD ? "to" : s == BG_STROKE_TAIL ? "from" : NULL;
  return BGD_OK;
}

/* Bond ids as the numbers the model writes, in the handle's arena. */
static const int *numbers(bgd_model *m, const int *ids, int n) {
  int *v = bg_arena_alloc(&m->arena, (size_t)(n ? n : 1) * sizeof *v);
  for (int k = 0; k < n; k++) v[k] = m->run->model->bond_num[ids[k]];
  return v;
}

int bgd_causal_path_at(bgd_model *m, int i, bgd_path *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  const bg_analysis *a = &r->analysis;
  if (i < 0 || i >= a->npath) return BGD_USAGE;
  out->from = r->model->elem_name[a->path_end0[i]];
  out->to = r->model->elem_name[a->path_end1[i]];
  out->kind = a->path_kind[i];
  out->cls = a->path_class[i];
  out->order = a->path_order[i] == BG_PATH_ORDER_NONE ? BGD_NO_ORDER : a->path_order[i];
  out->nbonds = a->path_n[i];
  out->bonds = numbers(m, a->path_bonds + a->path_adr[i], a->path_n[i]);
  return BGD_OK;
}

int bgd_causal_loop_at(bgd_model *m, int i, bgd_loop *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  const bg_analysis *a = &r->analysis;
  if (i < 0 || i >= a->ncloop) return BGD_USAGE;
  memset(out, 0, sizeof *out);
  out->nbonds = a->cloop_n[i];
  out->bonds = numbers(m, a->cloop_bonds + a->cloop_adr[i], a->cloop_n[i]);
  out->gain = a->cloop_gain[i];
  out->gain_value = a->cloop_gain_value[i];
  out->cls = a->cloop_class[i];
  out->kind = "causal";
  return BGD_OK;
}

int bgd_topological_loop_at(bgd_model *m, int i, bgd_loop *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  const bg_analysis *a = &r->analysis;
  if (i < 0 || i >= a->ntloop) return BGD_USAGE;
  memset(out, 0, sizeof *out);
  /* the loop's bonds: each signal names its bond (BG_SIG_*), once each */
  int n = a->tloop_n[i], nb = 0;
  int *ids = bg_arena_alloc(&m->arena, (size_t)(n ? n : 1) * sizeof *ids);
  for (int k = 0; k < n; k++) {
    int b = a->tloop_signals[a->tloop_adr[i] + k] / 2, seen = 0;
    for (int j = 0; j < nb; j++) seen |= ids[j] == b;
    if (!seen) ids[nb++] = b;
  }
  out->nbonds = nb;
  out->bonds = numbers(m, ids, nb);
  out->gain = a->tloop_gain[i];
  out->gain_value = a->tloop_gain_value[i];
  out->kind = a->tloop_kind[i] == BG_TLOOP_FLAT ? "flat" : "open";
  out->order = a->tloop_order[i];
  out->algebraic = a->tloop_algebraic[i];
  return BGD_OK;
}

int bgd_conflict_at(bgd_model *m, int i, bgd_conflict *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  const bg_analysis *a = &r->analysis;
  if (i < 0 || i >= a->nconflict) return BGD_USAGE;
  out->element = r->model->elem_name[a->conflict_node[i]];
  out->type = a->conflict_type[i];
  out->degree = a->conflict_degree[i];
  out->nbonds = a->conflict_n[i];
  out->bonds = numbers(m, a->conflict_bonds + a->conflict_adr[i], a->conflict_n[i]);
  return BGD_OK;
}

int bgd_index_info(bgd_model *m, bgd_index *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  bg_run_need(r, BG_STAGE_REDUCTION);
  const bg_analysis *a = &r->analysis;
  const bg_index_facts *f = &r->facts;
  int set = bg_index_facts_numeric_set(f), computed = set && f->numeric->index >= 0;
  out->form = bg_form_name(a->form);
  out->predicted = a->index_predicted;
  out->reason = a->index_reason;
  out->numeric = computed ? f->numeric->index : -1;
  out->numeric_status = computed ? "computed" : set ? "singular" : "not computed";
  out->reduced_form = f->reduced_form;
  out->reduction = f->reduction ? f->reduction->message : NULL;
  return BGD_OK;
}

int bgd_eigenvalues(bgd_model *m, const double **re, const double **im) {
  bg_run *r = analysed(m);
  if (!r) return -1;
  bg_run_need(r, BG_STAGE_INDEX);
  if (!r->index_computed) return *re = *im = NULL, 0;
  *re = r->index.eig_re, *im = r->index.eig_im;
  return r->index.neig;
}

int bgd_simulate(bgd_model *m, bgd_simulation *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  bg_output_need(&m->out, bg_output_find("csv")); /* as the command line orders the stages */
  const bg_simresult *s = &r->sim;
  out->status = r->sim_status == 0 ? BGD_OK : BGD_REFUSED;
  out->message = s->message ? s->message : r->sim_status ? r->eqsys_problem : NULL;
  out->nrows = s->nrows, out->ncolumns = s->nout;
  out->time = s->t;
  out->names = s->names;
  out->solver = s->solver_used;
  out->partial = s->partial;
  return out->status;
}

const double *bgd_column(bgd_model *m, int j) {
  bg_run *r = analysed(m);
  if (!r || !bg_run_has(r, BG_STAGE_SIMULATION) || j < 0 || j >= r->sim.nout) return NULL;
  if (!m->columns) m->columns = calloc((size_t)r->sim.nout, sizeof *m->columns);
  if (!m->columns[j]) { /* the result is row-major; a column is copied out once */
    int n = r->sim.nrows;
    m->columns[j] = malloc((size_t)(n ? n : 1) * sizeof(double));
    for (int k = 0; k < n; k++) m->columns[j][k] = r->sim.values[(size_t)k * r->sim.nout + j];
  }
  return m->columns[j];
}

int bgd_linearise(bgd_model *m, bgd_linear *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  bg_run_need(r, BG_STAGE_LINEAR);
  const bg_linear *l = &r->lin;
  memset(out, 0, sizeof *out);
  out->status = l->ok ? BGD_OK : BGD_REFUSED;
  out->message = l->message;
  out->reduced = l->reduced;
  out->n = l->reduced ? l->n : 0, out->nu = l->nu, out->ny = l->ny;
  out->A = l->A, out->B = l->B, out->C = l->C, out->D = l->D;
  out->inputs = l->uname, out->outputs = l->yname;
  out->npoles = l->npole, out->pole_re = l->pole_re, out->pole_im = l->pole_im;
  return out->status;
}

int bgd_transfer_function_at(bgd_model *m, int k, bgd_transfer *out) {
  bg_run *r = analysed(m);
  if (!r) return BGD_MODEL;
  bg_run_need(r, BG_STAGE_LINEAR);
  if (k < 0 || k >= r->lin.ntf) return BGD_USAGE;
  const bg_lin_tf *t = &r->lin.tf[k];
  out->input = t->iu, out->output = t->iy;
  out->nnum = t->nnum, out->nden = t->nden, out->num = t->num, out->den = t->den;
  out->dc_gain = t->dc_gain;
  out->npoles = t->npole, out->nzeros = t->nzero;
  out->pole_re = t->pole_re, out->pole_im = t->pole_im;
  out->zero_re = t->zero_re, out->zero_im = t->zero_im;
  return BGD_OK;
}

/* ---------------------------------------------------------------- outputs */
static void keep_error(bgd_model *m) {
  char *buf = NULL;
  size_t n = 0;
  FILE *f = open_memstream(&buf, &n);
  if (f) {
    bg_diags_print(&m->out.dg_model, f);
    bg_diags_print(&m->out.dg, f);
    if (m->out.refusal) fprintf(f, "bgdraw: %s\n", m->out.refusal);
    fclose(f);
  }
  free(m->last_error);
  m->last_error = buf && *buf ? buf : (free(buf), NULL);
  bg_output_clear_messages(&m->out);
}

static int produce(bgd_model *m, const char *kind, const char *form, const char *path,
                   bg_strbuf *sb) {
  if (!loaded(m)) return m ? (m->status ? m->status : BGD_MODEL) : BGD_MODEL;
  int rc = (int)bg_output_write(&m->out, kind, form, path, sb);
  keep_error(m);
  if (rc == BGD_OK && m->out.nothing) { /* a CSV or plot of a simulation without rows */
    const bg_run *r = m->run;
    const char *why = r->sim.message ? r->sim.message : r->eqsys_problem;
    size_t n = (why ? strlen(why) : 0) + 200;
    free(m->last_error);
    m->last_error = malloc(n);
    snprintf(m->last_error, n, "bgdraw: nothing to write: the simulation has no rows (%s)\n",
             why ? why : "no reason given");
    rc = BGD_REFUSED;
  }
  return rc;
}

int bgd_output(bgd_model *m, const char *kind, const char *form, char **data, size_t *len) {
  bg_strbuf sb = {0};
  *data = NULL;
  int rc = produce(m, kind, form, NULL, &sb);
  if (rc) {
    bg_sb_free(&sb);
    return rc;
  }
  if (len) *len = sb.len;
  *data = sb.s ? sb.s : strdup("");
  return BGD_OK;
}

int bgd_write(bgd_model *m, const char *kind, const char *form, const char *path) {
  bg_strbuf sb = {0};
  int rc = produce(m, kind, form, path, &sb);
  if (rc == BGD_OK && bg_write_file_atomic(path, sb.s ? sb.s : "", sb.len) != 0) {
    free(m->last_error);
    size_t n = strlen(path) + 200;
    m->last_error = malloc(n);
    snprintf(m->last_error, n, "bgdraw: error: cannot write '%s': %s\n", path, bg_file_strerror(errno));
    rc = BGD_WRITE;
  }
  bg_sb_free(&sb);
  return rc;
}

const char *bgd_last_error(const bgd_model *m) { return m ? m->last_error : NULL; }

static const char *kept(bgd_model *m, const char *s) { return s ? bg_arena_strdup(&m->arena, s) : NULL; }

int bgd_set_drawing(bgd_model *m, const bgd_options *o) {
  bgd_options d;
  if (!o) bgd_options_init(&d), o = &d;
  bg_render_opts rd;
  bg_strbuf err = {0};
  free(m->last_error);
  m->last_error = NULL;
  if (drawing(o, &rd, &err) != 0) { /* the handle keeps its drawing options */
    bg_strbuf msg = {0};
    bg_sb_printf(&msg, "bgdraw: error: %s\n", bg_sb_str(&err));
    m->last_error = msg.s;
    bg_sb_free(&err);
    return BGD_USAGE;
  }
  bg_render_opts *ro = &m->out.o.render;
  /* the strings outlive the caller's: copies in the handle (a few bytes a call) */
  ro->show = rd.show, ro->highlight_kind = rd.highlight_kind, ro->highlight_index = rd.highlight_index;
  ro->style = kept(m, rd.style), ro->layout = kept(m, rd.layout);
  if (m->out.diagram) bg_diagram_free(m->out.diagram), m->out.diagram = NULL; /* laid out anew */
  return BGD_OK;
}

/* ------------------------------------------------------ the first API */
static void give_text(char **errors, char *text) {
  if (errors) *errors = text;
  else free(text);
}

static bg_api_model *load_checked(bgd_model *m, char **errors) {
  if (m && m->status == BGD_OK) {
    bg_run_need(m->run, BG_STAGE_ANALYSIS);
    if (errors) *errors = NULL;
    return m;
  }
  give_text(errors, m ? bgd_diagnostics_text(m) : NULL);
  bgd_free(m);
  return NULL;
}

bg_api_model *bg_api_load_file(const char *path, char **errors) {
  return load_checked(bgd_open_file(path, NULL), errors);
}

bg_api_model *bg_api_load_string(const char *name, const char *text, char **errors) {
  return load_checked(bgd_open(name, text, NULL), errors);
}

const char *bg_api_name(const bg_api_model *m) { return bgd_name(m); }

int bg_api_count(const bg_api_model *m, const char *what) {
  static const char *const words[] = {"bonds", "elements", "states", "conflicts",
                                      "causal_paths", "causal_loops", "topological_loops", NULL};
  for (int i = 0; words[i]; i++) /* loading analysed it already */
    if (!strcmp(what, words[i])) return bgd_count((bgd_model *)m, what);
  return -1;
}

char *bg_api_summary(const bg_api_model *m) {
  bg_strbuf sb = {0};
  bg_model_summary(m->run->model, &sb);
  bg_sb_putc(&sb, '\n');
  bg_analysis_summary(m->run->model, &m->run->analysis, &sb);
  return sb.s;
}

char *bg_api_json(const bg_api_model *m) {
  char *data = NULL;
  bgd_output((bgd_model *)m, "json", NULL, &data, NULL);
  return data;
}

int bg_api_render(bg_api_model *m, const char *format, const char *style, const char *show,
                  char **data, size_t *len, char **errors) {
  bg_render_opts saved = m->out.o.render;
  bg_render_opts *ro = &m->out.o.render;
  int rc = BGD_OK;
  ro->style = style;
  if (!format || (strcmp(format, "svg") && strcmp(format, "pdf") && strcmp(format, "png") &&
                  strcmp(format, "dot"))) {
    give_text(errors, strdup("bgdraw: error: unknown diagram format (svg, pdf, png, dot)\n"));
    *data = NULL;
    return -1;
  }
  if (show && bg_show_parse(show, &ro->show) != 0) { /* the list is the set of layers */
    free(m->last_error);
    size_t n = strlen(show) + 64;
    m->last_error = malloc(n);
    snprintf(m->last_error, n, "bgdraw: error: unknown layer in show list '%s'\n", show);
    rc = BGD_USAGE;
    *data = NULL;
  }
  if (m->out.diagram) bg_diagram_free(m->out.diagram), m->out.diagram = NULL;
  if (!rc) rc = bgd_output(m, format, NULL, data, len);
  if (m->out.diagram) bg_diagram_free(m->out.diagram), m->out.diagram = NULL;
  m->out.o.render = saved;
  if (rc) give_text(errors, m->last_error ? strdup(m->last_error) : NULL);
  else if (errors) *errors = NULL;
  return rc ? -1 : 0;
}

void bg_api_free(bg_api_model *m) { bgd_free(m); }

const char *bg_api_version(void) { return bgd_version(); }
