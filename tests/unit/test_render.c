/* SPDX-License-Identifier: BSD-3-Clause */
/* Rendering: options, styles, scene contents (counted from the scene dump),
 * byte-identical output across runs, and every example in every format. */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "causality/causality.h"
#include "examples_list.h"
#include "harness.h"
#include "analysis/analysis.h"
#include "lang/lang.h"
#include "diagram/render.h"
#include "scene/style.h"

/* ---------------------------------------------------------------- a hand-built model */
static void model_alloc(bg_model *m) {
#define X(type, name, count) m->name = calloc((size_t)m->count + 1, sizeof(type));
  BG_MODEL_ARRAYS(X)
#undef X
}

static void model_release(bg_model *m) {
#define X(type, name, count) free((void *)m->name);
  BG_MODEL_ARRAYS(X)
#undef X
}

enum { U, J1, R1, T, J0, C1, I2, R2, NELEM };
static const int kinds[NELEM] = {BG_ELEM_SE, BG_ELEM_J1, BG_ELEM_R, BG_ELEM_TF,
                                 BG_ELEM_J0, BG_ELEM_C,  BG_ELEM_I, BG_ELEM_R};
static const char *names[NELEM] = {"U", "j1", "R1", "T", "j0", "C1", "I_2", "R2"};
static const int btail[] = {U, J1, J1, T, J0, J0, J0}, bhead[] = {J1, R1, T, J0, C1, I2, R2};
static const int bstroke[] = {BG_STROKE_HEAD, BG_STROKE_TAIL, BG_STROKE_HEAD, BG_STROKE_TAIL,
                              BG_STROKE_TAIL, BG_STROKE_HEAD, BG_STROKE_HEAD};

static void hand_model(bg_model *m) {
  memset(m, 0, sizeof *m);
  m->name = "hand";
  m->nelem = NELEM, m->nbond = 7, m->nbondref = 14, m->nsignal = 4;
  m->nstate = 1, m->nxnode = 1;
  model_alloc(m);
  for (int e = 0; e < NELEM; e++) m->elem_kind[e] = kinds[e], m->elem_name[e] = names[e];
  m->elem_modulated[I2] = 1;
  for (int b = 0; b < m->nbond; b++) {
    m->bond_num[b] = b + 1, m->bond_tail[b] = btail[b], m->bond_head[b] = bhead[b];
  }
  int k = 0;
  for (int e = 0; e < NELEM; e++) {
    m->elem_bondadr[e] = k;
    for (int b = 0; b < m->nbond; b++)
      if (btail[b] == e || bhead[b] == e) m->elem_bonds[k++] = b, m->elem_nbond[e]++;
  }
  m->signal_from[0] = C1, m->signal_to[0] = I2, m->signal_var[0] = "C1.e";
  /* self-modulation (MTF T = 1 + k*T.f2^2), a bond variable, a user state */
  m->elem_modulated[T] = 1;
  m->signal_from[1] = T, m->signal_to[1] = T, m->signal_var[1] = "T.f2";
  m->signal_from[2] = -1, m->signal_to[2] = R2, m->signal_var[2] = "e4";
  m->state_name[0] = "phi", m->state_expr[0] = 0, m->state_init[0] = -1;
  m->xnode[0] = (bg_xnode){.op = BG_X_FLOW, .ref = 0}; /* phi' = j1.f, the flow of bond 1 */
  m->signal_from[3] = -1, m->signal_to[3] = R1, m->signal_var[3] = "phi";
}

static int *ints(bg_analysis *a, int n, const int *v) {
  int *p = bg_arena_alloc(&a->arena, sizeof(int) * (size_t)n);
  memcpy(p, v, sizeof(int) * (size_t)n);
  return p;
}

