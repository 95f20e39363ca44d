/* SPDX-License-Identifier: BSD-3-Clause */
/* State events (issue 12, docs/simulation.md "State events"): switching
 * conditions that read states or bond variables are found by CVODE's and
 * IDA's root finding, the run stops at each and restarts in the new mode.
 * Each model is piecewise linear (the bouncing ball piecewise a free fall
 * and a damped oscillator), so the reference is its closed-form solution,
 * piece by piece, with the switching times solved for by bisection here:
 * the event times must agree to 1e-8, the rows to 1e-7. Without root
 * finding (opts.no_events) the same runs are measurably wrong. */
#include "harness.h"

#include "sim_fixture.h"

#define PI 3.14159265358979323846
#define MAXEV 64

/* ------------------------------------------------------------------ references */
/* x' = -a x + c0 + c1 sin(w t) from (tk, xk): closed form at t. */
typedef struct lin1 { double a, c0, c1, w; } lin1;

static double lin1_at(const lin1 *p, double tk, double xk, double t) {
  double w = p->w, tau = t - tk;
  if (p->a == 0) return xk + p->c0 * tau - p->c1 * (cos(w * t) - cos(w * tk)) / w;
  double a = p->a, d = a * a + w * w;
  double xp_t = p->c0 / a + p->c1 * (a * sin(w * t) - w * cos(w * t)) / d;
  double xp_k = p->c0 / a + p->c1 * (a * sin(w * tk) - w * cos(w * tk)) / d;
  return xp_t + (xk - xp_k) * exp(-a * tau);
}

/* A piecewise-linear scalar model: mode(t, x) is the mode the state is in,
 * params(mode) its equation; the reference integrates piece by piece and
 * finds each switch by scanning (steps of `scan`) and bisection. */
typedef struct pwl {
  int (*mode)(double t, double x);
  lin1 (*params)(int mode);
  double scan;
} pwl;

typedef struct piece { double t, x; int mode; } piece;

/* Pieces from (t0, x0) to t1; returns their count (the switch times are
 * pieces[1..].t). */
static int pwl_pieces(const pwl *P, double t0, double x0, double t1, piece *pc, int max) {
  int n = 0;
  double t = t0, x = x0;
  /* a state exactly on a switching point at t0 is in the mode it enters
   * (the run decides it the same way: by looking a moment ahead) */
  int m = P->mode(t0 + 1e-12, x0);
  pc[n++] = (piece){t, x, m};
  while (n < max) {
    lin1 L = P->params(m);
    double lo = t, hi = t;
    int found = 0;
    for (double s = t + P->scan; s <= t1 + P->scan; s += P->scan) {
      if (P->mode(s, lin1_at(&L, t, x, s)) != m) { hi = s, found = 1; break; }
      lo = s;
    }
    if (!found || lo > t1) break;
    for (int k = 0; k < 200 && hi - lo > 1e-15 * fmax(1, fabs(hi)); k++) {
      double mid = 0.5 * (lo + hi);
      if (P->mode(mid, lin1_at(&L, t, x, mid)) != m) hi = mid;
      else lo = mid;
    }
    x = lin1_at(&L, t, x, hi), t = hi;
    m = P->mode(t, x);
    if (t > t1) break;
    pc[n++] = (piece){t, x, m};
  }
  return n;
}

static double pwl_at(const pwl *P, const piece *pc, int n, double t) {
  int k = 0;
  while (k + 1 < n && pc[k + 1].t <= t) k++;
  lin1 L = P->params(pc[k].mode);
  return lin1_at(&L, pc[k].t, pc[k].x, t);
}

/* The distinct event times of a run (several conditions may fire at once). */
static int event_times(const bg_simresult *r, double *t, int max) {
  int n = 0;
  for (int i = 0; i < r->nevents && n < max; i++)
    if (n == 0 || r->event_t[i] > t[n - 1] + 1e-12) t[n++] = r->event_t[i];
  return n;
}

