#!/bin/sh
# The game as a person plays it: a real window under Xvfb, keys typed with xdotool. Enter on the
# title screen starts the first level, holding Right walks it to the goal, Enter goes on to the next
# level, Esc and the pause menu quit. The level must be recorded as done in the progress file (a
# fresh XDG data folder), and the game must say where the player stood when it quit. Run by ctest as
#   xvfb-run -a real_window_game.sh PLATON
set -eu
platon=$1
unset SDL_VIDEODRIVER  # the X server xvfb-run started, not offscreen
data=$(mktemp -d)
log="$data/log"
XDG_DATA_HOME="$data" "$platon" game > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/focus_window.sh"
focus_window || fail "no window appeared"
sleep 0.3
xdotool key Return
for _ in $(seq 200); do grep -q "^playing cube_intro" "$log" && break; sleep 0.1; done
grep -q "^playing cube_intro" "$log" || fail "Enter on the title screen did not start the first level"
xdotool keydown Right
for _ in $(seq 1500); do  # up to 150 s of play (a slow machine drops steps): the walk takes about 18
  grep -q "^level complete: cube_intro" "$log" && break
  kill -0 "$pid" 2>/dev/null || fail "the game ended"
  sleep 0.1
done
xdotool keyup Right
grep -q "^level complete: cube_intro" "$log" || fail "holding Right did not finish the first level"
xdotool key Return
for _ in $(seq 200); do grep -q "^playing tetra_around" "$log" && break; sleep 0.1; done
grep -q "^playing tetra_around" "$log" || fail "Enter after the level did not start the next one"
xdotool key Escape
sleep 0.3
xdotool key Down Down Down Return  # the pause menu: Quit
for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$pid" 2>/dev/null && fail "Quit in the pause menu did not end the game"
wait "$pid" || fail "the game failed"
cat "$log"
grep -q "^cube_intro " "$data/platon/progress.txt" || fail "the progress file does not record cube_intro"
grep -q "^quit on tetra_around" "$log" || fail "the game did not say where it quit"
rm -rf "$data"
