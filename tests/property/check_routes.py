# SPDX-License-Identifier: BSD-3-Clause
"""The property campaign's checks of other routes to the same numbers
(docs/property.md): the Python export and the FMU against bgdraw's run, the
reduced form against the full DAE, the linear model's step response against
the simulation of a small step, the index reduction against parasitic
stores as they shrink. check.py calls routes(...) after its own checks.

The SciPy side runs in tests/property/scipy_run.py under a Python with NumPy
and SciPy (PROP_PYTHON, default Debian's /usr/bin/python3): the campaign's
own Python needs neither.
"""
import copy
import json
import os
import re
import xml.etree.ElementTree as ET
import zipfile

import check as ck
import limits
from gen import Elem

HERE = os.path.dirname(os.path.abspath(__file__))
SCIPY_RUN = os.path.join(HERE, "scipy_run.py")
EXPORT_PY_EVERY = 10   # the Python export for one model in 10 (by seed; the C export takes seed % 10 == 0)
FMU_EVERY = 10         # the FMU (compiled by bgdraw) for one model in 10, seed % 10 == 5
ROUTE_EVERY = 3        # the reduced form (seed % 3 == 1) and the step response (seed % 3 == 2):
                       # each starts SciPy (0.3 s), more than the rest of a model's checks
CHECKS = ["export_py", "fmu", "reduced_form", "step_response", "parasitic"]


def scipy_python():
    return os.environ.get("PROP_PYTHON", "/usr/bin/python3")


def _scipy(res, name, args, workdir):
    """Runs scipy_run.py; True when it wrote its CSV (exit 0), else records
    a skip (exit 2: the route does not apply) or a failure."""
    p = limits.run([scipy_python(), SCIPY_RUN] + args, _bound(workdir, stiff=True))
    if p.status is None:
        res[name] = ("fail", "scipy_run.py %s: %s" % (args[0], p.over))
        return False
    err = p.err.decode("utf-8", "replace").strip()
    if p.status == 2:
        res[name] = ("skip", err.splitlines()[-1] if err else "does not apply")
    elif p.status != 0:
        res[name] = ("fail", "scipy_run.py %s: exit status %d\n%s" % (args[0], p.status, err[-1500:]))
    return p.status == 0


def _bound(workdir, stiff=False):
    """The CPU bound (limits.py) for the model in workdir/m.bg."""
    return limits.file_bound(os.path.join(workdir, "m.bg"), stiff)


def _bgdraw(res, cmd, workdir, stiff=False):
    """bgdraw (cmd) on the model in workdir, bounded by its size's CPU time;
    past the bound `robust` fails too."""
    p = limits.run(cmd, _bound(workdir, stiff))
    if p.status is None:
        res["robust"] = ("fail", "%s: %s" % (" ".join(os.path.basename(c) for c in cmd[1:3]), p.over))
    return p


def compare(res, name, what, ref_path, path, rel=1e-5, cols=None):
    """Every column of path against the same-named column of the reference
    CSV on the same times, to rel of the reference column's range (plus
    1e-9): records pass or fail under name."""
    worst, why = deviation(what, ref_path, path, 1e-9 / rel, cols)
    res[name] = ("pass", "") if worst <= rel else ("fail", why)


def deviation(what, ref_path, path, absolute=0.0, cols=None):
    """The largest difference of a column of path from the same-named column
    of the reference CSV on the same times, less `absolute`, against the
    reference column's range, and where it is (inf when the rows or columns
    do not match)."""
    rh, rr = ck.read_csv(ref_path)
    h, rows = ck.read_csv(path)
    if len(rows) != len(rr) or any(abs(a[0] - b[0]) > 1e-9 * (1 + abs(b[0])) for a, b in zip(rows, rr)):
        return float("inf"), "%s: %d rows, bgdraw's %d" % (what, len(rows), len(rr))
    worst, why = 0.0, ""
    for j, c in enumerate(h):
        if j == 0 or (cols is not None and c not in cols):
            continue
        if c not in rh:
            return float("inf"), "%s: column %s not in bgdraw's CSV" % (what, c)
        k = rh.index(c)
        col = [r[k] for r in rr]
        span = max(col) - min(col) + 1e-9 * max(1.0, max(abs(v) for v in col))
        for a, b in zip(rows, rr):
            d = (abs(a[j] - b[k]) - absolute) / span
            if not d <= worst:  # a NaN counts
                worst = d if d == d else float("inf")
                why = "%s at t = %g: %s %.12g, bgdraw %.12g (range %.3g)" % (c, b[0], what, a[j], b[k], span)
    return worst, why


