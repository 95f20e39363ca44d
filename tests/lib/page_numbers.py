# SPDX-License-Identifier: BSD-3-Clause
"""What the number checks of tests/tutorial.sh and tests/gallery.sh share: reading a
CSV the page's commands wrote (in the folder D), and comparing a number with its
hand-derived value, printed one line each and counted."""
import csv

D = "."
failed = 0


def table(name):
    """The header and the rows of D/name, numbers as floats (other cells as they are)."""
    with open(f"{D}/{name}") as f:
        r = list(csv.reader(f))

    def num(x):
        try:
            return float(x)
        except ValueError:
            return x
    return r[0], [[num(x) for x in row] for row in r[1:]]


def rows(name):
    return table(name)[1]


def at(name, t):
    """The row of time t."""
    return next(r for r in rows(name) if abs(r[0] - t) < 1e-9)


def worst(name, col, f):
    """The largest deviation of column col from f(t) over the rows."""
    return max(abs(r[col] - f(r[0])) for r in rows(name))


def tf_at(tf, s):
    """A transfer function of --linear json (its num and den coefficients, highest power
    first) at the complex frequency s."""
    def poly(c):
        return sum(x * s ** (len(c) - 1 - i) for i, x in enumerate(c))
    return poly(tf["num"]) / poly(tf["den"])


def close(what, got, want, tol):
    global failed
    ok = abs(got - want) <= tol
    print(("ok  " if ok else "FAIL"), f"{what}: {got:.9g} (hand: {want:.9g})")
    failed += not ok
