/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_sym printing, text, LaTeX and presentation MathML (sym.h): sums start
 * with a positive term (n - 1, not -1 + n), products print as numerator /
 * denominator, and a negative product with a sum among its factors flips
 * that sum instead of printing a minus (Kv*(1 - u), not -Kv*(u - 1)). The
 * three forms come from one walk of the tree: MathML's elements wrap what
 * LaTeX writes as braces (\frac{a}{b} is <mfrac>, x^{2} is <msup>). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/model.h"
#include "sym/sym.h"

enum { P_CMP, P_ADD, P_NEG, P_MUL, P_POW, P_ATOM };

typedef struct pctx {
  bg_sym *S;
  int latex; /* LaTeX or MathML: fractions, braces, no '*' */
  int ml;    /* MathML (BG_SYM_MATHML) */
  int mode;  /* the caller's BG_SYM_* (the name callback's argument) */
  bg_sym_namefn name;
  void *ctx;
} pctx;

static void pr(pctx *P, int a, bg_strbuf *out);

#define ML_MINUS "<mo>&#x2212;</mo>"
#define ML_TIMES "<mo>&#x2062;</mo>" /* invisible times */

static void put_num(pctx *P, double v, bg_strbuf *out) {
  char buf[40];
  if (P->ml && (isnan(v) || isinf(v))) {
    bg_sb_puts(out, isnan(v) ? "<mi>NaN</mi>" : v < 0 ? ML_MINUS "<mi>&#x221e;</mi>" : "<mi>&#x221e;</mi>");
    return;
  }
  if (isnan(v)) { bg_sb_puts(out, "nan"); return; }
  if (isinf(v)) { bg_sb_puts(out, v < 0 ? "-inf" : "inf"); return; }
  bg_num_format(buf, sizeof buf, v, 6); /* %g's style for round numbers */
  char *e = strchr(buf, 'e'), *mant = buf;
  if (P->ml && *mant == '-') bg_sb_puts(out, ML_MINUS), mant++;
  if (!P->latex || !e) {
    bg_sb_printf(out, P->ml ? "<mn>%s</mn>" : "%s", mant);
    return;
  }
  *e = 0;
  int ex = atoi(e + 1);
  if (P->ml) {
    if (strcmp(mant, "1")) bg_sb_printf(out, "<mn>%s</mn><mo>&#x22c5;</mo>", mant);
    bg_sb_printf(out, "<msup><mn>10</mn><mrow>%s<mn>%d</mn></mrow></msup>", ex < 0 ? ML_MINUS : "",
                 ex < 0 ? -ex : ex);
    return;
  }
  if (strcmp(buf, "1")) bg_sb_printf(out, "%s \\cdot ", buf);
  bg_sb_printf(out, "10^{%d}", ex);
}

static int prec(const bg_sym *S, int a) {
  const bg_symnode *x = &S->node[a];
  switch (x->kind) {
  case SYM_NUM: return x->c < 0 ? P_NEG : P_ATOM;
  case SYM_ADD: return P_ADD;
  case SYM_MUL:
    if (x->c < 0) return P_NEG;
    if (x->n == 1 && x->c == 1 && S->w[x->adr] > 0) return P_POW;
    return P_MUL;
  case SYM_POW: return P_POW;
  case SYM_OP: return x->ref == BG_X_NOT ? P_NEG : P_CMP;
  default: return P_ATOM;
  }
}

static void open_p(pctx *P, bg_strbuf *out) {
  bg_sb_puts(out, P->ml ? "<mrow><mo>(</mo>" : P->latex ? "\\left(" : "(");
}
static void close_p(pctx *P, bg_strbuf *out) {
  bg_sb_puts(out, P->ml ? "<mo>)</mo></mrow>" : P->latex ? "\\right)" : ")");
}
/* MathML's operators: text as it is, in <mo> with < > & escaped. */
static void put_op(pctx *P, const char *text, const char *ml, bg_strbuf *out) {
  if (P->ml) bg_sb_printf(out, "<mo>%s</mo>", ml);
  else bg_sb_puts(out, text);
}

