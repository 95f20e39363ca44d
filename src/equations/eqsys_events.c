/* SPDX-License-Identifier: BSD-3-Clause */
/* State events (docs/simulation.md, "State events"): the instructions of the
 * main tape whose switching condition reads an unknown (a comparison, abs,
 * sign, step, ramp, pulse, min, max, sat, floor, ceil, a table segment),
 * one root function per switching condition, and a mode per instruction:
 * between events the solver evaluates the branch the mode holds (continued
 * smoothly past its switching point), so Newton and the error test never
 * see the kink; at a root the simulation stops, sets the modes from the
 * values there and restarts. Conditions of t shifted by a constant in
 * step, ramp, pulse and tables are input breakpoints (bg_eqsys_breakpoints),
 * not events; other conditions of t (step(sin(t)), t > 1) are events.
 * A mode whose two sides are one law where it switches (a continuous
 * piecewise law) and whose switching function chatters in the solver's
 * noise is let loose: evaluated as compiled until that function leaves a
 * band round 0 (bg_eqsys_mode_loosen; docs/simulation.md, "Continuous
 * switches"). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "equations/eqsys_int.h"
#include "model/model.h"

/* ------------------------------------------------------------ which ops */
/* Number of root functions of instruction I (0: not piecewise), and in
 * *cond the bitmask of its arguments whose dependence makes it an event. */
static int roots_of(const bg_eqsys *s, const tinstr *I, int *cond) {
  *cond = 1;
  switch (I->op) {
  case BG_X_LT: case BG_X_LE: case BG_X_GT: case BG_X_GE: *cond = 3; return 1;
  case BG_X_TABLE: return s->m->table_n[I->ref] > 1 ? 2 : 0;
  case BG_X_CALL: break;
  default: return 0; /* == and != hold at an instant only; logic follows its comparisons */
  }
  switch (I->ref) {
  case BG_FN_ABS: case BG_FN_SIGN: case BG_FN_STEP: case BG_FN_RAMP: return 1;
  case BG_FN_FLOOR: case BG_FN_CEIL: return 2;
  case BG_FN_MIN: case BG_FN_MAX: *cond = 3; return 1;
  case BG_FN_PULSE: *cond = 3; return 2;
  case BG_FN_SAT: *cond = 7; return 2;
  case BG_FN_HYST: case BG_FN_STICK: *cond = 7; return 2; /* memory: one root per way out of each mode */
  default: return 0; /* if() switches where its condition (a comparison) does */
  }
}

/* Which slots read y or yp (bit 1) and which read t (bit 2). */
static void mark_deps(bg_eqsys *s) {
  s->slot_dep = bg_arena_alloc(&s->arena, (size_t)s->nslot + 1);
  memset(s->slot_dep, 0, (size_t)s->nslot + 1);
  memset(s->slot_dep + s->slot_y, 1, (size_t)(2 * s->n));
  s->slot_dep[0] = 2; /* t */
  for (int k = 0; k < s->nmain; k++) {
    const tinstr *I = &s->code[k];
    unsigned char d = 0;
    if (I->op == T_LIN)
      for (int q = 0; q < I->a[0]; q++) d |= s->slot_dep[s->tl_slot[I->ref + q]];
    else
      for (int q = 0; q < I->na; q++) d |= s->slot_dep[I->a[q]];
    s->slot_dep[I->out] = d;
  }
}

/* t, t + c, t - c, c + t (c constant): the arguments an input breakpoint
 * covers (bg_eqsys_breakpoints); prod: the instruction producing each slot. */
static int t_shift(const bg_eqsys *s, const int *prod, int slot) {
  if (slot == 0) return 1;
  int k = prod[slot];
  if (k < 0) return 0;
  const tinstr *I = &s->code[k];
  if (I->op == BG_X_ADD) return (I->a[0] == 0 && s->is_const[I->a[1]]) || (I->a[1] == 0 && s->is_const[I->a[0]]);
  if (I->op == BG_X_SUB) return I->a[0] == 0 && s->is_const[I->a[1]];
  return 0;
}

/* Whether instruction k is an event: its switching arguments read an
 * unknown, or read t in a way no input breakpoint covers (step(sin(t)),
 * t > 1, floor(t): a breakpoint is known only for step, ramp, pulse and
 * tables of t shifted by a constant). */
