/* SPDX-License-Identifier: BSD-3-Clause */
/* Report section 7: the equations typeset from the text printer's lines
 * (eqprint.h): bond variables with subscripts, derivatives with a dot,
 * aligned on "=", long right-hand sides wrapped. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/equations.h"
#include "report/report_int.h"

#define MAX_EQ_LINES 600 /* per block; the rest: --equations text */
#define EQ_SIZE RP_SIZE_BODY

typedef struct eqblock {
  char title[96];  /* plain text */
  char *intro;     /* nullable: what follows the heading's colon (plain) */
  char **lhs, **rhs, **note; /* markup; note nullable */
  int n, cap;
} eqblock;

#define MAX_BLOCKS 8

static void block_add(eqblock *b, char *lhs, char *rhs, char *note) {
  if (b->n == b->cap) {
    b->cap = b->cap ? 2 * b->cap : 32;
    b->lhs = bg_xrealloc(b->lhs, (size_t)b->cap * sizeof(char *));
    b->rhs = bg_xrealloc(b->rhs, (size_t)b->cap * sizeof(char *));
    b->note = bg_xrealloc(b->note, (size_t)b->cap * sizeof(char *));
  }
  b->lhs[b->n] = lhs, b->rhs[b->n] = rhs, b->note[b->n++] = note;
}

static void block_free(eqblock *b) {
  for (int i = 0; i < b->n; i++) free(b->lhs[i]), free(b->rhs[i]), free(b->note[i]);
  free(b->lhs), free(b->rhs), free(b->note), free(b->intro);
  memset(b, 0, sizeof *b);
}

static char *markup_of(const char *s, size_t n) {
  bg_strbuf plain = {0}, m = {0};
  bg_sb_putn(&plain, s, n);
  rp_eq_markup(bg_sb_str(&plain), EQ_SIZE, &m);
  char *r = strdup(bg_sb_str(&m));
  bg_sb_free(&plain), bg_sb_free(&m);
  return r;
}

/* "lhs = rhs    (note)" */
static void parse_line(const char *line, eqblock *b) {
  const char *eq = strstr(line, " = ");
  if (!eq) return;
  const char *note = strstr(eq, "    (");
  size_t rn = note ? (size_t)(note - (eq + 3)) : strlen(eq + 3);
  char *nt = NULL;
  if (note) {
    bg_strbuf t = {0};
    rp_eq_markup(note + 4, EQ_SIZE * 0.85, &t);
    nt = strdup(bg_sb_str(&t));
    bg_sb_free(&t);
  }
  block_add(b, markup_of(line, (size_t)(eq - line)), markup_of(eq + 3, rn), nt);
}

typedef struct eqcols {
  double xeq, eqw, width; /* "=" at xeq, rhs from xeq + eqw, width wide */
} eqcols;

static char *rhs_markup(const eqblock *b, int i) {
  bg_strbuf r = {0};
  bg_sb_puts(&r, b->rhs[i]);
  if (b->note[i]) bg_sb_printf(&r, "   <span foreground=\"#6b6b6b\" size=\"85%%\">%s</span>", b->note[i]);
  char *s = strdup(bg_sb_str(&r));
  bg_sb_free(&r);
  return s;
}

/* One equation at (x offset dx, d->y), the rhs wrapped; returns its lines. */
static int put_eq(rp_doc *d, const eqcols *k, double dx, const char *lhs, const char *rhs, int flow) {
  double lh = rp_line_height(d->font, EQ_SIZE);
  rp_lines l;
  rp_wrap(d->font, EQ_SIZE, rhs, k->width, k->width - 12, &l);
  if (flow) rp_need(d, lh * (l.n < 3 ? l.n : 3));
  rp_text(d, lhs, dx + k->xeq - 3, d->y, EQ_SIZE, 1, rp_ink);
  rp_text(d, "=", dx + k->xeq, d->y, EQ_SIZE, 0, rp_ink);
  for (int i = 0; i < l.n; i++) {
    if (flow) rp_need(d, lh);
    rp_text(d, l.line[i], dx + k->xeq + k->eqw + (i ? 12 : 0), d->y, EQ_SIZE, 0, rp_ink);
    d->y += lh;
  }
  int n = l.n;
  rp_lines_free(&l);
  return n;
}

/* Short equations in two balanced columns, page by page. */
static void two_columns(rp_doc *d, const eqblock *b, char **rhs, const eqcols *k, double colw) {
  double rowh = rp_line_height(d->font, EQ_SIZE) + 1.5;
  int *page = bg_xmalloc((size_t)b->n * sizeof(int)), *col = bg_xmalloc((size_t)b->n * sizeof(int));
  int *row = bg_xmalloc((size_t)b->n * sizeof(int));
  int first = (int)(rp_room(d) / rowh), full = (int)(rp_page_room(d) / rowh);
  rp_two_columns(b->n, first, full, page, col, row);
  double y0 = d->y, bottom = d->y;
  for (int i = 0, cur = 0; i < b->n; i++) {
    if (page[i] != cur) rp_new_page(d, 0), y0 = bottom = d->y, cur = page[i];
    d->y = y0 + row[i] * rowh;
    put_eq(d, k, col[i] * colw, b->lhs[i], rhs[i], 0);
    if (d->y + 1.5 > bottom) bottom = d->y + 1.5;
  }
  d->y = bottom;
  free(page), free(col), free(row);
}

