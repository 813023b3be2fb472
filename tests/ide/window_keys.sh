#!/bin/sh
# No lost keys in the IDE's real window: under Xvfb, xdotool drags a place of a copy of MODEL's
# net (an edit), then types `xdotool key ctrl+s` with its default 12 ms between press and
# release, much less than a frame of the IDE on a software renderer; the model file must be
# saved with the place where it was dropped. The positions are those the headless IDE reports
# for the same window size. Before the drag, Reset (Shift+F5: the window was opened running),
# then Ctrl+V with nothing on the clipboard (a fresh
# display's) must do nothing and print nothing (GLFW's "Format unavailable" once did); at the
# end SIGTERM ends the IDE at once (within 5 s here; the time is printed) as the signal's
# default would (status 143), the saved file intact. Skipped (77) when Xvfb or xdotool is missing.
# usage: window_keys.sh GDPN MODEL.gdpn.yaml PLACE (a place of its page `main`)
set -eu
command -v Xvfb >/dev/null 2>&1 || { echo "Xvfb missing (Debian package xvfb): skipped"; exit 77; }
command -v xdotool >/dev/null 2>&1 || { echo "xdotool missing (Debian package xdotool): skipped"; exit 77; }
gdpn=$1
place=$3
dir=$(mktemp -d "${TMPDIR:-/tmp}/gdpn_ide_keys_$$.XXXXXX")
xvfb=""
ide=""
cleanup() {
  [ -z "$ide" ] || kill "$ide" 2>/dev/null || true
  [ -z "$xvfb" ] || kill "$xvfb" 2>/dev/null || true
  rm -rf "$dir"
}
trap cleanup EXIT
export XDG_CONFIG_HOME="$dir/config" XDG_STATE_HOME="$dir/state"
model="$dir/model.gdpn.yaml"
cp "$2" "$model"
cp "$model" "$dir/original.yaml"

# where the place stands in a 1280 x 720 window, from the headless IDE's report
"$gdpn" ide "$model" --headless --size 1280x720 --report "$dir/report.json" >/dev/null
pos=$(python3 -c 'import json, sys; p = json.load(open(sys.argv[1]))["net_view"]["at"]["main/" + sys.argv[2]]; print(int(p[0]), int(p[1]))' \
  "$dir/report.json" "$place") || { echo "the headless IDE shows no place main/$place"; exit 1; }
x=${pos% *}
y=${pos#* }

# a display of our own: Xvfb writes its number once it listens
Xvfb -displayfd 3 -screen 0 1600x900x24 -nolisten tcp 3>"$dir/display" 2>"$dir/xvfb.log" &
xvfb=$!
i=0
while [ ! -s "$dir/display" ]; do
  i=$((i + 1))
  [ "$i" -le 600 ] || { echo "Xvfb did not start"; cat "$dir/xvfb.log"; exit 1; }
  sleep 0.1
done
DISPLAY=":$(cat "$dir/display")"
export DISPLAY

# the IDE in its window (it ends by itself after 10 minutes, should this script be killed)
"$gdpn" ide "$model" --size 1280x720 --quit-after 600 >"$dir/ide.log" 2>&1 &
ide=$!
wid=$(timeout 120 xdotool search --sync --onlyvisible --name "gdpn ide") || {
  echo "no IDE window"
  cat "$dir/ide.log"
  exit 1
}
wid=$(echo "$wid" | head -n 1)
timeout 60 xdotool windowfocus --sync "$wid" || { echo "the window did not take the keyboard"; exit 1; }

# back to editing (--quit-after started the run), where paste is offered; nothing to paste:
# nothing happens, silently
xdotool key shift+F5 ctrl+v

# the edit: the place dragged 60 px to the right; then Ctrl+S, the default 12 ms
xdotool mousemove --window "$wid" "$x" "$y" mousedown 1 mousemove --window "$wid" $((x + 60)) "$y" mouseup 1
xdotool key ctrl+s

# the IDE takes the events in order, a frame at a time: wait for the file to change
i=0
while cmp -s "$model" "$dir/original.yaml"; do
  i=$((i + 1))
  if [ "$i" -gt 1200 ] || ! kill -0 "$ide" 2>/dev/null; then
    echo "Ctrl+S did not save the model"
    cat "$dir/ide.log"
    exit 1
  fi
  sleep 0.1
done
before=$(grep "^ *$place:" "$dir/original.yaml" || true)
after=$(grep "^ *$place:" "$model" || true)
if [ "$before" = "$after" ]; then
  echo "the model was saved without the drag of $place:"
  cat "$model"
  exit 1
fi
"$gdpn" check "$model" >/dev/null || { echo "the saved model does not check"; cat "$model"; exit 1; }
if grep -qE -- '-0([],]|$)' "$model"; then  # a place snapped to 0 was once written as -0
  echo "the saved model holds a negative zero:"
  grep -nE -- '-0([],]|$)' "$model"
  exit 1
fi
if grep -q "GLFW error" "$dir/ide.log"; then
  echo "the IDE printed a GLFW error (Ctrl+V with an empty clipboard?):"
  cat "$dir/ide.log"
  exit 1
fi

# SIGTERM: the IDE ends by it at once, saving nothing more
cp "$model" "$dir/saved.yaml"
(sleep 5 && kill -KILL "$ide" 2>/dev/null) &
watchdog=$!
start=$(date +%s%N)
kill -TERM "$ide"
status=0
wait "$ide" || status=$?
ended=$(( ($(date +%s%N) - start) / 1000000 ))
{ kill "$watchdog" && wait "$watchdog"; } 2>/dev/null || true
ide=""
[ "$status" -ne 137 ] || { echo "the IDE still ran 5 s after SIGTERM"; exit 1; }
[ "$status" -eq 143 ] || { echo "after SIGTERM the exit status is $status, not 143"; cat "$dir/ide.log"; exit 1; }
cmp -s "$model" "$dir/saved.yaml" || { echo "the model changed after SIGTERM"; exit 1; }
echo "ok: Ctrl+S saved $(grep "^ *$place:" "$model" | sed 's/^ *//'); SIGTERM ended the IDE in $ended ms"
