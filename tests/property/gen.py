# SPDX-License-Identifier: BSD-3-Clause
"""Random valid bond graphs for the property campaign (docs/property.md).

A model is kept as data (elements, bonds) so that the checker can rename,
reorder and renumber it, and the shrinker can drop parts of it; `text()`
writes it in the .bg language. Everything is drawn from random.Random(seed):
the same seed gives the same model, byte for byte.

Classes: "lossless" (C, I, TF/GY/MTF/MGY, junctions), "passive" (the same
and R >= 0), "driven" (any of it and sources, modulated ones included).
Valid by construction: every bond numbered, every junction with two bonds
or more, every one-port with one, every two-port with one bond in and one
out. Causality may be incomplete or in conflict: the checks that need
equations are then counted as skipped.
"""
import random


class Elem:
    """kind: 0 1 C I R Se Sf MSe MSf TF GY MTF MGY. `decl` is the text after
    the name (`= 2` or `: e = ...`); `energy(x)` the stored energy of a store
    as a function of its state (None for others)."""

    def __init__(self, kind, name, decl="", energy=None, mods=()):
        self.kind, self.name, self.decl, self.energy = kind, name, decl, energy
        self.mods = list(mods)  # names of elements its expression reads


class Model:
    def __init__(self, cls):
        self.cls = cls
        self.elems = []          # Elem, in statement order
        self.bonds = []          # [number, tail name, head name]
        self.sim = ""            # the simulate statement

    def elem(self, name):
        for x in self.elems:
            if x.name == name:
                return x
        return None

    def copy(self):
        m = Model(self.cls)
        m.elems = list(self.elems)
        m.bonds = [list(b) for b in self.bonds]
        m.sim = self.sim
        return m

    def stores(self):
        return [x for x in self.elems if x.kind in ("C", "I")]

    def plot_columns(self):
        """The plot expressions (model names), in a fixed logical order: every
        bond's effort and flow, then every store's state."""
        cols = []
        for b in self.bonds:
            cols += ["e%d" % b[0], "f%d" % b[0]]
        for x in self.stores():
            cols.append("%s.%s" % (x.name, "q" if x.kind == "C" else "p"))
        return cols

    def text(self, names=None, order=None, numbers=None):
        """The .bg text. names: old -> new element names; order: a
        permutation of the statements (elements then bonds); numbers: old ->
        new bond numbers. The plot keeps its logical order so that the CSV
        columns of two variants line up."""
        nm = names or {}
        num = numbers or {}
        rn = lambda s: _rename(s, nm, num)
        stmts = []
        for x in self.elems:
            stmts.append("%-3s %s %s" % (x.kind, nm.get(x.name, x.name), rn(x.decl)))
        for b in self.bonds:
            stmts.append("bond %d %s -> %s" % (num.get(b[0], b[0]), nm.get(b[1], b[1]),
                                               nm.get(b[2], b[2])))
        if order:
            stmts = [stmts[i] for i in order]
        cols = [rn(c) for c in self.plot_columns()]
        out = ["model prop \"generated (%s)\"" % self.cls] + stmts
        out.append(self.sim)
        out.append("plot " + ", ".join(cols))
        return "\n".join(out) + "\n"


def _rename(s, nm, num):
    """Renames element names (NAME.x) and bond variables (e7, f7) inside an
    expression written by this generator."""
    import re

    def sub(m):
        w = m.group(0)
        if w in nm:
            return nm[w]
        mm = re.fullmatch(r"([ef])(\d+)", w)
        if mm and int(mm.group(2)) in num:
            return mm.group(1) + str(num[int(mm.group(2))])
        return w
    return re.sub(r"[A-Za-z_][A-Za-z_0-9]*", sub, s)


def _val(rng, lo=0.5, hi=2.0):
    return float("%.3g" % rng.uniform(lo, hi))


