#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Compares an exported switching model's run with bgdraw's own
(tests/export_events.sh): the outputs row by row, relative to each column's
range in bgdraw's CSV, skipping the rows within SKIP seconds of a switching
(the two sides of a jump), and the switchings: the same count, the same root
functions and directions in the same order, each time within TTOL s.
usage: compare_events.py REF.csv REF.json OUT.csv EVENTS.txt TOL TTOL SKIP LABEL [instants]
EVENTS.txt: one switching a line, "t root direction" (direction +1 / -1).
instants: compare the instants at which something switched instead (entries
within 1e-6 of the span are one instant): bgdraw also logs a mode that
changed at an event without a root of its own, which an FMI master, seeing
only the indicators, cannot tell.
Exit 1 on a deviation beyond its tolerance."""
import json
import sys


def read_csv(path):
    rows = [l.strip().split(",") for l in open(path) if l.strip() and not l.startswith("#")]
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def main():
    ref_csv, ref_json, out_csv, ev_txt = sys.argv[1:5]
    tol, ttol, skip, label = float(sys.argv[5]), float(sys.argv[6]), float(sys.argv[7]), sys.argv[8]
    ev = json.load(open(ref_json))["simulation"]["events"]["list"]
    want = [(e["t"], e["condition"], 1 if e["direction"] == "rising" else -1) for e in ev]
    got = [(float(a), int(b), int(c)) for a, b, c in (l.split() for l in open(ev_txt) if l.strip())]
    if len(sys.argv) > 9 and sys.argv[9] == "instants":
        span = want[-1][0] - want[0][0] if want else 1.0
        def instants(evs):
            out = []
            for t, _, _ in sorted(evs):
                if not out or t - out[-1] > 1e-6 * span:
                    out.append(t)
            return [(t, 0, 1) for t in out]
        got, want = instants(got), instants(want)
    if len(got) != len(want):
        print("%s: %d switchings, bgdraw has %d" % (label, len(got), len(want)))
        print("  got ", got[:12])
        print("  want", want[:12])
        return 1
    dt = 0.0
    for (tg, rg, dg), (tw, rw, dw) in zip(got, want):
        if rg != rw or dg != dw:
            print("%s: switching at %.10g is root %d (%+d), bgdraw's at %.10g root %d (%+d)" % (label, tg, rg, dg, tw, rw, dw))
            return 1
        dt = max(dt, abs(tg - tw))
    if dt > ttol:
        print("%s: a switching time is %.3g s off (tolerance %g)" % (label, dt, ttol))
        return 1
    ha, ra = read_csv(ref_csv)
    hb, rb = read_csv(out_csv)
    if ha != hb or len(ra) != len(rb):
        print("%s: headers or row counts differ: %s (%d) vs %s (%d)" % (label, ha, len(ra), hb, len(rb)))
        return 1
    keep = [k for k, r in enumerate(ra) if all(abs(r[0] - w[0]) > skip for w in want)]
    worst = 0.0
    for j in range(1, len(ha)):
        col = [r[j] for r in ra]
        span = max(col) - min(col) or max(abs(c) for c in col) or 1.0
        dev = max(abs(ra[k][j] - rb[k][j]) for k in keep) / span
        worst = max(worst, dev)
        if dev > tol:
            print("%s: column %s deviates by %.3g of its range (tolerance %g)" % (label, ha[j], dev, tol))
            return 1
    print("%s: %d switchings within %.2g s of bgdraw's; %d of %d rows agree, largest deviation %.2g of a column's range"
          % (label, len(got), dt, len(keep), len(ra), worst))
    return 0


if __name__ == "__main__":
    sys.exit(main())
