# SPDX-License-Identifier: BSD-3-Clause
"""What bgdraw finds in a model, as Python objects: each has as_dict() for
plain dicts (the keys of the analysis JSON, docs/json.md, where it has one)."""
import re
from collections.abc import Mapping
from dataclasses import dataclass, field, fields

import numpy as np


def _plain(value):
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if hasattr(value, "as_dict"):
        return value.as_dict()
    return value


class _Record:
    # attribute -> key where Python's name differs from the JSON's
    _keys = {"from_": "from", "class_": "class"}

    def as_dict(self):
        return {self._keys.get(f.name, f.name): _plain(getattr(self, f.name)) for f in fields(self)}


@dataclass(frozen=True)
class Element(_Record):
    name: str
    kind: str  # "R", "C", "I", "Se", "Sf", "0", "1", "TF", "GY", ...
    causality: str  # "integral", "derivative", "resistance", ...; None for none


@dataclass(frozen=True)
class Bond(_Record):
    number: int  # as written in the model
    from_: str  # the element the half arrow leaves
    to: str  # the element it points at
    stroke: str  # "from" or "to": the end with the causal stroke; None: no stroke


@dataclass(frozen=True)
class CausalPath(_Record):
    from_: str
    to: str
    kind: str  # "R-R", "C-I", ...
    class_: int  # van Dijk's class 1 or 2; None: none
    order: int  # integrations in the loop it closes; None: it closes none (from a source)
    bonds: tuple  # bond numbers from end to end


@dataclass(frozen=True)
class Loop(_Record):
    kind: str  # "causal", or a topological loop's "flat" / "open"
    bonds: tuple
    gain: str  # symbolic
    gain_value: float
    class_: int = None  # causal loops: 4 or 5
    order: int = None  # topological loops: integrations around it
    algebraic: bool = None  # topological loops: an algebraic loop


@dataclass(frozen=True)
class Conflict(_Record):
    element: str
    type: int  # 1 or 2
    degree: int  # type 2: k; type 1: 0
    bonds: tuple


@dataclass(frozen=True)
class Index(_Record):
    form: str  # "ode", "dae", "incomplete"
    predicted: int  # from the causal pattern; None: unknown
    reason: str
    numeric: int  # Algorithm 4.1; None when not computed or singular
    numeric_status: str  # "computed", "singular", "not computed"
    reduced_form: str  # "ode" / "dae" after symbolic elimination; None
    reduction: str  # what index reduction did, in words; None: not tried


@dataclass(frozen=True)
class Analysis(_Record):
    """The causal analysis: elements with their causality, bonds with their
    strokes, causal paths, causal and topological loops, conflicts, states,
    form and index, and the linearised model's eigenvalues."""
    model: str
    elements: tuple
    bonds: tuple
    causal_paths: tuple
    causal_loops: tuple
    topological_loops: tuple
    conflicts: tuple
    states: int
    dependent_stores: int
    index: Index
    eigenvalues: np.ndarray = field(repr=False)

    @property
    def form(self):
        return self.index.form

    def bond(self, number):
        """The bond the model numbers `number`."""
        for b in self.bonds:
            if b.number == number:
                return b
        raise KeyError(number)

    def element(self, name):
        for e in self.elements:
            if e.name == name:
                return e
        raise KeyError(name)

    def as_dict(self):
        d = super().as_dict()
        d["eigenvalues"] = [[float(z.real), float(z.imag)] for z in self.eigenvalues]
        d["form"] = self.form
        return d


class Simulation(Mapping):
    """A simulation's result: each output column by name as a NumPy array
    (sim["C1.e"]), the output times (sim.time, also sim["t"] as the CSV's first
    column), the solver that ran it and whether it stopped early (partial).
    A notebook shows it as the model's plot."""

    def __init__(self, time, columns, solver, partial, plot=None):
        self.time = time
        self.columns = columns  # name -> array, in the model's order
        self.solver = solver
        self.partial = partial
        self._plot = plot  # the model's plot of it as SVG text, on demand

    def _repr_mimebundle_(self, include=None, exclude=None):
        """In a notebook: the model's plot of the run (its plot statement, as
        --plot draws it), and a line of text."""
        bundle = {"text/plain": repr(self)}
        if self._plot is not None:
            bundle["image/svg+xml"] = self._plot()
        return bundle

    @property
    def names(self):
        return list(self.columns)

    def __getitem__(self, name):
        if name == "t" and "t" not in self.columns:
            return self.time
        return self.columns[name]

    def __iter__(self):
        return iter(self.columns)

    def __len__(self):
        return len(self.columns)

    def as_dict(self):
        """{"t": times, name: values, ...}: what pandas.DataFrame takes."""
        return {"t": self.time, **self.columns}

    def __repr__(self):
        return (f"<bgdraw.Simulation {len(self.time)} rows, columns {', '.join(self.columns)}; "
                f"{self.solver}{', partial' if self.partial else ''}>")


