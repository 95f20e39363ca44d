/* SPDX-License-Identifier: BSD-3-Clause */
/* --report FILE.html: the driver. The page's head (style sheet inline), the
 * title with the verdict, the contents, the sections in the PDF's order
 * (the highlighted diagrams of the PDF's section 3 are the tables' rows
 * lighting the one diagram), then the script. Nothing depends on the
 * clock, the environment or addresses: the same run gives the same bytes. */
#include <string.h>

#include "html/html_int.h"

static void head(ht_ctx *c) {
  const bg_model *m = c->m;
  bg_strbuf *o = c->out;
  bg_sb_puts(o, "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
                "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n"
                "<meta name=\"generator\" content=\"bgdraw\"/>\n<title>");
  ht_esc(o, m->name);
  if (m->title) bg_sb_puts(o, " \u2014 "), ht_esc(o, m->title);
  bg_sb_puts(o, " \u2014 bgdraw analysis report</title>\n<style>\n");
  bg_sb_puts(o, ht_css);
  bg_sb_puts(o, "</style>\n<style id=\"bgdraw-parts\">\n");
  bg_sb_puts(o, ht_css_parts);
  bg_sb_puts(o, "</style>\n</head>\n<body>\n<a class=\"skip\" href=\"#main\">Skip to the report</a>\n"
                "<header>\n<p class=\"sub\">bgdraw analysis report</p>\n<h1>");
  ht_esc(o, m->title ? m->title : m->name);
  bg_sb_puts(o, "</h1>\n<p class=\"sub\">Model <b>");
  ht_esc(o, m->name);
  bg_sb_puts(o, "</b></p>\n</header>\n");
}

static void body(ht_ctx *c) {
  ht_summary(c);
  ht_diagram(c);
  ht_components(c);
  ht_fields(c);
  ht_trace(c);
  ht_tables(c);
  ht_index(c);
  ht_equations(c);
  ht_estimates(c);
  ht_simulation(c);
  ht_linear(c);
  ht_transform(c);
}

int bg_html_report_render(const bg_run *r, const bg_report_opts *ro, bg_strbuf *out, bg_diags *dg) {
  bg_report_input in = rp_input(r, ro);
  ht_ctx c;
  memset(&c, 0, sizeof c);
  c.rp.in = &in, c.rp.m = in.m, c.rp.a = in.a, c.rp.dg = dg;
  c.in = &in, c.m = in.m, c.a = in.a, c.dg = dg;
  bg_strbuf main_part = {0};
  c.out = &main_part;
  if (in.ropts) bg_logf(in.ropts->log, BG_LOG_PROGRESS, "report: HTML sections");
  body(&c);
  if (!c.failed) {
    c.out = out;
    head(&c);
    bg_sb_puts(out, "<nav aria-label=\"Contents\">\n<h2 id=\"contents\">Contents</h2>\n<ol>\n");
    bg_sb_puts(out, bg_sb_str(&c.toc));
    bg_sb_puts(out, "</ol>\n</nav>\n<main id=\"main\">\n");
    bg_sb_putn(out, main_part.s, main_part.len);
    bg_sb_puts(out, "</main>\n<script>//<![CDATA[\n"); /* the page is well-formed XML too */
    bg_sb_puts(out, ht_js);
    bg_sb_puts(out, "//]]></script>\n</body>\n</html>\n");
  }
  bg_sb_free(&main_part);
  bg_sb_free(&c.toc);
  return c.failed ? BG_RENDER_ERROR : BG_RENDER_OK;
}
