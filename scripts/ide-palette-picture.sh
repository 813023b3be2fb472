#!/usr/bin/env bash
# The picture of docs/ide.md's parts palette (docs/images/ide-palette.png), taken by the headless
# IDE while it builds a station from an empty file by dragging parts from the palette, the last
# one held over the world view: its ghost where it will land. Needs a build (cmake --preset ci &&
# cmake --build build/ci) and the parts library (the source tree's parts/, or PARTS_DIR).
# Usage: scripts/ide-palette-picture.sh [BUILD_DIR] [PARTS_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/ci}
parts=$(realpath "${2:-parts}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/data/gdpn"
ln -s "$parts" "$work/data/gdpn/parts"
printf 'gdpn: 1\n' > "$work/station.gdpn.yaml"
# user input only, at the named items of the IDE's report (docs/ide.md, "Replay files")
cat > "$work/palette.yaml" <<'YAML'
- wheel: {at: [800, 350], clicks: 3}
- drag: {from: [palette, items, belt_conveyor], to: [world, center]}
- drag: {from: [palette, items, belt_conveyor], to: [world, parts, belt_conveyor1, +x]}
- drag: {from: [palette, items, pusher], to: [world, parts, belt_conveyor2, -y]}
- key: enter
- click: [palette, controls, search]
- type: emitter
- drag: {from: [palette, items, emitter], to: [world, parts, belt_conveyor1, top -x]}
- click: [palette, controls, search]
- key: ctrl+a
- type: bin
- drag: {from: [palette, items, bin], to: [world, parts, belt_conveyor2, +y]}
- click: [palette, controls, search]
- key: ctrl+a
- type: beam
- drag: {from: [palette, items, through_beam], to: [world, parts, belt_conveyor2, top +x]}
- view: all
- wheel: {at: [800, 350], clicks: 1}
- click: [palette, controls, search]
- key: ctrl+a
- type: remover
- drag: {from: [palette, items, remover], to: [world, parts, belt_conveyor2, +x], hold: true}
YAML
XDG_DATA_HOME="$work/data" XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state" "$build/apps/gdpn/gdpn" ide \
  "$work/station.gdpn.yaml" --headless --size 1600x900 --replay "$work/palette.yaml" --screenshot docs/images/ide-palette.png
ls -l docs/images/ide-palette.png
