/* SPDX-License-Identifier: BSD-3-Clause */
/* Effort and flow detectors (docs/format.md, "Detectors"): `De NAME = NODE`
 * names the effort of a 0-junction or a one-port, `Df NAME = NODE` the flow of
 * a 1-junction or a one-port. A detector has no bond and carries no power: it
 * changes no causality and no equation. Its name reads that variable in any
 * expression (plots, hence CSV columns and plot panels) and it is one output
 * of the linear analysis. */
#include <string.h>

#include "lang/lang.h"
#include "model/model_int.h"

int bg_build_is_detector(const bg_ast_stmt *s) { return bg_ast_is_detector(s); }

void bg_build_declare_detector(bg_build *b, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  if (bg_build_declare(b, s->name, s->name_loc, NS_DETECTOR, m->ndet) != 0) return;
  int k = bg_build_new(b, &m->ndet);
  m->det_name[k] = bg_build_strdup(b, s->name);
  m->det_var[k] = s->kindword[1] == 'e' ? 'e' : 'f';
  m->det_node[k] = m->det_expr[k] = -1;
  m->det_loc[k] = s->name_loc;
}

/* The node a detector reads: its value names one (M1.jw in a composed model
 * is written as a dotted path). */
static const char *node_name(bg_build *b, const bg_expr *e, char *buf, size_t n) {
  (void)b;
  if (e->kind == BG_EX_NAME) return e->str;
  if (e->kind != BG_EX_FIELD || strlen(e->str) + strlen(e->field) + 2 > n) return NULL;
  strcpy(buf, e->str);
  strcat(buf, ".");
  strcat(buf, e->field);
  return buf;
}

static void resolve(bg_build *b, const bg_ast_stmt *s, int k) {
  bg_model *m = b->m;
  const char *kw = s->kindword;
  int var = m->det_var[k];
  if (!s->expr || s->has_law) {
    bg_diag_error(b->dg, s->has_law ? s->law_loc : s->name_loc, "%s %s needs the node it reads: "
                  "'%s %s = NODE'", kw, s->name, kw, s->name);
    return;
  }
  char buf[512];
  const char *name = node_name(b, s->expr, buf, sizeof buf);
  const ns_entry *n = name ? bg_build_lookup(b, name) : NULL;
  const char *guess = name && !n ? bg_build_suggest(b, name, NULL, 0) : NULL;
  const ns_entry *g = guess ? bg_build_lookup(b, guess) : NULL;
  if (!n && bg_diags_unsure(b->dg, name)) return; /* declared on a dropped line? */
  if (g && g->kind == NS_ELEM) {
    bg_diag_error(b->dg, s->expr->loc, "undefined name '%s' (did you mean '%s'?)", name, guess);
    return;
  }
  if (!n || n->kind != NS_ELEM) {
    bg_diag_error(b->dg, s->expr->loc, "%s %s reads a node: write the name of a %s or a one-port "
                  "element, not '%s'", kw, s->name, var == 'e' ? "0-junction" : "1-junction",
                  s->expr->text);
    return;
  }
  int kind = m->elem_kind[n->id];
  int ok = bg_elem_is_oneport(kind) || kind == (var == 'e' ? BG_ELEM_J0 : BG_ELEM_J1);
  if (!ok) {
    bg_diag_error(b->dg, s->expr->loc, "%s %s cannot read '%s': %s has no single %s (a %s reads "
                  "a %s or a one-port)", kw, s->name, name, bg_elem_kind_article(kind),
                  var == 'e' ? "effort" : "flow", kw, var == 'e' ? "0-junction" : "1-junction");
    return;
  }
  if (s->nopts)
    bg_diag_error(b->dg, s->opts[0].loc, "unknown option '%s' for %s '%s' (a detector takes none)",
                  s->opts[0].key, kw, s->name);
  m->det_node[k] = n->id;
}

void bg_build_detectors(bg_build *b) {
  for (int i = 0; i < b->ast->nstmts; i++) {
    const bg_ast_stmt *s = &b->ast->stmts[i];
    if (!bg_build_is_detector(s)) continue;
    const ns_entry *n = bg_build_lookup(b, s->name);
    if (n && n->kind == NS_DETECTOR && n->loc.line == s->name_loc.line &&
        n->loc.col == s->name_loc.col && n->loc.file == s->name_loc.file)
      resolve(b, s, n->id);
  }
}

void bg_build_detector_output(bg_build *b, const bg_ast_stmt *s) {
  bg_model *m = b->m;
  const ns_entry *n = bg_build_lookup(b, s->name);
  if (!n || n->kind != NS_DETECTOR || n->loc.line != s->name_loc.line ||
      m->det_node[n->id] < 0)
    return;
  bg_expr name = {0};
  name.kind = BG_EX_NAME;
  name.str = s->name;
  name.loc = s->name_loc;
  b->allow = ALLOW_TIME | ALLOW_INPUT | ALLOW_MODEL;
  b->input_limit = m->ninput;
  b->what = "a detector";
  b->elem = b->law_elem = -1;
  int root = bg_build_expr(b, &name);
  int k = bg_build_new(b, &m->noutput);
  m->output_name[k] = bg_build_strdup(b, s->name);
  m->output_expr[k] = root;
  m->output_det[k] = n->id;
  m->det_expr[n->id] = root;
  m->output_loc[k] = s->name_loc;
}
