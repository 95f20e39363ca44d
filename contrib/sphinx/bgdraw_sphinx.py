# SPDX-License-Identifier: BSD-3-Clause
"""Sphinx extension: bond graph diagrams drawn by bgdraw.

    extensions = ["bgdraw_sphinx"]      # with contrib/sphinx on sys.path

    .. bgdraw:: models/rlc.bg
       :show: paths
       :highlight: path:1
       :style: print

    .. bgdraw::
       :layout: dot

       Se U = 1
       1 j
       R R1 = 2
       bond U -> j
       bond j -> R1

The diagram is bgdraw's web SVG, put inline in HTML pages (so its text is
searchable and its CSS classes -- bond b3, path p2, loop l1, conflict -- can be
styled by the page) and written as a PDF image for the other builders. A model
file is a dependency of the page; a model with errors is a Sphinx warning with
bgdraw's diagnostics. Options: show, highlight, style, layout, causality, alt.
The bgdraw program is `bgdraw_command` in conf.py (default "bgdraw").
"""
import hashlib
import os
import subprocess

from docutils import nodes
from docutils.parsers.rst import Directive, directives

OPTIONS = ("show", "highlight", "style", "layout", "causality")


class BgdrawError(Exception):
    pass


def run_bgdraw(command, source, fmt, options, cwd):
    args = [command, "-", "-T", fmt, "-q"]
    for key in OPTIONS:
        if options.get(key):
            args += ["--" + key, options[key]]
    try:
        done = subprocess.run(args, input=source.encode(), capture_output=True, cwd=cwd)
    except OSError as e:
        raise BgdrawError("cannot run %s: %s" % (command, e))
    if done.returncode != 0:
        raise BgdrawError(done.stderr.decode(errors="replace").strip())
    return done.stdout


class BgdrawDirective(Directive):
    has_content = True
    optional_arguments = 1
    final_argument_whitespace = True
    option_spec = {key: directives.unchanged for key in OPTIONS}
    option_spec["alt"] = directives.unchanged

    def model(self, env):
        if self.arguments:
            rel, path = env.relfn2path(self.arguments[0])
            env.note_dependency(rel)
            with open(path, encoding="utf-8") as f:
                return f.read(), os.path.dirname(path), rel
        return "\n".join(self.content) + "\n", os.path.dirname(env.doc2path(env.docname)), None

    def run(self):
        env = self.state.document.settings.env
        command = env.config.bgdraw_command
        source, cwd, rel = self.model(env)
        where = rel or "inline model in %s" % env.docname
        try:
            if env.app.builder.format == "html":
                svg = run_bgdraw(command, source, "svg", self.options, cwd).decode()
                svg = svg[svg.index("<svg"):]  # no XML declaration inside HTML
                return [nodes.raw("", '<div class="bgdraw">%s</div>' % svg, format="html")]
            pdf = run_bgdraw(command, source, "pdf", self.options, cwd)
        except BgdrawError as e:
            return [self.state.document.reporter.warning(
                "bgdraw: %s:\n%s" % (where, e), line=self.lineno)]
        key = hashlib.sha1(source.encode() + repr(sorted(self.options.items())).encode())
        outdir = os.path.join(env.app.srcdir, "_bgdraw")
        os.makedirs(outdir, exist_ok=True)
        name = "bgdraw-%s.pdf" % key.hexdigest()[:16]
        with open(os.path.join(outdir, name), "wb") as f:
            f.write(pdf)
        return [nodes.image(uri="/_bgdraw/" + name, alt=self.options.get("alt", where))]


def setup(app):
    app.add_config_value("bgdraw_command", "bgdraw", "env")
    app.add_directive("bgdraw", BgdrawDirective)
    return {"version": "1", "parallel_read_safe": True}
