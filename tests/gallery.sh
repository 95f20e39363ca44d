#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# docs/gallery.md, run as a reader would: every model of the page is its file in
# examples/gallery, every command block runs (tools/gallery.sh in a private folder),
# every picture is made, and each entry's numbers are checked against the hand-derived
# or textbook answer the page states. Each gallery model also passes --check without
# a warning, and the property checks that apply to it and to each tutorial model
# (tests/property/prop.py --file).
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
(cd "$d" && "$BGDRAW" divider_parasitic.bg --check) >"$d/divider_parasitic.check" 2>&1
# the building's every state (its plot statement left out: the CSV then has the states)
grep -v '^plot ' "$d/building.bg" >"$tmp/building_states.bg"
"$BGDRAW" "$tmp/building_states.bg" --simulate -o "$d/building_states.csv"
check "the building simulates with every state" $?
# the imported model is the text the page shows
cmp -s "$tmp/out/output-rlc_bgt-import.txt" "$d/rlc_bgt.bg"
check "--import rlc_bgt.yaml writes what the page shows" $?

python3 - "$d" <<'EOF'
import cmath, json, math, sys
sys.path.insert(0, "tests/lib")
import page_numbers as pn
from page_numbers import close, rows, table, tf_at, worst
d = pn.D = sys.argv[1]
def linear(name):
    return json.load(open(f"{d}/{name}"))

# RC filter: pole -1/RC, DC gain 1, |H(j/RC)| = 1/sqrt(2), step response 1 - e^(-t/RC)
j = linear("rc_filter_linear.json")
close("RC: pole", j["poles"][0]["re"], -1000, 1e-6)
tf = j["transfer_functions"][0]
close("RC: DC gain", tf["dc_gain"], 1, 1e-12)
H = tf_at(tf, 1000j)
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

# field-controlled motor: the field current Vf/Rf sets the gyrator's ratio r = k i_f;
# the controller's voltage Kp (wref - w) balances Ra i + r w, and r i = b w
Vf, Rf, k, Ra, b, Kp, wref = 10, 20, 0.5, 0.5, 1e-3, 2, 100
r = k * Vf / Rf
w = Kp * wref / (Ra * b / r + r + Kp)
last = rows("field_motor.csv")[-1]
close("field motor: speed", last[1], w, 1e-6)
close("field motor: armature current", last[2], b * w / r, 1e-6)
close("field motor: field current", last[3], Vf / Rf, 1e-6)

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
# loudspeaker: v/U = Bl / ((Re + s Le)(m s + b + k/s) + Bl^2), x/U = v/(s U)
Re_, Le, Bl, m, k, b = 6, 0.5e-3, 7, 0.02, 2000, 1
want = [1, Re_ / Le + b / m, (Re_ * b + Le * k + Bl ** 2) / (Le * m), Re_ * k / (Le * m)]
tfs = linear("loudspeaker_linear.json")["transfer_functions"]
for tf in tfs:
    for i, (got, w) in enumerate(zip(tf["den"], want)):
        close(f"loudspeaker {tf['output']}: s^{3 - i} coefficient", got / tf["den"][0], w, 1e-9 * abs(w))
w0 = math.sqrt(k / m)
H = tf_at(tfs[0], 1j * w0)
Hh = Bl / ((Re_ + 1j * w0 * Le) * b + Bl ** 2)
close("loudspeaker: |v/U| at w0 [dB]", 20 * math.log10(abs(H)), 20 * math.log10(abs(Hh)), 1e-9)
close("loudspeaker: phase of v/U at w0 [deg]", math.degrees(cmath.phase(H)), math.degrees(cmath.phase(Hh)), 1e-9)
close("loudspeaker: DC gain of x [m/V]", tfs[1]["dc_gain"], Bl / (Re_ * k), 1e-12)


