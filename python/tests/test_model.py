# SPDX-License-Identifier: BSD-3-Clause
"""bgdraw.Model against independent results: the series RLC circuit's
closed forms (eigenvalues, step response, state space, transfer functions),
the command line's JSON document for every example, the command line's bytes
for the same outputs, and its diagnostics."""
import gc
import glob
import json
import math
import os

import numpy as np
import pytest

import bgdraw
from conftest import ROOT, cli, example

# examples/rlc.bg: V = 1, R0 = 10, L0 = 1e-3, C0 = 1e-6
V, R, L, C = 1.0, 10.0, 1e-3, 1e-6
ALPHA = R / (2 * L)
WD = np.sqrt(1 / (L * C) - ALPHA ** 2)


def test_rlc_strokes_and_index(rlc):
    a = rlc.analysis
    assert rlc.name == "rlc"
    assert [(b.number, b.from_, b.to, b.stroke) for b in a.bonds] == [
        (1, "U", "j", "to"), (2, "j", "R1", "from"), (3, "j", "L1", "to"), (4, "j", "C1", "from")]
    assert a.element("C1").causality == "integral" and a.element("L1").causality == "integral"
    assert a.element("R1").causality == "resistance"
    assert (a.form, a.index.predicted, a.index.numeric, a.states) == ("ode", 0, 0, 2)
    assert a.bond(3).to == "L1"


def test_rlc_eigenvalues_closed_form(rlc):
    eig = sorted(rlc.analysis.eigenvalues, key=lambda z: z.imag)
    assert np.allclose(eig, [-ALPHA - 1j * WD, -ALPHA + 1j * WD], rtol=1e-9)


def test_rlc_step_response_closed_form(rlc, tmp_path):
    sim = rlc.simulate()
    t = sim.time
    assert sim.names == ["C1.e", "L1.f"] and len(t) == 2001 and t[-1] == pytest.approx(2e-3)
    vc = V * (1 - np.exp(-ALPHA * t) * (np.cos(WD * t) + ALPHA / WD * np.sin(WD * t)))
    i = V / (L * WD) * np.exp(-ALPHA * t) * np.sin(WD * t)
    assert np.max(np.abs(sim["C1.e"] - vc)) < 1e-5  # of a 1 V step
    assert np.max(np.abs(sim["L1.f"] - i)) < 1e-6  # of a 25 mA peak
    assert sim["t"] is sim.time and list(sim.as_dict()) == ["t", "C1.e", "L1.f"]
    assert rlc.simulate() is sim  # run once
    # in a notebook: the model's plot, as --plot draws it
    cli(example("rlc.bg"), "--plot", str(tmp_path / "plot.svg"))
    plot = (tmp_path / "plot.svg").read_text()
    assert sim._repr_mimebundle_()["image/svg+xml"] == plot and "<svg" in plot


def test_rlc_simulation_is_the_csv(rlc):
    _, csv, _ = cli(example("rlc.bg"), "--simulate", "-T", "csv")
    rows = np.loadtxt(csv.decode().splitlines()[1:], delimiter=",")
    sim = rlc.simulate()
    assert np.array_equal(rows[:, 0], sim.time)
    assert np.array_equal(rows[:, 1], sim["C1.e"]) and np.array_equal(rows[:, 2], sim["L1.f"])


def test_rlc_linear_closed_form(rlc):
    lin = rlc.linear()
    assert lin.inputs == ["U"] and lin.outputs == ["L1.p", "C1.q"] and lin.reduced
    assert np.allclose(lin.A, [[-R / L, -1 / C], [1 / L, 0]])
    assert np.allclose(lin.B, [[1], [0]]) and np.allclose(lin.C, np.eye(2))
    assert np.allclose(lin.D, [[0], [0]])
    assert np.allclose(sorted(lin.poles, key=lambda z: z.imag), [-ALPHA - 1j * WD, -ALPHA + 1j * WD])
    q = lin.transfer_function("C1.q", "U")  # q/U = (1/L) / (s^2 + R/L s + 1/(LC))
    assert q.dc_gain == pytest.approx(C)
    assert np.allclose(q.num, [1 / L]) and np.allclose(q.den, [1, R / L, 1 / (L * C)])
    assert len(q.zeros) == 0
    # each transfer function is C (sI - A)^-1 B + D at a few frequencies
    for s in (1j * 1e3, 1j * 3e4, 2e4 + 5e3j):
        H = lin.C @ np.linalg.solve(s * np.eye(2) - lin.A, lin.B) + lin.D
        for t in lin.transfer_functions:
            k, j = lin.outputs.index(t.output), lin.inputs.index(t.input)
            assert t(s) == pytest.approx(H[k, j], rel=1e-9)
    assert str(q) == "C1.q/U = (1000) / (s^2 + 10000*s + 1e+09)"
    assert q._repr_latex_() == "$\\frac{1000}{s^{2} + 10000 s + 1 \\cdot 10^{9}}$"
    # in a notebook: bgdraw's LaTeX of the linear analysis, each align* block as display math
    latex = lin._repr_latex_()
    want = cli(example("rlc.bg"), "--linear", "latex")[1].decode()
    assert latex.count("$$\\begin{align*}") == want.count("\\begin{align*}") == 2
    assert "\\frac{C1.q}{U} &= \\frac{1000}{s^{2} + 10000 s + 1e+09}" in latex and "%" not in latex
    with pytest.raises(ValueError):
        lin.transfer_function()  # two outputs: name one


