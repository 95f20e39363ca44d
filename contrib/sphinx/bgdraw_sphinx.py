# SPDX-License-Identifier: BSD-3-Clause
"""Sphinx extension: bond graph diagrams drawn by bgdraw (docs/integrations.md).

    extensions = ["bgdraw_sphinx"]      # with contrib/sphinx on sys.path
    numfig = True                       # for :numref: to a diagram

    .. bgdraw:: models/rlc.bg
       :caption: The series RLC circuit
       :name: fig-rlc
       :show: paths
       :style: print

    .. bgdraw::
       :caption: A source and a load

       Se U = 1
       R R1 = 2
       bond U -> R1

Options as sphinx.ext.graphviz has them -- caption, name (a target for :ref:
and, with a caption, :numref:), align (left, center, right), class, alt --,
bgdraw's drawing options show, highlight, style, layout, causality, and
format: how an HTML page shows the diagram, "inline" (the SVG in the page:
its text searchable, its CSS classes styleable), "svg" (an <img> of an SVG
file) or "png"; conf.py's bgdraw_html_format sets the default ("inline").
LaTeX gets a PDF, text and man pages the alt text.

report: bgdraw's HTML analysis report of the model (--report FILE.html), written
into the output folder beside the images: "link" (the diagram, then a link to
the report), "embed" (the whole report in an <iframe>), "tables" (the report's
diagram with its layer toggles and its tables of causal paths, loops and
conflicts in the page: hovering or focusing a row lights its bonds, and a link
to PAGE.html#path-3 selects causal path 3; one such block a page), each with
the link. Other builders ignore it.

The model is drawn while the page is read: a model with errors is a warning
with bgdraw's diagnostics, which name the model file and line, or for a model
written in the page the page's own file and line (sphinx-build -W makes it
fail the build; the page is read again in every build until it draws). Every file bgdraw read -- the model, the files it `use`s,
table files, the style -- is a dependency of the page (bgdraw -M), so an edit
of any of them rebuilds the page. Image files go to the output folder (as
sphinx.ext.graphviz writes them), never into the source folder.

conf.py: bgdraw_command (default "bgdraw"), bgdraw_html_format.
"""
import hashlib
import os
import posixpath
import re
import subprocess
import tempfile

from docutils import nodes
from docutils.parsers.rst import directives
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

logger = logging.getLogger(__name__)

DRAW_OPTIONS = ("show", "highlight", "style", "layout", "causality")
REPORT_OPTIONS = ("style", "layout", "causality")  # what --report takes of them
HTML_FORMATS = ("inline", "svg", "png")
REPORT_MODES = ("link", "embed", "tables")


class BgdrawError(Exception):
    pass


class bgdraw(nodes.General, nodes.Inline, nodes.Element):
    """A diagram: the model (file or text), its options and its SVG."""


def shown_path(path):
    """A path as a compiler names it: relative to the working directory when
    inside it, else absolute."""
    rel = os.path.relpath(path)
    return path if rel.startswith(os.pardir) else rel


def run_bgdraw(command, model, options, args):
    """Runs bgdraw on the model (a file, or text on stdin with its name) with
    the drawing options and args; its standard output, or BgdrawError with
    its diagnostics."""
    cmd = [command, model["file"] or "-", "-q"]
    if not model["file"]:
        cmd += ["--stdin-name", model["name"]]
    for key in DRAW_OPTIONS:
        if options.get(key):
            cmd += ["--" + key, options[key]]
    try:
        done = subprocess.run(cmd + args, input=None if model["file"] else model["text"].encode(),
                              capture_output=True)
    except OSError as e:
        raise BgdrawError("cannot run %s: %s" % (command, e)) from e
    if done.returncode != 0:
        raise BgdrawError(done.stderr.decode(errors="replace").rstrip())
    return done.stdout


def make_prerequisites(depfile):
    """The prerequisites of the rule bgdraw -M writes (its first line), with
    make's escapes undone."""
    line = depfile.split("\n", 1)[0]
    rule = line.split(": ", 1)[1] if ": " in line else ""
    out, word, i = [], "", 0
    while i < len(rule):
        c = rule[i]
        if c == "\\" and i + 1 < len(rule):
            word += rule[i + 1]
            i += 2
            continue
        if c == "$" and rule[i + 1:i + 2] == "$":
            word += "$"
            i += 2
            continue
        if c == " ":
            if word:
                out.append(word)
            word = ""
        else:
            word += c
        i += 1
    if word:
        out.append(word)
    return out


def draw_svg(command, model, options):
    """The SVG and the files bgdraw read to draw it."""
    with tempfile.TemporaryDirectory(prefix="bgdraw-sphinx-") as tmp:
        svg_path, dep_path = os.path.join(tmp, "d.svg"), os.path.join(tmp, "d.d")
        run_bgdraw(command, model, options, ["-o", svg_path, "-M", dep_path])
        with open(svg_path, encoding="utf-8") as f:
            svg = f.read()
        with open(dep_path, encoding="utf-8") as f:
            deps = make_prerequisites(f.read())
    return svg, [os.path.abspath(p) for p in deps]


