#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# BondGraphTools YAML import (issue 35, docs/import.md): each model of
# tests/data/import/bgt_*.yaml against the same model written by hand in .bg
# (the --import text, the --check analysis, the equations, the simulation byte
# for byte) and against its hand-derived trajectory; detection by content
# whatever the extension; --import refuses a .bg model; errors at YAML lines.
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
d=tests/data/import

for m in rc gyrator; do
  "$BGDRAW" --import $d/bgt_$m.yaml -T bg | tail -n +2 >"$tmp/$m.bg"
  tail -n +3 $d/bgt_$m.bg | diff - "$tmp/$m.bg" >/dev/null
  check "$m: --import text equals the hand-written .bg" $?
  "$BGDRAW" $d/bgt_$m.yaml --check >"$tmp/a" && "$BGDRAW" $d/bgt_$m.bg --check >"$tmp/b"
  cmp -s "$tmp/a" "$tmp/b"; check "$m: --check equals the hand-written model's" $?
  "$BGDRAW" $d/bgt_$m.yaml --equations text >"$tmp/a" && "$BGDRAW" $d/bgt_$m.bg --equations text >"$tmp/b"
  cmp -s "$tmp/a" "$tmp/b"; check "$m: equations equal the hand-written model's" $?
  "$BGDRAW" $d/bgt_$m.yaml -o "$tmp/a.csv" && "$BGDRAW" $d/bgt_$m.bg -o "$tmp/b.csv"
  cmp -s "$tmp/a.csv" "$tmp/b.csv"; check "$m: simulation equals the hand-written model's" $?
  cp "$tmp/a.csv" "$tmp/$m.csv"
done

"$BGDRAW" $d/bgt_modular.yaml -o "$tmp/modular.csv"; check "modular: simulates" $?
grep -q '^submodel load$' <("$BGDRAW" --import $d/bgt_modular.yaml -T bg); check "modular: a submodel" $?
"$BGDRAW" $d/bgt_biochem.yaml --set A_q0=1.5 --set B_q0=0.5 -o "$tmp/biochem.csv"
check "biochem: simulates with --set initial amounts" $?

# detected by content: the same YAML named .bg (BondGraphTools' own extension)
cp $d/bgt_rc.yaml "$tmp/rc_as.bg"
"$BGDRAW" "$tmp/rc_as.bg" -o "$tmp/c.csv" && cmp -s "$tmp/c.csv" "$tmp/rc.csv"
check "a YAML model named .bg is imported" $?
"$BGDRAW" --import examples/rlc.bg -T bg >/dev/null 2>"$tmp/err"
[ $? = 2 ] && grep -q 'not another tool' "$tmp/err"; check "--import refuses a .bg model" $?
"$BGDRAW" $d/bgt_rc.yaml -o "$tmp/x.bg" 2>/dev/null; [ $? = 2 ] && [ ! -e "$tmp/x.bg" ]
check ".bg output without --import or --transform is refused" $?
"$BGDRAW" --import $d/bgt_rc.yaml --transform merge-stores -o "$tmp/x.bg" 2>/dev/null; [ $? = 2 ]
check "--import with --transform is refused" $?
# an error of the .bg text points at the YAML line it came from
sed 's/  - plot C1.q/  - plot C9.q/' $d/bgt_rc.yaml >"$tmp/bad.yaml"
"$BGDRAW" "$tmp/bad.yaml" --check 2>"$tmp/err"
grep -q "bad.yaml:$(grep -n 'plot C9' "$tmp/bad.yaml" | cut -d: -f1):" "$tmp/err"; check "a .bg error at the YAML's line" $?

"$BGDRAW" --import $d/bgt_version04.yaml -T bg >"$tmp/v.bg" && grep -q '^# file format version 0.4 read as 0.1' "$tmp/v.bg" &&
  grep -q '^bond R1 -> kcl$' "$tmp/v.bg" && "$BGDRAW" $d/bgt_version04.yaml --check | grep -q '^states (1): C1.q$'
