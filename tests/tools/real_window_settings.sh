#!/bin/sh
# The settings screen in a real window (Xvfb, keys typed with xdotool), as a player uses it: each
# button's row rebinds that button (Enter on "Jump key" rebinds Jump; it rebound Restart, one row
# off), Restart can be rebound too, multisampling changes, Esc saves the file, and the new jump key
# jumps in a level. Run by ctest as
#   with_xvfb.sh real_window_settings.sh PLATON
set -eu
platon=$1
export SDL_VIDEODRIVER=x11  # the X server xvfb-run started: never a silent fallback to offscreen
data=$(mktemp -d)
log="$data/log"
settings="$data/config/platon/settings.txt"
XDG_DATA_HOME="$data" XDG_CONFIG_HOME="$data/config" "$platon" game > "$log" 2>&1 &
pid=$!
fail() { echo "$1"; cat "$log"; [ -f "$settings" ] && cat "$settings"; kill "$pid" 2>/dev/null; rm -rf "$data"; exit 1; }
. "$(dirname "$0")/window_test.sh"
await_title
xdotool key Tab  # the settings, from the title
# The rows: music, effects, shake, full screen, vsync, game speed, multisampling, then the keys of
# Left, Right, Up, Down, Jump, Restart, then Back.
xdotool key Down Down Down Down Down Down  # multisampling
xdotool key Right  # auto -> off
xdotool key Down Down Down Down Down  # Jump key
xdotool key Return
xdotool key j
await "^settings: Jump is J$"
xdotool key Down Return  # Restart key
xdotool key t
await "^settings: Restart is T$"
xdotool key Escape  # back to the title: saved
await "^settings: music"
grep -q "^keys_jump J$" "$settings" || fail "Jump is not J in the file"
grep -q "^keys_restart T$" "$settings" || fail "Restart is not T in the file"
grep -q "^multisampling 0$" "$settings" || fail "multisampling did not change"
xdotool key Escape  # quit? asks
await "^quit asked"
xdotool key Escape  # no: back to the title
xdotool key Escape  # quit? asks again
await "^quit asked" 2
kill -0 "$pid" || fail "the game quit without asking"
xdotool key Return  # yes
await_exit "Enter on the question did not end the game"
wait "$pid" || fail "the game failed"
echo "every row rebinds its own button"
rm -rf "$data"