static void hand_analysis(const bg_model *m, bg_analysis *a) {
  bg_analysis_init(a, m);
  for (int b = 0; b < m->nbond; b++) a->bond_stroke[b] = bstroke[b];
  a->elem_caus[I2] = BG_CAUS_DERIVATIVE;
  a->bond_conflict[6] = 1;
  a->nconflict = 1;
  a->conflict_node = ints(a, 1, (int[]){J0});
  a->conflict_type = ints(a, 1, (int[]){2});
  a->conflict_degree = ints(a, 1, (int[]){1});
  a->conflict_adr = ints(a, 1, (int[]){0});
  a->conflict_n = ints(a, 1, (int[]){2});
  a->conflict_bonds = ints(a, 2, (int[]){5, 6});
  a->npath = 1;
  a->path_adr = ints(a, 1, (int[]){0});
  a->path_n = ints(a, 1, (int[]){4});
  a->path_bonds = ints(a, 4, (int[]){1, 2, 3, 6});
  a->path_end0 = ints(a, 1, (int[]){R1});
  a->path_end1 = ints(a, 1, (int[]){R2});
  a->path_class = ints(a, 1, (int[]){2});
  a->path_order = ints(a, 1, (int[]){0});
  a->ntloop = 1;
  a->tloop_kind = ints(a, 1, (int[]){BG_TLOOP_FLAT});
  a->tloop_order = ints(a, 1, (int[]){1});
  a->tloop_adr = ints(a, 1, (int[]){0});
  a->tloop_n = ints(a, 1, (int[]){4});
  a->tloop_signals = ints(a, 4, (int[]){BG_SIG_FLOW(4), BG_SIG_EFFORT(4), BG_SIG_EFFORT(5), BG_SIG_FLOW(5)});
  a->nlag = 1;
  a->lag_junction = ints(a, 1, (int[]){J1});
  a->lag_bond = ints(a, 1, (int[]){-1});
}

/* ---------------------------------------------------------------- options and styles */
static void test_options(void) {
  unsigned bits = 0;
  INT_EQ(bg_show_parse("strokes,numbers", &bits), 0);
  INT_EQ(bits, BG_SHOW_STROKES | BG_SHOW_NUMBERS);
  INT_EQ(bg_show_parse("all", &bits), 0);
  INT_EQ(bits, BG_SHOW_ALL);
  INT_EQ(bg_show_parse("none", &bits), 0);
  INT_EQ(bits & BG_SHOW_ALL, 0);
  OK(bits != 0);
  INT_EQ(bg_show_parse("strokes,bogus", &bits), -1);
  int kind = 0, index = 0;
  INT_EQ(bg_highlight_parse("path:2", &kind, &index), 0);
  INT_EQ(kind, 'p');
  INT_EQ(index, 2);
  INT_EQ(bg_highlight_parse("conflict:1", &kind, &index), 0);
  INT_EQ(kind, 'c');
  INT_EQ(bg_highlight_parse("loop:0", &kind, &index), -1);
  INT_EQ(bg_highlight_parse("road:1", &kind, &index), -1);
}

static void test_styles(void) {
  bg_diags dg;
  bg_diags_init(&dg, "t", NULL, 0);
  bg_style st;
  bg_style_default(&st);
  INT_EQ(bg_style_parse(&st, "# c\nfont_size = 14\nharpoon = down\nlayer_colors = #ff0000, #00ff00\n", "x", &dg), 0);
  DBL_NEAR(st.font_size, 14, 0);
  INT_EQ(st.harpoon, BG_HARPOON_DOWN);
  INT_EQ(st.nlayer_color, 2);
  INT_EQ(dg.nerrors, 0);
  INT_EQ(bg_style_parse(&st, "fontsize = 3\n", "x", &dg), -1);
  INT_EQ(dg.nerrors, 1);
  OK(dg.n == 1 && strstr(dg.items[0].msg, "unknown style key 'fontsize'"));
  INT_EQ(bg_style_parse(&st, "color = red\n", "x", &dg), -1);
  INT_EQ(dg.nerrors, 2);
  const char *styles[] = {"default", "print", "slides"};
  for (int i = 0; i < 3; i++) {
    INT_EQ(bg_style_load(&st, styles[i], BG_SOURCE_DIR "/styles", &dg), 0);
  }
  INT_EQ(dg.nerrors, 2);
  INT_EQ(bg_style_load(&st, "nosuchstyle", BG_SOURCE_DIR "/styles", &dg), -1);
  INT_EQ(dg.nerrors, 3);
  /* the default file and the built-in default agree */
  bg_style file, builtin;
  bg_style_default(&builtin);
  bg_style_load(&file, BG_SOURCE_DIR "/styles/default.style", NULL, &dg);
  DBL_NEAR(file.font_size, builtin.font_size, 0);
  DBL_NEAR(file.line_width, builtin.line_width, 0);
  DBL_NEAR(file.layer_offset, builtin.layer_offset, 0);
  INT_EQ(file.nlayer_color, builtin.nlayer_color);
  bg_diags_free(&dg);
}

/* ---------------------------------------------------------------- the hand model */
static bg_render_opts opts_all(void) {
  bg_render_opts o = {0};
  o.show = BG_SHOW_ALL;
  o.style_dir = BG_SOURCE_DIR "/styles";
  return o;
}