def _simulated(res, name, bgdraw, text, workdir, tag, outs, what, stiff=False):
    """bgdraw --simulate on a variant: the Run when it ran to the end; else
    None, with a failure recorded for a crash or hang (past its CPU bound,
    limits.py; stiff: a parasitic run's), a skip (what stops) for a stated
    stop."""
    r = ck.run(bgdraw, text, workdir, tag, ["--simulate"], outs, stiff)
    if not ck._robust(res, r, name):
        res[name] = ("fail", "crashed or hung")
    elif r.status != 0:
        res[name] = ("skip", "%s stops (exit %d)" % (what, r.status))
    else:
        return r
    return None


def routes(res, bgdraw, m, workdir, seed, an, rows):
    for c in CHECKS:
        res[c] = ("skip", "")
    _export_py(res, bgdraw, m, workdir, seed, an, rows)
    _fmu(res, bgdraw, m, workdir, seed, an, rows)
    if seed % ROUTE_EVERY == 1 or not ck.SAMPLE:
        _reduced_form(res, bgdraw, workdir, an, rows)
    else:
        res["reduced_form"] = ("skip", "one model in %d" % ROUTE_EVERY)
    if seed % ROUTE_EVERY == 2 or not ck.SAMPLE:
        _step_response(res, bgdraw, m, workdir)
    else:
        res["step_response"] = ("skip", "one model in %d" % ROUTE_EVERY)
    _parasitic(res, bgdraw, m, workdir, an, rows)


def _plain_run(an, rows):
    """Why bgdraw's run is no reference for another route, or None."""
    if rows is None:
        return "no simulation"
    if ck._dae_repaired(an):
        return "index reduced or initial values made consistent"
    return None


def _export_py(res, bgdraw, m, workdir, seed, an, rows):
    """The Python export (-o NAME.py) simulated by its own simulate()
    (SciPy's solve_ivp, BDF, rtol 1e-10) reproduces bgdraw's CSV to 1e-5 of
    every column's range."""
    why = "one model in %d" % EXPORT_PY_EVERY if seed % EXPORT_PY_EVERY != 5 and ck.SAMPLE else _plain_run(an, rows)
    if why is None and (an.get("simulation") or {}).get("events"):
        why = "switching conditions (tests/export_events.sh checks the export's events)"
    if why:
        res["export_py"] = ("skip", why)
        return
    w = lambda n: os.path.join(workdir, n)
    p = _bgdraw(res, [bgdraw, w("m.bg"), "-q", "-o", w("prop_model.py")], workdir)
    if p.status != 0:
        res["export_py"] = ("fail", "the export: %s\n%s" % (p.over or "exit status %d" % p.status, p.err.decode()[-500:]))
        return
    if _scipy(res, "export_py", ["pyexport", workdir, "prop_model", w("m.csv"), w("py.csv")], workdir):
        compare(res, "export_py", "Python export", w("m.csv"), w("py.csv"))


