/* SPDX-License-Identifier: BSD-3-Clause */
/* Style files: `key = value` lines, `#` comments, applied over the default. */
#include "scene/style.h"

#include <ctype.h>
#include <errno.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/arena.h"
#include "base/fileio.h"

typedef enum { K_STR, K_NUM, K_COLOR, K_BOOL, K_HARPOON, K_COLORS } key_type;

typedef struct style_key {
  const char *name;
  key_type type;
  size_t off;
} style_key;

#define KEY(n, t, f) {n, t, offsetof(bg_style, f)}
static const style_key keys[] = {
    KEY("font", K_STR, font),
    KEY("font_size", K_NUM, font_size),
    KEY("number_scale", K_NUM, number_scale),
    KEY("line_width", K_NUM, line_width),
    KEY("harpoon", K_HARPOON, harpoon),
    KEY("color", K_COLOR, fg),
    KEY("background", K_COLOR, background),
    KEY("derivative_color", K_COLOR, derivative),
    KEY("conflict_color", K_COLOR, conflict),
    KEY("signal_color", K_COLOR, signal),
    KEY("muted_color", K_COLOR, muted),
    KEY("flash_outline", K_COLOR, flash_outline),
    KEY("signal_dashed", K_BOOL, signal_dashed),
    KEY("signal_width", K_NUM, signal_width),
    KEY("derivative_double", K_BOOL, derivative_double),
    KEY("conflict_cross", K_BOOL, conflict_cross),
    KEY("layer_colors", K_COLORS, layer_color),
    KEY("layer_patterns", K_BOOL, layer_patterns),
    KEY("layer_width", K_NUM, layer_width),
    KEY("layer_offset", K_NUM, layer_offset),
    KEY("node_pad", K_NUM, node_pad),
    KEY("node_sep", K_NUM, node_sep),
    KEY("rank_sep", K_NUM, rank_sep),
    KEY("margin", K_NUM, margin),
    KEY("splines", K_BOOL, splines),
    KEY("png_scale", K_NUM, png_scale),
};

static bg_rgba rgb(int hex) {
  return (bg_rgba){((hex >> 16) & 255) / 255.0, ((hex >> 8) & 255) / 255.0, (hex & 255) / 255.0, 1};
}

void bg_style_default(bg_style *st) {
  static const int layers[] = {0x1f77b4, 0x2ca02c, 0x9467bd, 0x8c564b, 0xe377c2, 0x17becf,
                               0xbcbd22, 0x7f7f7f};
  memset(st, 0, sizeof *st);
  snprintf(st->name, sizeof st->name, "default");
  snprintf(st->font, sizeof st->font, "DejaVu Sans");
  st->font_size = 11, st->number_scale = 0.75, st->line_width = 1;
  st->harpoon = BG_HARPOON_LEFT;
  st->fg = rgb(0x000000), st->background = rgb(0xffffff), st->derivative = rgb(0xe07000);
  st->conflict = rgb(0xd62020), st->signal = rgb(0x8b3a1a), st->muted = rgb(0xc8c8c8);
  st->flash_outline = rgb(0x401010);
  st->nlayer_color = (int)(sizeof layers / sizeof layers[0]);
  for (int i = 0; i < st->nlayer_color; i++) st->layer_color[i] = rgb(layers[i]);
  st->layer_width = 1.2, st->layer_offset = 7, st->signal_width = 0.7;
  st->node_pad = 3, st->node_sep = 28, st->rank_sep = 56, st->margin = 12;
  st->png_scale = 2;
}

/* ---------------------------------------------------------------- values */
static int parse_color(const char *s, bg_rgba *c) {
  size_t n = strlen(s);
  if (s[0] != '#' || (n != 7 && n != 9)) return -1;
  for (size_t i = 1; i < n; i++)
    if (!isxdigit((unsigned char)s[i])) return -1;
  unsigned long v = strtoul(s + 1, NULL, 16);
  if (n == 9) {
    *c = rgb((int)(v >> 8));
    c->a = (v & 255) / 255.0;
  } else {
    *c = rgb((int)v);
  }
  return 0;
}

static int parse_colors(const char *s, bg_style *st) {
  char buf[512];
  snprintf(buf, sizeof buf, "%s", s);
  int n = 0;
  for (char *save = NULL, *tok = strtok_r(buf, ", ", &save); tok; tok = strtok_r(NULL, ", ", &save)) {
    if (n == BG_STYLE_MAX_COLORS || parse_color(tok, &st->layer_color[n]) != 0) return -1;
    n++;
  }
  if (n == 0) return -1;
  st->nlayer_color = n;
  return 0;
}

static int parse_num(const char *s, double *v) {
  char *end;
  errno = 0;
  double x = strtod(s, &end);
  if (end == s || *end || errno || !(x >= 0) || x > 1e4) return -1;
  *v = x;
  return 0;
}

