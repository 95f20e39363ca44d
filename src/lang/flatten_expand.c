/* SPDX-License-Identifier: BSD-3-Clause */
/* The flattener, part 2: expanding instances. Each statement of a scope is
 * copied into the flat AST with its names qualified by the instance path
 * (Ra in instance M1 becomes M1.Ra) and its positions moved into the
 * instance's diagnostics source (so messages carry the instance chain).
 * Bonds become segments, joined into flat bonds by flatten_bonds.c. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "base/log.h"
#include "lang/flatten_int.h"

enum { MAX_INSTANCE_DEPTH = 100 };

/* One scope being expanded: the model itself or one instance. */
typedef struct fl_scopectx {
  fl_flattener *f;
  int def, inst;        /* inst -1: the model */
  const char *prefix;   /* "" or the instance path */
  int src;              /* diagnostics source of positions */
  int depth;
  long next_offset;     /* bond offset of the scope's next instance */
  int *stmt_inst;       /* per statement of the def: the instance it made, -1 */
  int *bond_seg;        /* per statement: its segment, -1 */
  int law;              /* rewriting an element law: e, f, q, p are its own */
  const bg_ast_stmt *field; /* rewriting a multiport field's laws: its port variables
                               (e1, q2, el.e) are its own, not the scope's names */
} fl_scopectx;

/* e1, f2, q3: a numbered port's variable in a field's law */
static int port_var_name(const char *s) {
  if (!strchr("efq", s[0]) || !s[0] || !s[1]) return 0;
  for (const char *p = s + 1; *p; p++)
    if (!isdigit((unsigned char)*p)) return 0;
  return 1;
}

/* el.e in a field's law: the head names one of the field's ports. */
static int field_port_path(const fl_scopectx *c, const char *path) {
  size_t n = strcspn(path, ".");
  for (int k = 0; c->field && k < c->field->nitems; k++)
    if (strlen(c->field->items[k].name) == n && !strncmp(c->field->items[k].name, path, n)) return 1;
  return 0;
}

static fl_def *ctx_def(const fl_scopectx *c) { return &c->f->defs[c->def]; }
static int in_model(const fl_scopectx *c) { return c->inst < 0; }

static bg_srcloc moved(const fl_scopectx *c, bg_srcloc l) {
  l.file = c->src;
  return l;
}

/* e7, f12 */
static int bond_var_number(const char *s) {
  if ((s[0] != 'e' && s[0] != 'f') || !s[1]) return 0;
  for (const char *p = s + 1; *p; p++)
    if (!isdigit((unsigned char)*p) || p - s > 9) return 0;
  return atoi(s + 1);
}

static const char *const kind_words[] = {"an element", "a param", "an input", "a state",
                                         "an instance", "a port", "a parameter"};

/* ---------------------------------------------------------------- expressions */
static bg_expr *rewrite(fl_scopectx *c, const bg_expr *e);

static void rewrite_name(fl_scopectx *c, bg_expr *x) {
  fl_flattener *f = c->f;
  if (in_model(c) || !strcmp(x->str, "t") || !strcmp(x->str, "pi")) return;
  if (c->law && strchr("efqp", x->str[0]) && !x->str[1]) return;
  if (c->field && port_var_name(x->str)) return;
  int num = bond_var_number(x->str);
  if (num > 0) {
    *FL_PUSH(f->bondvars, f->nbondvars) = (fl_bondvar){x, c->inst, num};
    return;
  }
  const sc_entry *n = bg_fl_lookup(&ctx_def(c)->names, x->str);
  if (n && (n->kind == SC_INST || n->kind == SC_PORT)) {
    bg_diag_error(f->dg, x->loc, "'%s' is %s; name a variable of an element instead%s", x->str,
                  kind_words[n->kind], n->kind == SC_INST ? " (e.g. M1.R1.e)" : "");
    return;
  }
  if (!n) {
    if (bg_diags_unsure(f->dg, x->str)) return; /* declared on a dropped line? */
    const char *s = bg_fl_suggest(&ctx_def(c)->names, x->str, ~(1u << SC_PORT));
    bg_diag_error(f->dg, x->loc, "undefined name '%s' in submodel %s%s%s%s", x->str,
                  ctx_def(c)->name, s ? " (did you mean '" : "", s ? s : "", s ? "'?)" : "");
    return;
  }
  x->str = bg_fl_join(f, c->prefix, x->str);
}

