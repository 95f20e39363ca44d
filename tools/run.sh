#!/usr/bin/env bash
# The main job: set up, build, and render an example (diagram, analysis) into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p out
MODEL=${1:-examples/hydraulic_bridge.bg}
NAME=$(basename "$MODEL" .bg)
build/bgdraw "$MODEL" -o "out/$NAME.svg" -o "out/$NAME.png" -o "out/$NAME.json" --show all
echo "wrote out/$NAME.svg, out/$NAME.png, out/$NAME.json"
