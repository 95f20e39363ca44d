#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Parameter studies on the command line (docs/study.md): the same bytes from
# 1 and 2 threads; the study split into jobs run by GNU parallel (and the Slurm
# array script run task by task) and merged gives the single-machine study's
# table and plots byte for byte; a merge with a part missing or from another
# study is refused; failed runs are in the table; usage errors name the fix.
# Usage: bash tests/study_cli.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
PATH=$(dirname "$BGDRAW"):$PATH # the jobs call bgdraw by name, as on a cluster
export PATH
m=examples/rlc.bg
study=(--sweep R0=5:80:7 --sweep L0=1e-3,2e-3 --collect C1.e:max --collect C1.e:tmax
       --collect C1.e:cross=0.5)

"$BGDRAW" "$m" "${study[@]}" -j 1 --study "$tmp/one.csv" --study "$tmp/one.json" \
  --study "$tmp/one.svg" --family "$tmp/fam1.svg"
check "sweep on one thread" $?
"$BGDRAW" "$m" "${study[@]}" -j 2 --study "$tmp/two.csv" --study "$tmp/two.json" \
  --study "$tmp/two.svg" --family "$tmp/fam2.svg"
check "sweep on two threads" $?
for f in csv json svg; do cmp -s "$tmp/one.$f" "$tmp/two.$f"; check "same $f from 1 and 2 threads" $?; done
cmp -s "$tmp/fam1.svg" "$tmp/fam2.svg"; check "same family plot from 1 and 2 threads" $?
[ "$(wc -l <"$tmp/one.csv")" -eq 15 ] && head -1 "$tmp/one.csv" | grep -qx \
  'run,R0,L0,status,C1.e:max,C1.e:tmax,C1.e:cross=0.5,reason'
check "one row per run and the header" $?
# the grid: the first param slowest; the legend names each run
sed -n 2,3p "$tmp/one.csv" | cut -d, -f1-4 | tr '\n' ' ' | grep -qx '0,5,0.001,ok 1,5,0.002,ok '
check "grid order" $?
grep -q 'R0 = 80, L0 = 0.002' "$tmp/fam1.svg"; check "the family's legend" $?
grep -q 'C1.e: 12 of 14 runs' "$tmp/fam1.svg"; check "the family's title: the runs drawn of the study's" $?
grep -q 'C1.e:cross=0.5' "$tmp/one.svg"; check "the quantities' plot" $?

# split and merge: GNU parallel runs the job list, the merge gives the same bytes
"$BGDRAW" "$m" "${study[@]}" --split "3:$tmp/parts" --job-list "$tmp/jobs.txt" \
  --slurm "$tmp/study.sbatch"
check "split writes the jobs" $?
[ "$(wc -l <"$tmp/jobs.txt")" -eq 3 ] && grep -q -- "--runs 10:4 --study '$tmp/parts/part-000002.csv'" "$tmp/jobs.txt"
check "three jobs, the last with runs 10..13" $?
mkdir -p "$tmp/parts"
if command -v parallel >/dev/null; then
  parallel --will-cite --jobs 2 <"$tmp/jobs.txt"
  check "GNU parallel runs the jobs" $?
else
  echo "FAIL GNU parallel is not installed (bash tools/deps.sh --tests)"; fail=$((fail + 1))
fi
"$BGDRAW" "$m" "${study[@]}" --merge "$tmp/parts" --study "$tmp/merged.csv" \
  --study "$tmp/merged.json" --study "$tmp/merged.svg"
check "merge" $?
for f in csv json svg; do cmp -s "$tmp/one.$f" "$tmp/merged.$f"; check "merged $f = one machine's" $?; done
# the Slurm array script, task by task as Slurm would run it
bash -n "$tmp/study.sbatch" && grep -q '^#SBATCH --array=0-2$' "$tmp/study.sbatch"
check "the Slurm script" $?
mv "$tmp/parts" "$tmp/parallel_parts"
for k in 0 1 2; do SLURM_ARRAY_TASK_ID=$k SLURM_CPUS_PER_TASK=2 bash "$tmp/study.sbatch" || fail=$((fail + 1)); done
"$BGDRAW" "$m" "${study[@]}" --merge "$tmp/parts" --study "$tmp/slurm.csv"
cmp -s "$tmp/one.csv" "$tmp/slurm.csv"; check "the Slurm array's parts merge to the same table" $?
# a part missing, a part twice, a part of another study: refused
rm "$tmp/parts/part-000001.csv"
"$BGDRAW" "$m" "${study[@]}" --merge "$tmp/parts" --study "$tmp/x.csv" 2>"$tmp/err"
[ $? -eq 1 ] && grep -q 'runs are in no part (the first: run 5)' "$tmp/err" && [ ! -e "$tmp/x.csv" ]
check "a missing part is refused" $?
cp "$tmp/parts/part-000000.csv" "$tmp/parts/part-000009.csv"
"$BGDRAW" "$m" "${study[@]}" --merge "$tmp/parts" --study "$tmp/x.csv" 2>"$tmp/err"
[ $? -eq 1 ] && grep -q 'run 0 is in two parts' "$tmp/err"; check "a run in two parts is refused" $?
"$BGDRAW" "$m" --sweep R0=5:80:8 --sweep L0=1e-3,2e-3 --collect C1.e:max --collect C1.e:tmax \
  --collect C1.e:cross=0.5 --merge "$tmp/parallel_parts" --study "$tmp/x.csv" 2>"$tmp/err"
