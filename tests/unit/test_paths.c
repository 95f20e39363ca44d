/* SPDX-License-Identifier: BSD-3-Clause */
/* Causal paths and causal loops: a hand-built model, then the reference
 * examples (docs/examples.md), comparing whole lists. */
#include "harness.h"

#include "analysis_fixture.h"

/* ------------------------------------------------------------ list texts */
/* One line per path: "bonds ends kind class order" (order "-" at a source). */
static const char *path_line(const fx *f, int p) {
  static char buf[8][600];
  static int k;
  const bg_model *m = f->m;
  const bg_analysis *a = &f->a;
  char *s = buf[k++ % 8], ord[16];
  if (a->path_order[p] == BG_PATH_ORDER_NONE) snprintf(ord, sizeof ord, "-");
  else snprintf(ord, sizeof ord, "%d", a->path_order[p]);
  snprintf(s, 600, "%s %s-%s %s %d %s", fx_bonds(m, a->path_bonds + a->path_adr[p], a->path_n[p]),
           m->elem_name[a->path_end0[p]], m->elem_name[a->path_end1[p]], a->path_kind[p],
           a->path_class[p], ord);
  return s;
}

static void check_paths(const fx *f, const char **want, int n) {
  INT_EQ(f->a.npath, n);
  INT_EQ(f->a.npath_omitted, 0);
  for (int i = 0; i < n && i < f->a.npath; i++) STR_EQ(path_line(f, i), want[i]);
}

/* The zero-order paths between non-source ends, in list order. */
static void check_zero_order(const fx *f, const char **want, int n) {
  int k = 0;
  for (int p = 0; p < f->a.npath; p++) {
    if (f->a.path_order[p] != 0) continue;
    if (k < n) STR_EQ(path_line(f, p), want[k]);
    k++;
  }
  INT_EQ(k, n);
}

static const char *cloop_bonds(const fx *f, int l) {
  return fx_bonds(f->m, f->a.cloop_bonds + f->a.cloop_adr[l], f->a.cloop_n[l]);
}

/* ------------------------------------------------------------ hand-built model */
/* Series RLC: Se U -> 1 j; j -> R1, j -> L1, j -> C1, strokes as SCAP sets them. */
static void test_hand_rlc(void) {
  bg_model m;
  memset(&m, 0, sizeof m);
  static int kind[] = {BG_ELEM_SE, BG_ELEM_J1, BG_ELEM_R, BG_ELEM_I, BG_ELEM_C};
  static const char *name[] = {"U", "j", "R1", "L1", "C1"};
  static int bondadr[] = {0, 1, 5, 6, 7}, nbond[] = {1, 4, 1, 1, 1};
  static int bonds[] = {0, 0, 1, 2, 3, 1, 2, 3};
  static int expr[] = {-1, -1, -1, -1, -1}, form[] = {1, 0, 1, 1, 1}, init[] = {-1, -1, -1, -1, -1};
  static int num[] = {1, 2, 3, 4}, tail[] = {0, 1, 1, 1}, head[] = {1, 2, 3, 4};
  m.nelem = 5; m.nbond = 4; m.nbondref = 8;
  m.elem_kind = kind; m.elem_name = name; m.elem_bondadr = bondadr; m.elem_nbond = nbond;
  m.elem_bonds = bonds; m.elem_expr = expr; m.elem_form = form; m.elem_init = init;
  m.bond_num = num; m.bond_tail = tail; m.bond_head = head;
  bg_analysis a;
  fx_init_analysis(&a, &m);
  a.complete = 1;
  int stroke[] = {BG_STROKE_HEAD, BG_STROKE_TAIL, BG_STROKE_HEAD, BG_STROKE_TAIL};
  memcpy(a.bond_stroke, stroke, sizeof stroke);
  bg_paths_find(&m, &a, 0);
  bg_cloops_find(&m, &a, 0);
  fx f = {NULL, &m, a, {0}, NULL};
  const char *want[] = {"1,3 U-L1 S-* 0 -", "2,3 R1-L1 I-R 0 1", "3,4 L1-C1 C-I 0 2"};
  check_paths(&f, want, 3);
  INT_EQ(a.ncloop, 0);
  OK(bg_paths_store_integral(&m, &a, 3));
  OK(bg_paths_store_integral(&m, &a, 4));
  /* a cap of 1 lists the first path found and counts the rest */
  bg_paths_find(&m, &a, 1);
  INT_EQ(a.npath, 1);
  INT_EQ(a.npath_omitted, 2);
  bg_arena_free(&a.arena);
}

