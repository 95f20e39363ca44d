#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# State events in the exports (docs/export.md, "State events"; issue 29):
# four switching models, each exported to C, Python and an FMU and run
# elsewhere, against bgdraw's own run (its CSV and its JSON's event list):
# - tests/data/bouncing_ball.bg (a contact spring and damper: 2 root
#   functions, 12 switchings in 2 s), tests/data/half_wave.bg (a diode:
#   5 switchings in 3 periods), tests/data/thermostat.bg (hyst(): 12
#   switchings), tests/data/stick_slip.bg (stick() and sign(): 7 instants),
#   tests/data/switch_kinds.bg (every kind of switching instruction in one
#   law, 18 root functions: 26 instants);
# - C: tests/export/events_driver.c drives the export with CVODE's root
#   finding on ev_roots, ev_event at each root, CVodeReInit; and a DAE
#   (tests/data/half_wave_dae.bg, a series resistor) with IDA;
# - Python: the module's simulate() (solve_ivp events, restart per event);
# - FMU: tests/export/fmu_import.c as an FMI master (event indicators,
#   bisection of the step, event mode, fmi2NewDiscreteStates);
# each: the same switchings (root, direction, order; the last two: the same
# instants, as bgdraw also logs modes that change without a root) within
# 2e-7 s, every row within 1e-6 of its column's range (rows within 1e-6 s of
# a switching skipped: the two sides of a jump).
# Also: numberOfEventIndicators, the header's interface; the bouncing ball in
# Octave (it warns: no events; ode15s within 1e-6 at RelTol 1e-10) and in
# Modelica (a balanced model); memory refused by Octave and Modelica.
# Usage: bash tests/export_events.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: export_events.sh PATH_TO_BGDRAW}
. tests/export/harness.sh
cmp_ev() { /usr/bin/python3 tests/export/compare_events.py "$@"; }
cc -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror tests/export/fmu_import.c -o "$tmp/import" -ldl -lm
check "the test importer compiles" $?

for mdl in bouncing_ball half_wave thermostat stick_slip switch_kinds; do
  how=""; [ $mdl = stick_slip ] || [ $mdl = switch_kinds ] && how=instants
  "$BGDRAW" tests/data/$mdl.bg -q --simulate -o "$tmp/$mdl.csv" -o "$tmp/$mdl.json"; check "$mdl: bgdraw simulates" $?
  # C with CVODE
  mkdir -p "$tmp/c_$mdl"
  "$BGDRAW" tests/data/$mdl.bg -q --prefix ev -o "$tmp/c_$mdl/ev.c"; check "$mdl: -o ev.c" $?
  cc -std=c11 -Wall -Wextra -Werror -I"$tmp/c_$mdl" tests/export/events_driver.c "$tmp/c_$mdl/ev.c" -o "$tmp/c_$mdl/drv" \
    -lsundials_ida -lsundials_cvode -lsundials_nvecserial -lsundials_sunmatrixdense -lsundials_sunlinsoldense -lm
  check "$mdl: the C export compiles with the CVODE driver (-Wall -Wextra -Werror)" $?
  "$tmp/c_$mdl/drv" "$tmp/$mdl.csv" "$tmp/c_$mdl.csv" "$tmp/c_$mdl.ev" 2>/dev/null; check "$mdl: C + CVODE runs" $?
  cmp_ev "$tmp/$mdl.csv" "$tmp/$mdl.json" "$tmp/c_$mdl.csv" "$tmp/c_$mdl.ev" 1e-6 2e-7 1e-6 "$mdl C + CVODE" $how
  check "$mdl: C + CVODE against bgdraw" $?
  # Python with solve_ivp
  "$BGDRAW" tests/data/$mdl.bg -q -o "$tmp/${mdl}_m.py"; check "$mdl: -o ${mdl}_m.py" $?
  /usr/bin/python3 - "$tmp" "${mdl}_m" "$tmp/$mdl.csv" "$tmp/py_$mdl.csv" "$tmp/py_$mdl.ev" <<'PY'
import importlib, sys
sys.path.insert(0, sys.argv[1])
m = importlib.import_module(sys.argv[2])
lines = [l for l in open(sys.argv[3]) if l.strip()]
times = [float(l.split(",")[0]) for l in lines[1:]]
ev = []
t, y, out = m.simulate(t_eval=times, rtol=1e-11, atol=1e-13, events=ev)
assert len(t) == len(times), (len(t), len(times))
with open(sys.argv[4], "w") as f:
    f.write(lines[0])
    for k in range(len(t)):
        f.write(",".join(["%.17g" % times[k]] + ["%.17g" % out[j][k] for j in range(len(m.OUTPUTS))]) + "\n")
