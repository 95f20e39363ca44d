# SPDX-License-Identifier: BSD-3-Clause
"""tour.ipynb executed headless by Debian's Jupyter (jupyter nbconvert
--execute, the python3 kernel of ipykernel): the model displays as the
command line's SVG, equations as LaTeX mathematics, a simulation as its
plot, the simulation's and the linear analysis' numbers are the closed forms', the %%bgdraw magic draws a
cell's model and shows its equations, and a bad model fails its cell with
bgdraw's diagnostic instead of a Python traceback."""
import json
import os
import re
import shutil
import subprocess

import numpy as np

import bgdraw

from conftest import ROOT, cli, example

RC = "Se U = 1\n1 j\nR R1 = 2\nC C1 = 1e-3\nbond U -> j\nbond j -> R1\nbond j -> C1\n"


def _execute(tmp_path):
    shutil.copy(os.path.join(ROOT, "python", "tests", "tour.ipynb"), tmp_path)
    shutil.copy(example("rlc.bg"), tmp_path)
    # the kernel imports the package these tests import
    package = os.path.dirname(os.path.dirname(os.path.abspath(bgdraw.__file__)))
    env = dict(os.environ, PYDEVD_DISABLE_FILE_VALIDATION="1", PYTHONPATH=package)
    jupyter = shutil.which("jupyter", path="/usr/bin") or "jupyter"
    subprocess.run([jupyter, "nbconvert", "--to", "notebook", "--execute", "tour.ipynb",
                    "--output", "done.ipynb", "--ExecutePreprocessor.timeout=300"],
                   cwd=tmp_path, env=env, check=True, capture_output=True)
    nb = json.loads((tmp_path / "done.ipynb").read_text())
    return [c.get("outputs", []) for c in nb["cells"] if c["cell_type"] == "code"]


def _data(outputs, mime):
    found = [o["data"][mime] for o in outputs if mime in o.get("data", {})]
    assert len(found) == 1, outputs
    return "".join(found[0]) if isinstance(found[0], list) else found[0]


def _stream(outputs):
    return "".join("".join(o["text"]) if isinstance(o["text"], list) else o["text"]
                   for o in outputs if o["output_type"] == "stream")


def test_notebook_runs_headless(tmp_path):
    cells = _execute(tmp_path)
    # a model displays as its diagram: the command line's bytes
    assert _data(cells[0], "image/svg+xml") == cli(example("rlc.bg"), "-T", "svg")[1].decode()
    # equations as mathematics
    latex = _data(cells[1], "text/latex")
    assert latex.startswith("$$\\begin{align*}") and latex.rstrip().endswith("\\end{align*}$$")
    assert "\\dot{q_{\\mathrm{C1}}} &= f_{4}" in latex
    # numbers: the capacitor charged to the 1 V step; DC gain q/U = C0; the poles
    assert _stream(cells[2]) == "C1.e at the end: 1.0\n"
    cli(example("rlc.bg"), "--plot", str(tmp_path / "plot.svg"))  # a simulation shows as its plot
    assert _data(cells[2], "image/svg+xml") == (tmp_path / "plot.svg").read_text()
    gain = float(re.search(r"DC gain of C1.q/U: (\S+)", _stream(cells[3])).group(1))
    assert abs(gain - 1e-6) < 1e-15
    poles = eval(_data(cells[3], "text/plain"), {"array": np.array})  # numpy's repr
    wd = np.sqrt(1e9 - 5000.0 ** 2)
    assert np.allclose(sorted(poles, key=lambda z: z.imag), [-5000 - 1j * wd, -5000 + 1j * wd])
    # the cell magic: the cell's model drawn with the magic line's options
    (tmp_path / "cell.bg").write_text(RC)
    want = cli(str(tmp_path / "cell.bg"), "--show", "paths", "-T", "svg")[1].decode()
    assert _data(cells[4], "image/svg+xml") == want
    eig = eval(_data(cells[5], "text/plain"), {"array": np.array})
    assert np.allclose(eig, [-1 / (2 * 1e-3)])  # -1/(R C)
    latex = _data(cells[6], "text/latex")
    assert "&= 0.5 e_{2}" in latex and latex.startswith("$$\\begin{align*}")
    # a bad model: bgdraw's diagnostic, line and caret, no Python traceback
    (err,) = [o for o in cells[7] if o["output_type"] == "error"]
    assert err["ename"] == "ModelError"
    assert err["traceback"] == ["cell.bg:3:1: error: unknown element kind 'Q' (did you mean 'C'?)",
                                "    3 | Q C1 = 1e-3", "      | ^"]
