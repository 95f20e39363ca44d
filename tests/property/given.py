# SPDX-License-Identifier: BSD-3-Clause
"""The property checks that apply to a model someone wrote (prop.py --file,
docs/property.md "Given models"): the tutorial's and the gallery's models, an
example, a user's file. The generator's own checks need the laws it wrote (the
stores' energies) or rewrite its text (renaming, reordering, reversing bonds);
on a given file bgdraw's analysis JSON describes the flat model instead, and
these run:
  robust, accepted    no crash, hang or undocumented exit; exit 0 or a stated refusal
  junction_power      each 0- and 1-junction: power in = power out, common effort/flow
  twoport_power       each TF, GY, MTF, MGY: power in = power out
  tellegen            the ports around the junction structure take no power in total
  detector            each detector reads its node's common effort or flow
  methods_agree       SCAP, relaxed and van Dijk: the same states and predicted index
  index_agree         predicted index = numeric index, or the run says why not
  export_c            an ODE's C export integrated by tests/export/*driver.c reproduces
                      the CSV (at rtol 1e-10 on both sides)
For the first five the model is run once more with its plot statements replaced by
every bond's effort and flow and every detector (fed on stdin with --stdin-name, so
its `use`d files and tables are found). The rest are reported "skip" with the reason."""
import json
import os
import re
import shutil
import tempfile

import check
import limits


class _Elem:
    """An element of the flat model under a name without dots (check.py takes
    the part before a dot as the element of a bond end)."""

    def __init__(self, kind, name, decl=""):
        self.kind, self.name, self.decl = kind, name, decl
        self.states, self.mods = [], []


class Given:
    """The flat model of a file, as check.py's physics reads a generated one:
    elements, bonds [number, tail, head] and detectors; no store energies."""

    def __init__(self, an, text):
        alias = lambda n: n.replace(".", "__")
        self.elems = [_Elem(e["kind"], alias(e["name"])) for e in an["elements"]]
        self.elems += [_Elem(d["kind"], alias(d["name"]), alias(d["node"])) for d in an.get("detectors") or []]
        self.dnames = [d["name"] for d in an.get("detectors") or []]
        self.bonds = [[b["id"], alias(b["from"]), alias(b["to"])] for b in an["bonds"]]
        self._text = text

    def stores(self):
        return []  # the energy checks need the generator's laws

    def detectors(self):
        return [x for x in self.elems if x.kind in ("De", "Df")]

    def text(self):
        return self._text


def _without_plots(text):
    """The model's text without its plot statements (and their continuation lines)."""
    out, cont = [], False
    for line in text.split("\n"):
        if cont or re.match(r"\s*plot\b", line):
            cont = line.rstrip().endswith("\\")
            continue
        out.append(line)
    return "\n".join(out)


def _tight(text):
    """The simulate statement at rtol 1e-10 (when it names none): the C export's
    drivers integrate at 1e-10, and the comparison is to 1e-5 of each range."""
    def tighten(mm):
        line, comment = mm.group(1), mm.group(2) or ""
        if "rtol" in line:
            return mm.group(0)
        if line.rstrip().endswith("]"):
            return line.rstrip()[:-1] + ", rtol = 1e-10]" + comment
        return line.rstrip() + ", rtol = 1e-10" + comment
    return re.sub(r"^(\s*simulate\b[^#\n]*?)(\s*#.*)?$", tighten, text, flags=re.M)


def _run(bgdraw, path, text, args):
    """bgdraw on text read from stdin as if it were the file path, bounded
    by the CPU time for its size (limits.py)."""
    p = limits.run([bgdraw, "-", "--stdin-name", path] + args, limits.cpu_bound(limits.bonds_of(text)),
                   stdin=text.encode())
    return check.Run(p.status, p.out, p.err.decode("utf-8", "replace"), {}, p.over)


def check_file(bgdraw, path):
    """{check: (status, detail)} for the model file path."""
    res = {}
    _checks(res, bgdraw, path)
    for c in check.CHECKS:
        res.setdefault(c, ("skip", "not for a given model (the generator's laws or text)"))
    return res


def _checks(res, bgdraw, path):
    text = open(path, encoding="utf-8").read()
    with tempfile.TemporaryDirectory() as wd:
        w = lambda n: os.path.join(wd, n)
        base = _run(bgdraw, path, text, ["--simulate", "-q", "-o", w("base.json"), "-o", w("base.csv")])
        if not check._robust(res, base, "simulate"):
            return
        if base.status not in (0, 3):
            res["accepted"] = ("fail", "exit status %d\n%s" % (base.status, base.err[-2000:]))
            return
        res["accepted"] = ("pass", "")
        an = json.load(open(w("base.json")))
        m = Given(an, text)
        cols = ["e%d, f%d" % (b[0], b[0]) for b in m.bonds] + m.dnames
        variant = _tight(_without_plots(text)) + "\nplot " + ", ".join(cols) + "\n"
        rows = None
        if base.status == 0:
            r = _run(bgdraw, path, variant, ["--simulate", "-q", "-o", w("m.csv")])
            if check._robust(res, r, "simulate every bond") and r.status == 0:
                rows = check.read_csv(w("m.csv"))[1]
        check._physics(res, m, None, rows, an)
        for c in ("energy_lossless", "energy_passive"):
            res[c] = ("skip", "the stores' energies need the generator's laws")
        for c in ("junction_power", "twoport_power", "detector"):
            if rows is not None and res[c] == ("skip", "no simulation"):
                res[c] = ("skip", "none in the model")
        # the other methods and the export read the model as a file: beside it, in the
        # temporary folder, with what it uses copied when it lives in a folder of its own
        with open(w("m.bg"), "w", encoding="utf-8") as f:
            f.write(variant)
        uses = re.findall(r'^\s*use\s+"([^"]+)"', text, re.M) + re.findall(r'table\(\s*"([^"]+)"', text)
        for u in uses:
            src = os.path.join(os.path.dirname(os.path.abspath(path)), u)
            if os.path.isfile(src):
                os.makedirs(os.path.dirname(w(u)) or wd, exist_ok=True)
                shutil.copy(src, w(u))
        check._methods(res, bgdraw, m, variant, wd, an)
        if rows is not None and re.search(r"\b(pulse|ramp)\(", text):
            # check.py knows the generator's step() and table(t); the drivers integrate
            # straight through these too
            res["export_c"] = ("skip", "input breakpoints (the drivers integrate straight through)")
        elif rows is not None and an["form"] != "ode":
            # the driver's IDA and bgdraw's agree on the states, but a DAE's derivative-level
            # variables (a dependent store's effort) are BDF estimates on both sides:
            # pendulum's hub torque differs by 1.6e-5 of its range at rtol 1e-10, each side
            # within 3e-5 of the exact value
            res["export_c"] = ("skip", "a DAE: its derivative-level variables are the integrators' BDF estimates")
        elif rows is not None:
            check._export_c(res, bgdraw, m, wd, 0, an, rows)
