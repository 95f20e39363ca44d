/* SPDX-License-Identifier: BSD-3-Clause */
/* The evaluation tape of an export build in C, Python or Octave syntax: one
 * assignment per instruction over a value array, from per-language
 * templates, so every exporter computes exactly what bgdraw computes. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "export/export_int.h"

/* the functions defined everywhere (Python's raise outside the domain: FN_DOMAIN) */
#define FN_TOTAL(P)                                                                            \
  [BG_FN_SIN] = P "sin(%0)", [BG_FN_COS] = P "cos(%0)", [BG_FN_TAN] = P "tan(%0)",             \
  [BG_FN_ATAN] = P "atan(%0)", [BG_FN_ATAN2] = P "atan2(%0, %1)", [BG_FN_TANH] = P "tanh(%0)"
#define FN_DOMAIN(P)                                                                           \
  [BG_FN_SQRT] = P "sqrt(%0)", [BG_FN_EXP] = P "exp(%0)", [BG_FN_LOG] = P "log(%0)",           \
  [BG_FN_LOG10] = P "log10(%0)", [BG_FN_ASIN] = P "asin(%0)", [BG_FN_ACOS] = P "acos(%0)",     \
  [BG_FN_SINH] = P "sinh(%0)", [BG_FN_COSH] = P "cosh(%0)", [BG_FN_FLOOR] = P "floor(%0)",     \
  [BG_FN_CEIL] = P "ceil(%0)"
#define FN_COMMON(P) FN_TOTAL(P), FN_DOMAIN(P)

const bg_xlang bg_xlang_c = {
    0, "[", "]", ";", "  ",
    {FN_COMMON(""), [BG_FN_ABS] = "fabs(%0)", [BG_FN_SIGN] = "(%0 > 0 ? 1.0 : %0 < 0 ? -1.0 : 0.0)",
     [BG_FN_MIN] = "fmin(%0, %1)", [BG_FN_MAX] = "fmax(%0, %1)", [BG_FN_POW] = "pow(%0, %1)",
     [BG_FN_IF] = "(%0 != 0 ? %1 : %2)", [BG_FN_STEP] = "(%0 < 0 ? 0.0 : 1.0)",
     [BG_FN_RAMP] = "(%0 < 0 ? 0.0 : %0)", [BG_FN_PULSE] = "(%0 >= 0 && %0 < %1 ? 1.0 : 0.0)",
     [BG_FN_SAT] = "(%0 < %1 ? %1 : %0 > %2 ? %2 : %0)",
     /* memory: the value it starts with (an export with memory is refused: bg_export_refusal) */
     [BG_FN_HYST] = "(%0 >= %2 ? 1.0 : 0.0)", [BG_FN_STICK] = "(%0 == 0 && fabs(%1) <= %2 ? 1.0 : 0.0)"},
    "-%0", "(double)(%0 == 0)", "(double)(%0 != 0 && %1 != 0)", "(double)(%0 != 0 || %1 != 0)",
    "pow(%0, %1)", "%0 / %1", "(double)(%0 %o %1)", "bg_tab(%t, %0)", "==", "!=", bg_reserved_c};

const bg_xlang bg_xlang_python = {
    0, "[", "]", "", "    ",
    /* Python's math raises where C returns inf or NaN (log(0), sqrt(-1), exp(1000),
     * floor(nan)): the helpers give C's values, so a tape evaluated at a point
     * outside a law's domain (initial() with every unknown 0) runs on as in C. */
    {FN_TOTAL("math."), FN_DOMAIN("_"),
     [BG_FN_ABS] = "math.fabs(%0)",
     [BG_FN_SIGN] = "(1.0 if %0 > 0 else -1.0 if %0 < 0 else 0.0)", [BG_FN_MIN] = "_fmin(%0, %1)",
     [BG_FN_MAX] = "_fmax(%0, %1)", [BG_FN_POW] = "_pow(%0, %1)", [BG_FN_IF] = "(%1 if %0 != 0 else %2)",
     [BG_FN_STEP] = "(0.0 if %0 < 0 else 1.0)", [BG_FN_RAMP] = "(0.0 if %0 < 0 else %0)",
     [BG_FN_PULSE] = "(1.0 if %0 >= 0 and %0 < %1 else 0.0)",
     [BG_FN_SAT] = "(%1 if %0 < %1 else %2 if %0 > %2 else %0)",
     [BG_FN_HYST] = "(1.0 if %0 >= %2 else 0.0)", [BG_FN_STICK] = "(1.0 if %0 == 0 and math.fabs(%1) <= %2 else 0.0)"},
    "-%0", "float(%0 == 0)", "float(%0 != 0 and %1 != 0)", "float(%0 != 0 or %1 != 0)",
    "_pow(%0, %1)", "_div(%0, %1)", /* Python raises on a division by 0, C gives inf or NaN */
    "float(%0 %o %1)", "_tab(%t, %0)", "==", "!=", bg_reserved_python};

