/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzz target: the run's load as the program does it, so a BondGraphTools
 * YAML input goes through the import stage (libyaml, the reader, the .bg
 * text and its line map), then causality and analysis; a .bg input is
 * parsed as usual. Write-back to YAML runs on every model that loads. */
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "import/import.h"
#include "run/run.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > FUZZ_MAX_LEN) return 0;
  char *text = malloc(size + 1);
  if (!text) return 0;
  memcpy(text, data, size);
  text[size] = 0;
  bg_run *r = bg_run_new(NULL);
  if (bg_run_load(r, "fuzz.yaml", text, size) == 0) { /* the run owns text now */
    bg_run_need(r, BG_STAGE_ANALYSIS);
    bg_strbuf sb = {0};
    free(bg_bgt_write(r->model, &sb));
    bg_sb_free(&sb);
  }
  bg_run_free(r);
  return 0;
}
