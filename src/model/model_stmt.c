/* SPDX-License-Identifier: BSD-3-Clause */
/* The model compiler, part 3: elements (bond counts, values and laws,
 * modulation, linearity, options) and the statements model, causality,
 * simulate, layout, plot, and the options of bonds and states. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/expr.h"
#include "model/model_int.h"

/* ---------------------------------------------------------------- elements */
static void check_bond_count(bg_build *b, int e) {
  const bg_model *m = b->m;
  int kind = m->elem_kind[e], n = m->elem_nbond[e];
  const char *name = m->elem_name[e], *kn = bg_elem_kind_name(kind);
  if (b->elem_guessed[e]) return; /* the misspelled bond end is reported instead */
  if (bg_diags_unsure_bonds(b->dg, name)) return; /* its bond may be on a dropped line */
  if (m->elem_field[e] >= 0 && n != 1) { /* a port of a field */
    int f = m->elem_field[e];
    if (n == 0)
      bg_diag_error(b->dg, m->elem_loc[e], "port %s of %s field %s has no bond (bond it as "
                    "'%s')", bg_elem_port_name(m, e), bg_elem_kind_name(kind), m->field_name[f], name);
    else {
      int second = m->elem_bonds[m->elem_bondadr[e] + 1];
      bg_diag_error(b->dg, m->bond_loc[second], "port %s of %s field %s is bonded twice (a port "
                    "takes one bond; join several through a junction)", bg_elem_port_name(m, e),
                    bg_elem_kind_name(kind), m->field_name[f]);
      bg_diag_note(b->dg, m->bond_loc[m->elem_bonds[m->elem_bondadr[e]]], "the first bond of %s",
                   name);
    }
    return;
  }
  if (n == 0) {
    bg_diag_error(b->dg, m->elem_loc[e], "'%s' has no bond (every element and junction needs "
                  "at least one)", name);
  } else if (bg_elem_is_oneport(kind) && n != 1) {
    bg_diag_error(b->dg, m->elem_loc[e], "'%s' has %d bonds; %s element has exactly one",
                  name, n, bg_elem_kind_article(kind));
  } else if (bg_elem_is_twoport(kind)) {
    int in = 0, out = 0;
    for (int i = 0; i < n; i++) {
      int bond = m->elem_bonds[m->elem_bondadr[e] + i];
      in += m->bond_head[bond] == e;
      out += m->bond_tail[bond] == e;
    }
    if (in != 1 || out != 1)
      bg_diag_error(b->dg, m->elem_loc[e], "%s '%s' needs one bond pointing in and one pointing "
                    "out (it has %d in, %d out)", kn, name, in, out);
  } else if (bg_elem_is_junction(kind) && n < 2) {
    bg_diag_error(b->dg, m->elem_loc[e], "junction '%s' has 1 bond; a junction needs at least two",
                  name);
  }
}

/* The law's left-hand side: 'e' or 'f' as the kind allows; 0 after an error. */
static char law_lhs(bg_build *b, int e, const bg_ast_stmt *s) {
  int kind = b->m->elem_kind[e];
  const char *lhs = s->law_lhs;
  if (kind != BG_ELEM_C && kind != BG_ELEM_I && kind != BG_ELEM_R) {
    bg_diag_error(b->dg, s->law_loc, "%s takes no law; write '%s %s = EXPR'",
                  bg_elem_kind_article(kind), bg_elem_kind_name(kind), s->name);
    return 0;
  }
  if (kind == BG_ELEM_C && strcmp(lhs, "e") != 0) {
    bg_diag_error(b->dg, s->law_loc, "a C law is 'e = F(q)', not '%s = ...'", lhs);
    return 0;
  }
  if (kind == BG_ELEM_I && strcmp(lhs, "f") != 0) {
    bg_diag_error(b->dg, s->law_loc, "an I law is 'f = F(p)', not '%s = ...'", lhs);
    return 0;
  }
  if (kind == BG_ELEM_R && strcmp(lhs, "e") != 0 && strcmp(lhs, "f") != 0) {
    bg_diag_error(b->dg, s->law_loc, "an R law is 'e = F(f)' or 'f = G(e)', not '%s = ...'", lhs);
    return 0;
  }
  return lhs[0];
}

