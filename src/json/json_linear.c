/* SPDX-License-Identifier: BSD-3-Clause */
/* The "linear" key of the analysis JSON (docs/json.md#linear): operating
 * point, descriptor and state-space matrices (rows as lists), poles with
 * natural frequency and damping, transfer functions per input/output pair. */
#include <math.h>
#include <string.h>

#include "json/json_linear.h"
#include "json/json_sim.h"

static void str_or_null(bg_strbuf *o, const char *s) {
  if (s) bg_sb_json_str(o, s);
  else bg_sb_puts(o, "null");
}

static void names(bg_strbuf *o, const char *const *v, int n) {
  bg_sb_putc(o, '[');
  for (int i = 0; i < n; i++) {
    if (i) bg_sb_puts(o, ", ");
    bg_sb_json_str(o, v[i]);
  }
  bg_sb_putc(o, ']');
}

static void nums(bg_strbuf *o, const double *v, int n) {
  bg_sb_putc(o, '[');
  for (int i = 0; i < n; i++) {
    if (i) bg_sb_puts(o, ", ");
    bg_sb_json_num(o, v[i]);
  }
  bg_sb_putc(o, ']');
}

/* A column-major rows x cols matrix as a list of rows, one per line. */
static void matrix(bg_strbuf *o, const char *key, const double *M, int rows, int cols, int last) {
  bg_sb_printf(o, "      \"%s\": [", key);
  for (int i = 0; i < rows; i++) {
    bg_sb_puts(o, i ? ",\n        [" : "\n        [");
    for (int j = 0; j < cols; j++) {
      if (j) bg_sb_puts(o, ", ");
      bg_sb_json_num(o, M[(size_t)j * rows + i]);
    }
    bg_sb_putc(o, ']');
  }
  bg_sb_puts(o, rows ? "\n      ]" : "]");
  bg_sb_puts(o, last ? "\n" : ",\n");
}

/* Roots with wn = |p| and zeta = -Re p / |p|. */
static void roots(bg_strbuf *o, const double *re, const double *im, int n) {
  bg_sb_putc(o, '[');
  for (int i = 0; i < n; i++) {
    double wn = hypot(re[i], im[i]);
    bg_sb_puts(o, i ? ", {\"re\": " : "{\"re\": ");
    bg_sb_json_num(o, re[i]);
    bg_sb_puts(o, ", \"im\": ");
    bg_sb_json_num(o, im[i]);
    bg_sb_puts(o, ", \"wn\": ");
    bg_sb_json_num(o, wn);
    bg_sb_puts(o, ", \"zeta\": ");
    if (wn > 0) bg_sb_json_num(o, -re[i] / wn);
    else bg_sb_puts(o, "null");
    bg_sb_putc(o, '}');
  }
  bg_sb_putc(o, ']');
}

static void point(bg_strbuf *o, const bg_linear *l) {
  bg_sb_printf(o, "    \"operating_point\": {\"kind\": \"%s\", \"t\": ", l->steady ? "steady" : "initial");
  bg_sb_json_num(o, l->t);
  bg_sb_puts(o, ", \"residual\": ");
  bg_sb_json_num(o, l->resid);
  bg_sb_puts(o, ",\n      \"unknowns\": ");
  names(o, l->uname_all, l->N);
  bg_sb_puts(o, ",\n      \"values\": ");
  nums(o, l->y0, l->N);
  bg_sb_puts(o, ",\n      \"outputs\": ");
  nums(o, l->h0, l->ny);
  bg_sb_puts(o, "},\n");
}

static void matrices(bg_strbuf *o, const bg_linear *l) {
  int N = l->N, nu = l->nu, ny = l->ny, n = l->n;
  int show = N <= BG_JSON_LINEAR_MAX_MATRIX;
  bg_sb_printf(o, "    \"matrices_omitted\": %s,\n", show ? "false" : "true");
  if (!show) {
    bg_sb_puts(o, "    \"descriptor\": null,\n    \"state_space\": null,\n");
    return;
  }
  bg_sb_puts(o, "    \"descriptor\": {\n");
  matrix(o, "E", l->E, N, N, 0), matrix(o, "A", l->Ad, N, N, 0), matrix(o, "B", l->Bd, N, nu, 0);
  matrix(o, "C", l->Cd, ny, N, 0), matrix(o, "Cp", l->Cpd, ny, N, 0), matrix(o, "D", l->Dd, ny, nu, 1);
  bg_sb_puts(o, "    },\n    \"state_space\": ");
  if (!l->reduced) {
    bg_sb_puts(o, "null,\n");
    return;
  }
  bg_sb_puts(o, "{\n      \"states\": [");
  for (int i = 0; i < n; i++) {
    if (i) bg_sb_puts(o, ", ");
    bg_sb_json_str(o, l->uname_all[l->state[i]]);
  }
  bg_sb_puts(o, "],\n      \"eliminated\": [");
  for (int i = 0; i < l->nelim; i++) {
    if (i) bg_sb_puts(o, ", ");
    bg_sb_json_str(o, l->uname_all[l->elim[i]]);
  }
  bg_sb_puts(o, "],\n");
  matrix(o, "A", l->A, n, n, 0), matrix(o, "B", l->B, n, nu, 0);
  matrix(o, "C", l->C, ny, n, 0), matrix(o, "D", l->D, ny, nu, 1);
  bg_sb_puts(o, "    },\n");
}

