# SPDX-License-Identifier: BSD-3-Clause
"""MkDocs hook: ```bgdraw fenced blocks become numbered bond graph figures
(docs/integrations.md).

    # mkdocs.yml
    hooks:
      - path/to/bgdraw/contrib/mkdocs/bgdraw_mkdocs.py

    ```{.bgdraw #fig-rlc caption="The series RLC circuit" show=paths}
    Se U = 1
    ...
    ```

    ```{.bgdraw file=models/rlc.bg caption="The same from a file"}
    ```

    As [](#fig-rlc) shows, ...          (an empty link: "Figure 1")

The block's attributes are those of the pandoc filter (contrib/pandoc), so
one Markdown source serves both: `bgdraw` or `.bgdraw` first, then `#NAME`
or name=NAME (the figure's id), caption, file (a model file, relative to the
page, or to the docs folder when it begins with '/'), alt, align (left,
center, right), class, format (inline: the SVG in the page, the default;
svg: an <img> of an SVG file; png) and bgdraw's show, highlight, style,
layout, causality, and report: bgdraw's HTML analysis report of the model
(--report FILE.html) written into the site folder, "link" (the diagram, then
a link to it), "embed" (the whole report in an <iframe>) or "tables" (the
report's diagram with its layer toggles and its tables of causal paths, loops
and conflicts in the page, whose rows light their bonds on hover and focus,
and PAGE/#path-3 selects causal path 3; one such block a page), each with the
link. A figure with a caption is numbered in its page
("Figure 1: ..."); an empty link to its id, from any page, reads "Figure N".

A model with errors stops the build with bgdraw's diagnostics, which name
the page (or the model file) and the line and column there. Image files go
to the site folder (_bgdraw/), never into the docs folder. `mkdocs build`
draws every figure again, so an edit of a file the model `use`s is in the
next build; `mkdocs serve` watches the docs folder (add folders outside it
to mkdocs.yml's `watch:`). BGDRAW in the environment names the program.
"""
import hashlib
import html
import os
import posixpath
import re
import shlex
import subprocess
import tempfile

from mkdocs.exceptions import PluginError
from mkdocs.utils import get_relative_url

DRAW_OPTIONS = ("show", "highlight", "style", "layout", "causality")
KNOWN = DRAW_OPTIONS + ("caption", "name", "file", "alt", "align", "class", "format", "report")
FORMATS = ("inline", "svg", "png")
REPORT_OPTIONS = ("style", "layout", "causality")  # what --report takes of them
REPORT_MODES = ("link", "embed", "tables")
FENCE = re.compile(r"^(?P<indent> {0,3})(?P<fence>`{3,}|~{3,})\s*(?P<info>.*)$")

# (page url, figure id) -> figure number, filled while pages are converted
# and read when their HTML is written (after every page is converted).
figures = {}


def on_pre_build(config):
    figures.clear()


def parse_info(info, where):
    """The attributes of a fence's info string ({.bgdraw #id key=value} or
    bgdraw key=value), or None when the block is not a bgdraw block."""
    info = info.strip()
    if info.startswith("{") and info.endswith("}"):
        info = info[1:-1]
    try:
        words = shlex.split(info)
    except ValueError as e:
        raise PluginError("%s: bgdraw block: %s" % (where, e)) from e
    if not words or words[0] not in ("bgdraw", ".bgdraw"):
        return None
    attrs = {}
    for w in words[1:]:
        if w.startswith("#"):
            attrs["name"] = w[1:]
        elif w.startswith("."):
            attrs["class"] = (attrs.get("class", "") + " " + w[1:]).strip()
        elif "=" in w:
            key, value = w.split("=", 1)
            if key not in KNOWN:
                raise PluginError("%s: bgdraw block: unknown attribute '%s' (known: %s)"
                                  % (where, key, ", ".join(KNOWN)))
            attrs[key] = value
        else:
            raise PluginError("%s: bgdraw block: '%s' is not key=value" % (where, w))
    if attrs.get("format", "inline") not in FORMATS:
        raise PluginError("%s: bgdraw block: format is one of %s" % (where, ", ".join(FORMATS)))
    if attrs.get("report", "link") not in REPORT_MODES:
        raise PluginError("%s: bgdraw block: report is one of %s" % (where, ", ".join(REPORT_MODES)))
    return attrs


