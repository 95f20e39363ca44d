/* SPDX-License-Identifier: BSD-3-Clause */
/* The flattener, part 1: the driver, used files and submodel definitions
 * (their names, bond numbers and bond spans). Instances and expressions are
 * in flatten_expand.c, ports and flat bonds in flatten_bonds.c, the name
 * tables and growable arrays all three use in flatten_scope.c. */
#undef _POSIX_C_SOURCE
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/fileio.h"
#include "base/strbuf.h"
#include "lang/flatten_int.h"
#include "lang/parse.h"

enum { MAX_USE_DEPTH = 64 };

/* ---------------------------------------------------------------- definitions */
static int def_is_model(const fl_def *d) { return d->head == NULL; }

/* Declares one name of a def. In the model's own scope only clashes with
 * instances are reported here; the model compiler reports the others with
 * its version 1 messages. */
static void def_declare(fl_flattener *f, fl_def *d, const char *name, int kind, int index,
                        bg_srcloc loc) {
  const sc_entry *old = bg_fl_declare(&d->names, name, kind, index, loc);
  if (!old) return;
  if (def_is_model(d) && kind != SC_INST && old->kind != SC_INST) return;
  bg_diag_error(f->dg, loc, "'%s' already defined at line %d", name, old->loc.line);
}

static void def_declare_stmt(fl_flattener *f, fl_def *d, const bg_ast_stmt *s, int k) {
  switch (s->kind) {
  case BG_ST_ELEMENT: def_declare(f, d, s->name, SC_ELEM, k, s->name_loc); break;
  case BG_ST_PARAM: def_declare(f, d, s->name, SC_PARAM, k, s->name_loc); break;
  case BG_ST_INPUT: def_declare(f, d, s->name, SC_INPUT, k, s->name_loc); break;
  case BG_ST_STATE: def_declare(f, d, s->name, SC_STATE, k, s->name_loc); break;
  case BG_ST_INSTANCE: def_declare(f, d, s->name, SC_INST, k, s->name_loc); break;
  case BG_ST_PORT:
    for (int i = 0; i < s->nitems; i++) {
      def_declare(f, d, s->items[i].name, SC_PORT, d->nports, s->items[i].loc);
      *FL_PUSH(d->port_stmt, d->nports) = s;
      d->port_item = bg_xrealloc(d->port_item, (size_t)d->nports * sizeof *d->port_item);
      d->port_item[d->nports - 1] = i;
    }
    break;
  default: break;
  }
}

typedef struct numbered { int num, order; } numbered;

static int cmp_numbered(const void *a, const void *b) {
  const numbered *x = a, *y = b;
  if (x->num != y->num) return x->num < y->num ? -1 : 1;
  return x->order - y->order;
}

/* Bond numbers in the scope as in version 1: explicit numbers unique, the
 * others the smallest free numbers in file order. */
static void number_def_bonds(fl_flattener *f, fl_def *d) {
  const bg_ast_stmt **bonds = NULL;
  int n = 0, nexp = 0;
  for (int i = 0; i < d->nstmt; i++)
    if (d->stmt[i]->kind == BG_ST_BOND) *FL_PUSH(bonds, n) = d->stmt[i];
  numbered *exp = bg_xmalloc((size_t)(n ? n : 1) * sizeof *exp);
  for (int k = 0; k < n; k++)
    if (bonds[k]->number) exp[nexp++] = (numbered){bonds[k]->number, k};
  qsort(exp, (size_t)nexp, sizeof *exp, cmp_numbered);
  for (int i = 1; i < nexp; i++)
    if (exp[i].num == exp[i - 1].num)
      bg_diag_error(f->dg, bonds[exp[i].order]->number_loc, "bond %d already defined at line %d",
                    exp[i].num, bonds[exp[i - 1].order]->loc.line);
  d->bondnum = bg_xmalloc((size_t)(n ? n : 1) * sizeof *d->bondnum);
  int next = 1, e = 0;
  d->maxnum = nexp ? exp[nexp - 1].num : 0;
  for (int k = 0; k < n; k++) {
    if (bonds[k]->number) { d->bondnum[k] = bonds[k]->number; continue; }
    for (;;) { /* skip explicit numbers */
      while (e < nexp && exp[e].num < next) e++;
      if (e < nexp && exp[e].num == next) next++;
      else break;
    }
    d->bondnum[k] = next++;
    if (d->bondnum[k] > d->maxnum) d->maxnum = d->bondnum[k];
  }
  d->nbonds = n;
  free(exp);
  free(bonds);
}

