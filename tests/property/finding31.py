# SPDX-License-Identifier: BSD-3-Clause
"""Finding 31 (docs/property.md): seeds 7724 and 7607, each in its own naming
and in check.py's shuffled renaming (rename_shuffled). Each run must exit 0
and follow an independent solution: the model reduced by hand to an ODE in
two states, integrated by classical Runge-Kutta from the state the run held
(SCAP's free choices decide which stores are dependent, so the two namings
start from different consistent points). The two namings must also agree
with each other, value by value, when the renamed one starts from the
consistent point of the model's own naming.

    python3 finding31.py BGDRAW FOUND_DIR TMPDIR      (found.sh runs it)
"""
import csv
import os
import random
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen  # noqa: E402


def rk4(f, y, times, dt=1e-4):
    """y at each of times, classical Runge-Kutta from times[0] (step 1e-4:
    the same to 1e-9 at 2e-5)."""
    t, out = times[0], []
    for tr in times:
        while t < tr - 1e-12:
            h = min(dt, tr - t)
            k1 = f(y)
            k2 = f([a + h / 2 * b for a, b in zip(y, k1)])
            k3 = f([a + h / 2 * b for a, b in zip(y, k2)])
            k4 = f([a + h * b for a, b in zip(y, k3)])
            y = [a + h / 6 * (b + 2 * c + 2 * d + e) for a, b, c, d, e in zip(y, k1, k2, k3, k4)]
            t += h
        out.append(y)
    return out


def newton(g, dg, x):
    """The root of a monotone scalar law."""
    for _ in range(100):
        x -= g(x) / dg(x)
    return x


def seed7724(col, rows):
    """C1 (cubic) and L3 independent, K1 (a two-port C) dependent through
    T1 in one naming; L3 and K1.pa independent, C1 and K1.pb dependent in
    the other. K1's efforts are (0.681 e_C1, e_C1), so its charges are
    A e_C1 and B e_C1; R2, R3, R4 carry no flow (a 1-junction of three
    resistors alone); R1 reads e_C1."""
    eC = lambda q: q / 1.96 + 0.362 * q ** 3
    deC = lambda q: 1 / 1.96 + 3 * 0.362 * q ** 2
    m11, m12, m22 = 1 / 1.01, 0.525, 1 / 1.35
    det = m11 * m22 - m12 * m12
    A, B = (m22 * 0.681 - m12) / det, (m11 - m12 * 0.681) / det

    def f(y):
        q, p = y
        e = eC(q)
        f6 = -(e / 0.855 if e > 0 else e / 0.55)
        return [(0.681 * p / 1.21 + f6) / (1 + (0.681 * A + B) * deC(q)), -0.681 * e]

    held_pa = col(rows[0], "K1.pa.q") == 0.908
    q0 = newton(lambda q: A * eC(q) - 0.908, lambda q: A * deC(q), -0.488) if held_pa else -0.488
    ref = rk4(f, [q0, 0.44], [r[0] for r in rows])
    return [((col(r, "C1.q"), q), (col(r, "L3.p"), p), (col(r, "K1.pa.q"), A * eC(q)),
             (col(r, "K1.pb.q"), B * eC(q))) for r, (q, p) in zip(rows, ref)]


def seed7607(col, rows):
    """C4 and one of L3 (cubic) and L4 independent, the other dependent
    (L4.p = 1.92 f_L3); C3's charge 0 (its effort is e3, which the loop of
    gain 0.207 through MU1 holds at 0); R2's table and R4's if on L3's flow."""
    fl = lambda p: p / 0.642 + 0.454 * p ** 3
    dfl = lambda p: 1 / 0.642 + 3 * 0.454 * p ** 2
    pts = [(-20, -32.35), (-1, -1.19), (1, 1.19), (20, 32.35)]

    def table(x):
        for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
            if x <= x1 or x1 == pts[-1][0]:
                return y0 + (y1 - y0) * (x - x0) / (x1 - x0)

    def f(y):
        q, p = y
        v = fl(p)
        e12 = -0.241 * v if -v > 0 else -0.878 * v
        return [v, (table(-v) - q / 1.35 + e12) / (1 + 1.92 * dfl(p))]

    held_l4 = col(rows[0], "L4.p") == 0.426
    p0 = newton(lambda p: 1.92 * fl(p) - 0.426, lambda p: 1.92 * dfl(p), 0.0) if held_l4 else -0.795
    ref = rk4(f, [-0.0238, p0], [r[0] for r in rows])
    return [((col(r, "C4.q"), q), (col(r, "L3.p"), p), (col(r, "L4.p"), 1.92 * fl(p)),
             (col(r, "C3.q"), 0.0)) for r, (q, p) in zip(rows, ref)]


