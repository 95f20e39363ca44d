/* SPDX-License-Identifier: BSD-3-Clause */
/* FMI 2.0 Model Exchange (docs/export.md): modelDescription.xml and a glue
 * source that implements the fmi2 functions on top of the reusable C export
 * (bg_export_c). The fmi2 types are declared here from the standard's text,
 * not copied from its headers. ODE models only: FMI 2.0 ME has no algebraic
 * unknowns. Value references: the record's params, then the states, their
 * derivatives, the outputs; that is also the order of ModelVariables. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "export/export_int.h"

static void xml_attr(bg_strbuf *o, const char *s) {
  for (; *s; s++) {
    switch (*s) {
    case '&': bg_sb_puts(o, "&amp;"); break;
    case '<': bg_sb_puts(o, "&lt;"); break;
    case '>': bg_sb_puts(o, "&gt;"); break;
    case '"': bg_sb_puts(o, "&quot;"); break;
    default: bg_sb_putc(o, *s); break;
    }
  }
}

/* 1 when name is a state's name or a param's: an output of that name is
 * renamed "out(name)" (without plot the outputs are the states). */
static int name_taken(const bg_eqsys *s, const char *name) {
  for (int i = 0; i < s->nx; i++)
    if (!strcmp(s->uname[i], name)) return 1;
  for (int k = 0; k < s->m->nparam; k++)
    if (!bg_eqsys_param_is_derived(s, k) && !strcmp(s->m->param_name[k], name)) return 1;
  return 0;
}

void bg_export_fmu_guid(const char *text, size_t len, char *buf, size_t n) {
  /* two FNV-1a 64-bit hashes with different offsets: 128 bits of the text */
  uint64_t a = 14695981039346656037ull, b = 0x6a09e667f3bcc908ull;
  for (size_t i = 0; i < len; i++) {
    a = (a ^ (unsigned char)text[i]) * 1099511628211ull;
    b = (b ^ (unsigned char)text[i]) * 1099511628211ull;
  }
  snprintf(buf, n, "{%08x-%04x-%04x-%04x-%012llx}", (unsigned)(a >> 32), (unsigned)(a >> 16) & 0xffff,
           (unsigned)a & 0xffff, (unsigned)(b >> 48), (unsigned long long)(b & 0xffffffffffffull));
}

static void xml_var(bg_strbuf *o, const char *name, int vr, const char *attrs) {
  bg_sb_puts(o, "    <ScalarVariable name=\"");
  xml_attr(o, name);
  bg_sb_printf(o, "\" valueReference=\"%d\" %s>\n", vr, attrs);
}

static void xml_variables(const bg_eqsys *s, bg_strbuf *o) {
  int np = bg_export_nparams(s), vr = 0;
  char buf[600];
  bg_sb_puts(o, "  <ModelVariables>\n");
  for (int k = 0; k < s->m->nparam; k++) {
    if (bg_eqsys_param_is_derived(s, k)) continue;
    xml_var(o, s->m->param_name[k], vr++, "causality=\"parameter\" variability=\"tunable\"");
    bg_sb_puts(o, "      <Real start=\"");
    bg_sb_num(o, s->m->param_value[k]);
    bg_sb_puts(o, "\"/>\n    </ScalarVariable>\n");
  }
  for (int i = 0; i < s->nx; i++) {
    xml_var(o, s->uname[i], vr++, "causality=\"local\" variability=\"continuous\" initial=\"calculated\"");
    bg_sb_puts(o, "      <Real/>\n    </ScalarVariable>\n");
  }
  for (int i = 0; i < s->nx; i++) {
    snprintf(buf, sizeof buf, "der(%s)", s->uname[i]);
    xml_var(o, buf, vr++, "causality=\"local\" variability=\"continuous\" initial=\"calculated\"");
    bg_sb_printf(o, "      <Real derivative=\"%d\"/>\n    </ScalarVariable>\n", np + i + 1);
  }
  for (int k = 0; k < s->nout; k++) {
    const char *nm = s->out_name[k];
    if (name_taken(s, nm)) snprintf(buf, sizeof buf, "out(%s)", nm), nm = buf;
    xml_var(o, nm, vr++, "causality=\"output\" variability=\"continuous\" initial=\"calculated\"");
    bg_sb_puts(o, "      <Real/>\n    </ScalarVariable>\n");
  }
  bg_sb_puts(o, "  </ModelVariables>\n");
}

