/* SPDX-License-Identifier: BSD-3-Clause */
/* State events in the C and Python exports (docs/export.md, "State
 * events"): each switching instruction of the tape (eqsys_events.c) goes
 * through its mode; the exported code gets the root functions, the modes
 * as a discrete state the caller keeps, and a function that applies an
 * event (the modes set from the values, in tape order, with the directions
 * of the roots just found and the look-ahead for a switching function that
 * sits at 0), written from the same rules bgdraw's own runs use, so the
 * exported code switches where bgdraw does. Memory (hyst, stick) is a mode
 * like the others: it changes only in the event function. */
#include <stdio.h>
#include <string.h>

#include "export/export_int.h"
#include "model/model.h"

/* ------------------------------------------------------------ C */
static const char c_kinds[] =
    "/* State events (docs/export.md, \"State events\"): the kinds of switching\n"
    " * instruction, their root functions, how each sets its mode at an event,\n"
    " * and its value and slope in the mode it holds (continued smoothly past its\n"
    " * switching point, so the integrator sees one smooth system per mode). */\n"
    "enum { BG_K_LT, BG_K_LE, BG_K_GT, BG_K_GE, BG_K_TABLE, BG_K_ABS, BG_K_SIGN, BG_K_STEP, BG_K_RAMP, BG_K_MIN,\n"
    "       BG_K_MAX, BG_K_PULSE, BG_K_SAT, BG_K_HYST, BG_K_STICK, BG_K_FLOOR, BG_K_CEIL };\n"
    "static const int bg_k_nroot[] = {1, 1, 1, 1, 2, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2};\n";

static const char c_tables[] =
    "static int bg_tseg_dir(int t, double x, int dir) {\n"
    "  const double *X = bg_tx + bg_tadr[t];\n  int n = bg_tn[t], k;\n"
    "  if (x < X[0]) k = -1;\n  else if (x >= X[n - 1]) k = n - 1;\n  else k = bg_tseg(X, n, x);\n"
    "  if (dir < 0 && k >= 0 && x == X[k]) k--;\n  return k;\n}\n"
    "static double bg_tseg_val(int t, int k, double x, int der) {\n"
    "  const double *X = bg_tx + bg_tadr[t], *Y = bg_ty + bg_tadr[t];\n  int n = bg_tn[t];\n"
    "  if (k < 0 || k >= n - 1) return der ? 0 : Y[k < 0 ? 0 : n - 1];\n"
    "  double slope = (Y[k + 1] - Y[k]) / (X[k + 1] - X[k]);\n  return der ? slope : Y[k] + slope * (x - X[k]);\n}\n";

static const char c_no_tables[] =
    "static int bg_tseg_dir(int t, double x, int dir) { (void)t, (void)x, (void)dir; return 0; }\n"
    "static double bg_tseg_val(int t, int k, double x, int der) { (void)t, (void)k, (void)x, (void)der; return 0; }\n"
    "static const double bg_tx[1] = {0};\nstatic const int bg_tadr[1] = {0}, bg_tn[1] = {1};\n";

