#!/usr/bin/env bash
# Builds gdpn and passes every test, from a fresh Debian 12 machine:
#   1. installs the Debian packages (scripts/install-deps.sh, skipped when present);
#   2. release build with warnings as errors; unit and golden tests (CTest);
#   3. debug build under AddressSanitizer + UBSan; the unit tests again;
#   4. clang build of the libFuzzer targets; 45 s of fuzzing each loader (scripts/fuzz.sh:
#      models, PNML, meshes, elevation files, input events, queries, witnesses, Modbus requests;
#      GDPN_FUZZ_SECONDS for more),
#      so that the whole stays within 30 minutes on 2 cores (the builds of 3 and 4 compile
#      the libraries as unity builds, GDPN_UNITY_LIBRARIES: 22.75 minutes in all on 2026-11-27).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

bash scripts/install-deps.sh

echo "== release build, unit and golden tests"
cmake --preset ci >/dev/null
cmake --build --preset ci -j "$jobs"
ctest --preset ci -j "$jobs"

echo "== ASan + UBSan build, unit tests"
cmake --preset asan >/dev/null
cmake --build --preset asan -j "$jobs"
ctest --preset asan -j "$jobs"

echo "== libFuzzer: model loader"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$jobs"
bash scripts/fuzz.sh "${GDPN_FUZZ_SECONDS:-45}"
