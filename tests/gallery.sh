#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# docs/gallery.md, run as a reader would: every model of the page is its file in
# examples/gallery, every command block runs (tools/gallery.sh in a private folder),
# every picture is made, and each entry's numbers are checked against the hand-derived
# or textbook answer the page states. Each gallery model also passes --check without
# a warning.
#     bash tests/gallery.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
. "$(dirname "$0")/lib/doc_pages.sh"
page_build gallery
page_files gallery

# the event times of the two models with memory, as bgdraw reports them
for m in thermostat belt_friction; do
  (cd "$d" && "$BGDRAW" "$m.bg" --simulate -v -o "$tmp/events.csv") 2>&1 |
    sed -n 's/^bgdraw: simulate: state event at t = \([0-9.e+-]*\): law of F: stick.*(\(slips\|sticks\):.*/\1 \2/p;
            s/^bgdraw: simulate: state event at t = \([0-9.e+-]*\): value of heater: hyst.*(\(rises\|falls\):.*/\1 \2/p' \
    >"$d/$m.events"
done
(cd "$d" && "$BGDRAW" gear_merged.bg --check) >"$d/gear_merged.check" 2>&1

python3 - "$d" <<'EOF'
import cmath, json, math, sys
sys.path.insert(0, "tests/lib")
import page_numbers as pn
from page_numbers import close, rows, table, worst
d = pn.D = sys.argv[1]
def linear(name):
    return json.load(open(f"{d}/{name}"))

# RC filter: pole -1/RC, DC gain 1, |H(j/RC)| = 1/sqrt(2), step response 1 - e^(-t/RC)
j = linear("rc_filter_linear.json")
close("RC: pole", j["poles"][0]["re"], -1000, 1e-6)
tf = j["transfer_functions"][0]
close("RC: DC gain", tf["dc_gain"], 1, 1e-12)
s = 1000j
H = sum(c * s ** (len(tf["num"]) - 1 - i) for i, c in enumerate(tf["num"])) / \
    sum(c * s ** (len(tf["den"]) - 1 - i) for i, c in enumerate(tf["den"]))
close("RC: magnitude at 1000 rad/s [dB]", 20 * math.log10(abs(H)), -10 * math.log10(2), 1e-9)
close("RC: phase at 1000 rad/s [deg]", math.degrees(cmath.phase(H)), -45, 1e-9)
close("RC: largest deviation from 1 - e^(-t/RC)", worst("rc_filter.csv", 1, lambda t: 1 - math.exp(-t / 1e-3)), 0, 1e-6)
# the exported C with R0 doubled, integrated by the driver
drv = [[float(x) for x in line.split()] for line in open(f"{d}/rc_driver.txt")]
close("RC export: lines", len(drv), 11, 0)
close("RC export: largest deviation from 1 - e^(-t/2 ms)", max(abs(v - (1 - math.exp(-t / 2e-3))) for t, v in drv), 0, 1e-9)

# quarter car: static deflections, DC gain, characteristic polynomial
mb, mw, g, ks, bs, kt = 250, 35, 9.81, 16000, 1000, 160000
last = rows("quarter_car.csv")[-1]
close("quarter car: suspension deflection", last[1], -mb * g / ks, 1e-6)
close("quarter car: tyre deflection", last[2], -(mb + mw) * g / kt, 1e-6)
tf = linear("quarter_car_linear.json")["transfer_functions"][0]
close("quarter car: DC gain zb/Wb", tf["dc_gain"], 1 / ks + 1 / kt, 1e-12)
poly = [mb * mw, bs * (mb + mw), ks * (mb + mw) + kt * mb, bs * kt, ks * kt]
for i, (got, want) in enumerate(zip(tf["den"], [c / poly[0] for c in poly])):
    close(f"quarter car: s^{4 - i} coefficient", got, want, 1e-9 * max(1, abs(want)))

# DC motor and gear: the steady state
V, Ra, K, bm, bl, n = 12, 1, 0.05, 1e-5, 1e-3, 10
wm = K * V / (Ra * (bm + bl / n**2) + K**2)
last = rows("dc_motor_gear.csv")[-1]
close("DC motor: load speed", last[1], wm / n, 1e-6)
close("DC motor: current", last[2], (V - K * wm) / Ra, 1e-6)

# two inertias: one state after merge-stores, and both models' load speed
check = open(f"{d}/gear_merged.check").read()
close("merged gear: states", int("states (1): Jl.p" in check), 1, 0)
close("merged gear: its inertia is Jl0 + Jm0*n^2", int("I   Jl = Jl0 + Jm0*n^2" in open(f"{d}/gear_merged.bg").read()), 1, 0)
for m in ("gear_inertias.csv", "gear_merged.csv"):
    close(f"{m}: largest deviation from 10 (1 - e^(-t/2))", worst(m, 1, lambda t: 10 * (1 - math.exp(-t / 2))), 0, 1e-5)

# Torricelli: h = (sqrt(h0) - Cd a sqrt(2g) t / (2A))^2
c = 0.6 * 1e-3 * math.sqrt(2 * 9.81) / 2
close("draining tank: empty after [s]", 1 / c, 752.5, 0.05)
close("draining tank: largest deviation from Torricelli", worst("torricelli.csv", 1, lambda t: (1 - c * t) ** 2), 0, 1e-5)

# thermostat: 798.5 s to 21 degC, then 100.1 s cooling, 200.7 s heating
ev = [line.split() for line in open(f"{d}/thermostat.events")]
tau = 1000
want, t, kind = [], tau * math.log(20 / 9), "rises"
while t < 3000:
    want.append((t, kind))
    t += tau * math.log(21 / 19) if kind == "rises" else tau * math.log(11 / 9)
    kind = "falls" if kind == "rises" else "rises"
close("thermostat: events", len(ev), len(want), 0)
for (got, gk), (w, wk) in zip(ev, want):
    close(f"thermostat: {wk} at", float(got) if gk == wk else float("nan"), w, 1e-3)

# block on a belt: stuck 0.2 s (Fs / (k v0)), slipping 3 pi / (2 omega), stuck again 0.2 s ...
ev = [line.split() for line in open(f"{d}/belt_friction.events")]
want, t, kind = [], 0.2, "slips"
while t < 1.5:
    want.append((t, kind))
    t += 0.3 * math.pi / 2 if kind == "slips" else 0.2
    kind = "sticks" if kind == "slips" else "slips"
close("belt: events", len(ev), len(want), 0)
for (got, gk), (w, wk) in zip(ev, want):
    close(f"belt: {wk} at", float(got) if gk == wk else float("nan"), w, 1e-6)
stuck = [r for r in rows("belt_friction.csv") if r[0] < 0.2 or 0.68 < r[0] < 0.87]
close("belt: largest deviation of the stuck block's speed from the belt's", max(abs(r[1] - 0.1) for r in stuck), 0, 1e-9)

# reaction: nA = 0.7333 + 0.2667 e^(-3t), nA + nB = 1.1
close("reaction: largest deviation of nA", worst("reaction.csv", 1, lambda t: 1.1 * 2 / 3 + (1 - 1.1 * 2 / 3) * math.exp(-3 * t)), 0, 1e-6)
close("reaction: largest deviation of nA + nB from 1.1", max(abs(r[1] + r[2] - 1.1) for r in rows("reaction.csv")), 0, 1e-9)

# damping sweep: peak F0/k (1 + e^(-zeta pi / sqrt(1 - zeta^2))) at pi / (omega sqrt(1 - zeta^2))
head, runs = table("msd_study.csv")
close("sweep: runs", len(runs), 7, 0)
for r in runs:
    b = r[head.index("b")]
    z = b / (2 * math.sqrt(100))
    close(f"sweep b = {b:g}: peak", r[head.index("K.q:max")], 0.01 * (1 + math.exp(-z * math.pi / math.sqrt(1 - z * z))), 1e-5)
    close(f"sweep b = {b:g}: time of the peak", r[head.index("K.q:tmax")], math.pi / (10 * math.sqrt(1 - z * z)), 1e-3)
sys.exit(1 if pn.failed else 0)
EOF
check "the gallery's numbers (above)" $?

# every gallery model passes --check without a warning
for f in examples/gallery/*.bg; do
  "$BGDRAW" "$f" --check >/dev/null 2>"$tmp/err" && ! [ -s "$tmp/err" ]
  check "$f passes --check quietly" $?
done
finish
