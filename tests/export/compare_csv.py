#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Compares two simulation CSVs (same header, same times): for every column
the largest deviation relative to that column's range in the first file.
usage: compare_csv.py A.csv B.csv TOL [LABEL]; exit 1 when a column deviates
by more than TOL (or the files do not line up)."""
import sys


def read(path):
    rows = [l.strip().split(",") for l in open(path) if l.strip() and not l.startswith("#")]
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def main():
    a, b, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
    label = sys.argv[4] if len(sys.argv) > 4 else b
    ha, ra = read(a)
    hb, rb = read(b)
    if ha != hb or len(ra) != len(rb) or not ra:
        print("%s: headers or row counts differ: %s (%d rows) vs %s (%d rows)" % (label, ha, len(ra), hb, len(rb)))
        return 1
    worst = 0.0
    for j in range(len(ha)):
        col = [r[j] for r in ra]
        span = max(col) - min(col) or max(abs(c) for c in col) or 1.0
        dev = max(abs(x[j] - y[j]) for x, y in zip(ra, rb)) / span
        worst = max(worst, dev)
        if dev > tol:
            print("%s: column %s deviates by %.3g of its range (tolerance %g)" % (label, ha[j], dev, tol))
            return 1
    print("%s: %d rows x %d columns agree, largest deviation %.2g of a column's range" % (label, len(ra), len(ha), worst))
    return 0


if __name__ == "__main__":
    sys.exit(main())
