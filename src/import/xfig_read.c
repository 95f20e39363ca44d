/* SPDX-License-Identifier: BSD-3-Clause */
/* xfig's text format (FIG 3.0 to 3.2, the drawings MTT reads) into a list of
 * its open polylines and its texts with their coordinates; every other
 * object (ellipses, boxes, arcs, splines, pictures) is read past as
 * artwork. The format is a stream of numbers after each object's code, but
 * a text's string runs to its "\001" and a picture's file name to the end
 * of its line, so the reader walks tokens and knows each object's shape.
 * Work is linear in the file; counts in the file are checked against what
 * is left of it before anything is allocated. */
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "import/import_int.h"

typedef struct {
  const char *s, *end;
  int line;
  int obj_line; /* the line the object being read starts on */
  bg_diags *dg;
  int file;
  int failed;
} lexer;

static void fail(lexer *lx, int line, const char *what) {
  if (!lx->failed)
    bg_diag_error(lx->dg, (bg_srcloc){line, 1, lx->file}, "xfig drawing: %s", what);
  lx->failed = 1;
}

static void skip_blank(lexer *lx) {
  while (lx->s < lx->end) {
    char c = *lx->s;
    if (c == '\n') lx->line++, lx->s++;
    else if (c == ' ' || c == '\t' || c == '\r') lx->s++;
    else if (c == '#') { /* a comment line (FIG 3.2 puts them before objects) */
      while (lx->s < lx->end && *lx->s != '\n') lx->s++;
    } else break;
  }
}

/* The next whitespace-separated word as a number (a float is accepted where
 * xfig writes one; ints are rounded), or a failure naming what was read. */
static double number(lexer *lx, const char *what) {
  skip_blank(lx);
  if (lx->failed) return 0;
  if (lx->s >= lx->end) {
    fail(lx, lx->obj_line, "the file ends inside an object");
    return 0;
  }
  char buf[64];
  size_t n = 0;
  while (lx->s + n < lx->end && !strchr(" \t\r\n", lx->s[n])) n++;
  if (n >= sizeof buf) n = sizeof buf - 1;
  memcpy(buf, lx->s, n);
  buf[n] = 0;
  char *e;
  errno = 0;
  double v = strtod(buf, &e);
  if (!n || *e || errno || v != v || v > 1e9 || v < -1e9) {
    bg_diag_error(lx->dg, (bg_srcloc){lx->line, 1, lx->file},
                  "xfig drawing: expected a number (%s), found '%s'", what, buf);
    lx->failed = 1;
    return 0;
  }
  lx->s += n;
  return v;
}

static int integer(lexer *lx, const char *what) {
  double v = number(lx, what);
  return v >= 0 ? (int)(v + 0.5) : -(int)(-v + 0.5);
}

/* A coordinate: within +-10^8 (xfig's own canvas is far smaller), so squared
 * distances stay exact in 64 bits. */
static int coordinate(lexer *lx, const char *what) {
  int line = lx->line;
  double v = number(lx, what);
  if (!lx->failed && (v > BG_FIG_MAX_COORD || v < -BG_FIG_MAX_COORD)) {
    bg_diag_error(lx->dg, (bg_srcloc){line, 1, lx->file},
                  "xfig drawing: the coordinate %.0f is beyond +-%d", v, BG_FIG_MAX_COORD);
    lx->failed = 1;
  }
  return v >= 0 ? (int)(v + 0.5) : -(int)(-v + 0.5);
}

/* A count the rest of the file can hold (each item takes at least `per`
 * bytes), so a huge number in a small file allocates nothing. */
static int count(lexer *lx, const char *what, int per) {
  int n = integer(lx, what);
  if (!lx->failed && (n < 0 || (size_t)n * (size_t)per > (size_t)(lx->end - lx->s) + 1)) {
    bg_diag_error(lx->dg, (bg_srcloc){lx->line, 1, lx->file},
                  "xfig drawing: %s %d is more than the rest of the file holds", what, n);
    lx->failed = 1;
    return 0;
  }
  return n;
}

