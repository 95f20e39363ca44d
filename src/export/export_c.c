/* SPDX-License-Identifier: BSD-3-Clause */
/* Reusable C (docs/export.md): a header and a source with a symbol prefix,
 * a parameter record with the model's values as defaults, initial values,
 * names, the differential/algebraic id vector, right-hand side or residual,
 * the sparse Jacobian (pattern and values, exact: forward-mode derivatives
 * with the rules of eqsys_tape.c, one pass per column colour), and the
 * outputs. Reentrant: every function works in a caller's scratch array. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "export/export_int.h"

/* Derivatives of the functions: the rules of call_der (eqsys_tape.c). */
static void prelude_fn(bg_strbuf *o) {
  bg_sb_puts(o, "static inline double bg_csum(double a, double b) {\n  double r = a + b;\n"
                "  return fabs(r) <= 16 * DBL_EPSILON * (fabs(a) + fabs(b)) ? 0.0 : r;\n}\n"
                "static inline double bg_powd(double x, double y, double v, double dx, double dy) {\n"
                "  double r = dx != 0 ? dx * (y == 0 ? 0 : y * pow(x, y - 1)) : 0;\n"
                "  if (dy != 0) r = bg_csum(r, dy * v * log(x));\n  return r;\n}\n");
  bg_sb_puts(o, "static inline double bg_fn_d(int fn, double x0, double x1, double x2, double d0, double d1,\n"
                "                             double d2, double v) {\n  switch (fn) {\n");
  bg_sb_printf(o, "  case %d: return x0 > 0 ? d0 : x0 < 0 ? -d0 : 0;\n  case %d: return d0 / (2 * v);\n", BG_FN_ABS, BG_FN_SQRT);
  bg_sb_printf(o, "  case %d: return v * d0;\n  case %d: return d0 / x0;\n  case %d: return d0 / (x0 * log(10.0));\n", BG_FN_EXP, BG_FN_LOG, BG_FN_LOG10);
  bg_sb_printf(o, "  case %d: return cos(x0) * d0;\n  case %d: return -sin(x0) * d0;\n  case %d: return (1 + v * v) * d0;\n", BG_FN_SIN, BG_FN_COS, BG_FN_TAN);
  bg_sb_printf(o, "  case %d: return d0 / sqrt(1 - x0 * x0);\n  case %d: return -d0 / sqrt(1 - x0 * x0);\n", BG_FN_ASIN, BG_FN_ACOS);
  bg_sb_printf(o, "  case %d: return d0 / (1 + x0 * x0);\n", BG_FN_ATAN);
  bg_sb_printf(o, "  case %d: return bg_csum(x1 * d0, -x0 * d1) / (x0 * x0 + x1 * x1);\n", BG_FN_ATAN2);
  bg_sb_printf(o, "  case %d: return cosh(x0) * d0;\n  case %d: return sinh(x0) * d0;\n  case %d: return (1 - v * v) * d0;\n", BG_FN_SINH, BG_FN_COSH, BG_FN_TANH);
  bg_sb_printf(o, "  case %d: return x0 <= x1 ? d0 : d1;\n  case %d: return x0 >= x1 ? d0 : d1;\n", BG_FN_MIN, BG_FN_MAX);
  bg_sb_printf(o, "  case %d: return bg_powd(x0, x1, v, d0, d1);\n  case %d: return x0 != 0 ? d1 : d2;\n", BG_FN_POW, BG_FN_IF);
  bg_sb_printf(o, "  case %d: return x0 < 0 ? 0 : d0;\n  case %d: return x0 < x1 ? d1 : x0 > x2 ? d2 : d0;\n", BG_FN_RAMP, BG_FN_SAT);
  bg_sb_puts(o, "  default: return 0;\n  }\n}\n");
}


