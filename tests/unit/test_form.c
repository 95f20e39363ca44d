/* States, form, predicted index, algebraic variables and estimates of the
 * reference examples (EXAMPLES.md), plus the incomplete case. */
#include "harness.h"

/* Loads examples/NAME.bg, assigns causality with `method` and runs the
 * analysis. The per-bond/per-element arrays causality needs are allocated
 * here so the test does not depend on where bg_analysis_init lives. */
#include <stdlib.h>
#include "causality.h"
#include "expr.h"
#include "parse.h"
#include "paths.h"
#include "sfg.h"

typedef struct fx {
  bg_model *m;
  bg_analysis a;
  bg_diags dg;
  char *src;
} fx;

static void fx_init_analysis(bg_analysis *a, const bg_model *m) {
  memset(a, 0, sizeof *a);
  size_t nb = (size_t)m->nbond + 1, ne = (size_t)m->nelem + 1;
  a->bond_stroke = bg_arena_alloc(&a->arena, nb * sizeof(int));
  a->bond_reason = bg_arena_alloc(&a->arena, nb * sizeof(int));
  a->bond_step = bg_arena_alloc(&a->arena, nb * sizeof(int));
  a->bond_conflict = bg_arena_alloc(&a->arena, nb * sizeof(int));
  a->elem_caus = bg_arena_alloc(&a->arena, ne * sizeof(int));
  a->elem_inverted = bg_arena_alloc(&a->arena, ne * sizeof(int));
  a->index_predicted = -1;
}

/* edit: optional (from, to) text replacement in the source, for variants */
static int fx_load(fx *f, const char *name, int method, const char *set_name, double set_value,
                   const char *from, const char *to) {
  char path[512];
  size_t len;
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  memset(f, 0, sizeof *f);
  f->src = bg_read_file(path, &len);
  if (!f->src) { fprintf(stderr, "cannot read %s\n", path); return -1; }
  if (from) {
    char *p = strstr(f->src, from);
    if (!p) { fprintf(stderr, "%s: no '%s'\n", name, from); return -1; }
    size_t nf = strlen(from), nt = strlen(to);
    char *s = bg_xmalloc(len - nf + nt + 1);
    memcpy(s, f->src, (size_t)(p - f->src));
    memcpy(s + (p - f->src), to, nt);
    strcpy(s + (p - f->src) + nt, p + nf);
    free(f->src);
    f->src = s;
    len = strlen(s);
  }
  bg_diags_init(&f->dg, path, f->src, len);
  bg_ast *ast = bg_parse_string(path, f->src, len, &f->dg);
  bg_param_override ov = {set_name, set_value};
  if (ast && !f->dg.nerrors) f->m = bg_model_compile(ast, &ov, set_name ? 1 : 0, &f->dg);
  if (ast) bg_ast_free(ast);
  if (!f->m) { bg_diags_print(&f->dg, stderr); return -1; }
  fx_init_analysis(&f->a, f->m);
  bg_causality_assign(f->m, method, &f->a, &f->dg);
  bg_analysis_run(f->m, &f->a, NULL);
  return 0;
}

static void fx_free(fx *f) {
  bg_arena_free(&f->a.arena);
  if (f->m) bg_model_free(f->m);
  bg_diags_free(&f->dg);
  free(f->src);
}

/* "1,2,3" from bond numbers of a list */
__attribute__((unused)) static const char *fx_bonds(const bg_model *m, const int *b, int n) {
  static char buf[4][512];
  static int k;
  char *s = buf[k++ % 4];
  s[0] = 0;
  for (int i = 0; i < n; i++)
    snprintf(s + strlen(s), 512 - strlen(s), "%s%d", i ? "," : "", m->bond_num[b[i]]);
  return s;
}

__attribute__((unused)) static const char *fx_sigs(const bg_model *m, const int *sig, int n) {
  static char buf[4][1024];
  static int k;
  char *s = buf[k++ % 4], nm[96];
  s[0] = 0;
  for (int i = 0; i < n; i++) {
    bg_sfg_node_name(m, sig[i], nm, sizeof nm);
    snprintf(s + strlen(s), 1024 - strlen(s), "%s%s", i ? " " : "", nm);
  }
  return s;
}

