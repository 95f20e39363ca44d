/* SPDX-License-Identifier: BSD-3-Clause */
/* The flattener, part 3: bond numbers and ports. A port is one bond end:
 * the bond inside the submodel and the bond outside it become one flat bond,
 * whose direction both must agree on. Every bond written in some scope is a
 * segment; a chain of segments joined through ports is one flat bond, which
 * takes the number (and the place in file order) of its outermost segment. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/strbuf.h"
#include "lang/flatten_int.h"
#include "lang/parse.h"

enum { MAX_NUMBER = BG_BOND_NUMBER_MAX, MAX_DEF_DEPTH = 100 };

static const char *const element_kinds[] = {"Se", "Sf", "MSe", "MSf", "C", "I", "R",
                                            "TF", "MTF", "GY", "MGY", "De", "Df"};

/* ---------------------------------------------------------------- spans */
static void unknown_submodel(fl_flattener *f, const bg_ast_stmt *s) {
  if (bg_diags_unsure(f->dg, s->kindword)) return; /* its header had a syntax error? */
  if (!strcmp(s->kindword, "port") || !strcmp(s->kindword, "end")) {
    bg_diag_error(f->dg, s->loc, "'%s' belongs inside a submodel (submodel NAME ... end)",
                  s->kindword);
    return;
  }
  for (size_t i = 0; i < sizeof element_kinds / sizeof *element_kinds; i++)
    if (!strcasecmp(s->kindword, element_kinds[i])) { /* a case slip: r is R, tf is TF */
      bg_diag_error(f->dg, s->loc, "unknown element kind or submodel '%s' (did you mean '%s'?)",
                    s->kindword, element_kinds[i]);
      return;
    }
  const char *best = bg_fl_suggest(&f->defnames, s->kindword, ~0u);
  int bestd = best ? bg_edit_distance(s->kindword, best) : (strlen(s->kindword) < 3 ? 2 : 3);
  for (size_t i = 0; i < sizeof element_kinds / sizeof *element_kinds; i++) {
    int d = bg_edit_distance(s->kindword, element_kinds[i]);
    if (d > 0 && d < bestd) { bestd = d; best = element_kinds[i]; }
  }
  if (best)
    bg_diag_error(f->dg, s->loc, "unknown element kind or submodel '%s' (did you mean '%s'?)",
                  s->kindword, best);
  else bg_diag_error(f->dg, s->loc, "unknown element kind or submodel '%s'", s->kindword);
}

static long span_of(fl_flattener *f, int di, bg_srcloc use, int depth) {
  fl_def *d = &f->defs[di];
  if (d->span_state == 2) return d->span;
  if (d->span_state == 1 || depth > MAX_DEF_DEPTH) {
    if (d->span_state == 1)
      bg_diag_error(f->dg, use, "recursive submodel: %s contains an instance of itself "
                    "(directly or through other submodels)", d->name);
    else bg_diag_error(f->dg, use, "submodels nested too deeply (more than %d levels)",
                       MAX_DEF_DEPTH);
    return 0;
  }
  d->span_state = 1;
  long total = d->maxnum, size = d->head ? d->head->nitems : 0; /* its parameters */
  for (int k = 0; k < d->nstmt; k++) {
    const bg_ast_stmt *s = d->stmt[k];
    if (s->kind != BG_ST_INSTANCE) {
      size += s->kind != BG_ST_PORT;
      continue;
    }
    const sc_entry *n = bg_fl_lookup(&f->defnames, s->kindword);
    if (!n) { unknown_submodel(f, s); continue; }
    total += span_of(f, n->index, s->loc, depth + 1);
    if (total > MAX_NUMBER) total = MAX_NUMBER + 1L; /* reported once, at the model */
    size += f->defs[n->index].size;
    if (size > BG_FLAT_MAX) size = BG_FLAT_MAX + 1L; /* reported at the instance that crosses */
  }
  d->span = total;
  d->size = size;
  d->span_state = 2;
  return total;
}

long bg_fl_span(fl_flattener *f, int di, bg_srcloc use) {
  long n = span_of(f, di, use, 0);
  if (di == 0 && n > MAX_NUMBER)
    bg_diag_error(f->dg, use, "the flat model would need bond numbers above %d", MAX_NUMBER);
  return n;
}

