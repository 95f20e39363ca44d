#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# MTT import (issue 35, docs/import.md "MTT"): each model folder of
# tests/data/import/mtt_*/ (drawn for these tests: an RLC behind a
# transformer with a step input; amplifiers, a gyrator and detectors; a
# subsystem used twice with a coerced port direction and an EMTF) against the
# same model written by hand in .bg (--check, the simulation byte for byte)
# and against its hand-derived trajectory (the label files' #DESCRIPTION);
# the reading of strokes, port directions and labels; the ambiguity warning;
# errors at the drawing's lines and coordinates and at the label and
# parameter files' lines.
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
d=tests/data/import

for m in mtt_rlc mtt_amps mtt_chain; do
  "$BGDRAW" --import $d/$m -T bg >"$tmp/$m.bg" 2>"$tmp/err"
  [ $? = 0 ] && [ ! -s "$tmp/err" ] && head -1 "$tmp/$m.bg" | grep -q "^# $m, imported from ${m}_abg.fig (MTT xfig drawing)"
  check "$m: imported without a warning, the header names the drawing" $?
  "$BGDRAW" --import $d/$m/ -T bg | cmp -s - "$tmp/$m.bg" &&
    "$BGDRAW" --import $d/$m/${m}_abg.fig -T bg | cmp -s - "$tmp/$m.bg"
  check "$m: the folder, the folder/ and the drawing give the same model" $?
  "$BGDRAW" $d/$m --check >"$tmp/a" && "$BGDRAW" $d/$m.bg --check >"$tmp/b"
  cmp -s "$tmp/a" "$tmp/b"; check "$m: --check equals the hand-written model's" $?
  "$BGDRAW" $d/$m -T json >"$tmp/a.json" && "$BGDRAW" $d/$m.bg -T json >"$tmp/b.json" &&
    python3 - "$tmp/a.json" "$tmp/b.json" <<'PY'
import json, sys
def view(d):  # the causal analysis: strokes and why, paths, loops, states, index
    return ([(b["id"], b["from"], b["to"], b["stroke"], b["reason"], b["conflict"]) for b in d["bonds"]],
            d["causal_paths"], d["causal_loops"], d["conflicts"], d["states"], d["dependent_stores"],
            [(t["bonds"], t["gain_value"], t["algebraic"]) for t in d["topological_loops"]],
            d.get("detectors"), d["form"], d["index"])
a, b = (view(json.load(open(f))) for f in sys.argv[1:3])
sys.exit(a != b)
PY
  check "$m: the causal analysis (strokes, paths, loops, states) equals the hand-written model's" $?
  "$BGDRAW" $d/$m -o "$tmp/$m.csv" && "$BGDRAW" $d/$m.bg -o "$tmp/b.csv"
  cmp -s "$tmp/$m.csv" "$tmp/b.csv"; check "$m: simulation equals the hand-written model's" $?
  "$BGDRAW" "$tmp/$m.bg" -o "$tmp/c.csv" && cmp -s "$tmp/$m.csv" "$tmp/c.csv"
  check "$m: the --import text simulates the same" $?
done

# what the drawings say, read right: strokes, coerced port directions, sides
grep -q '^bond u ->| mtt1$' "$tmp/mtt_rlc.bg"; check "rlc: the source's stroke is a fixed stroke" $?
grep -q '^input u_u = 1.0\*(t>=0)$' "$tmp/mtt_rlc.bg" && grep -q '^param r_par = 2.0 "MTT parameter r"$' "$tmp/mtt_rlc.bg" &&
  grep -q '^simulate t_end = 6, dt = 0.05$' "$tmp/mtt_rlc.bg"