/* elem_linear of a law: affine in the element's own input variable. */
static int law_linear(const bg_model *m, int e) {
  int kind = m->elem_kind[e], root = m->elem_expr[e];
  if (kind == BG_ELEM_C || kind == BG_ELEM_I) return bg_build_is_affine(m, root, BG_X_STORE, e);
  int bond = bg_elem_port_bond(m, e);
  if (bond < 0) return 0;
  return bg_build_is_affine(m, root, m->elem_form[e] == BG_FORM_LAW_E ? BG_X_FLOW : BG_X_EFFORT,
                            bond);
}

/* A plain source or two-port may not read model variables; C, I, R become MC, MI, MR. */
static void check_modulation(bg_build *b, int e) {
  bg_model *m = b->m;
  int kind = m->elem_kind[e];
  if (!b->modvar) return;
  static const int plain[] = {BG_ELEM_SE, BG_ELEM_SF, BG_ELEM_TF, BG_ELEM_GY};
  static const int mod[] = {BG_ELEM_MSE, BG_ELEM_MSF, BG_ELEM_MTF, BG_ELEM_MGY};
  for (int i = 0; i < 4; i++)
    if (kind == plain[i]) {
      bg_diag_error(b->dg, b->modvar_loc, "%s %s is modulated by %s: declare it %s",
                    bg_elem_kind_name(kind), m->elem_name[e], b->modvar, bg_elem_kind_name(mod[i]));
      return;
    }
  m->elem_modulated[e] = 1;
}

static void compile_element_expr(bg_build *b, int e, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  int kind = m->elem_kind[e];
  if (bg_elem_is_junction(kind)) {
    if (s->expr)
      bg_diag_error(b->dg, s->has_law ? s->law_loc : s->expr->loc,
                    "a junction takes no value or law");
    return;
  }
  if (!s->expr) {
    bg_diag_error(b->dg, s->name_loc, "%s '%s' needs a value: '%s %s = EXPR'%s",
                  bg_elem_kind_name(kind), s->name, bg_elem_kind_name(kind), s->name,
                  kind == BG_ELEM_C || kind == BG_ELEM_I || kind == BG_ELEM_R ? " or a law ': v = EXPR'" : "");
    return;
  }
  char lhs = s->has_law ? law_lhs(b, e, s) : 0;
  if (s->has_law && !lhs) return;
  b->allow = ALLOW_TIME | ALLOW_INPUT | ALLOW_MODEL;
  b->input_limit = m->ninput;
  b->what = "an element";
  b->elem = e;
  b->law_elem = lhs ? e : -1;
  b->law_lhs = lhs;
  b->modvar = NULL;
  m->elem_expr[e] = bg_build_expr(b, s->expr);
  m->elem_form[e] = !lhs ? BG_FORM_VALUE : lhs == 'e' ? BG_FORM_LAW_E : BG_FORM_LAW_F;
  m->elem_linear[e] = !lhs || law_linear(m, e);
  check_modulation(b, e);
  b->elem = b->law_elem = -1;
}

static int caus_opt(bg_build *b, int e, const bg_ast_stmt *s) {
  int kind = b->m->elem_kind[e];
  const char *valid = bg_elem_is_store(kind) ? "integral, derivative" : "resistance, conductance";
  const char *w = bg_build_word_opt(b, s, "causality", valid);
  if (!w) return BG_CAUS_OPT_NONE;
  if (!strcmp(w, "integral")) return BG_CAUS_OPT_INTEGRAL;
  if (!strcmp(w, "derivative")) return BG_CAUS_OPT_DERIVATIVE;
  if (!strcmp(w, "resistance")) return BG_CAUS_OPT_RESISTANCE;
  return BG_CAUS_OPT_CONDUCTANCE;
}

static void element_options(bg_build *b, int e, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  int kind = m->elem_kind[e];
  const char *valid = kind == BG_ELEM_C   ? "label, color, at, causality, q0"
                      : kind == BG_ELEM_I ? "label, color, at, causality, p0"
                      : kind == BG_ELEM_R ? "label, color, at, causality"
                                          : "label, color, at";
  char whose[160];
  snprintf(whose, sizeof whose, "%s '%s'", bg_elem_kind_name(kind), s->name);
  bg_build_check_options(b, s, valid, whose);
  m->elem_label[e] = bg_build_string_opt(b, s, "label");
  m->elem_color[e] = bg_build_color_opt(b, s);
  bg_build_at_opt(b, e, s);
  if (kind == BG_ELEM_C || kind == BG_ELEM_I || kind == BG_ELEM_R) m->elem_causopt[e] = caus_opt(b, e, s);
  if (kind == BG_ELEM_C) m->elem_init[e] = bg_build_init_opt(b, s, "q0");
  if (kind == BG_ELEM_I) m->elem_init[e] = bg_build_init_opt(b, s, "p0");
}