# coupled coils: det(L s + R), DC gains, the exact solution (Sylvester's formula)
def coils(R2):
    L1, L2, M, R1 = 1e-2, 4e-2, 1.6e-2, 1
    det = L1 * L2 - M * M
    A = [[-R1 * L2 / det, R2 * M / det], [R1 * M / det, -R2 * L1 / det]]  # -L^-1 R
    tr, dt_ = A[0][0] + A[1][1], A[0][0] * A[1][1] - A[0][1] * A[1][0]
    l1 = (tr + math.sqrt(tr * tr - 4 * dt_)) / 2
    l2 = (tr - math.sqrt(tr * tr - 4 * dt_)) / 2

    def i(t):  # i(0) = 0, i_inf = (1/R1, 0): i = i_inf - e^(At) i_inf
        e1, e2 = math.exp(l1 * t), math.exp(l2 * t)
        E = [[(e1 * (A[r][c] - l2 * (r == c)) - e2 * (A[r][c] - l1 * (r == c))) / (l1 - l2)
              for c in range(2)] for r in range(2)]
        return [1 / R1 - E[0][0] / R1, -E[1][0] / R1]
    return det, l1, l2, i


det, l1, l2, i = coils(2)
lin = linear("coupled_coils_linear.json")
want = [1, (1 * 4e-2 + 2 * 1e-2) / det, 2 / det]
for tf in lin["transfer_functions"]:
    for n, (got, w) in enumerate(zip(tf["den"], want)):
        close(f"coupled coils {tf['output']}: s^{2 - n} coefficient", got / tf["den"][0], w, 1e-9 * w)
close("coupled coils: DC gain of i1", lin["transfer_functions"][0]["dc_gain"], 1, 1e-9)
close("coupled coils: DC gain of i2", lin["transfer_functions"][1]["dc_gain"], 0, 1e-9)
close("coupled coils: slow pole", max(p["re"] for p in lin["poles"]), l1, 1e-6)
close("coupled coils: fast pole", min(p["re"] for p in lin["poles"]), l2, 1e-6)
for col in (1, 2):
    close(f"coupled coils: largest deviation of i{col} [A]", worst("coupled_coils.csv", col, lambda t: i(t)[col - 1]), 0, 1e-5)
i8 = coils(8)[3]
py = [[float(x) for x in line.split()] for line in open(f"{d}/coupled_python.txt")]
close("coupled coils, Python export: lines", len(py), 11, 0)
close("coupled coils, Python export with R2 = 8: largest deviation [A]",
      max(max(abs(r[1] - i8(r[0])[0]), abs(r[2] - i8(r[0])[1])) for r in py), 0, 1e-6)


# pendulum: T = 4 sqrt(J/(m g L)) K(sin(th0/2)), energy constant
def ellip_k(kk):
    a, b = 1.0, math.sqrt(1 - kk * kk)
    while abs(a - b) > 1e-15:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


J, g = 0.01 + 1, 9.81
T = 4 * math.sqrt(J / g) * ellip_k(math.sin(1))
r = rows("pendulum.csv")
cross = [a[0] + (b[0] - a[0]) * a[1] / (a[1] - b[1]) for a, b in zip(r, r[1:]) if a[1] > 0 >= b[1]]
close("pendulum: downward zero crossings", len(cross), 4, 0)
for n, (a, b) in enumerate(zip(cross, cross[1:])):
    close(f"pendulum: period {n + 1} [s]", b - a, T, 1e-5)
E0 = g * (1 - math.cos(2))
close("pendulum: largest energy deviation / E0", max(abs(J * x[2] ** 2 / 2 + g * (1 - math.cos(x[1])) - E0) for x in r) / E0, 0, 1e-5)

# heat conduction: poles -(2/(Rs Cs))(1 - cos(k pi/4)), the modal solution from 20 degC
a = 1 / (0.5 * 200)
lam = [-2 * a * (1 - math.cos(kk * math.pi / 4)) for kk in (1, 2, 3)]
got = sorted(p["re"] for p in linear("heat_rod_linear.json")["poles"])
for gp, w in zip(got, sorted(lam)):
    close("heat rod: pole", gp, w, 1e-12)
Tss, x0 = [80, 60, 40], [-60, -40, -20]
vec = [[math.sin(j * kk * math.pi / 4) for j in (1, 2, 3)] for kk in (1, 2, 3)]
c = [sum(x * v for x, v in zip(x0, vk)) / sum(v * v for v in vk) for vk in vec]
for j in range(3):
    close(f"heat rod: largest deviation of T{j + 1}",
          worst("heat_rod.csv", j + 1, lambda t: Tss[j] + sum(c[kk] * vec[kk][j] * math.exp(lam[kk] * t) for kk in range(3))), 0, 1e-4)


