/* SPDX-License-Identifier: BSD-3-Clause */
/* Text metrics with pango (through pangocairo), and the pango set-up the
 * cairo surfaces share: text is measured and drawn with the same settings
 * (no hint metrics, no glyph position rounding, 72 units per inch), so SVG,
 * PDF and PNG agree with the layout's idea of every label's size. Scene code
 * measures through here and never calls into the surfaces.
 *
 * Thread safety: pango objects may not be used by two threads at once, cairo
 * shares its fonts' caches between surfaces, and the measurements are
 * remembered for the process. One lock (text_lock) guards the font map, the
 * measuring context and the memo, and the surfaces hold it from creating a
 * cairo surface to finishing it (bg_text_lock). */
#include "scene/text_int.h"

#include <fontconfig/fontconfig.h>
#include <pthread.h>
#include <string.h>

#include "base/arena.h"
#include "scene/scene.h"
#include "scene/surface.h"

static pthread_mutex_t text_lock = PTHREAD_MUTEX_INITIALIZER;

void bg_text_lock(void) { pthread_mutex_lock(&text_lock); }
void bg_text_unlock(void) { pthread_mutex_unlock(&text_lock); }

/* The font map, with fontconfig's configuration loaded as FcInit would load
 * it but for one step: FcInit also parses every template in fontconfig's
 * conf.avail folder, disabled, for the descriptions only fc-conflist shows
 * (10 M of a small diagram's 64 M instructions; pango starts FcInit in a
 * thread when its font map is made). Here the same
 * configuration file (FONTCONFIG_FILE or the system's fonts.conf, with its
 * includes) is parsed into a config that becomes fontconfig's current one
 * before pango asks, so fonts, rules and caches are the same. When that
 * fails, or the configuration names no cache folder (FcInit would then add
 * fallbacks), fontconfig is left to FcInit. Only when the program asked
 * for it (bg_fonts_own): setting the current configuration would replace
 * one a host program of libbgdraw already uses. */
static void load_font_config(void) {
  FcConfig *cfg = FcConfigCreate();
  if (!cfg) return;
  FcStrList *caches = NULL;
  int ok = FcConfigParseAndLoad(cfg, NULL, FcTrue) && (caches = FcConfigGetCacheDirs(cfg)) &&
           FcStrListNext(caches) && FcConfigBuildFonts(cfg);
  if (caches) FcStrListDone(caches);
  /* the current config keeps it (fontconfig >= 2.13.9x holds a reference,
   * older ones the pointer): not destroyed when it was taken */
  if (!ok || !FcConfigSetCurrent(cfg)) FcConfigDestroy(cfg);
}

static int own_fonts;

void bg_fonts_own(void) { own_fonts = 1; }

/* The caller holds text_lock. When the program owns fontconfig, the font
 * map's own resolution is set to the 72 units per inch every context here
 * is set to: pango 1.50 measures a font's metrics (the first time a layout
 * asks for them) in a fresh context of the font map, at the map's resolution
 * (96 by default), so each font size was matched by fontconfig twice, once
 * for each resolution, each match in two threads of pango's own (13
 * threads for rlc instead of 7, 16 % of a small diagram's instructions).
 * Those metrics are of the font at its absolute size, the same at either
 * resolution: every example's SVG, PDF, PNG, plot and report in every
 * style is byte-identical. A host program of libbgdraw keeps its default
 * map's resolution. */
PangoFontMap *bg_text_font_map(void) {
  static PangoFontMap *map;
  if (!map) {
    if (own_fonts) load_font_config();
    map = pango_cairo_font_map_get_default();
    if (own_fonts) pango_cairo_font_map_set_resolution(PANGO_CAIRO_FONT_MAP(map), 72);
  }
  return map;
}

/* Font options free of the surface's defaults (hinting differs per backend). */
cairo_font_options_t *bg_text_font_options(void) {
  cairo_font_options_t *fo = cairo_font_options_create();
  cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
  return fo;
}

void bg_text_setup_context(PangoContext *ctx) {
  cairo_font_options_t *fo = bg_text_font_options();
  pango_cairo_context_set_font_options(ctx, fo);
  cairo_font_options_destroy(fo);
  pango_cairo_context_set_resolution(ctx, 72);
  pango_context_set_round_glyph_positions(ctx, FALSE);
}

PangoLayout *bg_text_layout(PangoContext *ctx, const char *font, double size,
                            const char *markup) {
  PangoLayout *lay = pango_layout_new(ctx);
  PangoFontDescription *fd = pango_font_description_from_string(font);
  pango_font_description_set_absolute_size(fd, size * PANGO_SCALE);
  pango_layout_set_font_description(lay, fd);
  pango_font_description_free(fd);
  pango_layout_set_markup(lay, markup, -1);
  return lay;
}

void bg_text_layout_size(PangoLayout *lay, double *w, double *h) {
  PangoRectangle logical;
  pango_layout_get_extents(lay, NULL, &logical);
  *w = (double)logical.width / PANGO_SCALE;
  *h = (double)logical.height / PANGO_SCALE;
}

/* Measurements remembered for the process (under text_lock): a diagram measures every label,
 * and each redraw (the report's highlights) and each report table measures
 * the same strings again; pango's layout is the cost. Keyed by font, size
 * and markup. A 100 000-mass chain has a million distinct labels, so the
 * memo is kept compact: the entries in one array, an open-addressing table
 * of their indices (grown at half full), the markup in an arena and each
 * font once (an entry of 48 bytes and a slot of 4, where a table of whole
 * entries and two strdups a label were a sixth of the SVG's memory). */