check "rlc: input, numpar (the last assignment) and simpar read" $?
grep -q '^TF t_ = n$' "$tmp/mtt_rlc.bg" && grep -q '^De v = mtt0$' "$tmp/mtt_rlc.bg"
check "rlc: TF effort,n is bgdraw's TF n; De on a 0-junction is a detector" $?
grep -q '^  bond in -> mtt1$' "$tmp/mtt_chain.bg" && grep -q '^  bond mtt1 -> out$' "$tmp/mtt_chain.bg"
check "chain: the port drawn inwards is coerced to the outside bond's direction" $?
grep -q '^Stage s1(r_par = 1)$' "$tmp/mtt_chain.bg" && grep -q '^Stage s2(r_par = 2)$' "$tmp/mtt_chain.bg" &&
  grep -q '^MTF t_ = k \* t_mod.e$' "$tmp/mtt_chain.bg"
check "chain: \$1 passed to each instance; EMTF modulated by its [mod] port's effort" $?
grep -q '^MSe a = g_par \* a_in.e$' "$tmp/mtt_amps.bg" && grep -q '^MSf b = 3 \* b_in.f$' "$tmp/mtt_amps.bg" &&
  grep -q '^R  r1 = 1/0.5$' "$tmp/mtt_amps.bg" && grep -q '^C  c1 = 1/2$' "$tmp/mtt_amps.bg" &&
  grep -q '^Df i3 = j3$' "$tmp/mtt_amps.bg"
check "amps: AE, AF, R effort,g, C state,k, Df on a 1-junction" $?

python3 - "$tmp" <<'PY'
import csv, math, sys
tmp = sys.argv[1]
def rows(name):
    with open(f"{tmp}/{name}.csv") as f:
        r = csv.reader(f); h = next(r)
        return h, [dict(zip(h, map(float, row))) for row in r]
bad = 0
h, R = rows("mtt_rlc")
for r in R:
    t = r["t"]
    bad += abs(r["c.q"] - (1 - (1 + t) * math.exp(-t)) / 2) > 1e-7   # primary charge Q = 2 q
    bad += abs(r["l.p"] - t * math.exp(-t)) > 1e-7                    # current dQ/dt
    bad += abs(r["v"] - r["c.q"] / 0.25) > 1e-9
h, R = rows("mtt_amps")
for r in R:
    t = r["t"]
    bad += abs(r["c1.q"] - 0.75 * (1 - math.exp(-t))) > 1e-7
    bad += abs(r["m.p"] - (1 - math.exp(-t))) > 1e-7
    bad += abs(r["c4.q"] - 1.5 * (1 - math.exp(-t))) > 1e-7
    bad += abs(r["s_y"] - 2 * r["m.p"]) > 1e-9 or r["v_y"] != 0.5 or r["i3"] != 0.5
h, R = rows("mtt_chain")
for r in R:
    bad += abs(r["c.q"] - 2 * (1 - math.exp(-r["t"] / 12))) > 1e-7
sys.exit(1 if bad else 0)
PY
check "trajectories against the hand-derived answers" $?

# generated models (tests/import_mtt_gen.py: junction chains with R, C, I, TF,
# GY, bonds and half arrows either way, text anchors left, centre or right)
# against the same models in .bg: --check and the simulation byte for byte
n=0
for seed in $(seq 1 25); do
  python3 tests/import_mtt_gen.py $seed $((1 + seed % 6)) "$tmp/gen" || break
  g=$tmp/gen/gen$seed
  "$BGDRAW" "$g" --check >"$tmp/a" 2>&1; "$BGDRAW" "$g.bg" --check >"$tmp/b" 2>&1
  cmp -s "$tmp/a" "$tmp/b" || { echo "  gen$seed: --check differs"; diff "$tmp/a" "$tmp/b" | head -5; continue; }
  "$BGDRAW" "$g" -o "$tmp/a.csv" 2>/dev/null; sa=$?
  "$BGDRAW" "$g.bg" -o "$tmp/b.csv" 2>/dev/null; sb=$?
  [ $sa = $sb ] && { [ $sa != 0 ] || cmp -s "$tmp/a.csv" "$tmp/b.csv"; } && n=$((n + 1))
