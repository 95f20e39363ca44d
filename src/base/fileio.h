/* Atomic output files: write to a temporary file beside the target, then
 * rename, so a failed run never leaves a half-written output. */
#ifndef BG_FILEIO_H
#define BG_FILEIO_H
#include <stddef.h>

/* Writes len bytes to path atomically. Returns 0, or -1 with errno set. */
int bg_write_file_atomic(const char *path, const void *data, size_t len);

/* For writers that need a file name (cairo surfaces): a temporary path beside
 * `path` (caller frees), to be renamed with bg_atomic_commit or removed with
 * bg_atomic_abort. */
char *bg_atomic_tmp_path(const char *path);
int bg_atomic_commit(const char *tmp, const char *path); /* 0 or -1 (errno) */
void bg_atomic_abort(const char *tmp);
/* The extension of path without the dot ("svg"), or "" */
const char *bg_path_ext(const char *path);
#endif
