/* SPDX-License-Identifier: BSD-3-Clause */
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
 * are written in ASCII, a figure shows them as a book prints them. Not a
 * letter drawn as a Latin one (Mu is Μ, omicron ο): a quarter car's
 * unsprung mass `I : Mu` was drawn `I : Μ`, read as M, another name. */
static const char *greek(const char *name, size_t n) {
  static const char *const word[] = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta",
                                     "theta", "iota", "kappa", "lambda", "mu", "nu", "xi", "omicron",
                                     "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega"};
  static const char *const lower[] = {"α", "β", "γ", "δ", "ε", "ζ", "η", "θ", "ι", "κ", "λ", "μ",
                                      "ν", "ξ", NULL, "π", "ρ", "σ", "τ", "υ", "φ", "χ", "ψ", "ω"};
  static const char *const upper[] = {NULL, NULL, "Γ", "Δ", NULL, NULL, NULL, "Θ", NULL, NULL, "Λ", NULL,
                                      NULL, "Ξ", NULL, "Π", NULL, "Σ", NULL, NULL, "Φ", NULL, "Ψ", "Ω"};
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
static void simple_name_markup(bg_strbuf *b, const char *name, size_t n, double font_size);

/* A qualified name (O1.M.S.C1, C1.e): the instance path as written and the
 * subscript rule for the element's part only, so an instance's digit is no
 * subscript (O1.M.S.C, not O₁.M.S.C); a variable after the element (.e,
 * .f, .p, .q) stays as written (C₁.e). */
void bg_name_markup(bg_strbuf *b, const char *name, double font_size) {
  size_t n = strlen(name);
  const char *end = name + n, *last = strrchr(name, '.');
  if (last && last > name && last + 2 == end && strchr("efpq", last[1])) {
    end = last; /* the element's part ends before the variable */
    last = NULL;
    for (const char *p = name; p < end; p++)
      if (*p == '.') last = p;
  }
  const char *elem = last && last[1] && last > name ? last + 1 : name;
  if (elem >= end) elem = name;
  bg_markup_escapen(b, name, (size_t)(elem - name));
  simple_name_markup(b, elem, (size_t)(end - elem), font_size);
  bg_markup_escapen(b, end, strlen(end));
}

static void simple_name_markup(bg_strbuf *b, const char *whole, size_t n, double font_size) {
  char small[256], *name = n < sizeof small ? small : bg_xmalloc(n + 1);
  memcpy(name, whole, n);
  name[n] = 0;
  size_t k = n;
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
  if (name != small) free(name);
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

/* Whether c may stand next to a number without being part of it. */
static int number_edge(char c) { return !c || !(isalnum((unsigned char)c) || c == '.' || c == '_' || c == '\''); }

/* The length of the unsigned integer at p (not part of a name or a decimal), or 0. */
static size_t integer_at(const char *g, const char *p) {
  if (p > g && !number_edge(p[-1])) return 0;
  size_t n = 0;
  while (isdigit((unsigned char)p[n])) n++;
  return n && p[n] != '.' ? n : 0;
}

/* Puts the k characters of num in place of the len at p, shifting the rest
 * of the string; only when that is no longer (the string has no more room:
 * a power written out in place, 10^5 as 100000, ran past its end). k < 0:
 * nothing to put. Returns whether it did. */
static int splice(char *p, size_t len, const char *num, int k) {
  if (k < 0 || (size_t)k > len) return 0;
  memmove(p + k, p + len, strlen(p + len) + 1);
  memcpy(p, num, (size_t)k);
  return 1;
}

/* One rewrite of a gain whose numbers were put in: an integer power of an
 * integer evaluated where that is no longer (1^2 → 1, 2^2 → 4; 9^9 and 10^5
 * stay), a factor 1 dropped (1*s → s,
 * x*1 → x, x/1 → x), a fraction of integers in lowest terms (-4/2 → -2,
 * 2/4 → 1/2; 3/2 stays), brackets round a single name or number dropped
 * where they stand alone (/(s) → /s, not exp(s)). Returns whether it
 * changed g. */
static int simplify_once(char *g) {
  for (char *p = g; *p; p++) {
    size_t a = integer_at(g, p);
    if (a && p[a] == '/' && a < 9 && (p == g || (p[-1] != '^' && p[-1] != '/'))) { /* 4/2 → 2 */
      size_t b = integer_at(g, p + a + 1);
      const char *after = p + a + 1 + b;
      if (b && b < 9 && number_edge(*after) && *after != '^') {
        long x = strtol(p, NULL, 10), y = strtol(p + a + 1, NULL, 10), c = x, r = y;
        while (r) { /* gcd */
          long t = c % r;
          c = r, r = t;
        }
        char num[48];
        int k = y <= 0 || c <= 1 ? -1
                : y == c         ? snprintf(num, sizeof num, "%ld", x / c)
                                 : snprintf(num, sizeof num, "%ld/%ld", x / c, y / c);
        if (splice(p, a + 1 + b, num, k)) return 1;
      }
    }
    if (p[0] == '/' && p[1] == '1' && integer_at(g, p + 1) == 1 && number_edge(p[2]) && p[2] != '^') { /* x/1 → x */
      return splice(p, 2, "", 0);
    }
    if (a && p[a] == '^') {
      size_t b = integer_at(g, p + a + 1);
      if (b && b < 3 && a < 6 && number_edge(p[a + 1 + b])) {
        double v = pow(strtod(p, NULL), strtod(p + a + 1, NULL));
        char num[32];
        if (splice(p, a + 1 + b, num, v < 1e9 ? snprintf(num, sizeof num, "%.0f", v) : -1)) return 1; /* 9^9, 10^5 stay */
      }
    }
    if (p[0] == '1' && p[1] == '*' && integer_at(g, p) == 1 && (p == g || (p[-1] != '/' && p[-1] != '^'))) { /* 1*x → x */
      return splice(p, 2, "", 0);
    }
    if (p[0] == '*' && p[1] == '1' && integer_at(g, p + 1) == 1 && number_edge(p[2]) && p[2] != '^') { /* x*1 → x */
      return splice(p, 2, "", 0);
    }
    if (p[0] == '(' && (p == g || !(isalnum((unsigned char)p[-1]) || p[-1] == '_'))) {
      char *q = p + 1;
      while (isalnum((unsigned char)*q) || *q == '_' || *q == '.' || *q == '\'' || *q == '^') q++;
      if (*q == ')' && q > p + 1) { /* (s) → s */
        memmove(q, q + 1, strlen(q + 1) + 1);
        memmove(p, p + 1, strlen(p + 1) + 1);
        return 1;
      }
    }
  }
  return 0;
}

void bg_gain_markup(const char *gain, double size, bg_strbuf *out) {
  char name[128], *g = bg_xmalloc(strlen(gain) + 1);
  strcpy(g, gain);
  for (int k = 0; k < 64 && simplify_once(g); k++) {
  }
  for (const char *p = g; *p;) {
    if (isalpha((unsigned char)*p) || *p == '_') {
      const char *e = p; /* a name, qualified ones (O1.M.S.C) whole */
      while (isalnum((unsigned char)*e) || *e == '_' || (*e == '.' && (isalpha((unsigned char)e[1]) || e[1] == '_'))) e++;
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
  free(g);
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
