/* SPDX-License-Identifier: BSD-3-Clause */
/* Solver failure flags in plain words: what each usually means for a bond
 * graph model and what to try (docs/simulation.md). IDA fails on index-2 and
 * singular systems with generic flags, so the words for those name the
 * likely structural causes as well as the numerical ones. */
#include <cvode/cvode.h>
#include <ida/ida.h>

#include "simulate/simulate_words_int.h"

typedef struct flagword {
  int flag;
  const char *words;
} flagword;

static const flagword CV_WORDS[] = {
    {CV_TOO_MUCH_WORK, "the solver took the maximum number of steps without reaching the next "
                       "output time: the model is stiff (try solver = cvode_bdf) or has a very "
                       "fast time scale (a tiny store, a huge resistance) or a chattering law"},
    {CV_TOO_MUCH_ACC, "the requested accuracy cannot be reached in double precision: "
                      "increase rtol or atol"},
    {CV_ERR_FAILURE, "the error test failed repeatedly at the minimum step size: the solution "
                     "changes abruptly here (a discontinuous law such as sign, step or a table "
                     "edge, a value escaping to infinity, or a finite-time blow-up)"},
    {CV_CONV_FAILURE, "the corrector (Newton) iteration failed to converge repeatedly: the "
                      "equations are near a singular point here (a modulus or inertance "
                      "passing through zero) or change too fast"},
    {CV_LSETUP_FAIL, "the Jacobian matrix could not be factored (singular): a store, "
                     "modulus or resistance became zero or infinite"},
    {CV_LSOLVE_FAIL, "the linear solver failed: the Jacobian is singular or badly scaled"},
    {CV_RHSFUNC_FAIL, "the equations could not be evaluated"},
    {CV_FIRST_RHSFUNC_ERR, "the equations could not be evaluated at the initial values"},
    {CV_REPTD_RHSFUNC_ERR, "the equations could not be evaluated, even with ever smaller "
                           "steps"},
    {CV_UNREC_RHSFUNC_ERR, "the equations could not be evaluated"},
    {CV_RTFUNC_FAIL, "the search for state events stopped"},
    {CV_TOO_CLOSE, "t_end is too close to t0"},
    {CV_ILL_INPUT, "the solver rejected an input (a tolerance, time or option out of range)"},
    {CV_MEM_FAIL, "out of memory"},
};

static const flagword IDA_WORDS[] = {
    {IDA_TOO_MUCH_WORK, "the solver took the maximum number of steps without reaching the next "
                        "output time: a very fast time scale, a chattering law, or an index "
                        "above 1 that the analysis did not detect"},
    {IDA_TOO_MUCH_ACC, "the requested accuracy cannot be reached in double precision: "
                       "increase rtol or atol"},
    {IDA_ERR_FAIL, "the error test failed repeatedly at the minimum step size: the solution "
                   "changes abruptly here (a discontinuous law, a blow-up), or the algebraic "
                   "constraints have an index above 1 (a causal loop of gain +1, class 1 paths "
                   "sharing bonds with a loop)"},
    {IDA_CONV_FAIL, "the algebraic equations could not be solved: Newton's method did not "
                    "converge (an algebraic loop near a singular point, where its gain "
                    "approaches +1, a dependent store whose modulus passes through zero, or a "
                    "nonlinear law with no solution here)"},
    {IDA_LSETUP_FAIL, "the Jacobian of the algebraic equations is singular: an algebraic "
                      "loop of gain +1 or a dependent store whose coupling vanishes at this "
                      "point (index above 1 here)"},
    {IDA_LSOLVE_FAIL, "the linear solver failed: the Jacobian is singular or badly scaled"},
    {IDA_RES_FAIL, "the equations could not be evaluated"},
    {IDA_REP_RES_ERR, "the equations could not be evaluated, even with ever smaller steps"},
    {IDA_FIRST_RES_FAIL, "the equations could not be evaluated at the initial values"},
    {IDA_RTFUNC_FAIL, "the search for state events stopped"},
    {IDA_CONSTR_FAIL, "a constraint on the unknowns could not be met"},
    {IDA_LINESEARCH_FAIL, "no consistent initial values were found: the line search failed "
                          "(the algebraic equations may have no solution for the given "
                          "initial states)"},
    {IDA_NO_RECOVERY, "no consistent initial values were found: the equations failed to "
                      "evaluate or the algebraic part is singular at the initial point "
                      "(check q0/p0 of dependent stores)"},
    {IDA_BAD_EWT, "an error weight became zero: give atol > 0"},
    {IDA_ILL_INPUT, "the solver rejected an input (a tolerance, time or option out of range, "
                    "or inconsistent initial values that IDACalcIC could not correct)"},
    {IDA_MEM_FAIL, "out of memory"},
};

static const char *lookup(const flagword *w, int n, int flag) {
  for (int i = 0; i < n; i++)
    if (w[i].flag == flag) return w[i].words;
  return "the solver failed";
}

void bg_sim_explain(int ida, int flag, const char *evalerr, bg_strbuf *sb) {
  const char *w = ida ? lookup(IDA_WORDS, (int)(sizeof IDA_WORDS / sizeof *IDA_WORDS), flag)
                      : lookup(CV_WORDS, (int)(sizeof CV_WORDS / sizeof *CV_WORDS), flag);
  bg_sb_puts(sb, w);
  if (!evalerr) return;
  int evalflag = ida ? flag == IDA_RES_FAIL || flag == IDA_REP_RES_ERR || flag == IDA_FIRST_RES_FAIL ||
                           flag == IDA_RTFUNC_FAIL
                     : flag == CV_RHSFUNC_FAIL || flag == CV_FIRST_RHSFUNC_ERR ||
                           flag == CV_REPTD_RHSFUNC_ERR || flag == CV_UNREC_RHSFUNC_ERR ||
                           flag == CV_RTFUNC_FAIL;
  bg_sb_printf(sb, evalflag ? ": %s" : "; the equations also failed to evaluate nearby: %s", evalerr);
}
