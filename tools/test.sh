#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The test suite: set up (with the tests' packages), build, run ctest.
#   bash tools/test.sh          every test (CI: .ci/run)
#   bash tools/test.sh --quick  the tests labelled quick: under a minute on an
#                               idle machine, for the developer's loop
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh --tests
label=()
[ "${1:-}" = "--quick" ] && label=(-L quick)
ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure -j"$(nproc)" "${label[@]}"
