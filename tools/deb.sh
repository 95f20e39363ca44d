#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds the Debian packages bgdraw, libbgdraw0 and libbgdraw-dev with CPack
# (tools/packaging.cmake) into OUTDIR (default out/deb):
#   bash tools/deb.sh [OUTDIR]
# The build is a packager's: installed under /usr (multiarch library folder),
# no tests, Debian's compiler and linker flags from dpkg-buildflags
# (hardening: fortify, stack protector, relro, bindnow), stripped binaries,
# Debian's copyright file and changelog in each package. Needs dpkg-dev
# (dpkg-buildflags, dpkg-shlibdeps) beside what tools/deps.sh installs.
set -euo pipefail
cd "$(dirname "$0")/.."
OUT=$(mkdir -p "${1:-out/deb}" && cd "${1:-out/deb}" && pwd)
bash tools/deps.sh
command -v dpkg-buildflags >/dev/null && command -v dpkg-shlibdeps >/dev/null || {
  echo "bgdraw: tools/deb.sh needs dpkg-dev (apt-get install dpkg-dev)" >&2; exit 2; }
B=${DEB_BUILD_DIR:-build-deb}
export DEB_BUILD_MAINT_OPTIONS=hardening=+all
cmake -S . -B "$B" -DCMAKE_BUILD_TYPE=None -DCMAKE_INSTALL_PREFIX=/usr -DBUILD_TESTING=OFF \
  -DBG_DEBIAN_FILES=ON \
  -DCMAKE_C_FLAGS="$(dpkg-buildflags --get CFLAGS) $(dpkg-buildflags --get CPPFLAGS)" \
  -DCMAKE_EXE_LINKER_FLAGS="$(dpkg-buildflags --get LDFLAGS)" \
  -DCMAKE_SHARED_LINKER_FLAGS="$(dpkg-buildflags --get LDFLAGS)" \
  -DCMAKE_MODULE_LINKER_FLAGS="$(dpkg-buildflags --get LDFLAGS)" >/dev/null
cmake --build "$B" -j"$(nproc)" >/dev/null
(cd "$B" && cpack -G DEB -B "$OUT" >/dev/null)
rm -rf "$OUT/_CPack_Packages"
ls "$OUT"/*.deb
