#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The property campaign's short run in the test suite (docs/property.md): 300
# generated models of 2 to 30 elements, seeds 1..300, every check, two at a
# time (JOBS); shrunk failures go to a private folder and are printed.
#     bash tests/property/short.sh BGDRAW [PROP_LIBJSON]   (from the project root)
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
LIBJSON=${2:-} MAX_ELEMS=30 JOBS=${JOBS:-2} bash "$(dirname "$0")/campaign.sh" "${1:?usage: short.sh BGDRAW}" 300 1 "$tmp/found"; st=$?
for f in "$tmp"/found/*.bg; do [ -f "$f" ] && { echo "== $f"; cat "$f"; }; done
exit $st