check "version 0.4: imported with a note" $?

# write-back (-o m.yaml): the hand-written models and generated ones go to YAML and
# back; the analysis, the equations and the simulation are the same byte for byte
roundtrip() { # NAME MODEL.bg
  "$BGDRAW" "$2" -o "$tmp/rt.yaml" || return 1
  python3 -c "import sys, yaml; d = yaml.safe_load(open(sys.argv[1])); sys.exit(0 if str(d['version']) == '0.1' and '/' in d['models'] else 1)" "$tmp/rt.yaml" || return 1
  for opt in --check "--equations text"; do
    "$BGDRAW" "$2" $opt >"$tmp/a" 2>&1; "$BGDRAW" "$tmp/rt.yaml" $opt >"$tmp/b" 2>&1
    cmp -s "$tmp/a" "$tmp/b" || { echo "  $1: $opt differs"; diff "$tmp/a" "$tmp/b" | head -5; return 1; }
  done
  "$BGDRAW" "$2" -o "$tmp/a.csv" 2>"$tmp/ea"; sa=$?
  "$BGDRAW" "$tmp/rt.yaml" -o "$tmp/b.csv" 2>"$tmp/eb"; sb=$?
  [ $sa = $sb ] && { [ $sa != 0 ] || cmp -s "$tmp/a.csv" "$tmp/b.csv"; }
}
for m in rc gyrator; do roundtrip $m $d/bgt_$m.bg; check "$m: bgdraw -> YAML -> bgdraw is the same model" $?; done
n=0
for seed in $(seq 1 25); do
  python3 tests/import_gen.py $seed $((2 + seed % 7)) >"$tmp/gen.bg"
  roundtrip gen$seed "$tmp/gen.bg" && n=$((n + 1))
done
[ $n = 25 ]; check "25 generated models: bgdraw -> YAML -> bgdraw is the same model ($n)" $?

# what the format cannot carry is refused, naming it (status 3, nothing written)
for c in "examples/rlc.bg|Se U has a value that varies in time" \
         "examples/internal_mod_r.bg|reads js.f, a signal" \
         "tests/data/fields/transducer.bg|multiport field"; do
  f=${c%%|*} want=${c#*|}
  [ -f "$f" ] || { check "refusal model $f exists" 1; continue; }
  "$BGDRAW" "$f" -o "$tmp/r.yaml" 2>"$tmp/err"; st=$?
  [ $st = 3 ] && [ ! -e "$tmp/r.yaml" ] && grep -q "cannot write BondGraphTools YAML: .*$want" "$tmp/err"
  check "$f: refused ($want)" $?
done
# a model with submodels is written flat
"$BGDRAW" $d/bgt_modular.yaml -o "$tmp/flat.yaml" && grep -q '^      - A_C1 base/C C=1$' "$tmp/flat.yaml" &&
  "$BGDRAW" "$tmp/flat.yaml" --check | grep -q '^dependent stores: B_C1$'
check "submodels written flat" $?

# hand-derived trajectories (the models' header comments)
python3 - "$tmp" <<'PY'
import csv, math, sys
tmp = sys.argv[1]
def rows(name):
    with open(f"{tmp}/{name}.csv") as f:
        r = csv.reader(f); next(r)
        return [[float(x) for x in row] for row in r]
bad = 0
for t, q in rows("rc"):
    bad += abs(q - 2 * (1 - math.exp(-t / 2))) > 1e-7
for t, i, w in rows("gyrator"):
    bad += abs(i - math.sin(2 * t) / 2) > 1e-7 or abs(w - (math.cos(2 * t) - 1) / 2) > 1e-7
for t, a, b in rows("modular"):
    bad += abs(a - 1.5 * (1 - math.exp(-t))) > 1e-7 or a != b
for t, a, b in rows("biochem"):
    bad += abs(a - b - math.exp(-2 * t)) > 1e-7 or abs(a + b - 2) > 1e-7
sys.exit(1 if bad else 0)
PY
check "trajectories against the hand-derived answers" $?
finish