/* ---------------------------------------------------------------- ports */
static const char *port_name(const fl_flattener *f, const fl_inst *in, int p) {
  const fl_def *d = &f->defs[in->def];
  return d->port_stmt[p]->items[d->port_item[p]].name;
}

/* Every port joined once inside and once outside, both bonds in one direction
 * (the bond of an open or short port is turned to agree). */
static void check_ports(fl_flattener *f) {
  for (int i = 0; i < f->ninst; i++) {
    const fl_inst *in = &f->inst[i];
    const fl_def *d = &f->defs[in->def];
    for (int p = 0; p < d->nports; p++) {
      fl_port *pt = &f->ports[in->port_adr + p];
      const char *name = port_name(f, in, p);
      bg_srcloc decl = d->port_stmt[p]->items[d->port_item[p]].loc;
      decl.file = in->src;
      if ((pt->ninner == 0 || pt->nouter == 0) && bg_diags_unsure_bonds(f->dg, name)) continue;
      if (pt->ninner == 0)
        bg_diag_error(f->dg, decl, "port '%s' of %s has no bond inside the submodel", name,
                      d->name);
      if (pt->nouter == 0)
        bg_diag_error(f->dg, in->pub.loc, "port '%s' of %s (%s) is not connected: bond it, or "
                      "write 'open %s.%s' (zero flow) or 'short %s.%s' (zero effort)", name,
                      in->pub.name, d->name, in->pub.name, name, in->pub.name, name);
      if (pt->ninner == 0 || pt->nouter == 0 || pt->outer_is_head == pt->inner_is_tail) continue;
      fl_seg *g = &f->segs[pt->outer];
      if (f->stmts[g->slot].zero_port) { /* open/short: a zero source takes either direction */
        fl_end tail = g->end[0];
        g->end[0] = g->end[1], g->end[1] = tail;
        pt->outer_is_head = !pt->outer_is_head;
        continue;
      }
      bg_diag_error(f->dg, pt->outer_loc, "power direction at port %s.%s: %s takes power %s at "
                    "'%s' (its bond at line %d), this bond takes it %s; reverse this bond",
                    in->pub.name, name, d->name, pt->inner_is_tail ? "in" : "out", name,
                    pt->inner_loc.line, pt->outer_is_head ? "in" : "out");
    }
  }
}

/* ---------------------------------------------------------------- chains */
/* The segment on the other side of end j of segment g, -1 at a node. */
static int across(const fl_flattener *f, int g, int j) {
  int p = f->segs[g].end[j].port;
  if (p < 0) return -1;
  return f->ports[p].inner == g ? f->ports[p].outer : f->ports[p].inner;
}

/* Walks to the chain's tail, then collects it tail to head; -1 if the
 * segments through ports close a loop without an element. */
static int collect_chain(fl_flattener *f, int g, int **list, int *n) {
  int first = g, steps = 0;
  while (across(f, first, 0) >= 0) {
    first = across(f, first, 0);
    if (++steps > f->nsegs) return -1;
  }
  *n = 0;
  for (int cur = first; cur >= 0; cur = across(f, cur, 1)) {
    *FL_PUSH(*list, *n) = cur;
    if (*n > f->nsegs) return -1;
  }
  return 0;
}

/* The chain's fixed stroke: segments may fix it only at the same end. */
static int chain_fix(fl_flattener *f, const int *list, int n) {
  int fix = BG_ARROW_PLAIN;
  for (int i = 0; i < n; i++) {
    int s = f->segs[list[i]].fix;
    if (s == BG_ARROW_PLAIN) continue;
    if (fix != BG_ARROW_PLAIN && s != fix)
      bg_diag_error(f->dg, f->segs[list[i]].stmt->loc, "this bond fixes the causal stroke at the "
                    "other end than the bond it is joined to through a port");
    fix = s;
  }
  return fix;
}