/* Event times and the state column against the pieces. With `extra`, the
 * run may have more events than the reference has switches (a condition
 * that switches nothing visible, abs(e) at e = 0 inside a dead band):
 * every switch must then be one of the events. */
static void pwl_check_x(const char *name, const bg_simresult *r, const pwl *P, const piece *pc, int npc,
                        const char *column, double xtol, int extra) {
  double t[MAXEV], terr = 0, xerr = 0;
  int ne = event_times(r, t, MAXEV), k = col(r, column);
  if (extra) OK(ne >= npc - 1);
  else INT_EQ(ne, npc - 1);
  for (int i = 0; !extra && i < ne && i + 1 < npc; i++) terr = fmax(terr, fabs(t[i] - pc[i + 1].t));
  for (int j = 1; extra && j < npc; j++) {
    double best = INFINITY;
    for (int i = 0; i < ne; i++) best = fmin(best, fabs(t[i] - pc[j].t));
    terr = fmax(terr, best);
  }
  OK(k >= 0 && r->nrows > 10);
  for (int i = 0; k >= 0 && i < r->nrows; i++) xerr = fmax(xerr, fabs(val(r, i, k) - pwl_at(P, pc, npc, r->t[i])));
  if (!(terr <= 1e-8) || !(xerr <= xtol))
    fprintf(stderr, "%s: %d events (want %d), time error %g, %s error %g\n", name, ne, npc - 1, terr, column, xerr);
  OK(terr <= 1e-8);
  OK(xerr <= xtol);
}

static void pwl_check(const char *name, const bg_simresult *r, const pwl *P, const piece *pc, int npc,
                      const char *column, double xtol) {
  pwl_check_x(name, r, P, pc, npc, column, xtol, 0);
}

static int run_text(fx *f, const char *text, const char *solver, int no_events) {
  bg_sim_opts o = {0};
  o.solver = solver, o.no_events = no_events;
  if (fx_text(f, text, &o)) return -1;
  INT_EQ(f->rc, 0);
  return f->rc;
}

/* ------------------------------------------------------------------ bouncing ball */
/* m x'' = -m g - [x < 0] (k x + c x'): free fall, then a damped oscillator
 * while in contact. Event times: x = 0 after a fall from rest at h,
 * t = sqrt(2 h / g) (then every flight lasts 2 v / g), and the first
 * return of the oscillator to x = 0 (bisection of its closed form). */
#define B_M 1.0
#define B_G 9.81
#define B_K 1e4
#define B_C 20.0
#define B_H 1.0
static const char *BALL =
    "param m0 = 1, g0 = 9.81, k0 = 1e4, c0 = 20, h0 = 1\n"
    "Se G = -m0*g0\n1 v\nI M = m0\nC K : e = if(q < 0, k0*q, 0) [q0 = h0]\n"
    "R D : e = if(K.q < 0, c0*f, 0)\n"
    "bond G -> v\nbond v -> M\nbond v -> K\nbond v -> D\n"
    "simulate t_end = 2, rtol = 1e-10, atol = 1e-12\nplot K.q, M.f\n";

typedef struct ballpc { double t, x, v; int contact; } ballpc;

static void ball_state(const ballpc *p, double t, double *x, double *v) {
  double tau = t - p->t;
  if (!p->contact) { *x = p->x + p->v * tau - 0.5 * B_G * tau * tau, *v = p->v - B_G * tau; return; }
  double w0 = sqrt(B_K / B_M), z = B_C / (2 * sqrt(B_K * B_M)), a = z * w0, wd = w0 * sqrt(1 - z * z);
  double xe = -B_M * B_G / B_K, A = p->x - xe, B = (p->v + a * A) / wd, e = exp(-a * tau);
  *x = xe + e * (A * cos(wd * tau) + B * sin(wd * tau));
  *v = e * ((-a * A + wd * B) * cos(wd * tau) + (-a * B - wd * A) * sin(wd * tau));
}

