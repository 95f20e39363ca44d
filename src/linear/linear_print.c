/* SPDX-License-Identifier: BSD-3-Clause */
/* The linear analysis as text (--linear text) and LaTeX (--linear latex):
 * the operating point, the matrices, poles with natural frequency and
 * damping, and each transfer function with its poles, zeros and DC gain.
 * Numbers with 6 significant digits (the JSON has them all). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "linear/linear.h"

static void num(bg_strbuf *o, double v) { bg_sb_printf(o, "%.6g", v == 0 ? 0.0 : v); }

static void text_matrix(bg_strbuf *o, const char *name, const double *M, int r, int c) {
  bg_sb_printf(o, "%s = [", name);
  for (int i = 0; i < r; i++) {
    if (i) bg_sb_printf(o, ";\n%*s", (int)strlen(name) + 4, "");
    for (int j = 0; j < c; j++) bg_sb_printf(o, "%s%.6g", j ? "  " : "", M[(size_t)j * r + i] + 0.0);
  }
  bg_sb_puts(o, "]\n");
}

static void latex_matrix(bg_strbuf *o, const char *name, const double *M, int r, int c) {
  bg_sb_printf(o, "%s &= \\begin{bmatrix}", name);
  for (int i = 0; i < r; i++) {
    if (i) bg_sb_puts(o, " \\\\");
    for (int j = 0; j < c; j++) bg_sb_printf(o, "%s%.6g", j ? " & " : " ", M[(size_t)j * r + i] + 0.0);
  }
  bg_sb_puts(o, " \\end{bmatrix}");
}

/* A polynomial in s, highest power first: "s^2 + 4*s + 20" (latex: "s^{2} + 4 s + 20"). */
static void poly(bg_strbuf *o, const double *c, int nc, int latex) {
  int first = 1;
  for (int k = 0; k < nc; k++) {
    int p = nc - 1 - k;
    double v = c[k];
    if (v == 0 && !(nc == 1)) continue;
    /* the coefficient as printed decides: 0.99999999 prints as 1 and is left
     * out before a power of s ("s^5", not "1*s^5") */
    char a[32];
    snprintf(a, sizeof a, "%.6g", fabs(v));
    int one = !strcmp(a, "1");
    bg_sb_puts(o, first ? (v < 0 ? "-" : "") : (v < 0 ? " - " : " + "));
    first = 0;
    if (!one || p == 0) bg_sb_puts(o, a);
    if (p > 0 && !one) bg_sb_puts(o, latex ? " " : "*");
    if (p == 1) bg_sb_puts(o, "s");
    else if (p > 1) bg_sb_printf(o, latex ? "s^{%d}" : "s^%d", p);
  }
  if (first) bg_sb_puts(o, "0");
}

/* Roots as "-2 ± 4j" for conjugate pairs (the one with im > 0 listed). */
static void roots(bg_strbuf *o, const double *re, const double *im, int n) {
  int any = 0;
  for (int i = 0; i < n; i++) {
    if (im[i] < 0) continue;
    bg_sb_puts(o, any ? ", " : "");
    any = 1;
    num(o, re[i]);
    if (im[i] > 0) bg_sb_printf(o, " ± %.6gj", im[i]);
  }
  if (!any) bg_sb_puts(o, "none");
}

static void pole_lines(bg_strbuf *o, const bg_linear *l) {
  bg_sb_printf(o, "poles (%d):\n", l->npole);
  for (int i = 0; i < l->npole; i++) {
    double re = l->pole_re[i], im = l->pole_im[i], wn = hypot(re, im);
    if (im < 0) continue;
    bg_sb_puts(o, "  ");
    num(o, re);
    if (im > 0) bg_sb_printf(o, " ± %.6gj   wn = %.6g rad/s, zeta = %.6g\n", im, wn, -re / wn + 0.0);
    else if (re != 0) bg_sb_printf(o, "   tau = %.6g s\n", -1 / re);
    else bg_sb_puts(o, "   (integrator)\n");
  }
}

