#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The HTML report in a real browser: Debian's chromium, headless, driven over
# its DevTools pipe (tests/html/cdp.py; tools/deps.sh --tests installs it).
# tests/html/browser.py loads every example's report and a few test models'
# and checks hover, focus, #path-K, Enter, layer toggles, the plot readout
# against the CSV, no console errors and no requests, the dark and print
# styles, and the diagram's screenshot against its PNG. BGDRAW_SHOTS=DIR keeps
# the screenshots (DIR/NAME-diagram.png, NAME-pathK.png) to look at.
# Usage: bash tests/html_browser.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
out=${BGDRAW_SHOTS:-$tmp/shots}
python3 tests/html/browser.py "$BGDRAW" "$out" examples/*.bg tests/data/linear_rlc.bg \
  tests/data/thermostat.bg tests/data/coupled_coils.bg examples/components/rc_ladder_lib.bg \
  tests/data/fields/dependent.bg
check "the reports in chromium" $?
finish
