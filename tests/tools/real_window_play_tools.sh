#!/bin/sh
# `platon play` has the tools the game has, in a real window (Xvfb, keys typed with xdotool): the
# console (` then a line of Lua and Enter), F5 reloads the level (and ends the recording: the new
# version starts from a state no replay reproduces), and the play ends by itself at the goal, as
# its help says. The recording up to the reload replays bit for bit. Run by ctest as
#   with_xvfb.sh real_window_play_tools.sh PLATON
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" play levels/cube_intro --record "$data/run.replay" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
focus_window
await "^playing "
xdotool key grave
xdotool type --delay 20 '6 * 7'
xdotool key Return
await "^console> 6 \* 7"
await "^42$"
xdotool type --delay 20 'game.frame() > 0'
xdotool key Return
await "^true$"
xdotool type --delay 20 "game.message('typed in the console')"
xdotool key Return
xdotool key grave  # closed: the letters typed moved nobody
await "^frame [0-9]*: typed in the console"  # a frame played after the lines: they are in the recording
xdotool key F5
await "^reloaded in "
await "^recording stops at frame "
xdotool keydown Right
await "^goal reached at frame "
xdotool keyup Right
await_exit "play did not end at the goal"
wait "$pid" || fail "play failed"
[ -f "$data/run.replay" ] || fail "no recording"
grep -q '^console [0-9]* "6 \* 7"$' "$data/run.replay" || fail "the console's line is not in the recording: $(cat "$data/run.replay")"
"$platon" replay "$data/run.replay" > "$data/replayed" 2>&1 || fail "the recording differs: $(cat "$data/replayed")"
cat "$log"
rm -rf "$data"