/* The first part of a dotted path, looked up in the scope. */
static const sc_entry *path_head(const fl_scopectx *c, const char *path) {
  char head[256];
  size_t n = strcspn(path, ".");
  if (n >= sizeof head) return NULL;
  memcpy(head, path, n);
  head[n] = '\0';
  return bg_fl_lookup(&ctx_def(c)->names, head);
}

/* X.e, M1.La.p, M1.K: qualified; a path into an instance may name a param
 * (M1.K), which is decided once every flat name is known. */
static void rewrite_field(fl_scopectx *c, bg_expr *x) {
  fl_flattener *f = c->f;
  if (field_port_path(c, x->str)) return; /* a port of the field whose law this is */
  const sc_entry *n = path_head(c, x->str);
  if (n && n->kind == SC_INST) *FL_PUSH(f->fields, f->nfields) = x;
  if (in_model(c)) return;
  if (!n) {
    if (bg_diags_unsure(f->dg, x->str)) return;
    const char *s = bg_fl_suggest(&ctx_def(c)->names, x->str, 1u << SC_ELEM | 1u << SC_INST);
    bg_diag_error(f->dg, x->loc, "undefined name '%s' in submodel %s%s%s%s", x->str,
                  ctx_def(c)->name, s ? " (did you mean '" : "", s ? s : "", s ? "'?)" : "");
    return;
  }
  x->str = bg_fl_join(f, c->prefix, x->str);
}

/* table(x, "file.csv") in a used file: the file is found beside that file. */
static void rewrite_table_file(fl_scopectx *c, bg_expr *x) {
  const char *dir = c->f->files[ctx_def(c)->file].dir_rel;
  if (strcmp(x->str, "table") != 0 || x->nargs != 2 || x->args[1]->kind != BG_EX_STR) return;
  const char *file = x->args[1]->str;
  if (file[0] == '/' || strcmp(dir, ".") == 0) return;
  x->args[1]->str = bg_fl_join(c->f, dir, file);
  ((char *)x->args[1]->str)[strlen(dir)] = '/';
}

static bg_expr *rewrite(fl_scopectx *c, const bg_expr *e) {
  if (!e) return NULL;
  fl_flattener *f = c->f;
  bg_expr *x = bg_arena_alloc(&f->out->arena, sizeof *x);
  *x = *e;
  x->loc = moved(c, e->loc);
  x->field_loc = moved(c, e->field_loc);
  x->str = bg_fl_strdup(f, e->str);
  x->field = bg_fl_strdup(f, e->field);
  x->text = bg_fl_strdup(f, e->text);
  if (e->nargs) {
    x->args = bg_arena_alloc(&f->out->arena, (size_t)e->nargs * sizeof *x->args);
    for (int i = 0; i < e->nargs; i++) x->args[i] = rewrite(c, e->args[i]);
  }
  if (x->kind == BG_EX_NAME) rewrite_name(c, x);
  else if (x->kind == BG_EX_FIELD) rewrite_field(c, x);
  else if (x->kind == BG_EX_CALL) rewrite_table_file(c, x);
  return x;
}

/* ---------------------------------------------------------------- statements */
static int emit(fl_flattener *f, const bg_ast_stmt *s, int inst) {
  int k = f->nstmts;
  *FL_PUSH(f->stmts, f->nstmts) = *s;
  if ((k & (k - 1)) == 0) /* grown with f->stmts: 0, 1, 2, 4, ... */
    f->stmt_inst = bg_xrealloc(f->stmt_inst, (size_t)(k ? 2 * k : 1) * sizeof *f->stmt_inst);
  f->stmt_inst[k] = inst;
  if (f->nstmts >= f->next_progress) {
    bg_logf(f->dg->log, BG_LOG_PROGRESS, "flattening: %d statements, %d instances so far", f->nstmts, f->ninst);
    f->next_progress += 100000;
  }
  return k;
}

/* A field's ports (names as written: they are qualified with the field) and
 * its laws (port variables left as they are, other names qualified). */