static const char c_rules[] =
    "static void bg_ev_roots(int k, int tab, double m, double x, double y, double z, double *g) {\n"
    "  switch (k) {\n"
    "  case BG_K_LT: case BG_K_LE: case BG_K_GT: case BG_K_GE: case BG_K_MIN: case BG_K_MAX: g[0] = x - y; return;\n"
    "  case BG_K_TABLE: {\n    const double *X = bg_tx + bg_tadr[tab];\n    int n = bg_tn[tab], s = (int)m;\n"
    "    g[0] = s >= 0 ? x - X[s] : 1.0, g[1] = s + 1 <= n - 1 ? x - X[s + 1] : -1.0;\n    return;\n  }\n"
    "  case BG_K_PULSE: g[0] = x, g[1] = x - y; return;\n"
    "  case BG_K_SAT: g[0] = x - y, g[1] = x - z; return;\n"
    "  /* memory: only the way out of the mode held is watched */\n"
    "  case BG_K_HYST: g[0] = m ? -1.0 : x - z, g[1] = m ? x - y : 1.0; return;\n"
    "  case BG_K_STICK: g[0] = m ? fabs(y) - z : -1.0, g[1] = m ? 1.0 : x; return;\n"
    "  case BG_K_FLOOR: g[0] = x - m, g[1] = x - (m + 1); return;\n"
    "  case BG_K_CEIL: g[0] = x - (m - 1), g[1] = x - m; return;\n"
    "  default: g[0] = x; return;\n  }\n}\n\n"
    "static double bg_eff(double g, int dir) { return g != 0 ? g : (double)dir; }\n\n"
    "/* The mode from the values; dir (nullable): the directions of a root just\n"
    " * found, which decide a switching function that is exactly 0; fresh: the\n"
    " * start of a run (memory takes the value it starts with). */\n"
    "static double bg_ev_mode(int k, int tab, double m, int fresh, double x, double y, double z, const int *dir) {\n"
    "  double g[2] = {0, 0};\n  int d0 = dir ? dir[0] : 0, d1 = dir && bg_k_nroot[k] > 1 ? dir[1] : 0;\n"
    "  bg_ev_roots(k, tab, m, x, y, z, g);\n  double g0 = bg_eff(g[0], d0), g1 = bg_eff(g[1], d1);\n"
    "  switch (k) {\n  case BG_K_LT: return g0 < 0;\n  case BG_K_LE: return g0 <= 0;\n"
    "  case BG_K_GT: return g0 > 0;\n  case BG_K_GE: return g0 >= 0;\n"
    "  case BG_K_TABLE: return bg_tseg_dir(tab, x, d0 ? d0 : d1);\n"
    "  case BG_K_SIGN: return g0 > 0 ? 1 : g0 < 0 ? -1 : 0;\n  case BG_K_MIN: return g0 <= 0;\n"
    "  case BG_K_PULSE: return g0 >= 0 && g1 < 0;\n  case BG_K_SAT: return g0 < 0 ? 0 : g1 > 0 ? 2 : 1;\n"
    "  case BG_K_HYST: return fresh ? x >= z : m ? g1 > 0 : g0 >= 0;\n"
    "  case BG_K_STICK:\n    if (fresh) return x == 0 && fabs(y) <= z;\n    if (m) return !(g0 > 0);\n"
    "    return (d1 != 0 || x == 0) && (d1 != 0 ? fabs(y) <= z : fabs(y) < z);\n"
    "  case BG_K_FLOOR: return floor(x) - (x == floor(x) && (d0 < 0 || d1 < 0));\n"
    "  case BG_K_CEIL: return ceil(x) + (x == ceil(x) && (d0 > 0 || d1 > 0));\n"
    "  default: return g0 >= 0; /* max, abs, step, ramp */\n  }\n}\n\n"
    "static double bg_ev_value(int k, int tab, double m, double x, double y, double z) {\n"
    "  switch (k) {\n  case BG_K_TABLE: return bg_tseg_val(tab, (int)m, x, 0);\n"
    "  case BG_K_ABS: return m ? x : -x;\n  case BG_K_RAMP: return m ? x : 0;\n"
    "  case BG_K_MIN: case BG_K_MAX: return m ? x : y;\n"
    "  case BG_K_SAT: return m == 0 ? y : m == 2 ? z : x;\n  default: return m;\n  }\n}\n\n"
    "static double bg_ev_der(int k, int tab, double m, double x, double dx, double dy, double dz) {\n"
    "  switch (k) {\n  case BG_K_TABLE: return bg_tseg_val(tab, (int)m, x, 1) * dx;\n"
    "  case BG_K_ABS: return m ? dx : -dx;\n  case BG_K_RAMP: return m ? dx : 0;\n"
    "  case BG_K_MIN: case BG_K_MAX: return m ? dx : dy;\n"
    "  case BG_K_SAT: return m == 0 ? dy : m == 2 ? dz : dx;\n  default: return 0;\n  }\n}\n\n"
    "/* 1 when a root function sits exactly at 0 and no root direction decides it */\n"
    "static int bg_ev_zero(int k, int tab, double m, double x, double y, double z, const int *dir) {\n"
    "  double g[2] = {1, 1};\n  bg_ev_roots(k, tab, m, x, y, z, g);\n"
    "  for (int j = 0; j < bg_k_nroot[k]; j++)\n    if (g[j] == 0 && !(dir && dir[j])) return 1;\n  return 0;\n}\n\n";

static const char c_at[] =
    "/* how: 0 as compiled (memory keeps its mode: it is its value), 1 the modes\n"
    " * held, 2 each mode set from the values as they are computed, then held. */\n"
    "typedef struct bg_mc { bg_modes_t *md; int how; const int *dir; const unsigned char *only; } bg_mc;\n\n"
    "static double bg_at(bg_mc *c, int e, int k, int tab, double x, double y, double z, int r0, double compiled) {\n"
    "  if (!c) return compiled;\n  bg_modes_t *md = c->md;\n"
    "  if (c->how == 2 && (!c->only || c->only[e]))\n"
    "    md->m[e] = bg_ev_mode(k, tab, md->m[e], md->fresh, x, y, z, c->dir ? c->dir + r0 : NULL);\n"
    "  if (k == BG_K_HYST || k == BG_K_STICK) return md->m[e];\n"
    "  if (c->how == 0 || md->undecided[e]) return compiled;\n"
    "  return bg_ev_value(k, tab, md->m[e], x, y, z);\n}\n\n"
    "static int bg_held(const bg_mc *c, int e) { return c && c->how != 0 && !c->md->undecided[e]; }\n\n";