def blocks(lines):
    """The fenced blocks of a page: (first line, line after the closing
    fence, info string); fences inside other fences are text."""
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m or (m.group("fence")[0] == "`" and "`" in m.group("info")):
            i += 1
            continue
        fence, end = m.group("fence"), i + 1
        while end < len(lines):
            c = FENCE.match(lines[end])
            if c and c.group("fence")[0] == fence[0] and len(c.group("fence")) >= len(fence) \
                    and not c.group("info").strip():
                break
            end += 1
        yield i, min(end + 1, len(lines)), m.group("info")
        i = end + 1


def run_bgdraw(cmd, text=None):
    try:
        done = subprocess.run(cmd, input=text.encode() if text is not None else None,
                              capture_output=True)
    except OSError as e:
        raise PluginError("cannot run %s: %s" % (cmd[0], e)) from e
    if done.returncode != 0:
        raise PluginError("bgdraw could not draw a figure:\n"
                          + done.stderr.decode(errors="replace").rstrip())
    return done.stdout


def shown_path(path):
    rel = os.path.relpath(path)
    return path if rel.startswith(os.pardir) else rel


def report_parts(page):
    """The report's diagram (with its layer toggles) and its tables of paths,
    loops and conflicts, with the style and the script that make the rows
    light the diagram: the report's own headings left out."""
    part = lambda ident: re.search(r'<section id="%s".*?</section>' % ident, page, re.S).group(0)
    body = part("diagram") + part("paths-loops-conflicts")
    body = re.sub(r'<h2 id="[^"]*">.*?</h2>\n', "", body)
    body = re.sub(r' aria-labelledby="[^"]*"', "", body)
    style = re.search(r'<style id="bgdraw-parts">.*?</style>', page, re.S).group(0)
    script = page[page.rindex("<script>"):page.rindex("</script>") + len("</script>")]
    return '<div class="bgdraw-report">%s%s%s</div>' % (style, body, script)


