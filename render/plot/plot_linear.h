/* SPDX-License-Identifier: BSD-3-Clause */
/* Plots of the linear analysis (docs/linear.md#plots): Bode, Nyquist, step
 * and impulse responses, in the simulation plots' look (docs/plots.md). */
#ifndef BG_PLOT_LINEAR_H
#define BG_PLOT_LINEAR_H
#include "base/diag.h"
#include "linear/linear.h"
#include "model/model.h"
#include "scene/scene.h"
#include "scene/style.h"
#include "simulate/simulate.h"

enum { BG_PLOT_BODE, BG_PLOT_NYQUIST, BG_PLOT_STEP };

/* The rows a Bode or step plot draws: the abscissa (frequencies, times) in
 * r.t, one column per curve, m's plot statements the panels (the HTML
 * report's readout reads them). */
typedef struct bg_plot_table {
  bg_simresult r;
  bg_model m;
  int *expradr, *nexpr;                 /* panel k: curves expradr[k] .. + nexpr[k] */
  const char **title, **ylabel, **xlabel; /* per panel; ylabel "" */
  char **names, **own_title;            /* curve names; titles made for the table */
} bg_plot_table;
/* A table of npanel panels of ncurve curves each and nrow rows, as the plot
 * code reads a model and its run (the linear plots, the studies' plots). */
void bg_plot_table_init(bg_plot_table *T, const char *name, const char *title, int nrow, int ncurve,
                        int npanel);
/* 0 with T filled (free it with bg_plot_table_free), or -1: nothing drawn
 * (not linearised, no pair, Nyquist, no step response). */
int bg_plot_linear_table(const bg_model *m, const bg_linear *l, int kind, bg_plot_table *T);
void bg_plot_table_free(bg_plot_table *T);

/* Draws plot `kind` of every input/output pair into out, width points wide
 * (height chosen). 0, or -1 when there is nothing to draw (not linearised,
 * no pair, step responses of a descriptor-only system or above 400 states). */
int bg_plot_linear_scene(const bg_model *m, const bg_linear *l, int kind, const bg_style *st,
                         double width, bg_scene *out);
/* Into out in format fmt (svg, pdf, png); path (nullable) names it in
 * messages. BG_RENDER_OK / _ERROR. */
int bg_plot_linear_render(const bg_model *m, const bg_linear *l, int kind, const char *style,
                          const char *style_dir, const char *fmt, const char *path,
                          bg_strbuf *out, bg_diags *dg);
#endif