static void skip_numbers(lexer *lx, int n, const char *what) {
  for (int i = 0; i < n && !lx->failed; i++) number(lx, what);
}

static void skip_arrows(lexer *lx, int forward, int backward) {
  skip_numbers(lx, forward ? 5 : 0, "a forward arrow's parameters");
  skip_numbers(lx, backward ? 5 : 0, "a backward arrow's parameters");
}

/* "\ddd" octal escapes and "\\" of a text's string, up to its "\001". */
static const char *text_string(lexer *lx, bg_arena *a, int line) {
  if (lx->s < lx->end && *lx->s == ' ') lx->s++; /* the one blank before it */
  const char *start = lx->s;
  const char *stop = NULL;
  for (const char *p = start; p + 3 < lx->end && *p != '\n'; p++)
    if (!memcmp(p, "\\001", 4)) {
      stop = p;
      break;
    }
  if (!stop) {
    fail(lx, line, "a text object's string has no \\001 before the end of its line");
    return "";
  }
  char *out = bg_arena_alloc(a, (size_t)(stop - start) + 1);
  size_t k = 0;
  for (const char *p = start; p < stop; p++) {
    if (*p == '\\' && p + 1 < stop && p[1] == '\\') out[k++] = '\\', p++;
    else if (*p == '\\' && p + 3 < stop && p[1] >= '0' && p[1] <= '7' && p[2] >= '0' &&
             p[2] <= '7' && p[3] >= '0' && p[3] <= '7') {
      int c = (p[1] - '0') * 64 + (p[2] - '0') * 8 + (p[3] - '0');
      out[k++] = c ? (char)c : ' ';
      p += 3;
    } else out[k++] = *p;
  }
  out[k] = 0;
  lx->s = stop + 4;
  return out;
}

static void push(bg_fig *f, bg_fig_obj o) {
  if (f->n == f->cap) {
    f->cap = f->cap ? 2 * f->cap : 64;
    f->objs = bg_xrealloc(f->objs, (size_t)f->cap * sizeof *f->objs);
  }
  f->objs[f->n++] = o;
}

/* The header: "#FIG 3.x" and the lines up to the resolution line (two
 * integers: FIG 3.0/3.1 have three lines before it, 3.2 seven). */
static int header(lexer *lx, int *minor) {
  if (lx->end - lx->s < 6 || memcmp(lx->s, "#FIG 3", 6)) {
    fail(lx, 1, "not an xfig 3 file (its first line is not '#FIG 3.x')");
    return -1;
  }
  *minor = lx->s + 7 < lx->end && lx->s[6] == '.' ? lx->s[7] - '0' : 0;
  while (lx->s < lx->end && *lx->s != '\n') lx->s++;
  for (int k = 0; k < 12 && lx->s < lx->end; k++) {
    lx->s++, lx->line++;
    const char *e = memchr(lx->s, '\n', (size_t)(lx->end - lx->s));
    if (!e) e = lx->end;
    if (*lx->s != '#') {
      char buf[64];
      size_t n = (size_t)(e - lx->s) < sizeof buf - 1 ? (size_t)(e - lx->s) : sizeof buf - 1;
      memcpy(buf, lx->s, n);
      buf[n] = 0;
      int res, cs;
      char extra;
      if (sscanf(buf, "%d %d %c", &res, &cs, &extra) == 2) {
        lx->s = e;
        return 0;
      }
    }
    lx->s = e;
  }
  fail(lx, lx->line, "no resolution line ('1200 2') in the header");
  return -1;
}

