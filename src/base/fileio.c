/* SPDX-License-Identifier: BSD-3-Clause */
/* Output files that never damage what they point at (fileio.h): regular
 * files are replaced atomically through a mkstemp file beside them, devices,
 * FIFOs and sockets are written in place, symlinks are followed, inputs and
 * block devices are refused. A signal between creating the temporary file
 * and renaming it removes the temporary file. */
#include "base/fileio.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include "base/arena.h"

/* ------------------------------------------------- the signal clean-up */
/* The one temporary file in existence: signal handlers are the process's,
 * so is this slot. Outputs are written one at a time: replace_file holds
 * replace_lock from creating the temporary file to its rename, so runs on
 * several threads take turns (fileio.h). */
static char pending_tmp[PATH_MAX + 64];
static volatile sig_atomic_t pending_set;
static int handlers_installed;
static pthread_mutex_t replace_lock = PTHREAD_MUTEX_INITIALIZER;
static void (*before_rename_hook)(const char *tmp);

void bg_fileio_set_before_rename_hook(void (*hook)(const char *tmp)) { before_rename_hook = hook; }

static void remove_pending_and_die(int sig) {
  if (pending_set) unlink(pending_tmp); /* async-signal-safe */
  signal(sig, SIG_DFL);
  raise(sig);
}

static const int cleanup_signals[] = {SIGINT, SIGTERM, SIGHUP};

/* Installs the handlers once, leaving alone a signal someone ignores or
 * handles already (nohup, a host program). */
