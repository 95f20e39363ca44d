/* SPDX-License-Identifier: BSD-3-Clause */
/* What the transformations (tx_merge.c, tx_parasitic.c, tx_relax.c,
 * tx_virtual.c) share, under the driver (transform.c): the statements of
 * elements and bonds, constant expressions, fresh names, bond edits, and a
 * new text compiled and analysed. */
#include <stdlib.h>
#include <string.h>

#include "analysis/analysis.h"
#include "causality/causality.h"
#include "lang/lang.h"
#include "transform/tx_int.h"

const bg_ast_stmt *tx_elem_stmt(const tx_ctx *c, int e) {
  const bg_ast *ast = c->in->ast;
  for (int i = 0; i < ast->nstmts; i++)
    if (ast->stmts[i].kind == BG_ST_ELEMENT && !strcmp(ast->stmts[i].name, c->m->elem_name[e]))
      return &ast->stmts[i];
  BG_FATAL("element %s has no statement", c->m->elem_name[e]);
}

/* A version 1 model keeps its bonds in file order (docs/format.md). */
static const bg_ast_stmt *bond_stmt(const tx_ctx *c, int b) {
  const bg_ast *ast = c->in->ast;
  for (int i = 0, k = 0; i < ast->nstmts; i++)
    if (ast->stmts[i].kind == BG_ST_BOND && k++ == b) return &ast->stmts[i];
  BG_FATAL("bond %d has no statement", b);
}

int tx_elem_line(const tx_ctx *c, int e) { return tx_elem_stmt(c, e)->loc.line; }
static int bond_line(const tx_ctx *c, int b) { return bond_stmt(c, b)->loc.line; }

int tx_expr_constant(const bg_model *m, int x) {
  if (x < 0) return 1;
  const bg_xnode *n = &m->xnode[x];
  switch (n->op) {
  case BG_X_TIME: case BG_X_INPUT: case BG_X_STATE: case BG_X_EFFORT: case BG_X_FLOW:
  case BG_X_STORE: case BG_X_TABLE:
    return 0;
  default: break;
  }
  for (int i = 0; i < n->nargs; i++)
    if (!tx_expr_constant(m, n->arg[i])) return 0;
  return 1;
}

static int name_taken(const tx_ctx *c, const char *s) {
  const bg_model *m = c->m;
  if (bg_model_find_elem(m, s) >= 0) return 1;
  for (int i = 0; i < m->nparam; i++) if (!strcmp(m->param_name[i], s)) return 1;
  for (int i = 0; i < m->ninput; i++) if (!strcmp(m->input_name[i], s)) return 1;
  for (int i = 0; i < m->nstate; i++) if (!strcmp(m->state_name[i], s)) return 1;
  for (int i = 0; i < m->noutput; i++) if (!strcmp(m->output_name[i], s)) return 1;
  for (int i = 0; i < c->nmade; i++) if (!strcmp(c->made[i], s)) return 1;
  return 0;
}

const char *tx_fresh_name(tx_ctx *c, const char *base, char *buf, size_t n) {
  snprintf(buf, n, "%s", base);
  for (int k = 2; name_taken(c, buf); k++) snprintf(buf, n, "%s_%d", base, k);
  if (c->nmade < (int)(sizeof c->made / sizeof *c->made))
    snprintf(c->made[c->nmade++], sizeof c->made[0], "%s", buf);
  return buf;
}

/* Writes every unnumbered bond's number, so that removing a bond renumbers nothing. */
static void number_bonds(tx_ctx *c) {
  if (c->bonds_numbered) return;
  c->bonds_numbered = 1;
  for (int b = 0; b < c->m->nbond; b++) {
    const bg_ast_stmt *s = bond_stmt(c, b);
    if (s->number) continue;
    bg_strbuf t = {0};
    tx_print_bond(&t, c->m->bond_num[b], s->from, s->arrow, s->to, s);
    tx_replace_stmt(&c->doc, s->loc.line, bg_sb_str(&t));
    bg_sb_free(&t);
  }
}

void tx_split_bond(const tx_ctx *c, tx_doc *d, int b, const char *j, int number) {
  const bg_ast_stmt *s = bond_stmt(c, b);
  bg_strbuf t = {0};
  tx_print_bond(&t, c->m->bond_num[b], s->from,
                s->arrow == BG_ARROW_STROKE_TAIL ? BG_ARROW_STROKE_TAIL : BG_ARROW_PLAIN, j, s);
  tx_replace_stmt(d, s->loc.line, bg_sb_str(&t));
  bg_sb_clear(&t);
  tx_print_bond(&t, number, j, s->arrow == BG_ARROW_STROKE_HEAD ? BG_ARROW_STROKE_HEAD
                : BG_ARROW_PLAIN, s->to, NULL);
  tx_insert_after(d, s->loc.line, bg_sb_str(&t));
  bg_sb_free(&t);
}

void tx_remove_bond(tx_ctx *c, int b) {
  number_bonds(c); /* unnumbered bonds after it would take other numbers */
  tx_delete_stmt(&c->doc, bond_line(c, b));
}

int tx_compile(const tx_ctx *c, const char *text, bg_run **out, char **why) {
  bg_run_opts o;
  bg_run_opts_init(&o);
  o.sets = c->in->sets, o.nsets = c->in->nsets;
  bg_run *r = bg_run_new(&o);
  *out = NULL;
  if (bg_run_load_string(r, c->in->path, text) != 0) {
    const bg_diags *dg = &r->dg;
    bg_strbuf b = {0};
    bg_sb_printf(&b, "internal error: the transformed model does not compile (line %d: %s)",
                 dg->n ? dg->items[0].loc.line : 0, dg->n ? dg->items[0].msg : "?");
    *why = strdup(bg_sb_str(&b));
    bg_sb_free(&b);
    bg_run_free(r);
    return -1;
  }
  bg_run_need(r, BG_STAGE_ANALYSIS); /* the model's own causality method */
  *out = r;
  return 0;
}

int tx_param_line(const tx_ctx *c) {
  int line = 0;
  const bg_ast *ast = c->in->ast;
  for (int i = 0; i < ast->nstmts; i++)
    if (ast->stmts[i].kind == BG_ST_PARAM || (ast->stmts[i].kind == BG_ST_MODEL && !line))
      line = ast->stmts[i].loc.line;
  return line;
}

int tx_last_bond_line(const tx_ctx *c) { return bond_line(c, c->m->nbond - 1); }

double tx_estimate_scale(const bg_analysis *a, int k) {
  return a->estimate_kind[k] == 0 ? a->estimate_value[k] : 1 / a->estimate_value[k];
}