/* Builds the def's scope and numbers its bonds (once); reports mistakes. */
static void def_names(fl_flattener *f, int di) {
  fl_def *d = &f->defs[di];
  if (d->names_built) return;
  d->names_built = 1;
  if (d->head)
    for (int i = 0; i < d->head->nitems; i++)
      def_declare(f, d, d->head->items[i].name, SC_ARG, i, d->head->items[i].loc);
  for (int i = 0; i < d->nstmt; i++) def_declare_stmt(f, d, d->stmt[i], i);
  number_def_bonds(f, d);
}

/* ---------------------------------------------------------------- files */
static const char *dir_part(fl_flattener *f, const char *path) {
  const char *slash = strrchr(path, '/');
  if (!slash) return ".";
  return bg_arena_strndup(&f->out->arena, path, (size_t)(slash - path + (slash == path)));
}

/* "dir/name" unless name is absolute or dir is "." */
static const char *path_in(fl_flattener *f, const char *dir, const char *name) {
  if (name[0] == '/' || strcmp(dir, ".") == 0) return bg_fl_strdup(f, name);
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "%s%s%s", dir, dir[strlen(dir) - 1] == '/' ? "" : "/", name);
  const char *s = bg_fl_strdup(f, bg_sb_str(&sb));
  bg_sb_free(&sb);
  return s;
}

static const char *canonical(fl_flattener *f, const char *path) {
  char *r = realpath(path, NULL);
  const char *k = bg_fl_strdup(f, r ? r : path);
  free(r);
  return k;
}

static void load_file(fl_flattener *f, int fi, int depth);

static void report_use_cycle(fl_flattener *f, int from, int to, bg_srcloc loc) {
  bg_strbuf sb = {0};
  int start = to;
  for (int i = start; i <= from; i++)
    if (f->files[i].loading) bg_sb_printf(&sb, "%s -> ", f->files[i].path);
  bg_sb_puts(&sb, f->files[to].path);
  bg_diag_error(f->dg, loc, "cyclic use: %s", bg_sb_str(&sb));
  bg_sb_free(&sb);
}

static int exists(const char *path) { return access(path, F_OK) == 0; }

/* The "not found" error of `use "NAME"`: every folder looked in, and why. */
static void report_not_found(fl_flattener *f, const bg_ast_stmt *s, const char *own) {
  const bg_ast *root = f->files[0].ast;
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "'%s' (the using file's folder)", own);
  int npath = 0;
  for (const char *const *d = root->use_path; d && *d; d++, npath++)
    bg_sb_printf(&sb, ", '%s'%s", *d, d[1] ? "" : " (BGDRAW_PATH)");
  if (root->use_lib) bg_sb_printf(&sb, ", '%s' (the installed component library)", root->use_lib);
  bg_diag_error(f->dg, s->name_loc, "cannot find used file '%s'; looked in %s%s", s->text,
                bg_sb_str(&sb), npath ? "" : "; BGDRAW_PATH is not set");
  bg_sb_free(&sb);
}

/* The file `use "NAME"` of file fi reads: an absolute NAME as it is; a
 * relative one in the using file's folder, then in the folders of
 * BGDRAW_PATH, then in the installed component library, the first where it
 * exists. A file found on the search path gets its canonical (absolute)
 * path, so its tables are found beside it. NULL after the error. */
static const char *find_used(fl_flattener *f, int fi, const bg_ast_stmt *s, int *searched) {
  const char *own = dir_part(f, f->files[fi].path);
  const char *path = path_in(f, own, s->text);
  *searched = 0;
  if (s->text[0] == '/' || exists(path)) return path;
  const bg_ast *root = f->files[0].ast;
  *searched = 1;
  for (const char *const *d = root->use_path; d && *d; d++) {
    const char *p = path_in(f, *d, s->text);
    if (exists(p)) return canonical(f, p);
  }
  if (root->use_lib) {
    const char *p = path_in(f, root->use_lib, s->text);
    if (exists(p)) return canonical(f, p);
  }
  report_not_found(f, s, own);
  return NULL;
}