const bg_xlang bg_xlang_octave = {
    1, "(", ")", ";", "  ",
    {FN_COMMON(""), [BG_FN_ABS] = "abs(%0)", [BG_FN_SIGN] = "sign(%0)", [BG_FN_MIN] = "bg_fmin(%0, %1)",
     [BG_FN_MAX] = "bg_fmax(%0, %1)", [BG_FN_POW] = "%0 ^ %1", [BG_FN_IF] = "bg_if(%0 ~= 0, %1, %2)",
     [BG_FN_STEP] = "double(%0 >= 0)", [BG_FN_RAMP] = "bg_if(%0 < 0, 0, %0)",
     [BG_FN_PULSE] = "double(%0 >= 0 && %0 < %1)", [BG_FN_SAT] = "bg_if(%0 < %1, %1, bg_if(%0 > %2, %2, %0))",
     [BG_FN_HYST] = "double(%0 >= %2)", [BG_FN_STICK] = "double(%0 == 0 && abs(%1) <= %2)"},
    "-%0", "double(%0 == 0)", "double(%0 ~= 0 && %1 ~= 0)", "double(%0 ~= 0 || %1 ~= 0)",
    "%0 ^ %1", "%0 / %1", "double(%0 %o %1)", "bg_tab(tables, %t, %0)", "==", "~=", bg_reserved_octave};

void bg_xl_slot(const bg_xlang *L, bg_strbuf *o, const char *arr, int k) {
  bg_sb_printf(o, "%s%s%d%s", arr, L->open, k + L->base, L->close);
}

void bg_xl_num(const bg_xlang *L, bg_strbuf *o, double c) {
  if (isnan(c)) bg_sb_puts(o, L == &bg_xlang_c ? "NAN" : L == &bg_xlang_python ? "math.nan" : "NaN");
  else if (isinf(c))
    bg_sb_puts(o, L == &bg_xlang_c ? (c > 0 ? "HUGE_VAL" : "(-HUGE_VAL)")
                  : L == &bg_xlang_python ? (c > 0 ? "math.inf" : "(-math.inf)") : (c > 0 ? "Inf" : "(-Inf)"));
  else if (c < 0) bg_sb_putc(o, '('), bg_sb_num(o, c), bg_sb_putc(o, ')');
  else bg_sb_num(o, c);
}

/* Expands a template with argument slots a[] (and table t). */
static void expand(const bg_xlang *L, bg_strbuf *o, const char *tpl, const int *a, int t,
                   const char *op, const char *arr) {
  for (const char *p = tpl; *p; p++) {
    if (*p != '%') { bg_sb_putc(o, *p); continue; }
    p++;
    if (*p >= '0' && *p <= '2') bg_xl_slot(L, o, arr, a[*p - '0']);
    else if (*p == 't') bg_sb_printf(o, "%d", t + L->base);
    else if (*p == 'o') bg_sb_puts(o, op);
    else bg_sb_putc(o, *p);
  }
}

static const char *cmp_op(const bg_xlang *L, int op) {
  switch (op) {
  case BG_X_LT: return "<"; case BG_X_LE: return "<="; case BG_X_GT: return ">";
  case BG_X_GE: return ">="; case BG_X_EQ: return L->eq; default: return L->ne;
  }
}

