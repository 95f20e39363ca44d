# SPDX-License-Identifier: BSD-3-Clause
"""The %%bgdraw cell magic's options, through run_cell (what the magic runs
in IPython; the notebook test runs it in a real kernel)."""
import numpy as np
import pytest

import bgdraw
from bgdraw.magic import run_cell
from conftest import cli

RC = "Se U = 1\n1 j\nR R1 = R0\nC C1 = 1e-3\nparam R0 = 2\nbond U -> j\nbond j -> R1\nbond j -> C1\n" \
     "simulate t_end = 0.01, dt = 1e-4\n"


def test_default_shows_the_model():
    m, shown = run_cell("", RC)
    assert shown == [m] and m.name == "cell"
    assert np.allclose(m.analysis.eigenvalues, [-500])


def test_options_as_the_command_line(tmp_path):
    ns = {}
    out = tmp_path / "rc.svg"
    m, shown = run_cell(f"--set R0=4 --show paths --style print -o {out} --as rc --name rc.bg", RC, ns)
    assert ns["rc"] is m and m.name == "rc"
    assert np.allclose(m.analysis.eigenvalues, [-1 / (4 * 1e-3)])
    (tmp_path / "rc.bg").write_text(RC)
    want = cli(str(tmp_path / "rc.bg"), "--set", "R0=4", "--show", "paths", "--style", "print",
               "-T", "svg")[1].decode()
    assert out.read_text() == want and shown[0].svg() == want


def test_text_outputs_instead_of_the_diagram(tmp_path):
    _, shown = run_cell("--check --equations latex --linear text", RC)
    check, eqs, lin = shown
    assert "states (1): C1.q" in check and repr(check) == str(check)
    assert eqs._repr_latex_().startswith("$$\\begin{align*}")
    assert "A = [-500]" in lin
    _, shown = run_cell(f"--simulate --report {tmp_path / 'r.pdf'} --plot {tmp_path / 'p.png'}", RC)
    assert "<svg" in shown[0]._repr_mimebundle_()["image/svg+xml"]
    assert (tmp_path / "r.pdf").read_bytes()[:5] == b"%PDF-"
    assert (tmp_path / "p.png").read_bytes()[:4] == b"\x89PNG"
    _, shown = run_cell(f"--bode {tmp_path / 'b.svg'} --step {tmp_path / 's.pdf'}", RC)
    assert "<svg" in (tmp_path / "b.svg").read_text()
    assert (tmp_path / "s.pdf").read_bytes()[:5] == b"%PDF-"
    m, _ = run_cell("--prefix rcm -W no-unused-param", RC + "param unused = 1\n")
    assert m.warnings == [] and "rcm_" in m.output("c").decode()
    with pytest.raises(bgdraw.ModelError, match="unused"):
        run_cell("-W error", RC + "param unused = 1\n")
    _, shown = run_cell("-T png", RC)
    assert shown[0]._repr_mimebundle_()["image/png"][:4] == b"\x89PNG"


def test_mistakes():
    with pytest.raises(bgdraw.UsageError, match="unrecognized arguments: --wings"):
        run_cell("--wings", RC)
    with pytest.raises(bgdraw.UsageError, match="NAME=VALUE"):
        run_cell("--set R0", RC)
    with pytest.raises(bgdraw.UsageError, match="causality"):
        run_cell("--causality nonsense", RC)
    with pytest.raises(bgdraw.ModelError) as e:
        run_cell("", "Se U = 1\n1 j\nbond U -> k\n")
    assert [(d.file, d.line) for d in e.value.errors][-1] == ("cell.bg", 3)
    assert "k" in e.value.errors[-1].message
