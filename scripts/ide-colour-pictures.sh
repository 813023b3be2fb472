#!/usr/bin/env bash
# The pictures of docs/ide.md's coloured nets, taken by the headless IDE on
# tests/data/colour/orders.gdpn.yaml (a copy: nothing is saved): the colour sets view with a new
# set's definition left unclosed (its mistake marked, not applied), and an arc's inscription
# typed with a type error (marked at its column, the old text in force). Written to
# docs/images/ide-colour-sets.png and ide-inscription.png. Needs a build (cmake --preset ci &&
# cmake --build build/ci). Usage: scripts/ide-colour-pictures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/ci}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out="$PWD/docs/images"
cp tests/data/colour/orders.gdpn.yaml "$work/orders.gdpn.yaml"
mkdir -p "$work/config/gdpn"
echo "palette=0" > "$work/config/gdpn/ide.ini"
# the bottom panel taller, so that the view shows its rows
cat > "$work/sets.yaml" <<'YAML'
- drag: {from: [900, 641], to: [900, 461]}
- press: colour-sets
- frames: 2
- click: [colour_sets, fields, new name]
- type: Size
- click: [colour_sets, fields, new definition]
- type: '{enum: [small, large'
- click: [1400, 887]                      # the pointer off the fields (the status bar)
YAML
cat > "$work/inscription.yaml" <<'YAML'
- drag: {from: [900, 641], to: [900, 461]}
- select: 'main: waiting -> serve'
- frames: 2
- click: [inspector, fields, inscription a0]
- key: ctrl+a
- type: '(s, n)'
- key: enter
YAML
for shot in sets:ide-colour-sets inscription:ide-inscription; do
  XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state" "$build/apps/gdpn/gdpn" ide "$work/orders.gdpn.yaml" \
    --headless --size 1600x900 --replay "$work/${shot%%:*}.yaml" --screenshot "$out/${shot##*:}.png"
done
ls "$out"/ide-colour-sets.png "$out"/ide-inscription.png