/* Tables as static arrays; lookup and slope exactly as xeval.c computes them. */
static void prelude_tables(const bg_model *m, bg_strbuf *o) {
  if (!m->ntable) return;
  const char *nm[2] = {"bg_tx", "bg_ty"};
  for (int a = 0; a < 2; a++) {
    bg_sb_printf(o, "static const double %s[] = {", nm[a]);
    for (int k = 0; k < m->ntabledata; k++) {
      if (k) bg_sb_puts(o, ", ");
      bg_xl_num(&bg_xlang_c, o, a ? m->table_y[k] : m->table_x[k]);
    }
    bg_sb_puts(o, "};\n");
  }
  bg_sb_puts(o, "static const int bg_tadr[] = {");
  for (int k = 0; k < m->ntable; k++) bg_sb_printf(o, "%s%d", k ? ", " : "", m->table_adr[k]);
  bg_sb_puts(o, "}, bg_tn[] = {");
  for (int k = 0; k < m->ntable; k++) bg_sb_printf(o, "%s%d", k ? ", " : "", m->table_n[k]);
  bg_sb_puts(o, "};\n"
                "static int bg_tseg(const double *X, int n, double x) {\n  int lo = 0, hi = n - 1;\n"
                "  while (hi - lo > 1) {\n    int mid = (lo + hi) / 2;\n    if (X[mid] <= x) lo = mid; else hi = mid;\n  }\n"
                "  return lo;\n}\n"
                "static double bg_tab(int t, double x) {\n"
                "  const double *X = bg_tx + bg_tadr[t], *Y = bg_ty + bg_tadr[t];\n  int n = bg_tn[t];\n"
                "  if (n == 0) return NAN;\n  if (x <= X[0]) return Y[0];\n  if (x >= X[n - 1]) return Y[n - 1];\n"
                "  int lo = bg_tseg(X, n, x), hi = lo + 1;\n  double w = (x - X[lo]) / (X[hi] - X[lo]);\n"
                "  return Y[lo] + w * (Y[hi] - Y[lo]);\n}\n"
                "static double bg_tab_slope(int t, double x) {\n"
                "  const double *X = bg_tx + bg_tadr[t], *Y = bg_ty + bg_tadr[t];\n  int n = bg_tn[t];\n"
                "  if (n < 2 || x < X[0] || x >= X[n - 1]) return 0;\n"
                "  int lo = bg_tseg(X, n, x), hi = lo + 1;\n"
                "  return X[hi] > X[lo] ? (Y[hi] - Y[lo]) / (X[hi] - X[lo]) : 0;\n}\n");
}

static void deriv_stmt(const bg_eqsys *s, const tinstr *I, bg_strbuf *o) {
  const int *a = I->a;
  int o_ = I->out;
  if (I->op == T_LIN) {
    bg_sb_puts(o, "  r = 0, mg = 0;\n");
    for (int k = 0; k < I->a[0]; k++) {
      bg_sb_puts(o, "  q = ");
      bg_xl_num(&bg_xlang_c, o, s->tl_coef[I->ref + k]);
      bg_sb_printf(o, " * d[%d], r += q, mg += fabs(q);\n", s->tl_slot[I->ref + k]);
    }
    bg_sb_printf(o, "  d[%d] = fabs(r) <= 16 * DBL_EPSILON * mg ? 0.0 : r;\n", o_);
    return;
  }
  int a1 = I->na > 1 ? a[1] : 0, a2 = I->na > 2 ? a[2] : 0;
  bg_sb_printf(o, "  d[%d] = d[%d] == 0 && d[%d] == 0 && d[%d] == 0 ? 0.0 : ", o_, a[0], I->na > 1 ? a1 : a[0],
               I->na > 2 ? a2 : a[0]);
  switch (I->op) {
  case BG_X_NEG: bg_sb_printf(o, "-d[%d]", a[0]); break;
  case BG_X_ADD: bg_sb_printf(o, "bg_csum(d[%d], d[%d])", a[0], a1); break;
  case BG_X_SUB: bg_sb_printf(o, "bg_csum(d[%d], -d[%d])", a[0], a1); break;
  case BG_X_MUL:
    bg_sb_printf(o, "bg_csum(d[%d] == 0 ? 0 : d[%d] * v[%d], d[%d] == 0 ? 0 : v[%d] * d[%d])", a[0], a[0], a1, a1, a[0], a1);
    break;
  case BG_X_DIV: bg_sb_printf(o, "bg_csum(d[%d], d[%d] == 0 ? 0 : -v[%d] * d[%d]) / v[%d]", a[0], a1, o_, a1, a1); break;
  case BG_X_POW: bg_sb_printf(o, "bg_powd(v[%d], v[%d], v[%d], d[%d], d[%d])", a[0], a1, o_, a[0], a1); break;
  case BG_X_CALL:
    bg_sb_printf(o, "bg_fn_d(%d, v[%d], v[%d], v[%d], d[%d], d[%d], d[%d], v[%d])", I->ref, a[0], a1, a2, a[0],
                 I->na > 1 ? a1 : 0, I->na > 2 ? a2 : 0, o_);
    break;
  case BG_X_TABLE: bg_sb_printf(o, "bg_tab_slope(%d, v[%d]) * d[%d]", I->ref, a[0], a[0]); break;
  default: bg_sb_puts(o, "0.0"); break;
  }
  bg_sb_puts(o, ";\n");
}

