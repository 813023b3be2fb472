#!/usr/bin/env bash
# `gdpn analyze` of the contest nets in bench/data/mcc (default output: the state space,
# deadlock and the path to one, bounds, liveness, the invariants), one thread and two:
# wall-clock seconds (the median of REPEATS runs, default 3), states per second over the
# whole command, and peak memory. Each run's state and edge counts are checked against
# bench/data/mcc/reference.tsv; a wrong count stops the script.
# Needs a Release build (cmake --preset ci && cmake --build build/ci).
# Usage: bench/mcc_bench.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"

printf '%-38s %8s %10s %9s %11s %12s\n' "net" "threads" "states" "time [s]" "states/s" "peak [MiB]"
tail -n +2 bench/data/mcc/reference.tsv | while IFS=$'\t' read -r net states edges _; do
  for threads in 1 2; do
    times=() mems=()
    for ((r = 0; r < repeats; ++r)); do
      set +e
      /usr/bin/time -f '%e %M' -o "$work/time" "$gdpn" analyze "bench/data/mcc/$net.pnml" --threads "$threads" --json \
        >"$work/out.json" 2>/dev/null
      rc=$?
      set -e
      # 0: complete; 3: some phase (the invariants) partial, the state space complete
      if [[ $rc != 0 && $rc != 3 ]]; then echo "$net: gdpn analyze failed ($rc)" >&2; exit 1; fi
      read -r got_states got_edges < <(python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["states"], j["edges"])' "$work/out.json")
      if [[ $got_states != "$states" || $got_edges != "$edges" ]]; then
        echo "$net: $got_states states, $got_edges edges; the reference has $states, $edges" >&2
        exit 1
      fi
      read -r t m < <(tail -n 1 "$work/time")
      times+=("$t") mems+=("$m")
    done
    t=$(printf '%s\n' "${times[@]}" | median)
    m=$(printf '%s\n' "${mems[@]}" | median)
    printf '%-38s %8d %10d %9.2f %10.2fM %12.1f\n' "$net" "$threads" "$states" "$t" "$(echo "$states / $t / 1000000" | bc -l)" \
      "$(echo "$m / 1024" | bc -l)"
  done
done
