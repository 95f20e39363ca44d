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
    """kind: 0 1 C I R Se Sf MSe MSf TF GY MTF MGY, CF and RF (a C or R field
    of two ports), De and Df (detectors), LC and RLC (instances of the
    submodels of SUBMODELS). `decl` is the text after the name (`= 2` or
    `: e = ...`); `states` the state variables after `NAME.` (`q`, `pa.q`,
    `c.q`); `energy(*x)` the stored energy as a function of them (None for
    elements that store none); `ports` the port names of a multiport (bond
    ends `NAME.port`)."""

    def __init__(self, kind, name, decl="", energy=None, mods=(), states=None, ports=()):
        self.kind, self.name, self.decl, self.energy = kind, name, decl, energy
        self.mods = list(mods)  # names of elements its expression reads
        self.word = {"CF": "C", "RF": "R"}.get(kind, kind)  # the statement's first word
        if states is None:
            states = ["q"] if kind == "C" else ["p"] if kind == "I" else []
        self.states = list(states)
        self.ports = list(ports)


# Two submodels the generator instantiates as one-ports (port a): a lossless
# series LC and a passive series RLC. Written before the model's statements.
SUBMODELS = {
    "LC": """submodel LC(k = 1, m = 1)
  port a
  1 s
  C c = k
  I l = m
  bond a -> s
  bond s -> c
  bond s -> l
end""",
    "RLC": """submodel RLC(k = 1, m = 1, r = 1)
  port a
  1 s
  C c = k
  I l = m
  R d = r
  bond a -> s
  bond s -> c
  bond s -> l
  bond s -> d
end""",
}


def base(end):
    """The element of a bond end (`K1.pa` -> `K1`)."""
    return end.split(".")[0]


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
        """Elements with states (C, I, C fields, instances), in order."""
        return [x for x in self.elems if x.states]

    def detectors(self):
        return [x for x in self.elems if x.kind in ("De", "Df")]

    def plot_columns(self):
        """The plot expressions (model names), in a fixed logical order: every
        bond's effort and flow, then every state, then every detector."""
        cols = []
        for b in self.bonds:
            cols += ["e%d" % b[0], "f%d" % b[0]]
        for x in self.stores():
            cols += ["%s.%s" % (x.name, v) for v in x.states]
        cols += [x.name for x in self.detectors()]
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
            stmts.append("%-3s %s %s" % (x.word, nm.get(x.name, x.name), rn(x.decl)))
        for b in self.bonds:
            stmts.append("bond %d %s -> %s" % (num.get(b[0], b[0]), rn(b[1]), rn(b[2])))
        if order:
            stmts = [stmts[i] for i in order]
        cols = [rn(c) for c in self.plot_columns()]
        subs = sorted({x.kind for x in self.elems if x.kind in SUBMODELS})
        out = ["model prop \"generated (%s)\"" % self.cls] + [SUBMODELS[k] for k in subs] + stmts
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


# One model in SINGULAR_EVERY is made singular on purpose (a junction pair
# joined by two bonds, or in a driven model two sources setting one
# junction's effort or flow): the runs must refuse it with the reason, and
# the methods' predictions on a singular pencil must agree (findings 5, 6,
# 14 and 18 came from such models). Elsewhere the generator avoids the two
# structures that made a quarter of its models singular before
# (docs/property.md, "Singular pencils"): a loop of junctions inside one
# lock group, and a second source fixing a lock group's variable.
SINGULAR_EVERY = 16
SOURCE_SHARE = 0.3     # of a driven model's one-ports
AGAINST_SHARE = 0.3    # of its sources: an effort source on a 0-junction, a flow source on a 1-junction