/* ------------------------------------------------------------ header */
typedef struct cx { const bg_eqsys *s; const char *P; char U[80]; } cx;

static void int_array(bg_strbuf *o, const char *decl, const int *v, int n) {
  bg_sb_printf(o, "%s = {", decl);
  for (int i = 0; i < n; i++) bg_sb_printf(o, "%s%d", i ? ", " : "", v[i]);
  bg_sb_puts(o, n ? "};\n" : "0};\n"); /* no empty initialiser */
}

static void name_array(bg_strbuf *o, const char *decl, const char *const *v, int n) {
  bg_sb_printf(o, "%s = {", decl);
  for (int i = 0; i < n; i++) bg_sb_puts(o, i ? ", " : ""), bg_sb_json_str(o, v[i]);
  bg_sb_puts(o, n ? "};\n" : "NULL};\n");
}

static void header(const cx *X, bg_strbuf *h) {
  const bg_eqsys *s = X->s;
  const char *P = X->P, *U = X->U;
  char id[300];
  int ode = bg_eqsys_is_ode(s);
  bg_sb_printf(h, "/* Generated by bgdraw from model %s: %s; y = (", s->m->name, ode ? "ODE y' = f(t, y)" : "DAE F(t, y, y') = 0");
  for (int i = 0; i < s->n; i++) bg_sb_printf(h, "%s%s", i ? ", " : "", s->uname[i]);
  bg_sb_printf(h, ").\n * Reentrant: every function works in the caller's scratch array work[%s_NWORK]. */\n", U);
  bg_sb_printf(h, "#ifndef %s_H\n#define %s_H\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n", U, U);
  bg_sb_printf(h, "#define %s_N %d      /* unknowns y */\n#define %s_NX %d     /* differential unknowns, first in y */\n", U, s->n, U, s->nx);
  bg_sb_printf(h, "#define %s_NOUT %d   /* outputs */\n#define %s_NPARAM %d /* fields of %s_params */\n", U, s->nout, U, bg_export_nparams(s), P);
  bg_sb_printf(h, "#define %s_NNZ %d    /* Jacobian entries (CSC pattern) */\n#define %s_NWORK %d  /* doubles of scratch */\n", U, s->nnz, U,
               2 * s->nslot + (s->nev ? 2 * s->n + 2 * s->nev : 0));
  bg_sb_printf(h, "#define %s_IS_ODE %d\n\n", U, ode);
  bg_sb_printf(h, "typedef struct %s_params {\n", P);
  for (int k = 0; k < s->m->nparam; k++)
    if (!bg_eqsys_param_is_derived(s, k)) bg_sb_printf(h, "  double %s;\n", bg_export_param_ident(&bg_xlang_c, s, k, id, sizeof id));
  if (!bg_export_nparams(s)) bg_sb_puts(h, "  char unused; /* the model has no params */\n");
  bg_sb_printf(h, "} %s_params;\n\n/* the model's values */\nextern const %s_params %s_default_params;\n", P, P, P);
  bg_sb_printf(h, "extern const char *const %s_param_names[%s_NPARAM + 1];\n", P, U);
  bg_sb_printf(h, "extern const char *const %s_unknown_names[%s_N + 1];\n", P, U);
  bg_sb_printf(h, "extern const char *const %s_output_names[%s_NOUT + 1];\n", P, U);
  bg_sb_printf(h, "/* 1: the derivative appears (IDASetId), 0: algebraic */\nextern const int %s_is_differential[%s_N + 1];\n", P, U);
  bg_sb_printf(h, "/* Jacobian pattern, compressed sparse columns, diagonal included */\n"
                  "extern const int %s_jac_colptr[%s_N + 1], %s_jac_rowind[%s_NNZ + 1];\n\n", P, U, P, U);
  if (s->nev) bg_xev_c_header(s, P, U, h);
  const char *md = s->nev ? "const " : "", *mdp = s->nev ? "_modes *md, " : "";
  char MD[120] = "";
  if (s->nev) snprintf(MD, sizeof MD, "%s%s%s", md, P, mdp);
  bg_sb_printf(h, "/* Initial values at t0 (states from the model's q0/p0/init with p; dependent\n"
                  " * stores and algebraic unknowns: consistent at the default params) */\n"
                  "void %s_initial(const %s_params *p, double t0, double *y0, double *work);\n", P, P);
  if (s->nev) bg_sb_puts(h, "/* Every function below evaluates with the modes md held */\n");
  if (ode) bg_sb_printf(h, "/* ydot = f(t, y); 0, or -1 when a value is not finite */\n"
                           "int %s_rhs(const %s_params *p, %sdouble t, const double *y, double *ydot, double *work);\n", P, P, MD);
  bg_sb_printf(h, "/* F(t, y, yp) = 0 (an ODE as yp - f); 0, or -1 when a value is not finite */\n"
                  "int %s_residual(const %s_params *p, %sdouble t, const double *y, const double *yp, double *res,\n"
                  "                double *work);\n", P, P, MD);
  bg_sb_printf(h, "/* Jacobian values in the pattern's order: %s */\n"
                  "int %s_jacobian(const %s_params *p, %sdouble t, const double *y, const double *yp, double cj,\n"
                  "                double *values, double *work);\n", ode ? "df/dy (yp and cj unused)" : "dF/dy + cj dF/dyp", P, P, MD);
  bg_sb_printf(h, "/* The outputs (plot expressions, or the states) */\n"
                  "int %s_outputs(const %s_params *p, %sdouble t, const double *y, const double *yp, double *out,\n"
                  "               double *work);\n", P, P, MD);
  bg_sb_printf(h, "\n#ifdef __cplusplus\n}\n#endif\n#endif\n");
}