class Page:
    """One page's figures: drawn while its Markdown is read, put into its
    HTML once converted."""

    def __init__(self, page, config):
        self.page, self.config = page, config
        self.src = page.file.abs_src_path
        self.figures = []  # (attrs, html body)

    def draw(self, attrs, lines, first, where, fmt):
        """bgdraw's output for a block whose model text is lines (at its
        line numbers in the page) or attrs["file"]: the diagram in format
        fmt, or for fmt "report" the HTML report."""
        if fmt == "report":
            with tempfile.TemporaryDirectory(prefix="bgdraw-mkdocs-") as tmp:
                out = os.path.join(tmp, "report.html")
                self.run(attrs, lines, first, where, ["--report", out], REPORT_OPTIONS)
                with open(out, "rb") as f:
                    return f.read()
        return self.run(attrs, lines, first, where, ["-T", fmt], DRAW_OPTIONS)

    def run(self, attrs, lines, first, where, args, keys):
        cmd = [os.environ.get("BGDRAW", "bgdraw"), "-q"] + args
        for key in keys:
            if key in attrs:
                cmd += ["--" + key, attrs[key]]
        if "file" in attrs:
            if "".join(lines).strip():
                raise PluginError("%s: bgdraw block: give file= or write the model in the block, "
                                  "not both" % where)
            f = attrs["file"]
            base = self.config["docs_dir"] if f.startswith("/") else os.path.dirname(self.src)
            path = os.path.normpath(os.path.join(base, f.lstrip("/")))
            if not os.path.isfile(path):
                raise PluginError("%s: bgdraw block: model file '%s' not found (%s)" % (where, f, path))
            return run_bgdraw(cmd + [shown_path(path)])
        if not "".join(lines).strip():
            raise PluginError("%s: bgdraw block: the block has no model (write it in the block, "
                              "or give file=)" % where)
        text = "\n" * first + "\n".join(lines) + "\n"
        return run_bgdraw(cmd + ["-", "--stdin-name", shown_path(self.src)], text)

    def image(self, data, fmt):
        """Writes an image into the site folder; its URL from the page."""
        name = "_bgdraw/bgdraw-%s.%s" % (hashlib.sha1(data).hexdigest()[:20], fmt)
        out = os.path.join(self.config["site_dir"], name)
        os.makedirs(os.path.dirname(out), exist_ok=True)
        with open(out, "wb") as f:
            f.write(data)
        return get_relative_url(name, self.page.url)

    def figure(self, attrs, lines, first, where):
        fmt = attrs.get("format", "inline")
        data = self.draw(attrs, lines, first, where, "png" if fmt == "png" else "svg")
        alt = attrs.get("alt") or attrs.get("caption") or "bond graph"
        classes = " ".join(["bgdraw"] + attrs.get("class", "").split())
        report, link = attrs.get("report"), ""
        if report:
            page = self.draw(attrs, lines, first, where, "report")
            url = self.image(page, "html")
            link = '<p class="bgdraw-report-link"><a href="%s">The analysis report</a></p>' % html.escape(url)
        if report == "embed":
            body = ('<iframe class="%s" src="%s" title="%s" loading="lazy" style="width: 100%%; '
                    'height: 40em; border: 1px solid #ccc"></iframe>'
                    % (classes, html.escape(url), html.escape(alt)))
        elif report == "tables":
            body = '<div class="%s">%s</div>' % (classes, report_parts(page.decode()))
        elif fmt == "inline":
            svg = data.decode()
            body = '<div class="%s" role="img" aria-label="%s">%s</div>' % (
                classes, html.escape(alt), svg[svg.index("<svg"):].strip())
        else:
            body = '<div class="%s"><img src="%s" alt="%s"/></div>' % (
                classes, html.escape(self.image(data, fmt)), html.escape(alt))
        return body + link

    def markdown(self, markdown):
        """Replaces each bgdraw block by a placeholder (the figure goes into
        the HTML after conversion, untouched by Markdown)."""
        with open(self.src, encoding="utf-8-sig") as f:
            whole = f.read().replace("\r\n", "\n")
        offset = whole[:len(whole) - len(markdown)].count("\n") if whole.endswith(markdown) else 0
        lines = markdown.split("\n")
        out, last, number = [], 0, 0
        for start, end, info in blocks(lines):
            where = "%s:%d" % (shown_path(self.src), offset + start + 1)
            attrs = parse_info(info, where)
            if attrs is None:
                continue
            body = self.figure(attrs, lines[start + 1:end - 1], offset + start + 1, where)
            if "caption" in attrs:
                number += 1
                if "name" in attrs:
                    figures[(self.page.url, attrs["name"])] = number
            self.figures.append((attrs, body, number))
            out += lines[last:start]
            indent = FENCE.match(lines[start]).group("indent")
            out += ["", indent + '<div class="bgdraw-figure-%d"></div>' % (len(self.figures) - 1), ""]
            last = end
        return "\n".join(out + lines[last:])

    def content(self, content):
        import markdown as md  # what MkDocs converts pages with
        for k, (attrs, body, number) in enumerate(self.figures):
            ident = ' id="%s"' % html.escape(attrs["name"]) if "name" in attrs else ""
            align = ' class="align-%s"' % attrs["align"] if "align" in attrs else ""
            caption = ""
            if "caption" in attrs:
                text = md.markdown(attrs["caption"])
                text = re.sub(r"^<p>(.*)</p>$", r"\1", text, flags=re.S)
                caption = ('<figcaption><span class="caption-number">Figure %d:</span> %s'
                           '</figcaption>' % (number, text))
            fig = "<figure%s%s>%s%s</figure>" % (ident, align, body, caption)
            content = content.replace('<div class="bgdraw-figure-%d"></div>' % k, fig, 1)
        return content


def on_page_markdown(markdown, page, config, files):
    p = Page(page, config)
    page.bgdraw = p
    return p.markdown(markdown)


def on_page_content(content, page, config, files):
    p = getattr(page, "bgdraw", None)
    return p.content(content) if p else content


EMPTY_LINK = re.compile(r'<a href="(?P<url>[^"#]*)#(?P<id>[^"]+)"></a>')


def on_post_page(output, page, config):
    """An empty link to a figure reads "Figure N" (every page's figures are
    known by now: MkDocs converts them all before it writes any)."""
    def norm(url):
        return posixpath.normpath("/" + url.lstrip("/")).rstrip("/")
    here = page.url
    base = "/" + here if here == "" or here.endswith("/") else posixpath.dirname("/" + here)

    def fill(m):
        url = m.group("url")
        target = norm(posixpath.join(base, url)) if url else norm(here)
        number = next((n for (u, i), n in figures.items()
                       if i == m.group("id") and norm(u) == target), None)
        if number is None:
            return m.group(0)
        return '<a href="%s#%s">Figure %d</a>' % (url, m.group("id"), number)
    return EMPTY_LINK.sub(fill, output)