static void test_hand_scene(void) {
  bg_model m;
  bg_analysis a;
  hand_model(&m);
  hand_analysis(&m, &a);
  bg_diags dg;
  bg_diags_init(&dg, "hand", NULL, 0);
  bg_render_opts o = opts_all();
  bg_diagram *d = bg_diagram_build(&m, &a, &o, &dg);
  OK(d != NULL);
  INT_EQ(dg.nerrors, 0);
  if (d) {
    INT_EQ(bg_diagram_count(d, "bond"), 7);
    INT_EQ(bg_diagram_count(d, "stroke"), 7);
    INT_EQ(bg_diagram_count(d, "number"), 7);
    INT_EQ(bg_diagram_count(d, "node"), NELEM);
    INT_EQ(bg_diagram_count(d, "flash"), 1);
    INT_EQ(bg_diagram_count(d, "conflict-text"), 1);
    INT_EQ(bg_diagram_count(d, "path"), 1);
    INT_EQ(bg_diagram_count(d, "loop"), 1);
    INT_EQ(bg_diagram_count(d, "gain"), 1);
    INT_EQ(bg_diagram_count(d, "signal"), 4);
    INT_EQ(bg_diagram_count(d, "signal-arrow"), 4);
    INT_EQ(bg_diagram_count(d, "state-node"), 1);
    INT_EQ(bg_diagram_count(d, "state-input"), 1);
    INT_EQ(bg_diagram_count(d, "lagrange"), 1);
    OK(bg_diagram_count(d, "legend-text") >= 5);
    bg_strbuf dump = {0};
    bg_diagram_dump(d, &dump);
    OK(strstr(bg_sb_str(&dump), "stroke bond=6 derivative") != NULL);
    OK(strstr(bg_sb_str(&dump), "stroke bond=7 conflict") != NULL);
    OK(strstr(bg_sb_str(&dump), "signal C1->I_2") != NULL);
    OK(strstr(bg_sb_str(&dump), "signal T->T") != NULL);
    OK(strstr(bg_sb_str(&dump), "signal-dot e4->R2") != NULL);
    OK(strstr(bg_sb_str(&dump), "signal phi->R1") != NULL);
    OK(strstr(bg_sb_str(&dump), "state-input j1->phi") != NULL);
    OK(strstr(bg_sb_str(&dump), "MI : I<span size=\"70%\"") != NULL);
    OK(strstr(bg_sb_str(&dump), "type 2, k = 1") != NULL);
    bg_sb_free(&dump);
    bg_strbuf dot = {0};
    INT_EQ(bg_diagram_render(d, "dot", &dot, &dg), 0);
    OK(strstr(bg_sb_str(&dot), "\"U\" -> \"j1\" [label=\"1\"") != NULL);
    bg_sb_free(&dot);
    INT_EQ(bg_diagram_write(d, "/nonexistent-dir/x.svg", NULL, &dg), BG_RENDER_EWRITE);
    INT_EQ(bg_diagram_write(d, BG_BINARY_DIR "/x.gif", NULL, &dg), BG_RENDER_ERROR);
    bg_diagram_free(d);
  }
  /* the default layers: no paths, loops or legend */
  o.show = 0;
  d = bg_diagram_build(&m, &a, &o, &dg);
  INT_EQ(bg_diagram_count(d, "path"), 0);
  INT_EQ(bg_diagram_count(d, "loop"), 0);
  INT_EQ(bg_diagram_count(d, "flash"), 1);
  INT_EQ(bg_diagram_count(d, "legend-text"), 0);
  bg_diagram_free(d);
  /* highlight: out of range is an error; in range draws the item */
  o.highlight_kind = 'p', o.highlight_index = 2;
  int before = dg.nerrors;
  OK(bg_diagram_build(&m, &a, &o, &dg) == NULL);
  INT_EQ(dg.nerrors, before + 1);
  o.highlight_index = 1;
  d = bg_diagram_build(&m, &a, &o, &dg);
  INT_EQ(bg_diagram_count(d, "path"), 1);
  bg_diagram_free(d);
  o.style = "nosuchstyle";
  OK(bg_diagram_build(&m, &a, &o, &dg) == NULL);
  bg_diags_free(&dg);
  bg_analysis_free(&a);
  model_release(&m);
}

/* ---------------------------------------------------------------- examples */
typedef struct loaded {
  char *src;
  size_t len;
  bg_diags dg;
  bg_model *m;
  bg_analysis a;
} loaded;

