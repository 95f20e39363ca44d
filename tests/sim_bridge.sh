#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Starting on a switching point (docs/simulation.md, "Starting on a switching
# point"): the diode bridge of tests/data/diode_bridge.bg (four if-law diodes,
# a sine source, every diode at its threshold at t = 0) runs from t = 0 at the
# default tolerances and agrees with an independent integration
# (tests/sim_bridge.py); its events come in pairs (two diodes switch at once)
# and no condition is logged twice at one switching; a run that fails at a
# switch says so in words, with what may work.
# Usage: bash tests/sim_bridge.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
/usr/bin/python3 "$root/tests/sim_bridge.py" "$BGDRAW" "$root/tests/data/diode_bridge.bg" "$tmp"
check "bridge from t = 0 against an independent integration" $?
"$BGDRAW" tests/data/diode_bridge.bg --simulate -o "$tmp/b.json" -o "$tmp/b.csv" 2>"$tmp/b.err"
check "bridge: exit 0" $?
/usr/bin/python3 - "$tmp/b.json" <<'PY'
import json, sys
ev = json.load(open(sys.argv[1]))["simulation"]["events"]["list"]
# conduction changes hands twice a period (0.02 s) over 0.04 s: each time two
# diodes switch together, and the start (D1, D4 on at t = 0+) is no event
ts = []
for e in ev:  # instants: events less than 1e-7 s apart are one
    if not ts or e["t"] - ts[-1] > 1e-7: ts.append(e["t"])
pairs = all(sum(1 for e in ev if 0 <= e["t"] - t <= 1e-7) == 2 for t in ts)
ups = all(sum(e["direction"] == "rising" for e in ev if 0 <= e["t"] - t <= 1e-7) in (0, 2) for t in ts)
once = all(not (a["condition"] == b["condition"] and a["direction"] == b["direction"] and abs(a["t"] - b["t"]) < 4e-8)
           for i, a in enumerate(ev) for b in ev[i + 1:])
print(len(ev), "events at", len(ts), "instants")
sys.exit(not (len(ts) >= 6 and pairs and ups and once and ev[0]["t"] > 1e-3))
PY
check "bridge: two diodes at each switching instant, the same way, none logged twice, none at t = 0" $?
sed 's/^simulate t_end = 0.04$/simulate t_end = 0.04, rtol = 1e-13, atol = 1e-13/' tests/data/diode_bridge.bg >"$tmp/tight.bg"
"$BGDRAW" "$tmp/tight.bg" --simulate -o "$tmp/t.csv" 2>"$tmp/t.err"; rc=$?
[ $rc -eq 3 ] && grep -q "the run failed at a switch; what may work: a looser atol" "$tmp/t.err"
check "bridge at rtol 1e-13: fails at a switch and says so, with what may work (got $rc)" $?
finish
