/* SPDX-License-Identifier: BSD-3-Clause */
/* Submodels (language version 2): flattening into the flat model, qualified
 * names, flat bond numbers and the instance bonds they came from, parameters,
 * nesting, ports passed through, bond variables inside submodels, and the
 * instance chain of diagnostics. The reference is a hand-flattened model. */
#include "causality/causality.h"
#include "equations/equations.h"
#include "harness.h"
#include "lang/lang.h"
#include "model/model.h"
#include "analysis/analysis.h"
#include "diagram/render.h"
#include "scene/scene.h"

#define DATA BG_SOURCE_DIR "/tests/data/components/"

typedef struct loaded {
  bg_model *m;
  bg_diags dg;
  char *src;
} loaded;

/* Loads a model from a file, or from text as if it were the file `path`. */
static int load(loaded *l, const char *path, const char *text) {
  size_t len = 0;
  memset(l, 0, sizeof *l);
  if (text) {
    len = strlen(text);
    l->src = malloc(len + 1);
    memcpy(l->src, text, len + 1);
  } else l->src = bg_read_file(path, &len);
  bg_diags_init(&l->dg, path, l->src, len);
  if (!l->src) return -1;
  bg_ast *ast = bg_parse_string(path, l->src, len, &l->dg);
  if (ast && !l->dg.nerrors) l->m = bg_model_compile(ast, NULL, 0, &l->dg);
  bg_ast_free(ast);
  return l->m ? 0 : -1;
}

static void unload(loaded *l) {
  bg_model_free(l->m);
  bg_diags_free(&l->dg);
  free(l->src);
}

/* The equations as text, with M1.Ra written M1_Ra (a name's dot, not a number's). */
static char *equations_text(const bg_model *m) {
  bg_analysis a;
  bg_diags dg;
  bg_diags_init(&dg, "eq", NULL, 0);
  bg_analysis_init(&a, m);
  bg_causality_assign(m, BG_METHOD_SCAP, &a, &dg);
  bg_analysis_run(m, &a, NULL);
  bg_eqsys *s = bg_eqsys_build(m, &a, &dg);
  bg_strbuf sb = {0};
  if (s) bg_eqprint_text(s, &sb);
  char *t = strdup(bg_sb_str(&sb));
  for (char *p = t; *p; p++)
    if (*p == '.' && p[1] && !(p[1] >= '0' && p[1] <= '9')) *p = '_';
  bg_sb_free(&sb);
  bg_eqsys_free(s);
  bg_analysis_free(&a);
  bg_diags_free(&dg);
  return t;
}

static int bond_by_num(const bg_model *m, int num) { return bg_model_find_bond(m, num); }

static void test_two_motors_against_hand_flattened(void) {
  loaded c, f;
  OK(load(&c, DATA "two_motors.bg", NULL) == 0);
  OK(load(&f, DATA "two_motors_flat.bg", NULL) == 0);
  if (!c.m || !f.m) { bg_diags_print(&c.dg, stderr); return; }
  INT_EQ(c.m->nelem, f.m->nelem);
  INT_EQ(c.m->nbond, f.m->nbond);
  for (int b = 0; b < c.m->nbond && c.m->nbond == f.m->nbond; b++)
    INT_EQ(c.m->bond_num[b], f.m->bond_num[b]);
  char *tc = equations_text(c.m), *tf = equations_text(f.m);
  STR_EQ(tc, tf);
  free(tc);
  free(tf);
  /* qualified names and instances */
  OK(bg_model_find_elem(c.m, "M1.Ra") >= 0);
  OK(bg_model_find_elem(c.m, "M2.Jm") >= 0);
  INT_EQ(c.m->ninst, 2);
  STR_EQ(c.m->inst_name[1], "M2");
  STR_EQ(c.m->inst_def[1], "DCMotor");
  INT_EQ(c.m->inst_bondoff[0], 5);
  INT_EQ(c.m->inst_bondoff[1], 13);
  INT_EQ(c.m->elem_inst[bg_model_find_elem(c.m, "M2.G")], 1);
  INT_EQ(c.m->elem_inst[bg_model_find_elem(c.m, "load")], -1);
  /* bond 2 is the model's bond 2 joined through port a to M1's bond 1 */
  int b2 = bond_by_num(c.m, 2), b4 = bond_by_num(c.m, 4), b17 = bond_by_num(c.m, 17);
  INT_EQ(c.m->bond_nseg[b2], 2);
  INT_EQ(c.m->seg_inst[c.m->bond_segadr[b2]], -1);
  INT_EQ(c.m->seg_num[c.m->bond_segadr[b2]], 2);
  INT_EQ(c.m->seg_inst[c.m->bond_segadr[b2] + 1], 0);
  INT_EQ(c.m->seg_num[c.m->bond_segadr[b2] + 1], 1);
  INT_EQ(c.m->seg_num[c.m->bond_segadr[b4] + 1], 8); /* M1's jw -> shaft */
  STR_EQ(c.m->elem_name[c.m->bond_tail[b4]], "M1.jw");
  INT_EQ(c.m->bond_nseg[b17], 1);
  INT_EQ(c.m->seg_inst[c.m->bond_segadr[b17]], 1);
  INT_EQ(c.m->seg_num[c.m->bond_segadr[b17]], 4); /* 13 + 4 */
  /* parameters: the argument, else the default, with the description */
  int id = -1;
  for (int p = 0; p < c.m->nparam; p++)
    if (!strcmp(c.m->param_name[p], "M1.R")) id = p;
  OK(id >= 0);
  if (id >= 0) DBL_NEAR(c.m->param_value[id], 2, 0);
  if (id >= 0) STR_EQ(c.m->param_desc[id], "armature resistance");
  OK(f.m->ninst == 0 && f.m->elem_inst[0] == -1);
  unload(&c);
  unload(&f);
}

