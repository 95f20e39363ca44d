/* SPDX-License-Identifier: BSD-3-Clause */
/* Expressions: the tree evaluator, the bytecode VM (which must agree with it
 * bit for bit) and printing. Models are built by hand, without the parser. */
#include <stdint.h>
#include <stdlib.h>

#include "model/model.h"
#include "harness.h"

#define PI 3.14159265358979323846

/* ---------------------------------------------------------------- hand-built models */
enum { CAP = 65536, NVAR = 8 };

/* A model with NVAR params, inputs, states, bonds and elements, and a table. */
static bg_model *model_new(void) {
  bg_model *m = calloc(1, sizeof *m);
  static const char *pn[NVAR] = {"a", "b", "c", "k", "m0", "p5", "p6", "p7"};
  static const char *sn[NVAR] = {"x", "y", "z", "w", "s4", "s5", "s6", "s7"};
  static const char *en[NVAR] = {"C1", "L1", "R1", "C2", "E4", "E5", "E6", "E7"};
  static const int ek[NVAR] = {BG_ELEM_C, BG_ELEM_I, BG_ELEM_R, BG_ELEM_C,
                               BG_ELEM_R, BG_ELEM_R, BG_ELEM_R, BG_ELEM_R};
  m->nparam = m->nstate = m->nbond = m->nelem = m->ninput = NVAR;
  m->param_name = (const char **)pn;
  m->state_name = (const char **)sn;
  m->elem_name = (const char **)en;
  m->elem_kind = (int *)ek;
  m->param_value = calloc(NVAR, sizeof(double));
  for (int i = 0; i < NVAR; i++) m->param_value[i] = 0.5 + i;
  m->bond_num = calloc(NVAR, sizeof(int));
  for (int i = 0; i < NVAR; i++) m->bond_num[i] = 3 * i + 1;
  static const char *in[NVAR] = {"u", "v", "i2", "i3", "i4", "i5", "i6", "i7"};
  m->input_name = (const char **)in;
  m->input_expr = calloc(NVAR, sizeof(int));
  m->xnode = calloc(CAP, sizeof(bg_xnode));
  return m;
}

static void model_free(bg_model *m) {
  free(m->param_value);
  free(m->bond_num);
  free(m->input_expr);
  free(m->xnode);
  free(m->table_adr);
  free(m->table_n);
  free(m->table_x);
  free(m->table_y);
  free(m);
}

static int push(bg_model *m, int op, int ref, int nargs, int a0, int a1, int a2, double num) {
  if (m->nxnode == CAP) abort();
  bg_xnode *n = &m->xnode[m->nxnode];
  *n = (bg_xnode){.op = (unsigned char)op, .nargs = (unsigned char)nargs, .ref = ref,
                  .arg = {a0, a1, a2}, .num = num};
  return m->nxnode++;
}

static int num(bg_model *m, double v) { return push(m, BG_X_NUM, 0, 0, 0, 0, 0, v); }
static int var(bg_model *m, int op, int ref) { return push(m, op, ref, 0, 0, 0, 0, 0); }
static int un(bg_model *m, int op, int a) { return push(m, op, 0, 1, a, 0, 0, 0); }
static int bin(bg_model *m, int op, int a, int b) { return push(m, op, 0, 2, a, b, 0, 0); }
static int call(bg_model *m, int fn, int nargs, int a0, int a1, int a2) {
  return push(m, BG_X_CALL, fn, nargs, a0, a1, a2, 0);
}
static int st(bg_model *m, int i) { return var(m, BG_X_STATE, i); }

/* ---------------------------------------------------------------- environment */
/* Variable values, and one flat vector with a deliberately scrambled layout. */
typedef struct world {
  double t, param[NVAR], state[NVAR], effort[NVAR], flow[NVAR], store[NVAR];
  int pslot[NVAR], sslot[NVAR], eslot[NVAR], fslot[NVAR], qslot[NVAR];
  double vars[1 + 5 * NVAR];
} world;

