# SPDX-License-Identifier: BSD-3-Clause
"""--verify's error bound against the true error (docs/simulation.md,
"Verification"): on every model of the test suite with an exact answer, at
the default tolerances and at looser ones, the bound --verify states (JSON
simulation.verify.bound: twice the largest deviation of any output or state
from the run 100 times tighter) is at least the true error of every output,
each relative to its exact range; every state is an output here (plot lists
them), so the states are held to it too.

    python3 tests/verify_bound.py BGDRAW TMPDIR

Exact answers: the series RLC's step response (rlc.bg), a chain of damped
masses (matrix exponential), the bouncing ball and the gear backlash (exact
piecewise solutions, tests/pwaffine.py).
"""
import json
import math
import os
import subprocess
import sys

import numpy as np
from scipy.linalg import expm

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pwaffine  # noqa: E402
import sim_accuracy  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def rlc_text(extra):
    src = open(os.path.join(ROOT, "examples", "rlc.bg")).read()
    return src.replace("simulate t_end = 2e-3, dt = 1e-6", "simulate t_end = 2e-3, dt = 1e-6" + extra)


def rlc_exact(T):
    R, L, C, V = 10.0, 1e-3, 1e-6, 1.0
    a = R / (2 * L)
    wd = math.sqrt(1 / (L * C) - a * a)
    vc = np.array([V * (1 - math.exp(-a * t) * (math.cos(wd * t) + a / wd * math.sin(wd * t))) for t in T])
    i = np.array([V / (L * wd) * math.exp(-a * t) * math.sin(wd * t) for t in T])
    return {"C1.e": vc, "L1.f": i}


def chain_text(extra, n=5):
    out = ["model chain", "param k = 1, b = 0.1, m = 1", "Se F = 1"]
    for i in range(1, n + 1):
        out += ["1 v%d" % i, "I M%d = m" % i, "R B%d = b" % i]
    for i in range(1, n):
        out += ["0 s%d" % i, "C K%d = 1/k" % i]
    out.append("bond F -> v1")
    for i in range(1, n + 1):
        out += ["bond v%d -> M%d" % (i, i), "bond v%d -> B%d" % (i, i)]
    for i in range(1, n):
        out += ["bond v%d -> s%d" % (i, i), "bond s%d -> K%d" % (i, i), "bond s%d -> v%d" % (i, i + 1)]
    out.append("simulate t_end = 10, dt = 0.05" + extra)
    out.append("plot " + ", ".join(["M%d.p" % i for i in range(1, n + 1)] + ["K%d.q" % i for i in range(1, n)]))
    return "\n".join(out) + "\n"


def chain_exact(T, n=5):
    N = 2 * n - 1
    A = np.zeros((N + 1, N + 1))
    for i in range(n):
        A[i, i] = -0.1
        if i > 0:
            A[i, n + i - 1] += 1
        if i < n - 1:
            A[i, n + i] -= 1
    for j in range(n - 1):
        A[n + j, j], A[n + j, j + 1] = 1, -1
    A[0, N] = 1
    x0 = np.zeros(N + 1)
    x0[N] = 1
    X = np.array([expm(A * t) @ x0 for t in T])
    d = {"M%d.p" % (i + 1): X[:, i] for i in range(n)}
    d.update({"K%d.q" % (j + 1): X[:, n + j] for j in range(n - 1)})
    return d


def ball_text(extra):
    return "\n".join([
        "model ball", "param m0 = 1, g0 = 9.81, k0 = 1e4, c0 = 20, h0 = 1", "Se G = -m0*g0", "1 v",
        "I M = m0", "C K : e = if(q < 0, k0*q, 0) [q0 = h0]", "R D : e = if(K.q < 0, c0*f, 0)",
        "bond G -> v", "bond v -> M", "bond v -> K", "bond v -> D",
        "simulate t_end = 2" + extra, "plot K.q, M.p", ""])


def ball_exact(T):
    m, g, k, c = 1.0, 9.81, 1e4, 20.0
    fly = np.zeros((3, 3))  # z = (q, p, 1)
    fly[0, 1], fly[1, 2] = 1 / m, -m * g
    hit = fly.copy()
    hit[1, 0], hit[1, 1] = -k, -c / m
    q = np.eye(3)[0]
    modes = {"fly": (fly, [(-q, "hit")]), "hit": (hit, [(q, "fly")])}
    _, Z, _ = pwaffine.solve(modes, "fly", [1, 0, 1], T, 2 * np.pi / math.sqrt(k / m) / 200)
    return {"K.q": Z[:, 0], "M.p": Z[:, 1]}


def backlash_text(extra):
    return sim_accuracy.model_text(sim_accuracy.BASE, 6, extra)


def backlash_exact(T):
    _, Z, _ = sim_accuracy.exact(sim_accuracy.BASE, T)
    return {"L.f": Z[:, 1] / sim_accuracy.BASE["J"], "S.q": Z[:, 0]}


CASES = [
    ("rlc", rlc_text, rlc_exact, ["", ", rtol = 1e-4", ", rtol = 1e-2"]),
    ("chain", chain_text, chain_exact, ["", ", rtol = 1e-4", ", rtol = 1e-3"]),
    ("ball", ball_text, ball_exact, ["", ", rtol = 1e-7", ", rtol = 1e-5"]),
    ("backlash", backlash_text, backlash_exact, ["", ", rtol = 1e-7", ", rtol = 1e-5"]),
]


def main():
    bgdraw, tmp = sys.argv[1], sys.argv[2]
    fails = 0
    for name, text, exact, tols in CASES:
        for extra in tols:
            bg, csv, js = (os.path.join(tmp, name + x) for x in (".bg", ".csv", ".json"))
            open(bg, "w").write(text(extra))
            subprocess.run([bgdraw, bg, "--verify", "-q", "-o", csv, "-o", js], check=True)
            head, rows = pwaffine.read_csv(csv)
            v = json.load(open(js))["simulation"]["verify"]
            want = exact(rows[:, 0])
            errs = {k: pwaffine.rel_error(rows[:, head.index(k)], w) for k, w in want.items()}
            worst = max(errs, key=errs.get)
            ok = v["bound"] >= errs[worst] and v["states"] is not None
            fails += not ok
            print("%s %s [%s]: bound %.3g, true error %.3g (%s)" % ("ok" if ok else "FAIL", name,
                  extra.strip(", ") or "default", v["bound"], errs[worst], worst))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
