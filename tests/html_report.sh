#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The HTML report without a browser (docs/report.md, "The HTML report"): every
# example and test model writes one with --report FILE.html; it is well-formed
# XML (xmllint), the same bytes on a second run and under another clock and
# folder, self-contained (no URL but XML namespaces, no src, no link, no
# url()), has the sections the run computed (linear analysis, transformation),
# rows with the bonds of the JSON's causal paths, plot data with the CSV's
# times; a wrong extension is a usage error; --equations mathml means what
# --equations text says (tests/html/mathml_check.py).
# Usage: bash tests/html_report.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"

for m in examples/*.bg tests/data/*.bg examples/components/*.bg tests/data/fields/*.bg; do
  n=$(basename "$m" .bg)
  "$BGDRAW" "$m" --report "$tmp/$n.html" -o "$tmp/$n.json" >/dev/null 2>&1
  [ -s "$tmp/$n.html" ]; check "$n: --report FILE.html writes the page" $?
  xmllint --noout "$tmp/$n.html" 2>"$tmp/xml.err"; cs_=$?; check "$n: well-formed ($(head -1 "$tmp/xml.err"))" $cs_
  grep -q '<section id="diagram"' "$tmp/$n.html" && grep -q '<svg id="bg-diagram"' "$tmp/$n.html"
  check "$n: the diagram inline" $?
  # no network at view time: the only URLs are XML namespaces
  ! grep -Eo '(https?|ftp)://[^"'"'"' )<]*' "$tmp/$n.html" | grep -vq '^http://www.w3.org/' &&
    ! grep -Eq '<(link|img|iframe|object|embed)[ >]| src=|url\(|@import' "$tmp/$n.html"
  check "$n: self-contained" $?
done

# deterministic: again, in another folder, with another clock
mkdir -p "$tmp/again"
(cd "$tmp/again" && SOURCE_DATE_EPOCH=1234567890 TZ=Asia/Tokyo "$BGDRAW" "$root/examples/delta.bg" --report d.html 2>/dev/null)
cmp -s "$tmp/again/d.html" "$tmp/delta.html"; check "delta: the same bytes in another folder and clock" $?
"$BGDRAW" examples/rlc.bg --report "$tmp/rlc2.html" 2>/dev/null
cmp -s "$tmp/rlc2.html" "$tmp/rlc.html"; check "rlc: the same bytes twice" $?
"$BGDRAW" examples/rlc.bg --report "$tmp/RLC.HTM" 2>/dev/null
cmp -s "$tmp/RLC.HTM" "$tmp/rlc.html"; check ".HTM is HTML too" $?
"$BGDRAW" examples/rlc.bg --report "$tmp/rlc.pdf" 2>/dev/null
head -c 5 "$tmp/rlc.pdf" | grep -q '%PDF-'; check ".pdf stays the PDF report" $?

# every causal path's row carries the JSON's bonds; every section present
python3 - "$tmp" <<'PY'; check "rows carry the JSON's bonds, sections present" $?
import json, os, re, sys
tmp = sys.argv[1]
bad = 0
for f in sorted(os.listdir(tmp)):
    if not f.endswith(".json"):
        continue
    n = f[:-5]
    j = json.load(open(os.path.join(tmp, f)))
    h = open(os.path.join(tmp, n + ".html"), encoding="utf-8").read()
    for k, p in enumerate(j["causal_paths"][:400]):
        m = re.search(r'<tr id="path-%d" tabindex="0" data-bonds="([0-9 ]*)"' % (k + 1), h)
        if not m or list(map(int, m.group(1).split())) != p["bonds"]:
            print("%s: path %d row %s, JSON %s" % (n, k + 1, m and m.group(1), p["bonds"])); bad += 1
    for k, c in enumerate(j["conflicts"]):
        m = re.search(r'<tr id="conflict-%d" tabindex="0" data-bonds="([0-9 ]*)"' % (k + 1), h)
        if not m or sorted(map(int, m.group(1).split())) != sorted(c["bonds"]):
            print("%s: conflict %d" % (n, k + 1)); bad += 1
    for sec in ("summary", "diagram", "trace", "paths-loops-conflicts", "form-index", "equations",
                "estimates", "simulation"):
        if '<section id="%s"' % sec not in h:
            print("%s: no section %s" % (n, sec)); bad += 1
    if h.count("<h1>") != 1 or "<html lang=\"en\">" not in h:
        print("%s: one h1, a language" % n); bad += 1
sys.exit(bad != 0)
PY

# a model of submodels: its instances and each bond's origin; a field: its ports
python3 - "$tmp/rc_ladder_lib" <<'PY'
import json, re, sys
h = open(sys.argv[1] + ".html", encoding="utf-8").read()
j = json.load(open(sys.argv[1] + ".json"))
rows = re.findall(r'<tr id="bond-([0-9]+)" tabindex="0" data-bonds="([0-9]+)"', h)
sys.exit(0 if '<section id="instances"' in h and [int(a) for a, _ in rows] == [b["id"] for b in j["bonds"]] else 1)
PY
check "submodels: the instances section, a row per flat bond" $?
grep -q '<h3 id="field-1">C field K: 2 ports, mixed causality</h3>' "$tmp/dependent.html" &&
  ! grep -q '<section id="fields"' "$tmp/rlc.html" && ! grep -q '<section id="instances"' "$tmp/rlc.html"
check "fields: the field's section (and neither section for rlc)" $?

# the linear analysis and the transformation, when the run has them
"$BGDRAW" tests/data/linear_rlc.bg --report "$tmp/lin.html" 2>/dev/null
grep -q '<section id="linear"' "$tmp/lin.html" && grep -q 'aria-label="Bode diagram"' "$tmp/lin.html"
check "linear analysis: its section and Bode diagram" $?
"$BGDRAW" tests/data/linear_rlc.bg --linear json >"$tmp/lin.json"
python3 - "$tmp/lin.html" "$tmp/lin.json" <<'PY'; check "Bode readout data: 20 log10 |num/den| of the transfer functions" $?
import json, math, re, sys
h = open(sys.argv[1], encoding="utf-8").read()
tf = json.load(open(sys.argv[2]))["transfer_functions"]
bode = h[h.index('aria-label="Bode diagram"'):]
d = json.loads(re.search(r'<script type="application/json" class="plot-data">(.*?)</script>', bode, re.S).group(1))
assert d["xlog"] == 1 and len(d["panels"]) == 2
def poly(c, s):
    v = 0
    for a in c:
        v = v * s + a
    return v
mag = d["panels"][0]
assert len(mag["names"]) == len(tf)
for j, t in enumerate(tf):
    assert mag["names"][j] == "%s \u2190 %s" % (t["output"], t["input"]), mag["names"][j]
    for w, v in zip(d["t"], mag["values"][j]):
        g = abs(poly(t["num"], 1j * w) / poly(t["den"], 1j * w))
        want = 20 * math.log10(g) if g > 0 else None
        assert (v is None and want is None) or abs(v - want) <= 1e-4 * max(1, abs(want)), (w, v, want)
PY
"$BGDRAW" tests/data/transform/gear.bg --transform merge-stores --report "$tmp/tx.html" 2>/dev/null
grep -q '<section id="transformation"' "$tmp/tx.html" && [ "$(grep -c 'aria-label="The bond graph' "$tmp/tx.html")" = 2 ] &&
  grep -qF '<tr><th scope="row">dependent stores</th><td class="n">1</td><td class="n">0</td></tr>' "$tmp/tx.html" &&
  grep -qF '<tr><th scope="row">form</th><td class="n">DAE</td><td class="n">ODE</td></tr>' "$tmp/tx.html"
check "transformation: its section, the analysis before and after (merging the gear's stores), both bond graphs" $?
! grep -q '<section id="transformation"' "$tmp/rlc.html"; check "no transformation section without --transform" $?

# the plot's readout data: the CSV's times and first column
"$BGDRAW" examples/rlc.bg -o "$tmp/rlc.csv" 2>/dev/null
python3 - "$tmp/rlc.html" "$tmp/rlc.csv" <<'PY'; check "plot data: the CSV's rows" $?
import csv, json, re, sys
h = open(sys.argv[1], encoding="utf-8").read()
d = json.loads(re.search(r'<script type="application/json" class="plot-data">(.*?)</script>', h, re.S).group(1))
rows = list(csv.reader(open(sys.argv[2])))
head, data = rows[0], [list(map(float, r)) for r in rows[1:]]
assert len(d["t"]) == len(data), (len(d["t"]), len(data))
p = d["panels"][0]
c = head.index(p["names"][0])
assert all(abs(a - r[0]) <= 1e-5 * max(abs(r[0]), 1e-12) for a, r in zip(d["t"], data))
assert all(abs(v - r[c]) <= 1e-5 * max(abs(r[c]), 1e-300) for v, r in zip(p["values"][0], data))
PY

# usage: the report is a PDF or an HTML page
"$BGDRAW" examples/rlc.bg --report "$tmp/r.txt" 2>"$tmp/err"; st=$?
[ $st -eq 2 ] && grep -q "give a .pdf or .html file" "$tmp/err"; check "--report r.txt: a usage error" $?

# MathML: the known rows of rlc, and the meaning of every example's rows
"$BGDRAW" examples/rlc.bg --equations mathml >"$tmp/rlc.mml"
grep -qF '<math display="block"><mrow><msub><mi>e</mi><mn>4</mn></msub><mo>=</mo><mfrac><mrow><msub><mi>q</mi><mi mathvariant="normal">C1</mi></msub></mrow><mrow><mi>C0</mi></mrow></mfrac></mrow></math>' "$tmp/rlc.mml"
check "--equations mathml: e4 = q_C1 / C0" $?
python3 tests/html/mathml_check.py "$BGDRAW" examples/*.bg examples/components/*.bg tests/data/*.bg
check "MathML rows mean the text rows" $?
finish
