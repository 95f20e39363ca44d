/* SPDX-License-Identifier: BSD-3-Clause */
/* bg_eqsys: the model's equations in computational order, ready to evaluate
 * numerically (simulation, linearisation, index). Built from a causal bond
 * graph (bg_model + bg_analysis); never modifies either.
 *
 * Unknowns y = [differential unknowns (states: integral stores' q/p, user
 * states, dependent stores' q/p); algebraic unknowns z (the algebraic
 * variables of algebraic blocks, after eliminating what can be computed
 * explicitly in sorted order)]. An ODE has nz = 0 and no dependent stores.
 *
 * Ownership: bg_eqsys_build returns an object the caller frees with
 * bg_eqsys_free; the model and analysis are borrowed and must outlive it.
 * Evaluation functions use scratch memory inside the object: not
 * thread-safe, no allocation. */
#ifndef BG_EQSYS_H
#define BG_EQSYS_H
#include "causality/causality.h"
#include "base/diag.h"
#include "model/model.h"

typedef struct bg_eqsys bg_eqsys;

/* Builds the equation system. Returns NULL (with a diagnostic) when the
 * causality is incomplete or the system cannot be formed. Under Lagrange
 * causality the flow of each artificial source's 1-junction is an algebraic
 * unknown ("ma.f") whose residual is the junction's effort balance; a bond
 * split by an inserted 1-junction keeps one flow (the unknown, named like the
 * bond's flow: "Cp.f", "f3") and its head's relation becomes that unknown's
 * residual (the two efforts of the bond agree). */
bg_eqsys *bg_eqsys_build(const bg_model *m, const bg_analysis *a, bg_diags *dg);
/* The same system for the model exporters (src/export): the model's params
 * stay variables of the evaluation tape (slots set from a parameter record)
 * instead of folded constants, and the initial values of the unknowns are
 * compiled too, so exported code can change params at run time. Evaluates
 * exactly like the system of bg_eqsys_build. */
bg_eqsys *bg_eqsys_build_export(const bg_model *m, const bg_analysis *a, bg_diags *dg);
void bg_eqsys_free(bg_eqsys *s);

int bg_eqsys_n(const bg_eqsys *s);          /* nx + nz */
int bg_eqsys_nx(const bg_eqsys *s);         /* differential unknowns, first in y */
int bg_eqsys_is_ode(const bg_eqsys *s);     /* nz == 0 and every state independent */
/* 1 for the system of an index reduction (equations/indexred.h). */
int bg_eqsys_is_reduced(const bg_eqsys *s);
const char *bg_eqsys_name(const bg_eqsys *s, int i); /* "L1.p", "phi", "e4", "R1.e" */
/* The order of two unknowns' names that an order-keeping renaming of the
 * elements keeps: names of elements' and user states' unknowns first, in
 * natural order, then bonds' variables ("e4", "f12") in natural order. */
int bg_eqsys_name_cmp(const char *a, const char *b);
/* 1 for unknowns whose derivative appears (IDASetId), 0 for algebraic ones. */
int bg_eqsys_is_differential(const bg_eqsys *s, int i);

/* Initial values from the model (q0, p0, state init; algebraic unknowns get
 * a guess consistent where it can be computed explicitly, else 0). */
void bg_eqsys_initial(const bg_eqsys *s, double *y0);
/* The same, with the derivatives that go with it: under Lagrange causality
 * every store keeps its model value (dependent ones too: they fix the
 * generalised velocities) and the algebraic unknowns and yp are solved
 * together; otherwise yp0 is 0 (IDACalcIC computes it). */
void bg_eqsys_initial_yp(const bg_eqsys *s, double *y0, double *yp0);

/* Newton on the algebraic rows (dependent stores' constraints, algebraic
 * unknowns) with the states of y held and yp = 0, at most maxit steps; y is
 * updated in place. Dense: skipped above 3000 unknowns. 0, or -1 when an
 * evaluation failed. (Called by bg_eqsys_initial.) */
int bg_eqsys_consistent(bg_eqsys *s, double t, double *y, int maxit);

