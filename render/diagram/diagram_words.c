/* The diagram's words, a leaf like diagram_base.c: names and gains as
 * pango markup (subscripts, raised powers, minus signs) and the one-line
 * descriptions of paths and loops that the legend and the DOT output
 * share. */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diagram/diagram_int.h"

/* The size of a subscript or a power, in per cent of the text's size: 70,
 * or more where 70 % of size would be below 6 pt, the least size a figure
 * is readable at (issue 31: bond-number subscripts were 5.77 pt, print's
 * 5.25). */
int bg_sub_percent(double size) {
  int pct = (int)ceil(600 / size - 1e-9);
  return pct > 70 ? pct : 70;
}

/* The Greek letter a name spells (alpha → α, Omega → Ω), or NULL: names
 * are written in ASCII, a figure shows them as a book prints them. */
static const char *greek(const char *name, size_t n) {
  static const char *const word[] = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta",
                                     "theta", "iota", "kappa", "lambda", "mu", "nu", "xi", "omicron",
                                     "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega"};
  static const char *const lower[] = {"α", "β", "γ", "δ", "ε", "ζ", "η", "θ", "ι", "κ", "λ", "μ",
                                      "ν", "ξ", "ο", "π", "ρ", "σ", "τ", "υ", "φ", "χ", "ψ", "ω"};
  static const char *const upper[] = {"Α", "Β", "Γ", "Δ", "Ε", "Ζ", "Η", "Θ", "Ι", "Κ", "Λ", "Μ",
                                      "Ν", "Ξ", "Ο", "Π", "Ρ", "Σ", "Τ", "Υ", "Φ", "Χ", "Ψ", "Ω"};
  for (size_t k = 0; k < sizeof word / sizeof word[0]; k++) {
    if (strlen(word[k]) != n || tolower((unsigned char)name[0]) != word[k][0]) continue;
    if (strncmp(name + 1, word[k] + 1, n - 1)) continue;
    return isupper((unsigned char)name[0]) ? upper[k] : lower[k];
  }
  return NULL;
}

/* A name with its trailing digits (or the part after the last '_') set as a
 * subscript: a pango span, since <sub> mis-scales on scaled surfaces. A
 * Greek letter's name (the whole name, or the part before the subscript)
 * is the letter: sigma1 → σ₁. */
void bg_name_markup(bg_strbuf *b, const char *name, double font_size) {
  size_t n = strlen(name), k = n;
  while (k > 0 && isdigit((unsigned char)name[k - 1])) k--;
  const char *us = strrchr(name, '_');
  size_t base = k, sub = k;
  if (k == n || k == 0) base = sub = n;
  if (us && us > name && us[1]) base = (size_t)(us - name), sub = base + 1;
  const char *g = greek(name, base);
  if (g) bg_sb_puts(b, g);
  else bg_markup_escapen(b, name, base);
  if (sub < n) {
    bg_sb_printf(b, "<span size=\"%d%%\" rise=\"%.1fpt\">", bg_sub_percent(font_size), -0.27 * font_size);
    const char *gs = greek(name + sub, n - sub);
    if (gs) bg_sb_puts(b, gs);
    else bg_markup_escapen(b, name + sub, n - sub);
    bg_sb_puts(b, "</span>");
  }
}

/* The exponent after a '^' at p: a number, a name or a bracketed group
 * (without its brackets); returns where it ends, the text in [from, to). */
static const char *exponent(const char *p, const char **from, const char **to) {
  const char *e = p;
  if (*e == '(') {
    int depth = 0;
    do depth += *e == '(' ? 1 : *e == ')' ? -1 : 0;
    while (*++e && depth > 0);
    *from = p + 1, *to = depth ? e : e - 1;
    return e;
  }
  if (*e == '-') e++;
  while (isalnum((unsigned char)*e) || *e == '.' || *e == '_') e++;
  *from = p, *to = e;
  return e;
}

