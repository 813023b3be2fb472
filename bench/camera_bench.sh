#!/usr/bin/env bash
# A 320 x 240 ColorCamera at 30 Hz in the factory (issue 23), rendered offscreen through EGL
# (llvmpipe where there is no GPU): `gdpn run --quiet` of the whole 120 s, the camera absent,
# present but unread, and read by a script at every sample (`c0.image`: rendered, read back and
# handed over as a NumPy array). The figures: wall-clock seconds and the real-time factor
# (model seconds per second), the median of REPEATS runs (default 3), and the cost of one
# picture handed to Python: the difference of the read and unread runs over the pictures taken.
# Needs a Release build (cmake --preset ci && cmake --build build/ci).
# Usage: bench/camera_bench.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"

cp examples/factory/factory.py "$work/"
# the camera over the first conveyor, looking down at the belt; a place watches it
camera='  - Transform: {name: mast, translation: [-5, 1.6, 3], rotation: [0, 1, 0, 90], children: [{ColorCamera: {name: cam, width: 320, height: 240, fov: 60, rate: 30}}]}'
watch='      watch: {sensors: {c0: mast/cam}, on_sample: "c0.image"}'
awk -v cam="$camera" '{print} /^scene:/ {print cam}' examples/factory/factory.gdpn.yaml >"$work/unread.gdpn.yaml"
awk -v cam="$camera" -v watch="$watch" '{print} /^scene:/ {print cam} /^    places:/ && !done {print watch; done=1}' \
  examples/factory/factory.gdpn.yaml >"$work/read.gdpn.yaml"
cp examples/factory/factory.gdpn.yaml "$work/none.gdpn.yaml"

printf '%-24s %10s %14s\n' "camera" "time [s]" "model s / s"
declare -A wall=()
for variant in none unread read; do
  times=()
  for ((r = 0; r < repeats; ++r)); do
    /usr/bin/time -f '%e' -o "$work/time" "$gdpn" run "$work/$variant.gdpn.yaml" --quiet >"$work/out.txt"
    times+=("$(cat "$work/time")")
  done
  t=$(printf '%s\n' "${times[@]}" | median)
  wall[$variant]=$t
  printf '%-24s %10.2f %14.1f\n' "$variant" "$t" "$(echo "120 / $t" | bc -l)"
done
pictures=$((120 * 30))
printf 'one picture to Python: %.2f ms (%d pictures)\n' \
  "$(echo "(${wall[read]} - ${wall[unread]}) * 1000 / $pictures" | bc -l)" "$pictures"
