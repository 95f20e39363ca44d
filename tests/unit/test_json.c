/* SPDX-License-Identifier: BSD-3-Clause */
/* The analysis JSON (docs/json.md): keys in the schema's order, values of a small
 * model, the generic writers of the lists other stages fill, determinism. */
#include <stdlib.h>
#include <string.h>

#include "causality/causality.h"
#include "harness.h"
#include "json/json.h"
#include "lang/lang.h"

static bg_model *load_example(const char *name) {
  char path[512];
  size_t len;
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  char *src = bg_read_file(path, &len);
  if (!src) return NULL;
  bg_diags dg;
  bg_diags_init(&dg, path, src, len);
  bg_ast *ast = bg_parse_string(path, src, len, &dg);
  bg_model *m = ast && !dg.nerrors ? bg_model_compile(ast, NULL, 0, &dg) : NULL;
  if (dg.nerrors) bg_diags_print(&dg, stderr);
  if (ast) bg_ast_free(ast);
  bg_diags_free(&dg);
  free(src);
  return m;
}

/* The JSON of an example after causality assignment (caller frees). */
static char *json_of(const char *name, int method) {
  bg_model *m = load_example(name);
  if (!m) return strdup("");
  bg_analysis a;
  bg_diags dg;
  bg_diags_init(&dg, name, NULL, 0);
  bg_analysis_init(&a, m);
  bg_causality_assign(m, method, &a, &dg);
  bg_strbuf sb = {0};
  bg_json_write_analysis(m, &a, NULL, &sb);
  bg_analysis_free(&a);
  bg_model_free(m);
  bg_diags_free(&dg);
  return sb.s ? sb.s : strdup("");
}

static int has(const char *s, const char *needle) { return strstr(s, needle) != NULL; }

static void test_key_order(void) {
  char *j = json_of("rlc", BG_METHOD_SCAP);
  static const char *keys[] = {
      "\"format\": \"bgdraw-analysis\"", "\"version\": 1", "\"model\": \"rlc\"",
      "\"method\": \"scap\"", "\"complete\": true", "\"bonds\": [", "\"elements\": [",
      "\"trace\": [", "\"conflicts\": [", "\"causal_paths\": [", "\"causal_loops\": [",
      "\"topological_loops\": [", "\"states\": [", "\"dependent_stores\": [",
      "\"algebraic_variables\": [", "\"form\": ", "\"index\": {\"predicted\": ",
      "\"estimates\": [", "\"lagrange\": {\"coordinates\": [], \"forces\": []}"};
  const char *prev = j;
  for (size_t i = 0; i < sizeof keys / sizeof *keys; i++) {
    const char *p = strstr(j, keys[i]);
    OK(p != NULL);
    if (!p) {
      fprintf(stderr, "missing: %s\n", keys[i]);
      continue;
    }
    OK(p >= prev);
    prev = p;
  }
  OK(strncmp(j, "{\n  \"format\"", 12) == 0);
  OK(j[0] && j[strlen(j) - 1] == '\n' && j[strlen(j) - 2] == '}');
  free(j);
}

