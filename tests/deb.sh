#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The Debian packages (tools/deb.sh, tools/packaging.cmake; docs/install.md),
# bgdraw, libbgdraw0, libbgdraw-dev and python3-bgdraw:
# built into a temporary folder, then
# - lintian finds no error and no warning (info-level notes are allowed);
# - each package has Debian's copyright file and changelog.Debian.gz, the man
#   page is compressed (gzip -9n: the same bytes each build), the binaries are
#   stripped, libbgdraw0 has its shlibs line and the ldconfig trigger, and
#   libbgdraw-dev depends on exactly this libbgdraw0;
# - apt would install them on this system (their Depends resolve: apt-get -s);
# - installed with dpkg into a scratch root (its own package database; as
#   root, since dpkg --root needs it; else unpacked with dpkg-deb -x), the
#   packaged bgdraw gives the build tree's --check and SVG bytes, and
#   docs/library.md's program, built with pkg-config against the installed
#   libbgdraw-dev, prints what it prints against the build tree's library;
#   purging the three packages leaves no file behind.
# Usage: bash tests/deb.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
BUILD=$(dirname "$BGDRAW")
DEB_BUILD_DIR="$tmp/build-deb" bash tools/deb.sh "$tmp/deb" >"$tmp/deb.log" 2>&1; st=$?
check "tools/deb.sh builds the packages (got $st)" $st
[ $st -eq 0 ] || tail -20 "$tmp/deb.log"
v=$(sed -n 's/^project(bgdraw VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
for p in bgdraw libbgdraw0 libbgdraw-dev python3-bgdraw; do
  [ -f "$tmp/deb/${p}_${v}-1_amd64.deb" ]; check "$p ${v}-1 built" $?
done
lintian --tag-display-limit 0 "$tmp"/deb/*.deb >"$tmp/lintian.out" 2>&1
! grep -E '^[EW]: ' "$tmp/lintian.out"; check "lintian: no error or warning" $?
for p in bgdraw libbgdraw0 libbgdraw-dev python3-bgdraw; do
  d="$tmp/x/$p"; mkdir -p "$d"; dpkg-deb -x "$tmp/deb/${p}_${v}-1_amd64.deb" "$d"
  grep -q '^Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/' \
    "$d/usr/share/doc/$p/copyright" && grep -q '^License: BSD-3-Clause' "$d/usr/share/doc/$p/copyright"
  check "$p: a machine-readable copyright file naming BSD-3-Clause" $?
  zcat "$d/usr/share/doc/$p/changelog.Debian.gz" | head -1 | grep -q "^bgdraw (${v}-1) "
  check "$p: changelog.Debian.gz of ${v}-1" $?
done
x=$tmp/x/bgdraw
gzip -t "$x/usr/share/man/man1/bgdraw.1.gz" && zcat "$x/usr/share/man/man1/bgdraw.1.gz" | grep -q "^\.TH BGDRAW 1"
check "the man page is compressed" $?
[ ! -e "$x/usr/share/man/man1/bgdraw.1" ]; check "and not also plain" $?
for f in "$x/usr/bin/bgdraw" "$x"/usr/lib/*/bgdraw/bgdraw_render.so "$tmp"/x/libbgdraw0/usr/lib/*/libbgdraw.so.$v; do
  ! readelf -S "$f" | grep -qE '\.(symtab|debug_info)'; check "stripped: ${f#$tmp/x/}" $?
done
dpkg-deb -e "$tmp/deb/libbgdraw0_${v}-1_amd64.deb" "$tmp/ctl"
grep -qx "libbgdraw 0 libbgdraw0 (>= $v)" "$tmp/ctl/shlibs"; check "libbgdraw0: shlibs" $?
grep -qx "activate-noawait ldconfig" "$tmp/ctl/triggers"; check "libbgdraw0: the ldconfig trigger" $?
dpkg-deb -f "$tmp/deb/libbgdraw-dev_${v}-1_amd64.deb" Depends | grep -q "libbgdraw0 (= ${v}-1)"
check "libbgdraw-dev depends on libbgdraw0 (= ${v}-1)" $?
dpkg-deb -f "$tmp/deb/bgdraw_${v}-1_amd64.deb" Depends | grep -q "libcairo2"
check "bgdraw's Depends computed by dpkg-shlibdeps (cairo among them)" $?
# LAPACKE and SUNDIALS are opened on first use: stated, not found
for p in bgdraw libbgdraw0; do
  for lib in liblapacke libsundials-cvode6 libsundials-ida6 libsundials-nvecserial6 \
    libsundials-sunmatrix4 libsundials-sunlinsol3; do
    dpkg-deb -f "$tmp/deb/${p}_${v}-1_amd64.deb" Depends | grep -Eq "(^|, )$lib \\(>= [0-9.+a-z]+\\)"
    check "$p depends on $lib (opened on first use, not linked)" $?
  done
done
cp examples/rlc.bg "$tmp/rlc.bg"
(cd "$tmp" && "$BGDRAW" rlc.bg --check >tree.check && "$BGDRAW" rlc.bg -o tree.svg)
# apt's view: every dependency resolvable on this system
apt-get install -s "$tmp"/deb/*.deb >"$tmp/apt.out" 2>&1
grep -q "^Inst bgdraw " "$tmp/apt.out" && grep -q "^Inst libbgdraw0 " "$tmp/apt.out" &&
  grep -q "^Inst libbgdraw-dev " "$tmp/apt.out" && grep -q "^Inst python3-bgdraw " "$tmp/apt.out"
check "apt-get -s would install the four packages" $?
# the scratch root: dpkg's own installation where root may, else the unpacked trees
all=$tmp/root
mkdir -p "$all/var/lib/dpkg/info" "$all/var/lib/dpkg/updates" "$all/var/lib/dpkg/triggers"
touch "$all/var/lib/dpkg/status" "$all/var/lib/dpkg/available"
if [ "$(id -u)" = 0 ]; then
  # --force-depends: the scratch root has no other package; the system's libraries serve
  dpkg --root="$all" --log=/dev/null --force-depends --force-script-chrootless -i "$tmp"/deb/*.deb \
    >"$tmp/dpkg.out" 2>&1
  check "dpkg installs the four packages into a scratch root" $?
  [ "$(dpkg --root="$all" -l | grep -c '^ii  \(bgdraw\|libbgdraw0\|libbgdraw-dev\|python3-bgdraw\) ')" = 4 ]
  check "dpkg's database there lists them installed" $?
else
  for p in bgdraw libbgdraw0 libbgdraw-dev python3-bgdraw; do cp -a "$tmp/x/$p/." "$all/"; done
fi
(cd "$tmp" && "$all/usr/bin/bgdraw" rlc.bg --check >inst.check && "$all/usr/bin/bgdraw" rlc.bg -o inst.svg) 2>>"$tmp/err"
cmp -s "$tmp/inst.check" "$tmp/tree.check" && cmp -s "$tmp/inst.svg" "$tmp/tree.svg"
check "the installed bgdraw gives the build tree's --check and SVG" $?
pcdir=$(dirname "$(find "$all" -name bgdraw.pc | head -1)")
awk '/^```c$/{on=1; next} /^```$/{if (on) exit} on' docs/library.md >"$tmp/rlcinfo.c"
cc -std=c11 -Wall -Wextra -Werror -o "$tmp/pkg_rlcinfo" "$tmp/rlcinfo.c" \
  $(PKG_CONFIG_PATH=$pcdir pkg-config --cflags --libs bgdraw) 2>"$tmp/cc.err"
check "docs/library.md's program builds against libbgdraw-dev with pkg-config" $?
cc -std=c11 -o "$tmp/tree_rlcinfo" "$tmp/rlcinfo.c" -Iinclude -I"$BUILD/include" -L"$BUILD" -lbgdraw
(cd "$tmp" && LD_LIBRARY_PATH="$(dirname "$(find "$all" -name 'libbgdraw.so.0' | head -1)")" \
  ./pkg_rlcinfo rlc.bg a.svg >pkg.out && LD_LIBRARY_PATH="$BUILD" ./tree_rlcinfo rlc.bg b.svg >tree.out)
cmp -s "$tmp/pkg.out" "$tmp/tree.out" && grep -q "bonds" "$tmp/pkg.out" && cmp -s "$tmp/a.svg" "$tmp/b.svg"
check "and prints and draws what it does against the build tree's library" $?
# the Python package finds the packaged library beside it (relative to itself)
(cd "$tmp" && PYTHONPATH="$all/usr/lib/python3/dist-packages" PYTHONDONTWRITEBYTECODE=1 /usr/bin/python3 -c '
import bgdraw, sys
m = bgdraw.Model.from_file("rlc.bg")
print(bgdraw.__version__, bgdraw.__file__.startswith(sys.argv[1]), len(m.analysis.bonds))
open("py.svg", "w").write(m.svg())' "$all" >py.out 2>>"$tmp/err")
[ "$(cat "$tmp/py.out")" = "$v True 4" ] && cmp -s "$tmp/py.svg" "$tmp/tree.svg"
check "python3-bgdraw imports from the scratch root and draws the build tree's SVG" $?
if [ "$(id -u)" = 0 ]; then
  dpkg --root="$all" --log=/dev/null --force-script-chrootless -P python3-bgdraw bgdraw libbgdraw-dev libbgdraw0 \
    >>"$tmp/dpkg.out" 2>&1
  check "dpkg purges them" $?
  [ -z "$(find "$all/usr" -type f 2>/dev/null)" ]; check "purging leaves no file in /usr" $?
fi
finish