def _fmu(res, bgdraw, m, workdir, seed, an, rows):
    """The FMU (-o NAME.fmu, compiled by bgdraw) run by the suite's own FMI
    importer (tests/export/fmu_import.c: RK4 at 100 steps per output
    interval, state events located by bisection) reproduces bgdraw's CSV to
    1e-5 of every column's range (the first 60 outputs: the importer's
    limit is 64)."""
    why = "one model in %d" % FMU_EVERY if seed % FMU_EVERY != 5 and ck.SAMPLE else _plain_run(an, rows)
    if why is None and an["form"] != "ode":
        why = "a DAE (FMI 2.0 Model Exchange: ODE models only)"
    if why is None and re.search(r"step\(|table\(t", m.text()):
        # the FMU declares no time events, so a master's fixed steps pass
        # straight through a step of the input (seed 265: 1e-4 of the range)
        why = "input breakpoints (the importer's RK4 steps straight through them)"
    if why:
        res["fmu"] = ("skip", why)
        return
    w = lambda n: os.path.join(workdir, n)
    p = _bgdraw(res, [bgdraw, w("m.bg"), "-q", "--prefix", "pfmu", "-o", w("m.fmu")], workdir, stiff=True)
    if p.status == 3:
        res["fmu"] = ("skip", "refused: " + p.err.decode()[-200:].strip())
        return
    if p.status != 0:
        res["fmu"] = ("fail", "the export: %s\n%s" % (p.over or "exit status %d" % p.status, p.err.decode()[-500:]))
        return
    z = zipfile.ZipFile(w("m.fmu"))
    z.extract("binaries/linux64/pfmu.so", w("fmu"))
    md = ET.fromstring(z.read("modelDescription.xml"))
    nx = len(md.findall("./ModelStructure/Derivatives/Unknown"))
    nz = int(md.get("numberOfEventIndicators", "0"))
    outs = [(v.get("name"), v.get("valueReference")) for v in md.iter("ScalarVariable")
            if v.get("causality") == "output"][:60]
    if nx > 64 or nz > 64:
        res["fmu"] = ("skip", "more than 64 states or event indicators (the importer's limit)")
        return
    head, ref = ck.read_csv(w("m.csv"))
    names = [re.sub(r"^out\((.*)\)$", r"\1", n) for n, _ in outs]
    if names != head[1:1 + len(names)]:
        res["fmu"] = ("fail", "outputs %s, the CSV's %s" % (names[:4], head[1:5]))
        return
    with open(w("fmu_ref.csv"), "w") as f:  # the first 60 columns: the importer's line and output limits
        f.write(",".join(head[:1 + len(names)]) + "\n")
        for r in ref:
            f.write(",".join("%.17g" % v for v in r[:1 + len(names)]) + "\n")
    steps = [["cc", "-std=c11", "-D_POSIX_C_SOURCE=200809L", "-O1", "-w",
              os.path.join(HERE, "..", "export", "fmu_import.c"), "-o", w("fmu_import"), "-ldl"],
             [w("fmu_import"), w("fmu/binaries/linux64/pfmu.so"), md.get("guid"), str(nx), w("fmu_ref.csv"),
              w("fmu.csv"), ",".join(vr for _, vr in outs), "nz=%d" % nz]]
    for cmd in steps:
        p = limits.run(cmd, _bound(workdir, stiff=True))
        if p.status != 0:
            res["fmu"] = ("fail", "%s: %s\n%s" % (os.path.basename(cmd[0]), p.over or "exit status %d" % p.status,
                                                  p.err.decode("utf-8", "replace")[-800:]))
            return
    compare(res, "fmu", "FMU", w("fmu_ref.csv"), w("fmu.csv"))


def _reduced_form(res, bgdraw, workdir, an, rows):
    """The reduced form (--equations json, key `reduced`: the explicit ODE
    after symbolic elimination, docs/equations.md) integrated by SciPy from
    the run's first row gives the states and dependent stores of bgdraw's
    run of the full equations (IDA on the DAE, or CVODE), to 1e-5 of each
    column's range."""
    why = _plain_run(an, rows)
    if why is None and an.get("reduced_form") != "ode":
        why = "no reduced ODE (reduced form %s)" % an.get("reduced_form")
    if why is None and re.search(r"step\(|table\(t", open(os.path.join(workdir, "m.bg")).read()):
        # the reduced ODE holds between input breakpoints; at a step a state
        # that follows the input (a capacitor across an effort source,
        # combined into the reduced states) jumps, which x' = ... cannot show
        # (docs/property.md, finding 10); bgdraw restarts there from the
        # constraints
        why = "input breakpoints (the reduced ODE holds between them)"
    if why:
        res["reduced_form"] = ("skip", why)
        return
    w = lambda n: os.path.join(workdir, n)
    p = _bgdraw(res, [bgdraw, w("m.bg"), "-q", "--equations", "json"], workdir)
    if p.status != 0:
        res["reduced_form"] = ("fail", "--equations json: %s" % (p.over or "exit status %d" % p.status))
        return
    with open(w("eq.json"), "wb") as f:
        f.write(p.out)
    if _scipy(res, "reduced_form", ["reduced", w("eq.json"), w("m.csv"), w("red.csv")], workdir):
        compare(res, "reduced_form", "reduced form", w("m.csv"), w("red.csv"))


