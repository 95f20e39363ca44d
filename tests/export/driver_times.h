/* SPDX-License-Identifier: BSD-3-Clause */
/* What the export test drivers (driver.c, events_driver.c) share: the output
 * times, read from the first column of a bgdraw CSV (comment lines skipped),
 * so a driver writes its rows where bgdraw's run wrote them. */
#ifndef BG_TEST_DRIVER_TIMES_H
#define BG_TEST_DRIVER_TIMES_H
#include <stdio.h>
#include <stdlib.h>

static double times[200000];
static int ntimes;

/* 0 when the CSV gave at least two times. */
static int read_times(const char *csv) {
  FILE *f = fopen(csv, "r");
  char line[65536];
  if (!f || !fgets(line, sizeof line, f)) {
    if (f) fclose(f);
    return -1;
  }
  while (ntimes < 200000 && fgets(line, sizeof line, f))
    if (line[0] != '#') times[ntimes++] = strtod(line, NULL);
  fclose(f);
  return ntimes > 1 ? 0 : -1;
}
#endif
