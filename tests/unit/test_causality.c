/* SPDX-License-Identifier: BSD-3-Clause */
/* Causality assignment: SCAP, relaxed, van Dijk, Lagrange on the reference
 * examples (docs/examples.md) and on small hand-made graphs. */
#include <stdlib.h>
#include <string.h>

#include "causality/causality.h"
#include "harness.h"
#include "lang/lang.h"
#include "base/strbuf.h"

/* ---------------------------------------------------------------- loading */
static bg_model *load_src(const char *path, const char *src) {
  bg_diags dg;
  bg_diags_init(&dg, path, src, strlen(src));
  bg_ast *ast = bg_parse_string(path, src, strlen(src), &dg);
  bg_model *m = ast && !dg.nerrors ? bg_model_compile(ast, NULL, 0, &dg) : NULL;
  if (dg.nerrors) bg_diags_print(&dg, stderr);
  if (ast) bg_ast_free(ast);
  bg_diags_free(&dg);
  return m;
}

static char *example_src(const char *name) {
  char path[512];
  size_t len;
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  return bg_read_file(path, &len);
}

/* src with the first occurrence of `from` replaced by `to` (caller frees). */
static char *replace(const char *src, const char *from, const char *to) {
  const char *p = strstr(src, from);
  if (!p) {
    fprintf(stderr, "replace: '%s' not found\n", from);
    return strdup(src);
  }
  bg_strbuf sb = {0};
  bg_sb_putn(&sb, src, p - src);
  bg_sb_puts(&sb, to);
  bg_sb_puts(&sb, p + strlen(from));
  return sb.s;
}

typedef struct run {
  bg_model *m;
  bg_analysis a;
} run;

static int run_src(run *r, const char *src, int method) {
  r->m = load_src("test.bg", src);
  if (!r->m) return -1;
  bg_diags dg;
  bg_diags_init(&dg, "test.bg", NULL, 0);
  bg_analysis_init(&r->a, r->m);
  bg_causality_assign(r->m, method, &r->a, &dg);
  bg_diags_free(&dg);
  return 0;
}

/* Runs an example, optionally with one text replacement. */
static int run_example(run *r, const char *name, int method, const char *from, const char *to) {
  char *src = example_src(name);
  if (!src) return -1;
  if (from) {
    char *s2 = replace(src, from, to);
    free(src);
    src = s2;
  }
  int rc = run_src(r, src, method);
  free(src);
  return rc;
}

static void run_free(run *r) {
  if (!r->m) return;
  bg_analysis_free(&r->a);
  bg_model_free(r->m);
  r->m = NULL;
}

/* ---------------------------------------------------------------- queries */
static const char *caus(const run *r, const char *name) {
  int e = bg_model_find_elem(r->m, name);
  return e < 0 ? "(no such element)" : bg_caus_name(r->a.elem_caus[e]);
}

static int inverted(const run *r, const char *name) {
  int e = bg_model_find_elem(r->m, name);
  return e < 0 ? -1 : r->a.elem_inverted[e];
}

/* "1:R1 2:n1 ..." : for each bond in order, the element at its stroke. */
static char *strokes(const run *r) {
  static char buf[4096];
  bg_strbuf sb = {0};
  const bg_model *m = r->m;
  for (int b = 0; b < m->nbond; b++) {
    int s = r->a.bond_stroke[b];
    const char *at = s == BG_STROKE_HEAD ? m->elem_name[m->bond_head[b]]
                     : s == BG_STROKE_TAIL ? m->elem_name[m->bond_tail[b]] : "-";
    bg_sb_printf(&sb, "%s%d:%s", b ? " " : "", m->bond_num[b], at);
  }
  snprintf(buf, sizeof buf, "%s", bg_sb_str(&sb));
  bg_sb_free(&sb);
  return buf;
}

/* "type 1 at n1 [1,2,10]; type 2/2 at j [2,3,4]" */
static char *conflicts(const run *r) {
  static char buf[4096];
  bg_strbuf sb = {0};
  const bg_analysis *a = &r->a;
  for (int i = 0; i < a->nconflict; i++) {
    bg_sb_printf(&sb, "%stype %d", i ? "; " : "", a->conflict_type[i]);
    if (a->conflict_type[i] == 2) bg_sb_printf(&sb, "/%d", a->conflict_degree[i]);
    bg_sb_printf(&sb, " at %s [", r->m->elem_name[a->conflict_node[i]]);
    for (int k = 0; k < a->conflict_n[i]; k++)
      bg_sb_printf(&sb, "%s%d", k ? "," : "",
                   r->m->bond_num[a->conflict_bonds[a->conflict_adr[i] + k]]);
    bg_sb_putc(&sb, ']');
  }
  snprintf(buf, sizeof buf, "%s", bg_sb_str(&sb));
  bg_sb_free(&sb);
  return buf;
}

static int reason_of(const run *r, int num) {
  int b = bg_model_find_bond(r->m, num);
  return b < 0 ? -1 : r->a.bond_reason[b];
}

