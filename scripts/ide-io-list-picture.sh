#!/usr/bin/env bash
# The picture of docs/ide.md's I/O list, taken by the headless IDE: the test part `lamp`
# (tests/data/parts/lamp.gdpn.yaml) with its control pattern, run a step, `seen` forced to 1
# (the pattern lights the lamp), `speed` forced by typing 0.25, and `light` asked to 0 while
# paused (waiting for the next step), beside a second lamp; written to docs/images/ide-io-list.png. Needs a build
# (cmake --preset ci && cmake --build build/ci).
# Usage: scripts/ide-io-list-picture.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/ci}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out="$PWD/docs/images"
{
  cat tests/data/parts/lamp.gdpn.yaml
  cat <<'YAML'
io:
  coils:
    0: {part: lamp1, io: light}
pages:
  main:
    places:
      waiting: {tokens: 1}
      done: {}
    transitions:
      watch: {guard: 'sim.part("lamp1").height > 0.5'}
    arcs: [waiting -> watch, watch -> done]
    instances:
      lamp1: {type: lamp}
      lamp1_control: {type: lamp_control, part: lamp1}
      lamp2: {type: lamp, translation: [0.4, 1.2, 0], params: {length: 1}}
scene:
  - Light: {}
  - Camera: {name: view, position: [2.4, -2.2, 2.0], target: [1, 0, 0.7]}
  - Transform: {translation: [0, 0, -0.3], children: [{Plane: {}}]}
YAML
} > "$work/lamp.gdpn.yaml"
# the bottom panel taller and the diagnostics narrower, so that the list shows whole
cat > "$work/io.yaml" <<'YAML'
- drag: {from: [900, 641], to: [900, 561]}
- drag: {from: [1177, 760], to: [1297, 760]}
- click: [inspector_tabs, I/O]
- press: step
- click: [io_list, rows, main/lamp1.seen, force1]
- steps: 5
- click: [io_list, rows, main/lamp1.speed, field]
- type: "0.25"
- key: enter
- steps: 2
- click: [io_list, rows, main/lamp1.light, force0]
- click: [1400, 887]                      # the pointer off the buttons (the status bar)
YAML
XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state" "$build/apps/gdpn/gdpn" ide "$work/lamp.gdpn.yaml" \
  --headless --size 1600x900 --replay "$work/io.yaml" --screenshot "$out/ide-io-list.png"
ls "$out"/ide-io-list.png
