/* SPDX-License-Identifier: BSD-3-Clause */
/* The linear analysis' outputs (docs/linear.md): --linear FORM (text,
 * latex, json; the state space as an Octave script or a Python module) and
 * the Bode, Nyquist and step plots. A refused analysis is BG_OUT_REFUSED
 * with its reason. */
#include <string.h>

#include "json/json.h"
#include "output/output_int.h"
#include "plot/plot_linear.h"

static bg_output_status refused(bg_output *w) {
  const bg_linear *l = &w->run->lin;
  if (l->ok) return BG_OUT_OK;
  return bg_out_refuse(w, "linear analysis refused: ", l->message ? l->message : "unknown reason");
}

bg_output_status bg_out_linear(bg_output *w, const bg_output_kind *k, const char *form,
                               const char *path, bg_strbuf *out) {
  (void)k, (void)path;
  const bg_linear *l = &w->run->lin;
  const bg_model *m = w->run->model;
  if (!form) form = "text";
  if (!strcmp(form, "octave") || !strcmp(form, "python")) {
    bg_output_status st = refused(w);
    if (st) return st;
    if (!l->reduced)
      return bg_out_error(w, BG_OUT_REFUSED, "no state space to export: %s%s",
                          l->reduce_note ? l->reduce_note : "not reduced", "");
    if (!strcmp(form, "octave")) bg_linear_export_m(l, m, out);
    else bg_linear_export_py(l, m, out);
    return BG_OUT_OK;
  }
  if (!strcmp(form, "json")) bg_json_write_linear(l, out), bg_sb_putc(out, '\n');
  else bg_linear_print(l, m, form, out);
  return BG_OUT_OK; /* the text says when it was refused */
}

bg_output_status bg_out_linear_plot(bg_output *w, const bg_output_kind *k, const char *form,
                                    const char *path, bg_strbuf *out) {
  bg_output_status st = refused(w);
  if (st) return st;
  int kind = !strcmp(k->name, "bode") ? BG_PLOT_BODE : !strcmp(k->name, "nyquist") ? BG_PLOT_NYQUIST
                                                                                   : BG_PLOT_STEP;
  const bg_render_opts *ro = &w->o.render;
  int rc = bg_plot_linear_render(w->run->model, &w->run->lin, kind, ro->style, ro->style_dir, form,
                                 path, out, &w->dg);
  return rc == 0 ? BG_OUT_OK : BG_OUT_REFUSED; /* no response to plot */
}