/* Indices (1-based) [a, b) as <Unknown/> elements; dependencies omitted:
 * every unknown may depend on everything (the standard's default). */
static void unknowns(bg_strbuf *o, int a, int b) {
  for (int i = a; i < b; i++) bg_sb_printf(o, "      <Unknown index=\"%d\"/>\n", i + 1);
}

static void xml_structure(const bg_eqsys *s, bg_strbuf *o) {
  int np = bg_export_nparams(s), nx = s->nx, nout = s->nout;
  int st = np, der = np + nx, out = np + 2 * nx, end = out + nout;
  bg_sb_puts(o, "  <ModelStructure>\n    <Outputs>\n");
  unknowns(o, out, end);
  bg_sb_puts(o, "    </Outputs>\n    <Derivatives>\n");
  unknowns(o, der, out);
  bg_sb_puts(o, "    </Derivatives>\n    <InitialUnknowns>\n");
  unknowns(o, st, end); /* states, derivatives and outputs: all calculated */
  bg_sb_puts(o, "    </InitialUnknowns>\n  </ModelStructure>\n");
}

void bg_export_fmu_description(const bg_eqsys *s, const char *prefix, const char *guid,
                               bg_strbuf *o) {
  const bg_model *m = s->m;
  bg_sb_puts(o, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<fmiModelDescription fmiVersion=\"2.0\" modelName=\"");
  xml_attr(o, m->name);
  bg_sb_printf(o, "\" guid=\"%s\"", guid);
  if (m->title) bg_sb_puts(o, " description=\""), xml_attr(o, m->title), bg_sb_puts(o, "\"");
  bg_sb_puts(o, " generationTool=\"bgdraw\" variableNamingConvention=\"flat\" numberOfEventIndicators=\"");
  bg_sb_printf(o, "%d\">\n", bg_eqsys_nroots(s));
  bg_sb_printf(o, "  <ModelExchange modelIdentifier=\"%s\">\n    <SourceFiles>\n", prefix);
  bg_sb_printf(o, "      <File name=\"%s.c\"/>\n      <File name=\"%s_fmi2.c\"/>\n", prefix, prefix);
  bg_sb_puts(o, "    </SourceFiles>\n  </ModelExchange>\n");
  if (m->sim.present) {
    bg_sb_puts(o, "  <DefaultExperiment startTime=\"");
    bg_sb_num(o, m->sim.t0);
    bg_sb_puts(o, "\" stopTime=\"");
    bg_sb_num(o, m->sim.t_end);
    if (m->sim.rtol > 0) bg_sb_puts(o, "\" tolerance=\""), bg_sb_num(o, m->sim.rtol);
    if (m->sim.dt > 0) bg_sb_puts(o, "\" stepSize=\""), bg_sb_num(o, m->sim.dt);
    bg_sb_puts(o, "\"/>\n");
  }
  xml_variables(s, o);
  xml_structure(s, o);
  bg_sb_puts(o, "</fmiModelDescription>\n");
}