def shuffled_names(m, seed):
    """check.py's rename_shuffled map for seed (_invariance)."""
    rng = random.Random(seed * 7919 + 1)
    rng.shuffle(list(range(len(m.elems) + len(m.bonds))))
    new = ["x%d" % i for i in range(len(m.elems))]
    rng.shuffle(new)
    return dict(zip([x.name for x in m.elems], new))


def run(bgdraw, text, path):
    with open(path + ".bg", "w") as f:
        f.write(text)
    p = subprocess.run([bgdraw, path + ".bg", "--simulate", "-o", path + ".csv"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if p.returncode != 0:
        return p.returncode, None, p.stderr.decode()
    rows = list(csv.reader(open(path + ".csv")))
    return 0, (rows[0], [[float(v) for v in r] for r in rows[1:]]), ""


def start_from(text, m, nm, header, row):
    """The renamed text with every store's initial value that of row (a run
    of the model's own naming)."""
    for x in m.elems:
        if not x.states or x.kind not in ("C", "I", "CF"):
            continue
        vals = [row[header.index("%s.%s" % (x.name, s))] for s in x.states]
        init = "%.17g" % vals[0] if len(vals) == 1 else "(%s)" % ", ".join("%.17g" % v for v in vals)
        text = re.sub(r"(\n\S+\s+%s\b[^\n]*\[[qp]0 = )[^\]]+\]" % re.escape(nm[x.name]),
                      lambda mm: mm.group(1) + init + "]", text)
    return text


def main():
    bgdraw, here, tmp = sys.argv[1:4]
    bad = 0
    for seed, ref in ((7724, seed7724), (7607, seed7607)):
        m = gen.parse(open(os.path.join(here, "found", "seed%d_shuffled_outcome.bg" % seed)).read())
        nm = shuffled_names(m, seed)
        back = {v: k for k, v in nm.items()}
        own = None
        for label, text in (("own naming", m.text()), ("shuffled naming", m.text(names=nm)),
                            ("shuffled from the own start", None)):
            if text is None:
                if own is None:
                    continue
                text = start_from(m.text(names=nm), m, nm, *own)
            st, res, err = run(bgdraw, text, os.path.join(tmp, "f31_%d" % seed))
            if st != 0:
                print("  seed %d %s: exit %d: %s" % (seed, label, st, err.strip().splitlines()[-1]))
                bad = 1
                continue
            h, rows = res
            # the columns by the model's names (x4.pa.q -> K1.pa.q)
            h = [back.get(c.split(".")[0], c.split(".")[0]) + c[len(c.split(".")[0]):] for c in h]
            col = lambda r, n: r[h.index(n)]
            worst = max(abs(a - b) / max(abs(b), 1e-3) for r in ref(col, rows) for a, b in r)
            msg = "  seed %d %s: from Runge-Kutta %.2g" % (seed, label, worst)
            bad |= worst > 1e-5
            if label == "own naming":
                own, own_rows = (h, rows[0]), rows
            elif label.endswith("own start"):
                same = max(abs(a - b) / max(abs(a), abs(b), 1e-3)
                           for ra, rb in zip(own_rows, rows) for a, b in zip(ra, rb))
                msg += ", from the own naming's run %.2g" % same
                bad |= same > 1e-5 or len(rows) != len(own_rows)
            print(msg)
    return bad


if __name__ == "__main__":
    sys.exit(main())