/* ODE right-hand side ydot = f(t, y) (only when bg_eqsys_is_ode).
 * Returns 0, or -1 when an evaluation produced NaN/Inf (a law evaluated
 * outside its domain); bg_eqsys_error then says which equation, in words. */
int bg_eqsys_rhs(bg_eqsys *s, double t, const double *y, double *ydot);
/* DAE residual F(t, y, yp) = 0 (any form; for an ODE F = yp - f(t, y)). */
int bg_eqsys_residual(bg_eqsys *s, double t, const double *y, const double *yp, double *res);
const char *bg_eqsys_error(const bg_eqsys *s); /* nullable */

/* Jacobians, exact (not finite differences): ODE: J = df/dy;
 * DAE: J = dF/dy + cj * dF/dyp. Dense: column-major n x n. */
int bg_eqsys_jac_dense(bg_eqsys *s, double t, const double *y, const double *yp, double cj,
                       double *J);
/* Sparse: the pattern in CSC form including every diagonal entry (docs/simulation.md:
 * KLU is slow without it); colptr has n+1 entries. nnz from bg_eqsys_jac_nnz. */
int bg_eqsys_jac_nnz(const bg_eqsys *s);
void bg_eqsys_jac_pattern(const bg_eqsys *s, int *colptr, int *rowind);
int bg_eqsys_jac_sparse(bg_eqsys *s, double t, const double *y, const double *yp, double cj,
                        double *values); /* in the pattern's order */

/* Linearisation at (t, y, yp): A = dF/dyp, B = dF/dy (dense, column-major),
 * so that A x' + B x = f approximates the model (Equation 4.5). */
int bg_eqsys_linearise(bg_eqsys *s, double t, const double *y, const double *yp, double *A,
                       double *B);

/* Linear analysis (docs/linear.md). An equation system like bg_eqsys_build's
 * whose inputs can be perturbed: inputs[k] >= 0 is a source element, whose
 * value becomes value + u_k; inputs[k] < 0 is the model input -1 - inputs[k],
 * likewise. The model's outputs (m->output_expr) are compiled too. With
 * u = 0 it evaluates exactly as bg_eqsys_build's system. */
bg_eqsys *bg_eqsys_build_io(const bg_model *m, const bg_analysis *a, const int *inputs, int nu,
                            bg_diags *dg);
/* Exact derivatives at (t, y, yp), u = 0, of the residual F (n rows) and the
 * outputs h (m->noutput rows) with respect to y, yp and u: dense column-major
 * Fy, Fyp (n x n), Fu (n x nu), Hy, Hyp (nh x n), Hu (nh x nu); h gets the
 * outputs' values. Any pointer may be NULL. 0, or -1 as bg_eqsys_residual. */
int bg_eqsys_jac_io(bg_eqsys *s, double t, const double *y, const double *yp, double *Fy,
                    double *Fyp, double *Fu, double *Hy, double *Hyp, double *Hu, double *h);

/* Values of the model's plot expressions (m->plotexpr_root order), or of the
 * states when the model has no plot statement (bg_eqsys_noutput/_output_name). */
int bg_eqsys_noutput(const bg_eqsys *s);
const char *bg_eqsys_output_name(const bg_eqsys *s, int k);
int bg_eqsys_outputs(bg_eqsys *s, double t, const double *y, const double *yp, double *out);

/* Every bond variable at (t, y, yp) (yp nullable: zeros): e[b] and f[b] by
 * bond id (arrays of m->nbond). 0, or -1 as bg_eqsys_residual. */
int bg_eqsys_signals(bg_eqsys *s, double t, const double *y, const double *yp, double *e,
                     double *f);

/* Times in (t0, t1) where an input is discontinuous (step, pulse and table
 * breakpoints of inputs and sources that depend on t only), sorted, unique;
 * returns the count (at most max written). */
/* Sets yp of the dependent stores whose rate no residual reads to the time
 * derivative of their constraints' solution at (t, y), by central
 * differences of width h (the other entries of yp are the rates of the
 * independent states). Dense: nothing happens above 1000 unknowns, nor when
 * the constraints cannot be solved at t -+ h. Returns the number of stores
 * set (0: none), or -1 when nothing could be set. */