void bg_xev_c_runtime(const bg_eqsys *s, const char *P, bg_strbuf *c) {
  bg_sb_puts(c, c_kinds);
  bg_sb_puts(c, s->m->ntable ? c_tables : c_no_tables);
  bg_sb_puts(c, c_rules);
  bg_sb_printf(c, "typedef %s_modes bg_modes_t;\n", P);
  bg_sb_puts(c, c_at);
}

void bg_xev_c_header(const bg_eqsys *s, const char *P, const char *U, bg_strbuf *h) {
  bg_sb_printf(h, "/* State events (docs/export.md, \"State events\"): %d switching instructions\n"
                  " * (modes) watched by %d root functions. The modes are a discrete state the\n"
                  " * caller keeps: set them at the start (%s_modes_start), pass them to every\n"
                  " * evaluation, let the integrator find the roots of %s_roots and apply each\n"
                  " * event with %s_event (no state jumps at an event). */\n", s->nev, s->nroot, P, P, P);
  bg_sb_printf(h, "#define %s_NMODE %d\n#define %s_NROOT %d\n", U, s->nev, U, s->nroot);
  bg_sb_printf(h, "typedef struct %s_modes {\n  double m[%s_NMODE];            /* the branch each switching instruction holds */\n"
                  "  unsigned char undecided[%s_NMODE]; /* 1: at 0 a moment later too: evaluated as compiled */\n"
                  "  int fresh;                        /* the next event starts a run (memory's start values) */\n"
                  "} %s_modes;\n", P, U, U, P);
  bg_sb_printf(h, "extern const char *const %s_root_names[%s_NROOT + 1]; /* \"law of K: K.q < 0\" */\n", P, U);
  bg_sb_printf(h, "extern const int %s_root_mode[%s_NROOT + 1];          /* the mode each root function watches */\n", P, U);
  bg_sb_printf(h, "extern const int %s_mode_is_memory[%s_NMODE + 1];     /* 1: hyst or stick */\n", P, U);
  bg_sb_printf(h, "/* The modes at the start t0 (memory: its start value). delta: the look-ahead\n"
                  " * of a switching function exactly at 0, bgdraw's is 1e-9 of the span. */\n"
                  "void %s_modes_start(const %s_params *p, double t0, const double *y0, const double *yp0, double delta,\n"
                  "                    %s_modes *md, double *work);\n", P, P, P);
  bg_sb_printf(h, "/* The root functions under the modes md: g[%s_NROOT]; 0, or -1 when one is not finite */\n"
                  "int %s_roots(const %s_params *p, const %s_modes *md, double t, const double *y, const double *yp,\n"
                  "             double *g, double *work);\n", U, P, P, P);
  bg_sb_printf(h, "/* At a root: every mode set from the values at (t, y, yp), in the equations'\n"
                  " * order; dir[%s_NROOT] (nullable): +1 for a root function that rose through 0,\n"
                  " * -1 fell, 0 not found (CVodeGetRootInfo's rootsfound). Returns how many modes\n"
                  " * changed. Restart the integrator at (t, y): the states do not jump. */\n"
                  "int %s_event(const %s_params *p, double t, const double *y, const double *yp, const int *dir, double delta,\n"
                  "             %s_modes *md, double *work);\n", U, P, P, P);
}

void bg_xev_c_der(const bg_eqsys *s, int e, bg_strbuf *c) {
  const tinstr *I = &s->code[s->ev_code[e]];
  bg_sb_printf(c, "  if (bg_held(c, %d)) d[%d] = bg_ev_der(%d, %d, c->md->m[%d], v[%d]", e, I->out, bg_xev_kind(s, e),
               I->op == BG_X_TABLE ? I->ref : 0, e, I->a[0]);
  for (int q = 0; q < 3; q++) {
    if (q < I->na) bg_sb_printf(c, ", d[%d]", I->a[q]);
    else bg_sb_puts(c, ", 0.0");
  }
  bg_sb_puts(c, ");\n  else\n");
}

static void c_tables_of_events(const bg_eqsys *s, const char *P, const char *U, bg_strbuf *c) {
  bg_sb_printf(c, "const char *const %s_root_names[%s_NROOT + 1] = {", P, U);
  for (int i = 0; i < s->nroot; i++) bg_sb_puts(c, i ? ", " : ""), bg_sb_json_str(c, s->root_text[i]);
  bg_sb_printf(c, "};\nconst int %s_root_mode[%s_NROOT + 1] = {", P, U);
  for (int i = 0; i < s->nroot; i++) bg_sb_printf(c, "%s%d", i ? ", " : "", s->root_ev[i]);
  bg_sb_printf(c, "};\nconst int %s_mode_is_memory[%s_NMODE + 1] = {", P, U);
  for (int e = 0; e < s->nev; e++) bg_sb_printf(c, "%s%d", e ? ", " : "", s->ev_mem[e]);
  bg_sb_puts(c, "};\n\n");
}