[ $? -eq 1 ] && grep -q 'not one of this study' "$tmp/err"; check "a part of another study is refused" $?

# Monte Carlo: the seed decides, the threads do not
mc=(tests/data/quarter_car.bg --monte-carlo 40 --seed 3 --vary 'v0=normal(0.5,0.05)'
    --vary 'ks=uniform(15000,17000)' --collect mb.f:max)
"$BGDRAW" "${mc[@]}" -j 1 --study "$tmp/mc1.csv" --family "$tmp/mc1.svg" &&
  "$BGDRAW" "${mc[@]}" -j 2 --study "$tmp/mc2.csv" --family "$tmp/mc2.svg"
check "Monte Carlo" $?
cmp -s "$tmp/mc1.csv" "$tmp/mc2.csv" && cmp -s "$tmp/mc1.svg" "$tmp/mc2.svg"
check "Monte Carlo: same bytes from 1 and 2 threads" $?
grep -q '95 % quantile' "$tmp/mc1.svg"; check "Monte Carlo envelope" $?
grep -q 'mb.f: envelope of 40 runs' "$tmp/mc1.svg"; check "the envelope's title says it is one" $?
"$BGDRAW" tests/data/quarter_car.bg --monte-carlo 40 --seed 4 --vary 'v0=normal(0.5,0.05)' \
  --vary 'ks=uniform(15000,17000)' --collect mb.f:max --study "$tmp/mc4.csv"
! cmp -s "$tmp/mc1.csv" "$tmp/mc4.csv"; check "another seed, other draws" $?

# a root locus: the poles are the table's columns, against the closed form
# -R/2L -+ sqrt((R/2L)^2 - 1/LC) (L = 1 mH, C = 1 uF); the plots are the same
# bytes from 1 and 2 threads and from the parts merged
rl=(--sweep R0=5:125:25 --collect poles)
"$BGDRAW" "$m" "${rl[@]}" -j 1 --study "$tmp/rl1.csv" --root-locus "$tmp/rl1.svg" \
  --bode-family "$tmp/bf1.svg" && "$BGDRAW" "$m" "${rl[@]}" -j 2 --study "$tmp/rl2.csv" \
  --root-locus "$tmp/rl2.svg" --bode-family "$tmp/bf2.svg"
check "root locus and Bode family" $?
cmp -s "$tmp/rl1.csv" "$tmp/rl2.csv" && cmp -s "$tmp/rl1.svg" "$tmp/rl2.svg" && cmp -s "$tmp/bf1.svg" "$tmp/bf2.svg"
check "root locus: same bytes from 1 and 2 threads" $?
head -1 "$tmp/rl1.csv" | grep -qx 'run,R0,status,pole1:re,pole1:im,pole2:re,pole2:im,reason'
check "the pole columns" $?
awk -F, 'function abs(x) { return x < 0 ? -x : x }
  NR > 1 { a = $2 / 2e-3; d = a * a - 1e9; tol = 1e-6
    if (d < 0) { r1 = -a; i1 = -sqrt(-d); r2 = -a; i2 = sqrt(-d) } else { r1 = -a - sqrt(d); i1 = 0; r2 = -a + sqrt(d); i2 = 0 }
    if (abs($4 - r1) > tol || abs($5 - i1) > tol || abs($6 - r2) > tol || abs($7 - i2) > tol) bad++; n++ }
  END { exit !(n == 25 && bad == 0) }' "$tmp/rl1.csv"
check "the poles are -R/2L -+ sqrt((R/2L)^2 - 1/LC)" $?
grep -q 'R0 = 125' "$tmp/bf1.svg"; check "the Bode family's legend" $?
[ "$(grep -c 'R0 = 125' "$tmp/bf1.svg")" -eq 1 ]; check "the Bode family's legend once, not in every panel" $?
"$BGDRAW" "$m" --sweep R0=5,50 --collect poles --family "$tmp/pf.svg" && grep -q 'L1.f' "$tmp/pf.svg"
check "a study of poles alone draws every output in its family" $?
"$BGDRAW" "$m" "${rl[@]}" --split "4:$tmp/rlparts" --job-list "$tmp/rljobs.txt" && mkdir -p "$tmp/rlparts" &&
  parallel --will-cite --jobs 2 <"$tmp/rljobs.txt" &&
  "$BGDRAW" "$m" "${rl[@]}" --merge "$tmp/rlparts" --study "$tmp/rlm.csv" --root-locus "$tmp/rlm.svg" \
    --bode-family "$tmp/bfm.svg"