static int load(const char *path, loaded *L) {
  memset(L, 0, sizeof *L);
  L->src = bg_read_file(path, &L->len);
  bg_diags_init(&L->dg, path, L->src, L->len);
  if (!L->src) return -1;
  bg_ast *ast = bg_parse_string(path, L->src, L->len, &L->dg);
  if (!ast) return -1;
  L->m = L->dg.nerrors ? NULL : bg_model_compile(ast, NULL, 0, &L->dg);
  bg_ast_free(ast);
  if (!L->m) return -1;
  bg_analysis_init(&L->a, L->m);
  bg_causality_assign(L->m, L->m->method, &L->a, &L->dg);
  bg_analysis_run(L->m, &L->a, NULL);
  return 0;
}

static void unload(loaded *L) {
  if (L->m) bg_analysis_free(&L->a), bg_model_free(L->m);
  bg_diags_free(&L->dg);
  free(L->src);
}

static int expected_strokes(const bg_model *m, const bg_analysis *a) {
  int n = 0;
  for (int b = 0; b < m->nbond; b++) n += a->bond_stroke[b] != BG_STROKE_NONE;
  return n;
}

/* User states some signal comes from: each gets an integrator node. */
static int expected_state_nodes(const bg_model *m) {
  int n = 0;
  for (int s = 0; s < m->nstate; s++) {
    int used = 0;
    for (int i = 0; i < m->nsignal; i++)
      used |= m->signal_from[i] < 0 && !strcmp(m->signal_var[i], m->state_name[s]);
    n += used;
  }
  return n;
}

static int expected_lagrange(const bg_analysis *a) {
  int n = 0;
  for (int i = 0; i < a->nlag; i++) n += a->lag_junction[i] >= 0 || a->lag_bond[i] >= 0;
  return n;
}

/* Lines of the scene dump that start with `prefix` and contain `part`. */
static int dump_lines(const bg_diagram *d, const char *prefix, const char *part) {
  bg_strbuf dump = {0};
  bg_diagram_dump(d, &dump);
  int n = 0;
  for (const char *line = bg_sb_str(&dump); line && *line;) {
    const char *end = strchr(line, '\n');
    size_t len = end ? (size_t)(end - line) : strlen(line);
    char buf[512];
    snprintf(buf, sizeof buf, "%.*s", (int)(len < 511 ? len : 511), line);
    n += !strncmp(buf, prefix, strlen(prefix)) && strstr(buf, part);
    line = end ? end + 1 : NULL;
  }
  bg_sb_free(&dump);
  return n;
}

/* The signals drawn: one per modulating signal, but one per source into a
 * multiport field (drawn as one node) however many of its ports' laws read
 * it. */
static int expected_signals(const bg_model *m) {
  int n = 0;
  for (int i = 0; i < m->nsignal; i++) {
    int f = bg_elem_field(m, m->signal_to[i]), dup = 0;
    for (int j = 0; j < i && f >= 0 && !dup; j++)
      dup = bg_elem_field(m, m->signal_to[j]) == f && m->signal_from[j] == m->signal_from[i] &&
            (m->signal_from[i] >= 0 || !strcmp(m->signal_var[j], m->signal_var[i]));
    n += !dup;
  }
  return n;
}

/* Every count the diagram must show for `show`: one stroke per causal bond,
 * one flash per conflict, one polyline per shown path or loop (a flat loop
 * drawn with its causal path counts as that path's "path K loop=L"), one
 * arrow per modulating signal (expected_signals), one number per bond. */
