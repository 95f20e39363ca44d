/* SPDX-License-Identifier: BSD-3-Clause */
/* The layout of bg_eqsys: its equation trees and its evaluation tape.
 * Part of the equations stage's front door (equations/equations.h) because
 * the exporters (src/export) write the same tape the engine evaluates, in
 * other languages; every other stage uses bg_eqsys through the functions of
 * eqsys.h. Written by eqsys.c (derivation of the equations), eqsys_order.c
 * (sorting and tearing) and eqsys_tape.c (evaluation and exact Jacobians);
 * the functions they share are in eqsys_int.h. */
#ifndef BG_EQTAPE_H
#define BG_EQTAPE_H
#include "base/arena.h"
#include "equations/eqsys.h"
#include "base/strbuf.h"

/* Equation trees: a tiny expression language over model expressions (EQ_X),
 * bond signals and unknowns, so the printers and the tape compiler read the
 * same equations. Children are node ids. */
typedef enum {
  EQ_NUM, /* c */
  EQ_X,   /* a = root xnode of a model expression */
  EQ_SIG, /* a = signal: 2*bond (effort), 2*bond+1 (flow) */
  EQ_Y,   /* a = unknown index */
  EQ_YP,  /* a = unknown index: its time derivative */
  EQ_LIN, /* sum of lin_coef[k] * node lin_node[k], k in [a, a+b) */
  EQ_MUL, /* a * b */
  EQ_DIV  /* a / b */
} eq_kind;

typedef struct eq_node {
  int kind, a, b;
  double c;
} eq_node;

/* How a signal's equation reads. */
enum { EQF_EXPLICIT, /* signal = tree */ EQF_IMPLICIT /* 0 = tree, solved for signal */ };

/* Tape instruction: out = op(args). op is a bg_xop (arithmetic, comparison,
 * BG_X_CALL with ref = bg_func, BG_X_TABLE with ref = table) or T_LIN. */
#define T_LIN 200
#define T_DTABLE 201 /* slope of table ref at a[0] (symbolic derivatives of tables) */
typedef struct tinstr {
  unsigned char op, na;
  int ref;     /* function or table id; T_LIN: first index into lin arrays */
  int out;
  int a[3];    /* argument slots; T_LIN: a[0] = number of terms */
  int eq;      /* which equation (signal, or -1 - row) for error messages */
  int xn;      /* the model expression node it computes (event descriptions), -1 */
} tinstr;

struct bg_eqsys {
  const bg_model *m;
  const bg_analysis *a;
  bg_arena arena;
  int nsig;               /* 2 * nbond */
  int nx, nz, n, ndep, nint; /* nint: integral stores + user states */

  /* equation trees */
  eq_node *node;
  int nnode, capnode;
  double *lin_coef;
  int *lin_node;
  int nlin, caplin;

  /* per signal */
  int *sig_form;  /* EQF_* */
  int *sig_root;  /* equation tree */
  int *sig_elem;  /* element whose relation it is */
  const char **sig_what; /* "law", "value", "balance", "modulus", ... */
  int *sig_torn;  /* an algebraic unknown: sig_z[s] is its index in y */
  int *sig_z;
  int *dep_adr, *dep_n, *dep; /* signals each signal's equation reads */

  /* computational order of the explicit signals */
  int norder;
  int *order;

  /* per unknown */
  const char **uname;
  int *u_elem;     /* store element, or -1 */
  int *u_state;    /* user state id, or -1 */
  int *u_sig;      /* torn signal for algebraic unknowns, else -1 */
  int *row_kind;   /* 0: res = yp - root (rhs form); 1: res = root */
  int *row_root;   /* equation tree of the row */
  int *store_y;    /* per element: unknown index of a store's state, -1 */
  int *state_y;    /* per user state: its unknown index */
  int *x_modulus;  /* per model xnode: the state-modulated two-port whose modulus
                      it is (printed by name), else -1; built once, so printing
                      an expression node costs no scan of the elements */

