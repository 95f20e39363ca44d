#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the tutorial and the gallery (docs/tutorial.md, docs/gallery.md) into OUT
# (default out/docs): every model and command block of each page is taken from the page
# (tests/doc_snippets.py) and run there, so the pictures beside the page are exactly
# what the page's commands draw; the page is copied beside them, and turned into HTML
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
pages=("${@:3}")
[ ${#pages[@]} -gt 0 ] || pages=(tutorial gallery)
for page in "${pages[@]}"; do
  [ -f "$root/docs/$page.md" ] || continue
  rm -rf "${out:?}/$page"
  mkdir -p "$out/$page"
  python3 "$root/tests/doc_snippets.py" "$root/docs/$page.md" "$out"
  # the gallery's models are files of examples/gallery, used where they are
  for script in "$out"/run-"$page"*.sh; do
    [ -f "$script" ] || continue
    echo "gallery.sh: running the commands of docs/$page.md (${script##*/})" >&2
    PATH="$out/bin:$PATH" BGDRAW_GALLERY_ROOT="$root" bash "$script" >"${script%.sh}.log"
  done
  cp "$root/docs/$page.md" "$out/$page.md"
  if command -v pandoc >/dev/null; then
    pandoc --standalone --metadata title="bgdraw $page" -f gfm -t html5 \
      "$out/$page.md" -o "$out/$page.html"
  fi
done
echo "gallery.sh: wrote $out" >&2