typedef struct measured {
  const char *markup; /* in memo_text */
  double size, w, h, base;
  unsigned font;      /* index into memo_fonts */
  unsigned char has_size, has_base; /* which of w, h and base are known */
} measured;
static measured *memo;               /* the entries, memo_n of them */
static size_t memo_n, memo_capn;
static unsigned *memo_slot_of;       /* per slot: entry index + 1, 0 empty */
static size_t memo_nslot;
static bg_arena memo_text;
static char **memo_fonts;
static unsigned memo_nfont;

static size_t key_hash(unsigned font, double size, const char *markup) { /* FNV-1a */
  size_t h = 1469598103934665603u;
  h = (h ^ font) * 1099511628211u;
  h = (h ^ (size_t)(size * 64)) * 1099511628211u;
  for (const char *s = markup; *s; s++) h = (h ^ (unsigned char)*s) * 1099511628211u;
  return h;
}

/* The index of font among the fonts seen (added when new). */
static unsigned font_index(const char *font) {
  for (unsigned i = 0; i < memo_nfont; i++)
    if (!strcmp(memo_fonts[i], font)) return i;
  memo_fonts = bg_xrealloc(memo_fonts, (memo_nfont + 1) * sizeof *memo_fonts);
  memo_fonts[memo_nfont] = bg_arena_strdup(&memo_text, font);
  return memo_nfont++;
}

/* The slot of (font, size, markup): its entry's, or the empty one where it goes. */
static unsigned *memo_slot(unsigned font, double size, const char *markup) {
  size_t i = key_hash(font, size, markup) & (memo_nslot - 1);
  for (;; i = (i + 1) & (memo_nslot - 1)) {
    unsigned k = memo_slot_of[i];
    if (!k) return &memo_slot_of[i];
    const measured *m = &memo[k - 1];
    if (m->size == size && m->font == font && !strcmp(m->markup, markup)) return &memo_slot_of[i];
  }
}

static void memo_grow(void) {
  size_t nslot = memo_nslot ? 2 * memo_nslot : 1024;
  free(memo_slot_of);
  memo_slot_of = bg_xcalloc(nslot, sizeof *memo_slot_of);
  memo_nslot = nslot;
  for (size_t i = 0; i < memo_n; i++)
    *memo_slot(memo[i].font, memo[i].size, memo[i].markup) = (unsigned)i + 1;
}

/* The entry of (font, size, markup), made when missing. */
static measured *memo_entry(const char *font, double size, const char *markup) {
  if (2 * (memo_n + 1) > memo_nslot) memo_grow();
  unsigned f = font_index(font);
  unsigned *slot = memo_slot(f, size, markup);
  if (*slot) return &memo[*slot - 1];
  if (memo_n == memo_capn) {
    memo_capn = memo_capn ? 2 * memo_capn : 512;
    memo = bg_xrealloc(memo, memo_capn * sizeof *memo);
  }
  measured *m = &memo[memo_n++];
  memset(m, 0, sizeof *m);
  m->markup = bg_arena_strdup(&memo_text, markup), m->size = size, m->font = f;
  *slot = (unsigned)memo_n;
  return m;
}

/* One measuring context for the process; surfaces get their own contexts
 * with the same settings. The caller holds text_lock. */
static PangoContext *measuring_context(void) {
  static PangoContext *ctx;
  if (!ctx) {
    ctx = pango_font_map_create_context(bg_text_font_map());
    bg_text_setup_context(ctx);
  }
  return ctx;
}

void bg_text_measure(const char *font, double size, const char *markup, double *w, double *h) {
  pthread_mutex_lock(&text_lock);
  PangoContext *ctx = measuring_context();
  measured *m = memo_entry(font, size, markup);
  if (!m->has_size) {
    PangoLayout *lay = bg_text_layout(ctx, font, size, markup);
    bg_text_layout_size(lay, &m->w, &m->h);
    /* the baseline too, while the lines are laid out: every text item of
     * an SVG asks for it, and a second layout doubled the cost of each
     * distinct label (a 100 000-mass chain has a million) */
    m->base = (double)pango_layout_get_baseline(lay) / PANGO_SCALE;
    g_object_unref(lay);
    m->has_size = m->has_base = 1;
  }
  *w = m->w, *h = m->h;
  pthread_mutex_unlock(&text_lock);
}

/* The baseline of markup's first line below the top of its logical box, in
 * points (the SVG writer places <text> by its baseline); remembered beside
 * the size, as every text item of a diagram asks once more when it is
 * written (a third of the SVG's instructions at 50 000 bonds). */
double bg_text_baseline(const char *font, double size, const char *markup) {
  pthread_mutex_lock(&text_lock);
  PangoContext *ctx = measuring_context();
  measured *m = memo_entry(font, size, markup);
  if (!m->has_base) {
    PangoLayout *lay = bg_text_layout(ctx, font, size, markup);
    m->base = (double)pango_layout_get_baseline(lay) / PANGO_SCALE;
    g_object_unref(lay);
    m->has_base = 1;
  }
  double base = m->base;
  pthread_mutex_unlock(&text_lock);
  return base;
}