/* A `use` statement of file fi: finds, reads, parses and loads the file once. */
static void use_file(fl_flattener *f, int fi, const bg_ast_stmt *s, int depth) {
  int searched;
  const char *path = find_used(f, fi, s, &searched);
  if (!path) return;
  const char *key = canonical(f, path);
  for (int i = 0; i < f->nfiles; i++) {
    if (strcmp(f->files[i].key, key) != 0) continue;
    if (f->files[i].loading) report_use_cycle(f, fi, i, s->name_loc);
    return; /* loaded already: its submodels are known */
  }
  if (depth >= MAX_USE_DEPTH) {
    bg_diag_error(f->dg, s->name_loc, "'use' nested too deeply (more than %d files)", MAX_USE_DEPTH);
    return;
  }
  size_t len = 0;
  char *src = bg_read_file(path, &len);
  if (!src) {
    bg_diag_error(f->dg, s->name_loc, "cannot read used file '%s' (%s): %s", s->text, path,
                  bg_file_strerror(errno));
    return;
  }
  int srcidx = bg_diags_add_source(f->dg, path, src, len);
  bg_ast *ast = bg_parse_source(path, src, len, srcidx, f->dg);
  free(src);
  fl_file *nf = FL_PUSH(f->files, f->nfiles);
  nf->path = path;
  nf->key = key;
  const char *sub = dir_part(f, s->text);
  if (searched) nf->dir_rel = dir_part(f, path); /* absolute */
  else nf->dir_rel = strcmp(sub, ".") == 0 ? f->files[fi].dir_rel : path_in(f, f->files[fi].dir_rel, sub);
  nf->ast = ast;
  load_file(f, f->nfiles - 1, depth + 1);
}

static void add_def(fl_flattener *f, int fi, const bg_ast_stmt *head, const bg_ast_stmt **body,
                    int n) {
  const sc_entry *old = bg_fl_declare(&f->defnames, head->name, 0, f->ndefs, head->name_loc);
  if (old) {
    bg_diag_error(f->dg, head->name_loc, "submodel '%s' already defined at %s:%d", head->name,
                  bg_diags_path(f->dg, old->loc), old->loc.line);
    free(body);
    return;
  }
  fl_def *d = FL_PUSH(f->defs, f->ndefs);
  d->name = head->name;
  d->head = head;
  d->stmt = body;
  d->nstmt = n;
  d->file = fi;
}

/* Collects the file's definitions (and, for the model file, its own
 * statements into defs[0]); loads the files it uses. */
static void load_file(fl_flattener *f, int fi, int depth) {
  const bg_ast *ast = fi == 0 ? f->files[0].ast : f->files[fi].ast;
  f->files[fi].loading = 1;
  const bg_ast_stmt *head = NULL, **body = NULL;
  int nbody = 0;
  for (int i = 0; i < ast->nstmts; i++) {
    const bg_ast_stmt *s = &ast->stmts[i];
    if (s->kind == BG_ST_SUBMODEL) { head = s; body = NULL; nbody = 0; }
    else if (s->kind == BG_ST_END) {
      if (head) add_def(f, fi, head, body, nbody);
      head = NULL;
    } else if (head) *FL_PUSH(body, nbody) = s;
    else if (s->kind == BG_ST_USE) use_file(f, fi, s, depth);
    else if (fi == 0) *FL_PUSH(f->defs[0].stmt, f->defs[0].nstmt) = s;
    else
      bg_diag_error(f->dg, s->loc, "a used file holds only submodels and 'use' lines; this "
                    "statement belongs in a model file");
  }
  if (head) free(body); /* no END: reported by the parser */
  f->files[fi].loading = 0;
}

/* ---------------------------------------------------------------- unbonded ports */
/* The port named `port` of def e: the other end of the bond inside e that
 * joins it, and that end's element kind word ("0", "1", ...; NULL when it
 * is not an element of e, e.g. a nested instance's port). */
static const char *inner_kind(const fl_def *e, const char *port, const char **node) {
  *node = NULL;
  for (int k = 0; k < e->nstmt && !*node; k++) {
    const bg_ast_stmt *s = e->stmt[k];
    if (s->kind == BG_ST_BOND && !strcmp(s->from, port)) *node = s->to;
    else if (s->kind == BG_ST_BOND && !strcmp(s->to, port)) *node = s->from;
  }
  for (int k = 0; *node && k < e->nstmt; k++)
    if (e->stmt[k]->kind == BG_ST_ELEMENT && !strcmp(e->stmt[k]->name, *node)) return e->stmt[k]->kindword;
  return NULL;
}

static int bonded_in(const fl_def *d, const char *end) {
  for (int k = 0; k < d->nstmt; k++)
    if (d->stmt[k]->kind == BG_ST_BOND && (!strcmp(d->stmt[k]->from, end) || !strcmp(d->stmt[k]->to, end)))
      return 1;
  return 0;
}

