#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""The HTML report in a real browser (Debian's chromium, headless, driven over
its DevTools pipe by cdp.py): for each model, its report, its JSON and its
diagram's PNG are written by bgdraw, and the page is checked against the JSON
(an independent output of the same run):
  - hovering a row of causal paths, topological loops, causal loops, the
    trace lights exactly the bonds the JSON lists for it (and the diagram's
    own drawing of that path or loop), focusing a conflict's row likewise;
  - #path-K selects path K on load; Enter on a focused row selects it and
    writes the fragment; a layer's check box hides that layer;
  - the plot readout under the pointer shows the simulation's values (CSV);
  - no console error, no exception, no request but the report itself;
  - dark scheme, print style, headings, table headers, alt texts;
  - the diagram's screenshot against the diagram's PNG (same geometry).
usage: browser.py BGDRAW OUTDIR MODEL...   (OUTDIR keeps the screenshots)"""
import base64
import csv
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cdp  # noqa: E402

failures = 0
passes = 0


def check(name, ok, detail=""):
    global failures, passes
    if ok:
        passes += 1
    else:
        failures += 1
        print("FAIL %s%s" % (name, (": " + str(detail)) if detail else ""))


def bonds_lit(page):
    return sorted(page.eval("Array.from(document.querySelectorAll('#bg-diagram .bond.hl'))"
                            ".map(e => +Array.from(e.classList).find(c => /^b[0-9]+$/.test(c)).slice(1))"))


def hover(page, row_id):
    r = page.eval("(() => { const r = document.getElementById(%r); if (!r) return null;"
                  " r.scrollIntoView({block: 'center'}); const b = r.getBoundingClientRect();"
                  " return [b.x + b.width / 2, b.y + b.height / 2]; })()" % row_id)
    if r is None:
        return False
    page.mouse(1, 1)
    page.mouse(r[0], r[1])
    return True


def away(page):
    page.eval("window.scrollTo(0, 0)")
    page.mouse(1, 1)


def click(page, x, y):
    for t in ("mousePressed", "mouseReleased"):
        page.cmd("Input.dispatchMouseEvent", {"type": t, "x": x, "y": y, "button": "left", "clickCount": 1})


def run(bgdraw, *args):
    return subprocess.run([bgdraw] + list(args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          timeout=300).returncode


def quiet_page(page, name, url):
    """Console errors, exceptions and requests other than the report."""
    bad = []
    for ev in page.events():
        m, p = ev.get("method"), ev.get("params", {})
        if m == "Runtime.exceptionThrown":
            bad.append("exception: %s" % p.get("exceptionDetails", {}).get("text"))
        elif m == "Runtime.consoleAPICalled" and p.get("type") in ("error", "warning", "assert"):
            bad.append("console %s" % p.get("type"))
        elif m == "Log.entryAdded" and p.get("entry", {}).get("level") in ("error", "warning"):
            bad.append("log: %s" % p["entry"].get("text"))
        elif m == "Network.requestWillBeSent":
            req = p.get("request", {}).get("url", "")
            if req.split("#")[0] != url.split("#")[0]:
                bad.append("request: %s" % req)
    check(name + ": no console errors, no requests but the report", not bad, bad)


def table_checks(page, name, j):
    paths = j["causal_paths"]
    for k, p in enumerate(paths[:4]):
        if not hover(page, "path-%d" % (k + 1)):
            check(name + ": row path-%d exists" % (k + 1), False)
            continue
        check(name + ": hover path %d lights its bonds" % (k + 1), bonds_lit(page) == sorted(p["bonds"]),
              (bonds_lit(page), p["bonds"]))
        drawn = page.eval("document.querySelectorAll('#bg-diagram .path.p%d').length" % (k + 1))
        lit = page.eval("document.querySelectorAll('#bg-diagram .path.p%d.hl').length" % (k + 1))
        check(name + ": hover path %d lights its drawing" % (k + 1), lit == drawn and (drawn == 0 or lit > 0))
        away(page)
        check(name + ": leaving the row clears the light", bonds_lit(page) == [])
    for k, l in enumerate(j["topological_loops"][:3]):
        hover(page, "loop-%d" % (k + 1))
        check(name + ": hover loop %d lights its bonds" % (k + 1), bonds_lit(page) == sorted(set(l["bonds"])),
              (bonds_lit(page), l["bonds"]))
        away(page)
    for k, l in enumerate(j["causal_loops"][:2]):
        hover(page, "cloop-%d" % (k + 1))
        check(name + ": hover causal loop %d" % (k + 1), bonds_lit(page) == sorted(set(l["bonds"])),
              (bonds_lit(page), l["bonds"]))
        away(page)
    for k, cf in enumerate(j["conflicts"][:2]):
        page.eval("document.getElementById('conflict-%d').focus()" % (k + 1))
        check(name + ": focus conflict %d lights its bonds" % (k + 1), bonds_lit(page) == sorted(cf["bonds"]),
              (bonds_lit(page), cf["bonds"]))
        lit = page.eval("document.querySelectorAll('#bg-diagram .flash.c%d.hl').length" % (k + 1))
        drawn = page.eval("document.querySelectorAll('#bg-diagram .flash.c%d').length" % (k + 1))
        check(name + ": focus conflict %d lights its mark" % (k + 1), lit == drawn)
        page.eval("document.activeElement.blur()")
    step1 = sorted(b["id"] for b in j["bonds"] if b.get("step") == 1)
    if j["trace"]:
        hover(page, "step-1")
        check(name + ": hover trace step 1 lights the bonds it fixed", bonds_lit(page) == step1,
              (bonds_lit(page), step1))
        away(page)


def layer_checks(page, name):
    for layer, cls in (("numbers", "number"), ("strokes", "stroke"), ("paths", "path")):
        n = page.eval("document.querySelectorAll('#bg-diagram .%s').length" % cls)
        if not n:
            continue
        box = page.eval("(() => { const i = document.querySelector('input[data-layer=%s]');"
                        " i.scrollIntoView({block: 'center'}); const b = i.getBoundingClientRect();"
                        " return [b.x + b.width / 2, b.y + b.height / 2]; })()" % layer)
        shown = "Array.from(document.querySelectorAll('#bg-diagram .%s')).filter(e => " \
                "getComputedStyle(e).display !== 'none').length" % cls
        click(page, box[0], box[1])
        check(name + ": unticking %s hides it" % layer, page.eval(shown) == 0, page.eval(shown))
        others = page.eval("Array.from(document.querySelectorAll('#bg-diagram .bond'))"
                           ".filter(e => getComputedStyle(e).display === 'none').length")
        check(name + ": unticking %s keeps the bonds" % layer, others == 0)
        click(page, box[0], box[1])
        check(name + ": ticking %s shows it again" % layer, page.eval(shown) == n)


def readout_check(page, name, csvpath):
    if not page.eval("!!document.querySelector('svg[aria-label^=Simulation] path.panel')"):
        return
    pt = page.eval("(() => { const p = document.querySelector('svg[aria-label^=Simulation] path.panel');"
                   " p.scrollIntoView({block: 'center'}); const b = p.getBoundingClientRect();"
                   " return [b.x + b.width * 0.37, b.y + b.height / 2]; })()")
    page.mouse(pt[0], pt[1])
    text = page.eval("document.querySelector('svg[aria-label^=Simulation]').closest('figure').querySelector('output.readout').textContent")
    ok = text.startswith("t = ") and ": " in text
    check(name + ": the readout shows values under the pointer", ok, text)
    if not ok or not csvpath:
        return
    t = float(text[4:text.index(": ")])
    d = json.loads(page.eval("document.querySelector('svg[aria-label^=Simulation]').closest('figure')"
                             ".querySelector('script.plot-data').textContent"))
    at = d["t0"] + 0.37 * (d["t1"] - d["t0"])
    gap = max(b - a for a, b in zip(d["t"], d["t"][1:])) if len(d["t"]) > 1 else 0
    check(name + ": the readout's time is where the pointer is (%g, %g)" % (t, at), abs(t - at) <= 1.5 * gap + 1e-9)
    first = text[text.index(": ") + 2:].split(", ")[0]
    col, val = first.rsplit(" = ", 1)
    rows = list(csv.reader(open(csvpath)))
    head, data = rows[0], [list(map(float, r)) for r in rows[1:]]
    if col not in head:
        check(name + ": readout column %s in the CSV" % col, False, head)
        return
    c = head.index(col)
    best = min(data, key=lambda r: abs(r[0] - t))
    want = best[c]
    check(name + ": readout at t = %g is the CSV's %s" % (t, col),
          abs(float(val) - want) <= 1e-4 * max(abs(want), 1e-12) + 1e-12 and abs(best[0] - t) <= 1e-4 * max(abs(t), 1e-12),
          (text, best[0], want))


def bode_check(page, name):
    """The Bode readout on its log axis: the pointer halfway across the panel
    reads the frequency halfway between the ends in decades."""
    fig = "document.querySelector('svg[aria-label=\"Bode diagram\"]').closest('figure')"
    if not page.eval("!!document.querySelector('svg[aria-label=\"Bode diagram\"]')"):
        return
    d = json.loads(page.eval(fig + ".querySelector('script.plot-data').textContent"))
    pt = page.eval("(() => { const p = %s.querySelector('path.panel'); p.scrollIntoView({block: 'center'});"
                   " const b = p.getBoundingClientRect(); return [b.x + b.width / 2, b.y + b.height / 2]; })()" % fig)
    page.mouse(pt[0], pt[1])
    text = page.eval(fig + ".querySelector('output.readout').textContent")
    ok = text.startswith("\u03c9 = ")
    check(name + ": the Bode readout names the frequency", ok, text)
    if not ok:
        return
    w = float(text[4:text.index(": ")])
    mid = 10 ** ((math.log10(d["t0"]) + math.log10(d["t1"])) / 2)
    step = (math.log10(d["t1"]) - math.log10(d["t0"])) / (len(d["t"]) - 1)
    check(name + ": the Bode readout's frequency is where the pointer is on the log axis (%g, %g)" % (w, mid),
          abs(math.log10(w) - math.log10(mid)) <= 1.5 * step)
    first = text[text.index(": ") + 2:].split(", ")[0].rsplit(" = ", 1)[1]
    i = min(range(len(d["t"])), key=lambda k: abs(d["t"][k] - w))
    want = d["panels"][0]["values"][0][i]
    check(name + ": the Bode readout shows the row's magnitude", abs(float(first) - want) <= 1e-4 * max(1, abs(want)),
          (first, want))


def a11y_checks(page, name):
    r = page.eval("""(() => ({
      h1: document.querySelectorAll('h1').length,
      thNoScope: Array.from(document.querySelectorAll('thead th')).filter(t => !t.getAttribute('scope')).length,
      figNoLabel: Array.from(document.querySelectorAll('figure svg')).filter(s => !s.getAttribute('aria-label')).length,
      rowsNoTab: Array.from(document.querySelectorAll('tr[data-bonds]')).filter(r => r.tabIndex !== 0).length,
      lang: document.documentElement.lang,
      sections: Array.from(document.querySelectorAll('main > section')).filter(s => !s.querySelector('h2')).length}))()""")
    check(name + ": one h1, th scope, svg labels, focusable rows, lang, headed sections",
          r["h1"] == 1 and r["thNoScope"] == 0 and r["figNoLabel"] == 0 and r["rowsNoTab"] == 0
          and r["lang"] == "en" and r["sections"] == 0, r)


def similar(r):
    """The thresholds of 'the same picture': the examples measure 1.5-3.5 % of
    4x4 blocks apart (text placed to other pixels) with 98.8-99.9 % of the
    PNG's ink found within 2 px; the same diagram without its paths and loops
    is 8 % or more apart."""
    return r["differ"] < 0.05 and r["recall"] > 0.97


def screenshot_check(b, name, url, pngpath, outdir, control=None):
    page = b.page(width=2400, height=1600, scale=2)
    page.goto(url)
    rect = page.eval("""(() => { const s = document.getElementById('bg-diagram');
      const vb = s.viewBox.baseVal; const pane = document.getElementById('diagram');
      pane.style.position = 'static'; pane.style.maxHeight = 'none'; pane.style.overflow = 'visible';
      s.style.maxWidth = 'none'; s.style.width = vb.width + 'px'; s.style.height = vb.height + 'px';
      s.scrollIntoView(); const r = s.getBoundingClientRect();
      return {x: r.x + window.scrollX, y: r.y + window.scrollY, width: r.width, height: r.height}; })()""")
    shot = page.screenshot(rect)
    page.close()
    open(os.path.join(outdir, name + "-diagram.png"), "wb").write(shot)
    r = compare_png(b, shot, open(pngpath, "rb").read())
    same = abs(r["wa"] - r["wb"]) <= 2 and abs(r["ha"] - r["hb"]) <= 2
    check(name + ": screenshot has the PNG's geometry", same, r)
    print("%s: %.3f%% blocks differ, %.2f%% of the PNG ink found" % (name, 100 * r["differ"], 100 * r["recall"]))
    check(name + ": screenshot matches the PNG (%.2f%% blocks differ, %.1f%% of its ink found)"
          % (100 * r["differ"], 100 * r["recall"]), similar(r), r)
    if control:  # the comparison tells another picture apart
        r = compare_png(b, shot, open(control, "rb").read())
        print("%s control: %.3f%% blocks differ, %.2f%% of its ink found" % (name, 100 * r["differ"], 100 * r["recall"]))
        check(name + ": the comparison fails against the diagram without paths and loops", not similar(r), r)


def compare_png(b, shot, png):
    ref = base64.b64encode(png).decode()
    cmp_page = b.page()
    r = cmp_page.eval("""(async () => {
      const load = src => new Promise((ok, no) => { const i = new Image(); i.onload = () => ok(i); i.onerror = no; i.src = src; });
      const a = await load('data:image/png;base64,%s'), b = await load('data:image/png;base64,%s');
      const w = Math.min(a.width, b.width), h = Math.min(a.height, b.height);
      const px = img => { const c = document.createElement('canvas'); c.width = w; c.height = h;
        const g = c.getContext('2d'); g.fillStyle = '#fff'; g.fillRect(0, 0, w, h); g.drawImage(img, 0, 0);
        return g.getImageData(0, 0, w, h).data; };
      const p = px(a), q = px(b);
      // text is placed to a pixel by pango and by the browser alike, but not to the
      // same pixel: compare 4x4 block means, and look for the PNG's ink within 2 px
      const B = 4, bw = Math.floor(w / B), bh = Math.floor(h / B);
      let differ = 0, ink = 0, both = 0;
      for (let by = 0; by < bh; by++) for (let bx = 0; bx < bw; bx++) {
        let d = 0;
        for (let c = 0; c < 3; c++) {
          let sa = 0, sb = 0;
          for (let y = 0; y < B; y++) for (let x = 0; x < B; x++) {
            const i = 4 * ((by * B + y) * w + bx * B + x) + c; sa += p[i]; sb += q[i];
          }
          d = Math.max(d, Math.abs(sa - sb) / (B * B));
        }
        if (d > 40) differ++;
      }
      const dark = (d, i) => Math.min(d[i], d[i + 1], d[i + 2]) < 128;
      for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) {
        if (!dark(q, 4 * (y * w + x))) continue;
        ink++;
        let found = false;
        for (let dy = -2; dy <= 2 && !found; dy++) for (let dx = -2; dx <= 2 && !found; dx++) {
          const yy = y + dy, xx = x + dx;
          if (yy >= 0 && yy < h && xx >= 0 && xx < w && dark(p, 4 * (yy * w + xx))) found = true;
        }
        if (found) both++;
      }
      differ /= bw * bh;
      return {wa: a.width, ha: a.height, wb: b.width, hb: b.height, differ: differ, recall: ink ? both / ink : 1};
    })()""" % (base64.b64encode(shot).decode(), ref))
    cmp_page.close()
    return r

def model(b, bgdraw, path, outdir, first):
    name = os.path.splitext(os.path.basename(path))[0]
    html = os.path.join(outdir, name + ".html")
    js = os.path.join(outdir, name + ".json")
    png = os.path.join(outdir, name + "-ref.png")
    csvpath = os.path.join(outdir, name + ".csv")
    check(name + ": bgdraw --report FILE.html", run(bgdraw, path, "--report", html, "-o", js) in (0, 1)
          and os.path.exists(html))
    run(bgdraw, path, "--show", "all", "-o", png)
    if run(bgdraw, path, "-o", csvpath) != 0 or not os.path.exists(csvpath):
        csvpath = None
    j = json.load(open(js))
    url = "file://" + os.path.abspath(html)
    page = b.page(width=1400, height=1000)
    page.goto(url)
    quiet_page(page, name, url)
    a11y_checks(page, name)
    table_checks(page, name, j)
    layer_checks(page, name)
    readout_check(page, name, csvpath)
    bode_check(page, name)
    quiet_page(page, name + " (after the interaction)", url)
    # Enter on a focused row selects it and writes the fragment
    if j["causal_paths"]:
        page.eval("document.getElementById('path-1').focus()")
        page.key("Enter", "Enter", 13)
        check(name + ": Enter selects the row and writes #path-1",
              page.eval("location.hash") == "#path-1"
              and page.eval("document.getElementById('path-1').classList.contains('selected')"))
    page.close()
    # a link to causal path K selects it on load
    if j["causal_paths"]:
        k = min(3, len(j["causal_paths"]))
        page = b.page(width=1400, height=1000)
        page.goto(url + "#path-%d" % k)
        check(name + ": #path-%d selects its row" % k,
              page.eval("document.getElementById('path-%d').classList.contains('selected')" % k))
        check(name + ": #path-%d lights its bonds" % k, bonds_lit(page) == sorted(j["causal_paths"][k - 1]["bonds"]),
              (bonds_lit(page), j["causal_paths"][k - 1]["bonds"]))
        open(os.path.join(outdir, name + "-path%d.png" % k), "wb").write(page.screenshot())
        page.close()
    # dark scheme and print style
    page = b.page(dark=True)
    page.goto(url)
    check(name + ": dark scheme", page.eval("getComputedStyle(document.body).backgroundColor") == "rgb(21, 23, 26)")
    page.cmd("Emulation.setEmulatedMedia", {"media": "print"})
    check(name + ": print style hides the contents and toggles",
          page.eval("getComputedStyle(document.querySelector('nav')).display") == "none"
          and page.eval("getComputedStyle(document.querySelector('fieldset.layers')).display") == "none")
    page.close()
    control = None
    if first:
        control = os.path.join(outdir, name + "-default.png")
        run(bgdraw, path, "--show", "strokes,numbers,conflicts,signals,labels,legend", "-o", control)
    screenshot_check(b, name, url, png, outdir, control)


def main():
    bgdraw, outdir, models = sys.argv[1], sys.argv[2], sys.argv[3:]
    os.makedirs(outdir, exist_ok=True)
    b = cdp.Browser()
    try:
        for i, m in enumerate(models):
            model(b, bgdraw, m, outdir, i == 0)
    finally:
        b.close()
    print("html browser: %d passed, %d failed" % (passes, failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
