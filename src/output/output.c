/* SPDX-License-Identifier: BSD-3-Clause */
/* The output table (output.h) and the writers of the analysis, the
 * diagram, the equations, the simulation and the report. Exports are in
 * output_export.c (the FMU in output_fmu.c), the linear analysis' outputs
 * in output_linear.c. */
#include "output/output.h"

#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "analysis/analysis.h"
#include "base/fileio.h"
#include "json/json.h"
#include "output/output_int.h"
#include "plot/plot.h"
#include "report/report.h"
#include "html/html.h"

void bg_output_init(bg_output *w, bg_run *run, const bg_output_opts *o) {
  memset(w, 0, sizeof *w);
  w->run = run;
  if (o) w->o = *o;
  bg_diags_init(&w->dg, "bgdraw", NULL, 0);
  bg_diags_init(&w->dg_model, run->name ? run->name : "bgdraw", run->src, run->srclen);
}

void bg_output_free(bg_output *w) {
  if (w->diagram) bg_diagram_free(w->diagram);
  w->diagram = NULL;
  bg_diags_free(&w->dg);
  bg_diags_free(&w->dg_model);
  free(w->refusal);
  w->refusal = NULL;
}

void bg_output_clear_messages(bg_output *w) {
  bg_diags_free(&w->dg);
  bg_diags_free(&w->dg_model);
  bg_diags_init(&w->dg, "bgdraw", NULL, 0);
  bg_diags_init(&w->dg_model, w->run->name ? w->run->name : "bgdraw", w->run->src, w->run->srclen);
  free(w->refusal);
  w->refusal = NULL;
}

/* BG_RENDER_* as a status. */
static bg_output_status render_status(int rc) {
  return rc == BG_RENDER_OK ? BG_OUT_OK : rc == BG_RENDER_EWRITE ? BG_OUT_WRITE : BG_OUT_USAGE;
}

/* ------------------------------------------------------------ the analysis */
static bg_output_status write_json(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out) {
  (void)k, (void)form, (void)path;
  bg_json_write_run(w->run, out);
  return BG_OUT_OK;
}

/* --check: the model and analysis summary, the numeric index, the index reduction. */
static bg_output_status write_check(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *sb) {
  (void)k, (void)form, (void)path;
  const bg_run *r = w->run;
  bg_model_summary(r->model, sb);
  bg_sb_putc(sb, '\n');
  bg_analysis_summary(r->model, &r->analysis, sb);
  if (r->facts.reduced_note) bg_sb_printf(sb, "reduced form: %s\n", r->facts.reduced_note);
  if (r->index_computed) {
    bg_sb_puts(sb, "numeric index: ");
    if (r->index.index >= 0) bg_sb_printf(sb, "%d", r->index.index);
    else bg_sb_puts(sb, r->index.index == BG_INDEX_SINGULAR ? "singular" : "not computed");
    if (r->index.message) bg_sb_printf(sb, " (%s)", r->index.message);
    bg_sb_putc(sb, '\n');
  } else if (r->eqsys_problem) {
    bg_sb_printf(sb, "equations: %s\n", r->eqsys_problem);
  }
  if (r->ired_tried) {
    bg_sb_puts(sb, "index reduction:\n");
    bg_indexred_text(&r->ired, "  ", sb);
  }
  return BG_OUT_OK;
}

/* ------------------------------------------------------------- the diagram */
static bg_output_status write_diagram(bg_output *w, const bg_output_kind *k, const char *form,
                                      const char *path, bg_strbuf *out) {
  (void)k, (void)path;
  if (!w->diagram) {
    w->diagram = bg_diagram_build(w->run->model, &w->run->analysis, &w->o.render, &w->dg_model);
    if (!w->diagram) return BG_OUT_USAGE;
  }
  return render_status(bg_diagram_render(w->diagram, form, out, &w->dg_model));
}

/* ----------------------------------------------------------- the equations */
static bg_output_status write_equations(bg_output *w, const bg_output_kind *k, const char *form,
                                        const char *path, bg_strbuf *out) {
  (void)k;
  if (!w->run->eqsys) return bg_out_no_equations(w, path);
  if (!strcmp(form, "c")) return bg_out_export(w, "c", NULL, out); /* header and source */
  bg_eqprint(w->run->eqsys, form, out);
  return BG_OUT_OK;
}

static bg_output_status write_tex(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out) {
  (void)k, (void)form;
  return write_equations(w, k, "latex", path, out);
}

