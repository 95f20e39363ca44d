#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The documentation-build integrations (contrib/, docs/integrations.md), run
# with their real tools: every file and command of docs/integrations.md is
# taken from the page (tests/doc_snippets.py) and run, then checked: Sphinx
# HTML and LaTeX, mkdocs build, pandoc to HTML, LaTeX and docx, make. For each:
# the figure is there with its caption and number, a cross-reference resolves
# to it, editing a file the model uses rebuilds it, a bad model fails the
# build naming the real file and line, nothing is written into the sources.
# Usage: bash tests/contrib.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
for tool in sphinx-build mkdocs pandoc make; do
  command -v $tool >/dev/null || { echo "FAIL $tool is not installed (bash tools/deps.sh --tests)"; exit 1; }
done
mkdir -p "$tmp/bin" && ln -s "$BGDRAW" "$tmp/bin/bgdraw"
export PATH="$tmp/bin:$PATH" # the page's commands say bgdraw
unset BGDRAW_PATH
p=$tmp/p
python3 tests/doc_snippets.py docs/integrations.md "$p" /usr/local/share/bgdraw/contrib "$root/contrib"
check "docs/integrations.md: every code block is a file, a command or an output this test uses" $?
for d in sphinx/docs mkdocs/docs pandoc shell make sphinx-report/docs mkdocs-report/docs; do
  mkdir -p "$p/$d/models" && cp examples/rlc.bg "$p/$d/models/rlc.bg"
done
bgdraw examples/rlc.bg -q --show paths --style print -T svg >"$tmp/rlc.svg"
bgdraw examples/rlc.bg -q --show paths --style print -T pdf >"$tmp/rlc.pdf"
snap() { (cd "$1" && find . -type f | sort | xargs md5sum); } # a folder's files and contents
lineof() { grep -n -- "$2" "$1" | head -1 | cut -d: -f1; }   # the line of the first match

