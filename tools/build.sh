#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs missing packages, configures (once) and builds bgdraw into build/.
#   bash tools/build.sh           what bgdraw needs (the main job)
#   bash tools/build.sh --tests   and what the tests need (tools/test.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/deps.sh "$@"
BUILD_TYPE=${BUILD_TYPE:-RelWithDebInfo}
BUILD_DIR=${BUILD_DIR:-build}
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then
  cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="$BUILD_TYPE" >/dev/null
fi
cmake --build "$BUILD_DIR" -j"$(nproc)" >/dev/null
