#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Makes the pictures the README and docs/ show from docs/images/ (all but
# gallery_entry.png, the gallery page's screenshot: GALLERY_SCREENSHOT=1
# tools/gallery.sh). Run it after a change to the diagrams or plots and commit
# the PNGs it changed; tests/doc_images.sh checks it makes every one of them.
#     bash tools/images.sh [BGDRAW [OUT]]   (from anywhere; OUT: docs/images)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bg=$(realpath "${1:-$root/build/bgdraw}")
out=$(realpath -m "${2:-$root/docs/images}")
[ -x "$bg" ] || { echo "images.sh: no bgdraw at $bg (build it first)" >&2; exit 2; }
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$root"
# README: the hydraulic bridge, every layer of its default view
"$bg" examples/hydraulic_bridge.bg -o "$out/hydraulic_bridge.png"
# docs/study.md: a damping sweep of the RLC (7 resistances) and its root locus (13)
"$bg" examples/rlc.bg --sweep R0=5:125:7 --collect C1.e:max --collect C1.e:tmax --study "$tmp/sweep.csv" \
  --family "$out/study_family.png"
"$bg" examples/rlc.bg --sweep R0=5:125:13 --collect poles --study "$tmp/poles.csv" \
  --root-locus "$out/study_root_locus.png"
echo "images.sh: wrote $out" >&2
