/* SPDX-License-Identifier: BSD-3-Clause */
/* Simulation results as CSV (docs/simulation.md): header "t,<names>", one row per output
 * time, numbers in the shortest form that reads back exactly (bg_sb_num),
 * identical on every run.
 * A name with a comma, quote or newline (a plot expression such as
 * "max(a, b)") is quoted CSV-style, with inner quotes doubled. A partial run
 * (the solver failed) ends with one comment line "# partial: <message>":
 * spreadsheet and pandas readers skip or flag it (pandas: comment='#'), and a
 * reader that ignores it still gets every complete row. */
#include <stdio.h>
#include <string.h>

#include "simulate/simulate.h"

static void put_name(bg_strbuf *out, const char *s) {
  if (!strpbrk(s, ",\"\n\r")) { bg_sb_puts(out, s); return; }
  bg_sb_putc(out, '"');
  for (; *s; s++) {
    if (*s == '"') bg_sb_putc(out, '"');
    bg_sb_putc(out, *s);
  }
  bg_sb_putc(out, '"');
}

/* The message on one line: newlines would start a row. */
static void put_comment(bg_strbuf *out, const char *msg) {
  bg_sb_puts(out, "# partial: ");
  for (; msg && *msg; msg++) bg_sb_putc(out, *msg == '\n' || *msg == '\r' ? ' ' : *msg);
  bg_sb_putc(out, '\n');
}

void bg_csv_write(const bg_simresult *r, bg_strbuf *out) {
  bg_sb_puts(out, "t");
  for (int k = 0; k < r->nout; k++) {
    bg_sb_putc(out, ',');
    put_name(out, r->names[k] ? r->names[k] : "");
  }
  bg_sb_putc(out, '\n');
  for (int i = 0; i < r->nrows; i++) {
    bg_sb_num(out, r->t[i]);
    for (int k = 0; k < r->nout; k++) {
      bg_sb_putc(out, ',');
      bg_sb_num(out, r->values[(size_t)i * (size_t)r->nout + (size_t)k]);
    }
    bg_sb_putc(out, '\n');
  }
  if (r->partial) put_comment(out, r->message ? r->message : "the simulation stopped early");
}
