#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# --equations json is self-contained (docs/json.md, "The equations
# document"; tests/equations_json.py): every example under its own and
# other causality methods, a model with a named input and a table; the
# JSON's reduced form has every row the text prints (the dependent stores
# too: slider_crank's m.p = m0*T*J.p/J0), and reruns are byte-identical.
# Usage: bash tests/equations_json.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: equations_json.sh PATH_TO_BGDRAW}
command -v python3 >/dev/null || { echo "python3 not found"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
files=()
run() { # NAME ARGS...
  local name=$1
  shift
  if ! "$BGDRAW" "$@" --equations json >"$tmp/$name.json" 2>"$tmp/err" ||
     ! "$BGDRAW" "$@" --equations text >"$tmp/$name.txt" 2>>"$tmp/err"; then
    echo "FAIL bgdraw $*: $(head -c 300 "$tmp/err")"; fail=$((fail + 1)); return
  fi
  "$BGDRAW" "$@" --equations json | cmp -s - "$tmp/$name.json" || { echo "FAIL $name: reruns differ"; fail=$((fail + 1)); }
  files+=("$tmp/$name.json")
  # every row of the text's reduced form is in the JSON's "reduced"
  python3 - "$tmp/$name.txt" "$tmp/$name.json" <<'PY' || fail=$((fail + 1))
import json, sys
text = open(sys.argv[1]).read().split("\n")
d = json.load(open(sys.argv[2]))
start = next((i for i, l in enumerate(text) if l.startswith("# reduced form: ")), None)
if start is None or d["reduced_form"] != "ode":
    sys.exit(0)
want = [l for l in text[start + 1:] if " = " in l and not l.startswith("#")]
mass = next((i for i, l in enumerate(text) if l.startswith("# explicit form")), None)
if mass is not None:
    want = [l for l in text[mass + 1:] if " = " in l]
got = {r["lhs"] + " = " + r["rhs"] for r in d["reduced"]}
missing = [l for l in want if l not in got]
if missing:
    print("FAIL %s: reduced rows the text prints are missing: %s" % (sys.argv[2], missing))
    sys.exit(1)
PY
}
for f in examples/*.bg; do run "$(basename "$f" .bg)" "$f"; done
run slider_crank_lagrange examples/slider_crank.bg --causality lagrange
run delta_vandijk examples/delta.bg --causality vandijk
run hydraulic_relaxed examples/hydraulic_bridge.bg --causality relaxed
run thermostat tests/data/thermostat.bg    # memory: hyst, and the "discrete" list
run stick_slip tests/data/stick_slip.bg
cat >"$tmp/given.bg" <<'M'
param A = 2, w = 3
input u = A * sin(w * t) + table(t, [0, 0; 1, 1; 2, 0])
Se U = u
1 j
R R1 = 1
C C1 = 0.5 [q0 = 0.25]
bond U -> j
bond j -> R1
bond j -> C1
M
run given "$tmp/given.bg"
python3 tests/equations_json.py "${files[@]}" || fail=$((fail + 1))
# slider_crank: T and dT/dphi defined, the dependent store's row present
python3 - "$tmp/slider_crank.json" <<'PY' || fail=$((fail + 1))
import json, sys
d = json.load(open(sys.argv[1]))
defs = {x["name"]: x["kind"] for x in d["definitions"]}
assert defs.get("T") == "alias" and defs.get("dT/dphi") == "derivative", defs
assert {"lhs": "m.p", "rhs": "m0*T*J.p/J0", "kind": "dependent"} in d["reduced"], d["reduced"]
assert {"name": "J0", "value": 0.05} in d["parameters"], d["parameters"]
PY
echo "equations_json: ${#files[@]} documents, $fail failed"
[ "$fail" -eq 0 ]
