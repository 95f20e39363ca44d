#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# cmake --install into a temporary prefix (docs/install.md): the installed
# bgdraw runs with the source and build trees out of sight (a private mount
# namespace puts empty folders over them) and the prefix moved elsewhere, finds
# --style print beside itself, and a ten-line C program links against the
# installed libbgdraw with pkg-config and gets the right numbers. Also: the man
# page describes every option of --help, bash completion completes them.
# Usage: bash tests/install.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
BUILD=$(dirname "$BGDRAW")
ROOT=$PWD

cmake --install "$BUILD" --prefix "$tmp/p" >"$tmp/install.log" 2>&1; st=$?
check "cmake --install (got $st)" $st
for f in bin/bgdraw share/bgdraw/styles/print.style share/man/man1/bgdraw.1 \
         share/bash-completion/completions/bgdraw include/bgdraw.h include/bgdraw_version.h \
         share/doc/bgdraw/cli.md share/doc/bgdraw/LICENSE share/doc/bgdraw/NEWS.md \
         share/bgdraw/contrib/sphinx/bgdraw_sphinx.py share/bgdraw/contrib/mkdocs/bgdraw_mkdocs.py \
         share/bgdraw/contrib/pandoc/bgdraw.lua share/bgdraw/contrib/Makefile.example; do
  [ -f "$tmp/p/$f" ]; check "installed $f" $?
done
pc=$(find "$tmp/p" -name bgdraw.pc | head -1)
lib=$(find "$tmp/p" -name 'libbgdraw.so' | head -1)
[ -n "$pc" ] && [ -n "$lib" ]; check "installed libbgdraw.so and bgdraw.pc" $?
# the render module, where the executable looks for it (src/cli/cli_render.h)
module=$(find "$tmp/p" -name bgdraw_render.so | head -1)
[ "$(dirname "$module")" = "$(dirname "$lib")/bgdraw" ]; check "installed bgdraw_render.so in LIBDIR/bgdraw (got '$module')" $?
objcopy --strip-debug "$tmp/p/bin/bgdraw" "$tmp/exe.nodebug" && objcopy --strip-debug "$lib" "$tmp/lib.nodebug"
objcopy --strip-debug "$module" "$tmp/module.nodebug"
! grep -qF "$ROOT" "$tmp/exe.nodebug" "$tmp/lib.nodebug" "$tmp/module.nodebug"
check "no path of the source tree in the installed code (debug info aside)" $?

# move the prefix: everything is found relative to the executable / library
mv "$tmp/p" "$tmp/q"
pc=${pc/$tmp\/p/$tmp/q}; lib=${lib/$tmp\/p/$tmp/q}
cp examples/rlc.bg "$tmp/rlc.bg"
sed 's#use "../../lib/mechanical.bg"#use "mechanical.bg"#' examples/components/motor_drive_lib.bg >"$tmp/drive.bg"
"$BGDRAW" "$tmp/rlc.bg" --style print -o "$tmp/want.svg"
"$BGDRAW" "$tmp/rlc.bg" -o "$tmp/default.svg"

# the C program: parse, analyse, render through the public header
cat >"$tmp/prog.c" <<'EOF'
#include <bgdraw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
int main(int argc, char **argv) {
  char *err = NULL, *svg = NULL; size_t n = 0;
  bg_api_model *m = bg_api_load_file(argv[1], &err);
  if (!m) { fputs(err, stderr); return 1; }
  int ok = bg_api_render(m, "svg", "print", NULL, &svg, &n, &err) == 0;
  printf("%s %d %d %d %d\n", bg_api_name(m), bg_api_count(m, "bonds"), bg_api_count(m, "states"), ok, ok && strstr(svg, "<svg") != NULL);
  fwrite(svg, 1, n, fopen(argv[2], "wb"));
  free(svg); bg_api_free(m); return argc < 3;
}
EOF
PKG_CONFIG_PATH=$(dirname "$pc") cc -std=c11 -Wall -Wextra -o "$tmp/prog" "$tmp/prog.c" \
  $(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --cflags --libs bgdraw) 2>"$tmp/cc.err"
check "the C program compiles and links with pkg-config bgdraw" $?

