/* --equations c: the evaluation tape written out as a self-contained C
 * translation unit (values and exact forward-mode derivatives, the same
 * rules as eqsys_tape.c), so the generated Jacobian is the tool's. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "equations/eqprint.h"
#include "equations/eqsys_int.h"
#include "model/expr.h"

static void num(bg_strbuf *o, double c) {
  if (isnan(c)) bg_sb_puts(o, "NAN");
  else if (isinf(c)) bg_sb_puts(o, c > 0 ? "HUGE_VAL" : "(-HUGE_VAL)");
  else bg_sb_num(o, c);
}

/* Function values and derivatives: copies of bg_func_apply and call_der. */
static void prelude_fn(bg_strbuf *o) {
  bg_sb_puts(o, "static inline double bg_fn(int fn, double a, double b, double c) {\n  switch (fn) {\n");
  bg_sb_printf(o, "  case %d: return fabs(a);\n  case %d: return a > 0 ? 1.0 : a < 0 ? -1.0 : 0.0;\n", BG_FN_ABS, BG_FN_SIGN);
  bg_sb_printf(o, "  case %d: return sqrt(a);\n  case %d: return exp(a);\n  case %d: return log(a);\n", BG_FN_SQRT, BG_FN_EXP, BG_FN_LOG);
  bg_sb_printf(o, "  case %d: return log10(a);\n  case %d: return sin(a);\n  case %d: return cos(a);\n", BG_FN_LOG10, BG_FN_SIN, BG_FN_COS);
  bg_sb_printf(o, "  case %d: return tan(a);\n  case %d: return asin(a);\n  case %d: return acos(a);\n", BG_FN_TAN, BG_FN_ASIN, BG_FN_ACOS);
  bg_sb_printf(o, "  case %d: return atan(a);\n  case %d: return atan2(a, b);\n  case %d: return sinh(a);\n", BG_FN_ATAN, BG_FN_ATAN2, BG_FN_SINH);
  bg_sb_printf(o, "  case %d: return cosh(a);\n  case %d: return tanh(a);\n  case %d: return fmin(a, b);\n", BG_FN_COSH, BG_FN_TANH, BG_FN_MIN);
  bg_sb_printf(o, "  case %d: return fmax(a, b);\n  case %d: return pow(a, b);\n  case %d: return floor(a);\n", BG_FN_MAX, BG_FN_POW, BG_FN_FLOOR);
  bg_sb_printf(o, "  case %d: return ceil(a);\n  case %d: return a != 0 ? b : c;\n  case %d: return a < 0 ? 0.0 : 1.0;\n", BG_FN_CEIL, BG_FN_IF, BG_FN_STEP);
  bg_sb_printf(o, "  case %d: return a < 0 ? 0.0 : a;\n  case %d: return a >= 0 && a < b ? 1.0 : 0.0;\n", BG_FN_RAMP, BG_FN_PULSE);
  bg_sb_printf(o, "  case %d: return a < b ? b : a > c ? c : a;\n  default: return NAN;\n  }\n}\n", BG_FN_SAT);
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

static void prelude_tables(const bg_model *m, bg_strbuf *o) {
  if (!m->ntable) return;
  const char *nm[2] = {"bg_tx", "bg_ty"};
  for (int a = 0; a < 2; a++) {
    bg_sb_printf(o, "static const double %s[] = {", nm[a]);
    for (int k = 0; k < m->ntabledata; k++) {
      if (k) bg_sb_puts(o, ", ");
      num(o, a ? m->table_y[k] : m->table_x[k]);
    }
    bg_sb_puts(o, "};\n");
  }
  bg_sb_puts(o, "static const int bg_tadr[] = {");
  for (int k = 0; k < m->ntable; k++) bg_sb_printf(o, "%s%d", k ? ", " : "", m->table_adr[k]);
  bg_sb_puts(o, "}, bg_tn[] = {");
  for (int k = 0; k < m->ntable; k++) bg_sb_printf(o, "%s%d", k ? ", " : "", m->table_n[k]);
  bg_sb_puts(o, "};\n/* linear interpolation clamped at the ends; slope: its derivative */\n"
                "static inline double bg_tab(int t, double x, int slope) {\n"
                "  const double *X = bg_tx + bg_tadr[t], *Y = bg_ty + bg_tadr[t];\n  int n = bg_tn[t];\n"
                "  if (x <= X[0] || n < 2) return slope ? 0 : Y[0];\n"
                "  if (x >= X[n - 1]) return slope ? 0 : Y[n - 1];\n  int lo = 0, hi = n - 1;\n"
                "  while (hi - lo > 1) {\n    int mid = (lo + hi) / 2;\n    if (X[mid] <= x) lo = mid; else hi = mid;\n  }\n"
                "  double s = X[hi] > X[lo] ? (Y[hi] - Y[lo]) / (X[hi] - X[lo]) : 0;\n"
                "  return slope ? s : Y[lo] + s * (x - X[lo]);\n}\n");
}

static const char *binop(int op) {
  switch (op) {
  case BG_X_ADD: return "+"; case BG_X_SUB: return "-"; case BG_X_MUL: return "*";
  case BG_X_DIV: return "/"; case BG_X_LT: return "<"; case BG_X_LE: return "<=";
  case BG_X_GT: return ">"; case BG_X_GE: return ">="; case BG_X_EQ: return "==";
  case BG_X_NE: return "!="; default: return NULL;
  }
}

static void value_stmt(const bg_eqsys *s, const tinstr *I, bg_strbuf *o) {
  const int *a = I->a;
  bg_sb_printf(o, "  v[%d] = ", I->out);
  if (I->op == T_LIN) {
    for (int k = 0; k < I->a[0]; k++) {
      if (k) bg_sb_puts(o, " + ");
      num(o, s->tl_coef[I->ref + k]);
      bg_sb_printf(o, " * v[%d]", s->tl_slot[I->ref + k]);
    }
    if (!I->a[0]) bg_sb_puts(o, "0");
  } else if (I->op == BG_X_CALL) {
    bg_sb_printf(o, "bg_fn(%d, v[%d], %s%d], %s%d])", I->ref, a[0], I->na > 1 ? "v[" : "0 * v[", I->na > 1 ? a[1] : 0,
                 I->na > 2 ? "v[" : "0 * v[", I->na > 2 ? a[2] : 0);
  } else if (I->op == BG_X_TABLE) bg_sb_printf(o, "bg_tab(%d, v[%d], 0)", I->ref, a[0]);
  else if (I->op == BG_X_NEG) bg_sb_printf(o, "-v[%d]", a[0]);
  else if (I->op == BG_X_NOT) bg_sb_printf(o, "(double)(v[%d] == 0)", a[0]);
  else if (I->op == BG_X_POW) bg_sb_printf(o, "pow(v[%d], v[%d])", a[0], a[1]);
  else if (I->op == BG_X_AND) bg_sb_printf(o, "(double)(v[%d] != 0 && v[%d] != 0)", a[0], a[1]);
  else if (I->op == BG_X_OR) bg_sb_printf(o, "(double)(v[%d] != 0 || v[%d] != 0)", a[0], a[1]);
  else bg_sb_printf(o, "(double)(v[%d] %s v[%d])", a[0], binop(I->op), a[1]);
  bg_sb_puts(o, ";\n");
}

static void deriv_stmt(const bg_eqsys *s, const tinstr *I, bg_strbuf *o) {
  const int *a = I->a;
  int o_ = I->out;
  if (I->op == T_LIN) {
    bg_sb_puts(o, "  r = 0, mg = 0;\n");
    for (int k = 0; k < I->a[0]; k++) {
      bg_sb_puts(o, "  q = ");
      num(o, s->tl_coef[I->ref + k]);
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
  case BG_X_TABLE: bg_sb_printf(o, "bg_tab(%d, v[%d], 1) * d[%d]", I->ref, a[0], a[0]); break;
  default: bg_sb_puts(o, "0.0"); break;
  }
  bg_sb_puts(o, ";\n");
}

static void eval_fn(const bg_eqsys *s, bg_strbuf *o) {
  bg_sb_puts(o, "static void bg_eval(double t, const double *y, const double *yp, double *v) {\n"
                "  v[0] = t;\n  for (int i = 0; i < BG_MODEL_N; i++)\n"
                "    v[1 + i] = y[i], v[1 + BG_MODEL_N + i] = yp ? yp[i] : 0;\n");
  for (int k = 0; k < s->nslot; k++)
    if (s->is_const[k]) bg_sb_printf(o, "  v[%d] = ", k), num(o, s->v[k]), bg_sb_puts(o, ";\n");
  for (int k = 0; k < s->nmain; k++) value_stmt(s, &s->code[k], o);
  bg_sb_puts(o, "}\n\nstatic void bg_deriv(const double *v, double *d) {\n  double r, q, mg;\n"
                "  (void)r, (void)q, (void)mg;\n");
  for (int k = 0; k < s->nmain; k++) deriv_stmt(s, &s->code[k], o);
  bg_sb_puts(o, "}\n\n");
}

static void row_table(const bg_eqsys *s, bg_strbuf *o) {
  bg_sb_puts(o, "static const int bg_row_slot[BG_MODEL_N + 1] = {");
  for (int i = 0; i < s->n; i++) bg_sb_printf(o, "%s%d", i ? ", " : "", s->row_slot[i]);
  bg_sb_puts(o, s->n ? "};\n" : "0};\n");
  bg_sb_puts(o, "static const int bg_row_kind[BG_MODEL_N + 1] = {");
  for (int i = 0; i < s->n; i++) bg_sb_printf(o, "%s%d", i ? ", " : "", s->row_kind[i]);
  bg_sb_puts(o, s->n ? "};\n" : "0};\n");
}

void bg_eqprint_c_tape(const bg_eqsys *s, bg_strbuf *o) {
  int ode = bg_eqsys_is_ode(s);
  bg_sb_printf(o, "/* Generated by bgdraw from model %s: %s, unknowns y = (", s->m->name, ode ? "ODE" : "DAE");
  for (int i = 0; i < s->n; i++) bg_sb_printf(o, "%s%s", i ? ", " : "", s->uname[i]);
  bg_sb_printf(o, "). */\n#include <float.h>\n#include <math.h>\n#include <string.h>\n\n"
                  "#define BG_MODEL_N %d\n#define BG_MODEL_NX %d\n#define BG_NSLOT %d\n\n",
               s->n, s->nx, s->nslot);
  prelude_fn(o);
  prelude_tables(s->m, o);
  row_table(s, o);
  eval_fn(s, o);
  bg_sb_puts(o, "static int bg_finite(const double *v) {\n  for (int i = 0; i < BG_MODEL_N; i++)\n"
                "    if (!isfinite(v[bg_row_slot[i]])) return 0;\n  return 1;\n}\n\n");
  bg_sb_puts(o, "/* F(t, y, yp) = 0; 0, or -1 when a value is not finite */\n"
                "int bg_model_residual(double t, const double *y, const double *yp, double *res) {\n"
                "  static double v[BG_NSLOT];\n  bg_eval(t, y, yp, v);\n"
                "  for (int i = 0; i < BG_MODEL_N; i++)\n"
                "    res[i] = bg_row_kind[i] == 0 ? yp[i] - v[bg_row_slot[i]] : v[bg_row_slot[i]];\n"
                "  return bg_finite(v) ? 0 : -1;\n}\n\n");
  if (ode)
    bg_sb_puts(o, "/* ydot = f(t, y) */\nint bg_model_rhs(double t, const double *y, double *ydot) {\n"
                  "  static double v[BG_NSLOT];\n  bg_eval(t, y, 0, v);\n"
                  "  for (int i = 0; i < BG_MODEL_NX; i++) ydot[i] = v[bg_row_slot[i]];\n"
                  "  return bg_finite(v) ? 0 : -1;\n}\n\n");
  bg_sb_printf(o, "/* dense column-major Jacobian: %s */\n"
                  "void bg_model_jacobian(double t, const double *y, const double *yp, double cj, double *J) {\n"
                  "  static double v[BG_NSLOT], d[BG_NSLOT];\n  const int ode = %d;\n  bg_eval(t, y, ode ? 0 : yp, v);\n"
                  "  for (int j = 0; j < BG_MODEL_N; j++) {\n    memset(d, 0, sizeof d);\n"
                  "    d[1 + j] = 1, d[1 + BG_MODEL_N + j] = ode ? 0 : cj;\n    bg_deriv(v, d);\n"
                  "    for (int i = 0; i < BG_MODEL_N; i++) {\n      double x = d[bg_row_slot[i]];\n"
                  "      if (bg_row_kind[i] == 0 && !ode) x = (i == j ? cj : 0) - x;\n"
                  "      J[j * BG_MODEL_N + i] = x;\n    }\n  }\n}\n",
               ode ? "df/dy" : "dF/dy + cj dF/dyp", ode);
}