void bg_build_elements(bg_build *b) {
  bg_model *m = b->m;
  for (int e = 0; e < m->nelem; e++) check_bond_count(b, e);
  for (int e = 0; e < m->nelem; e++) {
    int f = m->elem_field[e];
    if (f >= 0) { /* a field's ports: its laws and options, at its first port */
      if (e == m->field_elemadr[f]) {
        bg_build_field_laws(b, f);
        bg_build_field_options(b, f);
      }
      continue;
    }
    compile_element_expr(b, e, b->elem_stmt[e]);
    element_options(b, e, b->elem_stmt[e]);
  }
}

/* ---------------------------------------------------------------- statements */
/* At most one of model, causality, simulate, layout. */
static int once(bg_build *b, const bg_ast_stmt *s, const bg_ast_stmt **first, const char *word) {
  if (*first) {
    bg_diag_error(b->dg, s->loc, "'%s' already given at line %d (at most one per model)", word,
                  (*first)->loc.line);
    return 0;
  }
  *first = s;
  return 1;
}

static void st_causality(bg_build *b, const bg_ast_stmt *s) {
  int meth = bg_method_parse(s->name);
  if (meth < 0) {
    static const char *const names[] = {"scap", "relaxed", "vandijk", "lagrange"};
    const char *sug = bg_build_suggest(NULL, s->name, names, 4);
    bg_diag_error(b->dg, s->name_loc, "unknown causality method '%s'%s%s%s; valid: scap, relaxed, "
                  "vandijk, lagrange", s->name, sug ? " (did you mean '" : "", sug ? sug : "",
                  sug ? "'?)" : "");
    return;
  }
  b->m->method = meth;
  b->m->method_given = 1;
}

static void st_simulate(bg_build *b, const bg_ast_stmt *s) {
  bg_simspec *sim = &b->m->sim;
  bg_build_check_options(b, s, "t_end, t0, dt, solver, rtol, atol, max_step", "simulate");
  sim->present = 1;
  sim->loc = s->loc;
  sim->t0 = bg_build_num_opt(b, s, "t0", 0);
  sim->t_end = bg_build_num_opt(b, s, "t_end", 0);
  sim->dt = bg_build_num_opt(b, s, "dt", 0);
  sim->rtol = bg_build_num_opt(b, s, "rtol", 0);
  sim->atol = bg_build_num_opt(b, s, "atol", 0);
  sim->max_step = bg_build_num_opt(b, s, "max_step", 0);
  const char *solver = bg_build_word_opt(b, s, "solver", "auto, cvode_bdf, cvode_adams, ida");
  if (solver) sim->solver = solver;
  if (!bg_build_find_opt(s, "t_end")) {
    /* an unknown option reported above may be the misspelt t_end: no second error */
    int unknown = 0;
    for (int i = 0; i < s->nopts; i++)
      unknown |= !strstr("t_end, t0, dt, solver, rtol, atol, max_step", s->opts[i].key);
    if (!unknown) bg_diag_error(b->dg, s->loc, "simulate needs t_end (e.g. simulate t_end = 10)");
    return;
  }
  if (!(sim->t_end > sim->t0))
    bg_diag_error(b->dg, bg_build_find_opt(s, "t_end")->value->loc, "t_end (%g) must be greater than t0 (%g)",
                  sim->t_end, sim->t0);
  static const char *const positive[] = {"dt", "rtol", "atol", "max_step"};
  const double vals[] = {sim->dt, sim->rtol, sim->atol, sim->max_step};
  for (int i = 0; i < 4; i++)
    if (bg_build_find_opt(s, positive[i]) && !(vals[i] > 0))
      bg_diag_error(b->dg, bg_build_find_opt(s, positive[i])->value->loc, "%s must be positive, not %g",
                    positive[i], vals[i]);
}

static void st_layout(bg_build *b, const bg_ast_stmt *s) {
  bg_build_check_options(b, s, "engine, rankdir", "layout");
  const char *engine = bg_build_word_opt(b, s, "engine", "dot, neato, fdp, sfdp, pinned, rows");
  const char *rankdir = bg_build_word_opt(b, s, "rankdir", "LR, TB, RL, BT");
  if (engine) b->m->layout.engine = engine;
  if (rankdir) b->m->layout.rankdir = rankdir;
}