void bg_xev_c_api(const bg_eqsys *s, const char *P, const char *U, bg_strbuf *c) {
  c_tables_of_events(s, P, U, c);
  /* one line an event: a chain of equal switching elements loops (export_runs.c) */
  bg_strbuf roots = {0}, zeros = {0}, body = {0};
  for (int e = 0; e < s->nev; e++) {
    bg_sb_puts(&roots, "  bg_ev_roots(");
    bg_xev_args(&bg_xlang_c, s, e, "v", "md->m[%d]", &roots);
    bg_sb_printf(&roots, ", g + %d);\n", s->ev_root0[e]);
    bg_sb_printf(&zeros, "  n += zero[%d] = (!only || only[%d]) && bg_ev_zero(", e, e);
    bg_xev_args(&bg_xlang_c, s, e, "v", "md->m[%d]", &zeros);
    bg_sb_printf(&zeros, ", dir ? dir + %d : NULL);\n", s->ev_root0[e]);
  }
  bg_xruns_lines(bg_sb_str(&roots), "bg_roots_slots", c, &body);
  bg_sb_printf(c, "static void bg_roots_of(const double *v, const %s_modes *md, double *g) {\n  (void)v, (void)md;\n", P);
  bg_sb_printf(c, "%s}\n\n", bg_sb_str(&body));
  bg_sb_clear(&body);
  bg_xruns_lines(bg_sb_str(&zeros), "bg_zero_slots", c, &body);
  bg_sb_printf(c, "/* zero[e]: mode e's switching function sits at 0, undecided (only: those to look at) */\n"
                  "static int bg_zero_of(const double *v, const %s_modes *md, const int *dir, unsigned char *zero,\n"
                  "                      const unsigned char *only) {\n  int n = 0;\n", P);
  bg_sb_printf(c, "%s  return n;\n}\n\n", bg_sb_str(&body));
  bg_sb_free(&roots), bg_sb_free(&zeros), bg_sb_free(&body);
  bg_sb_printf(c, "static int bg_roots_finite(const double *g) {\n  for (int i = 0; i < %s_NROOT; i++)\n"
                  "    if (!isfinite(g[i])) return 0;\n  return 1;\n}\n\n", U);
  bg_sb_printf(c, "int %s_roots(const %s_params *p, const %s_modes *md, double t, const double *y, const double *yp,\n"
                  "             double *g, double *work) {\n  double *v = work;\n  bg_mc c = {(%s_modes *)md, 1, NULL, NULL};\n"
                  "  for (;; c.how = 0) { /* held; as compiled where a held value is not finite */\n"
                  "    bg_start(p, t, y, yp, v);\n    bg_main(v, &c);\n    bg_roots_of(v, md, g);\n"
                  "    if (bg_roots_finite(g)) return 0;\n    if (c.how == 0) return -1;\n  }\n}\n\n", P, P, P, P);
  bg_sb_printf(c, "int %s_event(const %s_params *p, double t, const double *y, const double *yp, const int *dir, double delta,\n"
                  "             %s_modes *md, double *work) {\n"
                  "  double *v = work, *ya = work + %d, *ydot = ya + %s_N, *prev = ydot + %s_N;\n"
                  "  unsigned char *zero = (unsigned char *)(prev + %s_NMODE);\n"
                  "  for (int e = 0; e < %s_NMODE; e++) prev[e] = md->m[e], md->undecided[e] = 0;\n"
                  "  bg_mc c = {md, 2, dir, NULL};\n  bg_start(p, t, y, yp, v);\n  bg_main(v, &c);\n  md->fresh = 0;\n"
                  "  /* a switching function exactly at 0 leaves it to one side or the other without a\n"
                  "   * sign change a root finder could see: decided by y + delta y' a moment later */\n"
                  "  int nzero = bg_zero_of(v, md, dir, zero, NULL);\n"
                  "  if (nzero && delta > 0) {\n    const double *yd = yp;\n"
                  "    if (!yp && %s_IS_ODE && bg_eval_modes(p, md, t, y, NULL, v, 0) >= 0 && bg_rows_finite(v)) {\n"
                  "      for (int i = 0; i < %s_N; i++) ydot[i] = v[bg_row_slot[i]];\n      yd = ydot;\n    }\n"
                  "    if (yd) {\n      for (int i = 0; i < %s_N; i++) ya[i] = y[i] + delta * yd[i];\n"
                  "      c.how = 2, c.dir = NULL, c.only = zero;\n      bg_start(p, t + delta, ya, yp, v);\n      bg_main(v, &c);\n"
                  "      bg_zero_of(v, md, NULL, zero, zero);\n    }\n  }\n"
                  "  int changed = 0;\n  for (int e = 0; e < %s_NMODE; e++)\n"
                  "    md->undecided[e] = zero[e] && nzero, changed += md->m[e] != prev[e];\n  return changed;\n}\n\n",
               P, P, P, 2 * s->nslot, U, U, U, U, U, U, U, U);
  bg_sb_printf(c, "void %s_modes_start(const %s_params *p, double t0, const double *y0, const double *yp0, double delta,\n"
                  "                    %s_modes *md, double *work) {\n  memset(md, 0, sizeof *md);\n  md->fresh = 1;\n"
                  "  %s_event(p, t0, y0, yp0, NULL, delta, md, work);\n}\n", P, P, P, P);
}