/* ---------------------------------------------------------- the simulation */
static bg_output_status write_csv(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out) {
  (void)k, (void)form, (void)path;
  if (!w->run->sim.nrows) return w->nothing = 1, BG_OUT_OK; /* refused: the run said why */
  bg_csv_write(&w->run->sim, out);
  return BG_OUT_OK;
}

/* The simulation plots, also of a partial run; none when it was refused. */
static bg_output_status write_plot(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out) {
  (void)k;
  if (!w->run->sim.nrows) return w->nothing = 1, BG_OUT_OK;
  const bg_render_opts *ro = &w->o.render;
  return render_status(bg_plot_render(w->run->model, &w->run->sim, ro->style, ro->style_dir,
                                             form, path, out, &w->dg));
}

/* ------------------------------------------------------ report, transform */
static bg_output_status write_report(bg_output *w, const bg_output_kind *k, const char *form,
                                     const char *path, bg_strbuf *out) {
  (void)k;
  bg_report_opts ro = {&w->o.render, w->o.tx ? w->o.transform : NULL, w->o.tx, NULL, NULL};
  /* the file's extension (or form "html") chooses: the HTML report, else the PDF */
  const char *ext = path ? bg_path_ext(path) : "";
  if (form ? !strcmp(form, "html") : !strcasecmp(ext, "html") || !strcasecmp(ext, "htm"))
    return render_status(bg_html_report_render(w->run, &ro, out, &w->dg));
  return render_status(bg_report_render(w->run, &ro, out, &w->dg));
}

static bg_output_status write_transformed(bg_output *w, const bg_output_kind *k, const char *form,
                                          const char *path, bg_strbuf *out) {
  (void)k, (void)form;
  if (!w->o.tx && w->run->imported && w->run->import.text) { /* another tool's model as .bg */
    bg_sb_puts(out, w->run->import.text);
    return BG_OUT_OK;
  }
  if (!w->o.tx) return bg_out_error(w, BG_OUT_USAGE, "%s%s: a .bg output is the model --transform "
                                    "writes, or another tool's model read as .bg; neither is here", "",
                                    path ? path : "");
  bg_sb_puts(out, w->o.tx->text);
  return BG_OUT_OK;
}

/* The model as BondGraphTools YAML (docs/import.md), or why it cannot be. */
static bg_output_status write_bgt_yaml(bg_output *w, const bg_output_kind *k, const char *form,
                                       const char *path, bg_strbuf *out) {
  (void)k, (void)form, (void)path;
  char *why = bg_bgt_write(w->run->model, out);
  if (!why) return BG_OUT_OK;
  bg_output_status st = bg_out_refuse(w, "cannot write BondGraphTools YAML: ", why);
  free(why);
  return st;
}