/* ------------------------------------------------------------ examples */
static void test_rlc(void) {
  fx f;
  if (fx_load(&f, "rlc", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  const char *want[] = {"1,3 U-L1 S-* 0 -", "2,3 R1-L1 I-R 0 1", "3,4 L1-C1 C-I 0 2"};
  check_paths(&f, want, 3);
  INT_EQ(f.a.ncloop, 0);
  fx_free(&f);
}

static void test_hydraulic_bridge(void) {
  fx f;
  if (fx_load(&f, "hydraulic_bridge", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  /* each path is listed from the end with the lower port bond number:
   * {4,5,6} from R4 to R3, as the reference writes it */
  const char *want[] = {"1,2,8,7 R1-pS S-* 0 -",   "6,9,7 R3-pS S-* 0 -",
                        "7,8,2,10,11,12 pS-mp S-* 0 -", "1,2,3 R1-R2 R-R 2 0",
                        "3,2,10,11,12 R2-mp I-R 0 1",  "4,5,6 R4-R3 R-R 2 0",
                        "4,14,13,12 R4-mp I-R 0 1",    "12,15 mp-Rb I-R 0 1"};
  check_paths(&f, want, 8);
  const char *zero[] = {"1,2,3 R1-R2 R-R 2 0", "4,5,6 R4-R3 R-R 2 0"};
  check_zero_order(&f, zero, 2);
  INT_EQ(f.a.ncloop, 0);
  fx_free(&f);
}

static void test_slider_crank(void) {
  fx f;
  if (fx_load(&f, "slider_crank", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  const char *zero[] = {"2,4,3,5 J-m I-I 1 0"};
  check_zero_order(&f, zero, 1);
  INT_EQ(f.a.ncloop, 0);
  fx_free(&f);
}

/* The chapter names {1,2,3,4} and {5,2,6,7,8}; by the definition there is a
 * second C1-C2 path through the transformer, {1,2,6,7,10,4} (Equation
 * 4.31c: e4 = (n - 1)(e1 + e5) adds both routes). */
static void test_class12(void) {
  fx f;
  if (fx_load(&f, "class12_paths", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  const char *zero[] = {"1,2,3,4 C1-C2 C-C 1 0", "1,2,6,7,10,4 C1-C2 C-C 1 0",
                        "5,2,6,7,8 R1-R2 R-R 2 0"};
  check_zero_order(&f, zero, 3);
  INT_EQ(f.a.ncloop, 0);
  /* the class 1 and class 2 paths share bond 2 */
  int share = 0;
  for (int i = 0; i < f.a.path_n[2]; i++)
    for (int k = 0; k < f.a.path_n[7]; k++)
      share += f.a.path_bonds[f.a.path_adr[2] + i] == f.a.path_bonds[f.a.path_adr[7] + k];
  INT_EQ(share, 1);
  fx_free(&f);
  /* without the fixed stroke: a causal loop of gain n through {3,6,7,10} */
  if (fx_load(&f, "class12_paths", BG_METHOD_SCAP, NULL, 0, "jB |-> R1", "jB -> R1")) { OK(0); return; }
  INT_EQ(f.a.ncloop, 1);
  if (f.a.ncloop == 1) {
    STR_EQ(cloop_bonds(&f, 0), "3,6,7,10");
    STR_EQ(f.a.cloop_gain[0], "n");
    DBL_NEAR(f.a.cloop_gain_value[0], 2.0, 1e-12);
    INT_EQ(f.a.cloop_class[0], 4);
  }
  check_zero_order(&f, NULL, 0);
  fx_free(&f);
}

static void test_loop_class1(void) {
  fx f;
  if (fx_load(&f, "loop_class1", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  const char *zero[] = {"1,2,3,4,5 C1-C2 C-C 1 0", "1,2,6,7,9,5 C1-C2 C-C 1 0"};
  check_zero_order(&f, zero, 2);
  INT_EQ(f.a.ncloop, 1);
  if (f.a.ncloop == 1) {
    STR_EQ(cloop_bonds(&f, 0), "2,6,7,8");
    STR_EQ(f.a.cloop_gain[0], "n1");
    DBL_NEAR(f.a.cloop_gain_value[0], 2.0, 1e-12);
    INT_EQ(f.a.cloop_class[0], 4);
  }
  fx_free(&f);
}

static void test_bond_loop(void) {
  fx f;
  if (fx_load(&f, "bond_loop", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  INT_EQ(f.a.ncloop, 1);
  if (f.a.ncloop == 1) {
    STR_EQ(cloop_bonds(&f, 0), "1,2,3,4");
    STR_EQ(f.a.cloop_gain[0], "n");
    DBL_NEAR(f.a.cloop_gain_value[0], 2.0, 1e-12);
    INT_EQ(f.a.cloop_class[0], 4);
  }
  OK(f.a.cloops_disjoint);
  OK(f.a.rosenberg_andry);
  check_zero_order(&f, NULL, 0);
  fx_free(&f);
  /* n = 1: gain +1, class 5 */
  if (fx_load(&f, "bond_loop", BG_METHOD_SCAP, "n", 1.0, NULL, NULL)) { OK(0); return; }
  INT_EQ(f.a.ncloop, 1);
  if (f.a.ncloop == 1) {
    DBL_NEAR(f.a.cloop_gain_value[0], 1.0, 1e-12);
    INT_EQ(f.a.cloop_class[0], 5);
  }
  OK(!f.a.rosenberg_andry);
  fx_free(&f);
  /* bond 2 reversed: gain -n */
  if (fx_load(&f, "bond_loop", BG_METHOD_SCAP, NULL, 0, "bond 2 jB -> jC", "bond 2 jC -> jB")) {
    OK(0);
    return;
  }
  INT_EQ(f.a.ncloop, 1);
  if (f.a.ncloop == 1) {
    STR_EQ(f.a.cloop_gain[0], "-n");
    DBL_NEAR(f.a.cloop_gain_value[0], -2.0, 1e-12);
    INT_EQ(f.a.cloop_class[0], 4);
  }
  fx_free(&f);
}

static void test_delta(void) {
  fx f;
  if (fx_load(&f, "delta", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  INT_EQ(f.a.ncloop, 1);
  if (f.a.ncloop == 1) {
    STR_EQ(cloop_bonds(&f, 0), "2,3,8,9,6,5"); /* the six internal bonds, in loop order */
    STR_EQ(f.a.cloop_gain[0], "1");
    DBL_NEAR(f.a.cloop_gain_value[0], 1.0, 1e-12);
    INT_EQ(f.a.cloop_class[0], 5);
  }
  OK(!f.a.rosenberg_andry);
  check_zero_order(&f, NULL, 0);
  fx_free(&f);
}

/* Van Dijk's modification (Figure 4.20): no causal loop, one class 1 path
 * between the inductors, two class 2 paths between resistors. */
static void test_delta_vandijk(void) {
  fx f;
  if (fx_load(&f, "delta", BG_METHOD_VANDIJK, NULL, 0, NULL, NULL)) { OK(0); return; }
  INT_EQ(f.a.ncloop, 0);
  const char *zero[] = {"4,2,5,6,9,10 R1-R3 R-R 2 0", "7,6,9,10 R2-R3 R-R 2 0",
                        "11,3,2,5,6,12 L1-L2 I-I 1 0"};
  check_zero_order(&f, zero, 3);
  fx_free(&f);
}

/* ------------------------------------------------------------ small models from text */
static int fx_text(fx *f, const char *text, int method) {
  memset(f, 0, sizeof *f);
  f->src = bg_xmalloc(strlen(text) + 1);
  strcpy(f->src, text);
  size_t len = strlen(text);
  bg_diags_init(&f->dg, "test.bg", f->src, len);
  bg_ast *ast = bg_parse_string("test.bg", f->src, len, &f->dg);
  if (ast && !f->dg.nerrors) f->m = bg_model_compile(ast, NULL, 0, &f->dg);
  if (ast) bg_ast_free(ast);
  if (!f->m) { bg_diags_print(&f->dg, stderr); return -1; }
  fx_init_analysis(&f->a, f->m);
  bg_causality_assign(f->m, method, &f->a, &f->dg);
  bg_analysis_run(f->m, &f->a, NULL);
  return 0;
}

#define TEXT(f, text, method)                                                  \
  if (fx_text(&f, text, method)) { OK(0); return; }

static const char *joined(char **v, int n) {
  static char buf[4][512];
  static int k;
  char *s = buf[k++ % 4];
  s[0] = 0;
  for (int i = 0; i < n; i++) snprintf(s + strlen(s), 512 - strlen(s), "%s%s", i ? " " : "", v[i]);
  return s;
}

/* Two effort sources on one 0-junction: a type 2 conflict of degree 1 that
 * no unknown resolves (E1 = E2 is a constraint on inputs): index above 1.
 * No causal path joins the sources (both strokes at j); c is dependent. */
static void test_two_effort_sources(void) {
  fx f;
  TEXT(f, "model two_se\nSe E1 = 1\nSe E2 = 2\n0 j\nC c = 1\n"
          "bond 1 E1 -> j\nbond 2 E2 -> j\nbond 3 j -> c\n", BG_METHOD_SCAP);
  INT_EQ(f.a.nconflict, 1);
  const char *want[] = {"1,3 E1-c S-* 0 -", "2,3 E2-c S-* 0 -"};
  check_paths(&f, want, 2);
  INT_EQ(f.a.form, BG_FORM_DAE);
  INT_EQ(f.a.index_predicted, 2);
  OK(strstr(f.a.index_reason, "type 2 conflict at j") != NULL);
  STR_EQ(joined(f.a.dependent_stores, f.a.ndependent), "c");
  fx_free(&f);
}

/* Two I stores on one 1-junction: the second is dependent, one class 1
 * path; the source's effort and L2's both enter j: no E-L2 path. */
static void test_two_inertias(void) {
  fx f;
  TEXT(f, "model two_i\nSe E = 1\n1 j\nI L1 = 1\nI L2 = 2\n"
          "bond 1 E -> j\nbond 2 j -> L1\nbond 3 j -> L2\n", BG_METHOD_SCAP);
  const char *want[] = {"1,2 E-L1 S-* 0 -", "2,3 L1-L2 I-I 1 0"};
  check_paths(&f, want, 2);
  INT_EQ(f.a.ncloop, 0);
  STR_EQ(joined(f.a.states, f.a.nstates), "L1.p");
  STR_EQ(joined(f.a.dependent_stores, f.a.ndependent), "L2");
  INT_EQ(f.a.form, BG_FORM_DAE);
  INT_EQ(f.a.index_predicted, 1);
  fx_free(&f);
}

/* A chain of three gyrators: a causal path passes a GY with both strokes
 * on the same side; the source's effort reaches the 1-junction as a flow
 * (odd count), so L is dependent and L-R is no path (both strokes at j). */
static void test_gyrator_chain(void) {
  fx f;
  TEXT(f, "model gys\nSe E = 1\nGY g1 = 2\nGY g2 = 3\nGY g3 = 5\nI L = 1\nR R = 1\n1 j\n"
          "bond 1 E -> g1\nbond 2 g1 -> g2\nbond 3 g2 -> g3\nbond 4 g3 -> j\n"
          "bond 5 j -> L\nbond 6 j -> R\n", BG_METHOD_SCAP);
  INT_EQ(f.a.nconflict, 0);
  const char *want[] = {"1,2,3,4,5 E-L S-* 0 -", "1,2,3,4,6 E-R S-* 0 -"};
  check_paths(&f, want, 2);
  STR_EQ(joined(f.a.dependent_stores, f.a.ndependent), "L");
  INT_EQ(f.a.nstates, 0);
  fx_free(&f);
  /* two gyrators between a C and an R: a first-order path; its flat loop
   * has gain r2^2/(r1^2 R C s), so tau = r1^2 R C / r2^2 = 4*5*1/9 */
  TEXT(f, "model gys2\nSf F = 1\n0 a\nC c = 1\nGY g1 = 2\nGY g2 = 3\nR R = 5\n"
          "bond 1 F -> a\nbond 2 a -> c\nbond 3 a -> g1\nbond 4 g1 -> g2\nbond 5 g2 -> R\n",
       BG_METHOD_SCAP);
  const char *want2[] = {"1,2 F-c S-* 0 -", "2,3,4,5 c-R C-R 0 1"};
  check_paths(&f, want2, 2);
  INT_EQ(f.a.nestimate, 1);
  if (f.a.nestimate == 1) DBL_NEAR(f.a.estimate_value[0], 4.0 * 5.0 / 9.0, 1e-12 * 20 / 9.0);
  fx_free(&f);
}

/* A bond loop through one gyrator cannot close a causal path: each bond has
 * its stroke at one end, a junction or TF on the loop takes exactly one of
 * the loop's strokes, a GY none or two, so a closed causal path passes an
 * even number of gyrators. SCAP either propagates into the loop without a
 * causal loop or, where it must choose, meets a conflict it records. */
static void test_gyrator_mesh(void) {
  fx f;
  TEXT(f, "model mesh1\nSf F = 1\n0 a\n1 b\nGY g = 2\nC c = 1\nI l = 1\n"
          "bond 1 F -> a\nbond 2 a -> b\nbond 3 b -> g\nbond 4 g -> a\nbond 5 a -> c\n"
          "bond 6 b -> l\n", BG_METHOD_SCAP);
  INT_EQ(f.a.ncloop, 0);
  INT_EQ(f.a.nconflict, 0);
  /* c's effort reaches l as a flow through the gyrator: l is dependent and
   * c-l is a zero-order path between an independent and a dependent store
   * (class 1 through an odd number of gyrators), flat loop gain -l/(r^2 c) */
  const char *want[] = {"1,5 F-c S-* 0 -", "5,4,3,6 c-l C-I 1 0"};
  check_paths(&f, want, 2);
  STR_EQ(joined(f.a.dependent_stores, f.a.ndependent), "l");
  INT_EQ(f.a.ntloop, 1);
  if (f.a.ntloop == 1) {
    INT_EQ(f.a.tloop_algebraic[0], 1);
    DBL_NEAR(f.a.tloop_gain_value[0], -0.25, 1e-12);
  }
  INT_EQ(f.a.index_predicted, 1);
  fx_free(&f);
  TEXT(f, "model mesh1b\nSf F = 1\n0 a\n1 b\nGY g = 2\nI l = 1\nC c = 1\n"
          "bond 1 F -> a\nbond 2 a -> b\nbond 3 b -> g\nbond 4 g -> a\nbond 5 a -> l\n"
          "bond 6 b -> c\n", BG_METHOD_SCAP);
  /* stores swapped: SCAP must choose at bond 2 and neither stroke is
   * consistent: a type 1 conflict at b whose effort balance turns out not to
   * depend on b's flow (it enters twice through g, with opposite signs):
   * index above 1 (the numeric index is 2) */
  INT_EQ(f.a.ncloop, 0);
  INT_EQ(f.a.nconflict, 1);
  if (f.a.nconflict == 1) INT_EQ(f.a.conflict_type[0], 1);
  INT_EQ(f.a.form, BG_FORM_DAE);
  STR_EQ(joined(f.a.algebraic_variables, f.a.nalgebraic), "c.f");
  INT_EQ(f.a.index_predicted, 2);
  fx_free(&f);
  /* through two gyrators the loop closes: gain r2/r1 on both open loops,
   * class 4 (an even number of gyrators, so not a mesh) */
  TEXT(f, "model mesh2\nparam r1 = 2, r2 = 3\nSf F = 1\n0 jA\n1 jB\n0 jC\nC Cs = 1\n"
          "I Is = 1\nGY g1 = r1\nGY g2 = r2\nbond 1 jA -> jB\nbond 2 jB -> jC\n"
          "bond 3 jC -> g1\nbond 4 g1 -> g2\nbond 5 g2 -> jA\nbond 6 F -> jA\n"
          "bond 7 jB -> Cs\nbond 8 jC -> Is\n", BG_METHOD_SCAP);
  INT_EQ(f.a.ncloop, 1);
  if (f.a.ncloop == 1) {
    STR_EQ(cloop_bonds(&f, 0), "1,2,3,4,5");
    STR_EQ(f.a.cloop_gain[0], "r2/r1");
    DBL_NEAR(f.a.cloop_gain_value[0], 1.5, 1e-12);
    INT_EQ(f.a.cloop_class[0], 4);
  }
  int nopen = 0;
  for (int t = 0; t < f.a.ntloop; t++)
    if (f.a.tloop_kind[t] == BG_TLOOP_OPEN) {
      nopen++;
      DBL_NEAR(f.a.tloop_gain_value[t], 1.5, 1e-12);
    }
  INT_EQ(nopen, 2);
  OK(f.a.rosenberg_andry);
  INT_EQ(f.a.index_predicted, 1);
  fx_free(&f);
}

/* The other places a causal mesh (Remark 4.8) was looked for; none closes a
 * causal path through an odd number of gyrators (docs/analysis.md, "Causal
 * meshes"). */
static void test_gyrator_rings(void) {
  fx f;
  /* a ring of three gyrators between three junctions: ca's effort
   * propagates around the whole ring; at a both ring bonds are weak, so the
   * bond loop is no causal path. ca-lb passes one gyrator (C-I, class 1),
   * ca-cc two (C-C, class 1) */
  TEXT(f, "model ring3\nSf F = 1\n0 a\n1 b\n0 c\nGY g1 = 2\nGY g2 = 3\nGY g3 = 5\n"
          "C ca = 1\nI lb = 1\nC cc = 1\nbond 1 F -> a\nbond 2 a -> g1\nbond 3 g1 -> b\n"
          "bond 4 b -> g2\nbond 5 g2 -> c\nbond 6 c -> g3\nbond 7 g3 -> a\nbond 8 a -> ca\n"
          "bond 9 b -> lb\nbond 10 c -> cc\n", BG_METHOD_SCAP);
  INT_EQ(f.a.ncloop, 0);
  INT_EQ(f.a.nconflict, 0);
  const char *ring3[] = {"1,8 F-ca S-* 0 -", "8,2,3,9 ca-lb C-I 1 0", "8,2,3,4,5,10 ca-cc C-C 1 0"};
  check_paths(&f, ring3, 3);
  STR_EQ(joined(f.a.dependent_stores, f.a.ndependent), "lb cc");
  fx_free(&f);
  /* one gyrator closing a loop of two junctions, resistors only: the bond
   * loop is no causal path (at b both loop bonds are weak), but the
   * order-0 subgraph has two open loops around it through rb's relation
   * with gains -rb/r = -3/2 (e2 e4 f3 f6 e6) and +rb/r = +3/2 (f2 f6 e6 e3
   * f4): equal magnitude, opposite signs, like Brown's neutral mesh, yet
   * not closed causal paths; and the class 2 path ra-rb through the
   * gyrator, flat loop gain -ra*rb/r^2 = -3/4 */
  TEXT(f, "model ring1\nSe E = 1\n1 a\n0 b\nGY g = 2\nR ra = 1\nR rb = 3\n"
          "bond 1 E -> a\nbond 2 a -> b\nbond 3 b -> g\nbond 4 g -> a\nbond 5 a -> ra\n"
          "bond 6 b -> rb\n", BG_METHOD_SCAP);
  INT_EQ(f.a.ncloop, 0);
  INT_EQ(f.a.nconflict, 0);
  const char *ring1[] = {"1,4,3,6 E-rb S-* 0 -", "5,4,3,6 ra-rb R-R 2 0"};
  check_paths(&f, ring1, 2);
  INT_EQ(f.a.ntloop, 3);
  if (f.a.ntloop == 3) {
    DBL_NEAR(f.a.tloop_gain_value[0], -0.75, 1e-12);
    DBL_NEAR(f.a.tloop_gain_value[1], -1.5, 1e-12);
    DBL_NEAR(f.a.tloop_gain_value[2], 1.5, 1e-12);
    INT_EQ(f.a.tloop_kind[1], BG_TLOOP_OPEN);
    INT_EQ(f.a.tloop_kind[2], BG_TLOOP_OPEN);
  }
  fx_free(&f);
  /* a gyrator between two junctions of one bond loop (a chord a-g-c of the
   * loop a-b-c-d): SCAP must choose at bond 2, and neither orientation is
   * consistent: a type 1 conflict at b, no causal loop */
  TEXT(f, "model chord\nSf F = 1\n0 a\n1 b\n0 c\n1 d\nGY g = 2\nR r1 = 1\nR r2 = 2\n"
          "C cb = 1\nI ld = 1\nbond 1 F -> a\nbond 2 a -> b\nbond 3 b -> c\nbond 4 c -> d\n"
          "bond 5 d -> a\nbond 6 a -> g\nbond 7 g -> c\nbond 8 b -> cb\nbond 9 d -> ld\n"
          "bond 10 b -> r1\nbond 11 d -> r2\n", BG_METHOD_SCAP);
  INT_EQ(f.a.ncloop, 0);
  INT_EQ(f.a.nconflict, 1);
  if (f.a.nconflict == 1) {
    INT_EQ(f.a.conflict_type[0], 1);
    STR_EQ(f.m->elem_name[f.a.conflict_node[0]], "b");
  }
  fx_free(&f);
}

/* No junction structure: a source directly on a store. */
static void test_empty_junction_structure(void) {
  fx f;
  TEXT(f, "model se_c\nSe E = 1\nC c = 1\nbond 1 E -> c\n", BG_METHOD_SCAP);
  const char *want[] = {"1 E-c S-* 0 -"};
  check_paths(&f, want, 1);
  INT_EQ(f.a.ncloop, 0);
  INT_EQ(f.a.ntloop, 0);
  STR_EQ(joined(f.a.dependent_stores, f.a.ndependent), "c");
  INT_EQ(f.a.nstates, 0);
  INT_EQ(f.a.form, BG_FORM_DAE);
  INT_EQ(f.a.index_predicted, 1);
  fx_free(&f);
  TEXT(f, "model sf_c\nSf F = 1\nC c = 1\nbond 1 F -> c\n", BG_METHOD_SCAP);
  check_paths(&f, (const char *[]){"1 F-c S-* 0 -"}, 1);
  STR_EQ(joined(f.a.states, f.a.nstates), "c.q");
  INT_EQ(f.a.form, BG_FORM_ODE);
  INT_EQ(f.a.index_predicted, 0);
  fx_free(&f);
}

int main(void) {
  test_two_effort_sources();
  test_two_inertias();
  test_gyrator_chain();
  test_gyrator_mesh();
  test_gyrator_rings();
  test_empty_junction_structure();
  test_hand_rlc();
  test_rlc();
  test_hydraulic_bridge();
  test_slider_crank();
  test_class12();
  test_loop_class1();
  test_bond_loop();
  test_delta();
  test_delta_vandijk();
  return bg_t_done();
}