static int is_event(const bg_eqsys *s, const int *prod, int k, int *nr) {
  const tinstr *I = &s->code[k];
  int cond, dep = 0, tdep = 0;
  *nr = roots_of(s, I, &cond);
  if (!*nr) return 0;
  for (int q = 0; q < I->na && q < 3; q++)
    if (cond >> q & 1) dep |= s->slot_dep[I->a[q]] & 1, tdep |= (s->slot_dep[I->a[q]] & 2) != 0;
  if (dep) return 1;
  if (!tdep) return 0;
  int covered = (I->op == BG_X_TABLE ||
                 (I->op == BG_X_CALL && (I->ref == BG_FN_STEP || I->ref == BG_FN_RAMP || I->ref == BG_FN_PULSE))) &&
                t_shift(s, prod, I->a[0]) && (I->op != BG_X_CALL || I->ref != BG_FN_PULSE || s->is_const[I->a[1]]);
  return !covered;
}

static const char *sub_text(const tinstr *I, int sub) {
  if (I->op == BG_X_TABLE) return sub ? " (segment's upper end)" : " (segment's lower end)";
  if (I->ref == BG_FN_SAT) return sub ? " (upper limit)" : " (lower limit)";
  if (I->ref == BG_FN_HYST) return sub ? " (falls: the lower threshold reached)" : " (rises: the upper threshold reached)";
  if (I->ref == BG_FN_STICK) return sub ? " (sticks: the velocity crosses 0)" : " (slips: the force reaches the limit)";
  if (I->ref == BG_FN_PULSE) return sub ? " (end)" : " (start)";
  if (I->ref == BG_FN_FLOOR || I->ref == BG_FN_CEIL) return sub ? " (next integer up)" : " (next integer down)";
  return "";
}

/* "law of D" and "e2 > 0": where the condition sits and what it is. */
static void where_what(const bg_eqsys *s, const tinstr *I, bg_strbuf *where, bg_strbuf *what) {
  const bg_model *m = s->m;
  if (I->eq >= 0) bg_sb_printf(where, "%s of %s", s->sig_what[I->eq], m->elem_name[s->sig_elem[I->eq]]);
  else if (I->eq > -1000000) bg_sb_printf(where, "equation of %s", s->uname[-1 - I->eq]);
  if (I->xn >= 0) bg_xprint(m, I->xn, what);
  else bg_sb_puts(what, "?");
}

void bg_eqsys_mode_describe(const bg_eqsys *s, int e, bg_strbuf *where, bg_strbuf *what) {
  where_what(s, &s->code[s->ev_code[e]], where, what);
}

/* "law of D: e2 > 0" with the root's part ("(upper limit)"). */
static const char *describe(bg_eqsys *s, const tinstr *I, int sub) {
  bg_strbuf sb = {0}, what = {0};
  where_what(s, I, &sb, &what);
  if (sb.len) bg_sb_puts(&sb, ": ");
  bg_sb_puts(&sb, bg_sb_str(&what));
  bg_sb_free(&what);
  bg_sb_puts(&sb, sub_text(I, sub));
  char *t = bg_arena_alloc(&s->arena, sb.len + 1);
  memcpy(t, bg_sb_str(&sb), sb.len + 1);
  bg_sb_free(&sb);
  return t;
}