static void st_plot(bg_build *b, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  bg_build_check_options(b, s, "title, ylabel, xlabel", "plot");
  int p = bg_build_new(b, &m->nplot);
  m->plot_expradr[p] = m->nplotexpr;
  m->plot_nexpr[p] = s->nexprs;
  m->plot_title[p] = bg_build_string_opt(b, s, "title");
  m->plot_ylabel[p] = bg_build_string_opt(b, s, "ylabel");
  m->plot_xlabel[p] = bg_build_string_opt(b, s, "xlabel");
  if (!m->plot_ylabel[p]) m->plot_ylabel[p] = "";
  if (!m->plot_xlabel[p]) m->plot_xlabel[p] = "t";
  b->allow = ALLOW_TIME | ALLOW_INPUT | ALLOW_MODEL;
  b->input_limit = m->ninput;
  b->what = "a plot";
  for (int i = 0; i < s->nexprs; i++) {
    int root = bg_build_expr(b, s->exprs[i]);
    int k = bg_build_new(b, &m->nplotexpr);
    m->plotexpr_root[k] = root;
    m->plotexpr_text[k] = bg_build_strdup(b, s->exprs[i]->text);
  }
}

static void st_state(bg_build *b, const bg_ast_stmt *s) {
  const ns_entry *n = bg_build_lookup(b, s->name);
  bg_build_check_options(b, s, "init", "a state");
  if (!n || n->kind != NS_STATE || n->loc.line != s->name_loc.line) return;
  b->m->state_init[n->id] = bg_build_init_opt(b, s, "init");
}

static void st_bond(bg_build *b, const bg_ast_stmt *s, int bond) {
  bg_build_check_options(b, s, "label, color", "a bond");
  b->m->bond_label[bond] = bg_build_string_opt(b, s, "label");
  b->m->bond_color[bond] = bg_build_color_opt(b, s);
}

static void st_model(bg_build *b, const bg_ast_stmt *s) {
  b->m->name = bg_build_strdup(b, s->name);
  b->m->title = bg_build_strdup(b, s->text);
}

/* output NAME = EXPR ["description"]: an output of the linear analysis. */
static void st_output(bg_build *b, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  const ns_entry *n = bg_build_lookup(b, s->name);
  if (n) {
    bg_diag_error(b->dg, s->name_loc, "'%s' is already %s (line %d); an output needs a name of "
                  "its own", s->name, bg_ns_what[n->kind], n->loc.line);
    return;
  }
  for (int k = 0; k < m->noutput; k++)
    if (strcmp(m->output_name[k], s->name) == 0) {
      bg_diag_error(b->dg, s->name_loc, "output '%s' already defined at line %d", s->name,
                    m->output_loc[k].line);
      return;
    }
  b->allow = ALLOW_TIME | ALLOW_INPUT | ALLOW_MODEL;
  b->input_limit = m->ninput;
  b->what = "an output";
  int root = bg_build_expr(b, s->expr);
  int k = bg_build_new(b, &m->noutput);
  m->output_name[k] = bg_build_strdup(b, s->name);
  m->output_expr[k] = root;
  m->output_desc[k] = bg_build_strdup(b, s->text);
  m->output_det[k] = -1;
  m->output_loc[k] = s->name_loc;
}

/* One name of `inputs = (...)`: a source element or an `input`. */
static void lin_input(bg_build *b, const bg_expr *e) {
  bg_model *m = b->m;
  const ns_entry *n = e->kind == BG_EX_NAME ? bg_build_lookup(b, e->str) : NULL;
  int ref = n && n->kind == NS_ELEM && bg_elem_is_source(m->elem_kind[n->id]) ? n->id
            : n && n->kind == NS_INPUT ? -1 - n->id : -2000000000;
  if (ref == -2000000000) {
    bg_diag_error(b->dg, e->loc, "'%s' is not a source (Se, Sf, MSe, MSf) or an input: "
                  "linearise inputs are sources and inputs", e->text ? e->text : "?");
    return;
  }
  for (int k = 0; k < m->nlininput; k++)
    if (m->lininput_ref[k] == ref) {
      bg_diag_error(b->dg, e->loc, "input '%s' named twice", e->str);
      return;
    }
  int k = bg_build_new(b, &m->nlininput); /* may move the array */
  m->lininput_ref[k] = ref;
}

