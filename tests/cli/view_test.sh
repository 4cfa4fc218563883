#!/usr/bin/env bash
# Checks of `simeco view` in a virtual X display (xvfb-run) on the Vulkan device there is: the window opens and
# draws frames, and its screenshot shows plants; moving the sun with --set moves the shadows to the other side of
# the plants; a broken edit of the scene on disk is reported at its line and column while the field before it keeps
# growing, and an edit that loads starts the field again; bad settings and a missing display are refused.
# Usage: view_test.sh SIMECO SOURCE_DIR
set -u
simeco=$1
source_dir=$2
. "$(dirname "$0")/checks.sh"
export PYTHONPATH="$(dirname "$0")"
cp "$source_dir/scenes/garden.eco" "$work/garden.eco"
scene="$work/garden.eco"

view() { # view LOG [OPTIONS...]: four garden plants in a small window, in a display of its own
  local log=$1
  shift
  xvfb-run -a -s "-screen 0 640x480x24" "$simeco" view "$scene" --plants 4 --size 320x240 "$@" >"$log" 2>&1
}

# No validation message, and no error, in a run's output.
clean() { ! grep -qiE 'validation|error' "$1"; }

# Multisampled (on a CPU device the viewer draws one sample a pixel unless told).
view "$work/a.txt" --frames 12 --screenshot "$work/a.png" --set msaa=4
code=$?
[ $code -eq 0 ] && clean "$work/a.txt"
ok=$?
check "view draws 12 multisampled frames, exits 0, cleanly ($code: $(grep -v warning "$work/a.txt" | head -c 400))" $ok
grep -q '12 frames, 12.0 s of growth, 4 plants' "$work/a.txt"
check "the field grows a tick a frame ($(tail -n 1 "$work/a.txt"))" $?

# The screenshot: the window's size, plants in it (green leaves), and the ground and sky around them.
python3 - "$work/a.png" <<'PY'
import sys
from png_pixels import read_png, is_leafy
width, height, rows = read_png(sys.argv[1])
assert (width, height) == (320, 240), (width, height)
leafy = sum(is_leafy(p) for row in rows for p in row)
assert 50 < leafy < width * height // 4, f"{leafy} leafy pixels"
PY
check "the screenshot shows the plants" $?

# The sun from +x, then from -x: the shadows fall on the other side of the plants.
view "$work/east.txt" --frames 12 --screenshot "$work/east.png" --set sun.azimuth=90 --set sun.elevation=35
view "$work/west.txt" --frames 12 --screenshot "$work/west.png" --set sun.azimuth=-90 --set sun.elevation=35
clean "$work/east.txt" && clean "$work/west.txt"
check "views with the sun set run cleanly" $?
python3 - "$work/east.png" "$work/west.png" <<'PY'
import sys
from collections import Counter
from png_pixels import read_png, is_leafy

