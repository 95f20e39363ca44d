#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Structural check of a Modelica file written by bgdraw (no Modelica tool is
packaged in Debian 12): one model, declarations before `equation`, the model
balanced (as many equations as non-parameter variables), every identifier in
an equation declared (or a built-in), der() only of variables with a start
value, no variable equation left unused. usage: check_modelica.py FILE.mo"""
import re
import sys

BUILTIN = {"der", "time", "if", "then", "else", "elseif", "and", "or", "not", "abs", "sign",
           "sqrt", "exp", "log", "log10", "sin", "cos", "tan", "asin", "acos", "atan", "atan2",
           "sinh", "cosh", "tanh", "min", "max", "floor", "ceil", "bg_table", "end"}


def main():
    text = open(sys.argv[1]).read()
    body = re.sub(r'"[^"]*"', '""', re.sub(r"//[^\n]*", "", text))
    m = re.search(r"^model (\w+)", body, re.M)
    if not m or not re.search(r"^end %s;" % m.group(1), body, re.M):
        return fail("no 'model NAME' ... 'end NAME;'")
    if "protected\n  function bg_table" in body:  # the table function's own declarations
        body = body[:body.index("protected\n  function bg_table")] + body[body.index("end bg_table;") + 13:]
    decl, eqs = body.split("\nequation\n", 1)
    eqs = eqs.split("\n  annotation(")[0].rsplit("\nend ", 1)[0]
    params = set(re.findall(r"parameter Real (\w+)", decl))
    variables = re.findall(r"^  Real (\w+)(\(start = [^)]*\))?", decl, re.M)
    names = {v for v, _ in variables}
    started = {v for v, s in variables if s}
    equations = [e.strip() for e in eqs.split(";") if e.strip()]
    if len(equations) != len(names):
        return fail("%d equations for %d variables" % (len(equations), len(names)))
    used = set()
    for e in equations:
        if "=" not in e:
            return fail("not an equation: " + e)
        for ident in re.findall(r"[A-Za-z_]\w*", re.sub(r"\b\d+(\.\d*)?(e[-+]?\d+)?", "", e)):
            if ident not in names and ident not in params and ident not in BUILTIN:
                return fail("undeclared '%s' in: %s" % (ident, e))
            used.add(ident)
        for d in re.findall(r"der\((\w+)\)", e):
            if d not in started:
                return fail("der(%s) of a variable without a start value" % d)
    unused = names - used
    if unused:
        return fail("variables in no equation: %s" % sorted(unused))
    print("%s: model %s balanced, %d equations, %d parameters" % (sys.argv[1], m.group(1), len(equations), len(params)))
    return 0


def fail(msg):
    print("%s: %s" % (sys.argv[1], msg))
    return 1


if __name__ == "__main__":
    sys.exit(main())