class Groups:
    """Lock groups of junctions (union-find): a 0-junction's effort and a
    1-junction's flow, tied by a direct bond between junctions of one kind
    (a common effort or flow), a TF or MTF between junctions of one kind (a
    ratio) or a GY or MGY between junctions of two kinds (e of one = r f of
    the other); `pure` ties by direct bonds alone. One source fixing a
    group's variable (an effort source on a 0-junction of it, a flow source
    on a 1-junction) makes its stores dependent (derivative causality, an
    index reduction), and so does a loop inside a group through a two-port
    (1-junctions joined directly and through a TF of ratio n: (1 - n) f = 0,
    finding 13): the group is locked. A second lock is a conflict, and a
    bond closing a loop inside a pure group leaves a circulating flow or
    effort that nothing sets: both singular pencils."""

    def __init__(self, juncs):
        self.up = {j.name: j.name for j in juncs}
        self.pure = {j.name: j.name for j in juncs}
        self.kind = {j.name: j.kind for j in juncs}
        self.locked = set()

    @staticmethod
    def _find(up, a):
        while up[a] != a:
            up[a] = up[up[a]]
            a = up[a]
        return a

    def find(self, a):
        return self._find(self.up, a)

    def ties(self, a, b, two_port=None):
        """Whether a bond (two_port None) or a two-port between junctions a
        and b ties their variables."""
        same = self.kind[a] == self.kind[b]
        return same if two_port in (None, "TF", "MTF") else not same

    def closes(self, a, b):
        """What a new bond between junctions a and b makes: "singular" (a
        loop inside a pure group), "lock" (a loop inside a group through a
        two-port, the group free: an index above 1), "conflict" (the same
        in a locked group) or None (no loop inside a group)."""
        if not self.ties(a, b) or self.find(a) != self.find(b):
            return None
        if self._find(self.pure, a) == self._find(self.pure, b):
            return "singular"
        return "conflict" if self.find(a) in self.locked else "lock"

    def add(self, name, like):
        """A new junction tied to junction like by a bond."""
        self.up[name], self.pure[name], self.kind[name] = like, like, self.kind[like]

    def join(self, a, b, two_port=None):
        if self.ties(a, b, two_port):
            ra, rb = self.find(a), self.find(b)
            if ra != rb:
                self.up[ra] = rb
                if ra in self.locked:
                    self.locked.add(rb)
            if two_port is None:
                self.pure[self._find(self.pure, a)] = self._find(self.pure, b)