/* ------------------------------------------------------------ source */
static void tables_of_names(const cx *X, bg_strbuf *c) {
  const bg_eqsys *s = X->s;
  const char *P = X->P, *U = X->U;
  char decl[200], id[300];
  const char **pn = bg_xcalloc((size_t)s->m->nparam + 1, sizeof(char *));
  int np = 0;
  bg_sb_printf(c, "const %s_params %s_default_params = {", P, P);
  for (int k = 0; k < s->m->nparam; k++) {
    if (bg_eqsys_param_is_derived(s, k)) continue;
    bg_sb_printf(c, "%s.%s = ", np ? ", " : "", bg_export_param_ident(&bg_xlang_c, s, k, id, sizeof id));
    bg_xl_num(&bg_xlang_c, c, s->m->param_value[k]);
    pn[np++] = s->m->param_name[k];
  }
  bg_sb_puts(c, np ? "};\n" : "0};\n");
  snprintf(decl, sizeof decl, "const char *const %s_param_names[%s_NPARAM + 1]", P, U);
  name_array(c, decl, pn, np);
  snprintf(decl, sizeof decl, "const char *const %s_unknown_names[%s_N + 1]", P, U);
  name_array(c, decl, s->uname, s->n);
  snprintf(decl, sizeof decl, "const char *const %s_output_names[%s_NOUT + 1]", P, U);
  name_array(c, decl, s->out_name, s->nout);
  int *isd = bg_xcalloc((size_t)s->n + 1, sizeof(int));
  for (int i = 0; i < s->n; i++) isd[i] = bg_eqsys_is_differential(s, i);
  snprintf(decl, sizeof decl, "const int %s_is_differential[%s_N + 1]", P, U);
  int_array(c, decl, isd, s->n);
  free(isd), free(pn);
  snprintf(decl, sizeof decl, "const int %s_jac_colptr[%s_N + 1]", P, U);
  int_array(c, decl, s->colptr, s->n + 1);
  snprintf(decl, sizeof decl, "const int %s_jac_rowind[%s_NNZ + 1]", P, U);
  int_array(c, decl, s->rowind, s->nnz);
  int_array(c, "static const int bg_row_slot[]", s->row_slot, s->n);
  int_array(c, "static const int bg_row_kind[]", s->row_kind, s->n);
  int_array(c, "static const int bg_out_slot[]", s->out_slot, s->nout);
  int_array(c, "static const int bg_color_adr[]", s->color_adr, s->ncolor + 1);
  int_array(c, "static const int bg_color_cols[]", s->color_cols, s->n);
  bg_sb_puts(c, "\n");
}

