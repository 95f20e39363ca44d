# SPDX-License-Identifier: BSD-3-Clause
"""bgdraw.Model: one model and everything bgdraw computes about it, over a
libbgdraw handle (the command line's run: each stage runs once, when asked).
"""
import ctypes
import functools
import json
import os
import threading

import numpy as np

from . import _lib
from ._lib import lib
from .errors import BY_STATUS, Diagnostic, ModelError, RefusedError, UsageError
from .results import (Analysis, Bond, CausalPath, Conflict, Element, Equations, HTMLReport, Index, Linear,
                      Loop, Simulation, TransferFunction)

# Files bgdraw writes, by extension: (output kind, form)
_BY_EXTENSION = {
    "svg": ("svg", None), "pdf": ("pdf", None), "png": ("png", None), "dot": ("dot", None),
    "json": ("json", None), "tex": ("tex", None), "c": ("c", None), "h": ("h", None),
    "py": ("py", None), "m": ("m", None), "mo": ("mo", None), "csv": ("csv", None),
}
_DRAWING = ("show", "style", "highlight", "layout")


def _b(s):
    return None if s is None else os.fsencode(s) if isinstance(s, os.PathLike) else str(s).encode()


def _s(b):
    # the library's text; a diagnostic quotes the model's line, which may not be UTF-8
    return None if b is None else b.decode("utf-8", "replace")


def _diagnostic(d):
    notes = tuple(_diagnostic(d.notes[i]) for i in range(max(d.nnotes, 0)))
    return Diagnostic(_s(d.file), d.line, d.column, _s(d.severity), _s(d.message), notes)


def _doubles(ptr, n):
    return np.ctypeslib.as_array(ptr, shape=(n,)).copy() if n > 0 and ptr else np.zeros(0)


def _complex(re, im, n):
    return _doubles(re, n) + 1j * _doubles(im, n) if n > 0 else np.zeros(0, dtype=complex)


def _matrix(ptr, rows, cols):
    """A column-major C matrix as a 2-D array."""
    if rows * cols == 0 or not ptr:
        return np.zeros((rows, cols))
    return np.ctypeslib.as_array(ptr, shape=(cols, rows)).T.copy()


def _ints(ptr, n):
    return tuple(ptr[i] for i in range(n))


def _none_if(v, absent):
    return None if v == absent else v


def _shown(value):
    """show= as a list or a comma string."""
    if value is None or isinstance(value, str):
        return value
    return ",".join(value)


def _locked(method):
    """One thread at a time in a handle (the library's rule); the library
    runs without the GIL, so different models work on different threads at
    once."""
    @functools.wraps(method)
    def run(self, *args, **kwargs):
        with self._lock:
            return method(self, *args, **kwargs)
    return run


