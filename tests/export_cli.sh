#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Model exports (docs/export.md) from the command line, each run by the tool
# it is for and compared with bgdraw's own simulation:
# - -o NAME.c writes NAME.c and NAME.h; two exported models (an ODE and a DAE,
#   prefixes ode and dae) link into one program that integrates them with
#   CVODE and IDA and matches bgdraw's CSVs to 1e-6 of each column's range,
#   also with a param changed in the record (against --set);
# - --equations c is one translation unit that compiles;
# - the Python module's simulate() (SciPy) and the Octave function file
#   (ode15s with the mass matrix) match bgdraw's CSVs to 1e-6;
# - every example's Modelica file is a balanced model (tests/export/check_modelica.py),
#   rlc's equations are the ones derived by hand;
# - a --prefix that is not a C identifier is a usage error (exit 2).
# Usage: bash tests/export_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: export_cli.sh PATH_TO_BGDRAW}
. tests/export/harness.sh
sed 's/^simulate .*/&, rtol = 1e-10/' examples/hydraulic_bridge.bg >"$tmp/hb.bg"
"$BGDRAW" "$tmp/rlc.bg" -q --simulate -o "$tmp/rlc.csv"; check "rlc simulates" $?
"$BGDRAW" "$tmp/rlc.bg" -q --simulate --set R0=25 -o "$tmp/rlc_r25.csv"; check "rlc --set R0=25 simulates" $?
"$BGDRAW" "$tmp/hb.bg" -q --simulate -o "$tmp/hb.csv"; check "hydraulic_bridge simulates" $?

# C: two models in one program
"$BGDRAW" "$tmp/rlc.bg" -q --prefix ode -o "$tmp/ode.c"; check "-o ode.c exit 0" $?
"$BGDRAW" "$tmp/hb.bg" -q --prefix dae -o "$tmp/dae.c"; check "-o dae.c exit 0" $?
[ -s "$tmp/ode.h" ] && [ -s "$tmp/dae.h" ]; check "headers written beside the sources" $?
grep -q 'typedef struct ode_params' "$tmp/ode.h"; check "parameter record named by the prefix" $?
cc -std=c11 -Wall -Wextra -Werror -I"$tmp" tests/export/driver.c "$tmp/ode.c" "$tmp/dae.c" -o "$tmp/driver" \
  -lsundials_ida -lsundials_cvode -lsundials_nvecserial -lsundials_sunmatrixdense -lsundials_sunlinsoldense -lm
check "two exported models link into one program" $?
"$tmp/driver" "$tmp/rlc.csv" "$tmp/hb.csv" "$tmp/d_ode.csv" "$tmp/d_dae.csv"; check "driver runs CVODE and IDA" $?
cmp_csv "$tmp/rlc.csv" "$tmp/d_ode.csv" 1e-6 "C + CVODE vs bgdraw (rlc)"; check "C export of rlc matches" $?
cmp_csv "$tmp/hb.csv" "$tmp/d_dae.csv" 1e-6 "C + IDA vs bgdraw (hydraulic_bridge)"; check "C export of hydraulic_bridge matches" $?
"$tmp/driver" "$tmp/rlc_r25.csv" "$tmp/hb.csv" "$tmp/d_r25.csv" "$tmp/d_dae2.csv" R0=25; check "driver with R0=25" $?
cmp_csv "$tmp/rlc_r25.csv" "$tmp/d_r25.csv" 1e-6 "C with R0 = 25 vs --set R0=25"; check "a param changed at run time" $?
! cmp -s "$tmp/d_ode.csv" "$tmp/d_r25.csv"; check "the changed param changes the response" $?

# --equations c: one translation unit
"$BGDRAW" examples/slider_crank.bg -q --equations c >"$tmp/one.c"; check "--equations c exit 0" $?
cc -std=c11 -Wall -Wextra -Werror -c "$tmp/one.c" -o "$tmp/one.o"; check "--equations c compiles alone" $?

# a bad prefix
"$BGDRAW" examples/rlc.bg -q --prefix 9lives -o "$tmp/bad.c" 2>"$tmp/err"; st=$?
[ "$st" = 2 ] && grep -q "not a C identifier" "$tmp/err" && [ ! -e "$tmp/bad.c" ]; check "--prefix 9lives: exit 2, nothing written" $?

# Python with SciPy (Debian's python3-scipy, installed by tools/deps.sh)
PY=/usr/bin/python3
"$BGDRAW" "$tmp/rlc.bg" -q -o "$tmp/rlc_model.py"; check "-o rlc_model.py exit 0" $?
"$BGDRAW" "$tmp/hb.bg" -q -o "$tmp/hb_model.py"; check "-o hb_model.py exit 0" $?
cat >"$tmp/run_py.py" <<'PY'
import importlib, sys
sys.path.insert(0, sys.argv[1])
mod = importlib.import_module(sys.argv[2])
p = dict(mod.PARAMS)
for kv in sys.argv[5:]:
    k, v = kv.split("=")
    p[k] = float(v)