static void lin_value(const bg_xlang *L, const bg_eqsys *s, const tinstr *I, const char *arr,
                      bg_strbuf *o) {
  for (int k = 0; k < I->a[0]; k++) {
    if (k) bg_sb_puts(o, " + ");
    bg_xl_num(L, o, s->tl_coef[I->ref + k]);
    bg_sb_puts(o, " * ");
    bg_xl_slot(L, o, arr, s->tl_slot[I->ref + k]);
  }
  if (!I->a[0]) bg_sb_puts(o, "0");
}

/* The value expression of tape instruction I (no assignment). */
static void xl_expr(const bg_xlang *L, const bg_eqsys *s, const tinstr *I, const char *arr, bg_strbuf *o) {
  static const char *arith[] = {[BG_X_ADD] = "%0 + %1", [BG_X_SUB] = "%0 - %1", [BG_X_MUL] = "%0 * %1"};
  const char *tpl;
  switch (I->op) {
  case T_LIN: lin_value(L, s, I, arr, o); return;
  case BG_X_CALL: tpl = L->fn[I->ref]; break;
  case BG_X_TABLE: tpl = L->table; break;
  case BG_X_NEG: tpl = L->neg; break;
  case BG_X_NOT: tpl = L->not_; break;
  case BG_X_POW: tpl = L->pow_; break;
  case BG_X_AND: tpl = L->and_; break;
  case BG_X_OR: tpl = L->or_; break;
  case BG_X_DIV: tpl = L->div_; break;
  case BG_X_ADD: case BG_X_SUB: case BG_X_MUL: tpl = arith[I->op]; break;
  default: tpl = L->cmp; break;
  }
  expand(L, o, tpl, I->a, I->ref, cmp_op(L, I->op), arr);
}

/* ------------------------------------------------------------ switching instructions
 * (docs/export.md, "State events"): written through their modes; the
 * runtime they call is export_events.c's. */
int bg_xev_kind(const bg_eqsys *s, int e) {
  const tinstr *I = &s->code[s->ev_code[e]];
  switch (I->op) {
  case BG_X_LT: return K_LT;
  case BG_X_LE: return K_LE;
  case BG_X_GT: return K_GT;
  case BG_X_GE: return K_GE;
  case BG_X_TABLE: return K_TABLE;
  default: break;
  }
  switch (I->ref) {
  case BG_FN_ABS: return K_ABS;
  case BG_FN_SIGN: return K_SIGN;
  case BG_FN_STEP: return K_STEP;
  case BG_FN_RAMP: return K_RAMP;
  case BG_FN_MIN: return K_MIN;
  case BG_FN_MAX: return K_MAX;
  case BG_FN_PULSE: return K_PULSE;
  case BG_FN_SAT: return K_SAT;
  case BG_FN_HYST: return K_HYST;
  case BG_FN_STICK: return K_STICK;
  case BG_FN_FLOOR: return K_FLOOR;
  default: return K_CEIL;
  }
}

/* "K, T, [MODE, ]v[a0], v[a1], v[a2]": the kind, the table (0 when none),
 * mode (when given: an expression with %d for the event) and the three
 * argument values (0 for an argument the instruction lacks). */
void bg_xev_args(const bg_xlang *L, const bg_eqsys *s, int e, const char *arr, const char *mode, bg_strbuf *o) {
  const tinstr *I = &s->code[s->ev_code[e]];
  bg_sb_printf(o, "%d, %d", bg_xev_kind(s, e), I->op == BG_X_TABLE ? I->ref : 0);
  if (mode) bg_sb_puts(o, ", "), bg_sb_printf(o, mode, e);
  for (int q = 0; q < 3; q++) {
    bg_sb_puts(o, ", ");
    if (q < I->na) bg_xl_slot(L, o, arr, I->a[q]);
    else bg_sb_puts(o, "0.0");
  }
}

/* The value of switching instruction e (event e of s) through its mode:
 * C and Python call the runtime (bg_at, _at) with the compiled value beside
 * it; Octave writes the compiled value (its export has no modes). */
