#!/usr/bin/env bash
# A sweep of RUNS factory runs of 120 s (default 200; seeds 1 to RUNS, the model as it is):
# the same runs (1) one after another as plain `gdpn run --report` calls, (2) through
# `gdpn sweep --workers 0` (the sweep's machinery, one run after another, no Dask), and
# (3) through `gdpn sweep --workers 2` (a local Dask cluster of two workers). Prints the wall
# time of each, the median plain run, the sweep's overhead per run, (2) against (1), and
# the speed-up of (3) over (1). Each figure is measured once (a sweep is many runs already).
# Needs a Release build (cmake --preset ci && cmake --build build/ci).
# Usage: bench/sweep_bench.sh [BUILD_DIR] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "${1:-build/ci}"
runs=${2:-200}
model=examples/factory

now() { date +%s.%N; }
calc() { awk "BEGIN { print $1 }"; }
: >"$work/each"
start=$(now)
for ((s = 1; s <= runs; ++s)); do
  t0=$(now)
  "$gdpn" run "$model" --quiet --until 120 --seed "$s" --report "$work/r.json"
  calc "$(now) - $t0" >>"$work/each"
done
plain=$(calc "$(now) - $start")
median_run=$(median <"$work/each")

start=$(now)
"$gdpn" sweep "$model" --seeds "$runs" --until 120 --workers 0 --quiet -o "$work/serial.csv"
serial=$(calc "$(now) - $start")

start=$(now)
"$gdpn" sweep "$model" --seeds "$runs" --until 120 --workers 2 --quiet -o "$work/two.csv"
two=$(calc "$(now) - $start")

cmp -s "$work/serial.csv" "$work/two.csv" || { echo "error: the two sweeps' tables differ" >&2; exit 1; }
printf 'runs of 120 s                      %d\n' "$runs"
printf 'plain runs, one after another      %.1f s (median run %.3f s)\n' "$plain" "$median_run"
printf 'gdpn sweep --workers 0             %.1f s (overhead per run %+.3f s)\n' "$serial" \
  "$(calc "($serial - $plain) / $runs")"
printf 'gdpn sweep --workers 2             %.1f s (%.2f times the plain runs'"'"' rate)\n' "$two" \
  "$(calc "$plain / $two")"
