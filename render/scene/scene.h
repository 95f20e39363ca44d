/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_scene: a backend-neutral display list. diagram.c fills it from the model
 * and the analysis; each surface (SVG, PDF, PNG) replays it unchanged, so all
 * formats show the same picture. Coordinates are points, y pointing down,
 * origin at the top-left corner of the page. Every item carries a role tag
 * ("stroke bond=3", "flash conflict=1") so tests can count what was drawn
 * from a text dump instead of parsing SVG. */
#ifndef BG_SCENE_H
#define BG_SCENE_H
#include "base/arena.h"
#include "base/strbuf.h"

typedef struct bg_rgba {
  double r, g, b, a;
} bg_rgba;

typedef enum { BG_OP_MOVE, BG_OP_LINE, BG_OP_CURVE, BG_OP_CLOSE } bg_scene_opcode;

/* A path is stored as slots, one point each (16 bytes and a code byte: a
 * line of two points takes 34 bytes, not the 112 of two whole operations):
 * MOVE, LINE and CLOSE take one slot (CLOSE's point is unused), CURVE three
 * (two controls, the end), all three with the code CURVE. */
typedef struct bg_scene_pt {
  double x, y;
} bg_scene_pt;

/* One path operation as read back from its slots (bg_scene_next_op): CURVE
 * uses all three points (two controls, the end), MOVE and LINE the first. */
typedef struct bg_scene_op {
  int code; /* bg_scene_opcode */
  double x[3], y[3];
} bg_scene_op;

typedef enum {
  BG_ITEM_STROKE, /* the path is stroked */
  BG_ITEM_FILL,   /* the path is filled, then outlined when width > 0 */
  BG_ITEM_TEXT    /* pango markup anchored at (x, y) */
} bg_item_kind;

typedef struct bg_scene_item {
  int kind;         /* bg_item_kind */
  int round;        /* round caps and joins (else butt caps, miter joins) */
  int opadr, nop;   /* path slots, into bg_scene.pt and .code (a text item has none) */
  bg_rgba color;    /* line or text colour */
  const char *text; /* TEXT: pango markup, owned by the scene; NULL for paths */
  const char *role; /* owned by the scene */
  /* What only paths and what only text need share their bytes (120 bytes an
   * item instead of 184: a 100 000-mass diagram has two million items). Read
   * a field of the other kind's part and you read the other part's bytes. */
  union {
    struct {          /* STROKE and FILL */
      bg_rgba fill;   /* FILL only */
      double width;   /* line width; FILL: outline width, 0 = none */
      double dash[2]; /* on, off lengths; dash[0] == 0: solid */
    };
    struct {               /* TEXT */
      double x, y;         /* anchor */
      double size;         /* font size in points */
      double halign, valign; /* 0 left/top, 0.5 centre, 1 right/bottom */
      double tw, th;       /* measured size, points */
    };
  };
} bg_scene_item;

typedef struct bg_scene {
  double width, height; /* page size in points */
  bg_rgba background;
  const char *font;     /* font family for every text item; owned */
  const char *title;    /* nullable; owned */
  bg_scene_item *item;
  int nitem, capitem;
  bg_scene_pt *pt;      /* path slots: points */
  unsigned char *code;  /* path slots: bg_scene_opcode */
  int nop, capop;       /* slots used, allocated */
  bg_arena arena;       /* strings */
} bg_scene;

void bg_scene_init(bg_scene *s, const char *font);
void bg_scene_free(bg_scene *s);
/* Starts a new item (path items get their operations from the calls below).
 * The returned pointer is valid until the next bg_scene_begin. */
bg_scene_item *bg_scene_begin(bg_scene *s, int kind, const char *role_fmt, ...)
    __attribute__((format(printf, 3, 4)));
/* Reads the operation at slot *k of item it's path into o and moves *k past
 * it; returns 0 past the last: for (int k = 0; bg_scene_next_op(s, it, &k, &o);). */
static inline int bg_scene_next_op(const bg_scene *s, const bg_scene_item *it, int *k, bg_scene_op *o) {
  if (*k >= it->nop) return 0;
  int a = it->opadr + *k, n = s->code[a] == BG_OP_CURVE ? 3 : 1;
  o->code = s->code[a];
  for (int j = 0; j < n; j++) o->x[j] = s->pt[a + j].x, o->y[j] = s->pt[a + j].y;
  *k += n;
  return 1;
}
void bg_scene_move(bg_scene *s, double x, double y);
void bg_scene_line(bg_scene *s, double x, double y);
void bg_scene_curve(bg_scene *s, double x1, double y1, double x2, double y2, double x3,
                    double y3);
void bg_scene_close(bg_scene *s);
/* A closed circle of radius r around (x, y): four cubic Béziers from its
 * rightmost point, clockwise in page coordinates (y down). */
void bg_scene_circle(bg_scene *s, double x, double y, double r);
/* A text item; markup is copied. */
bg_scene_item *bg_scene_text(bg_scene *s, const char *markup, double x, double y, double size,
                             double halign, double valign, bg_rgba color, const char *role);
/* Bounding box of everything drawn (line widths and text boxes included);
 * returns 0 when the scene is empty. */
int bg_scene_bbox(const bg_scene *s, double *x0, double *y0, double *x1, double *y1);
/* A box that surely holds everything item it draws (text: its measured box
 * plus its font size for ink beyond it; lines: their points plus what caps
 * and miter joins can add): x0, y0, x1, y1. Empty paths give x0 > x1. */
void bg_scene_item_box(const bg_scene *s, const bg_scene_item *it, double b[4]);
/* dst (initialised here) gets the items of src whose box meets the
 * rectangle clip (x0, y0, x1, y1), in their order, with src's page size,
 * background, font and title. Replaying dst clipped to any rectangle inside
 * clip draws what src draws there: the report keeps only this much of a
 * highlighted diagram that shows one part of a large one. */
void bg_scene_crop(const bg_scene *src, const double clip[4], bg_scene *dst);
/* The same with a say over each item that meets clip: keep(ctx, src, i,
 * copy) returns 0 to leave item i out, 1 to keep its copy (whose colours it
 * may change; its path and strings are src's until the crop copies them). */
typedef int (*bg_scene_keep_fn)(void *ctx, const bg_scene *src, int i, bg_scene_item *copy);
void bg_scene_crop_keep(const bg_scene *src, const double clip[4], bg_scene_keep_fn keep, void *ctx,
                        bg_scene *dst);
/* Moves everything so the bounding box starts at (margin, margin) and sets
 * the page size to the box plus margins. */
void bg_scene_fit(bg_scene *s, double margin);
/* Lists every item, one a line: role, kind, colour and rounded geometry.
 * Stable text, meant for tests and debugging. */
void bg_scene_dump(const bg_scene *s, bg_strbuf *out);
/* Number of items whose role starts with prefix followed by a space or the
 * end of the role ("path" counts "path 1", not "path-arrow 1"). */
int bg_scene_count(const bg_scene *s, const char *prefix);

/* Text metrics, implemented with pango in text.c with the settings the
 * surfaces draw with: the logical size in points of markup set in font at
 * size points. Safe to call from several threads (text.c's lock). */
void bg_text_measure(const char *font, double size, const char *markup, double *w, double *h);
/* Appends the first n bytes of s (or s up to its end) with pango markup's
 * special characters escaped; bg_markup_escape takes all of s. Every text
 * item that shows user text (names, labels, titles, gains) goes through it. */
void bg_markup_escapen(bg_strbuf *b, const char *s, size_t n);
void bg_markup_escape(bg_strbuf *b, const char *s);
#endif
