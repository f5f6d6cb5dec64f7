#!/bin/sh
# `platon game --record DIR` in a real window (Xvfb, keys typed with xdotool): one replay per level
# played, written at the level's goal, at a reload (F5) and when the game quits, each of which
# replays bit for bit. Run by ctest as
#   with_xvfb.sh game_records.sh PLATON
set -eu
platon=$1
unset SDL_VIDEODRIVER  # the X server xvfb-run started, not offscreen
data=$(mktemp -d)
log="$data/log"
rec="$data/rec"
XDG_DATA_HOME="$data" "$platon" game --record "$rec" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -rf "$data"; exit 1; }
await() {  # a line of the log, for up to $2 tenths of a second
  for _ in $(seq "$2"); do grep -q "$1" "$log" && return 0; kill -0 "$pid" 2>/dev/null || fail "the game ended"; sleep 0.1; done
  fail "no line '$1' in the log"
}
. "$(dirname "$0")/focus_window.sh"
focus_window || fail "no window appeared"
sleep 0.3
# The first level to its goal: written there.
xdotool key Return
await "^playing cube_intro" 200
xdotool keydown Right
await "^level complete: cube_intro" 1500
xdotool keyup Right
await "^recorded cube_intro: .* to $rec/cube_intro.replay" 50
# The next level, walked a little, then reloaded with F5: written at the reload.
xdotool key Return
await "^playing tetra_around" 200
xdotool keydown Right
sleep 1
xdotool keyup Right
xdotool key F5
await "^reloaded tetra_around" 100
await "^recorded tetra_around: .* to $rec/tetra_around.replay" 50
# Restarted from the pause menu, walked, and quit: a second replay of the level, not overwriting.
xdotool key Escape
sleep 0.3
xdotool key Down Return  # Restart the level
await "playing tetra_around" 100
[ "$(grep -c '^playing tetra_around' "$log")" -eq 2 ] || fail "the restart did not start the level again"
xdotool keydown Right
sleep 1
xdotool keyup Right
xdotool key Escape
sleep 0.3
xdotool key Down Down Down Return  # Quit
for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
kill -0 "$pid" 2>/dev/null && fail "Quit in the pause menu did not end the game"
wait "$pid" || fail "the game failed"
grep -q "^recorded tetra_around: .* to $rec/tetra_around-2.replay" "$log" || fail "quitting did not write the second replay"
cat "$log"
for replay in cube_intro tetra_around tetra_around-2; do
  out=$("$platon" replay "$rec/$replay.replay") || fail "$replay.replay does not replay: $out"
  echo "$out" | head -n 1
done
"$platon" replay "$rec/cube_intro.replay" | grep -q "goal at frame" || fail "cube_intro.replay does not reach the goal"
rm -rf "$data"