static void test_values(void) {
  char *j = json_of("rlc", BG_METHOD_SCAP);
  OK(has(j, "{\"id\": 1, \"from\": \"U\", \"to\": \"j\", \"stroke\": \"to\", \"reason\": \"source\""));
  OK(has(j, "{\"id\": 2, \"from\": \"j\", \"to\": \"R1\", \"stroke\": \"from\", \"reason\": "
            "\"propagation\""));
  OK(has(j, "{\"id\": 3, \"from\": \"j\", \"to\": \"L1\", \"stroke\": \"to\", \"reason\": \"store\""));
  OK(has(j, "{\"name\": \"R1\", \"kind\": \"R\", \"causality\": \"resistance\", \"inverted\": false}"));
  OK(has(j, "{\"name\": \"L1\", \"kind\": \"I\", \"causality\": \"integral\""));
  OK(has(j, "{\"name\": \"C1\", \"kind\": \"C\", \"causality\": \"integral\""));
  OK(has(j, "{\"name\": \"U\", \"kind\": \"Se\", \"causality\": \"fixed\""));
  /* junction-structure nodes have no causality of their own in docs/json.md's vocabulary */
  OK(has(j, "{\"name\": \"j\", \"kind\": \"1\", \"causality\": \"none\", \"inverted\": false}"));
  OK(!has(j, "transfer"));
  OK(has(j, "{\"step\": 1, \"text\": \"Se U fixes bond 1 (stroke at j)\"}"));
  OK(has(j, "\"conflicts\": [],\n"));
  OK(has(j, "\"index\": {\"predicted\": null, \"numeric\": null, \"reason\": null, "
            "\"numeric_status\": \"not computed\", \"disagreement\": null}"));
  OK(has(j, "\"omitted\": {\"causal_paths\": 0, \"causal_loops\": 0, \"topological_loops\": 0, "
                "\"topological_loops_complete\": true},\n"
            "  \"reduced_form\": null\n}\n"));
  OK(has(j, "\"form\": \"incomplete\""));
  free(j);

  j = json_of("parallel_conductance", BG_METHOD_RELAXED);
  OK(has(j, "\"method\": \"relaxed\""));
  OK(has(j, "{\"node\": \"k\", \"type\": 1, \"degree\": 0, \"bonds\": [1, 2, 3]}"));
  free(j);

  j = json_of("lagrange_rlc", BG_METHOD_LAGRANGE);
  OK(has(j, "\"lagrange\": {\"coordinates\": [\"ma\", \"mb\"], \"forces\": [\"-R0*f4\", \"0\"]}"));
  OK(has(j, "\"reason\": \"lagrange\""));
  free(j);
}