void bg_eqs_events_find(bg_eqsys *s) {
  mark_deps(s);
  int nev = 0, nroot = 0, nr;
  int *prod = bg_xmalloc((size_t)(s->nslot + 1) * sizeof(int));
  for (int i = 0; i <= s->nslot; i++) prod[i] = -1;
  for (int k = 0; k < s->nmain; k++) prod[s->code[k].out] = k;
  for (int k = 0; k < s->nmain; k++)
    if (is_event(s, prod, k, &nr)) nev++, nroot += nr;
  s->nev = nev, s->nroot = nroot;
  if (!nev) { free(prod); return; }
  s->code_ev = bg_arena_alloc(&s->arena, (size_t)s->nmain * sizeof(int));
  s->ev_code = bg_arena_alloc(&s->arena, (size_t)nev * sizeof(int));
  s->ev_root0 = bg_arena_alloc(&s->arena, (size_t)nev * sizeof(int));
  s->ev_mode = bg_arena_alloc(&s->arena, (size_t)nev * sizeof(double));
  s->root_ev = bg_arena_alloc(&s->arena, (size_t)nroot * sizeof(int));
  s->root_text = bg_arena_alloc(&s->arena, (size_t)nroot * sizeof(char *));
  s->ev_prev = bg_arena_alloc(&s->arena, (size_t)nev * sizeof(double));
  s->ev_zero = bg_arena_alloc(&s->arena, (size_t)nev);
  s->ev_free = bg_arena_alloc(&s->arena, (size_t)nev);
  memset(s->ev_free, 0, (size_t)nev);
  s->ev_band = bg_arena_alloc(&s->arena, (size_t)nev * sizeof(double));
  memset(s->ev_band, 0, (size_t)nev * sizeof(double));
  s->ev_mem = bg_arena_alloc(&s->arena, (size_t)nev);
  s->ev_y = bg_arena_alloc(&s->arena, (size_t)(s->n + 1) * sizeof(double));
  s->ev_yp = bg_arena_alloc(&s->arena, (size_t)(s->n + 1) * sizeof(double));
  nev = nroot = 0;
  for (int k = 0; k < s->nmain; k++) {
    const tinstr *I = &s->code[k];
    s->code_ev[k] = -1;
    if (!is_event(s, prod, k, &nr)) continue;
    s->code_ev[k] = nev, s->ev_code[nev] = k, s->ev_root0[nev] = nroot, s->ev_mode[nev] = 0;
    s->ev_mem[nev] = I->op == BG_X_CALL && (I->ref == BG_FN_HYST || I->ref == BG_FN_STICK);
    s->nmem += s->ev_mem[nev];
    for (int j = 0; j < nr; j++) s->root_ev[nroot + j] = nev, s->root_text[nroot + j] = describe(s, I, j);
    nev++, nroot += nr;
  }
  free(prod);
}

/* ------------------------------------------------------------ tables */
/* Segment k of x: -1 left of the first point, n - 1 from the last one on,
 * else tx[k] <= x < tx[k+1]; a point exactly on a breakpoint that is
 * left going down (dir < 0) belongs to the segment below. */
static int table_segment_of(const double *tx, int n, double x, int dir) {
  int k;
  if (x < tx[0]) k = -1;
  else if (x >= tx[n - 1]) k = n - 1;
  else {
    int lo = 0, hi = n - 1; /* tx[lo] <= x < tx[hi] */
    while (hi - lo > 1) {
      int mid = (lo + hi) / 2;
      if (tx[mid] <= x) lo = mid;
      else hi = mid;
    }
    k = lo;
  }
  if (dir < 0 && k >= 0 && x == tx[k]) k--;
  return k;
}

/* ------------------------------------------------------------ modes */
static double eff(double g, int dir) { return g != 0 ? g : (double)dir; }

/* The root functions of event e at the values v (continuous in the
 * unknowns whatever the mode; their signs decide the mode). */
static void ev_roots(const bg_eqsys *s, int e, const double *v, double *g) {
  const tinstr *I = &s->code[s->ev_code[e]];
  double x = v[I->a[0]], y = I->na > 1 ? v[I->a[1]] : 0, mode = s->ev_mode[e];
  if (I->op != BG_X_CALL && I->op != BG_X_TABLE) { g[0] = x - y; return; }
  if (I->op == BG_X_TABLE) {
    const bg_model *m = s->m;
    const double *tx = m->table_x + m->table_adr[I->ref];
    int n = m->table_n[I->ref], k = (int)mode;
    g[0] = k >= 0 ? x - tx[k] : 1.0;
    g[1] = k + 1 <= n - 1 ? x - tx[k + 1] : -1.0;
    return;
  }
  switch (I->ref) {
  case BG_FN_MIN: case BG_FN_MAX: g[0] = x - y; return;
  case BG_FN_PULSE: g[0] = x, g[1] = x - y; return;
  case BG_FN_SAT: g[0] = x - y, g[1] = x - v[I->a[2]]; return;
  /* memory (docs/format.md, "Memory"): only the way out of the mode held
   * is watched; the other root function is a constant that never crosses */
  case BG_FN_HYST: g[0] = mode ? -1.0 : x - v[I->a[2]], g[1] = mode ? x - y : 1.0; return;
  case BG_FN_STICK: g[0] = mode ? fabs(y) - v[I->a[2]] : -1.0, g[1] = mode ? 1.0 : x; return;
  case BG_FN_FLOOR: g[0] = x - mode, g[1] = x - (mode + 1); return;
  case BG_FN_CEIL: g[0] = x - (mode - 1), g[1] = x - mode; return;
  default: g[0] = x; return;
  }
}