static int ball_pieces(double t1, ballpc *pc, int max) {
  int n = 0;
  pc[n++] = (ballpc){0, B_H, 0, 0};
  while (n < max) {
    ballpc *p = &pc[n - 1];
    double tsw;
    if (!p->contact) {
      tsw = p->t + (p->v + sqrt(p->v * p->v + 2 * B_G * p->x)) / B_G;
    } else { /* first return to x = 0 from below: scan, then bisect */
      double lo = p->t + 1e-9, hi = lo, x, v;
      do { lo = hi, hi += 1e-4; ball_state(p, hi, &x, &v); } while (x < 0);
      for (int k = 0; k < 200 && hi - lo > 1e-15; k++) {
        double mid = 0.5 * (lo + hi);
        ball_state(p, mid, &x, &v);
        if (x < 0) lo = mid;
        else hi = mid;
      }
      tsw = hi;
    }
    if (tsw > t1) break;
    double x, v;
    ball_state(p, tsw, &x, &v);
    pc[n] = (ballpc){tsw, 0, v, !p->contact};
    n++;
  }
  return n;
}

static void ball_check(const char *solver) {
  fx f;
  if (run_text(&f, BALL, solver, 0)) { fx_free(&f); return; }
  ballpc pc[MAXEV];
  int npc = ball_pieces(2.0, pc, MAXEV), kx = col(&f.r, "K.q"), kv = col(&f.r, "M.f");
  INT_EQ(npc, 7); /* three bounces: in and out of contact three times in 2 s */
  INT_EQ(f.r.nconditions, 2);  /* x < 0 in K's law and in D's */
  INT_EQ(f.r.nevents, 2 * (npc - 1));
  double terr = 0, xerr = 0, verr = 0;
  for (int i = 0; i < f.r.nevents && i / 2 + 1 < npc; i++) {
    terr = fmax(terr, fabs(f.r.event_t[i] - pc[i / 2 + 1].t));
    /* falling into contact, rising out of it */
    INT_EQ(f.r.event_dir[i], pc[i / 2 + 1].contact ? -1 : 1);
  }
  for (int i = 0; kx >= 0 && kv >= 0 && i < f.r.nrows; i++) {
    int k = 0;
    while (k + 1 < npc && pc[k + 1].t <= f.r.t[i]) k++;
    double x, v;
    ball_state(&pc[k], f.r.t[i], &x, &v);
    xerr = fmax(xerr, fabs(val(&f.r, i, kx) - x)), verr = fmax(verr, fabs(val(&f.r, i, kv) - v));
  }
  if (!(terr <= 1e-8) || !(xerr <= 1e-7) || !(verr <= 1e-5))
    fprintf(stderr, "ball %s: event time error %g, x error %g, v error %g\n", solver ? solver : "auto", terr, xerr, verr);
  OK(terr <= 1e-8);
  OK(xerr <= 1e-7);
  OK(verr <= 1e-5);
  OK(has(f.r.condition_text[f.r.event_cond[0]], "K.q < 0"));
  fx_free(&f);
}

static double ball_error(const bg_simresult *r) {
  ballpc pc[MAXEV];
  int npc = ball_pieces(2.0, pc, MAXEV), kx = col(r, "K.q");
  double xerr = 0;
  for (int i = 0; kx >= 0 && i < r->nrows; i++) {
    int k = 0;
    while (k + 1 < npc && pc[k + 1].t <= r->t[i]) k++;
    double x, v;
    ball_state(&pc[k], r->t[i], &x, &v);
    xerr = fmax(xerr, fabs(val(r, i, kx) - x));
  }
  return xerr;
}

/* The same ball with opts.no_events (the integrator steps over the contact
 * switches and only its error test notices): at the same tolerances the
 * rows are more than 100 times worse and miss the accuracy asked for, with
 * twice the steps (measured: 2.5e-7 against 1.9e-10; 447 against 237). */
