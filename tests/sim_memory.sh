#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Memory (docs/format.md, "Memory"; issue 29): hyst() and stick() keep a
# discrete state that changes only at events. Against closed forms derived
# by hand, row by row and event by event, with CVODE (auto) and IDA:
# - tests/data/thermostat.bg, a relay with hysteresis heating a room: the
#   room's temperature is a piecewise exponential, on towards P*R and off
#   towards 0; it switches off at hi and on at lo (the first rise from 0);
# - tests/data/stick_slip.bg, a block pulled through a spring whose end moves
#   at V, Karnopp friction with static Fs and Coulomb Fc: stuck until the
#   spring's force reaches Fs at t = Fs/(k V), then a slip that is a harmonic
#   arc (w = sqrt(k/m)) lasting 2 (pi - atan((Fs - Fc)/(m w V)))/w, ending
#   where the speed returns to 0 with the force at 2 Fc - Fs, stuck again
#   for 2 (Fs - Fc)/(k V); the speed stays exactly 0 while stuck.
# The Octave and Modelica exports refuse a model with memory (status 3, the
# reason); C, Python and the FMU carry it (tests/export_events.sh).
# Usage: bash tests/sim_memory.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
judge() { # KIND CSV JSON
  /usr/bin/python3 - "$@" <<'PY'
import csv, json, math, sys
kind, rows = sys.argv[1], [[float(x) for x in r] for r in list(csv.reader(open(sys.argv[2])))[1:]]
ev = json.load(open(sys.argv[3]))["simulation"]["events"]
evs = [dict(e, text=ev["conditions"][e["condition"]]) for e in ev["list"]]
if kind == "thermostat":
    P, R, C, lo, hi = 3.0, 10.0, 0.5, 8.0, 12.0
    tau, Tinf = R * C, P * R
    sw, t, on = [], tau * math.log(Tinf / (Tinf - hi)), True
    while t < 20:
        sw.append(t)
        t += tau * math.log(hi / lo) if on else tau * math.log((Tinf - lo) / (Tinf - hi))
        on = not on
    def exact(t):
        T0, t0, heat = 0.0, 0.0, True
        for s in sw + [math.inf]:
            u = Tinf if heat else 0.0
            if t <= s:
                return [u + (T0 - u) * math.exp(-(t - t0) / tau), P if heat else 0.0]
            T0, t0, heat = hi if heat else lo, s, not heat
    scale = [hi, P]
    names = ["hyst"] * len(sw)
else:
    m, k, V, Fs, Fc = 1.0, 50.0, 0.2, 2.0, 1.0
    w, B = math.sqrt(k / m), (Fs - Fc) / (m * math.sqrt(k / m))
    slip, stuck = 2 * (math.pi - math.atan(B / V)) / w, 2 * (Fs - Fc) / (k * V)
    sw, t = [], Fs / (k * V)
    while t < 3:
        sw += [t, t + slip]
        t += slip + stuck
    sw = [s for s in sw if s < 3]
    def exact(t):
        F0, t0 = 0.0, 0.0
        for i, s in enumerate(sw + [math.inf]):
            if t <= s:
                if i % 2 == 0:  # stuck: speed 0, the spring's force grows at k V
                    return [0.0, F0 + k * V * (t - t0), F0 + k * V * (t - t0)]
                tau = t - t0
                z = -V * math.cos(w * tau) + B * math.sin(w * tau)
                return [V + z, Fc + m * w * (V * math.sin(w * tau) + B * math.cos(w * tau)), Fc]
            F0 = Fs if i % 2 == 0 else 2 * Fc - Fs
            t0 = s
    scale = [0.4, Fs, Fs]
    names = ["stick"] * len(sw)
mine = [e for e in evs if e["text"].split(":")[1].strip().startswith(names[0])]
dt = max(abs(a["t"] - b) for a, b in zip(mine, sw)) if len(mine) == len(sw) else math.inf
# near a switch a row may sit on the other side of the event in one run
# and not in the other: rows within 1e-6 s of a switching time are skipped
near = lambda t: min(abs(t - s) for s in sw) < 1e-6
err = [max(abs(r[1 + j] - exact(r[0])[j]) / scale[j] for r in rows if not near(r[0])) for j in range(len(scale))]
print("%s: %d of %d switchings, times within %.2g s; largest error over the range %s"
      % (kind, len(mine), len(sw), dt, ", ".join("%.2g" % e for e in err)))
sys.exit(not (dt < 2e-7 and max(err) < 1e-6))
PY
}
for solver in auto ida; do
  for m in thermostat stick_slip; do
    if [ $solver = auto ]; then cp "$root/tests/data/$m.bg" "$tmp/$m.bg"
    else sed 's/^simulate \(.*\)$/simulate \1, solver = ida/' "$root/tests/data/$m.bg" >"$tmp/$m.bg"; fi
    "$BGDRAW" "$tmp/$m.bg" --simulate -o "$tmp/$m.csv" -o "$tmp/$m.json"; check "$m ($solver): exit 0" $?
    judge "$m" "$tmp/$m.csv" "$tmp/$m.json"; check "$m ($solver): events and rows against the closed form" $?
  done
done
# the speed is exactly 0 while stuck (Karnopp: the floor's force is the spring's)
awk -F, 'NR > 1 && $1 > 0.01 && $1 < 0.19 && $2 != 0 { bad = 1 } END { exit bad }' "$tmp/stick_slip.csv"
check "stick_slip: speed exactly 0 while stuck" $?
# a rerun is byte-identical
"$BGDRAW" "$tmp/stick_slip.bg" --simulate -o "$tmp/again.csv"; cmp -s "$tmp/again.csv" "$tmp/stick_slip.csv"
check "stick_slip: rerun byte-identical" $?
# exports without modes (Octave, Modelica) refuse memory, saying why; C,
# Python and the FMU carry it (tests/export_events.sh runs them)
for ext in c py fmu; do
  "$BGDRAW" "$root/tests/data/thermostat.bg" -o "$tmp/t.$ext" 2>"$tmp/err" && [ -s "$tmp/t.$ext" ]
  check "export .$ext of a model with memory is written" $?
done
for ext in m mo; do
  "$BGDRAW" "$root/tests/data/thermostat.bg" -o "$tmp/t.$ext" 2>"$tmp/err"; st=$?
  [ $st -eq 3 ] && grep -q "discrete state (value of heater: hyst(" "$tmp/err" && [ ! -e "$tmp/t.$ext" ]
  cs_=$?; check "export .$ext refused with the reason (status $st: $(head -c 200 "$tmp/err"))" $cs_
done
finish