STEPS = (1e-3, 1e-4, 1e-5)  # the small step, smaller while a law's higher terms show (finding 17e)
STEP_TOL = 1e-5             # of each output's range
STEP_RATE = 0.2             # the deviation at a step 10 times smaller at least this much smaller


def _step_variant(m, size=STEPS[0]):
    """The model at rest with every source 0 but one, which steps by size at
    T1 (between two output rows): switching laws take their first slope (a
    kink at rest has no linearisation), time-modulated two-ports their
    constant part; cubic laws, tables (linear near 0) and modulation by
    states and detectors stay. Returns (text, source name, T1, outputs)."""
    v = m.copy()
    v.elems = []
    for x in m.elems:
        x = copy.copy(x)
        d = re.sub(r"\s*\[(?:[qp]0 = [^\]]+|q0 = \([^)]*\))\]", "", x.decl)
        if x.kind == "R":
            mm = re.match(r": e = if\(f > 0, ([0-9.e+-]+)\*f", d)
            d = "= " + mm.group(1) if mm else d
        elif x.kind in ("MTF", "MGY") and "sin(t)" in d:
            x.kind = x.word = x.kind[1:]
            d = "= " + re.match(r"= ([0-9.e+-]+)", d).group(1)
        elif x.kind in ("Se", "Sf") or (x.kind in ("MSe", "MSf") and not x.mods):
            x.kind = x.word = x.kind.lstrip("M")
            d, x.mods = "= 0", []
        x.decl = d
        v.elems.append(x)
    t_end = float(re.search(r"t_end = ([0-9.e+-]+)", m.sim).group(1))
    dt = t_end / 40
    t1 = 5.5 * dt
    plain = sorted((x.name for x in v.elems if x.kind in ("Se", "Sf")), key=lambda n: ck._natural(n))
    if plain:
        src = plain[0]
        x = v.elem(src)
        k = v.elems.index(x)
        v.elems[k] = copy.copy(x)
        v.elems[k].decl = "= %g*step(t - %.17g)" % (size, t1)
    else:
        juncs = [x for x in v.elems if x.kind in ("0", "1")]
        if not juncs:
            return None
        src = "Uprop"
        v.elems.append(Elem("Se", src, "= %g*step(t - %.17g)" % (size, t1)))
        v.bonds.append([max(b[0] for b in v.bonds) + 1, src, juncs[0].name])
    outs = (["%s.%s" % (x.name, x.states[0]) for x in v.elems if x.kind in ("C", "I")] + ck.resistor_ports(v))[:40]
    if not outs:
        return None
    text = re.sub(r"\nsimulate .*\n", "\nsimulate t_end = %g, dt = %.17g, rtol = 1e-10, atol = 1e-15\n" % (
        t_end, dt), v.text())
    text, names = ck.with_outputs(text, outs)
    return text, src, t1, names


