/* SPDX-License-Identifier: BSD-3-Clause */
/* libbgdraw as its users see it (include/bgdraw.h only, linked against the
 * shared library): every output of every example and test model is byte
 * for byte what the command line writes, with the same status; the results
 * as data (bonds, strokes, paths, loops, index, a simulation against its
 * closed form, a transfer function); diagnostics as records; options;
 * two handles on two threads. */
#include <bgdraw.h>
#include <dirent.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "harness.h"

static char tmp[256];
static char *out_of(bgd_model *m, const char *kind, const char *form);

static char *slurp(const char *path, size_t *len) {
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char *b = malloc((size_t)n + 1);
  size_t got = fread(b, 1, (size_t)n, f);
  fclose(f);
  b[got] = 0;
  *len = got;
  return b;
}

/* The command line's exit status for `bgdraw MODEL ARGS` (stdout into out, stderr dropped). */
static int cli(const char *model, const char *args, const char *out) {
  char cmd[4096];
  snprintf(cmd, sizeof cmd, "'%s' '%s' -q %s >'%s' 2>/dev/null", BG_EXE, model, args,
           out ? out : "/dev/null");
  int st = system(cmd);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* Same bytes in two files, or both missing. */
static int same_files(const char *a, const char *b) {
  size_t na = 0, nb = 0;
  char *x = slurp(a, &na), *y = slurp(b, &nb);
  int same = (!x && !y) || (x && y && na == nb && !memcmp(x, y, na));
  free(x), free(y);
  return same;
}

static int outputs_checked, files_checked;

/* One output kind through the library (bgd_write into lib/NAME) and the
 * command line (cli/NAME): the same bytes and the same status. */
static void compare_file(bgd_model *m, const char *model, const char *kind, const char *form,
                         const char *name, const char *cli_args) {
  char lib[512], cl[512], args[1200];
  snprintf(lib, sizeof lib, "%s/lib/%s", tmp, name);
  snprintf(cl, sizeof cl, "%s/cli/%s", tmp, name);
  unlink(lib), unlink(cl);
  int lrc = bgd_write(m, kind, form, lib);
  snprintf(args, sizeof args, cli_args, cl);
  int crc = cli(model, args, NULL);
  /* the command line writes a file and then may exit 3 (a simulation
   * refused after the outputs); the library refuses the one output */
  int agree = lrc == crc || (lrc == BGD_REFUSED && crc == 3) || (lrc == 0 && crc == 3);
  BG_T_REPORT(agree, "%s %s: library status %d, command line %d", model, name, lrc, crc);
  BG_T_REPORT(same_files(lib, cl), "%s %s: library and command line differ", model, name);
  files_checked++;
}

/* One output on standard output (--check, --equations, --linear). */
static void compare_stdout(bgd_model *m, const char *model, const char *kind, const char *form,
                           const char *cli_args) {
  char cl[512];
  snprintf(cl, sizeof cl, "%s/stdout", tmp);
  int crc = cli(model, cli_args, cl);
  char *data = NULL;
  size_t n = 0;
  int lrc = bgd_output(m, kind, form, &data, &n);
  size_t cn = 0;
  char *want = slurp(cl, &cn);
  int same = lrc == 0 ? want && cn == n && !memcmp(want, data, n) : cn == 0 || crc != 0;
  BG_T_REPORT(same, "%s %s %s: library (status %d, %zu bytes) and command line (status %d, %zu bytes) differ",
              model, kind, form ? form : "", lrc, n, crc, cn);
  outputs_checked++;
  free(data), free(want);
}

static void every_output(const char *model) {
  bgd_model *m = bgd_open_file(model, NULL);
  if (bgd_status(m) != BGD_OK) { /* a library file of submodels: both refuse */
    BG_T_REPORT(cli(model, "--check", NULL) == 1, "%s: the library refused, the CLI did not", model);
    bgd_free(m);
    return;
  }
  static const char *const diagram[] = {"svg", "pdf", "png", "dot", "json", "tex", "py", "m", "mo", "csv"};
  for (int i = 0; i < 10; i++) {
    char name[64], args[64];
    snprintf(name, sizeof name, "x.%s", diagram[i]);
    snprintf(args, sizeof args, "%s", "-o '%s'");
    compare_file(m, model, diagram[i], NULL, name, args);
  }
  compare_file(m, model, "c", NULL, "x.c", "-o '%s'"); /* and x.h beside it */
  char lib_h[512], cli_h[512];
  snprintf(lib_h, sizeof lib_h, "%s/lib/x.h", tmp);
  snprintf(cli_h, sizeof cli_h, "%s/cli/x.h", tmp);
  unlink(lib_h);
  int hrc = bgd_write(m, "h", NULL, lib_h);
  BG_T_REPORT(hrc == 0 ? same_files(lib_h, cli_h) : access(cli_h, F_OK) != 0,
              "%s x.h: library (status %d) and command line differ", model, hrc);
  unlink(cli_h);
  compare_file(m, model, "plot", NULL, "p.svg", "--plot '%s'");
  compare_file(m, model, "report", NULL, "r.pdf", "--report '%s'");
  compare_stdout(m, model, "check", NULL, "--check");
  static const char *const forms[] = {"text", "latex", "json", "c"};
  char args[64];
  for (int i = 0; i < 4; i++) {
    snprintf(args, sizeof args, "--equations %s", forms[i]);
    compare_stdout(m, model, "equations", forms[i], args);
  }
  compare_stdout(m, model, "linear", "text", "--linear text");
  compare_stdout(m, model, "linear", "json", "--linear json");
  bgd_free(m);
}

static void collect_models(const char *dir, char **out, int *n, int cap) {
  DIR *d = opendir(dir);
  if (!d) return;
  for (struct dirent *e; (e = readdir(d)) && *n < cap;) {
    if (e->d_name[0] == '.') continue;
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    struct stat st;
    if (stat(path, &st) != 0) continue;
    size_t len = strlen(e->d_name);
    if (S_ISDIR(st.st_mode)) collect_models(path, out, n, cap);
    else if (len > 3 && !strcmp(e->d_name + len - 3, ".bg")) out[(*n)++] = strdup(path);
  }
  closedir(d);
}

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

static void test_every_output(void) {
  char *models[256];
  int n = 0;
  collect_models("examples", models, &n, 256);
  collect_models("tests/data", models, &n, 256);
  qsort(models, (size_t)n, sizeof *models, by_name);
  OK(n >= 30);
  for (int i = 0; i < n; i++) {
    every_output(models[i]);
    free(models[i]);
  }
  OK(files_checked >= 30 * 14 && outputs_checked >= 30 * 7);
}

/* ---------------------------------------------------------- results as data */
static void test_rlc_data(void) {
  bgd_model *m = bgd_open_file("examples/rlc.bg", NULL);
  INT_EQ(bgd_status(m), BGD_OK);
  STR_EQ(bgd_name(m), "rlc");
  INT_EQ(bgd_count(m, "elements"), 5);
  INT_EQ(bgd_count(m, "bonds"), 4);
  INT_EQ(bgd_count(m, "states"), 2);
  INT_EQ(bgd_count(m, "conflicts"), 0);
  INT_EQ(bgd_count(m, "no such thing"), -1);
  bgd_element e;
  INT_EQ(bgd_element_at(m, 0, &e), BGD_OK);
  STR_EQ(e.name, "U");
  STR_EQ(e.kind, "Se");
  INT_EQ(bgd_element_at(m, 99, &e), BGD_USAGE);
  /* a 1-junction with an effort source: the source's bond has its stroke at
   * the junction; the inertia in integral causality is given the effort
   * (stroke at its end), the resistor and the capacitor the flow (stroke
   * at the junction's end) */
  bgd_bond b;
  INT_EQ(bgd_bond_at(m, 0, &b), BGD_OK);
  INT_EQ(b.number, 1);
  STR_EQ(b.from, "U");
  STR_EQ(b.to, "j");
  STR_EQ(b.stroke, "to");
  INT_EQ(bgd_bond_at(m, 2, &b), BGD_OK);
  STR_EQ(b.to, "L1");
  STR_EQ(b.stroke, "to");
  INT_EQ(bgd_bond_at(m, 3, &b), BGD_OK);
  STR_EQ(b.to, "C1");
  STR_EQ(b.stroke, "from");
  INT_EQ(bgd_element_at(m, 3, &e), BGD_OK);
  STR_EQ(e.name, "L1");
  STR_EQ(e.causality, "integral");
  /* the numeric index the command line reports (JSON 0, "computed", "ode") */
  bgd_index ix;
  INT_EQ(bgd_index_info(m, &ix), BGD_OK);
  STR_EQ(ix.form, "ode");
  INT_EQ(ix.predicted, 0);
  INT_EQ(ix.numeric, 0);
  STR_EQ(ix.numeric_status, "computed");
  STR_EQ(ix.reduced_form, "ode");
  OK(ix.reduction == NULL);
  /* eigenvalues of L q'' + R q' + q/C: -R/2L +- j sqrt(1/LC - (R/2L)^2) */
  const double *re, *im;
  int ne = bgd_eigenvalues(m, &re, &im);
  INT_EQ(ne, 2);
  double alpha = 10 / (2 * 1e-3), wd = sqrt(1 / (1e-3 * 1e-6) - alpha * alpha);
  if (ne == 2) {
    DBL_NEAR(re[0], -alpha, 1e-6 * alpha);
    DBL_NEAR(fabs(im[0]), wd, 1e-6 * wd);
  }
  /* the simulation against the closed form of the capacitor's voltage */
  bgd_simulation s;
  INT_EQ(bgd_simulate(m, &s), BGD_OK);
  OK(s.nrows > 10);
  int qcol = -1;
  for (int j = 0; j < s.ncolumns; j++)
    if (!strcmp(s.names[j], "C1.e")) qcol = j;
  OK(qcol >= 0);
  const double *q = qcol >= 0 ? bgd_column(m, qcol) : NULL;
  double worst = 0, range = 0;
  for (int k = 0; q && k < s.nrows; k++) {
    double t = s.time[k];
    double exact = 1 - exp(-alpha * t) * (cos(wd * t) + alpha / wd * sin(wd * t));
    worst = fmax(worst, fabs(q[k] - exact));
    range = fmax(range, fabs(exact));
  }
  OK(q && worst <= 1e-5 * range);
  INT_EQ(bgd_count(m, "rows"), s.nrows);
  OK(bgd_column(m, s.ncolumns) == NULL);
  bgd_free(m);
}

/* bond_loop: the second example; numeric index 1, an ODE after elimination. */
static void test_bond_loop_index(void) {
  bgd_model *m = bgd_open_file("examples/bond_loop.bg", NULL);
  bgd_index ix;
  INT_EQ(bgd_index_info(m, &ix), BGD_OK);
  INT_EQ(ix.numeric, 1);
  STR_EQ(ix.numeric_status, "computed");
  STR_EQ(ix.reduced_form, "ode");
  char *json = NULL;
  INT_EQ(bgd_output(m, "json", NULL, &json, NULL), BGD_OK);
  OK(json && strstr(json, "\"numeric\": 1,") && strstr(json, "\"reduced_form\": \"ode\""));
  free(json);
  bgd_free(m);
}

/* Paths and loops of the hydraulic bridge (Figure 4.2): five topological
 * loops, each with bonds and a gain; every causal path's bonds run between its ends. */
static void test_paths_loops(void) {
  bgd_model *m = bgd_open_file("examples/hydraulic_bridge.bg", NULL);
  int nt = bgd_count(m, "topological_loops"), np = bgd_count(m, "causal_paths");
  INT_EQ(nt, 5);
  OK(np > 0);
  for (int i = 0; i < nt; i++) {
    bgd_loop l;
    INT_EQ(bgd_topological_loop_at(m, i, &l), BGD_OK);
    OK(l.nbonds >= 1 && l.gain && *l.gain);
    OK(!strcmp(l.kind, "flat") || !strcmp(l.kind, "open"));
  }
  for (int i = 0; i < np; i++) {
    bgd_path p;
    INT_EQ(bgd_causal_path_at(m, i, &p), BGD_OK);
    OK(p.nbonds >= 1 && p.from && p.to && (p.cls == 0 || p.cls == 1 || p.cls == 2));
    /* a path from a source closes no loop: no order (the JSON's null) */
    int from_source = !strcmp(p.kind, "S-*");
    BG_T_REPORT(from_source ? p.order == BGD_NO_ORDER : p.order > -100 && p.order < 100,
                "path %d (%s): order %d", i + 1, p.kind, p.order);
    /* the first bond touches the first end, the last the other */
    bgd_bond first = {0}, last = {0};
    int fi = -1, li = -1, nb = bgd_count(m, "bonds");
    for (int k = 0; k < nb; k++) {
      bgd_bond b;
      bgd_bond_at(m, k, &b);
      if (b.number == p.bonds[0]) fi = k, first = b;
      if (b.number == p.bonds[p.nbonds - 1]) li = k, last = b;
    }
    OK(fi >= 0 && li >= 0);
    if (fi >= 0 && li >= 0) {
      OK(!strcmp(first.from, p.from) || !strcmp(first.to, p.from));
      OK(!strcmp(last.from, p.to) || !strcmp(last.to, p.to));
    }
  }
  bgd_free(m);
}

/* A conflict: two flow sources on one 1-junction fix each other's flow
 * (type 2, degree 1, as tests/data/twosf.bg). */
static void test_conflict(void) {
  const char *src = "model twosf\nSf S1 = 1\nSf S2 = 2\n1 j\nR R1 = 1\n"
                    "bond 1 S1 -> j\nbond 2 S2 -> j\nbond 3 j -> R1\n";
  bgd_model *m = bgd_open("twosf.bg", src, NULL);
  INT_EQ(bgd_status(m), BGD_OK);
  INT_EQ(bgd_count(m, "conflicts"), 1);
  bgd_conflict c;
  INT_EQ(bgd_conflict_at(m, 0, &c), BGD_OK);
  STR_EQ(c.element, "j");
  INT_EQ(c.type, 2);
  INT_EQ(c.degree, 1);
  INT_EQ(c.nbonds, 2);
  if (c.nbonds == 2) OK(c.bonds[0] == 1 && c.bonds[1] == 2);
  bgd_free(m);
}

/* The linear analysis of an RLC circuit with an output: the DC gain of the
 * capacitor voltage over the source is 1, the poles those of the circuit. */
static void test_linear(void) {
  bgd_model *m = bgd_open_file("tests/data/linear_rlc.bg", NULL);
  INT_EQ(bgd_status(m), BGD_OK);
  bgd_linear l;
  INT_EQ(bgd_linearise(m, &l), BGD_OK);
  OK(l.reduced && l.n == 2 && l.nu >= 1 && l.ny >= 1);
  INT_EQ(l.npoles, 2);
  int ntf = bgd_count(m, "transfer_functions");
  OK(ntf >= 1);
  bgd_transfer t;
  INT_EQ(bgd_transfer_function_at(m, 0, &t), BGD_OK);
  OK(t.nden == 3 && t.den[0] == 1.0);
  /* the DC gain from the numerator and denominator at s = 0 */
  if (t.nden == 3 && t.nnum >= 1) DBL_NEAR(t.dc_gain, t.num[t.nnum - 1] / t.den[2], 1e-9 * fabs(t.dc_gain) + 1e-12);
  bgd_free(m);
}

/* ------------------------------------------------------------ diagnostics */
/* Text with a NUL byte, from memory: the diagnostic a file with one gets
 * (bgd_open would stop at it); without one, bgd_open_buffer is bgd_open. */
static void test_open_buffer(void) {
  const char text[] = "Se U = 1\n1 j\0\nC C1 = 1\nbond U -> j\nbond j -> C1\n";
  bgd_model *m = bgd_open_buffer("nul.bg", text, sizeof text - 1, NULL);
  INT_EQ(bgd_status(m), BGD_MODEL);
  const bgd_diagnostic *d;
  OK(bgd_diagnostics(m, &d) == 1 && d[0].line == 2 && d[0].column == 4 &&
     strstr(d[0].message, "NUL byte") != NULL);
  bgd_free(m);
  const char *good = "Se U = 1\n1 j\nC C1 = 1\nbond U -> j\nbond j -> C1\n";
  bgd_model *a = bgd_open_buffer("ok.bg", good, strlen(good), NULL), *b = bgd_open("ok.bg", good, NULL);
  char *ja = out_of(a, "json", NULL), *jb = out_of(b, "json", NULL);
  OK(bgd_status(a) == BGD_OK && ja && jb && !strcmp(ja, jb));
  free(ja), free(jb);
  bgd_free(a), bgd_free(b);
  a = bgd_open_buffer("part.bg", good, 8, NULL); /* "Se U = 1" alone: a source with no bond */
  INT_EQ(bgd_status(a), BGD_MODEL);
  bgd_free(a);
}

static void test_diagnostics(void) {
  const char *src = "model bad\nR R1 = 1\nbond 1 R1 -> nowhere\n";
  bgd_model *m = bgd_open("bad.bg", src, NULL);
  INT_EQ(bgd_status(m), BGD_MODEL);
  const bgd_diagnostic *d;
  int n = bgd_diagnostics(m, &d);
  OK(n >= 1);
  if (n >= 1) {
    STR_EQ(d[0].file, "bad.bg");
    INT_EQ(d[0].line, 3);
    OK(d[0].column > 1);
    STR_EQ(d[0].severity, "error");
    OK(strstr(d[0].message, "nowhere") != NULL);
  }
  char *text = bgd_diagnostics_text(m);
  OK(text && strstr(text, "bad.bg:3:") && strstr(text, "^"));
  free(text);
  INT_EQ(bgd_count(m, "bonds"), -1);
  char *data;
  INT_EQ(bgd_output(m, "svg", NULL, &data, NULL), BGD_MODEL);
  bgd_free(m);
  /* an error inside a submodel instance: the instance chain as notes */
  m = bgd_open_file("tests/bad/sub_error_in_instance.bg", NULL);
  INT_EQ(bgd_status(m), BGD_MODEL);
  n = bgd_diagnostics(m, &d);
  OK(n >= 1);
  if (n >= 1) {
    STR_EQ(d[0].file, "tests/bad/parts/broken.bg");
    INT_EQ(d[0].line, 4);
    INT_EQ(d[0].column, 10);
    OK(d[0].nnotes >= 1);
    if (d[0].nnotes >= 1) {
      STR_EQ(d[0].notes[0].file, "tests/bad/sub_error_in_instance.bg");
      INT_EQ(d[0].notes[0].line, 6);
      STR_EQ(d[0].notes[0].severity, "note");
      OK(strstr(d[0].notes[0].message, "in instance L1 of Leaky") != NULL);
    }
  }
  bgd_free(m);
}

/* ---------------------------------------------------------------- options */
static void test_options(void) {
  bgd_options o;
  bgd_options_init(&o);
  o.causality = "vandijk";
  bgd_model *m = bgd_open_file("examples/delta.bg", &o);
  INT_EQ(bgd_status(m), BGD_OK);
  char *json = NULL;
  INT_EQ(bgd_output(m, "json", NULL, &json, NULL), BGD_OK);
  OK(json && strstr(json, "\"method\": \"vandijk\""));
  free(json);
  bgd_free(m);
  o.causality = "nonsense";
  m = bgd_open_file("examples/rlc.bg", &o);
  INT_EQ(bgd_status(m), BGD_USAGE);
  char *text = bgd_diagnostics_text(m);
  OK(text && strstr(text, "causality"));
  free(text);
  bgd_free(m);
  /* params overridden as --set: the capacitor ten times larger, the
   * eigenvalues' imaginary part about sqrt(10) times smaller */
  bgd_options_init(&o);
  const char *names[] = {"C0"};
  const double values[] = {1e-5};
  o.nparams = 1, o.param_names = names, o.param_values = values;
  m = bgd_open_file("examples/rlc.bg", &o);
  const double *re, *im;
  INT_EQ(bgd_eigenvalues(m, &re, &im), 2);
  double alpha = 5000, wd = sqrt(1 / (1e-3 * 1e-5) - alpha * alpha);
  DBL_NEAR(fabs(im[0]), wd, 1e-6 * wd);
  bgd_free(m);
  /* an unknown output */
  m = bgd_open_file("examples/rlc.bg", NULL);
  char *data;
  INT_EQ(bgd_output(m, "gif", NULL, &data, NULL), BGD_USAGE);
  OK(bgd_last_error(m) && strstr(bgd_last_error(m), "gif"));
  bgd_free(m);
  /* named warnings: off one by one, or errors */
  const char *wsrc = "param a = 1, unused = 3\nSe U = a\n1 j\nC C1 = 0\nbond U -> j\nbond j -> C1\n";
  m = bgd_open("w.bg", wsrc, NULL);
  const bgd_diagnostic *d;
  INT_EQ(bgd_status(m), BGD_OK);
  INT_EQ(bgd_diagnostics(m, &d), 2);
  bgd_free(m);
  bgd_options_init(&o);
  o.warnings = "no-unused-param,error";
  m = bgd_open("w.bg", wsrc, &o);
  INT_EQ(bgd_status(m), BGD_MODEL);
  INT_EQ(bgd_diagnostics(m, &d), 1);
  OK(strstr(d[0].message, "[-Werror=degenerate-value]") != NULL);
  bgd_free(m);
  INT_EQ(bgd_api_version(), BGDRAW_API_VERSION);
  STR_EQ(bgd_version(), BGDRAW_VERSION_STRING);
}

/* Drawing options changed on an open handle: the bytes of the command line
 * with the same options, back to the defaults, and a wrong layer refused
 * with the handle's options unchanged. */
static void test_set_drawing(void) {
  const char *model = "examples/class12_paths.bg";
  bgd_model *m = bgd_open_file(model, NULL);
  INT_EQ(bgd_status(m), BGD_OK);
  compare_file(m, model, "svg", NULL, "d0.svg", "-o '%s'");
  char style[16], show[16];
  snprintf(style, sizeof style, "print"), snprintf(show, sizeof show, "paths");
  bgd_options o;
  bgd_options_init(&o);
  o.style = style, o.show = show, o.highlight = "path:1", o.layout = "neato";
  INT_EQ(bgd_set_drawing(m, &o), BGD_OK);
  memset(style, 'x', sizeof style - 1), memset(show, 'x', sizeof show - 1); /* copied, not kept */
  compare_file(m, model, "svg", NULL, "d1.svg",
               "--style print --show paths --highlight path:1 --layout neato -o '%s'");
  compare_file(m, model, "pdf", NULL, "d1.pdf",
               "--style print --show paths --highlight path:1 --layout neato -o '%s'");
  o.style = NULL, o.show = "loops", o.highlight = NULL, o.layout = NULL;
  INT_EQ(bgd_set_drawing(m, &o), BGD_OK);
  compare_file(m, model, "svg", NULL, "d2.svg", "--show loops -o '%s'");
  o.show = "strokes,wings";
  INT_EQ(bgd_set_drawing(m, &o), BGD_USAGE);
  OK(bgd_last_error(m) && strstr(bgd_last_error(m), "wings"));
  compare_file(m, model, "svg", NULL, "d3.svg", "--show loops -o '%s'"); /* unchanged */
  o.show = NULL, o.highlight = "path:0x";
  INT_EQ(bgd_set_drawing(m, &o), BGD_USAGE);
  INT_EQ(bgd_set_drawing(m, NULL), BGD_OK);
  compare_file(m, model, "svg", NULL, "d4.svg", "-o '%s'");
  char *a = NULL, *b = NULL;
  OK(bgd_output(m, "svg", NULL, &a, NULL) == BGD_OK && bgd_set_drawing(m, NULL) == BGD_OK &&
     bgd_output(m, "svg", NULL, &b, NULL) == BGD_OK && !strcmp(a, b));
  free(a), free(b);
  bgd_free(m);
}

/* The log: progress only when verbose, every message through the function. */
static void count_log(void *ctx, int level, const char *msg) {
  (void)msg;
  ((int *)ctx)[level]++;
}

static void test_log(void) {
  int seen[4] = {0};
  bgd_options o;
  bgd_options_init(&o);
  o.log = count_log, o.log_ctx = seen, o.verbose = 1;
  bgd_model *m = bgd_open_file("examples/rlc.bg", &o);
  bgd_simulation s;
  bgd_simulate(m, &s);
  OK(seen[0] >= 4); /* causality, paths, equations, index, simulate... */
  bgd_free(m);
  memset(seen, 0, sizeof seen);
  o.verbose = 0;
  m = bgd_open_file("examples/rlc.bg", &o);
  bgd_simulate(m, &s);
  INT_EQ(seen[0], 0);
  bgd_free(m);
}

/* ------------------------------------------------------------ two threads */
typedef struct job {
  const char *model;
  char *json, *csv, *eq, *svg;
} job;

static char *out_of(bgd_model *m, const char *kind, const char *form) {
  char *d = NULL;
  if (bgd_output(m, kind, form, &d, NULL) != BGD_OK) return NULL;
  return d;
}

static void *run_job(void *arg) {
  job *j = arg;
  bgd_model *m = bgd_open_file(j->model, NULL);
  j->json = out_of(m, "json", NULL);
  j->csv = out_of(m, "csv", NULL);
  j->eq = out_of(m, "equations", "text");
  j->svg = out_of(m, "svg", NULL);
  bgd_free(m);
  return NULL;
}

static int same_str(const char *a, const char *b) { return (!a && !b) || (a && b && !strcmp(a, b)); }

static void test_threads(void) {
  const char *models[] = {"examples/slider_crank.bg", "examples/hydraulic_bridge.bg",
                          "examples/rlc.bg", "examples/delta.bg"};
  job alone[4] = {{0}};
  for (int i = 0; i < 4; i++) alone[i].model = models[i], run_job(&alone[i]);
  for (int round = 0; round < 3; round++) {
    job both[4] = {{0}};
    pthread_t th[4];
    for (int i = 0; i < 4; i++) both[i].model = models[i], pthread_create(&th[i], NULL, run_job, &both[i]);
    for (int i = 0; i < 4; i++) pthread_join(th[i], NULL);
    for (int i = 0; i < 4; i++) {
      BG_T_REPORT(same_str(both[i].json, alone[i].json), "%s: JSON differs on a thread", models[i]);
      BG_T_REPORT(same_str(both[i].csv, alone[i].csv), "%s: CSV differs on a thread", models[i]);
      BG_T_REPORT(same_str(both[i].eq, alone[i].eq), "%s: equations differ on a thread", models[i]);
      BG_T_REPORT(same_str(both[i].svg, alone[i].svg), "%s: SVG differs on a thread", models[i]);
      free(both[i].json), free(both[i].csv), free(both[i].eq), free(both[i].svg);
    }
  }
  for (int i = 0; i < 4; i++) free(alone[i].json), free(alone[i].csv), free(alone[i].eq), free(alone[i].svg);
}

/* The FMU through the library: the command line's archive, byte for byte
 * (the compiler is deterministic on the same sources); a DAE refused as the
 * command line refuses it; a missing compiler a message, not a stderr line;
 * the program's signal handlers untouched (a library must not take them). */
static int holds(const char *buf, size_t n, const char *s) {
  size_t k = strlen(s);
  for (size_t i = 0; buf && i + k <= n; i++)
    if (!memcmp(buf + i, s, k)) return 1;
  return 0;
}

static void test_fmu(void) {
  struct sigaction mine = {0}, after;
  mine.sa_handler = SIG_IGN;
  struct sigaction before;
  sigaction(SIGINT, &mine, &before);
  bgd_model *m = bgd_open_file(BG_SOURCE_DIR "/examples/rlc.bg", NULL);
  compare_file(m, BG_SOURCE_DIR "/examples/rlc.bg", "fmu", NULL, "x.fmu", "-o '%s'");
  char *zip = NULL;
  size_t n = 0;
  OK(bgd_output(m, "fmu", NULL, &zip, &n) == BGD_OK);
  OK(zip && n > 1000 && !memcmp(zip, "PK\3\4", 4));
  OK(holds(zip, n, "binaries/linux64/rlc.so") && holds(zip, n, "modelDescription.xml"));
  free(zip);
  const char *cc = getenv("CC");
  char *saved = cc ? strdup(cc) : NULL;
  setenv("CC", "/nonexistent/cc", 1);
  OK(bgd_output(m, "fmu", NULL, &zip, &n) == BGD_WRITE);
  OK(bgd_last_error(m) && strstr(bgd_last_error(m), "cannot run the C compiler '/nonexistent/cc'"));
  if (saved) setenv("CC", saved, 1);
  else unsetenv("CC");
  free(saved);
  bgd_free(m);
  m = bgd_open_file(BG_SOURCE_DIR "/examples/hydraulic_bridge.bg", NULL);
  OK(bgd_output(m, "fmu", NULL, &zip, &n) == BGD_REFUSED);
  OK(bgd_last_error(m) && strstr(bgd_last_error(m), "export refused: 'stdout': the model is a DAE"));
  compare_file(m, BG_SOURCE_DIR "/examples/hydraulic_bridge.bg", "fmu", NULL, "hb.fmu", "-o '%s'");
  bgd_free(m);
  sigaction(SIGINT, &before, &after);
  OK(after.sa_handler == SIG_IGN); /* still the program's own */
}

int main(int argc, char **argv) {
  snprintf(tmp, sizeof tmp, "%s/test_api_XXXXXX", BG_BINARY_DIR);
  if (!mkdtemp(tmp)) return 1;
  char d[300];
  snprintf(d, sizeof d, "%s/lib", tmp), mkdir(d, 0777);
  snprintf(d, sizeof d, "%s/cli", tmp), mkdir(d, 0777);
  int quick = argc > 1 && !strcmp(argv[1], "--quick");
  test_rlc_data();
  test_bond_loop_index();
  test_paths_loops();
  test_conflict();
  test_linear();
  test_open_buffer();
  test_diagnostics();
  test_options();
  test_set_drawing();
  test_log();
  test_threads();
  test_fmu();
  if (!quick) test_every_output();
  char cmd[400];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp);
  if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tmp);
  printf("%d passed, %d failed\n", bg_t_pass, bg_t_fail);
  return bg_t_fail != 0;
}