static void world_init(world *w, const bg_model *m) {
  w->t = 0.25;
  for (int i = 0; i < NVAR; i++) {
    w->param[i] = m->param_value[i];
    w->state[i] = 1.5 - 0.75 * i;
    w->effort[i] = 10 + i;
    w->flow[i] = -20 - i;
    w->store[i] = 100 + i;
    /* time last, kinds interleaved, to catch slot mix-ups */
    w->pslot[i] = 5 * i, w->sslot[i] = 5 * i + 1, w->eslot[i] = 5 * i + 2;
    w->fslot[i] = 5 * i + 3, w->qslot[i] = 5 * i + 4;
  }
}

static const double *world_vars(world *w) {
  w->vars[5 * NVAR] = w->t;
  for (int i = 0; i < NVAR; i++) {
    w->vars[w->pslot[i]] = w->param[i], w->vars[w->sslot[i]] = w->state[i];
    w->vars[w->eslot[i]] = w->effort[i], w->vars[w->fslot[i]] = w->flow[i];
    w->vars[w->qslot[i]] = w->store[i];
  }
  return w->vars;
}

static bg_slotmap world_map(const world *w, int with_params) {
  return (bg_slotmap){.time_slot = 5 * NVAR, .param_slot = with_params ? w->pslot : NULL,
                      .state_slot = w->sslot, .effort_slot = w->eslot,
                      .flow_slot = w->fslot, .store_slot = w->qslot};
}

static double tree(const bg_model *m, int root, const world *w) {
  bg_xenv env = {w->t, w->param, w->state, w->effort, w->flow, w->store};
  return bg_xeval(m, root, &env);
}

static double vm(const bg_model *m, int root, world *w, int with_params) {
  bg_slotmap map = world_map(w, with_params);
  bg_prog *p = bg_prog_compile(m, &root, 1, &map);
  double out = -12345;
  bg_prog_eval(p, world_vars(w), &out);
  bg_prog_free(p);
  return out;
}