def test_linear_to_control(rlc):
    lin = rlc.linear()
    try:
        import control  # noqa: F401  (not a Debian 12 package)
    except ImportError:
        with pytest.raises(ImportError, match="python-control"):
            lin.to_control()
    else:
        sys = lin.to_control()
        assert np.allclose(sorted(sys.poles(), key=lambda z: z.imag), sorted(lin.poles, key=lambda z: z.imag))


def test_params_and_causality():
    m = bgdraw.Model.from_file(example("rlc.bg"), params={"C0": 1e-5, "R0": 20})
    a, wd = 20 / (2 * L), np.sqrt(1 / (L * 1e-5) - (20 / (2 * L)) ** 2)
    assert np.allclose(sorted(m.analysis.eigenvalues, key=lambda z: z.imag), [-a - 1j * wd, -a + 1j * wd])
    assert m.linear().transfer_function("C1.q").dc_gain == pytest.approx(1e-5)
    d = bgdraw.Model.from_file(example("delta.bg"), causality="vandijk")
    assert d.json()["method"] == "vandijk"


def _json_view(doc):
    """The command line's JSON document in the record API's terms."""
    return {
        "bonds": [(b["id"], b["from"], b["to"], b["stroke"]) for b in doc["bonds"]],
        # the JSON writes "none" where the library says "transfer" (junctions, TF, GY)
        "elements": [(e["name"], e["kind"], e["causality"] if e["causality"] != "none" else
                      "transfer" if e["kind"] in ("0", "1", "TF", "GY", "MTF", "MGY") else None)
                     for e in doc["elements"]],
        "paths": [(p["ends"][0], p["ends"][1], p["kind"], p["class"], p["order"], tuple(p["bonds"]))
                  for p in doc["causal_paths"]],
        "cloops": [(tuple(c["bonds"]), c["gain"]) for c in doc["causal_loops"]],
        "tloops": [(t["kind"], t["order"], tuple(t["bonds"]), t["gain"], t["gain_value"], t["algebraic"])
                   for t in doc["topological_loops"]],
        "conflicts": [(c["node"], c["type"], c["degree"], tuple(c["bonds"])) for c in doc["conflicts"]],
        "index": (doc["form"], doc["index"]["predicted"], doc["index"]["numeric"],
                  doc.get("reduced_form")),
        "states": len(doc["states"]),
    }


def _record_view(a):
    return {
        "bonds": [(b.number, b.from_, b.to, b.stroke) for b in a.bonds],
        "elements": [(e.name, e.kind, e.causality) for e in a.elements],
        "paths": [(p.from_, p.to, p.kind, p.class_, p.order, p.bonds) for p in a.causal_paths],
        "cloops": [(c.bonds, c.gain) for c in a.causal_loops],
        # a gain that divides by zero at the initial point is null in the JSON
        # (docs/json.md: JSON has no NaN or infinity)
        "tloops": [(t.kind, t.order, t.bonds, t.gain, t.gain_value if math.isfinite(t.gain_value) else None,
                    t.algebraic) for t in a.topological_loops],
        "conflicts": [(c.element, c.type, c.degree, c.bonds) for c in a.conflicts],
        "index": (a.form, a.index.predicted, a.index.numeric, a.index.reduced_form),
        "states": a.states,
    }


EXAMPLES = sorted(glob.glob(os.path.join(ROOT, "examples", "*.bg")))


@pytest.mark.parametrize("path", EXAMPLES, ids=os.path.basename)
def test_analysis_is_the_command_lines(path):
    _, out, _ = cli(path, "-T", "json")
    m = bgdraw.Model.from_file(path)
    assert _record_view(m.analysis) == _json_view(json.loads(out))
    plain = m.analysis.as_dict()
    assert json.loads(json.dumps(plain)) == plain  # plain data all the way down
    assert plain["bonds"][0]["from"] == m.analysis.bonds[0].from_