static void check_counts(const bg_diagram *d, const loaded *L, unsigned show, const char *what) {
  const bg_model *m = L->m;
  const bg_analysis *a = &L->a;
  int merged = dump_lines(d, "path ", " loop=");
#define CNT(role, expect)                                                                   \
  BG_T_REPORT(bg_diagram_count(d, role) == (expect), "%s: %s: %d drawn, %d expected", what, \
              role, bg_diagram_count(d, role), (int)(expect))
  CNT("bond", m->nbond);
  CNT("node", m->nelem);
  CNT("stroke", show & BG_SHOW_STROKES ? expected_strokes(m, a) : 0);
  CNT("number", show & BG_SHOW_VARIABLES ? 0 : show & BG_SHOW_NUMBERS ? m->nbond : 0);
  CNT("variable", show & BG_SHOW_VARIABLES ? 2 * m->nbond : 0);
  CNT("flash", show & BG_SHOW_CONFLICTS ? a->nconflict : 0);
  CNT("conflict-text", show & BG_SHOW_CONFLICTS ? a->nconflict : 0);
  CNT("path", show & BG_SHOW_PATHS ? a->npath : 0);
  CNT("path-tag", show & BG_SHOW_PATHS ? a->npath : 0);
  CNT("loop", show & BG_SHOW_LOOPS ? a->ntloop - merged : 0);
  CNT("gain", show & BG_SHOW_LOOPS ? a->ntloop - merged : 0);
  BG_T_REPORT(merged == dump_lines(d, "path-tag ", " gain"), "%s: merged loops keep their gain", what);
  if (!((show & BG_SHOW_PATHS) && (show & BG_SHOW_LOOPS))) INT_EQ(merged, 0);
  CNT("signal", show & BG_SHOW_SIGNALS ? expected_signals(m) : 0);
  CNT("signal-arrow", show & BG_SHOW_SIGNALS ? expected_signals(m) : 0);
  CNT("state-node", show & BG_SHOW_SIGNALS ? expected_state_nodes(m) : 0);
  CNT("lagrange", expected_lagrange(a));
  BG_T_REPORT((bg_diagram_count(d, "legend-text") > 0) == !!(show & BG_SHOW_LEGEND),
              "%s: legend drawn iff shown", what);
#undef CNT
}

static int xml_ok(const bg_strbuf *svg) {
  char path[1024], cmd[1200];
  snprintf(path, sizeof path, "%s/render_check.svg", BG_BINARY_DIR);
  FILE *f = fopen(path, "wb");
  if (!f) return 0;
  fwrite(svg->s, 1, svg->len, f);
  fclose(f);
  snprintf(cmd, sizeof cmd, "xmllint --noout %s", path);
  return system(cmd) == 0;
}

static const char *const styles[] = {"default", "print", "slides"};
static const unsigned shows[] = {BG_SHOW_ALL, BG_SHOW_DEFAULT, BG_SHOW_DEFAULT | BG_SHOW_VARIABLES};

/* One example under every style and layer set: counts, every format, and
 * well-formed SVG. */
static void check_example(const char *path) {
  loaded L;
  OK(load(path, &L) == 0);
  if (!L.m) {
    fprintf(stderr, "cannot load %s\n", path);
    unload(&L);
    return;
  }
  for (int si = 0; si < 3; si++)
    for (int k = 0; k < 3; k++) {
      bg_render_opts o = opts_all();
      o.style = styles[si], o.show = shows[k];
      bg_diagram *d = bg_diagram_build(L.m, &L.a, &o, &L.dg);
      BG_T_REPORT(d != NULL, "%s builds with style %s", path, styles[si]);
      if (!d) continue;
      char what[1200];
      snprintf(what, sizeof what, "%s (%s, show %#x)", path, styles[si], shows[k]);
      check_counts(d, &L, shows[k], what);
      const char *formats[] = {"svg", "pdf", "png", "dot"};
      for (int i = 0; i < 4; i++) {
        if (k == 2 && i > 0) break; /* the variables layer: SVG is enough */
        bg_strbuf out = {0};
        INT_EQ(bg_diagram_render(d, formats[i], &out, &L.dg), 0);
        OK(out.len > 100);
        if (i == 0) BG_T_REPORT(xml_ok(&out), "%s: well-formed SVG", what);
        bg_sb_free(&out);
      }
      bg_diagram_free(d);
    }
  INT_EQ(L.dg.nerrors, 0);
  unload(&L);
}

static void test_examples(void) {
  char *names[256];
  int n = bg_t_list_examples(names, 256);
  OK(n >= 17);
  for (int i = 0; i < n; i++) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/%s", BG_SOURCE_DIR, names[i]);
    check_example(path);
    free(names[i]);
  }
}

/* ---------------------------------------------------------------- redrawing a layout */
/* The scene dump split into lines (a copy the caller frees with free_lines). */
typedef struct lines {
  char **l;
  int n;
} lines;

static lines dump_split(const bg_diagram *d) {
  bg_strbuf dump = {0};
  bg_diagram_dump(d, &dump);
  lines L = {calloc((size_t)dump.len + 1, sizeof(char *)), 0};
  for (char *p = strtok(dump.s, "\n"); p; p = strtok(NULL, "\n")) L.l[L.n++] = strdup(p);
  bg_sb_free(&dump);
  return L;
}

static void free_lines(lines *L) {
  for (int i = 0; i < L->n; i++) free(L->l[i]);
  free(L->l);
}

/* "node NAME\ttext #rrggbb X,Y size ..." → "X,Y" of every node label (and
 * state integrator), one string "role X,Y" per node, in scene order. */