/* The mode of event e from the actual values v; dir (nullable, indexed
 * like its roots) is the direction of a root just found, which decides a
 * switching function that is exactly zero. */
static double ev_mode_of(const bg_eqsys *s, int e, const double *v, const int *dir) {
  const tinstr *I = &s->code[s->ev_code[e]];
  double g[2] = {0, 0}, x = v[I->a[0]];
  int d0 = dir ? dir[0] : 0, d1 = dir && roots_of(s, I, &(int){0}) > 1 ? dir[1] : 0;
  ev_roots(s, e, v, g);
  double g0 = eff(g[0], d0), g1 = eff(g[1], d1);
  switch (I->op) {
  case BG_X_LT: return g0 < 0;
  case BG_X_LE: return g0 <= 0;
  case BG_X_GT: return g0 > 0;
  case BG_X_GE: return g0 >= 0;
  case BG_X_TABLE: {
    const bg_model *m = s->m;
    return table_segment_of(m->table_x + m->table_adr[I->ref], m->table_n[I->ref], x, d0 ? d0 : d1);
  }
  default: break;
  }
  switch (I->ref) {
  case BG_FN_SIGN: return g0 > 0 ? 1 : g0 < 0 ? -1 : 0;
  case BG_FN_MIN: return g0 <= 0;
  case BG_FN_MAX: case BG_FN_ABS: case BG_FN_STEP: case BG_FN_RAMP: return g0 >= 0;
  case BG_FN_PULSE: return g0 >= 0 && g1 < 0;
  case BG_FN_SAT: return g0 < 0 ? 0 : g1 > 0 ? 2 : 1;
  /* memory: the mode held changes only when its way out is reached; at
   * the start of a run (ev_fresh) the value the function starts with */
  case BG_FN_HYST:
    if (s->ev_fresh) return x >= v[I->a[2]];
    return s->ev_mode[e] ? g1 > 0 : g0 >= 0;
  case BG_FN_STICK: {
    double f = fabs(v[I->a[1]]), lim = v[I->a[2]];
    if (s->ev_fresh) return x == 0 && f <= lim;
    if (s->ev_mode[e]) return !(g0 > 0);
    /* slipping: sticks where the velocity crosses 0 (its root) or sits at
     * 0, unless the force there is beyond the limit (it slips on) */
    return (d1 != 0 || x == 0) && (d1 != 0 ? f <= lim : f < lim);
  }
  case BG_FN_FLOOR: return floor(x) - (x == floor(x) && (d0 < 0 || d1 < 0));
  case BG_FN_CEIL: return ceil(x) + (x == ceil(x) && (d0 > 0 || d1 > 0));
  default: return 0;
  }
}

/* ------------------------------------------------------------ public */
int bg_eqsys_nroots(const bg_eqsys *s) { return s->nroot; }
int bg_eqsys_nmodes(const bg_eqsys *s) { return s->nev; }
const char *bg_eqsys_root_text(const bg_eqsys *s, int i) { return s->root_text[i]; }
void bg_eqsys_modes_get(const bg_eqsys *s, double *modes) {
  if (s->nev) memcpy(modes, s->ev_mode, (size_t)s->nev * sizeof(double));
}
void bg_eqsys_modes_set(bg_eqsys *s, const double *modes) {
  if (s->nev) memcpy(s->ev_mode, modes, (size_t)s->nev * sizeof(double));
}
int bg_eqsys_mode_direction(const bg_eqsys *s, int e, double before, double after) {
  const tinstr *I = &s->code[s->ev_code[e]];
  int up = after > before ? 1 : -1;
  /* a < b, a <= b and min(a, b) hold their mode 1 while the root function
   * a - b is below 0: entering it is falling */
  if (I->op == BG_X_LT || I->op == BG_X_LE || (I->op == BG_X_CALL && I->ref == BG_FN_MIN)) return -up;
  if (I->op == BG_X_CALL && I->ref == BG_FN_STICK) return -up; /* slipping: |F| - limit rose through 0 */
  return up;
}

