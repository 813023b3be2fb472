#!/usr/bin/env bash
# The picture of docs/ide.md's I/O list, taken by the headless IDE on examples/station: 6 s into
# the run, the pusher's valve `extend` forced to 1 (the plate goes out and its front limit
# switch answers), the belt's `speed` forced to 0.2 m/s by typing, and the photo-eye's
# `detected` asked to 1 while paused (waiting for the next step); written to
# docs/images/ide-io-list.png. Needs a build (cmake --preset ci && cmake --build build/ci).
# Usage: scripts/ide-io-list-picture.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/ci}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out="$PWD/docs/images"
# the bottom panel taller and the diagnostics narrower, so that the list shows more
cat > "$work/io.yaml" <<'YAML'
- drag: {from: [900, 641], to: [900, 521]}
- drag: {from: [1177, 760], to: [1297, 760]}
- click: [inspector_tabs, I/O]
- run: 6
- click: [io_list, rows, main/pusher1.extend, force1]
- steps: 60
- click: [io_list, rows, main/belt_conveyor1.speed, field]
- type: "0.2"
- key: enter
- steps: 2
- click: [io_list, rows, main/diffuse_sensor1.detected, force1]
- click: [1400, 887]                      # the pointer off the buttons (the status bar)
YAML
XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state" "$build/apps/gdpn/gdpn" ide examples/station \
  --headless --size 1600x900 --replay "$work/io.yaml" --screenshot "$out/ide-io-list.png"
ls "$out"/ide-io-list.png
