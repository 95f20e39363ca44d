#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# I fields (docs/format.md, "Multiport fields"; issue 29): coupled coils
# (tests/data/coupled_coils.bg) written three ways, the inertance matrix
# L = [L1, M; M, L2], the co-energy's dual W(p) = p' L^-1 p / 2 and laws
# per port with L^-1 written out, each against the closed form: with
# p = L i, p' = b - R L^-1 p, so p(t) = A^-1 (expm(A t) - I) b, A = -R L^-1
# (SciPy's expm); every row of both currents within 2e-6 of their range and
# within --verify's error bound (the coupling 0.75 makes L^-1 ill-conditioned:
# the secondary's small current is the difference of large momenta).
# Then a port in derivative causality: the secondary driven by a current
# source i2 = I0 sin(w t), so its momentum is a dependent store and the
# primary's current solves L1 i1' = U - R1 i1 - M i2' (against SciPy at
# rtol 1e-12). Malformed fields are in tests/bad/ifield_*.bg.
# Usage: bash tests/ifield.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
judge() { # KIND CSV
  /usr/bin/python3 - "$@" <<'PY'
import csv, math, sys
import numpy as np
from scipy.linalg import expm
from scipy.integrate import solve_ivp
kind, rows = sys.argv[1], np.array([[float(x) for x in r] for r in list(csv.reader(open(sys.argv[2])))[1:]])
U, R1, R2, L1, L2, M = 1.0, 2.0, 5.0, 1e-2, 4e-2, 1.5e-2
L = np.array([[L1, M], [M, L2]])
G = np.linalg.inv(L)
if kind == "driven":
    I0, w = 0.5, 2 * math.pi * 50
    sol = solve_ivp(lambda t, y: [(U - R1 * y[0] - M * I0 * w * math.cos(w * t)) / L1], (0, rows[-1, 0]),
                    [0.0], method="DOP853", rtol=1e-12, atol=1e-14, dense_output=True)
    exact = np.array([[sol.sol(t)[0], I0 * math.sin(w * t)] for t in rows[:, 0]])
else:
    A, b = -np.diag([R1, R2]) @ G, np.array([U, 0.0])
    exact = np.array([G @ (np.linalg.solve(A, (expm(A * t) - np.eye(2)) @ b)) for t in rows[:, 0]])
got = rows[:, 1:3]
err = [np.max(np.abs(got[:, j] - exact[:, j])) / np.ptp(exact[:, j]) for j in range(2)]
print("%s: %d rows, largest error over the range: i1 %.2g, i2 %.2g" % (kind, len(rows), err[0], err[1]))
bound = float(sys.argv[3]) if len(sys.argv) > 3 else math.inf
print("  --verify's bound %.2g" % bound)
sys.exit(not (max(err) < 2e-6 and max(err) <= bound))
PY
}
bound() { # JSON: --verify's error bound
  python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["simulation"]["verify"]["bound"])' "$1"
}
src=$root/tests/data/coupled_coils.bg
law() { # NAME LAW: the model with the field's law replaced
  sed "s|^I K(prim, sec) : .*$|I K(prim, sec) : $2|" "$src" >"$tmp/$1.bg"
}
cp "$src" "$tmp/matrix.bg"
law energy 'energy = (L2o*prim.p^2 - 2*Mo*prim.p*sec.p + L1o*sec.p^2)/(2*(L1o*L2o - Mo^2))'
law laws 'f1 = (L2o*p1 - Mo*p2)/(L1o*L2o - Mo^2), f2 = (L1o*p2 - Mo*p1)/(L1o*L2o - Mo^2)'
for v in matrix energy laws; do
  "$BGDRAW" "$tmp/$v.bg" --verify -q -o "$tmp/$v.csv" -o "$tmp/$v.json"; check "$v: exit 0" $?
  judge field "$tmp/$v.csv" "$(bound "$tmp/$v.json")"; check "$v: the currents against expm, within --verify's bound" $?
done
# the three forms compile to the same flows (the equations agree at every row)
python3 - "$tmp/matrix.csv" "$tmp/energy.csv" "$tmp/laws.csv" <<'PY'
import csv, sys
t = [[list(map(float, r)) for r in list(csv.reader(open(f)))[1:]] for f in sys.argv[1:]]
d = max(abs(a - b) for x in t[1:] for ra, rb in zip(t[0], x) for a, b in zip(ra, rb))
sys.exit(not d < 1e-9)
PY
check "matrix, energy and laws agree to 1e-9" $?
# the secondary driven by a current source: a port in derivative causality
sed -e 's/, R2o = 5//' -e 's|^R R2 = R2o$|Sf I2 = 0.5*sin(2*pi*50*t)|' -e 's|^bond j2 -> R2$|bond I2 -> j2|' \
  -e 's|^bond K.sec -> j2$|bond j2 -> K.sec|' "$src" >"$tmp/driven.bg"
"$BGDRAW" "$tmp/driven.bg" --simulate -o "$tmp/driven.csv" 2>"$tmp/err"; cs_=$?; check "driven: exit 0 ($(head -c 300 "$tmp/err"))" $cs_
judge driven "$tmp/driven.csv"; check "driven: the primary's current against SciPy" $?
"$BGDRAW" "$tmp/driven.bg" --check >"$tmp/check.txt"
grep -q "K.sec" "$tmp/check.txt" && grep -qi "dependent" "$tmp/check.txt"; check "driven: K.sec is a dependent store" $?
finish