with open(sys.argv[5], "w") as f:
    for te, i, d in ev:
        f.write("%.17g %d %d\n" % (te, i, d))
PY
  check "$mdl: Python simulate() runs" $?
  cmp_ev "$tmp/$mdl.csv" "$tmp/$mdl.json" "$tmp/py_$mdl.csv" "$tmp/py_$mdl.ev" 1e-6 2e-7 1e-6 "$mdl Python + solve_ivp" $how
  check "$mdl: Python + solve_ivp against bgdraw" $?
  # FMU through the test importer
  mkdir -p "$tmp/f_$mdl"
  "$BGDRAW" tests/data/$mdl.bg -q -o "$tmp/f_$mdl/$mdl.fmu"; check "$mdl: -o $mdl.fmu" $?
  (cd "$tmp/f_$mdl" && python3 -c "import zipfile, sys; zipfile.ZipFile(sys.argv[1]).extractall('.')" $mdl.fmu)
  md="$tmp/f_$mdl/modelDescription.xml"
  guid=$(xmllint --xpath 'string(/fmiModelDescription/@guid)' "$md")
  nz=$(xmllint --xpath 'string(/fmiModelDescription/@numberOfEventIndicators)' "$md")
  nx=$(xmllint --xpath 'count(//ScalarVariable[Real/@derivative])' "$md")
  vrs=$(xmllint --xpath '//ScalarVariable[@causality="output"]/@valueReference' "$md" | grep -o '[0-9]*' | paste -sd,)
  want=$(grep -c '' <(python3 -c "import json,sys; [print(c) for c in json.load(open(sys.argv[1]))['simulation']['events']['conditions']]" "$tmp/$mdl.json"))
  [ "$nz" = "$want" ]; check "$mdl: numberOfEventIndicators $nz = bgdraw's root functions ($want)" $?
  "$tmp/import" "$tmp/f_$mdl/binaries/linux64/$mdl.so" "$guid" "$nx" "$tmp/$mdl.csv" "$tmp/fmu_$mdl.csv" "$vrs" \
    nz="$nz" events="$tmp/fmu_$mdl.ev" 2>/dev/null
  check "$mdl: the importer runs the FMU with its event indicators" $?
  cmp_ev "$tmp/$mdl.csv" "$tmp/$mdl.json" "$tmp/fmu_$mdl.csv" "$tmp/fmu_$mdl.ev" 1e-6 2e-7 1e-6 "$mdl FMU + RK4 master" $how
  check "$mdl: FMU against bgdraw" $?
done

# a DAE: the rectifier with a series resistor, its C export with IDA (root
# finding, the event function, IDACalcIC after each event until the modes
# agree); Python's simulate() refuses it, the FMU (ODE only) too
mdl=half_wave_dae
"$BGDRAW" tests/data/$mdl.bg -q --simulate -o "$tmp/$mdl.csv" -o "$tmp/$mdl.json"; check "$mdl: bgdraw simulates" $?
mkdir -p "$tmp/c_$mdl"
"$BGDRAW" tests/data/$mdl.bg -q --prefix ev -o "$tmp/c_$mdl/ev.c" && grep -q '#define EV_IS_ODE 0' "$tmp/c_$mdl/ev.h"
check "$mdl: -o ev.c, a DAE" $?
cc -std=c11 -Wall -Wextra -Werror -I"$tmp/c_$mdl" tests/export/events_driver.c "$tmp/c_$mdl/ev.c" -o "$tmp/c_$mdl/drv" \
  -lsundials_ida -lsundials_cvode -lsundials_nvecserial -lsundials_sunmatrixdense -lsundials_sunlinsoldense -lm
