# SPDX-License-Identifier: BSD-3-Clause
"""What must hold for every generated model (docs/property.md).

check(bgdraw, model, workdir, rng) runs bgdraw on the model and on variants
of it and returns {check name: ("pass" | "fail" | "skip", detail)}. Every
check can fail: each compares numbers the engine printed with an independent
statement (energy from the state columns and the generator's own laws, power
from the bond columns, the same numbers from another route).
"""
import csv
import json
import os
import random
import subprocess

TIME_LIMIT = 30          # seconds per bgdraw run; beyond it: a hang
DOCUMENTED_EXITS = {0, 1, 2, 3, 4}

CHECKS = ["robust", "accepted", "junction_power", "twoport_power", "energy_lossless",
          "energy_passive", "library", "rename", "reorder", "reorder_strokes", "renumber", "methods_agree", "index_agree"]


class Run:
    def __init__(self, status, out, err, files):
        self.status, self.out, self.err, self.files = status, out, err, files


def run(bgdraw, text, workdir, tag, args, outs):
    """Writes the model, runs bgdraw with args and -o for each of outs
    (extensions), returns a Run (status None: killed at the time limit;
    negative: a signal)."""
    path = os.path.join(workdir, tag + ".bg")
    with open(path, "w") as f:
        f.write(text)
    files = {x: os.path.join(workdir, "%s.%s" % (tag, x)) for x in outs}
    for p in files.values():
        if os.path.exists(p):
            os.remove(p)
    cmd = [bgdraw, path] + args
    for p in files.values():
        cmd += ["-o", p]
    try:
        p = subprocess.run(cmd, capture_output=True, timeout=TIME_LIMIT)
    except subprocess.TimeoutExpired:
        return Run(None, b"", b"", files)
    return Run(p.returncode, p.stdout, p.stderr.decode("utf-8", "replace"), files)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(v) for v in r] for r in rows[1:]]


def _robust(res, r, what):
    """Records a crash, a hang or an undocumented exit status."""
    if r.status is None:
        res["robust"] = ("fail", "%s: no answer within %d s" % (what, TIME_LIMIT))
    elif r.status not in DOCUMENTED_EXITS:
        res["robust"] = ("fail", "%s: exit status %s\n%s" % (what, r.status, r.err[-2000:]))
    elif "robust" not in res:
        res["robust"] = ("pass", "")
    return res["robust"][0] == "pass"


def close(a, b, scale, rel=1e-6, abs_=1e-9):
    return abs(a - b) <= rel * scale + abs_


def check(bgdraw, m, workdir, seed=0, lib=None):
    res = {}
    text = m.text()
    base = run(bgdraw, text, workdir, "m", ["--simulate"], ["json", "csv"])
    if not _robust(res, base, "simulate"):
        return res
    # a valid model is accepted: analysed (exit 0) or simulated with a
    # stated failure (exit 3), never refused as an error
    if base.status in (0, 3):
        res["accepted"] = ("pass", "")
    else:
        res["accepted"] = ("fail", "exit status %d\n%s" % (base.status, base.err[-2000:]))
        return res
    an = json.load(open(base.files["json"]))
    sim_ok = base.status == 0 and os.path.exists(base.files["csv"])
    if not sim_ok:
        import re
        why = [ln for ln in base.err.splitlines() if "error" in ln or "refused" in ln or "failed" in ln]
        # the reason without its numbers and names: a tally key
        res["_refused"] = re.sub(r"[A-Za-z]*[0-9][0-9.e+-]*", "#", (why or ["?"])[0])[:120]
    cols = rows = None
    if sim_ok:
        cols, rows = read_csv(base.files["csv"])
    _physics(res, m, cols, rows, an)
    _library(res, lib, base, workdir)
    _methods(res, bgdraw, m, text, workdir, an)
    _invariance(res, bgdraw, m, workdir, seed, an, rows)
    return res