@dataclass(frozen=True)
class TransferFunction(_Record):
    """output/input = num(s) / den(s), coefficients highest power first, den
    monic; its poles, zeros and DC gain."""
    input: str
    output: str
    num: np.ndarray
    den: np.ndarray
    dc_gain: float
    poles: np.ndarray
    zeros: np.ndarray

    def __call__(self, s):
        """The value at the complex frequency s (an array too)."""
        return np.polyval(self.num, s) / np.polyval(self.den, s)

    def __str__(self):
        return f"{self.output}/{self.input} = ({_poly(self.num)}) / ({_poly(self.den)})"

    def _repr_latex_(self):
        return (f"$\\frac{{{_poly(self.num, latex=True)}}}{{{_poly(self.den, latex=True)}}}$")

    def as_dict(self):
        d = super().as_dict()
        for k in ("poles", "zeros"):
            d[k] = [[float(z.real), float(z.imag)] for z in getattr(self, k)]
        return d


def _poly(c, latex=False):
    """Coefficients, highest power first, as a polynomial in s."""
    terms = []
    n = len(c) - 1
    for i, a in enumerate(c):
        p = n - i
        if a == 0 and len(c) > 1:
            continue
        mag = abs(a)
        num = "" if (mag == 1 and p > 0) else f"{mag:.6g}"
        if latex and "e" in num:
            m, e = num.split("e")
            num = f"{m} \\cdot 10^{{{int(e)}}}"
        sv = "" if p == 0 else ("s" if p == 1 else (f"s^{{{p}}}" if latex else f"s^{p}"))
        mul = "" if not num or not sv else (" " if latex else "*")
        term = num + mul + sv
        sign = "-" if a < 0 else "+"
        terms.append((sign, term))
    if not terms:
        return "0"
    out = ("-" if terms[0][0] == "-" else "") + terms[0][1]
    for sign, term in terms[1:]:
        out += f" {sign} {term}"
    return out


class Linear:
    """The linear analysis at the model's operating point: the state space
    dx/dt = A x + B u, y = C x + D u as NumPy arrays (when reduced), the
    input and output names, the poles and every transfer function."""

    def __init__(self, A, B, C, D, inputs, outputs, poles, reduced, transfer_functions,
                 latex=None):
        self.A, self.B, self.C, self.D = A, B, C, D
        self.inputs, self.outputs = inputs, outputs
        self.poles = poles
        self.reduced = reduced
        self.transfer_functions = transfer_functions
        self._latex = latex  # the model's `--linear latex`, on demand

    def _repr_latex_(self):
        """In a notebook: A, B, C, D and the transfer functions as
        mathematics (numeric, then in the params when the model is linear),
        from bgdraw's LaTeX printer."""
        if self._latex is None:
            return None
        blocks = re.findall(r"\\begin\{align\*\}.*?\\end\{align\*\}", self._latex(), re.S)
        return "\n".join(f"$${b}$$" for b in blocks) or None

    def transfer_function(self, output=None, input=None):
        """output/input by name (or index); either may be left out when the
        model has one."""
        def pick(which, names):
            if which is None:
                if len(names) != 1:
                    raise ValueError(f"name one of {', '.join(names)}")
                return names[0]
            return names[which] if isinstance(which, int) else which
        out, inp = pick(output, self.outputs), pick(input, self.inputs)
        for t in self.transfer_functions:
            if t.output == out and t.input == inp:
                return t
        raise KeyError(f"{out}/{inp}")

    def to_control(self):
        """A python-control state-space system (control.ss) with the input and
        output names; ImportError when python-control is not installed."""
        try:
            import control
        except ImportError:
            raise ImportError("bgdraw: Linear.to_control() needs the python-control package "
                              "(import control)") from None
        if not self.reduced:
            raise ValueError("bgdraw: the linear analysis has poles but no state space "
                             "(not reduced to ODE form)")
        return control.ss(self.A, self.B, self.C, self.D, inputs=list(self.inputs),
                          outputs=list(self.outputs))

    def as_dict(self):
        return {"A": _plain(self.A), "B": _plain(self.B), "C": _plain(self.C), "D": _plain(self.D),
                "inputs": list(self.inputs), "outputs": list(self.outputs),
                "poles": [[float(z.real), float(z.imag)] for z in self.poles],
                "reduced": self.reduced,
                "transfer_functions": [t.as_dict() for t in self.transfer_functions]}

    def __repr__(self):
        return (f"<bgdraw.Linear {self.A.shape[0]} states, inputs {', '.join(self.inputs)}, "
                f"outputs {', '.join(self.outputs)}>")


class HTMLReport(str):
    """The HTML analysis report (a str: the whole self-contained page, as
    `bgdraw --report FILE.html` writes it). In a notebook it displays in an
    <iframe srcdoc>, so its style sheet and script stay inside it; save()
    writes it to a file."""

    def __new__(cls, text, name):
        s = super().__new__(cls, text)
        s.name = name
        return s

    def _repr_html_(self):
        import html
        return ('<iframe srcdoc="%s" title="bgdraw analysis report of %s" '
                'style="width: 100%%; height: 640px; border: 1px solid #ccc"></iframe>'
                % (html.escape(str(self), quote=True), html.escape(self.name)))

    def save(self, path):
        with open(path, "w", encoding="utf-8") as f:
            f.write(str(self))


class Equations(str):
    """The equations as a printer writes them (a str); in a notebook the
    LaTeX form displays as mathematics."""

    def __new__(cls, text, form):
        s = super().__new__(cls, text)
        s.form = form
        return s

    def _repr_latex_(self):
        if self.form != "latex":
            return None
        return "$$" + str(self).strip() + "$$"

    def _repr_html_(self):
        return str(self) if self.form == "mathml" else None