/* ------------------------------------------------------------ Python */
static const char py_rules[] =
    "# State events (docs/export.md, \"State events\"): the kinds of switching\n"
    "# instruction, their root functions, how each sets its mode at an event, and\n"
    "# its value in the mode it holds (continued smoothly past its switching point).\n"
    "_K_NROOT = [1, 1, 1, 1, 2, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2]\n\n\n"
    "def _tseg_dir(t, x, d):\n    X = _TABLES[t][0]\n    n = len(X)\n"
    "    if x < X[0]:\n        k = -1\n    elif x >= X[-1]:\n        k = n - 1\n    else:\n"
    "        lo, hi = 0, n - 1\n        while hi - lo > 1:\n            mid = (lo + hi) // 2\n"
    "            if X[mid] <= x:\n                lo = mid\n            else:\n                hi = mid\n        k = lo\n"
    "    if d < 0 and k >= 0 and x == X[k]:\n        k -= 1\n    return k\n\n\n"
    "def _tseg_val(t, k, x):\n    X, Y = _TABLES[t]\n    n = len(X)\n"
    "    if k < 0 or k >= n - 1:\n        return Y[0 if k < 0 else n - 1]\n"
    "    slope = (Y[k + 1] - Y[k]) / (X[k + 1] - X[k])\n    return Y[k] + slope * (x - X[k])\n\n\n"
    "def _ev_roots(k, tab, m, x, y, z):\n"
    "    if k in (0, 1, 2, 3, 9, 10):\n        return [x - y, 0.0]\n"
    "    if k == 4:\n        X = _TABLES[tab][0]\n        s = int(m)\n"
    "        return [x - X[s] if s >= 0 else 1.0, x - X[s + 1] if s + 1 <= len(X) - 1 else -1.0]\n"
    "    if k == 11:\n        return [x, x - y]\n    if k == 12:\n        return [x - y, x - z]\n"
    "    if k == 13:  # memory: only the way out of the mode held is watched\n"
    "        return [-1.0 if m else x - z, x - y if m else 1.0]\n"
    "    if k == 14:\n        return [math.fabs(y) - z if m else -1.0, 1.0 if m else x]\n"
    "    if k == 15:\n        return [x - m, x - (m + 1)]\n    if k == 16:\n        return [x - (m - 1), x - m]\n"
    "    return [x, 0.0]\n\n\n"
    "def _eff(g, d):\n    return g if g != 0 else float(d)\n\n\n"
    "def _ev_mode(k, tab, m, fresh, x, y, z, d):\n"
    "    g = _ev_roots(k, tab, m, x, y, z)\n"
    "    d0 = d[0] if d is not None else 0\n    d1 = d[1] if d is not None and _K_NROOT[k] > 1 else 0\n"
    "    g0, g1 = _eff(g[0], d0), _eff(g[1], d1)\n"
    "    if k == 0:\n        return float(g0 < 0)\n    if k == 1:\n        return float(g0 <= 0)\n"
    "    if k == 2:\n        return float(g0 > 0)\n    if k == 3:\n        return float(g0 >= 0)\n"
    "    if k == 4:\n        return float(_tseg_dir(tab, x, d0 if d0 else d1))\n"
    "    if k == 6:\n        return 1.0 if g0 > 0 else -1.0 if g0 < 0 else 0.0\n"
    "    if k == 9:\n        return float(g0 <= 0)\n    if k == 11:\n        return float(g0 >= 0 and g1 < 0)\n"
    "    if k == 12:\n        return 0.0 if g0 < 0 else 2.0 if g1 > 0 else 1.0\n"
    "    if k == 13:\n        return float(x >= z) if fresh else float(g1 > 0) if m else float(g0 >= 0)\n"
    "    if k == 14:\n        if fresh:\n            return float(x == 0 and math.fabs(y) <= z)\n"
    "        if m:\n            return float(not g0 > 0)\n"
    "        return float((d1 != 0 or x == 0) and (math.fabs(y) <= z if d1 != 0 else math.fabs(y) < z))\n"
    "    if k == 15:\n        return float(math.floor(x) - (x == math.floor(x) and (d0 < 0 or d1 < 0)))\n"
    "    if k == 16:\n        return float(math.ceil(x) + (x == math.ceil(x) and (d0 > 0 or d1 > 0)))\n"
    "    return float(g0 >= 0)  # max, abs, step, ramp\n\n\n"
    "def _ev_value(k, tab, m, x, y, z):\n"
    "    if k == 4:\n        return _tseg_val(tab, int(m), x)\n    if k == 5:\n        return x if m else -x\n"
    "    if k == 8:\n        return x if m else 0.0\n    if k in (9, 10):\n        return x if m else y\n"
    "    if k == 12:\n        return y if m == 0 else z if m == 2 else x\n    return m\n\n\n"
    "def _ev_zero(k, tab, m, x, y, z, d):\n    g = _ev_roots(k, tab, m, x, y, z)\n"
    "    return any(g[j] == 0 and not (d is not None and d[j]) for j in range(_K_NROOT[k]))\n\n\n"
    "class Modes:\n"
    "    \"\"\"The modes of the switching instructions, a discrete state: m (the branch\n"
    "    each holds), undecided (at 0 a moment later too: evaluated as compiled),\n"
    "    fresh (the next event starts a run: memory takes its start value).\"\"\"\n\n"
    "    def __init__(self):\n        self.m = [0.0] * NMODE\n        self.undecided = [False] * NMODE\n"
    "        self.fresh = True\n\n\n"
    "class _Ctx:\n    def __init__(self, md, how, d=None, only=None):\n"
    "        self.md, self.how, self.dir, self.only = md, how, d, only\n\n\n"
    "def _at(c, e, k, tab, x, y, z, r0, compiled):\n"
    "    \"\"\"how: 0 as compiled (memory keeps its mode), 1 held, 2 set from the values, then held.\"\"\"\n"
    "    if c is None:\n        return compiled\n    md = c.md\n"
    "    if c.how == 2 and (c.only is None or c.only[e]):\n"
    "        md.m[e] = _ev_mode(k, tab, md.m[e], md.fresh, x, y, z, None if c.dir is None else c.dir[r0:r0 + 2])\n"
    "    if k == 13 or k == 14:\n        return md.m[e]\n"
    "    if c.how == 0 or md.undecided[e]:\n        return compiled\n"
    "    return _ev_value(k, tab, md.m[e], x, y, z)\n\n\n";