static int node_positions(const bg_diagram *d, char out[][192], int cap) {
  lines L = dump_split(d);
  int n = 0;
  for (int i = 0; i < L.n && n < cap; i++) {
    const char *ln = L.l[i];
    if (strncmp(ln, "node ", 5) && strncmp(ln, "state-node ", 11)) continue;
    const char *tab = strchr(ln, '\t'), *sz = strstr(ln, " size ");
    const char *xy = tab ? strchr(tab + 7, ' ') : NULL; /* after "\ttext #rrggbb" */
    if (!tab || !sz || !xy) continue;
    snprintf(out[n++], 192, "%.*s %.*s", (int)(tab - ln), ln, (int)(sz - xy - 1), xy + 1);
  }
  free_lines(&L);
  return n;
}

static int same_nodes(const bg_diagram *a, const bg_diagram *b) {
  static char pa[512][192], pb[512][192];
  int na = node_positions(a, pa, 512), nb = node_positions(b, pb, 512), same = na == nb && na > 0;
  for (int i = 0; same && i < na; i++) same = !strcmp(pa[i], pb[i]);
  return same;
}

/* Two dumps show the same items (roles, colours, texts, sizes) with every
 * point moved by one offset (within the dump's rounding). */
static int same_up_to_offset(const bg_diagram *a, const bg_diagram *b) {
  lines A = dump_split(a), B = dump_split(b);
  int same = A.n == B.n, have = 0;
  double dx = 0, dy = 0;
  for (int i = 1; same && i < A.n; i++) { /* line 0: the page size */
    char *sa, *sb, *ta = strtok_r(A.l[i], " ", &sa), *tb = strtok_r(B.l[i], " ", &sb);
    for (; same && ta && tb; ta = strtok_r(NULL, " ", &sa), tb = strtok_r(NULL, " ", &sb)) {
      double xa, ya, xb, yb;
      char ca, cb;
      int pa = sscanf(ta, "%lf,%lf%c", &xa, &ya, &ca) == 2, pb = sscanf(tb, "%lf,%lf%c", &xb, &yb, &cb) == 2;
      if (pa != pb) same = 0;
      else if (!pa) same = !strcmp(ta, tb);
      else if (!have) dx = xa - xb, dy = ya - yb, have = 1;
      else same = fabs(xa - xb - dx) < 0.15 && fabs(ya - yb - dy) < 0.15;
    }
    if (ta || tb) same = 0;
  }
  free_lines(&A);
  free_lines(&B);
  return same;
}

/* Bonds drawn in colour (not muted_color). */
static int hot_bonds(const bg_diagram *d) {
  lines L = dump_split(d);
  int n = 0;
  for (int i = 0; i < L.n; i++) n += !strncmp(L.l[i], "bond ", 5) && !strstr(L.l[i], " #c8c8c8 ");
  free_lines(&L);
  return n;
}

static int distinct(const int *v, int n, int half) {
  int k = 0;
  for (int i = 0; i < n; i++) {
    int seen = 0;
    for (int j = 0; j < i; j++) seen |= (half ? v[j] / 2 : v[j]) == (half ? v[i] / 2 : v[i]);
    k += !seen;
  }
  return k;
}

/* Every path, loop and conflict of an example highlighted from the full
 * diagram's layout (as the report does): the nodes stay where they are in
 * the full diagram, on its page; the highlight draws its own layer once and
 * its bonds in colour; and the drawing is a fresh build's, moved. */