# docs/library.md's complete program (its first C block) and CMake file
# (its CMake block): built with pkg-config and with find_package(bgdraw)
awk '/^```c$/{on=1; next} /^```$/{if (on) exit} on' docs/library.md >"$tmp/rlcinfo.c"
mkdir -p "$tmp/cm"
awk '/^```cmake$/{on=1; next} /^```$/{if (on) exit} on' docs/library.md >"$tmp/cm/CMakeLists.txt"
cp "$tmp/rlcinfo.c" "$tmp/cm/"
[ -s "$tmp/rlcinfo.c" ] && grep -q find_package "$tmp/cm/CMakeLists.txt"
check "docs/library.md has the example program and its CMake file" $?
cc -std=c11 -Wall -Wextra -Werror -o "$tmp/rlcinfo" "$tmp/rlcinfo.c" \
  $(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --cflags --libs bgdraw) 2>"$tmp/cc2.err"
check "docs/library.md's program compiles with pkg-config, no warning" $?
[ -s "$tmp/cc2.err" ] && cat "$tmp/cc2.err"
cmake -S "$tmp/cm" -B "$tmp/cm/build" -DCMAKE_PREFIX_PATH="$tmp/q" >"$tmp/cm.log" 2>&1 &&
  cmake --build "$tmp/cm/build" >>"$tmp/cm.log" 2>&1
st=$?; check "docs/library.md's program builds with find_package(bgdraw) (got $st)" $st
[ $st -eq 0 ] || tail -20 "$tmp/cm.log"
cp "$tmp/cm/build/rlcinfo" "$tmp/rlcinfo_cmake" 2>/dev/null

