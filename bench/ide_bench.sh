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
#   drop      examples/station (7 parts) with 20 belts dragged from the palette, each onto the
#             last one's end (+x): the drop and its next frame, and the ghost's way across the
#             window, each as milliseconds over as many idle frames (timed between screenshots
#             in one process; see `drop` below)
#   station50 10 stations of examples/station's emitter, belt, photo-eye, pusher (with its
#             control) and bin: 50 parts (generated): 240 headless frames running in real time
#             (per frame, and frames per second), and 8 s in a real window under Xvfb as
#             `window` measures the factory
# The windows' frame rates are given twice: as the status bar shows it, and counted (the
# buffer swaps, through a preloaded counter built with cc, when there is one).
# Needs a Release build (cmake --preset ci && cmake --build build/ci) and, for `window` and
# `station50`'s window, xvfb-run. Usage: bench/ide_bench.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/common.sh "$@"
export XDG_CONFIG_HOME="$work/config"  # the default layout, not the user's
export XDG_DATA_HOME="$work/data" XDG_DATA_DIRS="$work/data" XDG_STATE_HOME="$work/state"  # the source tree's parts alone

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

# drop: one process per repeat. Each of the 20 drops is four screenshots apart: the view framing
# all (`view: all`), screenshot z; a held drag from the palette to the last belt's +x end (the
# ghost on its way: 11 frames), screenshot a; the drag going on to where it is and let go there
# (the drop) and the next frame (11 frames), screenshot b; 11 idle frames, screenshot c. The
# files' times give the intervals, each of 11 frames and a screenshot: a drop is (b - a) less
# (c - b), the ghost's way across (a - z) less (c - b), averaged over the 20.
mkdir -p "$work/shots"
{
  printf -- '- click: [palette, controls, search]\n- type: belt\n- frames: 2\n'
  for k in $(seq 20); do
    end="[world, parts, belt_conveyor$k, +x]"
    printf -- '- view: all\n- screenshot: %s/z%02d.png\n' "$work/shots" "$k"
    printf -- '- drag: {from: [palette, items, belt_conveyor], to: %s, hold: true}\n- screenshot: %s/a%02d.png\n' "$end" "$work/shots" "$k"
    printf -- '- drag: {from: %s, to: %s}\n- frames: 1\n- screenshot: %s/b%02d.png\n' "$end" "$end" "$work/shots" "$k"
    printf -- '- frames: 11\n- screenshot: %s/c%02d.png\n' "$work/shots" "$k"
  done
} >"$work/drop.yaml"
for _ in $(seq "$repeats"); do
  rm -f "$work"/shots/*.png
  "$gdpn" ide examples/station --headless --size 1600x900 --autosave 0 --replay "$work/drop.yaml" --report "$work/drop.json" >/dev/null 2>&1
  python3 - "$work/shots" "$work/drop.json" <<'EOF'
import json, os, sys
t = lambda name: os.stat(f"{sys.argv[1]}/{name}.png").st_mtime_ns / 1e6
drops = [(t(f"b{k:02d}") - t(f"a{k:02d}")) - (t(f"c{k:02d}") - t(f"b{k:02d}")) for k in range(1, 21)]
ways = [(t(f"a{k:02d}") - t(f"z{k:02d}")) - (t(f"c{k:02d}") - t(f"b{k:02d}")) for k in range(1, 21)]
last = json.load(open(sys.argv[2]))["status"]["message"]
assert last.startswith("placed belt_conveyor21 "), f"the last drop: {last}"
print(sum(drops) / 20, sum(ways) / 20)
EOF
done | sort -g | awk '{d[NR]=$1; w[NR]=$2} END {m=int((NR+1)/2); printf "drop a belt from the palette        %.0f ms more than 11 idle frames (the ghost dragged across: %.0f ms more)\n", d[m], w[m]}'

# station50: examples/station's emitter, belt, photo-eye, pusher (with its control) and bin,
# 10 times in 2 columns of 5, each with its own net (a red box at the photo-eye stops the belt
# and asks for a stroke); every box red. Checked first: 20 s of it run put boxes in the bins.
mkdir -p "$work/station50"
python3 - examples/station/sorting_station.gdpn.yaml "$work/station50/station50.gdpn.yaml" <<'EOF'
import re, sys, yaml
class Loader(yaml.SafeLoader):  # YAML 1.2's booleans: the parts' `on:` and `off:` stay keys
    pass
Loader.yaml_implicit_resolvers = {k: [(t, r) for t, r in v if t != "tag:yaml.org,2002:bool"]
                                  for k, v in yaml.SafeLoader.yaml_implicit_resolvers.items()}
Loader.add_implicit_resolver("tag:yaml.org,2002:bool", re.compile(r"^(?:true|false)$"), list("tf"))
m = yaml.load(open(sys.argv[1]), Loader=Loader)
one = m["pages"]["main"]["instances"]
instances, places, transitions, arcs = {}, {}, {}, []
for k in range(1, 11):
    dx, dy = 6.0 * ((k - 1) % 2), 3.5 * ((k - 1) // 2)
    for kind in ("emitter", "belt_conveyor", "pusher", "diffuse_sensor", "bin"):
        i = dict(one[kind + "1"])
        x, y, z = i.get("translation", [0, 0, 0])
        i["translation"] = [x + dx, y + dy, z]
        if kind == "emitter":
            i["params"] = {"colours": 1}
        instances[f"{kind}{k}"] = i
    instances[f"pusher{k}_control"] = {"type": "pusher_control", "part": f"pusher{k}"}
    places.update({f"eye{k}": {"sensors": {"c0": f"diffuse_sensor{k}/head/beam/ray"}}, f"ready{k}": {"tokens": 1},
                   f"pushing{k}": {}, f"strokes{k}": {}})
    transitions.update({f"red{k}": {"pre_fire": f'sim.part("belt_conveyor{k}").run = False'},
                        f"resume{k}": {"pre_fire": f'sim.part("belt_conveyor{k}").run = True'}})
    arcs += [{"from": f"eye{k}", "to": f"red{k}", "condition": "c0.active"}, f"ready{k} -> red{k}",
             f"red{k} -> pushing{k}", f"red{k} -> pusher{k}_control/request", f"pushing{k} -> resume{k}",
             f"pusher{k}_control/done -> resume{k}", f"resume{k} -> ready{k}", f"resume{k} -> strokes{k}"]
m["description"] = "examples/station's emitter, belt, photo-eye, pusher and bin, 10 times: 50 parts"
m["scripts"] = {"globals": "def summary():\n    return {\n"
                "        \"boxes made\": sum(int(sim.part(f\"emitter{k}\").emitted) for k in range(1, 11)),\n"
                "        \"boxes in the bins\": sum(int(sim.part(f\"bin{k}\").count) for k in range(1, 11)),\n"
                "    }\n"}
m["pages"] = {"main": {"places": places, "transitions": transitions, "instances": instances, "arcs": arcs}}
del m["page_types"]["remover"], m["page_types"]["stack_light"]
for node in m["scene"]:
    if "Camera" in node:
        node["Camera"] = {"position": [4.5, -9.0, 11.0], "target": [4.5, 7.0, 0.0]}
class Dumper(yaml.SafeDumper):
    pass
Dumper.add_representer(str, lambda d, s: d.represent_scalar("tag:yaml.org,2002:str", s, style="|" if "\n" in s else None))
open(sys.argv[2], "w").write(yaml.dump(m, Dumper=Dumper, sort_keys=False, width=1000))
EOF
station50="$work/station50"
binned=$("$gdpn" run "$station50" --until 20 2>&1 | awk '/boxes in the bins:/ {print $NF}')
if ! [ "${binned:-0}" -gt 0 ]; then
  echo "station50: no box reached a bin in 20 s" >&2
  exit 1
fi
s50_open=$(each ide "$station50" "$work/one.yaml")
s50_running=$(each ide "$station50" "$work/run.yaml")
s50_frame=$(per_frame "$s50_running" "$s50_open")
printf 'station50 running, headless         %s ms a frame, %.1f fps (opening it: %.2f s)\n' "$s50_frame" "$(echo "1000 / $s50_frame" | bc -l)" "$s50_open"

if command -v xvfb-run >/dev/null; then
  # the buffer swaps counted: the frames a window really showed, beside the status bar's figure
  preload=""
  if command -v cc >/dev/null && cc -shared -fPIC -O2 -o "$work/swaps.so" -x c - -ldl 2>/dev/null <<'EOF'
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
typedef struct GLFWwindow GLFWwindow;
static double first, last;
static long swaps;
void glfwSwapBuffers(GLFWwindow* w) {
  static void (*real)(GLFWwindow*);
  if (!real) real = (void (*)(GLFWwindow*))dlsym(RTLD_NEXT, "glfwSwapBuffers");
  real(w);
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  last = t.tv_sec + t.tv_nsec * 1e-9;
  if (swaps++ == 0) first = last;
}
__attribute__((destructor)) static void done(void) {
  FILE* out = getenv("SWAPS") ? fopen(getenv("SWAPS"), "w") : NULL;
  if (out) fprintf(out, "%g\n", swaps > 1 ? (swaps - 1) / (last - first) : 0.0), fclose(out);
}
EOF
  then preload="$work/swaps.so"; fi
  window() {  # window MODEL LABEL: the status bar's frame rate and world view share, and the counted one
    for _ in $(seq "$repeats"); do
      echo 0 >"$work/swaps"
      SWAPS="$work/swaps" xvfb-run -a -s "-screen 0 1600x900x24" env ${preload:+LD_PRELOAD="$preload"} \
        "$gdpn" ide "$1" --quit-after 8 --autosave 0 --report "$work/w.json" >/dev/null 2>&1
      python3 -c "import json,sys; s=json.load(open(sys.argv[1]))['status']; print(s['fps'], s['world_scale'], open(sys.argv[2]).read().strip())" "$work/w.json" "$work/swaps"
    done >"$work/windows"
    printf '%-35s %.1f fps (world at %.0f %%; frames counted: %.1f a second)\n' "$2" "$(cut -d' ' -f1 "$work/windows" | median)" \
      "$(cut -d' ' -f2 "$work/windows" | median | awk '{print 100 * $1}')" "$(cut -d' ' -f3 "$work/windows" | median)"
  }
  window $factory "window, factory running"
  window "$station50" "window, station50 running"
fi
