#!/bin/sh
# The game's console in a real window (Xvfb, keys typed with xdotool): ` opens it while playing,
# a line of Lua runs in the level's sandbox with its `game` (an expression shows its value, an
# error says so, a loop is stopped by the sandbox's budget), and each line is recorded in the
# level's replay before the frame it ran ahead of: the replay reproduces the run bit for bit, and
# without its console lines it does not. Run by ctest as
#   with_xvfb.sh real_window_console.sh PLATON [COPY_SCREENSHOT_TO]
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
rec="$data/rec"
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" game --record "$rec" > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; xdotool keyup Right 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
await_title
xdotool key Return
await "^playing cube_intro"
xdotool keydown Right
sleep 0.5
xdotool keyup Right
xdotool key grave
xdotool type --delay 20 '6 * 7'
xdotool key Return
await "^console> 6 \* 7"
await "^42$"
xdotool type --delay 20 'game.world.setVelocity(game.player(), 0, 25)'
xdotool key Return
await "^console> game.world.setVelocity"
xdotool type --delay 20 'game.nothing()'
xdotool key Return
await "attempt to call field 'nothing'"
xdotool type --delay 20 'while true do end'
xdotool key Return
await "^console: script stopped"  # the budget, or on a loaded machine the deadline
xdotool key F12  # the console on screen, with what it answered
await "^screenshot: "
shot=$(grep "^screenshot: " "$log" | cut -c13-)
[ -n "${2:-}" ] && cp "$shot" "$2"
xdotool key grave
xdotool keydown Right
sleep 0.5
xdotool keyup Right
xdotool key Escape Down Down Down Down Return Return  # the pause menu: Quit, and yes
await_exit "Quit in the pause menu did not end the game"
wait "$pid" || fail "the game failed"
replay="$rec/cube_intro.replay"
[ -f "$replay" ] || fail "no replay recorded"
[ "$(grep -c '^console ' "$replay")" -eq 4 ] || fail "the replay has not the 4 console lines: $(cat "$replay")"
grep -q '^console [0-9]* "game.world.setVelocity(game.player(), 0, 25)"$' "$replay" || fail "the line as typed: $(grep console "$replay")"
"$platon" replay "$replay" > "$data/replayed" 2>&1 || fail "the replay with its console lines differs: $(cat "$data/replayed")"
grep -v '^console ' "$replay" > "$data/without.replay"
if "$platon" replay "$data/without.replay" > /dev/null 2>&1; then fail "the console lines changed nothing"; fi
cat "$log"
rm -rf "$data"