def test_conflicts_and_loops_as_records():
    m = bgdraw.Model.from_file(example("series_conductances.bg"))
    (c,) = m.analysis.conflicts
    assert (c.element, c.type, c.degree, c.bonds) == ("j", 2, 2, (2, 3, 4))
    assert m.analysis.as_dict()["conflicts"][0]["element"] == c.element
    loop = bgdraw.Model.from_file(example("bond_loop.bg")).analysis.causal_loops[0]
    assert loop.kind == "causal" and loop.class_ in (4, 5)


@pytest.mark.parametrize("kwargs,args", [
    ({}, []),
    ({"show": "paths"}, ["--show", "paths"]),
    ({"show": ["strokes", "numbers"], "style": "print"}, ["--show", "strokes,numbers", "--style", "print"]),
    ({"highlight": "path:3", "layout": "neato"}, ["--highlight", "path:3", "--layout", "neato"]),
])
def test_svg_is_the_command_lines(kwargs, args):
    path = example("class12_paths.bg")
    _, want, _ = cli(path, *args, "-T", "svg")
    m = bgdraw.Model.from_file(path)
    assert m.svg(**kwargs) == want.decode()
    assert m.svg() == cli(path, "-T", "svg")[1].decode()  # the call's options were for it only
    opened = bgdraw.Model.from_file(path, **kwargs)  # or the model's own
    assert opened.svg() == want.decode() and opened._repr_svg_() == want.decode()
    assert opened._repr_mimebundle_()["image/svg+xml"] == want.decode()


def test_save_report_equations(tmp_path, rlc):
    (tmp_path / "py").mkdir(), (tmp_path / "cli").mkdir()
    for ext in ("svg", "pdf", "png", "dot", "json", "tex", "py", "m", "mo", "csv"):
        rlc.save(tmp_path / "py" / f"rlc.{ext}")  # the same name: an Octave function is named after it
        cli(example("rlc.bg"), "-o", str(tmp_path / "cli" / f"rlc.{ext}"))
        assert (tmp_path / "py" / f"rlc.{ext}").read_bytes() == \
            (tmp_path / "cli" / f"rlc.{ext}").read_bytes(), ext
    rlc.save(tmp_path / "rlc.c")
    assert '#include "rlc.h"' in (tmp_path / "rlc.c").read_text() and (tmp_path / "rlc.h").exists()
    rlc.report(tmp_path / "r.pdf")
    assert (tmp_path / "r.pdf").read_bytes()[:5] == b"%PDF-"
    # the HTML report: the command line's bytes, rows with the analysis' bonds
    rlc.report(tmp_path / "r.html")
    cli(example("rlc.bg"), "--report", str(tmp_path / "cli.html"))
    page = rlc.report_html()
    assert page.encode() == (tmp_path / "r.html").read_bytes() == (tmp_path / "cli.html").read_bytes()
    for k, p in enumerate(rlc.analysis.causal_paths):
        assert '<tr id="path-%d" tabindex="0" data-bonds="%s"' % (k + 1, " ".join(map(str, p.bonds))) in page
    frame = page._repr_html_()
    assert frame.startswith("<iframe srcdoc=\"&lt;!DOCTYPE html&gt;") and "<script" not in frame
    page.save(tmp_path / "saved.html")
    assert (tmp_path / "saved.html").read_bytes() == (tmp_path / "r.html").read_bytes()
    latex = rlc.equations("latex")
    assert latex == cli(example("rlc.bg"), "--equations", "latex")[1].decode()
    assert latex._repr_latex_().startswith("$$\\begin{align*}")
    assert rlc.equations("text")._repr_latex_() is None
    mathml = rlc.equations("mathml")
    assert mathml == cli(example("rlc.bg"), "--equations", "mathml")[1].decode()
    assert mathml._repr_html_().startswith("<h3>Sorted equations</h3>") and rlc.equations("text")._repr_html_() is None
    eqs = rlc.equations("json")
    assert eqs["format"] and isinstance(eqs["equations"], list)
    assert rlc.check() == cli(example("rlc.bg"), "--check")[1].decode()
    assert rlc.plot(format="svg").startswith("<?xml") or "<svg" in rlc.plot(format="svg")
    with pytest.raises(bgdraw.UsageError, match="extension"):
        rlc.save(tmp_path / "rlc.gif")


BAD = "model pump\nSe U = 1\n1 j\nQ C1 = 1\nbond U -> j\nbond j -> C1\n"


def test_model_error_carries_diagnostics(tmp_path):
    with pytest.raises(bgdraw.ModelError) as e:
        bgdraw.Model.from_string(BAD, name="pump.bg")
    (d,) = e.value.errors
    assert (d.file, d.line, d.column, d.severity) == ("pump.bg", 4, 1, "error")
    assert "unknown element kind 'Q'" in d.message
    assert str(d) == f"pump.bg:4:1: error: {d.message}"
    # printed as the command line prints them
    (tmp_path / "pump.bg").write_text(BAD)
    status, _, err = cli(str(tmp_path / "pump.bg"), "--check", check=False)
    with pytest.raises(bgdraw.ModelError) as f:
        bgdraw.Model.from_file(tmp_path / "pump.bg")
    assert status == 1 and str(f.value) == err.rstrip("\n")
    assert "    4 | Q C1 = 1" in str(f.value)  # the line and a caret
    assert e.value._render_traceback_()[0] == str(d)


