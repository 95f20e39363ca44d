#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# -o NAME.fmu (docs/export.md, FMU): an FMI 2.0 Model Exchange archive.
# - rlc.bg (an ODE) exports; the archive's CRCs check (python3 zipfile) and it
#   holds exactly modelDescription.xml, sources/rlc.{h,c}, sources/rlc_fmi2.c
#   and binaries/linux64/rlc.so;
# - modelDescription.xml, field by field (xmllint --xpath): fmiVersion, names,
#   GUID format, modelIdentifier, params (tunable, start values), states and
#   their derivatives (derivative = the state's index), outputs, ModelStructure;
# - tests/export/fmu_import.c dlopens the library, runs the fmi2 calling
#   sequence and integrates with RK4 (100 steps per output interval); its
#   outputs match bgdraw's CSV to 1e-6 of each column's range, also with R0
#   set to 25 through fmi2SetReal (against --set R0=25); a wrong GUID and a
#   co-simulation instantiation are refused;
# - the archive is byte-identical on a rerun; --prefix names the identifier;
# - a DAE (hydraulic_bridge) is refused with exit 1 and nothing written; a
#   missing compiler is exit 4 with nothing written and no temporary folder left.
# Usage: bash tests/fmu_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
BGDRAW=${1:?usage: fmu_cli.sh PATH_TO_BGDRAW}
. tests/export/harness.sh
"$BGDRAW" "$tmp/rlc.bg" -q --simulate -o "$tmp/rlc.csv"; check "rlc simulates" $?
"$BGDRAW" "$tmp/rlc.bg" -q --simulate --set R0=25 -o "$tmp/rlc_r25.csv"; check "rlc --set R0=25 simulates" $?

"$BGDRAW" "$tmp/rlc.bg" -q -o "$tmp/rlc.fmu"; check "-o rlc.fmu exit 0" $?
python3 - "$tmp/rlc.fmu" "$tmp/x" <<'PY'
import sys, zipfile
z = zipfile.ZipFile(sys.argv[1])
assert z.testzip() is None, "a member's CRC is wrong"
names = [i.filename for i in z.infolist()]
want = ["modelDescription.xml", "sources/rlc.h", "sources/rlc.c", "sources/rlc_fmi2.c", "binaries/linux64/rlc.so"]
assert names == want, names
z.extractall(sys.argv[2])
PY
check "the archive's members and CRCs" $?
md="$tmp/x/modelDescription.xml"
xp() { xmllint --xpath "$1" "$md" 2>/dev/null; }
field() { # field NAME XPATH EXPECTED
  local got; got=$(xp "$2"); [ "$got" = "$3" ]; local st=$?
  [ $st -ne 0 ] && echo "  $1: got '$got', want '$3'"
  check "modelDescription: $1" $st
}
xmllint --noout "$md"; check "modelDescription.xml is well-formed" $?
field fmiVersion 'string(/fmiModelDescription/@fmiVersion)' 2.0
field modelName 'string(/fmiModelDescription/@modelName)' rlc
field events 'string(/fmiModelDescription/@numberOfEventIndicators)' 0
field modelIdentifier 'string(/fmiModelDescription/ModelExchange/@modelIdentifier)' rlc
guid=$(xp 'string(/fmiModelDescription/@guid)')
[[ "$guid" =~ ^\{[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}\}$ ]]; check "guid $guid" $?
field stopTime 'string(//DefaultExperiment/@stopTime)' 0.002
field "number of variables" 'count(//ScalarVariable)' 10
field "parameters" 'count(//ScalarVariable[@causality="parameter" and @variability="tunable"])' 4
field "R0 start" 'string(//ScalarVariable[@name="R0"]/Real/@start)' 10
field "C0 start" 'string(//ScalarVariable[@name="C0"]/Real/@start)' 1e-06
field "R0 value reference" 'string(//ScalarVariable[@name="R0"]/@valueReference)' 1
field "state L1.p" 'string(//ScalarVariable[@name="L1.p"]/@variability)' continuous
field "der(L1.p) is the derivative of variable 5" 'string(//ScalarVariable[@name="der(L1.p)"]/Real/@derivative)' 5
field "der(C1.q) is the derivative of variable 6" 'string(//ScalarVariable[@name="der(C1.q)"]/Real/@derivative)' 6
field "variable 6 is C1.q" 'string(//ModelVariables/ScalarVariable[6]/@name)' C1.q
field "outputs" 'count(//ScalarVariable[@causality="output"])' 2
field "C1.e value reference" 'string(//ScalarVariable[@name="C1.e" and @causality="output"]/@valueReference)' 8
field "L1.f value reference" 'string(//ScalarVariable[@name="L1.f" and @causality="output"]/@valueReference)' 9
field "Outputs" 'count(//Outputs/Unknown)' 2
field "Outputs index" 'string(//Outputs/Unknown[1]/@index)' 9
field "Derivatives" 'count(//Derivatives/Unknown)' 2
field "Outputs index 2" 'string(//Outputs/Unknown[2]/@index)' 10
field "Derivatives index 1" 'string(//Derivatives/Unknown[1]/@index)' 7
field "Derivatives index" 'string(//Derivatives/Unknown[2]/@index)' 8
field "InitialUnknowns" 'count(//InitialUnknowns/Unknown)' 6