static void pr_paren(pctx *P, int a, int need, bg_strbuf *out) {
  int p = prec(P->S, a) < need;
  if (p) open_p(P, out);
  pr(P, a, out);
  if (p) close_p(P, out);
}

static void pr_leaf(pctx *P, const bg_symnode *x, bg_strbuf *out) {
  const bg_model *m = P->S->m;
  if (x->kind == SYM_DALIAS) { /* (dT/dphi) */
    int al, var;
    bg_sym_dalias_info(P->S, x->ref, &al, &var);
    bg_symnode a = {SYM_ALIAS, al, 0, 0, 0, 0}, v = P->S->node[var];
    bg_sb_puts(out, P->ml ? "<mfrac><mrow><mo>&#x2202;</mo>" : P->latex ? "\\frac{\\partial " : "(d");
    pr_leaf(P, &a, out);
    bg_sb_puts(out, P->ml ? "</mrow><mrow><mo>&#x2202;</mo>" : P->latex ? "}{\\partial " : "/d");
    pr_leaf(P, &v, out);
    bg_sb_puts(out, P->ml ? "</mrow></mfrac>" : P->latex ? "}" : ")");
    return;
  }
  if (P->name) { P->name(P->ctx, x->kind, x->ref, P->mode, out); return; }
  if (P->ml) { /* names are identifiers: nothing to escape */
    bg_sb_puts(out, "<mi>");
    bg_symnode plain = *x;
    pctx T = {P->S, 0, 0, BG_SYM_TEXT, NULL, NULL};
    pr_leaf(&T, &plain, out);
    bg_sb_puts(out, "</mi>");
    return;
  }
  switch (x->kind) {
  case SYM_PARAM: bg_sb_puts(out, m->param_name[x->ref]); break;
  case SYM_INPUT: bg_sb_puts(out, m->input_name[x->ref]); break;
  case SYM_T: bg_sb_puts(out, "t"); break;
  case SYM_Y: bg_sb_printf(out, "y%d", x->ref); break;
  case SYM_YP: bg_sb_printf(out, "y%d'", x->ref); break;
  case SYM_ALIAS: bg_sb_printf(out, "A%d", x->ref); break;
  default: bg_sb_printf(out, "%c%d", x->ref & 1 ? 'f' : 'e', m->bond_num[x->ref / 2]); break;
  }
}

/* ------------------------------------------------------------ sums */
/* A sum with every sign flipped when `neg`. */
static void pr_sum(pctx *P, int a, int neg, bg_strbuf *out);

/* |w| * t, the sign printed by the caller. */
static void pr_term(pctx *P, double w, int t, bg_strbuf *out);
static void pr_prod(pctx *P, int a, double coef, bg_strbuf *out);

/* A product term printed with a negative weight can flip one of its sum
 * factors instead: - Kv*e*(u - 1) reads + Kv*e*(1 - u). */
/* A sum worth flipping: it has a negative term (flipped, it still starts
 * with a positive one: u - 1 -> 1 - u, never a + b -> -a - b). */
static int flip_sum(const bg_sym *S, int b) {
  const bg_symnode *x = &S->node[b];
  if (x->kind != SYM_ADD) return 0;
  if (x->c < 0) return 1;
  for (int k = 0; k < x->n; k++)
    if (S->w[x->adr + k] < 0) return 1;
  return 0;
}

static int flippable(const bg_sym *S, int t) {
  const bg_symnode *x = &S->node[t];
  if (x->kind != SYM_MUL) return 0;
  for (int k = 0; k < x->n; k++)
    if (S->w[x->adr + k] == 1 && flip_sum(S, S->arg[x->adr + k])) return 1;
  return 0;
}

