#include "base/fileio.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include <unistd.h>

#include "base/arena.h"

char *bg_atomic_tmp_path(const char *path) {
  size_t n = strlen(path) + 32;
  char *tmp = bg_xmalloc(n);
  snprintf(tmp, n, "%s.tmp%ld", path, (long)getpid());
  return tmp;
}

int bg_atomic_commit(const char *tmp, const char *path) {
  if (rename(tmp, path) != 0) {
    int e = errno;
    remove(tmp);
    errno = e;
    return -1;
  }
  return 0;
}

void bg_atomic_abort(const char *tmp) { remove(tmp); }

int bg_write_file_atomic(const char *path, const void *data, size_t len) {
  char *tmp = bg_atomic_tmp_path(path);
  FILE *f = fopen(tmp, "wb");
  int rc = -1;
  if (f) {
    size_t w = fwrite(data, 1, len, f);
    int closed = fclose(f);
    if (w == len && closed == 0) rc = bg_atomic_commit(tmp, path);
    else bg_atomic_abort(tmp);
  }
  free(tmp);
  return rc;
}

const char *bg_path_ext(const char *path) {
  const char *slash = strrchr(path, '/');
  const char *dot = strrchr(path, '.');
  if (!dot || (slash && dot < slash)) return "";
  return dot + 1;
}