static void copy_field(fl_scopectx *c, const bg_ast_stmt *s, bg_ast_stmt *x) {
  fl_flattener *f = c->f;
  x->items = bg_arena_alloc(&f->out->arena, (size_t)(s->nitems ? s->nitems : 1) * sizeof *x->items);
  for (int k = 0; k < s->nitems; k++) {
    x->items[k] = s->items[k];
    x->items[k].name = bg_fl_strdup(f, s->items[k].name);
    x->items[k].loc = moved(c, s->items[k].loc);
  }
  x->nitems = s->nitems;
  x->laws = bg_arena_alloc(&f->out->arena, (size_t)(s->nlaws ? s->nlaws : 1) * sizeof *x->laws);
  c->field = s;
  for (int k = 0; k < s->nlaws; k++) {
    x->laws[k] = s->laws[k];
    x->laws[k].name = bg_fl_strdup(f, s->laws[k].name);
    x->laws[k].loc = moved(c, s->laws[k].loc);
    x->laws[k].value = rewrite(c, s->laws[k].value);
  }
  c->field = NULL;
  x->nlaws = s->nlaws;
}

static bg_ast_stmt copy_stmt(fl_scopectx *c, const bg_ast_stmt *s) {
  fl_flattener *f = c->f;
  bg_ast_stmt x = *s;
  x.loc = moved(c, s->loc);
  x.name_loc = moved(c, s->name_loc);
  x.law_loc = moved(c, s->law_loc);
  x.number_loc = moved(c, s->number_loc);
  x.from_loc = moved(c, s->from_loc);
  x.to_loc = moved(c, s->to_loc);
  x.kindword = bg_fl_strdup(f, s->kindword);
  x.text = bg_fl_strdup(f, s->text);
  x.law_lhs = bg_fl_strdup(f, s->law_lhs);
  if (s->name && s->kind != BG_ST_MODEL && s->kind != BG_ST_CAUSALITY)
    x.name = bg_fl_join(f, c->prefix, s->name);
  c->law = s->kind == BG_ST_ELEMENT && s->has_law;
  x.expr = rewrite(c, s->expr);
  c->law = 0;
  if (s->nexprs) {
    x.exprs = bg_arena_alloc(&f->out->arena, (size_t)s->nexprs * sizeof *x.exprs);
    for (int i = 0; i < s->nexprs; i++) x.exprs[i] = rewrite(c, s->exprs[i]);
  }
  x.opts = bg_arena_alloc(&f->out->arena, (size_t)(s->nopts ? s->nopts : 1) * sizeof *x.opts);
  for (int i = 0; i < s->nopts; i++) {
    x.opts[i].key = bg_fl_strdup(f, s->opts[i].key);
    x.opts[i].loc = moved(c, s->opts[i].loc);
    x.opts[i].value = rewrite(c, s->opts[i].value);
  }
  x.items = NULL;
  x.nitems = 0;
  if (s->is_field) copy_field(c, s, &x);
  return x;
}

static void expand_scope(fl_scopectx *c);

/* The instance's parameters become flat params: the argument (read in the
 * enclosing scope) or the default (read in the submodel). */
static void emit_parameters(fl_scopectx *parent, fl_scopectx *child, const bg_ast_stmt *s) {
  fl_flattener *f = parent->f;
  const fl_def *d = ctx_def(child);
  const bg_ast_stmt *head = d->head;
  const bg_ast_item **given = bg_xcalloc((size_t)head->nitems + 1, sizeof *given);
  for (int i = 0; i < s->nitems; i++) {
    const sc_entry *n = bg_fl_lookup(&d->names, s->items[i].name);
    if ((!n || n->kind != SC_ARG) && bg_diags_unsure(f->dg, s->items[i].name)) continue;
    if (!n || n->kind != SC_ARG) {
      const char *sug = bg_fl_suggest(&d->names, s->items[i].name, 1u << SC_ARG);
      bg_diag_error(f->dg, moved(parent, s->items[i].loc), "submodel %s has no parameter '%s'%s%s%s",
                    d->name, s->items[i].name, sug ? " (did you mean '" : "", sug ? sug : "",
                    sug ? "'?)" : "");
    } else if (given[n->index])
      bg_diag_error(f->dg, moved(parent, s->items[i].loc), "parameter '%s' given twice",
                    s->items[i].name);
    else given[n->index] = &s->items[i];
  }
  for (int i = 0; i < head->nitems; i++) {
    const bg_ast_item *it = &head->items[i];
    bg_ast_stmt p = {0};
    p.kind = BG_ST_PARAM;
    p.name = bg_fl_join(f, child->prefix, it->name);
    p.text = bg_fl_strdup(f, it->text);
    p.loc = p.name_loc = given[i] ? moved(parent, given[i]->loc) : moved(child, it->loc);
    p.expr = given[i] ? rewrite(parent, given[i]->value) : rewrite(child, it->value);
    if (!p.expr) {
      bg_diag_error(f->dg, moved(parent, s->name_loc), "parameter '%s' of %s has no default; give "
                    "it: %s %s(%s = ...)", it->name, d->name, d->name, s->name, it->name);
      continue;
    }
    emit(f, &p, child->inst);
  }
  free(given);
}