done
[ $n = 25 ]; check "25 generated drawings read as the same models written in .bg" $?

# the size is bounded: a drawing of more components than that is refused at once
python3 -c "
print('#FIG 3.2\nLandscape\nCenter\nMetric\nA4\n100.00\nSingle\n-2\n1200 2')
for i in range(10001): print('4 1 0 0 0 0 20 0.0000 4 240 600 %d 0 R:r%d\\\\001' % (600 * i, i))
" >"$tmp/huge_abg.fig"
"$BGDRAW" "$tmp/huge_abg.fig" --check 2>"$tmp/err"
[ $? = 1 ] && grep -q "huge_abg.fig:10010:1: error: MTT drawing: more than 10000 components" "$tmp/err"
check "a drawing of more than 10000 components is refused" $?

# every other option on the folder directly; the same bytes twice
"$BGDRAW" $d/mtt_chain -o "$tmp/chain.svg" && grep -q '<svg' "$tmp/chain.svg" &&
  "$BGDRAW" $d/mtt_chain --equations text | grep -q "^c.q' = "
check "a diagram and the equations straight from the folder" $?
"$BGDRAW" --import $d/mtt_amps -T bg | cmp -s - "$tmp/mtt_amps.bg"; check "deterministic" $?
"$BGDRAW" - --stdin-name $d/mtt_amps/mtt_amps_abg.fig -o "$tmp/s.csv" <$d/mtt_amps/mtt_amps_abg.fig &&
  cmp -s "$tmp/s.csv" "$tmp/mtt_amps.csv"
check "the drawing on standard input, its files found from --stdin-name" $?
"$BGDRAW" --import examples/rlc.bg -T bg >/dev/null 2>"$tmp/err"
[ $? = 2 ] && grep -q 'not another tool' "$tmp/err"; check "--import refuses a .bg model" $?
mkdir -p "$tmp/empty"
"$BGDRAW" "$tmp/empty" --check 2>"$tmp/err"; [ $? = 1 ] && grep -q 'holds no MTT drawing (empty_abg.fig)' "$tmp/err"
check "a folder without a drawing is an error that names the file it looked for" $?

# a drawing read one way with a warning where a bond end is almost as near
# another component (the coordinates say where)
cp -r $d/mtt_amps "$tmp/amb"
sed -i 's/^\(4 1 0 0 0 0 20 0.0000 4 240 600\) 3000 2400 R:r0/\1 3280 1700 R:r0/' "$tmp/amb/mtt_amps_abg.fig"
mv "$tmp/amb/mtt_amps_abg.fig" "$tmp/amb/amb_abg.fig"
for f in lbl numpar simpar; do mv "$tmp/amb/mtt_amps_$f.txt" "$tmp/amb/amb_$f.txt"; done
"$BGDRAW" --import "$tmp/amb" -T bg >"$tmp/amb.bg" 2>"$tmp/err"
grep -q "warning: MTT drawing: the bond's tail at (3000, 1500) is almost as near R:r0 as 0: read as 0" "$tmp/err" &&
  grep -q 'amb_abg.fig:[0-9]*:1: warning' "$tmp/err" && grep -q '^bond mtt0 -> r0$' "$tmp/amb.bg" &&
  grep -q "^# amb_abg.fig:[0-9]*: the bond's tail at (3000, 1500) is almost as near R:r0 as 0: read as 0$" "$tmp/amb.bg"
check "an almost equally near label: the reading taken is said with its coordinates (stderr and the .bg text)" $?