/* ------------------------------------------------------------------ table */
const bg_output_kind bg_output_kinds[] = {
    /* chosen by -o FILE.EXT, in --help's order */
    {"svg", BG_STAGE_ANALYSIS, BG_OUTK_EXT | BG_OUTK_DRAWS | BG_OUTK_APPENDS, write_diagram, "annotated diagram, SVG"},
    {"pdf", BG_STAGE_ANALYSIS, BG_OUTK_EXT | BG_OUTK_DRAWS | BG_OUTK_APPENDS, write_diagram, "annotated diagram, PDF"},
    {"png", BG_STAGE_ANALYSIS, BG_OUTK_EXT | BG_OUTK_DRAWS | BG_OUTK_APPENDS, write_diagram, "annotated diagram, PNG"},
    {"json", BG_STAGE_REDUCTION, BG_OUTK_EXT | BG_OUTK_MODEL_LIN, write_json,
     "the analysis (docs/json.md)"},
    {"dot", BG_STAGE_ANALYSIS, BG_OUTK_EXT | BG_OUTK_DRAWS | BG_OUTK_APPENDS, write_diagram, "graph with positions (Graphviz)"},
    {"tex", BG_STAGE_EQUATIONS, BG_OUTK_EXT, write_tex, "equations in LaTeX"},
    {"c", BG_STAGE_EQUATIONS, BG_OUTK_EXT, bg_out_export_row, "equations as C, NAME.h beside it"},
    {"csv", BG_STAGE_SIMULATION, BG_OUTK_EXT, write_csv, "simulation results"},
    {"m", BG_STAGE_EQUATIONS, BG_OUTK_EXT, bg_out_export_row, "the model for Octave/MATLAB (export.md)"},
    {"py", BG_STAGE_EQUATIONS, BG_OUTK_EXT, bg_out_export_row, "the model for Python/SciPy"},
    {"mo", BG_STAGE_EQUATIONS, BG_OUTK_EXT, bg_out_export_row, "the model for Modelica"},
    {"fmu", BG_STAGE_EQUATIONS, BG_OUTK_EXT, bg_out_fmu,
     "FMI 2.0 Model Exchange FMU (ODE models; needs a C compiler)"},
    {"bg", BG_STAGE_ANALYSIS, BG_OUTK_EXT, write_transformed, "the model rewritten by --transform, or imported (--import)"},
    {"yaml", BG_STAGE_MODEL, BG_OUTK_EXT, write_bgt_yaml, "the model as BondGraphTools YAML (import.md)"},
    /* chosen by options of their own */
    {"h", BG_STAGE_EQUATIONS, 0, bg_out_export_row, "the C export's header"},
    {"check", BG_STAGE_REDUCTION, 0, write_check, "the --check summary"},
    {"equations", BG_STAGE_EQUATIONS, 0, write_equations, "the equations: text, latex, mathml, json or c"},
    {"plot", BG_STAGE_SIMULATION, BG_OUTK_DRAWS, write_plot, "the simulation plots: svg, pdf or png"},
    {"report", BG_STAGE_REDUCTION,
     BG_OUTK_DRAWS | BG_OUTK_MODEL_SIM | BG_OUTK_MODEL_LIN | BG_OUTK_APPENDS, write_report,
     "the report: multi-page PDF, or one HTML page (FILE.html or form html)"},
    {"linear", BG_STAGE_LINEAR, 0, bg_out_linear, "the linear analysis: text, latex, json, octave or python"},
    {"bode", BG_STAGE_LINEAR, BG_OUTK_DRAWS, bg_out_linear_plot, "Bode diagrams: svg, pdf or png"},
    {"nyquist", BG_STAGE_LINEAR, BG_OUTK_DRAWS, bg_out_linear_plot, "Nyquist diagrams: svg, pdf or png"},
    {"step", BG_STAGE_LINEAR, BG_OUTK_DRAWS, bg_out_linear_plot, "step and impulse responses: svg, pdf or png"},
    {NULL, 0, 0, NULL, NULL},
};

const bg_output_kind *bg_output_find(const char *name) {
  for (const bg_output_kind *k = bg_output_kinds; name && k->name; k++)
    if (!strcmp(k->name, name)) return k;
  return NULL;
}

const bg_output_kind *bg_output_for_ext(const char *ext) {
  for (const bg_output_kind *k = bg_output_kinds; ext && k->name; k++)
    if ((k->flags & BG_OUTK_EXT) && !strcasecmp(ext, k->name)) return k;
  return NULL;
}

void bg_output_need(bg_output *w, const bg_output_kind *k) {
  bg_run *r = w->run;
  const bg_model *m = r->model;
  if (!m) return;
  int lin = k->need == BG_STAGE_LINEAR || ((k->flags & BG_OUTK_MODEL_LIN) && m->linear.present);
  int sim = k->need == BG_STAGE_SIMULATION || ((k->flags & BG_OUTK_MODEL_SIM) && m->sim.present);
  bg_run_need(r, k->need == BG_STAGE_LINEAR || k->need == BG_STAGE_SIMULATION ? BG_STAGE_ANALYSIS
                                                                             : k->need);
  if (sim) bg_run_need(r, BG_STAGE_REDUCTION); /* its index decides whether it may run */
  if (lin) bg_run_need(r, BG_STAGE_LINEAR);
  if (sim) bg_run_need(r, BG_STAGE_SIMULATION);
}

bg_output_status bg_output_write(bg_output *w, const char *kind, const char *form, const char *path,
                                 bg_strbuf *out) {
  const bg_output_kind *k = bg_output_find(kind);
  if (!k || !k->write)
    return bg_out_error(w, BG_OUT_USAGE, "no output '%s'%s", kind ? kind : "(none)",
                        k ? " into a buffer (it is written by the command line)" : "");
  if (!w->run->model) return bg_out_error(w, BG_OUT_MODEL, "%s%s: the model did not load", "", kind);
  bg_output_need(w, k);
  w->nothing = 0;
  if (!form && k->write == write_diagram) form = kind;
  else if (!form && (k->flags & BG_OUTK_DRAWS) && strcmp(kind, "report"))
    form = path ? bg_path_ext(path) : "svg"; /* the plots: their file's format */
  return k->write(w, k, form, path, out);
}