/* linearise [at = initial | steady, inputs = (U, ...), t = T, w_min, w_max, t_end] */
static void st_linearise(bg_build *b, const bg_ast_stmt *s) {
  bg_linspec *l = &b->m->linear;
  bg_build_check_options(b, s, "at, inputs, t, w_min, w_max, t_end", "linearise");
  l->present = 1;
  l->loc = s->loc;
  const char *at = bg_build_word_opt(b, s, "at", "initial, steady");
  l->steady = at && strcmp(at, "steady") == 0;
  l->t_given = bg_build_find_opt(s, "t") != NULL;
  l->t = bg_build_num_opt(b, s, "t", 0);
  l->w_min = bg_build_num_opt(b, s, "w_min", 0);
  l->w_max = bg_build_num_opt(b, s, "w_max", 0);
  l->t_end = bg_build_num_opt(b, s, "t_end", 0);
  static const char *const positive[] = {"w_min", "w_max", "t_end"};
  const double vals[] = {l->w_min, l->w_max, l->t_end};
  for (int i = 0; i < 3; i++)
    if (bg_build_find_opt(s, positive[i]) && !(vals[i] > 0 && isfinite(vals[i])))
      bg_diag_error(b->dg, bg_build_find_opt(s, positive[i])->value->loc, "%s must be a positive finite "
                    "number, not %g", positive[i], isnan(vals[i]) ? NAN : vals[i]); /* not -nan */
  if (l->w_min > 0 && l->w_max > 0 && !(l->w_max > l->w_min))
    bg_diag_error(b->dg, bg_build_find_opt(s, "w_max")->value->loc, "w_max (%g) must be greater than "
                  "w_min (%g)", l->w_max, l->w_min);
  else if (isfinite(l->w_min) && isfinite(l->w_max) && l->w_min > 0 && l->w_max / l->w_min > BG_LIN_MAX_RANGE)
    bg_diag_error(b->dg, bg_build_find_opt(s, "w_max")->value->loc, "w_max / w_min (%g / %g) spans more "
                  "than %d decades, the limit of a frequency response", l->w_max, l->w_min,
                  BG_LIN_MAX_DECADES);
  const bg_ast_option *in = bg_build_find_opt(s, "inputs");
  if (!in) return;
  l->inputs_given = 1;
  if (in->value->kind == BG_EX_TUPLE)
    for (int i = 0; i < in->value->nargs; i++) lin_input(b, in->value->args[i]);
  else lin_input(b, in->value);
}

/* study sweep|vary|draws|collect (docs/format.md, "study"): the parser
 * checked the words' form; here the params are the model's, a study is a
 * sweep or a Monte Carlo draw, and nothing is given twice. */
static void st_study(bg_build *b, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  char kind = !strcmp(s->name, "sweep") ? 's' : !strcmp(s->name, "vary") ? 'v'
            : !strcmp(s->name, "collect") ? 'c' : 'd';
  for (int i = 0; i < s->nitems; i++) {
    const char *w = s->items[i].name;
    bg_srcloc loc = s->items[i].loc;
    char k = kind == 'd' && !strncmp(w, "seed=", 5) ? 'e' : kind;
    if (k == 's' || k == 'v') {
      size_t len = strcspn(w, "=");
      char name[256];
      snprintf(name, sizeof name, "%.*s", (int)(len < 255 ? len : 255), w);
      const ns_entry *n = bg_build_lookup(b, name);
      if (!n || n->kind != NS_PARAM) {
        const char *near = NULL;
        int bestd = 3;
        for (int p = 0; p < m->nparam; p++) {
          int d = bg_edit_distance(m->param_name[p], name);
          if (d < bestd) bestd = d, near = m->param_name[p];
        }
        bg_diag_error(b->dg, loc, "study %s: '%s' is not a param of the model%s%s%s", s->name, name,
                      near ? " (did you mean '" : "", near ? near : "", near ? "'?)" : "");
        continue;
      }
    }
    for (int j = 0; j < m->nstudy; j++) {
      char kj = (char)m->study_kind[j];
      const char *wj = m->study_word[j];
      size_t lj = strcspn(wj, "="), li = strcspn(w, "=");
      if ((k == 's' || k == 'v') && (kj == 's' || kj == 'v') && kj != k) {
        bg_diag_error(b->dg, loc, "a study is a sweep or a Monte Carlo draw: 'study %s' after "
                      "'study %s' (line %d)", s->name, kj == 's' ? "sweep" : "vary", m->study_loc[j].line);
        return;
      }
      if (kj == k && k != 'c' && lj == li && !strncmp(wj, w, li)) {
        bg_diag_error(b->dg, loc, "%s '%.*s' is already given at line %d", k == 's' || k == 'v'
                      ? "the param" : "study", (int)li, w, m->study_loc[j].line);
        return;
      }
      if (k == 'c' && kj == 'c' && !strcmp(wj, w)) {
        bg_diag_error(b->dg, loc, "'%s' is already collected at line %d", w, m->study_loc[j].line);
        return;
      }
    }
    int at = bg_build_new(b, &m->nstudy);
    m->study_kind[at] = k;
    m->study_word[at] = bg_build_strdup(b, w);
    m->study_loc[at] = loc;
  }
}

