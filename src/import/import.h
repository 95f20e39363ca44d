/* SPDX-License-Identifier: BSD-3-Clause */
/* The import stage's front door (docs/import.md): models of other bond graph
 * tools turned into bgdraw's own language before anything else reads them.
 * BondGraphTools' YAML (bgt_read.c over libyaml, yaml_tree.c) and MTT's
 * xfig drawings with their label files (mtt_read.c, mtt_geom.c,
 * mtt_files.c, xfig_read.c) become .bg text with a header comment naming the
 * source; errors point at the foreign file's own lines. And back: a compiled model as BondGraphTools YAML
 * (bgt_write.c), so the stage stands after model. The run (src/run) calls it when the text is foreign, so
 * every option works on an imported model. */
#ifndef BG_IMPORT_H
#define BG_IMPORT_H
#include <stddef.h>

#include "base/diag.h"
#include "base/strbuf.h"
#include "model/model.h"

typedef enum { BG_IMPORT_NONE, BG_IMPORT_BGT, BG_IMPORT_MTT } bg_import_format;

/* Which foreign format src is, by content (whatever the file's name):
 * BondGraphTools' YAML has at least two of the top-level keys root:,
 * models:, version: at the start of a line; an MTT drawing is an xfig file
 * (its first line "#FIG 3.x"). */
bg_import_format bg_import_detect(const char *src, size_t len);
const char *bg_import_format_name(bg_import_format f);
/* An MTT model folder's drawing: DIR/NAME_abg.fig for the folder NAME, else
 * its only *_abg.fig (malloc'd). NULL with *why (malloc'd) when neither. */
char *bg_import_find_drawing(const char *dir, char **why);

/* The imported model as .bg text, and for each of its lines the line of the
 * source it came from (0: none), so diagnostics of the .bg text can point
 * at the foreign file. */
typedef struct bg_import_result {
  char *text; /* owned, NUL-terminated; NULL after an error */
  size_t len;
  int *line_of; /* owned; line_of[k] for the text's line k (1-based), 0..nlines */
  int *file_of; /* owned; the source line_of[k] is in (a bg_diags index; 0: the model file) */
  int nlines;
} bg_import_result;

/* Converts src (named path in the header comment) from format f. Errors go to
 * dg at positions in src (file 0). 0 on success. */
int bg_import_convert(bg_import_format f, const char *path, const char *src, size_t len,
                      bg_diags *dg, bg_import_result *out);
void bg_import_result_free(bg_import_result *r);

/* Model m as BondGraphTools YAML appended to out (bgt_write.c): NULL, or
 * why the format cannot carry m (owned; nothing useful in out then). */
char *bg_bgt_write(const bg_model *m, bg_strbuf *out);
#endif