/* Instructions per generated function. Compilers take time superlinear in
 * the length of one straight-line function (gcc -O2: 92 s for the single
 * function of a 1 000-mass chain), so the straight code of [c0, c1) is cut
 * into parts of at most this many instructions, each its own function that
 * the compiler may not inline back (every value lives in v[] and d[], so a
 * cut between two instructions changes no result). Runs of a repeated
 * pattern become loops over tables of slots (export_runs.c), a part each. */
#define BG_PART 100

/* ev: the parts take the modes' context c (a model with state events:
 * the main code and its derivatives hold their switching instructions'
 * modes, export_events.c). */
static void part_head(const char *name, int part, int deriv, int ev, bg_strbuf *c) {
  if (deriv)
    bg_sb_printf(c, "static BG_NOINLINE void %s_%d(const double *v, double *d%s) {\n  double r, q, mg;\n"
                    "  (void)v, (void)d, (void)r, (void)q, (void)mg;\n", name, part, ev ? ", const bg_mc *c" : "");
  else bg_sb_printf(c, "static BG_NOINLINE void %s_%d(double *v%s) {\n  (void)v;\n", name, part, ev ? ", bg_mc *c" : "");
  if (ev) bg_sb_puts(c, "  (void)c;\n");
}

/* Every statement of [c0, c1), each closed in t: its value (deriv 0) or its
 * directional derivative (deriv 1). */
static void code_stmts(const bg_eqsys *s, int c0, int c1, int deriv, int ev, bg_xstmts *t) {
  for (int k = c0; k < c1; k++) {
    if (!deriv) bg_xl_code(&bg_xlang_c, s, k, k + 1, "v", &t->text);
    else {
      if (ev && s->code_ev[k] >= 0) bg_xev_c_der(s, s->code_ev[k], &t->text);
      deriv_stmt(s, &s->code[k], &t->text);
    }
    bg_xstmts_end(t);
  }
}

/* The function `name` of the code [c0, c1): its values (deriv 0) or their
 * directional derivatives (deriv 1), in parts. */
