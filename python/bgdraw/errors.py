# SPDX-License-Identifier: BSD-3-Clause
"""The exceptions of bgdraw, one per status of the library (the command
line's exit statuses, docs/cli.md), and a diagnostic as a record."""
from dataclasses import dataclass, field


@dataclass(frozen=True)
class Diagnostic:
    """One error, warning or note: where (file, line, column from 1; 0: no
    position) and what; notes are the ones that belong to it (the submodel
    instance an error sits in)."""
    file: str
    line: int
    column: int
    severity: str
    message: str
    notes: tuple = field(default=())

    def __str__(self):
        where = self.file
        if self.line:
            where += f":{self.line}:{self.column}" if self.column else f":{self.line}"
        return f"{where}: {self.severity}: {self.message}"

    def as_dict(self):
        return {"file": self.file, "line": self.line, "column": self.column,
                "severity": self.severity, "message": self.message,
                "notes": [n.as_dict() for n in self.notes]}


class Error(Exception):
    """Every error bgdraw raises. str(e) is what the command line prints."""

    def __init__(self, text, diagnostics=()):
        super().__init__(text.rstrip("\n"))
        self.text = text
        self.diagnostics = list(diagnostics)

    def _render_traceback_(self):
        """IPython and Jupyter show bgdraw's message, not a Python traceback."""
        return self.text.rstrip("\n").split("\n")


class ModelError(Error):
    """The model has errors (or cannot give what was asked: no equations):
    diagnostics holds them as records, str(e) as bgdraw prints them, with the
    source line and a caret."""

    @property
    def errors(self):
        return [d for d in self.diagnostics if d.severity == "error"]


class UsageError(Error, ValueError):
    """A wrong argument: an unknown causality method, layer, highlight, output
    or printer (the command line's exit status 2)."""


class RefusedError(Error):
    """The analysis refuses it: a simulation or linear analysis refused or
    failed (exit status 3); reason says why. A simulation that failed part of
    the way keeps its rows up to there in simulation (else None)."""
    simulation = None

    @property
    def reason(self):
        return self.text.rstrip("\n")


class WriteError(Error, OSError):
    """An output could not be produced or written (exit status 4)."""


BY_STATUS = {1: ModelError, 2: UsageError, 3: RefusedError, 4: WriteError}
