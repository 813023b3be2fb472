#!/usr/bin/env bash
# The pictures of docs/ide.md's scale and aim manipulators, taken by the headless IDE: a crate
# being scaled by the tab on its +x+y edge, and a spot light being aimed at the crate, written to
# docs/images/ide-scale.png and docs/images/ide-spot.png. Each drag goes where a first run's
# report places the handles. Needs a build (cmake --preset ci && cmake --build build/ci).
# Usage: scripts/ide-manipulator-pictures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/ci}
gdpn="$PWD/$build/apps/gdpn/gdpn"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out="$PWD/docs/images"
export XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state"
cat > "$work/stage.gdpn.yaml" <<'YAML'
gdpn: 1
scene:
  - Camera: {name: view, position: [1.7, -2.4, 1.6], target: [-0.2, 0.1, 0.45]}
  - Light: {name: sun, kind: directional, direction: [-0.6, 0.8, -1.5], intensity: 0.8}
  - Light: {name: spot, kind: spot, location: [-1.0, 0.6, 1.5], direction: [0, 0, -1], cutoff: 20, intensity: 1.2}
  - Material: {name: concrete, diffuse: [0.62, 0.63, 0.65]}
  - Plane: {name: floor}
  - Transform:
      name: crate
      translation: [0, 0, 0.3]
      children: [{Material: {name: wood, diffuse: [0.78, 0.52, 0.26]}}, {Cube: {name: box, size: [0.6, 0.4, 0.6]}}]
pages:
  main: {}
YAML
# runs the IDE on the stage with replay file $1 (1600 x 900), then "$@" after it
ide() {
  local replay=$1
  shift
  "$gdpn" ide "$work/stage.gdpn.yaml" --headless --size 1600x900 --replay "$replay" "$@"
}
# where the report $1 places item $2 of the world view ("pivot", or a handle's name), pulled $3
# times as far from the pivot
point() {
  python3 - "$1" "$2" "${3:-1}" <<'PY'
import json, sys
world = json.load(open(sys.argv[1]))["world"]
(px, py), k = world["pivot"], float(sys.argv[3])
hx, hy = world["pivot"] if sys.argv[2] == "pivot" else world["handles"][sys.argv[2]]
print(f"[{round(px + k * (hx - px))}, {round(py + k * (hy - py))}]")
PY
}
# the crate's +x+y edge tab pulled out, so that the box grows along x and y
scale=$'- press: scale-tool\n- select: crate/box\n'
printf '%s' "$scale" > "$work/scale-1.yaml"
ide "$work/scale-1.yaml" --report "$work/scale.json"
printf '%s- drag: {from: [world, handles, scale +x+y], to: %s}\n- frames: 2\n' "$scale" "$(point "$work/scale.json" 'scale +x+y' 1.45)" \
  > "$work/scale-2.yaml"
ide "$work/scale-2.yaml" --screenshot "$out/ide-scale.png"
# the spot's aim dot dragged onto the crate (where the first run saw its centre)
aim=$'- press: aim-tool\n- select: spot\n'
printf '%s' "$aim" > "$work/spot-1.yaml"
ide "$work/spot-1.yaml" --report "$work/spot.json"
printf '%s- drag: {from: [world, handles, aim], to: %s}\n- frames: 2\n' "$aim" "$(point "$work/scale.json" pivot)" \
  > "$work/spot-2.yaml"
ide "$work/spot-2.yaml" --screenshot "$out/ide-spot.png"
ls -l "$out"/ide-scale.png "$out"/ide-spot.png
