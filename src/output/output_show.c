/* SPDX-License-Identifier: BSD-3-Clause */
/* --show lists, for the command line and the library alike: overlays add to
 * the default layers, a base layer (strokes, numbers, labels, all, none)
 * makes the list the whole set; +LAYER always adds. */
#include <stdlib.h>
#include <string.h>

#include "output/output.h"

static const char *const layer_words[] = {"strokes", "numbers", "paths",  "loops",
                                          "conflicts", "signals", "labels", "legend",
                                          "variables", "all", "none", NULL};
static const char *const base_words[] = {"strokes", "numbers", "labels", "all", "none", NULL};

static int word_in(const char *w, const char *const *list) {
  for (int i = 0; list[i]; i++)
    if (!strcmp(w, list[i])) return 1;
  return 0;
}

static void unknown_layer(const char *w, const char *list, bg_strbuf *err) {
  const char *best = NULL;
  int bestd = 3;
  for (int i = 0; layer_words[i]; i++) {
    int d = bg_edit_distance(w, layer_words[i]);
    if (d < bestd) bestd = d, best = layer_words[i];
  }
  bg_sb_printf(err, "unknown layer '%s' in --show '%s'", w, list);
  if (best) bg_sb_printf(err, " (did you mean '%s'?)", best);
  bg_sb_puts(err, "\n  layers: strokes, numbers, paths, loops, conflicts, signals, labels, legend, "
                  "variables; or all, none; +LAYER adds to the default");
}

int bg_output_parse_show(const char *list, unsigned *bits, bg_strbuf *err) {
  bg_strbuf plain = {0};
  int replaces = 0;
  char *copy = strdup(list), *save = NULL;
  for (char *w = strtok_r(copy, ",", &save); w; w = strtok_r(NULL, ",", &save)) {
    while (*w == ' ') w++;
    for (size_t n = strlen(w); n && w[n - 1] == ' '; n--) w[n - 1] = '\0';
    int plus = *w == '+';
    if (plus) w++;
    if (!word_in(w, layer_words)) {
      unknown_layer(w, list, err);
      free(copy), bg_sb_free(&plain);
      return -1;
    }
    replaces |= !plus && word_in(w, base_words);
    bg_sb_printf(&plain, "%s%s", plain.len ? "," : "", w);
  }
  free(copy);
  unsigned b = 0;
  bg_show_parse(bg_sb_str(&plain), &b); /* every word was checked above */
  bg_sb_free(&plain);
  if (!replaces) b = (b & ~(1u << 31)) | BG_SHOW_DEFAULT;
  *bits = b;
  return 0;
}