/* ------------------------------------------------------------ glue */
static const char glue_types[] =
    "/* FMI 2.0 types and constants, declared from the standard's text. */\n"
    "typedef void *fmi2Component;\ntypedef void *fmi2ComponentEnvironment;\ntypedef void *fmi2FMUstate;\n"
    "typedef unsigned int fmi2ValueReference;\ntypedef double fmi2Real;\ntypedef int fmi2Integer;\n"
    "typedef int fmi2Boolean;\ntypedef char fmi2Char;\ntypedef const fmi2Char *fmi2String;\ntypedef char fmi2Byte;\n"
    "#define fmi2True 1\n#define fmi2False 0\n"
    "typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;\n"
    "typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;\n"
    "typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...);\n"
    "typedef void *(*fmi2CallbackAllocateMemory)(size_t, size_t);\ntypedef void (*fmi2CallbackFreeMemory)(void *);\n"
    "typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment, fmi2Status);\n"
    "typedef struct {\n  fmi2CallbackLogger logger;\n  fmi2CallbackAllocateMemory allocateMemory;\n"
    "  fmi2CallbackFreeMemory freeMemory;\n  fmi2StepFinished stepFinished;\n  fmi2ComponentEnvironment componentEnvironment;\n"
    "} fmi2CallbackFunctions;\n"
    "typedef struct {\n  fmi2Boolean newDiscreteStatesNeeded, terminateSimulation, nominalsOfContinuousStatesChanged,\n"
    "      valuesOfContinuousStatesChanged, nextEventTimeDefined;\n  fmi2Real nextEventTime;\n} fmi2EventInfo;\n"
    "#define FMI2_EXPORT __attribute__((visibility(\"default\")))\n\n";

/* The instance and its life cycle. M_* are the model's names (defined above
 * this text by glue_model). */
static const char glue_instance[] =
    "enum { MODE_INSTANTIATED, MODE_INIT, MODE_EVENT, MODE_CONTINUOUS, MODE_TERMINATED };\n"
    "typedef struct {\n  fmi2CallbackFunctions cb;\n  char *name;\n  int mode, logging;\n  M_params p;\n  double t;\n"
    "  double x[M_NX + 1], dx[M_NX + 1], out[M_NOUT + 1], work[M_NWORK + 1];\n  M_EVENT_FIELDS\n} bg_fmu;\n\n"
    "static fmi2Status bg_fail(bg_fmu *m, const char *msg) {\n"
    "  if (m && m->cb.logger) m->cb.logger(m->cb.componentEnvironment, m->name, fmi2Error, \"logStatusError\", \"%s\", msg);\n"
    "  return fmi2Error;\n}\n\n"
    "/* the states from the params at time t: the model's q0, p0, init */\n"
    "static void bg_reinit(bg_fmu *m) {\n  M_initial(&m->p, m->t, m->x, m->work);\n  M_MODES_START(m);\n}\n\n"
    "FMI2_EXPORT const char *fmi2GetTypesPlatform(void) { return \"default\"; }\n"
    "FMI2_EXPORT const char *fmi2GetVersion(void) { return \"2.0\"; }\n\n"
    "FMI2_EXPORT fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String location,\n"
    "                                          const fmi2CallbackFunctions *cb, fmi2Boolean visible, fmi2Boolean logging) {\n"
    "  (void)location, (void)visible;\n  bg_fmu tmp = {0};\n  if (cb) tmp.cb = *cb;\n  tmp.name = (char *)(name ? name : \"\");\n"
    "  if (type != fmi2ModelExchange) return bg_fail(&tmp, \"this FMU is for Model Exchange only\"), NULL;\n"
    "  if (!guid || strcmp(guid, M_GUID)) return bg_fail(&tmp, \"the GUID does not match modelDescription.xml\"), NULL;\n"
    "  bg_fmu *m = tmp.cb.allocateMemory ? tmp.cb.allocateMemory(1, sizeof *m) : calloc(1, sizeof *m);\n"
    "  if (!m) return bg_fail(&tmp, \"out of memory\"), NULL;\n  *m = tmp;\n  size_t n = strlen(tmp.name) + 1;\n"
    "  m->name = m->cb.allocateMemory ? m->cb.allocateMemory(n, 1) : calloc(n, 1);\n"
    "  if (m->name) memcpy(m->name, tmp.name, n);\n"
    "  m->logging = logging;\n  m->p = M_default_params;\n  M_SETUP_SPAN(m, 0, 0, 0);\n  bg_reinit(m);\n  return m;\n}\n\n"
    "FMI2_EXPORT void fmi2FreeInstance(fmi2Component c) {\n  bg_fmu *m = c;\n  if (!m) return;\n"
    "  void (*fr)(void *) = m->cb.freeMemory ? m->cb.freeMemory : free;\n  fr(m->name);\n  fr(m);\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cat[]) {\n"
    "  (void)n, (void)cat;\n  ((bg_fmu *)c)->logging = on;\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tol_defined, fmi2Real tol, fmi2Real t0,\n"
    "                                           fmi2Boolean stop_defined, fmi2Real stop) {\n"
    "  bg_fmu *m = c;\n  (void)tol_defined, (void)tol, (void)stop_defined, (void)stop;\n"
    "  if (m->mode != MODE_INSTANTIATED) return bg_fail(m, \"fmi2SetupExperiment only after fmi2Instantiate\");\n"
    "  m->t = t0;\n  M_SETUP_SPAN(m, t0, stop_defined, stop);\n  bg_reinit(m);\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) {\n  bg_fmu *m = c;\n"
    "  if (m->mode != MODE_INSTANTIATED) return bg_fail(m, \"fmi2EnterInitializationMode out of order\");\n"
    "  m->mode = MODE_INIT;\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c) {\n  bg_fmu *m = c;\n"
    "  if (m->mode != MODE_INIT) return bg_fail(m, \"fmi2ExitInitializationMode out of order\");\n"
    "  bg_reinit(m);\n  m->mode = MODE_EVENT;\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2Terminate(fmi2Component c) { ((bg_fmu *)c)->mode = MODE_TERMINATED; return fmi2OK; }\n\n"
    "FMI2_EXPORT fmi2Status fmi2Reset(fmi2Component c) {\n  bg_fmu *m = c;\n"
    "  m->mode = MODE_INSTANTIATED, m->t = 0, m->p = M_default_params;\n  bg_reinit(m);\n  return fmi2OK;\n}\n\n";