/* An instance's port that no bond of its scope joins, where its meaning is
 * unambiguous: a port whose inside bond ends at a 0-junction is left open
 * (zero flow), at a 1-junction shorted (zero effort); either way the
 * junction loses a branch that carries no power, which is what "not
 * connected" means. A warning names it (unbonded-port), and the two
 * statements `open`/`short` would write are added to the scope. Other
 * unbonded ports stay errors (check_ports). docs/format.md, "Open and
 * shorted ports". */
static void unbonded_ports(fl_flattener *f, int di) {
  fl_def *d = &f->defs[di];
  int n0 = d->nstmt;
  for (int k = 0; k < n0; k++) {
    const bg_ast_stmt *s = d->stmt[k];
    const sc_entry *de = s->kind == BG_ST_INSTANCE ? bg_fl_lookup(&f->defnames, s->kindword) : NULL;
    if (!de) continue;
    const fl_def *e = &f->defs[de->index];
    for (int j = 0; j < e->nstmt; j++) {
      const bg_ast_stmt *ps = e->stmt[j];
      for (int i = 0; ps->kind == BG_ST_PORT && i < ps->nitems; i++) {
        const char *port = ps->items[i].name, *node;
        char *end = bg_arena_alloc(&f->out->arena, strlen(s->name) + strlen(port) + 2);
        sprintf(end, "%s.%s", s->name, port);
        if (bonded_in(d, end)) continue;
        const char *kind = inner_kind(e, port, &node);
        int is_short = kind && !strcmp(kind, "1");
        if (!kind || (strcmp(kind, "0") && !is_short)) continue; /* ambiguous: an error later */
        bg_diag_warn(f->dg, BG_W_UNBONDED_PORT, s->name_loc, "port '%s' of %s (%s) is not bonded: "
                     "taken as %s (zero %s: the %s-junction %s inside loses a branch that carries no "
                     "power); write 'open %s' or 'short %s' to say which", port, s->name, e->name,
                     is_short ? "shorted" : "open", is_short ? "effort" : "flow", kind, node, end, end);
        size_t len = strlen(end);
        char *name = bg_arena_alloc(&f->out->arena, len + 7);
        for (size_t c = 0; c < len; c++) name[c] = end[c] == '.' ? '_' : end[c];
        strcpy(name + len, is_short ? "_short" : "_open");
        bg_ast_stmt *x = bg_arena_alloc(&f->out->arena, 2 * sizeof *x);
        bg_expr *zero = bg_arena_alloc(&f->out->arena, sizeof *zero);
        memset(x, 0, 2 * sizeof *x);
        memset(zero, 0, sizeof *zero);
        zero->kind = BG_EX_NUM, zero->loc = s->name_loc, zero->text = "0", zero->depth = 1;
        x[0].kind = BG_ST_ELEMENT, x[0].loc = x[0].name_loc = s->name_loc;
        x[0].kindword = is_short ? "Se" : "Sf", x[0].name = name, x[0].expr = zero, x[0].zero_port = 1;
        x[1].kind = BG_ST_BOND, x[1].loc = x[1].from_loc = x[1].to_loc = s->name_loc;
        x[1].from = name, x[1].to = end, x[1].zero_port = 1;
        *FL_PUSH(d->stmt, d->nstmt) = &x[0];
        *FL_PUSH(d->stmt, d->nstmt) = &x[1];
      }
    }
  }
}

