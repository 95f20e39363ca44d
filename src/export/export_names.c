/* SPDX-License-Identifier: BSD-3-Clause */
/* Identifiers of the exported code (export_int.h): a model's names made
 * identifiers of the target language, keeping clear of its keywords and of
 * the names its generated code or standard headers already mean (issue 28:
 * `param int = 1` gave `double int;`, `param for` an Octave parse error,
 * `parameter Real Real` in Modelica). A reserved name gets a trailing '_';
 * the exports keep a table of the original names. */
#include <stdio.h>
#include <string.h>

#include "export/export_int.h"

/* C11 and C23 keywords, and object-like macros of the headers the C export
 * includes (math.h, stdlib.h, string.h, stddef.h) or that gcc predefines in
 * its default GNU mode (`linux` is 1): a struct field named so does not
 * compile. */
const char *const bg_reserved_c[] = {
    "auto", "break", "case", "char", "const", "continue", "default", "do", "double", "else", "enum",
    "extern", "float", "for", "goto", "if", "inline", "int", "long", "register", "restrict",
    "return", "short", "signed", "sizeof", "static", "struct", "switch", "typedef", "union",
    "unsigned", "void", "volatile", "while", "alignas", "alignof", "bool", "constexpr", "false",
    "nullptr", "static_assert", "thread_local", "true", "typeof", "typeof_unqual", "asm",
    "NAN", "INFINITY", "HUGE_VAL", "HUGE_VALF", "HUGE_VALL", "FP_NAN", "FP_INFINITE", "FP_ZERO",
    "FP_SUBNORMAL", "FP_NORMAL", "FP_ILOGB0", "FP_ILOGBNAN", "MATH_ERRNO", "MATH_ERREXCEPT",
    "math_errhandling", "M_E", "M_LOG2E", "M_LOG10E", "M_LN2", "M_LN10", "M_PI", "M_PI_2",
    "M_PI_4", "M_1_PI", "M_2_PI", "M_2_SQRTPI", "M_SQRT2", "M_SQRT1_2", "NULL", "EXIT_SUCCESS",
    "EXIT_FAILURE", "RAND_MAX", "MB_CUR_MAX", "errno", "unix", "linux", "i386", NULL};

/* Python 3 keywords (a parameter is also a keyword argument of dict()). */
const char *const bg_reserved_python[] = {
    "False", "None", "True", "and", "as", "assert", "async", "await", "break", "class",
    "continue", "def", "del", "elif", "else", "except", "finally", "for", "from", "global", "if",
    "import", "in", "is", "lambda", "nonlocal", "not", "or", "pass", "raise", "return", "try",
    "while", "with", "yield", NULL};

/* Octave and MATLAB keywords (a struct field p.for does not parse). */
const char *const bg_reserved_octave[] = {
    "__FILE__", "__LINE__", "arguments", "break", "case", "catch", "classdef", "continue", "do",
    "else", "elseif", "end", "end_try_catch", "end_unwind_protect", "endarguments",
    "endclassdef", "endenumeration", "endevents", "endfor", "endfunction", "endif",
    "endmethods", "endparfor", "endproperties", "endspmd", "endswitch", "endwhile",
    "enumeration", "events", "for", "function", "global", "if", "methods", "otherwise",
    "parfor", "persistent", "properties", "return", "spmd", "switch", "try", "until",
    "unwind_protect", "unwind_protect_cleanup", "while", NULL};

/* Modelica 3.5 keywords, its predefined types and the built-in operators and
 * functions a component name would hide (`parameter Real Real`, `der`). */
const char *const bg_reserved_modelica[] = {
    "algorithm", "and", "annotation", "block", "break", "class", "connect", "connector",
    "constant", "constrainedby", "der", "discrete", "each", "else", "elseif", "elsewhen",
    "encapsulated", "end", "enumeration", "equation", "expandable", "extends", "external",
    "false", "final", "flow", "for", "function", "if", "import", "impure", "in", "initial",
    "inner", "input", "loop", "model", "not", "operator", "or", "outer", "output", "package",
    "parameter", "partial", "protected", "public", "pure", "record", "redeclare", "replaceable",
    "return", "stream", "then", "true", "type", "when", "while", "within", "time", "Real",
    "Integer", "Boolean", "String", "Clock", "StateSelect", "ExternalObject", "AssertionLevel",
    "abs", "sign", "sqrt", "div", "mod", "rem", "ceil", "floor", "integer", "sin", "cos", "tan",
    "asin", "acos", "atan", "atan2", "sinh", "cosh", "tanh", "exp", "log", "log10", "min", "max",
    "sum", "product", "noEvent", "smooth", "pre", "edge", "change", "sample", "reinit",
    "terminal", "assert", "terminate", "delay", "homotopy", "semiLinear", "inStream",
    "actualStream", "cardinality", "size", "ndims", "scalar", "vector", "matrix", "zeros", "ones",
    "fill", "identity", "diagonal", "linspace", "cat", "transpose", "cross", "skew",
    "getInstanceName", "spatialDistribution", NULL};

int bg_export_reserved(const char *const *reserved, const char *id) {
  for (int k = 0; reserved && reserved[k]; k++)
    if (!strcmp(reserved[k], id)) return 1;
  return 0;
}

void bg_export_ident(const char *name, char *buf, size_t n) {
  size_t i = 0;
  if (n == 0) return;
  if (!((name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= 'a' && name[0] <= 'z') || name[0] == '_'))
    if (i + 1 < n) buf[i++] = '_';
  for (const char *p = name; *p && i + 1 < n; p++) {
    char c = *p;
    int ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    buf[i++] = ok ? c : '_';
  }
  buf[i] = 0;
}

/* C reserves every identifier that begins with two underscores or with an
 * underscore and a capital letter for the implementation (C11 7.1.3): gcc
 * predefines many as macros (`__FILE__`, `__LINE__`, `__STDC__`), and a
 * trailing '_' would leave them reserved, so they get a leading 'p'. */
static int c_implementation_name(const char *id) {
  return id[0] == '_' && (id[1] == '_' || (id[1] >= 'A' && id[1] <= 'Z'));
}

void bg_export_ident_in(const char *const *reserved, const char *name, char *buf, size_t n) {
  bg_export_ident(name, buf, n);
  if (reserved == bg_reserved_c && c_implementation_name(buf) && strlen(buf) + 2 <= n) {
    memmove(buf + 1, buf, strlen(buf) + 1);
    buf[0] = 'p';
    return;
  }
  if (bg_export_reserved(reserved, buf) && strlen(buf) + 2 <= n) strcat(buf, "_");
}

const char *bg_export_param_ident(const bg_xlang *L, const bg_eqsys *s, int k, char *buf, size_t n) {
  const bg_model *m = s->m;
  bg_export_ident_in(L->reserved, m->param_name[k], buf, n);
  char other[300];
  for (int j = 0; j < m->nparam; j++) {
    if (j == k) continue;
    bg_export_ident_in(L->reserved, m->param_name[j], other, sizeof other);
    if (strcmp(other, buf) == 0) {
      size_t len = strlen(buf);
      snprintf(buf + len, n - len, "_%d", k);
      break;
    }
  }
  return buf;
}

int bg_export_params_renamed(const bg_xlang *L, const bg_eqsys *s) {
  char id[300];
  for (int k = 0; k < s->m->nparam; k++)
    if (!bg_eqsys_param_is_derived(s, k) && strcmp(bg_export_param_ident(L, s, k, id, sizeof id), s->m->param_name[k]))
      return 1;
  return 0;
}
