/* SPDX-License-Identifier: BSD-3-Clause */
/* The causality engine shared by the causality_*.c files (not a public
 * interface: other stages include causality/causality.h): a stroke store
 * with per-node counters, a worklist propagation that is linear in the
 * number of bonds, and an assignment log for trial propagation with
 * roll-back. */
#ifndef BG_CAUSALITY_INT_H
#define BG_CAUSALITY_INT_H
#include "causality/causality.h"

typedef struct bg_ceng {
  const bg_model *m;
  bg_analysis *a;
  int *stroke;              /* = a->bond_stroke */
  int *nat, *naway;         /* per element: bonds with the stroke at it / away from it */
  int *nblk;                /* per element: open bonds that propagation may not assign */
  unsigned char *blocked;   /* per bond: propagation may not assign it */
  unsigned char *split;     /* per bond: a Lagrange 1-junction was inserted into it */
  unsigned char *art;       /* per element: an artificial flow source sits at this 1-junction */
  unsigned char *force_der; /* per element: van Dijk gives this store derivative causality */
  int *queue, qhead, qlen;  /* circular worklist of nodes */
  unsigned char *inq;
  /* Junctions that could only complete by "all but one weak -> last one
   * strong" wait here until the worklist is empty, so a determination that
   * flows from a strong bond always wins over one by elimination (this is
   * what places relaxed-causality conflicts where docs/examples.md has them). */
  int *dqueue, dhead, dlen;
  unsigned char *indq;
  int *log, nlog;           /* bonds in the order they were assigned */
  int trial, bad;           /* in a trial: bad counts nodes whose violation grew */
  int step;                 /* trace step of the assignments being made */
  char **trace;             /* malloc'd texts */
  int ntrace, captrace;
  int nlag, caplag;         /* Lagrange sources found so far */
  /* The order every free choice is taken in, independent of the order of
   * the model's statements (docs/causality.md, "Ties"): bonds by number,
   * elements by name in natural order (R2 before R10), each element's bonds
   * by number. */
  int *bond_order, *elem_order;
  int *adj;                 /* like m->elem_bonds (elem_bondadr), sorted */
  int *lag_junction, *lag_bond;
} bg_ceng;

void bg_ceng_init(bg_ceng *E, const bg_model *m, bg_analysis *a);
void bg_ceng_reset(bg_ceng *E); /* back to no strokes, empty trace */
void bg_ceng_free(bg_ceng *E);
/* Element e's bonds in bond-number order (m->elem_nbond[e] of them). */
const int *bg_ceng_bonds(const bg_ceng *E, int e);

/* The stroke that puts bond b's stroke at node e (at != 0) or away from it. */
int bg_ceng_stroke_for(const bg_ceng *E, int b, int e, int at);
/* 1: stroke at e, 0: away from e (a split bond is away from both ends), -1: none. */
int bg_ceng_at(const bg_ceng *E, int b, int e);
int bg_ceng_open(const bg_ceng *E, int b); /* no stroke and not split */
/* Assigns a stroke (bond must be open) and queues both ends. */
void bg_ceng_set(bg_ceng *E, int b, int stroke, int reason);
/* Marks bond b split by an inserted 1-junction (Lagrange): away from both ends. */
void bg_ceng_split(bg_ceng *E, int b);
void bg_ceng_propagate(bg_ceng *E);
/* Assigns, propagates and keeps the result only if no node's rule became
 * more violated; returns 1 when kept. */
int bg_ceng_try(bg_ceng *E, int b, int stroke, int reason);
/* How badly node e breaks its rule now (0 = fine); for junctions the
 * conflict degree (type 2) or 1 (type 1 once all bonds are assigned). */
int bg_ceng_badness(const bg_ceng *E, int e);
int bg_ceng_port(const bg_ceng *E, int e); /* bond of a one-port */

/* The trace: bg_ceng_trace appends a step; bg_ceng_prop_list writes the
 * bonds assigned since log position `mark` (after the first `skip`). */
void bg_ceng_trace(bg_ceng *E, const char *text);
struct bg_strbuf;
void bg_ceng_prop_list(const bg_ceng *E, int mark, struct bg_strbuf *sb);

/* Element's natural or optioned causality helpers. */
int bg_ceng_r_nonlinear(const bg_model *m, int e);
int bg_ceng_r_natural(const bg_model *m, int e); /* BG_CAUS_RESISTANCE / CONDUCTANCE */
/* Stroke of a one-port's bond for a causality (BG_CAUS_*). */
int bg_ceng_oneport_stroke(const bg_ceng *E, int e, int caus);
/* Causality of a one-port from its stroke (BG_CAUS_NONE when open). */
int bg_ceng_oneport_caus(const bg_ceng *E, int e);

/* Shared first steps (causality_scap.c): block the bonds that steps assign
 * explicitly (sources, fixed strokes; nonlinear R when relaxed), then the
 * fixed strokes by bond number and the sources by name. */
void bg_ceng_block(bg_ceng *E, int relaxed);
void bg_ceng_fixed(bg_ceng *E);
void bg_ceng_sources(bg_ceng *E);
/* Procedures (causality_scap.c, causality_lagrange.c, causality_vandijk.c). */
void bg_ceng_scap(bg_ceng *E, int relaxed);
void bg_ceng_lagrange(bg_ceng *E);
void bg_ceng_vandijk(bg_ceng *E);
/* Writes elem_caus, elem_inverted, conflicts, complete, trace and lag lists into E->a. */
void bg_ceng_finish(bg_ceng *E);
/* The generalised force of Lagrange source i in words (causality_lagrange.c). */
void bg_ceng_lag_force(const bg_ceng *E, int i, struct bg_strbuf *sb);
#endif
