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
Usage: gen_layout_models.py chain N OUT | reactions S OUT | nearby S OUT"""
import sys


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


if __name__ == "__main__":
    what, n, path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    with open(path, "w") as f:
        if what == "chain":
            chain(n, f)
        else:
            reactions(n, f, near=(what == "nearby"))
