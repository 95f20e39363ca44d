/* SPDX-License-Identifier: BSD-3-Clause */
/* A small FMI 2.0 Model Exchange importer for tests/fmu_cli.sh: loads an
 * FMU's shared library with dlopen, calls the fmi2 functions in the order the
 * standard prescribes (instantiate, setup, set a parameter, initialise, event
 * iteration, continuous-time mode), integrates the states with classic RK4 at
 * SUB steps per output interval, and writes the outputs at the times of a
 * reference CSV, in its header's format. With event indicators it handles
 * state events as an FMI master does: after each step it compares the
 * indicators' signs with those at the start of the step; on a change it
 * locates the first crossing by bisection of the step, completes the step
 * to just past it, enters event mode, iterates fmi2NewDiscreteStates,
 * returns to continuous-time mode and goes on from there.
 * Usage: fmu_import LIB.so GUID NX REF.csv OUT.csv OUTVRS [nz=N] [events=FILE] [VR=VALUE]...
 *   OUTVRS: the outputs' value references, comma separated; nz: the number
 *   of event indicators; events: where each crossing is written ("t i dir"). */
#include <dlfcn.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef void *Comp;
typedef enum { OK, WARNING, DISCARD, ERROR, FATAL, PENDING } Status;
typedef struct {
  void (*logger)(void *, const char *, Status, const char *, const char *, ...);
  void *(*alloc)(size_t, size_t);
  void (*free_)(void *);
  void (*step_finished)(void *, Status);
  void *env;
} Callbacks;
typedef struct {
  int new_discrete, terminate, nominals_changed, values_changed, next_time_defined;
  double next_time;
} EventInfo;

static void logger(void *env, const char *name, Status st, const char *cat, const char *msg, ...) {
  (void)env;
  va_list ap;
  va_start(ap, msg);
  fprintf(stderr, "fmu[%s] %d %s: ", name, (int)st, cat);
  vfprintf(stderr, msg, ap);
  fputc('\n', stderr);
  va_end(ap);
}

static void *lib;
static void *sym(const char *name) {
  void *f = dlsym(lib, name);
  if (!f) fprintf(stderr, "missing %s\n", name), exit(2);
  return f;
}
#define FN(ret, name, ...) ret (*name)(__VA_ARGS__) = (ret (*)(__VA_ARGS__))sym(#name)
#define CHECK(call) do { if ((call) != OK) { fprintf(stderr, "failed: %s\n", #call); return 1; } } while (0)

static double times[200000];
static int ntimes;
static char header[4096];

static int read_ref(const char *path) {
  FILE *f = fopen(path, "r");
  char line[4096];
  if (!f || !fgets(header, sizeof header, f)) return -1;
  while (fgets(line, sizeof line, f) && ntimes < 200000) times[ntimes++] = atof(line);
  fclose(f);
  return ntimes > 1 ? 0 : -1;
}

/* The fmi2 functions the integration calls, looked up once in main. */
static Status (*set_time)(Comp, double), (*set_states)(Comp, const double *, size_t),
    (*get_derivatives)(Comp, double *, size_t);

/* One classic RK4 step of length h from (t, x) into xn; the FMU is left at (t + h, xn). */
static int rk4(Comp c, double t, const double *x, double h, double *xn, int nx) {
  static const double at[4] = {0, 0.5, 0.5, 1};
  double k[4][64], xs[64];
  for (int q = 0; q < 4; q++) {
    for (int i = 0; i < nx; i++) xs[i] = x[i] + (q ? at[q] * h * k[q - 1][i] : 0);
    if (set_time(c, t + at[q] * h) || set_states(c, xs, (size_t)nx) || get_derivatives(c, k[q], (size_t)nx))
      return fprintf(stderr, "failed: an evaluation at t = %g\n", t + at[q] * h), 1;
  }
  for (int i = 0; i < nx; i++) xn[i] = x[i] + h / 6 * (k[0][i] + 2 * k[1][i] + 2 * k[2][i] + k[3][i]);
  return set_time(c, t + h) || set_states(c, xn, (size_t)nx);
}

