# SPDX-License-Identifier: BSD-3-Clause
"""Exact solutions of piecewise affine systems, for the simulation tests.

A model whose every mode is linear with inputs that are themselves solutions
of linear ODEs (constants, sines) is, in each mode, z' = A_mode z on an
augmented state z (the states, then sin, cos, 1 ...). Its solution is
z(t) = expm(A (t - t_k)) z_k, exact to round-off; the switching times are the
roots of guard functions c . z(t), found by bisection (brentq) on that
closed form. Nothing here reads bgdraw's equations: each test builds A and
the guards from the model's physics.

    modes = {name: (A, [(c, next_mode_or_function), ...]), ...}
    T, Z, events = solve(modes, mode0, z0, times, h)

A guard fires when c . z rises through 0 (from < 0 to >= 0); write a falling
condition as -c. `next` is a mode name or a function (z) -> (mode, z) for a
mode change that also resets the state (a relay's memory is the mode itself).
h is the scan step: shorter than any time a guard can stay positive, so no
crossing hides between two scan points.
"""
import numpy as np
from scipy.linalg import expm
from scipy.optimize import brentq


def solve(modes, mode0, z0, times, h, max_events=100000):
    times = np.asarray(times, float)
    out = np.zeros((len(times), len(z0)))
    z = np.asarray(z0, float).copy()
    t, mode, j = float(times[0]), mode0, 0
    events = []
    t_end = float(times[-1])
    while True:
        A, guards = modes[mode]
        Eh = expm(A * h)
        zk, tau, hit = z.copy(), 0.0, None
        while t + tau < t_end and hit is None:
            step = min(h, t_end - t - tau)
            zn = Eh @ zk if step == h else expm(A * step) @ zk
            for gi, (c, nxt) in enumerate(guards):
                g0, g1 = float(np.dot(c, zk)), float(np.dot(c, zn))
                if g0 < 0 <= g1:
                    f = lambda s: float(np.dot(c, expm(A * s) @ z))
                    r = brentq(f, tau, tau + step, xtol=1e-15, rtol=4 * np.finfo(float).eps, maxiter=300)
                    if hit is None or r < hit[0]:
                        hit = (r, nxt)
            zk, tau = zn, tau + step
        t_next = t + hit[0] if hit else t_end
        while j < len(times) and times[j] <= t_next:
            out[j] = expm(A * (times[j] - t)) @ z
            j += 1
        if hit is None:
            break
        z = expm(A * hit[0]) @ z
        t = t_next
        nxt = hit[1]
        mode, z = nxt(z) if callable(nxt) else (nxt, z)
        events.append((t, mode))
        if len(events) > max_events:
            raise RuntimeError("too many events")
    while j < len(times):  # rows at t_end exactly (rounding)
        out[j] = z
        j += 1
    return times, out, events


def sine_rows(w):
    """The augmented block of sin(w t), cos(w t): s' = w c, c' = -w s."""
    return np.array([[0, w], [-w, 0]], float)


def read_csv(path):
    with open(path) as f:
        head = f.readline().strip().split(",")
    rows = np.loadtxt(path, delimiter=",", skiprows=1, comments="#", ndmin=2)
    return head, rows


def rel_error(got, want):
    """Largest deviation over the range of the exact values (as --verify measures)."""
    rng = np.max(want) - np.min(want)
    if rng <= 0:
        rng = max(np.max(np.abs(want)), 1.0)
    return float(np.max(np.abs(got - want)) / rng)