  /* the tape */
  tinstr *code;
  int ncode, capcode, nmain; /* [0, nmain): unknowns -> residual; rest: outputs */
  int *tl_slot;
  double *tl_coef;
  int ntl, captl;
  double *v, *dv; /* values and one directional derivative per slot */
  unsigned char *is_const;
  int nslot, capslot;
  int slot_y, slot_yp; /* slot of y[0], yp[0]; slot 0 is t */
  /* export builds (bg_eqsys_build_export): param k is read from slot
   * param_slot[k]: slot_p + k for a param given by a number (set from the
   * exported parameter record), computed code for one defined by other
   * params; code [nout_code, ncode) computes the initial values, init_slot[i]
   * per unknown (-1: none, the unknown starts at 0 or its consistent value) */
  int live_params, slot_p, nout_code;
  int *param_slot, *init_slot;
  int *sig_slot;
  int *row_slot;
  int *input_slot;

  /* outputs */
  int nout;
  const char **out_name;
  int *out_slot;
  /* the outputs' slice of the tape (bg_eqs_eval_outputs): the instructions
   * of [0, nout_code) the output slots depend on, in tape order, and the
   * unknowns and derivatives they read */
  int *oslice, noslice;
  int *oslice_y, noslice_y, *oslice_yp, noslice_yp;

  /* linear analysis (bg_eqsys_build_io): perturbable inputs u_k added to a
   * source's value or an input's value, and the model's outputs */
  int lin_nu, *lin_ref, *lin_uslot;
  int lin_nh, *lin_hslot;

  /* Jacobian pattern (CSC, with the diagonal) and its column colouring */
  int nnz, *colptr, *rowind;
  int ncolor, *color;
  int *color_adr, *color_cols;

  /* state events (eqsys_events.c): the main-tape instructions whose
   * switching condition reads an unknown, their modes and root functions */
  int nev, *ev_code, *ev_root0, *code_ev; /* code_ev: per main instruction, -1 */
  double *ev_mode, *ev_prev; /* ev_prev: the modes before an update */
  unsigned char *ev_zero;     /* per event: a switching function exactly zero */
  unsigned char *ev_free;     /* per event: undecided at the last update, evaluated as compiled */
  double *ev_band;            /* per event: > 0 while loose, the half-width of its band (continuous switches) */
  int ev_sliding;             /* 1 + the event the last update found sliding at its switching point, or 0 */
  int nroot, *root_ev;
  const char **root_text;
  unsigned char *slot_dep; /* per slot: reads y or yp (bit 1), t (bit 2) */
  double *ev_y, *ev_yp;    /* n-sized scratch of the look-ahead */
  int ev_frozen;           /* evaluate with the modes frozen (set by the simulation) */
  unsigned char *ev_mem;   /* per event: a memory function (hyst, stick): its mode is its value */
  int nmem;                /* how many */
  int ev_fresh;            /* the next update starts a run: memory takes its starting value */
  int vals_frozen;         /* the current values were computed with frozen modes */

  double *work;     /* n-sized scratch */
  char err[256];
  int has_err;

  /* index reduction (indexred.c): a system built from the symbolic rows of
   * another, with differentiated equations and dummy derivatives. Its rows
   * are all residuals (row_kind 1); row_alg marks those that read no yp;
   * its initial point is solved like Lagrange causality's (states held,
   * every row solved for the algebraic unknowns and the derivatives). */
  int reduced;
  unsigned char *row_alg;
};

/* The name of bond signal sig in ar: "R1.e" for a 1-port's bond, else "e4" (eqsys.c). */
const char *bg_eqs_signame(const bg_eqsys *s, int sig, bg_arena *ar);
/* 1 for a param defined by other params (not --set): export
 * builds compute it instead of reading it from the parameter record (eqsys_tape.c). */
int bg_eqsys_param_is_derived(const bg_eqsys *s, int k);
#endif