def align_spec(argument):
    return directives.choice(argument, ("left", "center", "right"))


def format_spec(argument):
    return directives.choice(argument, HTML_FORMATS)


def report_spec(argument):
    return directives.choice(argument, REPORT_MODES)


def report_parts(page):
    """The report's diagram (with its layer toggles) and its tables of paths,
    loops and conflicts, with the style and the script that make the rows
    light the diagram: the page's own headings left out."""
    part = lambda ident: re.search(r'<section id="%s".*?</section>' % ident, page, re.S).group(0)
    body = part("diagram") + part("paths-loops-conflicts")
    body = re.sub(r'<h2 id="[^"]*">.*?</h2>\n', "", body)
    body = re.sub(r' aria-labelledby="[^"]*"', "", body)
    style = re.search(r'<style id="bgdraw-parts">.*?</style>', page, re.S).group(0)
    script = page[page.rindex("<script>"):page.rindex("</script>") + len("</script>")]
    return '<div class="bgdraw-report">%s%s%s</div>\n' % (style, body, script)


class BgdrawDirective(SphinxDirective):
    has_content = True
    optional_arguments = 1
    final_argument_whitespace = True
    option_spec = {key: directives.unchanged for key in DRAW_OPTIONS}
    option_spec.update({
        "caption": directives.unchanged,
        "name": directives.unchanged,
        "align": align_spec,
        "class": directives.class_option,
        "alt": directives.unchanged,
        "format": format_spec,
        "report": report_spec,
    })

    def inline_model(self):
        """The model written in the page, as bgdraw should read it: at the
        page's own line numbers and columns (the lines before it blank), so
        its diagnostics point into the page. Its name is the page's."""
        source, first = self.content.items[0]
        lines = list(self.content)
        try:
            with open(source, encoding="utf-8") as f:
                raw = f.read().split("\n")[first:first + len(lines)]
            if [r.strip() for r in raw] == [l.strip() for l in lines]:
                lines = raw  # as indented in the page: the columns are the page's
        except OSError:
            pass
        text = "\n" * first + "\n".join(lines) + "\n"
        return {"file": None, "text": text, "name": shown_path(os.path.abspath(source))}

    def model(self):
        if self.arguments and self.content:
            raise self.error("bgdraw: give a model file or write the model in the block, not both")
        if self.arguments:
            rel, path = self.env.relfn2path(self.arguments[0])
            self.env.note_dependency(rel)
            if not os.path.isfile(path):
                raise self.error("bgdraw: model file '%s' not found (%s)" % (self.arguments[0], path))
            return {"file": shown_path(path), "text": None, "name": None}
        if not "".join(self.content).strip():
            raise self.error("bgdraw: the block has no model: give a model file or write the "
                             "model in the block")
        return self.inline_model()

    def run(self):
        model = self.model()
        options = {k: self.options[k] for k in DRAW_OPTIONS if k in self.options}
        try:
            svg, deps = draw_svg(self.config.bgdraw_command, model, options)
        except BgdrawError as e:
            logger.warning("bgdraw could not draw the model:\n%s", e,
                           location=(self.env.docname, self.lineno))
            failed_docs(self.env).add(self.env.docname)  # read again in the next build
            return []
        for dep in deps:
            self.env.note_dependency(dep)
        node = bgdraw()
        node["model"] = model
        node["options"] = options
        node["svg"] = svg[svg.index("<svg"):]  # no XML declaration inside HTML
        node["format"] = self.options.get("format")
        node["report"] = self.options.get("report")
        title = re.search(r"<title>(.*?)</title>", svg, re.S)
        node["alt"] = (self.options.get("alt") or self.options.get("caption")
                       or (title.group(1) if title else "bond graph"))
        node["classes"] += self.options.get("class", [])
        if "align" in self.options:
            node["align"] = self.options["align"]
        self.set_source_info(node)
        if "caption" not in self.options:
            self.add_name(node)
            return [node]
        figure = nodes.figure("", node)
        if "align" in node:
            figure["align"] = node.attributes.pop("align")
        inodes, messages = self.state.inline_text(self.options["caption"], self.lineno)
        caption = nodes.caption(self.options["caption"], "", *inodes)
        caption.extend(messages)
        self.set_source_info(caption)
        figure += caption
        self.add_name(figure)
        return [figure]


def image_file(translator, node, fmt):
    """Writes the diagram as an image file in the output folder (once: the
    name is a hash of the SVG, which reflects every file read, and of the
    options); its URI from the page, or None after a warning."""
    key = hashlib.sha1((node["svg"] + repr(sorted(node["options"].items())) + fmt).encode())
    name = "bgdraw-%s.%s" % (key.hexdigest()[:20], fmt)
    builder = translator.builder
    out = os.path.join(builder.outdir, builder.imagedir, name)
    if not os.path.isfile(out):
        os.makedirs(os.path.dirname(out), exist_ok=True)
        if fmt == "svg":
            data = ('<?xml version="1.0" encoding="UTF-8"?>\n' + node["svg"]).encode()
        else:
            try:
                data = run_bgdraw(builder.config.bgdraw_command, node["model"], node["options"],
                                  ["-T", fmt])
            except BgdrawError as e:
                logger.warning("bgdraw could not draw the model:\n%s", e, location=node)
                return None
        with open(out, "wb") as f:
            f.write(data)
    return posixpath.join(builder.imgpath, name)


