#!/usr/bin/env bash
# The IDE's speed, as a user meets it: whole processes of `gdpn ide`, each measured REPEATS
# times (default 3), the median printed.
#   open      the factory to its first frame, headless, 1600 x 900
#   idle      240 headless frames of the factory with nothing running (per frame)
#   running   240 headless frames running in real time (per frame; a headless frame always
#             draws the world view in full: its resolution follows only a window's frame rate)
#   window    the factory running in a real window under Xvfb for 8 s: the frame rate the
#             status bar shows at the end, and the share of the world view drawn
#   net-fit   240 headless frames of a generated page of 10,000 transitions and 10,000 places,
#             fitted into the net view (per frame)
#   net-pan   the same page zoomed in (the wheel, 20 clicks) and panned by 30 middle-button drags of 11
#             frames each (per frame)
#   net-edit  the factory's place P3 dragged in the net view 24 times (10 frames each, each a
#             move edit; per frame)
#   set-edit  240 field edits of the factory (`set`, one a frame: the world view draws again
#             each time; per frame)
# Needs a Release build (cmake --preset ci && cmake --build build/ci) and, for `window`,
# xvfb-run. Usage: bench/ide_bench.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"
export XDG_CONFIG_HOME="$work/config"  # the default layout, not the user's

seconds() {  # seconds COMMAND...: wall-clock seconds of one run
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
each() {  # each COMMAND...: the median of REPEATS runs, seconds
  for _ in $(seq "$repeats"); do seconds "$@"; done | median
}

factory=examples/factory
printf -- '- frames: 1\n' >"$work/one.yaml"
printf -- '- frames: 241\n' >"$work/idle.yaml"
printf -- '- press: run\n- frames: 240\n' >"$work/run.yaml"
{
  printf -- '- wheel: {at: [1390, 340], clicks: 20}\n- frames: 19\n'
  for i in $(seq 30); do printf -- '- drag: {from: [%d, 340], to: [%d, 360], button: middle}\n' $((1300 + i % 2 * 60)) $((1320 + i % 2 * 60)); done
} >"$work/pan.yaml"
python3 - "$work/big.gdpn.yaml" <<'EOF'
import sys
n, cols = 10000, 100
lines = ["gdpn: 1", "settings: {dt: 1, until: 10}", "pages:", "  main:", "    places:"]
for i in range(n):
    r, c = divmod(i, cols)
    lines.append(f"      p{i}: {{{'tokens: 1, ' if i % 10 == 0 else ''}at: [{2 * c}, {2 * r}]}}")
lines.append("    transitions:")
for i in range(n):
    r, c = divmod(i, cols)
    lines.append(f"      t{i}: {{at: [{2 * c + 1}, {2 * r}]}}")
lines.append("    arcs:")
for i in range(n):
    lines += [f"      - p{i} -> t{i}", f"      - t{i} -> p{(i + 1) % n}"]
open(sys.argv[1], "w").write("\n".join(lines) + "\n")
EOF

for i in $(seq 24); do
  printf -- '- drag: {from: [1304, %d], to: [1304, %d]}\n' $((366 + i % 2 * 20)) $((366 + (i + 1) % 2 * 20))
done >"$work/netdrag.yaml"
for i in $(seq 240); do printf -- '- set: {node: arm/turn, field: vel1, value: %d}\n' $((100 + i)); done >"$work/sets.yaml"

ide() { "$gdpn" ide "$1" --headless --size 1600x900 --replay "$2"; }
open=$(each ide $factory "$work/one.yaml")
idle=$(each ide $factory "$work/idle.yaml")
running=$(each ide $factory "$work/run.yaml")
big_open=$(each ide "$work/big.gdpn.yaml" "$work/one.yaml")
big=$(each ide "$work/big.gdpn.yaml" "$work/idle.yaml")
big_pan=$(each ide "$work/big.gdpn.yaml" "$work/pan.yaml")
per_frame() { echo "($1 - $2) * 1000 / ${3:-240}" | bc -l | xargs printf '%.1f'; }
printf 'open the factory (first frame)      %.2f s\n' "$open"
printf 'idle frame                          %s ms\n' "$(per_frame "$idle" "$open")"
printf 'running frame (world in full)       %s ms\n' "$(per_frame "$running" "$open")"
printf 'net view, 10,000 transitions fitted %s ms a frame (opening it: %.2f s)\n' "$(per_frame "$big" "$big_open")" "$big_open"
printf 'net view, zoomed in and panned      %s ms a frame\n' "$(per_frame "$big_pan" "$big_open" 350)"
net_edit=$(each ide $factory "$work/netdrag.yaml")
set_edit=$(each ide $factory "$work/sets.yaml")
printf 'net edits (a place dragged)         %s ms a frame\n' "$(per_frame "$net_edit" "$open")"
printf 'field edits (the world drawn again) %s ms a frame\n' "$(per_frame "$set_edit" "$open")"

if command -v xvfb-run >/dev/null; then
  for _ in $(seq "$repeats"); do
    xvfb-run -a -s "-screen 0 1600x900x24" "$gdpn" ide $factory --quit-after 8 --report "$work/w.json" >/dev/null 2>&1
    python3 -c "import json,sys; s=json.load(open(sys.argv[1]))['status']; print(s['fps'], s['world_scale'])" "$work/w.json"
  done | sort -g | awk '{f[NR]=$1; s[NR]=$2} END {m=int((NR+1)/2); printf "window, factory running              %.1f fps (world at %.0f %%)\n", f[m], 100*s[m]}'
fi