static void install_handlers(void) {
  if (handlers_installed) return;
  handlers_installed = 1;
  for (size_t i = 0; i < sizeof cleanup_signals / sizeof *cleanup_signals; i++) {
    struct sigaction old, sa;
    if (sigaction(cleanup_signals[i], NULL, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = remove_pending_and_die;
    sigemptyset(&sa.sa_mask);
    sigaction(cleanup_signals[i], &sa, NULL);
  }
}

/* Blocks (or restores) the clean-up signals around the steps that create or
 * rename the temporary file, so no signal falls between a step and its
 * bookkeeping. */
static void block_signals(sigset_t *saved) {
  sigset_t s;
  sigemptyset(&s);
  for (size_t i = 0; i < sizeof cleanup_signals / sizeof *cleanup_signals; i++)
    sigaddset(&s, cleanup_signals[i]);
  pthread_sigmask(SIG_BLOCK, &s, saved);
}

static void restore_signals(const sigset_t *saved) { pthread_sigmask(SIG_SETMASK, saved, NULL); }

/* ------------------------------------------------------------ helpers */
static int write_all(int fd, const char *p, size_t len) {
  while (len > 0) {
    ssize_t w = write(fd, p, len);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return -1;
    p += w;
    len -= (size_t)w;
  }
  return 0;
}

char *bg_resolve_links(const char *path) {
  char *p = strdup(path);
  for (int hops = 0; p && hops < 40; hops++) {
    struct stat st;
    if (lstat(p, &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    char link[PATH_MAX];
    ssize_t n = readlink(p, link, sizeof link - 1);
    if (n < 0) break;
    link[n] = '\0';
    const char *slash = strrchr(p, '/');
    size_t dirlen = link[0] == '/' || !slash ? 0 : (size_t)(slash - p) + 1;
    char *next = bg_xmalloc(dirlen + (size_t)n + 1);
    memcpy(next, p, dirlen);
    memcpy(next + dirlen, link, (size_t)n + 1);
    free(p);
    p = next;
  }
  if (p) errno = ELOOP;
  free(p);
  return NULL;
}

/* A character device, FIFO or terminal: written where it is. */
static int write_in_place(const char *path, const void *data, size_t len) {
  int fd = open(path, O_WRONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return -1;
  int rc = write_all(fd, data, len);
  int e = errno;
  if (close(fd) != 0 && rc == 0) return -1;
  errno = e;
  return rc;
}

/* A Unix-domain socket: connected to and written as a stream. */
static int write_socket(const char *path, const void *data, size_t len) {
  struct sockaddr_un sa;
  memset(&sa, 0, sizeof sa);
  sa.sun_family = AF_UNIX;
  if (strlen(path) >= sizeof sa.sun_path) {
    errno = ENAMETOOLONG;
    return -1;
  }
  strcpy(sa.sun_path, path);
  int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0) return -1;
  int rc = connect(fd, (struct sockaddr *)&sa, sizeof sa) == 0 ? write_all(fd, data, len) : -1;
  int e = errno;
  close(fd);
  errno = e;
  return rc;
}

/* The temporary name's template: ".<name>.XXXXXX" in the target's folder
 * (the name shortened so the result stays within NAME_MAX). */
static char *tmp_template(const char *target) {
  const char *slash = strrchr(target, '/');
  size_t dirlen = slash ? (size_t)(slash - target) + 1 : 0;
  const char *base = target + dirlen;
  size_t baselen = strlen(base) > 200 ? 200 : strlen(base);
  char *t = bg_xmalloc(dirlen + baselen + 16);
  snprintf(t, dirlen + baselen + 16, "%.*s.%.*s.XXXXXX", (int)dirlen, target, (int)baselen, base);
  return t;
}

/* Creates the temporary file with the mode the result must have: the old
 * file's, or the umask's default for a new one. -1 on failure. */
static int create_tmp(char *tmpl, const struct stat *old) {
  sigset_t saved;
  install_handlers();
  block_signals(&saved);
  int fd = mkstemp(tmpl);
  if (fd >= 0) {
    snprintf(pending_tmp, sizeof pending_tmp, "%s", tmpl);
    pending_set = 1;
  }
  restore_signals(&saved);
  if (fd < 0) return -1;
  mode_t mode;
  if (old) {
    mode = old->st_mode & 07777;
    if (geteuid() == 0 && fchown(fd, old->st_uid, old->st_gid) != 0) { /* keep root's owner */ }
  } else {
    mode_t mask = umask(0);
    umask(mask);
    mode = 0666 & ~mask;
  }
  fchmod(fd, mode);
  return fd;
}

/* Renames tmp onto target (or removes it) and forgets it. */
static int finish_tmp(const char *tmp, const char *target, int ok) {
  sigset_t saved;
  block_signals(&saved);
  int rc = ok ? rename(tmp, target) : -1;
  int e = errno;
  if (rc != 0) unlink(tmp);
  pending_set = 0;
  restore_signals(&saved);
  errno = e;
  return rc;
}

/* The temporary file of target's replacement, with the mode the result
 * must have: its descriptor (its name in *tmp, freed by tmp_end), or -1.
 * The caller holds replace_lock until tmp_end. */
static int tmp_begin(const char *target, const struct stat *old, char **tmp) {
  *tmp = tmp_template(target);
  int fd = create_tmp(*tmp, old);
  if (fd < 0) {
    int e = errno;
    free(*tmp);
    *tmp = NULL;
    errno = e;
  }
  return fd;
}

/* Closes fd, then renames tmp onto target (ok) or removes it; frees tmp. 0,
 * or -1 with errno set (a failed write's when not ok). */
static int tmp_end(int fd, char *tmp, const char *target, int ok) {
  int e = errno;
  if (close(fd) != 0 && ok) {
    ok = 0;
    e = errno;
  }
  if (ok && before_rename_hook) before_rename_hook(tmp);
  errno = e;
  int rc = finish_tmp(tmp, target, ok);
  if (!ok) errno = e;
  free(tmp);
  return rc;
}

/* A regular file or a new name: replaced atomically. */
static int replace_file_locked(const char *target, const struct stat *old, const void *data,
                               size_t len) {
  char *tmp;
  int fd = tmp_begin(target, old, &tmp);
  if (fd < 0) return -1;
  return tmp_end(fd, tmp, target, write_all(fd, data, len) == 0);
}

static int replace_file(const char *target, const struct stat *old, const void *data, size_t len) {
  pthread_mutex_lock(&replace_lock);
  int rc = replace_file_locked(target, old, data, len);
  int e = errno;
  pthread_mutex_unlock(&replace_lock);
  errno = e;
  return rc;
}

/* /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N name a file
 * descriptor this process already has open: written through it, so a pipe
 * gets the bytes and a shell's `>> file` appends (following the link to
 * the file would replace it). -1 when path is none of these. */
static int open_fd_of(const char *path) {
  if (!strcmp(path, "/dev/stdout")) return 1;
  if (!strcmp(path, "/dev/stderr")) return 2;
  if (!strcmp(path, "/dev/stdin")) return 0;
  const char *prefixes[] = {"/dev/fd/", "/proc/self/fd/"};
  for (int i = 0; i < 2; i++) {
    size_t n = strlen(prefixes[i]);
    if (strncmp(path, prefixes[i], n) || !path[n]) continue;
    char *end;
    long fd = strtol(path + n, &end, 10);
    if (!*end && fd >= 0 && fd < 1 << 20) return (int)fd;
  }
  return -1;
}

/* ------------------------------------------------------------- public */
int bg_write_file_atomic(const char *path, const void *data, size_t len) {
  int fd = open_fd_of(path);
  if (fd >= 0) {
    if (fd == 1) fflush(stdout); /* what stdio holds goes first */
    return write_all(fd, data, len);
  }
  char *target = bg_resolve_links(path);
  if (!target) return -1;
  struct stat st;
  int rc = -1;
  if (stat(target, &st) != 0) {
    if (errno == ENOENT) rc = replace_file(target, NULL, data, len);
  } else if (bg_path_is_input(target)) errno = BG_EISINPUT;
  else if (S_ISDIR(st.st_mode)) errno = EISDIR;
  else if (S_ISBLK(st.st_mode)) errno = BG_EBLOCKDEV;
  else if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) rc = write_in_place(target, data, len);
  else if (S_ISSOCK(st.st_mode)) rc = write_socket(target, data, len);
  else rc = replace_file(target, &st, data, len);
  int e = errno;
  free(target);
  errno = e;
  return rc;
}

/* ------------------------------------------------ outputs made in pieces */
/* Where the first piece goes, decided as bg_write_file_atomic decides: 0
 * with the temporary file open (replace_lock held until bg_stream_finish),
 * 1 for a target that gets the whole text at the end, -1 with errno set for
 * a refused target or a temporary file that cannot be made. */
static int stream_open(bg_stream *st) {
  if (open_fd_of(st->path) >= 0) return 1;
  char *target = bg_resolve_links(st->path);
  if (!target) return -1;
  struct stat old;
  int exists = stat(target, &old) == 0, rc = -1;
  if (!exists && errno != ENOENT) rc = -1; /* stat's errno says why */
  else if (exists && bg_path_is_input(target)) errno = BG_EISINPUT;
  else if (exists && S_ISDIR(old.st_mode)) errno = EISDIR;
  else if (exists && S_ISBLK(old.st_mode)) errno = BG_EBLOCKDEV;
  else if (exists && !S_ISREG(old.st_mode)) rc = 1; /* a device, FIFO or socket */
  else {
    pthread_mutex_lock(&replace_lock);
    st->fd = tmp_begin(target, exists ? &old : NULL, &st->tmp);
    if (st->fd >= 0) {
      st->target = target;
      return 0;
    }
    int e = errno;
    pthread_mutex_unlock(&replace_lock);
    errno = e;
  }
  int e = errno;
  free(target);
  errno = e;
  return rc;
}

static int stream_take(bg_sb_sink *k, const char *p, size_t n) {
  bg_stream *st = (bg_stream *)k;
  if (st->fd < 0) {
    int rc = stream_open(st);
    if (rc) return rc;
  }
  return write_all(st->fd, p, n);
}

void bg_stream_begin(bg_stream *st, bg_strbuf *b, const char *path) {
  memset(st, 0, sizeof *st);
  st->sink.take = stream_take;
  st->sink.chunk = BG_STREAM_CHUNK;
  st->path = path;
  st->fd = -1;
  b->sink = &st->sink;
}

int bg_stream_finish(bg_stream *st, bg_strbuf *b, int ok, size_t *bytes) {
  b->sink = NULL;
  if (bytes) *bytes = st->sink.passed + b->len;
  int rc = 0, e = 0;
  if (st->fd >= 0) { /* streamed: the rest, then the rename */
    if (ok && !st->sink.err && write_all(st->fd, bg_sb_str(b), b->len) != 0) st->sink.err = errno;
    rc = tmp_end(st->fd, st->tmp, st->target, ok && !st->sink.err);
    e = errno;
    pthread_mutex_unlock(&replace_lock);
    if (st->sink.err) rc = -1, e = st->sink.err;
    else if (!ok) rc = 0;
  } else if (st->sink.err) { /* the target was refused */
    rc = ok ? -1 : 0;
    e = st->sink.err;
  } else if (ok) { /* small, or a target written whole */
    rc = bg_write_file_atomic(st->path, bg_sb_str(b), b->len);
    e = errno;
  }
  free(st->target);
  st->target = st->tmp = NULL;
  st->fd = -1;
  errno = e;
  return rc;
}

int bg_write_stream(FILE *f, const void *data, size_t len) {
  errno = 0;
  size_t w = len ? fwrite(data, 1, len, f) : 0;
  if (w == len && fflush(f) == 0 && !ferror(f)) return 0;
  if (!errno) errno = EIO;
  return -1;
}

const char *bg_path_ext(const char *path) {
  const char *slash = strrchr(path, '/');
  const char *dot = strrchr(path, '.');
  if (!dot || (slash && dot < slash)) return "";
  return dot + 1;
}
