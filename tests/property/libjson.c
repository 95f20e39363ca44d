/* SPDX-License-Identifier: BSD-3-Clause */
/* prop_libjson MODEL.bg OUT.json OUT.csv: the property campaign's library route
 * (docs/property.md). Opens the model with libbgdraw, simulates it and writes
 * the analysis JSON and the CSV as the library gives them, so check.py can
 * compare them byte for byte with `bgdraw MODEL.bg --simulate -o OUT.json -o
 * OUT.csv`. Exit status: 0 both written, 1 the model has errors, 3 the
 * simulation failed (the JSON is still written, and the CSV of the rows up to
 * the failure when the library gives it), 4 an output failed. */
#include <bgdraw.h>
#include <stdio.h>
#include <stdlib.h>

static int put(bgd_model *m, const char *kind, const char *path) {
  char *data = NULL;
  size_t len = 0;
  if (bgd_output(m, kind, NULL, &data, &len) != BGD_OK) {
    const char *why = bgd_last_error(m);
    fprintf(stderr, "prop_libjson: %s: %s\n", kind, why ? why : "failed");
    return 0;
  }
  FILE *f = fopen(path, "wb");
  int ok = f && fwrite(data, 1, len, f) == len;
  if (f && fclose(f) != 0) ok = 0;
  free(data);
  return ok;
}

int main(int argc, char **argv) {
  if (argc != 4) {
    fputs("usage: prop_libjson MODEL.bg OUT.json OUT.csv\n", stderr);
    return 2;
  }
  bgd_options o;
  bgd_options_init(&o);
  bgd_model *m = bgd_open_file(argv[1], &o);
  if (bgd_status(m) != BGD_OK) {
    bgd_free(m);
    return 1;
  }
  bgd_simulation s;
  int sim = bgd_simulate(m, &s);
  int rc = put(m, "json", argv[2]) ? 0 : 4;
  /* a failed simulation still gives the rows up to where it stopped, as the
   * command line writes them (exit status 3) */
  if (rc == 0 && !put(m, "csv", argv[3]) && sim == BGD_OK) rc = 4;
  if (rc == 0 && sim != BGD_OK) rc = 3;
  bgd_free(m);
  return rc;
}