static void test_ball_without_events(void) {
  fx on, off;
  if (run_text(&on, BALL, NULL, 0) || run_text(&off, BALL, NULL, 1)) { fx_free(&on); fx_free(&off); return; }
  double e_on = ball_error(&on.r), e_off = ball_error(&off.r);
  INT_EQ(off.r.nevents, 0);
  INT_EQ(off.r.events_searched, 0);
  INT_EQ(on.r.events_searched, 1);
  OK(e_on < 1e-9);
  OK(e_off > 1e-7);
  OK(e_off > 100 * e_on);
  OK(off.r.steps > on.r.steps);
  fx_free(&on);
  fx_free(&off);
}

static void test_ball(void) {

  ball_check(NULL); /* auto: Adams */
  ball_check("cvode_bdf");
  ball_check("ida");
}

/* ------------------------------------------------------------------ diode rectifier */
/* U = A sin(w t) -> 1: an ideal-ish diode D (f = e/Ron conducting, e/Roff
 * blocking) -> 0: Cl || RL; with Rs in series the loop of Rs and D is
 * algebraic (IDA). C v' = (U - v)/(Rs + Rd) - v/RL: linear in each mode; D
 * conducts while U - v > 0 (its voltage has the sign of U - v). */
#define R_A 1.0
#define R_W (2 * PI * 50)
#define R_C 1e-4
#define R_RL 100.0
#define R_ON 1.0
#define R_OFF 1e6
static double r_rs; /* series resistance of the variant */

static int rect_mode(double t, double v) { return R_A * sin(R_W * t) - v > 0; }
static lin1 rect_params(int on) {
  double rd = r_rs + (on ? R_ON : R_OFF);
  return (lin1){(1 / rd + 1 / R_RL) / R_C, 0, R_A / (rd * R_C), R_W};
}

static const char *RECT =
    "param A = 1, w = 2*pi*50, C0 = 1e-4, RL0 = 100, Ron = 1, Roff = 1e6\n"
    "Se U = A*sin(w*t)\n1 s\nR D : f = if(e > 0, e/Ron, e/Roff)\n0 n\nC Cl = C0\nR RL = RL0\n"
    "bond U -> s\nbond s -> D\nbond s -> n\nbond n -> Cl\nbond n -> RL\n"
    "simulate t_end = 0.06, dt = 1e-4, rtol = 1e-10, atol = 1e-12\nplot Cl.e, D.f\n";

static void rect_check(const char *name, double rs, const char *solver, const char *want_solver) {
  fx f;
  memset(&f, 0, sizeof f);
  f.src = strdup(RECT);
  char buf[160];
  snprintf(buf, sizeof buf, "1 s\nR Rs = %g\nbond s -> Rs\n", rs);
  bg_sim_opts o = {0};
  o.solver = solver;
  /* IDA failed at t = 0 on this DAE with atol 1e-12 (its error test on the
   * first steps, from the algebraic unknowns' rates IDACalcIC leaves at 0):
   * the rates are computed at the start now (docs/simulation.md) */
  if ((rs > 0 && fx_edit(&f, "1 s\n", buf)) || fx_run(&f, name, BG_METHOD_SCAP, NULL, 0, &o)) { OK(0); fx_free(&f); return; }
  INT_EQ(f.rc, 0);
  STR_EQ(f.r.solver_used, want_solver);
  r_rs = rs;
  pwl P = {rect_mode, rect_params, 1e-5};
  piece pc[MAXEV];
  int npc = pwl_pieces(&P, 0, 0, 0.06, pc, MAXEV);
  OK(npc >= 6); /* on and off in each of three periods */
  INT_EQ(f.r.nconditions, 1);
  pwl_check(name, &f.r, &P, pc, npc, "Cl.e", 1e-7);
  fx_free(&f);
}

static void test_rectifier(void) {
  rect_check("rect_ode", 0, NULL, "cvode_adams");
  rect_check("rect_ida", 0, "ida", "ida");
  rect_check("rect_dae", 1, NULL, "ida");
}