def generate(seed, max_elems=100):
    rng = random.Random(seed)
    cls = rng.choice(["lossless", "passive", "passive", "driven"])
    m = Model(cls)
    target = 2 + int((max_elems - 2) * rng.random() ** 2)
    singular = rng.randrange(SINGULAR_EVERY) == 0
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
            if u < 0.5:
                return add(Elem(kind, n, "= %g" % r))
            if u < 0.65:
                return add(Elem(kind, n, ": e = %g*f + %g*f^3" % (r, _val(rng, 0.05, 0.5))))
            if u < 0.75:
                return add(Elem(kind, n, ": f = %g*e" % r))
            if u < 0.88:  # a switching law (events): two slopes, passive
                return add(Elem(kind, n, ": e = if(f > 0, %g*f, %g*f)" % (r, _val(rng, 0.2, 2))))
            # a table through the origin, increasing: passive, kinks at +-1
            # (none at 0, where a model starting at rest would sit)
            r2 = _val(rng, 0.2, 2)
            return add(Elem(kind, n, ": e = table(f, [-20, %g; -1, %g; 1, %g; 20, %g])" % (
                -r - 19 * r2, -r, r, r + 19 * r2)))
        if kind in ("Se", "Sf"):
            u = rng.random()
            if u < 0.35:
                return add(Elem(kind, n, "= %g" % _val(rng)))
            if u < 0.6:
                return add(Elem(kind, n, "= %g*sin(%g*t)" % (_val(rng), _val(rng))))
            if u < 0.85:
                return add(Elem(kind, n, "= %g*step(t - %g)" % (_val(rng), _val(rng, 0.1, 1))))
            return add(Elem(kind, n, "= table(t, [0, 0; %g, %g; 3, %g])" % (
                _val(rng, 0.2, 1), _val(rng), _val(rng))))
        # modulated source: reads a detector or a store's state when there is one
        dets = [x for x in m.elems if x.kind in ("De", "Df")]
        if dets and rng.random() < 0.5:
            d = rng.choice(dets)
            return add(Elem(kind, n, "= %g*%s" % (_val(rng, 0.1, 0.5), d.name), mods=[d.name]))
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
    passive_kinds = [k for k in kinds if k in ("C", "I", "R")]

    def kind_at(j, first=False):
        """A one-port's kind for junction j: in a driven model a source for
        SOURCE_SHARE of them, mostly one that adds to the junction (a flow
        source on a 0-junction, an effort source on a 1-junction), else one
        that fixes its lock group's variable when nothing fixes it yet. A
        junction's first one-port is a C, I or R: a junction of two bonds,
        one a source, passes the source on (an effort source on a two-bond
        1-junction sets the effort of the 0-junction beyond it)."""
        if cls != "driven" or first or rng.random() >= SOURCE_SHARE:
            return rng.choice(passive_kinds)
        against = rng.random() < AGAINST_SHARE and groups.find(j.name) not in groups.locked
        if against:
            groups.locked.add(groups.find(j.name))
        k = ("Se" if j.kind == "0" else "Sf") if against else ("Sf" if j.kind == "0" else "Se")
        return ("M" + k) if rng.random() < 0.4 else k

    # two one-ports on one bond: the smallest models
    if target <= 3 and rng.random() < 0.5:
        a = one_port(rng.choice(kinds))
        b = one_port(rng.choice(["C", "I"] + (["R"] if cls != "lossless" else [])))
        m.bonds.append([1, a.name, b.name] if rng.random() < 0.5 else [1, b.name, a.name])
        return _finish(m, rng)

    nj = max(1, target // 3)
    juncs = []
    bonds = []
    links = []  # (a, b, two-port kind or None) between junctions, for the lock groups
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
            links.append((a.name, b.name, tk))
        else:
            bonds.append([a.name, b.name])
            links.append((a.name, b.name, None))
    groups = Groups(juncs)
    for a, b, tk in links:
        groups.join(a, b, tk)
    # a few extra junction-junction bonds: loops of junctions; one that
    # leaves a circulating flow or effort free, or locks a group twice, only
    # in a model singular on purpose (Groups)
    for _ in range(rng.randrange(0, 1 + nj // 4)):
        if nj < 2:
            break
        a, b = rng.sample(juncs, 2)
        made = groups.closes(a.name, b.name)
        if made in ("singular", "conflict") and not singular:
            continue
        if made == "lock":
            groups.locked.add(groups.find(a.name))
        bonds.append([a.name, b.name])
        groups.join(a.name, b.name)
    if singular and (cls != "driven" or rng.random() < 0.5):
        # a new junction of j's kind joined to j by two bonds: the split of
        # the flow (effort) between them is undetermined
        j = rng.choice(juncs)
        jn = add(Elem(j.kind, name("j")))
        juncs.append(jn)
        groups.add(jn.name, j.name)
        bonds += [[j.name, jn.name], [j.name, jn.name] if rng.random() < 0.5 else [jn.name, j.name]]
        singular = False
    degree = {j.name: 0 for j in juncs}
    for b in bonds:
        for x in b:
            if x in degree:
                degree[x] += 1
    # detectors on junctions (a modulated source may read one)
    if rng.random() < 0.3:
        for _ in range(rng.choice([1, 1, 2])):
            j = rng.choice(juncs)
            add(Elem("De" if j.kind == "0" else "Df", name("d"), "= " + j.name, mods=[j.name]))
    # one-ports: at least one per junction, more up to the target size
    left = max(0, target - len(m.elems))
    homes = list(juncs)
    homes += [rng.choice(juncs) for _ in range(max(0, left - nj))]
    if singular:  # a driven model: two sources fixing one junction's effort or flow
        j = rng.choice(juncs)
        k = "Se" if j.kind == "0" else "Sf"
        for _ in range(2):
            e = one_port(k)
            bonds.append([e.name, j.name])
            degree[j.name] += 1
        groups.locked.add(groups.find(j.name))
    for i, j in enumerate(homes):
        e = one_port(kind_at(j, first=i < len(juncs)))
        out = e.kind in ("Se", "Sf", "MSe", "MSf")
        if rng.random() < 0.25:
            out = not out  # the other direction: same physics
        bonds.append([e.name, j.name] if out else [j.name, e.name])
        degree[j.name] += 1
    # multiports: a C field (two ports, energy with a coupling term, positive
    # definite), an R field (symmetric positive definite, passive), an
    # instance of a submodel (SUBMODELS) as a one-port; detectors on junctions
    if target >= 5 and rng.random() < 0.25:
        k1, k2 = _val(rng), _val(rng)
        c = float("%.3g" % (rng.uniform(-0.8, 0.8) / (k1 * k2) ** 0.5))
        q1, q2 = (float("%.3g" % rng.uniform(-1, 1)) for _ in range(2))
        n = name("K")
        e = add(Elem("CF", n, "(pa, pb) : energy = pa.q^2/(2*%g) + pb.q^2/(2*%g) + %g*pa.q*pb.q [q0 = (%g, %g)]"
                     % (k1, k2, c, q1, q2),
                     (lambda k1, k2, c: lambda a, b: a * a / (2 * k1) + b * b / (2 * k2) + c * a * b)(k1, k2, c),
                     states=["pa.q", "pb.q"], ports=["pa", "pb"]))
        stores.append(e)
        for port in e.ports:
            j = rng.choice(juncs)
            bonds.append([j.name, n + "." + port] if rng.random() < 0.8 else [n + "." + port, j.name])
            degree[j.name] += 1
    if cls != "lossless" and target >= 5 and rng.random() < 0.2:
        r1, r2 = _val(rng, 0.5, 2), _val(rng, 0.5, 2)
        r12 = float("%.3g" % (rng.uniform(-0.8, 0.8) * (r1 * r2) ** 0.5))
        n = name("RF")
        e = add(Elem("RF", n, "(pa, pb) : pa.e = %g*pa.f + %g*pb.f, pb.e = %g*pa.f + %g*pb.f" % (r1, r12, r12, r2),
                     ports=["pa", "pb"]))
        for port in e.ports:
            j = rng.choice(juncs)
            bonds.append([j.name, n + "." + port] if rng.random() < 0.8 else [n + "." + port, j.name])
            degree[j.name] += 1
    if target >= 4 and rng.random() < 0.25:
        kind = "LC" if cls == "lossless" or rng.random() < 0.5 else "RLC"
        k, mm = _val(rng), _val(rng)
        n = name("S")
        args = "(k = %g, m = %g%s)" % (k, mm, ", r = %g" % _val(rng, 0.2, 2) if kind == "RLC" else "")
        e = add(Elem(kind, n, args, (lambda k, mm: lambda q, p: q * q / (2 * k) + p * p / (2 * mm))(k, mm),
                     states=["c.q", "l.p"], ports=["a"]))
        j = rng.choice(juncs)
        bonds.append([j.name, n + ".a"])  # the submodel takes power in at a
        degree[j.name] += 1
    for j in juncs:  # every junction has two bonds or more
        while degree[j.name] < 2:
            e = one_port(kind_at(j))
            bonds.append([j.name, e.name])
            degree[j.name] += 1
    rng.shuffle(bonds)
    m.bonds = [[i + 1, a, b] for i, (a, b) in enumerate(bonds)]
    return _finish(m, rng)


def _finish(m, rng):
    t_end = rng.choice([1, 2, 3])
    m.sim = "simulate t_end = %g, dt = %g, rtol = 1e-9, atol = 1e-11" % (t_end, t_end / 40)
    return m


def parse(text):
    """A model written by text() back as data (the shrunk findings in
    tests/property/found/ are re-checked this way: prop.py --model). Only
    what this generator writes is understood."""
    import re
    m = Model("driven")
    inside = False
    for line in text.splitlines():
        line = "" if line.startswith("#") else line.rstrip()
        w = line.split(None, 2)
        if not w:
            continue
        if w[0] == "submodel":
            inside = True
        if inside:
            inside = w[0] != "end"
            continue
        if w[0] == "model":
            mm = re.search(r"\((\w+)\)", line)
            m.cls = mm.group(1) if mm else "driven"
        elif w[0] == "simulate":
            m.sim = line
        elif w[0] == "plot":
            continue
        elif w[0] == "bond":
            mm = re.match(r"bond (\d+) (\S+) -> (\S+)$", line)
            m.bonds.append([int(mm.group(1)), mm.group(2), mm.group(3)])
        else:
            m.elems.append(_elem_of(w[0], w[1], w[2] if len(w) > 2 else ""))
    return m


def _elem_of(word, name, decl):
    """One element statement as text() writes it, with its energy."""
    import re
    num = r"(-?[0-9.]+(?:e[+-]?[0-9]+)?)"
    reads = re.findall(r"([A-Za-z_]\w*)\.[qp]\b", decl) + re.findall(r"\*(d\d+)\b", decl)
    if word in ("De", "Df"):
        return Elem(word, name, decl, mods=[decl.split()[-1]])
    if word in SUBMODELS:
        mm = re.match(r"\(k = %s, m = %s" % (num, num), decl)
        k, mass = float(mm.group(1)), float(mm.group(2))
        return Elem(word, name, decl, lambda q, p: q * q / (2 * k) + p * p / (2 * mass),
                    states=["c.q", "l.p"], ports=["a"])
    if decl.startswith("(pa, pb)"):
        if word == "R":
            return Elem("RF", name, decl, ports=["pa", "pb"])
        mm = re.search(r"pa.q\^2/\(2\*%s\) \+ pb.q\^2/\(2\*%s\) \+ %s\*pa.q\*pb.q" % (num, num, num), decl)
        k1, k2, c = (float(mm.group(i)) for i in (1, 2, 3))
        return Elem("CF", name, decl, lambda a, b: a * a / (2 * k1) + b * b / (2 * k2) + c * a * b,
                    states=["pa.q", "pb.q"], ports=["pa", "pb"])
    if word not in ("C", "I"):
        return Elem(word, name, decl, mods=reads)
    mm = re.match(r"= %s" % num, decl)
    if mm:
        k = float(mm.group(1))
        return Elem(word, name, decl, lambda x: x * x / (2 * k))
    mm = re.match(r": [ef] = [qp]/%s \+ %s\*[qp]\^3" % (num, num), decl)
    k, a = float(mm.group(1)), float(mm.group(2))
    return Elem(word, name, decl, lambda x: x * x / (2 * k) + a * x ** 4 / 4)