static void tf_text(bg_strbuf *o, const bg_linear *l, const bg_lin_tf *t) {
  bg_sb_printf(o, "%s/%s = (", l->yname[t->iy], l->uname[t->iu]);
  poly(o, t->num, t->nnum, 0);
  bg_sb_puts(o, ") / (");
  poly(o, t->den, t->nden, 0);
  bg_sb_puts(o, ")\n  poles: ");
  roots(o, t->pole_re, t->pole_im, t->npole);
  bg_sb_puts(o, "; zeros: ");
  roots(o, t->zero_re, t->zero_im, t->nzero);
  bg_sb_puts(o, "; DC gain: ");
  if (isinf(t->dc_gain)) bg_sb_puts(o, "infinite (integrator)");
  else num(o, t->dc_gain);
  if (t->ncancel) bg_sb_printf(o, "; %d mode%s not seen by this pair", t->ncancel, t->ncancel > 1 ? "s" : "");
  bg_sb_putc(o, '\n');
}

/* A symbolic polynomial in s from printed coefficients (highest power first). */
static void sym_poly(bg_strbuf *o, char *const *c, int nc, int latex) {
  int first = 1;
  for (int k = 0; k < nc; k++) {
    int p = nc - 1 - k;
    if (!strcmp(c[k], "0")) continue;
    int plain = strspn(c[k], "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._{}\\") == strlen(c[k]);
    const char *v = c[k];
    if (!first && p == 0 && v[0] == '-') bg_sb_puts(o, " - "), v++; /* "... - Ra/(La*J0)" */
    else bg_sb_puts(o, first ? "" : " + ");
    first = 0;
    if (p == 0 || strcmp(v, "1")) {
      bg_sb_printf(o, plain || p == 0 ? "%s" : latex ? "\\left(%s\\right)" : "(%s)", v);
      if (p > 0) bg_sb_puts(o, latex ? " " : "*");
    }
    if (p == 1) bg_sb_puts(o, "s");
    else if (p > 1) bg_sb_printf(o, latex ? "s^{%d}" : "s^%d", p);
  }
  if (first) bg_sb_puts(o, "0");
}

static void sym_matrix(bg_strbuf *o, const char *name, char *const *M, int r, int c, int latex) {
  bg_sb_printf(o, latex ? "%s &= \\begin{bmatrix}" : "%s = [", name);
  for (int i = 0; i < r; i++) {
    if (i) bg_sb_puts(o, latex ? " \\\\" : "; ");
    for (int j = 0; j < c; j++) bg_sb_printf(o, "%s%s", j ? (latex ? " & " : ", ") : " ", M[(size_t)j * r + i]);
  }
  bg_sb_puts(o, latex ? " \\end{bmatrix}" : " ]\n");
}

/* The symbolic matrices and transfer functions (a linear model). */
static void print_symbolic(const bg_linear *l, bg_strbuf *o, int latex) {
  const bg_lin_symbolic *y = &l->sym;
  int n = y->n;
  if (!latex) bg_sb_puts(o, "symbolic (in the params):\n");
  const char *names[] = {"A", "B", "C", "D"};
  char **const *mats[] = {y->A, y->B, y->C, y->D};
  const int rows[] = {n, n, l->ny, l->ny}, cols[] = {n, l->nu, n, l->nu};
  for (int k = 0; k < 4; k++) {
    sym_matrix(o, names[k], mats[k][latex], rows[k], cols[k], latex);
    if (latex) bg_sb_puts(o, " \\\\\n");
  }
  for (int p = 0; p < l->ny * l->nu; p++) {
    const char *yn = l->yname[p / l->nu], *un = l->uname[p % l->nu];
    bg_sb_printf(o, latex ? "\\frac{%s}{%s} &= \\frac{" : "%s/%s = (", yn, un);
    sym_poly(o, y->num[latex] + (size_t)p * (n + 1), n + 1, latex);
    bg_sb_puts(o, latex ? "}{" : ") / (");
    sym_poly(o, y->den[latex], n + 1, latex);
    bg_sb_puts(o, latex ? (p + 1 < l->ny * l->nu ? "} \\\\\n" : "}\n") : ")\n");
  }
}

static void header(bg_strbuf *o, const bg_linear *l, const bg_model *m, const char *c) {
  bg_sb_printf(o, "%s linear analysis of %s at the %s, t = %g\n", c, m->name,
               l->steady ? "steady state" : "initial point", l->t);
  if (l->message) bg_sb_printf(o, "%s %s\n", c, l->message);
}