int bg_eqsys_dependent_rates(bg_eqsys *s, double t, const double *y, double *yp, double h);
/* Consistent values at a restart (after an input step or a state event) of
 * a DAE with dependent stores, where IDACalcIC cannot reduce the residual of
 * a constraint (it reads no rate): the algebraic rows solved with the states
 * held (bg_eqsys_consistent), then the rates and the algebraic unknowns
 * from every row that reads a rate and the constraints' time derivatives
 * (the partial derivative in t one-sided from the right, step h; from the
 * left for h < 0), the states held. Also the output rows of an IDA run
 * (simulate_run.c, record). 0 with y and yp set; -1 (nothing changed)
 * without dependent stores, above 1000 unknowns, when a constraint reads an
 * algebraic unknown, or when Newton fails. */
int bg_eqsys_restart_rates(bg_eqsys *s, double t, double *y, double *yp, double h);
/* The start of a DAE with dependent stores, after IDACalcIC: it holds the
 * states and solves the rows that read rates, but a constraint reads none,
 * so the rates it leaves need not satisfy the constraints' time derivatives
 * (a store tied to a time-varying input whose rate another row reads: IDA's
 * first step then failed its error test at t0, docs/property.md finding 17d).
 * When some constraint's time derivative is violated by more than
 * BG_EQSYS_RATE_TOL of the size of its terms, the rates and algebraic
 * unknowns are solved as in bg_eqsys_restart_rates (the states and algebraic
 * rows kept). 0: nothing to do, or nothing known (the equations cannot be
 * evaluated a moment later, or a constraint reads an algebraic unknown, whose
 * rate the check lacks); 1: y and yp set; -1: violated and Newton failed. */
#define BG_EQSYS_RATE_TOL 1e-6
int bg_eqsys_start_rates(bg_eqsys *s, double t, double *y, double *yp, double h);
/* The algebraic unknowns' rates at a consistent point (IDACalcIC leaves
 * them as guessed): the algebraic rows solved at t + h and t + 2h with the
 * differential states moved along yp, the one-sided difference of second
 * order (the limit from the right of a restart at a jump). Returns how
 * many were set (0 when a solve failed or above 1000 unknowns). */
int bg_eqsys_algebraic_rates(bg_eqsys *s, double t, const double *y, double *yp, double h);
/* The shortest period of the periodic functions of time (sin, cos, tan) in
 * the sources and inputs, from their angular rate at t0 and t1 (the larger);
 * 0 when there is none. The simulation keeps its steps below a fraction of
 * it (docs/simulation.md, "Steps against the inputs"). */
double bg_eqsys_input_period(const bg_eqsys *s, double t0, double t1);
/* 1 for rows that are algebraic equations (an algebraic unknown's residual,
 * a dependent store's constraint): output rows must satisfy them. */
int bg_eqsys_is_algebraic_row(const bg_eqsys *s, int i);
int bg_eqsys_breakpoints(const bg_eqsys *s, double t0, double t1, double *times, int max);

/* State events (docs/simulation.md, "State events"): every comparison, abs,
 * sign, step, ramp, pulse, min, max, sat, floor, ceil and table of the
 * equations whose switching condition reads an unknown has a mode (the
 * branch it takes) and one root function per switching point (sat and
 * pulse: two; floor, ceil, table: the two ends of the current piece).
 * bg_eqsys_nroots is 0 for a model without them, which then evaluates as
 * before. With the modes frozen, every evaluation (residual, right-hand
 * side, Jacobians, outputs) takes the branch the mode holds, continued
 * past its switching point, except that an evaluation that is not finite
 * that way is done as compiled. */
int bg_eqsys_nroots(const bg_eqsys *s);
int bg_eqsys_nmodes(const bg_eqsys *s);
/* Where root i sits and what it is: "law of D: e2 > 0", "law of V: sat(...)
 * (upper limit)"; valid while s lives. */
const char *bg_eqsys_root_text(const bg_eqsys *s, int i);
void bg_eqsys_modes_freeze(bg_eqsys *s, int on);
/* The root functions at (t, y, yp) (yp nullable) under the current modes:
 * g has bg_eqsys_nroots entries. 0, or -1 when one is not finite. */
