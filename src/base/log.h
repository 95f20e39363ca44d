/* SPDX-License-Identifier: BSD-3-Clause */
/* The engine's messages to whoever runs it: progress under -v, notes and
 * warnings about results. The engine never writes to stderr itself: a front
 * end (the command line, the library's caller) gives a sink; a NULL sink or a
 * NULL function is silence. */
#ifndef BG_LOG_H
#define BG_LOG_H

typedef enum bg_log_level {
  BG_LOG_PROGRESS, /* what runs now, with numbers (-v) */
  BG_LOG_DETAIL,   /* more of it: solver messages (-vv) */
  BG_LOG_INFO,     /* a result in words (--verify's summary) */
  BG_LOG_NOTE,     /* something the user may want to know */
  BG_LOG_WARNING   /* a result that may not be what the user thinks */
} bg_log_level;

typedef void (*bg_log_fn)(void *ctx, bg_log_level level, const char *msg);

typedef struct bg_log {
  bg_log_fn fn;
  void *ctx;
  int verbose; /* 1: PROGRESS is wanted, 2: DETAIL too; INFO and above always go to fn */
} bg_log;

/* Whether a message of this level reaches the sink (so a caller can skip
 * building an expensive message). */
int bg_log_on(const bg_log *l, bg_log_level level);
/* One message (no trailing newline; the sink adds what its medium needs). */
void bg_logf(const bg_log *l, bg_log_level level, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
#endif
