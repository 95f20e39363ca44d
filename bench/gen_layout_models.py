#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Models for bench/layout_bench.sh: a chain of N bonds (alternating 1- and
0-junctions with an R, I or C each) and a reaction network with S modulating
signals (species: a C on a 0-junction; reactions: an R on a 1-junction between
two species, its rate modulated by a third species' concentration).
The local network ("nearby") is the same but each reaction is modulated by
a species two places on along the ring, so a signal's route does not grow
with the figure (in "reactions" it spans a share of the whole figure, so
the routes' total length alone grows as S^1.5).
Held out (for the rows layout's counts, docs/drawing.md, nothing tuned to
them): "randnet" a reaction network whose reactions join random species and
are modulated by a random one; "randtree" junctions each joined to one of
the six before it; "randgraph" a random tree plus a quarter as many random
extra bonds; the trees' junctions carry none to two one-ports. SEED picks
the random graph.
A "star" is one 0-junction with N resistors (a fan: docs/drawing.md,
the bound on the bond router's work); a "fan" the star with a capacitor on
the junction modulating every resistor (N signals of one source, drawn as
branches off one tree); a "tree" is randtree with seed 1;
"states" a chain of N masses, each with a user state integrating its
velocity, fed back by a modulated source, and a detector (integrators and
detectors are nodes without bonds of their own).
Usage: gen_layout_models.py chain N OUT | reactions S OUT | nearby S OUT |
       star N OUT | fan N OUT | tree N OUT | states N OUT | randnet S SEED OUT | randtree N SEED OUT | randgraph N SEED OUT"""
import random
import sys


def states(n, out):
    lines = [f"model states{n}", "Se U = 1"]
    for i in range(n):
        lines += [f"{i % 2} j{i}", f"I m{i} = 1", f"R b{i} = 0.1", f"MSe F{i} = -x{i}",
                  f"state x{i}' = m{i}.f", f"De d{i} = m{i}"]
    lines.append("bond U -> j0")
    for i in range(n):
        lines += [f"bond j{i} -> m{i}", f"bond j{i} -> b{i}", f"bond F{i} -> j{i}"]
        if i + 1 < n:
            lines.append(f"bond j{i} -> j{i + 1}")
    out.write("\n".join(lines) + "\n")


def chain(nbond, out):
    n = nbond // 2
    kind = ["R r", "I m", "C c"]
    lines = [f"model chain{nbond}", "Se U = 1"]
    for i in range(n):
        lines += [f"{1 if i % 2 == 0 else 0} j{i}", f"{kind[i % 3]}{i} = 1"]
    lines.append("bond U -> j0")
    for i in range(n):
        lines.append(f"bond j{i} -> {kind[i % 3][2]}{i}")
        if i + 1 < n:
            lines.append(f"bond j{i} -> j{i + 1}")
    out.write("\n".join(lines) + "\n")


def reactions(nsignal, out, near=False):
    ns = max(4, (3 * nsignal) // 4)  # species; one reaction per signal
    lines = [f"model reactions{nsignal}", "Sf feed = 1"]
    for i in range(ns):
        lines += [f"0 s{i}", f"C c{i} = 1"]
    for k in range(nsignal):
        m = (k % ns + 2) % ns if near else (k * 7 + 3) % ns
        lines += [f"1 r{k}", f"R k{k} : f = (1 + c{m}.e) * e"]
    lines.append("bond feed -> s0")
    for i in range(ns):
        lines.append(f"bond s{i} -> c{i}")
    for k in range(nsignal):
        a = k % ns
        b = (a + 1) % ns if k < ns else (a + ns // 2) % ns
        lines += [f"bond s{a} -> r{k}", f"bond r{k} -> k{k}", f"bond r{k} -> s{b}"]
    out.write("\n".join(lines) + "\n")


def randnet(nsignal, seed, out):
    rng = random.Random(seed)
    ns = max(4, (3 * nsignal) // 4)
    lines = [f"model randnet{nsignal}_{seed}", "Sf feed = 1"]
    for i in range(ns):
        lines += [f"0 s{i}", f"C c{i} = 1"]
    for k in range(nsignal):
        lines += [f"1 r{k}", f"R k{k} : f = (1 + c{rng.randrange(ns)}.e) * e"]
    lines.append("bond feed -> s0")
    for i in range(ns):
        lines.append(f"bond s{i} -> c{i}")
    for k in range(nsignal):  # every species in a reaction: a junction needs two bonds
        a = k if k < ns else rng.randrange(ns)
        b = rng.randrange(ns - 1)
        b = b + 1 if b >= a else b
        lines += [f"bond s{a} -> r{k}", f"bond r{k} -> k{k}", f"bond r{k} -> s{b}"]
    out.write("\n".join(lines) + "\n")


def randtree(n, seed, out, extra=False):
    rng = random.Random(seed)
    edges = []
    for v in range(1, n):
        edges.append((rng.randrange(v) if extra else rng.randrange(max(0, v - 6), v), v))
    if extra:
        for _ in range(n // 4):
            a, b = rng.randrange(n), rng.randrange(n)
            if a != b and (a, b) not in edges and (b, a) not in edges:
                edges.append((min(a, b), max(a, b)))
    deg = [0] * n
    deg[0] = 1  # the source
    for a, b in edges:
        deg[a] += 1
        deg[b] += 1
    lines = [f"model rand{'graph' if extra else 'tree'}{n}_{seed}", "Se U = 1"]
    lines += [f"{v % 2} j{v}" for v in range(n)]
    lines.append("bond U -> j0")
    lines += [f"bond j{a} -> j{b}" for a, b in edges]
    for v in range(n):
        for q in range(rng.choice([0, 1, 1, 2]) or (1 if deg[v] < 2 else 0)):
            e = rng.choice("RCI")
            lines += [f"{e} p{v}_{q} = 1", f"bond j{v} -> p{v}_{q}"]
    out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    what, n = sys.argv[1], int(sys.argv[2])
    if what in ("randnet", "randtree", "randgraph"):
        seed, path = int(sys.argv[3]), sys.argv[4]
        with open(path, "w") as f:
            if what == "randnet":
                randnet(n, seed, f)
            else:
                randtree(n, seed, f, extra=(what == "randgraph"))
        sys.exit(0)
    path = sys.argv[3]
    with open(path, "w") as f:
        if what == "star":
            f.write(f"model star{n}\nSe U = 1\n0 j\nbond U -> j\n")
            f.write("".join(f"R r{i} = 1\nbond j -> r{i}\n" for i in range(n)))
        elif what == "fan":  # the star, each resistor modulated by one capacitor's effort: a fan of n signals
            f.write(f"model fan{n}\nSe U = 1\n0 j\nbond U -> j\nC c = 1\nbond j -> c\n")
            f.write("".join(f"R r{i} : f = (1 + c.e) * e\nbond j -> r{i}\n" for i in range(n)))
        elif what == "chain":
            chain(n, f)
        elif what == "tree":  # a random tree of n junctions (seed 1): the grid's tree drawing above 2 000 nodes
            randtree(n, 1, f)
        elif what == "states":
            states(n, f)
        else:
            reactions(n, f, near=(what == "nearby"))