/* 1 when an event indicator changed sign from z to zn (left 0 is no crossing). */
static int crossed(const double *z, const double *zn, int nz) {
  for (int i = 0; i < nz; i++)
    if ((z[i] < 0 && zn[i] >= 0) || (z[i] > 0 && zn[i] <= 0)) return 1;
  return 0;
}

int main(int argc, char **argv) {
  if (argc < 7 || read_ref(argv[4])) return fprintf(stderr, "usage: see the source\n"), 2;
  lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (!lib) return fprintf(stderr, "%s\n", dlerror()), 2;
  FN(const char *, fmi2GetVersion, void);
  FN(const char *, fmi2GetTypesPlatform, void);
  FN(Comp, fmi2Instantiate, const char *, int, const char *, const char *, const Callbacks *, int, int);
  FN(Status, fmi2SetupExperiment, Comp, int, double, double, int, double);
  FN(Status, fmi2SetReal, Comp, const unsigned *, size_t, const double *);
  FN(Status, fmi2GetReal, Comp, const unsigned *, size_t, double *);
  FN(Status, fmi2EnterInitializationMode, Comp);
  FN(Status, fmi2ExitInitializationMode, Comp);
  FN(Status, fmi2NewDiscreteStates, Comp, EventInfo *);
  FN(Status, fmi2EnterContinuousTimeMode, Comp);
  FN(Status, fmi2GetContinuousStates, Comp, double *, size_t);
  FN(Status, fmi2SetContinuousStates, Comp, const double *, size_t);
  FN(Status, fmi2GetDerivatives, Comp, double *, size_t);
  FN(Status, fmi2SetTime, Comp, double);
  FN(Status, fmi2CompletedIntegratorStep, Comp, int, int *, int *);
  FN(Status, fmi2Terminate, Comp);
  FN(Status, fmi2GetEventIndicators, Comp, double *, size_t);
  FN(Status, fmi2EnterEventMode, Comp);
  set_time = fmi2SetTime, set_states = fmi2SetContinuousStates, get_derivatives = fmi2GetDerivatives;
  FN(void, fmi2FreeInstance, Comp);
  if (strcmp(fmi2GetVersion(), "2.0") || strcmp(fmi2GetTypesPlatform(), "default")) return 3;
  Callbacks cb = {logger, calloc, free, NULL, NULL};
  if (fmi2Instantiate("wrong", 0, "{not-the-guid}", "", &cb, 0, 0)) return fprintf(stderr, "a wrong GUID was accepted\n"), 3;
  if (fmi2Instantiate("cs", 1, argv[2], "", &cb, 0, 0)) return fprintf(stderr, "co-simulation was accepted\n"), 3;
  Comp c = fmi2Instantiate("m", 0, argv[2], "", &cb, 0, 0);
  if (!c) return 3;
  int nx = atoi(argv[3]), nout = 0;
  unsigned ovr[64];
  for (char *t = strtok(argv[6], ","); t && nout < 64; t = strtok(NULL, ",")) ovr[nout++] = (unsigned)atoi(t);
  CHECK(fmi2SetupExperiment(c, 0, 0, times[0], 1, times[ntimes - 1]));
  int nz = 0;
  FILE *fe = NULL;
  for (int a = 7; a < argc; a++) { /* VR=VALUE: a parameter, then read back */
    if (!strncmp(argv[a], "nz=", 3)) { nz = atoi(argv[a] + 3); continue; }
    if (!strncmp(argv[a], "events=", 7)) { fe = fopen(argv[a] + 7, "w"); continue; }
    unsigned vr = (unsigned)atoi(argv[a]);
    double v = atof(strchr(argv[a], '=') + 1), back = 0;
    CHECK(fmi2SetReal(c, &vr, 1, &v));
    CHECK(fmi2GetReal(c, &vr, 1, &back));
    if (back != v) return fprintf(stderr, "parameter %u reads back %g, not %g\n", vr, back, v), 3;
  }
  CHECK(fmi2EnterInitializationMode(c));
  CHECK(fmi2ExitInitializationMode(c));
  EventInfo ev = {1, 0, 0, 0, 0, 0};
  while (ev.new_discrete && !ev.terminate) CHECK(fmi2NewDiscreteStates(c, &ev));
  CHECK(fmi2EnterContinuousTimeMode(c));
  double x[64], xn[64], out[64], z[64], zn[64];
  if (nx > 64 || nout > 64 || nz > 64) return 2;
  CHECK(fmi2GetContinuousStates(c, x, (size_t)nx));
  if (nz) CHECK(fmi2GetEventIndicators(c, z, (size_t)nz));
  FILE *f = fopen(argv[5], "w");
  fputs(header, f);
  const int SUB = 100;
  double t = times[0];
  for (int r = 0; r < ntimes; r++) {
    double h = r > 0 ? (times[r] - times[r - 1]) / SUB : 0;
    while (r > 0 && times[r] - t > 1e-9 * h) {
      double hs = h < times[r] - t ? h : times[r] - t;
      if (rk4(c, t, x, hs, xn, nx)) return 1;
      int enter = 0, term = 0;
      CHECK(fmi2CompletedIntegratorStep(c, 1, &enter, &term));
      if (enter || term) return fprintf(stderr, "unexpected step event\n"), 3;
      if (nz) {
        CHECK(fmi2GetEventIndicators(c, zn, (size_t)nz));
        if (crossed(z, zn, nz)) { /* the first crossing: bisection of the step */
          double lo = 0, hi = hs;
          for (int it = 0; it < 200 && hi - lo > 1e-15 * (t > 1 ? t : t < -1 ? -t : 1); it++) {
            double mid = 0.5 * (lo + hi);
            if (rk4(c, t, x, mid, xn, nx)) return 1;
            CHECK(fmi2GetEventIndicators(c, zn, (size_t)nz));
            if (crossed(z, zn, nz)) hi = mid;
            else lo = mid;
          }
          if (rk4(c, t, x, hi, xn, nx)) return 1; /* just past it */
          CHECK(fmi2GetEventIndicators(c, zn, (size_t)nz));
          for (int i = 0; i < nz && fe; i++)
            if ((z[i] < 0 && zn[i] >= 0) || (z[i] > 0 && zn[i] <= 0)) fprintf(fe, "%.17g %d %d\n", t + hi, i, zn[i] > z[i] ? 1 : -1);
          CHECK(fmi2EnterEventMode(c));
          EventInfo e = {1, 0, 0, 0, 0, 0};
          while (e.new_discrete && !e.terminate) CHECK(fmi2NewDiscreteStates(c, &e));
          if (e.values_changed) CHECK(fmi2GetContinuousStates(c, xn, (size_t)nx));
          CHECK(fmi2EnterContinuousTimeMode(c));
          CHECK(fmi2GetEventIndicators(c, zn, (size_t)nz));
          hs = hi;
        }
        memcpy(z, zn, sizeof(double) * (size_t)nz);
      }
      t += hs;
      memcpy(x, xn, sizeof(double) * (size_t)nx);
    }
    t = times[r];
    CHECK(fmi2SetTime(c, times[r]));
    CHECK(fmi2SetContinuousStates(c, x, (size_t)nx));
    CHECK(fmi2GetReal(c, ovr, (size_t)nout, out));
    fprintf(f, "%.17g", times[r]);
    for (int i = 0; i < nout; i++) fprintf(f, ",%.17g", out[i]);
    fputc('\n', f);
  }
  if (fe) fclose(fe);
  fclose(f);
  CHECK(fmi2Terminate(c));
  fmi2FreeInstance(c);
  dlclose(lib);
  return 0;
}
