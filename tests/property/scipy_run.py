# SPDX-License-Identifier: BSD-3-Clause
"""The property campaign's SciPy side (docs/property.md), run by check.py with
a Python that has NumPy and SciPy (Debian's /usr/bin/python3; tools/deps.sh
--tests): each command writes a CSV on the times of a reference CSV, for
check.py to compare column by column with bgdraw's run.

    scipy_run.py pyexport DIR MODULE REF.csv OUT.csv
        the Python export (-o MODULE.py in DIR): its simulate() on REF's times
    scipy_run.py reduced EQ.json REF.csv OUT.csv
        the reduced form of `--equations json` (key `reduced`: the explicit ODE
        after symbolic elimination) integrated by solve_ivp (Radau) from REF's
        first row; OUT has the states and the dependent stores REF plots
    scipy_run.py step LIN.json REF.csv OUT.csv INPUT DELTA T1
        the state space (A, B, C, D) of `--linear json` driven by a step of
        DELTA at T1 on input INPUT from rest, exactly (the matrix exponential
        of the augmented matrix [[A, B], [0, 0]]): the outputs at REF's times

Exit status 0 with OUT written; 2 with the reason on stderr when the route
does not apply (an expression this evaluator does not know, a dependent
store the export declines): check.py counts that as skipped; 1 on anything
else (a failed integration): a failure.
"""
import csv
import importlib
import json
import math
import re
import sys


class NotApplicable(Exception):
    pass


def read_ref(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(v) for v in r] for r in rows[1:]]