static int parse_bool(const char *s, int *v) {
  if (!strcmp(s, "true") || !strcmp(s, "yes") || !strcmp(s, "1")) return *v = 1, 0;
  if (!strcmp(s, "false") || !strcmp(s, "no") || !strcmp(s, "0")) return *v = 0, 0;
  return -1;
}

static int set_value(bg_style *st, const style_key *k, const char *v) {
  void *p = (char *)st + k->off;
  switch (k->type) {
  case K_STR:
    if (!*v || strlen(v) >= sizeof st->font) return -1;
    snprintf((char *)p, sizeof st->font, "%s", v);
    return 0;
  case K_NUM: return parse_num(v, (double *)p);
  case K_COLOR: return parse_color(v, (bg_rgba *)p);
  case K_BOOL: return parse_bool(v, (int *)p);
  case K_COLORS: return parse_colors(v, st);
  case K_HARPOON:
    if (!strcmp(v, "left")) return *(int *)p = BG_HARPOON_LEFT, 0;
    if (!strcmp(v, "down")) return *(int *)p = BG_HARPOON_DOWN, 0;
    return -1;
  }
  return -1;
}

/* ---------------------------------------------------------------- lines */
static char *trim(char *s) {
  while (isspace((unsigned char)*s)) s++;
  char *e = s + strlen(s);
  while (e > s && isspace((unsigned char)e[-1])) *--e = '\0';
  if (e - s >= 2 && s[0] == '"' && e[-1] == '"') e[-1] = '\0', s++;
  return s;
}

static const style_key *find_key(const char *name) {
  for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
    if (!strcmp(keys[i].name, name)) return &keys[i];
  return NULL;
}

static int parse_line(bg_style *st, char *line, const char *origin, int lineno, bg_diags *dg) {
  bg_srcloc none = {0};
  /* '#' opens a comment at the start of a line or as a word of its own
   * ("x = 1  # note"); "#ff0000" is a colour */
  for (char *h = strchr(line, '#'); h; h = strchr(h + 1, '#')) {
    int starts = h == line || isspace((unsigned char)h[-1]);
    int alone = !h[1] || isspace((unsigned char)h[1]);
    char *p = line;
    while (p < h && isspace((unsigned char)*p)) p++;
    if (p == h || (starts && alone)) {
      *h = '\0';
      break;
    }
  }
  char *s = trim(line);
  if (!*s) return 0;
  char *eq = strchr(s, '=');
  if (!eq) {
    bg_diag_error(dg, none, "style %s:%d: expected 'key = value'", origin, lineno);
    return -1;
  }
  *eq = '\0';
  const char *key = trim(s), *val = trim(eq + 1);
  const style_key *k = find_key(key);
  if (!k) {
    bg_diag_error(dg, none, "style %s:%d: unknown style key '%s'", origin, lineno, key);
    return -1;
  }
  if (set_value(st, k, val) != 0) {
    bg_diag_error(dg, none, "style %s:%d: bad value '%s' for '%s'", origin, lineno, val, key);
    return -1;
  }
  return 0;
}

int bg_style_parse(bg_style *st, const char *text, const char *origin, bg_diags *dg) {
  int rc = 0, lineno = 0;
  const char *p = text;
  while (*p) {
    const char *nl = strchr(p, '\n');
    size_t n = nl ? (size_t)(nl - p) : strlen(p);
    char line[1024];
    snprintf(line, sizeof line, "%.*s", (int)(n < sizeof line ? n : sizeof line - 1), p);
    if (parse_line(st, line, origin, ++lineno, dg) != 0) rc = -1;
    p += n + (nl ? 1 : 0);
  }
  return rc;
}

/* ---------------------------------------------------------------- files */
static int is_path(const char *name) {
  size_t n = strlen(name);
  return strchr(name, '/') || (n > 6 && !strcmp(name + n - 6, ".style"));
}

void bg_style_path(const char *name, const char *style_dir, char *buf, size_t n) {
  if (is_path(name)) {
    snprintf(buf, n, "%s", name);
    return;
  }
  const char *dir = style_dir ? style_dir : getenv("BGDRAW_STYLE_DIR");
  snprintf(buf, n, "%s/%s.style", dir && *dir ? dir : "styles", name);
}

int bg_style_load(bg_style *st, const char *name, const char *style_dir, bg_diags *dg) {
  bg_style_default(st);
  if (!name) name = "default";
  char path[4096];
  bg_style_path(name, style_dir, path, sizeof path);
  char *text = bg_read_file(path, NULL);
  if (!text) {
    if (!strcmp(name, "default")) return 0;
    bg_srcloc none = {0};
    bg_diag_error(dg, none, "unknown style '%s' (cannot read '%s': %s)", name, path,
                  bg_file_strerror(errno));
    return -1;
  }
  int rc = bg_style_parse(st, text, path, dg);
  free(text);
  snprintf(st->name, sizeof st->name, "%s", name);
  return rc;
}