static void code_fn(const bg_eqsys *s, const char *name, const char *what, int c0, int c1,
                    int deriv, int ev, bg_strbuf *c) {
  bg_xstmts t = {0};
  bg_xrun *run = NULL;
  int nrun = 0, nparts = 0;
  char tab[120];
  code_stmts(s, c0, c1, deriv, ev, &t);
  if (t.n) bg_xruns_plan(&t, &run, &nrun);
  for (int q = 0; q < nrun; q++) {
    const bg_xrun *r = &run[q];
    if (r->reps > 1) {
      snprintf(tab, sizeof tab, "%s_%d_slots", name, nparts);
      bg_xruns_table(&t, r, tab, c);
      part_head(name, nparts++, deriv, ev, c);
      bg_xruns_loop(&t, r, tab, c);
      bg_sb_puts(c, "}\n");
      continue;
    }
    for (int a = r->start, end = r->start + r->period; a < end; a += BG_PART) {
      part_head(name, nparts++, deriv, ev, c);
      bg_xruns_straight(&t, a, a + BG_PART < end ? a + BG_PART : end, c);
      bg_sb_puts(c, "}\n");
    }
  }
  free(run), bg_xstmts_free(&t);
  if (what) bg_sb_printf(c, "/* %s */\n", what);
  bg_sb_printf(c, "static void %s(%s%s) {\n  (void)v;%s%s\n", name,
               deriv ? "const double *v, double *d" : "double *v", ev ? (deriv ? ", const bg_mc *c" : ", bg_mc *c") : "",
               deriv ? " (void)d;" : "", ev ? " (void)c;" : "");
  for (int part = 0; part < nparts; part++)
    bg_sb_printf(c, "  %s_%d(v%s%s);\n", name, part, deriv ? ", d" : "", ev ? ", c" : "");
  bg_sb_puts(c, "}\n\n");
}

static void eval_fns(const cx *X, bg_strbuf *c) {
  const bg_eqsys *s = X->s;
  const char *P = X->P, *U = X->U;
  bg_strbuf k = {0}, body = {0};
  bg_xl_constants(&bg_xlang_c, s, "v", "p->%s", &k);
  bg_xruns_lines(bg_sb_str(&k), "bg_start_slots", c, &body);
  bg_sb_printf(c, "static void bg_start(const %s_params *p, double t, const double *y, const double *yp, double *v) {\n"
                  "  (void)p;\n  v[0] = t;\n  for (int i = 0; i < %s_N; i++) v[1 + i] = y ? y[i] : 0, v[1 + %s_N + i] = yp ? yp[i] : 0;\n",
               P, U, U);
  bg_sb_puts(c, bg_sb_str(&body));
  bg_sb_free(&k), bg_sb_free(&body);
  bg_sb_puts(c, "}\n\n");
  code_fn(s, "bg_main", "the equations in computational order", 0, s->nmain, 0, s->nev > 0, c);
  code_fn(s, "bg_output_code", NULL, s->nmain, s->nout_code, 0, 0, c);
  code_fn(s, "bg_initial_code", NULL, s->nout_code, s->ncode, 0, 0, c);
  code_fn(s, "bg_deriv", "one directional derivative d of every value, given v", 0, s->nmain, 1, s->nev > 0, c);
  bg_sb_puts(c, "\n");
  bg_sb_printf(c, "static int bg_rows_finite(const double *v) {\n  for (int i = 0; i < %s_N; i++)\n"
                  "    if (!isfinite(v[bg_row_slot[i]])) return 0;\n  return 1;\n}\n\n", U);
  if (!s->nev) return;
  bg_sb_printf(c, "/* The values with the modes held; as compiled where a held value is not\n"
                  " * finite (a branch continued past its switching point can leave a law's\n"
                  " * domain). Returns how they were computed: 1 held, 0 as compiled. */\n"
                  "static int bg_eval_modes(const %s_params *p, const %s_modes *md, double t, const double *y, const double *yp,\n"
                  "                         double *v, int outputs) {\n  bg_mc c = {(%s_modes *)md, 1, NULL, NULL};\n"
                  "  for (;; c.how = 0) {\n    bg_start(p, t, y, yp, v);\n    bg_main(v, &c);\n"
                  "    int ok = 1;\n    if (outputs) {\n      bg_output_code(v);\n"
                  "      for (int k = 0; k < %s_NOUT; k++) ok &= isfinite(v[bg_out_slot[k]]) != 0;\n"
                  "    } else ok = bg_rows_finite(v);\n    if (ok || c.how == 0) return c.how;\n  }\n}\n\n", P, P, P, U);
}