static void pr_sum(pctx *P, int a, int neg, bg_strbuf *out) {
  bg_sym *S = P->S;
  const bg_symnode *x = &S->node[a];
  int n = x->n, adr = x->adr, first = -2; /* -1: the constant */
  double c = neg ? -x->c : x->c, sg = neg ? -1 : 1;
  if (c > 0) first = -1;
  for (int k = 0; k < n && first == -2; k++)
    if (sg * S->w[adr + k] > 0) first = k;
  for (int k = 0; k < n && first == -2; k++)
    if (flippable(S, S->arg[adr + k])) first = k;
  if (first == -2) first = c != 0 ? -1 : 0;
  int printed = 0;
  for (int pass = 0; pass < 2; pass++)
    for (int k = -1; k < n; k++) {
      if ((pass == 0) != (k == first)) continue;
      double w = k < 0 ? c : sg * S->w[adr + k];
      if (w == 0) continue;
      int flip = k >= 0 && w < 0 && flippable(S, S->arg[adr + k]);
      if (printed) put_op(P, w < 0 && !flip ? " - " : " + ", w < 0 && !flip ? "&#x2212;" : "+", out);
      else if (w < 0 && !flip) put_op(P, "-", "&#x2212;", out);
      if (k < 0) put_num(P, fabs(w), out);
      else if (flip) pr_prod(P, S->arg[adr + k], w * S->node[S->arg[adr + k]].c, out);
      else pr_term(P, fabs(w), S->arg[adr + k], out);
      x = &S->node[a];
      printed++;
    }
  if (!printed) bg_sb_puts(out, "0");
}

/* ------------------------------------------------------------ products */
static void pr_factor(pctx *P, int b, double e, bg_strbuf *out, int flip, int alone) {
  if (alone && e == 1) { /* the whole numerator or denominator of a \frac */
    if (flip) pr_sum(P, b, 1, out);
    else pr(P, b, out);
    return;
  }
  if (flip) {
    open_p(P, out), pr_sum(P, b, 1, out), close_p(P, out);
    return;
  }
  if (e == 0.5 && !P->latex) {
    bg_sb_puts(out, "sqrt("), pr(P, b, out), bg_sb_puts(out, ")");
    return;
  }
  if (e == 0.5) {
    bg_sb_puts(out, P->ml ? "<msqrt>" : "\\sqrt{"), pr(P, b, out), bg_sb_puts(out, P->ml ? "</msqrt>" : "}");
    return;
  }
  if (P->ml && e != 1) bg_sb_puts(out, "<msup><mrow>");
  pr_paren(P, b, e == 1 ? P_POW : P_ATOM, out);
  if (e == 1) return;
  bg_sb_puts(out, P->ml ? "</mrow><mrow>" : P->latex ? "^{" : "^");
  if (e < 0 && !P->latex) bg_sb_puts(out, "(");
  put_num(P, e, out);
  if (e < 0 && !P->latex) bg_sb_puts(out, ")");
  if (P->latex) bg_sb_puts(out, P->ml ? "</mrow></msup>" : "}");
}

/* Factors with exponents of sign `sgn`, joined; returns how many. alone:
 * the only factor of a LaTeX fraction's part (no parentheses needed). */
static int pr_factors(pctx *P, int a, int sgn, int flip_at, int alone, bg_strbuf *out) {
  bg_sym *S = P->S;
  const bg_symnode *x = &S->node[a];
  int cnt = 0;
  for (int k = 0; k < x->n; k++) {
    double e = S->w[x->adr + k];
    if ((e > 0) != (sgn > 0)) continue;
    if (cnt++) bg_sb_puts(out, P->ml ? ML_TIMES : P->latex ? " " : "*");
    pr_factor(P, S->arg[x->adr + k], sgn > 0 ? e : -e, out, k == flip_at, alone);
    x = &S->node[a];
  }
  return cnt;
}

/* coef * (the factors of product a), coef >= 0 unless a negative product
 * is printed as such (the caller prints a leading '-'). */
