/* SPDX-License-Identifier: BSD-3-Clause */
/* How command-line options combine: an option that would be ignored, or two
 * outputs that both want stdout, is a usage error with a hint (docs/cli.md). */
#ifndef BG_CLI_USAGE_H
#define BG_CLI_USAGE_H
#include "cli/cli_opts.h"

/* Prints "bgdraw: error: " fmt (with a and b) and the --help hint; returns -1. */
int bg_cli_usage_error(const char *fmt, const char *a, const char *b);
/* Checks values and combinations, resolves every output's format (-T), and
 * adds the stdout output of -T with no -o. 0, or -1 after a message. */
int bg_cli_check_usage(bg_cli_opts *o);
#endif
