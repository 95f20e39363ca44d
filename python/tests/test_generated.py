# SPDX-License-Identifier: BSD-3-Clause
"""Models nobody tuned the package to: random valid bond graphs of the
property campaign's generator (tests/property/gen.py; chains, junction trees,
two-ports, modulated sources, conflicts and incomplete causality among them)
and the test models of tests/data, each read from a string by the package and
from a file by the command line. Every record of the analysis must be the
JSON document's, and every simulation column the CSV's, bit for bit."""
import glob
import json
import os
import sys

import numpy as np
import pytest

import bgdraw
from conftest import ROOT, cli
from test_model import _json_view, _record_view

sys.path.insert(0, os.path.join(ROOT, "tests", "property"))
import gen  # noqa: E402

SEEDS = range(1, 61)
DATA = sorted(glob.glob(os.path.join(ROOT, "tests", "data", "**", "*.bg"), recursive=True))


def _compare(text, name, path):
    status, out, err = cli(path, "-T", "json", check=False)
    try:
        m = bgdraw.Model.from_string(text, name=name)
    except bgdraw.ModelError as e:  # both refuse the model, with the same words
        assert status == 1 and str(e) == err.rstrip("\n").replace(path, name)
        return None
    assert status in (0, 3), err
    assert _record_view(m.analysis) == _json_view(json.loads(out))
    return m


def _simulation_is_the_csv(m, path):
    status, csv, _ = cli(path, "--simulate", "-T", "csv", check=False)
    try:
        sim = m.simulate()
    except bgdraw.RefusedError as e:
        if e.simulation is None:
            assert csv == b""  # the command line writes nothing either
            return 0
        sim = e.simulation  # failed part of the way: the rows up to there, as in the CSV
        assert sim.partial and csv.decode().splitlines()[-1] == f"# partial: {e.reason.split(': ', 2)[2]}"
    lines = [line for line in csv.decode().splitlines() if not line.startswith("#")]
    assert lines[0].split(",") == ["t", *sim.names]
    rows = np.array([[float(x) for x in line.split(",")] for line in lines[1:]]).reshape(-1, 1 + len(sim))
    assert np.array_equal(rows[:, 0], sim.time)
    for j, name in enumerate(sim.names):
        assert np.array_equal(rows[:, 1 + j], sim[name], equal_nan=True), name
    return 1


@pytest.mark.parametrize("seed", SEEDS)
def test_generated_model(seed, tmp_path):
    text = gen.generate(seed, max_elems=40).text()
    path = str(tmp_path / f"g{seed}.bg")
    with open(path, "w") as f:
        f.write(text)
    m = _compare(text, path, path)
    if m is not None and m.analysis.form != "incomplete":
        _simulation_is_the_csv(m, path)


@pytest.mark.parametrize("path", DATA, ids=lambda p: os.path.relpath(p, ROOT))
def test_data_model(path):
    _compare(open(path, encoding="utf-8").read(), path, path)