int bg_eqsys_mode_memory(const bg_eqsys *s, int e) { return s->ev_mem[e]; }
int bg_eqsys_has_memory(const bg_eqsys *s) { return s->nmem; }
void bg_eqsys_modes_reset(bg_eqsys *s) {
  s->ev_fresh = 1;
  if (s->nev) memset(s->ev_band, 0, (size_t)s->nev * sizeof(double)); /* each run starts with every mode held */
}

int bg_eqsys_mode_roots(const bg_eqsys *s, int e, int *first) {
  int cond;
  *first = s->ev_root0[e];
  return roots_of(s, &s->code[s->ev_code[e]], &cond);
}
void bg_eqsys_modes_freeze(bg_eqsys *s, int on) { s->ev_frozen = on && s->nev; }

static int roots_finite(bg_eqsys *s, double *g) {
  for (int e = 0; e < s->nev; e++) {
    double *ge = g + s->ev_root0[e];
    ev_roots(s, e, s->v, ge);
    /* loose: crosses 0 where the switching function leaves its band */
    for (int j = 0, c; s->ev_band[e] > 0 && j < roots_of(s, &s->code[s->ev_code[e]], &c); j++)
      ge[j] = s->ev_band[e] - fabs(ge[j]);
  }
  for (int i = 0; i < s->nroot; i++)
    if (!isfinite(g[i])) return 0;
  return 1;
}

/* The file line of the law or equation instruction I belongs to, or 0. */
static int line_of(const bg_eqsys *s, const tinstr *I) {
  const bg_model *m = s->m;
  if (I->eq >= 0) return m->elem_loc[s->sig_elem[I->eq]].line;
  if (I->eq <= -1000000) return 0;
  char name[256]; /* an unknown R1.f: element R1 */
  snprintf(name, sizeof name, "%s", s->uname[-1 - I->eq]);
  char *dot = strrchr(name, '.');
  if (dot) *dot = '\0';
  int e = bg_model_find_elem(m, name);
  return e >= 0 ? m->elem_loc[e].line : 0;
}

/* A root function that is not a number: which condition, where in the
 * file, and why (the operation that left its domain), in s->err. */
static void explain_roots(bg_eqsys *s, const double *g, double t) {
  int i = 0;
  while (i < s->nroot - 1 && isfinite(g[i])) i++;
  const tinstr *I = &s->code[s->ev_code[s->root_ev[i]]];
  int slot = -1;
  for (int q = 0; q < I->na && q < 3 && slot < 0; q++)
    if (!isfinite(s->v[I->a[q]])) slot = I->a[q];
  const char *what = slot >= 0 ? bg_eqs_why_not_finite(s, slot) : "a value that is not a finite number";
  int line = line_of(s, I);
  char at[32] = "";
  if (line > 0) snprintf(at, sizeof at, " (line %d)", line);
  /* formatted whole, then cut to s->err's size (a long reason and
   * condition are cut at the end, never mid-way) */
  bg_strbuf sb = {0};
  bg_sb_printf(&sb, "%s in the switching condition '%.150s'%s at t = %g", what, s->root_text[i], at, t);
  size_t n = sb.len < sizeof s->err ? sb.len : sizeof s->err - 1;
  memcpy(s->err, bg_sb_str(&sb), n);
  s->err[n] = 0;
  bg_sb_free(&sb);
  s->has_err = 1;
}

int bg_eqsys_roots(bg_eqsys *s, double t, const double *y, const double *yp, double *g) {
  bg_eqs_eval_raw(s, t, y, yp);
  if (roots_finite(s, g)) return 0;
  int was = s->ev_frozen; /* as bg_eqs_eval: the values as compiled then */
  s->ev_frozen = 0;
  bg_eqs_eval_raw(s, t, y, yp);
  s->ev_frozen = was;
  if (roots_finite(s, g)) return 0;
  explain_roots(s, g, t);
  return -1;
}

/* One pass over the main tape that sets the modes of the events (all, or
 * those with only[e]) from the values as they are computed. */
static void modes_pass(bg_eqsys *s, double t, const double *y, const double *yp, const int *dir,
                       const unsigned char *only) {
  double *v = s->v;
  v[0] = t;
  memcpy(v + s->slot_y, y, (size_t)s->n * sizeof *v);
  if (yp) memcpy(v + s->slot_yp, yp, (size_t)s->n * sizeof *v);
  else memset(v + s->slot_yp, 0, (size_t)s->n * sizeof *v);
  for (int k = 0; k < s->nmain; k++) {
    int e = s->code_ev[k];
    if (e >= 0 && (!only || only[e]) && !(s->ev_band[e] > 0))
      s->ev_mode[e] = ev_mode_of(s, e, v, dir ? dir + s->ev_root0[e] : NULL);
    v[s->code[k].out] = e >= 0 ? bg_eqs_ev_value(s, e, v) : bg_eqs_ins_value(s, k, v);
  }
}

