/* SPDX-License-Identifier: BSD-3-Clause */
/* Report section 10: the linear analysis (docs/linear.md): the operating
 * point, the state space, the poles each beside the nearest time constant
 * or natural frequency the chapter estimates from causal paths (and how far
 * apart they are), the transfer functions, the Bode diagram and the step
 * responses. Only when the run made a linear analysis. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot/plot_linear.h"
#include "report/report_int.h"

#define MAX_POLES 60
#define MAX_TFS 40

static void para(rp_ctx *c, const char *markup) {
  rp_para(&c->body, markup, RP_SIZE_BODY, 0, 0, rp_ink);
  rp_gap(&c->body, 3);
}

static void point_para(rp_ctx *c, const bg_linear *l) {
  bg_strbuf b = {0};
  bg_sb_printf(&b, "Linearised at the %s, t = ", l->steady ? "steady state" : "initial point");
  rp_num(&b, l->t);
  bg_sb_puts(&b, " s (inputs held at their values there");
  if (!l->steady) bg_sb_puts(&b, "; largest residual "), rp_num(&b, l->resid);
  bg_sb_puts(&b, "). Inputs: ");
  for (int k = 0; k < l->nu; k++) bg_sb_puts(&b, k ? ", " : ""), rp_esc(&b, l->uname[k]);
  bg_sb_puts(&b, l->nu ? ". Outputs: " : "none. Outputs: ");
  for (int k = 0; k < l->ny; k++) bg_sb_puts(&b, k ? ", " : ""), rp_esc(&b, l->yname[k]);
  bg_sb_puts(&b, l->outputs_are_states ? " (the states: the model has no output statement). " : ". ");
  if (l->reduced) bg_sb_printf(&b, "State space of order %d (x\u2032 = Ax + Bu, y = Cx + Du).", l->n);
  for (int i = 0; l->reduced && i < l->nelim; i++) /* dependent stores, fixed by constraints */
    bg_sb_puts(&b, i ? ", " : " Dependent stores eliminated: "), rp_esc(&b, l->uname_all[l->elim[i]]);
  if (l->nelim) bg_sb_puts(&b, ".");
  else bg_sb_puts(&b, "Descriptor form only: "), rp_esc(&b, l->reduce_note ? l->reduce_note : "");
  if (l->message) bg_sb_puts(&b, " Note: "), rp_esc(&b, l->message), bg_sb_puts(&b, ".");
  para(c, bg_sb_str(&b));
  bg_sb_free(&b);
}

/* The chapter's estimate nearest a pole on a log scale of magnitude
 * (time constants as 1/tau), -1 when there is none. */
static int nearest_estimate(const bg_analysis *a, double mag, int complex, double *ratio) {
  int best = -1;
  double bestd = 0;
  for (int pass = 0; pass < 2 && best < 0; pass++)
    for (int k = 0; k < a->nestimate; k++) {
      int kind = a->estimate_kind[k]; /* 0 time constant, 1 frequency */
      if (pass == 0 && kind != complex) continue;
      double v = a->estimate_value[k], m = kind == 0 ? 1 / v : v;
      if (!(m > 0) || !(mag > 0)) continue;
      double d = fabs(log(m / mag));
      if (best < 0 || d < bestd) best = k, bestd = d, *ratio = m / mag;
    }
  return best;
}

static void pole_cells(rp_table *t, double re, double im) {
  bg_strbuf b = {0};
  rp_num(&b, re);
  if (im != 0) bg_sb_puts(&b, " \u00b1 "), rp_num(&b, fabs(im)), bg_sb_puts(&b, "<i>i</i>");
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_clear(&b);
  double mag = hypot(re, im);
  if (mag == 0) bg_sb_puts(&b, "integrator");
  else if (im == 0) bg_sb_puts(&b, "\u03c4 = "), rp_num(&b, 1 / fabs(re)), bg_sb_puts(&b, re > 0 ? " s (unstable)" : " s");
  else bg_sb_puts(&b, "\u03c9<sub>n</sub> = "), rp_num(&b, mag), bg_sb_puts(&b, " rad/s, \u03b6 = "), rp_num(&b, -re / mag + 0.0);
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_free(&b);
}

static void estimate_cell(rp_table *t, const bg_analysis *a, double re, double im) {
  double ratio = 1, mag = hypot(re, im);
  int e = nearest_estimate(a, mag, im != 0, &ratio);
  bg_strbuf b = {0};
  if (e < 0) bg_sb_puts(&b, "\u2013");
  else {
    int kind = a->estimate_kind[e];
    bg_sb_printf(&b, "%s = ", kind == 0 ? "\u03c4" : "\u03c9<sub>0</sub>");
    rp_num(&b, a->estimate_value[e]);
    bg_sb_printf(&b, kind == 0 ? " s (path P%d): " : " rad/s (path P%d): ", a->estimate_path[e] + 1);
    double f = ratio >= 1 ? ratio : 1 / ratio;
    if (f < 1.005) bg_sb_puts(&b, "the same to 0.5 %");
    else if (f < 1.1) bg_sb_printf(&b, "within %.0f %%", ceil((f - 1) * 100));
    else bg_sb_puts(&b, ratio > 1 ? "faster by a factor " : "slower by a factor "), rp_num(&b, f);
  }
  rp_table_cell(t, "%s", bg_sb_str(&b));
  bg_sb_free(&b);
}

