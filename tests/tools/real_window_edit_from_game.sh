#!/bin/sh
# F4 in the game opens the editor on the level being played, in the same window; an edit saved
# there is what the game plays when Esc comes back (the level reloaded). The level is a copy (a
# campaign of its own), so the shipped one is never written. Run by ctest as
#   with_xvfb.sh real_window_edit_from_game.sh PLATON
set -eu
platon=$(realpath "$1")
tools=$(cd "$(dirname "$0")" && pwd)
source_root=$(pwd)
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
cp -r levels/cube_intro "$data/cube_intro"
printf 'cube_intro\n' > "$data/campaign.txt"
cd "$data"
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" game --campaign campaign.txt > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; kill "$pid" 2>/dev/null; rm -rf "$data"; exit 1; }
. "$tools/window_test.sh"
await_title
xdotool key Return
await "^playing cube_intro"
xdotool key F4
await "^editing .*cube_intro"
await "^editing .*cube_intro.level"
xdotool mousemove --window "$window" 640 300 key g  # the goal where the pointer is
await "^editor: move the goal"
xdotool key ctrl+s
await "^editor: saved "
xdotool key Escape
await "^reloaded cube_intro"
cmp -s "$data/cube_intro/cube_intro.level" "$source_root/levels/cube_intro/cube_intro.level" && fail "the goal did not move"
xdotool key Escape Down Down Down Down Return Return  # the pause menu: Quit, and yes
await_exit "Quit in the pause menu did not end the game"
wait "$pid" || fail "the game failed"
cat "$log"
rm -rf "$data"