def write(path, head, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(head)
        for r in rows:
            w.writerow(["%.17g" % v for v in r])


def pyexport(folder, module, ref, out):
    import numpy as np
    sys.path.insert(0, folder)
    m = importlib.import_module(module)
    head, rows = read_ref(ref)
    t = np.array([r[0] for r in rows])
    try:
        _, _, y = m.simulate(p=dict(m.PARAMS), rtol=1e-10, atol=1e-12, t_eval=t)
    except NotImplementedError as e:
        raise NotApplicable("the export declines: %s" % e)
    if list(m.OUTPUTS) != head[1:]:
        raise NotApplicable("outputs %s, the CSV's %s" % (m.OUTPUTS[:4], head[1:5]))
    write(out, head, [[t[k]] + list(y[:, k]) for k in range(len(t))])


FUNCS = {
    "sin": math.sin, "cos": math.cos, "tan": math.tan, "exp": math.exp, "log": math.log,
    "sqrt": math.sqrt, "abs": abs, "tanh": math.tanh, "sinh": math.sinh, "cosh": math.cosh,
    "atan": math.atan, "asin": math.asin, "acos": math.acos, "atan2": math.atan2,
    "step": lambda x: 1.0 if x >= 0 else 0.0, "pi": math.pi,
}
NAME = re.compile(r"\(d[A-Za-z_][\w.]*/d[A-Za-z_][\w.]*\)|[A-Za-z_][\w]*(?:\.[A-Za-z_]\w*)*'?")


class Expr:
    """A bgdraw expression of --equations json (docs/json.md, "equations")
    as Python: names become keys of one namespace, ^ becomes **."""
    def __init__(self, text, keys):
        if re.search(r"[<>=!&|]|\bif\(|\btable\(", text):
            raise NotApplicable("a switching or table expression: %s" % text[:60])

        def sub(mm):
            w = mm.group(0)
            if w.startswith("("):
                w = w[1:-1]
            if w in FUNCS:
                return w
            return keys.setdefault(w, "v%d" % len(keys))
        py = NAME.sub(sub, text).replace("^", "**")
        self.code = compile(py, "<expr>", "eval")
        self.text = text


def reduced(eqjson, ref, out):
    from scipy.integrate import solve_ivp
    d = json.load(open(eqjson))
    if d.get("reduced_form") != "ode" or not d.get("reduced"):
        raise NotApplicable("no reduced ODE")
    keys = {}
    env = dict(FUNCS)
    fixed = {}
    for p in d["parameters"]:
        fixed[p["name"]] = p["value"]
    inputs = [(i["name"], Expr(i["expr"], keys)) for i in d["inputs"]]
    defs = [(x["name"], Expr(x["expr"], keys)) for x in d["definitions"]]
    rows = [(r["lhs"], r["kind"], Expr(r["rhs"], keys)) for r in d["reduced"]]
    states = [lhs[:-1] for lhs, kind, _ in rows if kind == "state"]
    head, ref_rows = read_ref(ref)
    if any(s not in head for s in states):
        raise NotApplicable("a state not plotted")
    keys.setdefault("t", "v%d" % len(keys))
    for s in states:
        keys.setdefault(s, "v%d" % len(keys))
    for lhs, kind, _ in rows:
        if kind != "state":
            keys.setdefault(lhs, "v%d" % len(keys))
    known = set(fixed) | {"t"} | set(states) | {n for n, _ in inputs} | {n for n, _ in defs} | \
        {lhs for lhs, kind, _ in rows if kind != "state"}
    if set(keys) - known:
        raise NotApplicable("names the evaluator does not know: %s" % sorted(set(keys) - known)[:3])

    def evaluate(t, x):
        ns = env
        for n, v in fixed.items():
            ns[keys.get(n, "_")] = v
        ns[keys["t"]] = t
        for s, v in zip(states, x):
            ns[keys[s]] = v
        for n, e in inputs + defs:
            ns[keys.get(n, "_")] = eval(e.code, ns)
        dx = []
        for lhs, kind, e in rows:
            v = eval(e.code, ns)
            if kind == "state":
                dx.append(v)
            else:
                ns[keys.get(lhs, "_")] = v
        return ns, dx

    t = [r[0] for r in ref_rows]
    x0 = [ref_rows[0][head.index(s)] for s in states]
    sol = solve_ivp(lambda tt, x: evaluate(tt, x)[1], (t[0], t[-1]), x0, method="Radau", t_eval=t,
                    rtol=1e-11, atol=1e-13)
    if not sol.success:
        print("solve_ivp: %s" % sol.message, file=sys.stderr)
        return 1
    cols = [c for c in head[1:] if c in states or any(c == lhs for lhs, kind, _ in rows if kind == "dependent")]
    res = []
    for k in range(len(sol.t)):
        ns, _ = evaluate(sol.t[k], sol.y[:, k])
        res.append([sol.t[k]] + [ns[keys[c]] for c in cols])
    write(out, ["t"] + cols, res)
    return 0


def step(linjson, ref, out, inp, delta, t1):
    import numpy as np
    from scipy.linalg import expm
    L = json.load(open(linjson))
    ss = L.get("state_space")
    if not ss or ss.get("A") is None:
        raise NotApplicable("no state space")
    n, ni, no = len(ss["states"]), len(L["inputs"]), len(L["outputs"])
    A = np.array(ss["A"], dtype=float).reshape(n, n)
    B = np.array(ss["B"], dtype=float).reshape(n, ni)
    C = np.array(ss["C"], dtype=float).reshape(no, n)
    D = np.array(ss["D"], dtype=float).reshape(no, ni)
    k = L["inputs"].index(inp)
    head, ref_rows = read_ref(ref)
    aug = np.zeros((n + 1, n + 1))
    aug[:n, :n], aug[:n, n] = A, B[:, k] * delta
    res = []
    for r in ref_rows:
        if r[0] < t1:
            res.append([r[0]] + [0.0] * C.shape[0])
            continue
        x = expm(aug * (r[0] - t1))[:n, n]
        res.append([r[0]] + list(C @ x + D[:, k] * delta))
    write(out, ["t"] + list(L["outputs"]), res)
    return 0


def main(argv):
    try:
        if argv[1] == "pyexport":
            return pyexport(*argv[2:6]) or 0
        if argv[1] == "reduced":
            return reduced(*argv[2:5])
        if argv[1] == "step":
            return step(argv[2], argv[3], argv[4], argv[5], float(argv[6]), float(argv[7]))
    except NotApplicable as e:
        print(e, file=sys.stderr)
        return 2
    print("usage: scipy_run.py pyexport|reduced|step ...", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