check "root locus: split and merged" $?
cmp -s "$tmp/rl1.csv" "$tmp/rlm.csv" && cmp -s "$tmp/rl1.svg" "$tmp/rlm.svg" && cmp -s "$tmp/bf1.svg" "$tmp/bfm.svg"
check "root locus: the merge gives the same bytes" $?

# a study carried by the model (a `study` statement) gives the table of the
# same words on the command line; the command line's words replace the model's
"$BGDRAW" tests/data/rlc_study.bg --study "$tmp/ms.csv" -j 2 && "$BGDRAW" tests/data/rlc_study.bg \
  "${study[@]}" --collect poles --study "$tmp/cs.csv" -j 1
check "the model's own study" $?
cmp -s "$tmp/ms.csv" "$tmp/cs.csv"; check "the model's study = the same words on the command line" $?
"$BGDRAW" tests/data/rlc_study.bg --split "3:$tmp/mparts" --job-list "$tmp/mjobs.txt" && mkdir -p "$tmp/mparts" &&
  parallel --will-cite --jobs 2 <"$tmp/mjobs.txt" &&
  "$BGDRAW" tests/data/rlc_study.bg --merge "$tmp/mparts" --study "$tmp/mm.csv" && cmp -s "$tmp/ms.csv" "$tmp/mm.csv"
check "the model's own study split, run by GNU parallel and merged" $?
"$BGDRAW" tests/data/rlc_study.bg --sweep R0=5,6 --study "$tmp/ov.csv" &&
  head -1 "$tmp/ov.csv" | grep -qx 'run,R0,status,C1.e:max,C1.e:tmax,C1.e:cross=0.5,pole1:re,pole1:im,pole2:re,pole2:im,reason' &&
  [ "$(wc -l <"$tmp/ov.csv")" -eq 3 ]
check "--sweep replaces the model's sweeps, its collect lines stay" $?
"$BGDRAW" tests/data/rlc_study.bg --collect L1.f:max --study "$tmp/ov.csv" &&
  head -1 "$tmp/ov.csv" | grep -qx 'run,R0,L0,status,L1.f:max,reason'
check "--collect replaces the model's collect lines" $?
"$BGDRAW" tests/data/quarter_car_study.bg --study "$tmp/mmc.csv" &&
  "$BGDRAW" "${mc[@]}" --study "$tmp/cmc.csv" && cmp -s "$tmp/mmc.csv" "$tmp/cmc.csv"
check "the model's Monte Carlo study (draws and seed)" $?
"$BGDRAW" tests/data/quarter_car_study.bg --seed 4 --monte-carlo 40 --study "$tmp/mmc4.csv" &&
  cmp -s "$tmp/mmc4.csv" "$tmp/mc4.csv"
check "--seed and --monte-carlo replace the model's" $?
"$BGDRAW" tests/data/rlc_study.bg --seed 3 --study "$tmp/u.csv" 2>"$tmp/err"
[ $? -eq 2 ] && grep -q -- "--seed belongs to a Monte Carlo study" "$tmp/err"
check "usage: --seed with the model's sweep" $?
"$BGDRAW" "$m" --study "$tmp/u.csv" 2>"$tmp/err"
[ $? -eq 2 ] && grep -q "or a study statement in the model" "$tmp/err"
check "usage: no study in the model nor on the command line" $?
"$BGDRAW" tests/data/rlc_study.bg -o "$tmp/single.svg" && [ -s "$tmp/single.svg" ]
check "a model with a study still draws as a single run" $?