cc -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror tests/export/fmu_import.c -o "$tmp/import" -ldl
check "the test importer compiles" $?
"$tmp/import" "$tmp/x/binaries/linux64/rlc.so" "$guid" 2 "$tmp/rlc.csv" "$tmp/f.csv" 8,9 2>"$tmp/ierr"
check "the importer runs the FMU" $?
grep -q "GUID does not match" "$tmp/ierr"; check "a wrong GUID is refused with a logged reason" $?
cmp_csv "$tmp/rlc.csv" "$tmp/f.csv" 1e-6 "FMU + RK4 vs bgdraw (rlc)"; check "the FMU's outputs match bgdraw's" $?
"$tmp/import" "$tmp/x/binaries/linux64/rlc.so" "$guid" 2 "$tmp/rlc_r25.csv" "$tmp/f25.csv" 8,9 1=25 2>/dev/null
check "the importer sets R0 = 25 through fmi2SetReal" $?
cmp_csv "$tmp/rlc_r25.csv" "$tmp/f25.csv" 1e-6 "FMU with R0 = 25 vs --set R0=25"; check "a parameter set at run time" $?
! cmp -s "$tmp/f.csv" "$tmp/f25.csv"; check "the parameter changes the response" $?

"$BGDRAW" "$tmp/rlc.bg" -q -o "$tmp/again.fmu" && cmp -s "$tmp/rlc.fmu" "$tmp/again.fmu"
check "a rerun writes the same bytes" $?
"$BGDRAW" "$tmp/rlc.bg" -q --prefix m1 -o "$tmp/m1.fmu" &&
  python3 -c "import sys, zipfile; n = zipfile.ZipFile(sys.argv[1]).namelist(); assert 'binaries/linux64/m1.so' in n, n" "$tmp/m1.fmu"
check "--prefix m1: binaries/linux64/m1.so" $?

"$BGDRAW" examples/hydraulic_bridge.bg -q -o "$tmp/hb.fmu" 2>"$tmp/err"; st=$?
[ "$st" = 3 ] && grep -q "export refused: .*is a DAE" "$tmp/err" && [ ! -e "$tmp/hb.fmu" ]; check "a DAE: refused with status 3, nothing written (got $st)" $?
mkdir "$tmp/t"
CC=/nonexistent/cc TMPDIR="$tmp/t" "$BGDRAW" "$tmp/rlc.bg" -q -o "$tmp/nocc.fmu" 2>"$tmp/err"; st=$?
[ "$st" = 4 ] && grep -q "cannot run the C compiler '/nonexistent/cc'" "$tmp/err" && [ ! -e "$tmp/nocc.fmu" ] &&
  [ -z "$(ls -A "$tmp/t")" ]; check "no compiler: exit 4, nothing written, no temporary folder left" $?
if [ "$fail" -ne 0 ]; then echo "$fail check(s) failed"; exit 1; fi
echo "all FMU checks passed"