# run everything with the source and build trees hidden
hide="mount -t tmpfs none '$ROOT'"
case $BUILD in "$ROOT"/*) ;; *) hide="$hide && mount -t tmpfs none '$BUILD'" ;; esac
cat >"$tmp/run.sh" <<EOF
set -e
cd '$tmp'
[ "\${BG_TREES_HIDDEN:-1}" = 0 ] || [ ! -e '$ROOT/CMakeLists.txt' ]
unset BGDRAW_STYLE_DIR
'$tmp/q/bin/bgdraw' rlc.bg --style print -o got.svg
LD_LIBRARY_PATH='$(dirname "$lib")' ./prog rlc.bg lib.svg > prog.out
unset BGDRAW_PATH
'$tmp/q/bin/bgdraw' drive.bg -q -o drive.svg -M drive.d
LD_LIBRARY_PATH='$(dirname "$lib")' ./prog drive.bg drive_lib.svg > prog_drive.out
LD_LIBRARY_PATH='$(dirname "$lib")' ./rlcinfo rlc.bg info.svg > info.out
LD_LIBRARY_PATH='$(dirname "$lib")' ./rlcinfo_cmake rlc.bg info_cmake.svg > info_cmake.out
EOF
if unshare -m true 2>/dev/null; then
  unshare -m sh -c "$hide && sh '$tmp/run.sh'" 2>"$tmp/err"; st=$?
else # no mount namespaces here: the trees stay, the installed files must not use them
  echo "install.sh: no mount namespace: running with the source tree in place" >&2
  BG_TREES_HIDDEN=0 sh "$tmp/run.sh" 2>"$tmp/err"; st=$?
fi
check "installed bgdraw and the program run without the source tree (got $st)" $st
[ $st -eq 0 ] || cat "$tmp/err"
cmp -s "$tmp/want.svg" "$tmp/got.svg"; check "installed bgdraw --style print = the build's --style print" $?
! cmp -s "$tmp/default.svg" "$tmp/got.svg"; check "--style print differs from the default style" $?
[ "$(cat "$tmp/prog.out" 2>/dev/null)" = "rlc 4 2 1 1" ]
cs_=$?; check "the C program: name rlc, 4 bonds, 2 states, an SVG (got '$(cat "$tmp/prog.out" 2>/dev/null)')" $cs_
cmp -s "$tmp/want.svg" "$tmp/lib.svg"; check "libbgdraw's print-style SVG = bgdraw's" $?
# use "mechanical.bg": the installed component library, for bgdraw and libbgdraw
grep -q "^drive.svg: drive.bg $tmp/q/share/bgdraw/lib/mechanical.bg " "$tmp/drive.d"
cs_=$?; check "installed bgdraw finds use \"mechanical.bg\" in PREFIX/share/bgdraw/lib ($(head -1 "$tmp/drive.d" 2>/dev/null))" $cs_
[ "$(cut -d' ' -f1,2 "$tmp/prog_drive.out" 2>/dev/null)" = "motor_drive_lib 22" ]
cs_=$?; check "libbgdraw finds it too (got '$(cat "$tmp/prog_drive.out" 2>/dev/null)')" $cs_
# what docs/library.md's program prints of rlc: the strokes, the index, the
# last row (a series RLC after 2 ms: the capacitor charged to 1 V), and the
# same SVG as bgdraw --style print
printf '%s\n' 'rlc: 4 bonds, 2 states' 'bond 1 U -> j, stroke at the to end' \
  'bond 2 j -> R1, stroke at the from end' 'bond 3 j -> L1, stroke at the to end' \
  'bond 4 j -> C1, stroke at the from end' 'form ode, index 0 predicted, 0 numeric' >"$tmp/info.want"
head -6 "$tmp/info.out" 2>/dev/null | cmp -s - "$tmp/info.want"
cs_=$?; check "docs/library.md's program prints rlc's strokes and index (got '$(head -6 "$tmp/info.out" 2>/dev/null)')" $cs_
tail -1 "$tmp/info.out" 2>/dev/null | grep -qE '^t = 0.002: C1.e = 1(\.0+)? L1.f = -?[0-9.e+-]+$'
cs_=$?; check "docs/library.md's program prints the last row (got '$(tail -1 "$tmp/info.out" 2>/dev/null)')" $cs_
cmp -s "$tmp/want.svg" "$tmp/info.svg"; check "docs/library.md's program writes bgdraw's SVG" $?
cmp -s "$tmp/info.out" "$tmp/info_cmake.out" && cmp -s "$tmp/info.svg" "$tmp/info_cmake.svg"
check "the find_package build gives the same output" $?

# a packager's build: -DBUILD_TESTING=OFF configures the program, the
# renderers and the library, and no test or fuzzer
cmake -S "$ROOT" -B "$tmp/notests" -DBUILD_TESTING=OFF >"$tmp/notests.log" 2>&1 &&
  cmake --build "$tmp/notests" --target help >"$tmp/targets" 2>&1
grep -q "bgdraw$" "$tmp/targets" && grep -q "libbgdraw$" "$tmp/targets" && ! grep -q "test_\|fuzz_" "$tmp/targets"
check "-DBUILD_TESTING=OFF: bgdraw and libbgdraw, no test target" $?
# the installed man page carries the one version, and its copyright
v=$("$BGDRAW" --version | head -1 | awk '{print $2}')
grep -q "^.TH BGDRAW 1 \"2026\" \"bgdraw $v\"" "$tmp/q/share/man/man1/bgdraw.1" &&
  grep -q "BSD 3-Clause" "$tmp/q/share/man/man1/bgdraw.1"
check "installed man page: version $v and the licence" $?
# the man page describes every long option of --help
sed 's/\\-/-/g' docs/bgdraw.1 >"$tmp/man.txt"
missing=""
for o in $("$BGDRAW" --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
  grep -qF -- "$o" "$tmp/man.txt" || missing="$missing $o"
done
[ -z "$missing" ]; check "man page describes every option of --help (missing:$missing)" $?

# bash completion: option values and option names as --help has them
out=$(bash -c '. contrib/bash-completion/bgdraw
  COMP_WORDS=(bgdraw m.bg --causality ""); COMP_CWORD=3; _bgdraw; echo "${COMPREPLY[*]}"
  COMP_WORDS=(bgdraw --dep); COMP_CWORD=1; _bgdraw; echo "${COMPREPLY[*]}"')
[ "$out" = $'scap relaxed vandijk lagrange\n--depfile' ]; check "bash completion (got '$out')" $?
missing=""
for o in $("$BGDRAW" --help | grep -o -- '--[a-z][a-z-]*' | sort -u); do
  grep -qw -- "$o" contrib/bash-completion/bgdraw || missing="$missing $o"
done
[ -z "$missing" ]; check "bash completion knows every option of --help (missing:$missing)" $?

finish