/* src/study's limit (BG_STUDY_MAX_RUNS; the model stage comes before it) */
enum { BG_MODEL_STUDY_MAX_RUNS = 1000000 };

/* The study as a whole: draws and vary go together, a seed only with them,
 * and the grid is within the study's limit. */
static void study_whole(bg_build *b) {
  const bg_model *m = b->m;
  int first[128] = {0}, seen[128] = {0};
  for (int j = m->nstudy - 1; j >= 0; j--) seen[m->study_kind[j]] = 1, first[m->study_kind[j]] = j;
  if (seen['v'] && !seen['d'])
    bg_diag_error(b->dg, m->study_loc[first['v']], "a Monte Carlo study needs the number of runs: "
                  "add 'study draws = N'");
  if (seen['d'] && !seen['v'])
    bg_diag_error(b->dg, m->study_loc[first['d']], "'study draws' without 'study vary NAME = DIST' "
                  "draws nothing");
  double grid = 1; /* the grid's size: the product of the sweeps' counts */
  for (int j = 0; j < m->nstudy; j++) {
    if (m->study_kind[j] != 's') continue;
    const char *v = strchr(m->study_word[j], '=') + 1, *c1 = strchr(v, ':');
    double count = 1;
    if (c1) count = strtod(strchr(c1 + 1, ':') + 1, NULL); /* FROM:TO:COUNT[:log] */
    else for (; *v; v++) count += *v == ',';
    grid *= count;
    if (grid > BG_MODEL_STUDY_MAX_RUNS) {
      bg_diag_error(b->dg, m->study_loc[j], "the study's grid has more than %d runs (the sweeps' "
                    "counts multiply)", BG_MODEL_STUDY_MAX_RUNS);
      break;
    }
  }
  if (seen['e'] && !seen['v'])
    bg_diag_error(b->dg, m->study_loc[first['e']], "a seed belongs to a Monte Carlo study, not to a sweep");
}

void bg_build_statements(bg_build *b) {
  const bg_ast_stmt *model = NULL, *caus = NULL, *sim = NULL, *layout = NULL, *lin = NULL;
  int bond = 0;
  for (int i = 0; i < b->ast->nstmts; i++) {
    const bg_ast_stmt *s = &b->ast->stmts[i];
    switch (s->kind) {
    case BG_ST_MODEL: if (once(b, s, &model, "model")) st_model(b, s); break;
    case BG_ST_CAUSALITY: if (once(b, s, &caus, "causality")) st_causality(b, s); break;
    case BG_ST_SIMULATE: if (once(b, s, &sim, "simulate")) st_simulate(b, s); break;
    case BG_ST_LAYOUT: if (once(b, s, &layout, "layout")) st_layout(b, s); break;
    case BG_ST_PLOT: st_plot(b, s); break;
    case BG_ST_OUTPUT: st_output(b, s); break;
    case BG_ST_ELEMENT: if (bg_build_is_detector(s)) bg_build_detector_output(b, s); break;
    case BG_ST_LINEARISE: if (once(b, s, &lin, "linearise")) st_linearise(b, s); break;
    case BG_ST_STATE: st_state(b, s); break;
    case BG_ST_BOND: st_bond(b, s, bond++); break;
    case BG_ST_STUDY: st_study(b, s); break;
    default: break;
    }
  }
  study_whole(b);
}
