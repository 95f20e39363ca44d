#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Robustness: 150 deterministically damaged copies of the examples never crash
# bgdraw (exit 0 or 1 with caret diagnostics, no output on errors); see
# tests/mutated_models.py. Usage: bash tests/mutated_models.sh PATH_TO_BGDRAW
set -u
exec python3 "$(dirname "$0")/mutated_models.py" "${1:?usage: mutated_models.sh PATH_TO_BGDRAW}" 150