/* 1 when a root function of event e is exactly zero at the current values
 * and no root direction decides it. */
static int undecided(const bg_eqsys *s, int e, const int *dir) {
  double g[2] = {1, 1};
  int cond, nr = roots_of(s, &s->code[s->ev_code[e]], &cond);
  ev_roots(s, e, s->v, g);
  for (int j = 0; j < nr; j++)
    if (g[j] == 0 && !(dir && dir[s->ev_root0[e] + j])) return 1;
  return 0;
}

/* An ODE's look-ahead chose the modes of the switching functions exactly
 * zero at (t, y) from where the right-hand side moves y a moment later under
 * the modes as they were. Looked ahead again under the chosen modes: when a
 * function decided that way lands on the other side (a law with a jump
 * whose two sides each push the state to the other, e.g. friction stronger
 * than the push on a mass at rest) no mode holds there, a sliding mode at
 * its start; holding the chosen mode would be wrong from the first step
 * (SUNDIALS deactivates a root function that is 0 at the start and lets it
 * take its sign silently). Returns 1 + the first such event, or 0. The
 * modes are left as the first look-ahead chose them. */
static int sliding(bg_eqsys *s, double t, const double *y, double delta, const unsigned char *decided) {
  double *chosen = bg_xmalloc((size_t)s->nev * sizeof(double));
  int nd = 0, found = 0;
  for (int e = 0; e < s->nev; e++) nd += decided[e];
  memcpy(chosen, s->ev_mode, (size_t)s->nev * sizeof(double));
  if (nd && bg_eqsys_rhs(s, t, y, s->ev_yp) == 0) {
    for (int i = 0; i < s->n; i++) s->ev_y[i] = y[i] + delta * s->ev_yp[i];
    modes_pass(s, t + delta, s->ev_y, NULL, NULL, decided);
    for (int e = 0; e < s->nev && !found; e++)
      if (decided[e] && !undecided(s, e, NULL) && s->ev_mode[e] != chosen[e]) found = 1 + e;
  }
  memcpy(s->ev_mode, chosen, (size_t)s->nev * sizeof(double));
  free(chosen);
  return found;
}

int bg_eqsys_mode_sliding(const bg_eqsys *s) { return s->ev_sliding - 1; }

int bg_eqsys_modes_update(bg_eqsys *s, double t, const double *y, const double *yp, const int *dir,
                          double delta) {
  s->ev_sliding = 0;
  if (!s->nev) return 0;
  unsigned char *zero = s->ev_zero;
  int changed = 0, nzero = 0, was = s->ev_frozen;
  memcpy(s->ev_prev, s->ev_mode, (size_t)s->nev * sizeof(double));
  memset(s->ev_free, 0, (size_t)s->nev);
  modes_pass(s, t, y, yp, dir, NULL);
  s->ev_fresh = 0;
  /* A switching function exactly zero here leaves to one side or the other
   * without a sign change the root finder could see: decide it by where the
   * solution is a moment later, y + delta y' (y' under the modes just set). */
  for (int e = 0; e < s->nev; e++) nzero += zero[e] = (unsigned char)undecided(s, e, dir);
  if (nzero && delta > 0) {
    s->ev_frozen = 1;
    const double *ydot = yp;
    if (!yp && bg_eqsys_rhs(s, t, y, s->ev_yp) == 0) ydot = s->ev_yp;
    if (ydot) {
      for (int i = 0; i < s->n; i++) s->ev_y[i] = y[i] + delta * ydot[i];
      unsigned char *decided = bg_xmalloc((size_t)s->nev);
      memcpy(decided, zero, (size_t)s->nev);
      modes_pass(s, t + delta, s->ev_y, yp, NULL, zero);
      for (int e = 0; e < s->nev; e++) zero[e] = zero[e] && undecided(s, e, NULL), decided[e] &= !zero[e];
      if (!yp) s->ev_sliding = sliding(s, t, y, delta, decided);
      free(decided);
    }
  }
  /* Still zero a moment later (hydraulic_lift's throttle: its pressure drop
   * starts at 0 and leaves it with its second derivative): no side can be
   * held, and the root finder will not report its leaving 0 (SUNDIALS
   * deactivates a root function that is 0 at the start and then takes its
   * sign silently). Evaluated as compiled until its next root. */
  for (int e = 0; e < s->nev; e++) s->ev_free[e] = (zero[e] && nzero) || s->ev_band[e] > 0;
  s->ev_frozen = was;
  for (int e = 0; e < s->nev; e++) changed += s->ev_prev[e] != s->ev_mode[e];
  return changed;
}

