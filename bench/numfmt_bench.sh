#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Builds bench/numfmt_bench.c with the number printer at release optimisation
# and runs it on N random doubles of each kind (default 10 000 000), or of
# the kinds given (0 to 5, in the order of the table it prints).
#   bench/numfmt_bench.sh [N [KIND...]]
# Environment: CC (default cc), CFLAGS (default -O2 -DNDEBUG), OUT (binary dir),
# NUMFMT_SRC (the printer's source, default src/base/numfmt.c; the one of an
# earlier commit gives the "before": git show REV:src/base/numfmt.c > f.c).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cc=${CC:-cc}
cflags=${CFLAGS:--O2 -DNDEBUG}
out=${OUT:-$root/build-bench}
mkdir -p "$out"
$cc -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra $cflags -I"$root/src" \
  "$root/bench/numfmt_bench.c" "${NUMFMT_SRC:-$root/src/base/numfmt.c}" -lm -o "$out/numfmt_bench"
echo "# $($cc --version | head -n 1); CFLAGS=$cflags"
n=${1:-10000000}
[ $# -gt 0 ] && shift
"$out/numfmt_bench" "$n" "$@"
