#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# A condition of t that no input breakpoint covers is a state event
# (docs/simulation.md, "State events"): a square wave step(sin(w t)) charging
# an RC (tau 0.05 s, period 0.2 s) against its closed form, piece by piece;
# every zero of the sine an event at k/10 s; t > 0.35 in an if() too. Before,
# such conditions were stepped over.
# Usage: bash tests/sim_time_events.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
model() { # SOURCE
  printf 'model sq\nparam w = 2*pi*5, R0 = 1, C0 = 0.05\nSe U = %s\n1 j\nR R1 = R0\nC C1 = C0\n' "$1"
  printf 'bond U -> j\nbond j -> R1\nbond j -> C1\nsimulate t_end = 0.95, dt = 0.005\nplot C1.e\n'
}
judge() { # CSV JSON KIND
  /usr/bin/python3 - "$@" <<'PY'
import csv, json, math, sys
rows = [[float(x) for x in r] for r in list(csv.reader(open(sys.argv[1])))[1:]]
ev = [e["t"] for e in json.load(open(sys.argv[2]))["simulation"]["events"]["list"]]
tau, kind = 0.05, sys.argv[3]
if kind == "square":
    sw = [0.1 * k for k in range(1, 10)]
    level = lambda t: 1.0 if math.sin(2 * math.pi * 5 * t) >= 0 else 0.0
else:
    sw = [0.35]
    level = lambda t: 1.0 if t > 0.35 else 0.0
def exact(t):
    v, t0 = 0.0, 0.0
    for s in sw + [float("inf")]:
        u = level((t0 + min(s, t)) / 2)
        if t <= s:
            return u + (v - u) * math.exp(-(t - t0) / tau)
        v, t0 = u + (v - u) * math.exp(-(s - t0) / tau), s
err = max(abs(r[1] - exact(r[0])) for r in rows)
dt = max(abs(a - b) for a, b in zip(ev, sw)) if len(ev) == len(sw) else float("inf")
print("%s: %d events, times within %.2g s, C1.e within %.2g" % (kind, len(ev), dt, err))
sys.exit(not (dt < 1e-9 and err < 1e-6))
PY
}
model 'step(sin(w*t))' >"$tmp/sq.bg"
"$BGDRAW" "$tmp/sq.bg" --simulate -o "$tmp/sq.csv" -o "$tmp/sq.json"; check "square wave: exit 0" $?
judge "$tmp/sq.csv" "$tmp/sq.json" square; check "square wave: events at the sine's zeros, the closed form" $?
model 'if(t > 0.35, 1, 0)' >"$tmp/if.bg"
"$BGDRAW" "$tmp/if.bg" --simulate -o "$tmp/if.csv" -o "$tmp/if.json"; check "if(t > 0.35): exit 0" $?
judge "$tmp/if.csv" "$tmp/if.json" step; check "if(t > 0.35): one event, the closed form" $?
finish
