#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# docs/tutorial.md, run as a reader would: every model block of the page must be the file
# of examples/tutorial it names (and every such file is on the page), every command
# block runs (tools/gallery.sh, the build of the page's pictures, in a private folder),
# every output block is what its command prints, every picture the page shows is made,
# and every number the text states is checked against its hand-derived value (closed
# forms, and a matrix exponential computed here for the linear tank cascades).
#     bash tests/tutorial.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
BG=$BGDRAW

. "$(dirname "$0")/lib/doc_pages.sh"
page_build tutorial
page_files tutorial

# output blocks: MODEL-check and MODEL-equations are the whole output of the command,
# MODEL-linear its beginning (the page leaves out the symbolic part), MODEL-reduced lines
# of --equations text
for o in "$tmp"/out/output-*.txt; do
  name=${o##*/output-}; name=${name%.txt}; model=${name%-*}; what=${name##*-}
  case $what in
    check) args=(--check) ;;
    equations | reduced) args=(--equations text) ;;
    linear) args=(--linear text) ;;
    *) check "output block $name: unknown kind" 1; continue ;;
  esac
  (cd "$d" && "$BG" "$model.bg" "${args[@]}") >"$tmp/got" 2>&1
  case $what in
    check | equations) cmp -s "$o" "$tmp/got" ;;
    linear) head -n "$(wc -l <"$o")" "$tmp/got" | cmp -s "$o" - ;;
    reduced) grep -A"$(($(wc -l <"$o") - 1))" -xF "$(head -1 "$o")" "$tmp/got" | cmp -s "$o" - ;;
  esac
  check "output block $name is what 'bgdraw $model.bg ${args[*]}' prints" $?
done

# the numbers the text states, against their hand-derived values
python3 - "$d" <<'EOF'
import math, sys
sys.path.insert(0, "tests/lib")
import page_numbers as pn
from page_numbers import at, close, rows
pn.D = sys.argv[1]
def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(len(b))) for j in range(len(b[0]))] for i in range(len(a))]
def expm(a):
    """e^a by scaling and squaring with a 30-term Taylor series (small matrices)."""
    n, s = len(a), 0
    norm = max(sum(abs(x) for x in row) for row in a)
    while norm > 0.5:
        norm, s = norm / 2, s + 1
    a = [[x / 2**s for x in row] for row in a]
    e = [[float(i == j) for j in range(n)] for i in range(n)]
    term = [row[:] for row in e]
    for k in range(1, 30):
        term = [[x / k for x in row] for row in matmul(term, a)]
        e = [[e[i][j] + term[i][j] for j in range(n)] for i in range(n)]
    for _ in range(s):
        e = matmul(e, e)
    return e
def cascade(M, hss, t):
    """levels of tanks h' = a M h + b from rest: h(t) = hss - e^(a M t) hss, a = k/A."""
    E = expm([[1e-3 * x * t for x in row] for row in M])
    return [hss[i] - sum(E[i][j] * hss[j] for j in range(len(hss))) for i in range(len(hss))]

# step 1: h = (Q0/k)(1 - e^(-t/tau)), tau = A/k = 1000 s
close("tank: h(1000)", at("tank.csv", 1000)[1], 1 - math.exp(-1), 1e-4)
close("tank: h(5000)", at("tank.csv", 5000)[1], 1 - math.exp(-5), 1e-4)
# step 2: every row against the exact solution; steady 2 m and 1 m
M2 = [[-1, 1], [1, -2]]
worst = max(abs(r[i + 1] - cascade(M2, [2, 1], r[0])[i]) for r in rows("two_tanks.csv") for i in range(2))
close("two tanks: largest deviation from the exact levels", worst, 0, 1e-4)
h = at("two_tanks.csv", 10000)
close("two tanks: h1(10000)", h[1], 1.958, 5e-4)
close("two tanks: h2(10000)", h[2], 0.974, 5e-4)
# step 3: the reversed bond: tank 2 is the mirror image, steady h2 = -Q0/k = -1 m
M3 = [[-1, -1], [-1, -2]]  # h1' = a(Q0/k - h1 - h2), h2' = a(-h1 - 2 h2)
worst = max(abs(r[i + 1] - cascade(M3, [2, -1], r[0])[i]) for r in rows("two_tanks_wrong.csv") for i in range(2))
close("reversed bond: largest deviation from the exact levels", worst, 0, 1e-4)
close("reversed bond: h2(10000)", at("two_tanks_wrong.csv", 10000)[2], -0.974, 5e-4)
close("reversed bond: h1 as in step 2", at("two_tanks_wrong.csv", 10000)[1], h[1], 1e-6)
# step 5: two joined tanks: tau = 2A/k = 2000 s
close("joined tanks: level at 2000 s", at("joined_tanks.csv", 2000)[1] / 1.0, 1 - math.exp(-1), 1e-4)
# step 6: k doubled: 0.5 (1 - e^(-10))
close("wider outlet: h(5000)", at("tank_wide.csv", 5000)[1], 0.5 * (1 - math.exp(-10)), 1e-5)
# step 7: three tanks, steady 3, 2, 1 m; every row against the exact solution
M = [[-1, 1, 0], [1, -2, 1], [0, 1, -2]]
worst = max(abs(r[i + 1] - cascade(M, [3, 2, 1], r[0])[i]) for r in rows("three_tanks.csv") for i in range(3))
close("three tanks: largest deviation from the exact levels", worst, 0, 2e-4)
sys.exit(1 if pn.failed else 0)
EOF
check "the tutorial's numbers (above)" $?

# step 7's linear analysis: the poles -4 a sin^2((2j-1) pi/14) and the DC gain 1/k
(cd "$d" && "$BG" three_tanks.bg --linear json) >"$tmp/lin.json"
python3 - "$tmp/lin.json" <<'EOF'
import json, math, sys
j = json.load(open(sys.argv[1]))
poles = sorted(p["re"] for p in j["poles"])
want = sorted(-4e-3 * math.sin((2 * k - 1) * math.pi / 14) ** 2 for k in (1, 2, 3))
ok = len(poles) == 3 and all(abs(a - b) <= 1e-9 and p["im"] == 0 for a, b, p in zip(poles, want, j["poles"]))
print("ok  " if ok else "FAIL", "poles", poles, "hand", want)
dc = j["transfer_functions"][0]["dc_gain"]
ok2 = abs(dc - 1000) <= 1e-6
print("ok  " if ok2 else "FAIL", "DC gain", dc, "hand 1000")
sys.exit(0 if ok and ok2 else 1)
EOF
check "three tanks: poles and DC gain against the hand-derived ones" $?

finish