def generate(seed, max_elems=100):
    rng = random.Random(seed)
    cls = rng.choice(["lossless", "passive", "passive", "driven"])
    m = Model(cls)
    target = 2 + int((max_elems - 2) * rng.random() ** 2)
    counter = {}

    def name(prefix):
        counter[prefix] = counter.get(prefix, 0) + 1
        return "%s%d" % (prefix, counter[prefix])

    def add(e):
        m.elems.append(e)
        return e

    stores = []

    def one_port(kind):
        n = name({"C": "C", "I": "L", "R": "R", "Se": "U", "Sf": "F",
                  "MSe": "MU", "MSf": "MF"}[kind])
        if kind in ("C", "I"):
            k = _val(rng)
            x0 = float("%.3g" % rng.uniform(-1, 1))
            st, opt = ("q", "q0") if kind == "C" else ("p", "p0")
            if rng.random() < 0.25:
                a = _val(rng, 0.05, 0.5)
                var = "e" if kind == "C" else "f"
                decl = ": %s = %s/%g + %g*%s^3 [%s = %g]" % (var, st, k, a, st, opt, x0)
                en = (lambda k, a: lambda x: x * x / (2 * k) + a * x ** 4 / 4)(k, a)
            else:
                decl = "= %g [%s = %g]" % (k, opt, x0)
                en = (lambda k: lambda x: x * x / (2 * k))(k)
            e = add(Elem(kind, n, decl, en))
            stores.append(e)
            return e
        if kind == "R":
            r = _val(rng, 0.2, 2)
            u = rng.random()
            if u < 0.6:
                return add(Elem(kind, n, "= %g" % r))
            if u < 0.8:
                return add(Elem(kind, n, ": e = %g*f + %g*f^3" % (r, _val(rng, 0.05, 0.5))))
            return add(Elem(kind, n, ": f = %g*e" % r))
        if kind in ("Se", "Sf"):
            u = rng.random()
            if u < 0.4:
                return add(Elem(kind, n, "= %g" % _val(rng)))
            if u < 0.7:
                return add(Elem(kind, n, "= %g*sin(%g*t)" % (_val(rng), _val(rng))))
            return add(Elem(kind, n, "= %g*step(t - %g)" % (_val(rng), _val(rng, 0.1, 1))))
        # modulated source: reads a store's state when there is one
        if stores:
            s = rng.choice(stores)
            st = "q" if s.kind == "C" else "p"
            return add(Elem(kind, n, "= %g*%s.%s" % (_val(rng, 0.1, 0.5), s.name, st), mods=[s.name]))
        return add(Elem(kind, n, "= %g*cos(t)" % _val(rng)))

    kinds = ["C", "I"]
    if cls != "lossless":
        kinds += ["R"]
    if cls == "driven":
        kinds += ["Se", "Sf", "MSe", "MSf"]

    # two one-ports on one bond: the smallest models
    if target <= 3 and rng.random() < 0.5:
        a = one_port(rng.choice(kinds))
        b = one_port(rng.choice(["C", "I"] + (["R"] if cls != "lossless" else [])))
        m.bonds.append([1, a.name, b.name] if rng.random() < 0.5 else [1, b.name, a.name])
        return _finish(m, rng)

    nj = max(1, target // 3)
    juncs = []
    bonds = []
    for i in range(nj):
        j = add(Elem(rng.choice("01"), name("j")))
        juncs.append(j)
        if i == 0:
            continue
        other = rng.choice(juncs[:-1])
        a, b = (other, j) if rng.random() < 0.5 else (j, other)
        if rng.random() < 0.3:  # through a two-port, either direction
            tk = rng.choice(["TF", "GY", "MTF", "MGY"])
            tn = name("T" if "TF" in tk else "G")
            if tk in ("TF", "GY"):
                decl = "= %g" % _val(rng)
                mods = []
            elif stores and rng.random() < 0.5:
                s = rng.choice(stores)
                st = "q" if s.kind == "C" else "p"
                decl = "= %g + %g*%s.%s^2" % (_val(rng), _val(rng, 0.05, 0.3), s.name, st)
                mods = [s.name]
            else:
                decl = "= %g + %g*sin(t)" % (_val(rng, 1, 2), _val(rng, 0.1, 0.5))
                mods = []
            add(Elem(tk, tn, decl, mods=mods))
            bonds += [[a.name, tn], [tn, b.name]]
        else:
            bonds.append([a.name, b.name])
    # a few extra junction-junction bonds: loops of junctions
    for _ in range(rng.randrange(0, 1 + nj // 4)):
        if nj < 2:
            break
        a, b = rng.sample(juncs, 2)
        bonds.append([a.name, b.name])
    degree = {j.name: 0 for j in juncs}
    for b in bonds:
        for x in b:
            if x in degree:
                degree[x] += 1
    # one-ports: at least one per junction, more up to the target size
    left = max(0, target - len(m.elems))
    homes = list(juncs)
    homes += [rng.choice(juncs) for _ in range(max(0, left - nj))]
    for j in homes:
        e = one_port(rng.choice(kinds))
        out = e.kind in ("Se", "Sf", "MSe", "MSf")
        if rng.random() < 0.25:
            out = not out  # the other direction: same physics
        bonds.append([e.name, j.name] if out else [j.name, e.name])
        degree[j.name] += 1
    for j in juncs:  # every junction has two bonds or more
        while degree[j.name] < 2:
            e = one_port(rng.choice(kinds))
            bonds.append([j.name, e.name])
            degree[j.name] += 1
    rng.shuffle(bonds)
    m.bonds = [[i + 1, a, b] for i, (a, b) in enumerate(bonds)]
    return _finish(m, rng)


def _finish(m, rng):
    t_end = rng.choice([1, 2, 3])
    m.sim = "simulate t_end = %g, dt = %g, rtol = 1e-9, atol = 1e-11" % (t_end, t_end / 40)
    return m