static void print_text(const bg_linear *l, const bg_model *m, bg_strbuf *o) {
  header(o, l, m, "#");
  if (!l->ok) return;
  bg_sb_puts(o, "inputs: ");
  for (int k = 0; k < l->nu; k++) bg_sb_printf(o, "%s%s", k ? ", " : "", l->uname[k]);
  bg_sb_puts(o, l->nu ? "\noutputs: " : "none\noutputs: ");
  for (int k = 0; k < l->ny; k++) bg_sb_printf(o, "%s%s", k ? ", " : "", l->yname[k]);
  if (l->outputs_are_states && !l->ny) bg_sb_puts(o, "none (no output statement and no states)\n");
  else bg_sb_puts(o, l->outputs_are_states ? " (the states: no output statement)\n" : "\n");
  if (l->reduced && l->n <= 40) {
    bg_sb_puts(o, l->n ? "states: " : "states: none");
    for (int i = 0; i < l->n; i++) bg_sb_printf(o, "%s%s", i ? ", " : "", l->uname_all[l->state[i]]);
    for (int i = 0; i < l->nelim; i++)
      bg_sb_printf(o, "%s%s", i ? ", " : " (dependent stores eliminated: ", l->uname_all[l->elim[i]]);
    bg_sb_puts(o, l->nelim ? ")\n" : "\n");
    text_matrix(o, "A", l->A, l->n, l->n), text_matrix(o, "B", l->B, l->n, l->nu);
    text_matrix(o, "C", l->C, l->ny, l->n), text_matrix(o, "D", l->D, l->ny, l->nu);
  } else if (l->reduced) {
    bg_sb_printf(o, "%d states: matrices in the JSON and the .m/.py exports\n", l->n);
  } else {
    bg_sb_printf(o, "# %s\n", l->reduce_note ? l->reduce_note : "descriptor form");
    if (l->N <= 40) {
      text_matrix(o, "E", l->E, l->N, l->N), text_matrix(o, "A", l->Ad, l->N, l->N);
      text_matrix(o, "B", l->Bd, l->N, l->nu), text_matrix(o, "C", l->Cd, l->ny, l->N);
      if (l->has_cp) text_matrix(o, "Cp", l->Cpd, l->ny, l->N);
      text_matrix(o, "D", l->Dd, l->ny, l->nu);
    }
  }
  pole_lines(o, l);
  for (int k = 0; k < l->ntf; k++) tf_text(o, l, &l->tf[k]);
  if (l->tf_note) bg_sb_printf(o, "# %s\n", l->tf_note);
  if (l->sym.ok) print_symbolic(l, o, 0);
  else if (l->sym.note) bg_sb_printf(o, "# symbolic form: %s\n", l->sym.note);
}

static void print_latex(const bg_linear *l, const bg_model *m, bg_strbuf *o) {
  header(o, l, m, "%");
  if (!l->ok) return;
  bg_sb_puts(o, "\\begin{align*}\n");
  if (l->reduced && l->n <= 40) {
    latex_matrix(o, "A", l->A, l->n, l->n), bg_sb_puts(o, " \\\\\n");
    latex_matrix(o, "B", l->B, l->n, l->nu), bg_sb_puts(o, " \\\\\n");
    latex_matrix(o, "C", l->C, l->ny, l->n), bg_sb_puts(o, " \\\\\n");
    latex_matrix(o, "D", l->D, l->ny, l->nu), bg_sb_puts(o, l->ntf ? " \\\\\n" : "\n");
  }
  for (int k = 0; k < l->ntf; k++) {
    const bg_lin_tf *t = &l->tf[k];
    bg_sb_printf(o, "\\frac{%s}{%s} &= \\frac{", l->yname[t->iy], l->uname[t->iu]);
    poly(o, t->num, t->nnum, 1);
    bg_sb_puts(o, "}{");
    poly(o, t->den, t->nden, 1);
    bg_sb_puts(o, k + 1 < l->ntf ? "} \\\\\n" : "}\n");
  }
  bg_sb_puts(o, "\\end{align*}\n");
  if (!l->sym.ok) return;
  bg_sb_puts(o, "% symbolic (in the params)\n\\begin{align*}\n");
  print_symbolic(l, o, 1);
  bg_sb_puts(o, "\\end{align*}\n");
}

void bg_linear_print(const bg_linear *l, const bg_model *m, const char *form, bg_strbuf *o) {
  if (!strcmp(form, "latex")) print_latex(l, m, o);
  else print_text(l, m, o);
}
