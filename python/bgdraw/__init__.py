# SPDX-License-Identifier: BSD-3-Clause
"""bgdraw for Python: causal bond graphs in scripts and notebooks
(docs/python.md), over libbgdraw.

    import bgdraw
    m = bgdraw.Model.from_file("rlc.bg")
    m.analysis.bonds          # strokes, paths, loops, conflicts, index
    m.simulate()["C1.e"]      # NumPy arrays by column
    m.linear().poles
    m                         # in a notebook: the diagram

In IPython or Jupyter, `%load_ext bgdraw` adds the %%bgdraw cell magic."""
from ._lib import LibraryError, lib as _clib
from .errors import Diagnostic, Error, ModelError, RefusedError, UsageError, WriteError
from .model import Model
from .results import (Analysis, Bond, CausalPath, Conflict, Element, Equations, HTMLReport, Index,
                      Linear, Loop, Simulation, TransferFunction)

__version__ = _clib.bgd_version().decode()
API_VERSION = _clib.bgd_api_version()
library = _clib.path  # the libbgdraw file this package uses

__all__ = ["Model", "Analysis", "Element", "Bond", "CausalPath", "Loop", "Conflict", "Index",
           "Simulation", "Linear", "TransferFunction", "Equations", "HTMLReport", "Diagnostic", "Error",
           "ModelError", "UsageError", "RefusedError", "WriteError", "LibraryError",
           "from_file", "from_string"]

from_file = Model.from_file
from_string = Model.from_string


def load_ipython_extension(ip):
    """%load_ext bgdraw: the %%bgdraw cell magic."""
    from .magic import load_ipython_extension as load
    load(ip)