static void emit_block(rp_ctx *c, const eqblock *b) {
  rp_doc *d = &c->body;
  if (b->n == 0) return;
  double lh = rp_line_height(d->font, EQ_SIZE), cw = rp_content_w(d), lw = 0, rw = 0;
  char **rhs = bg_xmalloc((size_t)b->n * sizeof(char *));
  for (int i = 0; i < b->n; i++) {
    double w = rp_text_width(d->font, EQ_SIZE, b->lhs[i]);
    if (w > lw) lw = w;
    rhs[i] = rhs_markup(b, i);
    w = rp_text_width(d->font, EQ_SIZE, rhs[i]);
    if (w > rw) rw = w;
  }
  if (lw > cw / 3) lw = cw / 3;
  eqcols k;
  k.xeq = rp_left() + 12 + lw + 3, k.eqw = rp_text_width(d->font, EQ_SIZE, "=") + 4;
  double colw = cw / 2 + 6;
  int two = b->n > 6 && k.xeq - rp_left() + k.eqw + rw + 12 < colw;
  k.width = (two ? rp_left() + colw - 12 : rp_left() + cw) - (k.xeq + k.eqw);
  rp_subsection(d, b->title, 2 * lh + (b->intro ? lh : 0));
  if (b->intro) {
    bg_strbuf t = {0};
    rp_esc(&t, b->intro);
    bg_sb_puts(&t, ":");
    if (t.s[0] >= 'a' && t.s[0] <= 'z') t.s[0] = (char)(t.s[0] - 'a' + 'A');
    rp_para(d, bg_sb_str(&t), RP_SIZE_BODY, 0, 0, rp_ink);
    d->y += 2;
    bg_sb_free(&t);
  }
  if (two) {
    two_columns(d, b, rhs, &k, colw);
  } else {
    for (int i = 0; i < b->n; i++) put_eq(d, &k, 0, b->lhs[i], rhs[i], 1), d->y += 1.5;
  }
  for (int i = 0; i < b->n; i++) free(rhs[i]);
  free(rhs);
  rp_gap(d, 4);
}

/* A block from a heading line of the printer ("algebraic residuals",
 * "reduced form: explicit ODE after ..."): the title before the colon. */
static void start_block(eqblock *b, const char *head) {
  const char *colon = strchr(head, ':');
  size_t n = colon ? (size_t)(colon - head) : strlen(head);
  if (n >= sizeof b->title) n = sizeof b->title - 1;
  memcpy(b->title, head, n), b->title[n] = 0;
  if (b->title[0] >= 'a' && b->title[0] <= 'z') b->title[0] = (char)(b->title[0] - 'a' + 'A');
  while (colon && *++colon == ' ') {}
  if (colon && *colon) b->intro = strdup(colon);
}

static void form_line(rp_ctx *c, const char *text) {
  bg_strbuf b = {0};
  bg_sb_puts(&b, "<b>Form:</b> ");
  rp_eq_markup(text, RP_SIZE_BODY, &b);
  rp_para(&c->body, bg_sb_str(&b), RP_SIZE_BODY, 0, 12, rp_ink);
  rp_gap(&c->body, 3);
  bg_sb_free(&b);
}

void rp_sec_equations(rp_ctx *c) {
  rp_section(&c->body, "Equations", 1, 0, 160);
  const bg_eqsys *s = c->in->eqs;
  if (!s) {
    bg_strbuf b = {0};
    bg_sb_puts(&b, "No equations: ");
    rp_esc(&b, c->in->eqs_problem ? c->in->eqs_problem : "they could not be formed");
    bg_sb_puts(&b, ".");
    rp_para(&c->body, bg_sb_str(&b), RP_SIZE_BODY, 0, 0, rp_ink);
    bg_sb_free(&b);
    return;
  }
  rp_para(&c->body, "In computational order, with bond-numbered variables: <i>e</i><sub>k</sub> and "
          "<i>f</i><sub>k</sub> are the effort and the flow of bond k, <i>q</i><sub>X</sub> and "
          "<i>p</i><sub>X</sub> the states of store X; a dot marks the time derivative. Algebraic "
          "residuals 0 = \u2026 define the algebraic unknowns. The same equations in text, LaTeX "
          "or C: <tt>--equations text|latex|c</tt>.", RP_SIZE_BODY, 0, 0, rp_ink);
  rp_gap(&c->body, 4);
  bg_strbuf txt = {0};
  bg_eqprint_text(s, &txt);
  eqblock blk[MAX_BLOCKS];
  memset(blk, 0, sizeof blk);
  snprintf(blk[0].title, sizeof blk[0].title, "Sorted equations");
  int cur = 0, dropped = 0;
  char *p = txt.s;
  while (p && *p) {
    char *nl = strchr(p, '\n');
    if (nl) *nl = 0;
    if (!strncmp(p, "# form: ", 8)) form_line(c, p + 8);
    else if (!strncmp(p, "# ", 2) && strncmp(p, "# equations of", 14) && cur + 1 < MAX_BLOCKS)
      start_block(&blk[++cur], p + 2);
    else if (p[0] != '#' && blk[cur].n < MAX_EQ_LINES) parse_line(p, &blk[cur]);
    else if (p[0] != '#') dropped++;
    p = nl ? nl + 1 : NULL;
  }
  for (int i = 0; i <= cur; i++) emit_block(c, &blk[i]), block_free(&blk[i]);
  if (dropped) {
    char buf[160];
    snprintf(buf, sizeof buf, "%d more equations are not shown; <tt>--equations text</tt> prints them all.",
             dropped);
    rp_para(&c->body, buf, RP_SIZE_SMALL, 0, 0, rp_grey);
  }
  bg_sb_free(&txt);
}
