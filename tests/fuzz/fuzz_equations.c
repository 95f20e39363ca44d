/* Fuzz target: the equations (every printed form, the reduced form), the
 * numeric index of small systems, and the analysis JSON (fuzz_common.h). */
#include "equations/eqprint.h"
#include "equations/eqsym.h"
#include "equations/eqsys.h"
#include "equations/index.h"
#include "fuzz_common.h"
#include "json/json.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > FUZZ_MAX_LEN) return 0;
  fuzz_run f;
  if (fuzz_load(&f, data, size) == 0) {
    bg_eqsys *s = fuzz_eqsys(&f, size);
    bg_strbuf sb = {0};
    if (s) {
      static const char *const forms[] = {"text", "latex", "c", "json"};
      for (int i = 0; i < 4; i++) bg_eqprint(s, forms[i], &sb);
      if (bg_eqsys_n(s) <= 40) { /* the dense index is cubic: keep runs short */
        bg_index_result ix;
        bg_index_compute(s, f.model, &ix);
        f.analysis.index_numeric_set = ix.index != BG_INDEX_FAILED;
        f.analysis.index_numeric = ix.index;
        bg_index_free(&ix);
      }
    }
    bg_json_write_analysis(f.model, &f.analysis, &sb);
    bg_sb_free(&sb);
    if (s) bg_eqsys_free(s);
  }
  fuzz_free(&f);
  return 0;
}