/* Real variables by value reference. */
static const char glue_real[] =
    "static int bg_eval(bg_fmu *m, int outputs) {\n"
    "  if (M_rhs(&m->p, m->t, m->x, m->dx, m->work)) return -1;\n"
    "  return outputs ? M_outputs(&m->p, m->t, m->x, m->dx, m->out, m->work) : 0;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]) {\n"
    "  bg_fmu *m = c;\n  int need = 0;\n"
    "  for (size_t i = 0; i < n; i++) need |= vr[i] >= M_NPARAM + M_NX ? 1 + (vr[i] >= M_NPARAM + 2 * M_NX) : 0;\n"
    "  if (need && bg_eval(m, need > 1)) return bg_fail(m, \"a value is not finite (a law outside its domain)\");\n"
    "  for (size_t i = 0; i < n; i++) {\n    unsigned r = vr[i];\n"
    "    if (r < M_NPARAM) v[i] = *bg_param(&m->p, r);\n    else if ((r -= M_NPARAM) < M_NX) v[i] = m->x[r];\n"
    "    else if ((r -= M_NX) < M_NX) v[i] = m->dx[r];\n    else if ((r -= M_NX) < M_NOUT) v[i] = m->out[r];\n"
    "    else return bg_fail(m, \"fmi2GetReal: unknown value reference\");\n  }\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[]) {\n"
    "  bg_fmu *m = c;\n"
    "  for (size_t i = 0; i < n; i++)\n"
    "    if (vr[i] >= M_NPARAM) return bg_fail(m, \"fmi2SetReal: only parameters can be set (states: fmi2SetContinuousStates)\");\n"
    "  if (m->mode == MODE_CONTINUOUS) return bg_fail(m, \"fmi2SetReal: tunable parameters change in event mode\");\n"
    "  for (size_t i = 0; i < n; i++) *bg_param(&m->p, vr[i]) = v[i];\n"
    "  if (m->mode == MODE_INSTANTIATED || m->mode == MODE_INIT) bg_reinit(m); /* initial states follow the params */\n"
    "  return fmi2OK;\n}\n\n";