/* An instance statement: a new instance, its parameters and its body. */
static void expand_instance(fl_scopectx *c, int k) {
  fl_flattener *f = c->f;
  const bg_ast_stmt *s = ctx_def(c)->stmt[k];
  int di = bg_fl_lookup(&f->defnames, s->kindword)->index; /* checked by bg_fl_span */
  fl_def *d = &f->defs[di];
  if (f->capped) return;
  if (!f->dry && f->nstmts + d->size > BG_FLAT_MAX) {
    if (d->size > BG_FLAT_MAX)
      bg_diag_error(f->dg, moved(c, s->name_loc), "instance %s of %s expands to more than %ld "
                    "statements, the limit of a flat model (a submodel's size multiplies with "
                    "each level of instances)", s->name, d->name, BG_FLAT_MAX);
    else
      bg_diag_error(f->dg, moved(c, s->name_loc), "instance %s of %s (%ld statements) would make "
                    "the flat model larger than the limit of %ld statements (%d before it)",
                    s->name, d->name, d->size, BG_FLAT_MAX, f->nstmts);
    f->capped = 1;
    return;
  }
  if (s->nopts)
    bg_diag_error(f->dg, moved(c, s->opts[0].loc), "unknown option '%s' for instance %s (an "
                  "instance takes no options)", s->opts[0].key, s->name);
  int ii = f->ninst;
  fl_inst *in = FL_PUSH(f->inst, f->ninst);
  in->pub.name = bg_fl_join(f, c->prefix, s->name);
  in->pub.def = bg_fl_strdup(f, d->name);
  in->pub.parent = c->inst;
  in->pub.loc = moved(c, s->name_loc);
  in->pub.bond_offset = (int)c->next_offset;
  in->pub.bond_span = (int)d->span;
  in->def = di;
  in->port_adr = f->nports;
  c->next_offset += d->span;
  for (int p = 0; p < d->nports; p++) {
    fl_port *pt = FL_PUSH(f->ports, f->nports);
    pt->inner = pt->outer = -1;
  }
  char msg[512];
  snprintf(msg, sizeof msg, "in instance %s of %s", in->pub.name, d->name);
  in->src = bg_diags_add_context(f->dg, f->files[d->file].ast->file, in->pub.loc, msg);
  c->stmt_inst[k] = ii;
  fl_scopectx child = {f, di, ii, in->pub.name, in->src, c->depth + 1,
                       in->pub.bond_offset + d->maxnum, NULL, NULL, 0, NULL};
  if (child.depth > MAX_INSTANCE_DEPTH) {
    bg_diag_error(f->dg, in->pub.loc, "instances nested too deeply (more than %d levels)",
                  MAX_INSTANCE_DEPTH);
    return;
  }
  emit_parameters(c, &child, s);
  if (!f->dry) expand_scope(&child);
}

/* A bond statement: a segment with a placeholder slot in the output; its
 * ends are resolved when the scope's instances all exist. */
static void add_segment(fl_scopectx *c, int k, int nbond) {
  fl_flattener *f = c->f;
  const bg_ast_stmt *s = ctx_def(c)->stmt[k];
  bg_ast_stmt x = copy_stmt(c, s);
  int g = f->nsegs;
  fl_seg *seg = FL_PUSH(f->segs, f->nsegs);
  seg->inst = c->inst;
  seg->num = ctx_def(c)->bondnum[nbond];
  seg->flatnum = (c->inst < 0 ? 0 : f->inst[c->inst].pub.bond_offset) + (long)seg->num;
  seg->fix = s->arrow;
  seg->depth = c->depth;
  seg->chain = -1;
  x.kind = (bg_stkind)-1; /* a placeholder until the flat bond is known */
  seg->slot = emit(f, &x, c->inst);
  c->bond_seg[k] = g;
}

/* The end of a bond written `name` in the scope. */
static fl_end resolve_end(fl_scopectx *c, const char *name, bg_srcloc loc, int seg, int is_head);

