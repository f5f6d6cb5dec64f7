#!/bin/sh
# How long a level takes to make in the editor, measured on one: cube_switches (two faces: a back
# wall, a floor with a pit and its hazard, a checkpoint, a switch to jump into, a door, an end wall,
# the start and the goal) made again from `platon edit --new HEXAHEDRON` with the mouse and keys
# alone, as a person would (xdotool in Xvfb: every press of a button or key is one action), then
# checked, and its solution (tests/scenarios/cube_switches_solve.lua's input) played on it.
# Prints the number of actions and the session's time; the level is left in $1 (default: a
# temporary folder, removed).
#   xvfb-run -a -s "-screen 0 1280x720x24" tools/editor_remake.sh [FOLDER]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
platon="$root/build/apps/platon"
unset SDL_VIDEODRIVER
data=$(mktemp -d)
log="$data/log"
level=${1:-$data/switches}
name=$(basename "$level")
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; rm -rf "$data"; exit 1; }
began=$(date +%s.%N)
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" edit --new HEXAHEDRON "$level" > "$log" 2>&1 &
pid=$!
. "$root/tests/tools/window_test.sh"
. "$root/tests/tools/editor_probe.sh"
focus_window
await "^editing "
actions=0
act() { actions=$((actions + $1)); }  # each button press or key press of the session
said=0
wait_edit() { said=$((said + 1)); await "^editor: " "$said"; }  # one message more
probe_face0  # (probing is the test's way of seeing the screen; a person looks: not counted)

# Face 0: the back wall, the floor, the pit and the floor on to the edge as one chain of clicks.
xdotool key d && act 1
for p in "192 2816" "192 1216" "1920 1216" "1920 896" "2176 896" "2176 1216" "4096 1216"; do
  point $p
  xdotool click 1 && act 1
done
wait_edit; wait_edit; wait_edit; wait_edit; wait_edit; wait_edit
xdotool key Escape && act 1
wait_edit
# The checkpoint and the switch: a word of the palette each, and a drag.
xdotool key t t t && act 3
drag 1216 1216 1216 1792 && act 1
wait_edit
xdotool key t t && act 2
drag 3008 1472 3008 1792 && act 1
wait_edit
# The pit's bottom is deadly: select it, and the palette to hazard.
xdotool key s && act 1
point 2048 896
xdotool click 1 && act 1
xdotool key t t && act 2  # switch 1 -> solid (it is already) -> hazard: the selection takes it
wait_edit
# The start.
point 512 1344
xdotool key p && act 1
wait_edit
# Face 1: the solid turned (the right button, dragged left), the face head-on (F).
xdotool mousemove --window "$window" 900 400 mousedown 3 mousemove --window "$window" 640 400 \
  mousemove --window "$window" 600 400 mouseup 3 && act 1
xdotool mousemove --window "$window" 640 400 key f && act 1
probe_face 1
xdotool key d && act 1
xdotool key t t t t t && act 5  # hazard -> goal -> checkpoint -> door 1 -> switch 1 -> solid
for p in "20 1216" "3392 1216" "3392 2816"; do  # (20: on face 1 by the edge; the grid takes it to 0)
  point $p
  xdotool click 1 && act 1
done
xdotool key Escape && act 1
await "^editor: drawing cancelled"
said=$(grep -c "^editor: " "$log")
xdotool key t t t t && act 4  # solid -> hazard -> goal -> checkpoint -> door 1
drag 1472 1216 1472 2624 && act 1
wait_edit
point 2624 1408
xdotool key g && act 1
wait_edit
xdotool key ctrl+s && act 1
await "^editor: saved "
xdotool key Escape && act 1
await_exit "Esc did not quit the editor"
ended=$(date +%s.%N)
cat "$level/$name.level"
"$platon" check "$level" || fail "the remade level does not check"
# The original's solution: its input (hold right, two jumps), and the goal by its last frame, no death.
{
  echo 'return { scene = "scene.lua", frames = 720, input = {'
  echo '  { hold = "right", from = 1, to = 720 }, { press = "jump", at = 158, frames = 30 },'
  echo '  { press = "jump", at = 258, frames = 30 } }, expect = { goal_by = 720, deaths = 0 } }'
} > "$level/solve.lua"
if (cd "$level" && "$platon" run solve.lua); then solved="and cube_switches' own solution finishes it"; else
  solved="(cube_switches' own solution, played on it, does not finish it: the grid moved its lines)"; fi
echo "remade cube_switches in the editor: $actions actions, $(echo "$ended - $began" | bc) s scripted $solved"
[ -n "${1:-}" ] || rm -rf "$data"
