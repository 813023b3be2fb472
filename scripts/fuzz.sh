#!/usr/bin/env bash
# Runs each libFuzzer target for SECONDS (default 60): the model loader, seeded with every
# example and test model; the PNML reader, seeded with the test nets and the conformance nets
# (place/transition and coloured);
# the mesh loader, seeded with the test meshes; the elevation loader, seeded with the test
# elevation files; the input-event reader, seeded with the test input files; the query reader,
# seeded with the test queries; the witness reader; the Modbus request decoder, seeded with the
# test frames. Eight targets: about eight times SECONDS in all. Fails on any crash, hang, leak
# or sanitizer report.
# Needs the asan build, which holds the fuzz targets: cmake --preset asan && cmake --build --preset asan
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
# leaks inside Assimp and Coin3D on malformed meshes are theirs (see the file)
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"

fuzz() {  # fuzz NAME MAX_LEN 'NAME PATTERNS' SEED_DIRS...
  local name=$1 max_len=$2 patterns=$3
  shift 3
  local work=build/asan/fuzz-run/$name
  rm -rf "$work" && mkdir -p "$work/corpus" "$work/seeds"
  local find_names=() list pattern
  read -ra list <<<"$patterns"
  for pattern in "${list[@]}"; do
    find_names+=(${find_names[@]:+-o} -name "$pattern")
  done
  for dir in "$@"; do
    # each seed under its path's name: folders of one model.pnml each do not overwrite one another
    [ -d "$dir" ] && find "$dir" -maxdepth 1 -type f \( "${find_names[@]}" \) -print0 |
      while IFS= read -r -d '' f; do cp "$f" "$work/seeds/${f//\//_}"; done
  done
  "build/asan/fuzz/$name" "$work/corpus" "$work/seeds" -max_total_time="$seconds" -max_len="$max_len" -timeout=10 \
    -rss_limit_mb=2048 -artifact_prefix="$work/" -print_final_stats=1 2>"$work/log" || {
    tail -n 60 "$work/log"
    echo "fuzz: $name failed; the input is in $work/" >&2
    exit 1
  }
  grep -E "^(Done|stat::number_of_executed_units)" "$work/log" || true
  echo "fuzz: $name survived ${seconds} s"
}

meshes='*.obj *.stl *.ply *.gltf *.glb *.dae *.3ds *.wrl *.iv'
fuzz model_loader_fuzz 4096 '*.gdpn.yaml' examples/basics/* examples/plant/* examples/sorting examples/vision tests/data/good tests/data/bad tests/data/colour tests/data/hybrid
fuzz pnml_reader_fuzz 131072 '*.pnml' tests/data/pnml tests/data/conformance tests/data/conformance-col/*
fuzz mesh_loader_fuzz 32768 "$meshes" tests/data/meshes tests/data/bad/files tests/data/physics tests/data/good/parts
fuzz elevation_loader_fuzz 4096 '*.asc *.xyz *.tif *.png' tests/data/elevation tests/data/bad/files
fuzz input_events_fuzz 4096 '*.input.yaml' tests/data/input
fuzz query_parser_fuzz 8192 '*.query *.xml' tests/data/queries
fuzz witness_fuzz 4096 '*.json' tests/data/witnesses
fuzz modbus_request_fuzz 1024 "*.bin" tests/data/modbus
fuzz opcua_message_fuzz 8192 "*.bin" tests/data/opcua
