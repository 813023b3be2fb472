#!/usr/bin/env bash
# The Model Checking Contest's formulas on four place/transition nets far beyond memory
# (tests/data/conformance-large: Dekker-PT-050, FMS-PT-00050, Kanban-PT-00050,
# Philosophers-PT-000050; seven categories of 16 formulas each), one run per net, category and
# tool, LIMIT seconds for the whole file (default 60; also $LIMIT): `gdpn analyze --query
# --time-limit LIMIT`, the same with --no-reduction, and LoLA 2 where one is found ($LOLA, else
# `lola` on the PATH) as the contest ran it, its default
# reductions and portfolio: `lola --pnmlnet NET --xmlformula --formula=FILE --timelimit=LIMIT
# --mcc --json=FILE` (it prints `FORMULA id VALUE TECHNIQUES ...` for each formula it settles;
# its JSON's values are checked against those lines). Every run is wrapped in `timeout`
# LIMIT + 15 s. Each answer is checked against the net's oracle-formulas.tsv: a wrong one is
# printed at once and makes the script exit 1 once the table is done.
# The table: formulas answered (of 16 a net, of 64 a category summed over the nets; a `!`
# marks a cell with a wrong answer among them), wall-clock seconds (/usr/bin/time; summed over
# the nets) and peak resident memory in MiB (the largest over the nets), per category, then per
# net under it.
# $CATEGORIES (words) picks some of the seven.
# Needs a Release build (cmake --preset ci && cmake --build build/ci).
# Usage: bench/large_bench.sh [GDPN_BINARY] [LIMIT] [NET...]
set -euo pipefail
cd "$(dirname "$0")/.."
gdpn=$(realpath "${1:-build/ci/apps/gdpn/gdpn}")
limit=${2:-${LIMIT:-60}}
shift $(($# < 2 ? $# : 2))
[[ -x $gdpn ]] || { echo "$gdpn is not an executable" >&2; exit 2; }
if [[ ! $limit =~ ^[0-9]+$ || $limit -eq 0 ]]; then
  echo "LIMIT=$limit is not a whole number of seconds" >&2
  exit 2
fi
lola=${LOLA:-}
[[ -z $lola ]] && lola=$(command -v lola || true)
[[ -n $lola && ! -x $lola ]] && { echo "LOLA=$lola is not an executable" >&2; exit 2; }
data=$PWD/tests/data/conformance-large
nets=("$@")
((${#nets[@]})) || nets=(Dekker-PT-050 FMS-PT-00050 Kanban-PT-00050 Philosophers-PT-000050)
categories=(ReachabilityCardinality ReachabilityFireability UpperBounds CTLCardinality
  CTLFireability LTLCardinality LTLFireability)
if [[ -n ${CATEGORIES:-} ]]; then read -r -a categories <<<"$CATEGORIES"; fi
for net in "${nets[@]}"; do
  [[ -f $data/$net/model.pnml ]] || { echo "$net: no $data/$net/model.pnml" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "gdpn: $gdpn; LoLA: ${lola:-none}; limit ${limit} s a file; $(date '+%F %T')" >&2

# one run of `command...` on net $1, category $2, as tool $3: a line of $work/results.tsv
# (net, category, tool, answered, right, wrong, seconds, KiB, exit status), the wrong answers
# on stderr
run() {
  local net=$1 category=$2 tool=$3
  shift 3
  local out="$work/$net.$category.$tool"
  set +e
  /usr/bin/time -f '%e %M' -o "$out.time" timeout $((limit + 15)) "$@" >"$out.out" 2>"$out.err"
  local rc=$?
  set -e
  read -r secs kib < <(tail -n 1 "$out.time")
  python3 - "$out.out" "$data/$net/oracle-formulas.tsv" "$category" "$tool" "$out.json" <<'PY' |
import json, os, sys
out, oracle_file, category, tool, json_file = sys.argv[1:]
oracle = dict(line.split() for line in open(oracle_file) if line.strip())
answers = {}
for line in open(out, errors="replace"):
    f = line.split()
    if len(f) >= 3 and f[0] == "FORMULA" and f[2] != "CANNOT_COMPUTE":
        if f[1] in answers and answers[f[1]] != f[2].upper():
            print(f"ODD: {tool} gave {f[1]} twice: {answers[f[1]]} and {f[2]}", file=sys.stderr)
        answers[f[1]] = f[2].upper()
mine = [i for i in oracle if f"-{category}-" in i]
for i in answers:
    if i not in mine:
        print(f"ODD: {tool} answered {i}, not a formula of {category}", file=sys.stderr)
right = sum(answers.get(i) == oracle[i] for i in mine)
answered = sum(i in answers for i in mine)
for i in mine:
    if i in answers and answers[i] != oracle[i]:
        print(f"*** WRONG: {tool} says {i} is {answers[i]}; the oracle says {oracle[i]}",
              file=sys.stderr)
if os.path.exists(json_file):  # LoLA's JSON: the same answers as its FORMULA lines
    try:
        formulas = json.load(open(json_file))["formula"]
    except (ValueError, KeyError) as e:
        formulas = {}
        print(f"ODD: {tool}'s JSON {json_file} unreadable: {e}", file=sys.stderr)
    for i in mine:
        v = formulas.get(i, {})
        settled = v.get("delivering task", -1) != -1 if category == "UpperBounds" \
            else v.get("value") in (True, False, "true", "false")
        got = str(v.get("value")).upper() if settled else None
        if got != answers.get(i):
            print(f"ODD: {tool}'s JSON has {i} {got}, its output {answers.get(i)}",
                  file=sys.stderr)
print(answered, right, answered - right)
PY
  {
    read -r answered right wrong
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$net" "$category" "$tool" "$answered" "$right" \
      "$wrong" "$secs" "$kib" "$rc" >>"$work/results.tsv"
  }
  case $tool:$rc in
    gdpn*:0 | gdpn*:3 | lola:0) ;; # gdpn: 3, some formula unanswered
    *)
      echo "ODD: $tool on $net $category exited $rc ($secs s); its stderr ends:" >&2
      tail -n 3 "$out.err" | sed 's/^/    /' >&2
      ;;
  esac
}

: >"$work/results.tsv"
for net in "${nets[@]}"; do
  for category in "${categories[@]}"; do
    pnml="$data/$net/model.pnml" query="$data/$net/$category.xml"
    run "$net" "$category" gdpn "$gdpn" analyze "$pnml" --query "$query" --time-limit "$limit"
    run "$net" "$category" gdpn-nored "$gdpn" analyze "$pnml" --query "$query" \
      --time-limit "$limit" --no-reduction
    if [[ -n $lola ]]; then
      run "$net" "$category" lola "$lola" --pnmlnet "$pnml" --xmlformula --formula="$query" \
        --timelimit="$limit" --mcc --json="$work/$net.$category.lola.json"
    fi
    echo "done: $net $category ($(date +%T))" >&2
  done
done

python3 - "$work/results.tsv" "$limit" "${#nets[@]}" "${categories[@]}" <<'PY'
import sys
results_file, limit, n_nets, categories = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
rows = [line.rstrip("\n").split("\t") for line in open(results_file)]
tools = ["gdpn", "gdpn-nored", "lola"]
cell = {}
for net, cat, tool, answered, right, wrong, secs, kib, rc in rows:
    cell[net, cat, tool] = (int(answered), int(wrong), float(secs), int(kib))
nets = list(dict.fromkeys(r[0] for r in rows))

def fmt(values, of):
    if not values:
        return f"{'-':>8} {'-':>5} {'-':>5}"
    a = sum(v[0] for v in values)
    w = "!" if sum(v[1] for v in values) else " "
    return f"{f'{a}/{of}':>7}{w} {sum(v[2] for v in values):5.0f} " \
           f"{max(v[3] for v in values) / 1024:5.0f}"

def line(label, keys, of):
    print(f"{label:<25}" + "".join(
        " | " + fmt([cell[k + (t,)] for k in keys if k + (t,) in cell], of) for t in tools))

print(f"formulas answered, of 16 a net; {limit} s a file; `!`: a wrong answer among them")
print(f"{'':<25}" + "".join(f" | {h:<20}" for h in ("gdpn", "gdpn --no-reduction", "LoLA")))
print(f"{'category / net':<25}" + " | answered   sec   MiB" * 3)
for cat in categories:
    line(cat, [(n, cat) for n in nets], 16 * len(nets))
    for n in nets:
        line("  " + n, [(n, cat)], 16)
line("all", [(n, c) for n in nets for c in categories], 16 * len(nets) * len(categories))
PY
wrong=$(awk -F'\t' '{s += $6} END {print s + 0}' "$work/results.tsv")
if ((wrong)); then
  echo "*** $wrong WRONG answer(s): see the lines above" >&2
  exit 1
fi
