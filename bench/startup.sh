#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Start-up of a small diagram against Graphviz itself (issue 34): the same
# 5-node graph drawn by `bgdraw MODEL -o x.svg` and by `dot -Tsvg` on the
# DOT file bgdraw writes for it. Instructions with callgrind (one run each,
# deterministic), CPU as user + system seconds of RUNS alternating runs of
# each (paired, so a change in the machine's load falls on both). With a
# second bgdraw (a baseline build), the same for it.
#     bash bench/startup.sh build/bgdraw [BASELINE_BGDRAW] [MODEL] [RUNS]
# Needs valgrind and graphviz's dot (neither is a dependency of bgdraw).
set -u
new=$(readlink -f "${1:?usage: startup.sh BGDRAW [BASELINE] [MODEL] [RUNS]}")
shift
old=""
if [ $# -gt 0 ] && [ -x "$1" ]; then old=$(readlink -f "$1"); shift; fi
model=${1:-examples/rlc.bg}
runs=${2:-200}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$new" "$model" -o "$tmp/g.dot" || exit 1
instr() { # COMMAND... -> instructions callgrind counts
  valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" "$@" 2>&1 >/dev/null |
    sed -n 's/.*Collected : \([0-9]*\)/\1/p'
}
i_dot=$(instr dot -Tsvg "$tmp/g.dot" -o "$tmp/d.svg")
i_new=$(instr "$new" "$model" -o "$tmp/n.svg")
[ -n "$old" ] && i_old=$(instr "$old" "$model" -o "$tmp/o.svg")
python3 - "$runs" "$model" "$tmp" "$new" "${old:-}" "$i_dot" "$i_new" "${i_old:-}" <<'PY'
import os, subprocess, sys
runs, model, tmp, new, old = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5]
instr = {"dot": int(sys.argv[6]), "new": int(sys.argv[7])}
cmds = {"dot": ["dot", "-Tsvg", tmp + "/g.dot", "-o", tmp + "/d.svg"],
        "new": [new, model, "-o", tmp + "/n.svg"]}
if old:
    instr["old"] = int(sys.argv[8])
    cmds["old"] = [old, model, "-o", tmp + "/o.svg"]
cpu = {k: 0.0 for k in cmds}
for _ in range(runs):
    for k, c in cmds.items():  # alternating: each round runs every command once
        p = subprocess.Popen(c, stdout=subprocess.DEVNULL)
        _, status, ru = os.wait4(p.pid, 0)
        if status:
            sys.exit("%s failed" % " ".join(c))
        cpu[k] += ru.ru_utime + ru.ru_stime
print("%-22s %14s %8s %12s %8s" % ("command", "instructions", "vs dot", "CPU ms/run", "vs dot"))
names = {"dot": "dot -Tsvg", "new": "bgdraw -o x.svg", "old": "baseline -o x.svg"}
for k in cmds:
    print("%-22s %14d %7.3fx %12.2f %7.3fx" % (names[k], instr[k], instr[k] / instr["dot"],
          1000 * cpu[k] / runs, cpu[k] / cpu["dot"]))
PY
