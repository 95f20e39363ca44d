/* SPDX-License-Identifier: BSD-3-Clause */
/* Diagram options from the command line: --show with overlays added to the
 * default layers, --highlight, --max-list, and where the named styles are
 * (beside the executable, never a path compiled in from the source tree). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/strbuf.h"
#include "cli/cli_run.h"

/* Parses --show into *bits; -1 after a message. */
static int parse_show(const char *list, unsigned *bits) {
  bg_strbuf err = {0};
  int rc = bg_output_parse_show(list, bits, &err);
  if (rc) fprintf(stderr, "bgdraw: error: %s\n", bg_sb_str(&err));
  bg_sb_free(&err);
  return rc;
}

/* EXE/../share/bgdraw/WHAT (installed), else EXE/share/bgdraw/WHAT (the
 * build tree, where CMake copies styles and the component library) into
 * dir; NULL when neither is a folder. */
static const char *installed_share_dir(const char *what, char *dir, size_t n) {
  char exe[4096]; /* the executable's folder */
  if (cli_exe_dir(exe, sizeof exe) != 0) return NULL;
  static const char *const rel[] = {"/../share/bgdraw/", "/share/bgdraw/"};
  for (int i = 0; i < 2; i++) {
    struct stat st;
    snprintf(dir, n, "%s%s%s", exe, rel[i], what);
    if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode)) return dir;
  }
  return NULL;
}

/* The named styles' folder; NULL when there is none (style.c then tries
 * $BGDRAW_STYLE_DIR and ./styles). */
static const char *installed_style_dir(void) {
  static char dir[4200];
  return installed_share_dir("styles", dir, sizeof dir);
}

/* The component library `use "NAME.bg"` finds (docs/format.md, "Files"). */
const char *cli_lib_dir(void) {
  static char dir[4200];
  return installed_share_dir("lib", dir, sizeof dir);
}

static int parse_max_list(run *r, const char *s) {
  char *end;
  long n = strtol(s, &end, 10);
  if (end == s || *end || n < 1 || n > 100000000) {
    fprintf(stderr, "bgdraw: error: --max-list takes a positive whole number, not '%s'\n", s);
    return -1;
  }
  r->max_list = (int)n;
  return 0;
}

int cli_render_options(run *r) {
  const bg_cli_opts *o = &r->opts;
  bg_render_opts *ro = &r->ropts;
  ro->show = BG_SHOW_DEFAULT;
  if (o->show && parse_show(o->show, &ro->show) != 0) return -1;
  if (o->highlight && bg_highlight_parse(o->highlight, &ro->highlight_kind,
                                         &ro->highlight_index) != 0) {
    fprintf(stderr, "bgdraw: error: --highlight takes path:K, loop:K or conflict:K, not '%s'\n",
            o->highlight);
    return -1;
  }
  if (o->max_list && parse_max_list(r, o->max_list) != 0) return -1;
  ro->collapse = o->collapse, ro->ncollapse = o->ncollapse; /* names checked by the diagram */
  r->max_errors = BG_DIAG_MAX_ERRORS;
  if (o->max_errors) {
    char *end;
    long n = strtol(o->max_errors, &end, 10);
    if (end == o->max_errors || *end || n < 0 || n > 1000000000) {
      fprintf(stderr, "bgdraw: error: --max-errors takes a whole number (0: no limit), not '%s'\n",
              o->max_errors);
      return -1;
    }
    r->max_errors = (int)n;
  }
  ro->style = o->style;
  const char *env = getenv("BGDRAW_STYLE_DIR");
  ro->style_dir = env && *env ? NULL : installed_style_dir();
  ro->layout = o->layout;
  return 0;
}