# the study in the PDF report: the section, the table's numbers against the
# closed form (the peak 1 + exp(-pi z / sqrt(1 - z^2)), z = R/2 sqrt(C/L), and
# the poles -R/2L -+ j sqrt(1/LC - (R/2L)^2), printed as the report prints
# numbers: %.4g with a minus sign), the family, the quantities, the root locus
if command -v pdftotext >/dev/null; then
  "$BGDRAW" "$m" --sweep R0=5:125:7 --collect C1.e:max --collect poles --report "$tmp/sr.pdf" \
    --bode-family "$tmp/sr_bode.svg"
  check "a study's report" $?
  pdftotext -layout "$tmp/sr.pdf" "$tmp/sr.txt"
  grep -q 'Parameter study' "$tmp/sr.txt" &&
    grep -q 'A sweep of R0 over 5:125:7 (7 values): 7 runs; 0 runs failed' "$tmp/sr.txt"
  check "the report's study section" $?
  want=$(awk 'BEGIN { R = 5; L = 1e-3; C = 1e-6; z = R / 2 * sqrt(C / L); a = R / (2 * L)
    b = sqrt(1 / (L * C) - a * a); pi = atan2(0, -1)
    printf "0 5 ok %.4g -%.4g -%.4g -%.4g %.4g", 1 + exp(-pi * z / sqrt(1 - z * z)), a, b, a, b }' | sed 's/-/\xe2\x88\x92/g')
  grep -E '^ +0 +5 ok' "$tmp/sr.txt" | tr -s ' ' | sed 's/^ //' | grep -qxF "$want"
  check "the report's first row: $want" $?
  for t in 'Runs and collected quantities' 'Family of runs' 'Collected quantities against R0' \
           'Root locus' 'Bode family'; do
    grep -q "^$t" "$tmp/sr.txt"; check "the report shows: $t" $?
  done
  "$BGDRAW" tests/data/quarter_car_study.bg --report "$tmp/mr.pdf" -j 2 && pdftotext "$tmp/mr.pdf" "$tmp/mr.txt" &&
    grep -q 'A Monte Carlo study of 40 runs, seed 3' "$tmp/mr.txt" && grep -q 'Monte Carlo envelope' "$tmp/mr.txt"
  check "a model's Monte Carlo study in its report" $?
  "$BGDRAW" "$m" --sweep C0=1e-6,0 --collect C1.e:final --report "$tmp/fr.pdf" 2>/dev/null &&
    pdftotext -layout "$tmp/fr.pdf" - | grep -q '1 run failed'
  check "the report counts the failed run" $?
else
  echo "FAIL pdftotext is not installed (bash tools/deps.sh --tests)"; fail=$((fail + 1))
fi

# failed runs are rows with reasons; a study where every run fails is status 3
"$BGDRAW" "$m" --sweep C0=1e-6,0 --collect C1.e:final --study "$tmp/f.csv" 2>"$tmp/err"
[ $? -eq 0 ] && grep -q '^1,0,failed,,simulation failed' "$tmp/f.csv" && grep -q '1 of 2 runs failed' "$tmp/err"
check "a failed run is in the table" $?
"$BGDRAW" "$m" --sweep C0=0 --collect C1.e:final --study "$tmp/f.csv" 2>/dev/null
[ $? -eq 3 ]; check "every run failed: status 3" $?

# usage errors (status 2, nothing written)
usage() { # NAME EXPECTED-MESSAGE ARGS...
  local name=$1 want=$2
  shift 2
  "$BGDRAW" "$m" "$@" 2>"$tmp/err" >/dev/null
  [ $? -eq 2 ] && grep -q -- "$want" "$tmp/err"
  check "usage: $name" $?
}
usage "no outputs" "the study writes nothing" --sweep R0=1,2
usage "-o in a study" "a study writes --study, --family, --root-locus, --bode-family and --report outputs only" --sweep R0=1,2 --study "$tmp/u.csv" -o "$tmp/u.svg"
usage "--vary without draws" "--monte-carlo N" --vary 'R0=normal(1,2)' --study "$tmp/u.csv"
usage "--seed in a sweep" "--seed belongs to a Monte Carlo study" --sweep R0=1,2 --seed 3 --study "$tmp/u.csv"
usage "bad range" "FROM:TO:COUNT" --sweep R0=1:2 --study "$tmp/u.csv"
usage "bad -j" "number of threads" --sweep R0=1,2 -j 0 --study "$tmp/u.csv"
usage "family format" "the plot is .svg, .pdf or .png" --sweep R0=1,2 --family "$tmp/u.csv"
usage "--runs beyond" "the study has 2 runs" --sweep R0=1,2 --runs 1:5 --study "$tmp/u.csv"
usage "--job-list without --split" "needs --split" --sweep R0=1,2 --job-list "$tmp/j.txt"
usage "--family with --merge" "keep no trajectories" --sweep R0=1,2 --merge "$tmp" --family "$tmp/u.svg"
usage "--root-locus with --merge" "give the study --collect poles" --sweep R0=1,2 --merge "$tmp" --root-locus "$tmp/u.svg"
usage "root locus format" "--root-locus $tmp/u.csv: the plot is" --sweep R0=1,2 --root-locus "$tmp/u.csv"
[ ! -e "$tmp/u.csv" ] && [ ! -e "$tmp/u.svg" ]; check "usage errors write nothing" $?
"$BGDRAW" "$m" --sweep R0=1,2 --collect C9.e:max --study "$tmp/u.csv" 2>"$tmp/err"
[ $? -eq 1 ] && grep -q "'C9.e' is not an output of the simulation (outputs: C1.e, L1.f)" "$tmp/err"
check "an output the model has not" $?
finish