/* Time, continuous states, derivatives. */
static const char glue_me[] =
    "FMI2_EXPORT fmi2Status fmi2SetTime(fmi2Component c, fmi2Real t) { ((bg_fmu *)c)->t = t; return fmi2OK; }\n\n"
    "FMI2_EXPORT fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx) {\n"
    "  bg_fmu *m = c;\n  if (nx != M_NX) return bg_fail(m, \"fmi2SetContinuousStates: wrong number of states\");\n"
    "  for (size_t i = 0; i < nx; i++) m->x[i] = x[i];\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {\n"
    "  bg_fmu *m = c;\n  if (nx != M_NX) return bg_fail(m, \"fmi2GetContinuousStates: wrong number of states\");\n"
    "  for (size_t i = 0; i < nx; i++) x[i] = m->x[i];\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t nx) {\n"
    "  bg_fmu *m = c;\n  if (nx != M_NX) return bg_fail(m, \"fmi2GetDerivatives: wrong number of states\");\n"
    "  if (bg_eval(m, 0)) return bg_fail(m, \"a derivative is not finite (a law outside its domain)\");\n"
    "  for (size_t i = 0; i < nx; i++) dx[i] = m->dx[i];\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x[], size_t nx) {\n"
    "  (void)c;\n  for (size_t i = 0; i < nx; i++) x[i] = 1.0;\n  return fmi2OK;\n}\n\n";

/* Events: a model without switching conditions has none. */
static const char glue_no_events[] =
    "FMI2_EXPORT fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t nz) {\n"
    "  (void)z;\n  return nz == 0 ? fmi2OK : bg_fail(c, \"the model has no event indicators\");\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2EnterEventMode(fmi2Component c) { ((bg_fmu *)c)->mode = MODE_EVENT; return fmi2OK; }\n\n"
    "FMI2_EXPORT fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *e) {\n  (void)c;\n"
    "  e->newDiscreteStatesNeeded = e->terminateSimulation = fmi2False;\n"
    "  e->nominalsOfContinuousStatesChanged = e->valuesOfContinuousStatesChanged = fmi2False;\n"
    "  e->nextEventTimeDefined = fmi2False, e->nextEventTime = 0;\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {\n"
    "  ((bg_fmu *)c)->mode = MODE_CONTINUOUS;\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean no_set_state, fmi2Boolean *enter_event,\n"
    "                                                   fmi2Boolean *terminate) {\n"
    "  (void)c, (void)no_set_state;\n  *enter_event = *terminate = fmi2False;\n  return fmi2OK;\n}\n\n";

/* The same with state events: the root functions are the event indicators;
 * at an event (fmi2EnterEventMode, then fmi2NewDiscreteStates) every mode is
 * set from the values there, with the directions of the indicators that
 * changed sign since the continuous-time phase began; no state jumps. */
