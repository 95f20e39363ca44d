/* SPDX-License-Identifier: BSD-3-Clause */
/* The import stage's entry points (import.h): which format a text is, and
 * the conversion into .bg text through the imported graph. */
#include "import/import.h"

#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/strbuf.h"

#include "import/import_int.h"

bg_import_format bg_import_detect(const char *src, size_t len) {
  if (len >= 6 && !memcmp(src, "#FIG 3", 6)) return BG_IMPORT_MTT;
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
  return f == BG_IMPORT_BGT ? "BondGraphTools YAML" : f == BG_IMPORT_MTT ? "MTT xfig drawing" : "bgdraw";
}

char *bg_import_find_drawing(const char *dir, char **why) {
  *why = NULL;
  size_t n = strlen(dir);
  while (n > 1 && dir[n - 1] == '/') n--;
  const char *base = dir;
  for (size_t i = 0; i < n; i++)
    if (dir[i] == '/') base = dir + i + 1;
  size_t bn = (size_t)(dir + n - base);
  bg_strbuf p = {0};
  bg_sb_printf(&p, "%.*s/%.*s_abg.fig", (int)n, dir, (int)bn, base);
  struct stat st;
  if (!stat(p.s, &st) && S_ISREG(st.st_mode)) return p.s;
  /* else the folder's one drawing */
  DIR *d = opendir(dir);
  char *found = NULL;
  int count = 0;
  for (struct dirent *e; d && (e = readdir(d));) {
    size_t k = strlen(e->d_name);
    if (k > 8 && !strcmp(e->d_name + k - 8, "_abg.fig") && count++ == 0) {
      bg_sb_clear(&p);
      bg_sb_printf(&p, "%.*s/%s", (int)n, dir, e->d_name);
      found = strdup(p.s);
    }
  }
  if (d) closedir(d);
  bg_sb_free(&p);
  if (count == 1) return found;
  free(found);
  bg_strbuf w = {0};
  if (count)
    bg_sb_printf(&w, "the folder %.*s holds %d MTT drawings (*_abg.fig) and none is %.*s_abg.fig: "
                     "name the one to read", (int)n, dir, count, (int)bn, base);
  else bg_sb_printf(&w, "the folder %.*s holds no MTT drawing (%.*s_abg.fig)", (int)n, dir, (int)bn, base);
  *why = w.s;
  return NULL;
}

int bg_import_convert(bg_import_format f, const char *path, const char *src, size_t len,
                      bg_diags *dg, bg_import_result *out) {
  memset(out, 0, sizeof *out);
  if (f != BG_IMPORT_BGT && f != BG_IMPORT_MTT) return -1;
  bg_ig g;
  memset(&g, 0, sizeof g);
  const char *slash = strrchr(path ? path : "", '/');
  g.source_path = slash ? slash + 1 : path ? path : "<string>";
  g.format = bg_import_format_name(f);
  int errors = dg->nerrors, rc;
  if (f == BG_IMPORT_MTT) {
    rc = !bg_mtt_read(path, src, len, &g, dg) && dg->nerrors == errors ? 0 : -1;
  } else {
    bg_ynode *doc = bg_yaml_parse(src, len, &g.arena, dg);
    rc = doc && !bg_bgt_read(doc, &g, dg) && dg->nerrors == errors ? 0 : -1;
  }
  if (!rc) bg_ig_emit(&g, out);
  bg_ig_free(&g);
  return rc;
}

void bg_import_result_free(bg_import_result *r) {
  free(r->text);
  free(r->line_of);
  free(r->file_of);
  memset(r, 0, sizeof *r);
}
