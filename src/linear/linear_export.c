/* SPDX-License-Identifier: BSD-3-Clause */
/* The state space for a control engineer's next tool: an Octave/MATLAB
 * script (matrices, names, operating point; `ss` when the control package
 * is there) and a Python module (numpy arrays with names; `ss()` builds a
 * python-control system). Numbers round-trip (bg_sb_num, the shortest form). */
#include <stdio.h>
#include <string.h>

#include "linear/linear.h"

static void num(bg_strbuf *o, double v) {
  bg_sb_num(o, v == 0 ? 0.0 : v); /* no "-0" */
}

static void header(const bg_linear *l, const bg_model *m, const char *c, bg_strbuf *o) {
  bg_sb_printf(o, "%s bgdraw: linear state space of %s%s%s%s at the %s, t = ", c, m->name,
               m->title ? " (" : "", m->title ? m->title : "", m->title ? ")" : "",
               l->steady ? "steady state" : "initial point");
  num(o, l->t);
  bg_sb_printf(o, "\n%s x' = A x + B u, y = C x + D u; x, u, y are deviations from the operating "
               "point x0, u = 0, y0\n", c);
  if (l->message) bg_sb_printf(o, "%s note: %s\n", c, l->message);
}

/* ---------------------------------------------------------------- Octave */
static void m_matrix(bg_strbuf *o, const char *name, const double *M, int r, int c) {
  if (r == 0 || c == 0) {
    bg_sb_printf(o, "%s = zeros(%d, %d);\n", name, r, c);
    return;
  }
  bg_sb_printf(o, "%s = [", name);
  for (int i = 0; i < r; i++) {
    bg_sb_puts(o, i ? ";\n     " : "");
    for (int j = 0; j < c; j++) {
      if (j) bg_sb_putc(o, ' ');
      num(o, M[(size_t)j * r + i]);
    }
  }
  bg_sb_puts(o, "];\n");
}

static void m_names(bg_strbuf *o, const char *var, const char *const *names, const int *idx, int n) {
  bg_sb_printf(o, "%s = {", var);
  for (int i = 0; i < n; i++) {
    const char *s = names[idx ? idx[i] : i];
    bg_sb_puts(o, i ? ", '" : "'");
    for (; *s; s++) bg_sb_puts(o, *s == '\'' ? "''" : (char[]){*s, 0});
    bg_sb_putc(o, '\'');
  }
  bg_sb_puts(o, "};\n");
}

static void m_vector(bg_strbuf *o, const char *name, const double *v, const int *idx, int n) {
  bg_sb_printf(o, "%s = [", name);
  for (int i = 0; i < n; i++) {
    if (i) bg_sb_puts(o, "; ");
    num(o, v[idx ? idx[i] : i]);
  }
  bg_sb_puts(o, "];\n");
}

void bg_linear_export_m(const bg_linear *l, const bg_model *m, bg_strbuf *o) {
  header(l, m, "%", o);
  if (!l->reduced) { /* the CLI refuses this; a library caller gets a comment, not NULL matrices */
    bg_sb_printf(o, "%% no state space: %s\n", l->reduce_note ? l->reduce_note : "not reduced");
    return;
  }
  m_matrix(o, "A", l->A, l->n, l->n);
  m_matrix(o, "B", l->B, l->n, l->nu);
  m_matrix(o, "C", l->C, l->ny, l->n);
  m_matrix(o, "D", l->D, l->ny, l->nu);
  m_names(o, "state_names", l->uname_all, l->state, l->n);
  m_names(o, "input_names", l->uname, NULL, l->nu);
  m_names(o, "output_names", l->yname, NULL, l->ny);
  m_vector(o, "x0", l->y0, l->state, l->n);
  m_vector(o, "y0", l->h0, NULL, l->ny);
  bg_sb_puts(o, "if exist('ss') % the control package (Octave: pkg load control)\n"
                "  sys = ss(A, B, C, D, 'StateName', state_names, 'InputName', input_names, "
                "'OutputName', output_names);\nend\n");
}

/* ---------------------------------------------------------------- Python */
static void py_str(bg_strbuf *o, const char *s) {
  bg_sb_putc(o, '"');
  for (; *s; s++) {
    if (*s == '"' || *s == '\\') bg_sb_putc(o, '\\');
    bg_sb_putc(o, *s);
  }
  bg_sb_putc(o, '"');
}

static void py_matrix(bg_strbuf *o, const char *name, const double *M, int r, int c) {
  if (r == 0 || c == 0) {
    bg_sb_printf(o, "%s = np.zeros((%d, %d))\n", name, r, c);
    return;
  }
  bg_sb_printf(o, "%s = np.array([", name);
  for (int i = 0; i < r; i++) {
    bg_sb_puts(o, i ? ",\n              [" : "[");
    for (int j = 0; j < c; j++) {
      if (j) bg_sb_puts(o, ", ");
      num(o, M[(size_t)j * r + i]);
    }
    bg_sb_putc(o, ']');
  }
  bg_sb_puts(o, "], dtype=float)\n");
}

static void py_list(bg_strbuf *o, const char *var, const char *const *names, const double *v,
                    const int *idx, int n) {
  bg_sb_printf(o, "%s = %s[", var, v ? "np.array(" : "");
  for (int i = 0; i < n; i++) {
    if (i) bg_sb_puts(o, ", ");
    if (v) num(o, v[idx ? idx[i] : i]);
    else py_str(o, names[idx ? idx[i] : i]);
  }
  bg_sb_puts(o, v ? "], dtype=float)\n" : "]\n");
}

void bg_linear_export_py(const bg_linear *l, const bg_model *m, bg_strbuf *o) {
  bg_sb_puts(o, "\"\"\"\n");
  header(l, m, "", o);
  if (!l->reduced) { /* as bg_linear_export_m */
    bg_sb_printf(o, " no state space: %s\n\"\"\"\n", l->reduce_note ? l->reduce_note : "not reduced");
    return;
  }
  bg_sb_puts(o, "\"\"\"\nimport numpy as np\n\n");
  py_list(o, "states", l->uname_all, NULL, l->state, l->n);
  py_list(o, "inputs", l->uname, NULL, NULL, l->nu);
  py_list(o, "outputs", l->yname, NULL, NULL, l->ny);
  py_matrix(o, "A", l->A, l->n, l->n);
  py_matrix(o, "B", l->B, l->n, l->nu);
  py_matrix(o, "C", l->C, l->ny, l->n);
  py_matrix(o, "D", l->D, l->ny, l->nu);
  py_list(o, "x0", NULL, l->y0, l->state, l->n);
  py_list(o, "y0", NULL, l->h0, NULL, l->ny);
  bg_sb_puts(o, "\n\ndef ss():\n    \"\"\"The state space as a python-control system (needs the "
                "control package).\"\"\"\n    import control\n    return control.ss(A, B, C, D, "
                "states=states, inputs=inputs, outputs=outputs)\n");
}