def _step_response(res, bgdraw, m, workdir):
    """The linear model's step response is the simulation of a small step:
    the model at rest, one source stepping by STEPS[0] (_step_variant),
    simulated by bgdraw, against the step response of the state space of its
    `--linear json` at the initial point (rest: A, B, C, D) computed exactly
    (scipy_run.py step), at every output (stores' states, resistors' effort
    and flow) to STEP_TOL of its range. A law's higher terms make the
    simulation differ from the linear response by O(step) of the range (a
    quadratic term) or O(step^2) (a cubic one: seed 3269, e = 0.278 f +
    0.347 f^3, 1.6e-5 at 1e-3), so above the tolerance the step is made 10
    and 100 times smaller: the deviation must fall by STEP_RATE or more per
    step down to the tolerance. A wrong linear model (or simulation) keeps
    its deviation, a fixed fraction of the response, at every size."""
    sv = _step_variant(m)
    if sv is None:
        res["step_response"] = ("skip", "no junction for a source")
        return
    text, src, t1, names = sv
    w = lambda n: os.path.join(workdir, n)
    L = ck.linear_json(res, "step_response", bgdraw, text, workdir, "m_st", ("state_space",))
    if L is None:
        return
    if src not in L["inputs"] or [o for o in L["outputs"] if o in names] != names:  # detectors add outputs
        res["step_response"] = ("fail", "inputs %s, outputs %s" % (L["inputs"], L["outputs"][:4]))
        return
    if any(p["re"] > 1e-9 for p in L.get("poles") or []):
        res["step_response"] = ("skip", "unstable: the response leaves the small-signal range")
        return
    devs = []

    def falling(devs):  # by STEP_RATE per step, or to the runs' own error
        return all(b[0] <= STEP_RATE * a[0] or b[0] <= 0.1 * STEP_TOL for a, b in zip(devs, devs[1:]))
    for size in STEPS:
        if devs and (devs[-1][0] <= STEP_TOL or not falling(devs)):
            break
        r = _simulated(res, "step_response", bgdraw, _step_variant(m, size)[0] if devs else text, workdir,
                       "m_st", ["csv", "json"], "the step's run")
        if r is None:
            return
        if ck._dae_repaired(json.load(open(r.files["json"]))):
            res["step_response"] = ("skip", "index reduced or initial values made consistent")
            return
        head, rows = ck.read_csv(r.files["csv"])
        with open(w("st_sim.csv"), "w") as f:  # the plot's columns under the outputs' names
            f.write(",".join(["t"] + names) + "\n")
            for row in rows:
                f.write(",".join("%.17g" % v for v in row) + "\n")
        if not devs:
            with open(w("st_lin.json"), "w") as f:
                json.dump(L, f)
            if not _scipy(res, "step_response", ["step", w("st_lin.json"), w("st_sim.csv"), w("st_lin0.csv"),
                                                 src, "%.17g" % size, "%.17g" % t1], workdir):
                return
        lh, lrows = ck.read_csv(w("st_lin0.csv"))  # the linear response is linear in the step
        with open(w("st_lin.csv"), "w") as f:
            f.write(",".join(lh) + "\n")
            for row in lrows:
                f.write(",".join("%.17g" % v for v in row[:1] + [x * size / STEPS[0] for x in row[1:]]) + "\n")
        devs.append(deviation("linear step response", w("st_sim.csv"), w("st_lin.csv"), 1e-6 * size, names))
    shown = "; ".join("step %g: %.3g" % (z, d[0]) for z, d in zip(STEPS, devs))
    if devs[-1][0] <= STEP_TOL and falling(devs):
        res["step_response"] = ("pass", shown if len(devs) > 1 else "")
    else:
        res["step_response"] = ("fail", "%s (%s)" % (devs[-1][1], shown))


PARASITIC_SCALES = (1.0, 1e-2, 1e-4, 1e-6)  # the stated parameter times these, while needed
PARASITIC_TOL = 1e-3                  # the slow states at the last value, of their range
PARASITIC_RATE = 0.3                  # each of the last two steps of 100 at least this much closer
PARASITIC_FLOOR = 1e-5                # the runs' own error (rtol 1e-9: seed 871 at 40 elements levels at 2e-6)
PARASITIC_LIMIT = 0.05                # a last step this much closer is the O(parameter) limit's regime
PARASITIC_SQRT = 0.03                 # the last two steps together at least this much closer: O(sqrt(parameter))
PARASITIC_SQRT_TOL = 0.1              # ... and at most this far at the last value


