#!/bin/sh
# The IDE's real window under Xvfb (Mesa llvmpipe): open a model, run SECONDS (default 2) in
# real time, take a screenshot, quit with exit 0; still running at the end (a script error
# would have paused it). Skipped (77) when xvfb-run is missing.
# usage: window_smoke.sh GDPN MODEL [SECONDS]
set -eu
command -v xvfb-run >/dev/null 2>&1 || { echo "xvfb-run missing: skipped"; exit 77; }
dir=$(mktemp -d "${TMPDIR:-/tmp}/gdpn_ide_smoke_$$.XXXXXX")
trap 'rm -rf "$dir"' EXIT
XDG_CONFIG_HOME="$dir/config" xvfb-run -a -s "-screen 0 1600x900x24" \
  "$1" ide "$2" --size 1280x720 --quit-after "${3:-2}" --screenshot "$dir/shot.png" --report "$dir/report.json"
test -s "$dir/shot.png" || { echo "no screenshot"; exit 1; }
grep -q '"mode": "running"' "$dir/report.json" || { echo "the model did not run"; cat "$dir/report.json"; exit 1; }
echo "ok: $(wc -c < "$dir/shot.png") bytes of screenshot"
