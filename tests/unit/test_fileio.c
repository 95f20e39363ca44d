/* SPDX-License-Identifier: BSD-3-Clause */
/* fileio: the temporary file of an atomic write lives in the target's
 * folder under an unpredictable mkstemp name, and SIGINT/SIGTERM/SIGHUP
 * between writing it and renaming it remove it (the process still dies of
 * the signal, and the old target is untouched); bounded reads. */
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "base/fileio.h"
#include "harness.h"

static char seen_tmp[4096];
static int kill_with;

static void record_tmp(const char *tmp) { snprintf(seen_tmp, sizeof seen_tmp, "%s", tmp); }
static void raise_signal(const char *tmp) {
  (void)tmp;
  raise(kill_with);
}

static int count_entries(const char *dir) {
  DIR *d = opendir(dir);
  int n = 0;
  for (struct dirent *e; d && (e = readdir(d));)
    if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) n++;
  if (d) closedir(d);
  return n;
}

static void test_tmp_beside_target(const char *dir) {
  char target[4096];
  snprintf(target, sizeof target, "%s/out.json", dir);
  bg_fileio_set_before_rename_hook(record_tmp);
  INT_EQ(bg_write_file_atomic(target, "abc", 3), 0);
  bg_fileio_set_before_rename_hook(NULL);
  char prefix[4096];
  snprintf(prefix, sizeof prefix, "%s/.out.json.", dir);
  OK(strncmp(seen_tmp, prefix, strlen(prefix)) == 0);
  INT_EQ(strlen(seen_tmp), strlen(prefix) + 6); /* mkstemp's six random characters */
  INT_EQ(count_entries(dir), 1);
  size_t len = 0;
  char *back = bg_read_file(target, &len);
  OK(back && len == 3 && !strcmp(back, "abc"));
  free(back);
  OK(bg_path_is_input(target)); /* read, so remembered */
  errno = 0;
  OK(bg_write_file_atomic(target, "x", 1) == -1 && errno == BG_EISINPUT);
}

/* A child writes with the signal raised before the rename. */
static void test_signal_removes_tmp(const char *dir, int sig) {
  char target[4096];
  snprintf(target, sizeof target, "%s/sig%d.svg", dir, sig);
  pid_t pid = fork();
  if (pid == 0) {
    kill_with = sig;
    bg_fileio_set_before_rename_hook(raise_signal);
    bg_write_file_atomic(target, "<svg/>", 6);
    _exit(0); /* not reached when the signal killed us */
  }
  int status = 0;
  waitpid(pid, &status, 0);
  OK(WIFSIGNALED(status) && WTERMSIG(status) == sig);
  INT_EQ(count_entries(dir), 1); /* only out.json: no target, no temporary */
}

static void test_read_limits(const char *dir) {
  char big[4096];
  snprintf(big, sizeof big, "%s/big", dir);
  FILE *f = fopen(big, "wb");
  OK(f && fseek(f, (long)BG_INPUT_MAX_BYTES, SEEK_SET) == 0 && fputc('x', f) == 'x');
  fclose(f);
  errno = 0;
  OK(bg_read_file(big, NULL) == NULL && errno == BG_ETOOBIG);
  OK(strstr(bg_file_strerror(BG_ETOOBIG), "64 MiB") != NULL);
  unlink(big);
  errno = 0;
  OK(bg_read_file(dir, NULL) == NULL && errno == EISDIR);
  errno = 0;
  OK(bg_read_file("/dev/zero", NULL) == NULL && errno == BG_ENOTREG);
}

int main(void) {
  char dir[] = "/tmp/bg_fileio_XXXXXX";
  if (!mkdtemp(dir)) return 1;
  test_tmp_beside_target(dir);
  test_signal_removes_tmp(dir, SIGTERM);
  test_signal_removes_tmp(dir, SIGINT);
  test_signal_removes_tmp(dir, SIGHUP);
  test_read_limits(dir);
  char cmd[4200];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  if (system(cmd) != 0) return 1;
  return bg_t_done();
}