times = [float(l.split(",")[0]) for l in open(sys.argv[4]).readlines()[1:] if not l.startswith("#")]
t, y, out = mod.simulate(p=p, t_eval=times, rtol=1e-11, atol=1e-14)
with open(sys.argv[3], "w") as f:
    f.write(",".join(["t"] + mod.OUTPUTS) + "\n")
    for k in range(len(t)):
        f.write(",".join(repr(float(x)) for x in [t[k]] + list(out[:, k])) + "\n")
PY
$PY "$tmp/run_py.py" "$tmp" rlc_model "$tmp/py_rlc.csv" "$tmp/rlc.csv"; check "Python module simulates rlc" $?
cmp_csv "$tmp/rlc.csv" "$tmp/py_rlc.csv" 1e-6 "Python vs bgdraw (rlc)"; check "Python export of rlc matches" $?
$PY "$tmp/run_py.py" "$tmp" rlc_model "$tmp/py_r25.csv" "$tmp/rlc_r25.csv" R0=25; check "Python with R0=25" $?
cmp_csv "$tmp/rlc_r25.csv" "$tmp/py_r25.csv" 1e-6 "Python R0 = 25 vs --set"; check "Python params dict" $?
$PY "$tmp/run_py.py" "$tmp" hb_model "$tmp/py_hb.csv" "$tmp/hb.csv" 2>"$tmp/py_hb.err"; check "Python module simulates hydraulic_bridge (DAE)" $?
# fsolve stopping at round-off is judged by the module, not left as a warning
[ ! -s "$tmp/py_hb.err" ]; cs_=$?; check "hydraulic_bridge in Python: nothing on stderr ($(head -c 200 "$tmp/py_hb.err"))" $cs_
printf 'import sys; sys.path.insert(0, sys.argv[1]); import hb_model as m\nimport numpy as np\nprint(m._round_off(lambda z: [z[0] - 2.0], np.array([2.0])), m._round_off(lambda z: [z[0]**2 + 1], np.array([0.0])))\n' >"$tmp/ro.py"
[ "$($PY "$tmp/ro.py" "$tmp")" = "True False" ]; check "Python _round_off: a solved point accepted, a point with no root (z^2 + 1) refused" $?
cmp_csv "$tmp/hb.csv" "$tmp/py_hb.csv" 1e-6 "Python vs bgdraw (hydraulic_bridge)"; check "Python export of the DAE matches" $?
# mass action (log in the laws): the module evaluates its tape with every unknown 0
# (initial(), the consistent start), where Python's math.log raises and C gives -inf
cp examples/gallery/reaction.bg "$tmp/reaction.bg"
"$BGDRAW" "$tmp/reaction.bg" -q --simulate -o "$tmp/reaction.csv"; check "reaction simulates" $?
"$BGDRAW" "$tmp/reaction.bg" -q -o "$tmp/reaction_model.py"; check "-o reaction_model.py exit 0" $?
$PY "$tmp/run_py.py" "$tmp" reaction_model "$tmp/py_reaction.csv" "$tmp/reaction.csv"; check "Python module of a model with log() simulates" $?
cmp_csv "$tmp/reaction.csv" "$tmp/py_reaction.csv" 1e-6 "Python vs bgdraw (reaction)"; check "Python export of reaction matches" $?
# no states, every initial value an integer literal (property campaign seed 8665): initial()
# gave an int array, so the algebraic unknown was truncated to 0 at every row
printf '%s\n' 'model alg' '1 j1' 'R R1 : f = 1.79*e' 'Sf F1 = 1.64*sin(1.62*t)' 'MSe MU1 = 1.96*cos(t)' \
  'bond 1 MU1 -> j1' 'bond 2 F1 -> j1' 'bond 3 j1 -> R1' 'simulate t_end = 3, dt = 0.075' 'plot e3, f3' >"$tmp/alg.bg"
"$BGDRAW" "$tmp/alg.bg" -q --simulate -o "$tmp/alg.csv" && "$BGDRAW" "$tmp/alg.bg" -q -o "$tmp/alg_model.py"
check "the model without states simulates and exports" $?
$PY "$tmp/run_py.py" "$tmp" alg_model "$tmp/py_alg.csv" "$tmp/alg.csv"; check "Python module of the model without states simulates" $?
awk -F, 'NR > 1 { d = $2 - 1.64 * sin(1.62 * $1) / 1.79; if (d < 0) d = -d; if (d > 1e-9) bad++ } END { exit bad > 0 }' "$tmp/py_alg.csv"
check "Python export without states: e3 = 1.64 sin(1.62 t)/1.79 at every row" $?
printf '%s\n' 'import sys; sys.path.insert(0, sys.argv[1]); import reaction_model as m' \
  'print(m._div(1.0, 0.0), m._div(-1.0, 0.0), m._div(0.0, 0.0), m._div(1.0, -0.0), m._log(0.0), m._log(-1.0), m._log10(0.0),' \
  '      m._sqrt(-1.0), m._asin(2.0), m._acos(-2.0), m._exp(1e4), m._sinh(-1e4), m._cosh(-1e4), m._pow(0.0, -1.0),' \
  '      m._pow(-2.0, 2001.0), m._pow(2.0, 5000.0), m._pow(-8.0, 1 / 3), m._floor(float("nan")), m._ceil(2.5))' >"$tmp/cdom.py"