def _col(m, rows):
    """bond number -> (effort column, flow column) of the base CSV."""
    idx = {}
    for i, b in enumerate(m.bonds):
        idx[b[0]] = (1 + 2 * i, 2 + 2 * i)
    return idx


def _physics(res, m, cols, rows, an):
    for c in ("junction_power", "twoport_power", "energy_lossless", "energy_passive"):
        res[c] = ("skip", "no simulation")
    if rows is None:
        return
    idx = _col(m, rows)
    kinds = {x.name: x.kind for x in m.elems}
    # power balance: at a junction the power in equals the power out; a
    # 0-junction's efforts are equal, a 1-junction's flows are equal
    bad = None
    ran = False
    for x in m.elems:
        if x.kind not in ("0", "1", "TF", "GY", "MTF", "MGY"):
            continue
        ins = [b[0] for b in m.bonds if b[2] == x.name]
        outs = [b[0] for b in m.bonds if b[1] == x.name]
        for r in rows:
            pin = sum(r[idx[b][0]] * r[idx[b][1]] for b in ins)
            pout = sum(r[idx[b][0]] * r[idx[b][1]] for b in outs)
            scale = sum(abs(r[idx[b][0]] * r[idx[b][1]]) for b in ins + outs)
            if not close(pin, pout, scale):
                bad = bad or "%s %s at t = %g: power in %.12g, out %.12g" % (
                    x.kind, x.name, r[0], pin, pout)
            if x.kind in ("0", "1"):
                k = 0 if x.kind == "0" else 1
                common = [r[idx[b][k]] for b in ins + outs]
                sc = max(abs(v) for v in common)
                if any(not close(v, common[0], sc) for v in common):
                    bad = bad or "%s junction %s at t = %g: %s not common: %s" % (
                        x.kind, x.name, r[0], "effort" if k == 0 else "flow", common)
        name = "junction_power" if x.kind in ("0", "1") else "twoport_power"
        if bad:
            res[name] = ("fail", bad)
            return
        ran = True
        if res[name][0] == "skip":
            res[name] = ("pass", "")
    # energy: the stores' energy from their states and the generator's laws
    has_r = any(k == "R" for k in kinds.values())
    has_src = any(k in ("Se", "Sf", "MSe", "MSf") for k in kinds.values())
    stores = m.stores()
    if has_src or not stores:
        return
    first = 1 + 2 * len(m.bonds)
    energy = [sum(s.energy(r[first + i]) for i, s in enumerate(stores)) for r in rows]
    e0 = max(energy[0], 1e-12)
    if not has_r:
        worst = max(abs(v - energy[0]) for v in energy)
        if worst > 1e-5 * e0 + 1e-10:
            res["energy_lossless"] = ("fail", "energy %.12g at t0, drift %.3g" % (energy[0], worst))
        else:
            res["energy_lossless"] = ("pass", "")
    else:
        for k in range(1, len(energy)):
            if energy[k] > energy[k - 1] + 1e-6 * e0 + 1e-10:
                res["energy_passive"] = ("fail", "energy rises from %.12g to %.12g at t = %g" % (
                    energy[k - 1], energy[k], rows[k][0]))
                return
        res["energy_passive"] = ("pass", "")


def _library(res, lib, base, workdir):
    """libbgdraw gives the command line's bytes: the analysis JSON (with the
    simulation) and the CSV (tests/property/libjson.c)."""
    if not lib:
        res["library"] = ("skip", "no library program")
        return
    path = os.path.join(workdir, "m.bg")
    lj, lc = os.path.join(workdir, "lib.json"), os.path.join(workdir, "lib.csv")
    for p in (lj, lc):
        if os.path.exists(p):
            os.remove(p)
    try:
        p = subprocess.run([lib, path, lj, lc], capture_output=True, timeout=TIME_LIMIT)
    except subprocess.TimeoutExpired:
        res["robust"] = ("fail", "library: no answer within %d s" % TIME_LIMIT)
        res["library"] = ("fail", "hung")
        return
    if p.returncode != base.status:
        res["library"] = ("fail", "status %d, the command line's %d\n%s" % (
            p.returncode, base.status, p.stderr.decode("utf-8", "replace")[-1000:]))
        return
    for mine, theirs, what in ((lj, base.files["json"], "JSON"), (lc, base.files["csv"], "CSV")):
        a = open(mine, "rb").read() if os.path.exists(mine) else None
        b = open(theirs, "rb").read() if os.path.exists(theirs) else None
        if a != b:
            res["library"] = ("fail", "%s differs from the command line's (%s and %s bytes)" % (
                what, None if a is None else len(a), None if b is None else len(b)))
            return
    res["library"] = ("pass", "")