# ---------------------------------------------------------------- Sphinx
snap "$p/sphinx/docs" >"$tmp/src.before"
bash "$p/run-sphinx.sh" >"$tmp/out" 2>"$tmp/err"; st=$?
check "sphinx: the page's commands build HTML and LaTeX (got $st: $(head -3 "$tmp/err"))" $st
[ ! -s "$tmp/err" ]; check "sphinx: no warnings" $?
python3 - "$p/sphinx/build/html/index.html" "$tmp/rlc.svg" <<'PY'; check "sphinx html: both figures with caption and number, inline SVG as bgdraw draws it, numref links" $?
import re, sys
html, svg = open(sys.argv[1]).read(), open(sys.argv[2]).read()
fig = re.search(r'<figure class="align-center" id="fig-rlc">(.*?)</figure>', html, re.S).group(1)
assert svg[svg.index("<svg"):].strip() in fig, "the file model's inline SVG"
assert '<span class="caption-number">Fig. 1 </span><span class="caption-text">The series RLC circuit and its causal paths</span>' in fig
load = re.search(r'<figure class="align-default" id="fig-load">(.*?)</figure>', html, re.S).group(1)
assert '<div class="bgdraw wide" role="img" aria-label="A source and its load"><svg' in load
assert '>R : Rl<' in load and 'class="bond b' in load, "the used part drawn"
assert '<span class="caption-number">Fig. 2 </span><span class="caption-text">A source and its load</span>' in load
assert '<a class="reference internal" href="#fig-rlc"><span class="std std-numref">Fig. 1</span></a>' in html
assert '<a class="reference internal" href="#fig-load"><span class="std std-numref">Fig. 2</span></a>' in html
PY
tex=$(ls "$p"/sphinx/build/latex/*.tex | head -1)
python3 - "$tex" <<'PY'; check "sphinx latex: figures with \\caption and \\label, \\ref to them" $?
import re, sys
tex = open(sys.argv[1]).read()
for name, cap in (("fig-rlc", "The series RLC circuit and its causal paths"), ("fig-load", "A source and its load")):
    fig = re.search(r"\\begin\{figure\}(?:(?!\\end\{figure\}).)*?\\sphinxincludegraphics\[\]\{(bgdraw-[0-9a-f]+\.pdf)\}"
                    r"(?:(?!\\end\{figure\}).)*?\\caption\{%s\}\\label\{\\detokenize\{index:%s\}\}" % (cap, name), tex, re.S)
    assert fig, name
    assert r"\ref{\detokenize{index:%s}}" % name in tex
PY
rlcpdf=$(grep -o 'bgdraw-[0-9a-f]*\.pdf' "$tex" | head -1)
cmp -s "$p/sphinx/build/latex/$rlcpdf" "$tmp/rlc.pdf"; check "sphinx latex: the PDF in the output folder is bgdraw's ($rlcpdf)" $?
snap "$p/sphinx/docs" | cmp -s - "$tmp/src.before"; check "sphinx: nothing written into the source folder" $?

cd "$p/sphinx" || exit 1
sphinx-build -b html docs build/html >"$tmp/out" 2>&1
grep -q "0 added, 0 changed, 0 removed" "$tmp/out"; check "sphinx: nothing changed, nothing read again" $?
sleep 1; sed -i 's/Rl/Rload/g' docs/models/load.bg
sphinx-build -b html docs build/html >"$tmp/out" 2>&1
grep -q "0 added, 1 changed, 0 removed" "$tmp/out" && grep -q '>R : Rload<' build/html/index.html
check "sphinx: editing the used file rebuilds the page and its figure" $?
cp docs/index.rst "$tmp/index.rst"
sed -i 's/bond U -> L.p/bond Ux -> L.p/' docs/index.rst
sphinx-build -W -b html docs build/html >"$tmp/out" 2>"$tmp/err"; st=$?
line=$(lineof docs/index.rst "bond Ux -> L.p")
[ $st -ne 0 ] && grep -qF "docs/index.rst:$line:9: error: undefined name 'Ux'" "$tmp/err" &&
  [ "$(sed -n "${line}p" docs/index.rst | cut -c9-10)" = Ux ]
check "sphinx -W: a bad model in the page fails the build naming the page's line and column (got $st)" $?
grep -qF "$(head -1 "$p/output-sphinx-bad.txt")" "$tmp/err"; check "sphinx: the message docs/integrations.md shows" $?
cp "$tmp/index.rst" docs/index.rst
sed -i 's/R Rload = R/R Rload = Rx/' docs/models/load.bg
sphinx-build -b html docs build/html >"$tmp/out" 2>"$tmp/err"
line=$(lineof docs/models/load.bg "R Rload = Rx")
grep -qF "docs/models/load.bg:$line:13: error: undefined name 'Rx'" "$tmp/err"
check "sphinx: a mistake in the used file is a warning naming that file and line" $?
sed -i 's/R Rload = Rx/R Rload = R/' docs/models/load.bg
sphinx-build -b html docs build/html >"$tmp/out" 2>"$tmp/err"
[ ! -s "$tmp/err" ] && grep -q '>R : Rload<' build/html/index.html
cs_=$?; check "sphinx: the used file fixed, the page is read again and drawn ($(head -2 "$tmp/err"))" $cs_
printf 'Se U = 1\nbond U -> R9\n' >docs/models/bad.bg
printf '\n.. bgdraw:: models/bad.bg\n' >>docs/index.rst
sphinx-build -W -b html docs build/html >"$tmp/out" 2>"$tmp/err"; st=$?
[ $st -ne 0 ] && grep -qF "docs/models/bad.bg:2:11: error: undefined name 'R9'" "$tmp/err"
check "sphinx -W: a bad model file fails the build naming the model file and line" $?
cp "$tmp/index.rst" docs/index.rst
sed -i 's/   :class: wide/   :class: wide\n   :format: png/' docs/index.rst
sphinx-build -b html docs build/html >"$tmp/out" 2>"$tmp/err"
png=$(grep -o '<img src="_images/bgdraw-[0-9a-f]*\.png" alt="A source and its load"/>' build/html/index.html | grep -o 'bgdraw-[0-9a-f]*\.png')
[ -n "$png" ] && [ "$(head -c 4 "build/html/_images/$png" | tail -c 3)" = PNG ]
check "sphinx :format: png: an <img> of a PNG in the output folder's _images" $?
sed -i 's/   :format: png/   :format: svg/' docs/index.rst
sphinx-build -b html docs build/html >"$tmp/out" 2>"$tmp/err"
svgimg=$(grep -o '<img src="_images/bgdraw-[0-9a-f]*\.svg"' build/html/index.html | grep -o 'bgdraw-[0-9a-f]*\.svg')
[ -n "$svgimg" ] && xmllint --noout "build/html/_images/$svgimg"
check "sphinx :format: svg: an <img> of an SVG file" $?
cd "$root" || exit 1

# ---------------------------------------------------------------- MkDocs
snap "$p/mkdocs/docs" >"$tmp/src.before"
printf '# Other\n\nAs [](index.md#fig-load) shows.\n' >"$p/mkdocs/docs/other.md"
bash "$p/run-mkdocs.sh" >"$tmp/out" 2>&1; st=$?
check "mkdocs: the page's command builds the site (got $st: $(grep -m2 'WARNING\|ERROR' "$tmp/out"))" $st
python3 - "$p/mkdocs/site/index.html" "$tmp/rlc.svg" "$p/mkdocs/site/other/index.html" <<'PY'; check "mkdocs: both figures with caption and number, align and class, inline SVG as bgdraw draws it, links read Figure N" $?
import re, sys
html, svg, other = open(sys.argv[1]).read(), open(sys.argv[2]).read(), open(sys.argv[3]).read()
fig = re.search(r'<figure id="fig-rlc">(.*?)</figure>', html, re.S).group(1)
assert svg[svg.index("<svg"):].strip() in fig
assert '<figcaption><span class="caption-number">Figure 1:</span> The series RLC circuit and its causal paths</figcaption>' in fig
load = re.search(r'<figure id="fig-load" class="align-center">(.*?)</figure>', html, re.S).group(1)
assert load.startswith('<div class="bgdraw wide" role="img" aria-label="A source and its load"><svg')
assert '>R : Rl<' in load
assert '<span class="caption-number">Figure 2:</span> A source and its load' in load
assert '<a href="#fig-rlc">Figure 1</a> shows the causal paths; <a href="#fig-load">Figure 2</a>' in html
assert '<a href="../#fig-load">Figure 2</a>' in other, "a link from another page"
PY
rm "$p/mkdocs/docs/other.md"
snap "$p/mkdocs/docs" | cmp -s - "$tmp/src.before"; check "mkdocs: nothing written into the docs folder" $?
cd "$p/mkdocs" || exit 1
sed -i 's/Rl/Rload/g' docs/models/load.bg
mkdocs build -q >"$tmp/out" 2>&1 && grep -q '>R : Rload<' site/index.html
check "mkdocs: editing the used file changes the figure in the next build" $?
sed -i 's/bond U -> L.p/bond Ux -> L.p/' docs/index.md
mkdocs build -q >"$tmp/out" 2>&1; st=$?
line=$(lineof docs/index.md "bond Ux -> L.p")
[ $st -ne 0 ] && grep -qF "docs/index.md:$line:6: error: undefined name 'Ux'" "$tmp/out"
check "mkdocs: a bad model stops the build naming the page's line (got $st)" $?
sed -i 's/bond Ux -> L.p/bond U -> L.p/' docs/index.md
printf '\n```{.bgdraw caption="x"}\n```\n' >>docs/index.md
mkdocs build -q >"$tmp/out" 2>&1; st=$?
line=$(lineof docs/index.md '{.bgdraw caption="x"}')
[ $st -ne 0 ] && grep -qF "docs/index.md:$line: bgdraw block: the block has no model" "$tmp/out"
check "mkdocs: an empty block stops the build naming its line (got $st)" $?
cd "$root" || exit 1

# ---------------------------------------------------------------- pandoc
snap "$p/pandoc" >"$tmp/src.before"
bash "$p/run-pandoc.sh" >"$tmp/out" 2>"$tmp/err"; st=$?
check "pandoc: the page's commands convert to HTML, LaTeX and docx (got $st: $(head -3 "$tmp/err"))" $st
python3 - "$p/pandoc/doc.html" "$tmp/rlc.svg" <<'PY'; check "pandoc html: figures with caption and number, align and class, inline SVG, links read Figure N" $?
import re, sys
html, svg = open(sys.argv[1]).read(), open(sys.argv[2]).read()
fig = re.search(r'<figure id="fig-rlc">(.*?)</figure>', html, re.S).group(1)
assert svg[svg.index("<svg"):].strip() in fig
assert re.search(r"<figcaption>\s*Figure 1: The series RLC circuit and its causal paths\s*</figcaption>", fig)
load = re.search(r'<figure id="fig-load" class="align-center">(.*?)</figure>', html, re.S).group(1)
assert load.startswith('<div class="bgdraw wide" role="img" aria-label="A source and its load"><svg')
assert '>R : Rl<' in load and re.search(r"<figcaption>\s*Figure 2: A source and its load", load)
assert re.search(r'<a href="#fig-rlc">Figure 1</a> shows the causal paths;\s+<a\s+href="#fig-load">Figure 2</a>', html)
assert "```" not in html and ".bgdraw" not in html
PY
python3 - "$p/pandoc/doc.tex" <<'PY'; check "pandoc latex: figures with \\caption and \\label, Figure~\\ref" $?
import re, sys
tex = open(sys.argv[1]).read()
for name, cap in (("fig-rlc", "The series RLC circuit and its causal paths"), ("fig-load", "A source and its load")):
    assert re.search(r"\\begin\{figure\}(?:(?!\\end\{figure\}).)*?\\includegraphics\{media/bgdraw-[0-9a-f]+\.pdf\}"
                     r"(?:(?!\\end\{figure\}).)*?\\caption\{%s\}\\label\{%s\}" % (cap, name), tex, re.S), name
assert re.search(r"Figure~\\ref\{fig-rlc\} shows the causal paths;\s+Figure~\\ref\{fig-load\}", tex)
PY
rlcpdf=$(grep -o 'media/bgdraw-[0-9a-f]*\.pdf' "$p/pandoc/doc.tex" | head -1)
cmp -s "$p/pandoc/$rlcpdf" "$tmp/rlc.pdf"; check "pandoc latex: the extracted PDF is bgdraw's" $?
python3 - "$p/pandoc/doc.docx" <<'PY'; check "pandoc docx: two captioned figures with their images, links read Figure N" $?
import re, sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
xml = z.read("word/document.xml").decode()
paras = re.findall(r"<w:p>.*?</w:p>|<w:p .*?</w:p>", xml, re.S)
def text(p): return "".join(re.findall(r"<w:t[^>]*>([^<]*)</w:t>", p))
caps = [text(p) for p in paras if 'w:val="ImageCaption"' in p]
assert caps == ["Figure 1: The series RLC circuit and its causal paths", "Figure 2: A source and its load"], caps
assert xml.count("<pic:pic") == 2 and sum(n.startswith("word/media/") and n.endswith(".png") for n in z.namelist()) == 2
assert "Figure 1 shows the causal paths; Figure 2" in "".join(text(p) for p in paras)
PY
rm -rf "$p/pandoc/media" "$p/pandoc/doc.html" "$p/pandoc/doc.tex" "$p/pandoc/doc.docx"
snap "$p/pandoc" | cmp -s - "$tmp/src.before"; check "pandoc: nothing but the outputs written" $?
cd "$p/pandoc" || exit 1
filter=$root/contrib/pandoc/bgdraw.lua
sed -i 's/Rl/Rload/g' models/load.bg
pandoc doc.md --lua-filter "$filter" -o doc.html && grep -q '>R : Rload<' doc.html
check "pandoc: editing the used file changes the figure" $?
sed -i 's/bond U -> L.p/bond Ux -> L.p/' doc.md
pandoc doc.md --lua-filter "$filter" -o doc.tex 2>"$tmp/err"; st=$?
line=$(lineof doc.md "bond Ux -> L.p")
[ $st -ne 0 ] && grep -qF "doc.md:$line:6: error: undefined name 'Ux'" "$tmp/err" && ! grep -qi "traceback" "$tmp/err"
check "pandoc: a bad model stops the conversion with bgdraw's diagnostic at the file's line, no stack trace (got $st)" $?
sed -i 's/bond Ux -> L.p/bond U -> L.p/' doc.md
cp doc.md "$tmp/doc.md"
printf '\n```bgdraw\n```\n' >>doc.md
pandoc doc.md --lua-filter "$filter" -o doc.html 2>"$tmp/err"; st=$?
line=$(($(wc -l <doc.md) - 1))
[ $st -ne 0 ] && grep -qF "doc.md:$line: the \`\`\`bgdraw block is empty" "$tmp/err" && ! grep -qi "traceback" "$tmp/err"
cs_=$?; check "pandoc: an empty block is an error naming its line (got $st: $(cat "$tmp/err"))" $cs_
cp "$tmp/doc.md" doc.md
printf '\n```{.bgdraw file=models/none.bg}\n```\n' >>doc.md
pandoc doc.md --lua-filter "$filter" -o doc.html 2>"$tmp/err"; st=$?
[ $st -ne 0 ] && grep -qF "model file 'models/none.bg' not found" "$tmp/err"; check "pandoc: a missing file= is an error" $?
cp "$tmp/doc.md" doc.md
printf 'Se U = 1\nbond U -> R9\n' >models/bad.bg
printf '\n```{.bgdraw file=models/bad.bg}\n```\n' >>doc.md
pandoc doc.md --lua-filter "$filter" -o doc.html 2>"$tmp/err"; st=$?
[ $st -ne 0 ] && grep -qF "models/bad.bg:2:11: error: undefined name 'R9'" "$tmp/err"
check "pandoc: a bad model file names the model file and line" $?
cp "$tmp/doc.md" doc.md
cd "$root" || exit 1

# ---------------------------------------------------------------- make
mkdir -p "$p/make/parts"
cp "$p/shell/models/load.bg" "$p/make/parts/load.bg"
printf 'use "../parts/load.bg"\nSe U = 1\nRCLoad L\nbond U -> L.p\n' >"$p/make/models/loaded.bg"
printf '0, 1\n10, 1\n' >"$p/make/models/u.csv"
printf 'Se U = table(t, "u.csv")\nR R1 = 1\nbond U -> R1\n' >"$p/make/models/tab.bg"
bash "$p/run-make.sh" >"$tmp/out" 2>&1; st=$?
check "make: the page's commands build the figures (got $st)" $st
cd "$p/make" || exit 1
cmp -s figures/rlc.svg <(bgdraw models/rlc.bg -q -T svg) && grep -q '>R : Rl<' figures/loaded.svg && [ -s figures/tab.svg ]
check "make: every model drawn" $?
make -s -q; check "make: up to date after the build" $?
sleep 1; sed -i 's/Rl/Rload/g' parts/load.bg
make -s -q figures/loaded.svg; st=$?
make -s -q figures/rlc.svg figures/tab.svg; st2=$?
[ $st -eq 1 ] && [ $st2 -eq 0 ]; check "make: editing the used file makes its figure, and only it, out of date" $?
make -s >/dev/null 2>&1 && grep -q '>R : Rload<' figures/loaded.svg; check "make: the figure rebuilt" $?
sleep 1; touch models/u.csv
make -s -q figures/tab.svg; check "make: a table CSV makes its figure out of date" $(($? != 1))
printf 'Se U = 1\nbond U -> R9\n' >models/bad.bg
make -s >"$tmp/out" 2>&1; st=$?
[ $st -ne 0 ] && grep -qF "models/bad.bg:2:11: error: undefined name 'R9'" "$tmp/out" && [ ! -e figures/bad.svg ]
check "make: a bad model fails the build naming its file and line, no figure" $?
cd "$root" || exit 1

# ---------------------------------------------------------------- shell
bash "$p/run-shell.sh" >"$tmp/out" 2>&1; st=$?
check "shell: the page's commands run (got $st: $(head -3 "$tmp/out"))" $st
cd "$p/shell" || exit 1
cmp -s rlc.svg rlc-pipe.svg; check "shell: -o FILE.svg and -T svg from a pipe draw the same" $?
head -1 rlc.d | grep -q '^rlc.svg: models/rlc.bg '; check "shell: -M names the model" $?
grep -q '>R : Rl<' load.svg && grep -q '>R : Rl<' uses-load.svg
check "shell: --stdin-name finds the used file beside the name; BGDRAW_PATH finds it too" $?
cd "$root" || exit 1

# ---------------------------------------------------------------- reports in a page
bgdraw examples/rlc.bg --report "$tmp/rlc-report.html" -o "$tmp/rlc.json"
bash "$p/run-sphinx-report.sh" >"$tmp/out" 2>"$tmp/err"; st=$?
check "sphinx :report:: the page's command builds (got $st: $(head -3 "$tmp/err"))" $st
[ ! -s "$tmp/err" ]; check "sphinx :report:: no warnings" $?
bash "$p/run-mkdocs-report.sh" >"$tmp/out" 2>&1; st=$?
check "mkdocs report=: the page's command builds (got $st: $(grep -m2 'WARNING\|ERROR' "$tmp/out"))" $st
python3 - "$tmp/rlc-report.html" "$p/sphinx-report/build/html/index.html" "$p/mkdocs-report/site/index.html" <<'PY'
import os, re, sys
report = open(sys.argv[1], encoding="utf-8").read()
for page in sys.argv[2:]:
    html = open(page, encoding="utf-8").read()
    links = re.findall(r'<p class="bgdraw-report-link"><a href="([^"]+)">The analysis report</a></p>', html)
    assert len(links) == 2, (page, links)
    for l in links:  # the report itself, as --report FILE.html writes it
        assert open(os.path.join(os.path.dirname(page), l), encoding="utf-8").read() == report, l
    assert html.count('<svg id="bg-diagram"') == 1 and html.count('<div class="bgdraw-report">') == 1
    assert re.search(r'<tr id="path-2" tabindex="0" data-bonds="2 3"', html)
    assert '<style id="bgdraw-parts">' in html and "document.getElementById('bg-diagram')" in html
    assert 'href="#path-2"' in html
    if "mkdocs" in page:
        assert re.search(r'<iframe class="bgdraw" src="[^"]*_bgdraw/bgdraw-[0-9a-f]+\.html" title="bond graph"', html)
PY
check "sphinx and mkdocs: the report linked, embedded, and its diagram and tables in the page" $?
python3 - "$p/sphinx-report/build/html/index.html" "$p/mkdocs-report/site/index.html" "$tmp/rlc.json" <<'PY'
# in a browser: a row of the page lights the diagram's bonds, #path-2 selects the row
import json, os, sys
sys.path.insert(0, "tests/html")
import cdp
want = json.load(open(sys.argv[3]))["causal_paths"]
lit = ("Array.from(document.querySelectorAll('#bg-diagram .bond.hl'))"
       ".map(e => +Array.from(e.classList).find(c => /^b[0-9]+$/.test(c)).slice(1)).sort()")
b = cdp.Browser()
bad = []
try:
    for page in sys.argv[1:3]:
        url = "file://" + os.path.abspath(page)
        p = b.page(width=1400, height=1000)
        p.goto(url)
        p.eval("document.getElementById('path-1').focus()")
        if p.eval(lit) != sorted(want[0]["bonds"]):
            bad.append("%s: focus path 1 lit %s" % (page, p.eval(lit)))
        p.close()
        p = b.page(width=1400, height=1000)
        p.goto(url + "#path-2")
        if p.eval(lit) != sorted(want[1]["bonds"]) or not p.eval(
                "document.getElementById('path-2').classList.contains('selected')"):
            bad.append("%s#path-2: lit %s" % (page, p.eval(lit)))
        # (MkDocs' own theme fails offline: highlight.js from a CDN, a search worker on file://)
        errors = [e for e in p.events() if e.get("method") == "Runtime.exceptionThrown"]
        if errors and "sphinx" in page:
            bad.append("%s: %s" % (page, errors[0]["params"]["exceptionDetails"]["text"]))
        p.close()
finally:
    b.close()
print("\n".join(bad))
sys.exit(1 if bad else 0)
PY
check "sphinx and mkdocs pages in chromium: a row lights its bonds, #path-2 selects it" $?
finish