static void check_redraw(const char *path) {
  loaded L;
  OK(load(path, &L) == 0);
  if (!L.m) {
    unload(&L);
    return;
  }
  const bg_analysis *a = &L.a;
  bg_render_opts o = opts_all();
  bg_diagram *full = bg_diagram_build(L.m, a, &o, &L.dg);
  OK(full != NULL);
  static const int kinds[] = {'p', 'l', 'c'};
  for (int ki = 0; full && ki < 3; ki++) {
    int kind = kinds[ki], n = kind == 'p' ? a->npath : kind == 'l' ? a->ntloop : a->nconflict;
    for (int k = 0; k < n; k++) {
      bg_diagram *h = bg_diagram_redraw(full, BG_SHOW_DEFAULT, kind, k + 1, &L.dg);
      char what[1200];
      snprintf(what, sizeof what, "%s: %c%d redrawn", path, kind, k + 1);
      BG_T_REPORT(h != NULL, "%s", what);
      if (!h) continue;
      double fw, fh, hw, hh;
      bg_diagram_size(full, &fw, &fh), bg_diagram_size(h, &hw, &hh);
      BG_T_REPORT(fw == hw && fh == hh, "%s: on the full diagram's page", what);
      BG_T_REPORT(same_nodes(full, h), "%s: nodes where the full diagram has them", what);
      int want = kind == 'p' ? distinct(a->path_bonds + a->path_adr[k], a->path_n[k], 0)
                 : kind == 'l' ? distinct(a->tloop_signals + a->tloop_adr[k], a->tloop_n[k], 1)
                               : distinct(a->conflict_bonds + a->conflict_adr[k], a->conflict_n[k], 0);
      BG_T_REPORT(hot_bonds(h) == want, "%s: %d bonds in colour, %d expected", what, hot_bonds(h), want);
      BG_T_REPORT(bg_diagram_count(h, "path") == (kind == 'p') &&
                  bg_diagram_count(h, "path-tag") == (kind == 'p') &&
                  bg_diagram_count(h, "loop") == (kind == 'l') &&
                  bg_diagram_count(h, "gain") == (kind == 'l'), "%s: only its own layer", what);
      BG_T_REPORT(bg_diagram_count(h, "flash") == a->nconflict, "%s: conflicts", what);
      BG_T_REPORT(bg_diagram_count(h, "legend-text") == 0, "%s: no legend", what);
      bg_render_opts ho = opts_all();
      ho.show = BG_SHOW_DEFAULT, ho.highlight_kind = kind, ho.highlight_index = k + 1;
      ho.layer_room = 1; /* the full diagram's layout has room for its layers */
      bg_diagram *fresh = bg_diagram_build(L.m, a, &ho, &L.dg);
      BG_T_REPORT(fresh && same_up_to_offset(h, fresh), "%s: a fresh build's drawing", what);
      bg_diagram_free(fresh);
      bg_diagram_free(h);
    }
  }
  bg_diagram_free(full);
  INT_EQ(L.dg.nerrors, 0);
  unload(&L);
}

static void test_redraw(void) {
  char *names[256];
  int n = bg_t_list_examples(names, 256);
  for (int i = 0; i < n; i++) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/%s", BG_SOURCE_DIR, names[i]);
    check_redraw(path);
    free(names[i]);
  }
  /* the hand model: layers that decide the nodes stay; the page grows for a
   * larger drawing; a bad index is an error; the copy outlives its source */
  bg_model m;
  bg_analysis a;
  hand_model(&m);
  hand_analysis(&m, &a);
  bg_diags dg;
  bg_diags_init(&dg, "hand", NULL, 0);
  bg_render_opts o = opts_all();
  o.show = BG_SHOW_DEFAULT;
  bg_diagram *d = bg_diagram_build(&m, &a, &o, &dg);
  bg_diagram *strokes = bg_diagram_redraw(d, BG_SHOW_STROKES, 0, 0, &dg);
  OK(strokes && same_nodes(d, strokes));
  INT_EQ(bg_diagram_count(strokes, "signal"), 4); /* signals decide the nodes: kept */
  INT_EQ(bg_diagram_count(strokes, "number"), 0);
  bg_diagram *all = bg_diagram_redraw(d, BG_SHOW_ALL, 'l', 1, &dg);
  double w0, h0, w1, h1;
  bg_diagram_size(d, &w0, &h0), bg_diagram_size(all, &w1, &h1);
  OK(w1 >= w0 && h1 > h0); /* the legend below */
  INT_EQ(bg_diagram_count(all, "path"), 1);
  INT_EQ(bg_diagram_count(all, "loop"), 1);
  OK(bg_diagram_count(all, "legend-text") >= 5);
  int before = dg.nerrors;
  OK(bg_diagram_redraw(d, 0, 'c', 2, &dg) == NULL);
  INT_EQ(dg.nerrors, before + 1);
  bg_diagram *again = bg_diagram_redraw(strokes, 0, 'p', 1, &dg);
  bg_diagram_free(d);
  bg_diagram_free(strokes);
  OK(again && bg_diagram_count(again, "path") == 1);
  const char *formats[] = {"svg", "pdf", "png", "dot"};
  for (int i = 0; again && i < 4; i++) {
    bg_strbuf out = {0};
    INT_EQ(bg_diagram_render(again, formats[i], &out, &dg), 0);
    OK(out.len > 100);
    bg_sb_free(&out);
  }
  bg_diagram_free(again);
  bg_diagram_free(all);
  bg_diags_free(&dg);
  bg_analysis_free(&a);
  model_release(&m);
}

