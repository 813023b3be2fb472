#!/usr/bin/env bash
# `gdpn run` of a model of N producer/consumer cells (bench/cells.py: a page type of 3 places
# and 2 transitions, N instances), `--until 100`, the summary printed and the JSON report
# written (both include the cycle bounds from the P-invariants): wall-clock seconds and peak
# memory (maximum resident set), the median of REPEATS runs (default 3), for N = 1,000,
# 10,000 and 100,000, cells on their own and cells all fed from one place (one connected
# net). The last column is the memory per instance between N = 10,000 and N = 100,000. Then
# `gdpn analyze` of the cells on their own under --max-memory 1024.
# Needs a Release build (cmake --preset ci && cmake --build build/ci).
# Usage: bench/scale_bench.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"

printf '%-10s %9s %10s %12s %16s\n' "cells" "N" "time [s]" "peak [MiB]" "per instance [B]"
for shape in own linked; do
  declare -A kib=()
  for n in 1000 10000 100000; do
    model="$work/cells_${shape}_$n.gdpn.yaml"
    python3 bench/cells.py "$n" "$model" $([[ $shape == linked ]] && echo --linked)
    times=() mems=()
    for ((r = 0; r < repeats; ++r)); do
      /usr/bin/time -f '%e %M' -o "$work/time" "$gdpn" run "$model" --until 100 --report "$work/report.json" >"$work/out.txt"
      read -r t m <"$work/time"
      times+=("$t") mems+=("$m")
    done
    t=$(printf '%s\n' "${times[@]}" | median)
    m=$(printf '%s\n' "${mems[@]}" | median)
    kib[$n]=$m
    per="-"
    [[ $n == 100000 ]] && per=$(( (kib[100000] - kib[10000]) * 1024 / 90000 ))
    printf '%-10s %9d %10.2f %12.1f %16s\n' "$shape" "$n" "$t" "$(echo "$m / 1024" | bc -l)" "$per"
  done
done

# `gdpn analyze` of the same cells on their own, default output (invariants by page type,
# cycle-time bounds, the state space) under --max-memory 1024: the state space of N cells has
# 3^N markings, so the search stops at the limit; each marking of 10^5 cells takes 50 KiB and
# the first has 10^5 successors, which must not be made past the limit either
printf '\n%-10s %9s %10s %12s %12s %s\n' "analyze" "N" "time [s]" "peak [MiB]" "states" "stop"
for n in 1000 10000 100000; do
  model="$work/cells_own_$n.gdpn.yaml"
  times=() mems=()
  for ((r = 0; r < repeats; ++r)); do
    set +e
    /usr/bin/time -f '%e %M' -o "$work/time" "$gdpn" analyze "$model" --max-memory 1024 --json >"$work/analysis.json" 2>/dev/null
    code=$?
    set -e
    [[ $code == 0 || $code == 3 ]] || { echo "gdpn analyze of $n cells: exit $code" >&2; exit 1; }
    read -r t m < <(tail -n 1 "$work/time")  # (after "Command exited with non-zero status 3")
    times+=("$t") mems+=("$m")
  done
  read -r states stop < <(python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); print(j["states"], j["stop"])' "$work/analysis.json")
  t=$(printf '%s\n' "${times[@]}" | median)
  m=$(printf '%s\n' "${mems[@]}" | median)
  printf '%-10s %9d %10.2f %12.1f %12s %s\n' "own" "$n" "$t" "$(echo "$m / 1024" | bc -l)" "$states" "$stop"
done