static void xev_value(const bg_xlang *L, const bg_eqsys *s, int e, const char *arr, bg_strbuf *o) {
  const tinstr *I = &s->code[s->ev_code[e]];
  if (L == &bg_xlang_octave) { xl_expr(L, s, I, arr, o); return; }
  bg_sb_printf(o, "%s(c, %d, ", L == &bg_xlang_c ? "bg_at" : "_at", e);
  bg_xev_args(L, s, e, arr, NULL, o);
  bg_sb_printf(o, ", %d, ", s->ev_root0[e]);
  xl_expr(L, s, I, arr, o);
  bg_sb_puts(o, ")");
}

/* "arr[out] = value;" for tape instruction k; a switching instruction of a
 * model with state events goes through its mode (export_events.c). */
static void value_stmt(const bg_xlang *L, const bg_eqsys *s, int k, const char *arr, bg_strbuf *o) {
  const tinstr *I = &s->code[k];
  bg_sb_puts(o, L->indent);
  bg_xl_slot(L, o, arr, I->out);
  bg_sb_puts(o, " = ");
  int e = s->nev && k < s->nmain ? s->code_ev[k] : -1;
  if (e >= 0) xev_value(L, s, e, arr, o);
  else xl_expr(L, s, I, arr, o);
  bg_sb_printf(o, "%s\n", L->stmt_end);
}

void bg_xl_constants(const bg_xlang *L, const bg_eqsys *s, const char *arr, const char *pfmt,
                     bg_strbuf *o) {
  char id[300], ref[400];
  for (int k = 0; k < s->nslot; k++)
    if (s->is_const[k]) {
      bg_sb_puts(o, L->indent), bg_xl_slot(L, o, arr, k), bg_sb_puts(o, " = ");
      bg_xl_num(L, o, s->v[k]);
      bg_sb_printf(o, "%s\n", L->stmt_end);
    }
  for (int k = 0; k < s->m->nparam; k++) {
    if (bg_eqsys_param_is_derived(s, k)) continue;
    snprintf(ref, sizeof ref, pfmt, bg_export_param_ident(L, s, k, id, sizeof id));
    bg_sb_puts(o, L->indent), bg_xl_slot(L, o, arr, s->slot_p + k);
    bg_sb_printf(o, " = %s%s\n", ref, L->stmt_end);
  }
}

void bg_xl_code(const bg_xlang *L, const bg_eqsys *s, int c0, int c1, const char *arr, bg_strbuf *o) {
  for (int k = c0; k < c1; k++) value_stmt(L, s, k, arr, o);
}

int bg_export_nparams(const bg_eqsys *s) {
  int n = 0;
  for (int k = 0; k < s->m->nparam; k++) n += !bg_eqsys_param_is_derived(s, k);
  return n;
}

void bg_export_default_prefix(const bg_model *m, char *buf, size_t n) {
  bg_export_ident(m->name && *m->name ? m->name : "model", buf, n);
}

int bg_export_prefix_ok(const char *p) {
  if (!p || !*p || strlen(p) > 64 || (*p >= '0' && *p <= '9')) return 0;
  for (; *p; p++)
    if (!((*p >= 'A' && *p <= 'Z') || (*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9') || *p == '_'))
      return 0;
  return 1;
}

int bg_export_refusal(const bg_eqsys *s, const char *format, bg_strbuf *why) {
  /* C, Python and the FMU carry the modes (export_events.c); Octave and
   * Modelica do not, and a memory function has no value without its mode */
  if (!strcmp(format, "c") || !strcmp(format, "h") || !strcmp(format, "py") || !strcmp(format, "fmu")) return 0;
  int nm = bg_eqsys_nmodes(s), first;
  for (int e = 0; e < nm; e++) {
    if (!bg_eqsys_mode_memory(s, e)) continue;
    bg_eqsys_mode_roots(s, e, &first);
    bg_sb_printf(why, "the model keeps a discrete state (%s, %d memory function%s in all) that the "
                 "%s export does not carry: between events its value would be wrong; export it to C, "
                 "Python or an FMU, or simulate it with bgdraw (docs/export.md)", bg_eqsys_root_text(s, first),
                 bg_eqsys_has_memory(s), bg_eqsys_has_memory(s) == 1 ? "" : "s",
                 !strcmp(format, "m") ? "Octave/MATLAB" : "Modelica");
    return 1;
  }
  return 0;
}
