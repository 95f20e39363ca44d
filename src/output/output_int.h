/* SPDX-License-Identifier: BSD-3-Clause */
/* Shared by the output stage's files (output.h is the front door). */
#ifndef BG_OUTPUT_INT_H
#define BG_OUTPUT_INT_H
#include "output/output.h"

/* An error "bgdraw: error: ..." in w->dg (fmt takes two strings); returns st. */
bg_output_status bg_out_error(bg_output *w, bg_output_status st, const char *fmt, const char *a,
                              const char *b);
/* BG_OUT_REFUSED with w->refusal = what followed by why. */
bg_output_status bg_out_refuse(bg_output *w, const char *what, const char *why);
/* "no equations for 'path': why". */
bg_output_status bg_out_no_equations(bg_output *w, const char *path);
/* output_export.c: one export text (c, h, py, m, mo; "c" without a path: the
 * header and the source as one unit, as --equations c prints them). */
bg_output_status bg_out_export(bg_output *w, const char *format, const char *path, bg_strbuf *out);
/* The export build of the run's model (params stay variables) into *s
 * for format (c, py, m, mo, fmu: what it refuses)
 * (the caller frees it) and the exported symbols' prefix; BG_OUT_OK, or
 * the status after an error in w->dg (a bad --prefix, no equations). */
bg_output_status bg_out_export_system(bg_output *w, const char *format, const char *path,
                                      struct bg_eqsys **s, char *prefix, size_t n);
/* The table's writer of the export rows (the row's name is the format). */
bg_output_status bg_out_export_row(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out);
/* output_fmu.c: the FMI 2.0 Model Exchange archive, compiled by $CC. */
bg_output_status bg_out_fmu(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out);
/* output_linear.c: --linear FORM, and the Bode, Nyquist and step plots. */
bg_output_status bg_out_linear(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out);
bg_output_status bg_out_linear_plot(bg_output *w, const bg_output_kind *k, const char *form, const char *path, bg_strbuf *out);
#endif
