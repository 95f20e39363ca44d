/* SPDX-License-Identifier: BSD-3-Clause */
/* Simulation plots: one panel per `plot` statement of the model (or one
 * panel of the states when there is none), stacked over a shared time axis,
 * drawn into a bg_scene so the same surfaces (SVG, PDF, PNG) replay them and
 * the report can place them on a page. Conventions: docs/plots.md. */
#ifndef BG_PLOT_H
#define BG_PLOT_H
#include "base/diag.h"
#include "model/model.h"
#include "scene/scene.h"
#include "simulate/simulate.h"
#include "study/study.h"
#include "scene/style.h"

/* Draws every panel of r into out (initialised by the caller with
 * bg_scene_init), within a box of width x height points at the origin.
 * height <= 0 chooses a height from the number of panels. A partial result
 * is marked where it stops. */
void bg_plot_scene(const bg_model *m, const bg_simresult *r, const bg_style *st, double width,
                   double height, bg_scene *out);

/* The same look for data over another axis (the linear analysis'
 * frequency and time responses, render/plot/plot_linear.c): r holds the
 * rows (t = the abscissa), m the panels (plot_expradr, plot_nexpr, titles,
 * ylabels; sim.present = 0). */
typedef struct bg_plot_spec {
  int xlog;          /* log10 abscissa with decade ticks and a minor grid */
  const char *xname; /* the axis name ("ω"); NULL: the panels' xlabel or "t" */
  const char *xunit; /* written as " [unit]"; NULL: seconds with the axis' SI prefix; "":
                        no unit (the prefix alone, when there is one) */
  int angle_panel;   /* 1-based panel whose values are degrees (ticks at multiples of
                        45, or 90 on large ranges); 0: none */
  unsigned angle_mask; /* more such panels: bit k for panel k + 1 (the Bode family) */
  int legend_once;     /* the same curves in every panel: the legend on the first only */
} bg_plot_spec;
void bg_plot_scene_spec(const bg_model *m, const bg_simresult *r, const bg_plot_spec *spec,
                        const bg_style *st, double width, double height, bg_scene *out);
/* Curve j's colour and dash pattern (docs/plots.md, Line styles). */
void bg_plot_curve_style(const bg_style *st, int j, bg_scene_item *it);

/* A parameter study's plots (render/plot/plot_study.c, plot_locus.c,
 * docs/study.md): the quantities against the swept param, the family of
 * curves, the root locus (each run's poles in the complex plane coloured by
 * the first param, arrows along the branches as it grows) and the Bode
 * family (bode: computed by bg_study_bode_compute). */
enum { BG_STUDY_PLOT_QUANTITIES = 0, BG_STUDY_PLOT_FAMILY, BG_STUDY_PLOT_LOCUS, BG_STUDY_PLOT_BODE };
/* Plot kind into out (initialised by the caller), width points wide; 0, or
 * -1 with the reason in why (no run succeeded; quantities of a Monte Carlo
 * study; no poles). */
int bg_study_plot_scene(const bg_study *st, int kind, const bg_study_bode *bode, const bg_style *sty,
                        double width, bg_scene *out, char *why, size_t nwhy);
/* The root locus alone (plot_locus.c). */
int bg_study_locus_scene(const bg_study *st, const bg_style *sty, double width, bg_scene *out,
                         char *why, size_t nwhy);
/* The same in format fmt into out; BG_RENDER_OK or BG_RENDER_ERROR with the
 * reason in dg. */
int bg_study_plot_render(const bg_study *st, int kind, const bg_study_bode *bode, const char *style,
                         const char *style_dir, const char *fmt, const char *path, bg_strbuf *out,
                         bg_diags *dg);

/* --plot FILE: writes the plots to path (svg, pdf or png by its extension)
 * atomically. style and style_dir as in bg_render_opts. Returns
 * BG_RENDER_OK, BG_RENDER_ERROR or BG_RENDER_EWRITE (see render.h), with
 * errors reported to dg. */
int bg_plot_write(const bg_model *m, const bg_simresult *r, const char *style,
                  const char *style_dir, const char *path, bg_diags *dg);
/* The same plot in format fmt ("svg", "pdf", "png") into out; path (nullable)
 * only names it in messages. */
int bg_plot_render(const bg_model *m, const bg_simresult *r, const char *style,
                   const char *style_dir, const char *fmt, const char *path, bg_strbuf *out,
                   bg_diags *dg);
/* A scene in format fmt into out; BG_RENDER_OK or BG_RENDER_ERROR. */
int bg_plot_render_scene(const bg_scene *sc, const char *fmt, double png_scale, bg_strbuf *out,
                         bg_diags *dg);
#endif