class Model:
    """A bond graph model, loaded and checked.

        m = bgdraw.Model.from_file("rlc.bg", params={"R0": 20})
        m.analysis.bonds, m.analysis.index.predicted
        m.svg(show="paths"), m.save("rlc.pdf"), m.report("rlc-report.pdf")
        sim = m.simulate(); sim["C1.e"]
        lin = m.linear(); lin.A, lin.poles

    Loading raises ModelError (the diagnostics as records and as bgdraw prints
    them) or UsageError (a wrong option). The keyword options are the command
    line's: causality (--causality), params (--set NAME=VALUE), show, style,
    highlight, layout (the diagrams' defaults), max_list, max_errors, verify,
    warnings (-W), prefix (exported C's symbols); log, a function (level,
    message) for the run's messages (level 0 progress, with verbose=True; 1 a
    result; 2 a note; 3 a warning); warnings of the model are in
    m.diagnostics."""

    def __init__(self, *_args, **_kw):
        raise TypeError("use bgdraw.Model.from_file(path) or bgdraw.Model.from_string(text)")

    @classmethod
    def from_file(cls, path, **options):
        """Reads, parses and checks the model file at path."""
        return cls._open(None, None, os.fspath(path), options)

    @classmethod
    def from_string(cls, text, name="<string>", **options):
        """Parses and checks model text (str, or bytes of UTF-8); name appears
        in the diagnostics and gives the model's default name (its stem:
        "pump.bg" names it pump)."""
        return cls._open(name, text, None, options)

    @classmethod
    def _open(cls, name, text, path, options):
        self = object.__new__(cls)
        self._handle = None
        self._lock = threading.RLock()
        self._source = path or name
        known = {"causality", "params", "max_list", "max_errors", "verify", "warnings", "prefix",
                 "log", "verbose", *_DRAWING}
        unknown = set(options) - known
        if unknown:
            raise TypeError(f"unknown option {', '.join(sorted(unknown))} "
                            f"(options: {', '.join(sorted(known))})")
        self._options = dict(options)
        o = self._c_options(options)
        if path is not None:
            self._handle = lib.bgd_open_file(_b(path), ctypes.byref(o))
        else:  # every byte, a NUL too (then the diagnostic a file with one gets)
            data = text if isinstance(text, bytes) else str(text).encode("utf-8", "surrogateescape")
            self._handle = lib.bgd_open_buffer(_b(name), data, len(data), ctypes.byref(o))
        if not self._handle:
            raise MemoryError("bgdraw: out of memory")
        status = lib.bgd_status(self._handle)
        self.diagnostics = self._read_diagnostics()
        if status != _lib.OK:
            text = _lib.take_string(lib.bgd_diagnostics_text(self._handle)).decode("utf-8", "replace")
            diags = self.diagnostics
            self.close()
            raise BY_STATUS.get(status, ModelError)(text, diags)
        self._drawing = {k: options.get(k) for k in _DRAWING}
        self._cache = {}
        return self

    def _c_options(self, options):
        o = _lib.Options()
        lib.bgd_options_init(ctypes.byref(o))
        keep = []  # what the C structure points at, alive while the handle is
        params = options.get("params") or {}
        if params:
            names = (ctypes.c_char_p * len(params))(*[_b(k) for k in params])
            values = (ctypes.c_double * len(params))(*[float(v) for v in params.values()])
            o.nparams, o.param_names, o.param_values = len(params), names, values
            keep += [names, values]
        for key in ("causality", "style", "highlight", "layout", "prefix", "warnings"):
            if options.get(key) is not None:
                v = _b(options[key])
                keep.append(v)
                setattr(o, key, v)
        if options.get("show") is not None:
            v = _b(_shown(options["show"]))
            keep.append(v)
            o.show = v
        if options.get("max_list"):
            o.max_list = int(options["max_list"])
        if options.get("max_errors") is not None:
            o.max_errors = int(options["max_errors"])
        o.verify = int(bool(options.get("verify")))
        log = options.get("log")
        if log is not None:
            def relay(_ctx, level, message):
                try:
                    log(level, message.decode("utf-8", "replace"))
                except Exception:  # an exception cannot cross the C library
                    pass
            callback = _lib.LOG_FN(relay)  # the handle calls it until it is freed
            o.log = callback
            o.verbose = int(bool(options.get("verbose")))
            keep.append(callback)
        self._keep = keep
        return o

    def _read_diagnostics(self):
        arr = ctypes.POINTER(_lib.Diagnostic)()
        n = lib.bgd_diagnostics(self._handle, ctypes.byref(arr))
        return [_diagnostic(arr[i]) for i in range(n)]

    # ----------------------------------------------------------- life cycle
    @_locked
    def close(self):
        """Frees the library's handle (also when the object is collected)."""
        if getattr(self, "_handle", None):
            lib.bgd_free(self._handle)
            self._handle = None

    def __del__(self):
        if getattr(self, "_handle", None) and lib is not None:  # (not at interpreter exit)
            lib.bgd_free(self._handle)
            self._handle = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _h(self):
        if not self._handle:
            raise ValueError("bgdraw: the model was closed")
        return self._handle

    def __repr__(self):
        if not self._handle:
            return "<bgdraw.Model (closed)>"
        return (f"<bgdraw.Model {self.name}: {self.count('elements')} elements, "
                f"{self.count('bonds')} bonds, {self.count('states')} states>")

    # -------------------------------------------------------------- results
    @property
    @_locked
    def name(self):
        return _s(lib.bgd_name(self._h()))

    @property
    def warnings(self):
        return [d for d in self.diagnostics if d.severity == "warning"]

    @_locked
    def count(self, what):
        """How many elements, bonds, params, states, dependent_stores,
        conflicts, causal_paths, causal_loops, topological_loops, unknowns,
        rows, columns, poles, transfer_functions or eigenvalues."""
        n = lib.bgd_count(self._h(), _b(what))
        if n < 0:
            raise UsageError(f"bgdraw: cannot count '{what}'")
        return n

    def _records(self, call, record, what):
        out = []
        for i in range(self.count(what)):
            r = record()
            call(self._h(), i, ctypes.byref(r))
            out.append(r)
        return out

    @property
    def analysis(self):
        """The causal analysis as objects (Analysis; .as_dict() for plain
        dicts), computed once."""
        if "analysis" not in self._cache:
            self._cache["analysis"] = self._analysis()
        return self._cache["analysis"]

    @_locked
    def _analysis(self):
        h = self._h()
        elements = tuple(Element(_s(e.name), _s(e.kind), _s(e.causality))
                         for e in self._records(lib.bgd_element_at, _lib.Element, "elements"))
        bonds = tuple(Bond(b.number, _s(b.from_), _s(b.to), _s(b.stroke))
                      for b in self._records(lib.bgd_bond_at, _lib.Bond, "bonds"))
        paths = tuple(CausalPath(_s(p.from_), _s(p.to), _s(p.kind), _none_if(p.cls, 0),
                                 _none_if(p.order, _lib.NO_ORDER),
                                 _ints(p.bonds, p.nbonds))
                      for p in self._records(lib.bgd_causal_path_at, _lib.Path, "causal_paths"))
        cloops = tuple(Loop(_s(c.kind), _ints(c.bonds, c.nbonds), _s(c.gain), c.gain_value,
                            class_=c.cls)
                       for c in self._records(lib.bgd_causal_loop_at, _lib.Loop, "causal_loops"))
        tloops = tuple(Loop(_s(t.kind), _ints(t.bonds, t.nbonds), _s(t.gain), t.gain_value,
                            order=t.order, algebraic=bool(t.algebraic))
                       for t in self._records(lib.bgd_topological_loop_at, _lib.Loop,
                                              "topological_loops"))
        conflicts = tuple(Conflict(_s(c.element), c.type, c.degree, _ints(c.bonds, c.nbonds))
                          for c in self._records(lib.bgd_conflict_at, _lib.Conflict, "conflicts"))
        ix = _lib.Index()
        lib.bgd_index_info(h, ctypes.byref(ix))
        index = Index(_s(ix.form), _none_if(ix.predicted, -1), _s(ix.reason),
                      _none_if(ix.numeric, -1), _s(ix.numeric_status), _s(ix.reduced_form),
                      _s(ix.reduction))
        re, im = _lib.DOUBLES(), _lib.DOUBLES()
        n = lib.bgd_eigenvalues(h, ctypes.byref(re), ctypes.byref(im))
        return Analysis(self.name, elements, bonds, paths, cloops, tloops, conflicts,
                        self.count("states"), self.count("dependent_stores"), index,
                        _complex(re, im, n))

    def json(self):
        """The analysis document (docs/json.md) as dicts: with the trace,
        signals, estimates, and the simulation and linear analysis when the
        model asks for them."""
        return json.loads(self.output("json"))

    def check(self):
        """What `bgdraw --check` prints: the model and analysis summary."""
        return self.output("check").decode("utf-8", "replace")

    def equations(self, printer="text"):
        """The equations as a printer writes them: "text", "latex", "mathml",
        "json" (then as dicts) or "c". In a notebook LaTeX and MathML display
        as mathematics."""
        data = self.output("equations", printer).decode("utf-8", "replace")
        return json.loads(data) if printer == "json" else Equations(data, printer)

    @_locked
    def simulate(self):
        """Runs the model's simulate block (once): a Simulation, each output
        column by name as a NumPy array. RefusedError when the simulation is
        refused or fails, with the reason; after a failure part of the way,
        its simulation attribute holds the rows up to there (partial)."""
        if "simulation" not in self._cache:
            self._cache["simulation"] = self._simulation()
        sim = self._cache["simulation"]
        if isinstance(sim, Exception):
            raise sim
        return sim

    def _simulation(self):
        s = _lib.Simulation()
        st = lib.bgd_simulate(self._h(), ctypes.byref(s))
        if st == _lib.MODEL:
            return ModelError("bgdraw: the model has no equations to simulate")
        sim = None
        if s.nrows > 0:
            columns = {_s(s.names[j]): _doubles(lib.bgd_column(self._h(), j), s.nrows)
                       for j in range(s.ncolumns)}
            sim = Simulation(_doubles(s.time, s.nrows), columns, _s(s.solver),
                             bool(s.partial) or st != _lib.OK,
                             plot=lambda: self.output("plot", "svg").decode("utf-8", "replace"))
        if st != _lib.OK:  # a failure part of the way: its rows up to there, as the CSV has them
            e = RefusedError(f"bgdraw: simulation refused: {_s(s.message) or 'no reason given'}")
            e.simulation = sim
            return e
        return sim

    @_locked
    def linear(self):
        """The linear analysis (the model's linearise statement, else at the
        initial point): A, B, C, D, poles and transfer functions. RefusedError
        when it is refused (no steady state, equations not formed)."""
        if "linear" in self._cache:
            return self._cache["linear"]
        h = self._h()
        l = _lib.Linear()
        st = lib.bgd_linearise(h, ctypes.byref(l))
        if st == _lib.MODEL:
            raise ModelError("bgdraw: the model has no equations to linearise")
        if st != _lib.OK:
            raise RefusedError(f"bgdraw: linear analysis refused: {_s(l.message) or 'no reason'}")
        inputs = [_s(l.inputs[i]) for i in range(l.nu)]
        outputs = [_s(l.outputs[i]) for i in range(l.ny)]
        tfs = []
        for k in range(self.count("transfer_functions")):
            t = _lib.Transfer()
            lib.bgd_transfer_function_at(h, k, ctypes.byref(t))
            tfs.append(TransferFunction(inputs[t.input], outputs[t.output],
                                        _doubles(t.num, t.nnum), _doubles(t.den, t.nden),
                                        t.dc_gain, _complex(t.pole_re, t.pole_im, t.npoles),
                                        _complex(t.zero_re, t.zero_im, t.nzeros)))
        n = l.n
        lin = Linear(_matrix(l.A, n, n), _matrix(l.B, n, l.nu), _matrix(l.C, l.ny, n),
                     _matrix(l.D, l.ny, l.nu), inputs, outputs,
                     _complex(l.pole_re, l.pole_im, l.npoles), bool(l.reduced), tfs,
                     latex=lambda: self.output("linear", "latex").decode("utf-8", "replace"))
        self._cache["linear"] = lin
        return lin

    # -------------------------------------------------------------- outputs
    def _raise(self, status):
        text = _s(lib.bgd_last_error(self._h())) or f"bgdraw: failed with status {status}\n"
        raise BY_STATUS.get(status, ModelError)(text)

    def _with_drawing(self, drawing, produce):
        """produce() with drawing options (show, style, highlight, layout) for
        this one call; the model's own ones after it."""
        asked = {k: v for k, v in drawing.items() if v is not None}
        if not asked:
            return produce()
        self._set_drawing({**self._drawing, **asked})
        try:
            return produce()
        finally:
            self._set_drawing(self._drawing)

    def _set_drawing(self, d):
        o = _lib.Options()
        lib.bgd_options_init(ctypes.byref(o))
        keep = [_b(_shown(d.get("show"))), _b(d.get("style")), _b(d.get("highlight")),
                _b(d.get("layout"))]
        o.show, o.style, o.highlight, o.layout = keep
        st = lib.bgd_set_drawing(self._h(), ctypes.byref(o))
        if st != _lib.OK:
            self._raise(st)

    @_locked
    def output(self, kind, form=None, **drawing):
        """Any output as bgdraw writes it, as bytes: "svg", "pdf", "png",
        "dot", "json", "check", "equations" (form "text", "latex", "json",
        "c"), "tex", "c", "h", "py", "m", "mo", "csv", "plot" (form a format),
        "report", "linear" (form "text", "latex", "json", "octave", "python"),
        "bode", "nyquist", "step". Drawing options (show, style, highlight,
        layout) hold for this call."""
        def produce():
            data, n = ctypes.c_void_p(), ctypes.c_size_t()
            st = lib.bgd_output(self._h(), _b(kind), _b(form), ctypes.byref(data), ctypes.byref(n))
            if st != _lib.OK:
                self._raise(st)
            return _lib.take_string(data.value, n.value)
        return self._with_drawing(drawing, produce)

    @_locked
    def write(self, path, kind, form=None, **drawing):
        """An output into a file, written atomically (see output())."""
        def produce():
            st = lib.bgd_write(self._h(), _b(kind), _b(form), _b(os.fspath(path)))
            if st != _lib.OK:
                self._raise(st)
        self._with_drawing(drawing, produce)

    def svg(self, show=None, style=None, highlight=None, layout=None):
        """The annotated diagram as SVG text. show: layers as --show (a comma
        string or a list: "paths", ["strokes", "numbers"], "all"); style: a
        style name ("print", "slides") or file; highlight: "path:K", "loop:K",
        "conflict:K"; layout: "dot", "neato", ..., "rows"."""
        return self.output("svg", show=show, style=style, highlight=highlight,
                           layout=layout).decode("utf-8", "replace")

    def png(self, show=None, style=None, highlight=None, layout=None):
        return self.output("png", show=show, style=style, highlight=highlight, layout=layout)

    def save(self, path, show=None, style=None, highlight=None, layout=None):
        """Writes what the file's extension names, as `bgdraw -o FILE`:
        the diagram (.svg, .pdf, .png, .dot), the analysis (.json), the
        equations as LaTeX (.tex), exported code (.c with its .h, .py, .m,
        .mo), the simulation (.csv)."""
        ext = os.path.splitext(os.fspath(path))[1].lstrip(".").lower()
        if ext not in _BY_EXTENSION:
            raise UsageError(f"bgdraw: cannot tell what to write from '{os.fspath(path)}' "
                             f"(extensions: {', '.join(sorted(_BY_EXTENSION))})")
        kind, form = _BY_EXTENSION[ext]
        self.write(path, kind, form, show=show, style=style, highlight=highlight, layout=layout)
        if ext == "c":  # the header the source includes, beside it
            self.write(os.path.splitext(os.fspath(path))[0] + ".h", "h")

    def report(self, path, style=None):
        """The analysis report (as --report): the multi-page PDF, or the
        interactive HTML page for a path ending in .html or .htm."""
        self.write(path, "report", style=style)

    def report_html(self, style=None):
        """The HTML analysis report as an HTMLReport (a str; in a notebook
        it displays in a frame): the same bytes as --report FILE.html."""
        page = self.output("report", "html", style=style).decode("utf-8")
        return HTMLReport(page, self.name)

    def plot(self, path=None, format=None):
        """The simulation's plot (as --plot): into path (its extension the
        format), or as bytes/str of format ("svg", "pdf", "png")."""
        if path is not None:
            fmt = format or os.path.splitext(os.fspath(path))[1].lstrip(".").lower()
            return self.write(path, "plot", fmt)
        data = self.output("plot", format or "svg")
        return data.decode("utf-8", "replace") if (format or "svg") == "svg" else data

    # -------------------------------------------------------------- Jupyter
    def _repr_svg_(self):
        return self.svg()

    def _repr_mimebundle_(self, include=None, exclude=None):
        """The diagram as SVG, and a line of text for a plain display."""
        return {"image/svg+xml": self.svg(), "text/plain": repr(self)}
