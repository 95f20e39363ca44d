# SPDX-License-Identifier: BSD-3-Clause
"""Every command and snippet of docs/python.md, run: the shell block (build,
install into ~/.local of a private HOME, import with Debian's python3), each
Python block in order in one namespace with its printed output compared with
the text block after it, and the Jupyter blocks in an IPython shell."""
import contextlib
import io
import os
import re
import shutil
import subprocess
import sys

import numpy as np

import bgdraw
from conftest import BUILD, ROOT, example

FENCE = re.compile(r"^```(\w+)\n(.*?)^```$", re.M | re.S)


def blocks():
    text = open(os.path.join(ROOT, "docs", "python.md")).read()
    return [(m.group(1), m.group(2)) for m in FENCE.finditer(text)]


def test_the_page_has_its_blocks():
    kinds = [k for k, _ in blocks()]
    assert kinds.count("sh") == 1 and kinds.count("python") >= 6 and kinds.count("ipython") >= 5


def test_install_commands(tmp_path):
    (sh,) = [code for kind, code in blocks() if kind == "sh"]
    script = re.sub(r"(?<![-\w/])build\b", BUILD, sh)  # the build folder, not --build
    env = {k: v for k, v in os.environ.items() if not k.startswith(("PYTHON", "BGDRAW_"))}
    env.update(HOME=str(tmp_path), PATH="/usr/bin:" + env.get("PATH", ""))
    p = subprocess.run(["bash", "-e", "-c", script], cwd=ROOT, env=env, capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr
    assert p.stdout.splitlines()[-1] == bgdraw.__version__
    v = f"python{sys.version_info.major}.{sys.version_info.minor}"
    assert os.path.isfile(tmp_path / ".local" / "lib" / v / "site-packages" / "bgdraw" / "model.py")
    assert os.path.exists(tmp_path / ".local" / "bin" / "bgdraw")


def test_python_snippets(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    shutil.copy(example("rlc.bg"), tmp_path)
    namespace = {}
    found = blocks()
    ran = 0
    for i, (kind, code) in enumerate(found):
        if kind != "python":
            continue
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(compile(code, f"docs/python.md block {i + 1}", "exec"), namespace)
        ran += 1
        if i + 1 < len(found) and found[i + 1][0] == "text":
            assert out.getvalue() == found[i + 1][1], f"block {i + 1}"
        else:
            assert out.getvalue() == "", f"block {i + 1} prints but the page shows no output"
    assert ran >= 6
    for f in ("rlc.pdf", "rlc.png", "rlc-report.pdf", "rlc-report.html"):
        assert (tmp_path / f).stat().st_size > 1000


def test_jupyter_snippets(tmp_path, monkeypatch):
    from IPython.core.interactiveshell import InteractiveShell
    monkeypatch.chdir(tmp_path)
    shutil.copy(example("rlc.bg"), tmp_path)
    shell = InteractiveShell.instance()
    results = []
    for kind, code in blocks():
        if kind == "ipython":
            r = shell.run_cell(code)
            assert r.success, (code, r.error_in_exec)
            results.append(r.result)
    model, latex, _, _, eigenvalues = results
    assert "<svg" in model._repr_mimebundle_()["image/svg+xml"]
    assert latex._repr_latex_().startswith("$$\\begin{align*}")
    assert np.allclose(eigenvalues, [-500])
    assert shell.user_ns["rc"].name == "cell"
