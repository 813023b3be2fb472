#!/usr/bin/env bash
# `gdpn run` of a model of N producer/consumer cells (bench/cells.py: a page type of 3 places
# and 2 transitions, N instances), `--until 100`, the summary printed and the JSON report
# written (both include the cycle bounds from the P-invariants): wall-clock seconds and peak
# memory (maximum resident set), the median of REPEATS runs (default 3), for N = 1,000,
# 10,000 and 100,000, cells on their own and cells all fed from one place (one connected
# net). The last column is the memory per instance between N = 10,000 and N = 100,000.
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
