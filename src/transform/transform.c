/* The transformations' driver: the names, the shared look-ups, and the
 * check of the new model (parsed, compiled, given causality and analysed)
 * before it is handed back; docs/transform.md. */
#include <stdlib.h>
#include <string.h>

#include "analysis/analysis.h"
#include "causality/causality.h"
#include "lang/lang.h"
#include "transform/tx_int.h"

static const struct {
  const char *name;
  int (*run)(tx_ctx *);
} transforms[] = {
    {"merge-stores", tx_merge_stores},
    {"parasitic", tx_parasitic},
    {"relax-junction", tx_relax_junction},
};
enum { NTRANSFORM = sizeof transforms / sizeof *transforms };

int bg_transform_known(const char *name) {
  for (int i = 0; i < NTRANSFORM; i++)
    if (!strcmp(name, transforms[i].name)) return 1;
  return 0;
}

const char *bg_transform_names(void) { return "merge-stores, parasitic, relax-junction"; }

const bg_ast_stmt *tx_elem_stmt(const tx_ctx *c, int e) {
  const bg_ast *ast = c->in->ast;
  for (int i = 0; i < ast->nstmts; i++)
    if (ast->stmts[i].kind == BG_ST_ELEMENT && !strcmp(ast->stmts[i].name, c->m->elem_name[e]))
      return &ast->stmts[i];
  BG_FATAL("element %s has no statement", c->m->elem_name[e]);
}

/* A version 1 model keeps its bonds in file order (docs/format.md). */
const bg_ast_stmt *tx_bond_stmt(const tx_ctx *c, int b) {
  const bg_ast *ast = c->in->ast;
  for (int i = 0, k = 0; i < ast->nstmts; i++)
    if (ast->stmts[i].kind == BG_ST_BOND && k++ == b) return &ast->stmts[i];
  BG_FATAL("bond %d has no statement", b);
}

int tx_elem_line(const tx_ctx *c, int e) { return tx_elem_stmt(c, e)->loc.line; }
int tx_bond_line(const tx_ctx *c, int b) { return tx_bond_stmt(c, b)->loc.line; }

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

void tx_number_bonds(tx_ctx *c) {
  if (c->bonds_numbered) return;
  c->bonds_numbered = 1;
  for (int b = 0; b < c->m->nbond; b++) {
    const bg_ast_stmt *s = tx_bond_stmt(c, b);
    if (s->number) continue;
    bg_strbuf t = {0};
    tx_print_bond(&t, c->m->bond_num[b], s->from, s->arrow, s->to, s);
    tx_replace_stmt(&c->doc, s->loc.line, bg_sb_str(&t));
    bg_sb_free(&t);
  }
}

void tx_split_bond(const tx_ctx *c, tx_doc *d, int b, const char *j, int number) {
  const bg_ast_stmt *s = tx_bond_stmt(c, b);
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
  tx_number_bonds(c); /* unnumbered bonds after it would take other numbers */
  tx_delete_stmt(&c->doc, tx_bond_line(c, b));
}

/* The header comment: the transformation, the source, and why, wrapped. */
static void write_header(tx_ctx *c) {
  bg_strbuf *h = &c->doc.head;
  const char *base = strrchr(c->in->path, '/');
  bg_sb_printf(h, "# Transformed by bgdraw --transform %s from %s.\n", c->in->name,
               base ? base + 1 : c->in->path);
  const char *s = bg_sb_str(&c->why);
  while (*s) {
    while (*s == ' ') s++;
    int n = (int)strlen(s), cut = n;
    if (n > 76) {
      cut = 76;
      while (cut > 0 && s[cut] != ' ') cut--;
      if (cut == 0) cut = n;
    }
    bg_sb_puts(h, "# ");
    bg_sb_putn(h, s, (size_t)cut);
    bg_sb_putc(h, '\n');
    s += cut;
  }
}

int tx_compile(const tx_ctx *c, const char *text, bg_model **m, bg_analysis *a, char **why) {
  bg_diags dg;
  size_t len = strlen(text);
  bg_diags_init(&dg, c->in->path, text, len);
  bg_ast *ast = bg_parse_string(c->in->path, text, len, &dg);
  *m = NULL;
  if (ast && !dg.nerrors) *m = bg_model_compile(ast, c->in->sets, c->in->nsets, &dg);
  if (ast) bg_ast_free(ast);
  if (!*m || dg.nerrors) {
    bg_strbuf b = {0};
    bg_sb_printf(&b, "internal error: the transformed model does not compile (line %d: %s)",
                 dg.n ? dg.items[0].loc.line : 0, dg.n ? dg.items[0].msg : "?");
    *why = strdup(bg_sb_str(&b));
    bg_sb_free(&b);
    bg_diags_free(&dg);
    if (*m) bg_model_free(*m);
    *m = NULL;
    return -1;
  }
  bg_analysis_init(a, *m);
  bg_causality_assign(*m, (*m)->method, a, &dg);
  bg_analysis_run(*m, a, NULL);
  bg_diags_free(&dg);
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

int tx_last_bond_line(const tx_ctx *c) { return tx_bond_line(c, c->m->nbond - 1); }

double tx_estimate_scale(const bg_analysis *a, int k) {
  return a->estimate_kind[k] == 0 ? a->estimate_value[k] : 1 / a->estimate_value[k];
}

/* The new text compiled and analysed into out. */
static int check_result(tx_ctx *c, bg_transform_result *out, char **why) {
  if (tx_compile(c, out->text, &out->model, &out->analysis, why) != 0) return -1;
  out->analysed = 1;
  return 0;
}

int bg_transform_apply(const bg_transform_input *in, bg_transform_result *out, char **why) {
  memset(out, 0, sizeof *out);
  *why = NULL;
  int k = 0;
  while (k < NTRANSFORM && strcmp(in->name, transforms[k].name)) k++;
  if (k == NTRANSFORM) BG_FATAL("unknown transformation %s", in->name);
  if (in->ast->has_components) {
    *why = strdup("the model has submodels: transformations edit models without components "
                  "(version 1) only");
    return -1;
  }
  tx_ctx c;
  memset(&c, 0, sizeof c);
  c.in = in;
  c.m = in->model;
  c.a = in->analysis;
  c.method = -1;
  for (int b = 0; b < c.m->nbond; b++)
    if (c.m->bond_num[b] >= c.next_bond) c.next_bond = c.m->bond_num[b] + 1;
  tx_doc_init(&c.doc, in->src, in->srclen);
  int rc = transforms[k].run(&c);
  if (rc == 0) {
    write_header(&c);
    out->text = tx_doc_text(&c.doc);
    out->summary = strdup(bg_sb_str(&c.why));
    rc = check_result(&c, out, why);
  } else {
    *why = strdup(bg_sb_str(&c.problem));
  }
  tx_doc_free(&c.doc);
  bg_sb_free(&c.why);
  bg_sb_free(&c.problem);
  if (rc) bg_transform_result_free(out);
  return rc;
}

void bg_transform_result_free(bg_transform_result *r) {
  free(r->text);
  free(r->summary);
  if (r->analysed) bg_analysis_free(&r->analysis);
  if (r->model) bg_model_free(r->model);
  memset(r, 0, sizeof *r);
}
