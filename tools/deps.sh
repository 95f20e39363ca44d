#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian 12 packages bgdraw needs, only if some are missing:
#   bash tools/deps.sh          what building and running bgdraw needs (the main job)
#   bash tools/deps.sh --tests  that and what the test suite needs
# Runs as root (or with sudo available). Idempotent and quick when nothing is missing.
set -euo pipefail
PKGS=(gcc make cmake pkg-config
      libsundials-dev libgraphviz-dev libcairo2-dev libpango1.0-dev liblapacke-dev zlib1g-dev libyaml-dev
      fonts-dejavu-core)
if [ "${1:-}" = "--tests" ]; then
  PKGS+=(python3 poppler-utils libxml2-utils  # checkers, PDF pages, SVG well-formedness
         python3-numpy python3-scipy octave   # the Python and Octave exports, reference solutions
         librsvg2-bin pandoc python3-sphinx   # SVG rasterisation check; contrib/ integrations
         mkdocs                               # contrib/mkdocs (tests/contrib.sh)
         valgrind                             # tests/valgrind_outputs.sh
         python3-pytest jupyter-nbconvert     # the Python package's tests (python/tests),
         python3-ipykernel python3-nbformat   # a notebook executed headless
         dpkg-dev lintian                     # tests/deb.sh: the Debian packages
         parallel                             # tests/study_cli.sh: a study split over GNU parallel
         python3-yaml                         # tests/import_bgt.sh: the written YAML read by PyYAML
         chromium)                            # tests/html_browser.sh: the HTML report, headless
fi
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "bgdraw: installing ${missing[*]}" >&2
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
