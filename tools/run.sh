#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The main job: set up, build, and render an example into out/: its annotated
# diagram (SVG and PNG), its analysis (JSON) and its multi-page report (PDF).
# usage: bash tools/run.sh [MODEL.bg]   (default examples/hydraulic_bridge.bg)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p out
MODEL=${1:-examples/hydraulic_bridge.bg}
NAME=$(basename "$MODEL" .bg)
build/bgdraw "$MODEL" -q --show strokes,numbers,loops,conflicts,signals,labels,legend \
  -o "out/$NAME.svg" -o "out/$NAME.png" -o "out/$NAME.json" --report "out/$NAME.pdf"
echo "wrote out/$NAME.svg, out/$NAME.png, out/$NAME.json, out/$NAME.pdf"