static void expand_scope(fl_scopectx *c) {
  fl_def *d = ctx_def(c);
  c->stmt_inst = bg_xmalloc((size_t)(d->nstmt + 1) * sizeof *c->stmt_inst);
  c->bond_seg = bg_xmalloc((size_t)(d->nstmt + 1) * sizeof *c->bond_seg);
  int nbond = 0;
  for (int k = 0; k < d->nstmt; k++) {
    const bg_ast_stmt *s = d->stmt[k];
    c->stmt_inst[k] = c->bond_seg[k] = -1;
    if (s->kind == BG_ST_INSTANCE) expand_instance(c, k);
    else if (s->kind == BG_ST_BOND) add_segment(c, k, nbond++);
    else if (s->kind != BG_ST_PORT) {
      bg_ast_stmt x = copy_stmt(c, s);
      emit(c->f, &x, c->inst);
    }
  }
  for (int k = 0; k < d->nstmt && !c->f->capped; k++) { /* capped: the ends may be missing */
    int g = c->bond_seg[k];
    if (g < 0) continue;
    const bg_ast_stmt *s = d->stmt[k];
    fl_end tail = resolve_end(c, s->from, moved(c, s->from_loc), g, 0);
    fl_end head = resolve_end(c, s->to, moved(c, s->to_loc), g, 1);
    c->f->segs[g].end[0] = tail;
    c->f->segs[g].end[1] = head;
  }
  free(c->stmt_inst);
  free(c->bond_seg);
}

/* ---------------------------------------------------------------- bond ends */
static void note_outer(fl_flattener *f, int port, int seg, bg_srcloc loc, const char *inst,
                       const char *pname, int is_head) {
  fl_port *p = &f->ports[port];
  if (p->nouter++ == 0) {
    p->outer = seg;
    p->outer_loc = loc;
    p->outer_is_head = is_head;
    return;
  }
  bg_diag_error(f->dg, loc, "port %s.%s is connected twice (first at line %d); a port takes "
                "one bond (join several with a junction)", inst, pname, p->outer_loc.line);
}

static void note_inner(fl_flattener *f, int port, int seg, bg_srcloc loc, const char *def,
                       const char *pname, int is_head) {
  fl_port *p = &f->ports[port];
  if (p->ninner++ == 0) {
    p->inner = seg;
    p->inner_is_tail = !is_head;
    p->inner_loc = loc;
    return;
  }
  bg_diag_error(f->dg, loc, "port '%s' of %s is joined by a second bond inside the submodel "
                "(the first at line %d); a port is one bond end (join bonds with a junction)",
                pname, def, p->inner_loc.line);
}

/* M1.a: port a of the scope's instance M1 (outside side). */
static fl_end resolve_port(fl_scopectx *c, const char *name, bg_srcloc loc, int seg, int is_head,
                           const sc_entry *n) {
  fl_flattener *f = c->f;
  fl_end end = {NULL, -1, loc};
  const char *pname = name + strcspn(name, ".") + 1;
  int ii = c->stmt_inst[n->index];
  if (ii < 0) return end; /* its expansion failed (reported) */
  const fl_def *d = &f->defs[f->inst[ii].def];
  if (strchr(pname, '.')) {
    bg_diag_error(f->dg, loc, "'%s' reaches inside instance %s; a bond joins only the ports of "
                  "the instances of its own scope", name, f->inst[ii].pub.name);
    return end;
  }
  const sc_entry *p = bg_fl_lookup(&d->names, pname);
  if ((!p || p->kind != SC_PORT) && bg_diags_unsure(f->dg, pname)) return end;
  if (!p || p->kind != SC_PORT) {
    const char *s = bg_fl_suggest(&d->names, pname, 1u << SC_PORT);
    bg_diag_error(f->dg, loc, "unknown port '%s' of %s (%s)%s%s%s", pname, f->inst[ii].pub.name,
                  d->name, s ? "; did you mean '" : "", s ? s : "", s ? "'?" : "");
    return end;
  }
  end.port = f->inst[ii].port_adr + p->index;
  note_outer(f, end.port, seg, loc, f->inst[ii].pub.name, pname, is_head);
  return end;
}

