#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# --verify states an error bound (docs/simulation.md, "Verification"): twice
# the largest deviation of any output or state from a run 100 times tighter.
# tests/verify_bound.py holds it against the true error on every model of the
# suite with an exact answer (rlc, a damped mass chain, the bouncing ball, the
# gear backlash), each at the default tolerances and two looser ones. Then a
# chaotic backlash at rtol 1e-6: the runs' events part, and --verify says when.
# Usage: bash tests/verify_bound.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
/usr/bin/python3 "$root/tests/verify_bound.py" "$BGDRAW" "$tmp"
check "the bound holds on every model with an exact answer" $?
/usr/bin/python3 -c "
import sys; sys.path.insert(0, '$root/tests'); import sim_accuracy as S
open('$tmp/s5.bg', 'w').write(S.model_text(S.parameter_sets()[5], 12, ', rtol = 1e-6'))"
"$BGDRAW" "$tmp/s5.bg" --verify -o "$tmp/s5.csv" -o "$tmp/s5.json" 2>"$tmp/s5.err"
check "chaotic backlash: exit 0" $?
grep -q "warning: the tighter run has [0-9]* state events, this run [0-9]*: they part at t = " "$tmp/s5.err"
check "chaotic backlash: the events part, and the run says when" $?
/usr/bin/python3 -c "
import json, sys; e = json.load(open(sys.argv[1]))['simulation']['verify']['events']
sys.exit(not (e['count'] != e['tighter_count'] and e['time_deviation'] is None and 0 < e['part_at'] < 12))" "$tmp/s5.json"
check "chaotic backlash: the JSON's verify.events" $?
finish