int bg_fig_parse(const char *src, size_t len, bg_arena *a, bg_diags *dg, int file, bg_fig *out) {
  memset(out, 0, sizeof *out);
  lexer lx = {src, src + len, 1, 1, dg, file, 0};
  int minor;
  if (header(&lx, &minor)) return -1;
  int depth = 0;
  for (;;) {
    skip_blank(&lx);
    if (lx.failed || lx.s >= lx.end) break;
    if (out->n >= BG_FIG_MAX_OBJECTS) {
      fail(&lx, lx.line, "more than 1000000 objects");
      break;
    }
    int line = lx.obj_line = lx.line;
    int code = integer(&lx, "an object code");
    switch (code) {
    case 0: /* a colour: 0 NUMBER #rrggbb */
      number(&lx, "a colour number");
      while (lx.s < lx.end && *lx.s != '\n') lx.s++; /* #rrggbb: not a comment */
      break;
    case 1: /* ellipse */
      skip_numbers(&lx, 19, "an ellipse's fields");
      break;
    case 2: { /* polyline */
      bg_fig_obj o = {.kind = BG_FIG_LINE, .line = line};
      o.sub_type = integer(&lx, "a polyline's sub type");
      o.style = integer(&lx, "a line style");
      skip_numbers(&lx, 3, "thickness and colours");
      o.depth = integer(&lx, "a depth");
      skip_numbers(&lx, 6, "a polyline's fields");
      int fwd = integer(&lx, "forward arrow"), back = integer(&lx, "backward arrow");
      o.arrows = fwd || back;
      int np = count(&lx, "a polyline's number of points", 4);
      skip_arrows(&lx, fwd, back);
      if (o.sub_type == 5) { /* picture: flipped, then the file name to the line's end */
        number(&lx, "a picture's flip flag");
        while (lx.s < lx.end && *lx.s != '\n') lx.s++;
      }
      if (lx.failed) break;
      o.pts = bg_arena_alloc(a, (size_t)(np ? np : 1) * sizeof *o.pts);
      for (int i = 0; i < np && !lx.failed; i++) {
        o.pts[i].x = coordinate(&lx, "a point's x");
        o.pts[i].y = coordinate(&lx, "a point's y");
      }
      o.npts = np;
      if (!lx.failed) push(out, o);
      break;
    }
    case 3: { /* spline: control values after the points */
      int sub = integer(&lx, "a spline's sub type");
      skip_numbers(&lx, 9, "a spline's fields");
      int fwd = integer(&lx, "forward arrow"), back = integer(&lx, "backward arrow");
      int np = count(&lx, "a spline's number of points", 4);
      skip_arrows(&lx, fwd, back);
      skip_numbers(&lx, 2 * np, "a spline's points");
      if (minor >= 2) skip_numbers(&lx, np, "a spline's shape factors");
      else if (sub == 2 || sub == 3) skip_numbers(&lx, 4 * np, "a spline's control points");
      break;
    }
    case 4: { /* text */
      bg_fig_obj o = {.kind = BG_FIG_TEXT, .line = line};
      o.sub_type = integer(&lx, "a text's justification");
      number(&lx, "a colour");
      o.depth = integer(&lx, "a depth");
      skip_numbers(&lx, 7, "a text's fields");
      o.pts = bg_arena_alloc(a, sizeof *o.pts);
      o.pts[0].x = coordinate(&lx, "a text's x");
      o.pts[0].y = coordinate(&lx, "a text's y");
      o.npts = 1;
      if (lx.failed) break;
      o.text = text_string(&lx, a, line);
      if (!lx.failed) push(out, o);
      break;
    }
    case 5: { /* arc */
      skip_numbers(&lx, 11, "an arc's fields");
      int fwd = integer(&lx, "forward arrow"), back = integer(&lx, "backward arrow");
      skip_numbers(&lx, 8, "an arc's points");
      skip_arrows(&lx, fwd, back);
      break;
    }
    case 6:
      skip_numbers(&lx, 4, "a compound's corners");
      depth++;
      break;
    case -6:
      if (--depth < 0) fail(&lx, line, "'-6' ends a compound that was not begun");
      break;
    default:
      if (!lx.failed) {
        bg_diag_error(dg, (bg_srcloc){line, 1, file}, "xfig drawing: unknown object code %d", code);
        lx.failed = 1;
      }
    }
  }
  if (!lx.failed && depth > 0) fail(&lx, lx.line, "a compound object ('6') is not closed by '-6'");
  if (lx.failed) {
    free(out->objs);
    memset(out, 0, sizeof *out);
    return -1;
  }
  return 0;
}