def _parasitic(res, bgdraw, m, workdir, an, rows):
    """Index reduction against parasitic stores (the chapter's Section 4.3):
    for a model whose run reduced the index, `--transform parasitic` adds
    small stores where the analysis names the problem; run at the stated
    value and at 1/100 and 1/10 000 of it, and at 1/1 000 000 when the slow
    states are still converging but not yet close (each new store at the
    reduced run's value of its junction's variable, every store of the model
    at the reduced run's first row, so no run starts off the constraint),
    the slow variables converge to the reduced run's: the model's own stores'
    states (Equations 4.13 -> 4.1 describe the limit of the slow subsystem;
    the fast one, the new stores' states and the efforts or flows they set,
    rings undamped about it with an amplitude that falls only as the square
    root of the parameter, finding 16). The deviation of each is taken
    against its range (at least 1e-3 of the largest range or value: a state
    the reduced run holds still); over the last three values it must fall by
    PARASITIC_RATE or more per factor 100 (the limit is O(parameter): 0.01
    per step; seeds 1379 and 1725 at 30 elements, whose stated value is far
    from small, 146 -> 4.9 -> 0.034 -> 3.4e-4) down to the runs' own error,
    and be below PARASITIC_TOL at the last. A reduced
    run with other dynamics than the model's (the indexred plant) stays at a
    fixed distance from the parasitic runs, which converge to the model's."""
    red = ((an.get("index") or {}).get("reduction") or {}).get("status")
    if rows is None or red != "reduced":
        res["parasitic"] = ("skip", "the run did not reduce the index" if rows is not None else "no simulation")
        return
    w = lambda n: os.path.join(workdir, n)
    if os.path.exists(w("par.bg")):
        os.remove(w("par.bg"))
    tr = ck.run(bgdraw, m.text(), workdir, "m_par", ["--transform", "parasitic", "-o", w("par.bg")], [])
    if not ck._robust(res, tr, "parasitic"):
        res["parasitic"] = ("fail", "crashed or hung")
        return
    if tr.status != 0:
        why = [ln for ln in tr.err.splitlines() if "error" in ln]
        res["parasitic"] = ("skip", "the transformation does not apply" + (
            ": " + why[0].split("does not apply to prop: ")[-1][:100] if why else ""))
        return
    if "internal error" in tr.err:
        res["parasitic"] = ("fail", tr.err[-300:])
        return
    text = open(w("par.bg")).read()
    params = dict(re.findall(r"^param (\w+) = ([0-9.e+-]+)", text, re.M))
    # the new stores, `I Ip_j8 = Ip_j8_0 [p0 = Ip_j8_0*-0.157]`: the start
    # clause, when the transformation writes one, is replaced below (seeds 421
    # and 563: a pattern without it found no store, so every run was at the
    # stated parameter and the deviation could not fall, finding 17b)
    start = r"(?:\s*\[[qp]0 = [^\]]*\])?\s*$"
    stores = re.findall(r"^([CI])\s+(\w+) = (\w+)" + start, text, re.M)
    stores = [(k, n, p) for k, n, p in stores if p in params]
    if len(stores) != len(params):
        res["parasitic"] = ("fail", "the transformed model's parameters %s, its stores read %s" % (
            sorted(params), sorted(p for _, _, p in stores)))
        return
    bonds = re.findall(r"^bond (\d+) (\S+) -> (\S+)$", text, re.M)
    head, _ = ck.read_csv(w("m.csv"))
    orig = {b[0] for b in m.bonds}
    slow = []
    for x in m.stores():  # every store from the reduced run's consistent start
        if x.kind not in ("C", "I", "CF"):
            res["parasitic"] = ("skip", "a store the check cannot restart (%s)" % x.kind)
            return
        cols = [head.index("%s.%s" % (x.name, st)) for st in x.states]
        slow += cols
        vals = [rows[0][c] for c in cols]
        init = "[%s0 = %s]" % ("p" if x.kind == "I" else "q", "%.17g" % vals[0] if len(vals) == 1 else
                               "(%s)" % ", ".join("%.17g" % v for v in vals))
        pat = re.compile(r"^(%s\s+%s\b.*?)(\s*\[[qp]0 = [^\]]*\])?$" % (x.word, x.name), re.M)
        text = pat.sub(lambda mm: mm.group(1) + " " + init, text, count=1)
    if not slow:
        res["parasitic"] = ("skip", "no store of the model's own")
        return
    # each state against its range, but at least 1e-3 of the largest range or
    # size of any: a state the reduced run holds (still, or all of them: seed
    # 1328 at 30 elements is a locked mechanism, every flow 0) moves by
    # O(parameter) with the parasitic stores
    spans = {j: max(x[j] for x in rows) - min(x[j] for x in rows) for j in slow}
    floor = 1e-3 * max(max(spans[j], max(abs(x[j]) for x in rows)) for j in slow) + 1e-12
    devs = []

    def converging():  # the last three values show it
        return all(b[0] <= PARASITIC_RATE * a[0] or b[0] <= PARASITIC_FLOOR for a, b in zip(devs[-3:], devs[-2:]))
    for scale in PARASITIC_SCALES:
        if len(devs) >= 3 and (devs[-1][0] <= PARASITIC_TOL or not converging()):
            break
        t = text
        for k, n, p in stores:
            j = [b[1] if b[2] == n else b[2] for b in bonds if n in (b[1], b[2])][0]
            nums = [int(b[0]) for b in bonds if j in (b[1], b[2]) and int(b[0]) in orig]
            if not nums:
                res["parasitic"] = ("fail", "the store %s sits at %s, which has no bond of the model" % (n, j))
                return
            col = head.index(("e%d" if k == "C" else "f%d") % nums[0])
            value = float(params[p]) * scale
            t = re.sub(r"^param %s = [0-9.e+-]+" % p, "param %s = %.17g" % (p, value), t, flags=re.M)
            t, subs = re.subn(r"^(%s\s+%s = %s)%s" % (k, n, p, start), r"\1 [%s0 = %.17g]" % (
                "q" if k == "C" else "p", value * rows[0][col]), t, flags=re.M)
            if subs != 1:
                res["parasitic"] = ("fail", "the store %s's line not found in the transformed model" % n)
                return
        r = _simulated(res, "parasitic", bgdraw, t, workdir, "m_par%d" % len(devs), ["csv"],
                       "the parasitic model's run at %g of its parameter" % scale, stiff=True)
        if r is None:
            return
        h, pr = ck.read_csv(r.files["csv"])
        if h != head or len(pr) != len(rows):
            res["parasitic"] = ("fail", "columns or rows differ from the reduced run's")
            return
        devs.append(max((max(abs(a[j] - b[j]) for a, b in zip(rows, pr)) / max(spans[j], floor), head[j])
                        for j in slow))
    shown = ", ".join("%.3g (%s)" % d for d in devs)
    # above the tolerance at 1/10^6 but already falling as the parameter
    # (seed 5141 at 100 elements: a loop of a TF of 1.22 and an MTF of 1.23 +
    # 0.469 sin(t) makes the parasitic mode 10^4 times softer than stated,
    # 108 -> 8.3 -> 0.37 -> 0.0060; at 1/10^8 its undamped ringing exhausts
    # the solver): the next factor of 100 at the last step's rate is below it
    # Or falling steadily as the square root of the parameter (seed 1405 at
    # 100 elements, finding 28: a cubic C on an MTF modulated by sin(t) beside
    # the new stores; their undamped ringing, whose amplitude falls as the
    # square root of the parameter (finding 16), reaches the slow states:
    # 8.63 -> 0.759 -> 0.125 -> 0.0073, and the shrunk model's at every factor
    # of 10 from 1e-3 to 1e-7: 0.94, 0.27, 0.092, 0.031, 0.0080, each step
    # sqrt(10) closer). A reduced run with other dynamics levels off instead.
    ratio = devs[-1][0] / devs[-2][0] if len(devs) >= 2 and devs[-2][0] > 0 else 1.0
    fall2 = devs[-1][0] / devs[-3][0] if len(devs) >= 3 and devs[-3][0] > 0 else 1.0
    last = len(devs) == len(PARASITIC_SCALES)
    near = devs[-1][0] <= PARASITIC_TOL or (
        last and ratio <= PARASITIC_LIMIT and devs[-1][0] * ratio <= PARASITIC_TOL) or (
        last and fall2 <= PARASITIC_SQRT and devs[-1][0] <= PARASITIC_SQRT_TOL)
    if not converging() or not near:
        res["parasitic"] = ("fail", "the slow states' deviation from the reduced run at %s of the parasitic "
                            "parameter: %s" % (", ".join("%g" % x for x in PARASITIC_SCALES[:len(devs)]), shown))
    else:
        res["parasitic"] = ("pass", shown)
