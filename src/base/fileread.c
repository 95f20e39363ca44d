/* SPDX-License-Identifier: BSD-3-Clause */
/* Bounded reads of regular files and streams, and the set of files a run
 * read (by device and inode), which no output may replace (fileio.h). */
#include "base/fileio.h"

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/arena.h"

typedef struct file_id {
  dev_t dev;
  ino_t ino;
} file_id;

/* The process's inputs (fileio.h says why one set): runs on several threads
 * add to it and ask it under this lock. */
static file_id *inputs;
static int ninputs, inputs_cap;
static pthread_mutex_t inputs_lock = PTHREAD_MUTEX_INITIALIZER;

static int known(dev_t dev, ino_t ino) {
  for (int i = 0; i < ninputs; i++)
    if (inputs[i].dev == dev && inputs[i].ino == ino) return 1;
  return 0;
}

static void remember(const struct stat *st) {
  pthread_mutex_lock(&inputs_lock);
  if (!known(st->st_dev, st->st_ino)) {
    if (ninputs == inputs_cap) {
      inputs_cap = inputs_cap ? 2 * inputs_cap : 8;
      inputs = bg_xrealloc(inputs, (size_t)inputs_cap * sizeof *inputs);
    }
    inputs[ninputs++] = (file_id){st->st_dev, st->st_ino};
  }
  pthread_mutex_unlock(&inputs_lock);
}

void bg_input_note(const char *path) {
  struct stat st;
  if (path && stat(path, &st) == 0) remember(&st);
}

int bg_path_is_input(const char *path) {
  struct stat st;
  if (stat(path, &st) != 0) return 0;
  pthread_mutex_lock(&inputs_lock);
  int yes = known(st.st_dev, st.st_ino);
  pthread_mutex_unlock(&inputs_lock);
  return yes;
}

const char *bg_file_strerror(int err) {
  switch (err) {
  case BG_ENOTREG: return "not a regular file (bgdraw reads only regular files and stdin)";
  case BG_ETOOBIG: return "the file is larger than bgdraw's limit of 64 MiB";
  case BG_EISINPUT: return "it is one of the run's input files (refusing to overwrite an input)";
  case BG_EBLOCKDEV: return "it is a block device (refusing to write one)";
  default: return strerror(err);
  }
}

/* Opens path for reading if it is a regular file within the size limit;
 * O_NONBLOCK so that a FIFO without a writer is refused, not waited for. */
static int open_regular(const char *path, struct stat *st) {
  int fd = open(path, O_RDONLY | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return -1;
  int err = 0;
  if (fstat(fd, st) != 0) err = errno;
  else if (S_ISDIR(st->st_mode)) err = EISDIR;
  else if (!S_ISREG(st->st_mode)) err = BG_ENOTREG;
  else if ((size_t)st->st_size > BG_INPUT_MAX_BYTES) err = BG_ETOOBIG;
  if (err) {
    close(fd);
    errno = err;
    return -1;
  }
  return fd;
}

/* Reads fd to its end into a buffer of at least cap bytes, refusing more
 * than the limit; NULL with errno set. */
static char *read_fd(int fd, size_t cap, size_t *len) {
  char *buf = bg_xmalloc(cap + 1);
  size_t n = 0;
  for (;;) {
    if (n == cap) {
      if (cap > BG_INPUT_MAX_BYTES) break;
      cap = cap * 2 > BG_INPUT_MAX_BYTES + 1 ? BG_INPUT_MAX_BYTES + 1 : cap * 2;
      buf = bg_xrealloc(buf, cap + 1);
    }
    ssize_t r = read(fd, buf + n, cap - n);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      int e = errno;
      free(buf);
      errno = e;
      return NULL;
    }
    if (r == 0) break;
    n += (size_t)r;
  }
  if (n > BG_INPUT_MAX_BYTES) {
    free(buf);
    errno = BG_ETOOBIG;
    return NULL;
  }
  buf[n] = '\0';
  if (len) *len = n;
  return buf;
}

char *bg_read_file(const char *path, size_t *len) {
  struct stat st;
  int fd = open_regular(path, &st);
  if (fd < 0) return NULL;
  /* one read more than the size, to see the end (or a file that grew) */
  char *buf = read_fd(fd, (size_t)st.st_size + 1, len);
  int e = errno;
  close(fd);
  if (buf) remember(&st);
  errno = e;
  return buf;
}

char *bg_read_stream(FILE *f, size_t *len) {
  size_t cap = 4096, n = 0, r;
  char *buf = bg_xmalloc(cap + 1);
  while (n <= BG_INPUT_MAX_BYTES && (r = fread(buf + n, 1, cap - n, f)) > 0) {
    n += r;
    if (n == cap) buf = bg_xrealloc(buf, (cap *= 2) + 1);
  }
  int err = ferror(f) ? (errno ? errno : EIO) : n > BG_INPUT_MAX_BYTES ? BG_ETOOBIG : 0;
  if (err) {
    free(buf);
    errno = err;
    return NULL;
  }
  buf[n] = '\0';
  if (len) *len = n;
  return buf;
}