/* The modes of the limit from the right at a point where switching
 * functions sit at 0 together (a diode bridge at the end of a conduction
 * interval: two diodes in series leave it at once, and the modes from the
 * values at t flip back and forth): the differential unknowns moved to
 * t + delta along yp, the algebraic ones solved there under the current
 * modes (held: each mode is smooth), the modes set from that point, until
 * they no longer change. All at once for two rounds; then one mode at a
 * time (the first that disagrees), since two diodes in series that each
 * flip when the other does never meet at "both off" all at once. Returns 0
 * when they agree, 1 when they still changed after maxit rounds, -1 when a
 * solve failed. */
int bg_eqsys_modes_right(bg_eqsys *s, double t, const double *y, const double *yp, double delta, int maxit) {
  if (!s->nev || !(delta > 0)) return 0;
  int was = s->ev_frozen, rc = 1;
  s->ev_frozen = 1;
  for (int e = 0; e < s->nev; e++) s->ev_free[e] = s->ev_band[e] > 0;
  for (int k = 0; k < maxit && rc == 1; k++) {
    for (int i = 0; i < s->n; i++) s->ev_y[i] = y[i] + delta * yp[i];
    if (bg_eqsys_consistent(s, t + delta, s->ev_y, 30)) { rc = -1; break; }
    memcpy(s->ev_prev, s->ev_mode, (size_t)s->nev * sizeof(double));
    modes_pass(s, t + delta, s->ev_y, yp, NULL, NULL);
    int first = -1;
    for (int e = 0; e < s->nev && first < 0; e++)
      if (s->ev_mode[e] != s->ev_prev[e]) first = e;
    if (first < 0) rc = 0;
    else if (k >= 2) { /* one at a time */
      double keep = s->ev_mode[first];
      memcpy(s->ev_mode, s->ev_prev, (size_t)s->nev * sizeof(double));
      s->ev_mode[first] = keep;
    }
  }
  s->ev_frozen = was;
  s->has_err = 0;
  return rc;
}

/* ------------------------------------------------------------ loose modes
 * docs/simulation.md, "Continuous switches". */
int bg_eqsys_root_mode(const bg_eqsys *s, int i) { return s->root_ev[i]; }
int bg_eqsys_mode_loose(const bg_eqsys *s, int e) { return s->ev_band[e] > 0; }
void bg_eqsys_mode_tighten(bg_eqsys *s, int e) { s->ev_band[e] = 0; }

/* The rows at (t, y, yp) (yp NULL: the right-hand side) with mode e held at
 * mode, into out; 0, or -1 when they are not finite. */
static int rows_in_mode(bg_eqsys *s, int e, double mode, double t, const double *y, const double *yp, double *out) {
  double keep = s->ev_mode[e];
  s->ev_mode[e] = mode;
  int rc = yp ? bg_eqsys_residual(s, t, y, yp, out) : bg_eqsys_rhs(s, t, y, out);
  s->ev_mode[e] = keep;
  return rc;
}

/* A DAE's counterpart of sliding(): the limit from the right chose the
 * modes (bg_eqsys_modes_right, from rates consistent under the modes before
 * it) and IDACalcIC then gave rates yp consistent under the chosen ones.
 * Looked ahead along those rates (the algebraic unknowns solved at
 * t + delta under the chosen modes): a switching function exactly zero at
 * (t, y) that lands on the other side, of a law with a jump there (its two
 * sides' rows differ by more than tol), has no mode that holds (friction
 * stronger than the push on a mass at rest whose velocity is a dependent
 * store's: the settle rounds flip between the sides, and holding the one
 * chosen ran the whole span on it while the function had the other sign,
 * exit 0). A continuous law is one law there (either side holds at t; its
 * look-ahead from rest reads second-order values and rounding: seed 6101's
 * model flipped with the statements' order). Returns 1 + the first such
 * event, or 0, or -1 when the solve failed; the modes are left as they are. */
