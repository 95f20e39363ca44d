#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Outputs never damage what they point at, and inputs are read safely
# (docs/cli.md "Output files" and "Input files"; issues 13 and 22):
# - an output that is an input (the model, a table CSV, a style file; by
#   name, by symlink, by hard link) is refused with status 2, the input
#   unchanged;
# - a symlink is written through (target replaced, link kept, also a
#   dangling one); a regular target keeps its mode; a new file gets the
#   umask's mode; no temporary file is left behind;
# - character devices (mknod'd null/full), a FIFO and a Unix socket are
#   written in place and stay what they were; a write error (full, or stdout
#   on full) exits 4; a block device is refused;
# - a model that is a character device, a FIFO or bigger than 64 MiB is
#   refused with a reason (status 1), without reading it.
# Usage: bash tests/files_safe.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
cd "$tmp"
cp "$root/examples/rlc.bg" m.bg
sum0=$(cksum < m.bg)

# ------------------------------------------------------ outputs that are inputs
"$BGDRAW" m.bg -T svg -o m.bg 2>err; st=$?
check "-o model.bg exits 2 (got $st)" $((st != 2))
grep -q "output 'm.bg' is one of the run's input files" err; check "-o model.bg: message" $?
ln -s m.bg alias.svg; ln m.bg hard.json
"$BGDRAW" m.bg -o alias.svg 2>/dev/null; st=$?
check "symlink to the model exits 2 (got $st)" $((st != 2))
"$BGDRAW" m.bg -o ok.svg -o hard.json 2>/dev/null; st=$?
check "hard link to the model exits 2 (got $st)" $((st != 2))
[ ! -e ok.svg ]; check "refused before anything is written" $?
[ "$(cksum < m.bg)" = "$sum0" ] && [ -L alias.svg ]; check "model unchanged" $?

mkdir sub && cp "$root/tests/data/table_ramp.csv" sub/data.csv
cat > sub/t.bg <<'M'
model t
Se U = table(t, "data.csv")
R R1 = 1
bond U -> R1
M
tsum=$(cksum < sub/data.csv)
"$BGDRAW" sub/t.bg -o sub/data.csv 2>err; st=$?
check "-o TABLE.csv exits 2 (got $st)" $((st != 2))
[ "$(cksum < sub/data.csv)" = "$tsum" ]; check "table unchanged" $?
cp "$root/styles/print.style" my.style
"$BGDRAW" m.bg --style my.style -T svg -o my.style 2>/dev/null; st=$?
check "-o STYLE exits 2 (got $st)" $((st != 2))
cmp -s my.style "$root/styles/print.style"; check "style unchanged" $?

# ------------------------------------------------------------ regular files
echo old > target.json; chmod 640 target.json
ln -s target.json link.json
"$BGDRAW" m.bg -o link.json; st=$?
check "write through a symlink exits 0 (got $st)" $st
[ -L link.json ] && grep -q '"bgdraw-analysis"' target.json; check "link kept, target written" $?
[ "$(stat -c %a target.json)" = 640 ]; cs_=$?; check "target keeps mode 640 (got $(stat -c %a target.json))" $cs_
ln -s newdir.json dangling.json
"$BGDRAW" m.bg -o dangling.json && [ -L dangling.json ] && [ -f newdir.json ]
check "a dangling symlink creates its target" $?
(umask 027 && "$BGDRAW" m.bg -o fresh.svg)
[ "$(stat -c %a fresh.svg)" = 640 ]; cs_=$?; check "new file follows the umask (got $(stat -c %a fresh.svg))" $cs_
[ -z "$(ls -A | grep '^\.')" ]; check "no temporary file left" $?

# --------------------------------------------------- devices, FIFOs, sockets
# Device nodes of our own (root in CI); without CAP_MKNOD, symlinks to the system's.
mknod -m 666 null c 1 3 2>/dev/null || ln -s /dev/null null
mknod -m 666 full c 1 7 2>/dev/null || ln -s /dev/full full
mknod -m 666 zero c 1 5 2>/dev/null || ln -s /dev/zero zero
"$BGDRAW" m.bg -T svg -o null; st=$?
check "-o null exits 0 (got $st)" $st
[ -c null ]; check "null is still a character device" $?
"$BGDRAW" m.bg -T svg -o full 2>err; st=$?
check "-o full exits 4 (got $st)" $((st != 4))
grep -q "No space left on device" err; check "-o full: message" $?
[ -c full ]; check "full is still a character device" $?
"$BGDRAW" m.bg --equations text > full 2>err; st=$?
check "--equations text > full exits 4 (got $st)" $((st != 4))
"$BGDRAW" m.bg --check > full 2>/dev/null; st=$?
check "--check > full exits 4 (got $st)" $((st != 4))
if mknod blk b 7 200 2>/dev/null; then
  "$BGDRAW" m.bg -T svg -o blk 2>err; st=$?
  check "a block device is refused with 4 (got $st)" $((st != 4))
  grep -q "block device" err && [ -b blk ]; check "block device: message, node kept" $?
fi
mkfifo fifo
cat fifo > from_fifo & reader=$!
"$BGDRAW" m.bg -T json -o fifo; st=$?
wait $reader
check "-o FIFO exits 0 (got $st)" $st
[ -p fifo ] && grep -q '"bgdraw-analysis"' from_fifo; check "FIFO kept, reader got the JSON" $?
python3 - "$BGDRAW" <<'PY'; check "-o SOCKET: written in place" $?
import os, socket, subprocess, stat, sys
s = socket.socket(socket.AF_UNIX); s.bind("sock"); s.listen(1)
p = subprocess.Popen([sys.argv[1], "m.bg", "-T", "json", "-o", "sock"])
c, _ = s.accept(); data = b""
while True:
    x = c.recv(65536)
    if not x: break
    data += x
ok = p.wait() == 0 and b'"bgdraw-analysis"' in data and stat.S_ISSOCK(os.lstat("sock").st_mode)
sys.exit(0 if ok else 1)
PY

# ------------------------------------------------------------------ inputs
for bad in zero fifo; do
  timeout 10 "$BGDRAW" $bad --check 2>err; st=$?
  check "model '$bad' exits 1 (got $st)" $((st != 1))
  grep -q "not a regular file" err; check "model '$bad': not a regular file" $?
done
truncate -s 65M big.bg
timeout 10 "$BGDRAW" big.bg --check 2>err; st=$?
check "a model above 64 MiB exits 1 (got $st)" $((st != 1))
grep -q "larger than bgdraw's limit of 64 MiB" err; check "too big: message" $?
cat > sub/z.bg <<'M'
model z
Se U = table(t, "zero")
R R1 = 1
bond U -> R1
M
ln -s ../zero sub/zero
timeout 10 "$BGDRAW" sub/z.bg --check 2>err; st=$?
check "a table that is /dev/zero exits 1 (got $st)" $((st != 1))
grep -q "cannot read table file 'zero'.*not a regular file" err; check "table: not a regular file" $?

echo "files_safe: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
