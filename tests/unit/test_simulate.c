/* Simulation (issue 5): analytic comparisons of EXAMPLES.md, the slider
 * crank's DAE against its Lagrange equation integrated here with CVODE,
 * consistent initial values of the hydraulic bridge, refusals with their
 * reasons, a failing run with partial results, the solver choice, CSV. */
#include "harness.h"

#include <stdlib.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "causality.h"
#include "eqsys.h"
#include "expr.h"
#include "fileio.h"
#include "parse.h"
#include "paths.h"
#include "simulate.h"

typedef struct fx {
  bg_model *m;
  bg_analysis a;
  bg_eqsys *s;
  bg_diags dg;
  char *src;
  bg_simresult r;
  int rc;
} fx;

/* Replaces the first `from` in f->src by `to` (model variants). */
static int fx_edit(fx *f, const char *from, const char *to) {
  char *p = strstr(f->src, from);
  if (!p) { fprintf(stderr, "no '%s' in the model\n", from); return -1; }
  size_t nf = strlen(from), nt = strlen(to), len = strlen(f->src);
  char *s = bg_xmalloc(len - nf + nt + 1);
  memcpy(s, f->src, (size_t)(p - f->src));
  memcpy(s + (p - f->src), to, nt);
  strcpy(s + (p - f->src) + nt, p + nf);
  free(f->src);
  f->src = s;
  return 0;
}

/* Parses f->src, compiles with an optional --set, assigns causality,
 * analyses, builds the equations (which may fail: s NULL) and simulates. */
static int fx_run(fx *f, const char *path, int method, const char *set_name, double set_value,
                  const bg_sim_opts *o) {
  size_t len = strlen(f->src);
  bg_diags_init(&f->dg, path, f->src, len);
  bg_ast *ast = bg_parse_string(path, f->src, len, &f->dg);
  bg_param_override ov = {set_name, set_value};
  if (ast && !f->dg.nerrors) f->m = bg_model_compile(ast, &ov, set_name ? 1 : 0, &f->dg);
  if (ast) bg_ast_free(ast);
  if (!f->m) { bg_diags_print(&f->dg, stderr); return -1; }
  bg_analysis_init(&f->a, f->m);
  bg_causality_assign(f->m, method, &f->a, &f->dg);
  bg_analysis_run(f->m, &f->a, NULL);
  if (f->a.complete) f->s = bg_eqsys_build(f->m, &f->a, &f->dg);
  f->rc = bg_simulate(f->m, &f->a, f->s, o, &f->r);
  if (f->r.message) fprintf(stderr, "%s: %s\n", path, f->r.message);
  return 0;
}

static int fx_load(fx *f, const char *name, int method, const char *set_name, double set_value,
                   const char *from, const char *to, const bg_sim_opts *o) {
  char path[512];
  size_t len;
  snprintf(path, sizeof path, "%s/examples/%s.bg", BG_SOURCE_DIR, name);
  memset(f, 0, sizeof *f);
  f->src = bg_read_file(path, &len);
  if (!f->src) { fprintf(stderr, "cannot read %s\n", path); return -1; }
  if (from && fx_edit(f, from, to)) return -1;
  return fx_run(f, path, method, set_name, set_value, o);
}

static int fx_text(fx *f, const char *text, const bg_sim_opts *o) {
  memset(f, 0, sizeof *f);
  f->src = strdup(text);
  return fx_run(f, "inline.bg", BG_METHOD_SCAP, NULL, 0, o);
}

static void fx_free(fx *f) {
  bg_simresult_free(&f->r);
  if (f->s) bg_eqsys_free(f->s);
  bg_analysis_free(&f->a);
  if (f->m) bg_model_free(f->m);
  bg_diags_free(&f->dg);
  free(f->src);
}

static int col(const bg_simresult *r, const char *name) {
  for (int k = 0; k < r->nout; k++)
    if (r->names[k] && !strcmp(r->names[k], name)) return k;
  return -1;
}

