/* SPDX-License-Identifier: BSD-3-Clause */
/* Model exports (docs/export.md): the equation system of an export build
 * (bg_eqsys_build_export: params stay variables) written as code other tools
 * run. Every exporter appends text to strbufs and touches no file. */
#ifndef BG_EXPORT_H
#define BG_EXPORT_H
#include <stddef.h>

#include "base/strbuf.h"
#include "equations/equations.h"

/* The default symbol prefix: the model name made a C identifier ("rlc",
 * "my_model"); buf of size n. */
void bg_export_default_prefix(const bg_model *m, char *buf, size_t n);
/* 1 when prefix is a usable C identifier (letters, digits, '_'; not a digit
 * first; at most 64 characters). */
int bg_export_prefix_ok(const char *prefix);

/* Reusable C: header text into h, source into c. The source includes
 * "<header_name>"; with header_name NULL the two are meant to be one
 * translation unit (the header is printed first, no #include). */
void bg_export_c(const bg_eqsys *s, const char *prefix, const char *header_name, bg_strbuf *h,
                 bg_strbuf *c);
/* A Python module: numpy right-hand side or residual, parameters as a dict,
 * simulate() with SciPy (solve_ivp for ODEs). */
void bg_export_python(const bg_eqsys *s, bg_strbuf *out);
/* An Octave/MATLAB function file named fname (the file's base name, e.g.
 * "rlc_model"): a function returning a struct with parameters, initial
 * values, and handles for ode15s (mass matrix) and ode15i. */
void bg_export_octave(const bg_eqsys *s, const char *fname, bg_strbuf *out);
/* A Modelica model: parameters, the states with start values, every bond
 * variable, and the bond graph's equations unsorted, with der(...). */
void bg_export_modelica(const bg_eqsys *s, bg_strbuf *out);

/* 1 when the export to format ("c", "h", "py", "m", "mo", "fmu") cannot be
 * trusted to compute what bgdraw computes, with the reason in why: memory
 * (hyst, stick) in the Octave and Modelica exports, which carry no modes
 * (docs/export.md). */
int bg_export_refusal(const bg_eqsys *s, const char *format, bg_strbuf *why);

/* FMI 2.0 Model Exchange (ODE models only; the caller refuses a DAE).
 * The GUID: a hash of text (the C export), "{8-4-4-4-12}" into buf of n >= 40. */
void bg_export_fmu_guid(const char *text, size_t len, char *buf, size_t n);
/* modelDescription.xml; the model identifier is the C prefix. */
void bg_export_fmu_description(const bg_eqsys *s, const char *prefix, const char *guid,
                               bg_strbuf *xml);
/* The fmi2 functions over the C export whose header is header_name. */
void bg_export_fmu_glue(const bg_eqsys *s, const char *prefix, const char *header_name,
                        const char *guid, bg_strbuf *c);

/* One member of a zip archive: its path in the archive and its bytes. */
typedef struct bg_zip_entry {
  const char *name;
  const char *data;
  size_t len;
} bg_zip_entry;
/* The archive of n entries, stored (not compressed), appended to out. */
void bg_export_zip(const bg_zip_entry *e, int n, bg_strbuf *out);
#endif