static void initial_fn(const cx *X, bg_strbuf *c) {
  const bg_eqsys *s = X->s;
  const char *P = X->P, *U = X->U;
  double *y0 = bg_xcalloc((size_t)s->n + 1, sizeof(double));
  bg_eqsys_initial(s, y0);
  bg_strbuf k = {0}, body = {0};
  for (int i = 0; i < s->n; i++) {
    bg_sb_printf(&k, "  y0[%d] = ", i);
    if (i < s->nint && s->init_slot[i] >= 0) bg_sb_printf(&k, "v[%d]", s->init_slot[i]);
    else if (i < s->nint) bg_sb_puts(&k, "0");
    else bg_xl_num(&bg_xlang_c, &k, y0[i]);
    bg_sb_puts(&k, ";\n");
  }
  bg_xruns_lines(bg_sb_str(&k), "bg_initial_slots", c, &body);
  bg_sb_printf(c, "void %s_initial(const %s_params *p, double t0, double *y0, double *work) {\n"
                  "  double *v = work;\n  bg_start(p, t0, NULL, NULL, v);\n  bg_main(v%s);\n  bg_initial_code(v);\n", P, P,
               s->nev ? ", NULL" : "");
  bg_sb_puts(c, bg_sb_str(&body));
  bg_sb_free(&k), bg_sb_free(&body);
  bg_sb_printf(c, "  (void)y0;\n}\n\n");
  free(y0);
  (void)U;
}

/* The evaluation at (t, y, yp) into v: as compiled, or (a model with state
 * events) with the modes md held (bg_eval_modes; outputs: 1 with them). */
static void eval_stmt(const bg_eqsys *s, const char *y, const char *yp, int outputs, bg_strbuf *c) {
  if (s->nev) bg_sb_printf(c, "  bg_eval_modes(p, md, t, %s, %s, v, %d);\n", y, yp, outputs);
  else bg_sb_printf(c, "  bg_start(p, t, %s, %s, v);\n  bg_main(v);\n%s", y, yp, outputs ? "  bg_output_code(v);\n" : "");
}

/* rhs, residual, jacobian, outputs; a model with state events takes the
 * modes md after p (a model without keeps its interface byte for byte). */