__attribute__((unused)) static void fx_dump(const fx *f) {
  const bg_model *m = f->m;
  const bg_analysis *a = &f->a;
  printf("== %s complete=%d\n", m->name, a->complete);
  for (int b = 0; b < m->nbond; b++) printf(" b%d:%s", m->bond_num[b], a->bond_stroke[b] == 1 ? "H" : a->bond_stroke[b] == 2 ? "T" : "-");
  printf("\n");
  for (int p = 0; p < a->npath; p++)
    printf(" path %d: {%s} %s-%s %s class %d order %d\n", p + 1,
           fx_bonds(m, a->path_bonds + a->path_adr[p], a->path_n[p]), m->elem_name[a->path_end0[p]],
           m->elem_name[a->path_end1[p]], a->path_kind[p], a->path_class[p], a->path_order[p]);
  for (int l = 0; l < a->ncloop; l++)
    printf(" cloop %d: {%s} gain %s = %g class %d mesh %d\n", l + 1,
           fx_bonds(m, a->cloop_bonds + a->cloop_adr[l], a->cloop_n[l]), a->cloop_gain[l],
           a->cloop_gain_value[l], a->cloop_class[l], a->cloop_mesh[l]);
  for (int t = 0; t < a->ntloop; t++)
    printf(" tloop %d: %s order %d [%s] gain %s = %g alg %d cause %s\n", t + 1,
           a->tloop_kind[t] ? "open" : "flat", a->tloop_order[t],
           fx_sigs(m, a->tloop_signals + a->tloop_adr[t], a->tloop_n[t]), a->tloop_gain[t],
           a->tloop_gain_value[t], a->tloop_algebraic[t], a->tloop_cause[t]);
  printf(" states:");
  for (int i = 0; i < a->nstates; i++) printf(" %s", a->states[i]);
  printf("\n dependent:");
  for (int i = 0; i < a->ndependent; i++) printf(" %s", a->dependent_stores[i]);
  printf("\n algebraic:");
  for (int i = 0; i < a->nalgebraic; i++) printf(" %s", a->algebraic_variables[i]);
  printf("\n form %d index %d (%s) pdep %d disjoint %d RA %d\n", a->form, a->index_predicted,
         a->index_reason, a->form_parameter_dependent, a->cloops_disjoint, a->rosenberg_andry);
  for (int i = 0; i < a->nestimate; i++)
    printf(" estimate %s path %d = %g\n", a->estimate_kind[i] ? "omega" : "tau", a->estimate_path[i] + 1,
           a->estimate_value[i]);
}

static const char *join(char **v, int n) {
  static char buf[4][512];
  static int k;
  char *s = buf[k++ % 4];
  s[0] = 0;
  for (int i = 0; i < n; i++) snprintf(s + strlen(s), 512 - strlen(s), "%s%s", i ? " " : "", v[i]);
  return s;
}

/* form, index, states, dependent stores, algebraic variables */
static void check(const char *name, int method, const char *set, double val, int form, int index,
                  const char *states, const char *dep, const char *alg) {
  fx f;
  if (fx_load(&f, name, method, set, val, NULL, NULL)) { OK(0); return; }
  INT_EQ(f.a.form, form);
  INT_EQ(f.a.index_predicted, index);
  STR_EQ(join(f.a.states, f.a.nstates), states);
  STR_EQ(join(f.a.dependent_stores, f.a.ndependent), dep);
  if (alg) STR_EQ(join(f.a.algebraic_variables, f.a.nalgebraic), alg);
  OK(f.a.index_reason && f.a.index_reason[0]);
  fx_free(&f);
}

static void reason_has(const char *name, int method, const char *set, double val, const char *text) {
  fx f;
  if (fx_load(&f, name, method, set, val, NULL, NULL)) { OK(0); return; }
  BG_T_REPORT(strstr(f.a.index_reason, text) != NULL, "%s: reason \"%s\" lacks \"%s\"", name,
              f.a.index_reason, text);
  fx_free(&f);
}

static void test_forms(void) {
  const int S = BG_METHOD_SCAP, ODE = BG_FORM_ODE, DAE = BG_FORM_DAE;
  check("rlc", S, NULL, 0, ODE, 0, "L1.p C1.q", "", "");
  check("hydraulic_bridge", S, NULL, 0, DAE, 1, "mp.p", "", "R1.f R2.e R3.f R4.e");
  check("bridge_compliance", S, NULL, 0, ODE, 0, "mp.p C1.q C2.q", "", "");
  check("slider_crank", S, NULL, 0, DAE, 1, "J.p phi", "m", "");
  check("bond_loop", S, NULL, 0, DAE, 1, "Cs.q Is.p", "", "e4 f3");
  check("bond_loop", S, "n", 1, DAE, 2, "Cs.q Is.p", "", "e4 f3");
  check("class12_paths", S, NULL, 0, DAE, 1, "C1.q", "C2", "R1.e R2.f");
  check("loop_class1", S, NULL, 0, DAE, 2, "C1.q L.p", "C2", "e7 f6");
  check("delta", S, NULL, 0, DAE, 2, "L1.p L2.p", "", "e2 f5");
  check("delta", BG_METHOD_VANDIJK, NULL, 0, DAE, 1, "L2.p", "L1", "R1.e R3.f R2.e");
  /* relaxed causality: the conflicts' algebraic state variables (Section
   * 4.9): the effort of the nonlinear conductance at each type 1 conflict at
   * a 0-junction (Equations 4.51), the efforts of the k violating
   * conductances of a type 2 conflict of degree k at a 1-junction */
  check("hydraulic_bridge", BG_METHOD_RELAXED, NULL, 0, DAE, 1, "mp.p", "", "R1.e R4.e");
  check("series_conductances", BG_METHOD_RELAXED, NULL, 0, DAE, 1, "Cl.q", "", "Rb.e Rc.e");
  check("parallel_conductance", BG_METHOD_RELAXED, NULL, 0, DAE, 1, "Lk.p", "", "Rg.e");
  /* SCAP inverts Rg's law instead: an implicit algebraic equation */
  check("parallel_conductance", S, NULL, 0, DAE, 1, "Lk.p", "", "Rg.e");
  reason_has("parallel_conductance", S, NULL, 0, "inverted resistor law solved implicitly (Rg)");
  check("internal_mod_tf", S, NULL, 0, DAE, 1, "Cj.q", "", "f2");
  check("internal_mod_r", S, NULL, 0, DAE, 1, "Cs.q", "", "Ra.f");
  check("mod_no_loop", S, NULL, 0, ODE, 0, "Cp.q", "", "");
  check("series_motor", S, NULL, 0, DAE, 1, "J.p", "", "e3");
  check("series_motor_L", S, NULL, 0, ODE, 0, "J.p La.p", "", "");
  check("modulated_source", S, NULL, 0, DAE, 1, "Cc.q", "", "U.e");
  reason_has("loop_class1", S, NULL, 0, "Proposition 5.10");
  reason_has("delta", S, NULL, 0, "gain +1");
  reason_has("bond_loop", S, "n", 1, "gain +1");
  reason_has("modulated_source", S, NULL, 0, "Equation 4.45");
  reason_has("hydraulic_bridge", S, NULL, 0, "class 2");
}

