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

/* Appends n bytes of a numbered pattern to b, in lines as a writer does. */
static void append_lines(bg_strbuf *b, size_t n, bg_strbuf *copy) {
  for (size_t i = 0; copy->len < n; i++) {
    char line[64];
    int k = snprintf(line, sizeof line, "<path d=\"M%zu\"/>\n", i);
    bg_sb_putn(b, line, (size_t)k);
    bg_sb_putn(copy, line, (size_t)k);
  }
}

static int file_is(const char *path, const bg_strbuf *want) {
  size_t len = 0;
  FILE *f = fopen(path, "rb");
  char *got = f ? bg_read_stream(f, &len) : NULL;
  if (f) fclose(f);
  int same = got && len == want->len && !memcmp(got, bg_sb_str(want), len);
  free(got);
  return same;
}

/* bg_stream: text past the chunk size goes to the temporary file while it
 * is made (the strbuf holds at most a chunk), the target keeps its old
 * bytes until the rename; a failed writer leaves the old file and no
 * temporary; small text and other targets are written whole at the end; a
 * refused target is reported at the end. */
static void test_stream(const char *dir) {
  char target[4096];
  snprintf(target, sizeof target, "%s/stream.svg", dir);
  bg_strbuf old = {0};
  bg_sb_puts(&old, "old");
  OK(bg_write_file_atomic(target, "old", 3) == 0);
  for (int ok = 0; ok < 2; ok++) {
    int before = count_entries(dir);
    bg_strbuf sb = {0}, copy = {0};
    bg_stream st;
    bg_stream_begin(&st, &sb, target);
    append_lines(&sb, 3 * BG_STREAM_CHUNK + 12345, &copy);
    OK(sb.cap <= 2 * BG_STREAM_CHUNK && st.sink.passed >= 2 * BG_STREAM_CHUNK);
    INT_EQ(count_entries(dir), before + 1); /* the temporary file, beside the target */
    OK(file_is(target, &old));              /* untouched while the text is made */
    size_t bytes = 0;
    INT_EQ(bg_stream_finish(&st, &sb, ok, &bytes), 0);
    INT_EQ(count_entries(dir), before);
    OK(bytes == copy.len && sb.sink == NULL);
    OK(file_is(target, ok ? &copy : &old)); /* replaced only when the writer succeeded */
    bg_sb_free(&sb);
    bg_sb_free(&copy);
  }
  /* small: written at the end, as bg_write_file_atomic writes it */
  bg_strbuf sb = {0}, copy = {0};
  bg_stream st;
  bg_stream_begin(&st, &sb, target);
  append_lines(&sb, 1000, &copy);
  OK(st.sink.passed == 0 && st.fd < 0);
  INT_EQ(bg_stream_finish(&st, &sb, 1, NULL), 0);
  OK(file_is(target, &copy));
  bg_sb_free(&sb);
  /* a character device takes the whole text at the end */
  bg_stream_begin(&st, &sb, "/dev/null");
  bg_sb_clear(&copy);
  append_lines(&sb, 2 * BG_STREAM_CHUNK, &copy);
  OK(sb.len >= 2 * BG_STREAM_CHUNK && sb.sink == NULL); /* declined: kept whole */
  INT_EQ(bg_stream_finish(&st, &sb, 1, NULL), 0);
  bg_sb_free(&sb);
  /* a refused target: the text dropped, the error at the end */
  bg_stream_begin(&st, &sb, dir);
  bg_sb_clear(&copy);
  append_lines(&sb, 4 * BG_STREAM_CHUNK, &copy);
  OK(sb.cap <= 2 * BG_STREAM_CHUNK);
  errno = 0;
  OK(bg_stream_finish(&st, &sb, 1, NULL) == -1 && errno == EISDIR);
  bg_sb_free(&sb);
  bg_sb_free(&old);
  /* a signal while the text is made removes the temporary file */
  int before = count_entries(dir);
  pid_t pid = fork();
  if (pid == 0) {
    bg_stream_begin(&st, &sb, target);
    append_lines(&sb, 2 * BG_STREAM_CHUNK, &copy);
    raise(SIGINT);
    _exit(0);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  OK(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT);
  INT_EQ(count_entries(dir), before);
  bg_sb_free(&copy);
  unlink(target);
}

int main(void) {
  char dir[] = "/tmp/bg_fileio_XXXXXX";
  if (!mkdtemp(dir)) return 1;
  test_tmp_beside_target(dir);
  test_signal_removes_tmp(dir, SIGTERM);
  test_signal_removes_tmp(dir, SIGINT);
  test_signal_removes_tmp(dir, SIGHUP);
  test_read_limits(dir);
  test_stream(dir);
  char cmd[4200];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  if (system(cmd) != 0) return 1;
  return bg_t_done();
}
