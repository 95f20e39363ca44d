#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes a chain of N instances of a 10-element submodel, composed (one
`submodel Cell` used N times) and the same model written flat by hand, for
bench/components.sh.  Usage: gen_components.py N COMPOSED.bg FLAT.bg"""
import sys

# One cell: 1 s (R, I), 0 n (C), 1 m (R), 0 k (C), 1 o (R): ten elements.
CELL = [("1", "s", None), ("R", "r1", "R0"), ("I", "l1", "L0"), ("0", "n", None),
        ("C", "c1", "C0"), ("1", "m", None), ("R", "r2", "R0"), ("0", "k", None),
        ("C", "c2", "C0"), ("R", "r3", "10*R0")]
BONDS = [("s", "r1"), ("s", "l1"), ("s", "n"), ("n", "c1"), ("n", "m"), ("m", "r2"),
         ("m", "k"), ("k", "c2"), ("k", "r3")]


def composed(n, out):
    out.write("submodel Cell(R0 = 1, L0 = 1e-3, C0 = 1e-6)\n  port p, q\n")
    for kind, name, val in CELL:
        out.write("  %s %s%s\n" % (kind, name, " = " + val if val else ""))
    out.write("  bond p -> s\n")
    for a, b in BONDS:
        out.write("  bond %s -> %s\n" % (a, b))
    out.write("  bond k -> q\nend\nSe U = 1\n")
    for i in range(n):
        out.write("Cell X%d\n" % i)
    out.write("R load = 1\nbond U -> X0.p\n")
    for i in range(n - 1):
        out.write("bond X%d.q -> X%d.p\n" % (i, i + 1))
    out.write("bond X%d.q -> load\n" % (n - 1))


def flat(n, out):
    out.write("Se U = 1\n")
    for i in range(n):
        out.write("param X%d_R0 = 1, X%d_L0 = 1e-3, X%d_C0 = 1e-6\n" % (i, i, i))
        for kind, name, val in CELL:
            v = val.replace("R0", "X%d_R0" % i).replace("L0", "X%d_L0" % i).replace("C0", "X%d_C0" % i) if val else None
            out.write("%s X%d_%s%s\n" % (kind, i, name, " = " + v if v else ""))
        for a, b in BONDS:
            out.write("bond X%d_%s -> X%d_%s\n" % (i, a, i, b))
    out.write("R load = 1\nbond U -> X0_s\n")
    for i in range(n - 1):
        out.write("bond X%d_k -> X%d_s\n" % (i, i + 1))
    out.write("bond X%d_k -> load\n" % (n - 1))


n = int(sys.argv[1])
with open(sys.argv[2], "w") as f:
    composed(n, f)
with open(sys.argv[3], "w") as f:
    flat(n, f)