static void gain_char(bg_strbuf *out, char c) {
  if (c == '*') bg_sb_puts(out, "\u2009"); /* a product: juxtaposition */
  else if (c == '-') bg_sb_puts(out, "\u2212");
  else if (c == '\'') bg_sb_puts(out, "\u2032");
  else bg_markup_escapen(out, &c, 1);
}

void bg_gain_markup(const char *g, double size, bg_strbuf *out) {
  char name[128];
  for (const char *p = g; *p;) {
    if (isalpha((unsigned char)*p) || *p == '_') {
      const char *e = p;
      while (isalnum((unsigned char)*e) || *e == '_') e++;
      snprintf(name, sizeof name, "%.*s", (int)(e - p), p);
      bg_name_markup(out, name, size);
      p = e;
    } else if (*p == '^' && p[1]) {
      const char *from, *to;
      p = exponent(p + 1, &from, &to);
      bg_sb_printf(out, "<span size=\"%d%%\" rise=\"%.1fpt\">", bg_sub_percent(size), 0.42 * size);
      for (const char *q = from; q < to; q++) gain_char(out, *q);
      bg_sb_puts(out, "</span>");
    } else {
      gain_char(out, *p++);
    }
  }
}

/* ---------------------------------------------------------------- descriptions */
static void describe_bonds(const bg_diagram *d, const int *bonds, int n, bg_strbuf *out) {
  for (int k = 0; k < n; k++) bg_sb_printf(out, "%s%d", k ? "-" : "", d->m->bond_num[bonds[k]]);
}

static void describe_text(const bg_diagram *d, int kind, int i, int markup, bg_strbuf *out,
                          bg_strbuf *dst);

/* Appends t to out (escaped for markup) and empties t. */
static void flush_text(bg_strbuf *t, int markup, bg_strbuf *out) {
  if (markup) bg_markup_escape(out, bg_sb_str(t));
  else bg_sb_puts(out, bg_sb_str(t));
  bg_sb_clear(t);
}

void bg_layer_describe(const bg_diagram *d, int kind, int i, int markup, bg_strbuf *dst) {
  bg_strbuf t = {0}, *out = &t;
  describe_text(d, kind, i, markup, out, dst);
  flush_text(out, markup, dst);
  bg_sb_free(&t);
}

/* The description into out; a typeset gain goes to dst directly. */
static void describe_text(const bg_diagram *d, int kind, int i, int markup, bg_strbuf *out,
                          bg_strbuf *dst) {
  const bg_analysis *a = d->a;
  const bg_model *m = d->m;
  if (kind == 'p') {
    bg_sb_printf(out, "P%d causal path %s \u2013 %s, bonds ", i + 1, m->elem_name[a->path_end0[i]],
                 m->elem_name[a->path_end1[i]]);
    describe_bonds(d, a->path_bonds + a->path_adr[i], a->path_n[i], out);
    bg_sb_printf(out, " (%s", a->path_kind && a->path_kind[i] ? a->path_kind[i] : "?");
    if (a->path_class && a->path_class[i]) bg_sb_printf(out, ", class %d", a->path_class[i]);
    if (a->path_order && a->path_order[i] != BG_PATH_ORDER_NONE)
      bg_sb_printf(out, ", order %d", a->path_order[i]);
    bg_sb_putc(out, ')');
    return;
  }
  bg_sb_printf(out, "L%d %s topological loop, order %d", i + 1,
               a->tloop_kind[i] == BG_TLOOP_FLAT ? "flat" : "open", a->tloop_order[i]);
  if (a->tloop_gain && a->tloop_gain[i] && markup) {
    bg_sb_puts(out, ", G = ");
    flush_text(out, markup, dst);
    bg_gain_markup(a->tloop_gain[i], d->st.font_size * d->st.number_scale, dst);
  } else if (a->tloop_gain && a->tloop_gain[i])
    bg_sb_printf(out, ", G = %s", a->tloop_gain[i]);
  if (a->tloop_algebraic && a->tloop_algebraic[i]) bg_sb_puts(out, ", algebraic");
  if (a->tloop_cause && a->tloop_cause[i]) bg_sb_printf(out, " (%s)", a->tloop_cause[i]);
}
