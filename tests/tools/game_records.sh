#!/bin/sh
# `platon game --record DIR` in a real window (Xvfb, keys typed with xdotool): one replay per level
# played, written at the level's goal, at a reload (F5) and when the game quits, each of which
# replays bit for bit. Run by ctest as
#   with_xvfb.sh game_records.sh PLATON
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
rec="$data/rec"
XDG_DATA_HOME="$data" "$platon" game --record "$rec" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
await_title
# The first level to its goal: written there.
xdotool key Return
await "^playing cube_intro"
xdotool keydown Right
await "^level complete: cube_intro"
xdotool keyup Right
await "^recorded cube_intro: .* to $rec/cube_intro.replay"
# The next level, walked a little, then reloaded with F5: written at the reload.
xdotool key Return
await "^playing tetra_around"
xdotool keydown Right
sleep 1  # how far it walks does not matter
xdotool keyup Right
xdotool key F5
await "^reloaded tetra_around"
await "^recorded tetra_around: .* to $rec/tetra_around.replay"
# Restarted from the pause menu, walked, and quit: a second replay of the level, not overwriting.
xdotool key Escape Down Return  # the pause menu: Restart the level
await "^playing tetra_around" 2
xdotool keydown Right
sleep 1
xdotool keyup Right
xdotool key Escape Down Down Down Down Return Return  # the pause menu: Quit, and yes
await_exit "Quit in the pause menu did not end the game"
wait "$pid" || fail "the game failed"
grep -q "^recorded tetra_around: .* to $rec/tetra_around-2.replay" "$log" || fail "quitting did not write the second replay"
cat "$log"
for replay in cube_intro tetra_around tetra_around-2; do
  out=$("$platon" replay --shard 1/1 "$rec/$replay.replay") || fail "$replay.replay does not replay: $out"
  echo "$out" | head -n 1
done
"$platon" replay --shard 1/1 "$rec/cube_intro.replay" | grep -q "goal at frame" || fail "cube_intro.replay does not reach the goal"
rm -rf "$data"