/* ---------------------------------------------------------------- determinism */
/* Renders the hand model and an example in a child process (cairo's SVG ids
 * are per-process counters: a fresh process is what a user's rerun sees). */
static void render_in_child(const char *tag) {
  pid_t pid = fork();
  if (pid == 0) {
    bg_model m;
    bg_analysis a;
    hand_model(&m);
    hand_analysis(&m, &a);
    bg_diags dg;
    bg_diags_init(&dg, "hand", NULL, 0);
    bg_render_opts o = opts_all();
    bg_diagram *d = bg_diagram_build(&m, &a, &o, &dg);
    const char *formats[] = {"svg", "pdf", "png", "dot"};
    int rc = d ? 0 : 1;
    for (int i = 0; d && i < 4; i++) {
      char path[1024];
      snprintf(path, sizeof path, "%s/render_%s.%s", BG_BINARY_DIR, tag, formats[i]);
      rc |= bg_diagram_write(d, path, NULL, &dg);
    }
    bg_diagram_free(d);
    _exit(rc ? 1 : 0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  OK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

/* Every example under every style (all layers), in a child process: one line
 * "example style format hash" per output, to compare two runs. */
static unsigned long long fnv1a(const char *s, size_t n) {
  unsigned long long h = 1469598103934665603ull;
  for (size_t i = 0; i < n; i++) h = (h ^ (unsigned char)s[i]) * 1099511628211ull;
  return h;
}

static void hash_examples_in_child(const char *tag) {
  pid_t pid = fork();
  if (pid == 0) {
    char path[1024], *names[256];
    snprintf(path, sizeof path, "%s/render_hashes_%s.txt", BG_BINARY_DIR, tag);
    FILE *out = fopen(path, "w");
    int n = bg_t_list_examples(names, 256), rc = out ? 0 : 1;
    for (int i = 0; out && i < n; i++) {
      loaded L;
      snprintf(path, sizeof path, "%s/examples/%s", BG_SOURCE_DIR, names[i]);
      if (load(path, &L) != 0) rc = 1;
      for (int si = 0; L.m && si < 3; si++) {
        bg_render_opts o = opts_all();
        o.style = styles[si];
        bg_diagram *d = bg_diagram_build(L.m, &L.a, &o, &L.dg);
        const char *formats[] = {"svg", "pdf", "png", "dot"};
        for (int k = 0; d && k < 4; k++) {
          bg_strbuf b = {0};
          rc |= bg_diagram_render(d, formats[k], &b, &L.dg);
          fprintf(out, "%s %s %s %016llx\n", names[i], styles[si], formats[k], fnv1a(b.s, b.len));
          bg_sb_free(&b);
        }
        rc |= d == NULL;
        bg_diagram_free(d);
      }
      unload(&L);
    }
    if (out) fclose(out);
    _exit(rc ? 1 : 0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  OK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

static int same_file(const char *a, const char *b) {
  FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
  int same = fa && fb;
  while (same) {
    int ca = fgetc(fa), cb = fgetc(fb);
    if (ca != cb) same = 0;
    if (ca == EOF) break;
  }
  if (fa) fclose(fa);
  if (fb) fclose(fb);
  return same;
}

static void test_determinism(void) {
  render_in_child("a");
  render_in_child("b");
  const char *formats[] = {"svg", "pdf", "png", "dot"};
  for (int i = 0; i < 4; i++) {
    char a[1024], b[1024];
    snprintf(a, sizeof a, "%s/render_a.%s", BG_BINARY_DIR, formats[i]);
    snprintf(b, sizeof b, "%s/render_b.%s", BG_BINARY_DIR, formats[i]);
    BG_T_REPORT(same_file(a, b), "%s and %s are identical", a, b);
  }
  char cmd[2048];
  snprintf(cmd, sizeof cmd, "xmllint --noout %s/render_a.svg", BG_BINARY_DIR);
  INT_EQ(system(cmd), 0);
  /* every example, style and format: byte-identical across processes */
  hash_examples_in_child("a");
  hash_examples_in_child("b");
  char a[1024], b[1024];
  snprintf(a, sizeof a, "%s/render_hashes_a.txt", BG_BINARY_DIR);
  snprintf(b, sizeof b, "%s/render_hashes_b.txt", BG_BINARY_DIR);
  BG_T_REPORT(same_file(a, b), "%s and %s are identical", a, b);
}

int main(void) {
  test_options();
  test_styles();
  test_hand_scene();
  test_examples();
  test_redraw();
  test_determinism();
  return bg_t_done();
}
