#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# What docs/examples.md says bgdraw finds in each example, on the analysis JSON
# (tests/examples_analysis.py: whole lists, gains to 1e-12).
# Usage: bash tests/examples_analysis.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: examples_analysis.sh PATH_TO_BGDRAW}
command -v python3 >/dev/null || { echo "python3 not found"; exit 1; }
exec python3 tests/examples_analysis.py "$BGDRAW"
