/* SPDX-License-Identifier: BSD-3-Clause */
/* Linear analysis (docs/linear.md): an operating point, the linearisation
 * there as a descriptor system E x' = A x + B u, y = C x + Cp x' + D u over
 * every unknown of the equations, the state space A, B, C, D after
 * eliminating the algebraic unknowns where that is possible, transfer
 * functions per input/output pair, frequency and time responses.
 * Built on the exact AD Jacobians of the equations (bg_eqsys_jac_io) and
 * LAPACK. Matrices are dense, column-major. */
#ifndef BG_LINEAR_H
#define BG_LINEAR_H
#include "base/arena.h"
#include "base/strbuf.h"
#include "causality/causality.h"
#include "equations/equations.h"
#include "model/model.h"

/* Above these sizes the dense parts are skipped (documented in docs/linear.md). */
enum { BG_LIN_MAX_UNKNOWNS = 3000, BG_LIN_MAX_TF = 200, BG_LIN_MAX_TIME = 400 };

typedef struct bg_lin_tf {
  int iu, iy;             /* input and output */
  int nnum, nden;         /* number of coefficients (degree + 1) */
  double *num, *den;      /* highest power first; den monic */
  int npole, nzero;       /* after cancelling uncontrollable/unobservable modes */
  double *pole_re, *pole_im, *zero_re, *zero_im; /* sorted by (re, im) */
  double dc_gain;         /* +-inf with a pole at s = 0, NaN for 0/0 */
  int ncancel;            /* poles cancelled by zeros */
} bg_lin_tf;

/* The symbolic form of a linear time-invariant model with at most 8 states
 * (linear_sym.c): printed entries, [0] text and [1] LaTeX, column-major as
 * the numeric matrices; den: n + 1 coefficients (s^n first, monic); num:
 * per pair (output-major) n + 1 coefficients. Full order. */
typedef struct bg_lin_symbolic {
  int ok, n;
  const char *note; /* why there is none (static text), nullable */
  char **A[2], **B[2], **C[2], **D[2], **den[2], **num[2];
} bg_lin_symbolic;

typedef struct bg_linear {
  int ok;                 /* 0: not linearised; message says why */
  char *message;          /* one line: the refusal, or notes about the point */
  /* the operating point */
  int steady;             /* Newton steady state (else the initial point) */
  double t;               /* inputs held at their values at t */
  int N;                  /* unknowns of the equations */
  const char **uname_all; /* their names */
  double *y0, *h0;        /* unknowns and outputs at the point */
  double resid;           /* max |F| at the point (0 at an exact steady state) */
  /* inputs and outputs */
  int nu, ny;
  const char **uname, **yname; /* "U", "y" (model strings) */
  int outputs_are_states; /* no output statement: y = the states */
  /* descriptor form over all N unknowns: E x' = A x + B u, y = C x + Cp x' + D u */
  double *E, *Ad, *Bd, *Cd, *Cpd, *Dd;
  int has_cp;             /* some output reads a derivative (Cp != 0) */
  /* state space after eliminating the algebraic unknowns */
  int reduced;            /* 1: A, B, C, D below are valid */
  char *reduce_note;      /* why not (nullable) */
  int n;                  /* states */
  int *state;             /* index of each state among the N unknowns */
  int nelim, *elim;       /* dependent stores eliminated (unknowns fixed by constraints) */
  double *A, *B, *C, *D;
  /* poles of the linearisation (eigenvalues of A, or finite generalised ones) */
  int npole;
  double *pole_re, *pole_im;
  /* transfer functions, output-major: tf[iy * nu + iu] */
  int ntf;
  bg_lin_tf *tf;
  char *tf_note;          /* why there are none (nullable) */
  bg_lin_symbolic sym;    /* the symbolic form (linear models) */
  bg_arena arena;         /* owns the names */
} bg_linear;

/* Linearises the model at its operating point (m->linear; `steady` < 0 takes
 * the model's choice). Builds its own equation system with the inputs made
 * perturbable. Returns 0, or -1 with out->message (out must be freed with
 * bg_linear_free either way). */
int bg_linear_compute(const bg_model *m, const bg_analysis *a, int steady, bg_linear *out);
void bg_linear_free(bg_linear *l);

/* ---- frequency responses (linear_freq.c) */
/* Frequencies (rad/s) for Bode and Nyquist plots: the model's w_min/w_max or
 * two decades around the poles and zeros, log-spaced; returns the count. */
int bg_linear_freqs(const bg_linear *l, const bg_model *m, int nw, double *w);
/* H(j w_k) for every pair: re/im arrays of nw * ny * nu, pair-major
 * ((iy * nu + iu) * nw + k). Reduced systems: A in Hessenberg form once,
 * O(n^2) per frequency; descriptor only: a dense complex solve each. */
int bg_linear_freqresp(const bg_linear *l, int nw, const double *w, double *re, double *im);
/* The phase in degrees of one pair's samples re/im (nw each) at w, continuous
 * along w (linear_phase.c): each sample's angle, on the branch its transfer
 * function's poles and zeros give, or unwrapped where there is none; NaN
 * where H is 0. The first sample keeps its angle in (-180, 180]. */
void bg_linear_phase(const bg_linear *l, int pair, int nw, const double *w, const double *re,
                     const double *im, double *ph);

/* ---- time responses (linear_time.c): step and impulse of every pair,
 * nt points on [0, t_end] (t_end: the model's or 5 slowest time constants);
 * y arrays of nt * ny * nu pair-major. 0, or -1 (not reduced, too large). */
double bg_linear_t_end(const bg_linear *l, const bg_model *m);
int bg_linear_step(const bg_linear *l, double t_end, int nt, int impulse, double *y);

/* ---- printing (linear_print.c) */
void bg_linear_print(const bg_linear *l, const bg_model *m, const char *form, bg_strbuf *out);
/* State space as an Octave/MATLAB script or a Python module (linear_export.c). */
void bg_linear_export_m(const bg_linear *l, const bg_model *m, bg_strbuf *out);
void bg_linear_export_py(const bg_linear *l, const bg_model *m, bg_strbuf *out);
#endif
