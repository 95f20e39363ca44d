# SPDX-License-Identifier: BSD-3-Clause
"""The %%bgdraw cell magic: the cell is a model, the magic line the command
line's options (`%load_ext bgdraw` first).

    %%bgdraw --show paths --style print
    Se U = 1
    ...

shows the diagram; --check, --equations FORM, --linear FORM and --simulate
show those instead (LaTeX as mathematics, the simulation as its plot);
-o FILE, --report FILE and --plot FILE write files as bgdraw does; --as NAME
keeps the Model in the notebook's variable NAME. A model with errors fails
the cell with bgdraw's diagnostics."""
import argparse
import shlex

from .errors import UsageError
from .model import Model


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error, not SystemExit
        raise UsageError(f"%%bgdraw: error: {message}\n{self.format_usage()}")


def parser():
    p = _Parser(prog="%%bgdraw", add_help=False,
                description="the cell is a bond graph model; options as bgdraw's")
    p.add_argument("--causality")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    p.add_argument("--show")
    p.add_argument("--style")
    p.add_argument("--highlight")
    p.add_argument("--layout")
    p.add_argument("--check", action="store_true")
    p.add_argument("--equations", metavar="FORM")
    p.add_argument("--linear", metavar="FORM")
    p.add_argument("--simulate", action="store_true")
    p.add_argument("--verify", action="store_true")
    p.add_argument("-T", "--format", choices=("svg", "png"))
    p.add_argument("-o", "--output", action="append", default=[], metavar="FILE")
    p.add_argument("--report", metavar="FILE")
    p.add_argument("--plot", metavar="FILE")
    for kind in ("bode", "nyquist", "step"):
        p.add_argument(f"--{kind}", metavar="FILE")
    p.add_argument("--prefix")
    p.add_argument("-W", dest="warnings", action="append", default=[], metavar="WARNING")
    p.add_argument("--max-list", type=int)
    p.add_argument("--max-errors", type=int)
    p.add_argument("--name", default="cell.bg", help="the name diagnostics give the cell")
    p.add_argument("--as", dest="var", metavar="NAME")
    return p


def _params(pairs):
    out = {}
    for pair in pairs:
        name, eq, value = pair.partition("=")
        try:
            out[name.strip()] = float(value)
        except ValueError:
            raise UsageError(f"%%bgdraw: error: --set wants NAME=VALUE with a number, not '{pair}'")
        if not eq:
            raise UsageError(f"%%bgdraw: error: --set wants NAME=VALUE, not '{pair}'")
    return out


def run_cell(line, cell, namespace=None, display=None):
    """What the magic does, without IPython: returns (model, [displayed
    objects]) with display None, else shows them with display()."""
    a = parser().parse_args(shlex.split(line))
    m = Model.from_string(cell, name=a.name, causality=a.causality, params=_params(a.set),
                          show=a.show, style=a.style, highlight=a.highlight, layout=a.layout,
                          verify=a.verify, max_list=a.max_list, max_errors=a.max_errors,
                          prefix=a.prefix, warnings=",".join(a.warnings) or None)
    for path in a.output:
        m.save(path)
    if a.report:
        m.report(a.report)
    if a.plot:
        m.plot(a.plot)
    for kind in ("bode", "nyquist", "step"):
        path = getattr(a, kind)
        if path:  # the format from the file's extension, as bgdraw takes it
            m.write(path, kind, path.rsplit(".", 1)[-1].lower() if "." in path else None)
    shown = []
    if a.check:
        shown.append(_Text(m.check()))
    if a.equations:
        shown.append(m.equations(a.equations))
    if a.linear:
        shown.append(_Text(m.output("linear", a.linear).decode("utf-8", "replace")))
    if a.simulate:
        shown.append(_Figure(m.plot(format="svg"), "image/svg+xml"))
    if a.format == "png":
        shown.append(_Figure(m.png(), "image/png"))
    elif a.format == "svg" or not shown:
        shown.append(m)
    if namespace is not None and a.var:
        namespace[a.var] = m
    if display is not None:
        for item in shown:
            display(item)
    return m, shown


class _Text(str):
    """Text shown as it is (not as a quoted string)."""

    def __repr__(self):
        return str(self)


class _Figure:
    def __init__(self, data, mime):
        self.data, self.mime = data, mime

    def _repr_mimebundle_(self, include=None, exclude=None):
        return {self.mime: self.data}


def load_ipython_extension(ip):
    from IPython.core.magic import register_cell_magic
    from IPython.display import display

    @register_cell_magic("bgdraw")
    def bgdraw_magic(line, cell):
        run_cell(line, cell, ip.user_ns, display)