/* ------------------------------------------------------------------ dead zone */
/* U = A sin(w t) -> 1: an R with a dead band of +-d, f = (max(e - d, 0) +
 * min(e + d, 0))/R0, and C: C v' = f(U - v); in the band v holds. */
#define Z_A 1.0
#define Z_W 10.0
#define Z_D 0.3
#define Z_R 1.0
#define Z_C 0.1
static int dz_mode(double t, double v) {
  double e = Z_A * sin(Z_W * t) - v;
  return e > Z_D ? 1 : e < -Z_D ? -1 : 0;
}
static lin1 dz_params(int m) {
  if (m == 0) return (lin1){0, 0, 0, Z_W};
  return (lin1){1 / (Z_R * Z_C), -m * Z_D / (Z_R * Z_C), Z_A / (Z_R * Z_C), Z_W};
}

static const char *DEADZONE =
    "param A = 1, w = 10, d = 0.3, R0 = 1, C0 = 0.1\n"
    "Se U = A*sin(w*t)\n1 s\nR DZ : f = (max(e - d, 0) + min(e + d, 0))/R0\nC Cv = C0\n"
    "bond U -> s\nbond s -> DZ\nbond s -> Cv\n"
    "simulate t_end = 2, dt = 1e-3, rtol = 1e-10, atol = 1e-12\nplot Cv.e, DZ.f\n";

static void dz_check(const char *solver) {
  fx f;
  if (run_text(&f, DEADZONE, solver, 0)) { fx_free(&f); return; }
  pwl P = {dz_mode, dz_params, 1e-4};
  piece pc[MAXEV];
  int npc = pwl_pieces(&P, 0, 0, 2.0, pc, MAXEV);
  OK(npc >= 8);
  INT_EQ(f.r.nconditions, 2);
  pwl_check("deadzone", &f.r, &P, pc, npc, "Cv.e", 1e-7);
  fx_free(&f);
}

/* The same dead zone written with each piecewise function: the same
 * switches, the same solution (abs and sign also switch at e = 0 inside the
 * band, where nothing visible changes). */
static void dz_spelling(const char *law, int nconditions, int extra) {
  fx f;
  memset(&f, 0, sizeof f);
  f.src = strdup(DEADZONE);
  if (fx_edit(&f, "(max(e - d, 0) + min(e + d, 0))/R0", law) || fx_run(&f, law, BG_METHOD_SCAP, NULL, 0, NULL)) {
    OK(0);
    fx_free(&f);
    return;
  }
  INT_EQ(f.rc, 0);
  INT_EQ(f.r.nconditions, nconditions);
  pwl P = {dz_mode, dz_params, 1e-4};
  piece pc[MAXEV];
  int npc = pwl_pieces(&P, 0, 0, 2.0, pc, MAXEV);
  pwl_check_x(law, &f.r, &P, pc, npc, "Cv.e", 1e-7, extra);
  fx_free(&f);
}

static void test_deadzone(void) {
  dz_check(NULL);
  dz_check("ida");
  dz_spelling("(e - sat(e, -d, d))/R0", 2, 0);
  dz_spelling("(ramp(e - d) - ramp(-e - d))/R0", 2, 0);
  dz_spelling("(step(e - d)*(e - d) + step(-e - d)*(e + d))/R0", 2, 0);
  dz_spelling("if(abs(e) <= d, 0, e - d*sign(e))/R0", 3, 1);
  dz_spelling("table(e, [-10, -9.7; -0.3, 0; 0.3, 0; 10, 9.7])/R0", 2, 0);
}

/* ------------------------------------------------------------------ quantiser */
/* The same circuit with a flow law that is piecewise constant: floor and
 * ceil of 4 e (a quantiser: the state rises at a constant rate in each
 * level). */
