#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The property campaign's driver (docs/property.md).

    prop.py BGDRAW [--count N] [--seed S | --seeds S1,S2,...] [--max-elems K] [--found DIR] [--jobs J]
                   [--lib PROP_LIBJSON]
    prop.py BGDRAW --model FILE.bg [--seed S] [--lib PROP_LIBJSON]
                                 every check on one model written by the generator
                                 (a shrunk finding of tests/property/found/): exit 1
                                 when a check fails
    prop.py BGDRAW --file FILE.bg [--file ...]
                                 the checks that apply to a model someone wrote
                                 (given.py: the tutorial's and the gallery's
                                 models in tests/gallery.sh): exit 1 when one fails
    prop.py --self-test          the shrinker shrinks (a synthetic predicate)

Generates models seed S, S+1, ..., S+N-1 (tests/property/gen.py), checks each
(check.py), shrinks each failure by delta debugging over its elements and
bonds to a small model that fails the same check, writes it to DIR, prints
the table of checks (ran, passed, failed, skipped) and exits 1 when any
check failed.
"""
import argparse
import os
import resource
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check  # noqa: E402
import gen    # noqa: E402


def ddmin(items, fails):
    """Zeller's delta debugging: a 1-minimal sublist of items for which
    fails(sublist) holds (fails(items) must hold)."""
    n = 2
    while len(items) >= 2:
        size = max(1, len(items) // n)
        chunks = [items[i:i + size] for i in range(0, len(items), size)]
        reduced = False
        for i in range(len(chunks)):
            rest = [x for k, c in enumerate(chunks) if k != i for x in c]
            if rest and fails(rest):
                items, n, reduced = rest, max(n - 1, 2), True
                break
        if not reduced:
            if n >= len(items):
                break
            n = min(len(items), 2 * n)
    return items


def submodel(m, keep):
    """The model with only the elements and bonds in keep (('e', name) and
    ('b', number)); a bond to a dropped element is dropped, an element that
    reads a dropped one is dropped."""
    names = {k[1] for k in keep if k[0] == "e"}
    changed = True
    while changed:
        changed = False
        for x in m.elems:
            if x.name in names and any(d not in names for d in x.mods):
                names.discard(x.name)
                changed = True
    s = m.copy()
    s.elems = [x for x in m.elems if x.name in names]
    s.bonds = [b for b in s.bonds if ("b", b[0]) in keep and gen.base(b[1]) in names
               and gen.base(b[2]) in names]
    return s


def contractions(m):
    """The models with one two-bond junction contracted: the junction and its
    two bonds become one bond between their other ends, in either direction
    (the first bond's number; a junction a detector or a law reads stays).
    Physics need not be kept: the shrinker only asks whether the same check
    still fails, and an invalid model (a two-port with both bonds in) is
    refused by bgdraw and does not fail it."""
    read = {d for x in m.elems for d in x.mods}
    for j in m.elems:
        if j.kind not in ("0", "1") or j.name in read:
            continue
        bs = [b for b in m.bonds if j.name in (b[1], b[2])]
        if len(bs) != 2:
            continue
        ends = [b[1] if b[2] == j.name else b[2] for b in bs]
        if j.name in ends or ends[0] == ends[1]:
            continue
        for a, z in ((ends[0], ends[1]), (ends[1], ends[0])):
            c = m.copy()
            c.elems = [x for x in m.elems if x is not j]
            c.bonds = [[bs[0][0], a, z] if b is bs[0] else list(b) for b in m.bonds if b is not bs[1]]
            yield c


def shrink(bgdraw, m, name, workdir, seed, lib=None):
    """Shrinks m to a small model that still fails check `name`: ddmin over
    elements and bonds, then chains of two-bond junctions contracted one
    junction at a time (docs/property.md, finding 8), then ddmin again."""
    def fails_model(s):
        if not s.bonds:
            return False
        r = check.check(bgdraw, s, workdir, seed, lib)
        return r.get(name, ("skip",))[0] == "fail"

    def minimal(m):
        items = [("e", x.name) for x in m.elems] + [("b", b[0]) for b in m.bonds]
        return submodel(m, set(ddmin(items, lambda keep: fails_model(submodel(m, set(keep))))))
    small = minimal(m)
    contracted = False
    again = True
    while again:
        again = False
        for c in contractions(small):
            if fails_model(c):
                small, again, contracted = c, True, True
                break
    return minimal(small) if contracted else small


def one(args):
    bgdraw, seed, max_elems, found, known, lib = args
    m = gen.generate(seed, max_elems)
    with tempfile.TemporaryDirectory() as wd:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        res = check.check(bgdraw, m, wd, seed, lib)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
        failed = [k for k, v in res.items() if v[0] == "fail" and k not in known]
        shrunk = []
        for name in failed[:1]:  # the first failing check of the model
            small = shrink(bgdraw, m, name, wd, seed, lib)
            again = check.check(bgdraw, small, wd, seed, lib)[name]
            if found:
                os.makedirs(found, exist_ok=True)
                base = os.path.join(found, "seed%d_%s" % (seed, name))
                with open(base + ".bg", "w") as f:
                    f.write("# property campaign, seed %d, check %s: %s\n# shrunk from %d elements "
                            "and %d bonds\n" % (seed, name, again[1].splitlines()[0] if again[1] else "",
                                                len(m.elems), len(m.bonds)))
                    f.write(small.text())
            shrunk.append((name, len(small.elems), len(small.bonds), again[1]))
    res_ = {k: v[0] for k, v in res.items() if not k.startswith("_")}
    res_["_refused"] = res.get("_refused")
    res_["_cpu"] = res["_cpu"] + (cpu,)  # the costliest run (s, bound, tag), the checks' CPU
    res_["_skipped"] = {k: skip_key(v[1]) for k, v in res.items() if not k.startswith("_") and v[0] == "skip"}
    return seed, len(m.elems), res_, \
        {k: v[1] for k, v in res.items() if v[0] == "fail"}, shrunk


def skip_key(why):
    """A skip's reason as a tally key: its first line without numbers and
    store names (`the store C3 ...` and `C5` count as one reason)."""
    import re
    first = (why or "(no reason given)").splitlines()[0]
    return re.sub(r"[A-Za-z_]*[0-9][0-9.e+-]*", "#", first)[:100]


def self_test():
    """The shrinker shrinks: a predicate that fails when two given items are
    both present is shrunk to exactly those two, from 100 items; and a
    generated model with a planted 'failure' (a GY present) shrinks to a
    model holding that GY."""
    calls = []

    def fails(xs):
        calls.append(1)
        return 17 in xs and 63 in xs
    got = ddmin(list(range(100)), fails)
    assert got == [17, 63], got
    print("ddmin: 100 items -> %s in %d tests" % (got, len(calls)))
    for seed in range(200):
        m = gen.generate(seed, 60)
        gy = [x.name for x in m.elems if x.kind == "GY"]
        if len(m.elems) > 20 and gy:
            break
    keep = ddmin([("e", x.name) for x in m.elems] + [("b", b[0]) for b in m.bonds],
                 lambda k: any(x.kind == "GY" for x in submodel(m, set(k)).elems))
    small = submodel(m, set(keep))
    assert [x.kind for x in small.elems] == ["GY"], small.text()
    print("submodel: %d elements -> %s" % (len(m.elems), [x.name for x in small.elems]))
    # a chain of three two-bond junctions between a source and a resistor
    # contracts to the source on the resistor
    c = gen.Model("driven")
    c.elems = [gen.Elem("Se", "U", "= 1"), gen.Elem("0", "j1"), gen.Elem("1", "j2"), gen.Elem("0", "j3"),
               gen.Elem("R", "R1", "= 2")]
    c.bonds = [[1, "U", "j1"], [2, "j1", "j2"], [3, "j3", "j2"], [4, "j3", "R1"]]
    steps = 0
    while True:
        nxt = next((k for k in contractions(c) if {"U", "R1"} <= {x.name for x in k.elems}), None)
        if nxt is None:
            break
        c, steps = nxt, steps + 1
    assert [x.name for x in c.elems] == ["U", "R1"] and len(c.bonds) == 1, c.text()
    print("contractions: 3 junctions -> bond %s in %d steps" % (c.bonds[0], steps))
    print("self-test passed")


def check_files(bgdraw, paths, seed, lib):
    """Every check on each model file (gen.parse), the sampled ones too;
    prints each check's result."""
    check.SAMPLE = False
    bad = 0
    for path in paths:
        m = gen.parse(open(path).read())
        with tempfile.TemporaryDirectory() as wd:
            res = check.check(bgdraw, m, wd, seed, lib)
        for c in check.CHECKS:
            st, why = res.get(c, ("skip", ""))
            print("%s %s: %s%s" % (os.path.basename(path), c, st, (" (" + why.splitlines()[0] + ")") if why else ""))
            bad += st == "fail"
    return 1 if bad else 0


def check_given(bgdraw, paths):
    """The checks that apply to each hand-written model (given.py), one line each."""
    import given
    bad = 0
    for path in paths:
        res = given.check_file(bgdraw, path)
        for c in check.CHECKS:
            st, why = res[c]
            print("%s %s: %s%s" % (path, c, st, (" (" + why.splitlines()[0] + ")") if why else ""))
            bad += st == "fail"
    return 1 if bad else 0


def print_table(table, out):
    print("| check | ran | passed | failed | skipped |", file=out)
    print("|---|---|---|---|---|", file=out)
    for c in check.CHECKS:
        t = table[c]
        print("| %s | %d | %d | %d | %d |" % (c, t["pass"] + t["fail"], t["pass"], t["fail"], t["skip"]),
              file=out, flush=True)


def print_skips(skips, out):
    """Each check's skips by reason, most frequent first."""
    print("Skipped, by reason:", file=out)
    for c in check.CHECKS:
        for why, n in sorted(skips[c].items(), key=lambda kv: (-kv[1], kv[0])):
            print("  %-20s %6d  %s" % (c, n, why), file=out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bgdraw", nargs="?")
    ap.add_argument("--count", type=int, default=300)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--seeds", help="a comma list of seeds instead of --count and --seed")
    ap.add_argument("--max-elems", type=int, default=100)
    ap.add_argument("--found", default=None)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--lib", default=None, help="tests/property/libjson.c built (prop_libjson)")
    ap.add_argument("--known", action="append",
                    help="a check whose failures are counted but do not fail the run (docs/property.md)")
    ap.add_argument("--self-test", action="store_true")
    ap.add_argument("--model", action="append", help="check these models instead of generated ones")
    ap.add_argument("--file", action="append", help="check these hand-written models (given.py)")
    a = ap.parse_args()
    if a.self_test:
        return self_test()
    bgdraw = os.path.abspath(a.bgdraw)
    if a.file:
        return check_given(bgdraw, a.file)
    if a.model:
        return check_files(bgdraw, a.model, a.seed, os.path.abspath(a.lib) if a.lib else None)
    table = {c: {"pass": 0, "fail": 0, "skip": 0} for c in check.CHECKS}
    skips = {c: {} for c in check.CHECKS}
    sizes = []
    costliest = (0.0, 1.0, "", 0, 0)  # CPU s, its bound, tag, seed, size
    cpu_total = 0.0
    refused = {}
    nfail = 0
    known = set(a.known or [])
    nknown = 0
    lib = os.path.abspath(a.lib) if a.lib else None
    seeds = [int(x) for x in a.seeds.split(",")] if a.seeds else list(range(a.seed, a.seed + a.count))
    jobs = [(bgdraw, s, a.max_elems, a.found, known, lib) for s in seeds]
    with ProcessPoolExecutor(max_workers=a.jobs) as ex:
        for k, (seed, size, res, why, shrunk) in enumerate(ex.map(one, jobs, chunksize=4)):
            sizes.append(size)
            run_cpu, bound, tag, cpu = res["_cpu"]
            cpu_total += cpu
            if run_cpu / max(bound, 1e-9) > costliest[0] / costliest[1]:
                costliest = (run_cpu, bound, tag, seed, size)
            if res.get("_refused"):
                refused[res["_refused"]] = refused.get(res["_refused"], 0) + 1
            for c in check.CHECKS:
                table[c][res.get(c, "skip")] += 1
                if res.get(c, "skip") == "skip":
                    r = res["_skipped"].get(c, "(not reached: the model stopped before this check)")
                    skips[c][r] = skips[c].get(r, 0) + 1
            if set(why) & known:
                nknown += 1
                for c in sorted(set(why) & known):
                    print("KNOWN seed %d (%d elements) %s: %s" % (seed, size, c, why[c].splitlines()[0] if why[c] else ""))
            why = {c: d for c, d in why.items() if c not in known}
            if why:
                nfail += 1
                for c, d in why.items():
                    print("FAIL seed %d (%d elements) %s: %s" % (seed, size, c, d.splitlines()[0]))
                for name, ne, nb, d in shrunk:
                    print("  shrunk to %d elements, %d bonds: %s" % (ne, nb, d.splitlines()[0] if d else ""))
            if (k + 1) % 500 == 0:
                print("... %d models, %d with a failure" % (k + 1, nfail), file=sys.stderr, flush=True)
                print_table(table, sys.stderr)
    print("%d models (seeds %s), %d to %d elements (mean %.1f), %d with a failure" % (
        len(seeds), a.seeds or "%d..%d" % (a.seed, a.seed + a.count - 1), min(sizes), max(sizes),
        sum(sizes) / len(sizes), nfail))
    print("CPU (bgdraw, SciPy, the compilers; shrinking not counted): %.1f s, %.3f s a model; the run "
          "closest to its bound (limits.py): %.2f s of %.1f s (seed %d, %d elements, %s)" % (
              cpu_total, cpu_total / len(sizes), costliest[0], costliest[1], costliest[3], costliest[4],
              costliest[2] or "-"))
    print("%d models not simulated (exit status 3, the reason stated):" % sum(refused.values()))
    for k, v in sorted(refused.items(), key=lambda kv: -kv[1]):
        print("  %5d  %s" % (v, k))
    if known:
        print("%d models failed a known check (%s): counted, not shrunk, each printed (KNOWN)" % (nknown, ", ".join(sorted(known))))
    print_table(table, sys.stdout)
    print_skips(skips, sys.stdout)
    return 1 if nfail else 0


if __name__ == "__main__":
    sys.exit(main())
