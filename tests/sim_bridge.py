# SPDX-License-Identifier: BSD-3-Clause
"""A diode bridge started on its switching point (docs/simulation.md,
"Starting on a switching point"): four diodes f = if(e > 0, e/Ron, e/Roff),
a sine source, a load RL || CL. At t = 0 every diode sits at its threshold.
bgdraw runs it at the default tolerances from t = 0; this checks every row
against an independent integration:

    the source between a and b (b the reference), diodes D1 a->p, D2 b->p,
    D3 n->a, D4 n->b; with V = V_p - V_n the capacitor voltage, V_n solves
    i1 + i2 = i3 + i4 (the current into p leaves n), a monotone equation
    (brentq); C V' = i1 + i2 - V/RL. SciPy's DOP853 at rtol 1e-12 from V = 0,
    restarted at every zero of a diode voltage.

    python3 tests/sim_bridge.py BGDRAW MODEL TMPDIR
"""
import os
import subprocess
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pwaffine  # noqa: E402

A, W, RON, ROFF, RL, CL = 10.0, 314.159, 0.1, 1e6, 100.0, 1e-4


def g(e):
    return e / RON if e > 0 else e / ROFF


def diodes(t, V):
    U = A * np.sin(W * t)
    def F(vn):
        vp = vn + V
        return g(U - vp) + g(-vp) - g(vn - U) - g(vn)
    lo, hi = -2 * A - abs(V) - 1, 2 * A + abs(V) + 1
    vn = brentq(F, lo, hi, xtol=1e-15, rtol=1e-15, maxiter=500)
    vp = vn + V
    return U, vp, vn, (U - vp, -vp, vn - U, vn)


def rhs(t, x):
    U, vp, vn, e = diodes(t, x[0])
    return [(g(e[0]) + g(e[1]) - x[0] / RL) / CL]


def exact(T):
    evs = []
    for k in range(4):
        f = lambda t, x, k=k: diodes(t, x[0])[3][k]
        f.terminal = True
        evs.append(f)
    t, x, out = 0.0, [0.0], []
    j = 0
    while t < T[-1]:
        # leave the switching point before looking for the next one
        t1 = min(t + 1e-9, T[-1])
        s = solve_ivp(rhs, (t, t1), x, method="DOP853", rtol=1e-12, atol=1e-15)
        t, x = t1, s.y[:, -1]
        s = solve_ivp(rhs, (t, T[-1]), x, method="DOP853", rtol=1e-12, atol=1e-15, events=evs,
                      dense_output=True, max_step=1e-4)
        while j < len(T) and T[j] <= s.t[-1]:
            out.append(s.sol(T[j])[0] if T[j] >= t else x[0])
            j += 1
        t, x = s.t[-1], s.y[:, -1]
    while j < len(T):
        out.append(x[0])
        j += 1
    return np.array(out)


def main():
    bgdraw, model, tmp = sys.argv[1:4]
    csv = os.path.join(tmp, "bridge.csv")
    subprocess.run([bgdraw, model, "--simulate", "-q", "-o", csv], check=True)
    head, rows = pwaffine.read_csv(csv)
    T = rows[:, 0]
    V = exact(T)
    err = pwaffine.rel_error(rows[:, head.index("CL0.e")], V)
    cur = np.array([[g(e) for e in diodes(t, v)[3]] for t, v in zip(T, rows[:, head.index("CL0.e")])])
    ierr = max(pwaffine.rel_error(rows[:, head.index("D%d.f" % (k + 1))], cur[:, k]) for k in range(4))
    ok = T[0] == 0 and len(T) == 501 and err <= 1e-6 and ierr <= 1e-6
    print("%s bridge from t = 0: CL0.e within %.2g of its range, diode currents %.2g (of their own voltages)"
          % ("ok" if ok else "FAIL", err, ierr))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
