#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Builds bench/expr_bench.c with the evaluator sources at release optimisation
# and runs it: ns per linear term, tree walker vs bytecode VM, and the ratio.
#   bench/expr_bench.sh [N...]     (default: 100 1000 10000)
# Environment: CC (default cc), CFLAGS (default -O2 -DNDEBUG), OUT (binary dir).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cc=${CC:-cc}
cflags=${CFLAGS:--O2 -DNDEBUG}
out=${OUT:-$root/build-bench}
mkdir -p "$out"
# Only what the evaluators need, so the benchmark does not depend on the rest
# of the engine (or on a configured CMake build of a particular type).
$cc -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra $cflags -I"$root/src" \
  "$root/bench/expr_bench.c" "$root/src/model/xeval.c" "$root/src/model/prog.c" "$root/src/base/arena.c" \
  -lm -o "$out/expr_bench"
echo "# $($cc --version | head -n 1); CFLAGS=$cflags"
[ $# -gt 0 ] || set -- 100 1000 10000
for n in "$@"; do "$out/expr_bench" "$n"; done
