/* SPDX-License-Identifier: BSD-3-Clause */
/* Internal to src/simulate*.c: solver failure flags in plain words. */
#ifndef BG_SIMULATE_WORDS_H
#define BG_SIMULATE_WORDS_H
#include "base/strbuf.h"

/* Appends what a CVODE (ida 0) or IDA (ida 1) failure flag usually means for
 * a bond graph. evalerr: the last equation evaluation failure, or NULL. */
void bg_sim_explain(int ida, int flag, const char *evalerr, bg_strbuf *sb);
#endif
