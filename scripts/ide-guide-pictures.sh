#!/usr/bin/env bash
# The pictures of docs/ide.md's guide, taken by the headless IDE while it performs the tutorial
# (examples/tutorial/build.yaml): the scene built, the net drawn, the scripts typed, and the run,
# written to docs/images/ide-guide-*.png. Needs a build (cmake --preset ci && cmake --build build/ci).
# Usage: scripts/ide-guide-pictures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/ci}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
out="$PWD/docs/images"
# a picture before three of the tutorial's sections and one at its end, the whole scene in view
python3 - examples/tutorial/build.yaml "$work/guide.yaml" "$out" <<'PY'
import sys
src, dst, out = sys.argv[1:]
before = {"# ---- the net": "scene", "# ---- the scripts": "net", "# ---- the model's own figure": "scripts"}
lines = []
for line in open(src):
    for start, name in before.items():
        if line.startswith(start):
            lines.append(f"- view: all\n- frames: 20\n- screenshot: {out}/ide-guide-{name}.png\n")
    lines.append(line)
lines.append(f"- frames: 20\n- screenshot: {out}/ide-guide-run.png\n")
open(dst, "w").writelines(lines)
PY
XDG_CONFIG_HOME="$work/config" XDG_STATE_HOME="$work/state" "$build/apps/gdpn/gdpn" ide "$work/pusher.gdpn.yaml" \
  --headless --size 1600x1000 --replay "$work/guide.yaml"
ls "$out"/ide-guide-*.png