def _summary(an):
    """What the analysis says about the model, with names and bond numbers."""
    return {
        "complete": an["complete"],
        "strokes": sorted((b["id"], b["stroke"]) for b in an["bonds"]),
        "states": sorted(an["states"]),
        "conflicts": len(an["conflicts"]),
        "form": an["form"],
        "predicted": an["index"]["predicted"],
    }


def _consistent(an):
    """Whether the simulation changed the model's initial values."""
    sim = an.get("simulation") or {}
    return bool((sim.get("initial_values") or {}).get("changed"))


def _methods(res, bgdraw, m, text, workdir, an):
    """SCAP, relaxed and van Dijk: the same states and predicted index when
    SCAP finds no conflict and completes; the predicted index equals the
    numeric one or the run states the disagreement (tests/index_agree.sh)."""
    ix = an["index"]
    p, k, why = ix["predicted"], ix["numeric"], ix["disagreement"]
    if p is None or ix["numeric_status"] == "not computed":
        res["index_agree"] = ("skip", "no index")
    else:
        agree = p == k or (k is not None and p >= 2 and k >= 2)
        if agree and why is not None:
            res["index_agree"] = ("fail", "agree (%s, %s) but a disagreement is stated" % (p, k))
        elif not agree and why is None:
            res["index_agree"] = ("fail", "predicted %s, numeric %s, not stated" % (p, k))
        else:
            res["index_agree"] = ("pass", "")
    if an["conflicts"] or not an["complete"]:
        res["methods_agree"] = ("skip", "conflicts or incomplete")
        return
    ref = _summary(an)
    for meth in ("relaxed", "vandijk"):
        r = run(bgdraw, text, workdir, "m_" + meth, ["--causality", meth], ["json"])
        if not _robust(res, r, meth):
            res["methods_agree"] = ("fail", "%s: crashed or hung" % meth)
            return
        if r.status != 0:
            res["methods_agree"] = ("fail", "%s: exit status %d" % (meth, r.status))
            return
        s = _summary(json.load(open(r.files["json"])))
        for key in ("states", "predicted"):
            if s[key] != ref[key]:
                res["methods_agree"] = ("fail", "%s: %s %s, scap %s" % (meth, key, s[key], ref[key]))
                return
    res["methods_agree"] = ("pass", "")


def _traj_equal(rows_a, rows_b, rel=1e-5, abs_=1e-7):
    if rows_a is None or rows_b is None:
        return None
    if len(rows_a) != len(rows_b):
        return "row counts %d and %d" % (len(rows_a), len(rows_b))
    for ra, rb in zip(rows_a, rows_b):
        for j, (a, b) in enumerate(zip(ra, rb)):
            if not close(a, b, max(abs(a), abs(b)), rel, abs_):
                return "column %d at t = %g: %.12g and %.12g" % (j, ra[0], a, b)
    return ""


