#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Every picture of docs/images/ has its recipe in tools/images.sh (or, for the
# gallery page's screenshot, in tools/gallery.sh): the script makes each one, as a
# PNG of the size the repository's copy has within a third (a layout change may
# move it; a picture of something else would not be near).
#     bash tests/doc_images.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
bash tools/images.sh "$BGDRAW" "$tmp/img" 2>"$tmp/err"
st=$?
check "tools/images.sh runs: $(tail -2 "$tmp/err")" $st
for f in docs/images/*.png; do
  name=${f##*/}
  [ "$name" = gallery_entry.png ] && continue
  [ -f "$tmp/img/$name" ] && file "$tmp/img/$name" | grep -q 'PNG image data'
  check "tools/images.sh makes $name" $?
  read -r w0 h0 < <(file "$f" | sed -n 's/.*PNG image data, \([0-9]*\) x \([0-9]*\).*/\1 \2/p')
  read -r w1 h1 < <(file "$tmp/img/$name" | sed -n 's/.*PNG image data, \([0-9]*\) x \([0-9]*\).*/\1 \2/p')
  [ "${w1:-0}" -gt $((w0 * 2 / 3)) ] && [ "${w1:-0}" -lt $((w0 * 4 / 3)) ] &&
    [ "${h1:-0}" -gt $((h0 * 2 / 3)) ] && [ "${h1:-0}" -lt $((h0 * 4 / 3)) ]
  check "$name: ${w1:-?} x ${h1:-?}, the repository's ${w0} x ${h0}" $?
done
grep -q 'gallery_entry.png' tools/gallery.sh; check "the screenshot's recipe is tools/gallery.sh's" $?
# every picture the README and docs show from docs/images is there
for img in $(grep -oh 'images/[a-z_]*\.png' README.md docs/*.md | sort -u); do
  [ -f "docs/$img" ]; check "docs/$img, which a page shows, exists" $?
done
finish