int bg_eqsys_roots(bg_eqsys *s, double t, const double *y, const double *yp, double *g);
/* Sets every mode from the values at (t, y, yp); dir (nullable, one per
 * root: +1 rising, -1 falling, 0) decides a root function that is exactly
 * zero at a root just found; one still undecided is decided by the point
 * y + delta y' (y' = yp, or the right-hand side when yp is NULL). Returns
 * how many modes changed. */
/* After an ODE's bg_eqsys_modes_update: the event whose switching function
 * sat exactly at 0 and that no mode holds (each side's rate points to the
 * other: a sliding mode at its start), or -1. */
int bg_eqsys_mode_sliding(const bg_eqsys *s);
int bg_eqsys_modes_update(bg_eqsys *s, double t, const double *y, const double *yp, const int *dir,
                          double delta);
/* The modes of the limit from the right of (t, y, yp): the algebraic
 * unknowns solved at t + delta (the differential ones moved along yp) under
 * the modes, the modes set from there, until they agree (at most maxit
 * rounds): 0 agreed, 1 not, -1 a solve failed (docs/simulation.md,
 * "Starting on a switching point"). */
int bg_eqsys_modes_right(bg_eqsys *s, double t, const double *y, const double *yp, double delta, int maxit);
/* After a DAE's limit from the right and consistent values under its
 * modes: 1 + the event whose switching function sits exactly at 0, whose
 * chosen mode its own rates leave and whose law jumps there (its two
 * sides' rows differ by more than tol, one per row): a sliding mode at its
 * start; 0 when there is none, -1 when the solve a moment later failed. */
int bg_eqsys_modes_slide(bg_eqsys *s, double t, const double *y, const double *yp, double delta,
                         const double *tol);
/* The root functions of mode e: how many, *first the index of the first. */
int bg_eqsys_mode_roots(const bg_eqsys *s, int e, int *first);
/* How the root function of mode e crossed 0 when the mode went from before
 * to after: +1 rising, -1 falling. */
int bg_eqsys_mode_direction(const bg_eqsys *s, int e, double before, double after);
/* Memory (hyst, stick; docs/format.md, "Memory"): mode e is a memory
 * function's discrete state, its value between events whatever the
 * freezing; bg_eqsys_has_memory counts them. bg_eqsys_modes_reset makes the
 * next bg_eqsys_modes_update a run's first: memory takes its starting value. */
int bg_eqsys_mode_memory(const bg_eqsys *s, int e);
int bg_eqsys_has_memory(const bg_eqsys *s);
void bg_eqsys_modes_reset(bg_eqsys *s);
/* Where mode e's instruction sits ("value of heater", "law of F") and what
 * it is ("hyst(e2, lo, hi)"), appended to where and what. */
void bg_eqsys_mode_describe(const bg_eqsys *s, int e, bg_strbuf *where, bg_strbuf *what);
/* Continuous switches (docs/simulation.md, "Continuous switches"): mode e,
 * whose switching function just crossed 0 and back, is let loose when its
 * two sides (the mode it holds and other) give rows at (t, y, yp) (yp NULL:
 * an ODE's right-hand side) that differ by at most tol[i] in each row (one
 * law here: a continuous piecewise law) and its switching function sits
 * within band = 100 (atol + rtol |operands|) of 0. Loose, it is evaluated
 * as compiled, its mode is not updated, and its root functions are band -
 * |g|: they cross 0 only where the switching function leaves the band, and
 * the caller then tightens it (a mode again, set by the next update). The
 * solver must restart after either. Returns 1 when let loose. */
int bg_eqsys_mode_loosen(bg_eqsys *s, int e, double other, double t, const double *y, const double *yp,
                         const double *tol, double rtol, double atol);
int bg_eqsys_mode_loose(const bg_eqsys *s, int e);
void bg_eqsys_mode_tighten(bg_eqsys *s, int e);
int bg_eqsys_root_mode(const bg_eqsys *s, int i); /* the mode root function i belongs to */
void bg_eqsys_modes_get(const bg_eqsys *s, double *modes); /* bg_eqsys_nmodes values */
void bg_eqsys_modes_set(bg_eqsys *s, const double *modes);
#endif
