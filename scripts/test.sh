#!/usr/bin/env bash
# Builds gdpn and passes every test, from a fresh Debian 12 machine:
#   1. installs the Debian packages (scripts/install-deps.sh, skipped when present);
#   2. release build with warnings as errors; unit, golden, python and gui tests (CTest; the
#      label `full`, every contest formula on the two largest nets, is left to `ctest --preset
#      full` by hand);
#   3. one clang build (-O1) under AddressSanitizer + UBSan with libFuzzer's coverage: the unit
#      tests again, and the libFuzzer targets;
#   4. GDPN_FUZZ_SECONDS (default 45) of fuzzing each loader and server with that build
#      (scripts/fuzz.sh: models, PNML, meshes, elevation files, input events, queries,
#      witnesses, Modbus requests).
# The whole must stay within 30 minutes on 2 cores. Each stage has a budget, in seconds on
# the project's 2-core machine (docs/performance.md, "CI"); the script prints each stage's
# time beside it at the end, and a stage over its budget is said there (not a failure: the
# machines' speed varies by a third from run to run). The builds of 2, 3 and 4 compile the
# libraries as unity builds (GDPN_UNITY_LIBRARIES; the dev preset does not, so that a file
# that lacks an include still fails there).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

stages=()
stage() {  # stage NAME BUDGET_SECONDS COMMAND...: runs it, timed
  local name=$1 budget=$2 start=$SECONDS
  shift 2
  echo "== $name"
  "$@"
  stages+=("$name|$((SECONDS - start))|$budget")
}

report() {  # each stage's seconds beside its budget; the builds and tests together beside 30 minutes
  local total=0 line name took budget over
  echo "== stages: seconds taken, budget"
  for line in "${stages[@]}"; do
    IFS='|' read -r name took budget <<<"$line"
    over=""
    if [ "$budget" != - ]; then
      total=$((total + took))
      [ "$took" -gt "$budget" ] && over="  over budget"
    fi
    printf '%-26s %5d  %5s%s\n' "$name" "$took" "$budget" "$over"
  done
  over=""
  [ "$total" -gt 1800 ] && over="  over budget"
  printf '%-26s %5d  %5d%s\n' "builds and tests" "$total" 1800 "$over"
}

stage "Debian packages" - bash scripts/install-deps.sh
stage "release build" 600 bash -c "cmake --preset ci >/dev/null && cmake --build --preset ci -j $jobs"
stage "release tests" 300 ctest --preset ci -j "$jobs"
stage "ASan + UBSan + fuzz build" 540 bash -c "cmake --preset asan >/dev/null && cmake --build --preset asan -j $jobs"
stage "ASan + UBSan unit tests" 150 ctest --preset asan -j "$jobs"
stage "fuzzing" 390 bash scripts/fuzz.sh "${GDPN_FUZZ_SECONDS:-45}"
report
