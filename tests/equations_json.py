#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Checks that an equations JSON document (bgdraw --equations json) is
self-contained (docs/json.md, "The equations document"): every name an
expression uses is defined in the same document (parameters with values,
inputs, tables, alias definitions and their derivatives, unknowns with
initial values, bond variables by their equations), and every expression
evaluates with only the document. When the reduced form is an ODE and the
equations read no derivative of a dependent store, the state rows of the
equations (algebraic unknowns from the reduced form's solved rows) must
equal the reduced form's state rows at pseudo-random points: the two
descriptions agree using nothing but the document.
Usage: equations_json.py FILE.json...   exit 1 with a message on a failure."""
import json
import math
import random
import re
import sys

FUNCS = {
    "abs": abs, "sign": lambda x: (x > 0) - (x < 0), "sqrt": math.sqrt, "exp": math.exp,
    "log": math.log, "log10": math.log10, "sin": math.sin, "cos": math.cos, "tan": math.tan,
    "asin": math.asin, "acos": math.acos, "atan": math.atan, "atan2": math.atan2,
    "sinh": math.sinh, "cosh": math.cosh, "tanh": math.tanh, "min": min, "max": max,
    "pow": math.pow, "floor": math.floor, "ceil": math.ceil,
    "if": lambda c, a, b: a if c else b, "step": lambda x: 1.0 if x >= 0 else 0.0,
    "ramp": lambda x: x if x > 0 else 0.0,
    "pulse": lambda x, w: 1.0 if 0 <= x < w else 0.0,
    "sat": lambda x, lo, hi: min(max(x, lo), hi),
    # memory (docs/format.md): the value it starts with, as outside a simulation
    "hyst": lambda x, lo, hi: 1.0 if x >= hi else 0.0,
    "stick": lambda v, f, fs: 1.0 if v == 0 and abs(f) <= fs else 0.0,
}
TOKEN = re.compile(r"\(d[A-Za-z_][\w.]*/d[A-Za-z_][\w.]*\)|#\d+|[A-Za-z_][\w]*(?:\.[A-Za-z_]\w*)*'?"
                   r"|\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?|&&|\|\||[<>=!]=|\S")


def fail(msg):
    print("FAIL " + msg)
    sys.exit(1)


def translate(expr, names, where):
    """Python source for expr; every identifier must be in names."""
    out = []
    for tok in TOKEN.findall(expr):
        if tok[0].isdigit() or tok[0] == "." and len(tok) > 1:
            out.append(tok)
        elif tok in FUNCS:
            out.append("F_" + tok)
        elif tok in ("table", "dtable"):
            out.append("T" if tok == "table" else "DT")
        elif tok[0] == "#":
            if tok not in names:
                fail(f"{where}: table '{tok}' is used in '{expr}' but not defined in the document")
            out.append(repr(tok))
        elif tok[0] == "(" and len(tok) > 1 or tok[0] == "#" or tok[0].isalpha() or tok[0] == "_":
            key = tok[1:-1] if tok[0] == "(" and len(tok) > 1 else tok
            if key not in names:
                fail(f"{where}: '{key}' is used in '{expr}' but not defined in the document")
            out.append(f"V[{key!r}]")
        else:
            out.append({"^": "**", "&&": " and ", "||": " or ", "!": " not "}.get(tok, tok))
    return "".join(out)


def table(x, tab):
    xs, ys = tab["x"], tab["y"]
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    for i in range(len(xs) - 1):
        if xs[i] <= x < xs[i + 1]:
            return ys[i] + (x - xs[i]) / (xs[i + 1] - xs[i]) * (ys[i + 1] - ys[i])
    return ys[-1]


class Doc:
    def __init__(self, d, path):
        self.d, self.path = d, path
        for key in ("format", "version", "parameters", "inputs", "tables", "unknowns",
                    "equations", "rows", "reduced", "definitions", "t0"):
            if key not in d:
                fail(f"{path}: no '{key}'")
        if d["format"] != "bgdraw-equations" or d["version"] != 1:
            fail(f"{path}: format/version {d['format']}/{d['version']}")
        self.names = {"t"} | {p["name"] for p in d["parameters"]} | {i["name"] for i in d["inputs"]}
        self.names |= {t["name"] for t in d["tables"]} | {x["name"] for x in d["definitions"]}
        for u in d["unknowns"]:
            self.names |= {u["name"], u["name"] + "'"} | ({u["signal"]} if "signal" in u else set())
        self.names |= {e["lhs"] for e in d["equations"]}

    def code(self, expr, where):
        src = translate(expr, self.names, f"{self.path}: {where}")
        return compile(src, where, "eval")

    def env(self, t, values):
        V = {"t": t}
        V.update({p["name"]: p["value"] for p in self.d["parameters"]})
        V.update(values)
        tabs = {tb["name"]: tb for tb in self.d["tables"]}
        G = {"F_" + k: f for k, f in FUNCS.items()}
        G["T"] = lambda x, name: table(x, tabs[name])
        G["DT"] = lambda x, name: (table(x + 1e-7, tabs[name]) - table(x - 1e-7, tabs[name])) / 2e-7
        G["V"] = V
        for inp in self.d["inputs"]:
            V[inp["name"]] = eval(self.code(inp["expr"], "input " + inp["name"]), G)
        for df in self.d["definitions"]:
            V[df["name"]] = eval(self.code(df["expr"], "definition " + df["name"]), G)
        return V, G

    def evaluate_all(self, t, values):
        V, G = self.env(t, values)
        for e in self.d["equations"]:
            V[e["lhs"]] = eval(self.code(e["rhs"], "equation " + e["lhs"]), G)
        rows = [eval(self.code(r["expr"], "row " + r["unknown"]), G) for r in self.d["rows"]]
        return V, G, rows


def check(path):
    d = json.load(open(path))
    doc = Doc(d, path)
    rnd = random.Random(12)
    start = {u["name"]: u["initial"] for u in d["unknowns"]}
    start.update({u["signal"]: u["initial"] for u in d["unknowns"] if "signal" in u})
    start.update({u["name"] + "'": 0.0 for u in d["unknowns"]})
    V, G, rows = doc.evaluate_all(d["t0"], start)  # every name resolves, every expression evaluates
    for r in d["reduced"]:
        eval(doc.code(r["rhs"], "reduced " + r["lhs"]), G)
    reads_yp = any("'" in e["rhs"] for e in d["equations"]) or any(
        "'" in r["expr"] for r in d["rows"] if r["type"] == "residual")
    if d["reduced_form"] != "ode" or reads_yp or any(r["kind"] == "dependent" for r in d["reduced"]):
        return 0
    checked = 0
    for _ in range(3):
        x = {u["name"]: rnd.uniform(0.2, 1.5) for u in d["unknowns"] if u["kind"] == "state"}
        t = d["t0"] + rnd.uniform(0.1, 1.0)
        V, G = doc.env(t, dict(x))
        for r in d["reduced"]:
            if r["kind"] == "solved":
                x[r["lhs"]] = eval(doc.code(r["rhs"], "reduced " + r["lhs"]), G)
        x.update({u["signal"]: x[u["name"]] for u in d["unknowns"] if "signal" in u})
        V, G, rows = doc.evaluate_all(t, x)
        by_unknown = {r["unknown"]: (r, v) for r, v in zip(d["rows"], rows)}
        for r in d["reduced"]:
            if r["kind"] != "state":
                continue
            want = eval(doc.code(r["rhs"], "reduced " + r["lhs"]), G)
            row, got = by_unknown[r["lhs"].rstrip("'")]
            if abs(got - want) > 1e-9 * max(1.0, abs(want)):
                fail(f"{path}: {r['lhs']} = {got} from the equations, {want} from the reduced form")
            checked += 1
        for row, v in zip(d["rows"], rows):
            if row["type"] == "residual" and abs(v) > 1e-9 * max(1.0, max(abs(w) for w in x.values())):
                fail(f"{path}: residual of {row['unknown']} is {v} at the reduced form's solution")
    return checked


if __name__ == "__main__":
    total = 0
    for p in sys.argv[1:]:
        total += check(p)
    print(f"equations_json: {len(sys.argv) - 1} documents self-contained, {total} state rows agree")