check "$mdl: the C export compiles with the IDA driver" $?
"$tmp/c_$mdl/drv" "$tmp/$mdl.csv" "$tmp/c_$mdl.csv" "$tmp/c_$mdl.ev" 2>/dev/null; check "$mdl: C + IDA runs" $?
cmp_ev "$tmp/$mdl.csv" "$tmp/$mdl.json" "$tmp/c_$mdl.csv" "$tmp/c_$mdl.ev" 1e-6 2e-7 1e-6 "$mdl C + IDA"
check "$mdl: C + IDA against bgdraw" $?
"$BGDRAW" tests/data/$mdl.bg -q -o "$tmp/${mdl}_m.py"
/usr/bin/python3 -c "import sys; sys.path.insert(0, sys.argv[1]); import ${mdl}_m as m; m.simulate()" "$tmp" 2>"$tmp/err"
[ $? -ne 0 ] && grep -q "NotImplementedError: switching conditions in a DAE" "$tmp/err"
check "$mdl: Python's simulate() refuses a switching DAE, saying what to use" $?
# the header says it: the modes, the roots, the event function
h="$tmp/c_bouncing_ball/ev.h"
grep -q '#define EV_NROOT 2' "$h" && grep -q '#define EV_NMODE 2' "$h" && grep -q 'int ev_event(' "$h" &&
  grep -q 'int ev_roots(const ev_params \*p, const ev_modes \*md' "$h" && grep -q 'void ev_modes_start(' "$h" &&
  grep -q 'int ev_rhs(const ev_params \*p, const ev_modes \*md, double t' "$h"
check "the header declares the modes, ev_roots, ev_event, ev_modes_start and rhs under the modes" $?
grep -q '"law of K: K.q < 0"' "$tmp/c_bouncing_ball/ev.c"; check "ev_root_names say each condition" $?
# a model without switching conditions keeps its interface (and no events in the FMU)
"$BGDRAW" examples/rlc.bg -q --prefix r -o "$tmp/r.c"; ! grep -q 'NROOT\|_modes' "$tmp/r.h"
check "rlc's header has no modes" $?
# Octave has no event handling: a warning; ode15s at RelTol 1e-10 still comes
# within 1e-6 of the range on the bouncing ball (its step control; measured 5.2e-8)
"$BGDRAW" tests/data/bouncing_ball.bg -q -o "$tmp/bb_fn.m" 2>/dev/null
(cd "$tmp" && octave-cli --no-gui --norc --quiet --eval "
  m = bb_fn(); d = dlmread('bouncing_ball.csv', ',', 1, 0); y0 = m.initial(m.params, m.t0);
  opt = odeset('Mass', m.mass, 'RelTol', 1e-10, 'AbsTol', 1e-14, 'InitialSlope', m.slope(m.params, m.t0, y0));
  [t, y] = ode15s(@(t, y) m.f(t, y, m.params), d(:, 1)', y0, opt);
  f = fopen('oct_bb.csv', 'w'); fprintf(f, '%s', 't'); fprintf(f, ',%s', m.outputs{:}); fprintf(f, '\n');
  for k = 1:numel(t)
    o = m.output(t(k), y(k, :)', m.params);
    fprintf(f, '%.17g', t(k)); fprintf(f, ',%.17g', o); fprintf(f, '\n');
  end
  fclose(f);" >/dev/null 2>&1)
cmp_csv "$tmp/bouncing_ball.csv" "$tmp/oct_bb.csv" 1e-6 "Octave ode15s vs bgdraw (bouncing ball, no events)"
check "bouncing ball: the Octave export with ode15s" $?
# Modelica (no tool in Debian 12): the bouncing ball's file is a balanced model
"$BGDRAW" tests/data/bouncing_ball.bg -q -o "$tmp/bb.mo" && python3 tests/export/check_modelica.py "$tmp/bb.mo" >/dev/null &&
  grep -q 'if (K_q) < (0) then' "$tmp/bb.mo"
check "bouncing ball: the Modelica export is a balanced model with its if-expressions" $?
# memory is refused by Octave and Modelica
"$BGDRAW" tests/data/bouncing_ball.bg -o "$tmp/bb.m" 2>"$tmp/err"; st=$?
[ $st -eq 0 ] && grep -q "warning: .*no event handling: ode15s steps over the model's 2 switching conditions" "$tmp/err"
check "Octave export of a switching model warns (status $st)" $?
for ext in m mo; do
  "$BGDRAW" tests/data/thermostat.bg -o "$tmp/t.$ext" 2>"$tmp/err"; st=$?
  [ $st -eq 3 ] && grep -q "discrete state (value of heater: hyst(" "$tmp/err" && [ ! -e "$tmp/t.$ext" ]
  check "thermostat .$ext refused (status $st)" $?
done
[ $fail -eq 0 ] && echo "all export event checks passed"
exit $((fail > 0))