static const char glue_me_events[] =
    "FMI2_EXPORT fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t nz) {\n  bg_fmu *m = c;\n"
    "  if (nz != M_NROOT) return bg_fail(m, \"fmi2GetEventIndicators: wrong number of event indicators\");\n"
    "  if (M_roots(&m->p, &m->md, m->t, m->x, NULL, z, m->work))\n"
    "    return bg_fail(m, \"an event indicator is not finite (a law outside its domain)\");\n"
    "  /* one at 0 when the phase began (a speed held at 0 while stuck) takes the\n"
    "   * side it leaves to: crossing back later is a crossing */\n"
    "  for (int i = 0; i < M_NROOT; i++)\n    if (m->gpre[i] == 0) m->gpre[i] = z[i];\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2EnterEventMode(fmi2Component c) {\n  bg_fmu *m = c;\n"
    "  m->mode = MODE_EVENT, m->event_pending = 1;\n  return fmi2OK;\n}\n\n"
    "/* the indicators at the start of a continuous-time phase: the signs a crossing changes */\n"
    "static int bg_mark(bg_fmu *m) { return M_roots(&m->p, &m->md, m->t, m->x, NULL, m->gpre, m->work); }\n\n"
    "FMI2_EXPORT fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *e) {\n  bg_fmu *m = c;\n"
    "  e->newDiscreteStatesNeeded = e->terminateSimulation = fmi2False;\n"
    "  e->nominalsOfContinuousStatesChanged = e->valuesOfContinuousStatesChanged = fmi2False;\n"
    "  e->nextEventTimeDefined = fmi2False, e->nextEventTime = 0;\n"
    "  if (!m->event_pending) return fmi2OK; /* after initialisation: the modes are set */\n"
    "  m->event_pending = 0;\n"
    "  if (M_roots(&m->p, &m->md, m->t, m->x, NULL, m->g, m->work))\n"
    "    return bg_fail(m, \"an event indicator is not finite (a law outside its domain)\");\n"
    "  for (int i = 0; i < M_NROOT; i++)\n"
    "    m->dir[i] = m->gpre[i] < 0 && m->g[i] >= 0 ? 1 : m->gpre[i] > 0 && m->g[i] <= 0 ? -1 : 0;\n"
    "  M_event(&m->p, m->t, m->x, NULL, m->dir, 1e-9 * m->span, &m->md, m->work);\n"
    "  bg_mark(m);\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {\n  bg_fmu *m = c;\n"
    "  m->mode = MODE_CONTINUOUS;\n  bg_mark(m);\n  return fmi2OK;\n}\n\n"
    "FMI2_EXPORT fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean no_set_state, fmi2Boolean *enter_event,\n"
    "                                                   fmi2Boolean *terminate) {\n"
    "  (void)c, (void)no_set_state;\n  *enter_event = *terminate = fmi2False;\n  return fmi2OK;\n}\n\n";

/* What the model does not have: Integer, Boolean, String variables, FMU
 * states, directional derivatives (the capability flags say so). */
static const char glue_none[] =
    "#define BG_NO_VARS(T, f) FMI2_EXPORT fmi2Status f(fmi2Component c, const fmi2ValueReference vr[], size_t n, T v[]) {\\\n"
    "    (void)vr, (void)v;\\\n    return n == 0 ? fmi2OK : bg_fail(c, #f \": the model has no such variables\");\\\n  }\n"
    "BG_NO_VARS(fmi2Integer, fmi2GetInteger)\nBG_NO_VARS(const fmi2Integer, fmi2SetInteger)\n"
    "BG_NO_VARS(fmi2Boolean, fmi2GetBoolean)\nBG_NO_VARS(const fmi2Boolean, fmi2SetBoolean)\n"
    "BG_NO_VARS(fmi2String, fmi2GetString)\nBG_NO_VARS(const fmi2String, fmi2SetString)\n\n"
    "FMI2_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)s; return bg_fail(c, \"no FMU states\"); }\n"
    "FMI2_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate s) { (void)s; return bg_fail(c, \"no FMU states\"); }\n"
    "FMI2_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *s) { (void)s; return bg_fail(c, \"no FMU states\"); }\n"
    "FMI2_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate s, size_t *n) {\n"
    "  (void)s, (void)n;\n  return bg_fail(c, \"no FMU states\");\n}\n"
    "FMI2_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate s, fmi2Byte b[], size_t n) {\n"
    "  (void)s, (void)b, (void)n;\n  return bg_fail(c, \"no FMU states\");\n}\n"
    "FMI2_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *s) {\n"
    "  (void)s, (void)b, (void)n;\n  return bg_fail(c, \"no FMU states\");\n}\n"
    "FMI2_EXPORT fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,\n"
    "                                                    const fmi2ValueReference z[], size_t nz, const fmi2Real dv[],\n"
    "                                                    fmi2Real dz[]) {\n"
    "  (void)u, (void)nu, (void)z, (void)nz, (void)dv, (void)dz;\n  return bg_fail(c, \"no directional derivatives\");\n}\n";