static int q_kind; /* 0 floor, 1 ceil */
static double q_level(double e) { return q_kind ? ceil(4 * e) / 4 : floor(4 * e) / 4; }
/* the mode is the level times 4 (an integer) */
static int q_mode(double t, double v) { return (int)lround(4 * q_level(Z_A * sin(Z_W * t) - v)); }
static lin1 q_params(int m) { return (lin1){0, m / 4.0 / (Z_R * Z_C), 0, Z_W}; }

static void quantiser(int kind, const char *law) {
  fx f;
  memset(&f, 0, sizeof f);
  f.src = strdup(DEADZONE);
  if (fx_edit(&f, "(max(e - d, 0) + min(e + d, 0))/R0", law) || fx_run(&f, law, BG_METHOD_SCAP, NULL, 0, NULL)) {
    OK(0);
    fx_free(&f);
    return;
  }
  INT_EQ(f.rc, 0);
  INT_EQ(f.r.nconditions, 2);
  q_kind = kind;
  pwl P = {q_mode, q_params, 1e-4};
  piece pc[MAXEV];
  int npc = pwl_pieces(&P, 0, 0, 2.0, pc, MAXEV);
  OK(npc >= 10);
  pwl_check(law, &f.r, &P, pc, npc, "Cv.e", 1e-7);
  fx_free(&f);
}

static void test_quantiser(void) {
  quantiser(0, "floor(4*e)/4/R0");
  quantiser(1, "ceil(4*e)/4/R0");
}

/* ------------------------------------------------------------------ pulse and step of a state */
/* X.q = t (a store charged at rate 1); Y is charged by pulse(X.q - 0.2, 0.5)
 * + 2 step(X.q - 1): Y.q = clamp(t - 0.2, 0, 0.5) + 2 max(t - 1, 0), events
 * at 0.2, 0.7 and 1. (A pulse of a variable it feeds back on, e.g. the
 * dead zone's e, is a sliding mode: that run chatters and stops.) */
static const char *PULSE =
    "Sf S = 1\n0 a\nC X = 1\nbond S -> a\nbond a -> X\n"
    "MSf P = pulse(X.q - 0.2, 0.5) + 2*step(X.q - 1)\n0 b\nC Y = 1\nbond P -> b\nbond b -> Y\n"
    "simulate t_end = 1.5, dt = 0.01, rtol = 1e-10, atol = 1e-12\nplot Y.q\n";

static void pulse_check(const char *solver) {
  fx f;
  if (run_text(&f, PULSE, solver, 0)) { fx_free(&f); return; }
  static const double want[] = {0.2, 0.7, 1.0};
  INT_EQ(f.r.nconditions, 3);
  INT_EQ(f.r.nevents, 3);
  for (int i = 0; i < 3 && i < f.r.nevents; i++) DBL_NEAR(f.r.event_t[i], want[i], 1e-8);
  int k = col(&f.r, "Y.q");
  double err = 0;
  for (int i = 0; k >= 0 && i < f.r.nrows; i++) {
    double t = f.r.t[i], y = fmin(fmax(t - 0.2, 0), 0.5) + 2 * fmax(t - 1, 0);
    err = fmax(err, fabs(val(&f.r, i, k) - y));
  }
  OK(k >= 0 && err < 1e-9);
  fx_free(&f);
}

static void test_pulse(void) {
  pulse_check(NULL);
  pulse_check("ida");
  fx f; /* the pulse of the dead zone's own effort: a sliding mode, refused in words */
  memset(&f, 0, sizeof f);
  f.src = strdup(DEADZONE);
  if (fx_edit(&f, "(max(e - d, 0) + min(e + d, 0))/R0", "pulse(e - 0.2, 0.5)/R0") ||
      fx_run(&f, "pulse_dz", BG_METHOD_SCAP, NULL, 0, NULL)) { OK(0); fx_free(&f); return; }
  INT_EQ(f.rc, 2);
  OK(has(f.r.message, "more than 1000 state events in one output interval"));
  OK(f.r.partial && f.r.t_reached > 0.1);
  fx_free(&f);
}