static const char py_api[] =
    "def _finite(v, outs):\n"
    "    return all(math.isfinite(v[k]) for k in _ROW_SLOT) and (not outs or all(math.isfinite(v[k]) for k in _OUT_SLOT))\n\n\n"
    "def _eval_modes(p, t, y, yp, md, outs):\n"
    "    \"\"\"The values with the modes held; as compiled where a held value is not finite.\"\"\"\n"
    "    if md is None:\n"
    "        if HAS_MEMORY:\n"
    "            raise ValueError(\"the model keeps a discrete state (hyst, stick): pass its modes, md = modes_start(...)\")\n"
    "        v = _eval(p, t, y, yp)\n        return _output_code(v) if outs else v\n"
    "    for how in (1, 0):\n        v = _eval(p, t, y, yp, _Ctx(md, how))\n"
    "        if outs:\n            _output_code(v)\n        if how == 0 or _finite(v, outs):\n            return v\n\n\n"
    "def rhs(t, y, p=None, md=None):\n"
    "    \"\"\"y' = f(t, y) of an ODE model under the modes md (None: as compiled).\"\"\"\n"
    "    v = _eval_modes(p, t, y, None, md, False)\n    return np.array([v[_ROW_SLOT[i]] for i in range(NX)])\n\n\n"
    "def residual(t, y, yp, p=None, md=None):\n    \"\"\"F(t, y, y') = 0 (an ODE as y' - f) under the modes md.\"\"\"\n"
    "    v = _eval_modes(p, t, y, yp, md, False)\n"
    "    return np.array([yp[i] - v[_ROW_SLOT[i]] if _ROW_KIND[i] == 0 else v[_ROW_SLOT[i]] for i in range(N)])\n\n\n"
    "def outputs(t, y, yp=None, p=None, md=None):\n    v = _eval_modes(p, t, y, yp, md, True)\n"
    "    return np.array([v[k] for k in _OUT_SLOT])\n\n\n"
    "def roots(t, y, p=None, md=None, yp=None):\n"
    "    \"\"\"The root functions (NROOT values, ROOT_NAMES) under the modes md.\"\"\"\n"
    "    for how in (1, 0):\n        v = _eval(p, t, y, yp, _Ctx(md, how))\n        g = _roots_of(v, md)\n"
    "        if how == 0 or all(math.isfinite(x) for x in g):\n            return g\n\n\n"
    "def event(t, y, p, md, d=None, delta=0.0, yp=None):\n"
    "    \"\"\"At a root: every mode set from the values at (t, y), in the equations'\n"
    "    order; d (NROOT values or None): +1 for a root function that rose through 0,\n"
    "    -1 fell, 0 not found. delta: the look-ahead of a switching function exactly\n"
    "    at 0. The states do not jump. Returns how many modes changed.\"\"\"\n"
    "    prev = list(md.m)\n    md.undecided = [False] * NMODE\n"
    "    v = _eval(p, t, y, yp, _Ctx(md, 2, d))\n    md.fresh = False\n"
    "    zero = _zero_of(v, md, d, None)\n"
    "    if any(zero) and delta > 0:\n        yd = yp\n"
    "        if yp is None and IS_ODE:\n            w = _eval_modes(p, t, y, None, md, False)\n"
    "            if _finite(w, False):\n                yd = [w[_ROW_SLOT[i]] for i in range(N)]\n"
    "        if yd is not None:\n            ya = [y[i] + delta * yd[i] for i in range(N)]\n"
    "            v = _eval(p, t + delta, ya, yp, _Ctx(md, 2, None, zero))\n"
    "            zero = _zero_of(v, md, None, zero)\n"
    "    md.undecided = list(zero)\n    return sum(1 for e in range(NMODE) if md.m[e] != prev[e])\n\n\n"
    "def modes_start(p=None, t0=0.0, y0=None, delta=0.0, yp0=None):\n"
    "    \"\"\"The modes at the start (memory: its start value).\"\"\"\n"
    "    md = Modes()\n    event(t0, initial(p, t0) if y0 is None else y0, p, md, None, delta, yp0)\n    return md\n\n\n"
    "def simulate(t_end=None, dt=None, p=None, rtol=1e-9, atol=1e-12, t0=None, t_eval=None, events=None):\n"
    "    \"\"\"Integrates with SciPy's solve_ivp (BDF) on the simulate block's grid (or\n"
    "    at t_eval), one root function per solve_ivp event (terminal): at each\n"
    "    root the modes are set by event() a hair (1e-12 of the span) past it and the\n"
    "    integration restarts there. Returns (t, y, out); events (a list) receives\n"
    "    (t, root, direction) for each switching.\"\"\"\n"
    "    from scipy.integrate import solve_ivp\n"
    "    if not IS_ODE:\n"
    "        raise NotImplementedError(\"switching conditions in a DAE: use residual(), roots() and event() with a DAE solver\")\n"
    "    sim = SIMULATE or {\"t0\": 0.0, \"t_end\": 1.0, \"dt\": 0.0}\n"
    "    t0 = sim[\"t0\"] if t0 is None else t0\n    t_end = sim[\"t_end\"] if t_end is None else t_end\n"
    "    dt = sim[\"dt\"] if dt is None else dt\n"
    "    grid = None if not dt else np.linspace(t0, t_end, int(round((t_end - t0) / dt)) + 1)\n"
    "    if t_eval is not None:\n        grid = np.asarray(t_eval, dtype=float)\n        t0, t_end = grid[0], grid[-1]\n"
    "    delta = 1e-9 * (t_end - t0)\n    x = np.array(initial(p, t0), dtype=float)\n"
    "    md = modes_start(p, t0, x, delta)\n    T, Y, O = [], [], []\n    log = [] if events is None else events\n"
    "    memo = {}\n\n"
    "    def g_all(tt, xx):\n        key = (id(md), tuple(md.m), tt, xx.tobytes())\n"
    "        if memo.get(\"key\") != key:\n            memo[\"key\"], memo[\"g\"] = key, roots(tt, xx, p, md)\n"
    "        return memo[\"g\"]\n\n"
    "    def keep(tt, xx):\n        T.append(tt)\n        Y.append(np.array(xx, dtype=float))\n"
    "        O.append(outputs(tt, xx, None, p, md))\n\n"
    "    f = lambda tt, xx: rhs(tt, xx, p, md)\n"
    "    t = t0\n    if grid is None or grid[0] <= t0:\n        keep(t0, x)\n"
    "    done = 0 if grid is None else int(np.searchsorted(grid, t0, side=\"right\"))\n"
    "    while t < t_end:\n"
    "        g0 = g_all(t, x)\n"
    "        if any(v == 0 for v in g0):  # a root function at 0: a hair on, as the solvers' root finding does\n"
    "            x = x + delta * f(t, x)\n            t = t + delta\n            g0 = g_all(t, x)\n"
    "        fns = []\n        for i in range(NROOT):\n"
    "            fn = (lambda i: lambda tt, xx: g_all(tt, xx)[i])(i) if g0[i] != 0 else (lambda tt, xx: 1.0)\n"
    "            fn.terminal = g0[i] != 0\n            fns.append(fn)\n"
    "        te_ = None if grid is None else grid[done:][grid[done:] >= t]\n"
    "        sol = solve_ivp(f, (t, t_end), x, method=\"BDF\", t_eval=te_, events=fns, rtol=rtol, atol=atol)\n"
    "        if sol.status < 0:\n            raise RuntimeError(sol.message)\n"
    "        for k in range(len(sol.t)):\n            keep(sol.t[k], sol.y[:, k])\n"
    "        done += len(sol.t) if grid is not None else 0\n"
    "        if sol.status == 0:\n            break\n"
    "        hit = [i for i in range(NROOT) if len(sol.t_events[i])]\n"
    "        te = min(sol.t_events[i][-1] for i in hit)\n"
    "        xe = sol.y_events[[i for i in hit if sol.t_events[i][-1] == te][0]][-1]\n"
    "        # a hair past the root (the states do not jump), under the modes held:\n"
    "        # 1e-12 of the span, longer while a root found is not yet past 0 (each\n"
    "        # hair moves the states with the rates before the event); solve_ivp\n"
    "        # reports one terminal event: the others that crossed with it are those\n"
    "        # whose sign differs there from the segment's start\n"
    "        fe, h = f(te, xe), 1e-12 * (t_end - t0)\n"
    "        for _ in range(7):\n            xh = xe + h * fe\n            gh = g_all(te + h, xh)\n"
    "            if all(gh[i] != 0 and (gh[i] > 0) != (g0[i] > 0) for i in hit if sol.t_events[i][-1] == te):\n"
    "                break\n            h *= 10\n"
    "        d = [0] * NROOT\n        for i in range(NROOT):\n"
    "            if g0[i] != 0 and (gh[i] > 0) != (g0[i] > 0):\n                d[i] = 1 if g0[i] < 0 else -1\n"
    "        fired = [i for i in range(NROOT) if d[i]]\n"
    "        while grid is not None and done < len(grid) and grid[done] < te + h:\n"
    "            keep(grid[done], xe + (grid[done] - te) * fe)\n            done += 1\n"
    "        before = list(md.m)\n        event(te + h, xh, p, md, d, delta)\n"
    "        for i in fired:\n            e = ROOT_MODE[i]\n"
    "            if md.m[e] == before[e] and MODE_IS_MEMORY[e]:\n                continue  # memory that kept its mode: no switching\n"
    "            _log(log, te, i, d[i], 1e-6 * (t_end - t0))\n"
    "        t, x = te + h, xh\n"
    "    return np.array(T), np.array(Y).T, np.array(O).T\n\n\n"
    "def _log(log, t, i, d, near):\n"
    "    \"\"\"Every switching once: the same condition crossing the same way within\n"
    "    near is the same switching; crossing back within it cancels the entry.\"\"\"\n"
    "    for k in range(len(log) - 1, -1, -1):\n"
    "        if t - log[k][0] > near:\n            break\n"
    "        if log[k][1] == i:\n            if (log[k][2] > 0) != (d > 0):\n                del log[k]\n            return\n"
    "    log.append((t, i, 1 if d > 0 else -1))\n";