# a named component the label file does not list takes MTT's default label
# (R:r is lin flow,r); a third field in the drawing (R:r:flow,r) is its arguments
cp -r $d/mtt_rlc "$tmp/dl"
sed -i '/^\tr\tlin/d' "$tmp/dl/mtt_rlc_lbl.txt"
"$BGDRAW" --import "$tmp/dl" -T bg | cmp -s - "$tmp/mtt_rlc.bg"
check "a component missing from the label file: MTT's default label" $?
sed -i 's/ R:r\\001$/ R:r:effort,g\\001/' "$tmp/dl/mtt_rlc_abg.fig"
printf 'g = 0.5;\n' >>"$tmp/dl/mtt_rlc_numpar.txt"
"$BGDRAW" --import "$tmp/dl" -T bg | grep -q '^R  r = 1/g$' && "$BGDRAW" "$tmp/dl" -o "$tmp/dl.csv" &&
  cmp -s "$tmp/dl.csv" "$tmp/mtt_rlc.csv"
check "a drawing's TYPE:NAME:ARGS gives lin's arguments" $?

# errors at the foreign files' lines: a .bg error of a numpar value, a label
# file's CR, an unknown port of a subsystem
cp -r $d/mtt_rlc "$tmp/e1"
sed -i 's/^c = 0.25;.*/c = 0.25 +;/' "$tmp/e1/mtt_rlc_numpar.txt"
"$BGDRAW" "$tmp/e1" --check 2>"$tmp/err"
[ $? = 1 ] && grep -q "e1/mtt_rlc_numpar.txt:$(grep -n '^c = ' "$tmp/e1/mtt_rlc_numpar.txt" | cut -d: -f1):" "$tmp/err"
check "an error of a parameter's value points at the numpar file's line" $?
cp -r $d/mtt_rlc "$tmp/e2"
sed -i 's/^\tl\tlin\t\tflow,l/\tl\tpowerlaw\tflow,l/; s/^\tl\tlin\tflow,l/\tl\tpowerlaw\tflow,l/' "$tmp/e2/mtt_rlc_lbl.txt"
"$BGDRAW" "$tmp/e2" --check 2>"$tmp/err"
[ $? = 1 ] && grep -q "e2/mtt_rlc_lbl.txt:$(grep -n 'powerlaw' "$tmp/e2/mtt_rlc_lbl.txt" | cut -d: -f1):1: error: MTT model: I:l has the constitutive relationship 'powerlaw'" "$tmp/err"
check "an unknown CR is an error at the label file's line" $?
cp -r $d/mtt_chain "$tmp/e3"
sed -i 's/^\(4 1 0 0 0 0 20 0.0000 4 240 600 6800 2000\) \[mod\]/\1 [modulation]/' "$tmp/e3/mtt_chain_abg.fig"
"$BGDRAW" "$tmp/e3" --check 2>"$tmp/err"
[ $? = 1 ] && grep -q "mtt_chain_abg.fig:[0-9]*:1: error: MTT model: EMTF:t has no port \[modulation\]" "$tmp/err"
check "a port label the component does not have" $?
cp -r $d/mtt_chain "$tmp/e4"
sed -i 's/^#ALIAS\tin|left\tin/#ALIAS\tleft\tin/' "$tmp/e4/Stage/Stage_lbl.txt"
sed -i 's/^\(4 1 0 0 0 0 20 0.0000 4 240 600 3000 2400 Stage:s1\)/\1/' "$tmp/e4/mtt_chain_abg.fig"
printf '4 1 0 0 0 0 20 0.0000 4 240 600 2600 2250 [left]\\001\n' >>"$tmp/e4/mtt_chain_abg.fig"
"$BGDRAW" --import "$tmp/e4" -T bg | grep -q '^bond u -> s1.in$'
check "a subsystem's port alias ([left] for [in])" $?
printf '4 1 0 0 0 0 20 0.0000 4 240 600 4400 2250 [right]\\001\n' >>"$tmp/e4/mtt_chain_abg.fig"
"$BGDRAW" "$tmp/e4" --check 2>"$tmp/err"
[ $? = 1 ] && grep -q "error: MTT model: Stage:s2 at (4800, 2400): its subsystem has no port \[right\]" "$tmp/err"
check "a port label the subsystem does not have" $?
finish
