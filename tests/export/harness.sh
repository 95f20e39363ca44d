# SPDX-License-Identifier: BSD-3-Clause
# Sourced by the export tests (export_cli.sh, fmu_cli.sh): a temporary folder
# removed on exit, check NAME STATUS counting failures in $fail, cmp_csv, and
# rlc with tight tolerances in $tmp/rlc.bg (so comparisons see the equations,
# not the solvers).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { # check NAME STATUS
  if [ "$2" -ne 0 ]; then echo "FAIL $1"; fail=$((fail + 1)); else echo "ok   $1"; fi
}
cmp_csv() { python3 tests/export/compare_csv.py "$@"; }
sed 's/^simulate .*/&, rtol = 1e-10/' examples/rlc.bg >"$tmp/rlc.bg"