/* ------------------------------------------------------------------ saturating valve */
/* A tank (C, e = q/Ct) filled by Q = Q0 + Q1 sin(w t) drains through a
 * valve whose flow saturates: f = sat(e/Rv, -fmax, fmax). Saturated the
 * level falls at the rate Q - fmax, below it it relaxes with Ct Rv. */
#define V_Q0 0.8
#define V_Q1 0.5
#define V_W 2.0
#define V_FMAX 1.0
static int valve_mode(double t, double q) { (void)t; return q > V_FMAX ? 2 : q < -V_FMAX ? 0 : 1; }
static lin1 valve_params(int m) {
  if (m == 1) return (lin1){1, V_Q0, V_Q1, V_W};
  return (lin1){0, V_Q0 - (m == 2 ? V_FMAX : -V_FMAX), V_Q1, V_W};
}

static const char *VALVE =
    "param Q0 = 0.8, Q1 = 0.5, w = 2, Ct = 1, Rv = 1, fmax = 1\n"
    "Sf Q = Q0 + Q1*sin(w*t)\n0 tank\nC T = Ct [q0 = 2]\nR V : f = sat(e/Rv, -fmax, fmax)\n"
    "bond Q -> tank\nbond tank -> T\nbond tank -> V\n"
    "simulate t_end = 20, dt = 0.01, rtol = 1e-10, atol = 1e-12\nplot T.q, V.f\n";

static void valve_check(const char *solver) {
  fx f;
  if (run_text(&f, VALVE, solver, 0)) { fx_free(&f); return; }
  pwl P = {valve_mode, valve_params, 1e-3};
  piece pc[MAXEV];
  int npc = pwl_pieces(&P, 0, 2, 20.0, pc, MAXEV);
  OK(npc >= 4); /* out of saturation near t = 5, then back in at each peak */
  INT_EQ(f.r.nconditions, 2);
  pwl_check("valve", &f.r, &P, pc, npc, "T.q", 1e-7);
  fx_free(&f);
}

static void test_valve(void) {
  valve_check(NULL);
  valve_check("ida");
}

/* ------------------------------------------------------------------ undecided at the start */
/* X.q = t^2/2 starts at 0 and leaves it with its second derivative (the
 * look-ahead along y' sees 0 too), so sign(X.q) cannot be held at a side
 * at t0: it is evaluated as compiled until its next root. Y, charged by
 * sign(X.q), then follows t (held at sign(0) = 0 it stayed 0, and the
 * root finder never said: hydraulic_lift's throttle, whose pressure drop
 * starts like this, passed no flow). */
static void test_undecided_start(void) {
  fx f;
  if (run_text(&f, "Sf S = t\n0 a\nC X = 1\nbond S -> a\nbond a -> X\nMSf P = sign(X.q)\n0 b\n"
                   "C Y = 1\nbond P -> b\nbond b -> Y\nsimulate t_end = 1, dt = 0.1, rtol = 1e-10, atol = 1e-12\n"
                   "plot X.q, Y.q\n", NULL, 0)) { fx_free(&f); return; }
  int kx = col(&f.r, "X.q"), ky = col(&f.r, "Y.q");
  OK(kx >= 0 && ky >= 0 && f.r.nrows == 11);
  INT_EQ(f.r.nconditions, 1);
  INT_EQ(f.r.nevents, 0);
  for (int i = 0; kx >= 0 && ky >= 0 && i < f.r.nrows; i++) {
    DBL_NEAR(val(&f.r, i, kx), 0.5 * f.r.t[i] * f.r.t[i], 1e-9);
    DBL_NEAR(val(&f.r, i, ky), f.r.t[i], 1e-6); /* the first steps straddle the jump of sign at 0+ */
  }
  fx_free(&f);
}

int main(void) {
  test_undecided_start();
  test_ball();
  test_ball_without_events();
  test_rectifier();
  test_deadzone();
  test_quantiser();
  test_pulse();
  test_valve();
  return bg_t_done();
}
