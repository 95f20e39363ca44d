#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# State events in the outputs (issue 12; docs/simulation.md "State events"):
# the bouncing ball of tests/data/bouncing_ball.bg through the CLI: -v prints
# each event (the first contact at t = sqrt(2 h / g) = 0.4515236410), the JSON
# lists them (times against the closed-form solution to 1e-8, conditions,
# directions), the report has the events table, reruns give the same bytes;
# a model without switching conditions has no "events" key; friction at rest
# (chattering) stops the run with exit 3 and says why.
# Usage: bash tests/sim_events.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
command -v python3 >/dev/null || { echo "python3 not found"; exit 1; }
ball=tests/data/bouncing_ball.bg
"$BGDRAW" $ball -v -o "$tmp/b.json" -o "$tmp/b.csv" 2>"$tmp/b.err"; check "ball: exit status" $?
grep -q "bgdraw: simulate: state event at t = 0.451523641: law of K: K.q < 0 (falling)" "$tmp/b.err"
check "ball: -v prints the first contact" $?
grep -q "bgdraw: simulate: 12 state events at 2 switching conditions" "$tmp/b.err"; check "ball: -v count" $?
python3 - "$tmp/b.json" <<'PY'
import json, math, sys
ev = json.load(open(sys.argv[1]))["simulation"]["events"]
m, g, k, c, h = 1.0, 9.81, 1e4, 20.0, 1.0
w0 = math.sqrt(k / m); z = c / (2 * math.sqrt(k * m)); a = z * w0; wd = w0 * math.sqrt(1 - z * z)
xe = -m * g / k
def contact_exit(v):  # first return to x = 0 of the damped oscillator from (0, v < 0)
    A = -xe; B = (v + a * A) / wd
    x = lambda s: xe + math.exp(-a * s) * (A * math.cos(wd * s) + B * math.sin(wd * s))
    dx = lambda s: math.exp(-a * s) * ((-a * A + wd * B) * math.cos(wd * s) + (-a * B - wd * A) * math.sin(wd * s))
    lo = hi = 1e-9
    while x(hi) < 0: lo, hi = hi, hi + 1e-4
    for _ in range(200): lo, hi = (lo, (lo + hi) / 2) if x((lo + hi) / 2) >= 0 else ((lo + hi) / 2, hi)
    return hi, dx(hi)
times, t, v = [], math.sqrt(2 * h / g), -math.sqrt(2 * g * h)
while t < 2:
    times.append(t); s, v = contact_exit(v); t += s; times.append(t); t += 2 * v / g; v = -v
times = [x for x in times if x < 2]
assert ev["searched"] and ev["conditions"] == ["law of K: K.q < 0", "law of D: K.q < 0"], ev["conditions"]
got = [e["t"] for e in ev["list"]]
assert ev["count"] == len(got) == 2 * len(times) == 12, (ev["count"], len(times))
err = max(abs(x - times[i // 2]) for i, x in enumerate(got))
dirs = [e["direction"] for e in ev["list"]]
assert dirs == ["falling", "falling", "rising", "rising"] * 3, dirs
assert [e["condition"] for e in ev["list"][:2]] == [0, 1]
print("event times against the closed form: %.2g" % err)
sys.exit(0 if err < 1e-8 else 1)
PY
check "ball: JSON events against the closed form" $?
# the keys of simulation.events are the ones docs/json.md names, no more, no fewer
python3 - "$tmp/b.json" docs/json.md <<'PY'
import json, re, sys
ev = json.load(open(sys.argv[1]))["simulation"]["events"]
row = next(l for l in open(sys.argv[2]) if l.startswith("| `events` | object |"))
named = set(re.findall(r"`(\w+)`", row))
keys, entry = set(ev), set().union(*(set(e) for e in ev["list"]))
ok = keys == {"searched", "conditions", "count", "list"} and keys <= named
ok = ok and "`simulation.events.list`" in row and "{t, condition, direction}" in row and entry == {"t", "condition", "direction"}
print("simulation.events keys", sorted(keys), "entries", sorted(entry))
sys.exit(0 if ok else 1)
PY
check "ball: simulation.events and its list entries have the keys docs/json.md names" $?
"$BGDRAW" $ball -v -o "$tmp/b2.json" -o "$tmp/b2.csv" 2>/dev/null; cmp -s "$tmp/b.json" "$tmp/b2.json"; check "ball: rerun, same JSON bytes" $?
if command -v pdftotext >/dev/null; then
  "$BGDRAW" $ball --report "$tmp/b.pdf" 2>/dev/null
  pdftotext "$tmp/b.pdf" - | tr -s ' \n' ' ' >"$tmp/b.txt"
  grep -q "State events 12 at 2 switching conditions" "$tmp/b.txt"; check "ball: report statistics row" $?
  grep -q "State events t \[s\] Condition" "$tmp/b.txt" &&
    grep -q "0.4836257206 law of K: K.q < 0 rising" "$tmp/b.txt"; check "ball: report events table" $?
fi
"$BGDRAW" examples/rlc.bg --simulate -o "$tmp/rlc.json" 2>/dev/null
python3 -c "import json,sys; sys.exit('events' in json.load(open(sys.argv[1]))['simulation'])" "$tmp/rlc.json"
check "rlc (no conditions): no events key" $?
"$BGDRAW" tests/data/friction_stick.bg --simulate -o "$tmp/f.csv" 2>"$tmp/f.err"; rc=$?
[ $rc -eq 3 ]; check "friction at rest: exit 3 (got $rc)" $?
grep -q "more than 1000 state events in one output interval, the last at law of F: sign(f3)" "$tmp/f.err" &&
  grep -q "chattering" "$tmp/f.err"; check "friction at rest: says why" $?
grep -q "^# partial: simulation failed at t = 2: more than 1000 state events" "$tmp/f.csv" &&
  [ "$(grep -v '^#' "$tmp/f.csv" | tail -1 | cut -d, -f1)" = 2 ]; check "friction at rest: rows to t = 2, partial" $?
echo "sim_events: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
