#!/usr/bin/env bash
# `gdpn analyze` of the eleven contest nets in bench/data/mcc (its default output: the state
# space, deadlock and a path to one, bounds, liveness, reversibility, the invariants), one
# thread and two, beside LoLA 2 where one is found ($LOLA, else `lola` on the PATH): a full
# state space without reductions, `lola --check=full --stubborn=off --netreduction=off`.
# The runs take turns (gdpn one thread, gdpn two, LoLA; again), REPEATS of each (default 3);
# each figure is the median: wall-clock seconds, and peak resident memory (the process's
# maximum resident set, /usr/bin/time) per state, in bytes. The ratios are LoLA's figure over
# gdpn's one-thread figure: above 1, gdpn is faster or leaner; "2 thr" is gdpn's with two
# threads. Each gdpn run's state and edge counts are
# checked against bench/data/mcc/reference.tsv, and LoLA's state count too; a wrong count
# stops the script.
# Needs a Release build (cmake --preset ci && cmake --build build/ci).
# Usage: bench/mcc_bench.sh [BUILD_DIR] [REPEATS] [NET...]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"
shift $(($# < 2 ? $# : 2))
lola=${LOLA:-$(command -v lola || true)}
[[ -n $lola && ! -x $lola ]] && { echo "LOLA=$lola is not an executable" >&2; exit 2; }
nets=("$@")
if ((${#nets[@]} == 0)); then mapfile -t nets < <(tail -n +2 bench/data/mcc/reference.tsv | cut -f1); fi

# one run: "SECONDS KIB" of `command...`, its state count checked (and its edge count, for gdpn)
run() {
  local net=$1 states=$2 edges=$3
  shift 3
  set +e
  /usr/bin/time -f '%e %M' -o "$work/time" "$@" >"$work/out" 2>&1
  local rc=$?
  set -e
  if [[ $1 == "$gdpn" ]]; then
    # 0: complete; 3: some phase (the invariants) partial, the state space complete
    if [[ $rc != 0 && $rc != 3 ]]; then echo "$net: gdpn analyze failed ($rc)" >&2; exit 1; fi
    read -r got_states got_edges < <(python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); print(j["states"], j["edges"])' "$work/out")
  else
    if [[ $rc != 0 ]]; then echo "$net: lola failed ($rc)" >&2; exit 1; fi
    got_states=$(sed -n 's/^lola: *markings *: *\([0-9]*\).*/\1/p' "$work/out")
    got_edges=$edges
  fi
  if [[ $got_states != "$states" || $got_edges != "$edges" ]]; then
    echo "$net: $got_states states, $got_edges edges from $1; the reference has $states, $edges" >&2
    exit 1
  fi
  tail -n 1 "$work/time"
}

printf '%-36s %8s  %-31s  %-31s\n' "" "" "time [s]" "peak memory a state [bytes]"
printf '%-36s %8s  %7s %7s %7s %6s  %7s %7s %7s %6s\n' "net" "states" "gdpn" "2 thr" "LoLA" "ratio" "gdpn" "2 thr" "LoLA" "ratio"
for net in "${nets[@]}"; do
  IFS=$'\t' read -r _ states edges _ < <(grep -P "^$net\t" bench/data/mcc/reference.tsv)
  [[ -n ${states:-} ]] || { echo "$net: not in bench/data/mcc/reference.tsv" >&2; exit 2; }
  pnml="bench/data/mcc/$net.pnml"
  t1=() m1=() t2=() m2=() tl=() ml=()
  for ((r = 0; r < repeats; ++r)); do
    read -r t m < <(run "$net" "$states" "$edges" "$gdpn" analyze "$pnml" --threads 1 --json)
    t1+=("$t") m1+=("$m")
    read -r t m < <(run "$net" "$states" "$edges" "$gdpn" analyze "$pnml" --threads 2 --json)
    t2+=("$t") m2+=("$m")
    if [[ -n $lola ]]; then
      read -r t m < <(run "$net" "$states" "$edges" "$lola" --pnmlnet --check=full --stubborn=off --netreduction=off "$pnml")
      tl+=("$t") ml+=("$m")
    fi
  done
  T1=$(printf '%s\n' "${t1[@]}" | median) M1=$(printf '%s\n' "${m1[@]}" | median)
  T2=$(printf '%s\n' "${t2[@]}" | median) M2=$(printf '%s\n' "${m2[@]}" | median)
  per() { echo "$1 * 1024 / $states" | bc -l; }
  if [[ -n $lola ]]; then
    TL=$(printf '%s\n' "${tl[@]}" | median) ML=$(printf '%s\n' "${ml[@]}" | median)
    printf '%-36s %8d  %7.2f %7.2f %7.2f %6.2f  %7.1f %7.1f %7.1f %6.2f\n' "$net" "$states" "$T1" "$T2" "$TL" \
      "$(echo "$TL / $T1" | bc -l)" "$(per "$M1")" "$(per "$M2")" "$(per "$ML")" "$(echo "$ML / $M1" | bc -l)"
  else
    printf '%-36s %8d  %7.2f %7.2f %7s %6s  %7.1f %7.1f %7s %6s\n' "$net" "$states" "$T1" "$T2" "-" "-" \
      "$(per "$M1")" "$(per "$M2")" "-" "-"
  fi
done