static int trace_has(const run *r, const char *needle) {
  for (int i = 0; i < r->a.ntrace; i++)
    if (strstr(r->a.trace_text[i], needle)) return 1;
  return 0;
}

static int count_choices(const run *r) {
  int n = 0;
  for (int b = 0; b < r->m->nbond; b++) n += r->a.bond_reason[b] == BG_REASON_CHOICE;
  return n;
}

/* ---------------------------------------------------------------- examples */
static void test_hydraulic_bridge(void) {
  run r = {0};
  OK(run_example(&r, "hydraulic_bridge", BG_METHOD_SCAP, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(caus(&r, "mp"), "integral");
  STR_EQ(caus(&r, "R1"), "conductance");
  STR_EQ(caus(&r, "R3"), "conductance");
  STR_EQ(caus(&r, "R2"), "resistance");
  STR_EQ(caus(&r, "R4"), "resistance");
  INT_EQ(inverted(&r, "R1"), 0);
  INT_EQ(inverted(&r, "R2"), 1);
  INT_EQ(inverted(&r, "R3"), 0);
  INT_EQ(inverted(&r, "R4"), 1);
  STR_EQ(caus(&r, "Rb"), "resistance");
  INT_EQ(r.a.complete, 1);
  INT_EQ(r.a.nconflict, 0);
  INT_EQ(count_choices(&r), 0);
  STR_EQ(strokes(&r), "1:R1 2:n1 3:ja 4:n4 5:jb 6:R3 7:nS 8:ja 9:jb 10:A1 11:v 12:mp 13:v "
                      "14:A2 15:v");
  INT_EQ(reason_of(&r, 7), BG_REASON_SOURCE);
  INT_EQ(reason_of(&r, 12), BG_REASON_STORE);
  INT_EQ(reason_of(&r, 1), BG_REASON_RESISTOR);
  INT_EQ(reason_of(&r, 4), BG_REASON_PROPAGATION);
  OK(trace_has(&r, "Se pS fixes bond 7 (stroke at nS); propagated to bonds 8, 9"));
  OK(trace_has(&r, "R4 got resistance causality by propagation (law inverted)"));
  run_free(&r);
}

static void test_hydraulic_bridge_relaxed(void) {
  run r = {0};
  OK(run_example(&r, "hydraulic_bridge", BG_METHOD_RELAXED, NULL, NULL) == 0);
  if (!r.m) return;
  INT_EQ(r.a.method, BG_METHOD_RELAXED);
  const char *rs[] = {"R1", "R2", "R3", "R4"};
  for (int i = 0; i < 4; i++) {
    STR_EQ(caus(&r, rs[i]), "conductance");
    INT_EQ(inverted(&r, rs[i]), 0);
  }
  STR_EQ(caus(&r, "mp"), "integral");
  /* Figure 4.25: one resistor at a time (R1, R2, R3, R4). R1 leaves n1 with
   * one open bond, which propagation completes (bond 2 strong at n1, so
   * strong at ja too); R2 then gives ja a second determining flow: type 2 of
   * degree 1. R3 makes bond 5 weak at n4, R4 its last bond: no bond
   * determines n4's effort, type 1. */
  STR_EQ(conflicts(&r), "type 2/1 at ja [2,3]; type 1 at n4 [4,5,14]");
  INT_EQ(r.a.complete, 1);
  OK(trace_has(&r, "relaxed: nonlinear R1 gets its law's conductance causality (bond 1); "
                   "propagated to bond 2"));
  OK(trace_has(&r, "relaxed: nonlinear R3 gets its law's conductance causality (bond 6); "
                   "propagated to bond 5"));
  run_free(&r);
}

static void test_slider_crank(void) {
  run r = {0};
  OK(run_example(&r, "slider_crank", BG_METHOD_SCAP, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(caus(&r, "J"), "integral");
  STR_EQ(caus(&r, "m"), "derivative");
  STR_EQ(caus(&r, "Rb"), "resistance");
  STR_EQ(caus(&r, "T"), "transfer");
  STR_EQ(caus(&r, "M"), "fixed");
  INT_EQ(r.a.nconflict, 0);
  INT_EQ(r.a.complete, 1);
  OK(trace_has(&r, "m forced to derivative causality by propagation (dependent store)"));
  run_free(&r);

  OK(run_example(&r, "slider_crank", BG_METHOD_LAGRANGE, NULL, NULL) == 0);
  if (!r.m) return;
  INT_EQ(r.a.nlag, 1);
  if (r.a.nlag == 1) {
    STR_EQ(r.m->elem_name[r.a.lag_junction[0]], "w");
    INT_EQ(r.a.lag_bond[0], -1);
    STR_EQ(r.a.lag_force[0], "M");
  }
  INT_EQ(r.a.complete, 1);
  INT_EQ(r.a.nconflict, 0);
  STR_EQ(caus(&r, "J"), "derivative");
  STR_EQ(caus(&r, "m"), "derivative");
  run_free(&r);
}

static void test_bond_loop(void) {
  run r = {0};
  OK(run_example(&r, "bond_loop", BG_METHOD_SCAP, NULL, NULL) == 0);
  if (!r.m) return;
  INT_EQ(count_choices(&r), 1);
  INT_EQ(reason_of(&r, 1), BG_REASON_CHOICE);
  STR_EQ(strokes(&r), "1:jB 2:jC 3:tf 4:jA 5:F 6:jB 7:Is");
  STR_EQ(caus(&r, "Cs"), "integral");
  STR_EQ(caus(&r, "Is"), "integral");
  INT_EQ(r.a.nconflict, 0);
  INT_EQ(r.a.complete, 1);
  OK(trace_has(&r, "choice: internal bond 1 gets its stroke at jB; propagated to bonds 4, 3, 2"));
  run_free(&r);
  /* van Dijk leaves a loop of gain n alone */
  OK(run_example(&r, "bond_loop", BG_METHOD_VANDIJK, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(strokes(&r), "1:jB 2:jC 3:tf 4:jA 5:F 6:jB 7:Is");
  STR_EQ(caus(&r, "Cs"), "integral");
  run_free(&r);
}

static void test_class12(void) {
  run r = {0};
  OK(run_example(&r, "class12_paths", BG_METHOD_SCAP, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(caus(&r, "C2"), "derivative");
  STR_EQ(caus(&r, "C1"), "integral");
  STR_EQ(caus(&r, "R2"), "conductance");
  STR_EQ(caus(&r, "R1"), "resistance");
  INT_EQ(reason_of(&r, 5), BG_REASON_USER);
  INT_EQ(reason_of(&r, 4), BG_REASON_PROPAGATION);
  INT_EQ(count_choices(&r), 0);
  INT_EQ(r.a.nconflict, 0);
  OK(trace_has(&r, "C2 forced to derivative causality by propagation (dependent store)"));
  run_free(&r);

  OK(run_example(&r, "class12_paths", BG_METHOD_SCAP, "jB |-> R1", "jB -> R1") == 0);
  if (!r.m) return;
  STR_EQ(caus(&r, "R1"), "conductance");
  STR_EQ(caus(&r, "R2"), "conductance");
  STR_EQ(caus(&r, "C1"), "integral");
  STR_EQ(caus(&r, "C2"), "integral");
  INT_EQ(count_choices(&r), 1);
  INT_EQ(reason_of(&r, 3), BG_REASON_CHOICE);
  INT_EQ(r.a.nconflict, 0);
  INT_EQ(r.a.complete, 1);
  OK(trace_has(&r, "choice: internal bond 3 gets its stroke at jX"));
  run_free(&r);
}

static void test_loop_class1(void) {
  run r = {0};
  OK(run_example(&r, "loop_class1", BG_METHOD_SCAP, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(caus(&r, "C2"), "derivative");
  STR_EQ(caus(&r, "C1"), "integral");
  STR_EQ(caus(&r, "L"), "integral");
  INT_EQ(reason_of(&r, 7), BG_REASON_USER);
  INT_EQ(r.a.nconflict, 0);
  INT_EQ(r.a.complete, 1);
  run_free(&r);
}

static void test_delta(void) {
  run r = {0};
  OK(run_example(&r, "delta", BG_METHOD_SCAP, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(caus(&r, "R1"), "resistance");
  STR_EQ(caus(&r, "R2"), "resistance");
  STR_EQ(caus(&r, "R3"), "resistance");
  STR_EQ(caus(&r, "L1"), "integral");
  STR_EQ(caus(&r, "L2"), "integral");
  INT_EQ(count_choices(&r), 1);
  INT_EQ(reason_of(&r, 2), BG_REASON_CHOICE);
  STR_EQ(strokes(&r), "1:Is 2:b1 3:nB 4:b1 5:nA 6:b2 7:b2 8:b3 9:nC 10:b3 11:L1 12:L2");
  INT_EQ(r.a.nconflict, 0);
  run_free(&r);

  OK(run_example(&r, "delta", BG_METHOD_SCAP, "R   R1 = R10",
                 "R   R1 = R10 [causality = conductance]") == 0);
  if (!r.m) return;
  STR_EQ(caus(&r, "R1"), "conductance");
  INT_EQ(r.a.nconflict, 1);
  if (r.a.nconflict == 1) {
    INT_EQ(r.a.conflict_type[0], 1);
    INT_EQ(r.m->elem_kind[r.a.conflict_node[0]], BG_ELEM_J0);
  }
  STR_EQ(conflicts(&r), "type 1 at nC [6,9,12]");
  run_free(&r);

  OK(run_example(&r, "delta", BG_METHOD_VANDIJK, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(caus(&r, "L1"), "derivative");
  STR_EQ(caus(&r, "L2"), "integral");
  INT_EQ(count_choices(&r), 0);
  INT_EQ(r.a.nconflict, 0);
  INT_EQ(r.a.complete, 1);
  INT_EQ(r.a.method, BG_METHOD_VANDIJK);
  OK(r.a.ntrace > 0 && strstr(r.a.trace_text[0], "van Dijk: SCAP gave a causal loop of gain +1"));
  OK(r.a.ntrace > 0 && strstr(r.a.trace_text[0], "I L1 gets derivative causality"));
  OK(trace_has(&r, "I L1 gets derivative causality (van Dijk"));
  /* bond steps point at the renumbered trace */
  int b11 = bg_model_find_bond(r.m, 11);
  OK(b11 >= 0 && r.a.bond_step[b11] >= 2 && r.a.bond_step[b11] <= r.a.ntrace &&
     strstr(r.a.trace_text[r.a.bond_step[b11] - 1], "L1"));
  run_free(&r);
}

static void test_relaxed_conductances(void) {
  run r = {0};
  OK(run_example(&r, "series_conductances", BG_METHOD_RELAXED, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(conflicts(&r), "type 2/2 at j [2,3,4]");
  for (int e = 0; e < r.m->nelem; e++) INT_EQ(r.a.elem_inverted[e], 0);
  STR_EQ(caus(&r, "Cl"), "integral");
  run_free(&r);

  {
    char *src = example_src("series_conductances");
    char *s1 = replace(src, "R   Rc : f = G0*e^3\n", "");
    char *s2 = replace(s1, "bond 4 j -> Rc\n", "");
    OK(run_src(&r, s2, BG_METHOD_RELAXED) == 0);
    free(src), free(s1), free(s2);
    if (!r.m) return;
    STR_EQ(conflicts(&r), "type 2/1 at j [2,3]");
    run_free(&r);
  }

  OK(run_example(&r, "parallel_conductance", BG_METHOD_RELAXED, NULL, NULL) == 0);
  if (!r.m) return;
  STR_EQ(conflicts(&r), "type 1 at k [1,2,3]");
  STR_EQ(caus(&r, "Rg"), "conductance");
  STR_EQ(caus(&r, "Lk"), "integral");
  run_free(&r);

  /* the default SCAP makes them consistent instead, inverting laws */
  OK(run_example(&r, "series_conductances", BG_METHOD_SCAP, NULL, NULL) == 0);
  if (!r.m) return;
  INT_EQ(r.a.nconflict, 0);
  STR_EQ(caus(&r, "Ra"), "conductance");
  STR_EQ(caus(&r, "Rb"), "resistance");
  INT_EQ(inverted(&r, "Rb"), 1);
  run_free(&r);
}

static void test_lagrange_rlc(void) {
  run r = {0};
  OK(run_example(&r, "lagrange_rlc", BG_METHOD_LAGRANGE, NULL, NULL) == 0);
  if (!r.m) return;
  INT_EQ(r.a.nlag, 2);
  if (r.a.nlag == 2) {
    STR_EQ(r.m->elem_name[r.a.lag_junction[0]], "ma");
    STR_EQ(r.m->elem_name[r.a.lag_junction[1]], "mb");
    STR_EQ(r.a.lag_force[0], "-R0*f4");
    STR_EQ(r.a.lag_force[1], "0");
  }
  STR_EQ(caus(&r, "C1"), "integral");
  STR_EQ(caus(&r, "C2"), "integral");
  STR_EQ(caus(&r, "L1"), "derivative");
  STR_EQ(caus(&r, "R"), "resistance");
  STR_EQ(strokes(&r), "1:Ie 2:n1 3:ma 4:ma 5:ma 6:n2 7:mb 8:mb");
  INT_EQ(reason_of(&r, 3), BG_REASON_LAGRANGE);
  INT_EQ(reason_of(&r, 2), BG_REASON_PROPAGATION);
  INT_EQ(r.a.nconflict, 0);
  INT_EQ(r.a.complete, 1);
  OK(trace_has(&r, "lagrange: artificial flow source at 1-junction ma (generalised coordinate q1)"));
  run_free(&r);
}

/* Every example runs with every method, completes, and gives the same
 * bytes twice (determinism). */
static void test_all_examples(void) {
  const char *names[] = {"bond_loop", "bridge_compliance", "class12_paths", "delta",
                         "hydraulic_bridge", "internal_mod_r", "internal_mod_tf",
                         "lagrange_rlc", "loop_class1", "mod_no_loop", "modulated_source",
                         "parallel_conductance", "rlc", "series_conductances",
                         "series_motor", "series_motor_L", "slider_crank"};
  for (size_t i = 0; i < sizeof names / sizeof *names; i++)
    for (int method = BG_METHOD_SCAP; method <= BG_METHOD_LAGRANGE; method++) {
      run r1 = {0}, r2 = {0};
      OK(run_example(&r1, names[i], method, NULL, NULL) == 0);
      OK(run_example(&r2, names[i], method, NULL, NULL) == 0);
      if (!r1.m || !r2.m) continue;
      INT_EQ(r1.a.complete, 1);
      char s1[4096];
      snprintf(s1, sizeof s1, "%s", strokes(&r1));
      STR_EQ(s1, strokes(&r2));
      INT_EQ(r1.a.ntrace, r2.a.ntrace);
      run_free(&r1);
      run_free(&r2);
    }
  run r = {0};
  OK(run_example(&r, "bridge_compliance", BG_METHOD_SCAP, NULL, NULL) == 0);
  if (!r.m) return;
  const char *rs[] = {"R1", "R2", "R3", "R4"};
  for (int k = 0; k < 4; k++) {
    STR_EQ(caus(&r, rs[k]), "conductance");
    INT_EQ(inverted(&r, rs[k]), 0);
  }
  STR_EQ(caus(&r, "C1"), "integral");
  STR_EQ(caus(&r, "C2"), "integral");
  run_free(&r);
}

/* ---------------------------------------------------------------- hand-made graphs */
/* Elements "Kind name" and bonds "tail head [fix]" (fix: 'h' ->|, 't' |->). */
typedef struct hand {
  bg_model m;
  bg_analysis a;
  char *names; /* element names, NUL-separated */
} hand;

static int kind_of(const char *k) {
  static const char *names[] = {"Se", "Sf", "MSe", "MSf", "C", "I", "R",
                                "TF", "MTF", "GY", "MGY", "0", "1"};
  for (int i = 0; i < BG_ELEM_COUNT; i++)
    if (strcmp(names[i], k) == 0) return i;
  return -1;
}

/* Names of the form <letters><digits> of a generated ladder resolve fast. */
static int find(const bg_model *m, const char *name) {
  for (int e = 0; e < m->nelem; e++)
    if (strcmp(m->elem_name[e], name) == 0) return e;
  return -1;
}

static int find_hint(const bg_model *m, const char *name, const int *hint, int nhint) {
  for (int i = 0; i < nhint; i++)
    if (hint[i] >= 0 && hint[i] < m->nelem && strcmp(m->elem_name[hint[i]], name) == 0)
      return hint[i];
  return find(m, name);
}

static void hand_build(hand *h, const char **elems, int ne, const char **bonds, int nb) {
  bg_model *m = &h->m;
  memset(h, 0, sizeof *h);
  int last_t = 0, last_h = 0;
  m->nelem = ne;
  m->nbond = nb;
  m->nbondref = 2 * nb;
  m->elem_kind = calloc(ne, sizeof(int));
  m->elem_name = calloc(ne, sizeof(char *));
  m->elem_form = calloc(ne, sizeof(int));
  m->elem_expr = calloc(ne, sizeof(int));
  m->elem_linear = calloc(ne, sizeof(int));
  m->elem_modulated = calloc(ne, sizeof(int));
  m->elem_causopt = calloc(ne, sizeof(int));
  m->elem_bondadr = calloc(ne, sizeof(int));
  m->elem_nbond = calloc(ne, sizeof(int));
  m->elem_bonds = calloc(2 * nb + 1, sizeof(int));
  m->bond_num = calloc(nb, sizeof(int));
  m->bond_tail = calloc(nb, sizeof(int));
  m->bond_head = calloc(nb, sizeof(int));
  m->bond_fix = calloc(nb, sizeof(int));
  h->names = calloc(ne, 16);
  for (int e = 0; e < ne; e++) {
    char k[8];
    char *name = h->names + 16 * e;
    sscanf(elems[e], "%7s %15s", k, name);
    m->elem_kind[e] = kind_of(k);
    m->elem_name[e] = name;
    m->elem_form[e] = bg_elem_is_junction(m->elem_kind[e]) ? BG_FORM_NONE : BG_FORM_VALUE;
    m->elem_expr[e] = -1;
    m->elem_linear[e] = 1;
  }
  for (int b = 0; b < nb; b++) {
    char t[16], hd[16], fix[4] = "";
    sscanf(bonds[b], "%15s %15s %3s", t, hd, fix);
    m->bond_num[b] = b + 1;
    int ht[3] = {last_t, last_h, last_h + 1};
    m->bond_tail[b] = last_t = find_hint(m, t, ht, 3);
    int hh[2] = {last_t + 1, last_h + 1};
    m->bond_head[b] = last_h = find_hint(m, hd, hh, 2);
    m->bond_fix[b] = fix[0] == 'h' ? BG_FIX_HEAD : fix[0] == 't' ? BG_FIX_TAIL : BG_FIX_NONE;
    m->elem_nbond[m->bond_tail[b]]++;
    m->elem_nbond[m->bond_head[b]]++;
  }
  for (int e = 1; e < ne; e++) m->elem_bondadr[e] = m->elem_bondadr[e - 1] + m->elem_nbond[e - 1];
  int *fill = calloc(ne, sizeof(int));
  for (int b = 0; b < nb; b++) {
    int t = m->bond_tail[b], hd = m->bond_head[b];
    m->elem_bonds[m->elem_bondadr[t] + fill[t]++] = b;
    m->elem_bonds[m->elem_bondadr[hd] + fill[hd]++] = b;
  }
  free(fill);
}

static void hand_run(hand *h, int method) {
  bg_diags dg;
  bg_diags_init(&dg, "hand", NULL, 0);
  bg_analysis_init(&h->a, &h->m);
  bg_causality_assign(&h->m, method, &h->a, &dg);
  bg_diags_free(&dg);
}

static void hand_free(hand *h) {
  bg_model *m = &h->m;
  bg_analysis_free(&h->a);
  free(m->elem_kind); free(m->elem_name); free(m->elem_form); free(m->elem_expr);
  free(m->elem_linear); free(m->elem_modulated); free(m->elem_causopt);
  free(m->elem_bondadr); free(m->elem_nbond); free(m->elem_bonds);
  free(m->bond_num); free(m->bond_tail); free(m->bond_head); free(m->bond_fix);
  free(h->names);
}

static const char *hcaus(const hand *h, const char *name) {
  return bg_caus_name(h->a.elem_caus[find(&h->m, name)]);
}

static char *hconflicts(hand *h) {
  run r = {&h->m, h->a};
  return conflicts(&r);
}

static char *hstrokes(hand *h) {
  run r = {&h->m, h->a};
  return strokes(&r);
}

static void test_two_effort_sources(void) {
  const char *el[] = {"Se E1", "Se E2", "0 j", "C c"};
  const char *bo[] = {"E1 j", "E2 j", "j c"};
  hand h;
  hand_build(&h, el, 4, bo, 3);
  hand_run(&h, BG_METHOD_SCAP);
  STR_EQ(hconflicts(&h), "type 2/1 at j [1,2]");
  STR_EQ(hcaus(&h, "c"), "derivative");
  STR_EQ(hcaus(&h, "E1"), "fixed");
  INT_EQ(h.a.complete, 1);
  hand_free(&h);
}

static void test_two_inertias(void) {
  const char *el[] = {"Se E", "1 j", "I L1", "I L2"};
  const char *bo[] = {"E j", "j L1", "j L2"};
  hand h;
  hand_build(&h, el, 4, bo, 3);
  hand_run(&h, BG_METHOD_SCAP);
  STR_EQ(hcaus(&h, "L1"), "integral");
  STR_EQ(hcaus(&h, "L2"), "derivative");
  INT_EQ(h.a.nconflict, 0);
  INT_EQ(h.a.bond_reason[2], BG_REASON_PROPAGATION);
  hand_free(&h);
}

static void test_gyrator_chain(void) {
  /* Se -> GY -> GY -> GY -> I : each GY flips effort and flow */
  const char *el[] = {"Se E", "GY g1", "GY g2", "GY g3", "I L"};
  const char *bo[] = {"E g1", "g1 g2", "g2 g3", "g3 L"};
  hand h;
  hand_build(&h, el, 5, bo, 4);
  hand_run(&h, BG_METHOD_SCAP);
  /* Se puts its stroke at g1; a GY keeps both strokes at it or both away */
  STR_EQ(hstrokes(&h), "1:g1 2:g1 3:g3 4:g3");
  STR_EQ(hcaus(&h, "L"), "derivative");
  INT_EQ(h.a.nconflict, 0);
  hand_free(&h);
  /* with two gyrators the store ends integral */
  const char *el2[] = {"Se E", "GY g1", "GY g2", "I L"};
  const char *bo2[] = {"E g1", "g1 g2", "g2 L"};
  hand_build(&h, el2, 4, bo2, 3);
  hand_run(&h, BG_METHOD_SCAP);
  STR_EQ(hcaus(&h, "L"), "integral");
  INT_EQ(h.a.nconflict, 0);
  hand_free(&h);
}

static void test_gyrator_loop(void) {
  /* a bond loop 0 a -> 1 b -> GY g -> 0 a: the C on a imposes the effort,
   * the GY turns it into the flow of b, the I on b becomes dependent */
  const char *el[] = {"Sf F", "0 a", "1 b", "GY g", "C c", "I l"};
  const char *bo[] = {"F a", "a b", "b g", "g a", "a c", "b l"};
  hand h;
  hand_build(&h, el, 6, bo, 6);
  hand_run(&h, BG_METHOD_SCAP);
  INT_EQ(h.a.complete, 1);
  INT_EQ(h.a.nconflict, 0);
  STR_EQ(hstrokes(&h), "1:F 2:b 3:g 4:g 5:a 6:b");
  STR_EQ(hcaus(&h, "c"), "integral");
  STR_EQ(hcaus(&h, "l"), "derivative");
  hand_free(&h);
  /* swap the stores: nothing propagates into the loop; with one GY neither
   * orientation of the chosen bond is consistent (a causal mesh cannot
   * close), so SCAP records the conflict and goes on */
  const char *el2[] = {"Sf F", "0 a", "1 b", "GY g", "I l", "C c"};
  const char *bo2[] = {"F a", "a b", "b g", "g a", "a l", "b c"};
  hand_build(&h, el2, 6, bo2, 6);
  hand_run(&h, BG_METHOD_SCAP);
  INT_EQ(h.a.complete, 1);
  INT_EQ(h.a.bond_reason[1], BG_REASON_CHOICE);
  STR_EQ(hcaus(&h, "l"), "integral");
  STR_EQ(hcaus(&h, "c"), "integral");
  STR_EQ(hconflicts(&h), "type 1 at b [2,3,6]");
  run r = {&h.m, h.a};
  OK(trace_has(&r, "choice: internal bond 2 gets its stroke at b (both orientations conflict"));
  hand_free(&h);
}

static void test_empty_junction_structure(void) {
  const char *el[] = {"Se E", "C c"};
  const char *bo[] = {"E c"};
  hand h;
  hand_build(&h, el, 2, bo, 1);
  hand_run(&h, BG_METHOD_SCAP);
  STR_EQ(hcaus(&h, "c"), "derivative");
  STR_EQ(hstrokes(&h), "1:c");
  INT_EQ(h.a.complete, 1);
  INT_EQ(h.a.nconflict, 0);
  hand_free(&h);
  const char *el2[] = {"Sf F", "C c"};
  const char *bo2[] = {"F c"};
  hand_build(&h, el2, 2, bo2, 1);
  hand_run(&h, BG_METHOD_SCAP);
  STR_EQ(hcaus(&h, "c"), "integral");
  STR_EQ(hstrokes(&h), "1:F");
  hand_free(&h);
  /* a fixed stroke against the source: recorded at the source */
  const char *bo3[] = {"F c h"};
  hand_build(&h, el2, 2, bo3, 1);
  hand_run(&h, BG_METHOD_SCAP);
  STR_EQ(hconflicts(&h), "type 2/1 at F [1]");
  INT_EQ(h.a.bond_reason[0], BG_REASON_USER);
  hand_free(&h);
}

static void test_store_option(void) {
  /* Se forces both C derivative; c1's option asks integral: a conflict at c1 */
  const char *el[] = {"Se E", "0 j", "C c1", "C c2"};
  const char *bo[] = {"E j", "j c1", "j c2"};
  hand h;
  hand_build(&h, el, 4, bo, 3);
  h.m.elem_causopt[2] = BG_CAUS_OPT_INTEGRAL;
  hand_run(&h, BG_METHOD_SCAP);
  STR_EQ(hcaus(&h, "c1"), "derivative");
  STR_EQ(hcaus(&h, "c2"), "derivative");
  STR_EQ(hconflicts(&h), "type 2/1 at c1 [2]");
  run r = {&h.m, h.a};
  OK(trace_has(&r, "c1 forced to derivative causality by propagation against its option"));
  hand_free(&h);
  /* an option for derivative causality is honoured in step 2 */
  const char *el2[] = {"Sf F", "0 j", "C c1", "C c2"};
  const char *bo2[] = {"F j", "j c1", "j c2"};
  hand_build(&h, el2, 4, bo2, 3);
  h.m.elem_causopt[2] = BG_CAUS_OPT_DERIVATIVE;
  hand_run(&h, BG_METHOD_SCAP);
  STR_EQ(hcaus(&h, "c1"), "derivative");
  STR_EQ(hcaus(&h, "c2"), "integral");
  INT_EQ(h.a.nconflict, 0);
  hand_free(&h);
}

/* A long ladder built by hand (the parser is not under test here): R and C
 * alternating on 1- and 0-junctions, 300 000 bonds. Linear-time propagation
 * keeps this well under a second; a quadratic rescan would not finish. */
static void test_ladder(void) {
  enum { N = 100000 };
  const char **el = calloc(2 * N + 1, sizeof(char *)), **bo = calloc(2 * N, sizeof(char *));
  char *text = calloc(2 * N + 1 + 2 * N, 40), *p = text;
  int ne = 0, nb = 0;
  el[ne++] = "Se E";
  for (int i = 0; i < N; i++) {
    el[ne++] = p, p += sprintf(p, "%s j%d", i % 2 ? "0" : "1", i) + 1;
    el[ne++] = p, p += sprintf(p, "%s s%d", i % 2 ? "C" : "R", i) + 1;
  }
  bo[nb++] = "E j0";
  for (int i = 0; i < N; i++) {
    bo[nb++] = p, p += sprintf(p, "j%d s%d", i, i) + 1;
    if (i + 1 < N) bo[nb++] = p, p += sprintf(p, "j%d j%d", i, i + 1) + 1;
  }
  hand h;
  hand_build(&h, el, ne, bo, nb);
  for (int method = BG_METHOD_SCAP; method <= BG_METHOD_LAGRANGE; method++) {
    hand_run(&h, method);
    INT_EQ(h.a.complete, 1);
    INT_EQ(h.a.nconflict, 0);
    bg_analysis_free(&h.a);
  }
  hand_run(&h, BG_METHOD_SCAP);
  hand_free(&h);
  free(el), free(bo), free(text);
}

/* src with the lines that start with `prefix` in reverse order, each other
 * line in its place (caller frees). */
static char *reverse_lines(const char *src, const char *prefix) {
  const char *line[512];
  size_t len[512];
  int n = 0, hit[512], nhit = 0;
  for (const char *p = src; *p && n < 512; n++) {
    const char *nl = strchr(p, '\n');
    line[n] = p;
    len[n] = nl ? (size_t)(nl - p) + 1 : strlen(p);
    if (strncmp(p, prefix, strlen(prefix)) == 0) hit[nhit++] = n;
    p += len[n];
  }
  bg_strbuf sb = {0};
  for (int i = 0, k = 0; i < n; i++) {
    int j = i;
    if (k < nhit && hit[k] == i) j = hit[nhit - 1 - k++];
    bg_sb_putn(&sb, line[j], len[j]);
  }
  return sb.s;
}

/* ---------------------------------------------------------------- ties */
/* "1:L1 2:j1 ..." by bond number, whatever the order of the statements. */
static char *strokes_by_number(const run *r) {
  static char buf[4096];
  const bg_model *m = r->m;
  bg_strbuf sb = {0};
  for (int num = 0, done = 0; done < m->nbond && num < 1000; num++) {
    int b = bg_model_find_bond(m, num);
    if (b < 0) continue;
    int s = r->a.bond_stroke[b];
    const char *at = s == BG_STROKE_HEAD ? m->elem_name[m->bond_head[b]]
                     : s == BG_STROKE_TAIL ? m->elem_name[m->bond_tail[b]] : "-";
    bg_sb_printf(&sb, "%s%d:%s", done++ ? " " : "", num, at);
  }
  snprintf(buf, sizeof buf, "%s", bg_sb_str(&sb));
  bg_sb_free(&sb);
  return buf;
}

/* SCAP's free choices follow names (stores, sources, resistors) and bond
 * numbers (fixed strokes, internal bonds, a junction's bonds), never the
 * order of the lines (docs/causality.md, "Ties"; the property campaign's
 * reorder_strokes, tests/property/found/reorder_strokes_two_inertias.bg). */
static void test_ties(void) {
  static const char *orders[] = {
    "model t\n0 j1\nI L1 = 1.11\nI L2 = 1.71\nbond 1 j1 -> L1\nbond 2 L2 -> j1\n",
    "model t\nbond 2 L2 -> j1\nI L2 = 1.71\nbond 1 j1 -> L1\nI L1 = 1.11\n0 j1\n",
  };
  for (int i = 0; i < 2; i++) {
    run r = {0};
    OK(run_src(&r, orders[i], BG_METHOD_SCAP) == 0);
    if (!r.m) continue;
    STR_EQ(caus(&r, "L1"), "integral"); /* L1 before L2 by name */
    STR_EQ(caus(&r, "L2"), "derivative");
    STR_EQ(strokes_by_number(&r), "1:L1 2:j1");
    run_free(&r);
  }
  /* natural order: L2 before L10 */
  run r = {0};
  OK(run_src(&r, "model t\n0 j1\nI L10 = 1\nI L2 = 1\nbond 1 j1 -> L10\nbond 2 L2 -> j1\n",
             BG_METHOD_SCAP) == 0);
  if (r.m) STR_EQ(caus(&r, "L2"), "integral");
  run_free(&r);
  /* a store whose initial value the model gives comes first: it keeps it */
  OK(run_src(&r, "model t\n0 j1\nI L1 = 1\nI L2 = 1 [p0 = 2]\nbond 1 j1 -> L1\n"
                 "bond 2 L2 -> j1\n", BG_METHOD_SCAP) == 0);
  if (r.m) STR_EQ(caus(&r, "L2"), "integral");
  run_free(&r);
  /* the bridge with its resistors' and its bonds' lines in reverse order:
   * the same strokes, and Figure 4.25's conflicts (which depend on the
   * order R1, R2, R3, R4) stay */
  char *src = example_src("hydraulic_bridge");
  if (!src) return;
  char *a = reverse_lines(src, "R   R"), *b = reverse_lines(a, "bond ");
  OK(strcmp(src, b) != 0);
  for (int method = BG_METHOD_SCAP; method <= BG_METHOD_LAGRANGE; method++) {
    run r1 = {0}, r2 = {0};
    OK(run_src(&r1, src, method) == 0 && run_src(&r2, b, method) == 0);
    if (r1.m && r2.m) {
      char s1[4096];
      snprintf(s1, sizeof s1, "%s", strokes_by_number(&r1));
      STR_EQ(strokes_by_number(&r2), s1);
      snprintf(s1, sizeof s1, "%s", conflicts(&r1));
      STR_EQ(conflicts(&r2), s1);
      if (method == BG_METHOD_RELAXED) STR_EQ(s1, "type 2/1 at ja [2,3]; type 1 at n4 [4,5,14]");
    }
    run_free(&r1);
    run_free(&r2);
  }
  free(a), free(b), free(src);
}

int main(void) {
  test_two_effort_sources();
  test_two_inertias();
  test_gyrator_chain();
  test_gyrator_loop();
  test_empty_junction_structure();
  test_store_option();
  test_hydraulic_bridge();
  test_hydraulic_bridge_relaxed();
  test_slider_crank();
  test_bond_loop();
  test_class12();
  test_loop_class1();
  test_delta();
  test_relaxed_conductances();
  test_lagrange_rlc();
  test_all_examples();
  test_ladder();
  test_ties();
  return bg_t_done();
}