static fl_end resolve_end(fl_scopectx *c, const char *name, bg_srcloc loc, int seg, int is_head) {
  fl_flattener *f = c->f;
  fl_end end = {NULL, -1, loc};
  const sc_entry *n = path_head(c, name);
  if (strchr(name, '.')) {
    if (n && n->kind == SC_INST) return resolve_port(c, name, loc, seg, is_head, n);
    if (n && n->kind == SC_ELEM) { /* K.el: a port of a field (the compiler checks it) */
      end.node = bg_fl_join(f, c->prefix, name);
      return end;
    }
    bg_diag_error(f->dg, loc, "'%.*s' is not an instance; a dotted bond end names a port of an "
                  "instance (M1.a)", (int)strcspn(name, "."), name);
    return end;
  }
  if (n && n->kind == SC_PORT && !in_model(c)) {
    end.port = f->inst[c->inst].port_adr + n->index;
    note_inner(f, end.port, seg, loc, ctx_def(c)->name, name, is_head);
    return end;
  }
  if (n && n->kind == SC_INST) {
    bg_diag_error(f->dg, loc, "'%s' is an instance of %s; a bond joins one of its ports (%s.PORT)",
                  name, ctx_def(c)->stmt[n->index]->kindword, name);
    return end;
  }
  if (!in_model(c) && (!n || n->kind != SC_ELEM)) {
    if (n)
      bg_diag_error(f->dg, loc, "'%s' is %s (line %d); a bond joins elements, junctions and ports",
                    name, kind_words[n->kind], n->loc.line);
    else if (!bg_diags_unsure(f->dg, name)) {
      const char *s = bg_fl_suggest(&ctx_def(c)->names, name, 1u << SC_ELEM | 1u << SC_PORT);
      bg_diag_error(f->dg, loc, "undefined name '%s' in submodel %s%s%s%s", name,
                    ctx_def(c)->name, s ? " (did you mean '" : "", s ? s : "", s ? "'?)" : "");
    }
    return end;
  }
  end.node = bg_fl_join(f, c->prefix, name); /* in the model: the compiler checks it */
  return end;
}

/* The ports of a submodel checked on its own: each joined inside (once:
 * note_inner reports a second bond); nothing outside is asked for. */
static void check_inner_ports(fl_flattener *f, const fl_inst *in) {
  const fl_def *d = &f->defs[in->def];
  for (int p = 0; p < d->nports; p++) {
    const bg_ast_item *it = &d->port_stmt[p]->items[d->port_item[p]];
    if (f->ports[in->port_adr + p].ninner || bg_diags_unsure_bonds(f->dg, it->name)) continue;
    bg_srcloc decl = it->loc;
    decl.file = in->src;
    bg_diag_error(f->dg, decl, "port '%s' of %s has no bond inside the submodel", it->name, d->name);
  }
}

/* Submodel di alone: a stand-in instance whose positions are the
 * submodel's own (no instance chain in its messages); the parameters'
 * defaults are read in its scope, a parameter without one stands for
 * itself. */
static void check_def(fl_flattener *f, int di) {
  fl_def *d = &f->defs[di];
  int ii = f->ninst;
  fl_inst *in = FL_PUSH(f->inst, f->ninst);
  in->pub.name = d->name;
  in->pub.def = d->name;
  in->pub.parent = -1;
  in->pub.loc = d->head->name_loc;
  in->def = di;
  in->src = f->files[d->file].ast->file;
  in->port_adr = f->nports;
  for (int p = 0; p < d->nports; p++) {
    fl_port *pt = FL_PUSH(f->ports, f->nports);
    pt->inner = pt->outer = -1;
  }
  fl_scopectx c = {f, di, ii, "", in->src, 1, d->maxnum, NULL, NULL, 0, NULL}; /* names as written */
  for (int i = 0; i < d->head->nitems; i++) rewrite(&c, d->head->items[i].value);
  expand_scope(&c);
  check_inner_ports(f, &f->inst[ii]);
}

void bg_fl_check_unused(fl_flattener *f) {
  unsigned char *used = bg_xcalloc((size_t)f->ndefs + 1, 1);
  for (int i = 0; i < f->ninst; i++) used[f->inst[i].def] = 1;
  int nstmts = f->nstmts, ninst = f->ninst, nports = f->nports, nsegs = f->nsegs,
      nbondvars = f->nbondvars, nfields = f->nfields;
  f->dry = 1;
  for (int di = 1; di < f->ndefs; di++) {
    if (used[di]) continue;
    check_def(f, di);
    f->nstmts = nstmts, f->ninst = ninst, f->nports = nports, f->nsegs = nsegs;
    f->nbondvars = nbondvars, f->nfields = nfields;
  }
  f->dry = 0;
  free(used);
}

void bg_fl_expand_model(fl_flattener *f, int root) {
  f->next_progress = 100000;
  fl_scopectx c = {f, root, -1, "", f->files[0].ast->file, 0, f->defs[root].maxnum, NULL, NULL, 0, NULL};
  expand_scope(&c);
}
