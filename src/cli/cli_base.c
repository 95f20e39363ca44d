/* SPDX-License-Identifier: BSD-3-Clause */
/* The command line's leaf helpers, called by its other files and calling
 * none of them: the name that means standard output, writing an output's
 * bytes (atomically into a file, in place into stdout), and the running
 * executable's folder (where the render module and the styles are). */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "base/fileio.h"
#include "base/strbuf.h"
#include "cli/cli_opts.h"
#include "cli/cli_run.h"

int bg_cli_is_stdout(const char *path) { return path && strcmp(path, BG_CLI_STDOUT) == 0; }

/* The folder of /proc/self/exe. */
int cli_exe_dir(char *buf, size_t n) {
  char exe[4096];
  ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (len <= 0) return -1;
  exe[len] = '\0';
  char *slash = strrchr(exe, '/');
  if (!slash) return -1;
  *slash = '\0';
  snprintf(buf, n, "%s", exe);
  return 0;
}

/* Text to stdout, flushed; EXIT_WRITE (with a message) on a write error. */
static int write_stdout(const bg_strbuf *sb) {
  if (bg_write_stream(stdout, bg_sb_str(sb), sb->len) == 0) return EXIT_OK;
  fprintf(stderr, "bgdraw: error: cannot write to stdout: %s\n", bg_file_strerror(errno));
  return EXIT_WRITE;
}

int cli_write_text(const char *path, const bg_strbuf *sb) {
  if (bg_cli_is_stdout(path)) return write_stdout(sb); /* in place, never renamed */
  if (bg_write_file_atomic(path, bg_sb_str(sb), sb->len) == 0) return EXIT_OK;
  fprintf(stderr, "bgdraw: error: cannot write '%s': %s\n", path, bg_file_strerror(errno));
  return EXIT_WRITE;
}