/* The model's names for the fixed text, and the params by value reference. */
static void glue_model(const bg_eqsys *s, const char *P, const char *guid, bg_strbuf *c) {
  char U[80], id[300];
  size_t i = 0;
  for (; P[i] && i + 1 < sizeof U; i++) U[i] = (char)(P[i] >= 'a' && P[i] <= 'z' ? P[i] - 32 : P[i]);
  U[i] = 0;
  bg_sb_printf(c, "#define M_GUID \"%s\"\n#define M_params %s_params\n#define M_default_params %s_default_params\n", guid, P, P);
  bg_sb_printf(c, "#define M_initial %s_initial\n#define M_rhs %s_rhs\n#define M_outputs %s_outputs\n", P, P, P);
  bg_sb_printf(c, "#define M_NX %s_NX\n#define M_NOUT %s_NOUT\n#define M_NWORK %s_NWORK\n#define M_NPARAM %s_NPARAM\n", U, U, U, U);
  if (!s->nev) bg_sb_puts(c, "#define M_EVENT_FIELDS\n#define M_MODES_START(m)\n#define M_SETUP_SPAN(m, t0, defined, stop)\n\n");
  else {
    const bg_model *m = s->m;
    double span = m->sim.present && m->sim.t_end > m->sim.t0 ? m->sim.t_end - m->sim.t0 : 1;
    bg_sb_printf(c, "/* state events: the modes, the indicators, the span (the look-ahead is 1e-9 of it) */\n"
                    "#define M_NROOT %s_NROOT\n#define M_roots %s_roots\n#define M_event %s_event\n"
                    "#define M_EVENT_FIELDS %s_modes md; double g[M_NROOT + 1], gpre[M_NROOT + 1], span; "
                    "int dir[M_NROOT + 1], event_pending;\n", U, P, P, P);
    bg_sb_printf(c, "#define M_MODES_START(m) (%s_modes_start(&(m)->p, (m)->t, (m)->x, NULL, 1e-9 * (m)->span, &(m)->md, (m)->work), \\\n"
                    "                          M_roots(&(m)->p, &(m)->md, (m)->t, (m)->x, NULL, (m)->gpre, (m)->work))\n", P);
    bg_sb_puts(c, "#define M_SETUP_SPAN(m, t0, defined, stop) ((m)->span = (defined) && (stop) > (t0) ? (stop) - (t0) : ");
    bg_xl_num(&bg_xlang_c, c, span);
    bg_sb_printf(c, ")\n/* the functions of an instance m evaluate with its modes */\n"
                    "#undef M_rhs\n#undef M_outputs\n#define M_rhs(p, t, x, dx, w) %s_rhs(p, &m->md, t, x, dx, w)\n"
                    "#define M_outputs(p, t, x, dx, o, w) %s_outputs(p, &m->md, t, x, dx, o, w)\n\n", P, P);
  }
  bg_sb_printf(c, "static double bg_unused_param;\n/* the record's field of value reference r (< M_NPARAM) */\n"
                  "static double *bg_param(%s_params *p, unsigned r) {\n  switch (r) {\n", P);
  int vr = 0;
  for (int k = 0; k < s->m->nparam; k++)
    if (!bg_eqsys_param_is_derived(s, k))
      bg_sb_printf(c, "  case %d: return &p->%s;\n", vr++, bg_export_param_ident(&bg_xlang_c, s, k, id, sizeof id));
  bg_sb_puts(c, "  default: (void)p; return &bg_unused_param;\n  }\n}\n\n");
}

void bg_export_fmu_glue(const bg_eqsys *s, const char *prefix, const char *header_name, const char *guid,
                        bg_strbuf *c) {
  bg_sb_printf(c, "/* Generated by bgdraw from model %s: the FMI 2.0 Model Exchange functions over\n"
                  " * the C export in %s (docs/export.md). */\n", s->m->name, header_name);
  bg_sb_printf(c, "#include <stdlib.h>\n#include <string.h>\n\n#include \"%s\"\n\n", header_name);
  bg_sb_puts(c, glue_types);
  glue_model(s, prefix, guid, c);
  bg_sb_puts(c, glue_instance);
  bg_sb_puts(c, glue_real);
  bg_sb_puts(c, glue_me);
  bg_sb_puts(c, s->nev ? glue_me_events : glue_no_events);
  bg_sb_puts(c, glue_none);
}