void bg_xev_python(const bg_eqsys *s, bg_strbuf *o) {
  bg_sb_printf(o, "NMODE = %d\nNROOT = %d\nHAS_MEMORY = %s\nROOT_NAMES = [", s->nev, s->nroot, s->nmem ? "True" : "False");
  for (int i = 0; i < s->nroot; i++) bg_sb_puts(o, i ? ", " : ""), bg_sb_json_str(o, s->root_text[i]);
  bg_sb_puts(o, "]\nROOT_MODE = [");
  for (int i = 0; i < s->nroot; i++) bg_sb_printf(o, "%s%d", i ? ", " : "", s->root_ev[i]);
  bg_sb_puts(o, "]\nMODE_IS_MEMORY = [");
  for (int e = 0; e < s->nev; e++) bg_sb_printf(o, "%s%d", e ? ", " : "", s->ev_mem[e]);
  bg_sb_puts(o, "]\n\n\n");
  bg_sb_puts(o, py_rules);
  bg_sb_puts(o, "def _roots_of(v, md):\n    g = [0.0] * NROOT\n");
  for (int e = 0; e < s->nev; e++) {
    int nr, first = s->ev_root0[e];
    nr = bg_eqsys_mode_roots(s, e, &first);
    bg_sb_printf(o, "    g[%d:%d] = _ev_roots(", first, first + nr);
    bg_xev_args(&bg_xlang_python, s, e, "v", "md.m[%d]", o);
    bg_sb_printf(o, ")[:%d]\n", nr);
  }
  bg_sb_puts(o, "    return g\n\n\n");
  bg_sb_puts(o, "def _zero_of(v, md, d, only):\n    z = [False] * NMODE\n");
  for (int e = 0; e < s->nev; e++) {
    bg_sb_printf(o, "    z[%d] = (only is None or only[%d]) and _ev_zero(", e, e);
    bg_xev_args(&bg_xlang_python, s, e, "v", "md.m[%d]", o);
    bg_sb_printf(o, ", None if d is None else d[%d:%d])\n", s->ev_root0[e], s->ev_root0[e] + 2);
  }
  bg_sb_puts(o, "    return z\n\n\n");
  bg_sb_puts(o, py_api);
}