static void poles_table(rp_ctx *c, const bg_linear *l) {
  if (l->npole == 0) {
    para(c, "No poles: the linearisation has no finite eigenvalues (or more than 500 states).");
    return;
  }
  static const char *head[] = {"#", "Pole", "Time constant or frequency", "Nearest estimate from causal paths"};
  rp_table t;
  rp_table_init(&t, 4, head, "rrll");
  int shown = 0;
  for (int k = 0; k < l->npole && shown < MAX_POLES; k++) {
    if (l->pole_im[k] > 0) continue; /* a pair is one row (its member with im < 0 lists it) */
    rp_table_cell(&t, "%d", ++shown);
    pole_cells(&t, l->pole_re[k], l->pole_im[k]);
    estimate_cell(&t, c->a, l->pole_re[k], l->pole_im[k]);
  }
  rp_table_emit(&c->body, &t);
}

/* "20/(s^2 + 4*s + 20)" as equation markup. */
static void poly_text(bg_strbuf *b, const double *p, int n) {
  int first = 1;
  for (int k = 0; k < n; k++) {
    int pw = n - 1 - k;
    if (p[k] == 0 && n > 1) continue;
    double a = fabs(p[k]);
    bg_sb_puts(b, first ? (p[k] < 0 ? "\u2212" : "") : (p[k] < 0 ? " \u2212 " : " + "));
    first = 0;
    if (a != 1 || pw == 0) rp_num(b, a);
    if (pw >= 1) bg_sb_puts(b, "<i>s</i>");
    if (pw > 1) bg_sb_printf(b, "<sup>%d</sup>", pw);
  }
  if (first) bg_sb_puts(b, "0");
}

static void tf_table(rp_ctx *c, const bg_linear *l) {
  if (l->ntf == 0) {
    bg_strbuf b = {0};
    bg_sb_puts(&b, "No transfer functions");
    if (l->tf_note) bg_sb_puts(&b, ": "), rp_esc(&b, l->tf_note);
    bg_sb_puts(&b, ".");
    para(c, bg_sb_str(&b));
    bg_sb_free(&b);
    return;
  }
  static const char *head[] = {"Output \u2190 input", "Transfer function", "DC gain"};
  rp_table t;
  rp_table_init(&t, 3, head, "llr");
  for (int k = 0; k < l->ntf && k < MAX_TFS; k++) {
    const bg_lin_tf *f = &l->tf[k];
    bg_strbuf b = {0};
    rp_esc(&b, l->yname[f->iy]), bg_sb_puts(&b, " \u2190 "), rp_esc(&b, l->uname[f->iu]);
    rp_table_cell(&t, "%s", bg_sb_str(&b));
    bg_sb_clear(&b);
    bg_sb_puts(&b, "("), poly_text(&b, f->num, f->nnum), bg_sb_puts(&b, ") / (");
    poly_text(&b, f->den, f->nden), bg_sb_puts(&b, ")");
    rp_table_cell(&t, "%s", bg_sb_str(&b));
    bg_sb_clear(&b);
    if (isinf(f->dc_gain)) bg_sb_puts(&b, "\u221e (integrator)");
    else rp_num(&b, f->dc_gain);
    rp_table_cell(&t, "%s", bg_sb_str(&b));
    bg_sb_free(&b);
  }
  rp_table_emit(&c->body, &t);
  if (l->ntf > MAX_TFS) {
    char buf[120];
    snprintf(buf, sizeof buf, "%d more in the JSON (--linear json).", l->ntf - MAX_TFS);
    para(c, buf);
  }
}

/* A plot scene kept in c until the PDF is written, placed at the page width. */
static void place_plot(rp_ctx *c, const bg_linear *l, int kind, const char *title) {
  bg_scene *s = bg_xcalloc(1, sizeof *s);
  bg_scene_init(s, c->st.font);
  if (bg_plot_linear_scene(c->m, l, kind, &c->st, rp_content_w(&c->body), s) != 0) {
    bg_scene_free(s), free(s);
    return;
  }
  s->background.a = 0;
  c->lin_plot[c->nlin_plot++] = s;
  rp_figure(&c->body, s, title);
}

void rp_sec_linear(rp_ctx *c) {
  const bg_linear *l = c->in->lin;
  if (!l) return;
  rp_section(&c->body, "Linear analysis", 1, 0, 80);
  if (!l->ok) {
    bg_strbuf b = {0};
    bg_sb_puts(&b, "Not linearised: "), rp_esc(&b, l->message ? l->message : "unknown reason");
    para(c, bg_sb_str(&b));
    bg_sb_free(&b);
    return;
  }
  point_para(c, l);
  rp_subsection(&c->body, "Poles beside the estimates from causal paths", 30);
  poles_table(c, l);
  rp_subsection(&c->body, "Transfer functions", 30);
  tf_table(c, l);
  if (l->nu * l->ny > 0 && l->nu * l->ny <= 12) {
    place_plot(c, l, BG_PLOT_BODE, "Bode diagram");
    if (l->reduced) place_plot(c, l, BG_PLOT_STEP, "Step and impulse responses");
  }
}