/* Nested instances, parameters passed down, a port passed straight through,
 * e<N> inside a submodel, a fixed stroke through a port, M1.K outside. */
static const char *nested =
    "submodel Wire\n"
    "  port a, b\n"
    "  bond a ->| b\n"               /* passes the bond through, stroke at b's end */
    "end\n"
    "submodel Stage(k = 2, m = 1)\n"
    "  port a\n"
    "  param k2 = 2 * k\n"
    "  0 j\n"
    "  C c = 1 / k2\n"
    "  I mass = m\n"
    "  Wire W\n"
    "  bond a -> W.a\n"
    "  bond W.b -> j\n"
    "  bond j -> c\n"
    "  bond j -> mass\n"
    "  MSe probe = e3\n"              /* bond 3 of Stage: j -> c */
    "  1 jp\n"
    "  R rp = 1\n"
    "  bond probe -> jp\n"
    "  bond jp -> rp\n"
    "end\n"
    "submodel Pair(k = 1)\n"
    "  port a\n"
    "  0 j\n"
    "  Stage S1(k = k)\n"
    "  Stage S2(k = k + 1, m = 2)\n"
    "  bond a -> j\n"
    "  bond j -> S1.a\n"
    "  bond j -> S2.a\n"
    "end\n"
    "Sf v = 1\n"
    "Pair P(k = 3)\n"
    "bond v -> P.a\n"
    "plot P.S2.k2, P.S1.c.e\n";

static double param(const bg_model *m, const char *name) {
  for (int p = 0; p < m->nparam; p++)
    if (!strcmp(m->param_name[p], name)) return m->param_value[p];
  return NAN;
}

static void test_nested(void) {
  loaded l;
  OK(load(&l, "nested.bg", nested) == 0);
  if (!l.m) { bg_diags_print(&l.dg, stderr); return; }
  const bg_model *m = l.m;
  DBL_NEAR(param(m, "P.S1.k2"), 6, 0);
  DBL_NEAR(param(m, "P.S2.k2"), 8, 0);
  DBL_NEAR(param(m, "P.S2.m"), 2, 0);
  INT_EQ(m->ninst, 5); /* P, P.S1, P.S1.W, P.S2, P.S2.W */
  STR_EQ(m->inst_name[2], "P.S1.W");
  INT_EQ(m->inst_parent[2], 1);
  /* Pair: 3 own bonds; Stage: 6 own + Wire 1 = span 7 */
  INT_EQ(m->inst_bondoff[0], 1);
  INT_EQ(m->inst_bondoff[1], 4);
  INT_EQ(m->inst_bondoff[2], 10);
  INT_EQ(m->inst_bondoff[3], 11);
  /* v -> P.a -> j: bond 1; j -> S1.a -> W.a -> W.b -> S1.j: one bond through
   * three scopes, numbered as Pair's bond 2 (P offset 1 + 2 = 3) */
  int b = bg_model_find_bond(m, 3);
  OK(b >= 0);
  if (b < 0) { unload(&l); return; }
  STR_EQ(m->elem_name[m->bond_tail[b]], "P.j");
  STR_EQ(m->elem_name[m->bond_head[b]], "P.S1.j");
  INT_EQ(m->bond_nseg[b], 4);
  INT_EQ(m->bond_fix[b], BG_FIX_HEAD); /* Wire's ->| */
  INT_EQ(m->seg_inst[m->bond_segadr[b] + 3], 1); /* S1's W.b -> j, the head end */
  /* e3 inside S1 is S1's bond 3 (j -> c): flat 4 + 3 = 7 */
  int probe = bg_model_find_elem(m, "P.S1.probe");
  const bg_xnode *x = &m->xnode[m->elem_expr[probe]];
  INT_EQ(x->op, BG_X_EFFORT);
  INT_EQ(m->bond_num[x->ref], 7);
  STR_EQ(m->elem_name[m->bond_head[x->ref]], "P.S1.c");
  /* P.S2.k2 outside is the param, P.S1.c.e the effort of element P.S1.c */
  INT_EQ(m->xnode[m->plotexpr_root[0]].op, BG_X_PARAM);
  INT_EQ(m->xnode[m->plotexpr_root[1]].op, BG_X_EFFORT);
  STR_EQ(m->plotexpr_text[1], "P.S1.c.e");
  unload(&l);
}