static double val(const bg_simresult *r, int i, int k) { return r->values[(size_t)i * r->nout + k]; }

static int has(const char *s, const char *sub) { return s && strstr(s, sub) != NULL; }

static const bg_sim_opts TIGHT = {NULL, 0, 1e-10, 1e-10};

/* Largest |column(t) - exact(t)| over the run. */
static double max_err(const bg_simresult *r, int k, double (*exact)(double)) {
  double e = 0;
  for (int i = 0; i < r->nrows; i++) e = fmax(e, fabs(val(r, i, k) - exact(r->t[i])));
  return r->nrows && k >= 0 ? e : INFINITY;
}

/* ------------------------------------------------------------------ rlc */
/* Series RLC, step of V at t = 0, underdamped (alpha = R/2L = 5000 <
 * omega0 = 1/sqrt(LC) = 31623): vC = V (1 - e^(-alpha t) (cos wd t +
 * alpha/wd sin wd t)), wd = sqrt(omega0^2 - alpha^2). */
static double rlc_vc(double t) {
  const double V = 1, R = 10, L = 1e-3, C = 1e-6;
  double a = R / (2 * L), w0 = 1 / sqrt(L * C), wd = sqrt(w0 * w0 - a * a);
  return V * (1 - exp(-a * t) * (cos(wd * t) + a / wd * sin(wd * t)));
}