static void tfs(bg_strbuf *o, const bg_linear *l) {
  bg_sb_puts(o, "    \"transfer_functions\": [");
  for (int k = 0; k < l->ntf; k++) {
    const bg_lin_tf *t = &l->tf[k];
    bg_sb_puts(o, k ? ",\n      {\"input\": " : "\n      {\"input\": ");
    bg_sb_json_str(o, l->uname[t->iu]);
    bg_sb_puts(o, ", \"output\": ");
    bg_sb_json_str(o, l->yname[t->iy]);
    bg_sb_puts(o, ",\n       \"num\": ");
    nums(o, t->num, t->nnum);
    bg_sb_puts(o, ", \"den\": ");
    nums(o, t->den, t->nden);
    bg_sb_puts(o, ", \"dc_gain\": ");
    bg_sb_json_num(o, t->dc_gain);
    bg_sb_printf(o, ", \"integrator\": %s, \"cancelled\": %d,\n       \"poles\": ",
                 isinf(t->dc_gain) ? "true" : "false", t->ncancel);
    roots(o, t->pole_re, t->pole_im, t->npole);
    bg_sb_puts(o, ",\n       \"zeros\": ");
    roots(o, t->zero_re, t->zero_im, t->nzero);
    bg_sb_putc(o, '}');
  }
  bg_sb_puts(o, l->ntf ? "\n    ],\n" : "],\n");
}

/* Printed symbolic entries (text) as a list of rows of strings. */
static void str_matrix(bg_strbuf *o, const char *key, char *const *M, int rows, int cols) {
  bg_sb_printf(o, "      \"%s\": [", key);
  for (int i = 0; i < rows; i++) {
    bg_sb_puts(o, i ? ", [" : "[");
    for (int j = 0; j < cols; j++) {
      if (j) bg_sb_puts(o, ", ");
      bg_sb_json_str(o, M[(size_t)j * rows + i]);
    }
    bg_sb_putc(o, ']');
  }
  bg_sb_puts(o, "],\n");
}

static void str_list(bg_strbuf *o, char *const *v, int n) {
  bg_sb_putc(o, '[');
  for (int i = 0; i < n; i++) {
    if (i) bg_sb_puts(o, ", ");
    bg_sb_json_str(o, v[i]);
  }
  bg_sb_putc(o, ']');
}

static void symbolic(bg_strbuf *o, const bg_linear *l) {
  const bg_lin_symbolic *y = &l->sym;
  bg_sb_puts(o, "    \"symbolic_note\": ");
  str_or_null(o, y->ok ? NULL : y->note);
  bg_sb_puts(o, ",\n    \"symbolic\": ");
  if (!y->ok) {
    bg_sb_puts(o, "null,\n");
    return;
  }
  int n = y->n;
  bg_sb_puts(o, "{\n");
  str_matrix(o, "A", y->A[0], n, n), str_matrix(o, "B", y->B[0], n, l->nu);
  str_matrix(o, "C", y->C[0], l->ny, n), str_matrix(o, "D", y->D[0], l->ny, l->nu);
  bg_sb_puts(o, "      \"den\": ");
  str_list(o, y->den[0], n + 1);
  bg_sb_puts(o, ",\n      \"transfer_functions\": [");
  for (int p = 0; p < l->ny * l->nu; p++) {
    bg_sb_puts(o, p ? ",\n        {\"input\": " : "\n        {\"input\": ");
    bg_sb_json_str(o, l->uname[p % l->nu]);
    bg_sb_puts(o, ", \"output\": ");
    bg_sb_json_str(o, l->yname[p / l->nu]);
    bg_sb_puts(o, ", \"num\": ");
    str_list(o, y->num[0] + (size_t)p * (n + 1), n + 1);
    bg_sb_putc(o, '}');
  }
  bg_sb_puts(o, "]\n    },\n");
}

void bg_json_write_linear(const bg_linear *l, bg_strbuf *o) {
  bg_sb_printf(o, "{\n    \"status\": \"%s\",\n    \"message\": ", l->ok ? "ok" : "refused");
  str_or_null(o, l->message);
  bg_sb_puts(o, ",\n");
  if (l->ok) {
    point(o, l);
    bg_sb_puts(o, "    \"inputs\": ");
    names(o, l->uname, l->nu);
    bg_sb_puts(o, ",\n    \"outputs\": ");
    names(o, l->yname, l->ny);
    bg_sb_printf(o, ",\n    \"outputs_are_states\": %s,\n", l->outputs_are_states ? "true" : "false");
    matrices(o, l);
    bg_sb_puts(o, "    \"reduce_note\": ");
    str_or_null(o, l->reduce_note);
    bg_sb_puts(o, ",\n    \"poles\": ");
    roots(o, l->pole_re, l->pole_im, l->npole);
    bg_sb_puts(o, ",\n");
    tfs(o, l);
    symbolic(o, l);
    bg_sb_puts(o, "    \"tf_note\": ");
    str_or_null(o, l->tf_note);
    bg_sb_putc(o, '\n');
  }
  bg_sb_puts(o, "  }");
}

void bg_json_append_linear(bg_strbuf *doc, const bg_linear *l) {
  if (bg_json_reopen(doc)) return;
  bg_sb_puts(doc, "  \"linear\": ");
  bg_json_write_linear(l, doc);
  bg_sb_puts(doc, "\n}\n");
}
