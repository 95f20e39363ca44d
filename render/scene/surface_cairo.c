/* Scene replay with cairo and text with pango (through pangocairo). Text is
 * measured and drawn with the same settings — no hint metrics, no glyph
 * position rounding, 72 units per inch — so SVG, PDF and PNG agree with the
 * layout's idea of every label's size. */
#include "scene/surface_cairo.h"

#include <fontconfig/fontconfig.h>
#include <pango/pangocairo.h>
#include <string.h>

cairo_status_t bg_surface_sink(void *closure, const unsigned char *data, unsigned int len) {
  bg_sb_putn((bg_strbuf *)closure, (const char *)data, len);
  return CAIRO_STATUS_SUCCESS;
}

int bg_surface_close(cairo_t *cr, cairo_surface_t *sf) {
  cairo_status_t st = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(sf);
  if (st == CAIRO_STATUS_SUCCESS) st = cairo_surface_status(sf);
  cairo_surface_destroy(sf);
  return st == CAIRO_STATUS_SUCCESS ? 0 : -1;
}

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

static PangoFontMap *font_map(void) {
  static PangoFontMap *map;
  if (!map) {
    if (own_fonts) load_font_config();
    map = pango_cairo_font_map_get_default();
  }
  return map;
}

/* Font options free of the surface's defaults (hinting differs per backend). */
static cairo_font_options_t *neutral_font_options(void) {
  cairo_font_options_t *fo = cairo_font_options_create();
  cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
  return fo;
}

static void setup_context(PangoContext *ctx) {
  cairo_font_options_t *fo = neutral_font_options();
  pango_cairo_context_set_font_options(ctx, fo);
  cairo_font_options_destroy(fo);
  pango_cairo_context_set_resolution(ctx, 72);
  pango_context_set_round_glyph_positions(ctx, FALSE);
}

static PangoLayout *make_layout(PangoContext *ctx, const char *font, double size,
                                const char *markup) {
  PangoLayout *lay = pango_layout_new(ctx);
  PangoFontDescription *fd = pango_font_description_from_string(font);
  pango_font_description_set_absolute_size(fd, size * PANGO_SCALE);
  pango_layout_set_font_description(lay, fd);
  pango_font_description_free(fd);
  pango_layout_set_markup(lay, markup, -1);
  return lay;
}

static void layout_size(PangoLayout *lay, double *w, double *h) {
  PangoRectangle logical;
  pango_layout_get_extents(lay, NULL, &logical);
  *w = (double)logical.width / PANGO_SCALE;
  *h = (double)logical.height / PANGO_SCALE;
}

/* Measurements remembered for the process: a diagram measures every label,
 * and each redraw (the report's highlights) and each report table measures
 * the same strings again; pango's layout is the cost. Keyed by font, size
 * and markup; open addressing, grown at half full. */
typedef struct measured {
  char *font, *markup; /* g_strdup'd; markup NULL: empty slot */
  double size, w, h, base;
  unsigned char has_size, has_base; /* which of w, h and base are known */
} measured;
static measured *memo;
static size_t memo_cap, memo_n;

static size_t key_hash(const char *font, double size, const char *markup) { /* FNV-1a */
  size_t h = 1469598103934665603u;
  for (const char *s = font; *s; s++) h = (h ^ (unsigned char)*s) * 1099511628211u;
  h = (h ^ (size_t)(size * 64)) * 1099511628211u;
  for (const char *s = markup; *s; s++) h = (h ^ (unsigned char)*s) * 1099511628211u;
  return h;
}

static measured *memo_slot(measured *tab, size_t cap, const char *font, double size,
                           const char *markup) {
  size_t i = key_hash(font, size, markup) & (cap - 1);
  while (tab[i].markup &&
         (tab[i].size != size || strcmp(tab[i].markup, markup) || strcmp(tab[i].font, font)))
    i = (i + 1) & (cap - 1);
  return &tab[i];
}

static void memo_grow(void) {
  size_t cap = memo_cap ? 2 * memo_cap : 1024;
  measured *tab = g_new0(measured, cap);
  for (size_t i = 0; i < memo_cap; i++)
    if (memo[i].markup) *memo_slot(tab, cap, memo[i].font, memo[i].size, memo[i].markup) = memo[i];
  g_free(memo);
  memo = tab, memo_cap = cap;
}

/* The entry of (font, size, markup), made when missing. */
static measured *memo_entry(const char *font, double size, const char *markup) {
  if (2 * (memo_n + 1) > memo_cap) memo_grow();
  measured *m = memo_slot(memo, memo_cap, font, size, markup);
  if (!m->markup) m->font = g_strdup(font), m->markup = g_strdup(markup), m->size = size, memo_n++;
  return m;
}

/* One measuring context for the process; surfaces get their own contexts
 * with the same settings. */
