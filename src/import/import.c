/* SPDX-License-Identifier: BSD-3-Clause */
/* The import stage's entry points (import.h): which format a text is, and
 * the conversion into .bg text through the imported graph. */
#include "import/import.h"

#include <stdlib.h>
#include <string.h>

#include "import/import_int.h"

bg_import_format bg_import_detect(const char *src, size_t len) {
  static const char *const keys[] = {"root:", "models:", "version:"};
  int hits[3] = {0, 0, 0};
  for (size_t i = 0; i < len;) {
    size_t end = i;
    while (end < len && src[end] != '\n') end++;
    for (int k = 0; k < 3; k++) {
      size_t n = strlen(keys[k]);
      if (end - i >= n && !strncmp(src + i, keys[k], n)) hits[k] = 1;
    }
    i = end + 1;
  }
  return hits[0] + hits[1] + hits[2] >= 2 ? BG_IMPORT_BGT : BG_IMPORT_NONE;
}

const char *bg_import_format_name(bg_import_format f) {
  return f == BG_IMPORT_BGT ? "BondGraphTools YAML" : "bgdraw";
}

int bg_import_convert(bg_import_format f, const char *path, const char *src, size_t len,
                      bg_diags *dg, bg_import_result *out) {
  memset(out, 0, sizeof *out);
  if (f != BG_IMPORT_BGT) return -1;
  bg_ig g;
  memset(&g, 0, sizeof g);
  const char *slash = strrchr(path ? path : "", '/');
  g.source_path = slash ? slash + 1 : path ? path : "<string>";
  g.format = bg_import_format_name(f);
  int errors = dg->nerrors;
  bg_ynode *doc = bg_yaml_parse(src, len, &g.arena, dg);
  int rc = doc && !bg_bgt_read(doc, &g, dg) && dg->nerrors == errors ? 0 : -1;
  if (!rc) bg_ig_emit(&g, out);
  bg_ig_free(&g);
  return rc;
}

void bg_import_result_free(bg_import_result *r) {
  free(r->text);
  free(r->line_of);
  memset(r, 0, sizeof *r);
}