# enzyme: conservation, and the mass-action equations by RK4
def mass_action(y):
    S, E, C, P = y
    v1, v2 = 10 * S * E - 1 * C, 2 * C - 1e-3 * E * P
    return [-v1, -v1 + v2, v1 - v2, v2]


r = rows("enzyme.csv")
close("enzyme: largest deviation of S + ES + P from 1 mol", max(abs(x[1] + x[2] + x[3] - 1 - 2e-9) for x in r), 0, 1e-9)
y, h, ref = [1, 0.1, 1e-9, 1e-9], 1e-3, {0: [1, 0.1, 1e-9, 1e-9]}
for n in range(1, 10001):
    k1 = mass_action(y)
    k2 = mass_action([a + h / 2 * b for a, b in zip(y, k1)])
    k3 = mass_action([a + h / 2 * b for a, b in zip(y, k2)])
    k4 = mass_action([a + h * b for a, b in zip(y, k3)])
    y = [a + h / 6 * (p + 2 * q + 2 * s + u) for a, p, q, s, u in zip(y, k1, k2, k3, k4)]
    if n % 10 == 0:
        ref[n // 10] = y
close("enzyme: rows", len(r), 1001, 0)
close("enzyme: largest deviation from the mass-action equations [mol]",
      max(abs(x[col] - ref[round(x[0] * 100)][s]) for x in r for col, s in ((1, 0), (2, 2), (3, 3))), 0, 1e-6)
close("enzyme: E + ES of the reference", max(abs(v[1] + v[2] - 0.1 - 1e-9) for v in ref.values()), 0, 1e-12)

# hydraulic cylinder: travel Ps A / k, pressure Ps
last = rows("cylinder.csv")[-1]
close("cylinder: final travel [m]", last[1], 1e6 * 1e-3 / 1e5, 1e-8)
close("cylinder: final pressure [Pa]", last[2], 1e6, 1e-2)

# electrostatic actuator: k (x0 - x) x^2 = eps A V^2 / 2, its larger root; q = eps A V / x
epsA, V, x0, k = 8.854e-16, 5, 1e-5, 100
lo, hi = 2 * x0 / 3, x0  # k (x0 - x) x^2 falls from its maximum at 2 x0 / 3 to 0 at x0
for _ in range(200):
    mid = (lo + hi) / 2
    lo, hi = (mid, hi) if k * (x0 - mid) * mid * mid > epsA * V * V / 2 else (lo, mid)
last = rows("actuator.csv")[-1]
close("actuator: final gap [m]", last[1], lo, 1e-11)
close("actuator: final charge [C]", last[2], epsA * V / lo, 1e-15)

# loaded divider: vC = 5 (1 - e^(-t / 1 ms)); the parasitic store and the transformed model
close("divider: largest deviation from 5 (1 - e^(-t/1 ms)) [V]", worst("divider.csv", 1, lambda t: 5 * (1 - math.exp(-t / 1e-3))), 0, 1e-5)
close("divider, parasitic: largest deviation [V]", worst("divider_parasitic.csv", 1, lambda t: 5 * (1 - math.exp(-t / 1e-3))), 0, 5e-3)
text = open(f"{d}/divider_parasitic.bg").read()
close("divider, parasitic: Cp_mid_0 = 5e-09", int("param Cp_mid_0 = 5e-09 " in text), 1, 0)
close("divider, parasitic: the store at mid", int("bond 8 mid -> Cp_mid" in text), 1, 0)
check = open(f"{d}/divider_parasitic.check").read()
close("divider, parasitic: an explicit ODE without class 2 paths",
      int("form: ode" in check and "class 2: 0" in check and "states (2): Cp_mid.q, C1.q" in check), 1, 0)

# imported RLC: vC = 1 - e^(-2t)(cos 4t + sin 4t / 2), i = e^(-2t) sin 4t / 2
close("imported RLC: largest deviation of vC", worst("rlc_bgt.csv", 1, lambda t: 1 - math.exp(-2 * t) * (math.cos(4 * t) + math.sin(4 * t) / 2)), 0, 1e-5)
close("imported RLC: largest deviation of i", worst("rlc_bgt.csv", 2, lambda t: math.exp(-2 * t) * math.sin(4 * t) / 2), 0, 1e-5)

# thermometer: each run crosses 57.927 at Rf Cb ln(60 / 22.073); the mean of Rf Cb is 10 s
head, runs = table("thermometer_study.csv")
close("thermometer: runs", len(runs), 200, 0)
col = head.index("bulb.e:cross=57.927")
taus = [r[head.index("Rf")] * r[head.index("Cb")] for r in runs]
close("thermometer: largest deviation of a crossing from its Rf Cb ln(60/22.073) [s]",
      max(abs(r[col] - tau * math.log(60 / 22.073)) for r, tau in zip(runs, taus)), 0, 1e-4)
sd = 10 * math.sqrt(0.1 ** 2 + (0.1 / math.sqrt(12) / 0.5) ** 2)
close("thermometer: mean of Rf Cb against 10 s, in standard errors", (sum(taus) / len(taus) - 10) / (sd / math.sqrt(200)), 0, 3)

# building: omega_j = 2 sqrt(k/m) sin((2j - 1) pi / 18); energy kept once the ground stops
w = sorted(p["im"] for p in linear("building_linear.json")["poles"] if p["im"] > 0)
for j, got in enumerate(w, 1):
    close(f"building: mode {j} [rad/s]", got, 2 * math.sqrt(2e8 / 1e5) * math.sin((2 * j - 1) * math.pi / 18), 1e-9)
head, r = table("building_states.csv")
energy = [sum(x[head.index(f"S{s}.K.q")] ** 2 * 2e8 / 2 + x[head.index(f"S{s}.M.p")] ** 2 / 2e5 for s in (1, 2, 3, 4))
          for x in r if x[0] >= 0.2]
close("building: energy after the shake, largest deviation / its value", (max(energy) - min(energy)) / energy[0], 0, 1e-5)

# DC bus: ten loads in parallel, G = 0.5 S; v = 24 (1 - e^(-t/20 ms)), each load's current
# v/R at every row, one pole -G/C, the DC gain from the supply's current to the charge C/G
G, Cb, I0 = 2 / 10 + 4 / 20 + 4 / 40, 10e-3, 12
close("DC bus: largest deviation from 24 (1 - e^(-t/20 ms)) [V]",
      worst("dc_bus.csv", 1, lambda t: I0 / G * (1 - math.exp(-t * G / Cb))), 0, 1e-5)
for col, R in ((2, 10), (3, 20), (4, 40)):
    close(f"DC bus: largest deviation of a {R} ohm load's current from v/R [A]",
          max(abs(r[col] - r[1] / R) for r in rows("dc_bus.csv")), 0, 1e-12)
j = linear("dc_bus_linear.json")
close("DC bus: poles", len(j["poles"]), 1, 0)
close("DC bus: the pole -G/C [1/s]", j["poles"][0]["re"], -G / Cb, 1e-9)
close("DC bus: DC gain from the supply's current to the charge [C/A]", j["transfer_functions"][0]["dc_gain"], Cb / G, 1e-12)
sys.exit(1 if pn.failed else 0)
EOF
check "the gallery's numbers (above)" $?

# the plate: the steady state and three poles derived by hand on the page, the poles' sum
# (the trace), and every row against the modal solution of the conductance matrix (its
# eigenvectors by NumPy, Debian's python3 as in tests/ifield.sh)
/usr/bin/python3 - "$d" <<'EOF'
import json, math, sys
import numpy as np
sys.path.insert(0, "tests/lib")
import page_numbers as pn
from page_numbers import close
pn.D = d = sys.argv[1]
Rs, Cs, Ra, P = 0.5, 50.0, 2.0, 10.0
G = np.zeros((9, 9))
for r in range(3):
    for c in range(3):
        for rr, cc in ((r, c + 1), (r + 1, c)):
            if rr < 3 and cc < 3:
                a, b = 3 * r + c, 3 * rr + cc
                G[a, a] += 1 / Rs; G[b, b] += 1 / Rs; G[a, b] -= 1 / Rs; G[b, a] -= 1 / Rs
G[8, 8] += 1 / Ra
Tss = np.linalg.solve(G, np.eye(9)[0] * P)
for k, want in ((0, 27.5), (4, 23.75), (8, 20.0)):
    close(f"plate: steady temperature of cell {k // 3}{k % 3} [K]", Tss[k], want, 1e-12)
got = sorted(p["re"] for p in json.load(open(f"{d}/plate_linear.json"))["poles"])
close("plate: poles", len(got), 9, 0)
close("plate: sum of the poles = -trace(G)/Cs", sum(got), -0.97, 1e-12)
for i, j in ((0, 1), (0, 2), (1, 2)):
    want = -(4 - 2 * math.cos(i * math.pi / 3) - 2 * math.cos(j * math.pi / 3)) / (Rs * Cs)
    close(f"plate: the odd mode's pole ({i}, {j})", min(abs(g - want) for g in got), 0, 1e-12)
lam, V = np.linalg.eigh(-G / Cs)
for g, w in zip(got, sorted(lam)):
    close("plate: pole against the conductance matrix's", g, w, 1e-12)
coef = V.T @ Tss
for col, k in ((1, 0), (2, 4), (3, 8)):
    close(f"plate: largest deviation of T{k // 3}{k % 3} from the modal solution [K]",
          pn.worst("plate.csv", col, lambda t: Tss[k] - V[k] @ (coef * np.exp(lam * t))), 0, 1e-4)
sys.exit(1 if pn.failed else 0)
EOF
check "the plate's numbers (above)" $?

# the hydraulic cylinder's FMU, run by the suite's FMI importer (RK4) against bgdraw's run
python3 -c "import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])" "$d/cylinder.fmu" "$tmp/fmu"
guid=$(sed -n 's/.*guid="\([^"]*\)".*/\1/p' "$tmp/fmu/modelDescription.xml")
vrs=$(python3 -c '
import sys, xml.etree.ElementTree as ET
v = {s.get("name"): s.get("valueReference") for s in ET.parse(sys.argv[1]).iter("ScalarVariable")}
print(v["K.q"] + "," + v["oil.e"])' "$tmp/fmu/modelDescription.xml")
cc -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror tests/export/fmu_import.c -o "$tmp/fmu_import" -ldl &&
  "$tmp/fmu_import" "$tmp/fmu/binaries/linux64/cylinder.so" "$guid" 3 "$d/cylinder.csv" "$d/cylinder_fmu.csv" "$vrs" 2>"$tmp/fmu.err"
check "the cylinder's FMU runs in the test importer" $?
python3 - "$d" <<'EOF'
import sys
sys.path.insert(0, "tests/lib")
import page_numbers as pn
pn.D = sys.argv[1]
a, b = pn.rows("cylinder.csv"), pn.rows("cylinder_fmu.csv")
pn.close("cylinder FMU: rows", len(b), len(a), 0)
for col, name in ((1, "travel"), (2, "pressure")):
    span = max(r[col] for r in a) - min(r[col] for r in a)
    pn.close(f"cylinder FMU: largest deviation of the {name} / its range",
             max(abs(x[col] - y[col]) for x, y in zip(a, b)) / span, 0, 1e-5)
pn.close("cylinder FMU: final travel [m]", b[-1][1], 0.01, 1e-7)
sys.exit(1 if pn.failed else 0)
EOF
check "the cylinder's FMU against bgdraw and the hand answer (above)" $?
python3 tests/export/check_modelica.py "$d/heat_rod.mo" >/dev/null
check "heat_rod.mo is a balanced Modelica model (tests/export/check_modelica.py)" $?

# the property checks that apply to a hand-written model (tests/property/given.py), on
# every tutorial and gallery model (the YAML one as its --import text)
python3 tests/property/prop.py "$BGDRAW" $(for f in examples/tutorial/*.bg examples/gallery/*.bg; do
  printf -- '--file %s ' "$f"; done) --file "$d/rlc_bgt.bg" >"$tmp/prop.txt" 2>&1
st=$?
grep ': fail' "$tmp/prop.txt"
check "the property checks on the tutorial's and the gallery's models ($(grep -c ': pass$' "$tmp/prop.txt") passed)" $st

# every gallery model passes --check without a warning
for f in examples/gallery/*.bg; do
  "$BGDRAW" "$f" --check >/dev/null 2>"$tmp/err" && ! [ -s "$tmp/err" ]
  check "$f passes --check quietly" $?
done
finish