static void pr_prod(pctx *P, int a, double coef, bg_strbuf *out) {
  bg_sym *S = P->S;
  const bg_symnode *x = &S->node[a];
  int flip = -1, nnum = 0, nden = 0;
  if (coef < 0) { /* flip a sum in the numerator rather than print a minus */
    for (int k = 0; k < x->n && flip < 0; k++)
      if (S->w[x->adr + k] == 1 && flip_sum(S, S->arg[x->adr + k])) flip = k;
    if (flip < 0) put_op(P, "-", "&#x2212;", out);
    coef = -coef;
  }
  for (int k = 0; k < x->n; k++) nnum += S->w[x->adr + k] > 0, nden += S->w[x->adr + k] < 0;
  bg_strbuf num = {0}, den = {0};
  if (coef != 1 || nnum == 0) {
    put_num(P, coef, &num);
    if (nnum) bg_sb_puts(&num, P->ml ? ML_TIMES : P->latex ? " " : "*");
  }
  int frac = P->latex && nden > 0;
  pr_factors(P, a, 1, flip, frac && nnum == 1 && coef == 1, &num);
  if (nden) pr_factors(P, a, -1, -1, frac && nden == 1, &den);
  if (P->ml && nden) {
    bg_sb_printf(out, "<mfrac><mrow>%s</mrow><mrow>%s</mrow></mfrac>", bg_sb_str(&num), bg_sb_str(&den));
  } else if (P->latex && nden) {
    bg_sb_printf(out, "\\frac{%s}{%s}", bg_sb_str(&num), bg_sb_str(&den));
  } else {
    bg_sb_puts(out, bg_sb_str(&num));
    if (nden) {
      int wrap = nden > 1; /* one factor: x, x^2, (a + b) need no extra parentheses */
      bg_sb_puts(out, wrap ? "/(" : "/");
      bg_sb_puts(out, bg_sb_str(&den));
      if (wrap) bg_sb_puts(out, ")");
    }
  }
  bg_sb_free(&num), bg_sb_free(&den);
}

static void pr_term(pctx *P, double w, int t, bg_strbuf *out) {
  if (P->S->node[t].kind == SYM_MUL) {
    pr_prod(P, t, w * P->S->node[t].c, out);
    return;
  }
  if (w != 1) put_num(P, w, out), bg_sb_puts(out, P->ml ? ML_TIMES : P->latex ? " " : "*");
  pr_paren(P, t, w != 1 ? P_MUL : P_NEG, out);
}

/* ------------------------------------------------------------ functions */
static const char *latex_fn(int fn) {
  switch (fn) {
  case BG_FN_SIN: return "\\sin"; case BG_FN_COS: return "\\cos"; case BG_FN_TAN: return "\\tan";
  case BG_FN_EXP: return "\\exp"; case BG_FN_LOG: return "\\ln"; case BG_FN_SINH: return "\\sinh";
  case BG_FN_COSH: return "\\cosh"; case BG_FN_TANH: return "\\tanh"; case BG_FN_MIN: return "\\min";
  case BG_FN_MAX: return "\\max"; case BG_FN_ASIN: return "\\arcsin"; case BG_FN_ACOS: return "\\arccos";
  case BG_FN_ATAN: return "\\arctan";
  default: return NULL;
  }
}

static void pr_args(pctx *P, const bg_symnode *x0, int a, bg_strbuf *out) {
  if (P->ml) bg_sb_puts(out, "<mo>&#x2061;</mo>"); /* function application */
  open_p(P, out);
  for (int k = 0; k < x0->n; k++) {
    if (k) put_op(P, ", ", ",", out);
    pr(P, P->S->arg[P->S->node[a].adr + k], out);
  }
  close_p(P, out);
}

static void pr_call(pctx *P, int a, bg_strbuf *out) {
  bg_symnode x = P->S->node[a];
  if (P->latex && x.ref == BG_FN_SQRT) {
    bg_sb_puts(out, P->ml ? "<msqrt>" : "\\sqrt{"), pr(P, P->S->arg[x.adr], out);
    bg_sb_puts(out, P->ml ? "</msqrt>" : "}");
    return;
  }
  if (P->latex && x.ref == BG_FN_ABS) {
    bg_sb_puts(out, P->ml ? "<mrow><mo>|</mo>" : "\\left|"), pr(P, P->S->arg[x.adr], out);
    bg_sb_puts(out, P->ml ? "<mo>|</mo></mrow>" : "\\right|");
    return;
  }
  const char *ln = P->latex ? latex_fn(x.ref) : NULL;
  if (P->ml) bg_sb_printf(out, "<mi>%s</mi>", ln ? ln + 1 : bg_func_name(x.ref)); /* \sin is sin */
  else if (ln) bg_sb_puts(out, ln);
  else if (P->latex) bg_sb_printf(out, "\\operatorname{%s}", bg_func_name(x.ref));
  else bg_sb_puts(out, bg_func_name(x.ref));
  pr_args(P, &x, a, out);
}

