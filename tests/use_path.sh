#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Where `use "NAME.bg"` finds NAME.bg (docs/format.md, "Files"): the using
# file's folder, then BGDRAW_PATH's folders, then the installed component
# library, the first that has it; the error lists where it looked. -M lists
# every file read, used files through other used files included;
# --stdin-name names standard input in diagnostics and gives its folder.
# Usage: bash tests/use_path.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp" || exit 1
unset BGDRAW_PATH
mkdir -p doc/parts far near lib2

# Part "Load" in three places, its resistor named differently in each, so
# the model's elements tell which file was read.
part() { # FILE K
  printf 'submodel Load\n  port p\n  1 j\n  R R%s = 1\n  bond p -> j\n  bond j -> R%s\nend\n' "$2" "$2" >"$1"
}
part far/load.bg 3
part near/load.bg 2
part doc/load.bg 1
printf 'use "load.bg"\nSe U = 1\nLoad L\nbond U -> L.p\n' >doc/m.bg
r_of() { # K of the resistor L.RK in the JSON of the run "$@"
  "$BGDRAW" "$@" -T json 2>/dev/null | python3 -c '
import json, sys
d = json.load(sys.stdin)
print(*[e["name"][3:] for e in d["elements"] if e["kind"] == "R"])'
}
[ "$(BGDRAW_PATH=near:far r_of doc/m.bg)" = 1 ]; check "use: the model's own folder first" $?
rm doc/load.bg
[ "$(BGDRAW_PATH=near:far r_of doc/m.bg)" = 2 ]; check "use: then BGDRAW_PATH's folders in order" $?
[ "$(BGDRAW_PATH=:far::near r_of doc/m.bg)" = 3 ]; check "use: BGDRAW_PATH's empty entries skipped" $?

# Not found: the error lists every folder, and says BGDRAW_PATH is unset.
BGDRAW_PATH=/no/such:lib2 "$BGDRAW" doc/m.bg --check 2>err.txt; st=$?
[ $st -eq 1 ] && grep -qF "doc/m.bg:1:5: error: cannot find used file 'load.bg'; looked in 'doc' (the using file's folder), '/no/such', 'lib2' (BGDRAW_PATH), '" err.txt &&
  grep -qF "(the installed component library)" err.txt
check "use: the not-found error names every folder looked in (status $st)" $?
"$BGDRAW" doc/m.bg --check 2>err.txt
grep -qF "; BGDRAW_PATH is not set" err.txt; check "use: the error says BGDRAW_PATH is not set" $?