/* estimates: kind, path (1-based) and value, exactly */
static void check_estimates(const char *name, const int (*kp)[2], const double *v, int n) {
  fx f;
  if (fx_load(&f, name, BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  INT_EQ(f.a.nestimate, n);
  for (int i = 0; i < n && i < f.a.nestimate; i++) {
    INT_EQ(f.a.estimate_kind[i], kp[i][0]);
    INT_EQ(f.a.estimate_path[i] + 1, kp[i][1]);
    DBL_NEAR(f.a.estimate_value[i], v[i], 1e-12 * v[i]);
  }
  fx_free(&f);
}

static void test_estimates(void) {
  /* rlc: L1-R1 tau = L0/R0, L1-C1 omega = 1/sqrt(L0 C0) */
  const int r[2][2] = {{0, 2}, {1, 3}};
  const double rv[2] = {1e-4, 1 / sqrt(1e-9)};
  check_estimates("rlc", r, rv, 2);
  /* bridge_compliance: C-mp omega0^2 = A^2/(Cc m0) (Equation 4.18); the
   * C-R time constants use the slopes of the orifice laws at e = 0 */
  fx f;
  if (fx_load(&f, "bridge_compliance", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  int nomega = 0;
  for (int i = 0; i < f.a.nestimate; i++) {
    if (f.a.estimate_kind[i] != 1) continue;
    nomega++;
    DBL_NEAR(f.a.estimate_value[i], sqrt(5e-4 * 5e-4 / (1e-13 * 10)), 1e-12 * 500);
    STR_EQ(f.a.path_kind[f.a.estimate_path[i]], "C-I");
  }
  INT_EQ(nomega, 2);
  /* R1 (conductance Kv (1 + u)/sqrt(pt) at e = 0, u = 0.2) with C1: tau = Cc/slope */
  DBL_NEAR(f.a.estimate_value[0], 1e-13 / (2e-8 * 1.2 / sqrt(1e5)), 1e-12 * f.a.estimate_value[0]);
  fx_free(&f);
}

static void test_incomplete(void) {
  fx f;
  if (fx_load(&f, "rlc", BG_METHOD_SCAP, NULL, 0, NULL, NULL)) { OK(0); return; }
  f.a.complete = 0;
  f.a.bond_stroke[1] = BG_STROKE_NONE;
  bg_analysis_run(f.m, &f.a, NULL);
  INT_EQ(f.a.form, BG_FORM_INCOMPLETE);
  INT_EQ(f.a.index_predicted, -1);
  INT_EQ(f.a.npath, 2); /* paths avoid the open bond */
  fx_free(&f);
}

/* delta with R1 in conductance causality (Figure 4.17): the type 1 conflict
 * at nC has the cut-set law as its balance (iL2 = Is - iL1: R1's flow enters
 * it twice with opposite signs), so its effort is not determined: above 1. */
static void test_conflict_index(void) {
  fx f;
  if (fx_load(&f, "delta", BG_METHOD_SCAP, NULL, 0, "R   R1 = R10", "R   R1 = R10 [causality = conductance]")) {
    OK(0);
    return;
  }
  INT_EQ(f.a.nconflict, 1);
  INT_EQ(f.a.index_predicted, 2);
  STR_EQ(f.a.index_reason, "type 1 conflict at nC: the balance of its flows does not depend on its "
                           "effort, so it constrains states or inputs: index above 1");
  STR_EQ(join(f.a.algebraic_variables, f.a.nalgebraic), "R1.f R2.e R3.e L2.e");
  fx_free(&f);
}

int main(void) {
  test_forms();
  test_conflict_index();
  test_estimates();
  test_incomplete();
  return bg_t_done();
}