got=$($PY "$tmp/cdom.py" "$tmp")
[ "$got" = "inf -inf nan -inf -inf nan -inf nan nan nan inf -inf inf inf -inf inf nan nan 3.0" ]; cs_=$?
check "Python helpers give C's values outside the domain ($got)" $cs_

# Octave (Debian's octave, installed by tools/deps.sh)
"$BGDRAW" "$tmp/rlc.bg" -q -o "$tmp/rlc_fn.m"; check "-o rlc_fn.m exit 0" $?
"$BGDRAW" "$tmp/hb.bg" -q -o "$tmp/hb_fn.m"; check "-o hb_fn.m exit 0" $?
oct_run() { # oct_run FN OUT.csv BGDRAW.csv: at the times of bgdraw's CSV
  (cd "$tmp" && octave-cli --no-gui --norc --quiet --eval "
    m = $1(); d = dlmread('$3', ',', 1, 0); y0 = m.initial(m.params, m.t0);
    opt = odeset('Mass', m.mass, 'RelTol', 1e-10, 'AbsTol', 1e-14, 'InitialSlope', m.slope(m.params, m.t0, y0));
    [t, y] = ode15s(@(t, y) m.f(t, y, m.params), d(:, 1)', y0, opt);
    f = fopen('$2', 'w'); fprintf(f, '%s', 't'); fprintf(f, ',%s', m.outputs{:}); fprintf(f, '\n');
    for k = 1:numel(t)
      o = m.output(t(k), y(k, :)', m.params);
      fprintf(f, '%.17g', t(k)); fprintf(f, ',%.17g', o); fprintf(f, '\n');
    end
    fclose(f);" >/dev/null 2>"$tmp/oct.err")
  [ -s "$tmp/$2" ]
}
oct_run rlc_fn oct_rlc.csv rlc.csv; check "Octave ode15s runs the rlc export" $?
cmp_csv "$tmp/rlc.csv" "$tmp/oct_rlc.csv" 1e-6 "Octave vs bgdraw (rlc)"; check "Octave export of rlc matches" $?
oct_run hb_fn oct_hb.csv hb.csv; check "Octave ode15s runs the hydraulic_bridge export (mass matrix)" $?
cmp_csv "$tmp/hb.csv" "$tmp/oct_hb.csv" 1e-6 "Octave vs bgdraw (hydraulic_bridge)"; check "Octave export of the DAE matches" $?

# Modelica: no Modelica tool is packaged in Debian 12, so each file is checked field
# by field: balanced, every identifier declared, der() only of states (check_modelica.py)
for f in examples/*.bg; do
  b=$(basename "$f" .bg)
  # (what went wrong kept for the message: these failed once under load, from
  # hydraulic_bridge on, and passed alone; the log said nothing more)
  why=$("$BGDRAW" "$f" -q -o "$tmp/$b.mo" 2>&1 && python3 tests/export/check_modelica.py "$tmp/$b.mo" 2>&1); cs_=$?
  check "Modelica export of $b is a balanced model ($cs_: $(printf '%s' "$why" | head -c 300))" $cs_
done
mo="$tmp/rlc.mo"
grep -qx '  parameter Real R0 = 10;' "$mo" && grep -qx '  Real C1_q(start = 0, fixed = true);' "$mo" &&
  grep -qx '  L1_e = (U_e - R1_e - C1_e); // balance of j' "$mo" && grep -qx '  R1_e = (R0)\*(R1_f); // value of R1' "$mo" &&
  grep -qx '  der(L1_p) = L1_e;' "$mo" && grep -qx '  der(C1_q) = C1_f;' "$mo" &&
  grep -q 'annotation(experiment(StartTime = 0, StopTime = 0.002, Interval = 1e-06));' "$mo"
check "rlc.mo: parameters, states with start values, the junction balance, der() rows" $?
printf 'model k2\nparam der = 2, initial = 3\nSe U = der*table(t, [0, 0; 1, 2])\n1 j\nR R1 = initial\nC C1 = 1 [q0 = der]\nbond U -> j\nbond j -> R1\nbond j -> C1\n' >"$tmp/k2.bg"
"$BGDRAW" "$tmp/k2.bg" -q -o "$tmp/k2.mo" && python3 tests/export/check_modelica.py "$tmp/k2.mo" >/dev/null &&
  grep -qx '  parameter Real der_ = 2 "bgdraw param der";' "$tmp/k2.mo" && grep -q 'bg_table(time, tab1_x, tab1_y)' "$tmp/k2.mo" &&
  grep -qx '  parameter Real tab1_y\[2\] = {0, 2};' "$tmp/k2.mo"
check "Modelica keywords renamed (der_), tables as parameter arrays and a function" $?

echo "export_cli: $fail failures"
[ "$fail" -eq 0 ]
