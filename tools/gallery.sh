#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the tutorial and the gallery (docs/tutorial.md, docs/gallery.md) into OUT
# (default out/docs): every model and command block of each page is taken from the page
# (tests/doc_snippets.py) and run there, so the pictures beside the page are exactly
# what the page's commands draw; the page is written beside them with its pictures shown
# (the repository's page names them in comments), and turned into HTML
# when pandoc is installed. tests/tutorial.sh and tests/gallery.sh run the same
# commands and check their numbers.
#     bash tools/gallery.sh [BGDRAW [OUT [PAGE...]]]   (from anywhere; also: cmake --build build --target gallery)
# PAGE: tutorial, gallery (default both).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bg=$(realpath "${1:-$root/build/bgdraw}")
out=$(realpath -m "${2:-$root/out/docs}")
[ -x "$bg" ] || { echo "gallery.sh: no bgdraw at $bg (build it first)" >&2; exit 2; }
mkdir -p "$out/bin"
ln -sf "$bg" "$out/bin/bgdraw"
# the pages' python3 is Debian's, with the NumPy and SciPy of tools/deps.sh --tests, not
# whichever python3 comes first on PATH (a virtual environment without them)
[ -x /usr/bin/python3 ] && ln -sf /usr/bin/python3 "$out/bin/python3"
pages=("${@:3}")
[ ${#pages[@]} -gt 0 ] || pages=(tutorial gallery)
for page in "${pages[@]}"; do
  [ -f "$root/docs/$page.md" ] || continue
  rm -rf "${out:?}/$page"
  mkdir -p "$out/$page"
  python3 "$root/tests/doc_snippets.py" "$root/docs/$page.md" "$out"
  # the page's models are written from its blocks (tests/*.sh check they are the files
  # of examples/PAGE), then its commands run where they are
  for script in "$out"/run-"$page"*.sh; do
    [ -f "$script" ] || continue
    echo "gallery.sh: running the commands of docs/$page.md (${script##*/})" >&2
    PATH="$out/bin:$PATH" bash "$script" >"${script%.sh}.log"
  done
  # the page names its pictures in comments (no broken image links where the pictures
  # are not built, docs/gallery.md "Where the pictures are"); beside them they are images
  # (and the links to built files, such as the tutorial's reports, links)
  # and the links to the other docs lead to the repository's docs/ (relative, so the
  # folder moves with the checkout); to the built pages beside it, and in the HTML to
  # their HTML
  python3 - "$root/docs/$page.md" "$out" "$page" "$(realpath -m --relative-to="$out" "$root/docs")" \
    "${pages[@]}" <<'PY'
import re, sys
src, out, page, docs, built = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
text = open(src, encoding="utf-8").read()
text = re.sub(r"^<!-- (!?\[[^]]*\]\(" + re.escape(page) + r"/[^)]*\)) -->$", r"\1", text, flags=re.M)
def relink(html):
    def one(m):
        target = m.group(2)
        if re.match(r"[a-z]+:|#|/", target) or target.startswith(page + "/"):
            return m.group(0)
        name, _, anchor = target.partition("#")
        stem = name[:-3] if name.endswith(".md") else None
        if stem in built:
            name = stem + (".html" if html else ".md")
        else:
            name = docs + "/" + name
        return m.group(1) + "(" + name + ("#" + anchor if anchor else "") + ")"
    return re.sub(r"(\]|\]\s*)\(([^)\s]+)\)", one, text)
open(f"{out}/{page}.md", "w", encoding="utf-8").write(relink(False))
open(f"{out}/.{page}.html.md", "w", encoding="utf-8").write(relink(True))
PY
  if command -v pandoc >/dev/null; then
    pandoc --standalone --metadata pagetitle="bgdraw $page" -f gfm -t html5 \
      "$out/.$page.html.md" -o "$out/$page.html"
  fi
  rm -f "$out/.$page.html.md"
done
# README's picture of a gallery page, on request (GALLERY_SCREENSHOT=1, with Debian's
# chromium): one entry, the thermostat, as the HTML shows it; it is
# docs/images/gallery_entry.png
if [ "${GALLERY_SCREENSHOT:-0}" = 1 ] && [ -f "$out/gallery.html" ]; then
  python3 -c '
import sys
out = sys.argv[1]
page = open(out + "/gallery.html", encoding="utf-8").read()
start = page.index("<h2 id=\"thermostat\">")
end = page.index("<h2", start + 1)
with open(out + "/gallery_entry.html", "w", encoding="utf-8") as f:
    f.write(page[:page.index("<body>") + 6] + page[start:end] + "</body></html>\n")
' "$out"
  timeout 300 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --virtual-time-budget=5000 --window-size=900,2300 --screenshot="$out/gallery_entry.png" \
    "file://$out/gallery_entry.html" >/dev/null 2>&1 || echo "gallery.sh: no screenshot" >&2
fi
echo "gallery.sh: wrote $out" >&2