static void test_rlc(void) {
  fx f;
  if (fx_load(&f, "rlc", BG_METHOD_SCAP, NULL, 0, NULL, NULL, &TIGHT)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  INT_EQ(f.r.nrows, 2001);
  INT_EQ(f.r.partial, 0);
  if (f.r.nrows) DBL_NEAR(f.r.t[f.r.nrows - 1], 2e-3, 0);
  OK(max_err(&f.r, col(&f.r, "C1.e"), rlc_vc) <= 1e-6);
  STR_EQ(f.r.solver_used, "cvode_adams"); /* time scales 1e-4 and 3e-5 s over 2 ms */
  OK(has(f.r.solver_reason, "auto"));
  fx_free(&f);
}

static void test_rlc_forced(void) {
  fx f;
  bg_sim_opts o = {"cvode_bdf", 0, 1e-10, 1e-10};
  if (fx_load(&f, "rlc", BG_METHOD_SCAP, NULL, 0, NULL, NULL, &o)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  STR_EQ(f.r.solver_used, "cvode_bdf");
  OK(has(f.r.solver_reason, "forced"));
  OK(max_err(&f.r, col(&f.r, "C1.e"), rlc_vc) <= 1e-6);
  fx_free(&f);
  o.solver = "ida"; /* IDA on an ODE: residual yp - f, Jacobian cj I - df/dy */
  if (fx_load(&f, "rlc", BG_METHOD_SCAP, NULL, 0, NULL, NULL, &o)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  STR_EQ(f.r.solver_used, "ida");
  OK(max_err(&f.r, col(&f.r, "C1.e"), rlc_vc) <= 1e-6);
  fx_free(&f);
}

/* ------------------------------------------------------------------ bond_loop, delta, modulated source */
static double bl_cs(double t) { return 2 * sin(t); }
static double bl_is(double t) { return 2 * (1 - cos(t)); }

static void test_bond_loop(void) {
  fx f;
  if (fx_load(&f, "bond_loop", BG_METHOD_SCAP, NULL, 0, NULL, NULL, &TIGHT)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  INT_EQ(f.r.nrows, 1001);
  OK(max_err(&f.r, col(&f.r, "Cs.e"), bl_cs) <= 1e-6);
  OK(max_err(&f.r, col(&f.r, "Is.f"), bl_is) <= 1e-6);
  fx_free(&f);
}

static double delta_il1(double t) { return 0.5 * (1 - exp(-t / 3)); }

static void test_delta_vandijk(void) {
  fx f;
  if (fx_load(&f, "delta", BG_METHOD_VANDIJK, NULL, 0, NULL, NULL, &TIGHT)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  OK(max_err(&f.r, col(&f.r, "L1.f"), delta_il1) <= 1e-6);
  fx_free(&f);
}

static double ms_cc(double t) { return 0.5 * (1 - exp(-2 * t)); }

static void test_modulated_source(void) {
  fx f;
  if (fx_load(&f, "modulated_source", BG_METHOD_SCAP, NULL, 0, NULL, NULL, &TIGHT)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  OK(max_err(&f.r, col(&f.r, "Cc.e"), ms_cc) <= 1e-6);
  fx_free(&f);
}

/* ------------------------------------------------------------------ slider crank */
/* Equation 4.53 for the slider crank (one coordinate phi):
 * (J + m T^2) phi'' + m T T' phi' + r T^2 phi' = M + T F, T' = dT/dphi phi',
 * with T(phi) the modulus of the model's MTF. */
typedef struct crank { double J, m, rc, L, b, M, F; } crank;

static double crank_T(const crank *c, double phi) {
  double s = sin(phi), w = sqrt(c->L * c->L - c->rc * c->rc * s * s);
  return c->rc * (c->rc * cos(phi) + w) * s / w;
}

static int crank_rhs(sunrealtype t, N_Vector y, N_Vector yd, void *ud) {
  const crank *c = ud;
  double *x = N_VGetArrayPointer(y), *d = N_VGetArrayPointer(yd);
  double phi = x[0], w = x[1], h = 1e-6;
  double T = crank_T(c, phi), dT = (crank_T(c, phi + h) - crank_T(c, phi - h)) / (2 * h);
  (void)t;
  d[0] = w;
  d[1] = (c->M + T * c->F - c->m * T * dT * w * w - c->b * T * T * w) / (c->J + c->m * T * T);
  return 0;
}

/* phi at the given times, from the Lagrange equation with CVODE. */
static int crank_lagrange(const crank *c, const double *t, int n, double *phi) {
  SUNContext ctx;
  if (SUNContext_Create(NULL, &ctx)) return -1;
  N_Vector y = N_VNew_Serial(2, ctx);
  N_VConst(0.0, y);
  void *mem = CVodeCreate(CV_BDF, ctx);
  SUNMatrix A = SUNDenseMatrix(2, 2, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  int f = CVodeInit(mem, crank_rhs, t[0], y);
  f |= CVodeSStolerances(mem, 1e-11, 1e-13);
  f |= CVodeSetUserData(mem, (void *)c);
  f |= CVodeSetMaxNumSteps(mem, 100000);
  f |= CVodeSetLinearSolver(mem, LS, A);
  phi[0] = 0;
  for (int i = 1; i < n && f >= 0; i++) {
    double tret;
    f = CVode(mem, t[i], y, &tret, CV_NORMAL);
    phi[i] = N_VGetArrayPointer(y)[0];
  }
  CVodeFree(&mem);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
  return f < 0 ? -1 : 0;
}

static void test_slider_crank(void) {
  fx f;
  const crank c = {0.05, 2, 0.05, 0.2, 5, 1, 0};
  if (fx_load(&f, "slider_crank", BG_METHOD_SCAP, NULL, 0, NULL, NULL, &TIGHT)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  STR_EQ(f.r.solver_used, bg_eqsys_is_ode(f.s) ? f.r.solver_used : "ida");
  int k = col(&f.r, "phi");
  OK(k >= 0 && f.r.nrows > 10);
  if (k >= 0 && f.r.nrows > 10) {
    double *phi = bg_xmalloc((size_t)f.r.nrows * sizeof(double)), big = 0, err = 0;
    INT_EQ(crank_lagrange(&c, f.r.t, f.r.nrows, phi), 0);
    for (int i = 0; i < f.r.nrows; i++) {
      big = fmax(big, fabs(phi[i]));
      err = fmax(err, fabs(val(&f.r, i, k) - phi[i]));
    }
    OK(big > 1); /* the crank turns */
    OK(err <= 1e-4 * big);
    if (!(err <= 1e-4 * big)) fprintf(stderr, "slider_crank: phi error %g of %g\n", err, big);
    free(phi);
  }
  fx_free(&f);
}

/* ------------------------------------------------------------------ hydraulic bridge */
static void test_hydraulic_bridge(void) {
  fx f;
  if (fx_load(&f, "hydraulic_bridge", BG_METHOD_SCAP, NULL, 0, NULL, NULL, NULL)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  INT_EQ(f.r.partial, 0);
  STR_EQ(f.r.solver_used, "ida");
  OK(has(f.r.solver_reason, "DAE"));
  OK(f.r.n > 0 && f.r.y0 && f.r.yp0);
  if (f.s && f.r.y0) {
    int n = bg_eqsys_n(f.s), nx = bg_eqsys_nx(f.s);
    double *res = bg_xmalloc((size_t)n * sizeof(double)), worst = 0, scale = 0;
    INT_EQ(bg_eqsys_residual(f.s, f.m->sim.t0, f.r.y0, f.r.yp0, res), 0);
    for (int i = 0; i < n; i++) scale = fmax(scale, fabs(f.r.y0[i]));
    for (int i = nx; i < n; i++) worst = fmax(worst, fabs(res[i]));
    OK(n > nx);         /* algebraic unknowns exist */
    OK(worst <= 1e-6 * fmax(scale, 1.0));
    /* and the whole residual, derivatives included */
    for (int i = 0; i < nx; i++) OK(fabs(res[i]) <= 1e-6 * fmax(scale, 1.0));
    free(res);
  }
  if (f.r.nrows) DBL_NEAR(f.r.t[f.r.nrows - 1], 0.05, 0);
  fx_free(&f);
}

static void test_bridge_compliance_auto(void) {
  fx f;
  if (fx_load(&f, "bridge_compliance", BG_METHOD_SCAP, NULL, 0, NULL, NULL, NULL)) { OK(0); return; }
  INT_EQ(f.rc, 0);
  OK(f.r.solver_used && strncmp(f.r.solver_used, "cvode_", 6) == 0);
  OK(has(f.r.solver_reason, "auto: time scales"));
  fx_free(&f);
}

/* ------------------------------------------------------------------ refusals */
static void test_refusals(void) {
  fx f;
  if (!fx_load(&f, "loop_class1", BG_METHOD_SCAP, NULL, 0, NULL, NULL, NULL)) {
    INT_EQ(f.rc, 1);
    OK(f.r.solver_used == NULL && f.r.nrows == 0);
    OK(has(f.r.message, "index above 1"));
    OK(has(f.r.message, "Proposition 5.10"));
    OK(has(f.r.message, "causal loop 1"));
    OK(has(f.r.message, "bonds 2, 6, 7, 8") || has(f.r.message, "bonds 2, 8, 7, 6") ||
       has(f.r.message, "Causal loop 1 runs through bonds"));
    OK(has(f.r.message, "--causality vandijk"));
    OK(has(f.r.message, "Section 4.3"));
  } else OK(0);
  fx_free(&f);
  if (!fx_load(&f, "delta", BG_METHOD_SCAP, NULL, 0, NULL, NULL, NULL)) {
    INT_EQ(f.rc, 1);
    OK(has(f.r.message, "causal loop 1 (bonds "));
    OK(has(f.r.message, "gain +1"));
    OK(has(f.r.message, "class 5"));
    OK(has(f.r.message, "--causality vandijk"));
  } else OK(0);
  fx_free(&f);
  if (!fx_load(&f, "bond_loop", BG_METHOD_SCAP, "n", 1, NULL, NULL, NULL)) {
    INT_EQ(f.rc, 1);
    OK(has(f.r.message, "causal loop 1 (bonds 1, 2, 3, 4) has gain +1"));
    OK(has(f.r.message, "singular"));
  } else OK(0);
  fx_free(&f);
  if (!fx_load(&f, "modulated_source", BG_METHOD_SCAP, "k", 2, NULL, NULL, NULL)) {
    INT_EQ(f.rc, 1);
    OK(has(f.r.message, "gain k/R20 = 1"));
    OK(has(f.r.message, "internal modulation of U"));
    OK(has(f.r.message, "Equation 4.45"));
  } else OK(0);
  fx_free(&f);
  /* a CVODE method forced on a DAE */
  bg_sim_opts o = {"cvode_bdf", 0, 0, 0};
  if (!fx_load(&f, "hydraulic_bridge", BG_METHOD_SCAP, NULL, 0, NULL, NULL, &o)) {
    INT_EQ(f.rc, 1);
    OK(has(f.r.message, "DAE"));
  } else OK(0);
  fx_free(&f);
}

/* ------------------------------------------------------------------ failure */
/* q' = 2 - sqrt(1 - q)/R: the charge passes 1 near t = 0.6 and the law's
 * square root has no value beyond. */
static const char *BLOW =
    "model blow \"A capacitor charged past its law's domain\"\n"
    "param I0 = 2, R0 = 1\n"
    "Sf S = I0\n"
    "0  n\n"
    "C  C1 : e = sqrt(1 - q)\n"
    "R  R1 = R0\n"
    "bond 1 S -> n\n"
    "bond 2 n -> C1\n"
    "bond 3 n -> R1\n"
    "simulate t_end = 2, dt = 0.05\n"
    "plot C1.q\n";

static void test_failure(void) {
  fx f;
  if (fx_text(&f, BLOW, NULL)) { OK(0); return; }
  INT_EQ(f.rc, 2);
  INT_EQ(f.r.partial, 1);
  OK(f.r.nrows > 5 && f.r.nrows < 41);
  OK(f.r.t_reached > 0.3 && f.r.t_reached < 1.0);
  OK(has(f.r.message, "failed at t = "));
  OK(has(f.r.message, "could not be evaluated"));
  bg_strbuf sb = {0};
  bg_csv_write(&f.r, &sb);
  OK(has(bg_sb_str(&sb), "\n# partial: simulation failed at t = "));
  bg_sb_free(&sb);
  fx_free(&f);
}

/* ------------------------------------------------------------------ CSV */
static void test_csv(void) {
  const char *names[] = {"C1.e", "max(a, b)", "say \"hi\""};
  double t[] = {0, 0.5}, v[] = {1, 2, 3, 0.1, -1e-300, 1.0 / 3};
  bg_simresult r;
  memset(&r, 0, sizeof r);
  r.nout = 3, r.names = names, r.nrows = 2, r.t = t, r.values = v;
  bg_strbuf sb = {0};
  bg_csv_write(&r, &sb);
  STR_EQ(bg_sb_str(&sb), "t,C1.e,\"max(a, b)\",\"say \"\"hi\"\"\"\n"
                         "0,1,2,3\n"
                         "0.5,0.10000000000000001,-1e-300,0.33333333333333331\n");
  r.partial = 1;
  r.message = "simulation failed at t = 0.7:\nreason";
  bg_sb_clear(&sb);
  bg_csv_write(&r, &sb);
  OK(has(bg_sb_str(&sb), "\n# partial: simulation failed at t = 0.7: reason\n"));
  bg_sb_free(&sb);
}

int main(void) {
  test_csv();
  test_rlc();
  test_rlc_forced();
  test_bond_loop();
  test_delta_vandijk();
  test_modulated_source();
  test_slider_crank();
  test_hydraulic_bridge();
  test_bridge_compliance_auto();
  test_refusals();
  test_failure();
  return bg_t_done();
}
