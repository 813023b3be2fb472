#!/usr/bin/env bash
# The pictures of docs/ide.md's "Newer versions of parts" and "Save as Part"
# (docs/images/ide-parts-update.png, docs/images/ide-save-as-part.png), taken by the headless
# IDE on tests/data/part_update: a model keeping version 1 of the test part lamp, whose library
# holds version 2. Needs a build (cmake --preset ci && cmake --build build/ci).
# Usage: scripts/ide-parts-pictures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
gdpn=$(realpath "${1:-build/ci}/apps/gdpn/gdpn")
images=$(realpath docs/images)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# in the work folder, so that the pictures show short relative paths
cp tests/data/part_update/station.gdpn.yaml "$work/"
cp -r tests/data/part_update/data "$work/library"
cd "$work"
ide() {  # a replay on the model with the user's data folder $1, the user's other folders in $work
  XDG_DATA_HOME="$1" XDG_CONFIG_HOME=config XDG_STATE_HOME=state "$gdpn" ide station.gdpn.yaml --headless \
    --size 1600x900 --replay "$2" --screenshot "$3"
}
# user input only, at the named items of the IDE's report (docs/ide.md, "Replay files")
cat > update.yaml <<'YAML'
- click: [palette, updates, update]
YAML
ide library update.yaml "$images/ide-parts-update.png"
cat > save.yaml <<'YAML'
- click: [tree, rows, shelf]
- press: save-as-part
- type: wall_shelf
- click: [save_as_part, fields, group]
- type: Fixtures
YAML
ide data save.yaml "$images/ide-save-as-part.png"
ls -l "$images/ide-parts-update.png" "$images/ide-save-as-part.png"
