#!/usr/bin/env bash
# `gdpn analyze --query` of the contest's 2021 formulas on Kanban-PT-00005 and
# SwimmingPool-PT-02 (tests/data/conformance), one category (16 formulas) at a time: wall-clock
# seconds (the median of REPEATS runs, default 3), the markings explored summed over the
# formulas (a formula answered from the stored graph counts the whole graph), peak memory;
# every category with reductions (simplification, on the fly first, stubborn sets) and
# without (--no-reduction: the whole graph first). Every answer is checked
# against the contest's oracle; a wrong one stops the script.
# Needs a Release build (cmake --preset ci && cmake --build build/ci).
# Usage: bench/query_bench.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"
data=tests/data/conformance

printf '%-20s %-24s %-9s %8s %12s %11s\n' "net" "category" "reduced" "time [s]" "markings" "peak [MiB]"
for net in Kanban-PT-00005 SwimmingPool-PT-02; do
  for category in ReachabilityCardinality ReachabilityFireability UpperBounds CTLCardinality CTLFireability \
    LTLCardinality LTLFireability; do
    for mode in on off; do
      flag=()
      [[ $mode == off ]] && flag=(--no-reduction)
      times=() mems=()
      for ((r = 0; r < repeats; ++r)); do
        /usr/bin/time -f '%e %M' -o "$work/time" "$gdpn" analyze "$data/$net.pnml" \
          --query "$data/queries/$net/$category.xml" --json "${flag[@]}" >"$work/out.json"
        read -r t m < <(tail -n 1 "$work/time")
        times+=("$t") mems+=("$m")
      done
      markings=$(python3 - "$work/out.json" "$data/queries/oracle.tsv" <<'PY'
import json, sys
answers = json.load(open(sys.argv[1]))["queries"]
oracle = dict(line.split() for line in open(sys.argv[2]))
for q in answers:
    got = str(q["answer"]).upper()
    if got != oracle[q["id"]]:
        sys.exit(f"{q['id']}: {got}, the oracle says {oracle[q['id']]}")
print(sum(q["states"] for q in answers))
PY
)
      t=$(printf '%s\n' "${times[@]}" | median)
      m=$(printf '%s\n' "${mems[@]}" | median)
      printf '%-20s %-24s %-9s %8.2f %12s %11.0f\n' "$net" "$category" "$mode" "$t" "$markings" "$(echo "$m / 1024" | bc -l)"
    done
  done
done

# a witness 9 firings deep among 10^7 markings (7 independent rings of 10 places)
python3 - "$work/rings.pnml" <<'PY'
import sys
places, transitions, arcs = [], [], []
for r in range(7):
    for i in range(10):
        places.append(f'<place id="r{r}p{i}">' + ('<initialMarking><text>1</text></initialMarking>' if i == 0 else '') + '</place>')
        transitions.append(f'<transition id="r{r}t{i}"/>')
        arcs.append(f'<arc id="a{r}_{i}" source="r{r}p{i}" target="r{r}t{i}"/>')
        arcs.append(f'<arc id="b{r}_{i}" source="r{r}t{i}" target="r{r}p{(i + 1) % 10}"/>')
open(sys.argv[1], "w").write('<?xml version="1.0"?><pnml xmlns="http://www.pnml.org/version-2009/grammar/pnml">'
    '<net id="rings" type="http://www.pnml.org/version-2009/grammar/ptnet"><page id="page">'
    + "".join(places + transitions + arcs) + '</page></net></pnml>')
PY
times=()
for ((r = 0; r < repeats; ++r)); do
  /usr/bin/time -f '%e' -o "$work/time" "$gdpn" analyze "$work/rings.pnml" --query 'EF r0p9 = 1' --json >"$work/out.json"
  times+=("$(tail -n 1 "$work/time")")
done
read -r answer steps markings < <(python3 -c 'import json,sys; q=json.load(open(sys.argv[1]))["queries"][0]; print(q["answer"], len(q["path"]), q["states"])' "$work/out.json")
echo "rings 7x10 (10^7 markings): EF r0p9 = 1: $answer, $steps firings, $markings markings explored, $(printf '%s\n' "${times[@]}" | median) s (the whole command)"