def report_file(translator, node):
    """Writes the model's HTML report into the output folder (once: named by
    a hash, like the images); its URI and text, or (None, None) after a warning."""
    options = {k: v for k, v in node["options"].items() if k in REPORT_OPTIONS}
    key = hashlib.sha1((node["svg"] + repr(sorted(options.items())) + "report").encode())
    name = "bgdraw-%s.html" % key.hexdigest()[:20]
    builder = translator.builder
    out = os.path.join(builder.outdir, builder.imagedir, name)
    if not os.path.isfile(out):
        os.makedirs(os.path.dirname(out), exist_ok=True)
        try:
            run_bgdraw(builder.config.bgdraw_command, node["model"], options, ["--report", out])
        except BgdrawError as e:
            logger.warning("bgdraw could not write the report:\n%s", e, location=node)
            return None, None
    with open(out, encoding="utf-8") as f:
        return posixpath.join(builder.imgpath, name), f.read()


def html_visit(self, node):
    fmt = node.get("format") or self.builder.config.bgdraw_html_format
    if fmt not in HTML_FORMATS:
        logger.warning("bgdraw_html_format is one of %s, not %r", ", ".join(HTML_FORMATS), fmt,
                       location=node)
        fmt = "inline"
    classes = " ".join(["bgdraw"] + node["classes"])
    if "align" in node:
        self.body.append('<div class="align-%s">' % node["align"])
    report = node.get("report")
    report_uri, page = report_file(self, node) if report else (None, None)
    if report == "embed" and report_uri:
        self.body.append('<iframe class="%s" src="%s" title="%s" loading="lazy" '
                         'style="width: 100%%; height: 40em; border: 1px solid #ccc"></iframe>\n'
                         % (classes, self.attval(report_uri), self.attval(node["alt"])))
    elif report == "tables" and report_uri:
        self.body.append('<div class="%s">%s</div>\n' % (classes, report_parts(page)))
    elif fmt == "inline":
        self.body.append('<div class="%s" role="img" aria-label="%s">%s</div>\n'
                         % (classes, self.attval(node["alt"]), node["svg"]))
    else:
        uri = image_file(self, node, fmt)
        if uri:
            self.body.append('<div class="%s"><img src="%s" alt="%s"/></div>\n'
                             % (classes, self.attval(uri), self.attval(node["alt"])))
    if report_uri:
        self.body.append('<p class="bgdraw-report-link"><a href="%s">The analysis report</a></p>\n'
                         % self.attval(report_uri))
    if "align" in node:
        self.body.append("</div>\n")
    raise nodes.SkipNode


def latex_visit(self, node):
    uri = image_file(self, node, "pdf")
    if uri:
        pre, post = {"left": ("{", r"\hspace*{\fill}}"), "right": (r"{\hspace*{\fill}", "}"),
                     "center": (r"{\hfill", r"\hspace*{\fill}}")}.get(node.get("align"), ("", ""))
        self.body.append("\n%s\\sphinxincludegraphics[]{%s}%s\n" % (pre, uri, post))
    raise nodes.SkipNode


def text_visit(self, node):
    self.add_text("[bond graph: %s]" % node["alt"])
    raise nodes.SkipNode


def man_visit(self, node):
    self.body.append("[bond graph: %s]" % node["alt"])
    raise nodes.SkipNode


def failed_docs(env):
    """The pages with a model bgdraw could not draw: without bgdraw -M's
    list of the files it read, they are read again in every build until
    their models draw."""
    if not hasattr(env, "bgdraw_failed"):
        env.bgdraw_failed = set()
    return env.bgdraw_failed


def outdated(app, env, added, changed, removed):
    return sorted(failed_docs(env) - set(removed))


def purge(app, env, docname):
    failed_docs(env).discard(docname)


def merge(app, env, docnames, other):
    failed_docs(env).update(failed_docs(other) & set(docnames))


def setup(app):
    app.add_config_value("bgdraw_command", "bgdraw", "env")
    app.add_config_value("bgdraw_html_format", "inline", "html")
    app.add_node(bgdraw, html=(html_visit, None), latex=(latex_visit, None),
                 text=(text_visit, None), man=(man_visit, None), texinfo=(man_visit, None))
    app.add_directive("bgdraw", BgdrawDirective)
    app.connect("env-get-outdated", outdated)
    app.connect("env-purge-doc", purge)
    app.connect("env-merge-info", merge)
    return {"version": "2", "parallel_read_safe": True, "parallel_write_safe": True}
