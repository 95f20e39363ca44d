#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Compile time of the C export (issue 34): chains of mass-spring-dampers
# (bench/gen_models.py) exported to C and compiled with `gcc -O2 -c`; user
# CPU seconds and peak memory of the compiler, per size. With a second
# bgdraw (a baseline build), the same for it and the ratio.
#     bash bench/export_compile.sh build/bgdraw [BASELINE_BGDRAW] [MASSES...]
set -u
new=$(readlink -f "${1:?usage: export_compile.sh BGDRAW [BASELINE] [MASSES...]}")
shift
old=""
if [ $# -gt 0 ] && [ -x "$1" ]; then old=$(readlink -f "$1"); shift; fi
sizes=${*:-200 500 1000}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cpu() { # BGDRAW MODEL NAME: prints "lines seconds MB"
  "$1" "$2" -o "$tmp/$3.c" || return 1
  /usr/bin/time -f "%U %M" -o "$tmp/$3.time" gcc -O2 -c "$tmp/$3.c" -o "$tmp/$3.o" || return 1
  read -r s kb <"$tmp/$3.time"
  echo "$(wc -l <"$tmp/$3.c") $s $((kb / 1024))"
}
printf '%-8s %-8s %-10s %-8s %s\n' masses lines "gcc -O2 s" MB "baseline s (ratio)"
for n in $sizes; do
  python3 "$here/gen_models.py" chain $((5 * n)) >"$tmp/m.bg"
  read -r lines s mb < <(cpu "$new" "$tmp/m.bg" new)
  extra=""
  if [ -n "$old" ]; then
    read -r _ so _ < <(cpu "$old" "$tmp/m.bg" old)
    extra="$so ($(python3 -c "print('%.1fx' % ($so / max($s, 0.01)))"))"
  fi
  printf '%-8s %-8s %-10s %-8s %s\n' "$n" "$lines" "$s" "$mb" "$extra"
done
