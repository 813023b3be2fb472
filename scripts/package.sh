#!/usr/bin/env bash
# Builds a release and the Debian package of it (cmake/Package.cmake), from a fresh Debian 12
# machine as root: installs the Debian packages it needs (scripts/install-deps.sh), configures
# and builds the release preset, and runs cpack. Prints the package's path; install it with
# `apt install ./build/release/gdpn_VERSION_ARCH.deb`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh >/dev/null
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc)" >/dev/null
cd build/release
cpack -G DEB >/dev/null
ls "$PWD"/gdpn_*.deb
