# SPDX-License-Identifier: BSD-3-Clause
"""What the Python package's tests share: the source and build trees (ctest
sets BGDRAW_SOURCE_DIR and BGDRAW_BINARY_DIR and puts build/python on
PYTHONPATH), the bgdraw executable to compare with, and a runner for it."""
import os
import subprocess

import pytest

ROOT = os.environ.get("BGDRAW_SOURCE_DIR") or os.path.abspath(
    os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.environ.get("BGDRAW_BINARY_DIR") or os.path.join(ROOT, "build")
BGDRAW = os.path.join(BUILD, "bgdraw")


def example(name):
    return os.path.join(ROOT, "examples", name)


def cli(*args, check=True):
    """bgdraw ARGS: (exit status, stdout bytes, stderr text)."""
    p = subprocess.run([BGDRAW, *args], capture_output=True)
    if check and p.returncode != 0:
        raise AssertionError(f"bgdraw {' '.join(args)}: {p.returncode}\n{p.stderr.decode()}")
    return p.returncode, p.stdout, p.stderr.decode()


@pytest.fixture
def rlc():
    import bgdraw
    with bgdraw.Model.from_file(example("rlc.bg")) as m:
        yield m