static int same_bits(double a, double b) {
  return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

/* Both evaluators (the VM with params as variables and folded) agree bit for
 * bit and give `want`. */
#define CHECK(m, root, w, want, tol)                                           \
  do {                                                                         \
    double t_ = tree(m, root, w);                                              \
    double v1_ = vm(m, root, w, 1), v0_ = vm(m, root, w, 0);                   \
    BG_T_REPORT(same_bits(t_, v1_) && same_bits(t_, v0_),                      \
                "%s: tree %.17g vm %.17g / %.17g", #root, t_, v1_, v0_);       \
    double want_ = (want);                                                     \
    if (isnan(want_)) OK(isnan(t_));                                           \
    else if (isinf(want_)) OK(t_ == want_);                                    \
    else DBL_NEAR(t_, want_, tol);                                             \
  } while (0)

/* ---------------------------------------------------------------- operators */
static void test_operators(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  double x = w.state[0], y = w.state[3]; /* 1.5, -0.75 */
  int X = st(m, 0), Y = st(m, 3);
  CHECK(m, bin(m, BG_X_ADD, X, Y), &w, x + y, 0);
  CHECK(m, bin(m, BG_X_SUB, X, Y), &w, x - y, 0);
  CHECK(m, bin(m, BG_X_MUL, X, Y), &w, x * y, 0);
  CHECK(m, bin(m, BG_X_DIV, X, Y), &w, x / y, 0);
  CHECK(m, bin(m, BG_X_POW, X, num(m, 3)), &w, x * x * x, 1e-15);
  CHECK(m, bin(m, BG_X_POW, Y, num(m, 0.5)), &w, NAN, 0);
  CHECK(m, bin(m, BG_X_LT, X, Y), &w, 0, 0);
  CHECK(m, bin(m, BG_X_LE, Y, Y), &w, 1, 0);
  CHECK(m, bin(m, BG_X_GT, X, Y), &w, 1, 0);
  CHECK(m, bin(m, BG_X_GE, Y, X), &w, 0, 0);
  CHECK(m, bin(m, BG_X_EQ, X, X), &w, 1, 0);
  CHECK(m, bin(m, BG_X_NE, X, X), &w, 0, 0);
  CHECK(m, bin(m, BG_X_AND, X, num(m, 0)), &w, 0, 0);
  CHECK(m, bin(m, BG_X_AND, X, Y), &w, 1, 0);
  CHECK(m, bin(m, BG_X_OR, num(m, 0), num(m, 0)), &w, 0, 0);
  CHECK(m, bin(m, BG_X_OR, num(m, 0), Y), &w, 1, 0);
  CHECK(m, un(m, BG_X_NEG, X), &w, -x, 0);
  CHECK(m, un(m, BG_X_NOT, X), &w, 0, 0);
  CHECK(m, un(m, BG_X_NOT, num(m, 0)), &w, 1, 0);
  CHECK(m, un(m, BG_X_NOT, bin(m, BG_X_SUB, X, X)), &w, 1, 0);
  /* every operand combination of the arithmetic opcodes: R, V and K */
  int ops[4] = {BG_X_ADD, BG_X_SUB, BG_X_MUL, BG_X_DIV};
  for (int o = 0; o < 4; o++) {
    int leaves[3] = {bin(m, BG_X_MUL, X, Y), st(m, 4), num(m, 3.25)};
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        int e = bin(m, ops[o], leaves[i], leaves[j]);
        double tv = tree(m, e, &w);
        OK(same_bits(tv, vm(m, e, &w, 1)));
      }
  }
  /* fused x + c*y and x - c*y in all operand kinds, including c*y + x */
  int c3y = bin(m, BG_X_MUL, num(m, 3), Y), yc3 = bin(m, BG_X_MUL, Y, num(m, 3));
  int xy = bin(m, BG_X_MUL, X, Y), cxy = bin(m, BG_X_MUL, num(m, 0.1), bin(m, BG_X_MUL, X, Y));
  CHECK(m, bin(m, BG_X_ADD, X, c3y), &w, x + 3 * y, 0);
  CHECK(m, bin(m, BG_X_ADD, yc3, X), &w, x + 3 * y, 0);
  CHECK(m, bin(m, BG_X_SUB, X, c3y), &w, x - 3 * y, 0);
  CHECK(m, bin(m, BG_X_SUB, xy, cxy), &w, x * y - 0.1 * (x * y), 0);
  CHECK(m, bin(m, BG_X_ADD, xy, cxy), &w, x * y + 0.1 * (x * y), 0);
  CHECK(m, bin(m, BG_X_SUB, c3y, X), &w, 3 * y - x, 0);
  model_free(m);
}

/* ---------------------------------------------------------------- functions */
typedef struct fcase {
  int fn, nargs;
  double a[3], want;
} fcase;

static const fcase fcases[] = {
    {BG_FN_ABS, 1, {-3}, 3},          {BG_FN_SIGN, 1, {-2}, -1},
    {BG_FN_SIGN, 1, {0}, 0},          {BG_FN_SIGN, 1, {1e-300}, 1},
    {BG_FN_SQRT, 1, {2}, 1.4142135623730951}, {BG_FN_EXP, 1, {1}, 2.718281828459045},
    {BG_FN_LOG, 1, {2.718281828459045}, 1},   {BG_FN_LOG, 1, {0}, -INFINITY},
    {BG_FN_LOG10, 1, {1000}, 3},      {BG_FN_SIN, 1, {PI / 6}, 0.5},
    {BG_FN_COS, 1, {0}, 1},           {BG_FN_TAN, 1, {PI / 4}, 1},
    {BG_FN_ASIN, 1, {1}, PI / 2},   {BG_FN_ACOS, 1, {1}, 0},
    {BG_FN_ACOS, 1, {2}, NAN},        {BG_FN_ATAN, 1, {1}, PI / 4},
    {BG_FN_ATAN2, 2, {1, -1}, 3 * PI / 4}, {BG_FN_SINH, 1, {1}, 1.1752011936438014},
    {BG_FN_COSH, 1, {0}, 1},          {BG_FN_TANH, 1, {0}, 0},
    {BG_FN_MIN, 2, {2, -1}, -1},      {BG_FN_MAX, 2, {2, -1}, 2},
    {BG_FN_POW, 2, {2, 10}, 1024},    {BG_FN_FLOOR, 1, {-1.5}, -2},
    {BG_FN_CEIL, 1, {-1.5}, -1},      {BG_FN_IF, 3, {1, 2, 3}, 2},
    {BG_FN_IF, 3, {0, 2, 3}, 3},      {BG_FN_IF, 3, {NAN, 2, 3}, 2},
    {BG_FN_STEP, 1, {0}, 1},          {BG_FN_STEP, 1, {-1e-300}, 0},
    {BG_FN_STEP, 1, {5}, 1},          {BG_FN_RAMP, 1, {-1}, 0},
    {BG_FN_RAMP, 1, {0}, 0},          {BG_FN_RAMP, 1, {2.5}, 2.5},
    {BG_FN_PULSE, 2, {0, 1}, 1},      {BG_FN_PULSE, 2, {0.999, 1}, 1},
    {BG_FN_PULSE, 2, {1, 1}, 0},      {BG_FN_PULSE, 2, {-0.001, 1}, 0},
    {BG_FN_SAT, 3, {5, 0, 1}, 1},     {BG_FN_SAT, 3, {-5, 0, 1}, 0},
    {BG_FN_SAT, 3, {0.5, 0, 1}, 0.5}, {BG_FN_SAT, 3, {0, 0, 1}, 0},
    {BG_FN_SAT, 3, {1, 0, 1}, 1},
    /* memory without its memory: the value it starts a run with */
    {BG_FN_HYST, 3, {12, 8, 12}, 1},  {BG_FN_HYST, 3, {10, 8, 12}, 0},
    {BG_FN_HYST, 3, {7, 8, 12}, 0},   {BG_FN_STICK, 3, {0, -1.5, 2}, 1},
    {BG_FN_STICK, 3, {0, 2, 2}, 1},   {BG_FN_STICK, 3, {0, 2.5, 2}, 0},
    {BG_FN_STICK, 3, {1e-9, 0, 2}, 0},
};

/* Each case with its arguments read from variables, from constants (folded)
 * and mixed (constants loaded into argument registers). */
static void test_functions(void) {
  for (size_t i = 0; i < sizeof fcases / sizeof fcases[0]; i++) {
    const fcase *f = &fcases[i];
    bg_model *m = model_new();
    world w;
    world_init(&w, m);
    int va[3] = {0, 0, 0}, ka[3] = {0, 0, 0}, mix[3] = {0, 0, 0};
    for (int j = 0; j < f->nargs; j++) {
      w.state[j] = f->a[j];
      va[j] = st(m, j);
      ka[j] = num(m, f->a[j]);
      mix[j] = j % 2 ? ka[j] : va[j];
    }
    int e1 = call(m, f->fn, f->nargs, va[0], va[1], va[2]);
    int e2 = call(m, f->fn, f->nargs, ka[0], ka[1], ka[2]);
    int e3 = call(m, f->fn, f->nargs, mix[0], mix[1], mix[2]);
    CHECK(m, e1, &w, f->want, 1e-15);
    CHECK(m, e2, &w, f->want, 1e-15);
    CHECK(m, e3, &w, f->want, 1e-15);
    model_free(m);
  }
}

/* ---------------------------------------------------------------- if, tables, inputs */
static void test_if(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  int X = st(m, 0), Z = st(m, 2), C = st(m, 5);
  /* x + if(c, z, 3*y): the else branch ends in c*y; no fusion across the join */
  int e = bin(m, BG_X_ADD, X, call(m, BG_FN_IF, 3, C, Z, bin(m, BG_X_MUL, num(m, 3), st(m, 1))));
  int nested = call(m, BG_FN_IF, 3, C, call(m, BG_FN_IF, 3, X, num(m, 7), Z), bin(m, BG_X_MUL, X, num(m, 2)));
  int inmul = bin(m, BG_X_ADD, X, bin(m, BG_X_MUL, num(m, 2), call(m, BG_FN_IF, 3, C, Z, X)));
  double vals[3] = {0, 1, NAN};
  for (int i = 0; i < 3; i++) {
    w.state[5] = vals[i];
    int taken = vals[i] != 0;
    CHECK(m, e, &w, w.state[0] + (taken ? w.state[2] : 3 * w.state[1]), 0);
    CHECK(m, nested, &w, taken ? 7 : 2 * w.state[0], 0);
    CHECK(m, inmul, &w, w.state[0] + 2 * (taken ? w.state[2] : w.state[0]), 0);
  }
  /* a constant condition compiles only the branch taken */
  int k = call(m, BG_FN_IF, 3, num(m, 1), X, bin(m, BG_X_DIV, X, Z));
  CHECK(m, k, &w, w.state[0], 0);
  bg_slotmap map = world_map(&w, 1);
  bg_prog *p = bg_prog_compile(m, &k, 1, &map);
  INT_EQ(bg_prog_ninstr(p), 1);
  bg_prog_free(p);
  model_free(m);
}

static void test_tables(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  static double tx[] = {0, 1, 3, 5}, ty[] = {0, 10, 30, -5};
  m->ntable = 2;
  m->table_adr = calloc(2, sizeof(int));
  m->table_n = calloc(2, sizeof(int));
  m->table_x = malloc(sizeof tx);
  m->table_y = malloc(sizeof ty);
  memcpy(m->table_x, tx, sizeof tx);
  memcpy(m->table_y, ty, sizeof ty);
  m->table_n[0] = 4;
  m->table_adr[1] = 4; /* table 1 is empty */
  double xs[] = {-1, 0, 0.5, 1, 2, 3, 4, 5, 7};
  double want[] = {0, 0, 5, 10, 20, 30, 12.5, -5, -5};
  for (int i = 0; i < 9; i++) {
    w.state[0] = xs[i];
    CHECK(m, push(m, BG_X_TABLE, 0, 1, st(m, 0), 0, 0, 0), &w, want[i], 1e-14);
    CHECK(m, push(m, BG_X_TABLE, 0, 1, num(m, xs[i]), 0, 0, 0), &w, want[i], 1e-14);
  }
  CHECK(m, push(m, BG_X_TABLE, 1, 1, st(m, 0), 0, 0, 0), &w, NAN, 0);
  model_free(m);
}

static void test_inputs(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  /* u = 2*t + a; v = u*u (an input using an earlier one) */
  int T = var(m, BG_X_TIME, 0);
  m->input_expr[0] = bin(m, BG_X_ADD, bin(m, BG_X_MUL, num(m, 2), T), var(m, BG_X_PARAM, 0));
  int U = var(m, BG_X_INPUT, 0);
  m->input_expr[1] = bin(m, BG_X_MUL, U, U);
  int e = bin(m, BG_X_SUB, var(m, BG_X_INPUT, 1), num(m, 1));
  double u = 2 * w.t + w.param[0];
  CHECK(m, e, &w, u * u - 1, 0);
  model_free(m);
}

/* ---------------------------------------------------------------- slots and folding */
static void test_slots(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  for (int i = 0; i < NVAR; i++) {
    CHECK(m, var(m, BG_X_PARAM, i), &w, 0.5 + i, 0);
    CHECK(m, var(m, BG_X_STATE, i), &w, 1.5 - 0.75 * i, 0);
    CHECK(m, var(m, BG_X_EFFORT, i), &w, 10 + i, 0);
    CHECK(m, var(m, BG_X_FLOW, i), &w, -20 - i, 0);
    CHECK(m, var(m, BG_X_STORE, i), &w, 100 + i, 0);
  }
  CHECK(m, var(m, BG_X_TIME, 0), &w, 0.25, 0);
  /* a param given in the vector is read from it, not from the model */
  int pa = var(m, BG_X_PARAM, 2);
  w.param[2] = 42;
  DBL_NEAR(vm(m, pa, &w, 1), 42, 0);
  DBL_NEAR(vm(m, pa, &w, 0), 2.5, 0);
  model_free(m);
}

static int ninstr_of(const bg_model *m, int root, world *w, int with_params) {
  bg_slotmap map = world_map(w, with_params);
  bg_prog *p = bg_prog_compile(m, &root, 1, &map);
  int n = bg_prog_ninstr(p);
  bg_prog_free(p);
  return n;
}

static void test_folding(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  int five = bin(m, BG_X_ADD, num(m, 2), num(m, 3));
  int k = bin(m, BG_X_MUL, call(m, BG_FN_SIN, 1, bin(m, BG_X_DIV, num(m, PI), num(m, 2)), 0, 0),
              bin(m, BG_X_POW, five, var(m, BG_X_PARAM, 1)));
  INT_EQ(ninstr_of(m, k, &w, 0), 1); /* OUT_K */
  INT_EQ(ninstr_of(m, k, &w, 1), 2); /* pow(5, b), then out */
  CHECK(m, k, &w, pow(5, 1.5), 1e-12);
  int kx = bin(m, BG_X_MUL, st(m, 0), five);
  INT_EQ(ninstr_of(m, kx, &w, 0), 2);
  CHECK(m, kx, &w, 7.5, 0);
  INT_EQ(ninstr_of(m, st(m, 1), &w, 0), 1);
  /* no slot map at all: params fold, the program needs no variables */
  bg_prog *p = bg_prog_compile(m, &k, 1, NULL);
  double out = 0;
  bg_prog_eval(p, NULL, &out);
  OK(same_bits(out, tree(m, k, &w)));
  INT_EQ(bg_prog_ninstr(p), 1);
  bg_prog_free(p);
  model_free(m);
}

/* sum c_i*x_i over N states: one instruction per term (the first product,
 * a CHAIN header and its TERMs) plus the output. */
static void test_linear_many_roots(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  int sum = bin(m, BG_X_MUL, num(m, 0.5), st(m, 0));
  for (int i = 1; i < NVAR; i++)
    sum = bin(m, BG_X_ADD, sum, bin(m, BG_X_MUL, num(m, 0.5 + i), st(m, i)));
  INT_EQ(ninstr_of(m, sum, &w, 0), NVAR + 2);
  CHECK(m, sum, &w, tree(m, sum, &w), 0);
  enum { NR = 40 };
  int roots[NR];
  for (int k = 0; k < NR; k++) {
    int a = bin(m, BG_X_MUL, var(m, BG_X_FLOW, k % NVAR), num(m, k));
    roots[k] = k % 3 == 0 ? bin(m, BG_X_SUB, var(m, BG_X_EFFORT, k % NVAR), a)
               : k % 3 == 1 ? num(m, k) : call(m, BG_FN_COS, 1, a, 0, 0);
  }
  bg_slotmap map = world_map(&w, 1);
  bg_prog *p = bg_prog_compile(m, roots, NR, &map);
  double out[NR];
  bg_prog_eval(p, world_vars(&w), out);
  int agree = 1;
  for (int k = 0; k < NR; k++) agree &= same_bits(out[k], tree(m, roots[k], &w));
  OK(agree);
  w.flow[3] = 7; /* a second run on new values reuses the program */
  bg_prog_eval(p, world_vars(&w), out);
  DBL_NEAR(out[3], w.effort[3] - 7 * 3, 0);
  bg_prog_free(p);
  model_free(m);
}

/* Sums with subtraction, mixed operand kinds and jumps into the chain. */
static void test_chains(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  int coef[NVAR];
  for (int i = 0; i < NVAR; i++) coef[i] = num(m, 0.3 * i - 1.1);
  int sum = st(m, 0); /* x - c1*y1 + c2*y2 - c3*y3 ... */
  for (int i = 1; i < NVAR; i++)
    sum = bin(m, i % 2 ? BG_X_SUB : BG_X_ADD, sum, bin(m, BG_X_MUL, coef[i], st(m, i)));
  CHECK(m, sum, &w, tree(m, sum, &w), 0);
  /* starting after an if (its join lands on the chain header) */
  int s2 = call(m, BG_FN_IF, 3, st(m, 5), st(m, 1), bin(m, BG_X_MUL, num(m, 2), st(m, 2)));
  for (int i = 1; i < NVAR; i++)
    s2 = bin(m, BG_X_ADD, s2, bin(m, BG_X_MUL, st(m, i), coef[i]));
  for (int k = 0; k < 2; k++) {
    w.state[5] = k;
    CHECK(m, s2, &w, tree(m, s2, &w), 0);
  }
  /* a product of variables interrupts the chain; a second chain follows */
  int s3 = bin(m, BG_X_MUL, coef[1], st(m, 1));
  for (int i = 2; i < NVAR; i++) {
    int term = bin(m, BG_X_MUL, coef[i], i == 4 ? bin(m, BG_X_MUL, st(m, i), st(m, 0)) : st(m, i));
    s3 = bin(m, BG_X_SUB, s3, term);
  }
  CHECK(m, s3, &w, tree(m, s3, &w), 0);
  /* a chain in each branch of an if, and chains nested as right operands */
  int in = bin(m, BG_X_ADD, bin(m, BG_X_MUL, coef[2], st(m, 2)), bin(m, BG_X_MUL, coef[3], st(m, 3)));
  in = bin(m, BG_X_ADD, in, bin(m, BG_X_MUL, coef[4], st(m, 4)));
  int s4 = call(m, BG_FN_IF, 3, st(m, 5), in, bin(m, BG_X_SUB, in, bin(m, BG_X_MUL, coef[1], st(m, 1))));
  s4 = bin(m, BG_X_MUL, s4, bin(m, BG_X_SUB, st(m, 6), in));
  for (int k = 0; k < 2; k++) {
    w.state[5] = k;
    CHECK(m, s4, &w, tree(m, s4, &w), 0);
  }
  model_free(m);
}

/* A deep left-leaning chain and a deep right-leaning one (register pressure). */
static void test_deep(void) {
  bg_model *m = model_new();
  world w;
  world_init(&w, m);
  int l = st(m, 0), r = st(m, 0);
  for (int i = 0; i < 300; i++) {
    l = bin(m, BG_X_SUB, l, bin(m, BG_X_DIV, st(m, i % NVAR), num(m, i + 1)));
    r = bin(m, BG_X_SUB, bin(m, BG_X_DIV, st(m, i % NVAR), num(m, i + 1)), r);
  }
  CHECK(m, l, &w, tree(m, l, &w), 0);
  CHECK(m, r, &w, tree(m, r, &w), 0);
  /* a left-deep sum deeper than the compiler's recursion guard compiles
   * (the tree walker would recurse that deep, so compare to a loop) */
  int s = st(m, 0);
  double want = w.state[0];
  for (int i = 1; i < 12000; i++) {
    s = bin(m, BG_X_ADD, s, bin(m, BG_X_MUL, num(m, i), st(m, i % NVAR)));
    want = want + i * w.state[i % NVAR];
  }
  DBL_NEAR(vm(m, s, &w, 1), want, 0);
  bg_strbuf b = {0};
  bg_xprint(m, s, &b); /* printing walks the same spine without recursing */
  OK(strncmp(bg_sb_str(&b), "x + 1*y + 2*z + 3*w + 4*s4", 26) == 0);
  OK(strstr(bg_sb_str(&b), " + 11999*s7") != NULL && b.len > 12000 * 6);
  bg_sb_free(&b);
  model_free(m);
}

/* ---------------------------------------------------------------- printing */
static void print_is(const bg_model *m, int root, const char *want) {
  bg_strbuf b = {0};
  bg_xprint(m, root, &b);
  STR_EQ(bg_sb_str(&b), want);
  bg_sb_free(&b);
}

static void test_print(void) {
  bg_model *m = model_new();
  int a = var(m, BG_X_PARAM, 0), b = var(m, BG_X_PARAM, 1), c = var(m, BG_X_PARAM, 2);
  int x = st(m, 0);
  print_is(m, bin(m, BG_X_MUL, a, bin(m, BG_X_ADD, b, c)), "a*(b + c)");
  print_is(m, bin(m, BG_X_ADD, bin(m, BG_X_MUL, a, b), c), "a*b + c");
  print_is(m, un(m, BG_X_NEG, bin(m, BG_X_POW, x, num(m, 2))), "-x^2");
  print_is(m, bin(m, BG_X_POW, un(m, BG_X_NEG, x), num(m, 2)), "(-x)^2");
  print_is(m, un(m, BG_X_NEG, bin(m, BG_X_MUL, a, b)), "-(a*b)");
  print_is(m, bin(m, BG_X_MUL, un(m, BG_X_NEG, a), b), "-a*b");
  print_is(m, un(m, BG_X_NEG, un(m, BG_X_NEG, a)), "-(-a)");
  print_is(m, bin(m, BG_X_SUB, bin(m, BG_X_SUB, a, b), c), "a - b - c");
  print_is(m, bin(m, BG_X_SUB, a, bin(m, BG_X_SUB, b, c)), "a - (b - c)");
  print_is(m, bin(m, BG_X_ADD, a, bin(m, BG_X_ADD, b, c)), "a + (b + c)");
  print_is(m, bin(m, BG_X_DIV, a, bin(m, BG_X_MUL, b, c)), "a/(b*c)");
  print_is(m, bin(m, BG_X_SUB, a, un(m, BG_X_NEG, b)), "a - (-b)");
  print_is(m, bin(m, BG_X_SUB, a, num(m, -2)), "a - (-2)");
  print_is(m, bin(m, BG_X_POW, num(m, 2), bin(m, BG_X_POW, num(m, 3), num(m, 2))), "2^3^2");
  print_is(m, bin(m, BG_X_POW, bin(m, BG_X_POW, num(m, 2), num(m, 3)), num(m, 2)), "(2^3)^2");
  print_is(m, bin(m, BG_X_POW, x, un(m, BG_X_NEG, a)), "x^(-a)");
  print_is(m, bin(m, BG_X_POW, num(m, -2), num(m, 2)), "(-2)^2");
  print_is(m, call(m, BG_FN_SIN, 1, bin(m, BG_X_ADD, x, a), 0, 0), "sin(x + a)");
  print_is(m, call(m, BG_FN_ATAN2, 2, x, un(m, BG_X_NEG, a), 0), "atan2(x, -a)");
  print_is(m, call(m, BG_FN_IF, 3, bin(m, BG_X_LT, x, a), num(m, 1), num(m, 0.1)),
           "if(x < a, 1, 0.1)");
  print_is(m, bin(m, BG_X_LT, bin(m, BG_X_LT, a, b), c), "(a < b) < c");
  print_is(m, bin(m, BG_X_EQ, bin(m, BG_X_ADD, a, b), c), "a + b == c");
  print_is(m, bin(m, BG_X_OR, bin(m, BG_X_AND, a, b), un(m, BG_X_NOT, c)), "(a && b) || !c");
  print_is(m, bin(m, BG_X_AND, bin(m, BG_X_AND, a, b), c), "a && b && c");
  print_is(m, bin(m, BG_X_MUL, bin(m, BG_X_DIV, bin(m, BG_X_MUL, a, b), c), x), "a*b/c*x");
  print_is(m, bin(m, BG_X_SUB, bin(m, BG_X_MUL, bin(m, BG_X_ADD, a, b), c), x), "(a + b)*c - x");
  print_is(m, bin(m, BG_X_POW, bin(m, BG_X_POW, bin(m, BG_X_POW, a, b), c), x), "((a^b)^c)^x");
  print_is(m, un(m, BG_X_NOT, bin(m, BG_X_GT, a, b)), "!(a > b)");
  print_is(m, bin(m, BG_X_ADD, var(m, BG_X_EFFORT, 2), var(m, BG_X_FLOW, 0)), "e7 + f1");
  print_is(m, bin(m, BG_X_SUB, var(m, BG_X_STORE, 0), var(m, BG_X_STORE, 1)), "C1.q - L1.p");
  print_is(m, bin(m, BG_X_MUL, var(m, BG_X_INPUT, 1), var(m, BG_X_TIME, 0)), "v*t");
  print_is(m, push(m, BG_X_TABLE, 3, 1, x, 0, 0, 0), "table(x, #3)");
  print_is(m, num(m, 0.1), "0.1");
  print_is(m, num(m, 1.0 / 3), "0.3333333333333333");
  print_is(m, num(m, 1e-20), "1e-20");
  print_is(m, num(m, 250), "250");
  model_free(m);
}

int main(void) {
  test_operators();
  test_functions();
  test_if();
  test_tables();
  test_inputs();
  test_slots();
  test_folding();
  test_linear_many_roots();
  test_chains();
  test_deep();
  test_print();
  return bg_t_done();
}
