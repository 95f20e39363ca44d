/* SPDX-License-Identifier: BSD-3-Clause */
/* The model compiler's entry point: a model with submodels is flattened
 * first (lang/flatten.h) and its flat AST compiled like a version 1 file;
 * where each element and bond came from is then recorded in the model. */
#include <string.h>

#include "lang/lang.h"
#include "model/model_int.h"

static void *arena_copy(bg_model *m, const void *src, size_t n) {
  void *p = bg_arena_alloc(&m->arena, n ? n : 1);
  if (n) memcpy(p, src, n);
  return p;
}

static void attach_components(bg_model *m, const bg_flat *f) {
  m->ninst = f->ninst;
  m->inst_name = bg_arena_alloc(&m->arena, sizeof(char *) * (size_t)(f->ninst + 1));
  m->inst_def = bg_arena_alloc(&m->arena, sizeof(char *) * (size_t)(f->ninst + 1));
  m->inst_parent = bg_arena_alloc(&m->arena, sizeof(int) * (size_t)(f->ninst + 1));
  m->inst_loc = bg_arena_alloc(&m->arena, sizeof(bg_srcloc) * (size_t)(f->ninst + 1));
  m->inst_bondoff = bg_arena_alloc(&m->arena, sizeof(int) * (size_t)(f->ninst + 1));
  m->inst_bondspan = bg_arena_alloc(&m->arena, sizeof(int) * (size_t)(f->ninst + 1));
  for (int i = 0; i < f->ninst; i++) {
    m->inst_name[i] = bg_arena_strdup(&m->arena, f->inst[i].name);
    m->inst_def[i] = bg_arena_strdup(&m->arena, f->inst[i].def);
    m->inst_parent[i] = f->inst[i].parent;
    m->inst_loc[i] = f->inst[i].loc;
    m->inst_bondoff[i] = f->inst[i].bond_offset;
    m->inst_bondspan[i] = f->inst[i].bond_span;
  }
  if (f->nelem != m->nelem || f->nbond != m->nbond)
    BG_FATAL("flat model has %d elements and %d bonds, the flattener made %d and %d", m->nelem,
             m->nbond, f->nelem, f->nbond);
  m->elem_inst = arena_copy(m, f->elem_inst, sizeof(int) * (size_t)f->nelem);
  m->bond_segadr = arena_copy(m, f->bond_segadr, sizeof(int) * (size_t)f->nbond);
  m->bond_nseg = arena_copy(m, f->bond_nseg, sizeof(int) * (size_t)f->nbond);
  m->nseg = f->nseg;
  m->seg_inst = bg_arena_alloc(&m->arena, sizeof(int) * (size_t)(f->nseg + 1));
  m->seg_num = bg_arena_alloc(&m->arena, sizeof(int) * (size_t)(f->nseg + 1));
  for (int i = 0; i < f->nseg; i++) {
    m->seg_inst[i] = f->seg[i].inst;
    m->seg_num[i] = f->seg[i].num;
  }
}

bg_model *bg_model_compile(const bg_ast *ast, const bg_param_override *ov, int nov,
                           bg_diags *dg) {
  if (!ast->has_components) {
    bg_model *m = bg_model_compile_flat(ast, ov, nov, dg);
    if (m) bg_model_warnings(m, ast, dg);
    return m;
  }
  bg_flat *flat = bg_flat_expand(ast, dg);
  if (!flat) return NULL;
  bg_model *m = bg_model_compile_flat(flat->ast, ov, nov, dg);
  if (m) attach_components(m, flat);
  if (m) bg_model_warnings(m, ast, dg);
  bg_flat_free(flat);
  return m;
}
