#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes an RC ladder of N sections as a .bg model (4 bonds a section).

usage: gen_ladder.py N [OUT.bg]   (stdout without OUT)

Section k: 1-junction jk carrying resistor Rk, then 0-junction nk carrying
capacitor Ck; nk feeds the next section. With integral causality at every
C the ladder is an ODE: one first-order causal path per resistor-store pair.
"""
import sys


def ladder(n):
    out = [f"model ladder{n} \"RC ladder with {n} sections\"",
           "param V = 1, R0 = 1, C0 = 1e-3",
           "Se U = V * step(t)"]
    for k in range(1, n + 1):
        out += [f"1 j{k}", f"R R{k} = R0", f"0 n{k}", f"C C{k} = C0"]
    b = 1
    prev = "U"
    for k in range(1, n + 1):
        out += [f"bond {b} {prev} -> j{k}", f"bond {b + 1} j{k} -> R{k}",
                f"bond {b + 2} j{k} -> n{k}", f"bond {b + 3} n{k} -> C{k}"]
        b += 4
        prev = f"n{k}"
    out.append("simulate t_end = 1")
    return "\n".join(out) + "\n"


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    text = ladder(int(sys.argv[1]))
    if len(sys.argv) > 2:
        with open(sys.argv[2], "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
