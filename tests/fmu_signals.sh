#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# An interrupted FMU build leaves nothing behind (issue 28): with a stand-in
# compiler ($CC, a script that records its pid and its child's and waits) the
# build is stopped by SIGINT, SIGTERM and SIGHUP while it compiles; bgdraw
# dies of that signal (status 128 + n), its private folder bgdraw-fmu-* is
# gone from $TMPDIR, and the compiler and its child are gone too, also when
# the compiler ignores SIGTERM (killed after 2 s). A compiler that fails with
# its errors relayed into a closed pipe leaves no folder either. -v says what
# is being compiled. A real build still gives an archive.
# Usage: bash tests/fmu_signals.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp"
mkdir scratch
export TMPDIR=$tmp/scratch
cp "$root/examples/rlc.bg" rlc.bg
cat > slowcc <<EOF2
#!/usr/bin/env bash
\${IGNORE_TERM:+trap '' TERM}
echo \$\$ > $tmp/cc.pid
sleep 300 &
echo \$! > $tmp/child.pid
wait
EOF2
chmod +x slowcc
# running (a zombie waiting for an init that does not reap is gone)
alive() { local s; s=$(ps -o stat= -p "$1" 2>/dev/null) && [ "${s#Z}" = "$s" ]; }
for spec in INT:2 TERM:15 HUP:1 TERM_IGNORED:15; do
  sig=${spec%%:*} n=${spec#*:}
  rm -f cc.pid child.pid
  ign=""
  [ "$sig" = TERM_IGNORED ] && sig=TERM ign=1
  IGNORE_TERM=$ign CC=$tmp/slowcc "$BGDRAW" rlc.bg -o rlc.fmu -v 2>err &
  pid=$!
  for _ in $(seq 1 300); do [ -s child.pid ] && break; sleep 0.1; done
  [ -s child.pid ]; check "$spec: the compiler started" $?
  cc=$(cat cc.pid 2>/dev/null) child=$(cat child.pid 2>/dev/null)
  ls -d scratch/bgdraw-fmu-* > /dev/null 2>&1; check "$spec: the build folder exists while compiling" $?
  kill -$sig $pid
  wait $pid; st=$?
  check "$spec: bgdraw dies of SIG$sig (status $st)" $((st != 128 + n))
  [ -z "$(ls -A scratch)" ]; cs_=$?; check "$spec: no temporary left in TMPDIR ($(ls scratch | tr '\n' ' '))" $cs_
  sleep 0.2
  ! alive "$cc" && ! alive "$child"; check "$spec: the compiler and its child are gone" $?
  [ ! -e rlc.fmu ]; check "$spec: no archive written" $?
  grep -q "^bgdraw: compiling the FMU's library ([0-9]* bytes of C) in $tmp/scratch/bgdraw-fmu-.*: $tmp/slowcc -shared -fPIC -O2 -o rlc.so rlc.c rlc_fmi2.c -lm$" err
  check "$spec: -v says what is compiled, where" $?
done
[ -n "$cc" ] && kill -9 "$cc" "$child" 2>/dev/null # a failed check must not leave them

# a compiler whose errors go into a closed pipe
printf '#!/usr/bin/env bash\nfor i in $(seq 1 20000); do echo "error: line $i" >&2; done\nexit 1\n' > badcc
chmod +x badcc
CC=$tmp/badcc "$BGDRAW" rlc.bg -o rlc.fmu 2>&1 | head -c 10 > /dev/null
[ -z "$(ls -A scratch)" ]; check "closed pipe: no temporary left" $?
[ ! -e rlc.fmu ]; check "closed pipe: no archive" $?

# a real build
"$BGDRAW" rlc.bg -o rlc.fmu; st=$?
check "a real build exits 0 (got $st)" $st
python3 -c 'import zipfile,sys; z=zipfile.ZipFile("rlc.fmu"); sys.exit(0 if "binaries/linux64/rlc.so" in z.namelist() else 1)'
check "a real build: the archive holds the library" $?
[ -z "$(ls -A scratch)" ]; check "a real build: no temporary left" $?
finish
