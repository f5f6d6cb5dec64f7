#!/bin/sh
# The level editor in a real window (Xvfb; the mouse and keys by xdotool), once per solid: a new
# level (`platon edit --new SOLID`: a start and a goal, no floor) gets its floor drawn with the
# mouse; the draw is undone and redone; the start put into the floor is shown as an error and its
# save refused; the level is saved (its comments kept), checked by `platon check`, played from the
# cursor in the same window and finished by holding Right; K keeps the run as a test beside the
# level, which `platon run` passes. Run by ctest as
#   with_xvfb.sh real_window_editor.sh PLATON SOLID [SCREENSHOT_FOLDER]
# With a folder, F12's pictures of the drawn floor, the refused start and the finished play-test are
# copied there (editor_draw.png, editor_error.png, editor_play.png: docs/editing.md's).
set -eu
platon=$(realpath "$1")
solid=$2
pictures=${3:-}
unset SDL_VIDEODRIVER  # the X server xvfb-run started, not offscreen
data=$(mktemp -d)
log="$data/log"
level="$data/drawn"
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -rf "$data"; exit 1; }
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" edit --new "$solid" "$level" > "$log" 2>&1 &
pid=$!
. "$(dirname "$0")/window_test.sh"
shots=0
# shot NAME: F12, and the picture copied to the screenshot folder (when one was given).
shot() {
  [ -n "$pictures" ] || return 0
  xdotool key F12
  shots=$((shots + 1))
  await "^screenshot: " "$shots"
  cp "$(grep "^screenshot: " "$log" | sed -n "${shots}p" | cut -c13-)" "$pictures/$1.png"
}
focus_window
await "^editing "

# Three probing clicks in the select tool (a click on nothing selects nothing) tell how the
# window's pixels map onto face 0, seen head-on as the editor opens: (x, y) = o + u * px + v * py.
xdotool key s
xdotool mousemove --window "$window" 640 360 click 5 click 5 click 5  # the wheel: zoom out, the whole face in view
for p in "440 360" "840 360" "640 520"; do
  xdotool mousemove --window "$window" $p click 1
done
await "^press at pixel" 3
map=$(grep "^press at pixel" "$log" | head -3 | sed 's/[^-0-9. ]/ /g' | tr -s ' ' | tr '\n' ' ')
# pixel(x, y): the pixel of face 0's point (x, y), from the three presses (an affine map inverted).
pixel() {
  echo "$map" | awk -v X="$1" -v Y="$2" '{
    px1=$1; py1=$2; f1=$3; x1=$4; y1=$5; px2=$6; py2=$7; x2=$9; y2=$10; px3=$11; py3=$12; x3=$14; y3=$15;
    if (f1 != 0 || $8 != 0 || $13 != 0) { print "off"; exit }
    # face = A * (pixel - p1) + face1, A from two columns; solve for the pixel
    a = (x2 - x1) / (px2 - px1); c = (y2 - y1) / (px2 - px1); b = (x3 - x1 - a * (px3 - px1)) / (py3 - py1);
    d = (y3 - y1 - c * (px3 - px1)) / (py3 - py1); det = a * d - b * c;
    dx = X - x1; dy = Y - y1;
    printf "%d %d\n", px1 + (d * dx - b * dy) / det, py1 + (-c * dx + a * dy) / det }'
}
start_x=$(awk 'NR>1 && /# start/ {print $2}' "$level/drawn.level")
goal_x=$(awk 'NR>1 && /# goal/ {print $2}' "$level/drawn.level")
from=$(pixel $((start_x - 300)) 256)
to=$(pixel $((goal_x + 300)) 256)
[ "$from" != "off" ] || fail "the probing presses were not all on face 0: $map"

# The floor, dragged with the left button in the draw tool; undone and redone.
xdotool key d
xdotool mousemove --window "$window" $from mousedown 1
xdotool mousemove --window "$window" $(pixel 2048 256)
xdotool mousemove --window "$window" $to mouseup 1
await "^editor: draw a segment"
xdotool key ctrl+z
await "^editor: undone: draw a segment"
xdotool key ctrl+y
await "^editor: redone: draw a segment"
shot editor_draw

# The start onto the floor: an error where the start is; the save refused; undone.
xdotool mousemove --window "$window" $(pixel "$start_x" 280) key p
await "^editor: move the start"
xdotool key ctrl+s
await "^editor: not saved: the level would not load"
shot editor_error
xdotool key ctrl+z
await "^editor: undone: move the start"

xdotool key ctrl+s
await "^editor: saved "
grep -q "^# drawn: made by" "$level/drawn.level" || fail "the saved level lost its comments: $(cat "$level/drawn.level")"
grep -q "# face 0: draw a floor" "$level/drawn.level" || fail "the saved level lost a face's comment"
"$platon" check "$level" > "$data/check" 2>&1 || fail "platon check refused the drawn level: $(cat "$data/check")"

# Play from the cursor (on the start), hold Right to the goal, keep the run as a test.
xdotool mousemove --window "$window" $(pixel "$start_x" 420) key Return
await "^playing from face 0"
xdotool keydown Right
await "^goal reached at frame"
xdotool keyup Right
shot editor_play
xdotool key k
await "^kept as .*passes headless"
xdotool key Escape
await "^editor: kept as "
xdotool key Escape
await_exit "Esc did not quit the editor"
wait "$pid" || fail "the editor failed"
(cd "$level" && "$platon" run test_1.lua) > "$data/run" 2>&1 || fail "the kept test does not pass: $(cat "$data/run")"
grep -q "^  start = { face = 0" "$level/test_1.lua" || fail "the kept test does not start where the run did"
cat "$log"
rm -rf "$data"
