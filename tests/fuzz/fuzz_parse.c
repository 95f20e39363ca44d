/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzz target: parse + compile + causality + analysis (fuzz_common.h). */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > FUZZ_MAX_LEN) return 0;
  fuzz_run f;
  fuzz_load(&f, data, size);
  fuzz_free(&f);
  return 0;
}
