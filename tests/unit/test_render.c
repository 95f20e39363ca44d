/* Rendering: options, styles, scene contents (counted from the scene dump),
 * byte-identical output across runs, and every example in every format. */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "causality.h"
#include "harness.h"
#include "paths.h"
#include "parse.h"
#include "render.h"
#include "style.h"

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
  m->nelem = NELEM, m->nbond = 7, m->nbondref = 14, m->nsignal = 1;
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
    INT_EQ(bg_diagram_count(d, "signal"), 1);
    INT_EQ(bg_diagram_count(d, "lagrange"), 1);
    OK(bg_diagram_count(d, "legend-text") >= 5);
    bg_strbuf dump = {0};
    bg_diagram_dump(d, &dump);
    OK(strstr(bg_sb_str(&dump), "stroke bond=6 derivative") != NULL);
    OK(strstr(bg_sb_str(&dump), "stroke bond=7 conflict") != NULL);
    OK(strstr(bg_sb_str(&dump), "signal C1->I_2") != NULL);
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

static int expected_signals(const bg_model *m) {
  int n = 0;
  for (int i = 0; i < m->nsignal; i++) n += m->signal_from[i] >= 0 && m->signal_from[i] != m->signal_to[i];
  return n;
}

static void check_example(const char *path) {
  loaded L;
  OK(load(path, &L) == 0);
  if (!L.m) {
    fprintf(stderr, "cannot load %s\n", path);
    unload(&L);
    return;
  }
  bg_render_opts o = opts_all();
  bg_diagram *d = bg_diagram_build(L.m, &L.a, &o, &L.dg);
  OK(d != NULL);
  if (d) {
    INT_EQ(bg_diagram_count(d, "bond"), L.m->nbond);
    INT_EQ(bg_diagram_count(d, "stroke"), expected_strokes(L.m, &L.a));
    INT_EQ(bg_diagram_count(d, "flash"), L.a.nconflict);
    INT_EQ(bg_diagram_count(d, "path"), L.a.npath);
    INT_EQ(bg_diagram_count(d, "loop"), L.a.ntloop);
    INT_EQ(bg_diagram_count(d, "signal"), expected_signals(L.m));
    const char *formats[] = {"svg", "pdf", "png", "dot"};
    for (int i = 0; i < 4; i++) {
      bg_strbuf out = {0};
      INT_EQ(bg_diagram_render(d, formats[i], &out, &L.dg), 0);
      OK(out.len > 100);
      bg_sb_free(&out);
    }
    bg_diagram_free(d);
  }
  unload(&L);
}

static void test_examples(void) {
  DIR *dir = opendir(BG_SOURCE_DIR "/examples");
  OK(dir != NULL);
  if (!dir) return;
  char *names[256];
  int n = 0;
  for (struct dirent *e; (e = readdir(dir)) && n < 256;) {
    size_t len = strlen(e->d_name);
    if (len > 3 && !strcmp(e->d_name + len - 3, ".bg")) names[n++] = strdup(e->d_name);
  }
  closedir(dir);
  OK(n >= 10);
  for (int i = 0; i < n; i++) {
    char path[1024];
    snprintf(path, sizeof path, "%s/examples/%s", BG_SOURCE_DIR, names[i]);
    check_example(path);
    free(names[i]);
  }
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
}

int main(void) {
  test_options();
  test_styles();
  test_hand_scene();
  test_examples();
  test_determinism();
  return bg_t_done();
}
