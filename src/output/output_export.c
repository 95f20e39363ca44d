/* SPDX-License-Identifier: BSD-3-Clause */
/* Export outputs (docs/export.md): the equation system built again in
 * export form (params stay variables, bg_eqsys_build_export), once per
 * output, and written by src/export: C (header and source), Python,
 * Octave/MATLAB, Modelica. The FMU (output_fmu.c) is compiled from the
 * same export build. */
#include <stdio.h>
#include <string.h>

#include "export/export.h"
#include "output/output_int.h"

static void prefix_of(const bg_output *w, char *buf, size_t n) {
  if (w->o.prefix) snprintf(buf, n, "%s", w->o.prefix);
  else bg_export_default_prefix(w->run->model, buf, n);
}

/* Base name without folder and extension ("out/rlc_model.m" -> "rlc_model"). */
static void base_name(const char *path, char *buf, size_t n) {
  const char *b = strrchr(path, '/');
  b = b ? b + 1 : path;
  snprintf(buf, n, "%s", b);
  char *dot = strrchr(buf, '.');
  if (dot) *dot = 0;
}

bg_output_status bg_out_export_system(bg_output *w, const char *format, const char *path, bg_eqsys **s,
                                      char *prefix, size_t n) {
  *s = NULL;
  if (w->o.prefix && !bg_export_prefix_ok(w->o.prefix))
    return bg_out_error(w, BG_OUT_USAGE, "--prefix '%s' is not a C identifier (letters, digits, '_')%s",
                        w->o.prefix, "");
  bg_run *r = w->run;
  if (!r->eqsys) return bg_out_no_equations(w, path);
  bg_diags dg;
  bg_diags_init(&dg, r->name, r->src, r->srclen);
  *s = bg_eqsys_build_export(r->model, &r->analysis, &dg);
  bg_diags_free(&dg);
  if (!*s) return bg_out_error(w, BG_OUT_MODEL, "no equations for '%s'%s", path ? path : "stdout", "");
  bg_strbuf why = {0};
  if (bg_export_refusal(*s, format, &why)) { /* memory in an export without modes */
    char what[300];
    snprintf(what, sizeof what, "export refused: '%s': ", path ? path : "stdout");
    bg_output_status st = bg_out_refuse(w, what, bg_sb_str(&why));
    bg_sb_free(&why), bg_eqsys_free(*s);
    *s = NULL;
    return st;
  }
  if (!strcmp(format, "m") && bg_eqsys_nmodes(*s)) /* ode15s without 'Events' steps over them */
    bg_diag_warning(&w->dg, (bg_srcloc){0}, "'%s': the Octave/MATLAB export has no event handling: "
                    "ode15s steps over the model's %d switching conditions, so results near a switch are "
                    "only as good as its step control; export to C, Python or an FMU for located events "
                    "(docs/export.md)", path ? path : "stdout", bg_eqsys_nmodes(*s));
  prefix_of(w, prefix, n);
  return BG_OUT_OK;
}

bg_output_status bg_out_export(bg_output *w, const char *format, const char *path, bg_strbuf *out) {
  bg_eqsys *s;
  char prefix[80], name[300];
  bg_output_status st = bg_out_export_system(w, !strcmp(format, "h") ? "c" : format, path, &s, prefix, sizeof prefix);
  if (st != BG_OUT_OK) return st;
  if (!strcmp(format, "c") || !strcmp(format, "h")) {
    bg_strbuf h = {0}, c = {0};
    if (path) { /* NAME.c includes NAME.h */
      base_name(path, name, sizeof name);
      strncat(name, ".h", sizeof name - strlen(name) - 1);
    }
    bg_export_c(s, prefix, path ? name : NULL, &h, &c);
    if (!path && !strcmp(format, "c")) { /* header and source as one unit */
      bg_sb_putn(out, h.s ? h.s : "", h.len);
      bg_sb_puts(out, "\n");
      bg_sb_putn(out, c.s ? c.s : "", c.len);
    } else {
      const bg_strbuf *part = !strcmp(format, "h") ? &h : &c;
      bg_sb_putn(out, part->s ? part->s : "", part->len);
    }
    bg_sb_free(&h), bg_sb_free(&c);
  } else if (!strcmp(format, "py")) {
    bg_export_python(s, out);
  } else if (!strcmp(format, "mo")) {
    bg_export_modelica(s, out);
  } else { /* m: the function is named after its file, else by the prefix */
    if (path) base_name(path, name, sizeof name);
    else snprintf(name, sizeof name, "%s", prefix);
    bg_export_octave(s, name, out);
  }
  bg_eqsys_free(s);
  return BG_OUT_OK;
}

bg_output_status bg_out_export_row(bg_output *w, const bg_output_kind *k, const char *form,
                                   const char *path, bg_strbuf *out) {
  (void)form;
  return bg_out_export(w, k->name, path, out);
}