def _invariance(res, bgdraw, m, workdir, seed, an, rows):
    rng = random.Random(seed * 7919 + 1)
    nst = len(m.elems) + len(m.bonds)
    names = [x.name for x in m.elems]
    new = ["x%d" % i for i in range(len(names))]
    rng.shuffle(new)
    nm = dict(zip(names, new))
    order = list(range(nst))
    rng.shuffle(order)
    back = {v: k for k, v in nm.items()}
    ref = _summary(an)
    ref["consistent"] = _consistent(an)
    # renamed, same order: the same analysis with the names mapped and the
    # same numbers, exactly
    r = run(bgdraw, m.text(names=nm), workdir, "m_rn", ["--simulate"], ["json", "csv"])
    if _variant_ok(res, "rename", r, rows):
        s = _summary(json.load(open(r.files["json"])))
        s["states"] = sorted(back[x.split(".")[0]] + "." + x.split(".")[1] for x in s["states"])
        diff = [k for k in s if ref[k] != s[k]]
        t = _traj_equal(rows, read_csv(r.files["csv"])[1] if r.status == 0 else None, 0, 0)
        if diff:
            res["rename"] = ("fail", "analysis differs in %s: %s vs %s" % (
                diff, [ref[k] for k in diff], [s[k] for k in diff]))
        else:
            res["rename"] = ("fail", "trajectories differ: " + t) if t else ("pass", "")
    # reordered statements, names and bond numbers kept: the same counts and
    # trajectories (reorder); the same strokes (reorder_strokes)
    r = run(bgdraw, m.text(order=order), workdir, "m_ro", ["--simulate"], ["json", "csv"])
    if _variant_ok(res, "reorder", r, rows):
        j = json.load(open(r.files["json"]))
        s = _summary(j)
        s["consistent"] = _consistent(j)
        _same_counts(res, "reorder", ref, s, rows, r)
        if s["strokes"] != ref["strokes"] or s["states"] != ref["states"]:
            d = [(a, b) for a, b in zip(ref["strokes"], s["strokes"]) if a != b]
            res["reorder_strokes"] = ("fail", "strokes of bonds %s differ; states %s, before %s" % (
                [a[0] for a, b in d], s["states"], ref["states"]))
        else:
            res["reorder_strokes"] = ("pass", "")
    # renumbered bonds (sparse numbers): the same trajectories and the same
    # counts; which store of a tie takes derivative causality may follow the
    # numbering, so the strokes are not compared
    nums = rng.sample(range(1, 10 * len(m.bonds) + 10), len(m.bonds))
    numbers = {b[0]: n for b, n in zip(m.bonds, nums)}
    r = run(bgdraw, m.text(numbers=numbers), workdir, "m_nb", ["--simulate"], ["json", "csv"])
    if _variant_ok(res, "renumber", r, rows):
        j = json.load(open(r.files["json"]))
        s = _summary(j)
        s["consistent"] = _consistent(j)
        _same_counts(res, "renumber", ref, s, rows, r)


def _variant_ok(res, name, r, rows):
    """The variant ran as the model did: no crash, simulated when it was."""
    if not _robust(res, r, name):
        res[name] = ("fail", "crashed or hung")
    elif r.status not in (0, 3) or (r.status == 0) != (rows is not None):
        res[name] = ("fail", "exit status %d, the model's %s" % (r.status, "0" if rows else "3"))
    else:
        return True
    return False


def _same_counts(res, name, ref, s, rows, r):
    if name == "reorder" and (ref["conflicts"] or s["conflicts"]):
        # with conflicts SCAP's arbitrary choices, taken in file order, decide
        # how many conflicts remain (docs/property.md)
        res[name] = ("skip", "conflicts: the count follows the choices")
        return
    for k in ("complete", "conflicts", "form", "predicted"):
        if s[k] != ref[k]:
            res[name] = ("fail", "%s: %s, before %s" % (k, s[k], ref[k]))
            return
    if len(s["states"]) != len(ref["states"]):
        res[name] = ("fail", "%d states, before %d" % (len(s["states"]), len(ref["states"])))
        return
    if ref["consistent"] or s["consistent"]:
        # the run changed the initial values the model gave to its dependent
        # stores (and said so): which store is dependent may follow the
        # statement order, so the trajectories may differ by right
        res[name] = ("pass", "counts only: initial values made consistent")
        return
    t = _traj_equal(rows, read_csv(r.files["csv"])[1] if r.status == 0 else None)
    res[name] = ("fail", "trajectories differ: " + t) if t else ("pass", "")