/* A mistake two levels deep: the error in the submodel's line, then one
 * note per instance of the chain, innermost first. */
static void test_chain_notes(void) {
  const char *src =
      "submodel Inner\n"
      "  port a\n"
      "  R r = nope\n"
      "  bond a -> r\n"
      "end\n"
      "submodel Outer\n"
      "  port a\n"
      "  Inner In\n"
      "  bond a -> In.a\n"
      "end\n"
      "Se U = 1\n"
      "Outer O\n"
      "bond U -> O.a\n";
  loaded l;
  OK(load(&l, "chain.bg", src) != 0);
  FILE *out = tmpfile();
  bg_diags_print(&l.dg, out);
  rewind(out);
  char buf[4096];
  size_t n = fread(buf, 1, sizeof buf - 1, out);
  buf[n] = '\0';
  fclose(out);
  const char *e = strstr(buf, "chain.bg:3:9: error: undefined name 'nope' in submodel Inner");
  const char *n1 = strstr(buf, "chain.bg:8:9: note: in instance O.In of Inner");
  const char *n2 = strstr(buf, "chain.bg:12:7: note: in instance O of Outer");
  OK(e && n1 && n2 && e < n1 && n1 < n2);
  INT_EQ(l.dg.nerrors, 1);
  unload(&l);
}

/* A version 1 file is compiled without flattening: nothing recorded. */
static void test_version1_untouched(void) {
  loaded l;
  OK(load(&l, "v1.bg", "Se U = 1\nR R1 = 2\nbond U -> R1\n") == 0);
  if (l.m) {
    INT_EQ(l.m->ninst, 0);
    INT_EQ(l.m->nseg, 0);
    INT_EQ(l.m->elem_inst[1], -1);
  }
  unload(&l);
}

/* The box of the scene path whose role is `role`; 0 if there is none. */
static int frame_box(const bg_scene *s, const char *role, double *x0, double *y0, double *x1,
                     double *y1) {
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    if (!it->role || strcmp(it->role, role) != 0 || it->kind != BG_ITEM_STROKE) continue;
    *x0 = *y0 = 1e300, *x1 = *y1 = -1e300;
    bg_scene_op op_;
    for (int k = 0; bg_scene_next_op(s, it, &k, &op_);) {
      const bg_scene_op *op = &op_;
      if (op->code == BG_OP_CLOSE) continue;
      *x0 = fmin(*x0, op->x[0]), *x1 = fmax(*x1, op->x[0]);
      *y0 = fmin(*y0, op->y[0]), *y1 = fmax(*y1, op->y[0]);
    }
    return 1;
  }
  return 0;
}

/* Whether the text item `role` is anchored inside the box. */
static int inside(const bg_scene *s, const char *role, double x0, double y0, double x1, double y1) {
  for (int i = 0; i < s->nitem; i++)
    if (s->item[i].role && !strcmp(s->item[i].role, role))
      return s->item[i].x > x0 && s->item[i].x < x1 && s->item[i].y > y0 && s->item[i].y < y1;
  return -1;
}

/* Each instance is drawn in a labelled frame around exactly its elements. */
static void test_frames(void) {
  loaded l;
  OK(load(&l, DATA "two_motors.bg", NULL) == 0);
  if (!l.m) return;
  bg_analysis a;
  bg_diags dg;
  bg_diags_init(&dg, "frames", NULL, 0);
  bg_analysis_init(&a, l.m);
  bg_causality_assign(l.m, BG_METHOD_SCAP, &a, &dg);
  bg_analysis_run(l.m, &a, NULL);
  bg_render_opts o = {0};
  bg_diagram *d = bg_diagram_build(l.m, &a, &o, &dg);
  OK(d != NULL);
  if (d) {
    const bg_scene *s = bg_diagram_scene(d);
    INT_EQ(bg_diagram_count(d, "frame"), 2);
    INT_EQ(bg_diagram_count(d, "frame-label"), 2);
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    OK(frame_box(s, "frame M1", &x0, &y0, &x1, &y1));
    static const char *in_m1[] = {"node M1.Ra", "node M1.La", "node M1.G", "node M1.Jm", "node M1.bm"};
    for (int i = 0; i < 5; i++) INT_EQ(inside(s, in_m1[i], x0, y0, x1, y1), 1);
    static const char *out_m1[] = {"node U", "node load", "node M2.Ra", "node M2.Jm"};
    for (int i = 0; i < 4; i++) INT_EQ(inside(s, out_m1[i], x0, y0, x1, y1), 0);
    bg_diagram_free(d);
  }
  bg_analysis_free(&a);
  bg_diags_free(&dg);
  unload(&l);
}

int main(void) {
  test_frames();
  test_two_motors_against_hand_flattened();
  test_nested();
  test_chain_notes();
  test_version1_untouched();
  return bg_t_done();
}