static void make_flat_bond(fl_flattener *f, const int *list, int n) {
  int outer = list[0];
  for (int i = 1; i < n; i++)
    if (f->segs[list[i]].depth < f->segs[outer].depth) outer = list[i];
  const fl_seg *o = &f->segs[outer], *tail = &f->segs[list[0]], *head = &f->segs[list[n - 1]];
  int c = f->nchains++;
  f->chain_adr = bg_xrealloc(f->chain_adr, (size_t)f->nchains * sizeof *f->chain_adr);
  f->chain_n = bg_xrealloc(f->chain_n, (size_t)f->nchains * sizeof *f->chain_n);
  f->chain_adr[c] = f->nchain_segs;
  f->chain_n[c] = n;
  *FL_PUSH(f->chain_segs, f->nchain_segs) = outer;
  for (int i = 0; i < n; i++)
    if (list[i] != outer) *FL_PUSH(f->chain_segs, f->nchain_segs) = list[i];
  bg_ast_stmt *x = &f->stmts[o->slot];
  x->kind = BG_ST_BOND;
  x->number = (int)o->flatnum;
  x->from = tail->end[0].node;
  x->from_loc = tail->end[0].loc;
  x->to = head->end[1].node;
  x->to_loc = head->end[1].loc;
  x->arrow = chain_fix(f, list, n);
  for (int i = 0; i < n && x->nopts == 0; i++) /* options of the outermost, else the first */
    if (f->segs[list[i]].stmt->nopts) {
      x->opts = f->segs[list[i]].stmt->opts;
      x->nopts = f->segs[list[i]].stmt->nopts;
    }
  f->slot_chain[o->slot] = c;
  for (int i = 0; i < n; i++) f->segs[list[i]].chain = c;
}

/* e7 inside a submodel: bond 7 of that submodel, renumbered flat. */
static void renumber_bond_vars(fl_flattener *f) {
  for (int i = 0; i < f->nbondvars; i++) {
    fl_bondvar *v = &f->bondvars[i];
    int found = -1;
    for (int g = 0; g < f->nsegs && found < 0; g++)
      if (f->segs[g].inst == v->inst && f->segs[g].num == v->num) found = g;
    if (found < 0) {
      bg_diag_error(f->dg, v->node->loc, "no bond %d in submodel %s", v->num,
                    f->defs[f->inst[v->inst].def].name);
      continue;
    }
    const fl_seg *o = &f->segs[f->chain_segs[f->chain_adr[f->segs[found].chain]]];
    char buf[32];
    snprintf(buf, sizeof buf, "%c%ld", v->node->str[0], o->flatnum);
    v->node->str = bg_fl_strdup(f, buf);
  }
}

/* M1.K names the param K of instance M1 (not a field K of a node M1); M1.v
 * likewise its detector v (a name, not a field of an element). */
static void resolve_qualified_fields(fl_flattener *f) {
  fl_scope names = {0};
  for (int i = 0; i < f->nstmts; i++) {
    const bg_ast_stmt *s = &f->stmts[i];
    if (s->kind == BG_ST_PARAM || s->kind == BG_ST_INPUT || s->kind == BG_ST_STATE ||
        s->kind == BG_ST_OUTPUT || bg_ast_is_detector(s))
      bg_fl_declare(&names, s->name, 0, i, s->name_loc);
  }
  for (int i = 0; i < f->nfields; i++) {
    bg_expr *x = f->fields[i];
    const char *full = bg_fl_join(f, x->str, x->field);
    if (!bg_fl_lookup(&names, full)) continue;
    x->kind = BG_EX_NAME;
    x->str = full;
  }
  bg_fl_scope_free(&names);
}

void bg_fl_chain_bonds(fl_flattener *f) {
  int errors0 = bg_diags_failures(f->dg);
  check_ports(f);
  if (bg_diags_failures(f->dg) > errors0) return;
  /* the bond statements are copied when chains fill their slots: keep the
   * originals (of the bonds only: the other statements are most of the model) */
  bg_ast_stmt *orig = bg_xmalloc((size_t)(f->nsegs + 1) * sizeof *orig);
  for (int g = 0; g < f->nsegs; g++) orig[g] = f->stmts[f->segs[g].slot], f->segs[g].stmt = &orig[g];
  f->slot_chain = bg_xmalloc((size_t)(f->nstmts + 1) * sizeof *f->slot_chain);
  for (int i = 0; i < f->nstmts; i++) f->slot_chain[i] = -1;
  int *list = NULL, n = 0;
  for (int g = 0; g < f->nsegs; g++) {
    if (f->segs[g].chain >= 0) continue;
    if (collect_chain(f, g, &list, &n) != 0) {
      bg_diag_error(f->dg, f->segs[g].stmt->loc, "bonds joined through ports close a loop with "
                    "no element or junction on it");
      f->segs[g].chain = -2;
      continue;
    }
    make_flat_bond(f, list, n);
  }
  free(list);
  renumber_bond_vars(f);
  resolve_qualified_fields(f);
  free(orig);
}