# The installed component library (share/bgdraw/lib beside the executable):
# the library's motor by name, from anywhere.
cat >doc/drive.bg <<'EOF'
use "mechanical.bg"
Se U = 12
DCMotor M(R = 1, L = 2e-3, K = 0.08, J = 2e-4, b = 1e-5)
R bl = 0.02
bond U -> M.a
bond M.shaft -> bl
EOF
"$BGDRAW" doc/drive.bg -q -o drive.svg -M drive.d; check "use: the installed component library by name" $?
lib=$(sed -n 's/^\(.*mechanical\.bg\):$/\1/p' drive.d)
case $lib in /*/share/bgdraw/lib/mechanical.bg) cmp -s "$lib" "$root/lib/mechanical.bg" ;; *) false ;; esac
check "use: the library file found is lib/mechanical.bg, by its absolute path in -M ('$lib')" $?
# a part of the same name beside the model shadows the library's
printf 'submodel DCMotor(R = 1, L = 1, K = 1, J = 1, b = 1)\n  port a, shaft\n  GY g = K\n  bond a -> g\n  bond g -> shaft\nend\n' >doc/mechanical.bg
"$BGDRAW" doc/drive.bg -q -o drive.svg -M drive.d
grep -qx 'drive.svg: doc/drive.bg doc/mechanical.bg .*' drive.d; check "use: a file beside the model shadows the library's" $?
rm doc/mechanical.bg

# A table CSV of a part found on BGDRAW_PATH is read beside the part.
printf '0, 5\n1, 5\n' >far/volts.csv
printf 'submodel Src\n  port p\n  Se E = table(t, "volts.csv")\n  bond E -> p\nend\n' >far/src.bg
printf 'use "src.bg"\nSrc S\nR R1 = 1\nbond S.p -> R1\n' >doc/t.bg
BGDRAW_PATH=far "$BGDRAW" doc/t.bg -q -o t.svg -M t.d; check "use: a part on BGDRAW_PATH reads its table beside it" $?
grep -q "far/volts.csv" t.d; check "-M: the part's table listed" $?

# -M: every used file, through other used files too, and each once.
mkdir -p mk/parts/deep
printf 'use "deep/c.bg"\nsubmodel B\n  port p\n  C Cb = 1\n  bond p -> Cb\nend\n' >mk/parts/b.bg
printf 'submodel Cc\n  port p\n  I Ic = 1\n  bond p -> Ic\nend\n' >mk/parts/deep/c.bg
printf 'use "parts/b.bg"\nuse "parts/deep/c.bg"\nSe U = 1\n0 j\nB b1\nCc c1\nbond U -> j\nbond j -> b1.p\nbond j -> c1.p\n' >mk/a.bg
"$BGDRAW" mk/a.bg -q -o mk/a.svg -M mk/a.d
head -1 mk/a.d | grep -qx 'mk/a.svg: mk/a.bg mk/parts/b.bg mk/parts/deep/c.bg [^ ]*default.style'
cs_=$?; check "-M: the model, the used file and the file it uses, once each ($(head -1 mk/a.d))" $cs_
grep -qx 'mk/parts/deep/c.bg:' mk/a.d; check "-M: an empty rule for the nested used file" $?
cat >mk/Makefile <<EOF
a.svg: a.bg
	"$BGDRAW" a.bg -q -o a.svg -M a.d
-include a.d
EOF
rm -f mk/a.svg mk/a.d
make -s -C mk >/dev/null 2>&1 && make -s -q -C mk; check "make: up to date after the build" $?
sleep 1; echo "# edited" >>mk/parts/deep/c.bg
make -s -q -C mk; st=$?
check "make: editing the file a used file uses makes the figure out of date (make -q: $st)" $((st != 1))

# --stdin-name: the name in diagnostics, the folder for used files.
printf 'use "parts/b.bg"\nSe U = 1\nB b1\nbond U -> b1.p\nbond U -> X\n' >in.bg
(cd mk && "$BGDRAW" - --stdin-name page.rst --check <../in.bg 2>../err.txt); st=$?
[ $st -eq 1 ] && grep -q "^page.rst:5:11: error: undefined name 'X'" err.txt && ! grep -q "<stdin>" err.txt
check "--stdin-name: diagnostics name the file (status $st)" $?
"$BGDRAW" - --stdin-name mk/page.rst --check <in.bg 2>err.txt
grep -q "^mk/page.rst:5:11: error: undefined name 'X'" err.txt && ! grep -q "cannot find used file" err.txt
check "--stdin-name: used files are found from the named file's folder" $?
"$BGDRAW" - --check <in.bg 2>err.txt
grep -q "^<stdin>:1:5: error: cannot find used file 'parts/b.bg'; looked in '.'" err.txt
check "without --stdin-name: <stdin>, the working directory" $?
sed -i 's/bond U -> X//' in.bg
"$BGDRAW" - --stdin-name mk/page.rst -o s.svg -M s.d <in.bg
head -1 s.d | grep -qx 's.svg: mk/parts/b.bg mk/parts/deep/c.bg [^ ]*default.style'
cs_=$?; check "--stdin-name with -M: the used files, not the named file ($(head -1 s.d))" $cs_
"$BGDRAW" doc/m.bg --stdin-name x.bg --check 2>err.txt; st=$?
[ $st -eq 2 ] && grep -q "stdin-name names standard input" err.txt; check "--stdin-name with a model file: usage error" $?
"$BGDRAW" - --stdin-name= --check <in.bg 2>err.txt; st=$?
[ $st -eq 2 ]; check "--stdin-name with an empty name: usage error" $?
finish