static void api_fns(const cx *X, bg_strbuf *c) {
  const bg_eqsys *s = X->s;
  const char *P = X->P, *U = X->U;
  int ode = bg_eqsys_is_ode(s);
  char md[160] = "", half[120];
  if (s->nev) snprintf(md, sizeof md, "const %s_modes *md, ", P);
  if (s->nev) snprintf(half, sizeof half, "%d", s->nslot); /* U_NWORK holds the event scratch too */
  else snprintf(half, sizeof half, "%s_NWORK / 2", U);
  if (ode) {
    bg_sb_printf(c, "int %s_rhs(const %s_params *p, %sdouble t, const double *y, double *ydot, double *work) {\n"
                    "  double *v = work;\n", P, P, md);
    eval_stmt(s, "y", "NULL", 0, c);
    bg_sb_printf(c, "  for (int i = 0; i < %s_NX; i++) ydot[i] = v[bg_row_slot[i]];\n  return bg_rows_finite(v) ? 0 : -1;\n}\n\n", U);
  }
  bg_sb_printf(c, "int %s_residual(const %s_params *p, %sdouble t, const double *y, const double *yp, double *res,\n"
                  "                double *work) {\n  double *v = work;\n", P, P, md);
  eval_stmt(s, "y", "yp", 0, c);
  bg_sb_printf(c, "  for (int i = 0; i < %s_N; i++)\n"
                  "    res[i] = bg_row_kind[i] == 0 ? yp[i] - v[bg_row_slot[i]] : v[bg_row_slot[i]];\n"
                  "  return bg_rows_finite(v) ? 0 : -1;\n}\n\n", U);
  bg_sb_printf(c, "int %s_jacobian(const %s_params *p, %sdouble t, const double *y, const double *yp, double cj,\n"
                  "                double *values, double *work) {\n"
                  "  const int ode = %d;\n  double *v = work, *d = work + %s;\n", P, P, md, ode, half);
  if (s->nev)
    bg_sb_printf(c, "  bg_mc mc = {(%s_modes *)md, bg_eval_modes(p, md, t, y, ode ? NULL : yp, v, 0), NULL, NULL};\n", P);
  else bg_sb_puts(c, "  bg_start(p, t, y, ode ? NULL : yp, v);\n  bg_main(v);\n");
  bg_sb_printf(c, "  for (int c = 0; c < %d; c++) {\n    memset(d, 0, sizeof(double) * (%s));\n"
                  "    for (int k = bg_color_adr[c]; k < bg_color_adr[c + 1]; k++)\n"
                  "      d[1 + bg_color_cols[k]] = 1, d[1 + %s_N + bg_color_cols[k]] = ode ? 0 : cj;\n"
                  "    bg_deriv(v, d%s);\n    for (int q = bg_color_adr[c]; q < bg_color_adr[c + 1]; q++) {\n"
                  "      int j = bg_color_cols[q];\n      for (int k = %s_jac_colptr[j]; k < %s_jac_colptr[j + 1]; k++) {\n"
                  "        int i = %s_jac_rowind[k];\n        double x = d[bg_row_slot[i]];\n"
                  "        if (bg_row_kind[i] == 0 && !ode) x = (i == j ? cj : 0) - x;\n        values[k] = x;\n"
                  "      }\n    }\n  }\n  (void)cj, (void)yp;\n  return bg_rows_finite(v) ? 0 : -1;\n}\n\n",
               s->ncolor, half, U, s->nev ? ", &mc" : "", P, P, P);
  bg_sb_printf(c, "int %s_outputs(const %s_params *p, %sdouble t, const double *y, const double *yp, double *out,\n"
                  "               double *work) {\n  double *v = work;\n", P, P, md);
  eval_stmt(s, "y", "yp", 1, c);
  bg_sb_printf(c, "  int ok = 1;\n  for (int k = 0; k < %s_NOUT; k++) out[k] = v[bg_out_slot[k]], ok &= isfinite(out[k]) != 0;\n"
                  "  return ok ? 0 : -1;\n}\n%s", U, s->nev ? "\n" : "");
}

void bg_export_c(const bg_eqsys *s, const char *prefix, const char *header_name, bg_strbuf *h,
                 bg_strbuf *c) {
  cx X = {s, prefix, {0}};
  size_t i = 0;
  for (; prefix[i] && i + 1 < sizeof X.U; i++) X.U[i] = (char)(prefix[i] >= 'a' && prefix[i] <= 'z' ? prefix[i] - 32 : prefix[i]);
  X.U[i] = 0;
  header(&X, h);
  bg_sb_printf(c, "/* Generated by bgdraw from model %s (docs/export.md). */\n", s->m->name);
  if (header_name) bg_sb_printf(c, "#include \"%s\"\n", header_name);
  bg_sb_puts(c, "#include <float.h>\n#include <math.h>\n#include <stddef.h>\n#include <string.h>\n\n");
  bg_sb_puts(c, "/* the code comes in parts the compiler must not merge back (compile time) */\n"
                "#if defined(__GNUC__)\n#define BG_NOINLINE __attribute__((noinline))\n#else\n"
                "#define BG_NOINLINE\n#endif\n\n");
  prelude_fn(c);
  prelude_tables(s->m, c);
  if (s->nev) bg_xev_c_runtime(s, prefix, c);
  tables_of_names(&X, c);
  eval_fns(&X, c);
  initial_fn(&X, c);
  api_fns(&X, c);
  if (s->nev) bg_xev_c_api(s, prefix, X.U, c);
}
