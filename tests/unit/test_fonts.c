/* SPDX-License-Identifier: BSD-3-Clause */
/* The font configuration the renderers set up before pango's first use
 * when the program owns fontconfig (bg_fonts_own, surface_cairo.c) is the one FcInit would load, without the step FcInit
 * adds: the configuration files in effect are those of a configuration
 * parsed from the same file, no template of fontconfig's conf.avail folder
 * was parsed (FcInit parses them all, disabled, for their descriptions),
 * and the style fonts match the same font files as under a configuration
 * FcInit's way loads. */
#include <fontconfig/fontconfig.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "scene/scene.h"
#include "scene/surface.h"

/* Files parsed into cfg: applied (enabled) and only described (disabled). */
static void count_files(FcConfig *cfg, int *enabled, int *disabled) {
  FcConfigFileInfoIter it;
  *enabled = *disabled = 0;
  FcConfigFileInfoIterInit(cfg, &it);
  do {
    FcChar8 *name = NULL, *desc = NULL;
    FcBool on = FcFalse;
    if (!FcConfigFileInfoIterGet(cfg, &it, &name, &desc, &on)) break;
    ++*(on ? enabled : disabled);
    FcStrFree(name), FcStrFree(desc);
  } while (FcConfigFileInfoIterNext(cfg, &it));
}

/* The file fontconfig matches for family under cfg (the caller frees it). */
static char *match_file(FcConfig *cfg, const char *family) {
  FcPattern *p = FcNameParse((const FcChar8 *)family);
  FcConfigSubstitute(cfg, p, FcMatchPattern);
  FcDefaultSubstitute(p);
  FcResult r;
  FcPattern *m = FcFontMatch(cfg, p, &r);
  FcChar8 *file = NULL;
  char *out = NULL;
  if (m && FcPatternGetString(m, FC_FILE, 0, &file) == FcResultMatch) out = strdup((char *)file);
  if (m) FcPatternDestroy(m);
  FcPatternDestroy(p);
  return out;
}

int main(void) {
  bg_fonts_own(); /* as the bgdraw executable does */
  double w, h;
  bg_text_measure("DejaVu Sans", 11, "R<sub>1</sub>", &w, &h);
  OK(w > 0 && h > 0);
  FcConfig *cur = FcConfigGetCurrent();
  FcConfig *ref = FcConfigCreate();
  OK(FcConfigParseAndLoad(ref, NULL, FcTrue));
  int on, off, ref_on, ref_off;
  count_files(cur, &on, &off);
  count_files(ref, &ref_on, &ref_off);
  BG_T_REPORT(on > 0 && on == ref_on, "%d configuration files in effect, %d in the reference", on, ref_on);
  BG_T_REPORT(off == 0, "%d templates parsed for their descriptions", off);
  FcConfig *init = FcInitLoadConfigAndFonts(); /* FcInit's way, for the fonts */
  OK(init != NULL);
  static const char *const families[] = {"DejaVu Sans", "DejaVu Serif", "DejaVu Sans:bold",
                                         "DejaVu Sans:italic", "sans-serif", "monospace"};
  for (size_t i = 0; init && i < sizeof families / sizeof families[0]; i++) {
    char *a = match_file(cur, families[i]), *b = match_file(init, families[i]);
    BG_T_REPORT(a && b && !strcmp(a, b), "%s: %s here, %s under FcInit's configuration", families[i],
                a ? a : "nothing", b ? b : "nothing");
    free(a), free(b);
  }
  if (init) FcConfigDestroy(init);
  FcConfigDestroy(ref);
  return bg_t_done();
}