def test_text_is_every_byte():
    with pytest.raises(bgdraw.ModelError) as e:  # not cut at the NUL: the file's diagnostic
        bgdraw.Model.from_string("Se U = 1\n1 j\0\nC C1 = 1\nbond U -> j\nbond j -> C1\n",
                                 name="nul.bg")
    (d,) = e.value.errors
    assert (d.line, d.column) == (2, 4) and "NUL byte" in d.message
    with pytest.raises(bgdraw.ModelError, match="UTF-8"):
        bgdraw.Model.from_string(b"Se U = 1\n1 j\xff\n", name="latin.bg")
    m = bgdraw.Model.from_string(open(example("rlc.bg"), "rb").read(), name="rlc.bg")
    assert m.json() == bgdraw.Model.from_file(example("rlc.bg")).json()


def test_usage_and_refusals(rlc):
    with pytest.raises(bgdraw.UsageError, match="causality"):
        bgdraw.Model.from_file(example("rlc.bg"), causality="nonsense")
    with pytest.raises(bgdraw.UsageError, match="wings"):
        rlc.svg(show="wings")
    assert "<svg" in rlc.svg()  # the model is as it was
    with pytest.raises(bgdraw.UsageError):
        rlc.output("gif")
    with pytest.raises(TypeError, match="causalty"):
        bgdraw.Model.from_file(example("rlc.bg"), causalty="scap")
    static = bgdraw.Model.from_string("Se U = 1\n1 j\nR R1 = 2\nbond U -> j\nbond j -> R1\n",
                                      name="static.bg")
    with pytest.raises(bgdraw.RefusedError, match="no simulate block"):
        static.simulate()
    with pytest.raises(bgdraw.WriteError):
        rlc.save("/nonexistent-folder/x.svg")


def test_warnings_and_log():
    src = "param a = 1, unused = 3\nSe U = a\n1 j\nC C1 = 0\nbond U -> j\nbond j -> C1\n"
    m = bgdraw.Model.from_string(src, name="w.bg")
    assert len(m.warnings) == 2 and all(w.severity == "warning" for w in m.warnings)
    with pytest.raises(bgdraw.ModelError, match="Werror"):
        bgdraw.Model.from_string(src, name="w.bg", warnings="no-unused-param,error")
    seen = []
    r = bgdraw.Model.from_file(example("rlc.bg"), log=lambda level, msg: seen.append((level, msg)),
                               verbose=True)
    gc.collect()  # the callback lives as long as the model, not as long as the call
    before = len(seen)
    r.simulate()
    assert len([1 for level, _ in seen[before:] if level == 0]) >= 2  # stages after loading
    assert any("simulat" in msg for _, msg in seen[before:])


def test_closed_model():
    m = bgdraw.Model.from_file(example("rlc.bg"))
    m.close()
    with pytest.raises(ValueError, match="closed"):
        m.svg()
    assert repr(m) == "<bgdraw.Model (closed)>"


def test_threads():
    """Models on several threads at once give what they give alone; one model
    shared by threads that draw it with different layers gives each thread
    its own layers (a lock per model: the library's one thread per handle)."""
    from concurrent.futures import ThreadPoolExecutor
    names = ["rlc.bg", "slider_crank.bg", "hydraulic_bridge.bg", "delta.bg"]

    def work(name):
        m = bgdraw.Model.from_file(example(name))
        try:
            sim = m.simulate().as_dict()
        except bgdraw.RefusedError as e:
            sim = e.reason
        return m.svg(), m.json(), sim

    alone = [work(n) for n in names]
    with ThreadPoolExecutor(4) as pool:
        together = list(pool.map(work, names))
    for (svg, doc, sim), (svg2, doc2, sim2) in zip(alone, together):
        assert svg == svg2 and doc == doc2
        assert sim == sim2 if isinstance(sim, str) else all(np.array_equal(sim[k], sim2[k]) for k in sim)
    shared = bgdraw.Model.from_file(example("class12_paths.bg"))
    layers = ["paths", "loops", "strokes", "all", "none", "conflicts"]
    want = {s: shared.svg(show=s) for s in layers}
    assert len(set(want.values())) == len(layers)
    with ThreadPoolExecutor(3) as pool:
        got = list(pool.map(lambda s: (s, shared.svg(show=s)), layers * 20))
    assert all(svg == want[s] for s, svg in got)
