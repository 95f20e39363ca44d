/* SPDX-License-Identifier: BSD-3-Clause */
/* The HTML report's writing helpers: escaping, numbered sections with their
 * line in the contents, tables with a caption and column headers. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "html/html_int.h"
#include "scene/scene.h"

/* Pango markup's escaping is XML's (scene.c). */
void ht_esc(bg_strbuf *b, const char *s) {
  if (s) bg_markup_escapen(b, s, strlen(s));
}

void ht_row(void *ctx, const char *key, const char *plain) {
  bg_strbuf *b = ctx;
  bg_sb_puts(b, "<tr><th scope=\"row\">");
  ht_esc(b, key);
  bg_sb_puts(b, "</th><td>");
  ht_esc(b, plain);
  bg_sb_puts(b, "</td></tr>\n");
}

void ht_section(ht_ctx *c, const char *id, const char *title) {
  c->section++;
  bg_sb_printf(c->out, "<section id=\"%s\" aria-labelledby=\"%s-h\">\n<h2 id=\"%s-h\">%d. ", id, id, id,
               c->section);
  ht_esc(c->out, title);
  bg_sb_puts(c->out, "</h2>\n");
  bg_sb_printf(&c->toc, "<li><a href=\"#%s\">", id);
  ht_esc(&c->toc, title);
  bg_sb_puts(&c->toc, "</a></li>\n");
}

void ht_section_end(ht_ctx *c) { bg_sb_puts(c->out, "</section>\n"); }

void ht_sub(ht_ctx *c, const char *id, const char *title) {
  bg_sb_printf(c->out, "<h3 id=\"%s\">", id);
  ht_esc(c->out, title);
  bg_sb_puts(c->out, "</h3>\n");
}

void ht_para(ht_ctx *c, const char *fmt, ...) {
  char buf[2048];
  va_list ap;
  va_start(ap, fmt);
  int n = vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  bg_sb_puts(c->out, "<p>");
  bg_markup_escapen(c->out, buf, n < (int)sizeof buf ? (size_t)n : sizeof buf - 1);
  bg_sb_puts(c->out, "</p>\n");
}

void ht_table(ht_ctx *c, const char *cls, const char *caption, int ncol, const char *const *head) {
  bg_sb_puts(c->out, "<div class=\"scroll\"><table");
  if (cls) bg_sb_printf(c->out, " class=\"%s\"", cls);
  bg_sb_puts(c->out, ">");
  if (caption) bg_sb_puts(c->out, "<caption>"), ht_esc(c->out, caption), bg_sb_puts(c->out, "</caption>");
  bg_sb_puts(c->out, "\n<thead><tr>");
  for (int k = 0; k < ncol; k++) {
    bg_sb_puts(c->out, "<th scope=\"col\">");
    ht_esc(c->out, head[k]);
    bg_sb_puts(c->out, "</th>");
  }
  bg_sb_puts(c->out, "</tr></thead>\n<tbody>\n");
}

void ht_table_end(ht_ctx *c) { bg_sb_puts(c->out, "</tbody></table></div>\n"); }

void ht_more_rows(ht_ctx *c, int shown, int total, int omitted, const char *what) {
  if (shown >= total && !omitted) return;
  bg_sb_puts(c->out, "<p class=\"note\">");
  if (shown < total) bg_sb_printf(c->out, "The first %d of %d %s are listed; ", shown, total, what);
  if (omitted) bg_sb_printf(c->out, "%d more %s were found but not enumerated (listing cap); ", omitted, what);
  bg_sb_puts(c->out, "the JSON output (<code>-o model.json</code>) has every listed one.</p>\n");
}

void ht_bonds(bg_strbuf *b, const bg_model *m, const int *bonds, int n) {
  for (int i = 0; i < n; i++) bg_sb_printf(b, "%s%d", i ? ", " : "", m->bond_num[bonds[i]]);
}

void ht_num(bg_strbuf *b, double v) { rp_num(b, v); }
