/* SPDX-License-Identifier: BSD-3-Clause */
/* Files: bounded reads of the inputs (remembered by device and inode, so no
 * output can replace one), and outputs that never damage what they point at
 * (docs/cli.md, "Output files").
 *
 * Process-wide state, on purpose, each behind a lock so runs on several
 * threads may call every function here at once:
 * - the set of inputs is the process's, not a run's: a program with several
 *   runs refuses to write over a file any of them read (a stricter check,
 *   never a weaker one), and the readers (parser, flattening, styles) need no
 *   run handed down to them;
 * - the signal clean-up (SIGINT, SIGTERM, SIGHUP remove the temporary file of
 *   an atomic write) is the process's because signal handlers are: one
 *   temporary file exists at a time, so atomic writes take turns;
 * - bg_fileio_set_before_rename_hook is a test hook for the whole process.
 *
 * Every function reports failure as -1 / NULL with errno set; errno may be
 * one of bgdraw's own codes below, so print it with bg_file_strerror, not
 * strerror. */
#ifndef BG_FILEIO_H
#define BG_FILEIO_H
#include <stddef.h>
#include <stdio.h>

#include "base/strbuf.h"

/* The largest input file (model, table, style) bgdraw reads: 64 MiB. */
#define BG_INPUT_MAX_BYTES ((size_t)64 << 20)

/* bgdraw's own errno values (beyond the system's), for bg_file_strerror. */
enum {
  BG_ENOTREG = 100001, /* an input that is not a regular file (FIFO, device, ...) */
  BG_ETOOBIG,          /* an input larger than BG_INPUT_MAX_BYTES */
  BG_EISINPUT,         /* an output that is one of the run's inputs */
  BG_EBLOCKDEV         /* an output that is a block device */
};
/* strerror for the system's errno values and bgdraw's own. */
const char *bg_file_strerror(int err);

/* ------------------------------------------------------------------ inputs */
/* Reads a whole regular file (at most BG_INPUT_MAX_BYTES) into a
 * NUL-terminated buffer the caller frees, and remembers its device and inode
 * as an input of this run. NULL with errno set (BG_ENOTREG, BG_ETOOBIG,
 * EISDIR, ENOENT, ...) when it cannot. */
char *bg_read_file(const char *path, size_t *len);
/* The same for an open stream (stdin), with the same size limit. */
char *bg_read_stream(FILE *f, size_t *len);
/* Remembers an existing file as an input without reading it (a style file
 * read later); a path that does not exist is ignored. */
void bg_input_note(const char *path);
/* 1 if path (following symlinks) is a file this run read or noted. */
int bg_path_is_input(const char *path);

/* ----------------------------------------------------------------- outputs */
/* Writes len bytes to path without ever damaging what it points at:
 * - a regular file (or a new name) is replaced atomically: the bytes go to a
 *   mkstemp file in the target's directory, get the target's mode (or the
 *   umask's default for a new file), and are renamed onto it; a failed write
 *   leaves the old file as it was, and SIGINT/SIGTERM/SIGHUP remove the
 *   temporary file;
 * - a symlink is followed: its final target is written (atomically when
 *   regular) and the link stays;
 * - a character device, FIFO, terminal or socket is written in place;
 * - /dev/stdout, /dev/stderr, /dev/fd/N and /proc/self/fd/N are written
 *   through the descriptor the process has open (a pipe gets the bytes, a
 *   shell's `>> file` appends);
 * - a block device, a directory or one of the run's inputs is refused
 *   (BG_EBLOCKDEV, EISDIR, BG_EISINPUT).
 * Returns 0, or -1 with errno set. */
int bg_write_file_atomic(const char *path, const void *data, size_t len);
/* An output written to its file while it is made (a 100 000-mass SVG is
 * 500 MB of text, which bg_write_file_atomic needs whole in memory): a
 * strbuf sink (strbuf.h) that goes where bg_write_file_atomic would put the
 * whole text, with the same guarantees.
 *     bg_stream st;
 *     bg_stream_begin(&st, &sb, path);      // sb: an empty strbuf
 *     int ok = writer(&sb) == 0;            // appends only
 *     if (bg_stream_finish(&st, &sb, ok) != 0) report errno;
 * Text under BG_STREAM_CHUNK bytes is written by bg_stream_finish with
 * bg_write_file_atomic, exactly as before. Past that, the first piece decides:
 * - a regular file or a new name gets its temporary file now and every piece
 *   as it comes; bg_stream_finish renames it onto the target when the writer
 *   succeeded, and removes it when the writer or a write failed, leaving the
 *   old file as it was (SIGINT/SIGTERM/SIGHUP remove it too). Atomic writes
 *   take turns (one temporary file at a time), so another thread's
 *   bg_write_file_atomic waits until this one is finished, and the writer
 *   itself must write no other file;
 * - any other target (device, FIFO, socket, /dev/stdout, /dev/fd/N) gets
 *   the whole text at the end, as from bg_write_file_atomic (the strbuf keeps
 *   it);
 * - a refused target (an input, a directory, a block device) or a temporary
 *   file that cannot be made: the text is dropped and bg_stream_finish
 *   reports the error, as bg_write_file_atomic would have after the writer. */
#define BG_STREAM_CHUNK ((size_t)1 << 20)
typedef struct bg_stream {
  bg_sb_sink sink; /* first: the strbuf's sink */
  const char *path; /* borrowed until bg_stream_finish */
  char *target, *tmp;
  int fd;           /* the temporary file, or -1 */
} bg_stream;
void bg_stream_begin(bg_stream *st, bg_strbuf *b, const char *path);
/* ok: the writer succeeded. Writes the rest and renames, or (not ok, or a
 * write failed) removes the temporary file. Detaches the sink from b; the
 * bytes written are then in *bytes (nullable). 0, or -1 with errno set (a
 * failed write or a refused target; not ok alone returns 0). */
int bg_stream_finish(bg_stream *st, bg_strbuf *b, int ok, size_t *bytes);
/* Follows symlinks at the last component of path, as bg_write_file_atomic
 * does: the name the bytes go to (which may not exist yet, e.g. a dangling
 * link's target) in a buffer the caller frees, or NULL (ELOOP, ...). */
char *bg_resolve_links(const char *path);
/* Writes len bytes to an open stream (stdout) and flushes it: 0, or -1 with
 * errno set on any write error (ENOSPC on /dev/full, EPIPE, ...). */
int bg_write_stream(FILE *f, const void *data, size_t len);

/* For tests of the signal clean-up: called with the temporary file's path
 * after its bytes are written and before the rename (NULL: none). */
void bg_fileio_set_before_rename_hook(void (*hook)(const char *tmp));

/* The extension of path without the dot ("svg"), or "" */
const char *bg_path_ext(const char *path);
#endif