void bg_text_measure(const char *font, double size, const char *markup, double *w, double *h) {
  static PangoContext *ctx;
  if (!ctx) {
    ctx = pango_font_map_create_context(font_map());
    setup_context(ctx);
  }
  measured *m = memo_entry(font, size, markup);
  if (!m->has_size) {
    PangoLayout *lay = make_layout(ctx, font, size, markup);
    layout_size(lay, &m->w, &m->h);
    g_object_unref(lay);
    m->has_size = 1;
  }
  *w = m->w, *h = m->h;
}

/* The baseline of markup's first line below the top of its logical box, in
 * points (the SVG writer places <text> by its baseline); remembered beside
 * the size, as every text item of a diagram asks once more when it is
 * written (a third of the SVG's instructions at 50 000 bonds). */
double bg_text_baseline(const char *font, double size, const char *markup) {
  static PangoContext *ctx;
  if (!ctx) {
    ctx = pango_font_map_create_context(font_map());
    setup_context(ctx);
  }
  measured *m = memo_entry(font, size, markup);
  if (!m->has_base) {
    PangoLayout *lay = make_layout(ctx, font, size, markup);
    m->base = (double)pango_layout_get_baseline(lay) / PANGO_SCALE;
    g_object_unref(lay);
    m->has_base = 1;
  }
  return m->base;
}

static void set_color(cairo_t *cr, bg_rgba c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }

static void replay_path(cairo_t *cr, const bg_scene *s, const bg_scene_item *it) {
  cairo_new_path(cr);
  for (int i = 0; i < it->nop; i++) {
    const bg_scene_op *o = &s->op[it->opadr + i];
    switch (o->code) {
    case BG_OP_MOVE: cairo_move_to(cr, o->x[0], o->y[0]); break;
    case BG_OP_LINE: cairo_line_to(cr, o->x[0], o->y[0]); break;
    case BG_OP_CURVE:
      cairo_curve_to(cr, o->x[0], o->y[0], o->x[1], o->y[1], o->x[2], o->y[2]);
      break;
    default: cairo_close_path(cr); break;
    }
  }
}

static void set_line(cairo_t *cr, const bg_scene_item *it) {
  cairo_set_line_width(cr, it->width);
  cairo_set_line_cap(cr, it->round ? CAIRO_LINE_CAP_ROUND : CAIRO_LINE_CAP_BUTT);
  cairo_set_line_join(cr, it->round ? CAIRO_LINE_JOIN_ROUND : CAIRO_LINE_JOIN_MITER);
  if (it->dash[0] > 0) cairo_set_dash(cr, it->dash, 2, 0);
  else cairo_set_dash(cr, NULL, 0, 0);
}

static void replay_shape(cairo_t *cr, const bg_scene *s, const bg_scene_item *it) {
  replay_path(cr, s, it);
  set_line(cr, it);
  if (it->kind == BG_ITEM_FILL) {
    set_color(cr, it->fill);
    if (it->width > 0) {
      cairo_fill_preserve(cr);
      set_color(cr, it->color);
      cairo_stroke(cr);
    } else {
      cairo_fill(cr);
    }
  } else {
    set_color(cr, it->color);
    cairo_stroke(cr);
  }
}

static void replay_text(cairo_t *cr, PangoContext *ctx, const bg_scene *s,
                        const bg_scene_item *it) {
  PangoLayout *lay = make_layout(ctx, s->font, it->size, it->text);
  double w, h;
  layout_size(lay, &w, &h);
  set_color(cr, it->color);
  cairo_move_to(cr, it->x - it->halign * w, it->y - it->valign * h);
  pango_cairo_show_layout(cr, lay);
  g_object_unref(lay);
}

static void replay_items(cairo_t *cr, const bg_scene *s, const double *clip) {
  cairo_font_options_t *fo = neutral_font_options();
  cairo_set_font_options(cr, fo);
  cairo_font_options_destroy(fo);
  font_map(); /* pango_cairo_create_context takes the default map */
  PangoContext *ctx = pango_cairo_create_context(cr);
  setup_context(ctx);
  set_color(cr, s->background);
  cairo_paint(cr);
  for (int i = 0; i < s->nitem; i++) {
    const bg_scene_item *it = &s->item[i];
    if (clip) {
      double b[4];
      bg_scene_item_box(s, it, b);
      if (b[2] < clip[0] || b[0] > clip[2] || b[3] < clip[1] || b[1] > clip[3]) continue;
    }
    if (it->kind == BG_ITEM_TEXT) replay_text(cr, ctx, s, it);
    else replay_shape(cr, s, it);
  }
  g_object_unref(ctx);
}

const char *bg_surface_cairo_version(void) { return CAIRO_VERSION_STRING; }
const char *bg_surface_pango_version(void) { return PANGO_VERSION_STRING; }

void bg_surface_replay(cairo_t *cr, const bg_scene *s) { replay_items(cr, s, NULL); }

void bg_surface_replay_clipped(cairo_t *cr, const bg_scene *s, const double clip[4]) {
  replay_items(cr, s, clip);
}