static const char *op_mathml(int op) {
  switch (op) {
  case BG_X_LT: return "<mo>&lt;</mo>";
  case BG_X_LE: return "<mo>&#x2264;</mo>";
  case BG_X_GT: return "<mo>&gt;</mo>";
  case BG_X_GE: return "<mo>&#x2265;</mo>";
  case BG_X_EQ: return "<mo>=</mo>";
  case BG_X_NE: return "<mo>&#x2260;</mo>";
  case BG_X_AND: return "<mo>&#x2227;</mo>";
  case BG_X_OR: return "<mo>&#x2228;</mo>";
  default: return "<mo>&#x00ac;</mo>";
  }
}

static const char *op_text(int op, int latex) {
  switch (op) {
  case BG_X_LT: return " < ";
  case BG_X_LE: return latex ? " \\le " : " <= ";
  case BG_X_GT: return " > ";
  case BG_X_GE: return latex ? " \\ge " : " >= ";
  case BG_X_EQ: return latex ? " = " : " == ";
  case BG_X_NE: return latex ? " \\ne " : " != ";
  case BG_X_AND: return latex ? " \\land " : " && ";
  case BG_X_OR: return latex ? " \\lor " : " || ";
  default: return latex ? "\\lnot " : "!";
  }
}

static void pr(pctx *P, int a, bg_strbuf *out) {
  bg_sym *S = P->S;
  bg_symnode x = S->node[a];
  switch (x.kind) {
  case SYM_NUM: put_num(P, x.c, out); break;
  case SYM_ADD: pr_sum(P, a, 0, out); break;
  case SYM_MUL: pr_prod(P, a, x.c, out); break;
  case SYM_POW:
    if (P->ml) bg_sb_puts(out, "<msup><mrow>");
    pr_paren(P, S->arg[x.adr], P_ATOM, out);
    bg_sb_puts(out, P->ml ? "</mrow><mrow>" : P->latex ? "^{" : "^");
    if (P->latex) pr(P, S->arg[S->node[a].adr + 1], out), bg_sb_puts(out, P->ml ? "</mrow></msup>" : "}");
    else pr_paren(P, S->arg[S->node[a].adr + 1], P_ATOM, out);
    break;
  case SYM_CALL: pr_call(P, a, out); break;
  case SYM_TABLE: case SYM_DTABLE:
    if (P->ml) {
      bg_sb_printf(out, "<mi>%s</mi><mo>&#x2061;</mo><mrow><mo>(</mo>", x.kind == SYM_TABLE ? "table" : "dtable");
      pr(P, S->arg[x.adr], out);
      bg_sb_printf(out, "<mo>,</mo><mi>#%d</mi><mo>)</mo></mrow>", x.ref + 1);
      break;
    }
    bg_sb_puts(out, x.kind == SYM_TABLE ? "table(" : "dtable(");
    pr(P, S->arg[x.adr], out);
    bg_sb_printf(out, ", #%d)", x.ref + 1);
    break;
  case SYM_OP:
    if (x.ref == BG_X_NOT) {
      bg_sb_puts(out, P->ml ? op_mathml(x.ref) : op_text(x.ref, P->latex));
      pr_paren(P, S->arg[x.adr], P_ATOM, out);
    } else {
      pr_paren(P, S->arg[x.adr], P_ADD, out);
      bg_sb_puts(out, P->ml ? op_mathml(x.ref) : op_text(x.ref, P->latex));
      pr_paren(P, S->arg[S->node[a].adr + 1], P_ADD, out);
    }
    break;
  default: pr_leaf(P, &x, out); break;
  }
}

void bg_sym_print(bg_sym *S, int a, int mode, bg_sym_namefn name, void *ctx, bg_strbuf *out) {
  pctx P = {S, mode != BG_SYM_TEXT, mode == BG_SYM_MATHML, mode, name, ctx};
  pr(&P, a, out);
}