int bg_eqsys_modes_slide(bg_eqsys *s, double t, const double *y, const double *yp, double delta,
                         const double *tol) {
  if (!s->nev || !(delta > 0)) return 0;
  unsigned char *zero = bg_xmalloc((size_t)s->nev);
  double *chosen = bg_xmalloc((size_t)s->nev * sizeof(double));
  int nz = 0, found = 0, was = s->ev_frozen;
  memcpy(chosen, s->ev_mode, (size_t)s->nev * sizeof(double));
  s->ev_frozen = 1; /* every mode as held, not as compiled */
  bg_eqs_eval_raw(s, t, y, yp);
  for (int e = 0; e < s->nev; e++) nz += zero[e] = (unsigned char)(!(s->ev_band[e] > 0) && undecided(s, e, NULL));
  if (nz) {
    for (int i = 0; i < s->n; i++) s->ev_y[i] = y[i] + delta * yp[i];
    if (bg_eqsys_consistent(s, t + delta, s->ev_y, 30)) found = -1;
    else {
      modes_pass(s, t + delta, s->ev_y, yp, NULL, zero);
      double *ahead = bg_xmalloc((size_t)s->nev * sizeof(double));
      memcpy(ahead, s->ev_mode, (size_t)s->nev * sizeof(double));
      for (int e = 0; e < s->nev; e++) zero[e] = zero[e] && !undecided(s, e, NULL) && ahead[e] != chosen[e];
      memcpy(s->ev_mode, chosen, (size_t)s->nev * sizeof(double));
      double *a = bg_xmalloc((size_t)(2 * s->n + 1) * sizeof(double)), *b = a + s->n;
      for (int e = 0; e < s->nev && !found; e++) {
        if (!zero[e]) continue;
        int jump = rows_in_mode(s, e, chosen[e], t, y, yp, a) || rows_in_mode(s, e, ahead[e], t, y, yp, b);
        for (int i = 0; !jump && i < s->n; i++) jump = !(fabs(a[i] - b[i]) <= tol[i]);
        if (jump) found = 1 + e;
      }
      free(a), free(ahead);
    }
  }
  memcpy(s->ev_mode, chosen, (size_t)s->nev * sizeof(double));
  s->ev_frozen = was;
  s->has_err = 0;
  free(zero), free(chosen);
  return found;
}

int bg_eqsys_mode_loosen(bg_eqsys *s, int e, double other, double t, const double *y, const double *yp,
                         const double *tol, double rtol, double atol) {
  const tinstr *I = &s->code[s->ev_code[e]];
  if (s->ev_mem[e] || s->ev_band[e] > 0 || other == s->ev_mode[e]) return 0;
  int n = yp ? s->n : s->nx, was = s->ev_frozen, agree = 1;
  unsigned char free_was = s->ev_free[e];
  double *a = bg_xmalloc((size_t)(2 * n + 1) * sizeof(double)), *b = a + n;
  s->ev_frozen = 1, s->ev_free[e] = 0; /* both sides as held, not as compiled */
  if (rows_in_mode(s, e, s->ev_mode[e], t, y, yp, a) || rows_in_mode(s, e, other, t, y, yp, b)) agree = 0;
  for (int i = 0; agree && i < n; i++) agree = fabs(a[i] - b[i]) <= tol[i];
  free(a);
  /* the band: the solver's tolerance of the switching function's operands
   * (a and b of a > b, x of abs(x)), with the row check's margin */
  double size = 0, g[2] = {0, 0};
  int cond, nr = roots_of(s, I, &cond);
  bg_eqs_eval_raw(s, t, y, yp);
  for (int q = 0; q < I->na && q < 3; q++)
    if (cond >> q & 1) size += fabs(s->v[I->a[q]]);
  double band = 100 * (atol + rtol * size);
  ev_roots(s, e, s->v, g);
  int near = 0; /* it sits in the band now (a table: at one end of its segment) */
  for (int j = 0; j < nr; j++) near |= fabs(g[j]) < band;
  s->ev_frozen = was, s->ev_free[e] = free_was;
  if (!agree || !near) return 0;
  s->ev_band[e] = band, s->ev_free[e] = 1;
  return 1;
}
