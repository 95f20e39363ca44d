#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes one of three scalable bond graph models with about BONDS bonds.

usage: gen_models.py chain|ladder|grid BONDS [T_END]   (the model on stdout)

chain:  a mass-spring-damper chain, 5 bonds a mass: 1-junction vk with mass
        mk (I) and damper dk (R), then 0-junction sk with spring kk (C) to the
        next mass; a force step drives the first mass. ODE, 2 states a mass.
ladder: an RC ladder, 4 bonds a section (as gen_ladder.py). ODE, 1 state a section.
grid:   a K x K grid of junctions, 0- and 1-junctions alternating like a
        chess board, each with its store (I on 1, C on 0) and a resistor, and
        a bond to each right and lower neighbour: 4K^2 - 2K bonds, one
        topological loop per grid cell. Integral causality everywhere (every
        0-junction's C sets the effort its neighbours read), so an ODE with
        K^2 states. A force step drives the corner 1-junction.
"""
import math
import sys


def chain(bonds, t_end):
    n = max(1, (bonds + 1) // 5)
    out = [f'model chain{n} "mass-spring-damper chain of {n} masses"',
           "param m0 = 1, k0 = 100, b0 = 2", "Se F = step(t)"]
    for i in range(1, n + 1):
        out += [f"1 v{i}", f"I m{i} = m0", f"R d{i} = b0"]
        if i < n:
            out += [f"0 s{i}", f"C k{i} = 1/k0"]
    out.append("bond F -> v1")
    for i in range(1, n + 1):
        out += [f"bond v{i} -> m{i}", f"bond v{i} -> d{i}"]
        if i < n:
            out += [f"bond v{i} -> s{i}", f"bond s{i} -> k{i}", f"bond s{i} -> v{i + 1}"]
    out.append(f"simulate t_end = {t_end}")
    return out


def ladder(bonds, t_end):
    n = max(1, bonds // 4)
    out = [f'model ladder{n} "RC ladder of {n} sections"', "param V = 1, R0 = 1, C0 = 1",
           "Se U = V * step(t)"]
    for k in range(1, n + 1):
        out += [f"1 j{k}", f"R R{k} = R0", f"0 n{k}", f"C C{k} = C0"]
    prev = "U"
    for k in range(1, n + 1):
        out += [f"bond {prev} -> j{k}", f"bond j{k} -> R{k}", f"bond j{k} -> n{k}",
                f"bond n{k} -> C{k}"]
        prev = f"n{k}"
    out.append(f"simulate t_end = {t_end}")
    return out


def grid(bonds, t_end):
    k = max(2, round((1 + math.sqrt(1 + 16 * bonds)) / 8))
    out = [f'model grid{k} "{k} x {k} grid of junctions"',
           "param m0 = 1, c0 = 0.01, r0 = 1", "Se F = step(t)"]
    for i in range(k):
        for j in range(k):
            one = (i + j) % 2 == 0
            out += [f"{'1' if one else '0'} g{i}_{j}",
                    f"{'I' if one else 'C'} s{i}_{j} = {'m0' if one else 'c0'}",
                    f"R r{i}_{j} = r0"]
    out.append("bond F -> g0_0")
    for i in range(k):
        for j in range(k):
            out += [f"bond g{i}_{j} -> s{i}_{j}", f"bond g{i}_{j} -> r{i}_{j}"]
            for (a, b) in ((i, j + 1), (i + 1, j)):
                if a < k and b < k:
                    out.append(f"bond g{i}_{j} -> g{a}_{b}")
    out.append(f"simulate t_end = {t_end}")
    return out


def main():
    if len(sys.argv) < 3 or sys.argv[1] not in ("chain", "ladder", "grid"):
        sys.exit(__doc__)
    t_end = sys.argv[3] if len(sys.argv) > 3 else "0.1"
    lines = {"chain": chain, "ladder": ladder, "grid": grid}[sys.argv[1]](int(sys.argv[2]), t_end)
    sys.stdout.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
