#!/usr/bin/env bash
# Runs the model-loader fuzzer for SECONDS (default 60), seeded with every example and every
# good and bad test model. Fails on any crash, hang, leak or sanitizer report.
# Needs the fuzz build: cmake --preset fuzz && cmake --build --preset fuzz
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
fuzzer=build/fuzz/fuzz/model_loader_fuzz
work=build/fuzz/run
rm -rf "$work" && mkdir -p "$work/corpus" "$work/seeds"
find examples tests/data -name '*.gdpn.yaml' -exec cp {} "$work/seeds/" \;
"$fuzzer" "$work/corpus" "$work/seeds" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 -artifact_prefix="$work/" -print_final_stats=1 2>"$work/log" || {
  tail -n 60 "$work/log"
  echo "fuzz: the model loader failed; the input is in $work/" >&2
  exit 1
}
grep -E "^(Done|stat::number_of_executed_units)" "$work/log" || true
echo "fuzz: model loader survived ${seconds} s"