/* ---------------------------------------------------------------- driver */
static bg_flat *make_result(fl_flattener *f) {
  bg_flat *r = bg_xcalloc(1, sizeof *r);
  r->ast = f->out;
  f->out = NULL;
  /* the statements stay where they are (compacted below, in order): a copy
   * would double the flattening's largest array (issue 28, bounded_size.sh) */
  r->ast->stmts = r->ast->heap_stmts = f->stmts ? f->stmts : bg_xmalloc(sizeof *r->ast->stmts);
  f->stmts = NULL;
  r->inst = bg_xmalloc((size_t)(f->ninst ? f->ninst : 1) * sizeof *r->inst);
  for (int i = 0; i < f->ninst; i++) r->inst[i] = f->inst[i].pub;
  r->ninst = f->ninst;
  size_t nel = 1; /* a multiport field's statement makes one element per port */
  for (int i = 0; i < f->nstmts; i++)
    nel += r->ast->stmts[i].is_field ? (size_t)r->ast->stmts[i].nitems : 1;
  r->elem_inst = bg_xmalloc(nel * sizeof *r->elem_inst);
  r->bond_segadr = bg_xmalloc((size_t)(f->nstmts + 1) * sizeof *r->bond_segadr);
  r->bond_nseg = bg_xmalloc((size_t)(f->nstmts + 1) * sizeof *r->bond_nseg);
  r->seg = bg_xmalloc((size_t)(f->nsegs + 1) * sizeof *r->seg);
  for (int i = 0; i < f->nstmts; i++) {
    const bg_ast_stmt *s = &r->ast->stmts[i];
    if ((int)s->kind < 0) continue; /* a bond segment joined into another statement */
    if (r->ast->nstmts < i) r->ast->stmts[r->ast->nstmts] = *s;
    s = &r->ast->stmts[r->ast->nstmts++];
    for (int k = 0; s->kind == BG_ST_ELEMENT && !bg_ast_is_detector(s) &&
                    k < (s->is_field ? s->nitems : 1); k++) /* a detector is no element */
      r->elem_inst[r->nelem++] = f->stmt_inst[i];
    if (s->kind != BG_ST_BOND) continue;
    int c = f->slot_chain[i];
    r->bond_segadr[r->nbond] = r->nseg;
    for (int k = 0; k < f->chain_n[c]; k++) { /* outermost first, then tail to head */
      const fl_seg *g = &f->segs[f->chain_segs[f->chain_adr[c] + k]];
      r->seg[r->nseg++] = (bg_flat_segment){g->inst, g->num};
    }
    r->bond_nseg[r->nbond++] = f->chain_n[c];
  }
  return r;
}

static void flattener_free(fl_flattener *f) {
  for (int i = 0; i < f->ndefs; i++) {
    bg_fl_scope_free(&f->defs[i].names);
    free(f->defs[i].stmt);
    free(f->defs[i].port_stmt);
    free(f->defs[i].port_item);
    free(f->defs[i].bondnum);
  }
  for (int i = 1; i < f->nfiles; i++) bg_ast_free(f->files[i].ast);
  free(f->files);
  free(f->defs);
  bg_fl_scope_free(&f->defnames);
  free(f->inst);
  free(f->ports);
  free(f->segs);
  free(f->fields);
  free(f->bondvars);
  free(f->stmts);
  free(f->stmt_inst);
  free(f->slot_chain);
  free(f->chain_adr);
  free(f->chain_n);
  free(f->chain_segs);
  if (f->out) bg_ast_free(f->out);
}

bg_flat *bg_flat_expand(const bg_ast *ast, bg_diags *dg) {
  fl_flattener f;
  memset(&f, 0, sizeof f);
  f.dg = dg;
  int errors0 = bg_diags_failures(dg);
  f.out = bg_xcalloc(1, sizeof *f.out);
  f.out->path = bg_arena_strdup(&f.out->arena, ast->path ? ast->path : "");
  f.out->file = ast->file;
  fl_file *root = FL_PUSH(f.files, f.nfiles);
  root->path = f.out->path;
  root->key = canonical(&f, root->path);
  root->dir_rel = ".";
  root->ast = (bg_ast *)ast; /* borrowed: never freed here */
  fl_def *model = FL_PUSH(f.defs, f.ndefs);
  model->name = "the model";
  load_file(&f, 0, 0);
  for (int i = 0; i < f.ndefs; i++) unbonded_ports(&f, i);
  for (int i = 0; i < f.ndefs; i++) def_names(&f, i);
  for (int i = 1; i < f.ndefs && bg_diags_failures(dg) == errors0; i++) bg_fl_span(&f, i, f.defs[i].head->loc);
  if (bg_diags_failures(dg) == errors0) bg_fl_span(&f, 0, (bg_srcloc){0});
  int spans_ok = bg_diags_failures(dg) == errors0;
  if (spans_ok) bg_fl_expand_model(&f, 0);
  if (bg_diags_failures(dg) == errors0) bg_fl_chain_bonds(&f);
  if (spans_ok && !f.capped) bg_fl_check_unused(&f); /* their errors in the same run */
  bg_flat *r = bg_diags_failures(dg) == errors0 ? make_result(&f) : NULL;
  flattener_free(&f);
  return r;
}

void bg_flat_free(bg_flat *r) {
  if (!r) return;
  bg_ast_free(r->ast);
  free(r->inst);
  free(r->elem_inst);
  free(r->bond_segadr);
  free(r->bond_nseg);
  free(r->seg);
  free(r);
}
