#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The MathML equations mean what the text equations say: for each model,
`--equations mathml` is parsed as XML, each <math> row turned back into an
expression (mfrac a/b, msup a**b, msqrt, msub names e3 and C1.q, a dot above
as a derivative ', invisible times *), and evaluated at random values of its
names beside the same row of `--equations text`; the left sides must name the
same unknown and the right sides agree to 1e-9.
usage: mathml_check.py BGDRAW MODEL..."""
import math
import random
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

OPS = {"\u2212": "-", "\u2062": "*", "\u2061": "", "\u22c5": "*", "\u2264": "<=", "\u2265": ">=",
       "\u2260": "!=", "\u2227": " and ", "\u2228": " or ", "\u00ac": " not ", "\u2202": "d"}


def local(tag):
    return tag.split("}")[-1]


def conv(el):
    tag = local(el.tag)
    kids = list(el)
    if tag in ("math", "mrow"):
        parts = [conv(k) for k in kids]
        # |x| as <mo>|</mo> ... <mo>|</mo>
        if len(kids) >= 2 and local(kids[0].tag) == "mo" and kids[0].text == "|" and kids[-1].text == "|":
            return "abs(" + "".join(parts[1:-1]) + ")"
        return "".join(parts)
    if tag in ("mi", "mn"):
        return el.text.strip()
    if tag == "mo":
        t = el.text or ""
        return OPS.get(t, t)
    if tag == "mfrac":
        return "((%s)/(%s))" % (conv(kids[0]), conv(kids[1]))
    if tag == "msup":
        return "((%s)**(%s))" % (conv(kids[0]), conv(kids[1]))
    if tag == "msqrt":
        return "sqrt(" + "".join(conv(k) for k in kids) + ")"
    if tag == "msub":
        base, sub = conv(kids[0]), conv(kids[1])
        if local(kids[1].tag) == "mn":
            return base + sub  # e3
        return sub + "." + base  # C1.q
    if tag == "mover":
        return conv(kids[0]) + "'"
    raise ValueError("unexpected element <%s>" % tag)


NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_.]*'?")
FUNCS = {"sin": math.sin, "cos": math.cos, "tan": math.tan, "exp": math.exp, "log": math.log, "ln": math.log,
         "sqrt": math.sqrt, "abs": abs, "min": min, "max": max, "sinh": math.sinh, "cosh": math.cosh,
         "tanh": math.tanh, "asin": math.asin, "acos": math.acos, "atan": math.atan, "arcsin": math.asin,
         "arccos": math.acos, "arctan": math.atan, "step": lambda x: 1.0 if x >= 0 else 0.0,
         "sign": lambda x: (x > 0) - (x < 0), "atan2": math.atan2}


def python(expr, names):
    """expr with its names replaced by v0, v1... (functions kept)."""
    out, pos = [], 0
    for m in NAME.finditer(expr):
        out.append(expr[pos:m.start()])
        word = m.group(0)
        follows = expr[m.end():m.end() + 1]
        if follows == "(":  # a function: the model's (pulse, hyst) get a stand-in
            out.append("F_" + word)
        elif word in ("and", "or", "not"):
            out.append(word)
        else:
            names.setdefault(word, "v%d" % len(names))
            out.append(names[word])
        pos = m.end()
    out.append(expr[pos:])
    return "".join(out).replace("^", "**")


def rows_text(text):
    rows = []
    for line in text.splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        line = re.sub(r"\s+\((solved for [^)]*|dependent store: constraint)\)$", "", line)
        lhs, rhs = line.split(" = ", 1)
        rows.append((lhs.strip(), rhs.strip()))
    return rows


def rows_mathml(frag):
    root = ET.fromstring("<div>" + frag + "</div>")
    rows = []
    for m in root.iter():
        if local(m.tag) != "math":
            continue
        e = conv(m)
        lhs, rhs = e.split("=", 1)
        rows.append((lhs, rhs))
    return rows


def value(expr, names, env):
    code = python(expr, names)
    scope = {}
    for f in re.findall(r"F_(\w+)", code):  # the same stand-in on both sides
        scope["F_" + f] = FUNCS.get(f, lambda *a, n=len(f): n + sum((i + 1.3) * x for i, x in enumerate(a)))
    scope.update(env)
    return eval(code, {"__builtins__": {}}, scope)


def main():
    bgdraw, models = sys.argv[1], sys.argv[2:]
    fails = checked = skipped = 0
    rng = random.Random(36)
    for path in models:
        out = {}
        for form in ("text", "mathml"):
            r = subprocess.run([bgdraw, path, "--equations", form], stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL, timeout=120)
            out[form] = r.stdout.decode() if r.returncode == 0 else None
        if out["text"] is None:
            continue  # no equations: nothing to compare
        if out["mathml"] is None:
            print("FAIL %s: --equations mathml failed where text did not" % path)
            fails += 1
            continue
        t, m = rows_text(out["text"]), rows_mathml(out["mathml"])
        if len(t) != len(m):
            print("FAIL %s: %d text rows, %d MathML rows" % (path, len(t), len(m)))
            fails += 1
            continue
        names = {}
        for (tl, tr), (ml, mr) in zip(t, m):
            if tl != ml:
                print("FAIL %s: left side %r (text) vs %r (MathML)" % (path, tl, ml))
                fails += 1
                continue
            if "table(" in tr or "#" in tr or "&&" in tr or "||" in tr or "!" in tr or "if(" in tr:
                skipped += 1
                continue
            good = 0
            for trial in range(30):
                python(tr, names), python(mr, names)
                env = {v: rng.uniform(0.5, 2.0) for v in names.values()}
                try:
                    a = value(tr, names, env)
                except (ValueError, ZeroDivisionError, OverflowError):
                    continue  # outside the text's domain (sqrt of a negative): another point
                try:
                    b = value(mr, names, env)
                except (ValueError, ZeroDivisionError, OverflowError, TypeError, NameError, SyntaxError) as e:
                    print("FAIL %s: %s = %s / %s: %s" % (path, tl, tr, mr, e))
                    fails += 1
                    break
                if not abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b)):
                    print("FAIL %s: %s = %s is %r, the MathML %s is %r" % (path, tl, tr, a, mr, b))
                    fails += 1
                    break
                good += 1
                if good == 3:
                    checked += 1
                    break
            else:
                skipped += 1  # no point of the text's domain found
    print("mathml: %d rows agree with the text printer, %d skipped (tables, logic, no point in the domain), %d failures"
          % (checked, skipped, fails))
    return 1 if fails or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