def shadow_offset(path):
    """Mean x of the shadows minus mean x of the leaves: grey ground pixels well darker than the lit ground."""
    width, height, rows = read_png(path)
    ground = Counter(rows[y][x] for y in range(height * 3 // 4, height) for x in range(width)).most_common(1)[0][0]
    lit = sum(ground) / 3
    shade = [x for row in rows for x, p in enumerate(row) if max(p) - min(p) < 20 and sum(p) / 3 < 0.8 * lit]
    leaves = [x for row in rows for x, p in enumerate(row) if is_leafy(p)]
    assert len(shade) > 30 and len(leaves) > 30, (path, len(shade), len(leaves))
    return sum(shade) / len(shade) - sum(leaves) / len(leaves)

east, west = shadow_offset(sys.argv[1]), shadow_offset(sys.argv[2])
assert east < -5 and west > 5, (east, west)
PY
check "moving the sun moves the shadows" $?

# edit_while_viewing NAME FRAMES TEXT SEEN: views the scene for FRAMES frames, appends TEXT to it once the first is
# drawn, waits until the log shows SEEN (a grep pattern), and sets $code to the viewer's exit status.
edit_while_viewing() {
  local log="$work/$1.txt"
  view "$log" --frames "$2" --screenshot "$work/$1.png" &
  local viewer=$!
  for _ in $(seq 600); do grep -q 'the first frame is drawn' "$log" && break; sleep 0.2; done
  printf '%b' "$3" >>"$scene"
  for _ in $(seq 600); do grep -q "$4" "$log" && break; sleep 0.2; done
  wait $viewer
  code=$?
}

# A broken edit while the field grows: its error at its place, the field before it going on to the last frame.
edit_while_viewing edit 40 'Plant Broken {\n  Position = (0, 0\n' 'garden.eco:[0-9]*:[0-9]*: error'
grep -qE 'garden.eco:[0-9]+:[0-9]+: error: ' "$work/edit.txt"
check "a broken edit is reported at its line and column ($(grep error "$work/edit.txt" | head -c 300))" $?
[ $code -eq 0 ] && grep -q '40 frames, 40.0 s of growth, 4 plants' "$work/edit.txt" && [ -s "$work/edit.png" ]
ok=$?
check "the field before the edit keeps growing (exit $code: $(tail -n 1 "$work/edit.txt"))" $ok

# An edit that loads: the field starts again from the edited scene, the camera and panel kept.
cp "$source_dir/scenes/garden.eco" "$scene"
edit_while_viewing reload 30 '\n// edited while the viewer runs\n' 'garden.eco: reloaded'
[ $code -eq 0 ] && grep -q 'garden.eco: reloaded' "$work/reload.txt" && clean "$work/reload.txt" &&
  grep -q '30 frames, ' "$work/reload.txt" && [ -s "$work/reload.png" ]
ok=$?
check "an edit that loads starts the field again (exit $code: $(grep -v warning "$work/reload.txt" | head -c 300))" $ok

# The mouse, as xdotool moves it in the virtual display: a click on a plant picks it, a drag turns the camera.
# mouse_view NAME [XDOTOOL-ARGS...]: a paused 800x480 view of 80 frames, the mouse used once its first frame is drawn;
# its screenshot NAME.png, its output NAME.txt.
mouse_view() {
  local name=$1
  shift
  xvfb-run -a -s "-screen 0 1024x768x24" bash -c '
    simeco=$1 scene=$2 shot=$3 log=$4
    shift 4
    "$simeco" view "$scene" --plants 4 --size 800x480 --time 12 --set paused=on --frames 80 --screenshot "$shot" \
      >"$log" 2>&1 &
    viewer=$!
    for _ in $(seq 600); do grep -q "the first frame is drawn" "$log" && break; sleep 0.2; done
    [ $# -gt 0 ] && xdotool search --sync --name "simeco view" "$@"
    wait $viewer' _ "$simeco" "$scene" "$work/$name.png" "$work/$name.txt" "$@"
}
mouse_view still
# The middle of the plant most leaves gather at, right of the panel.
read -r px py < <(python3 - "$work/still.png" <<'PY'
import sys
from png_pixels import read_png, is_leafy
width, height, rows = read_png(sys.argv[1])
leafy = {(x, y) for y in range(height) for x in range(440, width) if is_leafy(rows[y][x])}
best = max(leafy, key=lambda p: sum((p[0] + dx, p[1] + dy) in leafy for dx in range(-3, 4) for dy in range(-3, 4)))
print(*best)
PY
)
[ -n "$px" ] && [ -n "$py" ]
check "a paused view shows a plant right of the panel ($(tail -n 1 "$work/still.txt"))" $?
mouse_view click mousemove --window %1 --sync "$px" "$py" click 1
grep -qE 'picked plant [0-3] \(' "$work/click.txt"
check "a click on a plant picks it ($(grep -a picked "$work/click.txt" | head -c 200))" $?
mouse_view drag mousemove --window %1 --sync 600 300 mousedown 1 sleep 0.5 mousemove --window %1 --sync 700 300 \
  sleep 0.5 mouseup 1
[ -s "$work/drag.png" ] && ! cmp -s "$work/still.png" "$work/drag.png" && ! grep -q picked "$work/drag.txt"
check "a drag turns the camera and picks nothing ($(tail -n 1 "$work/drag.txt"))" $?

# Bad settings and screenshots: exit 2, nothing written.
cp "$source_dir/scenes/garden.eco" "$scene"
view "$work/bad.txt" --frames 2 --screenshot "$work/bad.png" --set sun.colour=red
code=$?
[ $code -eq 2 ] && grep -q "no setting 'sun.colour'" "$work/bad.txt" && [ ! -e "$work/bad.png" ]
ok=$?
check "an unknown setting is refused (exit $code: $(head -c 300 "$work/bad.txt"))" $ok
view "$work/bad2.txt" --frames 2 --set sun.elevation=120
code=$?
[ $code -eq 2 ] && grep -q 'sun.elevation: 120 is outside' "$work/bad2.txt"
check "a setting out of its range is refused (exit $code)" $?
view "$work/bad3.txt" --frames 2 --screenshot "$work/shot.jpg"
[ $? -eq 2 ] && grep -q 'neither a .png nor an .exr' "$work/bad3.txt"
check "a screenshot other than PNG or EXR is refused" $?
env -u DISPLAY "$simeco" view "$scene" --frames 1 >"$work/nodisplay.txt" 2>&1
code=$?
[ $code -eq 1 ] && grep -q 'cannot open a window' "$work/nodisplay.txt"
check "without a display the viewer says so (exit $code: $(head -c 300 "$work/nodisplay.txt"))" $?

finish_checks
