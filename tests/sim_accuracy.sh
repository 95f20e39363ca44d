#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Accuracy through many state events at the default tolerances
# (docs/simulation.md, "Accuracy through events"): a gear backlash (a
# dead-zone spring) with 25 to 50 switchings, six parameter sets (one fixed,
# five drawn with seed 29), against its exact piecewise solution by matrix
# exponentials (tests/sim_accuracy.py, tests/pwaffine.py): every output within
# 1e-6 of its range, the same switchings, each within 1e-6 s.
# Usage: bash tests/sim_accuracy.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
/usr/bin/python3 "$root/tests/sim_accuracy.py" "$BGDRAW" "$tmp" 2>"$tmp/err"
check "backlash at default tolerances, six parameter sets" $?
# the ill-conditioned set 5 ends at the floor of the control and says so
grep -q "accuracy control kept its tightest run (rtol 1e-13)" "$tmp/err"
check "the control's warning when it stops at its floor" $?
finish