/* Lists written by later stages: filled here by hand, in the arena. */
static void test_generic_lists(void) {
  bg_model *m = load_example("rlc");
  if (!m) {
    OK(0);
    return;
  }
  bg_analysis a;
  bg_diags dg;
  bg_diags_init(&dg, "rlc", NULL, 0);
  bg_analysis_init(&a, m);
  bg_causality_assign(m, BG_METHOD_SCAP, &a, &dg);
  bg_arena *ar = &a.arena;
  static int adr[2] = {0, 2}, n[2] = {2, 2}, bonds[4] = {1, 2, 2, 3}, e0[2] = {2, 3},
             e1[2] = {3, 4}, cls[2] = {0, 1}, ord[2] = {1, 0};
  static const char *kind[2] = {"I-R", "C-I"};
  a.npath = 2;
  a.path_adr = adr, a.path_n = n, a.path_bonds = bonds, a.path_end0 = e0, a.path_end1 = e1;
  a.path_kind = kind, a.path_class = cls, a.path_order = ord;
  static int ladr[1] = {0}, ln[1] = {4}, lb[4] = {0, 1, 2, 3}, lcls[1] = {4};
  static double gv[1] = {2.0};
  a.ncloop = 1;
  a.cloop_adr = ladr, a.cloop_n = ln, a.cloop_bonds = lb, a.cloop_class = lcls;
  a.cloop_gain_value = gv;
  a.cloop_gain = bg_arena_alloc(ar, sizeof(char *));
  a.cloop_gain[0] = bg_arena_strdup(ar, "n");
  static int tk[1] = {BG_TLOOP_FLAT}, to[1] = {0}, tadr[1] = {0}, tn[1] = {4},
             tsig[4] = {BG_SIG_FLOW(1), BG_SIG_EFFORT(1), BG_SIG_EFFORT(2), BG_SIG_FLOW(2)},
             talg[1] = {1};
  static double tgv[1] = {0.5};
  a.ntloop = 1;
  a.tloop_kind = tk, a.tloop_order = to, a.tloop_adr = tadr, a.tloop_n = tn;
  a.tloop_signals = tsig, a.tloop_algebraic = talg, a.tloop_gain_value = tgv;
  a.tloop_gain = bg_arena_alloc(ar, sizeof(char *));
  a.tloop_gain[0] = bg_arena_strdup(ar, "1/2");
  a.tloop_cause = bg_arena_alloc(ar, sizeof(char *));
  a.tloop_cause[0] = bg_arena_strdup(ar, "causal path 1");
  a.nstates = 2;
  a.states = bg_arena_alloc(ar, 2 * sizeof(char *));
  a.states[0] = "L1.p", a.states[1] = "C1.q";
  a.form = BG_FORM_ODE;
  a.index_predicted = 0;
  a.index_reason = "no zero-order path";
  static int ek[1] = {0}, ep[1] = {0};
  static double ev[1] = {1e-4};
  a.nestimate = 1, a.estimate_kind = ek, a.estimate_path = ep, a.estimate_value = ev;
  bg_index_result ix = {.index = 0};
  bg_index_facts facts = {.numeric = &ix, .reduced_form = "ode"};
  bg_strbuf sb = {0};
  bg_json_write_analysis(m, &a, &facts, &sb);
  const char *j = bg_sb_str(&sb);
  OK(has(j, "{\"id\": 1, \"bonds\": [2, 3], \"ends\": [\"R1\", \"L1\"], \"kind\": \"I-R\", "
            "\"class\": null, \"order\": 1}"));
  OK(has(j, "{\"id\": 2, \"bonds\": [3, 4], \"ends\": [\"L1\", \"C1\"], \"kind\": \"C-I\", "
            "\"class\": 1, \"order\": 0}"));
  OK(has(j, "{\"id\": 1, \"bonds\": [1, 2, 3, 4], \"gain\": \"n\", \"gain_value\": 2, "
            "\"class\": 4}"));  /* no "mesh" key (docs/analysis.md, causal meshes) */
  OK(!has(j, "\"mesh\""));
  OK(has(j, "{\"id\": 1, \"kind\": \"flat\", \"order\": 0, \"bonds\": [2, 3], \"signals\": "
            "[\"f2\", \"e2\", \"e3\", \"f3\"], \"gain\": \"1/2\", \"gain_value\": 0.5, "
            "\"algebraic\": true, \"cause\": \"causal path 1\"}"));
  OK(has(j, "\"states\": [\"L1.p\", \"C1.q\"]"));
  OK(has(j, "\"dependent_stores\": []"));
  OK(has(j, "\"form\": \"ode\""));
  OK(has(j, "\"index\": {\"predicted\": 0, \"numeric\": 0, \"reason\": \"no zero-order path\", "
            "\"numeric_status\": \"computed\", \"disagreement\": null}"));
  OK(has(j, "\"reduced_form\": \"ode\"\n}\n"));
  bg_sb_free(&sb);
  /* a singular pencil has no index: null, and the status says why */
  ix.index = BG_INDEX_SINGULAR;
  a.npath_omitted = 7, a.ncloop_omitted = 2, a.ntloop_omitted = 3, a.tloop_capped = 1;
  sb = (bg_strbuf){0};
  bg_json_write_analysis(m, &a, &facts, &sb);
  j = bg_sb_str(&sb);
  OK(has(j, "\"numeric\": null, \"reason\": \"no zero-order path\", \"numeric_status\": \"singular\", \"disagreement\": null}"));
  OK(has(j, "\"omitted\": {\"causal_paths\": 7, \"causal_loops\": 2, \"topological_loops\": 3, "
                "\"topological_loops_complete\": false}"));
  OK(has(j, "{\"kind\": \"time_constant\", \"path\": 1, \"value\": 0.0001}"));
  bg_sb_free(&sb);
  /* the arrays above are static: detach them before the arena goes */
  bg_analysis_free(&a);
  bg_model_free(m);
  bg_diags_free(&dg);
}

static void test_deterministic(void) {
  static const char *names[] = {"delta", "hydraulic_bridge", "slider_crank", "lagrange_rlc"};
  for (size_t i = 0; i < sizeof names / sizeof *names; i++)
    for (int method = BG_METHOD_SCAP; method <= BG_METHOD_LAGRANGE; method++) {
      char *a = json_of(names[i], method), *b = json_of(names[i], method);
      OK(strlen(a) > 100);
      OK(strcmp(a, b) == 0);
      free(a);
      free(b);
    }
}

int main(void) {
  test_key_order();
  test_values();
  test_generic_lists();
  test_deterministic();
  return bg_t_done();
}
